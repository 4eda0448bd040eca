"""Matched pairs from a designation (``7014 C DB``, ``7014 CD/P4ADBB``, ``30206 DF``): arrangement, row
spacing and the preload force of a preload class. SI units (m, N).

**Preload classes: NSK's convention.** A preload class becomes a force by NSK's table of average
preloads for duplex angular contact ball bearings (NSK *Rolling Bearings*, CAT. No. E1102e, §10.4.2 and
Table 10.2, pp. A98–A99; ``data/preload_nsk.csv``): extra light EL, light L, medium M, heavy H in N for
the 15° bearings (symbol C) of series 79, 70 and 72, bore numbers 00–20 — "average preloads for duplex
angular contact ball bearings (contact angle of 15°) with precision better than P5 class, which are used
on the main shafts of machine tools" (A98). The catalogue defines the classes by the set itself: the
internal clearance of a matched set is adjusted to give the class's preload when the pair is tightened
axially till the side faces of its inner or outer rings touch (B49), and each bearing of the set then
carries the preload F_a0 (A96, §10.3.1) — which is what ``[operating] preload_force`` asks of each row.
NSK's 79 series is the ISO dimension series 19 (A54, Table 7.5): its rows are bearingkit's 719xx C.
The printed values are used as they stand, without interpolation or scaling to another series, angle,
size or maker.

The other makers' classes (SKF A/B/C/D, GA/GB/GC; FAG UL/UM/UH: :mod:`.suffixes`) map onto NSK's four
classes **by name only**: SKF's "B" of a 7014 CD set gets NSK's light preload of a 7014 C set, which is
not SKF's number (SKF prints its own per bearing and says the values "are not standardized"). Every note
of a class says whose value it is.

**Outside NSK's table** (another contact angle, series or size, or a set declared P0/PN/P6/P6X; P5 is
taken as inside, as B49 rates the C bearings' speeds for "precision of P5 and better") a class falls
back to bearingkit's rule of thumb on the single bearing's basic dynamic load rating C, F_pr = k · C,
k of :data:`PRELOAD_FRACTIONS` [from memory; not a maker's number]; the note says so and why.
``preload = "480 N"`` (``--preload 480N``) takes the force of your catalogue instead. C is the
catalogue's when the table row has one, else the ISO 281 C of the estimated geometry.

**Row spacing.** Two bearings of width B (tapered: T) side by side without a spacer: the element rows sit
near the middle of each bearing, so the rows are B (T) apart [assumption: the row's axial position in
its bearing is not in the tables; for the stiffness under radial load only the pressure-centre spread
counts, which follows from the contact angle and this spacing].
"""

from __future__ import annotations

import functools

from bearingkit.catalogue.suffixes import PRELOAD_CLASSES
from bearingkit.catalogue.tables import reference_table
from bearingkit.errors import InputError

#: Preload force as a fraction of the single bearing's C per class [-] (module docstring) [from memory]:
#: the fallback outside NSK's table, a rule of thumb for spindle bearing sets of 15°–40° angular contact
#: bearings of the 70, 72, 718, 719 series; the makers' tables differ by series, angle and maker.
PRELOAD_FRACTIONS = {"extra_light": 0.005, "light": 0.01, "medium": 0.02, "heavy": 0.04}
assert tuple(PRELOAD_FRACTIONS) == PRELOAD_CLASSES

#: The source of ``data/preload_nsk.csv``, as the notes name it.
NSK_SOURCE = "NSK Rolling Bearings CAT. No. E1102e, Table 10.2, pp. A98-A99"
#: What NSK's table covers, as the notes name it.
NSK_SCOPE = "15° duplex sets (C) of series 79, 70, 72, bore numbers 00-20, precision better than P5"
#: Tolerance classes below the table's "precision better than P5" (:mod:`.suffixes`).
_COARSE_TOLERANCES = ("P0", "PN", "P6", "P6X")


@functools.cache
def nsk_preloads() -> dict[str, dict]:
    """NSK's preloads per bearingkit base designation (``"7014C"``, ``"71914C"``): ``{"maker_designation":
    "7014 C", "extra_light": 145.0, "light": 290.0, "medium": 740.0, "heavy": 1470.0, "source": ...}``
    (N, each bearing of the set; ``data/preload_nsk.csv``)."""
    table = {}
    for row in reference_table("preload_nsk"):
        entry = {"maker_designation": row["maker_designation"], "source": row["source"]}
        entry.update({c: float(row[f"{c}_N"]) for c in PRELOAD_CLASSES})
        table[row["designation"]] = entry
    return table


def preload_force(preload, rating: float, base: str | None = None, tolerance_class: str | None = None):
    """(preload force [N], note) of a preload class or a force.

    Parameters
    ----------
    preload : str or float
        A class of :data:`PRELOAD_FRACTIONS` or a force [N] (> 0).
    rating : float [N]
        The single bearing's basic dynamic load rating C (the fallback rule's).
    base : str, optional
        The bearing's base designation (``"7014C"``): a row of NSK's table gives the class's force.
    tolerance_class : str, optional
        As printed (``"P4A"``); a class coarser than P5 (P0, PN, P6, P6X) is outside NSK's table.
    """
    if isinstance(preload, str):
        if preload not in PRELOAD_FRACTIONS:
            raise InputError(
                f"preload ({preload!r}) must be one of {', '.join(PRELOAD_FRACTIONS)} or a force such as "
                "'500 N'"
            )
        row = nsk_preloads().get(base) if base is not None else None
        coarse = tolerance_class is not None and tolerance_class.upper() in _COARSE_TOLERANCES
        if row is not None and not coarse:
            force = row[preload]
            return force, (
                f"preload class {preload}: {force:g} N, NSK's {preload.replace('_', ' ')} preload of a "
                f"{row['maker_designation']} duplex set ({NSK_SOURCE}: average preloads of {NSK_SCOPE}, "
                "machine-tool spindles); other makers' class letters map onto NSK's EL/L/M/H by name "
                "only: give your catalogue's force (preload = '480 N') for a set of another maker"
            )
        k = PRELOAD_FRACTIONS[preload]
        force = k * rating
        why = (
            f"NSK's preload table is for precision better than P5, the set is {tolerance_class}"
            if row is not None
            else f"{base or 'this bearing'} is not in NSK's preload table"
        )
        return force, (
            f"preload class {preload}: F_pr = {k:g} C = {force:.4g} N (C = {rating / 1e3:.4g} kN), a rule "
            f"of thumb [from memory], not a maker's number: {why} ({NSK_SOURCE}: {NSK_SCOPE}); give the "
            "catalogue's preload force (preload = '480 N') for a set you buy"
        )
    force = float(preload)
    if not force > 0:
        raise InputError(f"preload ({preload!r} N) must be a positive force")
    return force, f"preload force {force:.4g} N (given)"


def row_spacing(width: float) -> float:
    """Axial distance [m] of the two rows of a pair of bearings of width ``width`` (module docstring)."""
    return float(width)
