"""Carlson's R_F, R_D and the complete integrals in numpy (physics/contact/elliptic.py) against
scipy.special, the oracle (the package avoids importing it: ~0.3 s), and closed values."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import special

from bearingkit.physics.contact import elliptic


def test_complete_integrals_equal_scipys_over_every_ellipse():
    """p = 1 − m from 1e-14 (κ ≈ 10⁷) to 1: K and D to 2e-15 (a few ulp: 1.1e-15 measured), E to 2e-14
    (E = K − mD loses a digit as m → 1)."""
    p = np.concatenate([np.geomspace(1e-14, 1.0, 20000), np.random.default_rng(1).uniform(1e-6, 1.0, 20000)])
    k, e, d = elliptic.complete_integrals(p)
    assert k == pytest.approx(special.ellipkm1(p), rel=2e-15, abs=0)
    assert e == pytest.approx(special.ellipe(1.0 - p), rel=2e-14, abs=0)
    assert d == pytest.approx(special.elliprd(0.0, p, 1.0) / 3.0, rel=2e-15, abs=0)
    assert elliptic.ellipe(0.3) == pytest.approx(special.ellipe(0.3), rel=1e-15)


def test_closed_values():
    """K(0) = E(0) = π/2, D(0) = π/4; R_F(x, x, x) = x^(−1/2), R_D(x, x, x) = x^(−3/2); Legendre's
    relation EK' + E'K − KK' = π/2 at m = m' = 1/2 (DLMF 19.7.1)."""
    k, e, d = elliptic.complete_integrals(1.0)
    assert (k, e, d) == pytest.approx((np.pi / 2, np.pi / 2, np.pi / 4), rel=1e-15)
    rf, rd = elliptic.carlson_rf_rd(2.5, 2.5, 2.5)
    assert (rf, rd) == pytest.approx((2.5**-0.5, 2.5**-1.5), rel=1e-15)
    k, e, _ = elliptic.complete_integrals(0.5)
    assert 2 * e * k - k * k == pytest.approx(np.pi / 2, rel=1e-15)  # Legendre at m = m' = 1/2


@settings(max_examples=200, deadline=None)
@given(
    st.floats(0.0, 1e3),
    st.floats(1e-9, 1e3),
    st.floats(1e-9, 1e3),
)
def test_rf_rd_equal_scipys_for_any_arguments(x, y, z):
    rf, rd = elliptic.carlson_rf_rd(x, y, z)
    assert rf == pytest.approx(special.elliprf(x, y, z), rel=2e-15)
    assert rd == pytest.approx(special.elliprd(x, y, z), rel=2e-15)


def test_the_two_methods_agree():
    """The AGM's K, E, D against Carlson's R_F(0, p, 1), R_F − (m/3)R_D and R_D/3 (DLMF 19.25.1)."""
    p = np.geomspace(1e-12, 1.0, 5000)
    rf, rd = elliptic.carlson_rf_rd(0.0, p, 1.0)
    k, e, d = elliptic.complete_integrals(p)
    assert k == pytest.approx(rf, rel=1e-15, abs=0)
    assert d == pytest.approx(rd / 3.0, rel=2e-15, abs=0)
    assert e == pytest.approx(rf - (1.0 - p) * rd / 3.0, rel=2e-14, abs=0)


def test_batches_broadcast_and_leave_their_arguments_alone():
    y = np.array([[0.5, 1.0, 2.0]])
    z = np.array([[1.0], [3.0]])
    before = y.copy()
    rf, rd = elliptic.carlson_rf_rd(0.0, y, z)
    assert rf.shape == rd.shape == (2, 3)
    assert np.array_equal(y, before)
    assert rd[1, 2] == pytest.approx(special.elliprd(0.0, 2.0, 3.0), rel=2e-15)
