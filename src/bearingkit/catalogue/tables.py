"""Catalogue data files: ISO boundary dimensions and published load ratings per family. SI units out.

The CSV files in ``data/`` hold millimetres and newtons as printed in the source (one ``source`` column per
row, see ``data/SOURCES.md``); :func:`entries` converts them to SI (m, N) once and caches the result.
A *family* is one bearing type of one data file (deep groove ball, tapered roller, …); its rows are
:class:`Entry` objects keyed by the base designation (``"6205"``, ``"7206B"``, ``"NU206E"``).
"""

from __future__ import annotations

import csv
import functools
import io
from dataclasses import dataclass, field
from importlib import resources

MM = 1e-3

#: Family → (data file, bearing type of the input format, element kind). The bearing type is the
#: ``[bearing] type`` the estimated geometry is written for (``io.kinds`` for four-point, self-aligning
#: ball, spherical roller and needle roller bearings).
FAMILIES: dict[str, tuple[str, str | None, str]] = {
    "deep_groove_ball": ("deep_groove_ball.csv", "deep_groove_ball", "ball"),
    "angular_contact_ball": ("angular_contact_ball.csv", "angular_contact_ball", "ball"),
    "double_row_angular_contact_ball": (
        "double_row_angular_contact_ball.csv",
        "angular_contact_pair",
        "ball",
    ),
    "four_point_contact_ball": ("four_point_contact_ball.csv", "four_point_contact_ball", "ball"),
    "self_aligning_ball": ("self_aligning_ball.csv", "self_aligning_ball", "ball"),
    "cylindrical_roller": ("cylindrical_roller.csv", "cylindrical_roller", "roller"),
    "double_row_cylindrical_roller": ("double_row_cylindrical_roller.csv", "cylindrical_roller", "roller"),
    "tapered_roller": ("tapered_roller.csv", "tapered_roller", "roller"),
    "thrust_ball": ("thrust_ball.csv", "thrust_ball", "ball"),
    "thrust_cylindrical_roller": ("thrust_cylindrical_roller.csv", "cylindrical_roller_thrust", "roller"),
    "spherical_roller": ("spherical_roller.csv", "spherical_roller", "roller"),
    "spherical_roller_thrust": ("spherical_roller_thrust.csv", "spherical_roller_thrust", "roller"),
    "needle_roller": ("needle_roller.csv", "needle_roller", "roller"),
}
#: Prefix of the needle roller bearings without inner ring (RNA): each NA row of the data file has an RNA
#: twin with bore F_w (the shaft is the inner raceway) and the same ratings (NSK E1102 prints one).
NO_INNER_RING_PREFIX = "R"

#: CSV column (mm or N) → Entry attribute (SI). Other columns go to ``Entry.extra`` as text.
_LENGTHS = {"d_mm": "bore", "D_mm": "outer_diameter", "r_min_mm": "chamfer"}
_WIDTHS = ("B_mm", "T_mm")
_RATINGS = {"C_N": "C", "Ca_N": "C", "C0_N": "C0", "C0a_N": "C0"}


@dataclass(frozen=True)
class Entry:
    """One catalogue row in SI.

    Attributes
    ----------
    designation : str
        Base designation (no seal, clearance or cage suffixes), e.g. ``"6205"``, ``"7206B"``.
    family : str
        Key of :data:`FAMILIES`.
    series : str
        Dimension series as printed in the designation (``"62"``, ``"302"``, ``"QJ2"`` …).
    bore, outer_diameter, width : float [m]
        d, D and B (radial) or T (tapered: overall width T; thrust: height T).
    chamfer : float [m]
        Smallest chamfer r_s min of the rings.
    C, C0 : float or None [N]
        Published basic dynamic and static load rating (radial; axial for thrust and four-point
        bearings); None where the source has none.
    source : str
        Where the row comes from (``data/SOURCES.md``).
    extra : dict
        Further columns as printed (text): contact angle, cone/cup widths, e, F_w, D_w, rating direction.
    """

    designation: str
    family: str
    series: str
    bore: float
    outer_diameter: float
    width: float
    chamfer: float
    C: float | None
    C0: float | None
    source: str
    extra: dict = field(default_factory=dict)

    def number(self, key: str, scale: float = 1.0) -> float | None:
        """An ``extra`` column as a float times ``scale`` (None when empty or absent)."""
        text = self.extra.get(key, "")
        return float(text) * scale if text not in ("", None) else None


def _read(name: str) -> list[dict]:
    text = resources.files("bearingkit.catalogue").joinpath("data", name).read_text(encoding="utf-8")
    return list(csv.DictReader(io.StringIO(text)))


@functools.cache
def entries(family: str) -> dict[str, Entry]:
    """All rows of ``family`` keyed by base designation (SI values)."""
    path = FAMILIES[family][0]
    out: dict[str, Entry] = {}
    for row in _read(path):
        width_key = next(k for k in _WIDTHS if k in row)
        kw = {attr: float(row[col]) * MM for col, attr in _LENGTHS.items()}
        ratings = {
            attr: float(row[col]) if row[col] else None for col, attr in _RATINGS.items() if col in row
        }
        known = {"designation", "series", "source", width_key, *_LENGTHS, *_RATINGS}
        extra = {k: v for k, v in row.items() if k not in known}
        out[row["designation"]] = Entry(
            designation=row["designation"],
            family=family,
            series=row["series"],
            width=float(row[width_key]) * MM,
            C=ratings.get("C"),
            C0=ratings.get("C0"),
            source=row["source"],
            extra=extra,
            **kw,
        )
    if family == "needle_roller":
        out.update({e.designation: e for e in map(_without_inner_ring, list(out.values()))})
    return out


def _without_inner_ring(e: Entry) -> Entry:
    """The RNA twin of an NA row: bore = roller inscribed diameter F_w, the same outer ring and ratings."""
    return Entry(
        designation=NO_INNER_RING_PREFIX + e.designation,
        family=e.family,
        series=NO_INNER_RING_PREFIX + e.series,
        bore=e.number("F_w_mm", MM),
        outer_diameter=e.outer_diameter,
        width=e.width,
        chamfer=e.chamfer,
        C=e.C,
        C0=e.C0,
        source=f"{e.source}; without inner ring: d = F_w",
        extra={**e.extra, "inner_ring": "no"},
    )


@functools.cache
def reference_table(name: str) -> tuple[dict, ...]:
    """Rows (text) of a table ``data/<name>.csv`` that is not a bearing table: data of other catalogues
    or of related products kept to check the estimate, and NSK's preloads of duplex sets
    (:mod:`.pairs`) (``data/SOURCES.md``)."""
    return tuple(_read(f"{name}.csv"))


def reference_ratings(name: str) -> dict[str, tuple[float, float, str]]:
    """A comparison table with ``Cr_N``, ``C0r_N`` columns: designation → (C, C0, source) [N].

    ``four_point_radial_skf``: SKF's radial C, C0 of QJ bearings; ``spherical_roller_skf``: SKF's E design.
    """
    return {
        r["designation"]: (float(r["Cr_N"]), float(r["C0r_N"]), r["source"]) for r in reference_table(name)
    }


def all_entries() -> list[Entry]:
    """Every catalogue row of every family, in file order."""
    return [e for fam in FAMILIES for e in entries(fam).values()]


@dataclass(frozen=True)
class ClearanceRow:
    """ISO 5753-1 radial internal clearance groups of one bore range [m]."""

    element: str
    bore_over: float
    bore_incl: float
    groups: dict  # class name → (min, max) [m]
    source: str


@functools.cache
def clearance_rows() -> tuple[ClearanceRow, ...]:
    """Rows of ``radial_clearance.csv`` in SI (µm → m)."""
    rows = []
    for row in _read("radial_clearance.csv"):
        groups = {}
        for cls in ("C2", "CN", "C3", "C4", "C5"):
            lo, hi = row[f"{cls}_min_um"], row[f"{cls}_max_um"]
            if lo and hi:
                groups[cls] = (float(lo) * 1e-6, float(hi) * 1e-6)
        rows.append(
            ClearanceRow(
                element=row["element"],
                bore_over=float(row["bore_over_mm"]) * MM,
                bore_incl=float(row["bore_incl_mm"]) * MM,
                groups=groups,
                source=row["source"],
            )
        )
    return tuple(rows)
