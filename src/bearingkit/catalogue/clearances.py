"""ISO 5753-1 radial internal clearance groups C2, CN, C3, C4, C5. SI units (m).

The groups by bore range are the ISO 5753-1 values as reproduced in NSK E1102 Tables 9.9, 9.12, 9.14
and 9.15 (``data/radial_clearance.csv``): deep groove ball, self-aligning ball, cylindrical roller
(interchangeable rings; NSK E1102 B245 applies the same table to needle roller bearings with inner ring)
and spherical roller bearings with cylindrical bore; the tapered-bore groups of self-aligning ball and
spherical roller bearings as SKF General Catalogue 6000 (2006) pp. 477 and 706 print them (SKF: "ISO
5753"; its cylindrical-bore rows agree with NSK's), and above 225 mm the spherical roller tapered-bore
groups of NSK E1102 Table 9.15 (its rows to 225 mm equal SKF's). Four-point contact (QJ) bearings are
classed by their axial clearance (SKF General Catalogue 6000, 2006, p. 453 Table 1; group
``four_point_contact_ball_axial``, :data:`AXIAL_GROUPS`). The engine counts a radial
clearance twice (``clearance_radial`` = the diametral clearance P_d, each element sees P_d/2), which is
what these tables give (the total radial play of one ring against the other).
"""

from __future__ import annotations

from bearingkit.catalogue.tables import clearance_rows
from bearingkit.errors import InputError

#: Clearance classes, smallest to largest.
CLASSES = ("C2", "CN", "C3", "C4", "C5")
#: Family → element group of the clearance table (families not listed have no radial clearance class:
#: angular contact and tapered rows are set on mounting, thrust rows are axial).
CLEARANCE_GROUP = {
    "deep_groove_ball": "deep_groove_ball",
    "self_aligning_ball": "self_aligning_ball",
    "cylindrical_roller": "cylindrical_roller",
    "double_row_cylindrical_roller": "cylindrical_roller",
    "spherical_roller": "spherical_roller",
    "needle_roller": "cylindrical_roller",
    "four_point_contact_ball": "four_point_contact_ball_axial",
}
#: Groups whose classes are axial clearances (the resolver converts them to the row's P_d).
AXIAL_GROUPS = ("four_point_contact_ball_axial",)
#: Family → group of its tapered-bore variant (suffix K, K30): the unmounted clearance, larger than the
#: cylindrical bore's (the drive-up on the taper takes part of it).
TAPERED_BORE_GROUP = {
    "self_aligning_ball": "self_aligning_ball_tapered_bore",
    "spherical_roller": "spherical_roller_tapered_bore",
}
#: Where each group's numbers come from (short, for notes).
GROUP_SOURCES = {
    "deep_groove_ball": "ISO 5753-1",
    "self_aligning_ball": "ISO 5753-1",
    "cylindrical_roller": "ISO 5753-1",
    "spherical_roller": "ISO 5753-1",
    "four_point_contact_ball_axial": "SKF 6000 p. 453",
    "self_aligning_ball_tapered_bore": "tapered bore, SKF 6000 p. 477",
    "spherical_roller_tapered_bore": "tapered bore, SKF 6000 p. 706 to 225 mm, NSK E1102 Table 9.15 above",
}


def clearance_range(group: str, bore: float, cls: str = "CN") -> tuple[float, float]:
    """(min, max) radial internal clearance [m] of class ``cls`` for ``bore`` [m].

    Parameters
    ----------
    group : str
        ``"deep_groove_ball"``, ``"self_aligning_ball"``, ``"cylindrical_roller"`` or ``"spherical_roller"``.
    bore : float [m]
        Bearing bore d; the row with over < d ≤ incl applies (the first deep groove row: d = 10 mm).
    cls : str
        One of :data:`CLASSES`.
    """
    if cls not in CLASSES:
        raise InputError(f"clearance class ({cls!r}) must be one of {', '.join(CLASSES)}")
    rows = [r for r in clearance_rows() if r.element == group]
    if not rows:
        raise InputError(
            f"clearance group ({group!r}) must be one of "
            f"{', '.join(sorted({r.element for r in clearance_rows()}))}"
        )
    d_mm = bore * 1e3
    for r in rows:
        lo, hi = r.bore_over * 1e3, r.bore_incl * 1e3
        if lo - 1e-9 <= d_mm <= hi + 1e-9 and (d_mm > lo + 1e-9 or lo == 0.0 or r is rows[0]):
            if cls not in r.groups:
                raise InputError(
                    f"clearance class {cls} is not defined for {group.replace('_', ' ')} "
                    f"with bore {d_mm:g} mm; classes there: {', '.join(r.groups)}"
                )
            return r.groups[cls]
    raise InputError(
        f"bore ({d_mm:g} mm) lies outside the {group} clearance table "
        f"({rows[0].bore_over * 1e3:g}–{rows[-1].bore_incl * 1e3:g} mm)"
    )


def clearance(group: str, bore: float, cls: str = "CN", position: float = 0.5) -> float:
    """Radial internal clearance [m] at ``position`` in the class range (0 = min, 0.5 = mean, 1 = max)."""
    if not 0.0 <= position <= 1.0:
        raise InputError(
            f"clearance position ({position!r}) must lie in [0, 1] (0 = min, 0.5 = mean, 1 = max)"
        )
    lo, hi = clearance_range(group, bore, cls)
    return lo + position * (hi - lo)
