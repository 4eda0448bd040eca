"""Validation helpers for frozen dataclasses and physics inputs.

Each helper raises :class:`bearingkit.errors.InputError` (a ``ValueError``) with a one-line
message that names the field, shows the value and says what was expected. Values are SI.
"""

from __future__ import annotations

import math

import numpy as np

from bearingkit.errors import InputError


def _fmt(value) -> str:
    arr = np.asarray(value, dtype=float)
    if arr.ndim == 0:
        return f"{float(arr):.6g}"
    bad = arr.ravel()
    return f"array(shape={arr.shape}, min={np.nanmin(bad):.6g}, max={np.nanmax(bad):.6g})"


def _shown(value, unit: str) -> str:
    """The value and its unit as a message shows them: "2", "2 mm" (no space left by an empty unit)."""
    return f"{_fmt(value)} {unit}".rstrip()


def scalar_or_array(x):
    """``x`` as float: 0-d arrays come back as numpy scalars, everything else as arrays."""
    x = np.asarray(x, dtype=float)
    return x[()] if x.ndim == 0 else x


def _floats(value) -> np.ndarray:
    # Called ~100 times per batched physics call: skip asarray for what already is a float array.
    if type(value) is np.ndarray and value.dtype == np.float64:
        return value
    return np.asarray(value, dtype=float)


def _all_finite(arr: np.ndarray) -> bool:
    return bool(np.isfinite(arr).all())


def finite(field: str, value, unit: str = ""):
    """Require finite values; return ``value`` unchanged."""
    ok = math.isfinite(value) if type(value) is float else _all_finite(_floats(value))
    if not ok:
        raise InputError(f"{field} ({_shown(value, unit)}) must be finite")
    return value


def positive(field: str, value, unit: str = ""):
    """Require finite values > 0."""
    finite(field, value, unit)
    if not (value > 0 if type(value) is float else (_floats(value) > 0).all()):
        raise InputError(f"{field} ({_shown(value, unit)}) must be positive")
    return value


def non_negative(field: str, value, unit: str = ""):
    """Require finite values >= 0."""
    finite(field, value, unit)
    if not (value >= 0 if type(value) is float else (_floats(value) >= 0).all()):
        raise InputError(f"{field} ({_shown(value, unit)}) must be non-negative")
    return value


def in_range(field: str, value, low: float, high: float, unit: str = "", *, closed: bool = True):
    """Require ``low <= value <= high`` (or strict when ``closed`` is False)."""
    finite(field, value, unit)
    arr = _floats(value)
    ok = (arr >= low) & (arr <= high) if closed else (arr > low) & (arr < high)
    if not ok.all():
        br = "[]" if closed else "()"
        raise InputError(f"{field} ({_shown(value, unit)}) must lie in {br[0]}{low:g}, {high:g}{br[1]}")
    return value


def greater(field: str, value, other_field: str, other, unit: str = ""):
    """Require ``value > other`` elementwise, naming both fields."""
    finite(field, value, unit)
    if not np.all(np.asarray(value, dtype=float) > np.asarray(other, dtype=float)):
        raise InputError(f"{field} ({_shown(value, unit)}) must exceed {other_field} ({_shown(other, unit)})")
    return value


def one_of(field: str, value: str, choices) -> str:
    """Require ``value`` to be one of ``choices`` (a registry's names)."""
    if value not in choices:
        raise InputError(f"{field} ({value!r}) must be one of {', '.join(sorted(map(str, choices)))}")
    return value


def integer(field: str, value, low: int = 1) -> int:
    """Require an integer >= ``low``."""
    if isinstance(value, bool) or not float(value).is_integer() or value < low or math.isinf(value):
        raise InputError(f"{field} ({value!r}) must be an integer >= {low}")
    return int(value)
