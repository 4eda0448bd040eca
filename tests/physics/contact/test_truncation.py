"""Closed forms of contact-ellipse truncation (physics.contact.truncation)."""

from __future__ import annotations

import numpy as np
import pytest

from bearingkit.physics.contact import truncation as tr


def test_shoulder_angle_closed_form():
    # h = 0.20 D_w, r = 0.52 D_w: cos θ_s = 1 - 0.2/0.52 = 0.615385 -> θ_s = 52.0201°
    assert np.degrees(tr.shoulder_angle(0.20, 0.52)) == pytest.approx(52.0201, abs=1e-4)
    # h = r: the shoulder at the arc's equator, 90°
    assert np.degrees(tr.shoulder_angle(0.52, 0.52)) == pytest.approx(90.0)
    # measured from a seam at θ_b: cos θ_s = cos θ_b - h/r
    b = np.radians(3.0)
    assert np.cos(tr.shoulder_angle(0.1, 0.5, b)) == pytest.approx(np.cos(b) - 0.2, rel=1e-14)


def test_flag_switches_exactly_at_the_edge_angle():
    r, h, a = 0.52, 0.20, 0.10  # in units of D_w
    theta_s = np.arccos(1.0 - h / r)
    theta_a = np.arcsin(a / r)  # 11.09°: the ellipse's half-span on the arc
    edge = theta_s - theta_a  # the largest contact angle whose ellipse stays on the groove (40.93°)
    assert np.degrees(edge) == pytest.approx(52.0201 - 11.0880, abs=1e-3)
    assert not tr.truncated(edge - 1e-9, a, r, h)
    assert tr.truncated(edge + 1e-9, a, r, h)
    assert tr.truncated(-(edge + 1e-9), a, r, h)  # either side of the bottom runs towards its own shoulder
    assert not tr.truncated(edge + 1e-9, 0.0, r, h)  # an unloaded contact (a = 0) is never truncated


def test_gothic_arch_seam():
    f, alpha0 = 0.53, np.radians(45.0)
    seam = tr.seam_angle(f, alpha0)
    # sin θ_b = (f - 1/2)/f sin α0 = 0.03/0.53 * 0.7071 = 0.040026 -> 2.2939°
    assert np.degrees(seam) == pytest.approx(2.29387, abs=1e-4)
    r, a = f, 0.10
    theta_a = np.arcsin(a / r)
    low = seam + theta_a  # below this the ellipse crosses the seam into the other arc
    assert tr.truncated(low - 1e-9, a, r, 0.4, seam=seam)
    assert not tr.truncated(low + 1e-9, a, r, 0.4, seam=seam)
    assert not tr.truncated(low - 1e-9, a, r, 0.4)  # a single-arc groove has no seam


def test_required_height_is_the_edge_of_the_flag():
    # α = 40°, a = 0.10, r = 0.52 (units of D_w): h* = r (1 - cos(40° + 11.088°)) = 0.52 (1 - 0.628383)
    r, a, alpha = 0.52, 0.10, np.radians(40.0)
    h_star = tr.required_shoulder_height(alpha, a, r)
    # θ_a written to 1e-4° here (arcsin(0.1/0.52) = 11.0880°): tolerance 1e-4 relative
    assert h_star == pytest.approx(0.52 * (1 - np.cos(np.radians(40.0 + 11.0880))), rel=1e-4)
    assert tr.truncated(alpha, a, r, h_star * (1 - 1e-9))
    assert not tr.truncated(alpha, a, r, h_star * (1 + 1e-9))
    seam = tr.seam_angle(0.53, np.radians(45.0))  # measured from a gothic arch's seam
    h_seam = tr.required_shoulder_height(alpha, a, 0.53, seam)
    assert np.cos(tr.shoulder_angle(h_seam, 0.53, seam)) == pytest.approx(np.cos(alpha + np.arcsin(a / 0.53)))


# --------------------------------------------------------------------------- truncation as numbers
def test_load_fraction_of_a_cut_semi_ellipsoid():
    # F(τ) = (2 + 3τ − τ³)/4: none, half, all of the load; and a direct quadrature of ∬ √(1 − x² − y²)
    assert tr.load_fraction([-1.0, 0.0, 1.0]) == pytest.approx([0.0, 0.5, 1.0])
    t, w = np.polynomial.legendre.leggauss(400)
    for tau in (-0.6, 0.3, 0.8):
        x = -1 + (tau + 1) * (t + 1) / 2  # x ∈ [−1, τ]
        strip = np.pi / 2 * (1 - x * x)  # ∫ √(1 − x² − y²) dy over the chord
        inside = np.sum(w * strip) * (tau + 1) / 2
        assert tr.load_fraction(tau) == pytest.approx(inside / (2 * np.pi / 3), rel=1e-10)


def test_truncated_pressure_closed_forms():
    # nothing cut: p_max; the edge through the centre: s³/2 = 1 → 2^(1/3); the centre one semi-axis beyond
    # the edge: s³ F(−1/s) = 1 → 2s³ − 3s² − 3 = 0 (s = 1.9108)
    p = tr.truncated_pressure(1.0, [5.0, 1.0, 0.0, -1.0])
    assert p == pytest.approx([1.0, 1.0, 2 ** (1 / 3), 1.9108200], rel=1e-6)
    # cut on both sides at ±τ: s³ [2 F(τ/s) − 1] = 1
    s = float(tr.truncated_pressure(1.0, 0.5, 0.5))
    assert s**3 * (2 * tr.load_fraction(0.5 / s) - 1) == pytest.approx(1.0, rel=1e-9)
    # the deeper the cut, the higher the pressure
    assert np.all(np.diff(tr.truncated_pressure(3e9, np.linspace(1.0, -1.0, 9))) > 0)


def test_remaining_fraction_and_safety_follow_the_shoulder():
    r, h, a = 0.52, 0.20, 0.10  # units of D_w
    theta_s = np.arccos(1.0 - h / r)
    edge = theta_s - np.arcsin(a / r)  # the ellipse just reaches the shoulder
    assert tr.remaining_fraction(edge, a, r, theta_s) == pytest.approx(1.0, rel=1e-9)
    assert tr.remaining_fraction(theta_s, a, r, theta_s) == pytest.approx(0.0, abs=1e-12)
    assert tr.truncation_safety(edge, a, r, h) == pytest.approx(1.0, rel=1e-9)
    alpha = np.radians(40.0)
    need = tr.required_shoulder_height(alpha, a, r)
    assert tr.truncation_safety(alpha, a, r, h) == pytest.approx(h / need)
    assert tr.truncation_safety(alpha, 0.0, r, h) == np.inf
