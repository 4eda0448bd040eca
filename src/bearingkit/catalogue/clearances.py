"""ISO 5753-1 radial internal clearance groups C2, CN, C3, C4, C5. SI units (m).

The groups by bore range are the ISO 5753-1 values as reproduced in NSK E1102 Tables 9.9, 9.12, 9.14
and 9.15 (``data/radial_clearance.csv``): deep groove ball, self-aligning ball, cylindrical roller
(interchangeable rings) and spherical roller bearings with cylindrical bore. The engine counts a radial
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
    "spherical_roller": "spherical_roller",
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
                raise InputError(f"clearance class {cls} is not defined for {group} with bore {d_mm:g} mm")
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
