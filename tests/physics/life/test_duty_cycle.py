"""Palmgren–Miner over a duty cycle: closed forms of the linear damage sum."""

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.physics.life import duty_cycle as dc


def test_one_bin_and_equal_bins_keep_the_life():
    assert dc.miner_life([5e8], [1.0]) == pytest.approx(5e8, rel=1e-15)
    # the same life in every bin: the cycle has that life, whatever the shares
    assert dc.miner_life([2e7, 2e7, 2e7], [0.2, 0.5, 0.3]) == pytest.approx(2e7, rel=1e-15)


def test_miner_sum_equals_the_iso281_mean_equivalent_load():
    """L_i = (C/P_i)^p → L = (C/P_m)^p with P_m = (Σ U_i P_i^p)^(1/p) (ISO 281 variable load)."""
    c, p = 30e3, 3.0
    loads = np.array([2e3, 5e3, 9e3])
    u = np.array([0.5, 0.3, 0.2])
    lives = 1e6 * (c / loads) ** p
    p_mean = np.sum(u * loads**p) ** (1 / p)
    assert dc.miner_life(lives, u) == pytest.approx(1e6 * (c / p_mean) ** p, rel=1e-13)


def test_time_fractions_weigh_by_speed_and_rest_does_no_damage():
    t = np.array([0.6, 0.3, 0.1])
    n = np.array([300.0, -150.0, 0.0])  # rad/s; the sign is the direction only
    u = dc.revolution_fractions(t, n, "time")
    np.testing.assert_allclose(u, [0.8, 0.2, 0.0], rtol=1e-15)
    lives = np.array([4e9, 6e7, 1.0])  # the bin at rest has a tiny life: it must not count
    life = dc.miner_life(lives, u)
    assert life == pytest.approx(1.0 / (0.8 / 4e9 + 0.2 / 6e7), rel=1e-14)
    # hours: revolutions over the mean rate Σ t |n| / 2π
    rate = dc.mean_revolution_rate(t, n, "time")
    assert rate == pytest.approx((0.6 * 300 + 0.3 * 150) / (2 * np.pi), rel=1e-15)
    # from revolution fractions (t_i ∝ U_i / n_i) the time at rest is unknown: the rate of the turning time
    assert dc.mean_revolution_rate(u[:2], n[:2], "revolutions") == pytest.approx(rate / 0.9, rel=1e-14)


def test_unloaded_bin_and_unknown_life():
    assert dc.miner_life([np.inf, 1e8], [0.5, 0.5]) == pytest.approx(2e8, rel=1e-15)
    assert np.isposinf(dc.miner_life([np.inf, np.inf], [0.5, 0.5]))
    assert np.isnan(dc.miner_life([np.nan, 1e8], [0.5, 0.5]))
    assert dc.miner_life([np.nan, 1e8], [0.0, 1.0]) == pytest.approx(1e8)  # a bin without revolutions
    np.testing.assert_allclose(dc.damage_shares([1e8, 3e8], [0.5, 0.5]), [0.75, 0.25], rtol=1e-15)


def test_batched_over_leading_axes():
    lives = np.array([[1e8, 2e8], [4e8, 4e8]])
    got = dc.miner_life(lives, [[0.5, 0.5], [0.5, 0.5]])
    np.testing.assert_allclose(got, [1.0 / (0.5e-8 + 0.25e-8), 4e8], rtol=1e-15)


def test_bad_kind_and_missing_speeds():
    with pytest.raises(InputError, match="fraction kind"):
        dc.revolution_fractions([1.0], [1.0], "hours")
    with pytest.raises(InputError, match="need the speed"):
        dc.revolution_fractions([1.0], None, "time")
