"""Palmgren's friction torque of rolling bearings: a viscous part M0 plus a load part M1.

SI units at the boundary (m, N, rad/s, m²/s; moments in N·m). Inside, Palmgren's formula is evaluated
in its own units — d_m in **mm**, n in **r/min**, ν in **mm²/s** (cSt), loads in **N**, moments in
**N·mm** — because f0's numerical scale (1e-7, 160e-7) belongs to those units.

.. math::

    M = M_0 + M_1, \\qquad
    M_0 = \\begin{cases} 10^{-7} f_0 (\\nu n)^{2/3} d_m^3 & \\nu n \\ge 2000 \\\\
                         160\\cdot10^{-7} f_0 d_m^3 & \\nu n < 2000 \\end{cases}, \\qquad
    M_1 = f_1 P_1 d_m

The two branches of M0 meet (almost) continuously: 2000^{2/3} = 158.7 ≈ 160. Palmgren's low-speed
branch is a constant, so at zero speed this model returns M0(νn < 2000) + M1, not M1 alone (a property
of the published model, kept as published).

f0 (type × lubrication method) and f1 = z (P0/C0)^y with the load P1 (type) are data files
(``data/palmgren_f0.csv``, ``data/palmgren_f1.csv``). The rows of the original types are tagged [M] (from
memory of Harris & Kotzalas 2007 ch. 11 / Palmgren 1959, not verified with the search tool); the spherical
roller and needle rows are [S1] (one public transcription of Schaeffler's type values). Use the results as
indicative and pass ``f0``/``f1`` explicitly when you have the book's values. Types with no source for
their factors are refused (:data:`NOT_COVERED`).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks, references
from bearingkit.errors import InputError
from bearingkit.physics import tables
from bearingkit.physics.life import iso76

references.add(
    "harris2007_ch11",
    "Harris T.A., Kotzalas M.N. (2007) Rolling Bearing Analysis, 5th ed.: Essential Concepts of Bearing "
    "Technology, CRC Press, ch. 11 (friction in rolling bearings: Palmgren's M = M0 + M1, tables of f0, "
    "f1, P1).",
)

# --- unit conversions (exact) and constants ---------------------------------------------------------
M_TO_MM = 1.0e3  # [mm/m]
M2S_TO_MM2S = 1.0e6  # [(mm²/s)/(m²/s)]
RAD_S_TO_RPM = 60.0 / (2.0 * np.pi)  # [(r/min)/(rad/s)]
NMM_TO_NM = 1.0e-3  # [N·m/(N·mm)]
#: Palmgren (1959): coefficient of the viscous torque, valid for ν n ≥ 2000 (SKF units).
M0_COEFF = 1.0e-7  # [-]
#: Palmgren: exponent of ν n in M0.
M0_EXP = 2.0 / 3.0  # [-]
#: Palmgren: low-speed constant, M0 = 160e-7 f0 d_m³ for ν n < 2000.
M0_LOW_COEFF = 160.0e-7  # [-]
#: Threshold of ν n [mm²/s · r/min] between the two branches.
NU_N_THRESHOLD = 2000.0  # [mm²/s · r/min]
#: Spherical roller P1 (Schaeffler, via one public transcription [S1]): coefficients of 1.6 F_a/e and of
#: F_r [1 + 0.6 (F_a/(e F_r))³], and e = 1.5 tan α (ISO 281:2007 Table 8).
SPHERICAL_P1_HIGH = 1.6  # [-]
SPHERICAL_P1_CUBIC = 0.6  # [-]
SPHERICAL_E_FACTOR = 1.5  # [-]

_F0_FILE = "palmgren_f0.csv"
_F1_FILE = "palmgren_f1.csv"

#: Palmgren/Harris lubrication methods of the f0 table.
PALMGREN_LUBRICATIONS = ("grease", "oil_mist", "oil_bath", "oil_jet")

#: Equivalent ISO 76 P0 law per bearing type (for f1 = z (P0/C0)^y of ball bearings).
_P0_TYPE = {
    "deep_groove_ball": "deep_groove_ball",
    "angular_contact_ball": "angular_contact_ball",
    "angular_contact_ball_double": "angular_contact_ball",
    "thrust_ball": "thrust_ball",
}


def _p1_deep_groove(fr, fa, alpha):
    return np.maximum(3.0 * fa - 0.1 * fr, fr)


def _p1_angular(fr, fa, alpha):
    return np.maximum(0.9 * fa / np.tan(alpha) - 0.1 * fr, fr)


def _p1_radial(fr, fa, alpha):
    return fr


def _p1_tapered(fr, fa, alpha):
    return np.maximum(0.8 * fa / np.tan(alpha), fr)


def _p1_thrust(fr, fa, alpha):
    return fa


def _p1_spherical(fr, fa, alpha):
    """Schaeffler's P1 of spherical roller bearings [S1]: 1.6 F_a/e or F_r [1 + 0.6 (F_a/(e F_r))³].

    e = 1.5 tan α (ISO 281:2007 Table 8, double-row radial roller bearings); continuous at F_a/F_r = e.
    """
    e = SPHERICAL_E_FACTOR * np.tan(alpha)
    ratio = fa / np.maximum(e * fr, np.finfo(float).tiny)
    low = fr * (1.0 + SPHERICAL_P1_CUBIC * np.minimum(ratio, 1.0) ** 3)
    return np.where(fa > e * fr, SPHERICAL_P1_HIGH * fa / e, low)


#: Laws of the load P1 [N] of M1 (Harris & Kotzalas 2007 ch. 11 [M]); keys as in ``palmgren_f1.csv``.
P1_LAWS = {
    "deep_groove": _p1_deep_groove,
    "angular": _p1_angular,
    "radial": _p1_radial,
    "tapered": _p1_tapered,
    "thrust": _p1_thrust,
    "spherical": _p1_spherical,
}
#: Laws whose P1 needs the nominal contact angle.
_ANGLE_LAWS = ("angular", "tapered", "spherical")

#: Bearing types whose Palmgren factors no source gave, and what is missing (refused in one line).
NOT_COVERED = {
    "self_aligning_ball": (
        "no source found for the Palmgren factors of self-aligning ball bearings: f0 per lubrication, "
        "f1 = z (P0/C0)^y (z, y) and the load P1 (Harris & Kotzalas 2007 ch. 11 tabulates them; not in a "
        "searchable source, so bearingkit does not guess them)"
    ),
    "spherical_roller_thrust": (
        "no source found for the Palmgren load factor f1 and the load P1 of spherical roller thrust bearings "
        "(Harris & Kotzalas 2007 ch. 11 and Schaeffler's tables give them, neither is in a searchable "
        "source; f0 alone is published: SKF Rolling bearings 2018 p. 919, minimum load F_lub = 20 M0/d with "
        "Palmgren's M0, f0 = 3/3.5/4 (292/293/294, grease or oil bath) and 6/7/8 (oil jet or vertical "
        "shaft), not enough for M = M0 + M1): use the 'skf' model"
    ),
}


def palmgren_types() -> tuple[str, ...]:
    """Bearing types with an f1 row (the Palmgren registry)."""
    return tables.text_column(_F1_FILE, "bearing_type")


def f0_factor(bearing_type: str, lubrication: str) -> float:
    """Palmgren f0 [-] for a bearing type and lubrication method (mean of the tabulated range) [M].

    Parameters
    ----------
    bearing_type : str
        One of :func:`palmgren_types`.
    lubrication : str
        One of :data:`PALMGREN_LUBRICATIONS` (``oil_jet`` = oil jet or oil bath with vertical shaft).
    """
    checks.one_of("bearing_type", bearing_type, palmgren_types())
    checks.one_of("lubrication", lubrication, PALMGREN_LUBRICATIONS)
    types = tables.text_column(_F0_FILE, "bearing_type")
    lubs = tables.text_column(_F0_FILE, "lubrication")
    for i, (t, lub) in enumerate(zip(types, lubs, strict=True)):
        if t == bearing_type and lub == lubrication:
            return 0.5 * float(tables.column(_F0_FILE, "f0_low")[i] + tables.column(_F0_FILE, "f0_high")[i])
    given = [lub for t, lub in zip(types, lubs, strict=True) if t == bearing_type]
    raise InputError(
        f"lubrication ({lubrication!r}) has no f0 for {bearing_type}; tabulated: {', '.join(given)}"
    )


def f1_law(bearing_type: str) -> tuple[float, float, str]:
    """(z, y, p1_law) of ``palmgren_f1.csv`` for a bearing type [M]: f1 = z (P0/C0)^y (Palmgren 1959).

    Parameters
    ----------
    bearing_type : str
        A bearing type of the table (:func:`palmgren_types`).
    """
    checks.one_of("bearing_type", bearing_type, palmgren_types())
    i = palmgren_types().index(bearing_type)
    return (
        float(tables.column(_F1_FILE, "z")[i]),
        float(tables.column(_F1_FILE, "y")[i]),
        tables.text_column(_F1_FILE, "p1_law")[i],
    )


def viscous_moment(f0, nu_n, dm_mm):
    """Palmgren's load-independent moment M0 [N·mm] (SKF/Palmgren units).

    .. math::

        M_0 = 10^{-7} f_0 (\\nu n)^{2/3} d_m^3 \\;(\\nu n \\ge 2000), \\qquad
        M_0 = 160\\cdot10^{-7} f_0 d_m^3 \\;(\\nu n < 2000)

    Parameters
    ----------
    f0 : array_like
        Factor f0 [-].
    nu_n : array_like
        Product ν n [mm²/s · r/min], ≥ 0.
    dm_mm : array_like
        Pitch (mean) diameter d_m [mm].

    References
    ----------
    Palmgren A. (1959) Ball and Roller Bearing Engineering, 3rd ed.; Harris & Kotzalas (2007) ch. 11.
    """
    high = M0_COEFF * f0 * np.maximum(nu_n, NU_N_THRESHOLD) ** M0_EXP * dm_mm**3
    return np.where(nu_n >= NU_N_THRESHOLD, high, M0_LOW_COEFF * f0 * dm_mm**3)


def palmgren_friction_moment(
    bearing_type: str,
    *,
    pitch_diameter,
    speed,
    kinematic_viscosity,
    load_radial=0.0,
    load_axial=0.0,
    lubrication: str = "oil_bath",
    contact_angle=None,
    static_rating=None,
    f0=None,
    f1=None,
) -> dict:
    """Friction torque of a bearing by Palmgren's M = M0 + M1 [N·m].

    .. math:: M = M_0(f_0, \\nu n, d_m) + f_1 P_1 d_m, \\qquad f_1 = z (P_0/C_0)^y \\;\\text{(balls)}

    Parameters
    ----------
    bearing_type : str
        One of :func:`palmgren_types`.
    pitch_diameter : array_like
        d_m [m].
    speed : array_like
        Relative ring speed [rad/s] (sign ignored).
    kinematic_viscosity : array_like
        Operating kinematic viscosity (oil, or base oil of a grease) [m²/s], > 0.
    load_radial, load_axial : array_like
        F_r, F_a [N], ≥ 0.
    lubrication : str
        One of :data:`PALMGREN_LUBRICATIONS` (selects f0).
    contact_angle : array_like or None
        Nominal contact angle α [rad], needed by the angular and tapered P1 laws.
    static_rating : array_like or None
        C0 [N], needed for ball bearings (f1 = z (P0/C0)^y) unless ``f1`` is given.
    f0, f1 : array_like or None
        Override the tabulated factors [-].

    Returns
    -------
    dict
        ``viscous_Nm`` (M0), ``load_Nm`` (M1), ``total_Nm`` [N·m], ``f0``, ``f1`` [-], ``P1_N`` [N].

    References
    ----------
    Palmgren A. (1959) Ball and Roller Bearing Engineering, 3rd ed., SKF Industries; Harris T.A.,
    Kotzalas M.N. (2007) Rolling Bearing Analysis 5th ed., Essential Concepts, ch. 11.
    """
    if bearing_type in NOT_COVERED:
        raise InputError(
            f"bearing_type ({bearing_type!r}): Palmgren model refused: {NOT_COVERED[bearing_type]}"
        )
    checks.one_of("bearing_type", bearing_type, palmgren_types())
    checks.positive("pitch_diameter", pitch_diameter, "m")
    checks.finite("speed", speed, "rad/s")
    checks.positive("kinematic_viscosity", kinematic_viscosity, "m^2/s")
    checks.non_negative("load_radial", load_radial, "N")
    checks.non_negative("load_axial", load_axial, "N")
    z, y, p1_key = f1_law(bearing_type)
    fr = np.asarray(load_radial, dtype=float)
    fa = np.asarray(load_axial, dtype=float)
    if p1_key in _ANGLE_LAWS:
        if contact_angle is None:
            raise InputError(f"contact_angle (None rad) must be given for {bearing_type} (P1 law {p1_key!r})")
        checks.in_range("contact_angle", contact_angle, 0.0, np.pi / 2, "rad", closed=False)
        alpha = np.asarray(contact_angle, dtype=float)
    else:
        alpha = np.asarray(0.0)
    p1 = P1_LAWS[p1_key](fr, fa, alpha)
    if f0 is None:
        f0 = f0_factor(bearing_type, lubrication)
    checks.positive("f0", f0)
    if f1 is None:
        if y == 0.0:
            f1 = z
        else:
            if static_rating is None:
                raise InputError(
                    f"static_rating (None N) must be given for {bearing_type} (f1 = z (P0/C0)^y)"
                )
            checks.positive("static_rating", static_rating, "N")
            a0 = np.pi / 2 if bearing_type == "thrust_ball" else (0.0 if contact_angle is None else alpha)
            p0 = iso76.equivalent_static_load(fr, fa, _P0_TYPE[bearing_type], contact_angle=a0)
            f1 = z * (p0 / np.asarray(static_rating, dtype=float)) ** y
    checks.non_negative("f1", f1)
    dm = np.asarray(pitch_diameter, dtype=float) * M_TO_MM
    n = np.abs(np.asarray(speed, dtype=float)) * RAD_S_TO_RPM
    nu = np.asarray(kinematic_viscosity, dtype=float) * M2S_TO_MM2S
    m0 = viscous_moment(np.asarray(f0, dtype=float), nu * n, dm)
    m1 = np.asarray(f1, dtype=float) * p1 * dm
    m0, m1 = np.broadcast_arrays(m0, m1)
    return {
        "viscous_Nm": m0 * NMM_TO_NM,
        "load_Nm": m1 * NMM_TO_NM,
        "total_Nm": (m0 + m1) * NMM_TO_NM,
        "f0": np.broadcast_to(np.asarray(f0, dtype=float), m0.shape).copy(),
        "f1": np.broadcast_to(np.asarray(f1, dtype=float), m0.shape).copy(),
        "P1_N": np.broadcast_to(p1, m0.shape).copy(),
    }


#: Citation keys of this module.
REFERENCE_KEYS = ("palmgren1959", "harris2007_ch11")

__all__ = [
    "NOT_COVERED",
    "P1_LAWS",
    "PALMGREN_LUBRICATIONS",
    "f0_factor",
    "f1_law",
    "palmgren_friction_moment",
    "palmgren_types",
    "viscous_moment",
]
