"""ISO 281:2007 rating life, reliability factor a1, viscosity ratio κ and life modification factor a_ISO.

SI in and out: loads in N, lengths in m, speeds in rad/s, kinematic viscosity in m²/s, lives in
revolutions (ISO 281 quotes millions) or seconds. ISO 281 writes ν1 in mm²/s with n in r/min and Dpw in
mm; the conversion happens inside each function. The load ratings these lives use are in
:mod:`bearingkit.physics.life.iso281`, which re-exports everything here.

References: ISO 281:2007 (``cite("iso281")``) clauses 8–9 and Annex B; Harris & Kotzalas 2007 vol. 2
ch. 8 (``cite("harris2007")``).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics import tables

MM = 1.0e-3  # m per mm: ISO 281 formulas take lengths in mm
MM2_PER_S = 1.0e-6  # m²/s per mm²/s
RPM = 2.0 * np.pi / 60.0  # rad/s per r/min
MILLION = 1.0e6  # ISO 281 lives are in millions of revolutions

#: ISO 281:2007 5.3 / 7.3: life exponent p of L10 = (C/P)^p.
LIFE_EXPONENTS = {"ball": 3.0, "roller": 10.0 / 3.0}

#: ISO 281:2007 9.2, Table 12: a1 is tabulated for 90 % … 99.95 % reliability. Weibull form behind it:
#: a1 = (1 - A1_MIN) (ln R / ln 0.9)^(1/WEIBULL_SLOPE) + A1_MIN with slope 1.5 and minimum life 0.05 L10.
A1_MIN = 0.05
WEIBULL_SLOPE = 1.5
A1_WEIBULL_SCALE = 0.95

#: ISO 281:2007 eq. (26)-(27): reference kinematic viscosity ν1 [mm²/s] with n [r/min], Dpw [mm].
NU1_SLOW = (45000.0, -0.83, -0.5)  # n < 1000 r/min
NU1_FAST = (4500.0, -0.5, -0.5)  # n >= 1000 r/min
NU1_SPEED_SWITCH = 1000.0  # r/min

#: ISO 281:2007 9.3.3: κ above 4 is set to 4; the method does not apply below 0.1.
KAPPA_MIN, KAPPA_MAX = 0.1, 4.0
#: ISO 281:2007 9.3.2: a_ISO is limited to 50.
AISO_MAX = 50.0
#: ISO 281:2007 9.3.2 eq. (16)-(23): κ-band boundaries.
_KAPPA_BANDS = (0.4, 1.0)

#: ISO 281:2007 Annex B (simplified): Cu = C0 / divisor, times (100 mm / Dpw)^exponent above 100 mm.
#: Ball 22: the 1500 MPa fatigue limit against the 4200 MPa C0 pressure, (1500/4200)^3 = 1/21.95.
#: Roller 8.2 and the exponents 0.5 / 0.3 are from memory of the standard [M] — verify.
CU_DIVISOR = {"ball": 22.0, "roller": 8.2}
CU_SIZE_EXPONENT = {"ball": 0.5, "roller": 0.3}
CU_REFERENCE_DIAMETER = 100.0 * MM

_A1 = "iso281_a1.csv"


def basic_rating_life(load_rating, equivalent_load, element_kind):
    """Basic rating life L10 [rev], ISO 281:2007 eq. (8), (13), (14), (15).

    .. math:: L_{10} = 10^6 (C / P)^p,\\qquad p = 3\\ (\\text{ball}),\\ 10/3\\ (\\text{roller})

    Parameters
    ----------
    load_rating : array_like
        C [N], > 0.
    equivalent_load : array_like
        P [N], > 0.
    element_kind : {"ball", "roller"}

    Returns
    -------
    numpy.ndarray
        L10 in revolutions (ISO 281 quotes millions of revolutions: divide by 1e6).
    """
    checks.one_of("element_kind", element_kind, LIFE_EXPONENTS)
    checks.positive("load_rating", load_rating, "N")
    checks.positive("equivalent_load", equivalent_load, "N")
    ratio = np.asarray(load_rating, float) / np.asarray(equivalent_load, float)
    return MILLION * ratio ** LIFE_EXPONENTS[element_kind]


def life_in_seconds(life_revolutions, speed):
    """Life in seconds from life in revolutions at constant speed: t = 2π L / ω (L10h = t / 3600).

    Parameters
    ----------
    life_revolutions : array_like
        Life [rev], >= 0.
    speed : array_like
        Relative ring speed ω [rad/s], > 0.
    """
    checks.non_negative("life_revolutions", life_revolutions, "rev")
    checks.positive("speed", speed, "rad/s")
    return 2.0 * np.pi * np.asarray(life_revolutions, float) / np.asarray(speed, float)


def reliability_factor(reliability):
    """Life modification factor for reliability a1 [-], ISO 281:2007 Table 12 (linear interpolation).

    Parameters
    ----------
    reliability : array_like
        Reliability as a fraction, 0.90 … 0.9995 (outside → InputError).
    """
    pct = np.asarray(reliability, float) * 100.0
    return tables.interp_strict(
        "reliability", pct, tables.column(_A1, "reliability_percent"), tables.column(_A1, "a1"), "%"
    )


def reliability_factor_weibull(reliability):
    """Weibull form behind ISO 281:2007 Table 12 (slope 1.5, minimum life 0.05 L10).

    .. math:: a_1 = 0.95\\,\\bigl(\\ln R / \\ln 0.9\\bigr)^{1/1.5} + 0.05

    Parameters
    ----------
    reliability : array_like
        R as a fraction in [0.9, 1).
    """
    checks.in_range("reliability", reliability, 0.9, 1.0, closed=True)
    r = np.asarray(reliability, float)
    if np.any(r >= 1.0):
        raise InputError(f"reliability ({checks._fmt(r)}) must be below 1")
    return A1_WEIBULL_SCALE * (np.log(r) / np.log(0.9)) ** (1.0 / WEIBULL_SLOPE) + A1_MIN


def reference_viscosity(speed, pitch_diameter):
    """Reference kinematic viscosity ν1 [m²/s], ISO 281:2007 eq. (26)-(27).

    .. math::

        \\nu_1 = 45000\\, n^{-0.83} D_{pw}^{-0.5}\\ (n < 1000\\ \\mathrm{r/min}),\\qquad
        \\nu_1 = 4500\\, n^{-0.5} D_{pw}^{-0.5}\\ (n \\ge 1000\\ \\mathrm{r/min})

    with ν1 in mm²/s, n in r/min and Dpw in mm (converted here).

    Parameters
    ----------
    speed : array_like
        Relative ring speed ω [rad/s], > 0.
    pitch_diameter : array_like
        Dpw [m], > 0.
    """
    checks.positive("speed", speed, "rad/s")
    checks.positive("pitch_diameter", pitch_diameter, "m")
    n = np.asarray(speed, float) / RPM
    d = np.asarray(pitch_diameter, float) / MM
    slow = NU1_SLOW[0] * n ** NU1_SLOW[1] * d ** NU1_SLOW[2]
    fast = NU1_FAST[0] * n ** NU1_FAST[1] * d ** NU1_FAST[2]
    return np.where(n < NU1_SPEED_SWITCH, slow, fast) * MM2_PER_S


def viscosity_ratio(kinematic_viscosity, speed, pitch_diameter):
    """Viscosity ratio κ = ν / ν1 [-], ISO 281:2007 eq. (25).

    Parameters
    ----------
    kinematic_viscosity : array_like
        Operating kinematic viscosity ν [m²/s], > 0.
    speed : array_like
        ω [rad/s].
    pitch_diameter : array_like
        Dpw [m].
    """
    checks.positive("kinematic_viscosity", kinematic_viscosity, "m^2/s")
    return np.asarray(kinematic_viscosity, float) / reference_viscosity(speed, pitch_diameter)


def fatigue_load_limit_estimate(static_rating, pitch_diameter, element_kind):
    """Approximate fatigue load limit Cu [N] from C0, ISO 281:2007 Annex B (simplified method).

    .. math::

        C_u = \\frac{C_0}{k}\\ (D_{pw} \\le 100\\,\\mathrm{mm}),\\qquad
        C_u = \\frac{C_0}{k}\\Bigl(\\frac{100\\,\\mathrm{mm}}{D_{pw}}\\Bigr)^{m}
        \\ (D_{pw} > 100\\,\\mathrm{mm})

    ball k = 22, m = 0.5; roller k = 8.2, m = 0.3. For balls k follows from the 1500 MPa fatigue-limit
    pressure against the 4200 MPa pressure behind C0: (4200/1500)³ = 21.95. The roller constants are
    from memory of the standard and unverified (see module constants).

    Parameters
    ----------
    static_rating : array_like
        C0 [N], > 0.
    pitch_diameter : array_like
        Dpw [m], > 0.
    element_kind : {"ball", "roller"}
    """
    checks.one_of("element_kind", element_kind, CU_DIVISOR)
    checks.positive("static_rating", static_rating, "N")
    checks.positive("pitch_diameter", pitch_diameter, "m")
    d = np.asarray(pitch_diameter, float)
    size = np.where(
        d <= CU_REFERENCE_DIAMETER, 1.0, (CU_REFERENCE_DIAMETER / d) ** CU_SIZE_EXPONENT[element_kind]
    )
    return np.asarray(static_rating, float) / CU_DIVISOR[element_kind] * size


#: ISO 281:2007 9.3.2 eq. (16)-(23): a_ISO = 0.1 [1 - (A - B_band / κ^c_band)^m (e_C Cu / (k P))^q]^(-w)
#: keys: A; B per κ band (0.1-0.4, 0.4-1, 1-4); m, q, w; k (load divisor: 3 thrust ball, 2.5 thrust
#: roller). Ball/roller constants agree with formulas.md D1 [S]; band constants from memory [M], checked for
#: continuity of a_ISO at κ = 0.4 and 1 in the tests.
AISO_MODELS = {
    "radial_ball": dict(A=2.5671, B=(2.2649, 1.9987, 1.9987), m=0.83, q=1.0 / 3.0, w=9.3, k=1.0),
    "thrust_ball": dict(A=2.5671, B=(2.2649, 1.9987, 1.9987), m=0.83, q=1.0 / 3.0, w=9.3, k=3.0),
    "radial_roller": dict(A=1.5859, B=(1.3993, 1.2348, 1.2348), m=1.0, q=0.4, w=9.185, k=1.0),
    "thrust_roller": dict(A=1.5859, B=(1.3993, 1.2348, 1.2348), m=1.0, q=0.4, w=9.185, k=2.5),
}
#: κ exponents of the three bands, common to all bearing kinds (ISO 281:2007 eq. (16)-(23)).
AISO_KAPPA_EXPONENTS = (0.054381, 0.19087, 0.071739)
BEARING_KINDS = tuple(AISO_MODELS)
AISO_FACTOR = 0.1  # ISO 281:2007 eq. (16): a_ISO -> 0.1 as e_C Cu / P -> 0


def life_modification_factor(kappa, contamination_factor, fatigue_load_limit, equivalent_load, bearing_kind):
    """Life modification factor a_ISO [-], ISO 281:2007 9.3.2 eq. (16)-(23).

    .. math::

        a_\\mathrm{ISO} = 0.1\\Bigl[1 - \\bigl(A - B/\\kappa^{c}\\bigr)^{m}
        \\Bigl(\\frac{e_C C_u}{k P}\\Bigr)^{q}\\Bigr]^{-w}

    ball: A = 2.5671, m = 0.83, q = 1/3, w = 9.3; roller: A = 1.5859, m = 1, q = 0.4, w = 9.185;
    B, c by κ band (0.1–0.4, 0.4–1, 1–4) in :data:`AISO_MODELS`, :data:`AISO_KAPPA_EXPONENTS`;
    k = 1 radial, 3 thrust ball, 2.5 thrust roller. κ > 4 is set to 4; κ < 0.1 is outside the method
    (InputError); a_ISO is limited to 50 (also where the bracket reaches 0).

    Parameters
    ----------
    kappa : array_like
        Viscosity ratio κ [-], >= 0.1.
    contamination_factor : array_like
        e_C [-] in [0, 1].
    fatigue_load_limit : array_like
        Cu [N], >= 0.
    equivalent_load : array_like
        P [N], > 0.
    bearing_kind : str
        One of :data:`BEARING_KINDS`.

    Returns
    -------
    numpy.ndarray
        a_ISO in [0.1, 50].
    """
    checks.one_of("bearing_kind", bearing_kind, AISO_MODELS)
    checks.finite("kappa", kappa)
    if np.any(np.asarray(kappa, float) < KAPPA_MIN):
        raise InputError(
            f"kappa ({checks._fmt(kappa)}) must be at least {KAPPA_MIN:g}: ISO 281 a_ISO does not apply below"
        )
    checks.in_range("contamination_factor", contamination_factor, 0.0, 1.0)
    checks.non_negative("fatigue_load_limit", fatigue_load_limit, "N")
    checks.positive("equivalent_load", equivalent_load, "N")
    par = AISO_MODELS[bearing_kind]
    k = np.minimum(np.asarray(kappa, float), KAPPA_MAX)
    band = np.searchsorted(np.asarray(_KAPPA_BANDS), k, side="right")
    b = np.asarray(par["B"])[band]
    c = np.asarray(AISO_KAPPA_EXPONENTS)[band]
    # >= 0 within the method's range (ball: 2.5671 - 2.56688 at κ = 0.1)
    base = np.maximum(par["A"] - b / k**c, 0.0)
    load = np.asarray(contamination_factor, float) * np.asarray(fatigue_load_limit, float)
    load = load / (par["k"] * np.asarray(equivalent_load, float))
    term = base ** par["m"] * load ** par["q"]
    bracket = 1.0 - term
    # bracket -> 0 means a_ISO -> infinity: the standard's cap of 50 applies
    floor = (AISO_FACTOR / AISO_MAX) ** (1.0 / par["w"])
    capped = bracket <= floor
    a = AISO_FACTOR * np.where(capped, 1.0, np.maximum(bracket, floor)) ** (-par["w"])
    return np.where(capped, AISO_MAX, np.minimum(a, AISO_MAX))


def modified_rating_life(life, reliability_factor_, life_modification_factor_):
    """Modified rating life L_nm = a1 a_ISO L10 [same unit as ``life``], ISO 281:2007 eq. (15).

    Parameters
    ----------
    life : array_like
        L10 [rev] (or any life unit), >= 0.
    reliability_factor_ : array_like
        a1 [-], > 0.
    life_modification_factor_ : array_like
        a_ISO [-], > 0.
    """
    checks.non_negative("life", life)
    checks.positive("reliability_factor", reliability_factor_)
    checks.positive("life_modification_factor", life_modification_factor_)
    return np.asarray(reliability_factor_, float) * np.asarray(life_modification_factor_, float) * life
