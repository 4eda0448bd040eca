"""Display units of study tables and plots: SI values shown in the units an engineer reads.

SI in (every factor and output column holds SI values); out a unit label and the factor that converts
to it (µm for clearances, kN for loads, MPa for pressures, r/min for speeds, 10⁶ rev for lives …),
chosen from the column's dimension or unit and the size of its values. Axis labels name the factor or
output and the display unit: ``geometry.clearance_radial [µm]``.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["axis_label", "column_unit", "display", "scale_for"]

#: SI unit → (display unit, factor) by the size of the values (largest |value| below the bound).
_CHOICES = {
    "m": ((1e-3, "µm", 1e6), (1.0, "mm", 1e3), (math.inf, "m", 1.0)),
    "N": ((1e3, "N", 1.0), (1e6, "kN", 1e-3), (math.inf, "MN", 1e-6)),
    "N*m": ((1e3, "N·m", 1.0), (math.inf, "kN·m", 1e-3)),
    "N·m": ((1e3, "N·m", 1.0), (math.inf, "kN·m", 1e-3)),
    "Pa": ((1e10, "MPa", 1e-6), (math.inf, "GPa", 1e-9)),
    "rad": ((0.02, "mrad", 1e3), (math.inf, "deg", 180.0 / math.pi)),
    "rad/s": ((math.inf, "r/min", 30.0 / math.pi),),
    "N/m": ((math.inf, "N/µm", 1e-6),),
    "N/rad": ((math.inf, "N/mrad", 1e-3),),
    "N·m/rad": ((math.inf, "N·m/mrad", 1e-3),),
    "rev": ((math.inf, "10⁶ rev", 1e-6),),
    "h": ((math.inf, "h", 1.0),),
    "W": ((1e3, "W", 1.0), (math.inf, "kW", 1e-3)),
    "degC": ((math.inf, "°C", 1.0),),
    "kg/m^3": ((math.inf, "kg/m³", 1.0),),
    "kg": ((math.inf, "kg", 1.0),),
}
#: Dimension (of a factor) → SI unit (:data:`bearingkit.units.SI_UNITS` with the display spellings).
_DIMENSION_UNITS = {
    "length": "m",
    "force": "N",
    "moment": "N·m",
    "pressure": "Pa",
    "angle": "rad",
    "angular_velocity": "rad/s",
    "temperature": "degC",
    "density": "kg/m^3",
    "mass": "kg",
    "stiffness": "N/m",
    "rotational_stiffness": "N·m/rad",
}
#: Output-name suffix → SI unit (outputs name their unit: ``max_load_N``, ``k_xx_N_per_m``).
_SUFFIXES = (
    ("_Nm_per_rad", "N·m/rad"),
    ("_N_per_rad", "N/rad"),
    ("_N_per_m", "N/m"),
    ("_Nm", "N·m"),
    ("_N", "N"),
    ("_Pa", "Pa"),
    ("_rad_s", "rad/s"),
    ("_rad", "rad"),
    ("_m", "m"),
    ("_rev", "rev"),
    ("_h", "h"),
    ("_W", "W"),
    ("_C", "degC"),
)


def column_unit(name: str, dimension: str | None = None) -> str | None:
    """The SI unit of a column: from a factor's ``dimension``, else from the output name's suffix."""
    if dimension is not None:
        return _DIMENSION_UNITS.get(dimension)
    for suffix, unit in _SUFFIXES:
        if name.endswith(suffix):
            return unit
    return None


def scale_for(unit: str | None, values) -> tuple[str, float]:
    """(display unit, factor) for SI ``values`` of ``unit`` (``("", 1.0)`` when none applies)."""
    if unit not in _CHOICES:
        return ("" if unit in (None, "-") else unit), 1.0
    v = np.abs(np.asarray(values, dtype=float))
    big = float(np.nanmax(v)) if v.size and np.isfinite(v).any() else 0.0
    for bound, label, factor in _CHOICES[unit]:
        if big < bound:
            return label, factor
    return _CHOICES[unit][-1][1:]


def display(name: str, values, dimension: str | None = None) -> tuple[np.ndarray, str]:
    """``values`` in display units and the axis label ``name [unit]`` (an output's SI suffix dropped:
    ``k_zz_N_per_m`` → ``k_zz [N/µm]``)."""
    unit = column_unit(name, dimension)
    label, factor = scale_for(unit, values)
    shown = np.asarray(values, dtype=float) * factor
    if dimension is None and unit is not None:
        name = next(name[: -len(s)] for s, u in _SUFFIXES if name.endswith(s))
    return shown, axis_label(name, label)


def axis_label(name: str, unit: str) -> str:
    """``name [unit]`` (``name`` alone without a unit)."""
    return f"{name} [{unit}]" if unit else name
