"""Builders of tapered roller bearings: single row (seed 001's 32008J) and paired rows. SI units.

Seed 001 Table 1 is titled "32008J" while §2.3 says "30228J". The numbers decide: rollers of
6.131/6.846 mm × 13.66 mm, Z = 23, cup angle 0.2473 rad (14.2°) fit a 40 × 68 × 19 mm 32008 (a
30228 has ~30 mm rollers on a 140 mm bore). The table gives no pitch diameter; bearingkit takes
d_m = (d + D)/2 = 54 mm of the 32008 envelope (it only enters the friction radii and the
centrifugal force; the load distribution under axial load does not depend on it).
"""

from __future__ import annotations

from bearingkit import checks
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.rows.tapered.row import TaperedRow

#: Seed 001 Table 1 (TRB 32008J) in SI, plus the assumed pitch diameter (see module docstring).
SEED001_GEOMETRY = {
    "n_elements": 23,
    "small_diameter": 6.131e-3,
    "large_diameter": 6.846e-3,
    "effective_length": 13.66e-3,
    "contact_angle_outer": 0.2473,
    "contact_angle_inner": 0.1949,
    "roller_angle": 0.0262,
    "flange_angle": 1.5621,
    "pitch_diameter": 54e-3,  # ASSUMED: (40 + 68)/2 mm of the 32008 envelope
}
#: Seed 001 Table 1 material: E = 2.1e5 N/mm², ν = 0.278 (both bodies).
SEED001_YOUNGS_MODULUS = 2.1e11
SEED001_POISSON_RATIO = 0.278
#: Paired arrangements: directions of (row at −z, row at +z). Back-to-back (DB, "O"): the pressure
#: centres lie outside the rows (wide effective spread, stiff in tilt) and the cone apexes point
#: inwards; face-to-face (DF, "X"): the reverse (Harris & Kotzalas 2006, ch. 1; the same convention
#: as the ball pairs of :mod:`bearingkit.bearings.standard`).
PAIR_ARRANGEMENTS = {"DB": (1, -1), "DF": (-1, 1)}


def seed001_e_reduced() -> float:
    """E′ = E/(1 − ν²) of two steel bodies with seed 001's E and ν [Pa]."""
    return SEED001_YOUNGS_MODULUS / (1.0 - SEED001_POISSON_RATIO**2)


def seed001_row(*, diameter_deviation=None, deviation_model="taylor", speed=0.0, **overrides) -> TaperedRow:
    """The seed 001 row: whole-roller contacts (n_slices = 1, no crowning), Kunert K_a, eq. (4) by default."""
    kw = dict(SEED001_GEOMETRY)
    kw.update(
        e_reduced=seed001_e_reduced(),
        diameter_deviation=diameter_deviation,
        deviation_model=deviation_model,
        speed=speed,
        name="tapered",
    )
    kw.update(overrides)
    return TaperedRow(**kw)


def seed001_bearing(**kwargs) -> BearingModel:
    """Single-row TRB 32008J of seed 001 as a :class:`BearingModel` (keywords go to :func:`seed001_row`)."""
    row = seed001_row(**kwargs)
    return BearingModel(
        (row,), name="TRB 32008J (seed 001)", references=("liu2022", "kunert1961"), metadata={"seed": "001"}
    )


def tapered_pair(
    *, spacing: float, arrangement: str = "DB", name: str = "TRB pair", **row_kwargs
) -> BearingModel:
    """Two identical tapered rows on one inner ring, ``spacing`` apart (row centres at ∓spacing/2).

    Parameters
    ----------
    spacing : float [m]
        Axial distance between the two rows' roller centres (> 0).
    arrangement : str
        ``"DB"`` (back-to-back) or ``"DF"`` (face-to-face), :data:`PAIR_ARRANGEMENTS`.
    **row_kwargs
        :class:`~bearingkit.rows.tapered.row.TaperedRow` fields (``direction``, ``axial_position`` and
        ``name`` are set here).
    """
    checks.positive("spacing", spacing, "m")
    checks.one_of("arrangement", arrangement, PAIR_ARRANGEMENTS)
    for key in ("direction", "axial_position", "name"):
        if key in row_kwargs:
            raise InputError(f"{key} is set by tapered_pair; remove it from the row keywords")
    d_lo, d_hi = PAIR_ARRANGEMENTS[arrangement]
    rows = (
        TaperedRow(direction=d_lo, axial_position=-0.5 * spacing, name="row_a", **row_kwargs),
        TaperedRow(direction=d_hi, axial_position=0.5 * spacing, name="row_b", **row_kwargs),
    )
    meta = {"arrangement": arrangement}
    return BearingModel(rows, name=name, references=("liu2022", "kunert1961"), metadata=meta)


def seed001_pair(*, spacing: float = 0.04, arrangement: str = "DB", **kwargs) -> BearingModel:
    """Two seed-001 rows paired ``arrangement`` (sliced rows allowed through keywords)."""
    kw = dict(SEED001_GEOMETRY)
    kw.update(e_reduced=seed001_e_reduced())
    kw.update(kwargs)
    return tapered_pair(spacing=spacing, arrangement=arrangement, name=f"TRB 32008J pair {arrangement}", **kw)


__all__ = [
    "PAIR_ARRANGEMENTS",
    "SEED001_GEOMETRY",
    "seed001_bearing",
    "seed001_e_reduced",
    "seed001_pair",
    "seed001_row",
    "tapered_pair",
]
