"""Tapered rows with free tilts: pairs under combined loads, single rows, zero load, bounded effort."""

import warnings

import numpy as np
import pytest
from bk_tapered_helpers import assert_equilibrium as _assert_equilibrium

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.quasistatic import SolverOptions, load_vector, solve
from bearingkit.bearings.tapered import seed001_pair, seed001_row
from bearingkit.physics.contact.profiles import make_profile
from bearingkit.rows.tapered import kernel as tapered_kernel
from bearingkit.rows.tapered import row as tapered

#: Combined loads on a pair: (F_x, F_y, F_z [N], M_x, M_y [N·m]); the first is issue #4's stall.
PAIR_LOADS = load_vector(
    F_x=[3000.0, 3000.0, -2500.0, 0.0, 4000.0],
    F_y=[0.0, -1500.0, 2000.0, 1000.0, 0.0],
    F_z=[5000.0, 5000.0, -4000.0, 800.0, 0.0],
    M_x=[0.0, 40.0, -25.0, 60.0, 0.0],
    M_y=[0.0, -60.0, 30.0, 0.0, -80.0],
)
#: Whole solves stay far below the solver's caps (60 Newton steps, 40 roller steps per call).
GLOBAL_ITERATION_BOUND = 15
INNER_ITERATION_BOUND = 15


def _sliced(**kw):
    profile = make_profile("iso16281_tapered", effective_length=13.66e-3, element_diameter=6.4885e-3)
    return seed001_row(deviation_model="exact", n_slices=9, profile=profile, **kw)


@pytest.mark.parametrize("arrangement", ["DB", "DF"])
def test_pair_combined_loads_converge_with_bounded_effort(arrangement):
    model = seed001_pair(arrangement=arrangement, spacing=0.04)
    res = solve(model, PAIR_LOADS)
    assert res.converged.all(), res.reason
    assert res.residual_norm.max() <= 1e-9
    assert res.iterations.max() <= GLOBAL_ITERATION_BOUND
    for k in model.kernels:
        assert k.inner_iterations_max <= INNER_ITERATION_BOUND
        assert k.inner_unconverged == 0
    _assert_equilibrium(model, res, PAIR_LOADS)


@pytest.mark.parametrize("arrangement", ["DB", "DF"])
def test_pair_single_cases_converge_like_the_batch(arrangement):
    model = seed001_pair(arrangement=arrangement, spacing=0.04)
    batch = solve(model, PAIR_LOADS).displacement
    for c in (0, 2):
        one = solve(seed001_pair(arrangement=arrangement, spacing=0.04), PAIR_LOADS[c])
        assert one.converged.all() and one.residual_norm[0] <= 1e-9
        np.testing.assert_allclose(one.displacement[0], batch[c], rtol=1e-7, atol=1e-13)


def test_pair_with_sliced_rows_deviations_and_clearance():
    profile = make_profile("iso16281_tapered", effective_length=13.66e-3, element_diameter=6.4885e-3)
    dev = np.linspace(-1e-6, 1e-6, 23)
    model = seed001_pair(
        arrangement="DB",
        deviation_model="exact",
        diameter_deviation=dev,
        n_slices=9,
        profile=profile,
        clearance=5e-6,
    )
    res = solve(model, PAIR_LOADS[:3])
    assert res.converged.all(), res.reason
    assert res.residual_norm.max() <= 1e-9
    _assert_equilibrium(model, res, PAIR_LOADS[:3])


def test_pair_tilt_stiffness_follows_the_spread_of_the_pressure_centres():
    # One arrangement puts the pressure centres outside the rows (spread = spacing + 2|s_P|), the
    # other inside (spacing − 2|s_P|); the wider spread must give the smaller tilt under a moment.
    spacing = 0.04
    s_p = abs(seed001_row().pressure_centre)
    tilt, spread = {}, {}
    for arr in ("DB", "DF"):
        model = seed001_pair(arrangement=arr, spacing=spacing, clearance=-10e-6)
        res = solve(model, load_vector(M_y=50.0))
        assert res.converged.all()
        tilt[arr] = abs(res.displacement[0, 4])
        z = sorted(r.pressure_centre for r in model.rows)
        spread[arr] = z[1] - z[0]
    wide, narrow = sorted(spread, key=spread.get, reverse=True)
    assert (wide, narrow) == ("DB", "DF")  # back-to-back ("O"): pressure centres outside the rows
    assert spread[wide] == pytest.approx(spacing + 2 * s_p, rel=1e-12)
    assert spread[narrow] == pytest.approx(spacing - 2 * s_p, rel=1e-12)
    assert tilt[wide] < tilt[narrow]


def test_zero_load_gives_zero_without_warnings():
    models = [
        BearingModel((seed001_row(),)),
        BearingModel((_sliced(),)),
        seed001_pair(arrangement="DB"),
        seed001_pair(arrangement="DF", clearance=20e-6),
    ]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for model in models:
            res = solve(model, load_vector())
            assert res.converged.all()
            np.testing.assert_array_equal(res.displacement, 0.0)
            for st in res.rows:
                np.testing.assert_array_equal(st.load, 0.0)
                assert np.isfinite(st.max_pressure).all()
            res.to_dict(0)
            for k in model.kernels:
                resp = k.response(np.zeros((2, 5)))
                np.testing.assert_array_equal(resp.force, 0.0)
                np.testing.assert_array_equal(resp.energy, 0.0)
                assert np.isfinite(resp.jacobian).all()
                np.testing.assert_array_equal(resp.jacobian, 0.0)


def test_open_rollers_do_not_poison_later_calls():
    # Ring pulled away (every contact open), then loaded: the warm start must not carry NaN or a
    # stale position into the loaded solve.
    kernel = seed001_row(deviation_model="exact").kernel()
    q_open = np.array([[0.0, 0.0, -20e-6, 0.0, 0.0]])
    q_load = np.array([[1e-6, -2e-6, 30e-6, 2e-5, -1e-5]])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        open_resp = kernel.response(q_open)
        np.testing.assert_array_equal(open_resp.force, 0.0)
        after = kernel.response(q_load)
    fresh = seed001_row(deviation_model="exact").kernel().response(q_load)
    np.testing.assert_allclose(after.force, fresh.force, rtol=1e-10, atol=1e-9)
    np.testing.assert_allclose(after.jacobian, fresh.jacobian, rtol=1e-8, atol=1e-6)


def test_warm_start_gives_the_same_response_as_a_cold_start():
    kernel = _sliced(speed=1500.0).kernel()
    rng = np.random.default_rng(7)
    base = np.array([0.0, 0.0, 30e-6, 0.0, 0.0])
    for _ in range(4):
        q = base + rng.normal(size=(3, 5)) * np.array([3e-6, 3e-6, 3e-6, 5e-5, 5e-5])
        warm = kernel.response(q)
        cold = _sliced(speed=1500.0).kernel().response(q)
        np.testing.assert_allclose(warm.force, cold.force, rtol=1e-9, atol=1e-9 * np.abs(cold.force).max())
        assert kernel.inner_unconverged == 0


def test_single_sliced_row_pure_axial_free_tilts_gives_zero_tilt():
    row = _sliced()
    res = solve(BearingModel((row,)), load_vector(F_z=10_000.0))
    assert res.converged.all()
    q = res.displacement[0]
    length = row.kernel().char_length
    # Symmetry: no radial motion and no tilt (relative to the axial approach).
    assert np.abs(q[:2]).max() <= 1e-12 * q[2]
    assert np.abs(q[3:]).max() * length <= 1e-12 * q[2]
    load = res.row("tapered").load[0]
    np.testing.assert_allclose(load, load[0], rtol=1e-9)


def test_single_whole_roller_row_tilt_is_a_mechanism_about_the_pressure_centre():
    row = seed001_row(deviation_model="exact")
    z_p = row.pressure_centre
    res = solve(BearingModel((row,)), load_vector(F_z=10_000.0))
    assert res.converged.all() and res.residual_norm[0] <= 1e-9
    # Rotation about (0, 0, z_P): u_x = −z_P θ_y, u_y = z_P θ_x. The stiffness does not resist it …
    mech = np.array([[-z_p, 0.0, 0.0, 0.0, 1.0], [0.0, z_p, 0.0, 1.0, 0.0]])
    stiff = res.stiffness[0]
    assert np.abs(stiff @ mech.T).max() <= 1e-12 * np.abs(stiff).max()
    # … and any tilt in the solution is that rotation only: the rollers see the symmetric state.
    q = res.displacement[0]
    assert abs(q[0] + z_p * q[4]) <= 1e-12 * q[2]
    assert abs(q[1] - z_p * q[3]) <= 1e-12 * q[2]
    load = res.row("tapered").load[0]
    np.testing.assert_allclose(load, 10_000.0 / (23 * np.sin(0.2473)), rtol=1e-9)
    # The solver does not wander along the unloaded mechanism: no tilt, no radial shift at all.
    assert np.abs(q[[0, 1]]).max() <= 1e-12 * q[2]
    assert np.abs(q[[3, 4]]).max() * row.pitch_diameter <= 1e-12 * q[2]


def test_single_whole_roller_row_carries_a_load_through_its_pressure_centre():
    row = seed001_row(deviation_model="exact")
    z_p = row.pressure_centre
    load = load_vector(
        F_x=[2000.0, 0.0], F_y=[0.0, -1500.0], F_z=10_000.0, M_x=[0.0, 1500.0 * z_p], M_y=[2000.0 * z_p, 0.0]
    )
    model = BearingModel((row,))
    res = solve(model, load)
    assert res.converged.all(), res.reason
    assert res.residual_norm.max() <= 1e-9
    _assert_equilibrium(model, res, load)


def test_single_whole_roller_row_refuses_a_moment_free_radial_load_quickly():
    # F_x at the row plane misses the pressure centre: no equilibrium exists with free tilts. The
    # engine must say so, with bounded effort, and return finite numbers.
    model = BearingModel((seed001_row(deviation_model="exact"),))
    opts = SolverOptions()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        res = solve(model, load_vector(F_x=[2000.0, 5000.0], F_z=[10_000.0, 2000.0]), options=opts)
    assert not res.converged.any()
    assert all("cannot be carried" in r and "M_y" in r for r in res.reason)
    assert res.iterations.max() <= opts.max_iterations * (1 + opts.continuation_steps)
    kernel = model.kernels[0]
    assert kernel.inner_iterations_max < tapered_kernel.ROLLER_MAX_ITER
    assert np.isfinite(res.displacement).all() and np.isfinite(res.residual_norm).all()


def test_single_sliced_row_carries_a_combined_load_with_a_tilt():
    row = _sliced()
    model = BearingModel((row,))
    load = load_vector(F_x=[2000.0, 5000.0], F_z=[10_000.0, 2000.0])
    res = solve(model, load)
    assert res.converged.all(), res.reason
    assert res.residual_norm.max() <= 1e-9
    assert res.iterations.max() <= GLOBAL_ITERATION_BOUND
    assert model.kernels[0].inner_iterations_max <= INNER_ITERATION_BOUND
    # The moment about the pressure centre needs a tilt of the sign that loads the rollers there.
    assert np.all(res.displacement[:, 4] > 0.0)
    _assert_equilibrium(model, res, load)


def test_pressure_centre_mirrors_with_direction():
    a = seed001_row(axial_position=0.01).pressure_centre
    b = seed001_row(axial_position=0.01, direction=-1).pressure_centre
    assert a - 0.01 == pytest.approx(-(b - 0.01), rel=1e-12)
    # The usual construction (the cup normal through the mid-point of the cup contact) agrees
    # within a few per cent: the 2-DOF roller carries no moment balance, so the cone-side line of
    # action sits slightly apart from it. Both lie behind the large end (s < 0).
    geo = tapered.TapGeometry(seed001_row())
    cup_point = geo.centre + geo.r_m * geo.e
    construction = cup_point[1] - cup_point[0] * np.tan(0.2473)
    assert construction < 0.0
    assert seed001_row().pressure_centre == pytest.approx(construction, rel=0.05)
