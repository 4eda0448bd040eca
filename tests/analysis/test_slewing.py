"""Static load diagram of slewing rings (bearingkit.analysis.slewing)."""

import numpy as np
import pytest

from bearingkit.analysis.slewing import (
    LOAD_COMBINATIONS,
    closed_form_capacities,
    reference_loads,
    static_load_diagram,
)
from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings import slewing
from bearingkit.physics.contact import hertz

DEG = np.pi / 180


@pytest.fixture(scope="module")
def ring():
    return slewing.slewing_ring_four_point(n_elements=60, element_diameter=0.025, pitch_diameter=0.8)


@pytest.fixture(scope="module")
def diagram(ring):
    return static_load_diagram(ring, n_points=5)


def test_curve_reaches_the_limit_stress_on_every_ray(ring, diagram):
    assert diagram.converged.all()
    res = solve(ring, load_vector(F_z=diagram.axial_force, M_y=-diagram.moment))
    p = res.rows[0].max_pressure.max(axis=-1)
    np.testing.assert_allclose(p, 4200e6, rtol=2e-5)
    assert np.all(np.diff(diagram.axial_force) < 0) and np.all(np.diff(diagram.moment) > 0)


def test_pure_axial_end_is_z_q0_sin_alpha_at_the_operating_angle(ring, diagram):
    """M = 0: every ball carries F_a/(Z sin α) (one diagonal), so the curve's end is Z Q0 sin α_op with
    Q0 the Hertz load of 4200 MPa on the more stressed contact at that angle (closed form, exact)."""
    res = solve(ring, load_vector(F_z=diagram.axial_force[0]))
    alpha = float(res.rows[0].contact_angle[0, 0])
    row = ring.rows[0]
    q0 = np.inf
    for side, f in (("inner", row.conformity_inner), ("outer", row.conformity_outer)):
        s, fd = hertz.ball_raceway_curvature(row.element_diameter, row.pitch_diameter, alpha, f * 0.025, side)
        q0 = min(
            q0, (4200e6 / float(hertz.point_contact(1.0, s, fd, ring.kernels[0].e_reduced).max_pressure)) ** 3
        )
    assert diagram.axial_force[0] == pytest.approx(60 * q0 * np.sin(alpha), rel=1e-4)
    # the makers' line uses the unloaded 45°: the operating angle under C0a is larger, so it is conservative
    assert diagram.axial_force[0] > diagram.axial_capacity


def test_closed_form_line_uses_437(ring):
    c0a, m0, element = closed_form_capacities(ring)
    assert element == "ball" and m0 == pytest.approx(c0a * 0.8 * 0.2288, rel=1e-12)


def test_rothe_erde_load_combinations():
    load = load_vector(F_x=10e3, F_z=100e3, M_y=-50e3)
    fa, mk = reference_loads(load, f_stat=1.25, combination="I")
    assert fa[0] == pytest.approx((100e3 + 5.046 * 10e3) * 1.25) and mk[0] == pytest.approx(50e3 * 1.25)
    fa2, mk2 = reference_loads(load, f_stat=1.0, combination="II")
    assert fa2[0] == pytest.approx(1.225 * 100e3 + 2.676 * 10e3) and mk2[0] == pytest.approx(1.225 * 50e3)
    assert set(LOAD_COMBINATIONS) == {"I", "II"}


def test_utilisation_is_one_on_the_curve(diagram):
    u = diagram.utilisation(diagram.axial_force, diagram.moment)
    np.testing.assert_allclose(u, 1.0, rtol=1e-9)
    assert diagram.utilisation(0.5 * diagram.axial_force[2], 0.5 * diagram.moment[2]) == pytest.approx(0.5)


def test_crossed_roller_diagram_and_refused_kinds():
    ring = slewing.slewing_ring_crossed_roller(
        n_elements=120, element_diameter=0.016, effective_length=0.014, pitch_diameter=0.8
    )
    d = static_load_diagram(ring, n_points=3)
    assert d.element == "roller" and d.converged.all()
    # straight rollers, no clearance: pure axial is exactly Z/2 q0 sin 45° with the line-contact q0
    assert d.axial_force[0] == pytest.approx(d.axial_capacity, rel=1e-4)
    from bearingkit.bearings.self_aligning import spherical_roller
    from bearingkit.errors import InputError

    srb = spherical_roller(
        n_elements=17,
        element_diameter=0.02,
        effective_length=0.02,
        pitch_diameter=0.14,
        contact_angle=10 * DEG,
    )
    with pytest.raises(InputError, match="load diagram"):
        static_load_diagram(srb)
