"""Tolerance fields of shafts and housings (ISO 286) and of bearing rings (ISO 492), and fit interference.

SI units: deviations and interferences in m (the tables are in µm, the standards' unit, converted
here). A tolerance field is a code such as ``"k5"`` (shaft: lower-case letter) or ``"H7"`` (hole:
upper-case), built from a fundamental deviation (letter) and a standard tolerance grade IT (number)
per ISO 286-1:2010: for a shaft with upper fundamental deviation es (letters e–h) the field is
[es − IT, es]; with lower fundamental deviation ei (j, k, m, n, p) it is [ei, ei + IT]; js is ±IT/2.
Holes: EI (E–H) gives [EI, EI + IT]; ES gives [ES − IT, ES] with ES = −ei(shaft letter) + Δ for K, M,
N (IT ≤ 8) and P (IT ≤ 7), ES = −ei otherwise, K above IT8 and N above IT8 have ES = 0; JS is ±IT/2;
J6, J7, J8 are tabulated. The tables cover nominal sizes up to 500 mm (a bearing-seat range); the
letters and grades a bearing seat uses are tabulated (shafts e f g h j js k m n p, holes E F G H J JS
K M N P; IT3–IT11). Values and the status of each (verified or from memory) are in the CSV files
``bearingkit/data/iso286_*.csv`` and ``iso492_normal.csv``.

Interference of a fit between a "shaft" part (outer surface) and a "hole" part (bore), both given as
deviations from the same nominal diameter: smallest = shaft lower − hole upper, largest = shaft upper
− hole lower. A chosen percentile treats both deviations as independent normal variables centred in
their fields with ±3σ at the limits (statistical tolerancing; the common choice, not from a standard),
clipped to the smallest and largest interference.

References: ISO 286-1:2010 Geometrical product specifications — ISO code system for tolerances on
linear sizes, Tables 1–3; ISO 492:2014 Rolling bearings — Radial bearings — Tolerance values (Normal
class); NTN Ball and roller bearings handbook, table 5.1.
"""

from __future__ import annotations

import difflib
import re
from statistics import NormalDist

import numpy as np

from bearingkit import checks, references
from bearingkit.errors import InputError
from bearingkit.physics import tables

references.add(
    "iso286",
    "ISO 286-1:2010 Geometrical product specifications (GPS) - ISO code system for tolerances on linear "
    "sizes - Part 1: Basis of tolerances, deviations and fits (Tables 1-3).",
)
references.add(
    "iso492",
    "ISO 492:2014 Rolling bearings - Radial bearings - Geometrical product specifications (GPS) and "
    "tolerance values (Normal tolerance class).",
)

UM = 1e-6  # [m/µm]
MM = 1e-3  # [m/mm]
#: Letters with an upper fundamental deviation es (shafts) / lower EI (holes), tabulated.
SHAFT_UPPER = ("e", "f", "g", "h")
SHAFT_LOWER = ("j", "k", "m", "n", "p")
HOLE_LOWER = ("E", "F", "G", "H")
HOLE_UPPER = ("J", "K", "M", "N", "P")
GRADES = tuple(range(3, 12))
#: Half-width of a tolerance field in standard deviations (±3σ at the limits: statistical tolerancing).
FIELD_SIGMAS = 3.0
#: Named interference statistics (besides a percentile in (0, 100)).
STATISTICS = ("mean", "min", "max")

_CODE = re.compile(r"^\s*(js|JS|[a-zA-Z])(\d{1,2})\s*$")
_IT, _SHAFT, _HOLE, _RING = (
    "iso286_it_grades.csv",
    "iso286_shaft_deviations.csv",
    "iso286_hole_deviations.csv",
    "iso492_normal.csv",
)


def _all_codes() -> list[str]:
    shafts = [f"{x}{g}" for x in (*SHAFT_UPPER, "js", "k", "m", "n", "p") for g in GRADES]
    shafts += [f"j{g}" for g in (5, 6, 7)]
    holes = [f"{x}{g}" for x in (*HOLE_LOWER, "JS", "K", "M", "N", "P") for g in GRADES]
    holes += [f"J{g}" for g in (6, 7, 8)]
    return shafts + holes


def _bad_code(code: str, why: str) -> InputError:
    near = difflib.get_close_matches(str(code).strip(), _all_codes(), n=3, cutoff=0.5)
    hint = f"; did you mean {', '.join(near)}?" if near else ""
    return InputError(
        f"tolerance field ({code!r}) {why}; expected a shaft field such as k5, m6, js6, h6 or a housing "
        f"field such as H7, J7, K6, M7 (ISO 286, grades IT3-IT11, sizes up to 500 mm){hint}"
    )


def _row(table: str, size_mm: float) -> int:
    lo, hi = tables.column(table, "over_mm"), tables.column(table, "incl_mm")
    hit = np.flatnonzero((size_mm > lo) & (size_mm <= hi))
    if hit.size == 0:
        raise InputError(
            f"nominal diameter ({size_mm:.6g} mm) must lie in ({lo.min():g}, {hi.max():g}] mm for the "
            "ISO 286 tables bearingkit carries"
        )
    return int(hit[0])


def standard_tolerance(grade, nominal_diameter):
    """Standard tolerance IT of a grade at a nominal size (ISO 286-1 Table 1).

    Parameters
    ----------
    grade : int
        Tolerance grade n of ITn, 3 … 11.
    nominal_diameter : float [m]
        Nominal size, in (0, 0.5] m.

    Returns
    -------
    float [m]

    References
    ----------
    ISO 286-1:2010, Table 1.
    """
    checks.positive("nominal_diameter", nominal_diameter, "m")
    if int(grade) not in GRADES:
        raise InputError(f"tolerance grade (IT{grade}) must be one of IT3 ... IT11")
    i = _row(_IT, float(nominal_diameter) / MM)
    return float(tables.column(_IT, f"IT{int(grade)}")[i]) * UM


def tolerance_field(code: str, nominal_diameter) -> tuple[float, float]:
    """Upper and lower deviation of an ISO 286 tolerance field at a nominal diameter.

    Parameters
    ----------
    code : str
        Field code: a shaft letter (lower case) or a hole letter (upper case) and a grade, e.g.
        ``"k5"``, ``"js6"``, ``"H7"``, ``"M6"``.
    nominal_diameter : float [m]
        Nominal size of the seat (the bearing bore for a shaft, its outside diameter for a housing).

    Returns
    -------
    (upper, lower) : tuple of float [m]
        Deviations from the nominal size.

    References
    ----------
    ISO 286-1:2010, Tables 1–3 and the rules of its clause 5 (module docstring).
    """
    m = _CODE.match(str(code))
    if m is None:
        raise _bad_code(code, "is not a letter followed by a grade")
    letter, grade = m.group(1), int(m.group(2))
    if grade not in GRADES:
        raise _bad_code(code, f"has grade IT{grade}, outside IT3-IT11")
    size = float(nominal_diameter) / MM
    it = standard_tolerance(grade, nominal_diameter)
    if letter in ("js", "JS"):
        return it / 2.0, -it / 2.0
    if letter in SHAFT_UPPER:
        es = float(tables.column(_SHAFT, letter)[_row(_SHAFT, size)]) * UM
        return es, es - it
    if letter == "j":
        if grade not in (5, 6, 7):
            raise _bad_code(code, "is a j field; ISO 286 tabulates j5, j6 and j7 only")
        ei = float(tables.column(_SHAFT, f"j{grade}")[_row(_SHAFT, size)]) * UM
        return ei + it, ei
    if letter in SHAFT_LOWER:
        ei = float(tables.column(_SHAFT, letter)[_row(_SHAFT, size)]) * UM
        if letter == "k" and not 4 <= grade <= 7:
            ei = 0.0
        return ei + it, ei
    if letter in HOLE_LOWER:
        ei_hole = float(tables.column(_HOLE, letter)[_row(_HOLE, size)]) * UM
        return ei_hole + it, ei_hole
    if letter == "J":
        if grade not in (6, 7, 8):
            raise _bad_code(code, "is a J field; ISO 286 tabulates J6, J7 and J8 only")
        es = float(tables.column(_HOLE, f"J{grade}")[_row(_HOLE, size)]) * UM
        return es, es - it
    if letter in HOLE_UPPER:
        ei_shaft = float(tables.column(_SHAFT, letter.lower())[_row(_SHAFT, size)]) * UM
        with_delta = grade <= (7 if letter == "P" else 8)
        if letter == "K" and size <= 3.0:
            es = 0.0
        elif with_delta and size > 3.0:
            delta = float(tables.column(_HOLE, f"delta{grade}")[_row(_HOLE, size)]) if grade <= 8 else 0.0
            es = -ei_shaft + delta * UM
        elif letter in ("K", "N") and not with_delta:
            es = 0.0
        else:
            es = -ei_shaft
        return es, es - it
    raise _bad_code(code, f"has letter {letter!r}, which bearingkit does not tabulate")


def ring_deviation(ring: str, diameter) -> tuple[float, float]:
    """Deviation of a bearing ring's bore (``"inner"``) or outside diameter (``"outer"``), Normal class.

    Parameters
    ----------
    ring : {"inner", "outer"}
        Inner-ring bore or outer-ring outside diameter.
    diameter : float [m]
        Nominal bore d or outside diameter D.

    Returns
    -------
    (upper, lower) : tuple of float [m]
        t_Δdmp (inner) or t_ΔDmp (outer) of ISO 492:2014, upper 0.

    References
    ----------
    ISO 492:2014, Normal tolerance class tables (radial bearings except tapered roller bearings).
    """
    checks.one_of("ring", ring, ("inner", "outer"))
    checks.positive("diameter", diameter, "m")
    size = float(diameter) / MM
    which = np.array([r == ring for r in tables.text_column(_RING, "ring")])
    lo, hi = tables.column(_RING, "over_mm")[which], tables.column(_RING, "incl_mm")[which]
    hit = np.flatnonzero((size > lo) & (size <= hi))
    if hit.size == 0:
        raise InputError(
            f"{'bore' if ring == 'inner' else 'outer_diameter'} ({size:.6g} mm) must lie in ({lo.min():g}, "
            f"{hi.max():g}] mm for the ISO 492 Normal-class table bearingkit carries"
        )
    return 0.0, float(tables.column(_RING, "lower")[which][hit[0]]) * UM


def fit_interference(shaft, hole, statistic="mean"):
    """Interference of a fit from the deviations of the inner part (shaft) and the outer part (hole).

    Parameters
    ----------
    shaft : tuple (upper, lower) [m]
        Deviations of the inner part's outside diameter (a shaft seat, or a bearing's outer ring).
    hole : tuple (upper, lower) [m]
        Deviations of the outer part's bore (a bearing's inner ring, or a housing seat).
    statistic : {"mean", "min", "max"} or float
        Which interference: the mean, the smallest, the largest, or a percentile p in (0, 100) of the
        normal model (module docstring): the value below which p % of assemblies fall.

    Returns
    -------
    float [m]
        Diametral interference (negative: clearance fit).

    References
    ----------
    ISO 286-1:2010 clause 3 (fit, interference, clearance); statistical tolerancing with ±3σ fields
    (a documented choice, e.g. Harris & Kotzalas 2007 ch. on fitting practice use the probable range).
    """
    (su, sl), (hu, hl) = shaft, hole
    smallest, largest = sl - hu, su - hl
    mean = 0.5 * (su + sl) - 0.5 * (hu + hl)
    if isinstance(statistic, str):
        checks.one_of("statistic", statistic, STATISTICS)
        return {"mean": mean, "min": smallest, "max": largest}[statistic]
    p = float(statistic)
    if not 0.0 < p < 100.0:
        raise InputError(f"statistic ({p:g}) must be 'mean', 'min', 'max' or a percentile in (0, 100)")
    sigma = np.hypot((su - sl) / (2 * FIELD_SIGMAS), (hu - hl) / (2 * FIELD_SIGMAS))
    # the standard normal quantile (the standard library's: scipy.special costs ~0.3 s to import)
    return float(np.clip(mean + NormalDist().inv_cdf(p / 100.0) * sigma, smallest, largest))
