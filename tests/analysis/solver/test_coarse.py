"""The coarse stage of the solver (bearingkit.analysis.solver.coarse): it moves the start, not the
equilibrium.

Both cores run the first Newton iterations on the bearing with its sliced rollers at a few slices;
the full model then converges to ``rtol`` as before. Checked here: which rows are coarsened (and
thinned), that
the equilibrium and stiffness are those of a solve without the stage (to the solver tolerance),
that the stage saves full evaluations, that the two cores still agree step by step, and that a
given start or a disabled stage runs no coarse evaluation.
"""

import numpy as np
import pytest

from bearingkit.analysis.solver import backend
from bearingkit.analysis.solver.coarse import COARSE_SLICES, COARSE_THIN_FROM, coarse_kernels
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.quasistatic import SolverOptions, load_vector, solve
from bearingkit.bearings.standard import cylindrical_roller, deep_groove_ball
from bearingkit.bearings.turntable import composite_turntable, yrt_turntable
from bearingkit.errors import InputError

COMPILED = SolverOptions(backend="compiled")
NUMPY = SolverOptions(backend="numpy")
PLAIN = SolverOptions(backend="compiled", coarse_iterations=0)


def _loads(n: int, seed: int = 11) -> np.ndarray:
    """Seed-000-like loads: F_z 1–8 kN, F_x 0–3 kN, M_y −1800…0 N·m."""
    rng = np.random.default_rng(seed)
    return load_vector(
        F_x=rng.uniform(0, 3000, n), F_z=rng.uniform(1000, 8000, n), M_y=rng.uniform(-1800, 0, n)
    )


def _nu_bearing(n_slices: int = 20) -> BearingModel:
    return cylindrical_roller(
        n_elements=16, element_diameter=0.011, effective_length=0.016, pitch_diameter=0.07,
        clearance_radial=20e-6, n_slices=n_slices,
    )  # fmt: skip


def test_only_finely_sliced_cylindrical_rows_are_coarsened():
    model = composite_turntable()
    coarse = coarse_kernels(model.kernels)
    for fine, rough, row in zip(model.kernels, coarse, model.rows, strict=True):
        if row.kind == "cylindrical":
            # Rows of 31 and 97 rollers: thinned to ⌈Z/2⌉ rollers, fewer slices, the same total
            # line stiffness (c_s scales with the slice width and the rollers each stands for).
            z_coarse = -(-row.n_elements // 2)
            assert row.n_elements >= COARSE_THIN_FROM
            assert rough is not fine and rough.shape == (z_coarse, COARSE_SLICES)
            total = lambda k: float(k.c_s.ravel()[0]) * k.shape[0] * k.shape[1]  # noqa: E731
            assert total(rough) == pytest.approx(total(fine), rel=1e-14)
        else:
            assert rough is fine
    # A row of fewer rollers keeps them: the same rollers, fewer slices.
    nu = _nu_bearing()
    (fine,), (rough,) = nu.kernels, coarse_kernels(nu.kernels)
    assert nu.rows[0].n_elements < COARSE_THIN_FROM and rough.shape == (16, COARSE_SLICES)
    np.testing.assert_array_equal(rough.Ga, fine.Ga)
    assert float(rough.c_s.ravel()[0]) == pytest.approx(4 * float(fine.c_s.ravel()[0]), rel=1e-14)
    ball = deep_groove_ball(n_elements=9, element_diameter=0.0079, pitch_diameter=0.039)
    assert coarse_kernels(ball.kernels) is None
    assert coarse_kernels(_nu_bearing(n_slices=10).kernels) is None  # too few slices to pay


@pytest.mark.parametrize("name", ["seed000", "yrt", "nu"])
def test_the_equilibrium_is_that_of_the_plain_start(name):
    model = {"seed000": composite_turntable, "yrt": yrt_turntable, "nu": _nu_bearing}[name]()
    loads = _loads(40) if name != "nu" else load_vector(F_x=np.linspace(500.0, 20_000.0, 40))
    a = solve(model, loads, options=COMPILED)
    b = solve(model, loads, options=PLAIN)
    assert a.converged.all() and b.converged.all()
    # Both end below rtol = 1e-10 of the load scale: displacements agree to that order.
    for x, y in ((a.displacement, b.displacement), (a.stiffness, b.stiffness)):
        scale = np.abs(y).reshape(len(y), -1).max(axis=1)
        np.testing.assert_array_less(np.abs(x - y).reshape(len(y), -1).max(axis=1), 1e-8 * scale)
    # The stage pays: fewer full evaluations; each case evaluated the coarse model at least at the
    # start and after its first step (the second step's end is the full model's first evaluation).
    assert b.coarse_evaluations.max() == 0
    assert a.coarse_evaluations.min() >= 2
    assert a.evaluations.mean() < 0.75 * b.evaluations.mean()


@pytest.mark.parametrize("name", ["yrt", "nu"])
def test_both_cores_run_the_same_coarse_stage(name):
    model = {"yrt": yrt_turntable, "nu": _nu_bearing}[name]()
    loads = _loads(12) if name == "yrt" else load_vector(F_x=np.linspace(500.0, 20_000.0, 12))
    a = solve(model, loads, options=COMPILED)
    b = solve(model, loads, options=NUMPY)
    np.testing.assert_array_equal(a.iterations, b.iterations)
    scale = np.abs(b.displacement).max(axis=1)
    np.testing.assert_array_less(np.abs(a.displacement - b.displacement).max(axis=1), 1e-12 * scale)


def test_a_coarse_stage_stopped_by_the_divergence_limit_keeps_the_start_in_both_cores():
    """A divergence limit below the solution's displacement: the coarse iterate is dropped."""
    model = composite_turntable()
    tight = dict(divergence_limit=2e-5, continuation_steps=0)
    a = solve(model, _loads(6), options=SolverOptions(backend="compiled", **tight))
    b = solve(model, _loads(6), options=SolverOptions(backend="numpy", **tight))
    assert not a.converged.any()
    np.testing.assert_array_equal(a.iterations, b.iterations)
    scale = np.abs(b.displacement).max(axis=1)
    np.testing.assert_array_less(np.abs(a.displacement - b.displacement).max(axis=1), 1e-12 * scale)


def test_a_given_start_runs_no_coarse_stage():
    model = composite_turntable()
    loads = _loads(8)
    first = solve(model, loads)
    again = solve(model, loads, displacement=first.displacement)
    assert first.coarse_evaluations.min() >= 2 and again.coarse_evaluations.max() == 0
    assert again.evaluations.max() <= 2  # started at the solution


def test_the_coarse_model_is_built_once_per_bearing():
    model = composite_turntable()
    assert backend.coarse_of(model) is backend.coarse_of(model)


def test_coarse_iterations_must_be_a_non_negative_integer():
    with pytest.raises(InputError, match="coarse_iterations"):
        SolverOptions(coarse_iterations=-1)


def test_a_long_coarse_stage_leaves_the_cone_check_to_the_full_model_in_both_cores():
    """Past the cone-check iteration (8) the coarse stage goes on in both cores; the full model refuses."""
    from bearingkit.bearings.standard import cylindrical_roller_thrust

    thrust = cylindrical_roller_thrust(
        n_elements=20, element_diameter=0.01, effective_length=0.01, pitch_diameter=0.08
    )
    loads = load_vector(F_z=[-5000.0, 5000.0])  # the first pulls the rings apart: no contact can carry it
    long = dict(coarse_iterations=10, continuation_steps=0)
    a = solve(thrust, loads, options=SolverOptions(backend="compiled", **long))
    b = solve(thrust, loads, options=SolverOptions(backend="numpy", **long))
    assert list(a.converged) == [False, True] and list(b.converged) == [False, True]
    np.testing.assert_array_equal(a.iterations, b.iterations)
    scale = np.abs(b.displacement).max(axis=1)
    np.testing.assert_array_less(np.abs(a.displacement - b.displacement).max(axis=1), 1e-12 * scale)
