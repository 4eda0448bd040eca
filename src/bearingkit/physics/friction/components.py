"""Friction components of rolling contacts: hysteresis, sliding, EHL viscous rolling, spin, cage.

SI units: N, m, Pa, Pa·s, 1/Pa, m/s, rad/s, W, N·m. Pure numpy functions broadcasting over their
arguments (leading case axis first). Each returns a per-contact force [N] or moment [N·m]; the
assembly (:mod:`bearingkit.analysis.friction.components`) multiplies by the contact's speed to get a power
and divides the bearing's total power by the relative ring speed, as Tian et al. (2025, §4) do.

Registries
----------
:data:`COMPONENTS` names the seed-000 components (E11, M12, E2, E31, M32, M4, M5);
:data:`VISCOUS_LINE_MODELS` and :data:`VISCOUS_POINT_MODELS` hold the interchangeable EHL rolling
resistance models.

The seed text lost its equation layout; every form here is re-derived (hysteresis, spin, sliding)
or taken from the cited primary/secondary source, with its reliability stated.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks, references
from bearingkit.physics.contact.elliptic import ellipe

references.add(
    "tabor1955",
    "Tabor D. (1955) The mechanism of rolling friction II: the elastic range. Proc. R. Soc. A "
    "229:198-220. doi:10.1098/rspa.1955.0082; Johnson K.L. (1985) Contact Mechanics, §9.2(c).",
)
references.add(
    "matsuyama2012",
    "Matsuyama H. (2012) High efficiency and tribology in rolling bearings. JTEKT Engineering Journal "
    "1009E:108-113 (EHL rolling viscous resistance of line contacts).",
)
references.add(
    "fujiwara_ntn",
    "Fujiwara H. et al., NTN Technical Review (rolling viscous resistance of EHL point contacts, "
    "F_HD = 44.6 U^0.694 G^0.961 W^0.401 (1 - 0.962 exp(-0.818 k))); via formulas.md C3 [S].",
)
references.add(
    "houpert1999",
    "Houpert L. (1999) Numerical and analytical calculations in ball bearings. Proc. 8th European "
    "Space Mechanisms and Tribology Symposium, ESA SP-438, 283-290 (EHL rolling resistance).",
)
references.add(
    "deng2015",
    "Deng S., Li M., Lu Y., Dai Y. (2015) Study of friction torque of needle roller thrust bearings. "
    "Acta Armamentarii 36:1347-1355.",
)

# --- empirical constants -----------------------------------------------------------------------
#: Hysteresis loss fraction ξ of bearing steel for rollers, Tian et al. (2025) §4.1 (ξ = 0.01);
#: Tabor-type rolling tests give 0.005-0.02 for hardened steel.
HYSTERESIS_ROLLER = 0.01  # [-]
#: Hysteresis loss fraction β for the balls, Tian et al. (2025) §4.1 (β = 0.007), range 0.005-0.02.
HYSTERESIS_BALL = 0.007  # [-]
#: Moment arm of the leading-half Hertz pressure, line contact: ∫₀ᵇ p x dx = (2/3π) q b (exact).
LINE_FRONT_MOMENT = 2.0 / (3.0 * np.pi)  # [-]
#: Same for an elliptical contact rolling along its semi-axis b: ∬ p x dA = (3/16) Q b (exact).
POINT_FRONT_MOMENT = 3.0 / 16.0  # [-]
#: Spin moment of a Hertz ellipse with Coulomb friction: M = (3/8) μ Q a E(e) (Harris 2007 ch. 9).
SPIN_COEFF = 3.0 / 8.0  # [-]
#: Matsuyama (2012) line-contact rolling viscous resistance F = C E′ R l U^0.75 G^0.04 W^0.08 with
#: W = Q/(E′ R l). Constants as printed in Tian et al. (2025) §4.3 (E31) [M]: not checked against the
#: JTEKT paper (not available here); valid for mineral oils, U ~ 1e-12..1e-10.
MATSUYAMA_COEFF = 14.2  # [-]
MATSUYAMA_U_EXP = 0.75  # [-]
MATSUYAMA_G_EXP = 0.04  # [-]
MATSUYAMA_W_EXP = 0.08  # [-]
#: Aihara (1987) isothermal line-contact rolling resistance per contact, as used by Liu et al. (2022)
#: eq. (7): F = C (1/α)(G U)^0.658 W^0.31 R l (the extracted text prints "0.88 × 10 2"; read here as
#: 0.88×10² = 88, half of Aihara's 176 for two raceways) [M].
AIHARA_COEFF = 88.0  # [-]
AIHARA_GU_EXP = 0.658  # [-]
AIHARA_W_EXP = 0.31  # [-]
#: Fujiwara (NTN) point-contact rolling viscous resistance, formulas.md C3 [S].
FUJIWARA_COEFF = 44.6  # [-]
FUJIWARA_U_EXP = 0.694  # [-]
FUJIWARA_G_EXP = 0.961  # [-]
FUJIWARA_W_EXP = 0.401  # [-]
FUJIWARA_K_AMP = 0.962  # [-]
FUJIWARA_K_RATE = 0.818  # [-]
#: Standard gravity [m/s²] (CGPM 1901, exact).
STANDARD_GRAVITY = 9.80665


def _nonneg(name, v, unit):
    checks.non_negative(name, v, unit)
    return np.asarray(v, dtype=float)


# --- elastic hysteresis ---------------------------------------------------------------------------
def hysteresis_force_line(slice_load, half_width, radius_x, hysteresis=HYSTERESIS_ROLLER):
    """Rolling resistance from elastic hysteresis of one line contact (or slice) [N].

    Parameters
    ----------
    slice_load : array_like [N]
        Load q on the slice (≥ 0).
    half_width : array_like [m]
        Hertz semi-width b of the slice's contact strip.
    radius_x : array_like [m]
        Effective radius R_x in the rolling direction.
    hysteresis : array_like [-]
        Loss fraction ξ (Tian et al. 2025: 0.01).

    Returns
    -------
    ndarray [N]
        Force F_h resisting the rolling; power lost = F_h u_m.

    Notes
    -----
    The leading half of the Hertz pressure does work at the rate M_f u/R_x with
    M_f = ∫₀ᵇ p x dx = 2 q b/(3π); a fraction ξ is not recovered (Tabor 1955; Johnson 1985 §9.2):

    .. math:: F_h = \\xi\\,\\frac{2}{3\\pi}\\,\\frac{q\\,b}{R_x}

    This is the physics behind Tian et al. (2025) E11 (whose layout is lost) and Deng et al. (2015).
    """
    q = _nonneg("slice_load", slice_load, "N")
    b = _nonneg("half_width", half_width, "m")
    checks.positive("radius_x", radius_x, "m")
    checks.non_negative("hysteresis", hysteresis)
    return np.asarray(hysteresis, dtype=float) * LINE_FRONT_MOMENT * q * b / np.asarray(radius_x, dtype=float)


def hysteresis_force_point(load, semi_minor, radius_x, hysteresis=HYSTERESIS_BALL):
    """Rolling resistance from elastic hysteresis of an elliptical contact rolling along b [N].

    Parameters
    ----------
    load : array_like [N]
        Contact load Q.
    semi_minor : array_like [m]
        Semi-axis b in the rolling direction.
    radius_x : array_like [m]
        Effective radius R_x in the rolling direction.
    hysteresis : array_like [-]
        Loss fraction β (Tian et al. 2025: 0.007).

    Notes
    -----
    .. math:: F_h = \\beta\\,\\frac{3}{16}\\,\\frac{Q\\,b}{R_x}

    (front-half moment of the Hertz ellipse, Johnson 1985 §9.2). With b ∝ Q^(1/3) this is the
    Q^(4/3) law of Tian et al. (2025) M12 (the φ terms of elliptic integrals are b/Q^(1/3)).
    """
    q = _nonneg("load", load, "N")
    b = _nonneg("semi_minor", semi_minor, "m")
    checks.positive("radius_x", radius_x, "m")
    checks.non_negative("hysteresis", hysteresis)
    return (
        np.asarray(hysteresis, dtype=float) * POINT_FRONT_MOMENT * q * b / np.asarray(radius_x, dtype=float)
    )


# --- sliding and spin ------------------------------------------------------------------------------
def sliding_power(load, slide_velocity, traction):
    """Power dissipated by sliding of a slice or contact [W].

    Parameters
    ----------
    load : array_like [N]
        Normal load q of the slice.
    slide_velocity : array_like [m/s]
        Sliding velocity v (any sign).
    traction : array_like [-]
        Traction coefficient μ (≥ 0), e.g. :func:`bearingkit.physics.lubrication.traction.traction_mixed`.

    Notes
    -----
    .. math:: P = \\mu\\,q\\,|v|

    Tian et al. (2025) E2 (differential sliding of thrust rollers, after Deng et al. 2017).
    """
    q = _nonneg("load", load, "N")
    checks.finite("slide_velocity", slide_velocity, "m/s")
    mu = _nonneg("traction", traction, "")
    return mu * q * np.abs(np.asarray(slide_velocity, dtype=float))


def spin_moment(load, semi_major, ellipticity, traction):
    """Moment of Coulomb friction resisting spin in a Hertz ellipse [N·m].

    Parameters
    ----------
    load : array_like [N]
        Contact load Q.
    semi_major : array_like [m]
        Semi-major axis a.
    ellipticity : array_like [-]
        κ = a/b ≥ 1.
    traction : array_like [-]
        Friction coefficient μ in the contact.

    Notes
    -----
    Shear μ p over the ellipse, moment about its centre (Harris & Kotzalas 2007, ch. 9):

    .. math:: M_s = \\frac{3}{8}\\,\\mu\\,Q\\,a\\,\\mathcal{E}(e),\\qquad e^2 = 1 - 1/\\kappa^2

    Tian et al. (2025) M4. Check: a circle (κ = 1, E = π/2) gives 3πμQa/16, the closed form.
    """
    q = _nonneg("load", load, "N")
    a = _nonneg("semi_major", semi_major, "m")
    kappa = np.asarray(ellipticity, dtype=float)
    if np.any(~np.isfinite(kappa)) or np.any(kappa < 1.0):
        raise checks.InputError(f"ellipticity ({checks._fmt(kappa)}) must be finite and >= 1")
    mu = _nonneg("traction", traction, "")
    return SPIN_COEFF * mu * q * a * ellipe(1.0 - 1.0 / kappa**2)


def cage_torque(cage_weight, cage_friction, guide_diameter):
    """Torque of a cage sliding on its guiding surface under its own weight [N·m].

    Parameters
    ----------
    cage_weight : array_like [N]
        Weight W_g of the cage (mass × g).
    cage_friction : array_like [-]
        Cage–guide friction coefficient f_c.
    guide_diameter : array_like [m]
        Diameter of the guiding surface (Tian et al. use the pitch diameter d_m).

    Notes
    -----
    .. math:: M_5 = W_g\\, f_c\\, \\frac{d_m}{2}

    Tian et al. (2025) §4.5 (after Zhang et al. 2020).
    """
    w = _nonneg("cage_weight", cage_weight, "N")
    f = _nonneg("cage_friction", cage_friction, "")
    checks.positive("guide_diameter", guide_diameter, "m")
    return w * f * np.asarray(guide_diameter, dtype=float) / 2.0


#: SKF's constant friction coefficient of cylindrical roller thrust bearings, M = 0.5 μ P d (d: bore),
#: against 0.0013 for thrust ball bearings (SKF Rolling bearings catalogue, "Friction", Table 1,
#: "Constant coefficient of friction μ for open bearings"): the order of the load-proportional sliding
#: a thrust cylindrical roller row shows beyond rolling. A reference value for
#: :func:`roller_sliding_torque`, not a default of it.
THRUST_CYLINDRICAL_MU_SKF = 0.005  # [-]


def roller_sliding_torque(load, coefficient, pitch_diameter):
    """Load-proportional sliding torque of the rollers of a thrust (axial) roller row [N·m].

    Parameters
    ----------
    load : array_like [N]
        Normal load Q_j of each roller (leading case axis, elements last).
    coefficient : array_like [-]
        Sliding coefficient μ_rs, referred to the pitch radius (≥ 0).
    pitch_diameter : array_like [m]
        Pitch diameter d_m of the row (> 0).

    Returns
    -------
    ndarray [N·m]
        Torque about the bearing axis per roller.

    Notes
    -----
    .. math:: M_{rs} = \\mu_{rs}\\, Q_j\\, \\frac{d_m}{2}

    Coulomb sliding of a thrust cylindrical roller (roller end on its cage pocket, roller edges on the
    raceways: everything beyond the pitch-line differential sliding E2), referred to the pitch
    radius: the form of SKF's constant-μ estimate M = 0.5 μ P d, whose μ for cylindrical roller
    thrust bearings (:data:`THRUST_CYLINDRICAL_MU_SKF` = 0.005) is ≈ 4× that of thrust ball bearings
    (0.0013). The coefficient of a bearing without catalogue data is identified on a measured (or
    published) torque; seed 000: :mod:`bearingkit.papers.tian2025.calibration`.
    """
    q = _nonneg("load", load, "N")
    mu = _nonneg("coefficient", coefficient, "")
    checks.positive("pitch_diameter", pitch_diameter, "m")
    return mu * q * np.asarray(pitch_diameter, dtype=float) / 2.0


# --- EHL viscous rolling resistance ------------------------------------------------------------------
def _groups(viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x):
    checks.positive("viscosity", viscosity, "Pa*s")
    checks.non_negative("entrainment_speed", entrainment_speed, "m/s")
    checks.positive("pressure_viscosity", pressure_viscosity, "1/Pa")
    checks.positive("e_reduced", e_reduced, "Pa")
    checks.positive("radius_x", radius_x, "m")
    e = np.asarray(e_reduced, dtype=float)
    rx = np.asarray(radius_x, dtype=float)
    u_dim = np.asarray(viscosity, dtype=float) * np.asarray(entrainment_speed, dtype=float) / (e * rx)
    return u_dim, np.asarray(pressure_viscosity, dtype=float) * e, e, rx


def viscous_line_matsuyama(
    load, viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, effective_length
):
    """EHL rolling viscous resistance of a line contact, Matsuyama form [N].

    Parameters
    ----------
    load : array_like [N]
        Contact load Q (≥ 0; zero gives zero).
    viscosity : array_like [Pa·s]
        η₀ at the inlet temperature.
    entrainment_speed : array_like [m/s]
        u_m ≥ 0.
    pressure_viscosity : array_like [1/Pa]
        α.
    e_reduced : array_like [Pa]
        E′.
    radius_x : array_like [m]
        R_x.
    effective_length : array_like [m]
        Contact length l.

    Notes
    -----
    .. math::
        F = 14.2\\,E' R_x l\\;U^{0.75} G^{0.04} W^{0.08},\\quad
        U = \\frac{\\eta_0 u_m}{E' R_x},\\ G = \\alpha E',\\ W = \\frac{Q}{E' R_x l}

    Matsuyama (2012) as printed in Tian et al. (2025) E31 (there written as a moment
    E₀ l R₀² (…) ω_r: for a thrust roller R₀ ω_r = u_m, so power = F u_m is the same). [M]
    """
    u, g, e, rx = _groups(viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x)
    q = _nonneg("load", load, "N")
    checks.positive("effective_length", effective_length, "m")
    length = np.asarray(effective_length, dtype=float)
    w = q / (e * rx * length)
    return MATSUYAMA_COEFF * e * rx * length * u**MATSUYAMA_U_EXP * g**MATSUYAMA_G_EXP * w**MATSUYAMA_W_EXP


def viscous_line_aihara(
    load, viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, effective_length
):
    """Isothermal EHL rolling resistance of one line contact, Aihara form [N].

    Parameters
    ----------
    load : array_like [N]
        Contact load Q.
    viscosity : array_like [Pa·s]
        η₀ at the inlet temperature.
    entrainment_speed : array_like [m/s]
        Mean rolling speed u_m.
    pressure_viscosity : array_like [1/Pa]
        α.
    e_reduced : array_like [Pa]
        E′.
    radius_x : array_like [m]
        Reduced radius in the rolling direction.
    effective_length : array_like [m]
        Contact length l.

    Notes
    -----
    .. math:: F = 88\\,\\frac{1}{\\alpha}\\,(G U)^{0.658}\\,W^{0.31}\\,R_x\\,l,\\qquad W = \\frac{Q}{E' R_x l}

    Aihara (1987) J. Tribol. 109:471 (via Liu et al. 2022 eq. 7 [M], thermal factor omitted).
    """
    u, g, e, rx = _groups(viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x)
    q = _nonneg("load", load, "N")
    checks.positive("effective_length", effective_length, "m")
    length = np.asarray(effective_length, dtype=float)
    w = q / (e * rx * length)
    alpha = np.asarray(pressure_viscosity, dtype=float)
    return AIHARA_COEFF / alpha * (g * u) ** AIHARA_GU_EXP * w**AIHARA_W_EXP * rx * length


def viscous_point_fujiwara(
    load, viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, semi_major, semi_minor
):
    """EHL rolling viscous resistance of an elliptical contact, Fujiwara (NTN) form [N].

    Parameters
    ----------
    load : array_like [N]
    viscosity : array_like [Pa·s]
    entrainment_speed : array_like [m/s]
    pressure_viscosity : array_like [1/Pa]
    e_reduced : array_like [Pa]
    radius_x : array_like [m]
    semi_major, semi_minor : array_like [m]
        Hertz semi-axes a (transverse) and b (rolling direction); κ = a/b.

    Notes
    -----
    .. math::
        F = \\frac{R_x^2}{\\alpha}\\,44.6\\,U^{0.694} G^{0.961} W^{0.401}(1 - 0.962 e^{-0.818\\kappa}),
        \\quad W = \\frac{Q}{E' R_x^2}

    formulas.md C3 [S] (NTN Technical Review).
    """
    u, g, e, rx = _groups(viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x)
    q = _nonneg("load", load, "N")
    a = _nonneg("semi_major", semi_major, "m")
    b = _nonneg("semi_minor", semi_minor, "m")
    kappa = np.where(b > 0, a / np.where(b > 0, b, 1.0), 1.0)
    w = q / (e * rx**2)
    shape = 1.0 - FUJIWARA_K_AMP * np.exp(-FUJIWARA_K_RATE * kappa)
    f_hd = FUJIWARA_COEFF * u**FUJIWARA_U_EXP * g**FUJIWARA_G_EXP * w**FUJIWARA_W_EXP * shape
    return f_hd * rx**2 / np.asarray(pressure_viscosity, dtype=float)


def viscous_point_houpert(
    load, viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, semi_major, semi_minor
):
    """EHL rolling resistance of an elliptical contact, Houpert's analytical form [N].

    Parameters
    ----------
    load : array_like [N]
        Contact load Q.
    viscosity : array_like [Pa·s]
        η₀.
    entrainment_speed : array_like [m/s]
        Mean rolling speed u_m.
    pressure_viscosity : array_like [1/Pa]
        α (not used by this form; kept for a common signature).
    e_reduced : array_like [Pa]
        E′.
    radius_x : array_like [m]
        Reduced radius in the rolling direction.
    semi_major, semi_minor : array_like [m]
        Contact ellipse semi-axes a (transverse) and b (rolling direction).

    Notes
    -----
    With p = 1.5 Q/(π a b), κ_H = b/a, β_H = b E′/(π p R_x), W_H = 2π p b²/(3 κ_H E′ R_x²),
    U_H = 2 η u_m/(E′ R_x), M_H = β_H^0.25 κ_H W_H U_H^-0.75:

    .. math::
        T = \\frac{2a}{R_x}\\Big[\\frac{0.77\\beta_H^{-1/3}\\kappa_H^{0.12}U_H^{-1/12}
            - 1.8\\beta_H^{-1/4}}{1 + M_H/6.6} + 1.8\\beta_H^{-1/4}\\Big]U_H^{0.75},\\qquad
        F = T\\,E' R_x^2

    formulas.md C3 [S] gives the moment T E R_x³; divided by R_x here to give the resisting force
    (Houpert 1999) [S, not re-checked]. Zero speed or zero load gives zero.
    """
    checks.positive("viscosity", viscosity, "Pa*s")
    checks.non_negative("entrainment_speed", entrainment_speed, "m/s")
    checks.positive("e_reduced", e_reduced, "Pa")
    checks.positive("radius_x", radius_x, "m")
    q = _nonneg("load", load, "N")
    a = _nonneg("semi_major", semi_major, "m")
    b = _nonneg("semi_minor", semi_minor, "m")
    e = np.asarray(e_reduced, dtype=float)
    rx = np.asarray(radius_x, dtype=float)
    um = np.asarray(entrainment_speed, dtype=float)
    live = (q > 0) & (um > 0) & (b > 0)
    qs, us = np.where(live, q, 1.0), np.where(live, um, 1.0)
    a, b = np.where(live, a, 1.0), np.where(live, b, 1.0)
    p = 1.5 * qs / (np.pi * a * b)
    kh = b / a
    beta = b * e / (np.pi * p * rx)
    w_h = 2.0 * np.pi * p * b**2 / (3.0 * kh * e * rx**2)
    u_h = 2.0 * np.asarray(viscosity, dtype=float) * us / (e * rx)
    m_h = beta**0.25 * kh * w_h * u_h ** (-0.75)
    inner = (0.77 * beta ** (-1.0 / 3.0) * kh**0.12 * u_h ** (-1.0 / 12.0) - 1.8 * beta**-0.25) / (
        1.0 + m_h / 6.6
    ) + 1.8 * beta**-0.25
    t = 2.0 * a / rx * inner * u_h**0.75
    return np.where(live, t * e * rx**2, 0.0)


#: EHL rolling resistance of line contacts, by name (force [N] per contact).
VISCOUS_LINE_MODELS = {"matsuyama": viscous_line_matsuyama, "aihara": viscous_line_aihara}
#: EHL rolling resistance of point contacts, by name (force [N] per contact).
VISCOUS_POINT_MODELS = {"fujiwara": viscous_point_fujiwara, "houpert": viscous_point_houpert}

#: Seed-000 friction components (Tian et al. 2025 §4) → the pure function that implements each.
COMPONENTS = {
    "hysteresis_roller": hysteresis_force_line,  # E11
    "hysteresis_ball": hysteresis_force_point,  # M12
    "differential_sliding": sliding_power,  # E2
    "viscous_roller": viscous_line_matsuyama,  # E31 (alternatives in VISCOUS_LINE_MODELS)
    "viscous_ball": viscous_point_fujiwara,  # M32 (alternatives in VISCOUS_POINT_MODELS)
    "spin_ball": spin_moment,  # M4
    "cage": cage_torque,  # M5
    "roller_sliding": roller_sliding_torque,  # identified sliding of the thrust roller rows (not in Tian)
}
REFERENCE_KEYS = ("tian2025", "tabor1955", "johnson1985", "harris2007", "matsuyama2012", "fujiwara_ntn")
