"""PTRB physics: static contact load, ratings formulas, γ–β relations, tooth-root checks."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingkit.errors import InputError
from bearingkit.physics.contact import hertz
from bearingkit.physics.life import iso281
from bearingkit.physics.life import ptrb_rating as pr
from bearingkit.physics.structure import ptrb_strength as ps

E_RED = 212e9 / (1 - 0.29**2)


@given(st.floats(100.0, 5000.0), st.floats(0.0, 0.9))
@settings(max_examples=30, deadline=None)
def test_static_load_puts_4200_mpa(curvature_sum, f_rho):
    q0 = pr.static_contact_load(curvature_sum, f_rho, E_RED)
    p = hertz.point_contact(q0, curvature_sum, f_rho, E_RED).max_pressure
    assert p == pytest.approx(pr.CONTACT_STRESS_STATIC, rel=1e-9)


def test_static_ratings_closed_form():
    assert pr.static_rating_axial(500.0, 11, 10, np.pi / 6, 1.0) == pytest.approx(11 * 10 * 500 * 0.5)
    assert pr.static_rating_radial(500.0, 10, np.pi / 3, 0.5) == pytest.approx(2 * 10 * 500 * 0.5 / 0.5)
    with pytest.raises(InputError, match="f_rmax"):
        pr.static_rating_radial(500.0, 10, 0.5, 1.5)


def test_multi_row_combination_is_iso281():
    """C_a = n^0.7 C_Da (f_amax = 1) is ISO 281 eq. (7) for n identical rows."""
    cda, z, n = 7000.0, 11, 10
    iso = iso281.combine_thrust_rows(np.full(n, z), np.full(n, cda), "ball")
    assert pr.basic_dynamic_axial(cda, n, 1.0) == pytest.approx(iso, rel=1e-12)
    assert pr.basic_dynamic_radial(cda, n) == pytest.approx((2 * n) ** 0.7 * cda)


def test_stress_cycles():
    bi, bo = pr.stress_cycles(11, 6 / 42.5)
    assert bi + bo == pytest.approx(11)
    assert bi == pytest.approx(11 * (42.5 + 6) / (2 * 42.5))


def test_fc_conformity_term_flat_flank_and_limit():
    g, a, rrr, dr = 0.14, np.pi / 4, 5.1e-3, 6e-3
    flat = pr.fc_radial(g, a, rrr, np.inf, dr)
    curved = pr.fc_radial(g, a, rrr, 75e-3, dr)
    ratio = (1 / rrr) / (1 / rrr - 1 / 75e-3)
    assert curved / flat == pytest.approx(ratio**0.41, rel=1e-12)
    ax = pr.fc_axial(g, a, rrr, np.inf, dr)
    # the thrust factor carries (1 − sin α/3) and the 98.07 constant; at fixed γ the ratio is closed-form
    ring_r = (1 + (1.04 * ((1 - g) / (1 + g)) ** 1.72) ** (10 / 3)) ** -0.3
    ring_a = (1 + ((1 - g) / (1 + g)) ** (1.72 * 10 / 3)) ** -0.3
    assert ax / flat == pytest.approx(98.07 * (1 - np.sin(a) / 3) * ring_a / (39.91 * ring_r), rel=1e-12)


def test_dynamic_rating_large_ball_branch_continuous_enough():
    below = pr.dynamic_rating_thread(30.0, 25.4e-3, 11, 0.7, False)
    above = pr.dynamic_rating_thread(30.0, 25.4e-3 * (1 + 1e-9), 11, 0.7, False)
    assert above == pytest.approx(below, rel=1e-3)  # 3.647 = 25.4^0.4


def test_calibration_reproduces_published_static_ratings():
    """The calibration constants are what C0a = 38.36 kN and C0r = 19.93 kN require (flat flanks)."""
    from bearingkit.bearings.ptrb import ptrb_prototype
    from bearingkit.rows.threaded.row import contact_pairs

    g = ptrb_prototype()
    p = contact_pairs(g)["inner"]
    q0 = pr.static_contact_load(p.curvature_sum, p.curvature_difference, g.e_reduced)
    f_amax = g.n_elements * g.n_teeth * q0 * np.sin(g.contact_angle) / 38.36e3
    f_rmax = 2 * g.n_teeth * q0 * np.cos(g.contact_angle) / 19.93e3
    fa, fr = pr.calibrated_distribution_coefficients(g.n_elements)
    assert fa == pytest.approx(f_amax, rel=2e-4)
    assert fr == pytest.approx(f_rmax, rel=2e-4)


def test_tooth_root_stresses_closed_form():
    q, a, z, h, d, b = 500.0, np.pi / 4, 11, 0.24e-3, 6e-3, 1.05e-3
    ax = z * q * np.sin(a)
    assert ps.tooth_root_bending_stress(q, a, z, h, d, b) == pytest.approx(6 * h * ax / (np.pi * d * b**2))
    assert ps.tooth_root_shear_stress(q, a, z, d, b) == pytest.approx(ax / (np.pi * d * b))
    assert ps.contacts_per_tooth(11, "roller", "per_part") == 1
    assert ps.contacts_per_tooth(11, "roller", "paper") == 11
    assert ps.ALLOWED_SHEAR_STRESS == pytest.approx(0.6 * ps.ALLOWED_BENDING_STRESS)
    with pytest.raises(InputError, match="model"):
        ps.contacts_per_tooth(11, "roller", "other")


def test_curvature_rejects_ring_radius_below_roller():
    with pytest.raises(InputError, match="ring_contact_radius"):
        pr.thread_contact_curvature(6e-3, 36e-3, 5e-3, 4e-3, 0.7, "inner")
    with pytest.raises(InputError, match="contact_angle"):
        pr.thread_contact_curvature(6e-3, 36e-3, 5e-3, np.inf, 1.6, "inner")
