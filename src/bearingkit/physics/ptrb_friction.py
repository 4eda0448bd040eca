"""Friction of a planetary thread roller bearing (PTRB): per-contact torques, μ and efficiency.

SI units throughout: m, N, Pa, Pa·s, 1/Pa, rad, rad/s, N·m. Pure numpy functions that broadcast over
their arguments (leading case/population axis first).

Zheng et al. (2022, §3.3, eq. 13) write the friction torque of one ITP or OTP contact as

.. math:: M_X = M_{eX}\\cos\\alpha + M_{sX}\\sin\\alpha + M_{dX}\\cos\\alpha + M_{vX}

with M_e (elastic hysteresis), M_s (spin), M_d (differential sliding) and M_v (lubricant viscous
rolling resistance), and take the component formulas from Zheng et al. (2021), which the seed does not
print. bearingkit re-derives them (see each function) and turns every contact moment into the
*bearing* torque it costs by the power balance P = M_bearing ω (inner ring turning at ω, outer ring
fixed). The cos α / sin α of eq. (13) then appear by themselves: roller and ring turn about parallel
axes, so their relative angular velocity ΔΩ is axial; along a contact normal inclined by α it has a
rolling part ΔΩ cos α and a spin part ΔΩ sin α. A contact moment M_e (about the rolling axis) dissipates
M_e ΔΩ cos α, a spin moment M_s ΔΩ sin α: the bearing torque is k (M_e cos α + M_s sin α + M_d cos α)
with k = ΔΩ/ω (:func:`kinematics`) and the viscous force F_v costs F_v u/ω.

Parameters the paper does not give (each a named constant below): the hysteresis loss fraction, the
sliding traction coefficient in the contacts (the ONE calibrated number:
:data:`CONTACT_TRACTION_CALIBRATED`), the carrier (journal) friction, journal size and roller density.

References: ``zheng2022``, ``zheng2021``, ``harris2007`` (spin, Heathcote slip), ``tabor1955``
(hysteresis), ``houpert1999`` (EHL rolling resistance), ``heathcote1921``.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks, references
from bearingkit.physics import friction_components as fc
from bearingkit.physics import hertz
from bearingkit.physics.ptrb_rating import thread_contact_curvature

__all__ = [
    "CARRIER_FRICTION",
    "COMPONENTS",
    "CONTACT_TRACTION_CALIBRATED",
    "CONVENTIONS",
    "HEATHCOTE_COEFF",
    "HEATHCOTE_ROLLING_LINE",
    "HYSTERESIS_PTRB",
    "JOURNAL_DIAMETER_RATIO",
    "ROLLER_DENSITY",
    "carrier_torque",
    "contact_torques",
    "deformed_surface_radius",
    "efficiency",
    "friction_coefficient",
    "heathcote_moment",
    "hysteresis_moment",
    "kinematics",
]

references.add(
    "heathcote1921",
    "Heathcote H.L. (1921) The ball bearing: in the making, under test and on service. Proc. Inst. "
    "Automobile Eng. 15:569-702 (differential slip in conforming grooves); via Harris & Kotzalas (2007), "
    "Advanced Concepts of Bearing Technology, ch. 'Friction in rolling bearings'.",
)
REFERENCE_KEYS = ("zheng2022", "zheng2021", "harris2007", "tabor1955", "houpert1999", "heathcote1921")

#: Hysteresis loss fraction β of hardened bearing steel [1] (equivalent balls of a PTRB are steel balls
#: rolling on steel). Same value as :data:`bearingkit.physics.friction_components.HYSTERESIS_BALL`
#: (Tian et al. 2025 §4.1, β = 0.007); Tabor-type rolling tests give 0.005–0.02. Not in Zheng et al.
HYSTERESIS_PTRB = fc.HYSTERESIS_BALL
#: Sliding traction coefficient μ_c of the lubricated thread contacts [1], used for spin and
#: differential sliding. **CALIBRATED** — the ONE fitted friction parameter of bearingkit's PTRB model:
#: fitted once so that the prototype's axial friction torque at 20 kN and 600 rpm equals Zheng et al.
#: (2022) Table 7, simulation column, 0.476 N·m (see :func:`bearingkit.analysis.ptrb_friction.
#: calibrate_contact_traction`, which recomputes it). Every other Table 7/8 and Table 5 number follows.
#: 0.02465 is an ordinary EHL traction coefficient for a mineral oil at small slide-to-roll ratio
#: (0.01–0.05; the SKF model's μ_EHL is 0.05). Valid for L-AN oil, 40 °C, 1–30 kN, 100–4000 rpm.
CONTACT_TRACTION_CALIBRATED = 0.02465
#: Heathcote rolling lines: zero differential slip at y = ±t·a across the contact, t the root in (0, 1)
#: of 3t − t³ = 1 (free rolling, Coulomb friction, strip load ∝ 1 − y²/a²), t = 2 sin 10° [1] (exact).
HEATHCOTE_ROLLING_LINE = 2.0 * np.sin(np.pi / 18.0)
_T = HEATHCOTE_ROLLING_LINE
#: Heathcote coefficient C_H of M_d = C_H μ Q a²/R_c [1] (exact, = 0.0806; Harris quotes 0.08):
#: (3/4)∫₀¹(1 − s²)|s² − t²| ds.
HEATHCOTE_COEFF = 0.75 * (2.0 / 15.0 - 2.0 * _T**2 / 3.0 + 2.0 * (2.0 * _T**3 / 3.0 - 2.0 * _T**5 / 15.0))
#: Friction coefficient of the roller journals ("optical axes") in the planet carrier [1]: steel on
#: steel/brass, boundary lubrication, 0.05–0.15 (SKF μ_bl = 0.12–0.15). Assumed (not in the paper).
CARRIER_FRICTION = 0.1
#: Journal diameter of a threaded roller as a fraction of d_R [1]. Assumed (Fig. 1 is not available).
JOURNAL_DIAMETER_RATIO = 0.5
#: Density of GCr15 bearing steel [kg/m³] (GB/T 18254; 7.81e3).
ROLLER_DENSITY = 7810.0
#: Standard gravity [m/s²].
GRAVITY = fc.STANDARD_GRAVITY

#: How a contact moment becomes a bearing torque. ``"power"`` (default, calibrated): the power
#: balance P = M ω, k = ΔΩ_X/ω and M_v = F_v u/ω (physically consistent with the planetary
#: kinematics). ``"paper"``: Zheng et al. (2022) eq. (13) read literally — the contact moments
#: M_e cos α + M_s sin α + M_d cos α + M_v summed as they are (k = 1, M_v = F_v R_x); NOT calibrated
#: (its μ_c would be 0.0965, see ``calibrate_contact_traction(convention="paper")``): give your own.
#: The "paper" reading gets the d_R trend of Table 5 right but its viscous part is 2.5× smaller and
#: Table 8's speed slope is missed by up to 50 %; "power" misses it by up to 23 %.
CONVENTIONS = ("paper", "power")
#: Names of the friction components, in the order of Zheng et al. (2022) eq. (13) + the carrier.
COMPONENTS = ("elastic", "spin", "differential", "viscous")


def _a(x):
    return np.asarray(x, dtype=float)


def kinematics(roller_pitch_diameter, inner_pitch_diameter, outer_pitch_diameter):
    """Speed ratios of a PTRB with the inner ring turning and the outer ring fixed.

    Parameters
    ----------
    roller_pitch_diameter, inner_pitch_diameter, outer_pitch_diameter : array_like
        d_R, d_I, d_O [m] (pure rolling on both pitch lines needs d_O = d_I + 2 d_R).

    Returns
    -------
    dict of ndarray
        ``carrier`` ω_c/ω, ``roller`` ω_R/ω (roller about its axis, relative to the carrier),
        ``rolling_speed`` u/ω [m] (rolling speed of the contacts relative to the carrier),
        ``inner`` k_I = |ΔΩ_I|/ω and ``outer`` k_O = |ΔΩ_O|/ω (relative angular velocity of roller and
        ring, both about axes parallel to the bearing axis) [1].

    Notes
    -----
    Rolling without slip on the inner and outer pitch lines (planetary gear relation):

    .. math::
        \\frac{\\omega_c}{\\omega} = \\frac{d_I}{d_I + d_O},\\quad
        \\frac{u}{\\omega} = \\frac{d_I}{2}\\Big(1 - \\frac{\\omega_c}{\\omega}\\Big),\\quad
        k_I = \\Big(1 - \\frac{\\omega_c}{\\omega}\\Big)\\Big(1 + \\frac{d_I}{d_R}\\Big),\\quad
        k_O = \\Big(1 - \\frac{\\omega_c}{\\omega}\\Big)\\frac{d_I (d_O - d_R)}{d_R d_O}

    Check: k_X cos α · R_x,X = u/ω with 1/R_x,X = 2cos α (1/d_R ± 1/d_X) (rolling radius of the
    equivalent ball).
    """
    d_r = checks.positive("roller_pitch_diameter", _a(roller_pitch_diameter), "m")
    d_i = checks.positive("inner_pitch_diameter", _a(inner_pitch_diameter), "m")
    d_o = checks.positive("outer_pitch_diameter", _a(outer_pitch_diameter), "m")
    if np.any(d_o <= d_r):
        raise checks.InputError(
            f"outer_pitch_diameter ({checks._fmt(d_o)} m) must exceed "
            f"roller_pitch_diameter ({checks._fmt(d_r)} m)"
        )
    carrier = d_i / (d_i + d_o)
    rel = 1.0 - carrier
    return {
        "carrier": carrier,
        "roller": rel * d_i / d_r,
        "rolling_speed": 0.5 * d_i * rel,
        "inner": rel * (1.0 + d_i / d_r),
        "outer": rel * d_i * (d_o - d_r) / (d_r * d_o),
    }


def hysteresis_moment(load, rolling_semi_axis, hysteresis=HYSTERESIS_PTRB):
    """Rolling moment lost to elastic hysteresis in one elliptical contact [N·m].

    Parameters
    ----------
    load : array_like
        Contact load Q [N], ≥ 0.
    rolling_semi_axis : array_like
        Semi-axis of the ellipse in the rolling direction [m].
    hysteresis : array_like
        Loss fraction β [1].

    Notes
    -----
    The front half of the Hertz pressure has the moment ∬_{x>0} p x dA = (3/16) Q b about the contact
    centre (exact for an ellipse); a fraction β of this rolling work is not recovered (Tabor 1955;
    Johnson 1985 §9.2; Kakuta's M = 0.375 f_h b Q is the same law with a different constant):

    .. math:: M_e = \\beta\\,\\frac{3}{16}\\,Q\\,b
    """
    q = checks.non_negative("load", _a(load), "N")
    b = checks.non_negative("rolling_semi_axis", _a(rolling_semi_axis), "m")
    beta = checks.non_negative("hysteresis", _a(hysteresis))
    return beta * fc.POINT_FRONT_MOMENT * q * b


def deformed_surface_radius(roller_contact_radius, ring_contact_radius):
    """Radius R_c of the loaded contact surface in the meridional plane [m].

    Parameters
    ----------
    roller_contact_radius : array_like
        R_rr, convex flank arc of the roller [m].
    ring_contact_radius : array_like
        r_X, concave flank arc of the ring [m] (inf: flat flank).

    Notes
    -----
    Equal elastic constants: both surfaces displace equally, so the interface lies midway between the
    unloaded profiles y²/(2R_rr) and y²/(2r_X):

    .. math:: \\frac{1}{R_c} = \\frac{1}{2}\\Big(\\frac{1}{R_{rr}} + \\frac{1}{r_X}\\Big)

    (Harris's R = 2rD/(2r + D) for a ball in a groove; flat flank: R_c = 2R_rr).
    """
    r_rr = checks.positive("roller_contact_radius", _a(roller_contact_radius), "m")
    r_x = _a(ring_contact_radius)
    return 2.0 / (1.0 / r_rr + 1.0 / r_x)


def heathcote_moment(load, transverse_semi_axis, surface_radius, traction=CONTACT_TRACTION_CALIBRATED):
    """Moment equivalent of Heathcote's differential sliding in a conforming contact [N·m].

    Parameters
    ----------
    load : array_like
        Q [N].
    transverse_semi_axis : array_like
        Semi-axis across the rolling direction a [m].
    surface_radius : array_like
        R_c of the loaded surface across the rolling direction [m] (:func:`deformed_surface_radius`).
    traction : array_like
        Sliding friction coefficient μ [1].

    Notes
    -----
    A point at y across the contact sits y²/(2R_c) off the tangent plane, so its rolling radius and
    hence its sliding speed change: v(y) = ω_r (y² − c²)/(2R_c). With strip load q(y) = (3Q/4a)(1 −
    y²/a²) and Coulomb friction, free rolling (zero net traction) fixes c = t a, 3t − t³ = 1
    (t = 0.347); the dissipated power P = μ ∫ q |v| dy = M_d ω_r with

    .. math:: M_d = C_H\\,\\mu\\,\\frac{Q a^2}{R_c},\\qquad
        C_H = \\frac{3}{4}\\int_0^1 (1-s^2)\\,|s^2 - t^2|\\,ds = 0.0806

    (Heathcote 1921; Harris & Kotzalas 2007 give 0.08).
    """
    q = checks.non_negative("load", _a(load), "N")
    a = checks.non_negative("transverse_semi_axis", _a(transverse_semi_axis), "m")
    r_c = checks.positive("surface_radius", _a(surface_radius), "m")
    mu = checks.non_negative("traction", _a(traction))
    return HEATHCOTE_COEFF * mu * q * a**2 / r_c


def contact_torques(
    load,
    side,
    roller_pitch_diameter,
    inner_pitch_diameter,
    outer_pitch_diameter,
    roller_contact_radius,
    ring_contact_radius,
    contact_angle,
    e_reduced,
    viscosity,
    pressure_viscosity,
    speed,
    traction=CONTACT_TRACTION_CALIBRATED,
    hysteresis=HYSTERESIS_PTRB,
    viscous_model="houpert",
    convention="power",
):
    """Bearing friction torque caused by ONE ITP or OTP contact, by component [N·m].

    Parameters
    ----------
    load : array_like
        Normal load Q of the contact [N], ≥ 0.
    side : {"inner", "outer"}
        ITP or OTP.
    roller_pitch_diameter, inner_pitch_diameter, outer_pitch_diameter : array_like
        d_R, d_I, d_O [m].
    roller_contact_radius, ring_contact_radius : array_like
        R_rr and r_I or r_O [m] (inf: flat flank).
    contact_angle : array_like
        α [rad].
    e_reduced : array_like
        E′ [Pa].
    viscosity : array_like
        η₀ [Pa·s].
    pressure_viscosity : array_like
        α_p [1/Pa].
    speed : array_like
        Inner-ring speed ω [rad/s], ≥ 0 (outer ring fixed).
    traction : array_like
        μ_c [1] of spin and differential sliding.
    hysteresis : array_like
        β [1].
    viscous_model : str
        Key of :data:`bearingkit.physics.friction_components.VISCOUS_POINT_MODELS`.
    convention : {"paper", "power"}
        How contact moments become bearing torque (:data:`CONVENTIONS`).

    Returns
    -------
    dict of ndarray
        ``elastic``, ``spin``, ``differential``, ``viscous`` [N·m], torque on the inner ring.

    Notes
    -----
    Zheng et al. (2022) eq. (13) with the power balance (module docstring), k = ΔΩ_X/ω:

    .. math::
        M_X = k_X\\big(M_e\\cos\\alpha + M_s\\sin\\alpha + M_d\\cos\\alpha\\big) + F_v\\,\\frac{u}{\\omega}

    M_e :func:`hysteresis_moment`; M_s = (3/8) μ Q a E(e) (Harris & Kotzalas 2007,
    :func:`~bearingkit.physics.friction_components.spin_moment`); M_d :func:`heathcote_moment`;
    F_v EHL rolling resistance (Houpert 1999 by default) at u = rolling speed, R_x the rolling radius.
    Rolling is circumferential: the rolling semi-axis is the one along the circumferential curvature
    ρ_B, the transverse one lies in the meridional plane.
    """
    checks.one_of("viscous_model", viscous_model, fc.VISCOUS_POINT_MODELS)
    checks.one_of("side", side, ("inner", "outer"))
    w = checks.non_negative("speed", _a(speed), "rad/s")
    d_x = inner_pitch_diameter if side == "inner" else outer_pitch_diameter
    s, f, rho_a, rho_b = thread_contact_curvature(
        roller_pitch_diameter, d_x, roller_contact_radius, ring_contact_radius, contact_angle, side
    )
    q = checks.non_negative("load", _a(load), "N")
    c = hertz.point_contact(q, s, f, e_reduced)
    roll_is_minor = rho_b >= rho_a
    b_roll = np.where(roll_is_minor, c.semi_minor, c.semi_major)
    a_tr = np.where(roll_is_minor, c.semi_major, c.semi_minor)
    kin = kinematics(roller_pitch_diameter, inner_pitch_diameter, outer_pitch_diameter)
    checks.one_of("convention", convention, CONVENTIONS)
    if convention == "power":
        k, arm = kin[side], kin["rolling_speed"]
    else:
        k, arm = 1.0, 1.0 / rho_b
    alpha = _a(contact_angle)
    m_e = hysteresis_moment(q, b_roll, hysteresis)
    m_s = fc.spin_moment(q, c.semi_major, c.ellipticity, traction)
    m_d = heathcote_moment(
        q, a_tr, deformed_surface_radius(roller_contact_radius, ring_contact_radius), traction
    )
    u = kin["rolling_speed"] * w
    f_v = fc.VISCOUS_POINT_MODELS[viscous_model](
        q, viscosity, u, pressure_viscosity, e_reduced, 1.0 / rho_b, a_tr, b_roll
    )
    out = {
        "elastic": k * m_e * np.cos(alpha),
        "spin": k * m_s * np.sin(alpha),
        "differential": k * m_d * np.cos(alpha),
        "viscous": f_v * arm,
    }
    shape = np.broadcast_shapes(*(np.shape(v) for v in out.values()), np.shape(w))
    return {key: np.broadcast_to(v, shape).astype(float) for key, v in out.items()}


def carrier_torque(
    n_elements,
    roller_pitch_diameter,
    inner_pitch_diameter,
    outer_pitch_diameter,
    roller_length,
    carrier_friction=CARRIER_FRICTION,
    journal_ratio=JOURNAL_DIAMETER_RATIO,
    density=ROLLER_DENSITY,
):
    """Carrier friction torque M_h of the roller journals sliding in the planet carrier [N·m].

    Parameters
    ----------
    n_elements : array_like
        Z [1].
    roller_pitch_diameter, inner_pitch_diameter, outer_pitch_diameter : array_like
        d_R, d_I, d_O [m].
    roller_length : array_like
        Threaded length of a roller n·P [m] (its mass m_R = ρ π d_R² L/4).
    carrier_friction : array_like
        μ_h [1].
    journal_ratio : array_like
        Journal diameter / d_R [1].
    density : array_like
        ρ [kg/m³].

    Notes
    -----
    Zheng et al. (2022) say the carrier carries only a small force in balanced running, so M_h
    depends on the structure and not on the load. bearingkit takes that force to be the roller weight
    and converts the journal's sliding power (speed ω_R d_j/2) into a bearing torque:

    .. math:: M_h = Z\\,\\mu_h\\,m_R\\,g\\,\\frac{d_j}{2}\\,\\frac{\\omega_R}{\\omega}

    An assumption of bearingkit (~1e-4 N·m for the prototype, below 0.1 % of the total).
    """
    kin = kinematics(roller_pitch_diameter, inner_pitch_diameter, outer_pitch_diameter)
    length = checks.positive("roller_length", _a(roller_length), "m")
    mu_h = checks.non_negative("carrier_friction", _a(carrier_friction))
    d_r = _a(roller_pitch_diameter)
    mass = _a(density) * np.pi * d_r**2 * length / 4.0
    return _a(n_elements) * mu_h * mass * GRAVITY * 0.5 * _a(journal_ratio) * d_r * kin["roller"]


def friction_coefficient(friction_torque, load, bore_diameter):
    """Bearing friction coefficient μ = 2M/(d_0 F) [1], Zheng et al. (2022) eq. (14)-(15).

    Parameters
    ----------
    friction_torque : array_like
        M_PTRBa or M_PTRBr [N·m].
    load : array_like
        Axial or radial load F [N], > 0.
    bore_diameter : array_like
        d_0 [m] (the paper's check: 0.573 N·m at 20 kN → 0.0019 needs d_0 = 30 mm, the bore).
    """
    f = checks.positive("load", _a(load), "N")
    d0 = checks.positive("bore_diameter", _a(bore_diameter), "m")
    return 2.0 * _a(friction_torque) / (d0 * f)


def efficiency(friction_torque, input_torque):
    """Operating efficiency η = 1 − M/(M + M_D) [1], Zheng et al. (2022) eq. (16) (printed ×100 %).

    Parameters
    ----------
    friction_torque : array_like
        M_PTRB [N·m], ≥ 0.
    input_torque : array_like
        M_D, torque at the input side [N·m], > 0.
    """
    m = checks.non_negative("friction_torque", _a(friction_torque), "N*m")
    m_d = checks.positive("input_torque", _a(input_torque), "N*m")
    return 1.0 - m / (m + m_d)
