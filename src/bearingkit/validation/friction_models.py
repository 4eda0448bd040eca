"""Validation cases of the engineering friction models (SKF four-component, Palmgren). SI values (N·m).

No SKF worked example of the four-component model with its inputs and result could be retrieved with
the search tool (the catalogue pages holding it were not reachable), and Harris & Kotzalas' Palmgren
example is not in the searchable corpus. The published numbers used here are therefore the SKF
catalogue's own **constant-coefficient estimate** (SKF 2012/2018, "Estimating the frictional moment",
Table 1, verified in the catalogue text): M = 0.5 μ P d with μ = 0.0015 (deep groove ball bearings),
0.0011 (cylindrical roller bearings with a cage, F_a ≈ 0), valid for P ≈ 0.1 C, good lubrication and
normal operating conditions. Each case runs the detailed model at such a point — P = 0.1 C, oil jet /
low-level oil bath, mineral oil with ν = 20 mm²/s (κ ≈ 1.3 at 1500 r/min for d_m = 60 mm) — and the
tolerance (30 %) reflects that the constant-μ estimate is itself only an approximation of the detailed
model over "normal" conditions. C and C0 are SKF product-table values quoted from memory ([M]); a
10 % error in them moves P, and the compared torques nearly proportionally, so they do not decide the
cases.
"""

from __future__ import annotations

import numpy as np

from bearingkit.physics.friction.palmgren import palmgren_friction_moment
from bearingkit.physics.friction.skf import skf_friction_moment
from bearingkit.validation.registry import Case, register

_RPM = 2.0 * np.pi / 60.0
#: Operating point of the Table-1 comparisons: mineral oil ν = 20 mm²/s.
NU = 20.0e-6  # [m²/s]
#: SKF Table 1 constant coefficients of friction (verified in the catalogue text).
MU_TABLE1 = {"deep_groove_ball": 0.0015, "cylindrical_roller": 0.0011}
TOLERANCE = 0.30
_SRC = (
    "SKF Group (2012/2018) Rolling bearings 10000 EN / 17000 EN, 'Estimating the frictional moment', "
    "Table 1 (constant mu for P ~ 0.1 C): M = 0.5 mu P d; C from SKF product tables [M]"
)

#: (id label, bearing_type, series, d [m], D [m], C [N], C0 [N], speed [r/min]).
BEARINGS = (
    ("6208", "deep_groove_ball", "62", 0.040, 0.080, 32_500.0, 19_000.0, 1500.0),
    ("6006", "deep_groove_ball", "60", 0.030, 0.055, 13_800.0, 8_300.0, 3000.0),
    ("NU208ECP", "cylindrical_roller", "2", 0.040, 0.080, 62_000.0, 53_000.0, 1500.0),
)


def _published(btype, d, c):
    return 0.5 * MU_TABLE1[btype] * 0.1 * c * d


def _skf(btype, series, d, big_d, c, rpm):
    def compute():
        r = skf_friction_moment(
            btype,
            bore_diameter=d,
            outside_diameter=big_d,
            speed=rpm * _RPM,
            kinematic_viscosity=NU,
            load_radial=0.1 * c,
            series=series,
            lubrication="oil_jet",
        )
        return float(r["total_Nm"])

    return compute


def _palmgren(btype, d, big_d, c, c0, rpm):
    def compute():
        r = palmgren_friction_moment(
            btype,
            pitch_diameter=0.5 * (d + big_d),
            speed=rpm * _RPM,
            kinematic_viscosity=NU,
            load_radial=0.1 * c,
            lubrication="oil_bath",
            static_rating=c0,
        )
        return float(r["total_Nm"])

    return compute


for _label, _btype, _series, _d, _D, _C, _C0, _rpm in BEARINGS:
    register(
        Case(
            id=f"skf/table1_estimate/{_label}/M_total",
            source=_SRC,
            quantity=f"frictional moment of {_label} at P = 0.1 C, {_rpm:g} r/min, nu = 20 mm^2/s "
            "(SKF four-component model vs the catalogue's constant-mu estimate)",
            unit="N*m",
            published=_published(_btype, _d, _C),
            compute=_skf(_btype, _series, _d, _D, _C, _rpm),
            tolerance=TOLERANCE,
        )
    )

_LABEL, _BTYPE, _, _D_IN, _D_OUT, _C_6208, _C0_6208, _RPM_6208 = BEARINGS[0]
register(
    Case(
        id=f"palmgren/table1_estimate/{_LABEL}/M_total",
        source=_SRC + "; Palmgren f0 (oil bath) and f1 tables [M]",
        quantity="friction torque of 6208 at P = 0.1 C, 1500 r/min, nu = 20 mm^2/s (Palmgren M0 + M1 vs "
        "the SKF constant-mu estimate; not a Palmgren worked example)",
        unit="N*m",
        published=_published(_BTYPE, _D_IN, _C_6208),
        compute=_palmgren(_BTYPE, _D_IN, _D_OUT, _C_6208, _C0_6208, _RPM_6208),
        tolerance=TOLERANCE,
    )
)
