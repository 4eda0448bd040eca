"""Validation cases of the bearing kinds: four-point, crossed roller and self-aligning rows, ISO 76 f0.

SI values. Closed forms of the load distribution (Harris & Kotzalas 2007, Rolling Bearing Analysis 5th
ed., Table 7.4: Stribeck–Sjövall integrals J_r(ε = 0.5) = 0.2288 point contact and 0.2453 line contact,
so Q_max = 4.37 F_r/(Z cos α) and 4.08 F_r/(Z cos α) at zero clearance) recomputed with the engine on
slewing-ring geometries with many elements; and ISO 76:2006 Table 1 (f0 of radial ball bearings)
recomputed from the standard's own definition of C0 (4200 MPa, Q_max = 5 F_r/(Z cos α)).
"""

from __future__ import annotations

import numpy as np

from bearingkit.validation.registry import Case, register

_HARRIS = "Harris & Kotzalas 2007, Rolling Bearing Analysis 5th ed., Table 7.4 (J_r at ε = 0.5)"
_DEG = np.pi / 180


def _four_point_moment_factor() -> float:
    """Q_max Z d_m sin α / M of a zero-clearance four-point row under a pure moment (1/J_r, point)."""
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.bearings.slewing import slewing_ring_four_point

    ring = slewing_ring_four_point(n_elements=120, element_diameter=0.02, pitch_diameter=1.0)
    res = solve(ring, load_vector(M_y=20e3), free=[False, False, False, True, True])
    st = res.rows[0]
    top = int(np.argmax(st.load[0]))
    return float(st.load[0, top] * 120 * 1.0 * abs(np.sin(st.contact_angle[0, top])) / 20e3)


def _crossed_radial_factor() -> float:
    """Q_max Z cos α / F_r of a zero-clearance crossed roller row under a radial load (1/J_r, line)."""
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.bearings.slewing import slewing_ring_crossed_roller

    ring = slewing_ring_crossed_roller(
        n_elements=200, element_diameter=0.016, effective_length=0.014, pitch_diameter=1.2
    )
    res = solve(ring, load_vector(F_x=20e3), free=[True, True, False, False, False])
    return float(res.rows[0].load[0].max() * 200 * np.cos(45 * _DEG) / 20e3)


def _self_aligning_axial() -> float:
    """Pure axial load on a spherical roller bearing: Q Z sin α_op / F_a (one row carries; exact 1)."""
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.bearings.self_aligning import spherical_roller

    srb = spherical_roller(
        n_elements=19,
        element_diameter=0.021,
        effective_length=0.019,
        pitch_diameter=0.14,
        contact_angle=10 * _DEG,
    )
    res = solve(srb, load_vector(F_z=20e3), free=[True, True, True, False, False])
    st = res.rows[0]
    return float(st.load[0, 0] * 19 * np.sin(st.contact_angle[0, 0]) / 20e3)


def _f0(gamma: float) -> float:
    from bearingkit.physics.life.kinds import f0_from_contact_stress

    return float(f0_from_contact_stress(gamma, 0.52, 0.53, 4200e6))


register(
    Case(
        id="kinds/four-point/moment-stribeck",
        source=_HARRIS + "; 4370·M/D of the slewing-ring makers' selection formula",
        quantity="Q_max Z d_m sin α / M, four-point slewing row, zero clearance, pure tilting moment",
        unit="1",
        published=1.0 / 0.2288,
        compute=_four_point_moment_factor,
        tolerance=0.02,  # finite Z and the operating angle growing with load (the integral is for rigid α)
    )
)
register(
    Case(
        id="kinds/crossed-roller/radial-stribeck",
        source=_HARRIS + " (line contact)",
        quantity="Q_max Z cos α / F_r, crossed roller row, zero clearance, pure radial load",
        unit="1",
        published=1.0 / 0.2453,
        compute=_crossed_radial_factor,
        tolerance=0.01,  # finite Z = 200 (the integral is the continuous limit)
    )
)
register(
    Case(
        id="kinds/spherical-roller/axial-statics",
        source="Harris & Kotzalas 2007 §7.1: under centric axial load each roller of the loaded row carries "
        "Q = F_a/(Z sin α)",
        quantity="Q Z sin α_op / F_a of a spherical roller bearing under pure axial load",
        unit="1",
        published=1.0,
        compute=_self_aligning_axial,
        tolerance=1e-9,  # statics: exact up to the solver's tolerance
    )
)
for _gamma, _f0_iso in ((0.05, 15.7), (0.10, 16.4), (0.20, 14.0), (0.30, 11.6), (0.40, 9.4)):
    register(
        Case(
            id=f"kinds/iso76/f0-definition/gamma{_gamma:.2f}",
            source="ISO 76:2006 Table 1 (radial and angular contact groove ball bearings)",
            quantity="f0 recomputed from C0's definition (4200 MPa, Q_max = 5 F_r/(Z cos α), f = 0.52/0.53)",
            unit="MPa",
            published=_f0_iso,
            compute=lambda g=_gamma: _f0(g),
            tolerance=0.01,  # the table prints f0 to 0.1 MPa (0.6-1 %) and rounds E' and the constants
        )
    )
