"""Slewing-ring friction by the makers' formula and its pipeline model ``"slewing"``."""

from pathlib import Path

import pytest

import bearingkit as bk
from bearingkit.physics.friction.slewing import slewing_friction_moment

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"


def test_makers_formula_by_hand():
    """Rothe Erde: M_r = μ/2 (4.4 M_k + F_a D_L + 2.2·1.73 F_r D_L) (ball), μ/2 (4.1 M_k + F_a D_L +
    2.05 F_r D_L) (roller); here μ = 0.006, F_a = 250 kN, F_r = 20 kN, M_k = 450 kN·m, D_L = 1 m."""
    ball = slewing_friction_moment(250e3, 20e3, 450e3, 1.0, "ball", 0.006)
    assert float(ball) == pytest.approx(0.003 * (4.4 * 450e3 + 250e3 + 2.2 * 1.73 * 20e3), rel=1e-12)
    roller = slewing_friction_moment(250e3, 20e3, 450e3, 1.0, "roller", 0.006)
    assert float(roller) == pytest.approx(0.003 * (4.1 * 450e3 + 250e3 + 2.05 * 20e3), rel=1e-12)


def test_pipeline_model_slewing_and_refusal():
    a = bk.analyze(EXAMPLES / "slewing_four_point.toml", friction_model="slewing")
    f = a.friction
    assert f.model == "slewing" and f.total.shape == (3,)
    assert f.total[1] == pytest.approx(0.003 * (4.4 * 450e3 + 250e3 + 2.2 * 1.73 * 20e3), rel=1e-12)
    b = bk.analyze(EXAMPLES / "srb_22220.toml")
    with pytest.raises(bk.InputError, match="slewing"):
        b.friction_by("slewing")
