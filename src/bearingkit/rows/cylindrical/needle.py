"""Needle roller rows: radial cylindrical roller rows with needle proportions, with or without inner ring.

SI units. The mechanics are those of :class:`~bearingkit.rows.cylindrical.row.CylindricalRow` (sliced line
contacts, crowning, tilt); this kind adds what a needle bearing means for ratings and checks:

- proportions: a needle roller is long and thin; ISO 5593 calls a roller a needle when its length is
  at least about 2.5 D_w and its diameter small (≤ 6 mm in ISO 3096) [from memory]; rows outside
  ``NEEDLE_LENGTH_RATIO`` are refused as not needles (use a cylindrical row);
- ``inner_ring=False``: the needles run on the shaft, which must then be a raceway (hardened, ground):
  ISO 76 and ISO 281 apply only if "that surface is equivalent in all respects to the bearing surface
  it replaces" (ISO 76:2006 scope), which the rater repeats as a warning;
- ``construction``: ``"machined"`` (machined rings, NA/RNA) or ``"drawn_cup"`` (HK/BK): ISO 281 Table 1
  gives them different rating factors b_m.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from bearingkit import checks
from bearingkit.rows.cylindrical.row import CylindricalRow

#: Smallest length-to-diameter ratio of a needle [-] (ISO 5593 needle roller, [from memory]; catalogue
#: needles have l/D_w of about 2.5-10).
NEEDLE_LENGTH_RATIO = 2.5
#: Constructions and the ISO 281:2007 Table 1 bearing types whose b_m they take.
CONSTRUCTIONS = {"machined": "needle_roller_machined", "drawn_cup": "needle_roller_drawn_cup"}


@dataclass(frozen=True)
class NeedleRow(CylindricalRow):
    """A radial row of needle rollers (all fields of :class:`CylindricalRow`, radial only).

    Parameters
    ----------
    inner_ring : bool
        False when the needles run directly on the shaft (the shaft is the inner raceway).
    construction : str
        ``"machined"`` or ``"drawn_cup"`` (:data:`CONSTRUCTIONS`).
    """

    kind: ClassVar[str] = "needle"

    inner_ring: bool = True
    construction: str = "machined"
    name: str = "needles"

    def __post_init__(self):
        super().__post_init__()
        if self.orientation != "radial":
            raise checks.InputError(
                f"orientation ({self.orientation!r}) must be 'radial' for a needle row (thrust needle "
                "bearings: use a cylindrical_roller_thrust row)"
            )
        checks.one_of("construction", self.construction, CONSTRUCTIONS)
        ratio = np.asarray(self.effective_length) / np.asarray(self.element_diameter)
        if np.any(ratio < NEEDLE_LENGTH_RATIO):
            raise checks.InputError(
                f"effective_length ({np.min(self.effective_length):.6g} m) is {np.min(ratio):.3g} roller "
                f"diameters; a needle is at least {NEEDLE_LENGTH_RATIO:g} long (use a cylindrical roller row)"
            )

    @property
    def bearing_type(self) -> str:
        """The ISO 281 Table 1 type whose b_m applies."""
        return CONSTRUCTIONS[self.construction]
