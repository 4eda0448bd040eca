"""Tests of bearingkit.physics.lubrication.ehl: closed forms, scaling invariants, input checking."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingkit.errors import InputError
from bearingkit.physics.lubrication import ehl
from bearingkit.references import cite

# A steel ball–inner-race contact of typical size (SI): E' of steel on steel, mineral oil.
BALL = dict(
    viscosity=0.04,
    entrainment_speed=6.25,
    pressure_viscosity=2.3e-8,
    e_reduced=2.28e11,
    radius_x=5.1e-3,
    radius_y=0.165,
    load=4944.0,
)
ROLLER = dict(
    viscosity=0.01,
    entrainment_speed=10.0,
    pressure_viscosity=2.2e-8,
    e_reduced=2.28e11,
    radius_x=6.4e-3,
    load=3600.0,
    effective_length=0.016,
)


def test_dimensionless_groups_closed_form():
    u_, g_, w_ = ehl.dimensionless_groups(0.04, 6.0, 2.0e-8, 2.0e11, 5.0e-3, 1000.0)
    assert u_ == pytest.approx(0.04 * 6.0 / (2.0e11 * 5.0e-3), rel=1e-14)
    assert g_ == pytest.approx(4000.0, rel=1e-14)
    assert w_ == pytest.approx(1000.0 / (2.0e11 * 25e-6), rel=1e-14)
    _, _, w_line = ehl.dimensionless_groups(0.04, 6.0, 2.0e-8, 2.0e11, 5.0e-3, 1000.0, effective_length=0.01)
    assert w_line == pytest.approx(1000.0 / (2.0e11 * 5.0e-3 * 0.01), rel=1e-14)


def test_hamrock_dowson_closed_form_circular_contact():
    # Equal radii: k from Hamrock–Brewe is 1.0339; both films written out by hand.
    rx = 0.01
    u_, g_, w_ = 1e-11, 5000.0, 1e-6
    e = 2e11
    eta = u_ * e * rx / 5.0  # viscosity for speed 5 m/s
    q = w_ * e * rx**2
    f = ehl.film_point_hamrock_dowson(eta, 5.0, g_ / e, e, rx, rx, q)
    k = 1.0339
    hc = rx * 2.69 * u_**0.67 * g_**0.53 * w_**-0.067 * (1 - 0.61 * np.exp(-0.73 * k))
    hm = rx * 3.63 * u_**0.68 * g_**0.49 * w_**-0.073 * (1 - np.exp(-0.68 * k))
    assert f.central == pytest.approx(hc, rel=1e-12)
    assert f.minimum == pytest.approx(hm, rel=1e-12)


def test_ellipticity_hamrock_brewe_matches_1977_rounded_form():
    # H&D 1977 abstract gives k = 1.03 (Ry/Rx)^0.64; Hamrock–Brewe refines it (within ~1 %).
    ratio = np.array([1.0, 5.0, 20.0, 32.0])
    k = ehl.ellipticity_hamrock_brewe(1.0, ratio)
    np.testing.assert_allclose(k, 1.03 * ratio**0.64, rtol=0.02)


def test_point_film_minimum_below_central_for_bearing_contact():
    f = ehl.film_point_hamrock_dowson(**BALL)
    assert 0 < f.minimum < f.central
    # order of magnitude for a loaded ball–race contact: sub-micrometre
    assert 1e-8 < f.minimum < 5e-6


def test_line_films_pan_hamrock_closed_form_and_dh_relation():
    f = ehl.film_line_pan_hamrock(**ROLLER)
    u_, g_, w_ = ehl.dimensionless_groups(**ROLLER)
    rx = ROLLER["radius_x"]
    assert f.minimum == pytest.approx(rx * 1.714 * w_**-0.128 * u_**0.694 * g_**0.568, rel=1e-12)
    assert f.central == pytest.approx(rx * 2.922 * w_**-0.166 * u_**0.692 * g_**0.470, rel=1e-12)
    dh = ehl.film_line_dowson_higginson(**ROLLER)
    assert dh.minimum == pytest.approx(rx * 2.65 * u_**0.70 * g_**0.54 * w_**-0.13, rel=1e-12)
    assert dh.central == pytest.approx(4.0 / 3.0 * dh.minimum, rel=1e-12)
    # two independent fits of the same physics agree to within ~30 % in the bearing range
    assert dh.minimum == pytest.approx(f.minimum, rel=0.3)


def test_zero_speed_gives_zero_film_not_nan():
    for f in (
        ehl.film_point_hamrock_dowson(**{**BALL, "entrainment_speed": 0.0}),
        ehl.film_line_pan_hamrock(**{**ROLLER, "entrainment_speed": 0.0}),
        ehl.film_line_dowson_higginson(**{**ROLLER, "entrainment_speed": 0.0}),
    ):
        assert f.central == 0.0 and f.minimum == 0.0


@pytest.mark.parametrize("load", [0.0, -1.0])
def test_non_positive_load_raises(load):
    with pytest.raises(InputError, match="load"):
        ehl.film_point_hamrock_dowson(**{**BALL, "load": load})
    with pytest.raises(InputError, match="load"):
        ehl.film_line_pan_hamrock(**{**ROLLER, "load": load})


@pytest.mark.parametrize(
    "field,value",
    [
        ("viscosity", -0.01),
        ("entrainment_speed", -1.0),
        ("pressure_viscosity", 0.0),
        ("e_reduced", np.nan),
        ("radius_x", 0.0),
        ("radius_y", -1.0),
    ],
)
def test_bad_point_inputs_raise_naming_field(field, value):
    with pytest.raises(InputError, match=field):
        ehl.film_point_hamrock_dowson(**{**BALL, field: value})


def test_bad_effective_length_raises():
    with pytest.raises(InputError, match="effective_length"):
        ehl.film_line_dowson_higginson(**{**ROLLER, "effective_length": 0.0})


def test_broadcasting_over_cases():
    speeds = np.linspace(1.0, 10.0, 4)[:, None]
    loads = np.array([1000.0, 2000.0, 4000.0])[None, :]
    f = ehl.film_point_hamrock_dowson(**{**BALL, "entrainment_speed": speeds, "load": loads})
    assert f.central.shape == (4, 3) and f.minimum.shape == (4, 3)
    single = ehl.film_point_hamrock_dowson(**{**BALL, "entrainment_speed": 4.0, "load": 2000.0})
    assert f.central[1, 1] == pytest.approx(float(single.central), rel=1e-14)


def test_registry_dispatch_and_unknown_name():
    assert set(ehl.FILM_MODEL_REFERENCES) == set(ehl.FILM_MODELS)
    for key in ehl.FILM_MODEL_REFERENCES.values():
        assert cite(key)
    assert set(ehl.FILM_MODELS) == {"hamrock_dowson", "dowson_higginson", "pan_hamrock"}
    f = ehl.film_thickness("pan_hamrock", **ROLLER)
    assert f.minimum == pytest.approx(float(ehl.film_line_pan_hamrock(**ROLLER).minimum))
    with pytest.raises(InputError, match=r"film_model.*dowson_higginson"):
        ehl.film_thickness("grubin", **ROLLER)
    with pytest.raises(InputError, match="film_model"):
        ehl.film_thickness("pan_hamrock", **BALL)  # radius_y is not a line-contact argument


# --- invariants -------------------------------------------------------------------------------
positive_scale = st.floats(min_value=1.01, max_value=100.0)


@settings(max_examples=60, deadline=None)
@given(scale=positive_scale)
def test_film_scaling_with_speed_viscosity_load(scale):
    base = ehl.film_point_hamrock_dowson(**BALL)
    faster = ehl.film_point_hamrock_dowson(**{**BALL, "entrainment_speed": BALL["entrainment_speed"] * scale})
    thicker = ehl.film_point_hamrock_dowson(**{**BALL, "viscosity": BALL["viscosity"] * scale})
    heavier = ehl.film_point_hamrock_dowson(**{**BALL, "load": BALL["load"] * scale})
    # exact power laws of the regression: h_c ∝ (η u)^0.67, h_min ∝ (η u)^0.68, h ∝ Q^-0.067/-0.073
    assert faster.central / base.central == pytest.approx(scale**0.67, rel=1e-10)
    assert faster.minimum / base.minimum == pytest.approx(scale**0.68, rel=1e-10)
    assert thicker.central / base.central == pytest.approx(scale**0.67, rel=1e-10)
    assert heavier.central / base.central == pytest.approx(scale**-0.067, rel=1e-10)
    assert heavier.minimum / base.minimum == pytest.approx(scale**-0.073, rel=1e-10)
    assert faster.central > base.central and heavier.central < base.central
    # load dependence is weak: a 100-fold load costs less than 30 % of film
    assert heavier.minimum / base.minimum > 0.7


@settings(max_examples=60, deadline=None)
@given(scale=positive_scale)
def test_line_film_monotone(scale):
    for fn in (ehl.film_line_pan_hamrock, ehl.film_line_dowson_higginson):
        base = fn(**ROLLER)
        faster = fn(**{**ROLLER, "entrainment_speed": ROLLER["entrainment_speed"] * scale})
        heavier = fn(**{**ROLLER, "load": ROLLER["load"] * scale})
        longer = fn(**{**ROLLER, "effective_length": ROLLER["effective_length"] * scale})
        assert faster.minimum > base.minimum and faster.central > base.central
        assert heavier.minimum < base.minimum and heavier.central < base.central
        assert longer.minimum > base.minimum  # same load spread over a longer line


@settings(max_examples=60, deadline=None)
@given(
    h=st.floats(min_value=0.0, max_value=1e-5),
    r1=st.floats(min_value=1e-9, max_value=1e-6),
    r2=st.floats(min_value=0.0, max_value=1e-6),
    scale=positive_scale,
)
def test_film_parameter_scaling(h, r1, r2, scale):
    lam = ehl.film_parameter(h, r1, r2)
    assert lam == pytest.approx(h / np.sqrt(r1**2 + r2**2), rel=1e-12, abs=1e-300)
    assert ehl.film_parameter(h * scale, r1, r2) == pytest.approx(lam * scale, rel=1e-12, abs=1e-300)
    assert ehl.film_parameter(h, r1 * scale, r2 * scale) == pytest.approx(lam / scale, rel=1e-12, abs=1e-300)
    assert ehl.film_parameter(h, r1, r2) == pytest.approx(ehl.film_parameter(h, r2, r1) if r2 > 0 else lam)


def test_film_parameter_bad_input():
    with pytest.raises(InputError, match="roughness"):
        ehl.film_parameter(1e-7, 0.0, 0.0)
    with pytest.raises(InputError, match="film_minimum"):
        ehl.film_parameter(-1e-7, 1e-7, 1e-7)


def test_starvation_factor_limits_and_closed_form():
    h, rx, b = 5e-7, 5e-3, 2e-4
    f_star = 3.06 * ((rx / b) ** 2 * h / rx) ** 0.58
    half = ehl.starvation_factor(h, rx, b, 0.5 * f_star * b)
    assert half == pytest.approx(0.5**0.29, rel=1e-12)
    assert ehl.starvation_factor(h, rx, b, 2.0 * f_star * b) == 1.0  # fully flooded
    assert ehl.starvation_factor(h, rx, b, 0.0) == 0.0  # meniscus at the contact edge
    f_star_min = 3.34 * ((rx / b) ** 2 * h / rx) ** 0.56
    assert ehl.starvation_factor(h, rx, b, 0.5 * f_star_min * b, film="minimum") == pytest.approx(0.5**0.25)
    distances = np.linspace(0.0, 3 * f_star * b, 50)
    factors = ehl.starvation_factor(h, rx, b, distances)
    assert np.all(np.diff(factors) >= 0) and factors.shape == (50,)
    with pytest.raises(InputError, match="film"):
        ehl.starvation_factor(h, rx, b, 1e-4, film="mean")
    with pytest.raises(InputError, match="inlet_distance"):
        ehl.starvation_factor(h, rx, b, -1e-4)


def test_thermal_reduction_factor():
    assert ehl.thermal_reduction_factor(0.05, 0.03, 0.0, 0.13) == 1.0
    # closed form at L = 1 (φ = 3.94/4.94)
    k_oil, beta, eta = 0.13, 0.03, 0.05
    u = np.sqrt(k_oil / (eta * beta))
    assert ehl.thermal_reduction_factor(eta, beta, u, k_oil) == pytest.approx(3.94 / 4.94, rel=1e-12)
    phi = ehl.thermal_reduction_factor(eta, beta, np.linspace(0, 50, 20), k_oil)
    assert np.all(np.diff(phi) < 0) and np.all((phi > 0) & (phi <= 1))
    with pytest.raises(InputError, match="thermal_conductivity"):
        ehl.thermal_reduction_factor(eta, beta, 1.0, 0.0)


def test_mixed_load_share():
    assert ehl.mixed_load_share(0.0) == 1.0
    lam = np.linspace(0, 5, 30)
    share = ehl.mixed_load_share(lam)
    assert np.all(np.diff(share) < 0)
    assert ehl.mixed_load_share(3.0) == pytest.approx(np.exp(-1.8 * 3.0**1.2), rel=1e-14)
    assert ehl.mixed_load_share(10.0) < 1e-10
    with pytest.raises(InputError, match="film_parameter"):
        ehl.mixed_load_share(-0.1)


def test_film_thickness_dataclass_validates():
    with pytest.raises(InputError, match="film_central"):
        ehl.FilmThickness(central=np.array(-1.0), minimum=np.array(0.0))
    with pytest.raises(InputError, match="film_minimum"):
        ehl.FilmThickness(central=np.array(1.0), minimum=np.array(np.nan))
