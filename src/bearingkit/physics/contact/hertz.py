"""Hertz point (elliptical) contact: curvatures, ellipticity, dimensions, load–deflection law.

Line contact (rollers) is in :mod:`bearingkit.physics.contact.line`.

All quantities are SI: lengths in m, loads in N, moduli and pressures in Pa, curvatures in 1/m,
angles in rad. Every function is a pure, vectorised numpy function that broadcasts over its
arguments (a leading case axis, elements, slices ...).

Conventions
-----------
* ``e_reduced`` is Hamrock's E' = 2 / [(1-nu1^2)/E1 + (1-nu2^2)/E2]; Harris' sum
  Sigma (1-nu^2)/E equals 2/E' (the Kunert/Palmgren compliance eta).
* Point contact is described, as in Harris & Kotzalas (2007, ch. 6), by the curvature sum
  Sigma rho and the curvature difference F(rho). Hamrock's radii follow from them:
  1/R_x = Sigma rho (1 + F)/2, 1/R_y = Sigma rho (1 - F)/2, R = 1/Sigma rho.
* The ellipticity kappa = a/b >= 1, with ``a`` along the direction of smaller relative curvature.
* The two point-contact methods ("exact" and "hamrock_brewe") differ only in how kappa and the
  complete elliptic integrals K (first kind) and E (second kind) are obtained; every dimension is
  then computed by the same expressions, so the two are directly comparable.

References: ``harris2007`` (ch. 6, Hertz point and line contact, Table 6.1), ``hamrock1983`` (Brewe & Hamrock
approximations), ``kunert1961``/``palmgren1959`` (line-contact deflection), ``iso16281``.
"""

from __future__ import annotations

from collections.abc import Callable
from contextlib import contextmanager
from contextvars import ContextVar
from typing import NamedTuple

import numpy as np

from bearingkit import checks
from bearingkit.checks import scalar_or_array as _out
from bearingkit.errors import InputError
from bearingkit.physics.contact.elliptic import complete_integrals

__all__ = [
    "POINT_METHODS",
    "RACEWAYS",
    "REFERENCE_KEYS",
    "PointContact",
    "ball_raceway_curvature",
    "contact_coefficients",
    "curvature_difference_from_radii",
    "effective_radii",
    "ellipticity",
    "point_contact",
    "point_stiffness",
    "reduced_modulus",
    "reusing_integrals",
    "series_stiffness",
]

#: Keys of :data:`bearingkit.references.REFERENCES` this module implements.
REFERENCE_KEYS = ("harris2007", "hamrock1983", "johnson1985", "kunert1961", "palmgren1959", "iso16281")

# ---------------------------------------------------------------------------------------------
# Empirical constants (unit, source, valid range)
# ---------------------------------------------------------------------------------------------

#: Brewe & Hamrock (1977/1983) curve fit of the ellipticity, k = C_K (R_y/R_x)^P_K [1, 1];
#: Hamrock & Brewe (1983); fitted over 1 <= k <= 10 (1 <= R_y/R_x <~ 37).
HB_ELLIPTICITY_COEFF = 1.0339
HB_ELLIPTICITY_EXP = 0.6360
#: Curve fit of the complete elliptic integral of the 2nd kind, E ~ C0 + C1 R_x/R_y [1];
#: Hamrock & Brewe (1983); same range.
HB_ELLIPE_CONST = 1.0003
HB_ELLIPE_COEFF = 0.5968
#: Curve fit of the complete elliptic integral of the 1st kind, K ~ C0 + C1 ln(R_y/R_x) [1];
#: Hamrock & Brewe (1983); same range.
HB_ELLIPK_CONST = 1.5277
HB_ELLIPK_COEFF = 0.6023

#: Load-deflection exponent of point contact, Q ~ delta^(3/2) (Hertz) [1].
POINT_EXPONENT = 1.5

#: Largest ellipticity the exact solver handles (F(rho) up to 1 - ~1e-11) [1].
MAX_ELLIPTICITY = 1.0e6
#: Convergence of the exact ellipticity, |d ln kappa| per Newton step [1].
_ELLIPTICITY_TOL = 1.0e-14
_ELLIPTICITY_MAX_ITER = 100
#: Below this parameter m = 1 - 1/kappa^2 the derivative dF/dm uses its limit 3/8 [1].
_SMALL_M = 1.0e-6


# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------


def _registry_get(field: str, name: str, registry: dict):
    checks.one_of(field, name, registry)
    return registry[name]


def _check_curvature_difference(curvature_difference):
    checks.non_negative("curvature_difference", curvature_difference)
    f = np.asarray(curvature_difference, dtype=float)
    if np.any(f > _F_MAX):
        raise InputError(
            f"curvature_difference ({checks._fmt(curvature_difference)}) must be below {_F_MAX:.12g} "
            f"(ellipticity <= {MAX_ELLIPTICITY:g}); use a line-contact model"
        )
    return f


# ---------------------------------------------------------------------------------------------
# Materials and geometry
# ---------------------------------------------------------------------------------------------


def reduced_modulus(youngs_modulus_1, poisson_ratio_1, youngs_modulus_2, poisson_ratio_2):
    """Reduced (effective) modulus E' of two elastic bodies [Pa].

    Parameters
    ----------
    youngs_modulus_1, youngs_modulus_2 : array_like
        Young's moduli of the two bodies [Pa], > 0.
    poisson_ratio_1, poisson_ratio_2 : array_like
        Poisson's ratios [1], in (-1, 0.5].

    Returns
    -------
    e_reduced : ndarray
        E' [Pa].

    Notes
    -----
    .. math:: E' = \\frac{2}{(1-\\nu_1^2)/E_1 + (1-\\nu_2^2)/E_2}

    Hamrock & Brewe (1983); doi:10.1115/1.3254558. Two steel bodies give E/(1-nu^2).
    """
    checks.positive("youngs_modulus_1", youngs_modulus_1, "Pa")
    checks.positive("youngs_modulus_2", youngs_modulus_2, "Pa")
    for field, nu in (("poisson_ratio_1", poisson_ratio_1), ("poisson_ratio_2", poisson_ratio_2)):
        checks.in_range(field, nu, -1.0, 0.5)
        checks.greater(field, nu, "-1", -1.0)
    e1, n1 = np.asarray(youngs_modulus_1, float), np.asarray(poisson_ratio_1, float)
    e2, n2 = np.asarray(youngs_modulus_2, float), np.asarray(poisson_ratio_2, float)
    return _out(2.0 / ((1.0 - n1**2) / e1 + (1.0 - n2**2) / e2))


#: Sign of the raceway's circumferential curvature relative to the ball: +1 convex (inner ring),
#: -1 concave (outer ring). Harris & Kotzalas (2007), ch. 2 (contact geometry).
RACEWAYS: dict[str, float] = {"inner": 1.0, "outer": -1.0}


def ball_raceway_curvature(element_diameter, pitch_diameter, contact_angle, groove_radius, raceway: str):
    """Curvature sum and difference of a ball on a grooved raceway.

    Parameters
    ----------
    element_diameter : array_like
        Ball diameter D [m], > 0.
    pitch_diameter : array_like
        Pitch diameter d_m [m]; must exceed ``element_diameter * cos(contact_angle)``.
    contact_angle : array_like
        Contact angle alpha [rad] in [-pi/2, pi/2] (0 radial, pi/2 thrust).
    groove_radius : array_like
        Raceway groove (cross-section) radius r [m]; must exceed D/2 (conformity r/D > 0.5).
    raceway : {"inner", "outer"}
        Which ring's raceway.

    Returns
    -------
    curvature_sum : ndarray
        Sigma rho [1/m].
    curvature_difference : ndarray
        F(rho) [1], in [0, 1).

    Notes
    -----
    With :math:`\\gamma = D\\cos\\alpha/d_m` and s = +1 (inner), -1 (outer):

    .. math::
        \\Sigma\\rho = \\frac{2}{D}\\Big(2 + \\frac{s\\gamma}{1 - s\\gamma} - \\frac{D}{2r}\\Big),\\qquad
        F(\\rho) = \\Big|\\frac{s\\gamma/(1 - s\\gamma) + D/(2r)}{2 + s\\gamma/(1 - s\\gamma) - D/(2r)}\\Big|

    Harris & Kotzalas (2007), Rolling Bearing Analysis 5th ed., ch. 2 (ISO/TS 16281
    annex). The absolute value makes kappa >= 1 whichever principal plane is the flatter one.
    """
    sign = _registry_get("raceway", raceway, RACEWAYS)
    checks.positive("element_diameter", element_diameter, "m")
    checks.positive("pitch_diameter", pitch_diameter, "m")
    checks.in_range("contact_angle", contact_angle, -np.pi / 2, np.pi / 2, "rad")
    checks.positive("groove_radius", groove_radius, "m")
    d = np.asarray(element_diameter, float)
    checks.greater("groove_radius", groove_radius, "half the element_diameter", d / 2.0, "m")
    cos_a = np.cos(np.asarray(contact_angle, float))
    checks.greater("pitch_diameter", pitch_diameter, "element_diameter*cos(contact_angle)", d * cos_a, "m")
    gamma = d * cos_a / np.asarray(pitch_diameter, float)
    ring = sign * gamma / (1.0 - sign * gamma)
    groove = d / (2.0 * np.asarray(groove_radius, float))
    bracket = 2.0 + ring - groove
    curvature_sum = 2.0 / d * bracket
    curvature_difference = np.abs((ring + groove) / bracket)
    return _out(curvature_sum), _out(curvature_difference)


def effective_radii(curvature_sum, curvature_difference):
    """Hamrock's effective radii R_x <= R_y from Sigma rho and F(rho).

    Parameters
    ----------
    curvature_sum : array_like
        Sigma rho [1/m], > 0.
    curvature_difference : array_like
        F(rho) [1], in [0, 1).

    Returns
    -------
    radius_x, radius_y : ndarray
        R_x, R_y [m] (R_y is infinite for F = 1).

    Notes
    -----
    .. math:: \\frac{1}{R_x} = \\frac{\\Sigma\\rho\\,(1 + F)}{2},\\qquad
              \\frac{1}{R_y} = \\frac{\\Sigma\\rho\\,(1 - F)}{2}

    Hamrock & Brewe (1983), definitions of R_x, R_y, with F = (1/R_x - 1/R_y)/(1/R_x + 1/R_y).
    """
    checks.positive("curvature_sum", curvature_sum, "1/m")
    f = _check_curvature_difference(curvature_difference)
    s = np.asarray(curvature_sum, float)
    return _out(2.0 / (s * (1.0 + f))), _out(2.0 / (s * (1.0 - f)))


def curvature_difference_from_radii(radius_x, radius_y):
    """F(rho) = |1/R_x - 1/R_y| / (1/R_x + 1/R_y) [1] from two effective radii [m] (> 0).

    Parameters
    ----------
    radius_x, radius_y : array_like [m]
        Effective radii of curvature in the two principal planes (> 0).

    Notes
    -----
    .. math:: F(\\rho) = \\frac{|1/R_x - 1/R_y|}{1/R_x + 1/R_y}

    Harris & Kotzalas (2007), ch. 2 (curvature difference), written with Hamrock's effective radii.
    """
    checks.positive("radius_x", radius_x, "m")
    checks.positive("radius_y", radius_y, "m")
    cx, cy = 1.0 / np.asarray(radius_x, float), 1.0 / np.asarray(radius_y, float)
    return _out(np.abs(cx - cy) / (cx + cy))


# ---------------------------------------------------------------------------------------------
# Ellipticity and the elliptic integrals: the method registry
# ---------------------------------------------------------------------------------------------


def _f_of_log_kappa(u):
    """F(rho) and dF/du at u = ln(kappa), with stable elliptic integrals.

    Uses p = 1/kappa^2 = 1 - m, E(m) and K - E = (m/3) R_D(0, p, 1) (Carlson;
    :mod:`bearingkit.physics.contact.elliptic`), so that F = 1 - 2 p R_D / (3 E) has no cancellation
    near kappa = 1.
    """
    p = np.exp(-2.0 * u)
    m = -np.expm1(-2.0 * u)
    _, big_e, d_int = complete_integrals(p)  # D(m) = (K - E)/m = R_D(0, p, 1)/3
    f = 1.0 - 2.0 * p * d_int / big_e
    ratio = d_int / big_e
    with np.errstate(divide="ignore", invalid="ignore"):
        dfdm = -2.0 * (-ratio + (0.5 - p * ratio) / m + p * ratio**2 / 2.0)
    dfdm = np.where(m < _SMALL_M, 3.0 / 8.0, dfdm)
    return f, dfdm * 2.0 * p


#: (F grid, u grid) once built. Built whole and then bound in one assignment: two threads that both
#: find it missing each build one (the same table), and neither ever sees a half-built one (it was a
#: list extended in place: two study chunks solving at once made it four items, issue 34).
_START_TABLE: tuple | None = None


def _start_table():
    """F(ρ) on a dense grid of u = ln κ (built once): interpolating it starts Newton within ~1e-6."""
    global _START_TABLE
    table = _START_TABLE
    if table is None:
        u = np.concatenate(
            [np.linspace(0.0, 0.05, 200), np.linspace(0.05, np.log(MAX_ELLIPTICITY), 3000)[1:]]
        )
        table = _START_TABLE = (_f_of_log_kappa(u)[0], u)
    return table


def _exact_kappa(curvature_difference):
    """Solve F(rho) = 1 - 2(K - E)/((kappa^2 - 1) E) for kappa (vectorised safeguarded Newton)."""
    target = np.asarray(curvature_difference, float)
    lo = np.zeros_like(target)
    hi = np.full_like(target, np.log(MAX_ELLIPTICITY))
    f_grid, u_grid = _start_table()
    u = np.clip(np.interp(target, f_grid, u_grid), lo, hi)
    for _ in range(_ELLIPTICITY_MAX_ITER):
        f, dfdu = _f_of_log_kappa(u)
        resid = f - target
        lo = np.where(resid < 0.0, u, lo)
        hi = np.where(resid > 0.0, u, hi)
        step = resid / dfdu
        u_new = u - step
        outside = ~((u_new > lo) & (u_new < hi)) | ~np.isfinite(u_new)
        u_new = np.where(outside & (resid != 0.0), 0.5 * (lo + hi), u_new)
        u_new = np.where(resid == 0.0, u, u_new)
        done = np.max(np.abs(u_new - u), initial=0.0) <= _ELLIPTICITY_TOL
        u = u_new
        if done:
            break
    kappa = np.where(target == 0.0, 1.0, np.exp(u))
    return kappa


def _exact_integrals(curvature_difference):
    kappa = _exact_kappa(curvature_difference)
    big_k, big_e, _ = complete_integrals(1.0 / kappa**2)
    return kappa, big_k, big_e


def _hb_kappa(curvature_difference):
    f = np.asarray(curvature_difference, float)
    ratio = (1.0 + f) / (1.0 - f)  # R_y / R_x
    return HB_ELLIPTICITY_COEFF * ratio**HB_ELLIPTICITY_EXP


def _hb_integrals(curvature_difference):
    f = np.asarray(curvature_difference, float)
    ratio = (1.0 + f) / (1.0 - f)  # R_y / R_x
    kappa = _hb_kappa(f)
    big_e = HB_ELLIPE_CONST + HB_ELLIPE_COEFF / ratio
    big_k = HB_ELLIPK_CONST + HB_ELLIPK_COEFF * np.log(ratio)
    return kappa, big_k, big_e


#: Point-contact methods: name -> function F(rho) -> (kappa, K, E).
#: "exact": Hertz' transcendental equation solved with complete elliptic integrals
#: (Harris & Kotzalas 2007, ch. 6). "hamrock_brewe": curve fits of Hamrock & Brewe (1983),
#: fitted for 1 <= kappa <= 10.
POINT_METHODS: dict[str, Callable] = {"exact": _exact_integrals, "hamrock_brewe": _hb_integrals}

_F_MAX = float(_f_of_log_kappa(np.log(MAX_ELLIPTICITY))[0])


#: The κ, K, E already computed in the current :func:`reusing_integrals` block (None outside one).
_REUSED: ContextVar[dict | None] = ContextVar("hertz_reused_integrals", default=None)


@contextmanager
def reusing_integrals():
    """Within the block, κ, K, E of a curvature-difference array are computed once per set of values.

    A batched design evaluation asks for the same contacts several times (rating, stiffness, friction
    of the same curvatures): the later calls get copies of the first call's κ, K, E, reshaped to their
    own shape. The solve is elementwise except for its stopping test, which looks at the whole array,
    so equal values (in the same order) give equal bits whatever the shape: the results are those of
    computing every call. Per thread and per context (a :class:`~contextvars.ContextVar`); the memory
    is released when the block ends.
    """
    token = _REUSED.set({})
    try:
        yield
    finally:
        _REUSED.reset(token)


def _integrals(curvature_difference, method):
    fn = _registry_get("method", method, POINT_METHODS)
    f = _check_curvature_difference(curvature_difference)
    reused = _REUSED.get()
    if reused is None:
        return fn(f)
    key = (method, f.tobytes())
    if key not in reused:
        reused[key] = tuple(np.ravel(x).copy() for x in np.broadcast_arrays(*fn(f)))
    return tuple(x.reshape(f.shape).copy() for x in reused[key])


def ellipticity(curvature_difference, method="exact"):
    """Ellipticity kappa = a/b >= 1 of a Hertz point contact.

    Parameters
    ----------
    curvature_difference : array_like
        F(rho) [1], in [0, 1).
    method : {"exact", "hamrock_brewe"}
        Key of :data:`POINT_METHODS`.

    Returns
    -------
    kappa : ndarray
        a/b [1]; exactly 1 at F(rho) = 0 for the exact method.

    Notes
    -----
    The exact kappa solves, with K, E the complete elliptic integrals of parameter
    :math:`m = 1 - 1/\\kappa^2`,

    .. math:: F(\\rho) = 1 - \\frac{2\\,[K(m) - E(m)]}{(\\kappa^2 - 1)\\,E(m)}

    (Harris & Kotzalas 2007, ch. 6), to |d ln kappa| <= 1e-14. Hamrock–Brewe:
    :math:`\\kappa \\approx 1.0339\\,(R_y/R_x)^{0.6360}` with R_y/R_x = (1 + F)/(1 - F)
    (Hamrock & Brewe 1983; doi:10.1115/1.3254558).
    """
    return _out(_integrals(curvature_difference, method)[0])


def _coefficients_from(kappa, big_k, big_e):
    a_star = (2.0 * kappa**2 * big_e / np.pi) ** (1.0 / 3.0)
    b_star = (2.0 * big_e / (np.pi * kappa)) ** (1.0 / 3.0)
    delta_star = (2.0 * big_k / np.pi) * (np.pi / (2.0 * kappa**2 * big_e)) ** (1.0 / 3.0)
    return a_star, b_star, delta_star


def contact_coefficients(curvature_difference, method="exact"):
    """Dimensionless Hertz coefficients a*, b*, delta* of a point contact.

    Parameters
    ----------
    curvature_difference : array_like
        F(rho) [1], in [0, 1).
    method : {"exact", "hamrock_brewe"}
        Key of :data:`POINT_METHODS`.

    Returns
    -------
    a_star, b_star, delta_star : ndarray
        [1]; all equal 1 at F(rho) = 0 (exact method).

    Notes
    -----
    .. math::
        a^* = \\Big(\\frac{2\\kappa^2 E}{\\pi}\\Big)^{1/3},\\quad
        b^* = \\Big(\\frac{2E}{\\pi\\kappa}\\Big)^{1/3},\\quad
        \\delta^* = \\frac{2K}{\\pi}\\Big(\\frac{\\pi}{2\\kappa^2 E}\\Big)^{1/3}

    Harris & Kotzalas (2007), ch. 6 and Table 6.1. The "hamrock_brewe" method inserts
    Hamrock & Brewe's (1983) approximations of kappa, K and E in the same expressions.
    """
    return tuple(_out(c) for c in _coefficients_from(*_integrals(curvature_difference, method)))


# ---------------------------------------------------------------------------------------------
# Point contact
# ---------------------------------------------------------------------------------------------


class PointContact(NamedTuple):
    """Hertz point-contact result (arrays broadcast over the inputs, SI)."""

    semi_major: np.ndarray  #: a [m]
    semi_minor: np.ndarray  #: b [m]
    deflection: np.ndarray  #: delta, approach of the two bodies [m]
    max_pressure: np.ndarray  #: p_max [Pa]
    ellipticity: np.ndarray  #: kappa = a/b [1]


def point_contact(load, curvature_sum, curvature_difference, e_reduced, method="exact") -> PointContact:
    """Hertz elliptical point contact: ellipse semi-axes, approach and maximum pressure.

    Parameters
    ----------
    load : array_like
        Normal contact load Q [N], >= 0 (zero load gives zeros).
    curvature_sum : array_like
        Sigma rho [1/m], > 0.
    curvature_difference : array_like
        F(rho) [1], in [0, 1).
    e_reduced : array_like
        E' [Pa], > 0 (see :func:`reduced_modulus`).
    method : {"exact", "hamrock_brewe"}
        Key of :data:`POINT_METHODS`.

    Returns
    -------
    PointContact
        ``semi_major`` a [m], ``semi_minor`` b [m], ``deflection`` delta [m],
        ``max_pressure`` p_max [Pa], ``ellipticity`` kappa [1].

    Notes
    -----
    With :math:`c = \\big(\\tfrac{3Q}{2\\Sigma\\rho}\\cdot\\tfrac{2}{E'}\\big)^{1/3}`:

    .. math::
        a = a^* c,\\quad b = b^* c,\\quad
        \\delta = \\frac{\\delta^*}{2}\\,c^2\\,\\Sigma\\rho,\\quad
        p_{max} = \\frac{3Q}{2\\pi a b}

    Harris & Kotzalas (2007), ch. 6 (Sigma (1-nu^2)/E = 2/E'). Identical to Hamrock &
    Brewe (1983) with R = 1/Sigma rho.
    """
    checks.non_negative("load", load, "N")
    checks.positive("curvature_sum", curvature_sum, "1/m")
    checks.positive("e_reduced", e_reduced, "Pa")
    a_star, b_star, d_star = _coefficients_from(*_integrals(curvature_difference, method))
    kappa = a_star / b_star
    q = np.asarray(load, float)
    srho = np.asarray(curvature_sum, float)
    e_r = np.asarray(e_reduced, float)
    c = np.cbrt(3.0 * q / (srho * e_r))
    a = a_star * c
    b = b_star * c
    delta = 0.5 * d_star * c**2 * srho
    # p_max = 3Q/(2 pi a b) written without dividing by c (finite at Q = 0)
    p_max = 3.0 / (2.0 * np.pi * a_star * b_star) * np.cbrt(q) * np.cbrt(srho * e_r / 3.0) ** 2
    a, b, delta, p_max, kappa = np.broadcast_arrays(a, b, delta, p_max, kappa)
    return PointContact(_out(a), _out(b), _out(delta), _out(p_max), _out(kappa))


def point_stiffness(curvature_sum, curvature_difference, e_reduced, method="exact"):
    """Load–deflection constant K of ONE Hertz point contact, Q = K delta^1.5 [N/m^1.5].

    Parameters
    ----------
    curvature_sum : array_like
        Sigma rho [1/m], > 0.
    curvature_difference : array_like
        F(rho) [1], in [0, 1).
    e_reduced : array_like
        E' [Pa], > 0.
    method : {"exact", "hamrock_brewe"}
        Key of :data:`POINT_METHODS`.

    Returns
    -------
    stiffness_point : ndarray
        K [N/m^1.5].

    Notes
    -----
    Inverting delta of :func:`point_contact`:

    .. math:: K = \\frac{E'}{3}\\Big(\\frac{2}{\\delta^*}\\Big)^{3/2}(\\Sigma\\rho)^{-1/2}
              = \\frac{\\pi\\sqrt{2}}{3}\\,E'\\,\\kappa\\,E^{1/2}\\,K_1^{-3/2}(\\Sigma\\rho)^{-1/2}

    Harris & Kotzalas (2007), ch. 7 (load–deflection); Hamrock & Brewe (1983); the factor
    pi sqrt(2)/3 = 1.481 is ISO/TS 16281's 1.48.
    """
    checks.positive("curvature_sum", curvature_sum, "1/m")
    checks.positive("e_reduced", e_reduced, "Pa")
    d_star = _coefficients_from(*_integrals(curvature_difference, method))[2]
    e_r = np.asarray(e_reduced, float)
    srho = np.asarray(curvature_sum, float)
    return _out(e_r / 3.0 * (2.0 / d_star) ** POINT_EXPONENT / np.sqrt(srho))


def series_stiffness(k_1, k_2, exponent=POINT_EXPONENT):
    """Two contacts in series obeying the same law Q = k delta^n.

    Parameters
    ----------
    k_1, k_2 : array_like
        Stiffness constants of the two contacts [N/m^n], > 0.
    exponent : float
        Load–deflection exponent n [1] (1.5 point, 10/9 line), > 0.

    Returns
    -------
    k : ndarray
        Combined constant [N/m^n].

    Notes
    -----
    The same load passes both contacts and the approaches add, delta = (Q/k1)^(1/n) + (Q/k2)^(1/n):

    .. math:: K = \\big(k_1^{-1/n} + k_2^{-1/n}\\big)^{-n}

    Harris & Kotzalas (2007), ch. 7 (contacts in series, n = 3/2).
    """
    checks.positive("k_1", k_1)
    checks.positive("k_2", k_2)
    checks.positive("exponent", exponent)
    n = np.asarray(exponent, float)
    k1, k2 = np.asarray(k_1, float), np.asarray(k_2, float)
    return _out((k1 ** (-1.0 / n) + k2 ** (-1.0 / n)) ** (-n))
