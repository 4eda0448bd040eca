"""Units at the edge: parse strings such as ``"5 kN"`` or ``"-2 um"`` to SI floats.

Everything inside bearingkit is SI (m, N, Pa, rad, s, Pa·s, 1/Pa, rad/s). This module is the only
place that knows about pint; it is called by the input-file loader and the CLI, never by physics.
A rotational speed such as ``"5 rpm"`` becomes an angular velocity in rad/s.
"""

from __future__ import annotations

from functools import lru_cache

import pint

from bearingkit.errors import InputError

#: The SI unit each named dimension is converted to. Keys are what fields declare.
SI_UNITS: dict[str, str] = {
    "length": "m",
    "force": "N",
    "moment": "N*m",
    "pressure": "Pa",
    "angle": "rad",
    "angular_velocity": "rad/s",
    "dynamic_viscosity": "Pa*s",
    "kinematic_viscosity": "m^2/s",
    "pressure_viscosity": "1/Pa",
    "compliance": "m^2/N",
    "temperature": "degC",
    "density": "kg/m^3",
    "mass": "kg",
    "thermal_conductivity": "W/(m*K)",
    "time": "s",
    "acceleration": "m/s^2",
    "line_load": "N/m",
    "stiffness": "N/m",
    "rotational_stiffness": "N*m/rad",
    "power": "W",
    "thermal_conductance": "W/K",
    "volume_flow": "m^3/s",
    "dimensionless": "",
}


@lru_cache(maxsize=1)
def registry() -> pint.UnitRegistry:
    """The one pint registry (built lazily; pint is slow to import)."""
    ureg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True)
    # pint knows 'rpm' (revolution/minute); make the revolution explicit 2π rad so rpm → rad/s.
    return ureg


def parse(value, dimension: str, field: str) -> float:
    """Parse ``value`` (``"5 kN"``) to a float in the SI unit of ``dimension``.

    Parameters
    ----------
    value : str or number
        The text with its unit. A bare number is accepted only for ``dimension="dimensionless"``.
    dimension : str
        A key of :data:`SI_UNITS` (``"force"``, ``"length"`` …).
    field : str
        The field's name, used in the error message.

    Returns
    -------
    float
        The value in the SI unit of ``dimension`` (``"temperature"`` → °C, the one non-SI
        convenience: viscosity–temperature laws are written in °C and K explicitly).

    Raises
    ------
    InputError
        One line naming the field, the value and the expected dimension, for a missing unit, an
        unknown unit, a wrong dimension or a non-finite number.
    """
    if dimension not in SI_UNITS:
        raise InputError(f"{field}: unknown dimension {dimension!r}; expected one of {sorted(SI_UNITS)}")
    target = SI_UNITS[dimension]
    ureg = registry()
    if isinstance(value, bool):
        raise InputError(f"{field} ({value!r}) must be a quantity with a unit of {dimension} (e.g. {target})")
    if isinstance(value, (int, float)):
        if dimension == "dimensionless":
            return _finite(float(value), field, value)
        raise InputError(
            f"{field} ({value!r}) has no unit; expected a {dimension.replace('_', ' ')} such as "
            f"'{value} {target or '1'}'"
        )
    if not isinstance(value, str):
        raise InputError(f"{field} ({value!r}) must be a string with a unit, e.g. '1 {target}'")
    text = value.strip()
    known = _PARSED.get((text, dimension))
    if known is not None:  # pint takes ~2 ms per value; studies rebuild inputs from the same texts
        return known
    try:
        q = ureg.Quantity(text)
    except Exception as exc:  # pint raises several types; one line is what the user needs
        raise InputError(
            f"{field} ({value!r}) is not a quantity pint understands ({type(exc).__name__})"
        ) from None
    if not isinstance(q, pint.Quantity):  # a bare number inside a string
        q = ureg.Quantity(float(q), "")
    if dimension == "dimensionless":
        if not q.dimensionless:
            raise InputError(f"{field} ({value!r}) must be dimensionless")
        return _remember(text, dimension, _finite(float(q.to("").magnitude), field, value))
    if q.dimensionless and q.unitless:
        raise InputError(
            f"{field} ({value!r}) has no unit; expected a {dimension.replace('_', ' ')} "
            f"such as '{text} {target}'"
        )
    try:
        out = float(q.to(target).magnitude)
    except pint.DimensionalityError:
        raise InputError(
            f"{field} ({value!r}) has dimension {q.dimensionality}; expected {dimension.replace('_', ' ')} "
            f"(convertible to {target})"
        ) from None
    return _remember(text, dimension, _finite(out, field, value))


#: Texts already parsed, (text, dimension) → SI value (successful parses only; errors name their field).
_PARSED: dict[tuple[str, str], float] = {}
#: Most remembered texts (a bound on the memory an untrusted input can take).
_PARSED_MAX = 65536


def _remember(text: str, dimension: str, value: float) -> float:
    if len(_PARSED) < _PARSED_MAX:
        _PARSED[(text, dimension)] = value
    return value


def _finite(x: float, field: str, raw) -> float:
    if x != x or x in (float("inf"), float("-inf")):
        raise InputError(f"{field} ({raw!r}) must be finite")
    return x


def format_si(value: float, dimension: str) -> str:
    """Format an SI float with its unit, for messages and reports."""
    return f"{value:.6g} {SI_UNITS[dimension]}".rstrip()
