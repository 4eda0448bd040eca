"""Coupled flexible-ring solve: rigid limit, convergence diagnostics, bad input."""

import numpy as np
import pytest

from bearingkit.analysis.flexible import solve_flexible
from bearingkit.analysis.quasistatic import load_vector, solve
from bearingkit.bearings.ball_column import BallColumnGeometry, ball_column, outer_ring
from bearingkit.errors import InputError
from bearingkit.rings.flexible import FlexibleOuterRing
from bearingkit.rings.section import RingSection

G = BallColumnGeometry(n_slices=6)
MODEL = ball_column(G)
LOADS = load_vector(F_x=[5000.0, 20000.0], F_z=[0.0, 3000.0])


@pytest.mark.parametrize("bending", [True, False])
def test_rigid_limit_equals_engine(bending):
    rigid = solve(MODEL, LOADS)
    stiff = FlexibleOuterRing(
        RingSection(1e3, 1.0, 0.075, 0.198, 1e3), support_positions=(-0.025, 0.025), bending=bending
    )
    flex = solve_flexible(MODEL, LOADS, stiff)
    assert flex.converged.all()
    assert np.allclose(flex.result.displacement, rigid.displacement, rtol=1e-9, atol=1e-9 * 1e-5)
    for name in ("ball_1", "roller_2", "ball_3"):
        assert np.allclose(flex.row(name).load, rigid.row(name).load, rtol=1e-9, atol=1e-9 * 1e3)
    zero = solve_flexible(MODEL, LOADS, outer_ring(G, compliance_scale=0.0))
    assert np.array_equal(zero.result.displacement, rigid.displacement)


def test_flexible_ring_unloads_roller_row_and_converges():
    ring = outer_ring(G, bending=False)
    flex = solve_flexible(MODEL, LOADS, ring)
    rigid = solve(MODEL, LOADS)
    assert flex.converged.all() and (flex.iterations < 15).all()
    assert (flex.offset_change <= 1e-11 + 1e-8 * 1e-4).all()
    share_f = flex.row_load("roller_2")[:, 0] / LOADS[:, 0]
    share_r = rigid.row_load("roller_2")[:, 0] / LOADS[:, 0]
    assert np.all(share_f < share_r)
    # equilibrium: the rows carry the external load
    total = sum(flex.row_load(n) for n in ("ball_1", "roller_2", "ball_3"))
    assert np.allclose(total[:, :3], LOADS[:, :3], rtol=1e-8, atol=1e-6)
    # the beam opening equals FL³/(48 EI) of the roller row force
    span = 0.05
    expected = flex.row_load("roller_2")[:, 0] * span**3 / (48 * ring.beam_rigidity)
    assert np.allclose(flex.offsets["roller_2"].radial[:, 0], expected, rtol=1e-6)


def test_aitken_beats_constant_relaxation():
    ring = outer_ring(G, bending=False, compliance_scale=3.0)
    ait = solve_flexible(MODEL, LOADS[1:], ring, method="aitken")
    rel = solve_flexible(MODEL, LOADS[1:], ring, method="relaxed", relaxation=0.5, max_iterations=40)
    assert ait.converged.all()
    assert not rel.converged.all() or rel.iterations[0] > ait.iterations[0]


def test_bad_input():
    sec = RingSection.rectangular(0.075, 0.008, 0.195)
    with pytest.raises(InputError, match="support span"):
        FlexibleOuterRing(sec, support_positions=(-0.05, 0.05))
    with pytest.raises(InputError, match="method"):
        solve_flexible(MODEL, LOADS, outer_ring(G), method="newton")
    with pytest.raises(InputError, match="relaxation"):
        solve_flexible(MODEL, LOADS, outer_ring(G), relaxation=1.5)
    with pytest.raises(InputError, match="youngs_modulus"):
        FlexibleOuterRing(sec, youngs_modulus=-1.0)
