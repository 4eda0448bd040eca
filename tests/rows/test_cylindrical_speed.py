"""Radial cylindrical rows at speed: zero speed equals the row, exact condensation, Q_o − Q_i = F_c."""

import numpy as np
import pytest

from bearingkit.analysis.solver.quasistatic import solve
from bearingkit.analysis.solver.speed import model_at_speed
from bearingkit.bearings.standard import cylindrical_roller
from bearingkit.physics.contact.profiles import make_profile
from bearingkit.rows.cylindrical.row import CylindricalRow
from bearingkit.rows.cylindrical.speed import CylindricalSpeedKernel

RPM = np.pi / 30.0
ROW = CylindricalRow(
    n_elements=14,
    element_diameter=0.011,
    effective_length=0.011,
    pitch_diameter=0.065,
    clearance=2e-5,
    n_slices=12,
    profile=make_profile("iso16281", effective_length=0.011, element_diameter=0.011),
)


def _q():
    rng = np.random.default_rng(7)
    q = rng.normal(size=(12, 5)) * np.array([2e-5, 2e-5, 0.0, 3e-4, 3e-4])
    q[:, 0] += 3e-5
    return q


@pytest.mark.parametrize("pairing", ["series", "total_approach"])
def test_zero_speed_equals_the_zero_speed_row(pairing):
    import dataclasses

    row = dataclasses.replace(ROW, pairing=pairing)
    base, fast = row.kernel(), CylindricalSpeedKernel(row, 0.0)
    q = _q()
    r0, r1 = base.response(q), fast.response(q)
    assert np.abs(r1.force - r0.force).max() <= 1e-12 * np.abs(r0.force).max()
    assert np.abs(r1.jacobian - r0.jacobian).max() <= 1e-12 * np.abs(r0.jacobian).max()
    assert np.abs(r1.energy - r0.energy).max() <= 1e-12 * np.abs(r0.energy).max()
    s0, s1 = base.state(q), fast.state(q)
    np.testing.assert_allclose(s1.load, s0.load, rtol=1e-12, atol=1e-12 * s0.load.max())


def test_jacobian_and_virtual_work_at_speed():
    k = CylindricalSpeedKernel(ROW, 9000 * RPM)
    q = _q()[:3]
    r = k.response(q)
    h = np.array([1e-9, 1e-9, 1e-9, 2e-8, 2e-8])
    for j in (0, 1, 3, 4):
        dq = np.zeros(5)
        dq[j] = h[j]
        k._cache = None
        plus = k.response(q + dq)
        k._cache = None
        minus = k.response(q - dq)
        fd = (plus.force - minus.force) / (2 * h[j])
        assert np.abs(fd - r.jacobian[:, :, j]).max() <= 1e-6 * np.abs(r.jacobian).max()
        du = (plus.energy - minus.energy) / (2 * h[j])
        assert np.abs(du + r.force[:, j]).max() <= 1e-6 * np.abs(r.force).max()


def test_each_roller_carries_its_centrifugal_force_on_the_outer_ring():
    model = cylindrical_roller(
        n_elements=14,
        element_diameter=0.011,
        effective_length=0.011,
        pitch_diameter=0.065,
        clearance_radial=3e-5,
    )
    res = solve(model, [10000.0, 0.0, 0.0, 0.0, 0.0], free=[1, 1, 0, 1, 1], speed=8000 * RPM)
    assert res.converged.all()
    ex = res.rows[0].extras
    f_c = ex["centrifugal_force"][0]
    # Roller balance: Σ q_o − Σ q_i = F_c (no tilt moment at a straight or symmetric roller).
    np.testing.assert_allclose(
        ex["load_outer"][0] - ex["load_inner"][0], f_c, rtol=1e-9, atol=1e-9 * f_c.max()
    )
    m = 7810.0 * np.pi * 0.011**2 / 4 * 0.011
    w_c = 0.5 * 8000 * RPM * (1 - 0.011 / 0.065)
    assert f_c[0] == pytest.approx(m * 0.0325 * w_c**2, rel=1e-12)
    # More rollers touch the outer ring than the inner one (every roller is pressed outward).
    assert np.count_nonzero(ex["load_outer"][0]) == 14 > np.count_nonzero(ex["load_inner"][0])


def test_thrust_rows_keep_their_kernel_at_speed():
    from bearingkit.bearings.standard import cylindrical_roller_thrust

    model = cylindrical_roller_thrust(
        n_elements=20, element_diameter=0.007, effective_length=0.007, pitch_diameter=0.059
    )
    fast = model_at_speed(model, 3000 * RPM)
    q = np.array([[0.0, 0.0, 1e-5, 0.0, 0.0]])
    np.testing.assert_array_equal(fast.kernels[0].response(q).force, model.kernels[0].response(q).force)
