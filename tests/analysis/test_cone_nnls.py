"""The contact-cone NNLS: exact against scipy, and no round-off cycling on large slice cones."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import nnls as scipy_nnls

from bearingkit.analysis import cone
from bearingkit.analysis import quasistatic as qs
from bearingkit.bearings.turntable import composite_turntable


def test_nnls_matches_scipy_on_random_problems():
    rng = np.random.default_rng(7)
    for _ in range(30):
        a = rng.normal(size=(5, 40))
        b = rng.normal(size=5)
        x, misfit = cone.nnls(a, b)
        misfit_ref = scipy_nnls(a, b)[1]
        assert (x >= 0).all()
        assert misfit == pytest.approx(misfit_ref, rel=1e-9, abs=1e-12)


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
    from bearingkit.analysis.compiled_newton import _nnls_misfit

    g, scale, idx = turntable_cone
    load = np.array([2.27919853e00, 0.0, 6.83715617e03, 0.0, -4.43125820e02])
    f = (load * scale)[idx]
    size = np.linalg.norm(f)
    assert _nnls_misfit(np.ascontiguousarray(g), f) < cone.CONE_MISS_RTOL * size
    # A load outside a cone (directions all with a positive third component, the load negative
    # there) is still refused by both, with the same misfit (its distance to the cone: 1).
    rng = np.random.default_rng(3)
    dirs = rng.normal(size=(5, 300))
    dirs[2] = np.abs(dirs[2]) + 0.1
    out = np.array([0.0, 0.0, -1.0, 0.0, 0.0])
    compiled = _nnls_misfit(np.ascontiguousarray(dirs), out)
    assert compiled > cone.CONE_MISS_RTOL
    assert cone.nnls(dirs, out)[1] == pytest.approx(compiled, rel=1e-9)
    assert scipy_nnls(dirs, out)[1] == pytest.approx(compiled, rel=1e-9)
