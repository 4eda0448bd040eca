"""Seed-002 ball–column bearing: examples load, rigid counts, outputs, bad input."""

from pathlib import Path

import numpy as np
import pytest

from bearingkit.analysis.quasistatic import load_vector, solve
from bearingkit.bearings.ball_column import ROWS, BallColumnGeometry, ball_column, load_example, outer_ring
from bearingkit.errors import InputError

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize("cond,fr,fa", [(1, 20e3, 0.0), (2, 30e3, 20e3), (3, 13.5e3, 0.0)])
def test_examples_load_and_solve(cond, fr, fa):
    g, load, ring = load_example(EXAMPLES / f"ball_column_condition{cond}.toml")
    assert load[0] == pytest.approx(fr) and load[2] == pytest.approx(fa)
    assert g.n_balls == 74 and g.n_rollers == 78 and g.ball_diameter == pytest.approx(0.015)
    res = solve(ball_column(replace_slices(g)), load)
    assert res.converged.all()
    total = sum(res.row_load(n) for n in ROWS)
    assert np.allclose(total[0, :3], load[:3], atol=1e-6 * fr)
    assert ring["bending"] is False


def replace_slices(g):
    from dataclasses import replace

    return replace(g, n_slices=6)


def test_rigid_roller_zone_is_half_the_rollers():
    """Zero clearance, pure radial load: the load zone is ±90°, 39 of 78 rollers (seed 002 §3.2)."""
    res = solve(ball_column(n_slices=4), load_vector(F_x=20e3))
    assert res.row("roller_2").loaded_count[0] == 39
    assert res.row("ball_1").loaded_count[0] == res.row("ball_3").loaded_count[0]


def test_bad_input():
    with pytest.raises(InputError, match="pitch_diameter"):
        BallColumnGeometry(pitch_diameter=0.41)
    with pytest.raises(InputError, match="n_elements"):
        ball_column(roller_diameter=0.016)  # Table 1's Ø16 rollers do not fit 78 on the pitch circle
    with pytest.raises(InputError, match="support span"):
        outer_ring(BallColumnGeometry(support_positions=(-0.05, 0.05)))
    with pytest.raises(InputError, match="clearance_ball"):
        BallColumnGeometry(clearance_ball=-1e-6)
