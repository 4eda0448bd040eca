"""Seed 001 friction physics: Roelands, tractive integral, F_ro, F_rs, kinematics, ring torques."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate, special

from bearingkit.errors import InputError
from bearingkit.physics.friction import trb as tf
from bearingkit.physics.friction import trb_rheology as rh
from bearingkit.physics.lubrication import ehl

ETA = 0.04  # Pa·s
ALPHA = 2e-8  # 1/Pa
E_RED = 2.276e11  # Pa
R_X = 2.86e-3  # m
L = 13.66e-3  # m


def test_roelands_ratio_is_one_at_zero_pressure_and_slope_alpha():
    assert rh.roelands_viscosity_ratio(0.0, ETA) == pytest.approx(1.0)
    z = rh.roelands_exponent(ALPHA, ETA)
    dp = 1e3
    slope = np.log(rh.roelands_viscosity_ratio(dp, ETA, z)) / dp
    assert slope == pytest.approx(ALPHA, rel=1e-4)  # d ln η/dp at p = 0 equals Barus α


def test_roelands_rejects_viscosity_below_eta_inf():
    with pytest.raises(InputError, match="viscosity"):
        rh.roelands_viscosity_ratio(1e8, 5e-5)


def test_tractive_integral_limits():
    assert rh.tractive_integral(0.0, 7e-5, ETA) == pytest.approx(7e-5, rel=1e-12)  # I = b
    assert rh.tractive_integral(1e9, 0.0, ETA) == 0.0


def test_tractive_integral_closed_form_for_linear_exponent():
    # Z = 1: η/η0 = exp(c cos θ); ∫0^{π/2} e^{c cosθ} cosθ dθ = (π/2)[I1(c) + L1(c)] + 1.
    p_max, b = 6e8, 5e-5
    c = (np.log(ETA) + rh.ROELANDS_LN_ETA_INF) * p_max / rh.ROELANDS_PRESSURE
    exact = b * (0.5 * np.pi * (special.iv(1, c) + special.modstruve(1, c)) + 1.0)
    assert rh.tractive_integral(p_max, b, ETA, 1.0) == pytest.approx(exact, rel=1e-10)


@pytest.mark.parametrize("p_max", [3e8, 1.3e9, 2.5e9])
def test_tractive_integral_against_adaptive_quadrature(p_max):
    b = 6e-5

    def f(x):
        return rh.roelands_viscosity_ratio(p_max * np.sqrt(max(1.0 - (x / b) ** 2, 0.0)), ETA)

    ref = integrate.quad(f, 0.0, b, epsabs=0, epsrel=1e-12, limit=200)[0]
    assert rh.tractive_integral(p_max, b, ETA) == pytest.approx(ref, rel=1e-8)


def test_tractive_integral_broadcasts():
    out = rh.tractive_integral(np.array([[1e8, 1e9]]), np.array([[1e-5], [2e-5]]), ETA)
    assert out.shape == (2, 2)
    assert out[1, 0] == pytest.approx(2 * out[0, 0])


def _rolling(load=1776.0, u=1.39, model="aihara1987"):
    return tf.rolling_friction_force(load, ETA, u, ALPHA, E_RED, R_X, L, model)


def test_rolling_friction_exponents_and_zero_load():
    assert _rolling(2 * 1776.0) / _rolling() == pytest.approx(2**0.31)
    assert _rolling(u=2.78) / _rolling() == pytest.approx(2**0.658)
    assert _rolling(0.0) == 0.0
    assert _rolling(u=0.0) == 0.0
    assert _rolling(model="aihara1987") / _rolling(model="liu2022_literal") == pytest.approx(1e4)


def test_rolling_friction_is_dimensionally_consistent():
    # Same contact in the mm–N–MPa system: the force in N must be unchanged.
    si = _rolling()
    mm = tf.rolling_friction_force(1776.0, ETA * 1e-6, 1.39e3, ALPHA * 1e6, E_RED * 1e-6, R_X * 1e3, L * 1e3)
    assert mm == pytest.approx(si, rel=1e-12)


def test_rolling_friction_magnitude_is_hydrodynamic():
    # Aihara's reading (C = 88) gives a rolling-resistance coefficient F/Q of order 1e-4..1e-3 for a
    # bearing contact (EHL rolling friction is far below sliding friction; Aihara 1987).
    mu = _rolling() / 1776.0
    assert 1e-5 < mu < 1e-2


def _sliding(
    vs=2.5e-4, load=1776.0, u=1.39, z=rh.ROELANDS_EXPONENT_LIU2022, model="limiting_shear", lam=None
):
    kw = {} if lam is None else {"limiting_shear_coeff": lam}
    return tf.sliding_friction_force(vs, load, ETA, u, ALPHA, E_RED, R_X, L, z, model=model, **kw)


def test_newtonian_sliding_traction_is_linear_and_odd_in_slide_speed():
    n = "newtonian"
    assert _sliding(5e-4, model=n) / _sliding(2.5e-4, model=n) == pytest.approx(2.0, rel=1e-12)
    assert _sliding(-2.5e-4, model=n) == pytest.approx(-_sliding(2.5e-4, model=n))
    assert _sliding(0.0, model=n) == 0.0
    assert _sliding(load=0.0, model=n) == 0.0


def test_limited_sliding_traction_is_odd_monotone_and_sublinear():
    assert _sliding(-2.5e-4) == pytest.approx(-_sliding(2.5e-4), rel=1e-12)
    assert _sliding(0.0) == 0.0 and _sliding(load=0.0) == 0.0
    f = _sliding(np.array([1e-6, 1e-5, 1e-4, 2.5e-4, 1e-3, 1e-2]))
    assert np.all(np.diff(f) > 0)
    assert np.all(np.diff(f / [1e-6, 1e-5, 1e-4, 2.5e-4, 1e-3, 1e-2]) < 0)  # F/v_s falls: saturating


def test_sliding_traction_equals_newtonian_shear_with_implied_film():
    # eq. (8) = v_s η0 l I / h* with h* = R U^0.74 G^0.4 W^-0.2 / 0.168
    from bearingkit.physics.contact.line import line_contact

    c = line_contact(1776.0, L, R_X, E_RED)
    i = rh.tractive_integral(c.max_pressure, c.half_width, ETA)
    h = tf.sliding_film_thickness(ETA, 1.39, ALPHA, E_RED, R_X, 1776.0, L)
    assert _sliding(model="newtonian") == pytest.approx(2.5e-4 * ETA * L * i / h, rel=1e-12)


@pytest.mark.parametrize("load", [355.0, 1776.0, 2500.0])
def test_implied_film_is_the_central_film_over_the_full_strip(load):
    # Reading check of eqs. (8), (10): I runs over half the strip; Newtonian shear over the whole
    # strip (2I) at a film 2h* must be the EHL central film. Pan & Hamrock (1989): within 10 %.
    h = tf.sliding_film_thickness(ETA, 1.39, ALPHA, E_RED, R_X, load, L)
    hc = ehl.film_line_pan_hamrock(ETA, 1.39, ALPHA, E_RED, R_X, load, L).central
    assert 2 * h / hc == pytest.approx(1.0, abs=0.1)


@pytest.mark.parametrize("p_max, rate", [(3e8, 1e3), (1.3e9, 1e2), (1.3e9, 1e4), (2.5e9, 1e3)])
def test_limited_shear_integral_against_adaptive_quadrature(p_max, rate):
    b, lam = 6e-5, 0.075

    def tau(x):
        p = p_max * np.sqrt(max(1.0 - (x / b) ** 2, 0.0))
        if p == 0.0:
            return 0.0
        tau_n = ETA * rh.roelands_viscosity_ratio(p, ETA) * rate
        return lam * p * -np.expm1(-tau_n / (lam * p))

    ref = 2.0 * integrate.quad(tau, 0.0, b, epsabs=0, epsrel=1e-12, limit=400)[0]
    assert rh.limited_shear_integral(p_max, b, ETA, rate, limiting_shear_coeff=lam) == pytest.approx(
        ref, rel=1e-7
    )


def test_limiting_shear_reading_has_both_limits():
    # τ_N ≪ τ_L: eq. (8) exactly (same film, whole strip over 2h*); τ_N ≫ τ_L: Λ_L Q.
    small = _sliding(1e-9)
    assert small == pytest.approx(_sliding(1e-9, model="newtonian"), rel=1e-5)  # 1 − e^−x ≈ x(1 − x/2)
    for lam in (0.05, 0.075, 0.1):
        assert _sliding(10.0, lam=lam) == pytest.approx(lam * 1776.0, rel=2e-3)
    vs = np.geomspace(1e-7, 1e-1, 13)
    for q in (355.0, 1776.0):
        lim, newt = _sliding(vs, load=q), _sliding(vs, load=q, model="newtonian")
        assert np.all(lim <= newt * (1 + 1e-12)) and np.all(lim <= 0.075 * q)


def test_printed_newtonian_traction_is_not_physical_but_the_limited_one_is():
    # Seed contact at 10 kN (Q = 1776 N), S_c = 0.05 %: v_s = ω_i R_i S_c = 104.7·0.0238·5e-4 m/s.
    from bearingkit.physics.lubrication.traction import MU_BOUNDARY

    vs = 104.72 * 0.02383 * 5e-4
    assert _sliding(vs, model="newtonian") / 1776.0 > MU_BOUNDARY  # above dry/boundary friction
    assert _sliding(vs) / 1776.0 < rh.SLIDING_LIMITING_SHEAR_COEFF


def test_mpa_reading_is_isoviscous():
    # p in MPa inside Roelands' per-Pa constant: η(p)/η0 ≈ 1, I ≈ b (no piezoviscosity).
    from bearingkit.physics.contact.line import line_contact

    b = line_contact(1776.0, L, R_X, E_RED).half_width
    h = tf.sliding_film_thickness(ETA, 1.39, ALPHA, E_RED, R_X, 1776.0, L)
    assert _sliding(model="newtonian_mpa") == pytest.approx(2.5e-4 * ETA * L * b / h, rel=1e-4)
    assert _sliding(model="newtonian_mpa") < 1e-6 * _sliding(model="newtonian")


def test_sliding_traction_needs_a_film_when_sliding():
    with pytest.raises(InputError, match="entrainment_speed"):
        _sliding(u=0.0)


@settings(max_examples=50, deadline=None)
@given(
    w=st.floats(1.0, 500.0),
    s=st.floats(0.0, 0.2),
    ri=st.floats(5e-3, 0.2),
    gap=st.floats(1e-3, 0.05),
    rm=st.floats(1e-3, 2e-2),
)
def test_outer_control_kinematics_invariants(w, s, ri, gap, rm):
    re = ri + gap
    k = tf.outer_control_kinematics(w, s, ri, re, rm, ri + 0.5 * gap, 0.5 * rm)
    assert k.slide_outer == 0.0
    assert k.slide_inner == pytest.approx(w * ri * s, rel=1e-9, abs=1e-12)  # eq. (13)
    assert k.cage_speed == pytest.approx((1 - s) * w * ri / (ri + re))
    # the cup contact rolls: roller surface speed = cup speed relative to the cage
    assert k.roller_speed * rm == pytest.approx(k.cage_speed * re)
    assert k.entrainment_inner == pytest.approx(k.entrainment_outer + 0.5 * k.slide_inner)


def test_pure_rolling_without_cage_slip():
    k = tf.outer_control_kinematics(100.0, 0.0, 0.02383, 0.03017, 3.244e-3, 0.02683, 1.71e-3)
    assert k.slide_inner == pytest.approx(0.0, abs=1e-12)
    assert k.entrainment_inner == pytest.approx(k.entrainment_outer)
    assert k.entrainment_outer == pytest.approx(100.0 * 0.02383 * 0.03017 / (0.02383 + 0.03017))


@pytest.mark.parametrize(
    "kwargs",
    [dict(speed_inner=-1.0), dict(cage_slip=1.0), dict(cage_slip=-0.1), dict(radius_inner=0.0)],
)
def test_kinematics_bad_input(kwargs):
    base = dict(
        speed_inner=100.0,
        cage_slip=1e-4,
        radius_inner=0.024,
        radius_outer=0.03,
        roller_radius=3e-3,
        radius_flange=0.027,
        flange_roller_radius=1.7e-3,
    )
    base.update(kwargs)
    with pytest.raises(InputError):
        tf.outer_control_kinematics(**base)


def test_ring_torques_sum_rollers():
    z = 4
    ro_e, rs_e = np.full((2, z), 1.0), np.zeros((2, z))
    ro_i, rs_i, ff = np.full((2, z), 2.0), np.full((2, z), 3.0), np.full((2, z), 0.5)
    m_e, m_i = tf.ring_torques(ro_e, rs_e, ro_i, rs_i, ff, 0.03, 0.024, 0.027)
    np.testing.assert_allclose(m_e, [z * 0.03] * 2)
    np.testing.assert_allclose(m_i, [z * (5.0 * 0.024 + 0.5 * 0.027)] * 2)


def test_unknown_rolling_model_and_bad_values():
    with pytest.raises(InputError, match="rolling_model"):
        _rolling(model="nope")
    with pytest.raises(InputError, match="load"):
        _rolling(load=np.nan)
    with pytest.raises(InputError, match="slide_speed"):
        _sliding(vs=np.inf)
    with pytest.raises(InputError, match="sliding_model"):
        _sliding(model="eyring")
    with pytest.raises(InputError, match="limiting_shear_coeff"):
        _sliding(lam=0.0)
