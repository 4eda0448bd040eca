"""Planetary thread roller bearing (PTRB): equivalent-ball contact geometry and load ratings.

SI units throughout (m, N, Pa, rad); the only exception is inside the ISO-281-type dynamic rating,
whose constants are defined with D_w in mm and C in N (converted at the function boundary, as in
:mod:`bearingkit.physics.life.iso281`).

Each thread tooth of a roller touches the inner ring (ITP) and the outer ring (OTP). Zheng et al.
(2022) treat every tooth pair as an *equivalent steel ball* of diameter D_w = d_R / cos α whose
contact normals pass through the roller axis. The principal curvatures at a contact are

* in the axial (meridional) plane: roller flank arc +1/R_rr, ring flank −1/r_X (a concave,
  conforming flank of radius r_X > R_rr; r_X = inf is a flat flank);
* in the circumferential plane (Meusnier, surfaces of revolution): roller +2 cos α / d_R,
  inner ring +2 cos α / d_I (convex), outer ring −2 cos α / d_O (concave).

The ratings are those of Zheng et al. (2022) eq. (1)-(13): the static ratings put 4200 MPa at the
most loaded contact (ISO 76 basis for ball bearings); the dynamic ratings are Lundberg–Palmgren
ball ratings with PTRB-specific f_ca, f_cr, combined over the n teeth of a roller like n rows.

The load-distribution coefficients f_amax (axial: largest tooth load over the mean tooth load) and
f_rmax (radial: share of F_r carried by the most loaded roller) come from an earlier paper (Zheng et
al. 2020) and are not published. This module is the ONE place where bearingkit calibrates them, each on
one number of the prototype: :data:`BODY_COMPLIANCE_FACTOR` (f_amax of every design from the tooth
load-sharing model :func:`bearingkit.physics.life.ptrb_load_sharing.design_f_amax` at
:data:`F_AMAX_REFERENCE_LOAD`, identified on C0a = 38.36 kN) and :data:`K_RMAX_CALIBRATED` (f_rmax =
k_r/Z, on C0r = 19.93 kN). :func:`calibrated_distribution_coefficients` gives the prototype's pair.

References: ``zheng2022`` (doi:10.3390/machines10111051), ``zheng2021`` (doi:10.1115/1.4048983),
``zheng2020`` (doi:10.1155/2020/9593051), ``iso76``, ``iso281``, ``harris2007``.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks, references
from bearingkit.physics.contact import hertz

__all__ = [
    "BM_BALL",
    "BODY_COMPLIANCE_FACTOR",
    "CONTACT_STRESS_STATIC",
    "FC_AXIAL_CONST",
    "FC_LAMBDA",
    "FC_RADIAL_CONST",
    "F_AMAX_CALIBRATED",
    "F_AMAX_REFERENCE_LOAD",
    "K_RMAX_CALIBRATED",
    "SIDES",
    "basic_dynamic_axial",
    "basic_dynamic_radial",
    "calibrated_distribution_coefficients",
    "dynamic_rating_thread",
    "fc_axial",
    "fc_radial",
    "roller_structure_ratio",
    "static_contact_load",
    "static_rating_axial",
    "static_rating_radial",
    "stress_cycles",
    "thread_contact_curvature",
]

REFERENCE_KEYS = ("zheng2022", "zheng2021", "zheng2020", "iso76", "iso281", "harris2007")
references.add(
    "zheng2021",
    "Zheng S.C., Fu Y.L., Wang D.Y., Pan J.L., Li L.J., Wang J.B. (2021) A novel planetary thread roller "
    "bearing: design and analysis of load characteristic. J. Mech. Des. 143(6):064501. doi:10.1115/1.4048983",
)
references.add(
    "zheng2020",
    "Zheng S.C., Fu Y.L., Pan J.L., Li L.J., Wang D.Y. (2020) An in-depth study on load distribution "
    "characteristics of the planetary threaded roller bearing. Math. Probl. Eng. 2020:9593051. "
    "doi:10.1155/2020/9593051",
)

#: Contact stress at the centre of the most loaded contact under the basic static rating [Pa];
#: ISO 76:2006 clause 6.1 for ball bearings (except self-aligning); Zheng et al. (2022) eq. (1).
CONTACT_STRESS_STATIC = 4200.0e6
#: ISO 281 rating factor b_m of ball bearings [1]; ISO 281:2007 Table 1 (radial and angular ball).
BM_BALL = 1.3
#: Reduction factor λ in f_ca, f_cr [1] as printed by Zheng et al. (2022) eq. (7)-(8) ("0.9 ×").
FC_LAMBDA = 0.9
#: Lundberg–Palmgren constant of thrust ball bearings [N/mm^1.8 units of ISO 281], Zheng et al. (2022)
#: eq. (7) "98.07" (= ISO/TR 1281-1 thrust-ball constant 98.0665 rounded).
FC_AXIAL_CONST = 98.07
#: Lundberg–Palmgren constant of radial ball bearings, Zheng et al. (2022) eq. (8) "39.91"
#: (ISO/TR 1281-1: 39.9).
FC_RADIAL_CONST = 39.91
#: Exponent of the conformity term in f_c [1] (Lundberg & Palmgren 1947; ISO/TR 1281-1).
FC_CONFORMITY_EXP = 0.41
#: Ratio of the inner- and outer-raceway capacities' ellipse factor 1.04 [1] (radial ball, ISO/TR 1281-1).
FC_RADIAL_RING_FACTOR = 1.04
#: ISO 281 exponents: γ^0.3 (1−γ)^1.39 (1+γ)^(−1/3), {…}^(−0.3), ring ratio exponent 1.72, 10/3.
FC_GAMMA_EXP, FC_ONE_MINUS_EXP, FC_ONE_PLUS_EXP = 0.3, 1.39, 1.0 / 3.0
FC_OUTER_EXP, FC_RING_RATIO_EXP, FC_LIFE_EXP = 0.3, 1.72, 10.0 / 3.0
#: Ball-size limit of the D_w^1.8 law [m] and the large-ball constants (ISO 281:2007 eq. 2-3).
BALL_DIAMETER_LIMIT = 25.4e-3
LARGE_BALL_FACTOR, BALL_D_EXP, LARGE_BALL_D_EXP, BALL_Z_EXP, ROW_EXP = 3.647, 1.8, 1.4, 2.0 / 3.0, 0.7
_MM = 1.0e-3

#: Maximum axial load-distribution coefficient f_amax of the PROTOTYPE [1] (largest tooth load / mean
#: tooth load) that meets C0a = 38.36 kN: what the load-sharing model gives for the prototype with
#: :data:`BODY_COMPLIANCE_FACTOR` (by construction). Other designs: ``design_f_amax``.
F_AMAX_CALIBRATED = 1.0670
#: Bearing axial load at which f_amax of a design is evaluated [N]: 20 kN, the load of Zheng et al.
#: (2022) §5 and §6 ("the axial load or radial load was 20 kN"), where Table 4 and Table 6 are computed.
F_AMAX_REFERENCE_LOAD = 20.0e3
#: CALIBRATED multiplier of the core compliances P/(EA) of roller and rings in the tooth load-sharing
#: model [1], identified once so that the prototype's f_amax is :data:`F_AMAX_CALIBRATED` (i.e. on C0a =
#: 38.36 kN; :func:`bearingkit.bearings.ptrb.identify_body_compliance_factor`). 0.56: the cores are
#: ≈ 1.8× stiffer than their bare sections (the ring shoulders and thread ridges carry axial load too).
#: With it Table 4's C0a and Ca of every sweep endpoint follow to 0.5 % (α = 60°: 1.5 %).
BODY_COMPLIANCE_FACTOR = 0.5595
#: CALIBRATED Stribeck-type constant k_r of f_rmax = k_r / Z [1] (Stribeck's theoretical value for
#: point contact without clearance is 4.37, his design value 5). See
#: :func:`calibrated_distribution_coefficients`.
K_RMAX_CALIBRATED = 4.107

#: Contact pairs: inner ring – thread (ITP) and outer ring – thread (OTP).
SIDES = ("inner", "outer")


def _a(x):
    return np.asarray(x, dtype=float)


def thread_contact_curvature(
    roller_pitch_diameter,
    ring_pitch_diameter,
    roller_contact_radius,
    ring_contact_radius,
    contact_angle,
    side,
):
    """Principal curvatures of an ITP or OTP contact (equivalent ball on a thread flank).

    Parameters
    ----------
    roller_pitch_diameter : array_like
        d_R [m], > 0.
    ring_pitch_diameter : array_like
        d_I (``side="inner"``) or d_O (``side="outer"``) [m], > 0.
    roller_contact_radius : array_like
        R_rr, flank arc radius of the roller thread [m], > 0.
    ring_contact_radius : array_like
        r_I or r_O, flank arc radius of the ring thread [m], > R_rr; ``inf`` = flat flank.
    contact_angle : array_like
        α [rad], in (0, π/2).
    side : {"inner", "outer"}

    Returns
    -------
    curvature_sum, curvature_difference, rho_axial, rho_circumferential : ndarray
        Σρ [1/m], F(ρ) [1], and the two plane sums ρ_A (meridional) and ρ_B (circumferential) [1/m].

    Notes
    -----
    .. math::
        \\rho_A = \\frac{1}{R_{rr}} - \\frac{1}{r_X},\\qquad
        \\rho_B = \\frac{2\\cos\\alpha}{d_R} \\pm \\frac{2\\cos\\alpha}{d_X},\\qquad
        \\Sigma\\rho = \\rho_A + \\rho_B,\\qquad F(\\rho) = \\frac{|\\rho_B - \\rho_A|}{\\Sigma\\rho}

    (+ inner, − outer ring). Derived from Zheng et al. (2021, 2022, eq. 2) by Meusnier's theorem; with
    r_X = D_w/2 and R_rr = D_w/2 … it is Harris & Kotzalas (2007) eq. (2.27)-(2.34) of a ball.
    """
    checks.one_of("side", side, SIDES)
    d_r = checks.positive("roller_pitch_diameter", _a(roller_pitch_diameter), "m")
    d_x = checks.positive("ring_pitch_diameter", _a(ring_pitch_diameter), "m")
    r_rr = checks.positive("roller_contact_radius", _a(roller_contact_radius), "m")
    r_x = _a(ring_contact_radius)
    if np.any(np.isnan(r_x)) or np.any(r_x <= r_rr):
        raise checks.InputError(
            f"ring_contact_radius ({checks._fmt(r_x)} m) must exceed roller_contact_radius "
            f"({checks._fmt(r_rr)} m) (inf = flat flank)"
        )
    alpha = checks.in_range("contact_angle", _a(contact_angle), 0.0, np.pi / 2, "rad", closed=False)
    sign = 1.0 if side == "inner" else -1.0
    rho_a = 1.0 / r_rr - 1.0 / r_x
    rho_b = 2.0 * np.cos(alpha) / d_r + sign * 2.0 * np.cos(alpha) / d_x
    s = rho_a + rho_b
    return s, np.abs(rho_b - rho_a) / s, rho_a, rho_b


def static_contact_load(curvature_sum, curvature_difference, e_reduced, max_pressure=CONTACT_STRESS_STATIC):
    """Normal load Q_0 that raises the Hertz pressure of one contact to ``max_pressure`` [N].

    Parameters
    ----------
    curvature_sum : array_like
        Σρ [1/m].
    curvature_difference : array_like
        F(ρ) [1].
    e_reduced : array_like
        E′ = 2/[(1−ν₁²)/E₁ + (1−ν₂²)/E₂] [Pa].
    max_pressure : array_like
        Allowed p_max [Pa] (4200 MPa: ISO 76 ball basis).

    Returns
    -------
    ndarray
        Q_0 [N].

    Notes
    -----
    Inverting p_max = 3Q/(2πab), a = a*(3Q/(Σρ E′))^(1/3), b likewise (Harris & Kotzalas 2007, ch. 6):

    .. math::
        Q_0 = \\Big(\\frac{2\\pi a^* b^*\\sigma_{max}}{3}\\Big)^3
        \\Big(\\frac{3}{\\Sigma\\rho E'}\\Big)^2

    Zheng et al. (2022) eq. (2) with m_a = a*, m_b = b* and 3(1−ν²)/E = 3·(2/E′)/2.
    """
    checks.positive("max_pressure", max_pressure, "Pa")
    a_star, b_star, _ = hertz.contact_coefficients(curvature_difference)
    s = checks.positive("curvature_sum", _a(curvature_sum), "1/m")
    e_r = checks.positive("e_reduced", _a(e_reduced), "Pa")
    return (2.0 * np.pi * a_star * b_star * _a(max_pressure) / 3.0) ** 3 * (3.0 / (s * e_r)) ** 2


def static_rating_axial(contact_load_limit, n_elements, n_teeth, contact_angle, f_amax):
    """Basic static axial rating C_0a [N], Zheng et al. (2022) eq. (2).

    Parameters
    ----------
    contact_load_limit : array_like
        Q_0 of the weaker (ITP or OTP) contact [N] (:func:`static_contact_load`).
    n_elements : array_like
        Number of rollers Z [1].
    n_teeth : array_like
        Teeth per roller n [1].
    contact_angle : array_like
        α [rad].
    f_amax : array_like
        Maximum axial distribution coefficient (largest / mean tooth load) [1], ≥ 1.

    Notes
    -----
    .. math:: C_{0a} = \\frac{Z\\,n\\,Q_0\\sin\\alpha}{f_{a,max}}
    """
    checks.positive("f_amax", f_amax)
    return _a(n_elements) * _a(n_teeth) * _a(contact_load_limit) * np.sin(_a(contact_angle)) / _a(f_amax)


def static_rating_radial(contact_load_limit, n_teeth, contact_angle, f_rmax):
    """Basic static radial rating C_0r [N], Zheng et al. (2022) eq. (5).

    Parameters
    ----------
    contact_load_limit : array_like
        Q_0 [N].
    n_teeth : array_like
        n [1]; under radial load both flanks of every tooth carry (2n equivalent balls per roller).
    contact_angle : array_like
        α [rad].
    f_rmax : array_like
        Share of F_r carried by the most loaded roller [1], in (0, 1].

    Notes
    -----
    .. math:: C_{0r} = \\frac{2\\,n\\,Q_0\\cos\\alpha}{f_{r,max}}
    """
    checks.in_range("f_rmax", f_rmax, 0.0, 1.0)
    return 2.0 * _a(n_teeth) * _a(contact_load_limit) * np.cos(_a(contact_angle)) / _a(f_rmax)


def roller_structure_ratio(roller_pitch_diameter, pitch_diameter):
    """γ = d_R / D_pw [1] (= D_w cos α / D_pw of the equivalent ball), Zheng et al. (2022) eq. (9).

    Parameters
    ----------
    roller_pitch_diameter : array_like [m]
        d_R.
    pitch_diameter : array_like [m]
        D_pw, the bearing pitch diameter.
    """
    return _a(roller_pitch_diameter) / _a(pitch_diameter)


def stress_cycles(n_elements, gamma):
    """Stress cycles per revolution of the inner and outer ring threads, Zheng et al. (2022) eq. (9).

    Parameters
    ----------
    n_elements : array_like
        Z [1].
    gamma : array_like
        γ = d_R / D_pw [1].

    Returns
    -------
    beta_inner, beta_outer : ndarray
        [1]: β_I = Z(D_pw + d_R)/(2 D_pw) = Z(1 + γ)/2, β_O = Z(1 − γ)/2 (rollers passing a point
        of the ring per revolution of the ring relative to the carrier).
    """
    z, g = _a(n_elements), _a(gamma)
    return z * (1.0 + g) / 2.0, z * (1.0 - g) / 2.0


def _fc_common(gamma, roller_contact_radius, ring_contact_radius, roller_pitch_diameter, contact_angle):
    g = checks.in_range("gamma", _a(gamma), 0.0, 1.0, closed=False)
    r_rr = _a(roller_contact_radius)
    inv_r = 1.0 / _a(ring_contact_radius)  # 0 for a flat flank
    conform = 2.0 * np.cos(_a(contact_angle)) / (_a(roller_pitch_diameter) * (1.0 / r_rr - inv_r))
    size = g**FC_GAMMA_EXP * (1.0 - g) ** FC_ONE_MINUS_EXP / (1.0 + g) ** FC_ONE_PLUS_EXP
    return g, size * conform**FC_CONFORMITY_EXP


def fc_axial(gamma, contact_angle, roller_contact_radius, ring_contact_radius, roller_pitch_diameter):
    """PTRB thrust factor f_ca [ISO 281 units, N/mm^1.8], Zheng et al. (2022) eq. (7).

    Parameters
    ----------
    gamma : array_like
        d_R / D_pw [1].
    contact_angle : array_like
        α [rad].
    roller_contact_radius, ring_contact_radius : array_like
        R_rr, r_I [m] (r_I = inf: flat flank).
    roller_pitch_diameter : array_like
        d_R [m].

    Notes
    -----
    .. math::
        f_{ca} = \\lambda\\,98.07\\Big(1 - \\frac{\\sin\\alpha}{3}\\Big)
        \\frac{\\gamma^{0.3}(1-\\gamma)^{1.39}}{(1+\\gamma)^{1/3}}
        \\Big[\\frac{2R_{rr}r_I\\cos\\alpha}{d_R(r_I - R_{rr})}\\Big]^{0.41}
        \\Big[1 + \\Big(\\frac{1-\\gamma}{1+\\gamma}\\Big)^{17.2/3}\\Big]^{-0.3}

    The conformity term is ISO/TR 1281-1's 2f/(2f−1) = ρ_ball / (ρ_ball − ρ_groove) with the roller
    flank and ring flank of the thread in place of ball and groove.
    """
    g, common = _fc_common(
        gamma, roller_contact_radius, ring_contact_radius, roller_pitch_diameter, contact_angle
    )
    ring = (1.0 + ((1.0 - g) / (1.0 + g)) ** (FC_RING_RATIO_EXP * FC_LIFE_EXP)) ** (-FC_OUTER_EXP)
    return FC_LAMBDA * FC_AXIAL_CONST * (1.0 - np.sin(_a(contact_angle)) / 3.0) * common * ring


def fc_radial(gamma, contact_angle, roller_contact_radius, ring_contact_radius, roller_pitch_diameter):
    """PTRB radial factor f_cr [ISO 281 units], Zheng et al. (2022) eq. (8).

    Parameters
    ----------
    gamma : array_like
        γ = d_R / D_pw.
    contact_angle : array_like [rad]
        Thread flank angle α.
    roller_contact_radius : array_like [m]
        R_rr, the roller thread profile radius.
    ring_contact_radius : array_like [m]
        r_I (or r_O), the ring flank radius (``inf`` for flat flanks).
    roller_pitch_diameter : array_like [m]
        d_R.

    Notes
    -----
    .. math::
        f_{cr} = \\lambda\\,39.91\\frac{\\gamma^{0.3}(1-\\gamma)^{1.39}}{(1+\\gamma)^{1/3}}
        \\Big[\\frac{2R_{rr}r_I\\cos\\alpha}{d_R(r_I - R_{rr})}\\Big]^{0.41}
        \\Big\\{1 + \\Big[1.04\\Big(\\frac{1-\\gamma}{1+\\gamma}\\Big)^{1.72}\\Big]^{10/3}\\Big\\}^{-0.3}
    """
    g, common = _fc_common(
        gamma, roller_contact_radius, ring_contact_radius, roller_pitch_diameter, contact_angle
    )
    ring = (1.0 + (FC_RADIAL_RING_FACTOR * ((1.0 - g) / (1.0 + g)) ** FC_RING_RATIO_EXP) ** FC_LIFE_EXP) ** (
        -FC_OUTER_EXP
    )
    return FC_LAMBDA * FC_RADIAL_CONST * common * ring


def dynamic_rating_thread(fc, element_diameter, n_elements, contact_angle, axial: bool):
    """Dynamic rating of ONE thread (one tooth of every roller) C_Da or C_Dr [N], Zheng et al. eq. (6).

    Parameters
    ----------
    fc : array_like
        f_ca or f_cr [ISO 281 units].
    element_diameter : array_like
        Equivalent ball diameter D_w = d_R / cos α [m].
    n_elements : array_like
        Z [1].
    contact_angle : array_like
        α [rad].
    axial : bool
        True: C_Da (factor tan α); False: C_Dr.

    Notes
    -----
    .. math::
        C_D = b_m f_c (\\cos\\alpha)^{0.7} Z^{2/3} D_w^{1.8}\\,[\\tan\\alpha]\\quad(D_w \\le 25.4\\text{ mm}),
        \\qquad 3.647\\,b_m f_c (\\cos\\alpha)^{0.7} Z^{2/3} D_w^{1.4}\\,[\\tan\\alpha]\\quad\\text{otherwise}

    ISO 281:2007 eq. (2)-(3), (5)-(6) with D_w in mm.
    """
    dw = checks.positive("element_diameter", _a(element_diameter), "m")
    alpha = _a(contact_angle)
    dw_mm = dw / _MM
    size = np.where(dw <= BALL_DIAMETER_LIMIT, dw_mm**BALL_D_EXP, LARGE_BALL_FACTOR * dw_mm**LARGE_BALL_D_EXP)
    c = BM_BALL * _a(fc) * np.cos(alpha) ** ROW_EXP * _a(n_elements) ** BALL_Z_EXP * size
    return c * np.tan(alpha) if axial else c


def basic_dynamic_axial(thread_rating, n_teeth, f_amax):
    """Basic dynamic axial rating C_a = n^0.7 C_Da / f_amax [N], Zheng et al. (2022) eq. (11).

    Parameters
    ----------
    thread_rating : array_like [N]
        C_Da, the axial rating of one tooth row.
    n_teeth : array_like
        Engaged teeth per roller n.
    f_amax : array_like
        Axial load distribution coefficient of the most loaded tooth.

    n^0.7 C_Da is ISO 281 eq. (7) for n identical rows,
    (Σ Z)[Σ (Z/C_D)^(10/3)]^(−0.3) (:func:`bearingkit.physics.life.iso281.combine_thrust_rows`); f_amax
    corrects for the uneven axial share of the teeth of a roller.
    """
    checks.positive("f_amax", f_amax)
    return _a(n_teeth) ** ROW_EXP * _a(thread_rating) / _a(f_amax)


def basic_dynamic_radial(thread_rating, n_teeth):
    """Basic dynamic radial rating C_r = (2n)^0.7 C_Dr [N], Zheng et al. (2022) eq. (12).

    Parameters
    ----------
    thread_rating : array_like [N]
        C_Dr, the radial rating of one flank row.
    n_teeth : array_like
        Engaged teeth per roller n.

    Both flanks of the n teeth act as 2n rows of equivalent balls (ISO 281 factor i^0.7).
    """
    return (2.0 * _a(n_teeth)) ** ROW_EXP * _a(thread_rating)


def calibrated_distribution_coefficients(n_elements):
    """The calibrated load-distribution coefficients (f_amax, f_rmax) [1] of the PROTOTYPE — a CALIBRATION.

    Zheng et al. (2022) take f_amax and f_rmax from Zheng et al. (2020) without printing them. bearingkit
    calibrates them once, with flat ring flanks (r_I = r_O = inf) and exact Hertz coefficients:

    * f_amax = :data:`F_AMAX_CALIBRATED` = 1.0670 reproduces C_0a = 38.36 kN of the prototype
      (Zheng et al. 2022, Table 3); for another design f_amax comes from the load-sharing model with the
      identified :data:`BODY_COMPLIANCE_FACTOR` (:func:`bearingkit.bearings.ptrb.ptrb_ratings`,
      ``distribution="design"``), this constant is then the prototype's value;
    * f_rmax = :data:`K_RMAX_CALIBRATED` / Z with k_r = 4.107 reproduces C_0r = 19.93 kN and nothing else
      (the 1/Z law is Stribeck's; the paper's Table 4 shows C_0r ∝ Z, which it honours).

    C_a and C_r are not touched by the calibration (C_r does not contain f_rmax; C_a uses f_amax from
    C_0a). The physical distribution model
    (:func:`bearingkit.rows.threaded.distribution.axial_tooth_distribution`,
    :func:`bearingkit.rows.threaded.distribution.radial_roller_distribution`) gives f_amax ≈ 1.0 … 1.1 and
    f_rmax = 4.37/Z … 3.95/Z, the same order.

    Parameters
    ----------
    n_elements : array_like
        Number of rollers Z [1].

    Returns
    -------
    f_amax, f_rmax : ndarray
    """
    z = checks.positive("n_elements", _a(n_elements))
    return np.full_like(z, F_AMAX_CALIBRATED), K_RMAX_CALIBRATED / z
