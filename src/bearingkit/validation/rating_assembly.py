"""Internal-consistency cases of the rating assembly (solver + ISO/TS 16281 + ISO 281). SI values.

- ``iso16281/consistency/thrust-ball-equal-loads``: a single-direction thrust ball bearing (α = 90°) under
  a centric axial load has equal ball loads F_a/Z, and ISO/TS 16281 then reduces exactly to ISO 281
  L10 = (C_a/F_a)³ (the conformity term cancels between the two washers). The "published" value is that
  closed form; the tolerance covers only the solver's equilibrium tolerance (1e-10 relative).
- ``iso16281/consistency/deep-groove-radial-zero-clearance``: the 6205 of the CWRU data set (Dw 0.3126 in,
  Dpw 1.537 in, Z = 9, conformities 0.52/0.53) solved under F_r = 2 kN at zero clearance; ISO/TS 16281's
  constants 0.407/0.389 are the continuous Stribeck integrals, so L10r = (C/F_r)³ up to the discreteness
  of Z = 9 balls (−1.2 % with a ball on the load line, +0.9 % between balls): tolerance 1.5 %.
"""

from __future__ import annotations

import numpy as np

from bearingkit.physics.life import iso281
from bearingkit.validation.registry import Case, register

INCH = 25.4e-3
_THRUST = dict(n_elements=15, element_diameter=0.008, pitch_diameter=0.060)
_FA = 5000.0
_DGBB = dict(n_elements=9, element_diameter=0.3126 * INCH, pitch_diameter=1.537 * INCH)
_FR = 2000.0


def _thrust_rating() -> float:
    t = _THRUST
    return float(
        iso281.dynamic_rating_ball(
            t["element_diameter"], t["pitch_diameter"], np.pi / 2, t["n_elements"], bearing_type="thrust_ball"
        )
    )


def _dgbb_rating() -> float:
    d = _DGBB
    return float(iso281.dynamic_rating_ball(d["element_diameter"], d["pitch_diameter"], 0.0, d["n_elements"]))


def _thrust_life() -> float:
    from bearingkit.analysis.rating.assembly import rate
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.bearings.standard import thrust_ball

    res = solve(thrust_ball(**_THRUST), load_vector(F_z=_FA))
    return float(rate(res).life[0]) / 1e6


def _dgbb_life() -> float:
    from bearingkit.analysis.rating.assembly import rate
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.bearings.standard import deep_groove_ball

    res = solve(deep_groove_ball(**_DGBB), load_vector(F_x=_FR), free=[True, True, False, False, False])
    return float(rate(res).life[0]) / 1e6


register(
    Case(
        id="iso16281/consistency/thrust-ball-equal-loads",
        source="ISO 281:2007 eq. (8) L10 = (C_a/P)^3 with P = F_a (α = 90°), identity of ISO/TS 16281:2008 "
        "eq. (25)-(29) for equal ball loads",
        quantity="basic reference rating life L10r, thrust ball 15 × Ø8 mm on Ø60 mm, F_a = 5 kN",
        unit="1e6 rev",
        published=(_thrust_rating() / _FA) ** 3,
        compute=_thrust_life,
        tolerance=1e-8,
    )
)

register(
    Case(
        id="iso16281/consistency/deep-groove-radial-zero-clearance",
        source="ISO 281:2007 eq. (8) L10 = (C/F_r)^3, which ISO/TS 16281:2008 reproduces for zero clearance "
        "and pure radial load (Stribeck distribution); 6205 geometry of the CWRU Bearing Data Center",
        quantity="basic reference rating life L10r from the solved distribution, F_r = 2 kN, zero clearance",
        unit="1e6 rev",
        published=(_dgbb_rating() / _FR) ** 3,
        compute=_dgbb_life,
        # Z = 9 discrete balls: -1.2 % (ball on the load line, the case here) to +0.9 %
        tolerance=0.015,
    )
)
