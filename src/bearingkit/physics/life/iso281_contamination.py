"""ISO 281 contamination levels: named cleanliness levels to the contamination factor e_C.

SI units (pitch diameter in m). ISO 281:2007 Table 13 gives guideline ranges of e_C for seven levels
of contamination, one column for bearings with a pitch diameter D_pw below 100 mm and one at or above;
bearingkit uses the middle of each range (a documented choice: the standard gives ranges). The values
are in ``bearingkit/data/iso281_contamination.csv``: the middles are confirmed by two public bearing-life
tools (the ranges themselves are from memory of the standard).

References: ISO 281:2007 Rolling bearings — Dynamic load ratings and rating life, clause 9.3.3,
Table 13.
"""

from __future__ import annotations

import difflib

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics import tables

_TABLE = "iso281_contamination.csv"
#: Pitch diameter separating the two columns of ISO 281 Table 13 [m].
LARGE_BEARING_PITCH_DIAMETER = 0.1


def contamination_levels() -> tuple[str, ...]:
    """The level names of ISO 281 Table 13, cleanest first."""
    return tables.text_column(_TABLE, "level")


def contamination_factor(level: str, pitch_diameter) -> float:
    """Contamination factor e_C of a named level (middle of the ISO 281 Table 13 range).

    Parameters
    ----------
    level : str
        One of :func:`contamination_levels` (``"normal_cleanliness"`` …).
    pitch_diameter : float [m]
        D_pw of the bearing (selects the column: below or at/above 100 mm).

    Returns
    -------
    float [-]

    References
    ----------
    ISO 281:2007 Table 13.
    """
    checks.positive("pitch_diameter", pitch_diameter, "m")
    levels = contamination_levels()
    if level not in levels:
        near = difflib.get_close_matches(str(level), levels, n=2, cutoff=0.5)
        hint = f"; did you mean {', '.join(near)}?" if near else ""
        raise InputError(
            f"contamination ({level!r}) must be a number e_C in [0, 1] or an ISO 281 level: "
            f"{', '.join(levels)}{hint}"
        )
    i = levels.index(level)
    col = "large" if float(pitch_diameter) >= LARGE_BEARING_PITCH_DIAMETER else "small"
    lo, hi = tables.column(_TABLE, f"{col}_low")[i], tables.column(_TABLE, f"{col}_high")[i]
    return float(np.mean([lo, hi]))
