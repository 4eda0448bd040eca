"""Input section ``[hardness]``: the raceways' hardness against depth (docs/subsurface.md).

Hardness values are Vickers numbers (``650``) or strings with their scale (``"650 HV"``, ``"58 HRC"``,
converted by :func:`bearingkit.hardness.hrc_to_hv`); depths carry units. The section starts from a preset
(``preset``) or the material's profile and replaces the fields it gives; ``through_hardened = true``
drops the case. :func:`hardness_of` builds the :class:`~bearingkit.hardness.HardnessProfile` and checks it
against the ring (a case deeper than the ring wall below the raceways is refused).
"""

from __future__ import annotations

import re
from typing import Annotated, Literal

from pydantic import BeforeValidator, Field, ValidationInfo, WithJsonSchema

from bearingkit.errors import InputError, quote
from bearingkit.io.fields import Dimensionless, Strict, quantity

__all__ = ["HardnessSpec"]

_SCALE = re.compile(r"^\s*([0-9]+(?:\.[0-9]*)?)\s*(HV[0-9.]*|HRC)\s*$", re.IGNORECASE)


def _hardness(value, info: ValidationInfo) -> float:
    """A number (HV) or ``"<number> HV|HRC"`` → HV, within :data:`bearingkit.hardness.HARDNESS_RANGE_HV`."""
    from bearingkit.hardness import HARDNESS_RANGE_HV, HRC_RANGE, hrc_to_hv

    field = info.field_name
    low, high = HARDNESS_RANGE_HV
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise InputError(f"{field} ({quote(value)}) must be a Vickers number or a string such as '58 HRC'")
    if isinstance(value, str):
        match = _SCALE.match(value)
        if match is None:
            raise InputError(
                f"{field} ({quote(value)}) must be a Vickers number (650) or '<number> HV' / '<number> HRC'"
            )
        number, scale = float(match.group(1)), match.group(2).upper()
        if scale == "HRC":
            if not HRC_RANGE[0] <= number <= HRC_RANGE[1]:
                raise InputError(
                    f"{field} ({quote(value)}) must lie in [{HRC_RANGE[0]:g}, {HRC_RANGE[1]:g}] HRC, the "
                    "range "
                    "of the HRC → HV conversion"
                )
            value = float(hrc_to_hv(number))
        else:
            value = number
    hv = float(value)
    if not low <= hv <= high:
        raise InputError(
            f"{field} ({quote(value)} HV) must lie in [{low:g}, {high:g}] HV (steel rings); check the scale: "
            "a Rockwell value is written '58 HRC'"
        )
    return hv


Hardness = Annotated[
    float,
    BeforeValidator(_hardness),
    WithJsonSchema(
        {
            "type": ["number", "string"],
            "description": "a Vickers hardness (650) or a string with its scale, e.g. '650 HV' or '58 HRC'",
            "x-dimension": "hardness",
            "x-si-unit": "HV",
        }
    ),
]


class HardnessSpec(Strict):
    """``[hardness]``: the raceways' hardness profile (both rings; docs/subsurface.md)."""

    preset: str | None = Field(
        None, description="Start from a preset: through_hardened, 42CrMo4_induction, 50CrMo4_induction."
    )
    through_hardened: bool | None = Field(None, description="true: no hardened case (drops case_depth).")
    surface_hardness: Hardness | None = None
    case_depth: quantity("length", "positive") | None = Field(
        None, description="Effective case depth (SHD or CHD, depth_definition)."
    )
    core_hardness: Hardness | None = None
    depth_definition: Literal["SHD", "CHD"] | None = Field(
        None,
        description="SHD: limit hardness 0.8 × surface (ISO 3754/18203, induction); CHD: 550 HV (ISO 2639).",
    )
    limit_hardness: Hardness | None = Field(
        None, description="Limit hardness of the case depth, if not SHD/CHD's."
    )
    transition_width: Dimensionless | None = Field(
        None, description="Width of the fall to the core hardness over the case depth (default 0.5)."
    )
    strength_model: Literal["pavlina2008", "tabor"] | None = Field(
        None, description="Yield strength from hardness (default pavlina2008)."
    )
    static_limit_factor: Dimensionless | None = Field(
        None, description="Factor on ISO 76's limit pressures (default from the surface hardness)."
    )
