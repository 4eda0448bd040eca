"""Traction (friction) coefficients of lubricated rolling–sliding contacts.

All quantities are SI (Pa, Pa·s, 1/Pa, m, m/s, N); coefficients are dimensionless. Functions are
pure numpy and broadcast over their arguments.

Sign convention: the slide-to-roll ratio ``s = Δu / u_m`` (sliding speed over mean entrainment
speed) carries the direction of sliding; every slip-dependent coefficient is odd in ``s`` with
``μ(0) = 0``, so the traction force follows the sliding direction.

Models (registry :data:`TRACTION_MODELS`, dispatch with :func:`traction_coefficient`):

- ``"boundary"`` – constant Coulomb coefficient μ_bl (signed by the slip when a slip is given),
- ``"aihara"`` – saturating exponential curve μ_max (1 − e^(−2.6 s/s_max)) (Aihara 1987),
- ``"limiting_shear"`` – Bair–Winer viscous/limiting-shear-stress fluid in a parallel film (1979),
- ``"mixed"`` – asperity-load-share interpolation between boundary and EHL coefficients (SKF 2018).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics.lubrication.ehl import MIXED_COEFF, MIXED_EXP, mixed_load_share

# Boundary-lubrication coefficient. SKF rolling bearing catalogue, frictional moment model:
# μ_bl = 0.15 by default, 0.12 after running-in (used for the SKF sliding-friction weighting).
MU_BOUNDARY = 0.12  # [-] SKF μ_bl (run-in); typical boundary range 0.08..0.15
MU_BOUNDARY_UNRUN = 0.15  # [-] SKF μ_bl (default, not run-in)
# SKF full-film coefficients μ_EHL for the same weighting (mineral oil): cylindrical roller 0.02,
# tapered/spherical roller 0.002, other bearings 0.05. Listed for callers; not used inside here.
MU_EHL_SKF_CYLINDRICAL = 0.02  # [-]
MU_EHL_SKF_TAPERED = 0.002  # [-]
MU_EHL_SKF_MINERAL = 0.05  # [-]

# Aihara-type traction curve μ = μ_max (1 − exp(−2.6 s/s_max)): the constant makes μ reach
# 1 − e^(−2.6) ≈ 92.6 % of μ_max at s = s_max. Aihara S. (1987) J. Tribol. 109(3):471-477
# (via formulas.md C3 [S]; constant not re-checked against the paper here).
AIHARA_RATE = 2.6  # [-]

# Limiting shear stress proportional to pressure, τ_L = Λ_L p (Bair & Winer 1979); Λ_L of
# mineral and synthetic oils is of order 0.05..0.1. Default chosen mid-range.
LIMITING_SHEAR_COEFF = 0.075  # [-] τ_L / p, valid 0.03..0.12


def _sign(slide_to_roll):
    checks.finite("slide_to_roll", slide_to_roll)
    return np.sign(np.asarray(slide_to_roll, dtype=float))


def traction_boundary(mu_boundary=MU_BOUNDARY, slide_to_roll=None):
    """Constant boundary-lubrication (Coulomb) friction coefficient.

    Parameters
    ----------
    mu_boundary : array_like
        Boundary friction coefficient μ_bl [-], ``>= 0``. Default :data:`MU_BOUNDARY`.
    slide_to_roll : array_like, optional
        Slide-to-roll ratio s [-]; when given, the result carries its sign (0 at s = 0).

    Returns
    -------
    ndarray
        μ [-].

    Notes
    -----
    .. math:: \\mu = \\mu_{bl}\\,\\operatorname{sgn}(s)

    References
    ----------
    SKF Group (2018) Rolling bearings catalogue, "The SKF model for calculating the frictional
    moment" (μ_bl = 0.12 run-in, 0.15 otherwise).
    """
    checks.non_negative("mu_boundary", mu_boundary)
    mu = np.asarray(mu_boundary, dtype=float)
    if slide_to_roll is None:
        return mu
    return mu * _sign(slide_to_roll)


def traction_aihara(slide_to_roll, mu_max, slide_to_roll_at_max):
    """Saturating EHL traction curve of Aihara type.

    Parameters
    ----------
    slide_to_roll : array_like
        Slide-to-roll ratio s = Δu/u_m [-] (signed).
    mu_max : array_like
        Maximum (plateau) traction coefficient μ_max [-], ``>= 0``.
    slide_to_roll_at_max : array_like
        Slide-to-roll ratio s_max at which the curve is practically saturated [-], ``> 0``.

    Returns
    -------
    ndarray
        μ [-], odd in s, ``|μ| < μ_max``, increasing in ``|s|``.

    Notes
    -----
    .. math:: \\mu = \\mu_{max}\\left(1 - e^{-2.6\\,|s|/s_{max}}\\right)\\operatorname{sgn}(s)

    References
    ----------
    Aihara S. (1987) A new running torque formula for tapered roller bearings under axial load.
    J. Tribol. 109(3):471-477 (form as transcribed in bearingkit formulas.md C3).
    """
    sign = _sign(slide_to_roll)
    checks.non_negative("mu_max", mu_max)
    checks.positive("slide_to_roll_at_max", slide_to_roll_at_max)
    s = np.abs(np.asarray(slide_to_roll, dtype=float))
    ratio = s / np.asarray(slide_to_roll_at_max, dtype=float)
    return np.asarray(mu_max, dtype=float) * (-np.expm1(-AIHARA_RATE * ratio)) * sign


def traction_limiting_shear(
    slide_to_roll,
    entrainment_speed,
    viscosity,
    pressure_viscosity,
    mean_pressure,
    film_central,
    limiting_shear_coeff=LIMITING_SHEAR_COEFF,
):
    """Traction of a Bair–Winer (viscous + limiting shear stress) film at the mean contact pressure.

    The film is taken as parallel with thickness ``h_c``, pressure ``p̄`` and Barus viscosity
    ``η = η₀ exp(α p̄)``; the shear rate is ``Δu / h_c`` with ``Δu = s u_m``.

    Parameters
    ----------
    slide_to_roll : array_like
        Slide-to-roll ratio s [-] (signed).
    entrainment_speed : array_like
        Mean entrainment speed u_m [m/s], ``>= 0``.
    viscosity : array_like
        Ambient-pressure viscosity η₀ [Pa·s].
    pressure_viscosity : array_like
        Barus pressure–viscosity coefficient α [1/Pa], ``>= 0``.
    mean_pressure : array_like
        Mean Hertzian pressure p̄ [Pa], ``> 0``.
    film_central : array_like
        Central film thickness h_c [m], ``> 0``.
    limiting_shear_coeff : array_like
        Λ_L = τ_L / p [-], ``> 0``. Default :data:`LIMITING_SHEAR_COEFF`.

    Returns
    -------
    ndarray
        μ [-], odd in s, bounded by Λ_L, increasing in ``|s|``.

    Notes
    -----
    .. math::

        \\mu = \\frac{\\tau_L}{\\bar p}\\left[1 - \\exp\\left(
        -\\frac{\\eta\\,|s|\\,u_m}{h_c\\,\\tau_L}\\right)\\right]\\operatorname{sgn}(s),
        \\quad \\tau_L = \\Lambda_L\\,\\bar p,\\quad
        \\eta = \\eta_0 e^{\\alpha \\bar p}

    References
    ----------
    Bair S., Winer W.O. (1979) A rheological model for elastohydrodynamic contacts based on
    primary laboratory data. J. Lubr. Technol. 101(3):258-264.
    """
    sign = _sign(slide_to_roll)
    checks.non_negative("entrainment_speed", entrainment_speed, "m/s")
    checks.positive("viscosity", viscosity, "Pa*s")
    checks.non_negative("pressure_viscosity", pressure_viscosity, "1/Pa")
    checks.positive("mean_pressure", mean_pressure, "Pa")
    checks.positive("film_central", film_central, "m")
    checks.positive("limiting_shear_coeff", limiting_shear_coeff)
    p = np.asarray(mean_pressure, dtype=float)
    lam_l = np.asarray(limiting_shear_coeff, dtype=float)
    tau_l = lam_l * p
    # log-viscosity keeps exp(α p̄) from overflowing before it is divided by τ_L
    log_eta = np.log(np.asarray(viscosity, dtype=float)) + np.asarray(pressure_viscosity, dtype=float) * p
    shear_rate = (
        np.abs(np.asarray(slide_to_roll, dtype=float))
        * np.asarray(entrainment_speed, dtype=float)
        / np.asarray(film_central, dtype=float)
    )
    with np.errstate(over="ignore", divide="ignore"):
        arg = np.exp(np.minimum(log_eta - np.log(tau_l), 700.0)) * shear_rate
    arg = np.where(shear_rate > 0.0, arg, 0.0)
    return lam_l * (-np.expm1(-arg)) * sign


def traction_mixed(film_parameter, mu_ehl, mu_boundary=MU_BOUNDARY, slide_to_roll=None):
    """Mixed-lubrication traction by asperity load share.

    Parameters
    ----------
    film_parameter : array_like
        Film parameter Λ [-], ``>= 0``.
    mu_ehl : array_like
        Full-film (EHL) traction coefficient μ_EHL [-] (signed by the caller's slip).
    mu_boundary : array_like
        Boundary coefficient μ_bl [-], ``>= 0``. Default :data:`MU_BOUNDARY`.
    slide_to_roll : array_like, optional
        Slip that signs the boundary part; without it μ_bl enters as a magnitude.

    Returns
    -------
    ndarray
        μ [-]: μ_bl at Λ = 0, → μ_EHL as Λ → ∞, monotone in Λ.

    Notes
    -----
    .. math:: \\mu = f_a\\,\\mu_{bl} + (1 - f_a)\\,\\mu_{EHL},\\qquad f_a = e^{-1.8\\,\\Lambda^{1.2}}

    References
    ----------
    Form of the SKF weighting μ_sl = φ_bl μ_bl + (1 − φ_bl) μ_EHL (SKF catalogue) with the asperity
    share of Liu et al. (2022) Lubricants 10:154, eq. (9), doi:10.3390/lubricants10070154; seed
    Tian et al. (2025) Machines 13:588, §4.2 interpolates "through the oil film parameter".
    """
    checks.finite("mu_ehl", mu_ehl)
    share = mixed_load_share(film_parameter)
    boundary = traction_boundary(mu_boundary, slide_to_roll)
    return share * boundary + (1.0 - share) * np.asarray(mu_ehl, dtype=float)


def flange_friction_force(flange_load, film_parameter, mu_coulomb=MU_BOUNDARY):
    """Roller-end/flange sliding friction force in mixed lubrication (seed 001 eq. 9).

    Parameters
    ----------
    flange_load : array_like
        Normal load at the roller end–flange contact Q_f [N], ``>= 0``.
    film_parameter : array_like
        Film parameter of that contact Λ_r [-], ``>= 0``.
    mu_coulomb : array_like
        Coulomb friction coefficient μ₀ [-], ``>= 0``. Default :data:`MU_BOUNDARY`.

    Returns
    -------
    ndarray
        Friction force F_fs [N].

    Notes
    -----
    .. math:: F_{fs} = Q_f\\,\\mu_0\\,e^{-1.8\\,\\Lambda_r^{1.2}}

    Kept as the paper writes it: only the asperity-carried part of the load produces friction; the
    fluid part is neglected (its viscous traction is not added).

    References
    ----------
    Liu et al. (2022) An investigation for the friction torque of a tapered roller bearing
    considering the geometric homogeneity of rollers. Lubricants 10:154, eq. (9),
    doi:10.3390/lubricants10070154.
    """
    checks.non_negative("flange_load", flange_load, "N")
    checks.non_negative("mu_coulomb", mu_coulomb)
    checks.non_negative("film_parameter", film_parameter)
    lam = np.asarray(film_parameter, dtype=float)
    return (
        np.asarray(flange_load, dtype=float)
        * np.asarray(mu_coulomb, dtype=float)
        * np.exp(-MIXED_COEFF * lam**MIXED_EXP)
    )


TRACTION_MODELS: dict[str, Callable[..., np.ndarray]] = {
    "boundary": traction_boundary,
    "aihara": traction_aihara,
    "limiting_shear": traction_limiting_shear,
    "mixed": traction_mixed,
}

# Citation key (bearingkit.references) of each traction model, for run reports.
TRACTION_MODEL_REFERENCES: dict[str, str] = {
    "boundary": "skf_friction",
    "aihara": "aihara1987",
    "limiting_shear": "bair1979",
    "mixed": "liu2022",
}


def traction_coefficient(model: str, **kwargs):
    """Traction coefficient by model name from :data:`TRACTION_MODELS`.

    Parameters
    ----------
    model : str
        One of ``"boundary"``, ``"aihara"``, ``"limiting_shear"``, ``"mixed"``.
    **kwargs
        Keyword arguments of the selected function.

    Returns
    -------
    ndarray
        μ [-].
    """
    checks.one_of("traction_model", model, TRACTION_MODELS)
    try:
        return TRACTION_MODELS[model](**kwargs)
    except TypeError as exc:
        raise InputError(f"traction_model ({model!r}) got bad arguments: {exc}") from exc
