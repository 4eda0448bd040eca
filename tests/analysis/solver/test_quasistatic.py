"""Quasi-static solver: equilibrium, symmetry, monotonicity, planar vs 5-DOF, batching, bad input."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.quasistatic import SolverOptions, load_vector, solve
from bearingkit.bearings.common import eccentric_axial_load
from bearingkit.bearings.standard import (
    angular_contact_ball,
    angular_contact_pair,
    cylindrical_roller,
    deep_groove_ball,
    thrust_ball,
)
from bearingkit.bearings.turntable import composite_turntable
from bearingkit.errors import ConvergenceError, InputError


@pytest.fixture(scope="module")
def composite():
    return composite_turntable(clearance_axial_roller=-1e-6, clearance_axial_ball=-5e-6)


def _residual(result):
    """Max |F + Σ row forces| over the free DOFs, relative to the load scale (independent re-evaluation)."""
    force = sum(k.response(result.displacement).force for k in result.model.kernels)
    scale = np.array([1, 1, 1, 1 / 0.09, 1 / 0.09])
    r = (result.load + force)[:, result.free] * scale[result.free]
    ref = np.maximum(np.abs(result.load * scale).max(axis=1), 1.0)
    return np.abs(r).max(axis=1) / ref


def test_equilibrium_residual_combined_load(composite):
    loads = eccentric_axial_load(3000.0, np.linspace(0.0, 0.6, 7), radial_load=3000.0)
    res = solve(composite, loads)
    assert res.converged.all()
    assert (_residual(res) <= 1e-9).all()
    # The contact forces balance the load: row loads add up to the external load.
    total = sum(res.row_load(r.name) for r in composite.rows)
    np.testing.assert_allclose(total, loads, atol=1e-6 * np.abs(loads).max())


def test_radial_load_symmetric_about_its_line():
    model = deep_groove_ball(
        n_elements=12, element_diameter=0.0127, pitch_diameter=0.065, clearance_radial=10e-6
    )
    res = solve(model, load_vector(F_x=5000.0), free=[True, True, False, False, False])
    loads = res.rows[0].load[0]
    # element j at ψ_j and element Z−j at −ψ_j carry equal loads; u_y stays zero
    np.testing.assert_allclose(loads[1:], loads[1:][::-1], rtol=1e-9, atol=1e-9)
    assert abs(res.displacement[0, 1]) < 1e-12
    assert loads.argmax() == 0


@settings(max_examples=15, deadline=None)
@given(st.floats(100.0, 20000.0), st.floats(1.05, 3.0))
def test_load_deflection_monotone(force, factor):
    model = angular_contact_ball(
        n_elements=14, element_diameter=0.0119, pitch_diameter=0.0655, contact_angle=np.deg2rad(40)
    )
    res = solve(model, load_vector(F_z=[force, factor * force]))
    assert res.converged.all()
    uz = res.displacement[:, 2]
    assert uz[1] > uz[0] > 0
    assert res.rows[0].max_load[1] > res.rows[0].max_load[0]


def test_planar_model_equals_five_dof(composite):
    """Seed 000's planar (δ_a, δ_r, θ) model is the 5-DOF model with u_y, θ_x fixed at 0."""
    loads = eccentric_axial_load(3000.0, [0.0, 0.2, 0.5], radial_load=3000.0)
    full = solve(composite, loads)
    planar = solve(composite, loads, free=[True, False, True, False, True])
    np.testing.assert_allclose(planar.displacement, full.displacement, atol=1e-13, rtol=1e-8)
    for a, b in zip(planar.rows, full.rows, strict=True):
        np.testing.assert_allclose(a.load, b.load, rtol=1e-7, atol=1e-6)


def test_batch_equals_single_solves(composite):
    loads = load_vector(F_z=[1000.0, 5000.0, 8000.0], F_x=[0.0, 2000.0, 500.0], M_y=[0.0, -900.0, -300.0])
    batch = solve(composite, loads)
    for c in range(3):
        one = solve(composite, loads[c])
        np.testing.assert_allclose(one.displacement[0], batch.displacement[c], rtol=1e-8, atol=1e-14)


def test_displacement_control_reports_reactions(composite):
    q = np.array([1e-6, 0.0, 2e-6, 0.0, -1e-5])
    res = solve(composite, np.zeros(5), free=[False] * 5, displacement=q)
    force = sum(k.response(q[None]).force for k in composite.kernels)
    # F_y and M_x are zero up to round-off (q in the x-z plane); the compiled core sums in another
    # order than numpy's BLAS, so compare those at round-off of the load scale.
    np.testing.assert_allclose(res.load[0], -force[0], atol=1e-12 * np.abs(force).max())
    # and solving with that load recovers the displacement
    back = solve(composite, res.load[0])
    np.testing.assert_allclose(back.displacement[0], q, atol=1e-12)


def test_stiffness_matches_finite_difference_of_solution():
    model = angular_contact_pair(
        arrangement="DB",
        n_elements=15,
        element_diameter=0.0119,
        pitch_diameter=0.0655,
        contact_angle=np.deg2rad(25),
        row_spacing=0.02,
        axial_clearance=-10e-6,
    )
    f0 = load_vector(F_x=2000.0, F_z=1000.0, M_y=20.0)
    df = 1.0
    a = solve(model, f0)
    b = solve(model, f0 + np.array([0, 0, df, 0, 0]))
    compliance = np.linalg.inv(a.stiffness[0])
    np.testing.assert_allclose(
        b.displacement[0] - a.displacement[0], compliance[:, 2] * df, rtol=2e-3, atol=1e-13
    )


def test_preloaded_pair_carries_no_net_load_at_zero_load():
    model = angular_contact_pair(
        arrangement="DF",
        n_elements=15,
        element_diameter=0.0119,
        pitch_diameter=0.0655,
        contact_angle=np.deg2rad(25),
        row_spacing=0.02,
        axial_clearance=-10e-6,
    )
    res = solve(model, np.zeros(5))
    assert res.converged.all()
    a, b = (res.rows[0].load[0], res.rows[1].load[0])
    assert a.min() > 0 and b.min() > 0  # preload: every ball loaded
    np.testing.assert_allclose(a, b, rtol=1e-9)


def test_tandem_pair_shares_axial_load_equally():
    model = angular_contact_pair(
        arrangement="DT",
        n_elements=15,
        element_diameter=0.0119,
        pitch_diameter=0.0655,
        contact_angle=np.deg2rad(25),
        row_spacing=0.02,
    )
    res = solve(model, load_vector(F_z=4000.0), free=[False, False, True, False, False])
    np.testing.assert_allclose(res.row_load("balls_A")[0, 2], 2000.0, rtol=1e-9)


def test_uncarriable_load_on_unreached_dof_is_refused_before_solving():
    model = thrust_ball(n_elements=18, element_diameter=0.01, pitch_diameter=0.08)
    with pytest.raises(InputError, match="F_x"):
        solve(model, load_vector(F_x=100.0, F_z=1000.0))


def test_uncarriable_direction_reports_reason():
    model = angular_contact_ball(
        n_elements=14, element_diameter=0.0119, pitch_diameter=0.0655, contact_angle=np.deg2rad(40)
    )
    res = solve(model, load_vector(F_z=[1000.0, -1000.0]), options=SolverOptions(max_iterations=30))
    assert res.converged[0] and not res.converged[1]
    assert "cannot be carried" in res.reason[1]
    assert np.isfinite(res.displacement).all()
    with pytest.raises(ConvergenceError) as err:
        solve(model, load_vector(F_z=-1000.0), raise_on_failure=True)
    assert err.value.result is not None and not err.value.result.converged[0]


def test_large_clearance_is_closed():
    model = cylindrical_roller(
        n_elements=16,
        element_diameter=0.011,
        effective_length=0.011,
        pitch_diameter=0.0655,
        clearance_radial=60e-6,
    )
    res = solve(model, load_vector(F_x=[100.0, 30000.0]), free=[True, True, False, False, False])
    assert res.converged.all()
    assert res.displacement[0, 0] > 30e-6  # the ring first crosses half the clearance
    assert res.rows[0].loaded_count[0] < res.rows[0].loaded_count[1]


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        (dict(conformity_inner=0.5), "conformity_inner"),
        (dict(n_elements=0), "n_elements"),
        (dict(element_diameter=-0.01), "element_diameter"),
        (dict(n_elements=40), "n_elements"),  # 40 balls of 12.7 mm do not fit on a 65 mm circle
    ],
)
def test_bad_geometry_is_refused(kwargs, field):
    base = dict(n_elements=9, element_diameter=0.0127, pitch_diameter=0.065)
    with pytest.raises(InputError, match=field):
        deep_groove_ball(**{**base, **kwargs})


def test_model_needs_rows_with_unique_names():
    with pytest.raises(InputError, match="rows"):
        BearingModel(())
    m = deep_groove_ball(n_elements=9, element_diameter=0.0127, pitch_diameter=0.065)
    with pytest.raises(InputError, match="duplicate"):
        BearingModel((m.rows[0], m.rows[0]))


def test_non_finite_load_is_refused(composite):
    with pytest.raises(InputError, match="load"):
        solve(composite, load_vector(F_z=np.nan))
    for bad in (np.inf, -np.inf):  # one by one and in a sum that cancels them (inf − inf = nan)
        with pytest.raises(InputError, match="must be finite"):
            solve(composite, load_vector(F_x=bad, F_z=-bad))


@pytest.mark.filterwarnings("ignore:overflow:RuntimeWarning")  # numpy's, in diagnosing such a load
def test_finite_loads_whose_sum_overflows_are_accepted():
    """The finiteness check of a small load sums it first; a finite load beyond 1e308 in sum is then
    checked value by value, not refused (the solve itself reports what such a load does)."""
    model = deep_groove_ball(n_elements=9, element_diameter=0.0127, pitch_diameter=0.065)
    res = solve(model, load_vector(F_x=1.5e308, F_z=1.5e308))
    assert not res.converged[0] and res.reason[0]


def test_results_of_one_plan_share_a_read_only_free_mask(composite):
    a, b = solve(composite, load_vector(F_z=2000.0)), solve(composite, load_vector(F_z=3000.0))
    assert a.free is b.free and a.free.all()
    with pytest.raises(ValueError, match="read-only"):
        a.free[0] = False


def test_result_exports(composite):
    res = solve(composite, eccentric_axial_load(3000.0, 0.2, radial_load=3000.0))
    d = res.to_dict(0)
    assert d["converged"] and set(d["displacement"]) == {
        "u_x_m",
        "u_y_m",
        "u_z_m",
        "theta_x_rad",
        "theta_y_rad",
    }
    row = {r["name"]: r for r in d["rows"]}["ball_upper"]
    assert row["loaded_count"] == int(np.count_nonzero(res.row("ball_upper").load[0]))
    assert row["max_pressure_Pa"] > 1e8
    df = res.to_pandas()
    assert len(df) == composite.n_elements and np.isclose(
        df["load_N"].sum(), sum(r.load.sum() for r in res.rows)
    )


def test_row_loads_balance_the_external_load(composite):
    load = eccentric_axial_load(np.array([3000.0, 5000.0]), 0.2, radial_load=3000.0)
    res = solve(composite, load)
    total = sum(res.row_load(r.name) for r in composite.rows)
    scale = np.abs(load).max()
    assert np.abs(total - load).max() <= 1e-8 * scale
    entries = res.to_dict()
    assert [e["rows"][0]["axial_load_N"] for e in entries] == list(res.row_load(composite.rows[0].name)[:, 2])
    with pytest.raises(InputError, match="not in result"):
        res.row_load("no_such_row")


def test_raceway_shift_moves_the_solution_rigidly():
    from bearingkit.rows.base import RacewayOffset

    model = angular_contact_pair(
        arrangement="DB",
        n_elements=15,
        element_diameter=0.0119,
        pitch_diameter=0.0655,
        contact_angle=np.deg2rad(25),
        row_spacing=0.02,
        axial_clearance=-5e-6,
    )
    load = load_vector(F_x=2000.0, F_z=800.0)
    shift = np.array([[3e-6, -1e-6, 2e-6, 1e-5, -2e-5]])
    base = solve(model, load)
    moved = solve(model, load, raceway_offsets={r.name: RacewayOffset(shift=shift) for r in model.rows})
    np.testing.assert_allclose(moved.displacement, base.displacement + shift, atol=1e-13)
    np.testing.assert_allclose(moved.rows[0].load, base.rows[0].load, rtol=1e-7)


def test_uniform_radial_raceway_deflection_acts_as_clearance():
    from bearingkit.rows.base import RacewayOffset

    kw = dict(n_elements=16, element_diameter=0.011, effective_length=0.011, pitch_diameter=0.0655)
    w = 3e-6
    flexible = cylindrical_roller(**kw)
    offset = {"rollers": RacewayOffset(radial=np.full((1, 16), w))}
    a = solve(
        flexible, load_vector(F_x=5000.0), free=[True, True, False, False, False], raceway_offsets=offset
    )
    b = solve(
        cylindrical_roller(**kw, clearance_radial=2 * w),
        load_vector(F_x=5000.0),
        free=[True, True, False, False, False],
    )
    np.testing.assert_allclose(a.rows[0].load, b.rows[0].load, rtol=1e-8, atol=1e-8)
    with pytest.raises(InputError, match="not in the bearing"):
        solve(flexible, load_vector(F_x=1.0), raceway_offsets={"nope": RacewayOffset()})


def test_overlapping_rows_are_refused():
    from bearingkit.rows.ball.row import BallRow

    a = BallRow(n_elements=12, element_diameter=0.01, pitch_diameter=0.08, contact_angle=0.3, name="a")
    b = BallRow(
        n_elements=12,
        element_diameter=0.01,
        pitch_diameter=0.085,
        contact_angle=0.3,
        axial_position=0.004,
        name="b",
    )
    with pytest.raises(InputError, match="overlap"):
        BearingModel((a, b))
    far = BallRow(
        n_elements=12,
        element_diameter=0.01,
        pitch_diameter=0.08,
        contact_angle=-0.3,
        axial_position=0.02,
        name="far",
    )
    assert len(BearingModel((a, far)).rows) == 2


def test_deep_groove_ball_bearing_carries_axial_load_through_its_contact_angle():
    model = deep_groove_ball(
        n_elements=9, element_diameter=0.0127, pitch_diameter=0.065, clearance_radial=15e-6
    )
    res = solve(model, load_vector(F_x=2000.0, F_z=1000.0))
    assert res.converged.all()
    alpha = res.rows[0].contact_angle[0]
    assert alpha.max() > np.deg2rad(5)  # the free contact angle opened by the axial load
    np.testing.assert_allclose(res.row_load("balls")[0, 2], 1000.0, rtol=1e-8)


def test_per_case_clearance_batch_equals_single_solves():
    """Cases with their own clearance: the batch (which narrows to small subsets) = separate solves."""
    from bearingkit.bearings.standard import cylindrical_roller

    kw = dict(n_elements=16, element_diameter=0.012, effective_length=0.012, pitch_diameter=0.1, n_slices=8)
    clearances = np.array([0.0, 100e-6, -5e-6])  # case 1 converges last, alone
    batch = cylindrical_roller(clearance_radial=clearances, **kw)
    load = load_vector(F_x=np.array([20e3, 20e3, 2e3]))
    res = solve(batch, load)
    assert res.converged.all()
    for k, c in enumerate(clearances):
        one = solve(cylindrical_roller(clearance_radial=float(c), **kw), load[k : k + 1])
        np.testing.assert_allclose(res.displacement[k], one.displacement[0], rtol=1e-8, atol=1e-12)
        np.testing.assert_allclose(res.rows[0].load[k], one.rows[0].load[0], rtol=1e-8, atol=1e-6)


def test_slice_pressures_are_hertz_line_contacts(composite):
    """The per-slice pressures of the state equal line.line_contact of each slice load, both raceways."""
    from bearingkit.physics.contact import line

    res = solve(composite, eccentric_axial_load(np.array([2000.0, 6000.0]), 0.3, radial_load=3000.0))
    for kernel, state in zip(composite.kernels, res.rows, strict=True):
        if state.kind != "cylindrical":
            continue
        row = kernel.row
        d, dm = row.element_diameter, row.pitch_diameter
        width = row.effective_length / kernel.shape[1]
        radial = row.orientation == "radial"
        for side, sign in (("inner", -1.0), ("outer", 1.0)):
            rx = d / 2 * (1 + sign * d / dm) if radial else d / 2
            ref = line.line_contact(state.slice_load, width, rx, kernel.e_reduced).max_pressure
            np.testing.assert_allclose(state.extras[f"slice_pressure_{side}"], ref, rtol=1e-12, atol=1e-3)
        assert state.max_pressure.max() > 1e8
