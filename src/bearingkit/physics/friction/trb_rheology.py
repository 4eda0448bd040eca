"""Lubricant rheology of the tapered-roller friction model: Roelands viscosity, tractive integrals.

SI units: pressures in Pa, viscosities in Pa·s, lengths in m, forces per length in N/m. Seed 001
(Liu et al. 2022, Lubricants 10:154) eq. (10) with Roelands (1966); the limiting-shear form of the
traction uses Bair & Winer (1979). Used by :mod:`bearingkit.physics.friction.trb`.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics.lubrication.traction import LIMITING_SHEAR_COEFF

#: Λ_L = τ_L/p of the ``"limiting_shear"`` reading [-]: bearingkit's mineral-oil value (Bair & Winer
#: 1979, range 0.05…0.1; :data:`bearingkit.physics.lubrication.traction.LIMITING_SHEAR_COEFF`),
#: not fitted to seed 001.
SLIDING_LIMITING_SHEAR_COEFF = LIMITING_SHEAR_COEFF

# --- Eq. (10): Roelands viscosity ------------------------------------------------------------------
#: Roelands constant: ln η₀ + 9.67 = ln(η₀/η_∞) with η_∞ = 6.31e-5 Pa·s (Roelands 1966; η₀ in Pa·s).
ROELANDS_LN_ETA_INF = 9.67  # [-]
#: Roelands reference pressure p_r = 1.96e8 Pa (1/p_r = 5.1e-9 1/Pa, seed 001 eq. 10).
ROELANDS_PRESSURE = 1.96e8  # [Pa]
#: Roelands pressure–viscosity index Z printed in seed 001 eq. (10); mineral oils 0.5…0.8.
ROELANDS_EXPONENT_LIU2022 = 0.601  # [-]
#: Gauss–Legendre nodes of the tractive integral (θ-substitution x = b sin θ makes the integrand
#: smooth; 64 nodes integrate it to < 1e-10 relative for Roelands exponents up to ~20, see tests).
TRACTIVE_QUADRATURE_NODES = 64

_GL_X, _GL_W = np.polynomial.legendre.leggauss(TRACTIVE_QUADRATURE_NODES)
_THETA = 0.25 * np.pi * (_GL_X + 1.0)  # nodes on [0, π/2]
_THETA_W = 0.25 * np.pi * _GL_W


def _arr(x):
    return np.asarray(x, dtype=float)


def roelands_viscosity_ratio(pressure, viscosity, exponent=ROELANDS_EXPONENT_LIU2022):
    """Roelands pressure–viscosity ratio η(p)/η₀.

    Parameters
    ----------
    pressure : array_like
        Pressure p [Pa], ``>= 0``.
    viscosity : array_like
        Ambient-pressure viscosity η₀ [Pa·s], above η_∞ = 6.31e-5 Pa·s.
    exponent : array_like
        Pressure–viscosity index Z [-], ``> 0``.

    Returns
    -------
    ndarray
        η(p)/η₀ [-] (1 at p = 0, increasing in p).

    Notes
    -----
    .. math:: \\frac{\\eta}{\\eta_0} = \\exp\\left\\{(\\ln\\eta_0 + 9.67)
              \\left[\\left(1 + \\frac{p}{1.96\\times10^{8}}\\right)^{Z} - 1\\right]\\right\\}

    References
    ----------
    Roelands (1966); Liu et al. (2022) eq. (10), doi:10.3390/lubricants10070154.
    """
    checks.non_negative("pressure", pressure, "Pa")
    k = _log_ratio_coeff(viscosity)
    checks.positive("roelands_exponent", exponent)
    return np.exp(k * ((1.0 + _arr(pressure) / ROELANDS_PRESSURE) ** _arr(exponent) - 1.0))


def _log_ratio_coeff(viscosity):
    checks.positive("viscosity", viscosity, "Pa*s")
    k = np.log(_arr(viscosity)) + ROELANDS_LN_ETA_INF
    if np.any(k <= 0):
        raise InputError(
            f"viscosity ({float(np.min(viscosity)):.6g} Pa*s) must exceed the Roelands limit "
            f"eta_inf = {np.exp(-ROELANDS_LN_ETA_INF):.3g} Pa*s"
        )
    return k


def roelands_exponent(pressure_viscosity, viscosity):
    """Roelands index Z with the same low-pressure slope as a Barus coefficient α.

    Parameters
    ----------
    pressure_viscosity : array_like
        Barus α [1/Pa], ``> 0``.
    viscosity : array_like
        η₀ [Pa·s].

    Returns
    -------
    ndarray
        Z [-].

    Notes
    -----
    .. math:: Z = \\frac{\\alpha\\,p_r}{\\ln\\eta_0 + 9.67},\\qquad p_r = 1.96\\times10^{8}\\ \\mathrm{Pa}

    (d ln η/dp at p = 0 equals α.) Roelands (1966); Hamrock, Schmid & Jacobson (2004) ch. 4.
    """
    checks.positive("pressure_viscosity", pressure_viscosity, "1/Pa")
    return _arr(pressure_viscosity) * ROELANDS_PRESSURE / _log_ratio_coeff(viscosity)


def tractive_integral(max_pressure, half_width, viscosity, exponent=ROELANDS_EXPONENT_LIU2022):
    """Tractive integral I of a Hertz line contact (seed 001 eq. 10) [m].

    Parameters
    ----------
    max_pressure : array_like
        Hertz maximum pressure p_max [Pa], ``>= 0``.
    half_width : array_like
        Hertz semi-width b [m], ``>= 0``.
    viscosity : array_like
        η₀ [Pa·s].
    exponent : array_like
        Roelands index Z [-].

    Returns
    -------
    ndarray
        I [m]; I = b at p_max = 0, 0 at b = 0.

    Notes
    -----
    .. math::

        I = \\int_0^b \\frac{\\eta(p(x))}{\\eta_0}\\,dx
          = b\\int_0^{\\pi/2} \\frac{\\eta(p_{max}\\cos\\theta)}{\\eta_0}\\cos\\theta\\,d\\theta,
        \\qquad p = p_{max}\\sqrt{1 - x^2/b^2}

    (x = b sin θ; Gauss–Legendre with :data:`TRACTIVE_QUADRATURE_NODES` nodes.)

    References
    ----------
    Zhou & Hoeprich (1991) J. Tribol. 113:590; Liu et al. (2022) eq. (10).
    """
    checks.non_negative("max_pressure", max_pressure, "Pa")
    checks.non_negative("half_width", half_width, "m")
    k = _log_ratio_coeff(viscosity)
    checks.positive("roelands_exponent", exponent)
    p = _arr(max_pressure)[..., None] * np.cos(_THETA)
    z = _arr(exponent)[..., None]
    ratio = np.exp(_arr(k)[..., None] * ((1.0 + p / ROELANDS_PRESSURE) ** z - 1.0))
    return _arr(half_width) * (ratio * np.cos(_THETA) * _THETA_W).sum(-1)


def limited_shear_integral(
    max_pressure,
    half_width,
    viscosity,
    shear_rate,
    exponent=ROELANDS_EXPONENT_LIU2022,
    limiting_shear_coeff=SLIDING_LIMITING_SHEAR_COEFF,
):
    """Shear force per unit length of a Hertz strip with a limiting shear stress [N/m].

    Parameters
    ----------
    max_pressure : array_like
        Hertz maximum pressure p_max [Pa], ``>= 0``.
    half_width : array_like
        Hertz semi-width b [m], ``>= 0``.
    viscosity : array_like
        η₀ [Pa·s].
    shear_rate : array_like
        Film shear rate |v_s|/h [1/s], ``>= 0``.
    exponent : array_like
        Roelands index Z [-].
    limiting_shear_coeff : array_like
        Λ_L = τ_L/p [-], ``> 0``.

    Returns
    -------
    ndarray
        ∫ τ dx over the whole strip −b … b [N/m]; ≤ Λ_L π p_max b / 2 = Λ_L Q/l.

    Notes
    -----
    Bair–Winer fluid (viscous with a limiting shear stress) at the local Hertz pressure:

    .. math::

        \\tau = \\tau_L\\left[1 - e^{-\\tau_N/\\tau_L}\\right],\\quad \\tau_L = \\Lambda_L\\,p,\\quad
        \\tau_N = \\eta_0\\,\\frac{\\eta(p)}{\\eta_0}\\,\\dot\\gamma,\\quad
        \\int_{-b}^{b}\\tau\\,dx = 2b\\int_0^{\\pi/2}\\tau(p_{max}\\cos\\theta)\\cos\\theta\\,d\\theta

    with Roelands' η(p)/η₀ (:func:`roelands_viscosity_ratio`). For τ_N ≪ τ_L it is
    2 η₀ γ̇ I (eq. 10's I); for τ_N ≫ τ_L it is Λ_L Q/l.

    References
    ----------
    Bair S., Winer W.O. (1979) J. Lubr. Technol. 101(3):258-264; Liu et al. (2022) eq. (10).
    """
    checks.non_negative("max_pressure", max_pressure, "Pa")
    checks.non_negative("half_width", half_width, "m")
    checks.non_negative("shear_rate", shear_rate, "1/s")
    k = _log_ratio_coeff(viscosity)
    checks.positive("roelands_exponent", exponent)
    checks.positive("limiting_shear_coeff", limiting_shear_coeff)
    p = _arr(max_pressure)[..., None] * np.cos(_THETA)
    tau_l = _arr(limiting_shear_coeff)[..., None] * p
    log_ratio = _arr(k)[..., None] * ((1.0 + p / ROELANDS_PRESSURE) ** _arr(exponent)[..., None] - 1.0)
    # τ_N/τ_L in logs: η(p) overflows long before τ_N/τ_L does (Roelands ratios reach 1e300 at 3 GPa).
    with np.errstate(divide="ignore"):
        log_arg = (
            np.log(_arr(viscosity))[..., None]
            + log_ratio
            + np.log(_arr(shear_rate))[..., None]
            - np.log(tau_l)
        )
    arg = np.exp(np.minimum(log_arg, 700.0))
    tau = np.where((tau_l > 0) & (_arr(shear_rate)[..., None] > 0), -tau_l * np.expm1(-arg), 0.0)
    return 2.0 * _arr(half_width) * (tau * np.cos(_THETA) * _THETA_W).sum(-1)
