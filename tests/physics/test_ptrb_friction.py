"""PTRB friction (seed 004): physics invariants, assembly, calibration and Table 7/8 checks."""

import numpy as np
import pytest
from scipy import integrate
from scipy.special import ellipe

from bearingkit.analysis.ptrb_friction import (
    RPM,
    PTRBFrictionParameters,
    calibrate_contact_traction,
    design_geometry,
    ptrb_friction,
    ptrb_objectives,
)
from bearingkit.bearings.ptrb import ptrb_prototype, ptrb_ratings
from bearingkit.errors import InputError
from bearingkit.physics import ptrb_friction as pf
from bearingkit.physics.ptrb_rating import thread_contact_curvature
from bearingkit.validation import seed004_friction as v

G = ptrb_prototype()


def test_heathcote_constants_from_their_definition():
    t = pf.HEATHCOTE_ROLLING_LINE
    assert 3 * t - t**3 == pytest.approx(1.0, abs=1e-14)
    val, _ = integrate.quad(lambda s: (1 - s**2) * abs(s**2 - t**2), 0, 1, points=[t])
    assert pf.HEATHCOTE_COEFF == pytest.approx(0.75 * val, rel=1e-10)
    assert pf.HEATHCOTE_COEFF == pytest.approx(0.08, abs=0.002)  # Harris's 0.08


def test_heathcote_free_rolling_has_zero_net_traction():
    # strip load (1 - s^2): load inside the rolling lines equals load outside
    t = pf.HEATHCOTE_ROLLING_LINE
    inside, _ = integrate.quad(lambda s: 1 - s**2, 0, t)
    outside, _ = integrate.quad(lambda s: 1 - s**2, t, 1)
    assert inside == pytest.approx(outside, rel=1e-10)


def test_hysteresis_front_half_moment_of_hertz_ellipse():
    a, b, q = 2.0e-4, 1.0e-4, 100.0
    p0 = 3 * q / (2 * np.pi * a * b)
    val, _ = integrate.dblquad(
        lambda y, x: p0 * np.sqrt(max(1 - (x / b) ** 2 - (y / a) ** 2, 0.0)) * x,
        0,
        b,
        lambda x: -a * np.sqrt(1 - (x / b) ** 2),
        lambda x: a * np.sqrt(1 - (x / b) ** 2),
    )
    assert pf.hysteresis_moment(q, b, 1.0) == pytest.approx(val, rel=1e-6)


def test_deformed_surface_radius_limits():
    assert pf.deformed_surface_radius(5e-3, np.inf) == pytest.approx(10e-3)
    assert pf.deformed_surface_radius(5e-3, 5e-3) == pytest.approx(5e-3)


def test_kinematics_rolling_radius_consistency():
    k = pf.kinematics(G.roller_pitch_diameter, G.d_inner, G.d_outer)
    for side, d_x in (("inner", G.d_inner), ("outer", G.d_outer)):
        *_, rho_b = thread_contact_curvature(
            G.roller_pitch_diameter, d_x, G.roller_contact_radius, np.inf, G.contact_angle, side
        )
        # rolling part of the relative angular velocity times the rolling radius = rolling speed
        assert k[side] * np.cos(G.contact_angle) / rho_b == pytest.approx(k["rolling_speed"], rel=1e-12)
    # outer contact: ω_c d_O/2 = u as well
    assert k["carrier"] * G.d_outer / 2 == pytest.approx(k["rolling_speed"], rel=1e-12)


def test_spin_is_reused_from_harris_form():
    c = pf.contact_torques(100.0, "inner", 6e-3, 36.5e-3, 48.5e-3, 5.1e-3, np.inf, np.pi / 4, 2.3e11,
                           0.04, 2.46e-8, 0.0, traction=0.1, convention="paper")  # fmt: skip
    assert c["viscous"] == 0.0
    assert c["spin"] > 0 and c["elastic"] > 0 and c["differential"] > 0
    # spin scales with μ, hysteresis does not
    c2 = pf.contact_torques(100.0, "inner", 6e-3, 36.5e-3, 48.5e-3, 5.1e-3, np.inf, np.pi / 4, 2.3e11,
                            0.04, 2.46e-8, 0.0, traction=0.2, convention="paper")  # fmt: skip
    assert c2["spin"] == pytest.approx(2 * c["spin"])
    assert c2["elastic"] == pytest.approx(c["elastic"])
    assert ellipe(0.0) == pytest.approx(np.pi / 2)


def test_friction_coefficient_and_efficiency_definitions():
    # the paper's check: 0.573 N·m at 20 kN on a 30 mm bore → 0.0019
    assert pf.friction_coefficient(0.573, 20e3, 30e-3) == pytest.approx(0.0019, abs=1e-4)
    assert pf.efficiency(1.0, 99.0) == pytest.approx(0.99)
    with pytest.raises(InputError):
        pf.efficiency(1.0, 0.0)
    with pytest.raises(InputError):
        pf.friction_coefficient(1.0, -5.0, 0.03)


def test_calibration_reproduces_its_one_number():
    assert calibrate_contact_traction() == pytest.approx(pf.CONTACT_TRACTION_CALIBRATED, rel=1e-3)
    m = ptrb_friction(G, 20e3, 600 * RPM, "axial").torque
    assert float(m) == pytest.approx(0.476, rel=2e-3)


@pytest.mark.parametrize("load", [10, 15, 25, 30])
def test_table7_radial_follows_from_axial_calibration(load):
    m = float(ptrb_friction(G, load * 1e3, 600 * RPM, "radial").torque)
    assert m == pytest.approx(v.TABLE7["radial"][load], rel=0.06)


def test_torque_increases_with_load_and_speed():
    loads = np.linspace(1e3, 30e3, 7)
    for case in ("axial", "radial"):
        m = ptrb_friction(G, loads, 600 * RPM, case).torque
        assert np.all(np.diff(m) > 0)
        ms = ptrb_friction(G, 5e3, np.linspace(100, 4000, 6) * RPM, case).torque
        assert np.all(np.diff(ms) > 0)


def test_mu_range_of_section4():
    ll, ss = np.meshgrid(np.linspace(10e3, 30e3, 5), np.array([100, 600, 1500, 4000]) * RPM)
    mu_a = ptrb_friction(G, ll, ss, "axial").friction_coefficient
    mu_r = ptrb_friction(G, ll, ss, "radial").friction_coefficient
    assert 0.0011 <= mu_a.min() and mu_a.max() <= 0.0024
    assert 0.0016 <= mu_r.min() and mu_r.max() <= 0.0031


def test_batched_equals_scalar_and_components_sum():
    r = ptrb_friction(G, np.array([5e3, 20e3]), np.array([600, 2000]) * RPM, "axial")
    for i, (f, w) in enumerate(((5e3, 600 * RPM), (20e3, 2000 * RPM))):
        assert float(ptrb_friction(G, f, w, "axial").torque) == pytest.approx(r.torque[i], rel=1e-12)
    assert sum(r.by_component().values()) == pytest.approx(r.torque)
    d = r.to_dict()
    assert len(d["torque_Nm"]) == 2 and "spin_torque_Nm" in d
    assert list(r.to_pandas().columns)[-1] == "friction_coefficient"


def test_model_tooth_distribution_is_close_to_uniform():
    a = float(ptrb_friction(G, 20e3, 600 * RPM, tooth_distribution="uniform").torque)
    b = float(ptrb_friction(G, 20e3, 600 * RPM, tooth_distribution="model").torque)
    assert b >= a * (1 - 1e-9)  # Q^(4/3) terms: uneven shares cost more (Jensen)
    assert b == pytest.approx(a, rel=0.02)


def test_bad_input():
    with pytest.raises(InputError):
        ptrb_friction(G, 0.0, 600 * RPM)
    with pytest.raises(InputError):
        ptrb_friction(G, 1e3, -1.0)
    with pytest.raises(InputError):
        ptrb_friction(G, 1e3, 1.0, case="tilt")
    with pytest.raises(InputError):
        PTRBFrictionParameters(convention="magic")
    with pytest.raises(InputError):
        ptrb_objectives(np.radians(95.0), 10, 5.1e-3, 6e-3)


def test_objectives_match_the_scalar_api():
    o = ptrb_objectives(np.radians([45.0, 50.0]), [10, 12], [5.1e-3, 6.0e-3], [6.0e-3, 6.5e-3], "radial")
    g = design_geometry(np.radians(50.0), 12, 6.0e-3, 6.5e-3)
    r = ptrb_ratings(g)
    assert o["C0r"][1] == pytest.approx(r.static_radial, rel=1e-9)
    assert o["Cr"][1] == pytest.approx(r.dynamic_radial, rel=1e-9)
    assert o["C0a"][1] == pytest.approx(r.static_axial, rel=1e-9)
    assert o["Ca"][1] == pytest.approx(r.dynamic_axial, rel=1e-9)
    m = ptrb_friction(g, 20e3, 4000 * RPM, "radial").torque
    assert o["M"][1] == pytest.approx(float(m), rel=1e-9)
    assert o["feasible"].dtype == bool and o["feasible"].all()
    # prototype: the paper's ratings
    assert o["C0a"][0] == pytest.approx(38.36e3, rel=0.02) and o["Cr"][0] == pytest.approx(30.26e3, rel=0.02)
