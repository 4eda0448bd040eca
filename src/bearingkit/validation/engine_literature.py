"""Closed-form load-distribution checks of the quasi-static engine (issue: quasi-static engine).

Coordinate mapping: Stribeck/Harris write the element approach δ_ψ = δ_a sin α + δ_r cos α cos ψ for
a ring displacement (δ_r along ψ = 0, δ_a axial). In bearingkit δ_r = u_x, δ_a = u_z, ψ from +x;
all other DOFs fixed at 0. The integrals J_r, J_a assume a continuum of elements and a contact
angle that does not change with load, so the rows here have many small balls (Z = 180) in deep
grooves (f = 0.6, groove-centre distance 0.2·D_w ≫ δ): the operating angle then moves by < 1e-3 rad.
"""

from __future__ import annotations

import numpy as np

from bearingkit.validation.registry import Case, register

HARRIS = "Harris & Kotzalas (2007) Rolling Bearing Analysis 5th ed., Table 7.4 (point contact, single row)"
STRIBECK = (
    "Stribeck (1901); Harris & Kotzalas (2007) §7.2: Q_max = 4.37 F_r/(Z cos α) ball, 4.08 line (J_r(0.5))"
)

#: Harris Table 7.4: ε → (F_r tan α / F_a, J_r, J_a); the (0.5, 0.2288, 0.2782) row is Stribeck's.
HARRIS_TABLE_7_4 = {
    0.2: (0.9318, 0.1590, 0.1707),
    0.3: (0.8964, 0.1892, 0.2110),
    0.4: (0.8601, 0.2117, 0.2462),
    0.5: (0.8225, 0.2288, 0.2782),
    0.6: (0.7835, 0.2416, 0.3084),
    0.7: (0.7427, 0.2505, 0.3374),
    0.8: (0.6995, 0.2559, 0.3658),
    0.9: (0.6529, 0.2576, 0.3945),
    1.0: (0.6000, 0.2546, 0.4244),
    1.25: (0.4338, 0.2289, 0.5044),
    1.67: (0.3088, 0.1871, 0.6060),
    2.5: (0.1850, 0.1339, 0.7240),
    5.0: (0.0831, 0.0711, 0.8558),
}
_Z = 180
_ALPHA = np.deg2rad(40.0)
_E = 2.3e11  # [Pa] E′ of steel; the ratios checked here do not depend on it


def _many_ball_row(contact_angle):
    from bearingkit.rows.ball.row import BallRow

    return BallRow(
        n_elements=_Z,
        element_diameter=0.003,
        pitch_diameter=0.2,
        contact_angle=contact_angle,
        conformity_inner=0.6,
        conformity_outer=0.6,
        e_reduced=_E,
        name="balls",
    )


def harris_integrals(eps: float) -> dict:
    """J_r, J_a and F_r tan α / F_a of a Z = 180 angular row at ratio ε (displacement control)."""
    from bearingkit.analysis.solver.model import BearingModel
    from bearingkit.analysis.solver.quasistatic import solve

    model = BearingModel((_many_ball_row(_ALPHA),))
    delta_r = 1e-7  # small against A0 = 600 µm, so the contact angle stays at α (Harris assumes it fixed)
    delta_a = (2 * eps - 1) * delta_r / np.tan(_ALPHA)
    res = solve(model, np.zeros(5), free=[False] * 5, displacement=[delta_r, 0, delta_a, 0, 0])
    f_r, f_a = res.load[0, 0], res.load[0, 2]
    q_max = res.rows[0].max_load[0]
    return {
        "jr": f_r / (_Z * q_max * np.cos(_ALPHA)),
        "ja": f_a / (_Z * q_max * np.sin(_ALPHA)),
        "ratio": f_r * np.tan(_ALPHA) / f_a,
    }


def stribeck_ball() -> float:
    """Q_max Z cos α / F_r for a zero-clearance radial ball row under pure radial load."""
    from bearingkit.analysis.solver.model import BearingModel
    from bearingkit.analysis.solver.quasistatic import load_vector, solve

    model = BearingModel((_many_ball_row(0.0),))
    res = solve(model, load_vector(F_x=2000.0), free=[True, True, False, False, False], raise_on_failure=True)
    return res.rows[0].max_load[0] * _Z / 2000.0


def stribeck_line() -> float:
    """Q_max Z / F_r for a zero-clearance radial row of straight rollers under pure radial load."""
    from bearingkit.analysis.solver.model import BearingModel
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.rows.cylindrical.row import CylindricalRow

    row = CylindricalRow(
        n_elements=_Z,
        element_diameter=0.003,
        effective_length=0.004,
        pitch_diameter=0.2,
        n_slices=4,
        e_reduced=_E,
        name="rollers",
    )
    res = solve(
        BearingModel((row,)),
        load_vector(F_x=2000.0),
        free=[True, True, False, False, False],
        raise_on_failure=True,
    )
    return res.rows[0].max_load[0] * _Z / 2000.0


def pure_axial_ratio() -> float:
    """Q·Z·sin α / F_a for an angular contact row under pure axial load (exactly 1: equal loads)."""
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.bearings.standard import angular_contact_ball

    model = angular_contact_ball(
        n_elements=15, element_diameter=0.0127, pitch_diameter=0.0725, contact_angle=np.deg2rad(40)
    )
    res = solve(model, load_vector(F_z=5000.0), raise_on_failure=True)
    row = res.rows[0]
    return float(np.mean(row.load[0] * 15 * np.sin(row.contact_angle[0])) / 5000.0)


register(
    Case("stribeck/ball-zero-clearance", STRIBECK, "Q_max Z cos α / F_r", "1", 4.37, stribeck_ball, 0.01)
)
register(Case("stribeck/line-zero-clearance", STRIBECK, "Q_max Z / F_r", "1", 4.08, stribeck_line, 0.01))
register(
    Case(
        "axial/angular-contact-equal-share",
        "Harris & Kotzalas (2007) eq. 7.24: Q = F_a/(Z sin α) under pure axial load",
        "Q Z sin α / F_a",
        "1",
        1.0,
        pure_axial_ratio,
        1e-9,
    )
)
for _eps, (_ratio, _jr, _ja) in HARRIS_TABLE_7_4.items():
    for _key, _pub in (("jr", _jr), ("ja", _ja)):
        register(
            Case(
                f"harris/table7.4/eps-{_eps:g}/{_key}",
                HARRIS,
                f"J_{_key[1]}(ε={_eps:g})",
                "1",
                _pub,
                (lambda e=_eps, k=_key: harris_integrals(e)[k]),
                0.01,
            )
        )
