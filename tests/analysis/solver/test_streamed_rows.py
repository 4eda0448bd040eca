"""Per-element results of a large batch (streamed chunk by chunk) with per-case geometry.

A study that varies a clearance gives each case its own geometry; the per-element post-processing
of more than ``STATE_CHUNK`` cases runs chunk by chunk and must evaluate each chunk with its own
cases' geometry (it used to broadcast a chunk of displacements against every case's geometry and
fail), including the geometry the post-processing reads itself (groove curvature, diameters: a
study passes every batched geometry field as a per-case column). The reference is the same case solved
alone with its own geometry: same model, so the values must agree to the solver's tolerance (rtol
1e-10 of the load scale; 1e-8 relative on the element loads leaves room for the δ^1.5 law
amplifying a displacement difference).
"""

import numpy as np

from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.analysis.solver.solution import STATE_CHUNK
from bearingkit.bearings.turntable import composite_turntable


def test_streamed_rows_follow_per_case_geometry():
    n = STATE_CHUNK + 8
    clearance = np.linspace(-6e-6, -2e-6, n)
    curvature = np.linspace(0.515, 0.53, n)
    radial = np.full(n, 0.0)  # constant, but a per-case column as a study passes it
    loads = load_vector(F_z=np.linspace(1000.0, 8000.0, n), F_x=500.0, M_y=-300.0)
    geometry = dict(clearance_axial_ball=clearance, groove_curvature=curvature, clearance_radial=radial)
    res = solve(composite_turntable(**geometry), loads)
    assert res.converged.all()
    stats = res.row_stats("ball_upper")
    force = res.row_load("ball_upper")
    radial = res.row_stats("roller_radial")
    for c in (0, STATE_CHUNK - 1, STATE_CHUNK, n - 1):  # both chunks, either side of the seam
        alone = solve(composite_turntable(**{k: v[c] for k, v in geometry.items()}), loads[c])
        ref = alone.row("ball_upper")
        np.testing.assert_allclose(stats.max_load[c], ref.max_load[0], rtol=1e-8)
        np.testing.assert_allclose(stats.max_pressure[c], ref.max_pressure[0].max(), rtol=1e-8)
        np.testing.assert_allclose(force[c], alone.row_load("ball_upper")[0], rtol=1e-8, atol=1e-6)
        np.testing.assert_allclose(res.to_dict(c)["rows"][1]["loads_N"], ref.load[0], rtol=1e-8, atol=1e-9)
        ref_r = alone.row("roller_radial")
        np.testing.assert_allclose(radial.max_pressure[c], ref_r.max_pressure[0].max(), rtol=1e-8)
    streamed = res.row("ball_upper")  # the whole streamed state, every chunk
    np.testing.assert_allclose(streamed.max_load, stats.max_load, rtol=1e-14)
    np.testing.assert_allclose(streamed.max_pressure.max(axis=-1), stats.max_pressure, rtol=1e-14)
