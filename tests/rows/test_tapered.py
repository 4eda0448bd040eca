"""Tapered row: derivatives, virtual work, symmetry, equilibrium, closed forms, bad input."""

import dataclasses

import numpy as np
import pytest

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings.tapered import seed001_pair, seed001_row
from bearingkit.errors import InputError
from bearingkit.physics.contact.profiles import make_profile

ALPHA_E = 0.2473


def _rows():
    yield seed001_row(deviation_model="exact")
    yield seed001_row(deviation_model="exact", diameter_deviation=np.linspace(-1e-6, 1e-6, 23))
    yield seed001_row(deviation_model="taylor", diameter_deviation=np.linspace(-1e-6, 1e-6, 23))
    yield seed001_row(
        deviation_model="exact",
        n_slices=9,
        profile=make_profile("iso16281_tapered", effective_length=13.66e-3, element_diameter=6.4885e-3),
        direction=-1,
        axial_position=0.01,
        speed=500.0,
    )


def _q(rng, n, sign=1):
    q = rng.normal(size=(n, 5)) * np.array([2e-6, 2e-6, 2e-6, 3e-5, 3e-5])
    q[:, 2] = sign * (30e-6 + np.abs(q[:, 2]))  # axial preload-like: most rollers loaded
    return q


@pytest.mark.parametrize("row", list(_rows()), ids=["ideal", "exact", "taylor", "sliced"])
def test_jacobian_matches_finite_differences(row):
    kernel = row.kernel()
    q = _q(np.random.default_rng(1), 3, row.direction)
    jac = kernel.response(q).jacobian
    steps = np.array([1e-10, 1e-10, 1e-10, 1e-9, 1e-9])
    fd = np.empty_like(jac)
    for i in range(5):
        dq = np.zeros(5)
        dq[i] = steps[i]
        fd[:, :, i] = (kernel.response(q + dq).force - kernel.response(q - dq).force) / (2 * steps[i])
    np.testing.assert_allclose(jac, fd, atol=2e-5 * np.abs(fd).max(), rtol=2e-4)


@pytest.mark.parametrize("row", list(_rows()), ids=["ideal", "exact", "taylor", "sliced"])
def test_force_is_minus_energy_gradient(row):
    kernel = row.kernel()
    q = _q(np.random.default_rng(2), 3, row.direction)
    force = kernel.response(q).force
    steps = np.array([1e-10, 1e-10, 1e-10, 1e-9, 1e-9])
    for i in range(5):
        dq = np.zeros(5)
        dq[i] = steps[i]
        grad = (kernel.response(q + dq).energy - kernel.response(q - dq).energy) / (2 * steps[i])
        np.testing.assert_allclose(-grad, force[:, i], rtol=1e-4, atol=1e-6 * np.abs(force).max())


def test_jacobian_symmetric_negative_semidefinite():
    kernel = list(_rows())[3].kernel()
    jac = kernel.response(_q(np.random.default_rng(3), 4, -1)).jacobian
    np.testing.assert_allclose(jac, np.swapaxes(jac, 1, 2), atol=1e-9 * np.abs(jac).max())
    assert np.linalg.eigvalsh(jac).max() <= 1e-9 * np.abs(jac).max()


def test_pure_axial_load_equal_rollers_and_closed_form():
    row = seed001_row()
    res = solve(BearingModel((row,)), load_vector(F_z=10_000.0), free=[True, True, True, False, False])
    assert res.converged.all()
    q_e = res.row("tapered").load[0]
    np.testing.assert_allclose(q_e, q_e[0], rtol=1e-10)
    # Cup equilibrium (seed 001 eq. 6): Z Q_e sin α_e = F_a.
    np.testing.assert_allclose(q_e[0], 10_000.0 / (23 * np.sin(ALPHA_E)), rtol=1e-9)
    np.testing.assert_allclose(res.displacement[0, :2], 0.0, atol=1e-12)


def test_roller_equilibrium_residual():
    row = seed001_row(deviation_model="exact", diameter_deviation=np.linspace(-1e-6, 1e-6, 23), speed=2000.0)
    k = row.kernel()
    q = _q(np.random.default_rng(5), 2)
    st = k.roller_state(q)
    g = k.geo
    net = (
        st["load_inner"][..., None] * g.n_i
        + st["load_flange"][..., None] * g.n_f
        - st["load_outer"][..., None] * g.n_e
    )
    net[..., 0] += k.f_c
    assert k.f_c > 0
    assert np.abs(net).max() <= 1e-9 * st["load_outer"].max()


def test_global_equilibrium_with_deviations_and_radial_load():
    row = seed001_row(deviation_model="exact", diameter_deviation=np.linspace(-1.5e-6, 1.5e-6, 23))
    model = BearingModel((row,))
    load = load_vector(F_x=[0.0, 2000.0], F_z=[10_000.0, 8000.0])
    res = solve(model, load, free=[True, True, True, False, False])
    assert res.converged.all()
    f = model.kernels[0].response(res.displacement).force
    np.testing.assert_allclose(f[:, :3] + load[:, :3], 0.0, atol=1e-6 * 10_000)


def test_exact_and_taylor_agree_to_first_order():
    dev = np.linspace(-0.2e-6, 0.2e-6, 23)
    out = []
    for model in ("exact", "taylor"):
        row = seed001_row(deviation_model=model, diameter_deviation=dev)
        res = solve(BearingModel((row,)), load_vector(F_z=10_000.0), free=[True, True, True, False, False])
        out.append(res.row("tapered").load[0])
    ideal = 10_000.0 / (23 * np.sin(ALPHA_E))
    # The difference is second order in ΔD/δ (δ ≈ 4 µm): far below the first-order change.
    assert np.abs(out[0] - out[1]).max() < 0.05 * np.abs(out[0] - ideal).max()


def test_larger_roller_carries_more():
    dev = np.zeros(23)
    dev[4] = 1e-6
    row = seed001_row(deviation_model="exact", diameter_deviation=dev)
    res = solve(BearingModel((row,)), load_vector(F_z=10_000.0), free=[True, True, True, False, False])
    q = res.row("tapered").load[0]
    assert q.argmax() == 4 and q[4] > 1.05 * np.median(q)


def test_pair_carries_moment_and_both_axial_directions():
    for arr in ("DB", "DF"):
        model = seed001_pair(arrangement=arr, spacing=0.04, clearance=-10e-6)
        load = load_vector(F_x=[3000.0, 0.0], F_z=[2000.0, -2000.0], M_y=[0.0, 50.0])
        res = solve(model, load)
        assert res.converged.all(), res.reason
        total = sum(k.response(res.displacement).force for k in model.kernels)
        np.testing.assert_allclose(total + load, 0.0, atol=1e-6 * 3000)


def test_bad_input():
    with pytest.raises(InputError, match="diameter_deviation"):
        seed001_row(diameter_deviation=np.zeros(22))
    with pytest.raises(InputError, match="diameter_deviation"):
        seed001_row(diameter_deviation=np.r_[np.zeros(22), np.nan])
    with pytest.raises(InputError, match="flange_angle"):
        seed001_row(flange_angle=1.0)
    with pytest.raises(InputError, match="roller_angle"):
        seed001_row(roller_angle=0.04)
    with pytest.raises(InputError, match="direction"):
        dataclasses.replace(seed001_row(), direction=0)
