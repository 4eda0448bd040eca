"""Seed-000 §6.1.1/§6.1.3 mechanisms in the statics of the composite turntable bearing."""

import numpy as np
import pytest

from bearingkit.papers.tian2025.statics import clearance_map, eccentricity_sweep


@pytest.fixture(scope="module")
def cmap():
    return clearance_map()


def test_all_cases_converge(cmap):
    assert cmap["converged"].all()


def test_axial_load_balances(cmap):
    carried = sum(
        cmap[f"{r}_axial_N"] * s
        for r, s in (("roller_upper", 1), ("ball_upper", 1), ("roller_lower", -1), ("ball_lower", -1))
    )
    np.testing.assert_allclose(carried, 5000.0, rtol=1e-8)


def test_both_roller_rows_loaded_only_at_minus_two_micron(cmap):
    """§6.1.1: at roller clearance −2 µm both the upper and the lower axial roller rows carry load."""
    lower = cmap.set_index(["roller_clearance_m", "ball_clearance_m"])["roller_lower_axial_N"]
    assert (lower.loc[-2e-6] > 0).all()
    assert (lower.loc[0.0] == 0).all() and (lower.loc[-1e-6] == 0).all()


def test_ball_share_grows_with_ball_preload(cmap):
    for _, grp in cmap.groupby("roller_clearance_m"):
        share = grp.sort_values("ball_clearance_m", ascending=False)["ball_axial_share"].to_numpy()
        assert np.all(np.diff(share) > 0)


def test_roller_preload_takes_load_from_balls(cmap):
    for _, grp in cmap.groupby("ball_clearance_m"):
        share = grp.sort_values("roller_clearance_m", ascending=False)["ball_axial_share"].to_numpy()
        assert np.all(np.diff(share) < 0)


def test_rollers_carry_most_of_the_axial_load(cmap):
    """Conclusion (1) of seed 000: the rollers dominate (here: they carry most of F_a everywhere)."""
    assert (cmap["ball_axial_share"] < 0.5).all()


def test_eccentricity_raises_every_axial_row_and_loads_the_lower_rows():
    ecc = eccentricity_sweep()
    assert ecc["converged"].all()
    for row in ("roller_upper", "ball_upper", "roller_lower", "ball_lower"):
        assert np.all(np.diff(ecc[f"{row}_max_load_N"]) > 0)
    assert ecc["roller_lower_max_load_N"].iloc[0] == 0 and ecc["roller_lower_max_load_N"].iloc[-1] > 0
    assert np.all(np.diff(ecc["theta_y_rad"]) < 0)  # M_y = −e F_a tilts the ring about −y
