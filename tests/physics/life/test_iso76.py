"""Tests of bearingkit.physics.life.iso76 (ISO 76:2006 static ratings). SI units throughout."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from bearingkit.errors import InputError
from bearingkit.physics.life import iso76

MM = 1e-3
INCH = 25.4e-3
# CWRU Bearing Data Center, drive-end SKF 6205-2RS JEM: ball 0.3126 in, pitch 1.537 in, 9 balls
# (Smith & Randall 2015, MSSP 64-65:100-131, doi:10.1016/j.ymssp.2015.04.021).
DW_6205, DPW_6205, Z_6205 = 0.3126 * INCH, 1.537 * INCH, 9

# Steel constants the ISO 76 contact-stress basis uses (E = 207 GPa, nu = 0.3) and Stribeck's factor 5.
E_STEEL, NU_STEEL, STRIBECK = 207e9, 0.3, 5.0


def _hertz_load_at_pressure(curv_sum, curv_diff, p_max):
    """Point-contact load [N] that produces p_max (exact elliptic-integral Hertz theory)."""

    def eq(chi):
        m = 1 - 1 / chi**2
        return 1 - 2 * (ellipk(m) - ellipe(m)) / ((chi**2 - 1) * ellipe(m)) - curv_diff

    chi = brentq(eq, 1 + 1e-9, 100.0) if curv_diff > 1e-12 else 1.0
    e_m = ellipe(1 - 1 / chi**2)
    a_star = (2 * chi**2 * e_m / np.pi) ** (1 / 3)
    b_star = (2 * e_m / (np.pi * chi)) ** (1 / 3)
    comp = 2 * (1 - NU_STEEL**2) / E_STEEL
    # p = 3Q / (2 pi a b), a b = a* b* (3 Q comp / (2 sum rho))^(2/3)
    return (p_max * 2 * np.pi * a_star * b_star * (3 * comp / (2 * curv_sum)) ** (2 / 3) / 3) ** 3


def _contact(dw, gamma, conformity, inner):
    t = gamma / (1 - gamma) if inner else -gamma / (1 + gamma)
    s = (2 / dw) * (2 + t - 1 / (2 * conformity))
    return s, (t + 1 / (2 * conformity)) / (2 + t - 1 / (2 * conformity))


# --- tables ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("gamma", "f0"), [(0.0, 14.7), (0.09, 16.5), (0.10, 16.4), (0.20, 14.0), (0.40, 9.4)]
)
def test_f0_radial_entries(gamma, f0):
    # entries checked by hand against ISO 76 Table 1 as transcribed in formulas.md D2
    assert iso76.f0_radial_ball(gamma) == pytest.approx(f0, abs=1e-12)


def test_f0_linear_interpolation_and_range():
    assert iso76.f0_radial_ball(0.105) == pytest.approx(0.5 * (16.4 + 16.1))
    with pytest.raises(InputError, match=r"gamma .* table range \[0, 0.4\]"):
        iso76.f0_radial_ball(0.41)
    with pytest.raises(InputError, match="gamma"):
        iso76.f0_thrust_ball(-0.01)


@pytest.mark.parametrize("gamma", [0.0, 0.05, 0.1, 0.2, 0.3, 0.4])
def test_f0_radial_reproduces_hertz_4200_mpa(gamma):
    """ISO 76 f0 = Q_max(4200 MPa) / (5 Dw^2), r_i = 0.52 Dw, r_e = 0.53 Dw, weaker contact governs.

    Tolerance 0.6 %: the table has three significant digits (0.05 / 9.4 = 0.53 % at worst).
    """
    dw = 1 * MM
    q = min(
        _hertz_load_at_pressure(*_contact(dw, gamma, 0.52, True), 4200e6),
        _hertz_load_at_pressure(*_contact(dw, gamma, 0.53, False), 4200e6),
    )
    f0_hertz = q / STRIBECK / dw**2 / 1e6
    assert iso76.f0_radial_ball(gamma) == pytest.approx(f0_hertz, rel=6e-3)


@pytest.mark.parametrize("gamma", [0.0, 0.1, 0.2, 0.35])
def test_f0_thrust_reproduces_hertz_4200_mpa(gamma):
    """Thrust: every ball carries Fa/Z, so f0 = Q(4200 MPa)/Dw^2 with r = 0.54 Dw (tolerance as above)."""
    dw = 1 * MM
    q = min(
        _hertz_load_at_pressure(*_contact(dw, gamma, 0.54, True), 4200e6),
        _hertz_load_at_pressure(*_contact(dw, gamma, 0.54, False), 4200e6),
    )
    assert iso76.f0_thrust_ball(gamma) == pytest.approx(q / dw**2 / 1e6, rel=6e-3)


def test_c0_thrust_ball_90_is_hertz_on_a_washer_flat_in_rolling_direction():
    """At α = 90° the contact normal is axial: the washer groove has no curvature in the rolling direction
    (curvature = radial part of the normal / contact radius = 0), so every ball carries the Hertz load at
    4200 MPa of a ball in a straight groove of radius 0.54 Dw, whatever Dw/Dpw (tolerance as above)."""
    dw, z = 10 * MM, 15
    q = _hertz_load_at_pressure(*_contact(dw, 0.0, 0.54, True), 4200e6)
    for dpw in (40 * MM, 60 * MM, 200 * MM):
        c0 = iso76.static_rating_ball(dw, dpw, np.pi / 2, z, kind="thrust")
        assert c0 == pytest.approx(z * q, rel=6e-3)


def test_roller_factor_220_is_hertz_line_contact_at_4000_mpa():
    """Line contact: Q/(L Dwe) = pi p^2 (1-gamma)/E' at the inner contact; 220 MPa at 4000 MPa (0.5 %)."""
    e_prime = E_STEEL / (1 - NU_STEEL**2)
    factor = np.pi * 4000e6**2 / e_prime
    assert iso76.ROLLER_THRUST_FACTOR == pytest.approx(factor, rel=5e-3)
    assert iso76.ROLLER_RADIAL_FACTOR == pytest.approx(iso76.ROLLER_THRUST_FACTOR / STRIBECK)


# --- ratings ---------------------------------------------------------------------------------------------


def test_c0_ball_radial_by_hand_and_vectorised():
    dw, dpw = 10 * MM, 60 * MM
    alpha = np.radians([0.0, 30.0])
    gamma = dw * np.cos(alpha) / dpw
    f0 = np.interp(gamma, [0.14, 0.15, 0.16, 0.17], [15.4, 15.2, 14.9, 14.7])
    expected = f0 * 1e6 * 2 * 12 * dw**2 * np.cos(alpha)
    assert iso76.static_rating_ball(dw, dpw, alpha, 12, n_rows=2) == pytest.approx(expected, rel=1e-12)


def test_c0_6205_against_catalogue():
    # catalogue C0 of a 6205: 7.80 kN; geometry from the CWRU data centre. Tolerance 2 %: catalogue
    # rounding (3 digits) and the unknown groove radii / exact pitch diameter of the manufacturer.
    c0 = iso76.static_rating_ball(DW_6205, DPW_6205, 0.0, Z_6205)
    assert c0 == pytest.approx(7.80e3, rel=0.02)


def test_c0_thrust_ball_90_and_angular():
    dw, dpw, z = 12 * MM, 80 * MM, 18
    c90 = iso76.static_rating_ball(dw, dpw, np.pi / 2, z, kind="thrust")
    # α = 90°: γ = Dw cos α / Dpw = 0 (the table's curvature parameter), f0 = 61.6 for any Dw/Dpw
    assert c90 == pytest.approx(61.6e6 * z * dw**2, rel=1e-12)
    assert iso76.static_rating_ball(dw, 3 * dpw, np.pi / 2, z, kind="thrust") == pytest.approx(c90)
    a = np.radians(60)
    c60 = iso76.static_rating_ball(dw, dpw, a, z, kind="thrust")
    assert c60 == pytest.approx(iso76.f0_thrust_ball(dw * np.cos(a) / dpw) * 1e6 * z * dw**2 * np.sin(a))


def test_c0_roller_by_hand():
    # 44 MPa (1 - 10/60) * 14 * 10 mm * 10 mm = 51 333 N; thrust alpha = 90 deg: 220 MPa Z L D
    assert iso76.static_rating_roller(10 * MM, 10 * MM, 60 * MM, 0.0, 14) == pytest.approx(
        44 * (1 - 1 / 6) * 14 * 100
    )
    assert iso76.static_rating_roller(
        10 * MM, 10 * MM, 60 * MM, np.pi / 2, 14, kind="thrust"
    ) == pytest.approx(220 * 14 * 100)
    two = iso76.static_rating_roller(10 * MM, 10 * MM, 60 * MM, 0.2, 14, n_rows=2)
    assert two == pytest.approx(2 * iso76.static_rating_roller(10 * MM, 10 * MM, 60 * MM, 0.2, 14))


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        (dict(element_diameter=60 * MM, pitch_diameter=60 * MM), "pitch_diameter"),
        (dict(element_diameter=-1 * MM, pitch_diameter=60 * MM), "element_diameter"),
        (dict(element_diameter=5 * MM, pitch_diameter=60 * MM, contact_angle=1.0), "contact_angle"),
        (dict(element_diameter=5 * MM, pitch_diameter=60 * MM, n_elements=0), "n_elements"),
    ],
)
def test_c0_bad_input(kwargs, field):
    base = dict(contact_angle=0.0, n_elements=10)
    base.update(kwargs)
    with pytest.raises(InputError, match=field):
        iso76.static_rating_ball(**base)


def test_c0_thrust_needs_thrust_angle():
    with pytest.raises(InputError, match="contact_angle"):
        iso76.static_rating_roller(10 * MM, 10 * MM, 60 * MM, 0.3, 14, kind="thrust")
    with pytest.raises(InputError, match="kind"):
        iso76.static_rating_ball(10 * MM, 60 * MM, 0.0, 10, kind="axial")


# --- equivalent static load and safety -------------------------------------------------------------------


def test_p0_laws_by_hand():
    p = iso76.equivalent_static_load([1000.0, 100.0], [200.0, 1000.0], "deep_groove_ball")
    np.testing.assert_allclose(p, [1000.0, 0.6 * 100 + 0.5 * 1000])
    a40 = np.radians(40)
    assert iso76.equivalent_static_load(1000.0, 2000.0, "angular_contact_ball", a40) == pytest.approx(
        0.5 * 1000 + 0.26 * 2000
    )
    assert iso76.equivalent_static_load(
        1000.0, 2000.0, "angular_contact_ball", a40, n_rows=2
    ) == pytest.approx(1000 + 0.52 * 2000)
    a = np.radians(12)
    assert iso76.equivalent_static_load(1000.0, 3000.0, "radial_roller", a) == pytest.approx(
        0.5 * 1000 + 0.22 / np.tan(a) * 3000
    )
    a60 = np.radians(60)
    assert iso76.equivalent_static_load(100.0, 3000.0, "thrust_ball", a60) == pytest.approx(
        2.3 * 100 * np.tan(a60) + 3000
    )


def test_p0_impossible_cases():
    with pytest.raises(InputError, match="load_axial"):
        iso76.equivalent_static_load(1000.0, 10.0, "radial_roller", 0.0)
    with pytest.raises(InputError, match="load_radial"):
        iso76.equivalent_static_load(10.0, 1000.0, "thrust_ball", np.pi / 2)
    with pytest.raises(InputError, match="load_radial"):
        iso76.equivalent_static_load(-1.0, 1000.0, "deep_groove_ball")
    with pytest.raises(InputError, match="bearing_type"):
        iso76.equivalent_static_load(1.0, 1.0, "magneto")
    with pytest.raises(InputError, match="contact_angle"):
        iso76.equivalent_static_load(1.0, 1.0, "angular_contact_ball", np.radians(10))


def test_static_safety():
    assert iso76.static_safety(8000.0, 2000.0) == pytest.approx(4.0)
    with pytest.raises(InputError, match="equivalent_static_load"):
        iso76.static_safety(8000.0, 0.0)


@pytest.mark.parametrize(
    ("kind", "p_lim", "n"), [("ball", 4200e6, 3), ("self_aligning_ball", 4600e6, 3), ("roller", 4000e6, 2)]
)
def test_safety_from_pressure(kind, p_lim, n):
    assert iso76.static_safety_from_pressure(p_lim, kind) == pytest.approx(1.0)
    assert iso76.static_safety_from_pressure(p_lim / 2, kind) == pytest.approx(2.0**n)


def test_safety_from_pressure_bad_input():
    with pytest.raises(InputError, match="kind"):
        iso76.static_safety_from_pressure(1e9, "needle")
    with pytest.raises(InputError, match="max_pressure"):
        iso76.static_safety_from_pressure(0.0, "ball")


@given(pressure_ratio=st.floats(0.3, 3.0), gamma=st.floats(0.0, 0.3))
def test_pressure_safety_equals_load_safety_for_hertz_point_contact(pressure_ratio, gamma):
    """s0 from pressure equals Q(p_limit)/Q(p_max) computed with exact Hertz theory (exponent 3 check)."""
    s, f = _contact(1 * MM, gamma, 0.52, True)
    p = 4200e6 * pressure_ratio
    load_ratio = _hertz_load_at_pressure(s, f, 4200e6) / _hertz_load_at_pressure(s, f, p)
    assert iso76.static_safety_from_pressure(p, "ball") == pytest.approx(load_ratio, rel=1e-9)
