"""Validation cases for fits: ISO 286 limit deviations and ISO 492 ring tolerances. SI values (m).

The published limit deviations are the tabulated values of ISO 286-2 (shaft k5 and m6 at 30–50 mm,
housing H7 at 80–120 mm) as public transcriptions of the standard give them (K, M, N, P holes need the
Δ table, which is from memory: no case here), and the ISO 492
Normal-class bore and outside-diameter deviations as the NTN handbook (table 5.1, class 0) and public
Normal-class tables give them (found with the search tool). Tabulated integers in µm: exact.
"""

from __future__ import annotations

from bearingkit.physics.structure import tolerances
from bearingkit.validation.registry import Case, register

UM = 1e-6
_ISO286 = "ISO 286-2:2010 limit deviations (public transcriptions of ISO 286-1/-2 tables)"
_ISO492 = "ISO 492:2014 Normal class; NTN Ball and roller bearings handbook, table 5.1 (class 0)"

for code, size, which, value in (
    ("k5", 0.045, "upper", 13),
    ("k5", 0.045, "lower", 2),
    ("m6", 0.045, "upper", 25),
    ("H7", 0.085, "upper", 35),
):
    register(
        Case(
            id=f"iso286/{code}/{size * 1e3:g}mm/{which}",
            source=_ISO286,
            quantity=f"{which} deviation of {code} at {size * 1e3:g} mm",
            unit="m",
            published=value * UM,
            compute=lambda code=code, size=size, which=which: tolerances.tolerance_field(code, size)[
                0 if which == "upper" else 1
            ],
            tolerance=1e-9,
        )
    )

for ring, size, value in (("inner", 0.045, -12), ("outer", 0.085, -15), ("inner", 0.1, -20)):
    register(
        Case(
            id=f"iso492/normal/{ring}/{size * 1e3:g}mm",
            source=_ISO492,
            quantity=f"lower deviation of the {ring} ring ({'bore' if ring == 'inner' else 'outside'})",
            unit="m",
            published=value * UM,
            compute=lambda ring=ring, size=size: tolerances.ring_deviation(ring, size)[1],
            tolerance=1e-9,
        )
    )
