"""Settings of a bearing rating (:func:`bearingkit.analysis.rating.rate`), validated on construction.

SI units throughout: speeds in rad/s, loads in N; temperatures in °C (``temperature_C``, as in
:mod:`bearingkit.lubricants`). Shared by the rating assembly and the per-row raters
(:mod:`bearingkit.analysis.rating_rows`). ISO 281:2007 (reliability, e_C), ISO/TS 16281:2008 (edge-stress
factor).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from bearingkit import checks
from bearingkit.errors import InputError

__all__ = ["DEFAULT_EDGE_PRESSURE_RATIO", "DEFAULT_SHOULDER_HEIGHT", "EDGE_STRESS_MODES", "RatingOptions"]

#: Shoulder (land) height of a ball groove above the groove bottom, as a fraction of the ball diameter
#: [-]. Not stored on the rows; an assumed, deliberately shallow value (deep groove rings are made with
#: groove depths of roughly 0.2–0.3 D_w), so the truncation warning errs on the safe side. Valid
#: 0 < h/D_w < f (the groove radius over D_w).
DEFAULT_SHOULDER_HEIGHT = 0.20
#: Edge-loading criterion for roller rows [-]: a roller end slice whose Hertz pressure reaches this
#: fraction of the row's largest slice pressure means the contact runs to the roller end, where the real
#: pressure has an edge peak the slice model does not resolve. Engineering choice; valid (0, 1].
DEFAULT_EDGE_PRESSURE_RATIO = 0.8

#: When the ISO/TS 16281 edge-stress factor f_k multiplies the slice loads: ``"auto"`` for rollers
#: without a crowning profile (profile None), ``"always"``, ``"never"``.
EDGE_STRESS_MODES = ("auto", "always", "never")


@dataclass(frozen=True)
class RatingOptions:
    """Settings of :func:`rate` (validated on construction).

    Parameters
    ----------
    rotating : {"inner", "outer"}
        Ring rotating relative to the load (ISO/TS 16281 equivalent-load means).
    reliability : float
        Reliability of the L_nr / L_nmr lives [-], 0.90 … 0.9995 (ISO 281 Table 12).
    speed : float or ndarray (C,) or None [rad/s]
        Relative speed of the rotating ring; lives in hours and κ need it.
    lubricant : Lubricant or str or None
        Lubricant for κ (:func:`bearingkit.lubricants.as_lubricant`).
    temperature_C : float or ndarray (C,) or None [°C]
        Operating temperature for the lubricant viscosity.
    contamination_factor : float or ndarray (C,) or None [-]
        e_C of ISO 281 9.3.3, 0 … 1.
    shoulder_height : float or Mapping[str, float]
        Groove shoulder height / D_w [-] (per row name if a mapping), see :data:`DEFAULT_SHOULDER_HEIGHT`.
    edge_pressure_ratio : float
        See :data:`DEFAULT_EDGE_PRESSURE_RATIO`.
    edge_stress_factor : str
        One of :data:`EDGE_STRESS_MODES`.
    load_ratings : Mapping[str, float]
        Basic dynamic load rating C [N] per row name, replacing the ISO 281 computation (catalogue values,
        or rows whose ISO 281 factors are not shipped, e.g. thrust cylindrical rollers).
    """

    rotating: str = "inner"
    reliability: float = 0.9
    speed: object = None
    lubricant: object = None
    temperature_C: object = None
    contamination_factor: object = None
    shoulder_height: object = DEFAULT_SHOULDER_HEIGHT
    edge_pressure_ratio: float = DEFAULT_EDGE_PRESSURE_RATIO
    edge_stress_factor: str = "auto"
    load_ratings: Mapping = field(default_factory=dict)

    def __post_init__(self):
        checks.one_of("rotating", self.rotating, ("inner", "outer"))
        checks.in_range("reliability", self.reliability, 0.9, 0.9995)
        if self.speed is not None:
            checks.positive("speed", self.speed, "rad/s")
        heights = self.shoulder_height
        for value in heights.values() if isinstance(heights, Mapping) else (heights,):
            checks.positive("shoulder_height", value)
        checks.in_range("edge_pressure_ratio", self.edge_pressure_ratio, 0.0, 1.0)
        checks.positive("edge_pressure_ratio", self.edge_pressure_ratio)
        checks.one_of("edge_stress_factor", self.edge_stress_factor, EDGE_STRESS_MODES)
        for name, c in self.load_ratings.items():
            checks.positive(f"load_ratings[{name!r}]", c, "N")
        lube = (self.lubricant, self.temperature_C, self.contamination_factor)
        given = [v is not None for v in lube]
        if any(given) and not all(given):
            missing = [
                n
                for n, g in zip(("lubricant", "temperature_C", "contamination_factor"), given, strict=True)
                if not g
            ]
            raise InputError(
                f"{', '.join(missing)} (None) must be given with the other life-modification inputs "
                "(lubricant, temperature_C, contamination_factor) for a_ISO"
            )
        if all(given):
            if self.speed is None:
                raise InputError("speed (None) must be given for a_ISO: the viscosity ratio κ needs it")
            checks.in_range("contamination_factor", self.contamination_factor, 0.0, 1.0)

    @property
    def modified(self) -> bool:
        """True when a_ISO is requested (lubricant, temperature and contamination given)."""
        return self.lubricant is not None
