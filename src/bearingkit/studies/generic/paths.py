"""Factor paths of the generic evaluator: the named values of a bearing input a study may set or vary.

SI units: every path has a physical dimension (a key of :data:`bearingkit.units.SI_UNITS`), ``count``
or ``text``; a study file gives its values with units (``"20 um"``), the case table holds SI floats, and
:func:`apply` writes them back into the input as text with the SI unit (``"2e-05 m"``, read back
exactly).

A path names a field of the input file (docs/input-format.md):

- ``geometry.<field>`` — a field of the bearing type's geometry (``geometry.clearance_radial``),
  ``geometry.<table>.<field>`` inside a nested table (``geometry.ring.compliance_scale``, and
  ``geometry.profile.crown_radius`` when the file gives a profile);
- ``material.name`` (text), ``material.youngs_modulus``, ``material.poisson_ratio``,
  ``material.density`` (setting a constant of a named material sets all three from the preset first);
- ``lubricant.name`` (text: a preset or library entry), and every other field of ``[lubricant]``
  (``lubricant.nu_40``, ``lubricant.vi``, ``lubricant.base_oil`` …; a name set with them starts from that
  entry, docs/lubricants.md);
- ``load_cases.<case>.<field>`` — F_x, F_y, F_z, M_x, M_y, eccentricity, speed, temperature of a load
  case of the file (``<case>`` its name);
- ``duty_cycle.<bin>.<field>`` — the same fields of a duty-cycle bin (not eccentricity);
- ``solver.rtol``, ``solver.max_iterations``;
- ``operating.speed``, ``operating.temperature`` — the speed and temperature of the study's load case;
  ``operating.rotating`` (inner | outer), ``operating.reliability``, ``operating.contamination``
  (ISO 281 e_C, a number or a level name such as ``"normal_cleanliness"``),
  ``operating.friction_model`` (auto | components | skf | palmgren) — the analysis's settings;
- any field of the further sections a bearing file may have (their models in
  ``bearingkit.io.optional_sections.operating.SECTION_MODELS`` when that module exists).

Each path has a **kind**: ``file`` paths edit the input (cases that differ in one are solved as
separate groups), ``case`` paths are per load case (batched: cases that differ only in them share ONE
solve), ``analysis`` paths are settings of the Analysis (they group the cases too).
"""

from __future__ import annotations

import copy
import difflib
import functools
from collections.abc import Mapping
from dataclasses import dataclass

from bearingkit.errors import InputError
from bearingkit.io import schema
from bearingkit.units import SI_UNITS

__all__ = ["InputPath", "apply", "input_paths", "nearest", "value_text"]

#: Fields of a load case a path may set (the fields of :class:`bearingkit.io.schema.LoadCaseSpec`).
CASE_FIELDS = ("F_x", "F_y", "F_z", "M_x", "M_y", "eccentricity", "speed", "temperature")
#: Analysis settings a study may set or vary: name → (dimension, choices, description).
ANALYSIS_SETTINGS = {
    "rotating": ("text", ("inner", "outer"), "ring rotating relative to the load"),
    "reliability": ("dimensionless", (), "reliability of L_nr, 0.9 … 0.9995"),
    "contamination": ("dimensionless", (), "ISO 281 contamination factor e_C (gives a_ISO, L_nmr)"),
    "friction_model": ("text", ("auto", "components", "skf", "palmgren"), "friction model of the analysis"),
}


@dataclass(frozen=True)
class InputPath:
    """A value of a bearing input a study may set.

    Attributes
    ----------
    path : str
        ``geometry.clearance_radial``, ``load_cases.radial.F_x`` …
    dimension : str
        A key of :data:`bearingkit.units.SI_UNITS`, ``"count"``, ``"text"`` or ``"flag"`` (true/false).
    nominal : object
        The value in the input (SI), or None where the builder's default applies.
    kind : {"file", "case", "analysis"}
        How the value reaches the analysis (module docstring).
    choices : tuple of str
        The accepted text values, where the schema lists them.
    description : str
    named : tuple of (str, float)
        Values given by name and their SI value (the ISO 281 contamination levels of this bearing).
    """

    path: str
    dimension: str
    nominal: object
    kind: str
    choices: tuple = ()
    description: str = ""
    named: tuple = ()

    @property
    def unit(self) -> str:
        """The SI unit of the path's values (``-`` dimensionless, ``count``, ``text``)."""
        if self.dimension in ("count", "text", "flag"):
            return self.dimension
        return SI_UNITS[self.dimension] or "-"


@functools.lru_cache(maxsize=64)
def _json_schema(model) -> dict:
    return model.model_json_schema()


def _scalar(prop: dict, defs: dict):
    """(dimension, choices, ref) of a JSON-schema property; None for lists, flags and unions of tables."""
    options = prop.get("anyOf", [prop])
    options = [o for o in options if o.get("type") != "null"]
    if len(options) != 1:
        return None
    o = options[0]
    if "$ref" in o:
        return None, (), o["$ref"].rsplit("/", 1)[-1]
    if "x-dimension" in o and o.get("type") in ("string", "number", "integer"):
        return o["x-dimension"], (), None
    if o.get("type") == "string":
        return "text", tuple(o.get("enum", ())), None
    if o.get("type") == "boolean":
        return "flag", (), None
    return None


def model_paths(prefix: str, model, values: Mapping | None, kind: str = "file") -> dict:
    """Paths of the scalar fields of a pydantic ``model`` (nested tables of the model recursed into)."""
    js = _json_schema(model)
    defs = js.get("$defs", {})
    out = {}
    values = values or {}
    for name, prop in js.get("properties", {}).items():
        info = _scalar(prop, defs)
        if info is None:
            continue
        dimension, choices, ref = info
        path = f"{prefix}.{name}"
        if ref is not None:
            sub = model.model_fields[name].annotation
            sub_model = _submodel(sub, ref)
            if sub_model is None:
                continue
            present = values.get(name)
            required = any(f.is_required() for f in sub_model.model_fields.values())
            if present is None and required:
                continue  # a nested table with required fields exists only where the file gives it
            nested = present if isinstance(present, Mapping) else _dump(present)
            out.update(model_paths(path, sub_model, nested, kind))
            continue
        nominal = _dump(values.get(name))
        out[path] = InputPath(path, dimension, nominal, kind, choices, prop.get("description", ""))
    return out


def _dump(value):
    if hasattr(value, "model_dump"):
        return value.model_dump()
    return value


def _submodel(annotation, ref: str):
    """The pydantic model named ``ref`` inside an annotation such as ``ProfileSpec | None``."""
    from typing import get_args

    stack = [annotation]
    while stack:
        a = stack.pop()
        if isinstance(a, type) and a.__name__ == ref and hasattr(a, "model_fields"):
            return a
        stack.extend(get_args(a))
    return None


def _extra_sections() -> dict:
    """Section name → model of sections validated outside the schema module (operating conditions)."""
    try:
        from bearingkit.io.optional_sections import operating as schema_operating
    except ImportError:
        return {}
    return dict(getattr(schema_operating, "SECTION_MODELS", {}))


def input_paths(bearing) -> dict[str, InputPath]:
    """Every path of ``bearing`` (a loaded :class:`~bearingkit.io.loader.BearingInput`), by name."""
    from bearingkit.lubricants import lubricant_names
    from bearingkit.materials import MATERIALS
    from bearingkit.pipeline.operating_output import contamination_values

    spec = bearing.spec
    out = model_paths("geometry", schema.GEOMETRY_MODELS[bearing.bearing_type], bearing.geometry.model_dump())
    material = spec.material.model_dump() if spec.material is not None else {"name": "GCr15"}
    mat = model_paths("material", schema.MaterialSpec, material)
    mat["material.name"] = InputPath(
        "material.name", "text", material.get("name"), "file", tuple(MATERIALS), "material preset"
    )
    if material.get("name") in MATERIALS:  # the preset's constants are the nominal values
        preset = MATERIALS[material["name"]]
        for key in ("youngs_modulus", "poisson_ratio", "density"):
            p = mat[f"material.{key}"]
            mat[p.path] = InputPath(p.path, p.dimension, getattr(preset, key), "file", (), p.description)
    out.update(mat)
    given = spec.lubricant.model_dump(exclude_none=True) if spec.lubricant is not None else {}
    out.update(model_paths("lubricant", schema.LubricantSpec, given))  # every field of [lubricant]
    lube = None if bearing.lubricant is None else bearing.lubricant.name
    out["lubricant.name"] = InputPath(
        "lubricant.name", "text", lube, "file", tuple(lubricant_names()), "lubricant preset or library entry"
    )
    solver = spec.solver.model_dump()
    for key in ("rtol", "max_iterations"):
        p = model_paths("solver", schema.SolverSpec, solver)[f"solver.{key}"]
        out[p.path] = p
    case_paths = model_paths("x", schema.LoadCaseSpec, None, "case")
    for case in spec.load_cases:
        values = case.model_dump()
        for f in CASE_FIELDS:
            p = case_paths[f"x.{f}"]
            path = f"load_cases.{case.name}.{f}"
            out[path] = InputPath(path, p.dimension, values.get(f), "case", (), p.description)
    cycle = getattr(bearing, "duty_cycle", None)
    if cycle is not None:  # the bins' loads and speeds; their fractions stay as the file gives them
        for lc in cycle.bins:
            nominal = {
                "F_x": lc.load[0],
                "F_y": lc.load[1],
                "F_z": lc.load[2],
                "M_x": lc.load[3],
                "M_y": lc.load[4],
                "eccentricity": None,
                "speed": lc.speed,
                "temperature": lc.temperature,
            }
            for f in CASE_FIELDS:
                if f == "eccentricity":
                    continue  # a bin's load is kept as its moment M_y
                p = case_paths[f"x.{f}"]
                path = f"duty_cycle.{lc.name}.{f}"
                out[path] = InputPath(path, p.dimension, nominal[f], "case", (), p.description)
    for section, model in _extra_sections().items():
        raw = getattr(spec, section, None)
        out.update({k: v for k, v in model_paths(section, model, raw).items() if k not in out})
    out["operating.speed"] = InputPath(
        "operating.speed", "angular_velocity", None, "case", (), "speed of the study's load case"
    )
    out["operating.temperature"] = InputPath(
        "operating.temperature", "temperature", None, "case", (), "temperature of the study's load case"
    )
    for key, (dim, choices, text) in ANALYSIS_SETTINGS.items():
        out[f"operating.{key}"] = InputPath(f"operating.{key}", dim, None, "analysis", choices, text)
    # e_C by an ISO 281 level name too, as files and the command line take it (its value for this bearing)
    levels = tuple(contamination_values(bearing).items())
    p = out["operating.contamination"]
    out[p.path] = InputPath(p.path, p.dimension, None, "analysis", (), p.description, levels)
    return out


def nearest(path: str, known, n: int = 3) -> list[str]:
    """The ``n`` known paths closest to ``path`` (for one-line messages)."""
    known = list(known)
    close = difflib.get_close_matches(path, known, n=n, cutoff=0.5)
    if close:
        return close
    head = path.split(".", 1)[0]
    return [k for k in known if k.startswith(head + ".")][:n] or known[:n]


def value_text(value, dimension: str):
    """An SI value as the input file writes it: text with the SI unit, a bare number, or a name.

    ``repr`` keeps every digit, so :func:`bearingkit.units.parse` reads back the same float.
    """
    if dimension == "text":
        return str(value)
    if dimension == "flag":
        return bool(value)
    if dimension == "count":
        return int(value)
    if dimension == "dimensionless":
        return float(value)
    return f"{float(value)!r} {SI_UNITS[dimension]}"


def _table(data: dict, key: str) -> dict:
    table = data.get(key)
    if not isinstance(table, dict):
        table = {}
        data[key] = table
    return table


def apply(data: dict, values: Mapping[str, object], paths: Mapping[str, InputPath]) -> dict:
    """A copy of the parsed input ``data`` with the ``file`` paths in ``values`` set (SI values).

    None (or NaN) leaves the input's value. ``case`` and ``analysis`` paths are not written here (the
    generic evaluator builds the load cases and the Analysis settings from them).
    """
    from bearingkit.materials import MATERIALS

    out = copy.deepcopy(data)
    # a lubricant name first (it replaces the table), then the lubricant fields set with it
    ordered = sorted(values.items(), key=lambda kv: kv[0] != "lubricant.name")
    for path, value in ordered:
        p = paths[path]
        if p.kind != "file" or value is None or (isinstance(value, float) and value != value):
            continue
        text = value_text(value, p.dimension)
        parts = path.split(".")
        section = parts[0]
        if section == "material":
            mat = _table(out, "material")
            if parts[1] == "name":
                out["material"] = {"name": text}
                continue
            if "name" in mat:  # a preset: its constants, then the one set here
                preset = MATERIALS.get(mat["name"])
                if preset is None:
                    raise InputError(f"material.name ({mat['name']!r}) must be one of {', '.join(MATERIALS)}")
                mat.clear()
                mat.update(
                    {
                        "youngs_modulus": value_text(preset.youngs_modulus, "pressure"),
                        "poisson_ratio": float(preset.poisson_ratio),
                        "density": value_text(preset.density, "density"),
                    }
                )
            elif not mat:
                preset = MATERIALS["GCr15"]  # the loader's default material
                mat.update(
                    {
                        "youngs_modulus": value_text(preset.youngs_modulus, "pressure"),
                        "poisson_ratio": float(preset.poisson_ratio),
                        "density": value_text(preset.density, "density"),
                    }
                )
            mat[parts[1]] = text
        elif section == "lubricant":  # a name starts a new table; the other fields edit it
            if parts[1] == "name":
                out["lubricant"] = {"name": text}
            else:
                _table(out, "lubricant")[parts[1]] = text
        else:
            table = _table(out, section)
            for key in parts[1:-1]:
                sub = table.get(key)
                if isinstance(sub, str):  # profile = "iso16281" shorthand
                    sub = {"name": sub}
                if not isinstance(sub, dict):
                    sub = {}
                table[key] = sub
                table = sub
            table[parts[-1]] = text
    return out
