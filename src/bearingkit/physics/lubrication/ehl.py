"""Elastohydrodynamic (EHL) film thickness of rolling contacts: regression formulas and corrections.

All quantities are SI: m, N, Pa, Pa·s, 1/Pa, m/s, W/(m·K), 1/K. Every function is a pure numpy
function that broadcasts over its arguments (leading case axis first).

Dimensionless groups follow Hamrock's convention (Hamrock & Dowson 1977; Pan & Hamrock 1989):

- speed ``U = η₀ u / (E′ R_x)`` with ``u = (u₁ + u₂)/2`` the mean entrainment speed,
- material ``G = α E′`` with ``E′ = 2 / [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]`` (``e_reduced``),
- load ``W = Q / (E′ R_x²)`` for point contacts and ``W′ = Q / (E′ R_x l)`` for line contacts.

Conventions chosen here (the sources do not fix them):

- ``load <= 0`` raises :class:`~bearingkit.errors.InputError`: every formula carries ``W`` to a
  negative power, so the film would diverge as the load vanishes, and an unloaded element has no
  Hertzian contact to which the formulas apply. Callers must mask unloaded elements first.
- Zero entrainment speed is allowed and gives a zero film (not NaN); negative speed is an error
  (pass the magnitude of the mean rolling speed).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError

# --- Hamrock & Dowson (1977) point contact, Part III, eqs. for H_c and H_min ---------------------
# Fitted to 34 isothermal numerical solutions: 1 <= k <= 8, U over about two decades, W over one
# decade, materials bronze/steel/silicon nitride with paraffinic and naphthenic mineral oils.
HD_CENTRAL_COEFF = 2.69  # [-] H_c prefactor, Hamrock & Dowson 1977 (Part III)
HD_CENTRAL_U_EXP = 0.67  # [-] exponent of U in H_c
HD_CENTRAL_G_EXP = 0.53  # [-] exponent of G in H_c
HD_CENTRAL_W_EXP = -0.067  # [-] exponent of W in H_c
HD_CENTRAL_K_AMP = 0.61  # [-] amplitude of the ellipticity term (1 - 0.61 e^(-0.73 k))
HD_CENTRAL_K_RATE = 0.73  # [-] rate of the ellipticity term in H_c
HD_MIN_COEFF = 3.63  # [-] H_min prefactor, Hamrock & Dowson 1977 (Part III, abstract)
HD_MIN_U_EXP = 0.68  # [-] exponent of U in H_min
HD_MIN_G_EXP = 0.49  # [-] exponent of G in H_min
HD_MIN_W_EXP = -0.073  # [-] exponent of W in H_min
HD_MIN_K_RATE = 0.68  # [-] rate of the ellipticity term (1 - e^(-0.68 k)) in H_min

# Ellipticity k = a/b from the radius ratio, Hamrock & Brewe (1983) eq. for k̄; the 1977 abstract
# rounds it to 1.03 (R_y/R_x)^0.64. Accurate to a few per cent for 1 <= R_y/R_x <= 100.
ELLIPTICITY_COEFF = 1.0339  # [-] Hamrock & Brewe 1983
ELLIPTICITY_EXP = 0.636  # [-] Hamrock & Brewe 1983

# --- Dowson & Higginson line contact (minimum film) ------------------------------------------
# Dowson (1968) / Dowson & Higginson (1977 ed.): H_min = 2.65 U^0.70 G^0.54 W'^-0.13 with the
# load per unit length, W' = Q/(E' R_x l). Isothermal, Newtonian, fully flooded.
DH_MIN_COEFF = 2.65  # [-]
DH_MIN_U_EXP = 0.70  # [-]
DH_MIN_G_EXP = 0.54  # [-]
DH_MIN_W_EXP = -0.13  # [-]
# Dowson & Higginson give only h_min; the central film of their line-contact solutions is about
# 4/3 of it (h_min ≈ 0.75 h_c, the usual engineering ratio). Approximation, not a fitted formula.
DH_CENTRAL_TO_MINIMUM = 4.0 / 3.0  # [-]

# --- Pan & Hamrock (1989) line contact, J. Tribol. 111(2):246-251 ----------------------------
# Fitted to numerical solutions; W' = Q/(E' R_x l), U and G as above.
PH_MIN_COEFF = 1.714  # [-] H_min = 1.714 W'^-0.128 U^0.694 G^0.568
PH_MIN_U_EXP = 0.694  # [-]
PH_MIN_G_EXP = 0.568  # [-]
PH_MIN_W_EXP = -0.128  # [-]
PH_CENTRAL_COEFF = 2.922  # [-] H_c = 2.922 W'^-0.166 U^0.692 G^0.470
PH_CENTRAL_U_EXP = 0.692  # [-]
PH_CENTRAL_G_EXP = 0.470  # [-]
PH_CENTRAL_W_EXP = -0.166  # [-]

# --- Starvation, Hamrock & Dowson (1977) Part IV ---------------------------------------------
# Fully-flooded boundary m* - 1 = C [(R_x/b)^2 H]^e; starved film H_s = H (ψ)^s with
# ψ = (m-1)/(m*-1), m the inlet-meniscus distance from the contact centre in units of b.
STARVATION_CENTRAL_COEFF = 3.06  # [-] C for the central film
STARVATION_CENTRAL_EXP = 0.58  # [-] e for the central film
STARVATION_CENTRAL_POWER = 0.29  # [-] s for the central film
STARVATION_MIN_COEFF = 3.34  # [-] C for the minimum film
STARVATION_MIN_EXP = 0.56  # [-] e for the minimum film
STARVATION_MIN_POWER = 0.25  # [-] s for the minimum film

# --- Inlet shear heating, Murch & Wilson (1975) ----------------------------------------------
# φ_T = 3.94 / (3.94 + L^0.62), L = η₀ β u² / k_oil; line-contact inlet analysis, 0 <= L <~ 100.
THERMAL_COEFF = 3.94  # [-]
THERMAL_EXP = 0.62  # [-]

# --- Asperity load share, seed 001 eq. (9) (Liu et al. 2022) ---------------------------------
# f_a = exp(-1.8 Λ^1.2): fraction of the load carried by asperities; 1 at Λ = 0, 0.5 % at Λ = 3.
MIXED_COEFF = 1.8  # [-]
MIXED_EXP = 1.2  # [-]


@dataclass(frozen=True)
class FilmThickness:
    """Central and minimum EHL film thickness.

    Attributes
    ----------
    central : ndarray
        Central film thickness ``h_c`` [m].
    minimum : ndarray
        Minimum film thickness ``h_min`` [m].
    """

    central: np.ndarray
    minimum: np.ndarray

    def __post_init__(self):
        checks.non_negative("film_central", self.central, "m")
        checks.non_negative("film_minimum", self.minimum, "m")


def _validate_common(viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, load):
    checks.positive("viscosity", viscosity, "Pa*s")
    checks.non_negative("entrainment_speed", entrainment_speed, "m/s")
    checks.positive("pressure_viscosity", pressure_viscosity, "1/Pa")
    checks.positive("e_reduced", e_reduced, "Pa")
    checks.positive("radius_x", radius_x, "m")
    checks.positive("load", load, "N")


def dimensionless_groups(
    viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, load, effective_length=None
):
    """Hamrock's dimensionless speed, material and load parameters.

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity at inlet temperature and ambient pressure η₀ [Pa·s].
    entrainment_speed : array_like
        Mean entrainment speed u = (u₁ + u₂)/2 [m/s], ``>= 0``.
    pressure_viscosity : array_like
        Barus pressure–viscosity coefficient α [1/Pa].
    e_reduced : array_like
        Reduced modulus E′ [Pa].
    radius_x : array_like
        Effective radius in the rolling direction R_x [m].
    load : array_like
        Normal contact load Q [N], ``> 0``.
    effective_length : array_like, optional
        Roller effective length l [m]; when given, ``W`` is the line-contact ``W′``.

    Returns
    -------
    U, G, W : ndarray
        Speed, material and load parameters [-].

    Notes
    -----
    .. math::

        U = \\frac{\\eta_0 u}{E' R_x},\\quad G = \\alpha E',\\quad
        W = \\frac{Q}{E' R_x^2}\\ \\text{(point)},\\quad W' = \\frac{Q}{E' R_x l}\\ \\text{(line)}

    References
    ----------
    Hamrock B.J., Dowson D. (1977) J. Lubr. Technol. 99(2):264-275, doi:10.1115/1.3453074;
    Pan P., Hamrock B.J. (1989) J. Tribol. 111(2):246-251 (DOI not verified here).
    """
    _validate_common(viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, load)
    eta = np.asarray(viscosity, dtype=float)
    u = np.asarray(entrainment_speed, dtype=float)
    alpha = np.asarray(pressure_viscosity, dtype=float)
    e = np.asarray(e_reduced, dtype=float)
    rx = np.asarray(radius_x, dtype=float)
    q = np.asarray(load, dtype=float)
    speed = eta * u / (e * rx)
    material = alpha * e
    if effective_length is None:
        load_param = q / (e * rx**2)
    else:
        checks.positive("effective_length", effective_length, "m")
        load_param = q / (e * rx * np.asarray(effective_length, dtype=float))
    speed, material, load_param = np.broadcast_arrays(speed, material, load_param)
    return speed, material, load_param


def ellipticity_hamrock_brewe(radius_x, radius_y):
    """Approximate ellipticity k = a/b of a point contact from its radius ratio.

    Parameters
    ----------
    radius_x : array_like
        Effective radius in the rolling direction R_x [m].
    radius_y : array_like
        Effective radius transverse to rolling R_y [m].

    Returns
    -------
    ndarray
        Ellipticity parameter k [-].

    Notes
    -----
    .. math:: k = 1.0339\\,(R_y/R_x)^{0.636}

    References
    ----------
    Hamrock B.J., Brewe D. (1983) J. Lubr. Technol. 105(2):171-177, doi:10.1115/1.3254558.
    """
    checks.positive("radius_x", radius_x, "m")
    checks.positive("radius_y", radius_y, "m")
    ratio = np.asarray(radius_y, dtype=float) / np.asarray(radius_x, dtype=float)
    return ELLIPTICITY_COEFF * ratio**ELLIPTICITY_EXP


def film_point_hamrock_dowson(
    viscosity,
    entrainment_speed,
    pressure_viscosity,
    e_reduced,
    radius_x,
    radius_y,
    load,
    ellipticity=None,
) -> FilmThickness:
    """Central and minimum film thickness of an elliptical point contact (Hamrock & Dowson).

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity η₀ [Pa·s].
    entrainment_speed : array_like
        Mean entrainment speed u [m/s], ``>= 0``; zero gives a zero film.
    pressure_viscosity : array_like
        Pressure–viscosity coefficient α [1/Pa].
    e_reduced : array_like
        Reduced modulus E′ [Pa].
    radius_x : array_like
        Effective radius in the rolling direction R_x [m].
    radius_y : array_like
        Effective transverse radius R_y [m].
    load : array_like
        Normal load Q [N], ``> 0`` (InputError otherwise).
    ellipticity : array_like, optional
        Ellipticity k = a/b [-]; by default the Hamrock–Brewe estimate from R_y/R_x.

    Returns
    -------
    FilmThickness
        ``central`` and ``minimum`` [m].

    Notes
    -----
    .. math::

        \\frac{h_c}{R_x} = 2.69\\,U^{0.67} G^{0.53} W^{-0.067}\\,(1 - 0.61 e^{-0.73k}),\\qquad
        \\frac{h_{min}}{R_x} = 3.63\\,U^{0.68} G^{0.49} W^{-0.073}\\,(1 - e^{-0.68k})

    References
    ----------
    Hamrock B.J., Dowson D. (1977) Isothermal elastohydrodynamic lubrication of point contacts,
    Part III—fully flooded results. J. Lubr. Technol. 99(2):264-275, doi:10.1115/1.3453074.
    """
    u_, g_, w_ = dimensionless_groups(
        viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, load
    )
    if ellipticity is None:
        k = ellipticity_hamrock_brewe(radius_x, radius_y)
    else:
        checks.positive("radius_y", radius_y, "m")
        checks.in_range("ellipticity", ellipticity, 1.0, np.inf)
        k = np.asarray(ellipticity, dtype=float)
    rx = np.asarray(radius_x, dtype=float)
    central = (
        rx
        * HD_CENTRAL_COEFF
        * u_**HD_CENTRAL_U_EXP
        * g_**HD_CENTRAL_G_EXP
        * w_**HD_CENTRAL_W_EXP
        * (1.0 - HD_CENTRAL_K_AMP * np.exp(-HD_CENTRAL_K_RATE * k))
    )
    minimum = (
        rx
        * HD_MIN_COEFF
        * u_**HD_MIN_U_EXP
        * g_**HD_MIN_G_EXP
        * w_**HD_MIN_W_EXP
        * (1.0 - np.exp(-HD_MIN_K_RATE * k))
    )
    central, minimum = np.broadcast_arrays(central, minimum)
    return FilmThickness(central=np.array(central), minimum=np.array(minimum))


def film_line_dowson_higginson(
    viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, load, effective_length
) -> FilmThickness:
    """Minimum (and approximate central) film thickness of a line contact, Dowson–Higginson.

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity η₀ [Pa·s].
    entrainment_speed : array_like
        Mean entrainment speed u [m/s], ``>= 0``.
    pressure_viscosity : array_like
        Pressure–viscosity coefficient α [1/Pa].
    e_reduced : array_like
        Reduced modulus E′ [Pa].
    radius_x : array_like
        Effective radius in the rolling direction R_x [m].
    load : array_like
        Normal load on the whole length Q [N], ``> 0``.
    effective_length : array_like
        Effective contact length l [m].

    Returns
    -------
    FilmThickness
        ``minimum`` from the formula; ``central = (4/3) minimum`` (``DH_CENTRAL_TO_MINIMUM``), an
        approximation because Dowson & Higginson give only the minimum film.

    Notes
    -----
    .. math:: \\frac{h_{min}}{R_x} = 2.65\\,U^{0.70} G^{0.54} W'^{-0.13},\\quad W' = \\frac{Q}{E' R_x l}

    References
    ----------
    Dowson D. (1968) Elastohydrodynamics. Proc. IMechE 182(3A):151-167;
    Dowson D., Higginson G.R. (1977) Elasto-Hydrodynamic
    Lubrication, SI ed., Pergamon.
    """
    u_, g_, w_ = dimensionless_groups(
        viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, load, effective_length
    )
    rx = np.asarray(radius_x, dtype=float)
    minimum = rx * DH_MIN_COEFF * u_**DH_MIN_U_EXP * g_**DH_MIN_G_EXP * w_**DH_MIN_W_EXP
    minimum = np.array(np.broadcast_to(minimum, u_.shape))
    return FilmThickness(central=np.asarray(DH_CENTRAL_TO_MINIMUM * minimum), minimum=minimum)


def film_line_pan_hamrock(
    viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, load, effective_length
) -> FilmThickness:
    """Central and minimum film thickness of a rectangular line contact, Pan & Hamrock.

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity η₀ [Pa·s].
    entrainment_speed : array_like
        Mean entrainment speed u [m/s], ``>= 0``.
    pressure_viscosity : array_like
        Pressure–viscosity coefficient α [1/Pa].
    e_reduced : array_like
        Reduced modulus E′ [Pa].
    radius_x : array_like
        Effective radius in the rolling direction R_x [m].
    load : array_like
        Normal load on the whole length Q [N], ``> 0``.
    effective_length : array_like
        Effective contact length l [m].

    Returns
    -------
    FilmThickness
        ``central`` and ``minimum`` [m].

    Notes
    -----
    .. math::

        \\frac{h_{min}}{R_x} = 1.714\\,W'^{-0.128} U^{0.694} G^{0.568},\\qquad
        \\frac{h_c}{R_x} = 2.922\\,W'^{-0.166} U^{0.692} G^{0.470}

    References
    ----------
    Pan P., Hamrock B.J. (1989) Simple formulas for performance parameters used in
    elastohydrodynamically lubricated line contacts. J. Tribol. 111(2):246-251.
    """
    u_, g_, w_ = dimensionless_groups(
        viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, load, effective_length
    )
    rx = np.asarray(radius_x, dtype=float)
    minimum = rx * PH_MIN_COEFF * w_**PH_MIN_W_EXP * u_**PH_MIN_U_EXP * g_**PH_MIN_G_EXP
    central = rx * PH_CENTRAL_COEFF * w_**PH_CENTRAL_W_EXP * u_**PH_CENTRAL_U_EXP * g_**PH_CENTRAL_G_EXP
    central, minimum = np.broadcast_arrays(central, minimum)
    return FilmThickness(central=np.array(central), minimum=np.array(minimum))


FILM_MODELS: dict[str, Callable[..., FilmThickness]] = {
    "hamrock_dowson": film_point_hamrock_dowson,  # point contact; needs radius_y
    "dowson_higginson": film_line_dowson_higginson,  # line contact; needs effective_length
    "pan_hamrock": film_line_pan_hamrock,  # line contact; needs effective_length
}

# Citation key (bearingkit.references) of each film model, for run reports.
FILM_MODEL_REFERENCES: dict[str, str] = {
    "hamrock_dowson": "hamrock1977",
    "dowson_higginson": "dowson1968",
    "pan_hamrock": "pan1989",
}


def film_thickness(model: str, **kwargs) -> FilmThickness:
    """Film thickness by model name from :data:`FILM_MODELS` (keyword arguments of that model).

    Parameters
    ----------
    model : str
        ``"hamrock_dowson"`` (Hamrock & Dowson 1977), ``"dowson_higginson"`` or ``"pan_hamrock"`` (1989).
    **kwargs
        The selected model's arguments (SI).
    """
    checks.one_of("film_model", model, FILM_MODELS)
    try:
        return FILM_MODELS[model](**kwargs)
    except TypeError as exc:
        raise InputError(f"film_model ({model!r}) got bad arguments: {exc}") from exc


def film_parameter(film_minimum, roughness_1, roughness_2):
    """Film parameter (specific film thickness) Λ.

    Parameters
    ----------
    film_minimum : array_like
        Minimum film thickness h_min [m], ``>= 0``.
    roughness_1, roughness_2 : array_like
        RMS roughness R_q of the two surfaces [m], ``>= 0``, not both zero.

    Returns
    -------
    ndarray
        Λ [-].

    Notes
    -----
    .. math:: \\Lambda = \\frac{h_{min}}{\\sqrt{R_{q1}^2 + R_{q2}^2}}

    References
    ----------
    Hamrock B.J., Schmid S.R., Jacobson B.O. (2004) Fundamentals of Fluid Film Lubrication, 2nd ed.,
    Marcel Dekker, ch. 3 (film parameter).
    """
    checks.non_negative("film_minimum", film_minimum, "m")
    checks.non_negative("roughness_1", roughness_1, "m")
    checks.non_negative("roughness_2", roughness_2, "m")
    composite = np.hypot(np.asarray(roughness_1, dtype=float), np.asarray(roughness_2, dtype=float))
    checks.positive("composite roughness sqrt(roughness_1^2 + roughness_2^2)", composite, "m")
    return np.asarray(film_minimum, dtype=float) / composite


_STARVATION = {
    "central": (STARVATION_CENTRAL_COEFF, STARVATION_CENTRAL_EXP, STARVATION_CENTRAL_POWER),
    "minimum": (STARVATION_MIN_COEFF, STARVATION_MIN_EXP, STARVATION_MIN_POWER),
}


def starvation_factor(film_flooded, radius_x, semi_minor, inlet_distance, film: str = "central"):
    """Reduction factor of an EHL film for a starved inlet (Hamrock & Dowson Part IV).

    Parameters
    ----------
    film_flooded : array_like
        Fully-flooded film thickness h (central or minimum, matching ``film``) [m].
    radius_x : array_like
        Effective radius in the rolling direction R_x [m].
    semi_minor : array_like
        Hertzian semi-axis b in the rolling direction [m].
    inlet_distance : array_like
        Distance l_m from the leading edge of the Hertzian contact to the inlet meniscus [m],
        ``>= 0`` (H&D's m - 1 = l_m / b, m measured from the contact centre).
    film : {"central", "minimum"}
        Which film the factor applies to.

    Returns
    -------
    ndarray
        Factor in [0, 1]: 1 when the inlet is fully flooded (f >= f*).

    Notes
    -----
    .. math::

        f = \\frac{l_m}{b},\\quad f^* = C\\left[\\left(\\frac{R_x}{b}\\right)^2 \\frac{h}{R_x}\\right]^{e},
        \\quad \\phi_s = \\min\\left(1, \\frac{f}{f^*}\\right)^{s}

    with (C, e, s) = (3.06, 0.58, 0.29) for the central and (3.34, 0.56, 0.25) for the minimum film.

    References
    ----------
    Hamrock B.J., Dowson D. (1977) Isothermal elastohydrodynamic lubrication of point contacts,
    Part IV—starvation results. J. Lubr. Technol. 99(1):15-23 (DOI not verified here).
    """
    checks.one_of("film", film, _STARVATION)
    checks.non_negative("film_flooded", film_flooded, "m")
    checks.positive("radius_x", radius_x, "m")
    checks.positive("semi_minor", semi_minor, "m")
    checks.non_negative("inlet_distance", inlet_distance, "m")
    coeff, exp, power = _STARVATION[film]
    rx = np.asarray(radius_x, dtype=float)
    b = np.asarray(semi_minor, dtype=float)
    h_dimless = np.asarray(film_flooded, dtype=float) / rx
    f_star = coeff * ((rx / b) ** 2 * h_dimless) ** exp
    f = np.asarray(inlet_distance, dtype=float) / b
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(f_star > 0.0, f / np.where(f_star > 0.0, f_star, 1.0), 1.0)
    return np.minimum(ratio, 1.0) ** power


def thermal_reduction_factor(
    viscosity, temperature_viscosity_coefficient, entrainment_speed, thermal_conductivity
):
    """Inlet shear-heating reduction factor of the isothermal EHL film.

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity η₀ at inlet temperature [Pa·s].
    temperature_viscosity_coefficient : array_like
        β = −(1/η) ∂η/∂T [1/K], ``>= 0``.
    entrainment_speed : array_like
        Mean entrainment speed u [m/s], ``>= 0``.
    thermal_conductivity : array_like
        Lubricant thermal conductivity k [W/(m·K)].

    Returns
    -------
    ndarray
        φ_T in (0, 1]; multiply the isothermal film by it.

    Notes
    -----
    .. math:: \\phi_T = \\frac{3.94}{3.94 + L^{0.62}},\\qquad L = \\frac{\\eta_0 \\beta u^2}{k}

    References
    ----------
    Murch L.E., Wilson W.R.D. (1975) A thermal elastohydrodynamic inlet zone analysis.
    J. Lubr. Technol. 97(2):212-216 (DOI not verified here).
    """
    checks.positive("viscosity", viscosity, "Pa*s")
    checks.non_negative("temperature_viscosity_coefficient", temperature_viscosity_coefficient, "1/K")
    checks.non_negative("entrainment_speed", entrainment_speed, "m/s")
    checks.positive("thermal_conductivity", thermal_conductivity, "W/(m*K)")
    load_thermal = (
        np.asarray(viscosity, dtype=float)
        * np.asarray(temperature_viscosity_coefficient, dtype=float)
        * np.asarray(entrainment_speed, dtype=float) ** 2
        / np.asarray(thermal_conductivity, dtype=float)
    )
    return THERMAL_COEFF / (THERMAL_COEFF + load_thermal**THERMAL_EXP)


def mixed_load_share(film_parameter):
    """Fraction of the contact load carried by asperities in mixed lubrication.

    Parameters
    ----------
    film_parameter : array_like
        Film parameter Λ [-], ``>= 0``.

    Returns
    -------
    ndarray
        f_a in (0, 1]; 1 at Λ = 0 (boundary), → 0 as Λ → ∞ (full film).

    Notes
    -----
    .. math:: f_a = e^{-1.8\\,\\Lambda^{1.2}}

    References
    ----------
    Liu et al. (2022) Lubricants 10:154, eq. (9), doi:10.3390/lubricants10070154 (flange friction
    F_fs = Q_f μ₀ e^(−1.8Λ^1.2); the minus sign is lost in the text extraction and restored here).
    """
    checks.non_negative("film_parameter", film_parameter)
    lam = np.asarray(film_parameter, dtype=float)
    return np.exp(-MIXED_COEFF * lam**MIXED_EXP)
