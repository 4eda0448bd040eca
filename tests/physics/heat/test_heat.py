"""Heat flows out of a bearing and the batched root finder of the heat balance."""

from __future__ import annotations

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.physics.heat import dissipation, root


def test_heat_flows_are_their_formulas():
    assert dissipation.conductance_of_surface(0.12, 15.0) == pytest.approx(1.8)
    np.testing.assert_allclose(dissipation.conducted_heat(2.0, [20.0, 70.0], 20.0), [0.0, 100.0])
    # 0.5 l/min of oil, 870 kg/m³, 1900 J/(kg K), 10 K warmer out than in: rho c V dT by hand
    q = dissipation.oil_heat(0.5e-3 / 60, 870.0, 1900.0, 50.0, 40.0)
    assert q == pytest.approx(870.0 * 1900.0 * 0.5e-3 / 60 * 10.0, rel=1e-12)
    with pytest.raises(InputError, match="oil_flow"):
        dissipation.oil_heat(-1.0, 870.0, 1900.0, 50.0, 40.0)


def test_root_of_a_closed_form_balance_batched():
    # P(T) = P0 exp(-(T - 20)/b) falls as the oil thins; Phi(T) = H (T - 20). Reference root by a long
    # bisection written here.
    p0 = np.array([50.0, 200.0, 5.0])
    b, h = 60.0, 1.5

    def balance(t):
        p = p0 * np.exp(-(t - 20.0) / b)
        return p - h * (t - 20.0), p

    res = root.solve_decreasing(balance, np.full(3, 20.0), np.full(3, 250.0), np.full(3, h), rtol=1e-9)
    lo, hi = np.full(3, 20.0), np.full(3, 250.0)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        pos = balance(mid)[0] > 0
        lo, hi = np.where(pos, mid, lo), np.where(pos, hi, mid)
    assert res.converged.all() and not res.no_root.any()
    np.testing.assert_allclose(res.x, 0.5 * (lo + hi), rtol=1e-8)
    assert np.all(np.abs(res.value) <= 1e-9 * res.scale)
    assert res.iterations.max() <= 12  # secant, not bisection


def test_no_root_below_the_upper_limit_is_reported():
    def balance(t):
        p = np.full_like(t, 1000.0)
        return p - 0.1 * (t - 20.0), p

    res = root.solve_decreasing(balance, np.array([20.0]), np.array([250.0]), np.array([0.1]))
    assert res.no_root[0] and not res.converged[0] and res.x[0] == pytest.approx(250.0)
