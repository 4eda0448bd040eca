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
from bearingkit.catalogue.iso_ratings import ratings
from bearingkit.catalogue.resolve import Resolved, resolve
from bearingkit.catalogue.tables import FAMILIES, Entry, all_entries, entries


def find(pattern: str = "*") -> list[Entry]:
    """Catalogue rows whose base designation matches the shell pattern ``pattern`` (``"62*"``), any case."""
    pat = pattern.upper().replace(" ", "")
    return [e for e in all_entries() if fnmatch.fnmatchcase(e.designation.upper(), pat)]


__all__ = [
    "CLASSES",
    "FAMILIES",
    "RULES",
    "Designation",
    "Entry",
    "Estimate",
    "Resolved",
    "all_entries",
    "clearance",
    "clearance_range",
    "entries",
    "estimate",
    "fill_angle",
    "find",
    "nearest",
    "parse",
    "ratings",
    "resolve",
]
