"""Kinematics: closed forms of Tian et al. (2025) §3.5 and Harris (2007) ch. 8, and invariants."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingkit.analysis.friction.kinematics import (
    element_kinematics,
    row_kinematics,
    thrust_roller_kinematics,
)
from bearingkit.bearings.turntable import composite_turntable
from bearingkit.errors import InputError

W = 2 * np.pi * 5 / 60  # 5 r/min


def test_thrust_ball_seed000_closed_form():
    # Tian et al. §3.5: ω_b = 0.5 ω_i, u_b = 0.25 d_m ω_i, spin ω_b' = d_m ω_i/(2 D) (outer ring fixed).
    k = element_kinematics(0.1778, 0.006, np.pi / 2, W, 0.0)
    assert k.cage_speed == pytest.approx(W / 2)
    assert k.entrainment_inner == pytest.approx(0.25 * 0.1778 * W)
    assert abs(k.rolling_speed) == pytest.approx(0.1778 * W / (2 * 0.006))
    # α = 90°, tangent rolling axis: each contact spins at |ω_i − ω_c| = ω_i/2
    assert abs(k.spin_inner) == pytest.approx(W / 2) and abs(k.spin_outer) == pytest.approx(W / 2)


def test_radial_roller_seed000_closed_form():
    d, dm = 0.005, 0.15525
    k = element_kinematics(dm, d, 0.0, W, 0.0)
    assert k.cage_speed == pytest.approx(0.5 * W * (1 - d / dm))
    assert abs(k.rolling_speed) == pytest.approx(0.5 * dm / d * W * (1 - (d / dm) ** 2))
    assert k.spin_inner == 0.0 and k.spin_outer == 0.0


def test_outer_raceway_control_zero_outer_spin():
    k = element_kinematics(0.05, 0.008, np.radians(40), 100.0, 0.0, raceway_control="outer")
    assert k.spin_outer == pytest.approx(0.0, abs=1e-12)
    assert abs(k.spin_inner) > 0


def test_no_slip_at_contact_centres():
    # Raceway surface speed in the cage frame equals the element's surface speed at both contacts.
    dm, d, a, wi, wo = 0.06, 0.01, np.radians(25), 120.0, -30.0
    k = element_kinematics(dm, d, a, wi, wo)
    r_i, r_o = (dm - d * np.cos(a)) / 2, (dm + d * np.cos(a)) / 2
    assert (wi - k.cage_speed) * r_i == pytest.approx(-k.rolling_speed * d / 2)
    assert (wo - k.cage_speed) * r_o == pytest.approx(k.rolling_speed * d / 2)


@settings(max_examples=30, deadline=None)
@given(st.floats(-50, 50), st.floats(-50, 50), st.floats(0, 1.5))
def test_only_relative_speed_matters(wi, wo, alpha):
    a = element_kinematics(0.1, 0.01, alpha, wi, wo)
    b = element_kinematics(0.1, 0.01, alpha, wi - wo, 0.0)
    assert a.entrainment_inner == pytest.approx(b.entrainment_inner, abs=1e-9)
    assert a.spin_inner == pytest.approx(b.spin_inner, abs=1e-9)
    assert a.cage_speed - wo == pytest.approx(b.cage_speed, abs=1e-9)


def test_thrust_roller_sliding_zero_at_pitch_and_linear():
    y = np.array([0.0811, 0.0835, 0.0859])
    k = thrust_roller_kinematics(0.167, 0.004, y, W, 0.0)
    assert k.slide_inner[1] == pytest.approx(0.0)
    assert k.slide_inner[2] == pytest.approx(-k.slide_inner[0])
    assert k.slide_inner[2] == pytest.approx(W / 2 * (y[2] - 0.0835))
    assert k.entrainment_pitch == pytest.approx(W / 2 * 0.0835)


def test_row_dispatch_and_bad_input():
    m = composite_turntable()
    kin = row_kinematics(m.row("roller_upper"), W, 0.0)
    assert kin.slide_inner.shape[-1] == m.row("roller_upper").n_slices
    assert row_kinematics(m.row("ball_upper"), W, 0.0).cage_speed == pytest.approx(W / 2)
    with pytest.raises(InputError):
        element_kinematics(0.1, 0.01, 0.0, 1.0, 0.0, raceway_control="middle")
    with pytest.raises(InputError):
        element_kinematics(0.1, 0.01, 0.0, np.nan, 0.0)
