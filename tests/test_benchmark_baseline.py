"""The benchmark baseline (per-element loops + fsolve) and bearingkit solve the same problem.

Fast correctness check only (benchmarks are never timed tests): on the seed-000 composite turntable
bearing with few slices, the loop-and-fsolve baseline of ``benchmarks/baseline_fsolve.py`` and
bearingkit's vectorised Newton solver must give the same displacement and element loads. The two
codes share only the physics constants (Hertz K_n, line-law c_l, crown drop); kinematics, contact
geometry and the solver are written independently, so agreement checks both.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # the repository root holds benchmarks/

from benchmarks.baseline_fsolve import BaselineTurntable

from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings.turntable import composite_turntable

N_SLICES = 4
PLANAR = [True, False, True, False, True]


@pytest.fixture(scope="module")
def pair():
    return BaselineTurntable(n_slices=N_SLICES), composite_turntable(n_slices=N_SLICES)


@pytest.mark.parametrize(
    "fx, fz, my",
    [(2000.0, 5000.0, -800.0), (500.0, 1500.0, -1700.0)],  # combined load; moment-dominated (tilted ring)
)
def test_baseline_matches_bearingkit(pair, fx, fz, my):
    base, model = pair
    sol = base.solve(fx, fz, my)
    assert sol["converged"], sol["message"]
    ref = solve(model, load_vector(F_x=fx, F_z=fz, M_y=my), free=PLANAR)
    assert ref.converged[0]
    q = ref.displacement[0, [0, 2, 4]]
    np.testing.assert_allclose(sol["displacement"], q, rtol=1e-6, atol=1e-6 * np.abs(q).max())
    loads = base.element_loads(*sol["displacement"])
    assert set(loads) == {r.name for r in model.rows}
    for name, q_base in loads.items():
        q_ref = ref.row(name).load[0]
        scale = max(q_ref.max(), 1.0)
        np.testing.assert_allclose(q_base, q_ref, rtol=0, atol=1e-6 * scale, err_msg=name)


def test_baseline_force_balances_load(pair):
    """At the baseline's solution its own contact forces balance the applied load (F_x, F_z, M_y)."""
    base, _ = pair
    fx, fz, my = 1000.0, 4000.0, -600.0
    sol = base.solve(fx, fz, my)
    f = np.array(base.contact_force(*sol["displacement"]))
    np.testing.assert_allclose(f, [-fx, -fz, -my], rtol=1e-8, atol=1e-6)


def test_baseline_force_matches_engine_at_any_displacement(pair):
    """Residuals agree off equilibrium too (a stronger check than equal solutions)."""
    base, model = pair
    q = np.array([[1.5e-6, 0.0, 2.0e-6, 0.0, -2.5e-5]])
    force = sum(k.response(q).force for k in model.kernels)[0, [0, 2, 4]]
    np.testing.assert_allclose(base.contact_force(1.5e-6, 2.0e-6, -2.5e-5), force, rtol=1e-9)
