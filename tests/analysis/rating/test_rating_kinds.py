"""Ratings of the bearing kinds (bearingkit.analysis.rating.kinds)."""

import numpy as np
import pytest

from bearingkit.analysis.rating.assembly import ROW_RATERS, rate
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings import self_aligning as sa
from bearingkit.bearings import slewing
from bearingkit.physics.life import iso76, iso281
from bearingkit.rows.ball.four_point import FourPointRow
from bearingkit.rows.ball.row import BallRow

DEG = np.pi / 180
E_RED = 2.28e11


def test_every_kind_has_a_rater():
    assert {"four_point", "crossed_roller", "spherical_roller", "self_aligning_ball", "needle"} <= set(
        ROW_RATERS
    )


def test_four_point_life_under_axial_load_equals_single_row_angular_contact():
    """Under axial load one diagonal carries: two of the four raceways see the balls, the other two
    nothing, so the ISO/TS 16281 life equals that of the single-row angular contact row (same C)."""
    kw = dict(
        n_elements=16, element_diameter=0.0127, pitch_diameter=0.065, contact_angle=35 * DEG, e_reduced=E_RED
    )
    fp = solve(BearingModel((FourPointRow(**kw),)), load_vector(F_z=4e3))
    ball = solve(
        BearingModel((BallRow(**kw, conformity_inner=0.52, conformity_outer=0.53),)), load_vector(F_z=4e3)
    )
    r_fp, r_ball = rate(fp, speed=100.0), rate(ball, speed=100.0)
    assert float(r_fp.rows[0].load_rating[0]) == pytest.approx(
        float(r_ball.rows[0].load_rating[0]), rel=1e-12
    )
    assert float(r_fp.life[0]) == pytest.approx(float(r_ball.life[0]), rel=1e-7)


def test_four_point_radial_load_uses_all_four_raceways():
    """Radial load loads both diagonals: four raceways share the balls, so the life is below that of the
    same loads on two raceways ((1/2)^0.9 for equal raceways, Weibull slope 10/9)."""
    model = slewing.four_point_contact_ball(n_elements=16, element_diameter=0.0127, pitch_diameter=0.065)
    res = solve(model, load_vector(F_x=3e3), free=[True, True, True, False, False])
    rating = rate(res, speed=100.0)
    assert rating.converged.all() and np.isfinite(np.ma.getdata(rating.life)).all()
    cl = res.rows[0].extras["contact_load"][0]
    assert (cl[cl.max(axis=1) > 0] > 0).all()


def test_crossed_roller_rated_per_direction():
    model = slewing.slewing_ring_crossed_roller(
        n_elements=120, element_diameter=0.016, effective_length=0.014, pitch_diameter=0.8
    )
    res = solve(model, load_vector(F_z=[100e3, 100e3], M_y=[0.0, 60e3]))
    rating = rate(res, speed=0.5)
    c = float(rating.rows[0].load_rating[0])
    expected = iso281.dynamic_rating_roller(
        0.016, 0.014, 0.8, 45 * DEG, 60, bearing_type="cylindrical_roller"
    )
    assert c == pytest.approx(float(expected), rel=1e-12)
    c0 = iso76.static_rating_roller(0.016, 0.014, 0.8, 45 * DEG, 60)
    assert float(rating.rows[0].static_rating[0]) == pytest.approx(float(c0), rel=1e-12)
    assert float(rating.life[1]) < float(rating.life[0])  # a moment on top shortens the life


def test_spherical_roller_rows_rated_and_combined():
    model = sa.spherical_roller(
        n_elements=19,
        element_diameter=0.021,
        effective_length=0.019,
        pitch_diameter=0.14,
        contact_angle=10 * DEG,
    )
    res = solve(model, load_vector(F_x=[60e3, 60e3], F_z=[0.0, 15e3]), free=[True, True, True, False, False])
    rating = rate(res, speed=100.0)
    a, b = rating.rows
    assert a.bearing_type == "spherical_roller"
    c_row = iso281.dynamic_rating_roller(0.021, 0.019, 0.14, 10 * DEG, 19, bearing_type="spherical_roller")
    assert float(a.load_rating[0]) == pytest.approx(float(c_row), rel=1e-12)
    # pure radial: equal rows, the bearing life is 2^(-8/9) of a row's (two equal rows, slope 9/8)
    assert float(a.life[0]) == pytest.approx(float(b.life[0]), rel=1e-9)
    assert float(rating.life[0]) == pytest.approx(float(a.life[0]) * 2 ** (-8 / 9), rel=1e-9)
    assert float(a.life[1]) < float(a.life[0]) < float(b.life[1])  # the axial load shifts to row A


def test_self_aligning_ball_static_safety_at_4600_mpa():
    model = sa.self_aligning_ball(
        n_elements=15, element_diameter=0.009525, pitch_diameter=0.065, contact_angle=12 * DEG
    )
    res = solve(model, load_vector(F_x=3e3), free=[True, True, True, False, False])
    rating = rate(res, speed=100.0)
    p = res.rows[0].max_pressure[0].max()
    assert float(rating.rows[0].static_safety[0]) == pytest.approx((4600e6 / p) ** 3, rel=1e-12)


def test_needle_construction_and_shaft_warning():
    kw = dict(n_elements=56, element_diameter=0.003, effective_length=0.020, pitch_diameter=0.061)
    load = load_vector(F_x=10e3)
    free = [True, True, False, False, False]
    machined = rate(solve(sa.needle_roller(**kw), load, free=free), speed=100.0)
    cup = rate(
        solve(sa.needle_roller(**kw, construction="drawn_cup", inner_ring=False), load, free=free),
        speed=100.0,
    )
    ratio = float(cup.rows[0].load_rating[0]) / float(machined.rows[0].load_rating[0])
    assert ratio == pytest.approx(iso281.rating_factor("needle_roller_drawn_cup") / 1.1, rel=1e-12)
    assert any("shaft" in w for w in cup.warnings[0]) and not any("shaft" in w for w in machined.warnings[0])


def test_spherical_roller_thrust_rated_with_the_thrust_formulas():
    """One spherical roller row at α = atan 1.2 (NSK's X = 1.2): ISO 281 eq. (11) with b_m 1.15, ISO 76
    eq. (7), P = tan α F_r + F_a (ISO 281 8.2) and P0 = 2.3 tan α F_r + F_a (ISO 76 9.2), by hand."""
    alpha = np.arctan(1.2)
    dw, length, dm, z = 16.0, 16.0, 97.0, 15  # mm
    model = sa.spherical_roller_thrust(
        n_elements=z,
        element_diameter=dw * 1e-3,
        effective_length=length * 1e-3,
        pitch_diameter=dm * 1e-3,
        contact_angle=alpha,
    )
    fa, fr = 100e3, np.array([0.0, 20e3])
    res = solve(model, load_vector(F_z=fa, F_x=fr), free=[True, True, True, False, False])
    rating = rate(res, speed=100.0)
    row = rating.rows[0]
    assert row.bearing_type == "thrust_spherical_roller"
    gamma = dw * np.cos(alpha) / dm
    fc = float(iso281.fc_thrust_roller(gamma, alpha))
    c_a = 1.15 * fc * (length * np.cos(alpha)) ** (7 / 9) * z**0.75 * dw ** (29 / 27) * np.tan(alpha)
    c_0a = 220.0 * (1 - gamma) * z * length * dw * np.sin(alpha)
    assert float(row.load_rating[0]) == pytest.approx(c_a, rel=1e-12)
    assert float(row.static_rating[0]) == pytest.approx(c_0a, rel=1e-12)
    life = rating.iso281
    p = 1.2 * fr + fa
    np.testing.assert_allclose(np.ma.getdata(life.load), p, rtol=1e-12)
    np.testing.assert_allclose(np.ma.getdata(life.static_load), 2.3 * 1.2 * fr + fa, rtol=1e-12)
    np.testing.assert_allclose(np.ma.getdata(life.life), (c_a / p) ** (10 / 3) * 1e6, rtol=1e-12)
    assert float(row.life[1]) < float(row.life[0])  # the radial load shortens the L10r
