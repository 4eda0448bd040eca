"""The compiled core's per-case budget (issue 41, Deliver 5): the numpy reference's, case for case.

A case may use ``SolverOptions.max_evaluations`` row evaluations (every attempt, line-search trial and
continuation step together); past it the case is stopped where it stands, not retried, and refused
with one line naming the budget, while the rest of its batch goes on. The numpy reference stays the
oracle: both cores count the same evaluations, stop and refuse the same cases with the same reason,
and agree to 1e-12 on the converged ones. Budgets here are set below what the hardest cases of a
random batch need, so that some cases are stopped; the default (50 × max_iterations) stops none of
the examples' cases.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from bearingkit.analysis.solver import compiled_newton
from bearingkit.analysis.solver.newton import MAX_HALVINGS
from bearingkit.analysis.solver.quasistatic import SolverOptions, solve
from bearingkit.io.loader import load_file

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"
#: Example bearings the compiled core solves (ball, cylindrical, tapered rows).
FILES = ("dgbb_6209.toml", "crb_nu209.toml", "trb_32008.toml", "thrust_ball_51209.toml")


def _random_loads(rng: np.random.Generator, n: int, low: float = 0.0, high: float = 3.0) -> np.ndarray:
    """Loads of 10^low … 10^high N per component (moments [N m] a hundredth), random signs and zeros.

    From 1 N: below it, a tapered row's roller sub-problems (solved to 1e-12 of the roller load plus
    an absolute floor, from warm starts that differ between the cores) and the stiffness of contacts
    barely closed make the two cores agree to ~1e-7 and ~1e-11 only (tests/analysis/solver/
    test_compiled.py); the light-load set (test_light_load_set.py) covers those loads.
    """
    load = 10 ** rng.uniform(low, high, (n, 5)) * rng.choice([-1.0, 0.0, 1.0], (n, 5))
    load[:, 3:] *= 0.01
    return load


def _both(model, load, free, **kw):
    out = []
    for backend in ("compiled", "numpy"):
        opts = SolverOptions(backend=backend, **kw)
        out.append(solve(model, load, free=free, options=opts, raise_on_failure=False))
    return out


@pytest.mark.parametrize("name", FILES)
def test_both_cores_stop_the_same_cases_and_agree_on_the_others(name):
    inp = load_file(EXAMPLES / name)
    assert compiled_newton.pack_model(inp.model.kernels) is not None
    load = _random_loads(np.random.default_rng(41), 120, low=1.0)
    plain, _ = _both(inp.model, load, inp.free)
    used = np.asarray(plain.evaluations)
    # a budget that the hardest converging cases of this batch exceed (the median case fits in it)
    budget = int(np.median(used[plain.converged])) + 1
    a, b = _both(inp.model, load, inp.free, max_evaluations=budget)
    stopped = np.array(["budget" in (r or "") for r in a.reason])
    assert stopped.any() and a.converged.any(), (name, budget)
    np.testing.assert_array_equal(a.converged, b.converged)
    np.testing.assert_array_equal(a.evaluations, b.evaluations)
    np.testing.assert_array_equal(a.iterations, b.iterations)
    assert a.reason == b.reason  # the same refusals, word for word
    for c in np.flatnonzero(stopped):
        assert "\n" not in a.reason[c], a.reason[c]
        assert f"budget of one case (SolverOptions.max_evaluations = {budget})" in a.reason[c], a.reason[c]
        # stopped at the start of the iteration after the budget was reached: one line search more at
        # most, and one evaluation per continuation step that begins after it
        assert budget <= a.evaluations[c] <= budget + MAX_HALVINGS + 1 + 4, a.evaluations[c]
    # A tapered row's roller sub-problems are solved to ROLLER_RTOL (1e-12 of the roller load) from
    # warm starts that differ between the cores: its bearing agrees to 1e-10 (as test_compiled.py).
    rtol = 1e-10 if name.startswith("trb") else 1e-12
    ok = a.converged
    for x, y in ((a.displacement, b.displacement), (a.stiffness, b.stiffness)):
        x, y = x[ok].reshape(ok.sum(), -1), y[ok].reshape(ok.sum(), -1)
        err = np.abs(x - y).max(axis=1) - rtol * np.abs(y).max(axis=1)  # a zero load: both zero
        assert (err <= 1e-300).all(), (name, err.max())
    # the stopped cases are those that needed more: without the budget they used more evaluations
    assert (used[stopped] > budget).all() and (used[a.converged] <= budget).all()


@pytest.mark.parametrize("backend", ["compiled", "numpy"])
def test_a_poisoned_case_leaves_the_rest_of_its_batch_as_it_was(backend):
    inp = load_file(EXAMPLES / "crb_nu209.toml")
    load = _random_loads(np.random.default_rng(9), 64)  # its hardest case: 62 evaluations, the next 23
    opts = SolverOptions(backend=backend)
    clean = solve(inp.model, load, free=inp.free, options=opts, raise_on_failure=False)
    assert clean.converged.all()
    used = np.asarray(clean.evaluations)
    poison = int(np.argmax(used))
    # the poisoned case: the hardest one under a budget only it exceeds
    tight = SolverOptions(backend=backend, max_evaluations=int(np.sort(used)[-2]) + 1)
    assert used[poison] > tight.max_evaluations
    mixed = solve(inp.model, load, free=inp.free, options=tight, raise_on_failure=False)
    rest = np.arange(len(load)) != poison
    assert not mixed.converged[poison] and mixed.converged[rest].all()
    assert "budget of one case" in mixed.reason[poison] and "\n" not in mixed.reason[poison]
    np.testing.assert_array_equal(np.asarray(mixed.evaluations)[rest], used[rest])
    # the others alone, without the poisoned case: the same results. The compiled core solves case by
    # case (bit for bit); the numpy reference's batched array operations may round differently with
    # the batch's size (1e-16 relative seen).
    alone = solve(inp.model, load[rest], free=inp.free, options=tight, raise_on_failure=False)
    rtol = 0.0 if backend == "compiled" else 1e-13
    for other in (clean, alone):
        got = (other.displacement, other.stiffness) if other is alone else (x[rest] for x in (
            other.displacement, other.stiffness))  # fmt: skip
        for x, y in zip(got, (mixed.displacement[rest], mixed.stiffness[rest]), strict=True):
            np.testing.assert_allclose(x, y, rtol=rtol, atol=rtol * np.abs(y).max())
