"""Standard bearings by designation: ISO boundary dimensions, estimated internal geometry, clearances.

Layer: beside :mod:`bearingkit.io` (it imports physics only; the input loader imports it). SI units.

>>> from bearingkit.catalogue import resolve
>>> r = resolve("6205-2RS C3")
>>> r.bearing_type, r.geometry["n_elements"]                  # doctest: +SKIP
('deep_groove_ball', 8)

See docs/catalogue.md for the sources, the estimation rules and their accuracy.
"""

from __future__ import annotations

import fnmatch

from bearingkit.catalogue.clearances import CLASSES, clearance, clearance_range
from bearingkit.catalogue.designation import Designation, nearest, parse
from bearingkit.catalogue.internal import RULES, Estimate, estimate, fill_angle
from bearingkit.catalogue.iso_ratings import basis, four_point_radial, ratings
from bearingkit.catalogue.resolve import Resolved, resolve
from bearingkit.catalogue.tables import FAMILIES, Entry, all_entries, entries


def find(pattern: str = "*") -> list[Entry]:
    """Catalogue rows whose base designation matches the shell pattern ``pattern`` (``"62*"``), any case.

    A pattern that names a dimension series followed by ``*`` lists that series only: ``"222*"`` gives the
    spherical roller bearings 222xx, not the self-aligning 2220 and 2222 that the glob also matches;
    ``"NA49*"`` the needle bearings with inner ring, ``"RNA49*"`` those without.
    """
    pat = pattern.upper().replace(" ", "")
    rows = [e for e in all_entries() if fnmatch.fnmatchcase(e.designation.upper(), pat)]
    head = pat[:-1] if pat.endswith("*") else None
    if head and any(e.series.upper() == head for e in rows):
        rows = [e for e in rows if e.series.upper() == head]
    return rows


__all__ = [
    "CLASSES",
    "FAMILIES",
    "RULES",
    "Designation",
    "Entry",
    "Estimate",
    "Resolved",
    "all_entries",
    "basis",
    "clearance",
    "clearance_range",
    "entries",
    "estimate",
    "fill_angle",
    "find",
    "four_point_radial",
    "nearest",
    "parse",
    "ratings",
    "resolve",
]
