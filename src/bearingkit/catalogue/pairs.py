"""Matched pairs from a designation (``7014 C DB``, ``7014 CD/P4ADBB``, ``30206 DF``): arrangement, row
spacing and the preload force of a preload class. SI units (m, N).

**Preload classes.** The makers name their classes (SKF A/B/C/D, GA/GB/GC; FAG UL/UM/UH; NSK EL/L/M/H:
:mod:`.suffixes`) but print the forces per bearing in their product tables; SKF says the values "are
not standardized" (skf.com, super-precision bearings, bearing preload). bearingkit has no such table,
so a class becomes a force by a rule on the single bearing's basic dynamic load rating C,
F_pr = k · C, with k of :data:`PRELOAD_FRACTIONS` — a rule of thumb [from memory], not a maker's
number: every result of a class says so, and ``preload = "480 N"`` (``--preload 480N``) takes the
force of your catalogue instead. C is the catalogue's when the table row has one, else the ISO 281 C
of the estimated geometry.

**Row spacing.** Two bearings of width B (tapered: T) side by side without a spacer: the element rows sit
near the middle of each bearing, so the rows are B (T) apart [assumption: the row's axial position in
its bearing is not in the tables; for the stiffness under radial load only the pressure-centre spread
counts, which follows from the contact angle and this spacing].
"""

from __future__ import annotations

from bearingkit.catalogue.suffixes import PRELOAD_CLASSES
from bearingkit.errors import InputError

#: Preload force as a fraction of the single bearing's C per class [-] (module docstring) [from memory]:
#: a rule of thumb for spindle bearings sets, valid for 15°–40° angular contact bearings of the 70, 72,
#: 718, 719 series; the makers' tables differ by series, angle and maker.
PRELOAD_FRACTIONS = {"extra_light": 0.005, "light": 0.01, "medium": 0.02, "heavy": 0.04}
assert tuple(PRELOAD_FRACTIONS) == PRELOAD_CLASSES


def preload_force(preload, rating: float) -> tuple[float, str]:
    """(preload force [N], note) of a preload class or a force.

    Parameters
    ----------
    preload : str or float
        A class of :data:`PRELOAD_FRACTIONS` or a force [N] (> 0).
    rating : float [N]
        The single bearing's basic dynamic load rating C.
    """
    if isinstance(preload, str):
        if preload not in PRELOAD_FRACTIONS:
            raise InputError(
                f"preload ({preload!r}) must be one of {', '.join(PRELOAD_FRACTIONS)} or a force such as "
                "'500 N'"
            )
        k = PRELOAD_FRACTIONS[preload]
        force = k * rating
        return force, (
            f"preload class {preload}: F_pr = {k:g} C = {force:.4g} N (C = {rating / 1e3:.4g} kN), a rule of "
            "thumb, not the maker's table: give the catalogue's preload force (preload = '480 N') for a "
            "set you buy"
        )
    force = float(preload)
    if not force > 0:
        raise InputError(f"preload ({preload!r} N) must be a positive force")
    return force, f"preload force {force:.4g} N (given)"


def row_spacing(width: float) -> float:
    """Axial distance [m] of the two rows of a pair of bearings of width ``width`` (module docstring)."""
    return float(width)
