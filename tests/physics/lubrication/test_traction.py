"""Tests of bearingkit.physics.lubrication.traction: closed forms, odd symmetry, bounds, limits, registry."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingkit.errors import InputError
from bearingkit.physics.lubrication import traction
from bearingkit.references import cite

slip = st.floats(min_value=-5.0, max_value=5.0, allow_nan=False)
LS = dict(
    entrainment_speed=5.0,
    viscosity=0.05,
    pressure_viscosity=1.0e-8,
    mean_pressure=1.0e9,
    film_central=3.0e-7,
)


def test_boundary_constant_and_signed():
    assert traction.traction_boundary() == traction.MU_BOUNDARY
    np.testing.assert_array_equal(
        traction.traction_boundary(0.1, np.array([-0.2, 0.0, 0.3])), np.array([-0.1, 0.0, 0.1])
    )
    with pytest.raises(InputError, match="mu_boundary"):
        traction.traction_boundary(-0.1)


def test_aihara_closed_form():
    mu = traction.traction_aihara(0.05, 0.06, 0.05)
    assert mu == pytest.approx(0.06 * (1 - np.exp(-2.6)), rel=1e-14)
    assert traction.traction_aihara(0.0, 0.06, 0.05) == 0.0


@settings(max_examples=100, deadline=None)
@given(s=slip, ds=st.floats(min_value=1e-6, max_value=1.0))
def test_aihara_odd_bounded_monotone(s, ds):
    mu_max, s_max = 0.07, 0.04
    mu = traction.traction_aihara(s, mu_max, s_max)
    assert traction.traction_aihara(-s, mu_max, s_max) == pytest.approx(-mu, abs=1e-15)
    assert abs(mu) <= mu_max
    assert np.sign(mu) == np.sign(s) or mu == 0.0
    grown = traction.traction_aihara(abs(s) + ds, mu_max, s_max)
    assert grown >= abs(mu)


def test_limiting_shear_limits():
    # tiny slip: Newtonian, μ ≈ η |Δu| / (h p̄); large slip: μ → Λ_L
    eta = LS["viscosity"] * np.exp(LS["pressure_viscosity"] * LS["mean_pressure"])
    s_small = 1e-9
    mu_small = traction.traction_limiting_shear(s_small, **LS)
    newton = eta * s_small * LS["entrainment_speed"] / (LS["film_central"] * LS["mean_pressure"])
    assert mu_small == pytest.approx(newton, rel=1e-3)
    mu_big = traction.traction_limiting_shear(1.0, **LS)
    assert mu_big == pytest.approx(traction.LIMITING_SHEAR_COEFF, rel=1e-9)
    assert traction.traction_limiting_shear(0.0, **LS) == 0.0
    # huge α p̄ must not overflow into NaN
    mu_hot = traction.traction_limiting_shear(0.1, **{**LS, "pressure_viscosity": 1e-6})
    assert np.isfinite(mu_hot) and mu_hot == pytest.approx(traction.LIMITING_SHEAR_COEFF)


@settings(max_examples=100, deadline=None)
@given(s=slip, ds=st.floats(min_value=1e-9, max_value=1.0))
def test_limiting_shear_odd_bounded_monotone(s, ds):
    kw = {**LS, "pressure_viscosity": 1e-9}  # soft enough that the curve is not saturated at once
    mu = traction.traction_limiting_shear(s, **kw)
    assert traction.traction_limiting_shear(-s, **kw) == pytest.approx(-mu, abs=1e-15)
    assert abs(mu) <= traction.LIMITING_SHEAR_COEFF
    assert traction.traction_limiting_shear(abs(s) + ds, **kw) >= abs(mu)


def test_mixed_limits():
    mu_bl, mu_ehl = 0.12, 0.03
    assert traction.traction_mixed(0.0, mu_ehl, mu_bl) == pytest.approx(mu_bl)
    assert traction.traction_mixed(20.0, mu_ehl, mu_bl) == pytest.approx(mu_ehl, rel=1e-12)
    lam = 1.0
    fa = np.exp(-1.8)
    assert traction.traction_mixed(lam, mu_ehl, mu_bl) == pytest.approx(fa * mu_bl + (1 - fa) * mu_ehl)
    # signed: boundary part follows the slip direction
    assert traction.traction_mixed(0.0, -0.03, 0.12, slide_to_roll=-0.1) == pytest.approx(-0.12)


@settings(max_examples=100, deadline=None)
@given(
    lam=st.floats(min_value=0.0, max_value=10.0),
    dlam=st.floats(min_value=1e-6, max_value=5.0),
    mu_ehl=st.floats(min_value=0.0, max_value=0.1),
)
def test_mixed_monotone_in_lambda(lam, dlam, mu_ehl):
    mu_bl = 0.12
    a = traction.traction_mixed(lam, mu_ehl, mu_bl)
    b = traction.traction_mixed(lam + dlam, mu_ehl, mu_bl)
    assert b <= a + 1e-15  # μ_bl >= μ_EHL: more film, less friction
    assert min(mu_bl, mu_ehl) - 1e-15 <= a <= max(mu_bl, mu_ehl) + 1e-15


def test_flange_friction_force_seed001_eq9():
    q, mu0 = 800.0, 0.1
    assert traction.flange_friction_force(q, 0.0, mu0) == pytest.approx(80.0)
    assert traction.flange_friction_force(q, 2.0, mu0) == pytest.approx(80.0 * np.exp(-1.8 * 2.0**1.2))
    forces = traction.flange_friction_force(q, np.linspace(0, 4, 20), mu0)
    assert np.all(np.diff(forces) < 0)
    with pytest.raises(InputError, match="flange_load"):
        traction.flange_friction_force(-1.0, 1.0)


def test_registry_and_dispatch():
    assert set(traction.TRACTION_MODEL_REFERENCES) == set(traction.TRACTION_MODELS)
    for key in traction.TRACTION_MODEL_REFERENCES.values():
        assert cite(key)
    assert set(traction.TRACTION_MODELS) == {"boundary", "aihara", "limiting_shear", "mixed"}
    mu = traction.traction_coefficient("aihara", slide_to_roll=0.02, mu_max=0.06, slide_to_roll_at_max=0.05)
    assert mu == pytest.approx(traction.traction_aihara(0.02, 0.06, 0.05))
    with pytest.raises(InputError, match=r"traction_model.*aihara"):
        traction.traction_coefficient("eyring", slide_to_roll=0.1)
    with pytest.raises(InputError, match="traction_model"):
        traction.traction_coefficient("aihara", slide_to_roll=0.1)  # missing mu_max


@pytest.mark.parametrize(
    "kwargs,field",
    [
        (dict(slide_to_roll=np.nan, mu_max=0.06, slide_to_roll_at_max=0.05), "slide_to_roll"),
        (dict(slide_to_roll=0.1, mu_max=-0.06, slide_to_roll_at_max=0.05), "mu_max"),
        (dict(slide_to_roll=0.1, mu_max=0.06, slide_to_roll_at_max=0.0), "slide_to_roll_at_max"),
    ],
)
def test_aihara_bad_input(kwargs, field):
    with pytest.raises(InputError, match=field):
        traction.traction_aihara(**kwargs)


def test_limiting_shear_bad_input():
    with pytest.raises(InputError, match="film_central"):
        traction.traction_limiting_shear(0.1, **{**LS, "film_central": 0.0})
    with pytest.raises(InputError, match="mean_pressure"):
        traction.traction_limiting_shear(0.1, **{**LS, "mean_pressure": -1.0})


def test_broadcast():
    s = np.linspace(-0.1, 0.1, 7)[:, None]
    mu_max = np.array([0.05, 0.08])[None, :]
    assert traction.traction_aihara(s, mu_max, 0.03).shape == (7, 2)
    assert traction.traction_limiting_shear(s, **LS).shape == (7, 1)
