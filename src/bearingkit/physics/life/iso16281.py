"""ISO/TS 16281:2008 basic reference rating life from the internal load distribution.

All inputs and outputs are SI: lengths in m, loads in N, angles in rad, lives in revolutions (ISO/TS 16281
quotes L10r in millions of revolutions: divide by 1e6). The raceway ratings Q_c are derived from the
bearing's ISO 281 basic dynamic load rating C, so they carry the unit of C and need no mm conversion;
the only dimensional inputs (groove radii, diameters) enter as ratios.

Arrays carry leading case axes: element loads are ``Q[..., element]`` (balls) and slice loads
``q[..., element, slice]`` (rollers); ratings broadcast against the leading axes.

The modified reference rating life is ``a1 · a_ISO · L10r`` with the factors of
:mod:`bearingkit.physics.life.iso281` (:func:`~bearingkit.physics.life.iso281.modified_rating_life`),
a_ISO being evaluated with the reference equivalent load of :func:`reference_equivalent_load`.

Edition: every equation here is the 2008 Technical Specification's, ISO/TS 16281:2008. ISO 16281:2025 has
replaced it (an International Standard that also covers multi-row and thrust bearings); its text was not
available, so nothing here follows it, and where bearingkit rates multi-row or thrust bearings it applies
the 2008 equations row by row.

References: ISO/TS 16281:2008 (``cite("iso16281")``) eq. (19)-(29) ball, (47)-(65) roller (equation
numbers and constants as two public implementations of the TS transcribe them — minzhun/ISO16281 and the
``axisforge`` ISO/TS 16281 solver, which also quotes the TS's note on eq. (60); the TS text itself was not
available); Lundberg & Palmgren (1947, 1952); Harris & Kotzalas 2007 vol. 2 ch. 8 (``cite("harris2007")``).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError

__all__ = [
    "ROTATING_RING",
    "ball_raceway_ratings",
    "ball_reference_life",
    "edge_stress_factor",
    "reference_equivalent_load",
    "roller_raceway_ratings",
    "roller_reference_life",
]

MILLION = 1.0e6  # lives of the standard are in 1e6 revolutions
RADIAL_MAX_ANGLE = np.pi / 4

# --- ball (point contact), Lundberg–Palmgren as used by ISO/TS 16281 eq. (19)-(29) -----------------------
#: Ratio C_r / (Q_c Z cos α) for a radial row under the zero-clearance (ε = 0.5) Stribeck distribution,
#: Q = Q_max cos^1.5 ψ: J_r / J_1 for the rotating ring (cubic mean) and J_r / J_2 for the stationary ring
#: (10/3-power mean); the integrals give 0.2288/0.5625 = 0.4068 and 0.2288/0.5874 = 0.3895
#: (Lundberg & Palmgren 1947; Harris & Kotzalas 2007 ch. 8); the TS rounds to 0.407 and 0.389.
BALL_RADIAL_INNER = 0.407
BALL_RADIAL_OUTER = 0.389
#: Ratio of inner- to outer-raceway ratings Q_ci/Q_ce for a radial bearing (1.044 radial; thrust bearings
#: use 1: both washers see the same element load).
BALL_RING_RATIO = 1.044
BALL_GAMMA_EXP = 1.72  # exponent of (1-γ)/(1+γ) in the ring-rating ratio
BALL_CONFORMITY_EXP = 0.41  # exponent of the conformity term in the ring-rating ratio
BALL_ROW_EXP = 0.7  # i^0.7 multi-row law of ISO 281
#: Lundberg–Palmgren exponents: raceway lives combine with exponent 10/3 and the system exponent -9/10
#: (Weibull slope 10/9 for point contact); equivalent loads are the cubic mean on the rotating ring and
#: the 10/3-power mean on the stationary ring.
BALL_LOAD_EXP = 10.0 / 3.0
BALL_ROTATING_MEAN = 3.0
BALL_STATIONARY_MEAN = 10.0 / 3.0
BALL_LIFE_EXP = -0.9

# --- roller (line contact, sliced), ISO/TS 16281 eq. (47)-(65) ------------------------------------------
#: Ratios C_r / (λν Q_c Z cos α) for a radial row (zero clearance), rotating and stationary ring; the
#: Stribeck integrals with Q = Q_max cos^(10/9) ψ give 0.3764 and 0.3630 (the TS values are 0.378, 0.364).
ROLLER_RADIAL_INNER = 0.378
ROLLER_RADIAL_OUTER = 0.364
ROLLER_RING_RATIO = 1.038  # radial only; thrust uses 1
ROLLER_GAMMA_EXP = 143.0 / 108.0
ROLLER_COMBINE_EXP = 4.5  # 9/2
ROLLER_RATING_EXP = 2.0 / 9.0
ROLLER_ROW_EXP = 7.0 / 9.0
ROLLER_SLICE_EXP = 7.0 / 9.0  # q_c = Q_c (1/n_s)^(7/9)
ROLLER_ROTATING_MEAN = 4.0
ROLLER_STATIONARY_MEAN = 4.5
ROLLER_LIFE_EXP = -8.0 / 9.0
#: λν: reduction factor for edge stresses and non-uniform load that ISO 281 builds into C; ISO/TS 16281
#: divides it out because the slice loads resolve the load along the roller (ISO/TR 1281-1). ISO/TS
#: 16281:2008 eq. (49) (radial, 0.83) and (52) (thrust, 0.73), as both public implementations cited above
#: transcribe them; b_m (ISO 281 Table 1) is not divided out. Consequence: with uniform slice loads a
#: roller row's L10r is (C/(λν P))^4 against ISO 281's (C/P)^(10/3), i.e. λν^-4 (C/P)^(2/3) times longer
#: (2.1x at P = C, 9.8x at C/P = 10) before the profile and f_k shorten it (docs/ratings.md).
LAMBDA_NU = {"radial": 0.83, "thrust": 0.73}
#: ISO/TS 16281 eq. (60) edge-stress factor constants f_k = 1 - 0.01 / ln(1.985 |(2k - n_s - 1)/(2 n_s - 2)|)
EDGE_A, EDGE_B = 0.01, 1.985

#: Which raceway sees the rotating-ring (all-elements) mean and which the stationary-ring mean.
ROTATING_RING = {"inner": ("rotating", "stationary"), "outer": ("stationary", "rotating")}


def _kind_angle(contact_angle, kind):
    checks.one_of("kind", kind, ("radial", "thrust"))
    alpha = np.asarray(contact_angle, dtype=float)
    if kind == "radial":
        checks.in_range("contact_angle", alpha, 0.0, RADIAL_MAX_ANGLE, "rad")
    else:
        checks.in_range("contact_angle", alpha, 0.0, np.pi / 2, "rad")
        if np.any(alpha <= RADIAL_MAX_ANGLE):
            raise InputError(
                f"contact_angle ({checks._fmt(alpha)} rad) must exceed pi/4 for a thrust bearing"
            )
    return alpha


def ball_raceway_ratings(
    load_rating,
    element_diameter,
    pitch_diameter,
    contact_angle,
    groove_radius_inner,
    groove_radius_outer,
    n_elements,
    n_rows=1,
    kind="radial",
):
    """Element loads Q_ci, Q_ce [N] for the basic dynamic load rating of the inner and outer raceway.

    .. math::

        T = 1.044\\Bigl(\\frac{1-\\gamma}{1+\\gamma}\\Bigr)^{1.72}
            \\Bigl[\\frac{r_i}{r_e}\\frac{2r_e - D_w}{2r_i - D_w}\\Bigr]^{0.41},\\quad
        Q_{ci} = \\frac{C_r}{0.407 Z i^{0.7}\\cos\\alpha}(1 + T^{10/3})^{0.3},\\quad
        Q_{ce} = \\frac{C_r}{0.389 Z i^{0.7}\\cos\\alpha}(1 + T^{-10/3})^{0.3}

    Thrust (α != 90°): T without the factor 1.044 and Q_c = C_a/(Z sin α)(1 + T^{±10/3})^{0.3};
    α = 90°: T = [conformity term]^0.41 and Q_c = C_a/Z (1 + T^{±10/3})^{0.3}. γ = Dw cos α / Dpw.

    Parameters
    ----------
    load_rating : array_like
        Basic dynamic load rating C_r or C_a of ISO 281 [N].
    element_diameter : array_like
        Dw [m].
    pitch_diameter : array_like
        Dpw [m], > Dw.
    contact_angle : array_like
        Nominal α [rad].
    groove_radius_inner, groove_radius_outer : array_like
        r_i, r_e [m], > Dw/2.
    n_elements : array_like
        Balls per row Z [-].
    n_rows : array_like
        Rows i [-] (radial).
    kind : {"radial", "thrust"}

    Returns
    -------
    tuple of numpy.ndarray
        (Q_ci, Q_ce) [N].

    References
    ----------
    ISO/TS 16281:2008 eq. (19)-(24).
    """
    checks.positive("load_rating", load_rating, "N")
    checks.positive("element_diameter", element_diameter, "m")
    checks.greater("pitch_diameter", pitch_diameter, "element_diameter", element_diameter, "m")
    dw = np.asarray(element_diameter, float)
    checks.greater("groove_radius_inner", groove_radius_inner, "half the element_diameter", dw / 2, "m")
    checks.greater("groove_radius_outer", groove_radius_outer, "half the element_diameter", dw / 2, "m")
    checks.positive("n_elements", n_elements)
    checks.positive("n_rows", n_rows)
    alpha = _kind_angle(contact_angle, kind)
    ri = np.asarray(groove_radius_inner, float)
    re = np.asarray(groove_radius_outer, float)
    conformity = (ri / re * (2.0 * re - dw) / (2.0 * ri - dw)) ** BALL_CONFORMITY_EXP
    is_90 = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
    cos_a = np.where(is_90, 0.0, np.cos(alpha))
    g = dw * cos_a / np.asarray(pitch_diameter, float)
    geometric = ((1.0 - g) / (1.0 + g)) ** BALL_GAMMA_EXP * conformity
    c = np.asarray(load_rating, float)
    z = np.asarray(n_elements, float)
    if kind == "radial":
        t = BALL_RING_RATIO * geometric
        base = c / (z * np.asarray(n_rows, float) ** BALL_ROW_EXP * cos_a)
        q_ci = base / BALL_RADIAL_INNER * (1.0 + t**BALL_LOAD_EXP) ** 0.3
        q_ce = base / BALL_RADIAL_OUTER * (1.0 + t ** (-BALL_LOAD_EXP)) ** 0.3
    else:
        t = np.where(is_90, conformity, geometric)
        base = c / (z * np.sin(alpha))
        q_ci = base * (1.0 + t**BALL_LOAD_EXP) ** 0.3
        q_ce = base * (1.0 + t ** (-BALL_LOAD_EXP)) ** 0.3
    return q_ci, q_ce


def _loads(field, loads):
    q = np.asarray(loads, dtype=float)
    checks.non_negative(field, q, "N")
    return q


def _power_mean(q, exponent, axis):
    return np.mean(q**exponent, axis=axis) ** (1.0 / exponent)


def ball_reference_life(loads, load_inner_rating, load_outer_rating, rotating="inner", loads_outer=None):
    """Basic reference rating life L10r [rev] of a ball row from its element loads.

    .. math::

        Q_{e,\\mathrm{rot}} = \\Bigl(\\frac{1}{Z}\\sum_j Q_j^{3}\\Bigr)^{1/3},\\quad
        Q_{e,\\mathrm{stat}} = \\Bigl(\\frac{1}{Z}\\sum_j Q_j^{10/3}\\Bigr)^{3/10},\\quad
        L_{10r} = 10^6\\Bigl[\\Bigl(\\frac{Q_{ci}}{Q_{ei}}\\Bigr)^{-10/3}
                         + \\Bigl(\\frac{Q_{ce}}{Q_{ee}}\\Bigr)^{-10/3}\\Bigr]^{-0.9}

    The rotating ring's raceway (every point passes every load) takes the cubic mean, the stationary
    ring's the 10/3-power mean (Lundberg–Palmgren).

    Parameters
    ----------
    loads : array_like
        Element contact loads at the inner raceway Q[..., j] [N], >= 0 (elements on the last axis; Z is
        its length, unloaded elements included).
    load_inner_rating, load_outer_rating : array_like
        Q_ci, Q_ce [N] from :func:`ball_raceway_ratings` (broadcast against the leading axes).
    rotating : {"inner", "outer"}
        Which ring rotates relative to the load.
    loads_outer : array_like, optional
        Outer-raceway loads [N] when they differ (centrifugal force); default ``loads``.

    Returns
    -------
    numpy.ndarray
        L10r [rev], shape of the leading axes.

    References
    ----------
    ISO/TS 16281:2008 eq. (25)-(29).
    """
    checks.one_of("rotating", rotating, ROTATING_RING)
    qi = _loads("loads", loads)
    qo = qi if loads_outer is None else _loads("loads_outer", loads_outer)
    if np.any(np.max(qi, axis=-1) <= 0) or np.any(np.max(qo, axis=-1) <= 0):
        raise InputError("loads (all zero in a case) must include a positive element load: no finite life")
    checks.positive("load_inner_rating", load_inner_rating, "N")
    checks.positive("load_outer_rating", load_outer_rating, "N")
    mean = {"rotating": BALL_ROTATING_MEAN, "stationary": BALL_STATIONARY_MEAN}
    inner_role, outer_role = ROTATING_RING[rotating]
    q_ei = _power_mean(qi, mean[inner_role], -1)
    q_ee = _power_mean(qo, mean[outer_role], -1)
    s = (np.asarray(load_inner_rating, float) / q_ei) ** (-BALL_LOAD_EXP) + (
        np.asarray(load_outer_rating, float) / q_ee
    ) ** (-BALL_LOAD_EXP)
    return MILLION * s**BALL_LIFE_EXP


def roller_raceway_ratings(
    load_rating,
    element_diameter,
    pitch_diameter,
    contact_angle,
    n_elements,
    n_slices,
    n_rows=1,
    kind="radial",
):
    """Slice ratings q_ci, q_ce [N] of the inner and outer raceway of a roller row.

    .. math::

        T = 1.038\\Bigl(\\frac{1-\\gamma}{1+\\gamma}\\Bigr)^{143/108},\\quad
        Q_{ci} = \\frac{C_r\\,(1 + T^{9/2})^{2/9}}{\\lambda\\nu\\,0.378\\,Z\\cos\\alpha\\, i^{7/9}},\\quad
        Q_{ce} = \\frac{C_r\\,(1 + T^{-9/2})^{2/9}}{\\lambda\\nu\\,0.364\\,Z\\cos\\alpha\\, i^{7/9}},\\quad
        q_c = Q_c\\, n_s^{-7/9}

    λν = 0.83 radial, 0.73 thrust. Thrust (α != 90°): T without the factor 1.038 and
    Q_c = C_a (1 + T^{±9/2})^{2/9} / (λν Z sin α); α = 90°: Q_c = C_a 2^{2/9} / (λν Z).

    Parameters
    ----------
    load_rating : array_like
        C_r or C_a of ISO 281 [N].
    element_diameter : array_like
        Dwe [m].
    pitch_diameter : array_like
        Dpw [m], > Dwe.
    contact_angle : array_like
        α [rad].
    n_elements : array_like
        Rollers per row Z [-].
    n_slices : int
        Slices per roller n_s.
    n_rows : array_like
        Rows i [-] (radial).
    kind : {"radial", "thrust"}

    Returns
    -------
    tuple of numpy.ndarray
        (q_ci, q_ce) [N] per slice.

    References
    ----------
    ISO/TS 16281:2008 eq. (47)-(57).
    """
    checks.positive("load_rating", load_rating, "N")
    checks.positive("element_diameter", element_diameter, "m")
    checks.greater("pitch_diameter", pitch_diameter, "element_diameter", element_diameter, "m")
    checks.positive("n_elements", n_elements)
    checks.positive("n_rows", n_rows)
    n_slices = checks.integer("n_slices", n_slices)
    alpha = _kind_angle(contact_angle, kind)
    is_90 = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
    cos_a = np.where(is_90, 0.0, np.cos(alpha))
    g = np.asarray(element_diameter, float) * cos_a / np.asarray(pitch_diameter, float)
    shape = ((1.0 - g) / (1.0 + g)) ** ROLLER_GAMMA_EXP
    c = np.asarray(load_rating, float) / LAMBDA_NU[kind]
    z = np.asarray(n_elements, float)
    if kind == "radial":
        t = ROLLER_RING_RATIO * shape
        base = c / (z * cos_a * np.asarray(n_rows, float) ** ROLLER_ROW_EXP)
        q_ci = base / ROLLER_RADIAL_INNER * (1.0 + t**ROLLER_COMBINE_EXP) ** ROLLER_RATING_EXP
        q_ce = base / ROLLER_RADIAL_OUTER * (1.0 + t ** (-ROLLER_COMBINE_EXP)) ** ROLLER_RATING_EXP
    else:
        t = np.where(is_90, 1.0, shape)
        base = c / (z * np.sin(alpha))
        q_ci = base * (1.0 + t**ROLLER_COMBINE_EXP) ** ROLLER_RATING_EXP
        q_ce = base * (1.0 + t ** (-ROLLER_COMBINE_EXP)) ** ROLLER_RATING_EXP
    slice_factor = float(n_slices) ** (-ROLLER_SLICE_EXP)
    return q_ci * slice_factor, q_ce * slice_factor


def edge_stress_factor(n_slices):
    """Edge-stress factor f_k [-] of slice k = 1 … n_s, ISO/TS 16281:2008 eq. (60).

    .. math:: f_k = 1 - \\frac{0.01}{\\ln\\bigl(1.985\\,\\bigl|\\frac{2k - n_s - 1}{2n_s - 2}\\bigr|\\bigr)}

    1 at the roller centre, rising to ≈ 2.33 at the end slices (for any n_s). It multiplies the slice
    loads of both rings (f_i = f_e) in the equivalent-load sums when ``slice_factor`` is passed to
    :func:`roller_reference_life`. The TS gives it as the approximation of its pressure-based factors
    eq. (58)-(59), valid for rollers with its logarithmic profile eq. (42)-(44) under medium load and a
    misalignment below 4' (the TS's note, as quoted by a public implementation); the raters apply it to
    every sliced roller row (:data:`bearingkit.analysis.rating.options.EDGE_STRESS_MODES`). Formula as
    transcribed by two public implementations of the TS (not checked against the TS text).

    Parameters
    ----------
    n_slices : int
        n_s >= 2.

    Returns
    -------
    numpy.ndarray
        f_k, shape (n_s,).
    """
    n = checks.integer("n_slices", n_slices, low=2)
    k = np.arange(1, n + 1, dtype=float)
    x = EDGE_B * np.abs((2.0 * k - n - 1.0) / (2.0 * n - 2.0))
    log = np.log(np.where(x > 0, x, 0.5))  # the centre slice (x = 0) has f_k = 1
    return np.where(x > 0, 1.0 - EDGE_A / log, 1.0)


def roller_reference_life(
    slice_loads,
    slice_inner_rating,
    slice_outer_rating,
    rotating="inner",
    slice_loads_outer=None,
    slice_factor=None,
):
    """Basic reference rating life L10r [rev] of a roller row from its slice loads.

    .. math::

        q_{k,e,\\mathrm{rot}} = \\Bigl(\\frac{1}{Z}\\sum_j (f_k q_{jk})^{4}\\Bigr)^{1/4},\\quad
        q_{k,e,\\mathrm{stat}} = \\Bigl(\\frac{1}{Z}\\sum_j (f_k q_{jk})^{4.5}\\Bigr)^{1/4.5},\\quad
        L_{10r} = 10^6\\Bigl[\\sum_k \\Bigl(\\frac{q_{kei}}{q_{ci}}\\Bigr)^{4.5}
                            + \\Bigl(\\frac{q_{kee}}{q_{ce}}\\Bigr)^{4.5}\\Bigr]^{-8/9}

    Parameters
    ----------
    slice_loads : array_like
        Slice loads q[..., j, k] at the inner raceway [N], >= 0 (elements on axis -2, slices on axis -1).
    slice_inner_rating, slice_outer_rating : array_like
        q_ci, q_ce [N] from :func:`roller_raceway_ratings`.
    rotating : {"inner", "outer"}
        Which ring rotates relative to the load.
    slice_loads_outer : array_like, optional
        Outer-raceway slice loads [N] when they differ; default ``slice_loads``.
    slice_factor : array_like, optional
        f_k per slice [-] (e.g. :func:`edge_stress_factor`), broadcast along the last axis; default 1.

    Returns
    -------
    numpy.ndarray
        L10r [rev], shape of the leading axes.

    References
    ----------
    ISO/TS 16281:2008 eq. (58)-(65).
    """
    checks.one_of("rotating", rotating, ROTATING_RING)
    qi = _loads("slice_loads", slice_loads)
    qo = qi if slice_loads_outer is None else _loads("slice_loads_outer", slice_loads_outer)
    if qi.ndim < 2 or qo.ndim < 2:
        raise InputError(f"slice_loads (ndim {qi.ndim}) must have element and slice axes (ndim >= 2)")
    if np.any(np.max(qi, axis=(-2, -1)) <= 0) or np.any(np.max(qo, axis=(-2, -1)) <= 0):
        raise InputError(
            "slice_loads (all zero in a case) must include a positive slice load: no finite life"
        )
    checks.positive("slice_inner_rating", slice_inner_rating, "N")
    checks.positive("slice_outer_rating", slice_outer_rating, "N")
    if slice_factor is not None:
        checks.positive("slice_factor", slice_factor)
        f = np.asarray(slice_factor, float)
        qi, qo = qi * f, qo * f
    mean = {"rotating": ROLLER_ROTATING_MEAN, "stationary": ROLLER_STATIONARY_MEAN}
    inner_role, outer_role = ROTATING_RING[rotating]
    q_kei = _power_mean(qi, mean[inner_role], -2)  # [..., k]
    q_kee = _power_mean(qo, mean[outer_role], -2)
    ci = np.asarray(slice_inner_rating, float)[..., None]
    ce = np.asarray(slice_outer_rating, float)[..., None]
    s = np.sum((q_kei / ci) ** ROLLER_COMBINE_EXP + (q_kee / ce) ** ROLLER_COMBINE_EXP, axis=-1)
    return MILLION * s**ROLLER_LIFE_EXP


def reference_equivalent_load(life, load_rating, element_kind):
    """Dynamic equivalent reference load P_ref = C / (L10r / 10^6)^(1/p) [N] (p = 3 ball, 10/3 roller).

    Parameters
    ----------
    life : array_like
        L10r [rev], > 0.
    load_rating : array_like
        C [N], > 0.
    element_kind : {"ball", "roller"}
    """
    exps = {"ball": 3.0, "roller": 10.0 / 3.0}
    checks.one_of("element_kind", element_kind, exps)
    checks.positive("life", life, "rev")
    checks.positive("load_rating", load_rating, "N")
    return np.asarray(load_rating, float) / (np.asarray(life, float) / MILLION) ** (1.0 / exps[element_kind])
