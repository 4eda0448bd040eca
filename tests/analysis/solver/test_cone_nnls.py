"""The contact-cone NNLS: exact against scipy, and no round-off cycling on large slice cones."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from scipy.optimize import nnls as scipy_nnls

from bearingkit.analysis.solver import cone
from bearingkit.analysis.solver import quasistatic as qs
from bearingkit.bearings.turntable import composite_turntable


def test_nnls_matches_scipy_on_random_problems():
    from bearingkit.analysis.solver.compiled_linalg import nnls_misfit

    rng = np.random.default_rng(7)
    for _ in range(30):
        a = rng.normal(size=(5, 40))
        b = rng.normal(size=5)
        x, misfit = cone.nnls(a, b)
        misfit_ref = scipy_nnls(a, b)[1]
        assert (x >= 0).all()
        assert misfit == pytest.approx(misfit_ref, rel=1e-9, abs=1e-12)
        assert nnls_misfit(a, b) == pytest.approx(misfit_ref, rel=1e-9, abs=1e-12)


@pytest.fixture(scope="module")
def turntable_cone():
    model = composite_turntable()
    plan = qs._plan(model, qs._free_key(None), qs.DEFAULT_OPTIONS, None)
    return plan.cone_matrix, plan.scale, plan.idx


def test_load_inside_a_cone_of_thousands_of_slices_stops_at_round_off(turntable_cone, monkeypatch):
    """Seed-000 load that used to cycle: misfit 3e-15 of the load, the entering column leaving again
    at once, 19,468 least-squares solves to the 3n + 10 cap (0.3 s compiled, 2 s numpy)."""
    g, scale, idx = turntable_cone
    load = np.array([2.27919853e00, 0.0, 6.83715617e03, 0.0, -4.43125820e02])
    f = (load * scale)[idx]
    calls = []
    lstsq = np.linalg.lstsq
    monkeypatch.setattr(np.linalg, "lstsq", lambda *a, **k: calls.append(1) or lstsq(*a, **k))
    x, misfit = cone.nnls(g, f)
    assert len(calls) < 100
    assert misfit < 1e-12 * np.linalg.norm(f)  # inside the cone: not refused
    assert np.linalg.norm(g @ x - f) == pytest.approx(misfit)


def test_compiled_nnls_agrees_on_the_cycling_load(turntable_cone):
    from bearingkit.analysis.solver.compiled_linalg import nnls_misfit

    g, scale, idx = turntable_cone
    load = np.array([2.27919853e00, 0.0, 6.83715617e03, 0.0, -4.43125820e02])
    f = (load * scale)[idx]
    size = np.linalg.norm(f)
    assert nnls_misfit(np.ascontiguousarray(g), f) < cone.CONE_MISS_RTOL * size
    # A load outside a cone (directions all with a positive third component, the load negative
    # there) is still refused by both, with the same misfit (its distance to the cone: 1).
    rng = np.random.default_rng(3)
    dirs = rng.normal(size=(5, 300))
    dirs[2] = np.abs(dirs[2]) + 0.1
    out = np.array([0.0, 0.0, -1.0, 0.0, 0.0])
    compiled = nnls_misfit(np.ascontiguousarray(dirs), out)
    assert compiled > cone.CONE_MISS_RTOL
    assert cone.nnls(dirs, out)[1] == pytest.approx(compiled, rel=1e-9)
    assert scipy_nnls(dirs, out)[1] == pytest.approx(compiled, rel=1e-9)


def test_compiled_and_numpy_nnls_agree_where_the_inner_loop_meets_round_off():
    """6209 loads (F_r with a small F_a) where an inner step of Lawson–Hanson divides 0 by 0: the
    compiled NNLS took the NaN step and, stopped there, refused carriable loads (bench_generic)."""
    from pathlib import Path

    from bearingkit.analysis.solver.compiled_linalg import nnls_misfit
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.io.loader import load_file

    bearing = load_file(Path(__file__).resolve().parents[3] / "examples" / "dgbb_6209.toml")
    plan = qs._plan(bearing.model, qs._free_key(bearing.free), bearing.options, None)
    g = np.ascontiguousarray(plan.cone_matrix)
    # Full precision: the round-off path needs the exact values (bench_generic's 6209 cases).
    fx = np.array([1788.727248298261, 2636.492495279866, 2184.9203447667915, 3072.9739981488115])
    fz = np.array([87.65829751560594, 225.51795344152214, 125.04008191007077, 294.9628886413478])
    loads = load_vector(F_x=fx, F_z=fz)
    for load in loads:
        f = (load * plan.scale)[plan.idx]
        size = np.linalg.norm(f)
        assert nnls_misfit(g, f) < 1e-12 * size
        assert cone.nnls(g, f)[1] < 1e-12 * size
    for backend in ("compiled", "numpy"):
        options = dataclasses.replace(bearing.options, backend=backend)
        res = solve(bearing.model, loads, free=bearing.free, options=options)
        assert res.converged.all(), (backend, res.reason)
