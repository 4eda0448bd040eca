"""One parser, one model: every form a lubricant is given in becomes a :class:`Lubricant` here.

The forms (every face accepts the same; docs/lubricants.md):

- a **name**: a preset (:data:`~bearingkit.lubricants.presets.LUBRICANTS`) or a library entry
  (:data:`~bearingkit.lubricants.library.LIBRARY`);
- **fields** (the ``[lubricant]`` table of a file, the app's editor, a study's ``lubricant.*``
  factors, ``--lubricant-file``): ``nu_40`` and ``nu_100``, or ``iso_vg``/``nu_40`` and ``vi``, a
  ``base_oil`` (mineral, pao, ester, pag), optionally ``density``, ``pressure_viscosity``,
  ``thermal_conductivity``, ``specific_heat``; a grease adds ``thickener``, ``nlgi``, ``life_class``,
  ``temperature_min``/``temperature_max``. With a ``name`` of a preset or library entry the fields
  given replace that entry's (``name = "ISO_VG68"``, ``base_oil = "ester"``: the VG 68 as an ester);
- a **text** (``--lubricant "VG68 ester"``): words ``VG68``/``ISO VG 68``, a base oil, ``VI120``,
  ``NLGI2``, a thickener, a name, or ``field=value`` (``nu_40=68mm^2/s``) — turned into fields.

Values are SI numbers or text with a unit (parsed by :func:`bearingkit.units.parse`). Missing data
come from the base oil's typical values (``data/base_oils.csv``): ν100 from the type's typical VI, α
from its pressure–viscosity law, ρ15, k, c_p. Every error is one line naming the field and the value.
"""

from __future__ import annotations

import difflib
import functools
import re
from collections.abc import Mapping

from bearingkit import units
from bearingkit.errors import InputError, quote
from bearingkit.lubricants import base_oils
from bearingkit.lubricants.library import LIBRARY
from bearingkit.lubricants.model import (
    GREASE_LIFE_CLASSES,
    NLGI_CLASSES,
    THICKENERS,
    Grease,
    Lubricant,
)
from bearingkit.lubricants.presets import LUBRICANTS
from bearingkit.lubricants.viscosity_index import nu100_from_vi
from bearingkit.lubricants.walther import CST_TO_M2_PER_S

#: Field of a lubricant → its dimension (``text``: a name; ``dimensionless``: a number).
FIELDS: dict[str, str] = {
    "name": "text",
    "iso_vg": "dimensionless",
    "nu_40": "kinematic_viscosity",
    "nu_100": "kinematic_viscosity",
    "vi": "dimensionless",
    "base_oil": "text",
    "density": "density",
    "pressure_viscosity": "pressure_viscosity",
    "thermal_conductivity": "thermal_conductivity",
    "specific_heat": "specific_heat",
    "thickener": "text",
    "nlgi": "text",
    "life_class": "text",
    "temperature_min": "temperature",
    "temperature_max": "temperature",
    "source": "text",
}
#: ISO 3448 viscosity grades (mid-point ν40 in mm²/s).
ISO_VG_GRADES = (2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000, 1500, 2200, 3200)
_GREASE_FIELDS = ("thickener", "nlgi", "life_class", "temperature_min", "temperature_max")
_VISCOSITY_40 = ("iso_vg", "nu_40")
_VISCOSITY_100 = ("nu_100", "vi")
_EXPANSION = "thermal_expansion_per_K"


def lubricant_names() -> tuple[str, ...]:
    """Every name a lubricant may be given by: the presets, then the library."""
    return (*LUBRICANTS, *LIBRARY)


def _unknown_name(name, where: str) -> InputError:
    names = lubricant_names()
    near = difflib.get_close_matches(str(name), names, n=1, cutoff=0.6)
    hint = f"; did you mean {quote(near[0])}?" if near else ""
    return InputError(
        f"{where}.name ({quote(name)}) must be one of {', '.join(names)} — or give the oil's data "
        f"(nu_40 and nu_100, or iso_vg and vi){hint}"
    )


def _si(field: str, value, where: str):
    """One field's value in SI (numbers pass; text with a unit is parsed; names are checked as text)."""
    dim = FIELDS[field]
    name = f"{where}.{field}"
    if dim == "text":
        if field == "nlgi" and isinstance(value, int) and not isinstance(value, bool):
            value = str(value)
        if not isinstance(value, str) or not value.strip():
            raise InputError(f"{name} ({quote(value)}) must be a name (text)")
        return value.strip()
    if isinstance(value, bool):
        raise InputError(
            f"{name} ({value!r}) must be a number{'' if dim == 'dimensionless' else ' with a unit'}"
        )
    if isinstance(value, (int, float)) and dim != "dimensionless":
        x = float(value)  # already SI (a loaded file, a study's case table)
    else:
        x = units.parse(value, dim, name)
    if x != x or abs(x) == float("inf"):
        raise InputError(f"{name} ({quote(value)}) must be finite")
    if dim in (
        "kinematic_viscosity",
        "density",
        "pressure_viscosity",
        "thermal_conductivity",
        "specific_heat",
    ):
        if not x > 0:
            raise InputError(f"{name} ({quote(value)}) must be positive")
    return x


def _fields_of(lub: Lubricant) -> dict:
    """The fields of a preset (SI), with what only a preset carries under private keys."""
    out = {
        "base_oil": lub.base_oil,
        "density": lub.density_15C,
        "pressure_viscosity": lub.pressure_viscosity,
        "thermal_conductivity": lub.thermal_conductivity,
        "specific_heat": lub.specific_heat,
        "source": lub.source,
        "_exponent": lub.pressure_viscosity_exponent,
        "_expansion": lub.thermal_expansion,
    }
    if lub.is_constant_viscosity:
        out["_constant"] = lub.constant_viscosity
        out["_beta"] = lub.temperature_viscosity_coefficient
    else:
        out["nu_40"], out["nu_100"] = lub.kinematic_viscosity_40, lub.kinematic_viscosity_100
    if lub.grease is not None:
        g = lub.grease
        out.update(thickener=g.thickener, nlgi=g.nlgi, life_class=g.life_class)
        if g.temperature_min_C is not None:
            out["temperature_min"] = g.temperature_min_C
        if g.temperature_max_C is not None:
            out["temperature_max"] = g.temperature_max_C
    return out


@functools.cache
def named_lubricant(name: str) -> Lubricant:
    """The preset or library lubricant called ``name`` (InputError listing every name otherwise)."""
    if name in LUBRICANTS:
        return LUBRICANTS[name]
    if name in LIBRARY:
        return _build({"name": name, **LIBRARY[name]}, "lubricant", label=name)
    raise _unknown_name(name, "lubricant")


def lubricant_from_fields(fields: Mapping, where: str = "lubricant") -> Lubricant:
    """The :class:`Lubricant` of a table of fields (module docstring); one-line InputError otherwise.

    Parameters
    ----------
    fields : Mapping
        Field → value (:data:`FIELDS`); None values are ignored.
    where : str
        Prefix of the field names in messages (``"lubricant"``, ``"--lubricant"``, a file's name).
    """
    given = {k: v for k, v in dict(fields).items() if v is not None}
    for key in given:
        if key not in FIELDS:
            near = difflib.get_close_matches(key, FIELDS, n=1)
            hint = f"; did you mean {quote(near[0])}?" if near else ""
            raise InputError(f"{where}.{key}: unknown field; expected one of {', '.join(FIELDS)}{hint}")
    name = given.get("name")
    if name is not None and not isinstance(name, str):
        raise InputError(f"{where}.name ({quote(name)}) must be a name (text)")
    known = name is not None and name in lubricant_names()
    if known and set(given) <= {"name"}:
        return named_lubricant(name)
    if name is not None and not known and not any(k in given for k in _VISCOSITY_40):
        raise _unknown_name(name, where)
    return _build(given, where, label=None if known else name, base_name=name if known else None)


def _build(given: dict, where: str, label: str | None, base_name: str | None = None) -> Lubricant:
    si = {k: _si(k, v, where) for k, v in given.items()}
    base = {}
    if base_name is not None:
        entry = named_lubricant(base_name)
        base = _fields_of(entry)
        if any(k in si for k in _VISCOSITY_40):
            for k in (*_VISCOSITY_40, "_constant", "_beta"):
                base.pop(k, None)
        if any(k in si for k in _VISCOSITY_100):
            for k in _VISCOSITY_100:
                base.pop(k, None)
        if "base_oil" in si and base_oils.base_oil_key(si["base_oil"], f"{where}.base_oil") != entry.base_oil:
            for k in ("pressure_viscosity", "_exponent", "density", "_expansion", "thermal_conductivity"):
                base.pop(k, None)  # another base oil: its own α law and typical properties
            base.pop("specific_heat", None)
        if "pressure_viscosity" in si:
            base.pop("_exponent", None)
    merged = {**base, **si}
    oil = base_oils.base_oil_key(merged.get("base_oil", "mineral"), f"{where}.base_oil")
    typical = functools.partial(base_oils.base_oil_property, oil)
    density = merged.get("density", typical("density_15C_kg_m3"))
    expansion = merged.get("_expansion", typical(_EXPANSION))
    notes = []
    viscosity = _viscosities(merged, oil, where, notes)
    _, t = base_oils.pressure_viscosity_law(oil)
    if "pressure_viscosity" in merged:
        alpha40, exponent = merged["pressure_viscosity"], merged.get("_exponent", t)
    elif "_constant" in viscosity:
        alpha40, exponent = float(base_oils.pressure_viscosity(viscosity["_constant"], oil)), 0.0
    else:
        eta40 = viscosity["nu_40"] * density * (1.0 - expansion * (40.0 - 15.0))
        alpha40, exponent = float(base_oils.pressure_viscosity(eta40, oil)), t
    grease = _grease(merged, where)
    source = merged.get("source") or f"{where}: given by its data"
    if notes:
        source += "; " + "; ".join(notes)
    kw = dict(
        name=label or _label(oil, viscosity, grease, base_name, si),
        base_oil=oil,
        pressure_viscosity=alpha40,
        pressure_viscosity_exponent=exponent,
        density_15C=density,
        thermal_expansion=expansion,
        thermal_conductivity=merged.get("thermal_conductivity", typical("thermal_conductivity_W_mK")),
        specific_heat=merged.get("specific_heat", typical("specific_heat_J_kgK")),
        grease=grease,
        source=source,
    )
    if "_constant" in viscosity:
        kw.update(
            constant_viscosity=viscosity["_constant"], temperature_viscosity_coefficient=merged.get("_beta")
        )
    else:
        kw.update(kinematic_viscosity_40=viscosity["nu_40"], kinematic_viscosity_100=viscosity["nu_100"])
    try:
        return Lubricant(**kw)
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None


def _viscosities(merged: dict, oil: str, where: str, notes: list) -> dict:
    """ν40 and ν100 [m²/s] (or the constant η of a seed preset) from the viscosity fields."""
    if "_constant" in merged:
        return {"_constant": merged["_constant"]}
    if "iso_vg" in merged and "nu_40" in merged:
        raise InputError(f"{where}.iso_vg ({merged['iso_vg']:g}): give iso_vg or nu_40, not both")
    if "nu_100" in merged and "vi" in merged:
        raise InputError(f"{where}.vi ({merged['vi']:g}): give nu_100 or vi, not both")
    if "iso_vg" in merged:
        grade = merged["iso_vg"]
        if grade not in ISO_VG_GRADES:
            raise InputError(
                f"{where}.iso_vg ({grade:g}) must be an ISO 3448 grade: {', '.join(map(str, ISO_VG_GRADES))}"
            )
        nu40 = grade * CST_TO_M2_PER_S
    elif "nu_40" in merged:
        nu40 = merged["nu_40"]
    else:
        raise InputError(f"{where}: give the oil's viscosity: nu_40 and nu_100, or iso_vg (or nu_40) and vi")
    if "nu_100" in merged:
        nu100 = merged["nu_100"]
        if not nu100 < nu40:
            raise InputError(
                f"{where}.nu_100 ({nu100 / CST_TO_M2_PER_S:.4g} mm^2/s) must be below nu_40 "
                f"({nu40 / CST_TO_M2_PER_S:.4g} mm^2/s): an oil thins as it warms"
            )
    else:
        vi = merged.get("vi")
        if vi is None:
            vi = base_oils.base_oil_property(oil, "typical_vi")
            notes.append(f"nu_100 from the typical VI {vi:g} of {oil} oils (ASTM D2270)")
        try:
            nu100 = float(nu100_from_vi(nu40, vi))
        except InputError as exc:
            raise InputError(f"{where}.{exc}") from None
    return {"nu_40": nu40, "nu_100": nu100}


def _grease(merged: dict, where: str) -> Grease | None:
    if not any(k in merged for k in _GREASE_FIELDS):
        return None
    if "thickener" not in merged:
        raise InputError(
            f"{where}.thickener: missing; a grease needs its thickener ({', '.join(THICKENERS)})"
        )
    for field, choices in (
        ("thickener", THICKENERS),
        ("nlgi", NLGI_CLASSES),
        ("life_class", GREASE_LIFE_CLASSES),
    ):
        if field in merged and merged[field] not in choices:
            near = difflib.get_close_matches(str(merged[field]), choices, n=1)
            hint = f"; did you mean {quote(near[0])}?" if near else ""
            raise InputError(
                f"{where}.{field} ({quote(merged[field])}) must be one of {', '.join(choices)}{hint}"
            )
    try:
        return Grease(
            thickener=merged["thickener"],
            nlgi=merged.get("nlgi", "2"),
            life_class=merged.get("life_class", "general_purpose"),
            temperature_min_C=merged.get("temperature_min"),
            temperature_max_C=merged.get("temperature_max"),
        )
    except InputError as exc:
        raise InputError(f"{where}.{exc}") from None


def _label(oil: str, viscosity: dict, grease, base_name, si: dict) -> str:
    """A readable name for a lubricant given by its data."""
    if base_name is not None:
        changed = ", ".join(
            f"{k}={v:g}" if isinstance(v, float) else f"{k}={v}" for k, v in si.items() if k != "name"
        )
        return f"{base_name} ({changed})"
    if "_constant" in viscosity:
        return f"{oil} oil"
    kind = f"{grease.thickener} grease, {oil} base oil" if grease is not None else f"{oil} oil"
    return (
        f"{kind} nu40 {viscosity['nu_40'] / CST_TO_M2_PER_S:.4g} / nu100 "
        f"{viscosity['nu_100'] / CST_TO_M2_PER_S:.4g} mm^2/s"
    )


# --- the text form ---------------------------------------------------------------------------------
_VG = re.compile(r"^(?:iso_?)?vg_?(\d+)$", re.IGNORECASE)
_VI = re.compile(r"^vi_?([0-9]+(?:\.[0-9]*)?)$", re.IGNORECASE)
_NLGI = re.compile(r"^nlgi_?(\d{1,3})$", re.IGNORECASE)


def fields_from_text(text: str, where: str = "--lubricant") -> dict:
    """The fields of a text form (``"VG68 ester"``, ``"nu_40=68mm^2/s nu_100=8.7mm^2/s pao"``)."""
    if not isinstance(text, str) or not text.strip():
        raise InputError(f"{where} ({quote(text)}) must name a lubricant or give its data, e.g. 'VG68 ester'")
    clean = re.sub(r"(?i)\biso[\s_]*vg[\s_]*(\d+)", r"VG\1", text.strip())
    clean = re.sub(r"(?i)\bvg\s+(\d+)", r"VG\1", clean)
    clean = re.sub(r"(?i)\b(vi|nlgi)\s*[= ]\s*([0-9])", r"\1\2", clean)
    out: dict = {}
    for token in (t for t in re.split(r"[\s,;]+", clean) if t):
        key, sep, value = token.partition("=")
        if sep:
            out[key.strip()] = value.strip()
        elif token in lubricant_names():
            out["name"] = token
        elif (m := _VG.match(token)) is not None:
            out["iso_vg"] = float(m.group(1))
        elif (m := _VI.match(token)) is not None:
            out["vi"] = float(m.group(1))
        elif (m := _NLGI.match(token)) is not None:
            out["nlgi"] = m.group(1)
        elif token.lower() in THICKENERS:
            out["thickener"] = token.lower()
        else:
            try:
                out["base_oil"] = base_oils.base_oil_key(token)
            except InputError:
                words = [*base_oils.BASE_OILS, *lubricant_names(), *THICKENERS]
                near = difflib.get_close_matches(token, words, n=1)
                hint = f"; did you mean {quote(near[0])}?" if near else ""
                raise InputError(
                    f"{where} ({quote(text)}): unknown word {quote(token)}; expected a lubricant name, "
                    f"VG<grade>, a base oil ({', '.join(base_oils.BASE_OILS)}), VI<number>, NLGI<class>, "
                    f"a thickener or field=value such as nu_40=68mm^2/s{hint}"
                ) from None
    # "VG68" alone is the preset of that grade (the same oil as ISO_VG68)
    if set(out) == {"iso_vg"} and f"ISO_VG{out['iso_vg']:g}" in LUBRICANTS:
        return {"name": f"ISO_VG{out['iso_vg']:g}"}
    return out


def as_lubricant(value, where: str = "lubricant") -> Lubricant:
    """A :class:`Lubricant` from any form: itself, a name, a table of fields or a text form."""
    if isinstance(value, Lubricant):
        return value
    if isinstance(value, str):
        if value.strip() in lubricant_names():
            return named_lubricant(value.strip())
        fields = fields_from_text(value, where)
        if "name" not in fields and any(k in fields for k in _VISCOSITY_40):
            fields["name"] = " ".join(value.split())  # the text itself labels the oil
        return lubricant_from_fields(fields, where)
    if isinstance(value, Mapping):
        return lubricant_from_fields(value, where)
    raise InputError(
        f"{where} ({value!r}) must be a Lubricant, a name ({', '.join(lubricant_names())}), a table of "
        "fields or a text such as 'VG68 ester'"
    )
