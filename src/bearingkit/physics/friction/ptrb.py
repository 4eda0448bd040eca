"""Friction of a planetary thread roller bearing (PTRB): per-contact torques, μ and efficiency.

SI units throughout: m, N, Pa, Pa·s, 1/Pa, rad, rad/s, N·m. Pure numpy functions that broadcast over
their arguments (leading case/population axis first).

Zheng et al. (2022, §3.3, eq. 13) write the friction torque of one ITP or OTP contact as

.. math:: M_X = M_{eX}\\cos\\alpha + M_{sX}\\sin\\alpha + M_{dX}\\cos\\alpha + M_{vX}

with M_e (elastic hysteresis), M_s (spin), M_d (differential sliding) and M_v (lubricant viscous
rolling resistance), and take the component formulas from Zheng et al. (2021), which the seed does not
print. bearingkit re-derives them (see each function) and offers two documented readings of how the
contact moments add up to the bearing torque (:data:`CONVENTIONS`):

* ``"paper"`` (the default): eq. (13)–(15) summed **as printed**, M_PTRBa = Z Σ M_Ii + Z Σ M_Oi + M_h.
  Every term of eq. (13) is then the component of a contact moment along the bearing axis: M_e and
  M_d act about the equivalent ball's rolling axis, inclined by α to the bearing axis (hence cos α),
  M_s about the contact normal (hence sin α), and M_v is the moment of the viscous rolling-resistance
  force F_v, which acts circumferentially at the contact point on the pitch circle of ring X, about
  the bearing axis: M_v = F_v d_X/2 — the one term that needs no projection, as eq. (13) prints it
  (``viscous_projection="axis"``). No kinematic factor: the paper sums moments, not powers.
* ``"power"``: the power balance P = M_bearing ω (inner ring turning at ω, outer ring fixed). Roller
  and ring turn about parallel axes, so their relative angular velocity ΔΩ is axial; along a contact
  normal inclined by α it has a rolling part ΔΩ cos α and a spin part ΔΩ sin α, and the bearing
  torque is k (M_e cos α + M_s sin α + M_d cos α) with k = ΔΩ/ω (:func:`kinematics`), plus
  F_v u/(ω cos α) (``"eq13"``) or F_v u/ω (``"power"``). The previous default; k ∝ 1 + d_I/d_R
  falls with d_R and reverses the paper's Table 5 d_R trends (both loads) and its α trend under
  axial load. Get it complete with :data:`POWER_BALANCE_OPTIONS`.

The viscous term M_v (the speed dependence). The paper's simulation data themselves fix its form: the
speed-dependent part of its torque grows as n^0.66 (§4, 30 kN: 0.715 / 0.786 / 1.045 N·m at 100 / 600 /
4000 rpm) and as F^0.47 (Table 8 slopes at 2, 5, 8 kN, §4 at 30 kN) — the U^0.66 W^0.47 signature of
Harris's EHL rolling resistance F_v = 2.86 E′R_y² k^0.348 G^0.022 U^0.66 W^0.47
(:func:`viscous_rolling_harris`), with the printed L-AN data (η₀ = 0.04 Pa·s, α = 2.46e-8 1/Pa, i.e.
an L-AN46 oil at 40 °C). Its transverse radius R_y (:data:`VISCOUS_RADII_Y`) is by default that of the
paper's equivalent steel ball, D_w/2 = d_R/(2 cos α) (§2: "an equivalent steel ball and a plane or arc
surface"); the flank arc R_rr (``"flank"``) makes F_v ∝ R_rr² and the torque rise 67–82 % over the
R_rr range where the paper's rises 11–13 %. With the defaults and NO viscous parameter fitted, Tables
7 and 8 follow within 7 % and Table 5 within 15 % except its contact-angle row (see
``docs/ptrb_friction.md``).

Parameters the paper does not give (each a named constant below): the hysteresis loss fraction, the
sliding traction coefficient in the contacts (the ONE calibrated number:
:data:`CONTACT_TRACTION_CALIBRATED`), the carrier (journal) friction, journal size and roller density.

The laws of one contact (M_e, M_d, F_v) and the contact's parameters (hysteresis, traction, Harris's
constants) are in :mod:`bearingkit.physics.friction.ptrb_laws`; this module re-exports them and holds
the conventions, the kinematics, the per-contact torque of eq. (13), the carrier term, μ and η.

References: ``zheng2022``, ``zheng2021``, ``harris2007`` (spin, Heathcote slip, EHL rolling
resistance), ``tabor1955`` (hysteresis), ``houpert1999`` (alternative EHL rolling resistance),
``heathcote1921``.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.physics.contact import hertz
from bearingkit.physics.friction import components as fc
from bearingkit.physics.friction.ptrb_laws import (
    CONTACT_TRACTION_CALIBRATED,
    CONTACT_TRACTION_POWER_BALANCE,
    HARRIS_ROLLING,
    HEATHCOTE_COEFF,
    HEATHCOTE_ROLLING_LINE,
    HYSTERESIS_PTRB,
    deformed_surface_radius,
    heathcote_moment,
    hysteresis_moment,
    viscous_rolling_harris,
)
from bearingkit.physics.life.ptrb_rating import thread_contact_curvature

__all__ = [
    "CARRIER_FRICTION",
    "COMPONENTS",
    "CONTACT_TRACTION_CALIBRATED",
    "CONTACT_TRACTION_POWER_BALANCE",
    "CONVENTIONS",
    "DEFAULT_VISCOUS_PROJECTION",
    "HARRIS_ROLLING",
    "HEATHCOTE_COEFF",
    "HEATHCOTE_ROLLING_LINE",
    "HYSTERESIS_PTRB",
    "JOURNAL_DIAMETER_RATIO",
    "POWER_BALANCE_OPTIONS",
    "PROJECTIONS_OF_CONVENTION",
    "ROLLER_DENSITY",
    "VISCOUS_MODELS",
    "VISCOUS_PROJECTIONS",
    "VISCOUS_RADII_Y",
    "carrier_torque",
    "contact_torques",
    "deformed_surface_radius",
    "efficiency",
    "friction_coefficient",
    "heathcote_moment",
    "hysteresis_moment",
    "kinematics",
    "resolve_viscous_projection",
    "viscous_rolling_harris",
]

REFERENCE_KEYS = ("zheng2022", "zheng2021", "harris2007", "tabor1955", "houpert1999", "heathcote1921")

#: Friction coefficient of the roller journals ("optical axes") in the planet carrier [1]: steel on
#: steel/brass, boundary lubrication, 0.05–0.15 (SKF μ_bl = 0.12–0.15). Assumed (not in the paper).
CARRIER_FRICTION = 0.1
#: Journal diameter of a threaded roller as a fraction of d_R [1]. Assumed (Fig. 1 is not available).
JOURNAL_DIAMETER_RATIO = 0.5
#: Density of GCr15 bearing steel [kg/m³] (GB/T 18254; 7.81e3).
ROLLER_DENSITY = 7810.0
#: Standard gravity [m/s²].
GRAVITY = fc.STANDARD_GRAVITY

#: How contact moments become the bearing torque (module docstring):
#:
#: * ``"paper"`` (default): Zheng et al. (2022) eq. (13)–(15) summed as printed — the axial components
#:   M_e cos α + M_s sin α + M_d cos α + M_v of each contact, no kinematic factor. Reproduces the
#:   directions of Table 5 except α under axial load, with Tables 7–8 within 7 %.
#: * ``"power"``: the power balance P = M ω, the moments times k = ΔΩ_X/ω (:func:`kinematics`).
#:   Physically the energy-consistent one; reverses the d_R trends of Table 5 (k ∝ 1 + d_I/d_R).
CONVENTIONS = ("paper", "power")
#: How the viscous rolling resistance F_v of one contact enters eq. (13):
#:
#: * ``"axis"`` (``"paper"`` convention, default): M_v = F_v d_X/2, the moment of F_v (circumferential,
#:   at the contact point on the pitch circle of ring X) about the bearing axis — the one moment of
#:   eq. (13) that is already axial, which is why eq. (13) prints it without cos α or sin α.
#: * ``"contact"`` (``"paper"`` convention): M_v = F_v R_x, the rolling-resistance moment about the
#:   equivalent ball's centre (R_x = 1/ρ_B); 3.7–3.9× too small for Table 8's speed slope.
#: * ``"eq13"`` (``"power"`` convention, its default): k F_v R_x = F_v u/(ω cos α), F_v R_x added to
#:   eq. (13) without the cos α the paper puts on M_e and M_d.
#: * ``"power"`` (``"power"`` convention): the strict power balance F_v u/ω; cos α of ``"eq13"``.
#:
#: ``None`` picks the convention's default (:data:`DEFAULT_VISCOUS_PROJECTION`).
VISCOUS_PROJECTIONS = ("axis", "contact", "eq13", "power")
#: Viscous projections allowed under each convention, the first being its default.
PROJECTIONS_OF_CONVENTION = {"paper": ("axis", "contact"), "power": ("eq13", "power")}
#: Default viscous projection of each convention.
DEFAULT_VISCOUS_PROJECTION = {k: v[0] for k, v in PROJECTIONS_OF_CONVENTION.items()}
#: Transverse radius R_y of the contact in Harris's F_v (∝ R_y²):
#:
#: * ``"ball"`` (default): D_w/2 = d_R/(2 cos α), the paper's equivalent steel ball (§2: diameter
#:   d_R/cos α = 8.5 mm, contacting "a plane or arc surface"); F_v then feels R_rr only through the
#:   Hertz contact (ellipticity, W), and Table 5's R_rr row follows (+12 % vs the paper's +11–13 %).
#: * ``"flank"``: 1/ρ_A = (1/R_rr − 1/r_X)⁻¹, the meridional radius of the thread contact (R_rr for flat
#:   flanks). F_v ∝ R_rr²: the torque rises 67–82 % over R_rr = 4.5–7.5 mm. Ring arcs r_X (which the
#:   paper leaves blank) only make R_y larger and the rise steeper.
#: * ``"rolling"``: R_x = 1/ρ_B, i.e. Harris's group written in the Hamrock–Dowson scaling F_v/(E′R_x²)
#:   of W (offered because the R_y² of :data:`HARRIS_ROLLING` is a transcription not re-checked
#:   against the book); within 1 % of ``"ball"`` on Tables 5, 7 and 8.
VISCOUS_RADII_Y = ("ball", "flank", "rolling")
#: The complete power-balance reading (the default before the literal one), as keyword arguments of
#: :func:`contact_torques` and :class:`bearingkit.analysis.friction.threaded.PTRBFrictionParameters`:
#: Tables 7–8 within 5.3 %, Table 5 directions 7/10 (d_R both loads and α axial opposite).
POWER_BALANCE_OPTIONS = {
    "convention": "power",
    "viscous_projection": "eq13",
    "viscous_radius_y": "flank",
    "traction": CONTACT_TRACTION_POWER_BALANCE,
}
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


#: EHL rolling-resistance models a PTRB contact can use: Harris's (default) and the common
#: point-contact models of :data:`bearingkit.physics.friction.components.VISCOUS_POINT_MODELS`.
VISCOUS_MODELS = ("harris", *fc.VISCOUS_POINT_MODELS)


def resolve_viscous_projection(convention, viscous_projection=None):
    """The viscous projection a convention uses: ``viscous_projection`` checked, or its default.

    Parameters
    ----------
    convention : {"paper", "power"}
    viscous_projection : str or None
        One of :data:`PROJECTIONS_OF_CONVENTION` ``[convention]``; None: the first (the default).

    Returns
    -------
    str
    """
    checks.one_of("convention", convention, CONVENTIONS)
    allowed = PROJECTIONS_OF_CONVENTION[convention]
    if viscous_projection is None:
        return allowed[0]
    checks.one_of("viscous_projection", viscous_projection, VISCOUS_PROJECTIONS)
    if viscous_projection not in allowed:
        raise checks.InputError(
            f"viscous_projection ({viscous_projection!r}) must be one of {', '.join(allowed)} "
            f"under convention {convention!r}"
        )
    return viscous_projection


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
    viscous_model="harris",
    convention="paper",
    viscous_projection=None,
    viscous_radius_y="ball",
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
        One of :data:`VISCOUS_MODELS` (``"harris"``: :func:`viscous_rolling_harris`).
    convention : {"paper", "power"}
        How contact moments become bearing torque (:data:`CONVENTIONS`).
    viscous_projection : {"axis", "contact", "eq13", "power"} or None
        How the viscous force enters eq. (13) (:data:`VISCOUS_PROJECTIONS`; the first two belong to the
        paper convention, the last two to the power convention; None: the convention's default).
    viscous_radius_y : {"ball", "flank", "rolling"}
        R_y of Harris's F_v (:data:`VISCOUS_RADII_Y`); ignored by the other viscous models.

    Returns
    -------
    dict of ndarray
        ``elastic``, ``spin``, ``differential``, ``viscous`` [N·m], torque on the inner ring.

    Notes
    -----
    Zheng et al. (2022) eq. (13). As printed (``convention="paper"``, the default):

    .. math::
        M_X = M_e\\cos\\alpha + M_s\\sin\\alpha + M_d\\cos\\alpha + F_v\\,\\frac{d_X}{2}

    (``viscous_projection="axis"``; ``"contact"`` uses F_v R_x instead). With the power balance
    (``convention="power"``, module docstring), k = ΔΩ_X/ω:

    .. math::
        M_X = k_X\\big(M_e\\cos\\alpha + M_s\\sin\\alpha + M_d\\cos\\alpha + F_v R_x\\big),
        \\qquad k_X R_x = \\frac{u}{\\omega\\cos\\alpha}

    (``"eq13"``; ``"power"`` puts cos α on F_v R_x as well, giving F_v u/ω).
    M_e :func:`hysteresis_moment`; M_s = (3/8) μ Q a E(e) (Harris & Kotzalas 2007,
    :func:`~bearingkit.physics.friction.components.spin_moment`); M_d :func:`heathcote_moment`;
    F_v EHL rolling resistance (Harris's form by default) at u = rolling speed relative to the carrier,
    R_x = 1/ρ_B the rolling-direction radius and R_y per ``viscous_radius_y`` (default D_w/2 =
    d_R/(2 cos α), the paper's equivalent ball).
    Rolling is circumferential: the rolling semi-axis is the one along the circumferential curvature
    ρ_B, the transverse one lies in the meridional plane.
    """
    checks.one_of("viscous_model", viscous_model, VISCOUS_MODELS)
    checks.one_of("convention", convention, CONVENTIONS)
    projection = resolve_viscous_projection(convention, viscous_projection)
    checks.one_of("viscous_radius_y", viscous_radius_y, VISCOUS_RADII_Y)
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
    alpha = _a(contact_angle)
    k = kin[side] if convention == "power" else 1.0
    # lever arm of F_v in the bearing torque [m]
    arm = {
        "axis": 0.5 * _a(d_x),  # contact point on the pitch circle of ring X, F_v circumferential
        "contact": 1.0 / rho_b,
        "eq13": kin["rolling_speed"] / np.cos(alpha),  # k R_x = u/(ω cos α), see kinematics
        "power": kin["rolling_speed"],
    }[projection]
    m_e = hysteresis_moment(q, b_roll, hysteresis)
    m_s = fc.spin_moment(q, c.semi_major, c.ellipticity, traction)
    m_d = heathcote_moment(
        q, a_tr, deformed_surface_radius(roller_contact_radius, ring_contact_radius), traction
    )
    u = kin["rolling_speed"] * w
    if viscous_model == "harris":
        # the rolling direction is circumferential: R_x = 1/ρ_B; k = a/b across/along it
        live = b_roll > 0
        k_e = np.where(live, a_tr / np.where(live, b_roll, 1.0), 1.0)
        r_y = {
            "ball": 0.5 * _a(roller_pitch_diameter) / np.cos(alpha),  # D_w/2 of the equivalent ball
            "flank": 1.0 / rho_a,
            "rolling": 1.0 / rho_b,
        }[viscous_radius_y]
        f_v = viscous_rolling_harris(q, viscosity, u, pressure_viscosity, e_reduced, 1.0 / rho_b, r_y, k_e)
    else:
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
