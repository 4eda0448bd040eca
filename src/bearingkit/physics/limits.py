"""Speed and load limits of standard bearings: limiting speed, seal lip speed, requisite minimum load.

SI units at the boundary (m, rad/s, m/s, N, m²/s); the catalogue laws are evaluated in their own units
inside (d_m in mm, n in r/min, ν in mm²/s, kN) because their factors are defined in them.

- **Limiting speed** (kinematic): n_lim = (n d_m)_lim / d_m · f_lub · f_cage, with (n d_m)_lim per bearing
  type from ``data/speed_limits.csv`` (the median n·d_m of SKF's limiting speeds over the sizes of a series,
  :func:`speed_limit_row`), f_lub and f_cage from :data:`LUBRICATION_FACTOR` and :data:`CAGE_FACTOR`.
- **Seal lip speed**: v = ω d_s / 2 at the lip of a rubbing seal (counterface diameter d_s), against
  :data:`SEAL_LIP_SPEED_LIMIT`.
- **Minimum load** (no smearing from sliding of lightly loaded elements): the SKF rule of each type and
  series from ``data/minimum_load.csv`` (:func:`minimum_load`).

References: SKF Group (2018) Rolling bearings PUB BU/P1 17000 EN, "Speeds" and each product chapter's
"Minimum load"; the source and tag of every value are in the CSV files' headers.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks, references
from bearingkit.errors import InputError
from bearingkit.physics import tables

__all__ = [
    "CAGE_FACTOR",
    "LUBRICATION_FACTOR",
    "MATCHED_SET_SPEED_FACTOR",
    "PRECISION_ANGLE_MAX_DEG",
    "SEAL_LIP_SPEED_LIMIT",
    "limiting_speed",
    "minimum_load",
    "minimum_load_row",
    "seal_lip_speed",
    "speed_limit_key",
    "speed_limit_row",
    "speed_limit_types",
]

references.add(
    "skf2018_speeds",
    "SKF Group (2018) Rolling bearings, PUB BU/P1 17000 EN: 'Speeds' (reference and limiting speed) and the "
    "'Minimum load' rules of each product chapter.",
)

_SPEED_FILE = "speed_limits.csv"
_MIN_LOAD_FILE = "minimum_load.csv"
_RAD_S_TO_RPM = 30.0 / np.pi  # [(r/min)/(rad/s)]
_M_TO_MM = 1.0e3

#: Factor on the limiting speed by lubrication method [-]. SKF's limiting speeds hold for oil; grease:
#: the ratio of the grease and oil limiting speeds that NSK prints side by side in its bearing tables
#: (e.g. 6208: 11 000 / 13 000 r/min → 0.85) [M] (from memory; bearingkit's choice for a grease fill).
LUBRICATION_FACTOR = {"oil_bath": 1.0, "oil_jet": 1.0, "oil_air": 1.0, "grease": 0.85}
#: Factor on the limiting speed by cage [-]: the (n d_m) limits are those of each series' standard cage
#: (pressed steel, polyamide or machined brass, all within the spread of the table); a full-complement
#: bearing has its own row in ``speed_limits.csv``. bearingkit's choice, no further source.
CAGE_FACTOR = {"standard": 1.0, "steel": 1.0, "polyamide": 1.0, "brass": 1.0}
#: Highest sliding speed at the lip of a rubbing NBR seal [m/s] [M]: from memory of SKF's limiting speeds of
#: sealed deep groove ball bearings (6205-2RSH 7 500 r/min, 6208-2RS1 5 000 r/min, with d_s ≈ d1 of
#: 31.8 and 49.8 mm → 12.5 and 13.0 m/s); 12 m/s keeps below both. Low-friction (RSL) and non-contact
#: seals run at the open bearing's speed (SKF: "can be operated at the same speeds as shields").
SEAL_LIP_SPEED_LIMIT = 12.0  # [m/s]
#: Factor on the limiting speed of a matched set (DB, DF, DT) of angular contact ball bearings [-]: the
#: median of the matched-set to single-bearing oil limiting speeds NSK prints for every size of its 70 C
#: (data/nsk_70c_limiting_speeds.csv, NSK E1102 B50-B61: 0.79-0.87 over 23 sizes, median 0.8235; 0.800 for
#: grease) — two preloaded bearings side by side run hotter, so NSK rates the set slower.
MATCHED_SET_SPEED_FACTOR = 0.82
#: Largest nominal contact angle of the angular contact bearings that take the precision row of
#: ``speed_limits.csv`` [deg]: the row is NSK's 15° (C) limits. NSK prints precision limits for its 25° (A5)
#: rows too (B47), but about 0.85 of the C ones (a review over the 79 A5 sizes: the C row would overstate
#: them by 15-23 %), so 25° bearings keep their type's row (SKF's 72 BECBP, below NSK's A5: conservative).
PRECISION_ANGLE_MAX_DEG = 15.0


def speed_limit_types() -> tuple[str, ...]:
    """Bearing types with a limiting-speed row in ``data/speed_limits.csv``."""
    return tables.text_column(_SPEED_FILE, "bearing_type")


def speed_limit_key(bearing_type: str, contact_angle_deg: float | None = None) -> str:
    """The row of ``data/speed_limits.csv`` a bearing takes: its type's, or for an angular contact ball
    bearing of nominal contact angle ≤ :data:`PRECISION_ANGLE_MAX_DEG` (a 15° spindle bearing) the precision
    row ``angular_contact_ball_precision`` (NSK's 70 C limits).

    Parameters
    ----------
    bearing_type : str
        An engineering bearing type.
    contact_angle_deg : float, optional [deg]
        Nominal contact angle of the bearing's rows (None: unknown, the type's row).
    """
    if (
        bearing_type == "angular_contact_ball"
        and contact_angle_deg is not None
        and contact_angle_deg <= PRECISION_ANGLE_MAX_DEG
    ):
        return "angular_contact_ball_precision"
    return bearing_type


def speed_limit_row(bearing_type: str) -> dict:
    """The row of ``data/speed_limits.csv`` for ``bearing_type``: n·d_m limit [mm·r/min], tag, note and the
    factor for grease [-] (the row's own where it has one, else :data:`LUBRICATION_FACTOR`'s).

    Parameters
    ----------
    bearing_type : str
        An engineering bearing type (``deep_groove_ball`` …, :func:`speed_limit_types`).
    """
    types = speed_limit_types()
    checks.one_of("bearing_type (speed limits)", bearing_type, types)
    i = types.index(bearing_type)
    grease = tables.column(_SPEED_FILE, "grease_factor")
    return {
        "n_dm_limit": float(tables.column(_SPEED_FILE, "n_dm_limit")[i]),
        "grease_factor": float(np.nan_to_num(grease[i], nan=LUBRICATION_FACTOR["grease"])),
        "tag": tables.text_column(_SPEED_FILE, "tag")[i],
        "note": tables.text_column(_SPEED_FILE, "note")[i],
    }


def limiting_speed(
    n_dm_limit, pitch_diameter, lubrication: str = "oil_bath", cage: str = "standard", grease_factor=None
):
    """Kinematic limiting speed [rad/s].

    .. math:: n_{lim} = \\frac{(n d_m)_{lim}}{d_m} f_{lub} f_{cage}

    Parameters
    ----------
    n_dm_limit : array_like
        (n d_m)_lim [mm·r/min] (:func:`speed_limit_row`).
    pitch_diameter : array_like
        Bearing mean diameter d_m = (d + D)/2 [m].
    lubrication : str
        A key of :data:`LUBRICATION_FACTOR`.
    cage : str
        A key of :data:`CAGE_FACTOR`.
    grease_factor : float, optional [-]
        f_lub for grease of this bearing's row (:func:`speed_limit_row`); None: :data:`LUBRICATION_FACTOR`'s.

    Returns
    -------
    ndarray [rad/s]

    References
    ----------
    SKF (2018) Rolling bearings 17000 EN, "Limiting speed"; the factors' sources at their constants.
    """
    checks.one_of("lubrication", lubrication, LUBRICATION_FACTOR)
    checks.one_of("cage", cage, CAGE_FACTOR)
    checks.positive("n_dm_limit", n_dm_limit, "mm r/min")
    checks.positive("pitch_diameter", pitch_diameter, "m")
    dm_mm = np.asarray(pitch_diameter, dtype=float) * _M_TO_MM
    f_lub = LUBRICATION_FACTOR[lubrication]
    if lubrication == "grease" and grease_factor is not None:
        f_lub = checks.positive("grease_factor", grease_factor, "")
    rpm = np.asarray(n_dm_limit, dtype=float) / dm_mm * f_lub * CAGE_FACTOR[cage]
    return rpm / _RAD_S_TO_RPM


def seal_lip_speed(seal_diameter, speed):
    """Sliding speed at a seal lip v = |ω| d_s / 2 [m/s].

    Parameters
    ----------
    seal_diameter : array_like
        Seal counterface diameter d_s [m].
    speed : array_like
        Speed of the ring the lip rubs on relative to the seal [rad/s].
    """
    checks.positive("seal_diameter", seal_diameter, "m")
    return 0.5 * np.abs(np.asarray(speed, dtype=float)) * np.asarray(seal_diameter, dtype=float)


def minimum_load_row(bearing_type: str, series: str | None = None) -> dict:
    """The minimum-load rule of a type and series (``data/minimum_load.csv``): law, factor, tag.

    The row of the series if the table has one, else the type's ``*`` row.

    Parameters
    ----------
    bearing_type : str
        An engineering bearing type (``deep_groove_ball`` …).
    series : str or None
        Dimension series (``"62"``); None = the type's ``*`` row.
    """
    types = tables.text_column(_MIN_LOAD_FILE, "bearing_type")
    keys = tables.text_column(_MIN_LOAD_FILE, "series")
    rows = [i for i, t in enumerate(types) if t == bearing_type]
    if not rows:
        raise InputError(
            f"bearing_type ({bearing_type!r}) has no minimum-load rule; known: "
            f"{', '.join(dict.fromkeys(types))}"
        )
    exact = [i for i in rows if keys[i] == str(series)]
    i = (exact or [i for i in rows if keys[i] == "*"] or rows)[0]
    return {
        "law": tables.text_column(_MIN_LOAD_FILE, "law")[i],
        "factor": float(tables.column(_MIN_LOAD_FILE, "factor")[i]),
        "tag": tables.text_column(_MIN_LOAD_FILE, "tag")[i],
        "series": keys[i],
    }


def minimum_load(rule: dict, *, C=None, C0=None, viscosity=None, speed=None, pitch_diameter=None):
    """Requisite minimum load [N] by a rule of :func:`minimum_load_row`.

    .. math::

        F_{rm} = k_r \\Big(\\frac{\\nu n}{1000}\\Big)^{2/3}\\Big(\\frac{d_m}{100}\\Big)^2\\ \\mathrm{kN}
        \\quad\\text{(skf_viscous; } \\nu\\ \\mathrm{mm^2/s},\\ n\\ \\mathrm{r/min},\\ d_m\\ \\mathrm{mm)}

        F_{min} = k\\,C \\quad\\text{(share_C)}, \\qquad F_{min} = k\\,C_0 \\quad\\text{(share_C0)}

    Parameters
    ----------
    rule : dict
        ``law`` and ``factor``.
    C, C0 : float [N]
        Basic dynamic / static load rating (share laws).
    viscosity : array_like [m²/s]
        Operating kinematic viscosity (skf_viscous).
    speed : array_like [rad/s]
        Relative ring speed (skf_viscous).
    pitch_diameter : float [m]
        d_m (skf_viscous).

    Returns
    -------
    ndarray [N]

    References
    ----------
    SKF (2018) Rolling bearings 17000 EN, "Minimum load" of each product chapter.
    """
    law, k = rule["law"], rule["factor"]
    if law == "skf_viscous":
        if viscosity is None or speed is None or pitch_diameter is None:
            raise InputError("minimum load (skf_viscous) needs the viscosity, the speed and d_m")
        nu = np.asarray(viscosity, dtype=float) * 1.0e6
        n = np.abs(np.asarray(speed, dtype=float)) * _RAD_S_TO_RPM
        dm = float(pitch_diameter) * _M_TO_MM
        return 1.0e3 * k * (nu * n / 1000.0) ** (2.0 / 3.0) * (dm / 100.0) ** 2
    if law == "share_C":
        if C is None:
            raise InputError("minimum load (share_C) needs the basic dynamic load rating C")
        return np.asarray(k * float(C))
    if law == "share_C0":
        if C0 is None:
            raise InputError("minimum load (share_C0) needs the basic static load rating C0")
        return np.asarray(k * float(C0))
    raise InputError(f"minimum-load law ({law!r}) must be skf_viscous, share_C or share_C0")
