"""Element dynamics: masses, centrifugal force, gyroscopic moment, ball kinematics (closed forms)."""

import numpy as np
import pytest

from bearingkit.physics.dynamics import ball_kinematics as bk
from bearingkit.physics.dynamics import centrifugal as cf

D, DM, RHO = 0.0127, 0.065, 7810.0


def test_ball_mass_and_inertia_closed_form():
    m = cf.ball_mass(D, RHO)
    assert m == pytest.approx(RHO * 4.0 / 3.0 * np.pi * (D / 2) ** 3, rel=1e-14)
    # Solid sphere: J = (2/5) m r² = m D²/10.
    assert cf.ball_inertia(D, RHO) == pytest.approx(0.4 * m * (D / 2) ** 2, rel=1e-14)


def test_roller_mass_and_centrifugal_force():
    m = cf.roller_mass(0.011, 0.011, RHO)
    assert m == pytest.approx(RHO * np.pi * 0.0055**2 * 0.011, rel=1e-14)
    # Harris: F_c = ½ m d_m ω_m² for a ball on the pitch circle.
    assert cf.centrifugal_force(m, DM / 2, 300.0) == pytest.approx(0.5 * m * DM * 300.0**2, rel=1e-14)


def test_equal_angles_give_the_textbook_speeds():
    """α_i = α_o = α, inner ring turning: ω_m = ω(1 − γ′cos α)/2 and
    ω_R = −ω(1 − γ′²cos²α)/(2γ′ cos(α − β)) (Harris & Kotzalas, ω_R/ω at equal angles)."""
    w = 2000.0
    for alpha in (0.0, 0.3, np.radians(40.0)):
        for control in bk.RACEWAY_CONTROLS:
            sp = bk.ball_speeds(w, 0.0, alpha, alpha, D, DM, control)
            g = D / DM
            assert sp.cage_speed == pytest.approx(w * (1 - g * np.cos(alpha)) / 2, rel=1e-13)
            expected = -w * (1 - (g * np.cos(alpha)) ** 2) / (2 * g * np.cos(alpha - sp.attitude_angle))
            assert sp.spin_speed == pytest.approx(expected, rel=1e-13)


def test_controlling_raceway_has_no_spin_and_harris_attitude_angle():
    a_i, a_o, g = np.radians(48.0), np.radians(33.0), D / DM
    out = bk.ball_speeds(1500.0, 0.0, a_i, a_o, D, DM, "outer")
    inn = bk.ball_speeds(1500.0, 0.0, a_i, a_o, D, DM, "inner")
    assert abs(out.spin_outer) < 1e-12 * abs(out.spin_speed)
    assert abs(inn.spin_inner) < 1e-12 * abs(inn.spin_speed)
    assert np.tan(out.attitude_angle) == pytest.approx(np.sin(a_o) / (np.cos(a_o) + g), rel=1e-13)
    assert np.tan(inn.attitude_angle) == pytest.approx(np.sin(a_i) / (np.cos(a_i) - g), rel=1e-13)
    # Radial row: the ball turns about an axis parallel to the bearing axis and spins nowhere.
    rad = bk.ball_speeds(1500.0, 0.0, 0.0, 0.0, D, DM, "outer")
    assert rad.attitude_angle == 0.0 and rad.spin_inner == pytest.approx(0.0, abs=1e-12)


def test_rolling_without_slip_at_both_contacts():
    """The speeds satisfy the two rolling conditions they were solved from (either ring turning)."""
    a_i, a_o, g = 0.9, 0.5, D / DM
    sp = bk.ball_speeds(1000.0, -300.0, a_i, a_o, D, DM, "outer")
    b = sp.attitude_angle
    big_i, big_o = 1000.0 - sp.cage_speed, -300.0 - sp.cage_speed
    assert big_o * (1 + g * np.cos(a_o)) == pytest.approx(g * sp.spin_speed * np.cos(a_o - b), rel=1e-12)
    assert big_i * (1 - g * np.cos(a_i)) == pytest.approx(-g * sp.spin_speed * np.cos(a_i - b), rel=1e-12)


def test_gyroscopic_moment_is_the_rate_of_angular_momentum():
    """M_g = J ω_R ω_m sin β equals the t̂-component of −(J ω_m ẑ × ω_ball) written with np.cross in the
    (r̂, t̂, ẑ) frame, ω_ball = ω_R(−sin β, 0, cos β): the sign the ball kernel relies on."""
    j = cf.ball_inertia(D, RHO)
    sp = bk.ball_speeds(2000.0, 0.0, 0.8, 0.6, D, DM, "outer")
    w_ball = sp.spin_speed * np.array([-np.sin(sp.attitude_angle), 0.0, np.cos(sp.attitude_angle)])
    rate = j * np.cross(sp.cage_speed * np.array([0.0, 0.0, 1.0]), w_ball)
    m_g = cf.gyroscopic_moment(j, sp.spin_speed, sp.cage_speed, sp.attitude_angle)
    # In-plane moments are measured along r̂ × ẑ = −t̂.
    assert m_g == pytest.approx(-rate[1], rel=1e-13)
    assert m_g < 0.0  # inner ring turning +: the ball spins backwards, β > 0
