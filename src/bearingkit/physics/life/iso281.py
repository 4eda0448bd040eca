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
    "basic_rating_life",
    "combine_thrust_rows",
    "dynamic_rating_ball",
    "dynamic_rating_roller",
    "fatigue_load_limit_estimate",
    "fc_radial_ball",
    "fc_radial_roller",
    "fc_thrust_ball",
    "fc_thrust_roller",
    "life_in_seconds",
    "life_modification_factor",
    "modified_rating_life",
    "paired_unit_ratings",
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
_BM = "iso281_bm.csv"


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


#: Paired mounting (ISO 281:2007 5.1.3 ball, 7.1.3 roller; ISO 76:2006 6.1.3, 7.1.3 [clause numbers from
#: memory]): arrangement of two similar single-row angular contact ball or tapered roller bearings that
#: operate as a unit → rows whose X, Y (X0, Y0) apply: back-to-back and face-to-face are one double-row
#: bearing; a tandem set keeps the single-row factors.
PAIRED_UNIT_XY_ROWS = {"DB": 2, "DF": 2, "DT": 1}


def paired_unit_ratings(rating, static_rating, element_kind, n_bearings=2):
    """Basic ratings of similar single-row bearings mounted side by side as a unit (ISO 281:2007 5.1.3,
    7.1.3; ISO 76:2006 6.1.3, 7.1.3).

    .. math:: C_{unit} = n^{0.7} C\\ (\\text{ball}),\\qquad C_{unit} = n^{7/9} C\\ (\\text{roller}),
        \\qquad C_{0,unit} = n\\,C_0

    the i^0.7 and i^(7/9) of ISO 281 eq. (2) and (9) with i = n rows, and ISO 76's i C0: the same law for
    DB, DF (one double-row bearing) and DT (tandem) sets; the arrangement chooses only the X, Y
    (:data:`PAIRED_UNIT_XY_ROWS`).

    Parameters
    ----------
    rating : array_like
        C of one bearing [N].
    static_rating : array_like or None
        C0 of one bearing [N].
    element_kind : {"ball", "roller"}
    n_bearings : int
        Bearings in the set (2 for a pair).

    Returns
    -------
    (numpy.ndarray, numpy.ndarray or None)
        C and C0 of the unit [N].
    """
    checks.one_of("element_kind", element_kind, LIFE_EXPONENTS)
    n = checks.integer("n_bearings", n_bearings)
    if n < 1:
        raise InputError(f"n_bearings ({n}) must be at least 1")
    checks.positive("rating", rating, "N")
    exponent = BALL_ROW_EXP if element_kind == "ball" else ROLLER_ROW_EXP
    c = float(n) ** exponent * np.asarray(rating, float)
    if static_rating is None:
        return c, None
    checks.positive("static_rating", static_rating, "N")
    return c, float(n) * np.asarray(static_rating, float)
