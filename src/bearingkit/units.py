"""Units at the edge: parse strings such as ``"5 kN"`` or ``"-2 um"`` to SI floats.

Everything inside bearingkit is SI (m, N, Pa, rad, s, Pa·s, 1/Pa, rad/s). This module is the only
place that knows about pint; it is called by the input-file loader and the CLI, never by physics.
A rotational speed such as ``"5 rpm"`` becomes an angular velocity in rad/s.

**Accepted syntax** (checked before pint sees the text, so untrusted input cannot make pint's
expression evaluator run long or overflow: ``"9**9**9 N"`` ran for minutes, ``"10**400 N"`` raised
OverflowError): at most :data:`MAX_VALUE_CHARS` characters, made of

- a decimal number (ASCII digits) with an optional exponent: ``5``, ``-2.5``, ``.5``, ``1e-6``, ``+3E4``;
- optionally, after optional spaces, a unit expression of at most :data:`MAX_UNIT_CHARS` characters:
  unit names (letters, ``_``, ``µ``/``μ``, ``°``, ``Ω``) joined by ``*``, ``·``, ``/`` or a space,
  each optionally raised to a signed integer power of one or two digits (``^2``, ``**-1``), one
  level of parentheses (``W/(m*K)``), and a leading ``1/`` (``1/Pa``).

Everything else (arithmetic, hexadecimal, ``nan``, several numbers) is refused with one line. A unit
of the wrong dimension gets look-alike suggestions of the expected one (``"2 kn"`` is knots:
"did you mean '2 kN'?").

The units engineers type most (:data:`COMMON_UNITS`: ``kN``, ``mm``, ``rpm``, ``degC`` …) are converted
without pint: importing pint and building its registry takes about a second, most of the start-up
of a one-case analysis. Every entry is pint's own conversion, held to it bit for bit by
``tests/test_units.py``; any other unit, and every error, goes through pint.
"""

from __future__ import annotations

import difflib
import math
import re
from functools import lru_cache
from typing import TYPE_CHECKING

from bearingkit.errors import InputError, quote

#: The SI unit each named dimension is converted to. Keys are what fields declare.
#: Unit suggested when a value of a dimension comes without one, where engineers do not write the SI
#: unit (a speed is given in r/min, not rad/s); every other dimension suggests its SI unit.
SUGGESTED_UNITS: dict[str, str] = {"angular_velocity": "rpm", "angle": "deg"}

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
    "specific_heat": "J/(kg*K)",
    "heat_transfer_coefficient": "W/(m^2*K)",
    "area": "m^2",
    "second_moment": "m^4",
    "dimensionless": "",
}

#: Units suggested when a value has the wrong dimension or an unknown unit (``"did you mean kN?"``).
#: Every entry converts to the SI unit of its dimension (checked in the tests).
UNIT_LOOKALIKES: dict[str, tuple[str, ...]] = {
    "length": ("m", "mm", "um", "µm", "nm", "cm", "in", "ft"),
    "force": ("N", "kN", "MN", "mN", "lbf", "kgf"),
    "moment": ("N*m", "kN*m", "N*mm", "mN*m", "lbf*in", "lbf*ft"),
    "pressure": ("Pa", "kPa", "MPa", "GPa", "bar", "psi", "N/mm^2"),
    "angle": ("rad", "mrad", "deg", "arcmin", "arcsec"),
    "angular_velocity": ("rpm", "rad/s", "deg/s"),
    "dynamic_viscosity": ("Pa*s", "mPa*s", "cP"),
    "kinematic_viscosity": ("mm^2/s", "m^2/s", "cSt"),
    "pressure_viscosity": ("1/Pa", "1/GPa", "mm^2/N", "m^2/N"),
    "compliance": ("m^2/N", "mm^2/N"),
    "temperature": ("degC", "K", "degF"),
    "density": ("kg/m^3", "g/cm^3"),
    "mass": ("kg", "g"),
    "thermal_conductivity": ("W/(m*K)",),
    "time": ("s", "ms", "min", "h"),
    "acceleration": ("m/s^2", "mm/s^2"),
    "line_load": ("N/m", "N/mm", "kN/m"),
    "stiffness": ("N/m", "N/mm", "N/um", "kN/mm"),
    "rotational_stiffness": ("N*m/rad", "kN*m/rad", "N*m/mrad"),
    "power": ("W", "kW", "mW"),
    "thermal_conductance": ("W/K", "kW/K"),
    "volume_flow": ("m^3/s", "l/min", "mm^3/s"),
    "specific_heat": ("J/(kg*K)", "kJ/(kg*K)"),
    "heat_transfer_coefficient": ("W/(m^2*K)",),
    "area": ("m^2", "mm^2", "cm^2"),
    "second_moment": ("m^4", "mm^4", "cm^4"),
    "dimensionless": (),
}

if TYPE_CHECKING:
    import pint

_DEG = math.pi / 180.0
#: Units converted without pint: dimension → unit text (exactly as written after the number) →
#: (factor, offset), SI value = number × factor + offset. Each is pint's conversion of that unit to
#: :data:`SI_UNITS` (tests/test_units.py compares every entry with pint's, bit for bit); a unit not
#: listed here, or written differently (``"5 KN"``, ``"5 kN*1"``), is parsed by pint.
COMMON_UNITS: dict[str, dict[str, tuple[float, float]]] = {
    "length": {
        "m": (1.0, 0.0), "mm": (1e-3, 0.0), "um": (1e-6, 0.0), "µm": (1e-6, 0.0), "μm": (1e-6, 0.0),
        "nm": (1e-9, 0.0), "cm": (1e-2, 0.0), "in": (0.0254, 0.0),
    },
    "force": {"N": (1.0, 0.0), "kN": (1e3, 0.0), "MN": (1e6, 0.0), "mN": (1e-3, 0.0)},
    "moment": {
        "N*m": (1.0, 0.0), "N·m": (1.0, 0.0), "Nm": (1.0, 0.0), "kN*m": (1e3, 0.0), "kNm": (1e3, 0.0),
        "N*mm": (1e-3, 0.0), "Nmm": (1e-3, 0.0),
    },
    "pressure": {
        "Pa": (1.0, 0.0), "kPa": (1e3, 0.0), "MPa": (1e6, 0.0), "GPa": (1e9, 0.0), "bar": (1e5, 0.0),
        "N/mm^2": (1e6, 0.0),
    },
    "angle": {"rad": (1.0, 0.0), "mrad": (1e-3, 0.0), "deg": (_DEG, 0.0), "°": (_DEG, 0.0)},
    "angular_velocity": {"rad/s": (1.0, 0.0), "rpm": (math.pi / 30.0, 0.0)},
    "temperature": {"degC": (1.0, 0.0), "°C": (1.0, 0.0), "K": (1.0, -273.15)},
    "kinematic_viscosity": {"mm^2/s": (1e-6, 0.0), "m^2/s": (1.0, 0.0)},
    "dynamic_viscosity": {"Pa*s": (1.0, 0.0), "mPa*s": (1e-3, 0.0)},
    "pressure_viscosity": {
        "1/Pa": (1.0, 0.0), "1/GPa": (1e-9, 0.0), "mm^2/N": (1e-6, 0.0), "m^2/N": (1.0, 0.0),
    },
    "time": {"s": (1.0, 0.0), "min": (60.0, 0.0), "h": (3600.0, 0.0)},
    "power": {"W": (1.0, 0.0), "kW": (1e3, 0.0)},
    "mass": {"kg": (1.0, 0.0), "g": (1e-3, 0.0)},
    "density": {"kg/m^3": (1.0, 0.0)},
    "stiffness": {"N/m": (1.0, 0.0), "N/mm": (1e3, 0.0), "N/um": (1e6, 0.0)},
    "area": {"m^2": (1.0, 0.0), "mm^2": (1e-6, 0.0)},
}  # fmt: skip

#: Longest accepted value text [characters] (a number and its unit; "-1.23456789e-12 kN*m" is 20).
MAX_VALUE_CHARS = 64
#: Longest accepted unit expression [characters] ("kg/m^3" is 6, "W/(m*K)" 7).
MAX_UNIT_CHARS = 32

_NUMBER = r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?"  # ASCII digits only
_VALUE = re.compile(rf"\s*(?P<number>{_NUMBER})\s*(?P<unit>.*?)\s*")
_NON_FINITE = re.compile(r"\s*[+-]?(?:nan|inf|infinity)\b.*", re.IGNORECASE)
_NAME = r"[A-Za-z_µμ°Ω]+"
_POWER = r"(?:\^|\*\*)[+-]?[0-9]{1,2}"
_ATOM = rf"{_NAME}(?:{_POWER})?"
_GROUP = rf"\(\s*{_ATOM}(?:\s*[*·/]\s*{_ATOM}|\s+{_ATOM})*\s*\)(?:{_POWER})?"
_TERM = rf"(?:{_ATOM}|{_GROUP})"
#: The unit-expression grammar (applied to at most MAX_UNIT_CHARS characters: linear time).
_UNIT = re.compile(rf"(?:1\s*/\s*)?{_TERM}(?:\s*[*·/]\s*{_TERM}|\s+{_TERM})*")

#: What a value must look like, for messages.
SYNTAX = "a number and a unit such as '5 kN'"


@lru_cache(maxsize=1)
def registry() -> pint.UnitRegistry:
    """The one pint registry (pint is imported and the registry built on first use: both are slow).

    ``Nm`` and ``Nmm`` are the engineer's newton-metre and newton-millimetre (torque, moment); pint's
    own ``Nm`` is the obscure "number metre" ([length]/[mass]), which made ``M_y = "5 Nm"`` an error.
    """
    import pint

    reg = pint.UnitRegistry(autoconvert_offset_to_baseunit=True, on_redefinition="ignore")
    reg.define("newton_metre = newton * meter = Nm")
    reg.define("newton_millimetre = newton * millimeter = Nmm")
    return reg


@lru_cache(maxsize=1024)
def _unit(text: str):
    """The pint unit of a unit expression that passed :data:`_UNIT`, or the name of pint's error."""
    try:
        return registry().parse_units(text.replace("·", "*"))
    except Exception as exc:  # pint raises several types; the caller words one line
        return type(exc).__name__


def parse(value, dimension: str, field: str) -> float:
    """Parse ``value`` (``"5 kN"``) to a float in the SI unit of ``dimension``.

    Parameters
    ----------
    value : str or number
        The text with its unit (syntax in the module docstring). A bare number (or a string holding
        only a number) is accepted only for ``dimension="dimensionless"``.
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
        One line naming the field, the value (shortened) and the expectation, for text outside the
        accepted syntax, a missing or unknown unit, a wrong dimension (with look-alike units of the
        right one) or a non-finite number.
    """
    if dimension not in SI_UNITS:
        raise InputError(f"{field}: unknown dimension {dimension!r}; expected one of {sorted(SI_UNITS)}")
    target = SI_UNITS[dimension]
    words = dimension.replace("_", " ")
    article = "an" if words[0] in "aeiou" else "a"
    suggested = SUGGESTED_UNITS.get(dimension, target)
    if isinstance(value, bool):
        raise InputError(f"{field} ({value!r}) must be a quantity with a unit of {words} (e.g. '1 {target}')")
    if isinstance(value, (int, float)):
        if dimension == "dimensionless":
            return _finite(value, field, value)
        raise InputError(
            f"{field} ({quote(value)}) has no unit; "
            f"expected {article} {words} such as '{quote(value)} {suggested}'"
        )
    if not isinstance(value, str):
        raise InputError(f"{field} ({quote(value)}) must be a string with a unit, e.g. '1 {target or '1'}'")
    known = _PARSED.get((value, dimension))
    if known is not None:  # studies rebuild inputs from the same texts thousands of times
        return known
    number, unit_text = _split(value, field, dimension)
    if not unit_text:
        if dimension == "dimensionless":
            return _remember(value, dimension, _finite(number, field, value))
        raise InputError(
            f"{field} ({quote(value)}) has no unit; "
            f"expected {article} {words} such as '{value.strip()} {suggested}'"
        )
    common = COMMON_UNITS.get(dimension, {}).get(unit_text)
    if common is not None:  # pint's own conversion, without loading pint
        out = _finite(number * common[0] + common[1], field, value)
        return _remember(value, dimension, _above_absolute_zero(out, dimension, field, value))
    unit = _unit(unit_text)
    if isinstance(unit, str):
        raise InputError(
            f"{field} ({quote(value)}): unknown unit {unit_text!r}; expected a {words or 'pure number'}"
            f"{_suggestion(value, unit_text, dimension)}"
        )
    import pint  # already loaded by _unit's registry()

    quantity = registry().Quantity(number, unit)
    try:
        out = quantity.to(target).magnitude if target else quantity.to("").magnitude
    except pint.DimensionalityError:
        got = "dimensionless" if quantity.dimensionless else str(quantity.dimensionality)
        expected = f"a {words} (convertible to {target})" if target else "a pure number (no unit)"
        raise InputError(
            f"{field} ({quote(value)}) has dimension {got}; expected {expected}"
            f"{_suggestion(value, unit_text, dimension)}"
        ) from None
    except OverflowError:
        raise InputError(f"{field} ({quote(value)}) must be finite (it overflows in {target})") from None
    out = _finite(out, field, value)
    return _remember(value, dimension, _above_absolute_zero(out, dimension, field, value))


def _above_absolute_zero(out: float, dimension: str, field: str, value) -> float:
    """``out`` [°C for a temperature], refused below absolute zero (both conversion paths: the common
    units without pint, and pint's)."""
    if dimension == "temperature" and out < ABSOLUTE_ZERO_C:
        raise InputError(
            f"{field} ({quote(value)}) lies below absolute zero ({ABSOLUTE_ZERO_C} degC); expected an "
            "operating temperature such as '60 degC'"
        )
    return out


#: Absolute zero [°C]: the lowest temperature a ``temperature`` value may have (a value below it
#: used to pass wherever no lubricant's viscosity law looked at it).
ABSOLUTE_ZERO_C = -273.15


#: Texts already parsed, (text, dimension) → SI value (successful parses only; errors name their field).
_PARSED: dict[tuple[str, str], float] = {}
#: Most remembered texts (a bound on the memory an untrusted input can take: at most
#: 65,536 × (MAX_VALUE_CHARS + ~100 B) ≈ 11 MB).
_PARSED_MAX = 65536


def _remember(text: str, dimension: str, value: float) -> float:
    if len(_PARSED) < _PARSED_MAX:
        _PARSED[(text, dimension)] = value
    return value


def is_number(text: str) -> bool:
    """Whether ``text`` is a decimal number in the accepted syntax (``"9"``, ``"-1.5e3"``), nothing more."""
    return len(text) <= MAX_VALUE_CHARS and re.fullmatch(_NUMBER, text.strip()) is not None


def _split(value: str, field: str, dimension: str) -> tuple[float, str]:
    """(number, unit text) of a value string that passes the syntax check; InputError otherwise."""
    if len(value) > MAX_VALUE_CHARS:
        raise InputError(
            f"{field} ({quote(value)}) is too long ({len(value)} characters, at most {MAX_VALUE_CHARS}); "
            f"expected {SYNTAX}"
        )
    match = _VALUE.fullmatch(value)
    if match is None:
        if _NON_FINITE.fullmatch(value):
            raise InputError(f"{field} ({quote(value)}) must be finite")
        example = "a number such as 0.52" if dimension == "dimensionless" else SYNTAX
        raise InputError(f"{field} ({quote(value)}) is not {example}")
    unit_text = match["unit"]
    if unit_text and (len(unit_text) > MAX_UNIT_CHARS or _UNIT.fullmatch(unit_text) is None):
        raise InputError(
            f"{field} ({quote(value)}): {quote(unit_text, 20)} is not a unit expression (unit names "
            f"joined by *, / or a space, integer powers ^2; at most {MAX_UNIT_CHARS} characters); "
            f"expected {SYNTAX}"
        )
    return float(match["number"]), unit_text


def _suggestion(value: str, unit_text: str, dimension: str) -> str:
    """``"; did you mean '2 kN'?"`` from the look-alike units of ``dimension`` (empty when none is near)."""
    candidates = UNIT_LOOKALIKES.get(dimension, ())
    key = _squash(unit_text)
    near = [c for c in candidates if _squash(c) == key]
    if not near:
        squashed = {_squash(c): c for c in candidates}
        near = [squashed[k] for k in difflib.get_close_matches(key, list(squashed), n=2, cutoff=0.75)]
    if not near:
        return ""
    number = value.strip()[: len(value.strip()) - len(unit_text)].strip()
    return "; did you mean " + " or ".join(f"'{number} {c}'" for c in near) + "?"


def _squash(unit_text: str) -> str:
    """Lower case without multiplication signs and spaces: 'kn' ~ 'kN', 'Nm' ~ 'N*m'."""
    return re.sub(r"[*·\s]", "", unit_text).lower()


def _finite(x, field: str, raw) -> float:
    try:
        out = float(x)
    except OverflowError:  # an integer beyond the float range
        raise InputError(f"{field} ({quote(raw)}) must be finite (it is beyond the float range)") from None
    if out != out or out in (float("inf"), float("-inf")):
        raise InputError(f"{field} ({quote(raw)}) must be finite")
    return out


def format_si(value: float, dimension: str) -> str:
    """Format an SI float with its unit, for messages and reports."""
    return f"{value:.6g} {SI_UNITS[dimension]}".rstrip()
