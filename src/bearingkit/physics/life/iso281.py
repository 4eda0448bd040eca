"""ISO 281:2007 dynamic load ratings and equivalent dynamic load (rating life: :mod:`.iso281_life`).

All inputs and outputs are SI: lengths in m, loads in N, angles in rad, speeds in rad/s, kinematic
viscosity in m²/s, lives in revolutions (not millions) or seconds. ISO 281 writes its rating formulas in
N and mm (C = b_m f_c … Dw^1.8 with Dw in mm gives C in N) and ν1 in mm²/s with n in r/min and Dpw in
mm; lengths, speeds and viscosities are converted to those units inside each function and the result is
returned in SI. Table look-ups interpolate linearly inside the tabulated range and raise
:class:`~bearingkit.errors.InputError` (naming the field, the value and the range) outside it.

Radial bearings: nominal contact angle 0 <= α <= 45°; thrust bearings: 45° < α <= 90°.

References: ISO 281:2007 (``cite("iso281")``); ISO/TR 1281-1:2021 (explanatory notes, closed forms of
f_c); Lundberg & Palmgren (1947, 1952); Harris & Kotzalas 2007 vol. 2 ch. 8 (``cite("harris2007")``).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics import tables
from bearingkit.physics.life.iso281_life import (  # noqa: F401  (the life half of ISO 281, re-exported)
    AISO_MODELS,
    BEARING_KINDS,
    LIFE_EXPONENTS,
    MILLION,
    MM,
    RPM,
    basic_rating_life,
    fatigue_load_limit_estimate,
    life_in_seconds,
    life_modification_factor,
    modified_rating_life,
    reference_viscosity,
    reliability_factor,
    reliability_factor_weibull,
    viscosity_ratio,
)

__all__ = [
    "AISO_MODELS",
    "BEARING_KINDS",
    "LIFE_EXPONENTS",
    "P_MODELS",
    "basic_rating_life",
    "combine_thrust_rows",
    "dynamic_rating_ball",
    "dynamic_rating_roller",
    "equivalent_dynamic_load",
    "fatigue_load_limit_estimate",
    "fc_radial_ball",
    "fc_radial_roller",
    "fc_thrust_ball",
    "fc_thrust_roller",
    "life_in_seconds",
    "life_modification_factor",
    "modified_rating_life",
    "rating_factor",
    "reference_viscosity",
    "reliability_factor",
    "reliability_factor_weibull",
    "viscosity_ratio",
]

RADIAL_MAX_ANGLE = np.pi / 4  # ISO 281 clause 3: radial bearings α <= 45°

#: ISO 281:2007 5.1.1 / 6.1.1: ball diameter above which the Dw^1.4 form applies [m] (25.4 mm).
BALL_DIAMETER_LIMIT = 25.4 * MM
#: ISO 281:2007 eq. (3), (6): 3.647 = 25.4^(1.8 - 1.4), continuity of the two Dw laws at 25.4 mm.
LARGE_BALL_FACTOR = 3.647
#: Lundberg–Palmgren exponents used by ISO 281:2007 eq. (2)-(7) (ball) and (9)-(11) (roller).
BALL_ROW_EXP, BALL_Z_EXP, BALL_D_EXP, LARGE_BALL_D_EXP = 0.7, 2.0 / 3.0, 1.8, 1.4
ROLLER_ROW_EXP, ROLLER_Z_EXP, ROLLER_D_EXP = 7.0 / 9.0, 3.0 / 4.0, 29.0 / 27.0

#: ISO/TR 1281-1 (Lundberg–Palmgren) constant of the radial roller f_c closed form [N/mm^(...)]; with
#: LAMBDA_NU_RADIAL it reproduces ISO 281:2007 Table 7 (0.01 <= γ <= 0.30).
ROLLER_FC_CONSTANT = 207.9
#: ISO/TR 1281-1: reduction factor λν for edge stresses / non-uniform load of radial roller bearings.
LAMBDA_NU_RADIAL = 0.83
#: ISO/TR 1281-1: ratio factor of the rotating to stationary ring rating for line contact.
ROLLER_RING_RATIO = 1.04
ROLLER_GAMMA_RANGE = (0.01, 0.30)  # range of ISO 281:2007 Table 7

#: Lundberg–Palmgren line-contact raceway capacity constant [N, mm units] (Lundberg & Palmgren 1952;
#: ISO/TR 1281-1): Q_c = 552 (1∓γ)^(29/27) (1±γ)^(-1/4) (γ/cos α)^(2/9) Dwe^(29/27) Lwe^(7/9) Z^(-1/4).
#: The radial constant above is 207.9 = 0.37663 · 552 (0.37663: Stribeck integral of the radial load
#: zone, ε = 0.5); a thrust row under centric load has equal roller loads, so the full 552 applies.
LP_LINE_CONSTANT = 552.0
#: ISO/TR 1281-1: λ of thrust roller bearings (edge stresses, non-uniform load) [-]; the ISO/TS 16281
#: value for thrust rows (``iso16281.LAMBDA_NU["thrust"]``).
LAMBDA_THRUST_ROLLER = 0.73
#: ISO/TR 1281-1: η = 1 − 0.15 sin α, the reduction for the spin of thrust rollers on their washers [-].
#: The form is from memory of the TR [M]; its α = 90° value η = 0.85 is confirmed by Lubricants 2025,
#: 13(2), 65 (doi:10.3390/lubricants13020065: "η = 0.85" for cylindrical roller thrust bearings).
ETA_THRUST_ROLLER = 0.15
#: γ range of the thrust roller f_c [-] (taken as the range of the radial roller table, ISO 281 Table 7;
#: Table 9 itself could not be checked): outside it f_c raises InputError, never extrapolates.
THRUST_ROLLER_GAMMA_RANGE = (0.01, 0.30)

_FC_RADIAL_BALL = "iso281_fc_radial_ball.csv"
_FC_THRUST_BALL = "iso281_fc_thrust_ball.csv"
_FC_THRUST_BALL_90 = "iso281_fc_thrust_ball_90.csv"
_XY_RADIAL = "iso281_xy_radial_ball.csv"
_XY_ANGULAR = "iso281_xy_angular_ball.csv"
_BM = "iso281_bm.csv"

#: ISO 281:2007 Table 3: X of radial contact groove ball bearings for Fa/Fr > e (single, double row).
X_DEEP_GROOVE_SINGLE = 0.56
X_DEEP_GROOVE_DOUBLE = 0.78
#: Thrust ball bearings, single direction, ISO 281:2007 Table 6 [M]: α [deg], e, X (Fa/Fr > e), Y = 1.
_THRUST_BALL_XE = np.array([[45.0, 1.25, 0.66], [60.0, 2.17, 0.92], [75.0, 4.67, 1.66]])
#: ISO 281:2007 7.2 / 8.2: e = 1.5 tan α for radial and thrust roller bearings (and self-aligning ball).
E_TAN_FACTOR = 1.5


def _is_90(alpha):
    return np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)


def rating_factor(bearing_type: str) -> float:
    """Rating factor b_m [-] of ISO 281:2007 Table 1 for ``bearing_type`` (see ``iso281_bm.csv``).

    Parameters
    ----------
    bearing_type : str
        A bearing type of the table (``"deep_groove_ball"``, ``"cylindrical_roller"`` …).
    """
    names = tables.text_column(_BM, "bearing_type")
    checks.one_of("bearing_type", bearing_type, names)
    return float(tables.column(_BM, "bm")[names.index(bearing_type)])


def fc_radial_ball(gamma):
    """Factor f_c [-] (N, mm units) of radial and angular contact groove ball bearings, ISO 281:2007 Table 2.

    Parameters
    ----------
    gamma : array_like
        γ = Dw cos α / Dpw [-], tabulated 0.01 … 0.40 (column 1 of Table 2; linear interpolation).
    """
    t = _FC_RADIAL_BALL
    return tables.interp_strict("gamma", gamma, tables.column(t, "gamma"), tables.column(t, "fc"))


def fc_thrust_ball(gamma, contact_angle):
    """Factor f_c [-] of thrust ball bearings, ISO 281:2007 Table 4.

    α = 90°: column "90°" with γ = Dw/Dpw (0.01 … 0.34 shipped). 45° <= α <= 75°: linear interpolation in γ
    within the columns 45°, 60°, 75° (γ = Dw cos α / Dpw), then linear in α between the neighbouring
    columns; γ must lie inside both neighbouring columns. Other angles raise InputError.

    Parameters
    ----------
    gamma : array_like
        γ [-] as defined above.
    contact_angle : array_like
        α [rad].
    """
    g, alpha = np.broadcast_arrays(np.asarray(gamma, float), np.asarray(contact_angle, float))
    out = np.empty_like(g)
    is_90 = _is_90(alpha)
    if np.any(is_90):
        t90 = _FC_THRUST_BALL_90
        out[is_90] = tables.interp_strict(
            "gamma", g[is_90], tables.column(t90, "gamma"), tables.column(t90, "fc")
        )
    rest = ~is_90
    if np.any(rest):
        deg = np.degrees(alpha[rest])
        checks.in_range("contact_angle", deg, 45.0, 75.0, "deg")
        angles = np.array([45.0, 60.0, 75.0])
        gp = tables.column(_FC_THRUST_BALL, "gamma")
        cols = [tables.column(_FC_THRUST_BALL, f"fc_{a:.0f}") for a in angles]
        lo = np.clip(np.searchsorted(angles, deg, side="right") - 1, 0, 1)
        w = (deg - angles[lo]) / (angles[lo + 1] - angles[lo])
        f_lo = np.empty_like(deg)
        f_hi = np.empty_like(deg)
        for k in (0, 1):  # two column pairs, not a loop over elements
            m = lo == k
            if np.any(m):
                f_lo[m] = tables.interp_strict("gamma", g[rest][m], gp, cols[k])
                f_hi[m] = tables.interp_strict("gamma", g[rest][m], gp, cols[k + 1])
        out[rest] = (1.0 - w) * f_lo + w * f_hi
    return out


def fc_radial_roller(gamma):
    """Factor f_c [-] of radial roller bearings, closed form of ISO/TR 1281-1 behind ISO 281:2007 Table 7.

    .. math::

        f_c = 207.9\\,\\lambda\\nu\\,\\frac{\\gamma^{2/9}(1-\\gamma)^{29/27}}{(1+\\gamma)^{1/4}}
        \\Bigl\\{1 + \\Bigl[1.04\\Bigl(\\frac{1-\\gamma}{1+\\gamma}\\Bigr)^{143/108}
        \\Bigr]^{9/2}\\Bigr\\}^{-2/9},
        \\quad \\lambda\\nu = 0.83

    The ISO 281 table itself was not available verbatim; this closed form is the Lundberg–Palmgren
    expression of ISO/TR 1281-1 and is consistent with the ISO/TS 16281 raceway ratings (0.378 · 550 =
    207.9). Restricted to the table's range 0.01 <= γ <= 0.30.

    Parameters
    ----------
    gamma : array_like
        γ = Dwe cos α / Dpw [-].
    """
    checks.in_range("gamma", gamma, *ROLLER_GAMMA_RANGE)
    g = np.asarray(gamma, dtype=float)
    ratio = ROLLER_RING_RATIO * ((1.0 - g) / (1.0 + g)) ** (143.0 / 108.0)
    return (
        ROLLER_FC_CONSTANT
        * LAMBDA_NU_RADIAL
        * g ** (2.0 / 9.0)
        * (1.0 - g) ** (29.0 / 27.0)
        / (1.0 + g) ** 0.25
        * (1.0 + ratio**4.5) ** (-2.0 / 9.0)
    )


def fc_thrust_roller(gamma, contact_angle):
    """Factor f_c [-] (N, mm) of thrust roller bearings: the ISO/TR 1281-1 closed form behind ISO 281 Table 9.

    .. math::

        f_c = 552\\,\\lambda\\eta\\,\\frac{\\gamma^{2/9}(1-\\gamma)^{29/27}}{(1+\\gamma)^{1/4}}
        \\Bigl\\{1 + \\Bigl(\\frac{1-\\gamma}{1+\\gamma}\\Bigr)^{143/24}\\Bigr\\}^{-2/9}
        \\ (45° < \\alpha < 90°,\\ \\gamma = D_{we}\\cos\\alpha / D_{pw}),\\qquad
        f_c = 552\\,\\lambda\\eta\\, 2^{-2/9}\\gamma^{2/9}
        \\ (\\alpha = 90°,\\ \\gamma = D_{we}/D_{pw})

    with λ = 0.73 and η = 1 − 0.15 sin α. Derivation (Lundberg & Palmgren 1952): under a centric axial load
    every roller carries Q = C_a/(Z sin α); the two washers' raceway capacities Q_ci, Q_ce (constant 552,
    ratio Q_ci/Q_ce = ((1−γ)/(1+γ))^(143/108)) combine as (Q/Q_ci)^(9/2) + (Q/Q_ce)^(9/2) = 1, and
    (L_we cos α)^(7/9) tan α of ISO 281 eq. (11) absorbs the (γ/cos α)^(2/9) sin α of Q_c. At α = 90° the
    washers are flat in the rolling direction (Q_ci = Q_ce, factor 2^(−2/9)); the α = 90° form is the
    limit α → 90° of the other at fixed D_we/D_pw. ISO 281 Table 9 was not available to check the
    numbers; η is marked unverified in :data:`ETA_THRUST_ROLLER`.

    Parameters
    ----------
    gamma : array_like
        γ [-] as defined above, 0.01 … 0.30 (:data:`THRUST_ROLLER_GAMMA_RANGE`; outside → InputError).
    contact_angle : array_like
        α [rad], π/4 < α <= π/2.

    Returns
    -------
    numpy.ndarray
        f_c [-] (to be multiplied by b_m, ISO 281 eq. (11)-(12)).

    References
    ----------
    ISO 281:2007 clause 8.1, Table 9; ISO/TR 1281-1; Lundberg & Palmgren (1952).
    """
    checks.in_range("gamma", gamma, *THRUST_ROLLER_GAMMA_RANGE)
    checks.in_range("contact_angle", contact_angle, 0.0, np.pi / 2, "rad")
    g, alpha = np.broadcast_arrays(np.asarray(gamma, float), np.asarray(contact_angle, float))
    if np.any(alpha <= RADIAL_MAX_ANGLE):
        raise InputError(f"contact_angle ({checks._fmt(alpha)} rad) must exceed pi/4 for a thrust bearing")
    is_90 = _is_90(alpha)
    eta = 1.0 - ETA_THRUST_ROLLER * np.sin(alpha)
    base = LP_LINE_CONSTANT * LAMBDA_THRUST_ROLLER * eta * g ** (2.0 / 9.0)
    ratio = ((1.0 - g) / (1.0 + g)) ** (143.0 / 108.0)
    angular = (1.0 - g) ** (29.0 / 27.0) / (1.0 + g) ** 0.25 * (1.0 + ratio**4.5) ** (-2.0 / 9.0)
    return base * np.where(is_90, 2.0 ** (-2.0 / 9.0), angular)


def _check_common(element_diameter, pitch_diameter, contact_angle, n_elements, n_rows, thrust):
    checks.positive("element_diameter", element_diameter, "m")
    checks.positive("pitch_diameter", pitch_diameter, "m")
    checks.greater("pitch_diameter", pitch_diameter, "element_diameter", element_diameter, "m")
    checks.positive("n_elements", n_elements)
    checks.positive("n_rows", n_rows)
    alpha = np.asarray(contact_angle, dtype=float)
    if thrust:
        checks.in_range("contact_angle", alpha, 0.0, np.pi / 2, "rad")
        if np.any(alpha <= RADIAL_MAX_ANGLE):
            raise InputError(
                f"contact_angle ({checks._fmt(alpha)} rad) must exceed pi/4 for a thrust bearing"
            )
    else:
        checks.in_range("contact_angle", alpha, 0.0, RADIAL_MAX_ANGLE, "rad")
    return alpha


def dynamic_rating_ball(
    element_diameter,
    pitch_diameter,
    contact_angle,
    n_elements,
    n_rows=1,
    bearing_type="deep_groove_ball",
    fc=None,
):
    """Basic dynamic load rating C [N] of a ball bearing, ISO 281:2007 eq. (2)-(3) and (5)-(7).

    .. math::

        C_r = b_m f_c (i\\cos\\alpha)^{0.7} Z^{2/3} D_w^{1.8}\\quad (D_w \\le 25.4\\,\\mathrm{mm}),\\qquad
        C_r = 3.647\\, b_m f_c (i\\cos\\alpha)^{0.7} Z^{2/3} D_w^{1.4}\\quad (D_w > 25.4\\,\\mathrm{mm})

        C_a = b_m f_c (\\cos\\alpha)^{0.7}\\tan\\alpha\\, Z^{2/3} D_w^{1.8}\\ (\\alpha\\ne 90°),\\qquad
        C_a = b_m f_c Z^{2/3} D_w^{1.8}\\ (\\alpha = 90°)

    (thrust with Dw > 25.4 mm: 3.647 · … · Dw^1.4), with Dw in mm and C in N (converted here).
    The multi-row law is the factor i^0.7 (radial); for thrust bearings Z counts the balls of one row
    (combine rows with :func:`combine_thrust_rows`).

    Parameters
    ----------
    element_diameter : array_like
        Ball diameter Dw [m].
    pitch_diameter : array_like
        Pitch diameter Dpw [m], > Dw.
    contact_angle : array_like
        α [rad]; radial types 0 … π/4, ``thrust_ball`` (π/4, π/2].
    n_elements : array_like
        Balls per row Z [-].
    n_rows : array_like
        Rows i [-] (radial only).
    bearing_type : str
        A ball type of ISO 281 Table 1 (``rating_factor``); ``"thrust_ball"`` selects the thrust formulas.
    fc : array_like, optional
        f_c given explicitly (required for self-aligning and double-row deep groove bearings, whose
        Table 2 columns are not shipped); replaces the table look-up.

    Returns
    -------
    numpy.ndarray
        C_r or C_a [N].

    References
    ----------
    ISO 281:2007 clauses 5.1 and 6.1, Tables 1, 2 and 4.
    """
    bm = rating_factor(bearing_type)
    if not bearing_type.endswith("_ball"):
        raise InputError(
            f"bearing_type ({bearing_type!r}) must be a ball bearing type for dynamic_rating_ball"
        )
    thrust = bearing_type == "thrust_ball"
    alpha = _check_common(element_diameter, pitch_diameter, contact_angle, n_elements, n_rows, thrust)
    dw = np.asarray(element_diameter, float)
    dpw = np.asarray(pitch_diameter, float)
    is_90 = _is_90(alpha)
    cos_a = np.where(is_90, 0.0, np.cos(alpha))
    if fc is None:
        double_deep_groove = bearing_type == "deep_groove_ball" and np.any(np.asarray(n_rows) > 1)
        if bearing_type == "self_aligning_ball" or double_deep_groove:
            raise InputError(
                f"fc must be given for bearing_type {bearing_type!r} with n_rows {n_rows}: "
                "its ISO 281 Table 2 column is not shipped"
            )
        gamma = np.where(is_90, dw / dpw, dw * cos_a / dpw)
        fc = fc_thrust_ball(gamma, alpha) if thrust else fc_radial_ball(gamma)
    else:
        checks.positive("fc", fc)
    dw_mm = dw / MM
    size = np.where(dw <= BALL_DIAMETER_LIMIT, dw_mm**BALL_D_EXP, LARGE_BALL_FACTOR * dw_mm**LARGE_BALL_D_EXP)
    z_term = np.asarray(n_elements, float) ** BALL_Z_EXP
    if thrust:
        angle_term = np.where(is_90, 1.0, cos_a**BALL_ROW_EXP * np.tan(np.where(is_90, 0.0, alpha)))
    else:
        angle_term = (np.asarray(n_rows, float) * cos_a) ** BALL_ROW_EXP
    return bm * np.asarray(fc, float) * angle_term * z_term * size


def dynamic_rating_roller(
    element_diameter,
    effective_length,
    pitch_diameter,
    contact_angle,
    n_elements,
    n_rows=1,
    bearing_type="cylindrical_roller",
    fc=None,
):
    """Basic dynamic load rating C [N] of a roller bearing, ISO 281:2007 eq. (9) and (11)-(12).

    .. math::

        C_r = b_m f_c (i L_{we}\\cos\\alpha)^{7/9} Z^{3/4} D_{we}^{29/27},\\qquad
        C_a = b_m f_c (L_{we}\\cos\\alpha)^{7/9}\\tan\\alpha\\, Z^{3/4} D_{we}^{29/27}
        \\ (\\alpha\\ne 90°),\\qquad
        C_a = b_m f_c L_{we}^{7/9} Z^{3/4} D_{we}^{29/27}\\ (\\alpha = 90°)

    lengths in mm, C in N (converted here). Radial f_c from :func:`fc_radial_roller`, thrust f_c from
    :func:`fc_thrust_roller` (γ = Dwe/Dpw at α = 90°, Dwe cos α/Dpw otherwise).

    Parameters
    ----------
    element_diameter : array_like
        Roller diameter Dwe [m].
    effective_length : array_like
        Effective roller length Lwe [m].
    pitch_diameter : array_like
        Pitch diameter Dpw [m], > Dwe.
    contact_angle : array_like
        α [rad]; radial types 0 … π/4, thrust types (π/4, π/2].
    n_elements : array_like
        Rollers per row Z [-].
    n_rows : array_like
        Rows i [-] (radial only).
    bearing_type : str
        A roller type of ISO 281 Table 1; names starting with ``"thrust_"`` select the thrust formulas.
    fc : array_like, optional
        f_c given explicitly; replaces the look-up.

    Returns
    -------
    numpy.ndarray
        C_r or C_a [N].
    """
    bm = rating_factor(bearing_type)
    if not bearing_type.endswith("_roller") and "needle" not in bearing_type:
        raise InputError(
            f"bearing_type ({bearing_type!r}) must be a roller bearing type for dynamic_rating_roller"
        )
    thrust = bearing_type.startswith("thrust_")
    alpha = _check_common(element_diameter, pitch_diameter, contact_angle, n_elements, n_rows, thrust)
    checks.positive("effective_length", effective_length, "m")
    dwe = np.asarray(element_diameter, float)
    is_90 = _is_90(alpha)
    cos_a = np.where(is_90, 0.0, np.cos(alpha))
    if fc is None:
        dpw = np.asarray(pitch_diameter, float)
        if thrust:
            fc = fc_thrust_roller(np.where(is_90, dwe / dpw, dwe * cos_a / dpw), alpha)
        else:
            fc = fc_radial_roller(dwe * cos_a / dpw)
    else:
        checks.positive("fc", fc)
    lwe_mm = np.asarray(effective_length, float) / MM
    size = (dwe / MM) ** ROLLER_D_EXP * np.asarray(n_elements, float) ** ROLLER_Z_EXP
    if thrust:
        tan_a = np.tan(np.where(is_90, 0.0, alpha))
        length_term = np.where(is_90, lwe_mm**ROLLER_ROW_EXP, (lwe_mm * cos_a) ** ROLLER_ROW_EXP * tan_a)
    else:
        length_term = (np.asarray(n_rows, float) * lwe_mm * cos_a) ** ROLLER_ROW_EXP
    return bm * np.asarray(fc, float) * length_term * size


# --- equivalent dynamic load ----------------------------------------------------------------------------


def _ratio(fr, fa):
    # Fa/Fr with Fr = 0 treated as an infinite ratio
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(fr > 0, fa / np.where(fr > 0, fr, 1.0), np.inf)


def _p_deep_groove(fr, fa, alpha, n_rows, static_rating, f0):
    if static_rating is None or f0 is None:
        raise InputError(
            "static_rating and f0 must be given for bearing_type 'deep_groove_ball' (ISO 281 Table 3)"
        )
    checks.positive("static_rating", static_rating, "N")
    checks.positive("f0", f0, "MPa")
    t = _XY_RADIAL
    rel = np.asarray(f0, float) * fa / np.asarray(static_rating, float)
    has_axial = fa > 0
    x = tables.column(t, "f0_fa_c0r")
    rel_in = np.where(has_axial, rel, x[0])

    def col(name):
        return tables.interp_strict("relative_axial_load_f0_Fa_C0r", rel_in, x, tables.column(t, name))

    small = _ratio(fr, fa) <= col("e")
    if n_rows == 1:
        p = np.where(small, fr, X_DEEP_GROOVE_SINGLE * fr + col("y_single_gt") * fa)
    else:
        p = np.where(small, fr + col("y_double_le") * fa, X_DEEP_GROOVE_DOUBLE * fr + col("y_double_gt") * fa)
    return np.where(has_axial, p, fr)


def _p_angular(fr, fa, alpha, n_rows, static_rating, f0):
    t = _XY_ANGULAR
    deg = np.degrees(alpha)
    a = tables.column(t, "alpha_deg")

    def col(name):
        return tables.interp_strict("contact_angle", deg, a, tables.column(t, name), "deg")

    small = _ratio(fr, fa) <= col("e")
    if n_rows == 1:
        return np.where(small, fr, col("x_single_gt") * fr + col("y_single_gt") * fa)
    return np.where(small, fr + col("y_double_le") * fa, col("x_double_gt") * fr + col("y_double_gt") * fa)


def _p_self_aligning(fr, fa, alpha, n_rows, static_rating, f0):
    # ISO 281:2007 Table 3, self-aligning ball bearings (double row): e = 1.5 tan α [M]
    checks.positive("contact_angle", alpha, "rad")
    cot = 1.0 / np.tan(alpha)
    small = _ratio(fr, fa) <= E_TAN_FACTOR * np.tan(alpha)
    return np.where(small, fr + 0.42 * cot * fa, 0.65 * fr + 0.65 * cot * fa)


def _p_radial_roller(fr, fa, alpha, n_rows, static_rating, f0):
    zero = alpha == 0.0
    if np.any(zero & (fa > 0)):
        raise InputError(
            "load_axial must be 0 for a radial roller bearing with contact_angle 0 (ISO 281 7.2.2)"
        )
    a = np.where(zero, np.pi / 4, alpha)
    cot = 1.0 / np.tan(a)
    small = _ratio(fr, fa) <= E_TAN_FACTOR * np.tan(a)
    if n_rows == 1:
        p = np.where(small, fr, 0.4 * fr + 0.4 * cot * fa)
    else:
        p = np.where(small, fr + 0.45 * cot * fa, 0.67 * fr + 0.67 * cot * fa)
    return np.where(zero, fr, p)


def _p_thrust(fr, fa, alpha, ball: bool):
    if np.any(alpha <= RADIAL_MAX_ANGLE):
        raise InputError(f"contact_angle ({checks._fmt(alpha)} rad) must exceed pi/4 for a thrust bearing")
    is_90 = _is_90(alpha)
    if np.any(is_90 & (fr > 0)):
        raise InputError(
            "load_radial must be 0 for a thrust bearing with contact_angle pi/2 (ISO 281 6.2, 8.2)"
        )
    a = np.where(is_90, np.pi / 3, alpha)
    if ball:
        deg = np.where(is_90, 60.0, np.degrees(a))
        checks.in_range("contact_angle", deg, 45.0, 75.0, "deg")
        e = np.interp(deg, _THRUST_BALL_XE[:, 0], _THRUST_BALL_XE[:, 1])
        x = np.interp(deg, _THRUST_BALL_XE[:, 0], _THRUST_BALL_XE[:, 2])
    else:
        e = E_TAN_FACTOR * np.tan(a)
        x = np.tan(a)
    if np.any(~is_90 & (_ratio(fr, fa) <= e)):
        raise InputError(
            "load_axial/load_radial must exceed e for a single-direction thrust bearing with "
            "contact_angle < pi/2 (ISO 281 6.2, 8.2)"
        )
    return np.where(is_90, fa, x * fr + fa)


#: Equivalent dynamic load laws by bearing type (ISO 281:2007 5.2, 6.2, 7.2, 8.2).
P_MODELS = {
    "deep_groove_ball": _p_deep_groove,
    "angular_contact_ball": _p_angular,
    "self_aligning_ball": _p_self_aligning,
    "radial_roller": _p_radial_roller,
    "thrust_ball": lambda fr, fa, a, n, c0, f0: _p_thrust(fr, fa, a, True),
    "thrust_roller": lambda fr, fa, a, n, c0, f0: _p_thrust(fr, fa, a, False),
}


def equivalent_dynamic_load(
    load_radial, load_axial, bearing_type, contact_angle=0.0, n_rows=1, static_rating=None, f0=None
):
    """Dynamic equivalent load P [N], ISO 281:2007 clauses 5.2, 6.2, 7.2 and 8.2.

    .. math:: P = X F_r + Y F_a

    - ``deep_groove_ball``: e, Y from Table 3 as functions of f0 Fa/C0r (0.172 … 6.89; outside → error);
      Fa/Fr <= e: X = 1, Y = 0 (single row) or Y from the double-row column; Fa/Fr > e: X = 0.56 single
      row, 0.78 double row.
    - ``angular_contact_ball``: Table 3 rows α = 20° … 45°, linear interpolation in α.
    - ``self_aligning_ball``: e = 1.5 tan α; X = 1, Y = 0.42 cot α or X = 0.65, Y = 0.65 cot α.
    - ``radial_roller``: α = 0 → P = Fr (Fa must be 0); else e = 1.5 tan α, single row X = 0.4,
      Y = 0.4 cot α above e; double row X = 1, Y = 0.45 cot α / X = 0.67, Y = 0.67 cot α.
    - ``thrust_ball``/``thrust_roller``: α = 90° → P = Fa (Fr must be 0); else single direction with
      Fa/Fr > e: P = X Fr + Fa (ball X, e from Table 6 at 45°, 60°, 75°; roller X = tan α, e = 1.5 tan α).

    Parameters
    ----------
    load_radial, load_axial : array_like
        Fr, Fa [N], >= 0.
    bearing_type : str
        One of :data:`P_MODELS`.
    contact_angle : array_like
        α [rad].
    n_rows : int
        1 or 2.
    static_rating : array_like, optional
        C0r [N] (deep groove ball bearings).
    f0 : array_like, optional
        f0 [MPa] of ISO 76 (deep groove ball bearings).

    Returns
    -------
    numpy.ndarray
        P [N].
    """
    checks.one_of("bearing_type", bearing_type, P_MODELS)
    checks.non_negative("load_radial", load_radial, "N")
    checks.non_negative("load_axial", load_axial, "N")
    limit = np.pi / 2 if bearing_type.startswith("thrust") else RADIAL_MAX_ANGLE
    checks.in_range("contact_angle", contact_angle, 0.0, limit, "rad")
    n_rows = checks.integer("n_rows", n_rows)
    if n_rows > 2:
        raise InputError(f"n_rows ({n_rows}) must be 1 or 2 for ISO 281 equivalent dynamic load")
    fr, fa, alpha = np.broadcast_arrays(
        np.asarray(load_radial, float), np.asarray(load_axial, float), np.asarray(contact_angle, float)
    )
    return np.asarray(P_MODELS[bearing_type](fr, fa, alpha, n_rows, static_rating, f0), dtype=float)


def combine_thrust_rows(n_elements, ratings, element_kind, effective_length=None):
    """Rating of a multi-row thrust bearing from its rows, ISO 281:2007 eq. (7) and (12).

    .. math::

        C_a = (Z_1 + \\dots + Z_n)\\Bigl[\\sum_k (Z_k / C_{ak})^{10/3}\\Bigr]^{-3/10}\\ (\\text{ball}),\\qquad
        C_a = \\Bigl(\\sum_k Z_k L_{wek}\\Bigr)\\Bigl[\\sum_k (Z_k L_{wek} / C_{ak})^{9/2}\\Bigr]^{-2/9}
        \\ (\\text{roller})

    Parameters
    ----------
    n_elements : array_like
        Z_k per row [-], rows on the last axis.
    ratings : array_like
        C_ak per row [N], rows on the last axis.
    element_kind : {"ball", "roller"}
    effective_length : array_like, optional
        L_wek per row [m] (roller only).
    """
    checks.one_of("element_kind", element_kind, LIFE_EXPONENTS)
    checks.positive("n_elements", n_elements)
    checks.positive("ratings", ratings, "N")
    z = np.asarray(n_elements, float)
    c = np.asarray(ratings, float)
    if element_kind == "ball":
        return z.sum(axis=-1) * ((z / c) ** (10.0 / 3.0)).sum(axis=-1) ** (-0.3)
    if effective_length is None:
        raise InputError("effective_length must be given to combine thrust roller rows")
    checks.positive("effective_length", effective_length, "m")
    zl = z * np.asarray(effective_length, float)
    return zl.sum(axis=-1) * ((zl / c) ** 4.5).sum(axis=-1) ** (-2.0 / 9.0)
