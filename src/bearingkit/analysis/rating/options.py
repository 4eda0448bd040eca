"""Settings of a bearing rating (:func:`bearingkit.analysis.rating.assembly.rate`), validated on construction.

SI units throughout: speeds in rad/s, loads in N; temperatures in °C (``temperature_C``, as in
:mod:`bearingkit.lubricants`). Shared by the rating assembly and the per-row raters
(:mod:`bearingkit.analysis.rating.rows`). ISO 281:2007 (reliability, e_C), ISO/TS 16281:2008 (edge-stress
factor).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from bearingkit import checks
from bearingkit.errors import InputError

__all__ = [
    "DEFAULT_EDGE_PRESSURE_RATIO",
    "DEFAULT_SHOULDER_HEIGHT",
    "DEFAULT_SHOULDER_HEIGHTS",
    "EDGE_STRESS_MODES",
    "RatingOptions",
    "shoulder_heights",
]

#: Shoulder (land) height of a ball groove above the groove bottom, as a fraction of the ball diameter
#: [-], of deep groove rings and whatever kind :data:`DEFAULT_SHOULDER_HEIGHTS` does not list. Not stored on
#: the rows (input files may set it: ``shoulder_height_inner``/``_outer``). [from memory] deep groove rings
#: have groove depths of roughly 0.2–0.3 D_w; the shallow end makes the truncation warning err on the safe
#: side. Valid 0 < h/D_w < f (the groove radius over D_w).
DEFAULT_SHOULDER_HEIGHT = 0.20
#: Default shoulder heights (inner, outer) / D_w per bearing type [-] when neither the input nor the caller
#: gives them. No standard or catalogue publishes them (ISO 15 fixes only the boundary dimensions); values
#: [from memory] of ring designs, checked for consistency, not sourced:
#: - deep groove and thrust ball (both shoulders alike): 0.20, as :data:`DEFAULT_SHOULDER_HEIGHT`;
#: - angular contact ball (single, pairs): the *high* shoulder on the loaded side, 0.35 — consistent with a
#:   ring made to carry its static rating: a 40° contact's ellipse at the ISO 76 limit stress (4200 MPa,
#:   D_w 12.7 mm, d_m 65 mm) spans θ_a = 32° (f_i = 0.52) / 27° (f_o = 0.53), so it stays on the groove for
#:   h ≥ 0.36 / 0.32 D_w (θ_s = arccos(1 − h/r)); the low shoulder is never reached by a one-sided row;
#: - four-point (QJ, slewing rings; measured from the arch seam): 0.40 — the contact angle of a slewing
#:   ring rises by ~10° under tilting moment (45° → 52-55° in the examples), so its arches are deeper than
#:   an angular contact groove (the limit-stress ellipse at 45° alone needs 0.35 D_w);
#: - self-aligning ball: inner grooves 0.20 (the outer raceway is a sphere: no shoulder).
DEFAULT_SHOULDER_HEIGHTS = {
    "deep_groove_ball": (0.20, 0.20),
    "thrust_ball": (0.20, 0.20),
    "angular_contact_ball": (0.35, 0.35),
    "four_point": (0.40, 0.40),
    "self_aligning_ball": (0.20, None),
}
#: Edge-loading criterion for roller rows [-]: a roller end slice whose Hertz pressure reaches this
#: fraction of the row's largest slice pressure means the contact runs to the roller end, where the real
#: pressure has an edge peak the slice model does not resolve. Engineering choice; valid (0, 1].
DEFAULT_EDGE_PRESSURE_RATIO = 0.8

#: When the ISO/TS 16281 edge-stress factor f_k (eq. (60)) multiplies the slice loads: ``"auto"`` (the
#: default) and ``"always"`` on every sliced roller row (n_s >= 2), ``"never"`` not at all. The TS states
#: eq. (60) for rollers with its own logarithmic profile (eqs. (42)-(44), the profile of catalogue rows),
#: under medium load and a misalignment below 4'; for other profiles it asks for the pressure-based factors
#: of eqs. (58)-(59), which bearingkit does not have, so eq. (60) stands in there (the rater notes it).
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
    shoulder_height : None, float or Mapping[str, float or (float, float)]
        Groove shoulder height / D_w [-]: one value for every ball groove, or per row name a value or an
        (inner, outer) pair; None (and rows a mapping leaves out) take the kind's default
        (:data:`DEFAULT_SHOULDER_HEIGHTS`). Each in (0, 1); the raters also check it against the groove.
    edge_pressure_ratio : float
        See :data:`DEFAULT_EDGE_PRESSURE_RATIO`.
    edge_stress_factor : str
        One of :data:`EDGE_STRESS_MODES`.
    load_ratings : Mapping[str, float]
        Basic dynamic load rating C [N] per row name, replacing the ISO 281 computation (catalogue values,
        or rows whose ISO 281 factors are not shipped, e.g. thrust cylindrical rollers).
    catalogue_ratings : Mapping[str, float]
        C [N] per row derived from the catalogue C of the bearing (set by :func:`rate` for a designation,
        :func:`bearingkit.analysis.rating.iso281.catalogue_row_ratings`); used like ``load_ratings`` but
        not reported as the user's.
    static_limit_factor : float
        Multiplies ISO 76's limit pressures in s0 [-], (0, 1.5]: the raceway material's share (1 for rings
        of at least 58 HRC; :meth:`bearingkit.hardness.HardnessProfile.limit_factor`).
    """

    rotating: str = "inner"
    reliability: float = 0.9
    speed: object = None
    lubricant: object = None
    temperature_C: object = None
    contamination_factor: object = None
    shoulder_height: object = None
    edge_pressure_ratio: float = DEFAULT_EDGE_PRESSURE_RATIO
    edge_stress_factor: str = "auto"
    load_ratings: Mapping = field(default_factory=dict)
    catalogue_ratings: Mapping = field(default_factory=dict)
    static_limit_factor: float = 1.0

    def __post_init__(self):
        checks.one_of("rotating", self.rotating, ("inner", "outer"))
        checks.in_range("reliability", self.reliability, 0.9, 0.9995)
        if self.speed is not None:
            checks.positive("speed", self.speed, "rad/s")
        heights = self.shoulder_height
        for value in heights.values() if isinstance(heights, Mapping) else (heights,):
            pair = value if isinstance(value, (tuple, list)) else (value,)
            for v in pair:
                if v is not None:
                    checks.in_range("shoulder_height (/ D_w)", v, 0.0, 1.0, closed=False)
        checks.in_range("edge_pressure_ratio", self.edge_pressure_ratio, 0.0, 1.0)
        checks.positive("edge_pressure_ratio", self.edge_pressure_ratio)
        checks.one_of("edge_stress_factor", self.edge_stress_factor, EDGE_STRESS_MODES)
        checks.in_range("static_limit_factor", self.static_limit_factor, 0.0, 1.5)
        checks.positive("static_limit_factor", self.static_limit_factor)
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


def shoulder_heights(options: RatingOptions, row_name: str, bearing_type: str) -> tuple:
    """(inner, outer) shoulder heights / D_w [-] of a ball row: the caller's, else the kind's default.

    Parameters
    ----------
    options : RatingOptions
    row_name : str
        Row name (key of a per-row mapping).
    bearing_type : str
        Key of :data:`DEFAULT_SHOULDER_HEIGHTS` (others take :data:`DEFAULT_SHOULDER_HEIGHT` for both).
    """
    h = options.shoulder_height
    if isinstance(h, Mapping):
        h = h.get(row_name)
    default = DEFAULT_SHOULDER_HEIGHTS.get(bearing_type, (DEFAULT_SHOULDER_HEIGHT, DEFAULT_SHOULDER_HEIGHT))
    if h is None:
        return default
    pair = tuple(h) if isinstance(h, (tuple, list)) else (h, h)
    return tuple(d if v is None or d is None else float(v) for v, d in zip(pair, default, strict=True))
