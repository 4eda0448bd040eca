"""High-speed ball rows: zero speed equals the zero-speed row, exact condensed Jacobian, ball balance."""

import numpy as np
import pytest

from bearingkit.analysis.solver.quasistatic import solve
from bearingkit.analysis.solver.speed import OperatingSpeed, model_at_speed
from bearingkit.bearings.standard import angular_contact_ball, angular_contact_pair, deep_groove_ball
from bearingkit.rows.ball.row import BallRow
from bearingkit.rows.ball.speed import BallSpeedKernel
from bearingkit.rows.base import RacewayOffset

RPM = np.pi / 30.0


def _acbb():
    return angular_contact_ball(
        n_elements=13, element_diameter=0.0127, pitch_diameter=0.065, contact_angle=np.radians(40.0)
    )


def _q(rng, n):
    q = rng.normal(size=(n, 5)) * np.array([4e-6, 4e-6, 2e-5, 8e-5, 8e-5])
    q[:, 2] = np.abs(q[:, 2]) + 1e-5
    return q


@pytest.mark.parametrize(
    "row",
    [
        BallRow(
            13, 0.0127, 0.065, contact_angle=0.7, clearance=-2e-6, axial_position=0.002, azimuth_phase=0.1
        ),
        BallRow(9, 0.0127, 0.065, conformity_inner=0.52, conformity_outer=0.53, clearance=1.5e-5),
        BallRow(
            13,
            np.array([0.0127, 0.0125]),
            0.065,
            contact_angle=np.array([0.7, 0.6]),
            clearance=np.array([-2e-6, 0.0]),
        ),
    ],
)
def test_zero_speed_equals_the_zero_speed_row(row):
    """The per-ball sub-problem at ω = 0 condenses to the series contact of the zero-speed row (1e-12)."""
    rng = np.random.default_rng(3)
    base, fast = row.kernel(), BallSpeedKernel(row, 0.0)
    n = np.size(row.element_diameter)
    q = _q(rng, 2 * n) if n == 1 else _q(rng, n)
    for offset in (None, RacewayOffset(shift=1e-6 * rng.normal(size=(len(q), 5)) * [1, 1, 1, 0, 0])):
        r0, r1 = base.response(q, offset), fast.response(q, offset)
        assert np.abs(r1.force - r0.force).max() <= 1e-12 * np.abs(r0.force).max()
        assert np.abs(r1.jacobian - r0.jacobian).max() <= 1e-12 * np.abs(r0.jacobian).max()
        assert np.abs(r1.energy - r0.energy).max() <= 1e-12 * np.abs(r0.energy).max()
    s0, s1 = base.state(q), fast.state(q)
    np.testing.assert_allclose(s1.load, s0.load, rtol=1e-12, atol=1e-12 * s0.load.max())
    np.testing.assert_allclose(s1.contact_angle, s0.contact_angle, atol=1e-12)
    np.testing.assert_allclose(s1.extras["contact_angle_outer"], s0.contact_angle, atol=1e-12)


def test_solve_at_zero_speed_is_the_unchanged_path():
    model = _acbb()
    load = np.array([[2000.0, 0, 5000, 0, 0], [0, 0, 5000, 0, 0]])
    plain = solve(model, load)
    zero = solve(model, load, speed=0.0)
    assert model_at_speed(model, 0.0) is model
    np.testing.assert_array_equal(zero.displacement, plain.displacement)


@pytest.mark.parametrize("control", ["outer", "inner"])
def test_condensed_jacobian_matches_finite_differences(control):
    row = _acbb().rows[0]
    k = BallSpeedKernel(row, np.array([20000.0, 12000.0]) * RPM, raceway_control=control)
    q = np.array([[1e-5, 2e-6, 4e-5, 1e-5, -2e-5], [-5e-6, 0.0, 3e-5, 0.0, 3e-5]])
    jac = k.response(q).jacobian
    h = np.array([1e-9, 1e-9, 1e-9, 3e-8, 3e-8])
    for j in range(5):
        dq = np.zeros(5)
        dq[j] = h[j]
        k._cache = None
        fp = k.response(q + dq).force
        k._cache = None
        fm = k.response(q - dq).force
        fd = (fp - fm) / (2 * h[j])
        # central differences of a sub-problem solved to 1e-12: ~1e-7 of the stiffness
        assert np.abs(fd - jac[:, :, j]).max() <= 2e-6 * np.abs(jac).max()


def test_axial_load_at_speed_parts_the_contact_angles_and_balances_each_ball():
    model = _acbb()
    row = model.rows[0]
    res = solve(model, [0.0, 0.0, 5000.0, 0.0, 0.0], speed=20000 * RPM)
    assert res.converged.all()
    ex = res.rows[0].extras
    a_i, a_o = ex["contact_angle_inner"][0], ex["contact_angle_outer"][0]
    alpha0 = row.contact_angle
    assert np.all(a_o < alpha0) and np.all(a_i > alpha0)  # the outer angle drops, the inner rises
    np.testing.assert_allclose(a_i, a_i[0], rtol=1e-9)  # axisymmetric load: every ball alike
    q_i, q_o, f_c, m_g = (
        ex["load_inner"][0],
        ex["load_outer"][0],
        ex["centrifugal_force"][0],
        ex["gyroscopic_moment"][0],
    )
    d = row.element_diameter
    # Ball balance under outer-raceway control (λ_o = 2): radial and axial components.
    t_o = np.array([-np.sin(a_o), np.cos(a_o)])
    radial = -q_o * np.cos(a_o) + q_i * np.cos(a_i) + f_c + 2 * m_g / d * t_o[0]
    axial = -q_o * np.sin(a_o) + q_i * np.sin(a_i) + 2 * m_g / d * t_o[1]
    assert np.abs(radial).max() < 1e-9 * q_o.max() and np.abs(axial).max() < 1e-9 * q_o.max()
    # The ring's axial balance: Z Q_i sin α_i carries F_a (λ_i = 0: no friction on the inner ring).
    assert (q_i * np.sin(a_i)).sum() == pytest.approx(5000.0, rel=1e-9)
    # F_c = ½ m d_m ω_m² at the ball's own cage speed.
    m = 7810.0 * np.pi * d**3 / 6
    assert f_c[0] == pytest.approx(0.5 * m * row.pitch_diameter * ex["cage_speed"][0, 0] ** 2, rel=1e-12)


def test_per_case_speeds_batch_equals_single_solves():
    model = _acbb()
    load = np.array([[1000.0, 0, 4000, 0, 0], [0, 1500.0, 6000, 0, 0], [500.0, 0, 3000, 0, 0]])
    speeds = np.array([0.0, 18000.0, 9000.0]) * RPM
    batch = solve(model, load, speed=speeds)
    for c in range(3):
        single = solve(model, load[c], speed=speeds[c])
        np.testing.assert_allclose(batch.displacement[c], single.displacement[0], rtol=1e-8, atol=1e-13)


def test_pair_and_deep_groove_rows_at_speed_converge():
    pair = angular_contact_pair(
        n_elements=13,
        element_diameter=0.0127,
        pitch_diameter=0.065,
        arrangement="DB",
        contact_angle=np.radians(25.0),
        row_spacing=0.019,
        axial_clearance=-5e-6,
    )
    res = solve(pair, [3000.0, 0.0, 1000.0, 0.0, 50.0], speed=15000 * RPM)
    assert res.converged.all()
    dgbb = deep_groove_ball(
        n_elements=9, element_diameter=0.0127, pitch_diameter=0.065, clearance_radial=1.5e-5
    )
    res = solve(dgbb, [8900.0, 0.0, 0.0, 0.0, 0.0], free=[1, 1, 0, 0, 0], speed=OperatingSpeed(10000 * RPM))
    assert res.converged.all()
    ex = res.rows[0].extras
    # Unloaded balls are pressed on the outer ring by F_c alone: Q_o = F_c, Q_i = 0.
    free_balls = ex["load_inner"][0] == 0.0
    assert free_balls.any()
    np.testing.assert_allclose(
        ex["load_outer"][0][free_balls], ex["centrifugal_force"][0][free_balls], rtol=1e-9
    )


def test_speed_beyond_the_model_is_a_flagged_non_convergence():
    model = _acbb()
    res = solve(model, [2000.0, 0.0, 5000.0, 0.0, 0.0], speed=60000 * RPM)
    assert not res.converged[0]
    assert "above what the high-speed ball model holds" in res.reason[0]
