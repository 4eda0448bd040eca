"""Value types of the input-file schema: quantities with units in, SI floats out; strict counts.

Units live only here, at the edge: every dimensional value in a file is a string with its unit
(``"6 mm"``, ``"-5 um"``, ``"600 N*m"``, ``"5 rpm"``, ``"40 deg"``), parsed by
:func:`bearingkit.units.parse` into SI (m, N, N·m, Pa, rad, rad/s; temperature in °C; the accepted
syntax is in :mod:`bearingkit.units`). A dimensionless field takes a TOML number (``0.52``), a count
a TOML integer (``9``): a string there (``"9"``) is refused, so a quoting slip cannot hide.

:class:`Strict` is the base of every section model: unknown fields are errors, models are frozen and
pydantic's type coercion is off (``"true"`` is not a boolean, ``"3"`` not an integer).
"""

from __future__ import annotations

from typing import Annotated

from pydantic import BaseModel, BeforeValidator, ConfigDict, ValidationInfo, WithJsonSchema

from bearingkit import units
from bearingkit.errors import InputError, quote

#: Examples shown in messages and in the JSON Schema, per dimension.
UNIT_EXAMPLES = {
    "length": "6 mm",
    "force": "5 kN",
    "moment": "600 N*m",
    "pressure": "208 GPa",
    "angle": "40 deg",
    "angular_velocity": "5 rpm",
    "temperature": "40 degC",
    "density": "7810 kg/m^3",
}

#: Largest accepted counts: elements per row (the largest slewing rings carry a few hundred balls or
#: rollers per row), slices per roller (ISO/TS 16281 practice is 20–50), solver iterations (the
#: default is 60). Guards against typing errors that would exhaust memory or time.
MAX_ELEMENTS = 2_000
MAX_SLICES = 200
MAX_ITERATIONS = 1_000


class Strict(BaseModel):
    """Base of every section: unknown fields are errors, no type coercion, immutable."""

    model_config = ConfigDict(extra="forbid", frozen=True, strict=True, defer_build=True)


def example(dimension: str) -> str:
    """An example value of ``dimension`` with its unit (``'6 mm'``)."""
    return UNIT_EXAMPLES.get(dimension, "1 " + units.SI_UNITS[dimension])


def _quantity_parser(dimension: str, sign: str | None):
    def parse(value, info: ValidationInfo) -> float:
        x = units.parse(value, dimension, info.field_name)
        if sign == "positive" and not x > 0:
            raise InputError(f"{info.field_name} ({quote(value)}) must be positive")
        if sign == "non_negative" and not x >= 0:
            raise InputError(f"{info.field_name} ({quote(value)}) must be non-negative")
        return x

    return parse


def quantity(dimension: str, sign: str | None = None):
    """Annotated float type of a dimensional field: a string with a unit in, SI float out."""
    words = {"positive": "a positive ", "non_negative": "a non-negative "}.get(sign or "", "a ")
    return Annotated[
        float,
        BeforeValidator(_quantity_parser(dimension, sign)),
        WithJsonSchema(
            {
                "type": "string",
                "description": f"{words}{dimension.replace('_', ' ')} with its unit, e.g. "
                f"'{example(dimension)}'",
                "x-dimension": dimension,
                "x-si-unit": units.SI_UNITS[dimension],
            }
        ),
    ]


def _not_text(value, field: str, what: str) -> None:
    """A number field given as a string (``"9"``) or a boolean: one line saying how to write it."""
    if isinstance(value, bool):
        raise InputError(f"{field} ({value!r}) must be {what}, not a boolean")
    if isinstance(value, str):
        bare = value.strip()
        hint = f": write {field} = {bare} without quotes" if units.is_number(bare) else ""
        raise InputError(f"{field} ({quote(value)}) must be {what}, not a string{hint}")


def _dimensionless(value, info: ValidationInfo) -> float:
    _not_text(value, info.field_name, "a number")
    return units.parse(value, "dimensionless", info.field_name)


def _counter(high: int):
    def count(value, info: ValidationInfo) -> int:
        field = info.field_name
        _not_text(value, field, f"an integer in [1, {high}]")
        if isinstance(value, float):
            raise InputError(f"{field} ({quote(value)}) must be an integer in [1, {high}] such as 9")
        if not isinstance(value, int) or not 1 <= value <= high:
            raise InputError(f"{field} ({quote(value)}) must be an integer in [1, {high}]")
        return value

    return count


def _count_type(high: int):
    return Annotated[
        int,
        BeforeValidator(_counter(high)),
        WithJsonSchema({"type": "integer", "minimum": 1, "maximum": high, "x-dimension": "count"}),
    ]


Length = quantity("length")
PositiveLength = quantity("length", "positive")
NonNegativeLength = quantity("length", "non_negative")
Force = quantity("force")
PositiveForce = quantity("force", "positive")
Moment = quantity("moment")
PositivePressure = quantity("pressure", "positive")
#: Force per length per displacement [N/m²] (a Winkler foundation on a ring): the dimension of a pressure.
NonNegativeStiffnessPerLength = quantity("pressure", "non_negative")
Angle = quantity("angle")
AngularVelocity = quantity("angular_velocity")
Temperature = quantity("temperature")
PositiveDensity = quantity("density", "positive")
Dimensionless = Annotated[
    float,
    BeforeValidator(_dimensionless),
    WithJsonSchema({"type": "number", "x-dimension": "dimensionless"}),
]
Count = _count_type(MAX_ELEMENTS)
SliceCount = _count_type(MAX_SLICES)
IterationCount = _count_type(MAX_ITERATIONS)


def _shoulder(value, info: ValidationInfo) -> dict:
    """A groove shoulder height: a length with its unit (``"2.5 mm"``), or a TOML number = fraction of D_w.

    A number written as a string (``"0.35"``) is refused like every other strict number: it would be
    neither a length (no unit) nor, silently, a fraction.
    """
    name = info.field_name
    if isinstance(value, str) and units.is_number(value.strip()):
        raise InputError(
            f"{name} ({quote(value)}) is a number in quotes: write {name} = {value.strip()} for a fraction "
            "of the ball diameter, or a length with its unit such as '2.5 mm'"
        )
    if isinstance(value, bool):
        raise InputError(f"{name} ({value!r}) must be a length such as '2.5 mm' or a fraction of D_w")
    if isinstance(value, (int, float)):
        x = units.parse(value, "dimensionless", name)
        if not 0 < x < 1:
            raise InputError(
                f"{name} ({quote(value)}) must be a fraction of the ball diameter in (0, 1), or a length "
                "such as '2.5 mm'"
            )
        return {"fraction": x}
    x = units.parse(value, "length", name)
    if not x > 0:
        raise InputError(f"{name} ({quote(value)}) must be positive")
    return {"length": x}


#: Groove shoulder height above the groove bottom (truncation of the contact ellipse, docs/ratings.md): a
#: length (``"2.5 mm"``) or a TOML number, the fraction of the ball diameter (``0.35``). Stored as
#: ``{"length": m}`` or ``{"fraction": h/D_w}``; :mod:`bearingkit.io.build.shoulders` turns it into per-row
#: fractions checked against each groove.
ShoulderHeight = Annotated[
    dict,
    BeforeValidator(_shoulder),
    WithJsonSchema(
        {
            "anyOf": [
                {"type": "string", "description": "a positive length with its unit, e.g. '2.5 mm'"},
                {"type": "number", "exclusiveMinimum": 0, "exclusiveMaximum": 1},
            ],
            "description": "Groove shoulder height above the groove bottom: a length, or a number = "
            "fraction of the ball diameter D_w.",
            "x-dimension": "length",
        }
    ),
]
