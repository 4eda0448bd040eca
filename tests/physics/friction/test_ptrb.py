"""PTRB friction (seed 004): physics invariants, assembly, calibration and Table 7/8 checks."""

import numpy as np
import pytest
from scipy import integrate
from scipy.special import ellipe

from bearingkit.analysis.friction.threaded import RPM, PTRBFrictionParameters, ptrb_friction
from bearingkit.bearings.ptrb import ptrb_prototype, ptrb_ratings
from bearingkit.errors import InputError
from bearingkit.papers.zheng2022 import validation_friction as v
from bearingkit.papers.zheng2022.design import calibrate_contact_traction, design_geometry, ptrb_objectives
from bearingkit.physics.friction import ptrb as pf
from bearingkit.physics.life.ptrb_rating import thread_contact_curvature

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
    # a mixed-film sliding coefficient, between the SKF model's full-film μ_EHL = 0.05 and boundary
    # μ_bl = 0.12–0.15: not a number pushed to an extreme
    assert 0.05 < pf.CONTACT_TRACTION_CALIBRATED < 0.12
    m = ptrb_friction(G, 20e3, 600 * RPM, "axial").torque
    assert float(m) == pytest.approx(0.476, rel=2e-3)
    # the power-balance reading carries its own calibration at the same published value
    pb = PTRBFrictionParameters.power_balance()
    assert calibrate_contact_traction(parameters=pb) == pytest.approx(
        pf.CONTACT_TRACTION_POWER_BALANCE, rel=1e-3
    )
    assert float(ptrb_friction(G, 20e3, 600 * RPM, parameters=pb).torque) == pytest.approx(0.476, rel=2e-3)
    # `convention` overrides the parameters' convention together with its default projection
    assert calibrate_contact_traction(convention="power", parameters=pb) == pytest.approx(
        pf.CONTACT_TRACTION_POWER_BALANCE, rel=1e-3
    )


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
    """§4: μ_PTRBa 0.0011–0.0024, μ_PTRBr 0.0016–0.0031 over 10–30 kN and 100–4000 rpm."""
    lo_a, hi_a = v.mu_range("axial")
    lo_r, hi_r = v.mu_range("radial")
    # the default model lies inside the PRINTED bounds, no rounding allowance: axial 0.00117–0.00238,
    # radial 0.00161–0.00290 (the conclusions print 0.0023 as the axial maximum: 0.00238 is 3 % above
    # that, 1.3 % above its rounding interval; §4, which discusses Fig. 4, prints 0.0024 twice)
    assert 0.0011 <= lo_a < hi_a <= 0.0024
    assert 0.0016 <= lo_r < hi_r <= 0.0031
    # the extremes are close to the printed ones (endpoint errors +6.1 %, −1.0 %, +0.6 %, −6.4 %)
    assert (lo_a, hi_a) == pytest.approx((0.0011, 0.0024), rel=0.07)
    assert (lo_r, hi_r) == pytest.approx((0.0016, 0.0031), rel=0.07)
    # the speed effect spans most of the published range
    assert hi_r - lo_r > 0.8 * (0.0031 - 0.0016)


def test_mu_range_of_the_power_balance_reading_is_stated_not_hidden():
    """The former default reaches 0.00242 axially: 0.8 % above the printed 0.0024. Only the rounding of
    a two-digit number (0.0024 stands for 0.00235–0.00245) admits it — stated here, not widened."""
    lo_a, hi_a = v.mu_range("axial", PTRBFrictionParameters.power_balance())
    assert hi_a > 0.0024  # outside the printed bound …
    assert 0.00235 <= hi_a < 0.00245 and lo_a >= 0.0011  # … inside its two-digit rounding interval


def test_published_simulation_data_carry_harris_exponents():
    """The paper's own numbers (not bearingkit's) give the speed and load exponents of its M_v."""
    from scipy.optimize import brentq

    # §4, 30 kN axial: 0.715 / 0.786 / 1.045 N·m at 100 / 600 / 4000 rpm → M = M0 + c n^p
    r = (1.045 - 0.786) / (0.786 - 0.715)
    p = brentq(lambda p: (4000**p - 600**p) / (600**p - 100**p) - r, 0.2, 1.5)
    assert p == pytest.approx(pf.HARRIS_ROLLING["U"], abs=0.02)
    # slopes c(F) at the Harris speed exponent: Table 8 (2, 5, 8 kN) and §4 (30 kN), axial
    n = np.array(v.TABLE8_SPEEDS, float)
    x = n ** pf.HARRIS_ROLLING["U"]
    c = [np.polyfit(x, np.array(v.TABLE8["axial"][f]), 1)[0] for f in (2, 5, 8)]
    c.append((1.045 - 0.715) / (4000.0 ** pf.HARRIS_ROLLING["U"] - 100.0 ** pf.HARRIS_ROLLING["U"]))
    q = np.polyfit(np.log([2.0, 5.0, 8.0, 30.0]), np.log(c), 1)[0]
    assert q == pytest.approx(pf.HARRIS_ROLLING["W"], abs=0.03)


def test_harris_rolling_resistance_scaling():
    args = dict(
        viscosity=0.04,
        pressure_viscosity=2.46e-8,
        e_reduced=2.3e11,
        radius_x=3.6e-3,
        radius_y=5.1e-3,
        ellipticity=1.3,
    )
    f = pf.viscous_rolling_harris(100.0, entrainment_speed=1.0, **args)
    assert pf.viscous_rolling_harris(100.0, entrainment_speed=2.0, **args) == pytest.approx(f * 2**0.66)
    assert pf.viscous_rolling_harris(200.0, entrainment_speed=1.0, **args) == pytest.approx(f * 2**0.47)
    assert pf.viscous_rolling_harris(0.0, entrainment_speed=1.0, **args) == 0.0
    assert pf.viscous_rolling_harris(100.0, entrainment_speed=0.0, **args) == 0.0
    # dimensionless form: with η scaled by s and E′ by s (U, W, G fixed if Q scales by s), F scales by s
    s = 3.0
    scaled = dict(args, viscosity=0.04 * s, e_reduced=2.3e11 * s, pressure_viscosity=2.46e-8 / s)
    assert pf.viscous_rolling_harris(100.0 * s, entrainment_speed=1.0, **scaled) == pytest.approx(f * s)
    # order of magnitude for one prototype contact (2 kN axial, 600 rpm): a few hundredths of a newton
    assert 1e-3 < pf.viscous_rolling_harris(25.7, entrainment_speed=0.654, **args) < 0.05
    with pytest.raises(InputError):
        pf.viscous_rolling_harris(1.0, entrainment_speed=1.0, **dict(args, ellipticity=0.0))


PROTO_OUTER = (6e-3, 36.5e-3, 48.5e-3, 5.1e-3, np.inf)  # d_R, d_I, d_O, R_rr, r_O [m]


def _outer_contact(q, alpha, **kw):
    return pf.contact_torques(q, "outer", *PROTO_OUTER, alpha, 2.3e11, 0.04, 2.46e-8, **kw)


def _outer_fv(q, alpha, speed, radius_y):
    """Harris's F_v of the prototype's OTP contact, built by hand [N]."""
    from bearingkit.physics.contact import hertz

    u = pf.kinematics(*PROTO_OUTER[:3])["rolling_speed"] * speed
    s, f, ra, rb = thread_contact_curvature(PROTO_OUTER[0], PROTO_OUTER[2], 5.1e-3, np.inf, alpha, "outer")
    c = hertz.point_contact(q, s, f, 2.3e11)
    a_tr, b_roll = (c.semi_major, c.semi_minor) if rb >= ra else (c.semi_minor, c.semi_major)
    r_y = {"flank": 1 / ra, "ball": PROTO_OUTER[0] / (2 * np.cos(alpha)), "rolling": 1 / rb}[radius_y]
    return float(pf.viscous_rolling_harris(q, 0.04, u, 2.46e-8, 2.3e11, 1 / rb, r_y, a_tr / b_roll))


def test_default_reading_is_eq13_as_printed():
    """k = 1 (moments summed as printed) and M_v = F_v d_O/2, the moment of F_v about the bearing axis."""
    alpha = np.radians(45.0)
    d = _outer_contact(80.0, alpha, speed=300.0)
    p = _outer_contact(80.0, alpha, speed=300.0, convention="power", viscous_projection="eq13")
    k_o = pf.kinematics(*PROTO_OUTER[:3])["outer"]
    for comp in ("elastic", "spin", "differential"):
        assert d[comp] * k_o == pytest.approx(p[comp], rel=1e-12)  # no kinematic factor
    assert d["viscous"] == pytest.approx(
        _outer_fv(80.0, alpha, 300.0, "ball") * PROTO_OUTER[2] / 2, rel=1e-12
    )
    contact = _outer_contact(80.0, alpha, speed=300.0, viscous_projection="contact")
    assert contact["viscous"] / d["viscous"] < 0.25  # F_v R_x: R_x = 4.8 mm against d_O/2 = 24.25 mm
    for bad in ({"viscous_projection": "eq13"}, {"viscous_projection": "sideways"}):
        with pytest.raises(InputError):
            _outer_contact(80.0, alpha, speed=300.0, **bad)
    with pytest.raises(InputError):
        _outer_contact(80.0, alpha, speed=300.0, convention="power", viscous_projection="axis")
    with pytest.raises(InputError):
        _outer_contact(80.0, alpha, speed=300.0, viscous_radius_y="groove")


def test_equivalent_ball_radius_decouples_viscous_force_from_flank_radius():
    """R_y = D_w/2: F_v feels R_rr only through the Hertz contact; R_y = R_rr makes it ∝ R_rr^~2."""
    alpha = np.radians(45.0)
    ratio = {}
    for ry in ("ball", "flank"):
        args = (80.0, "outer", *PROTO_OUTER[:3])
        tail = (np.inf, alpha, 2.3e11, 0.04, 2.46e-8, 300.0)
        f = [
            float(pf.contact_torques(*args, r, *tail, viscous_radius_y=ry)["viscous"])
            for r in (4.5e-3, 7.5e-3)
        ]
        ratio[ry] = f[1] / f[0]
    assert 1.0 < ratio["ball"] < 1.25
    assert ratio["flank"] > 2.0
    # the three radii agree where they coincide: ball = flank when R_rr = D_w/2
    rr = PROTO_OUTER[0] / (2 * np.cos(alpha))
    args = (80.0, "outer", *PROTO_OUTER[:3], rr, np.inf, alpha, 2.3e11, 0.04, 2.46e-8, 300.0)
    b = pf.contact_torques(*args, viscous_radius_y="ball")["viscous"]
    assert pf.contact_torques(*args, viscous_radius_y="flank")["viscous"] == pytest.approx(b, rel=1e-12)


def test_viscous_projection_eq13_is_power_over_cos_alpha():
    u = pf.kinematics(*PROTO_OUTER[:3])["rolling_speed"]
    pb = dict(convention="power", viscous_radius_y="flank")
    for alpha in np.radians([30.0, 45.0, 60.0]):
        eq13 = _outer_contact(80.0, alpha, speed=300.0, viscous_projection="eq13", **pb)
        power = _outer_contact(80.0, alpha, speed=300.0, viscous_projection="power", **pb)
        assert _outer_contact(80.0, alpha, speed=300.0, **pb)["viscous"] == eq13["viscous"]  # its default
        assert eq13["viscous"] == pytest.approx(power["viscous"] / np.cos(alpha), rel=1e-12)
        assert eq13["spin"] == pytest.approx(power["spin"], rel=1e-12)
        # strict power balance: the bearing torque is F_v times the rolling speed u (per unit ω)
        assert power["viscous"] > 0
        assert power["viscous"] == pytest.approx(_outer_fv(80.0, alpha, 300.0, "flank") * u, rel=1e-12)


@pytest.mark.parametrize("case", ["axial", "radial"])
@pytest.mark.parametrize("reading", ["default", "power_balance"])
def test_table8_follows_with_nothing_fitted_in_the_viscous_term(case, reading):
    # worst errors: default −5.9 % (radial 2 kN, 1800 rpm), power balance −3.6 %
    par = PTRBFrictionParameters() if reading == "default" else PTRBFrictionParameters.power_balance()
    speeds = np.array(v.TABLE8_SPEEDS, float) * RPM
    for load, pub in v.TABLE8[case].items():
        m = ptrb_friction(G, load * 1e3, speeds, case, parameters=par).torque
        assert m == pytest.approx(np.array(pub), rel=0.065)
        # the speed slope 600 → 2000 rpm, the quantity Houpert's F_v missed by 25–45 % (here: default
        # −7…−10 %, power balance −4…−7 %)
        assert m[-1] - m[0] == pytest.approx(pub[-1] - pub[0], rel=0.12)


def test_power_projection_keeps_only_cos_alpha_of_the_speed_slope():
    eq13 = PTRBFrictionParameters.power_balance()
    par = PTRBFrictionParameters.power_balance(viscous_projection="power")
    w = np.array([600.0, 2000.0]) * RPM
    d_eq13 = np.diff(ptrb_friction(G, 5e3, w, "axial", parameters=eq13).torque)[0]
    d_power = np.diff(ptrb_friction(G, 5e3, w, "axial", parameters=par).torque)[0]
    assert d_power == pytest.approx(d_eq13 * np.cos(G.contact_angle), rel=1e-9)


def test_lubricant_temperature_is_stated_and_effective():
    # L-AN46 at 40 °C is the grade the printed η₀ = 0.04 Pa·s stands for: nearly the same torque
    base = float(ptrb_friction(G, 5e3, 2000 * RPM, "axial").torque)
    l46 = float(ptrb_friction(G, 5e3, 2000 * RPM, "axial", lubricant="L-AN46", temperature_C=40.0).torque)
    assert l46 == pytest.approx(base, rel=0.02)
    hot = float(ptrb_friction(G, 5e3, 2000 * RPM, "axial", lubricant="L-AN46", temperature_C=60.0).torque)
    assert hot < 0.9 * l46


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
        PTRBFrictionParameters(viscous_projection="sideways")
    with pytest.raises(InputError):
        PTRBFrictionParameters(viscous_projection="eq13")  # a power-balance projection, paper convention
    with pytest.raises(InputError):
        PTRBFrictionParameters(viscous_radius_y="groove")
    with pytest.raises(InputError):
        PTRBFrictionParameters(viscous_model="reynolds")
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
