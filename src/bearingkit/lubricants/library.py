"""The library of typical lubricants (``bearingkit/data/lubricant_library.csv``), as field tables.

Each row is a set of ``[lubricant]`` fields (the form of :mod:`bearingkit.lubricants.forms`) with its
source and tag: ``T`` a typical oil of its class (ISO 3448 grade, the class's typical VI), ``M`` a named
product's data sheet quoted from memory. The rows are built into :class:`~bearingkit.lubricants.Lubricant`
objects on first use by :func:`bearingkit.lubricants.forms.named_lubricant`.
"""

from __future__ import annotations

from bearingkit.lubricants.tables import rows

_TABLE = "lubricant_library.csv"
#: CSV column → ``[lubricant]`` field (values in the CSV's units, as text with the unit).
_COLUMNS = {
    "base_oil": ("base_oil", ""),
    "iso_vg": ("iso_vg", None),
    "nu_40_mm2_s": ("nu_40", "mm^2/s"),
    "nu_100_mm2_s": ("nu_100", "mm^2/s"),
    "thickener": ("thickener", ""),
    "nlgi": ("nlgi", ""),
    "life_class": ("life_class", ""),
    "temperature_min_C": ("temperature_min", "degC"),
    "temperature_max_C": ("temperature_max", "degC"),
}


def _fields(row: dict) -> dict:
    out = {}
    for column, (field, unit) in _COLUMNS.items():
        cell = row.get(column, "")
        if not cell:
            continue
        if unit is None:
            out[field] = float(cell)
        elif unit:
            out[field] = f"{cell} {unit}"
        else:
            out[field] = cell
    out["source"] = f"bearingkit library [{row['tag']}]: {row['source']}"
    return out


#: Library name → its ``[lubricant]`` fields (with ``source``).
LIBRARY: dict[str, dict] = {r["name"]: _fields(r) for r in rows(_TABLE)}
#: Library name → tag (T typical class, M data sheet from memory).
LIBRARY_TAGS: dict[str, str] = {r["name"]: r["tag"] for r in rows(_TABLE)}
