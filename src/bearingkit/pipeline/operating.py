"""Operating conditions of an analysis, per load case: speed, temperature, lubricant, life settings.

SI inside (rad/s, °C for temperatures as :mod:`bearingkit.lubricants` uses them). Values given as text
carry their unit (``"3000 rpm"``, ``"60 degC"``) and are parsed here, at the edge.

Sign of speed (one rule for every face): ``speed`` is the angular velocity of the *rotating* ring
(``rotating = "inner"`` or ``"outer"``) relative to the other ring, about the bearing axis +z,
positive counter-clockwise seen from +z (right-hand rule). The sign is the direction of rotation: it
sets the sign of the friction torques on the rings and nothing else; lives, κ, film thickness and
power loss use |speed|. Zero means at rest: lives in hours, κ and the speed-dependent friction are
then not available and say so.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError, quote
from bearingkit.units import parse

__all__ = ["DEFAULT_TEMPERATURE", "ROTATING_RINGS", "Operating"]

#: Operating temperature [°C] when neither the load case nor the caller gives one (room temperature,
#: the default of :class:`bearingkit.analysis.friction.components.OperatingPoint`).
DEFAULT_TEMPERATURE = 25.0
#: Which ring turns relative to the load.
ROTATING_RINGS = ("inner", "outer")


def _value(value, dimension: str, field: str):
    """None, a text with its unit, a number, or one number per case (array) — in SI."""
    if value is None:
        return None
    if isinstance(value, str):
        return parse(value, dimension, field)
    arr = np.asarray(checks.finite(field, value), dtype=float)
    return float(arr) if arr.ndim == 0 else arr


def _per_case(value, n: int, field: str):
    """A per-case array (n,) of ``value`` when it is one; None stays None, scalars stay scalars."""
    if value is None or np.ndim(value) == 0:
        return value
    arr = np.asarray(value, dtype=float).ravel()
    if arr.shape != (n,):
        raise InputError(f"{field} ({arr.shape[0]} values) must give one value per load case ({n})")
    return arr


@dataclass(frozen=True)
class Operating:
    """Per-case operating conditions (C = number of load cases).

    Attributes
    ----------
    speed : ndarray (C,) [rad/s]
        Signed speed of the rotating ring (module docstring); 0 = at rest.
    temperature : ndarray (C,) [°C]
        Operating temperature (:data:`DEFAULT_TEMPERATURE` where none was given).
    temperature_given : ndarray (C,) of bool
        Whether the temperature came from the user (a_ISO needs a given one).
    rotating : str
        ``"inner"`` or ``"outer"``.
    lubricant : Lubricant or None
    contamination : float or None [-]
        ISO 281 e_C; with a lubricant and given temperatures it gives a_ISO and L_nm.
    reliability : float [-]
        Reliability of L_nr (0.9 … 0.9995).
    """

    speed: np.ndarray
    temperature: np.ndarray
    temperature_given: np.ndarray
    rotating: str = "inner"
    lubricant: object = None
    contamination: float | None = None
    reliability: float = 0.9

    def __post_init__(self):
        checks.one_of("rotating", self.rotating, ROTATING_RINGS)
        checks.in_range("reliability", self.reliability, 0.9, 0.9995)
        if self.contamination is not None:
            checks.in_range("contamination", self.contamination, 0.0, 1.0)

    @property
    def n_cases(self) -> int:
        return self.speed.shape[0]

    @property
    def abs_speed(self) -> np.ndarray:
        """|speed| (C,) [rad/s]: what lives, κ and power loss use."""
        return np.abs(self.speed)

    @classmethod
    def of(
        cls,
        bearing,
        *,
        speed=None,
        temperature=None,
        rotating: str = "inner",
        lubricant=None,
        contamination=None,
        reliability=0.9,
    ) -> Operating:
        """Operating conditions of ``bearing``'s load cases, the arguments overriding the cases' values.

        Parameters
        ----------
        bearing : BearingInput
        speed : float [rad/s], str with unit, or array (C,), optional
            Speed of the rotating ring for every case, or one per case (else each case's ``speed``,
            else 0).
        temperature : float [°C], str with unit, or array (C,), optional
            For every case or one per case (else each case's ``temperature``, else
            :data:`DEFAULT_TEMPERATURE`).
        rotating : {"inner", "outer"}
        lubricant : str or Lubricant, optional
            A preset name (:data:`bearingkit.lubricants.LUBRICANTS`); default: the file's ``[lubricant]``.
        contamination : float or str, optional
            ISO 281 e_C, 0 … 1.
        reliability : float or str
            0.9 … 0.9995.
        """
        from bearingkit.lubricants import as_lubricant

        cases = bearing.cases
        n = len(cases)
        s_all = _per_case(_value(speed, "angular_velocity", "speed"), n, "speed")
        t_all = _per_case(_value(temperature, "temperature", "temperature"), n, "temperature")
        own_speed = np.array([c.speed or 0.0 for c in cases], float)
        speeds = own_speed if s_all is None else np.broadcast_to(s_all, (n,)).astype(float)
        own_temp = np.array([DEFAULT_TEMPERATURE if c.temperature is None else c.temperature for c in cases])
        temps = own_temp.astype(float) if t_all is None else np.broadcast_to(t_all, (n,)).astype(float)
        given = np.array([t_all is not None or c.temperature is not None for c in cases], bool)
        lube = bearing.lubricant if lubricant is None else as_lubricant(lubricant)
        e_c = _value(contamination, "dimensionless", "contamination")
        rel = _value(reliability, "dimensionless", "reliability")
        if rotating not in ROTATING_RINGS:
            raise InputError(f"rotating ({rotating!r}) must be one of {', '.join(ROTATING_RINGS)}")
        check_speeds(bearing, speeds, [c.name for c in cases])
        return cls(speeds.reshape(n), temps, given, rotating, lube, e_c, rel)

    def to_dict(self, case: int) -> dict:
        """JSON-ready operating point of one case (SI, units in keys)."""
        return {
            "speed_rad_s": float(self.speed[case]),
            "rotating_ring": self.rotating,
            "temperature_C": float(self.temperature[case]),
            "temperature_given": bool(self.temperature_given[case]),
            "lubricant": None if self.lubricant is None else self.lubricant.name,
            "contamination_factor": self.contamination,
            "reliability": self.reliability,
        }


#: Largest speed factor n·d_m a case may ask for [m·rad/s]: 5·10⁶ mm/min (n in rpm, d_m in mm), above
#: the 3–3.5·10⁶ mm/min of the fastest hybrid spindle bearings in makers' catalogues (from memory: no
#: catalogue at hand) and far above any steel bearing's. Beyond it no rolling bearing runs, and the
#: speed models solve forces of elements at tens of thousands of g (a 6209 at 10⁹ rpm: 15 s, then a
#: misleading Newton message).
MAX_SPEED_FACTOR = 5e6 * 1e-3 * 2.0 * np.pi / 60.0


def check_speeds(bearing, speeds, names) -> None:
    """Refuse a case whose |speed| × pitch diameter passes :data:`MAX_SPEED_FACTOR` (one line)."""
    speeds = np.abs(np.asarray(speeds, float)).reshape(-1)
    if not speeds.size or not speeds.max() > 0.0:
        return
    diameters = [
        np.max(r.pitch_diameter) for r in getattr(bearing.model, "rows", ()) if hasattr(r, "pitch_diameter")
    ]
    d_m = float(max(diameters)) if diameters else 0.0
    if not d_m > 0.0:
        return
    worst = int(np.argmax(speeds))
    if float(speeds[worst]) * d_m > MAX_SPEED_FACTOR:
        rpm = float(speeds[worst]) / (2.0 * np.pi / 60.0)  # Python floats: no overflow warning
        name = names[worst] if worst < len(names) else worst
        raise InputError(
            f"load case {quote(name)}: speed ({rpm:.4g} rpm) gives n·d_m = {rpm * d_m * 1e3:.3g} mm/min; "
            f"expected at most {MAX_SPEED_FACTOR * 60e3 / (2.0 * np.pi):.3g} mm/min (beyond every rolling "
            "bearing)"
        )
