"""One-line messages for validation errors of an input file: ``FILE: field (value): expectation``.

pydantic reports every problem of a table; the user gets one line, the most useful one: an unknown
key first (a typo in a required key also reports that key as missing; the typo is the cause), with
the nearest valid key as a suggestion (difflib). Values are quoted short (:func:`bearingkit.errors.quote`).
"""

from __future__ import annotations

from pydantic import BaseModel, ValidationError

from bearingkit.errors import InputError, nearest, quote
from bearingkit.io import schema

#: Valid keys are listed in an "unknown field" message only up to this many (else: the nearest one).
MAX_LISTED_FIELDS = 8


def section_models(geometry_model: type[BaseModel] | None) -> dict[str, type[BaseModel]]:
    """Dotted section name → its pydantic model (``""`` is the whole file)."""
    models = {
        "": schema.BearingFile,
        "bearing": schema.BearingHeader,
        "material": schema.MaterialSpec,
        "hardness": schema.HardnessSpec,
        "lubricant": schema.LubricantSpec,
        "load_cases": schema.LoadCaseSpec,
        "solver": schema.SolverSpec,
    }
    if geometry_model is not None:
        models["geometry"] = geometry_model
        models["geometry.profile"] = schema.ProfileSpec
        if "ring" in geometry_model.model_fields:
            models["geometry.ring"] = schema.BallColumnRingSpec
        if "diameter_deviation" in geometry_model.model_fields:
            models["geometry.diameter_deviation"] = schema.DeviationGenerator
    return models


def dotted(loc) -> str:
    """``("load_cases", 0, "F_x")`` → ``"load_cases[0].F_x"``; other keys quoted (``'\\u202e5 kN'``)."""
    out = ""
    for part in loc:
        if not isinstance(part, int):  # a key of the file: quoted unless a plain name (no control chars)
            part = part if str(part).isidentifier() else quote(str(part))
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


def prefix_field(message: str, section: str, fields) -> str:
    """``"conformity (0.4) …"`` → ``"geometry.conformity (0.4) …"`` when the field is in the section."""
    head = message.split(" ", 1)[0]
    if head in fields:
        return f"{section}.{message}"
    return f"{section}: {message}"


def one_line(source: str, exc: ValidationError, prefix: tuple, models: dict) -> InputError:
    """The most useful pydantic error of ``exc`` as one line: FILE: field (value): what was expected."""
    errors = exc.errors(include_url=False)
    err = _most_useful(errors)
    loc = (*prefix, *err["loc"])
    path = dotted(loc)
    kind, value = err["type"], err.get("input")
    section = ".".join(str(p) for p in loc[:-1] if not isinstance(p, int))
    if kind == "value_error":
        msg = str(err["ctx"]["error"])
        field = str(err["loc"][-1]) if err["loc"] else ""
        text = path + msg[len(field) :] if field and msg.startswith(field) else f"{path}: {msg}"
    elif kind == "missing":
        text = f"{path}: missing required field"
    elif kind == "extra_forbidden" and path == "geometry.ring":
        # [geometry.ring] belongs to the ball–column bearing; every bearing's rings go under [structure]
        text = (
            f"{path} ({quote(value)}): unknown field for this bearing type; flexible rings, housings and "
            "flanges of any bearing go under [structure.outer] / [structure.inner] (docs/structure.md)"
        )
    elif kind == "extra_forbidden":
        text = f"{path} ({quote(value)}): unknown field{_valid_fields(loc[-1], models.get(section), errors)}"
    else:
        text = f"{path} ({quote(value)}): {err['msg']}"
    return InputError(f"{source}: {text}")


def _most_useful(errors: list[dict]) -> dict:
    """An unknown key before anything else (it explains a 'missing' one), else the first error."""
    for err in errors:
        if err["type"] == "extra_forbidden":
            return err
    return errors[0]


def _valid_fields(key, model, errors) -> str:
    """``"; did you mean 'pitch_diameter' (required, missing)?"`` or the list of valid keys."""
    if model is None:
        return ""
    names = list(model.model_fields)
    missing = {str(e["loc"][-1]) for e in errors if e["type"] == "missing" and e["loc"]}
    alias = getattr(model, "FIELD_ALIASES", {}).get(str(key).lower())  # a known other spelling
    near = [alias] if alias else nearest(str(key), names)
    if near:
        note = " (required, missing)" if near[0] in missing else ""
        return f"; did you mean {near[0]!r}{note}?"
    if len(names) <= MAX_LISTED_FIELDS:
        return f"; expected one of {', '.join(names)}"
    return f"; see `bearingkit schema` for the {len(names)} valid keys"
