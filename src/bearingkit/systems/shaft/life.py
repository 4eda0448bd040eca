"""Ratings, lives and friction of every bearing of a shaft, and the system life.

SI units; lives in revolutions of the shaft (``*_rev``) and hours (``*_h``, at the cases' speed).
Each bearing is rated at its seat state by the bearing API (:func:`bearingkit.analysis.rating.assembly.rate`,
ISO 76 / ISO 281 / ISO/TS 16281, inner ring rotating with the shaft). The system life combines the
bearings as independently failing Weibull members (ISO 281:2007 eq. (7) and (12) slopes; Lundberg &
Palmgren 1947, 1952; Harris & Kotzalas 2007 vol. 2 ch. 8):

    L_sys = (Σ_i L_i^(−e))^(−1/e)     (one slope e: 10/9 balls, 9/8 rollers),

computed by :func:`bearingkit.analysis.rating.assembly.system_life` over the rows of all bearings, which for
rows of one slope per bearing is exactly this formula over the bearings and solves the Weibull
equation Σ (L_sys/L_i)^e_i = 1 when ball and roller bearings are mixed. :func:`combine_ratings` does
the combination for bearings already rated (the shaft's pipeline analyses,
:mod:`bearingkit.systems.shaft.shaft_analysis`), also for the modified lives L_nm (at 90 % reliability, then
times a1: the practice of system calculations, an assumption, as ISO 281 defines L_nm per bearing).

The ISO 281 system life (shown first, as the single bearing's ISO 281 life is) combines the bearings' ISO 281
L10 and L_nm (:class:`bearingkit.analysis.rating.iso281.Iso281Life`) by the same Weibull rule, one member
per bearing with the slope of its rows (10/9 ball, 9/8 roller: the slopes of the ISO/TS 16281 system life
above), :func:`iso281_system_life`. It is masked where a loaded bearing has no ISO 281 life (a bearing ISO
281 does not rate: slewing rings, composites, threaded rows).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit.analysis.rating.assembly import HOUR, system_life
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.physics.life import iso281

#: How the system lives are combined (every face that shows them can say so).
WEIBULL_RULE = (
    "Weibull: sum (L_sys/L_i)^e_i = 1 over the bearings (ISO 281) or their rows (ISO/TS 16281), "
    "e = 10/9 ball, 9/8 roller; for one slope 1/L_sys^e = sum 1/L_i^e (Lundberg-Palmgren; Harris & Kotzalas)"
)
#: Why the ISO 281 and the ISO/TS 16281 system lives differ (one line on every face).
SYSTEM_LIFE_DIFFERENCE = (
    "ISO 281 rates each bearing from its equivalent load P = X F_r + Y F_a (nominal load zone, no tilt or "
    "clearance); ISO/TS 16281 from the load distribution the shaft imposes (clearance, seat tilt, load "
    "zone, roller profile), so the two system lives differ as the bearings' lives do"
)
#: Why each system life is shown first.
SYSTEM_HEADLINE = {
    "ISO 281": "the bearings' ISO 281 lives (as catalogues and calculators give them), combined",
    "ISO/TS 16281": "a bearing has no ISO 281 life, so the ISO/TS 16281 system life leads",
}


def iso281_system_life(ratings: dict, attr: str, mask: np.ndarray, a1: float = 1.0):
    """System life (C,) [rev] and its mask from the bearings' ISO 281 ``attr`` lives (``life``: L10,
    ``modified_life``: L_nm, divided by a1 before and multiplied after, as :func:`combine_ratings` does).

    One Weibull member per bearing, slope e of its rows (10/9 ball, 9/8 roller;
    :func:`bearingkit.analysis.rating.assembly.system_life`): Σ (L_sys/L_i)^e_i = 1, i.e.
    L_sys = (Σ L_i^(−e))^(−1/e) for one slope (ISO 281:2007 eq. (7), (12) slopes; Lundberg & Palmgren
    1947, 1952; Harris & Kotzalas 2007 vol. 2 ch. 8). An unloaded bearing (no loaded row) does no damage;
    a loaded one without an ISO 281 life masks the case.
    """
    lives, slopes, mask = [], [], np.asarray(mask, bool).copy()
    for r in ratings.values():
        unloaded = np.all([np.asarray(row.loaded_count) == 0 for row in r.rows], axis=0)
        iso = getattr(r, "iso281", None)
        if iso is None:
            value = np.ma.masked_all(mask.shape)
        else:
            value = np.ma.asarray(getattr(iso, attr)).astype(float) / a1
        missing = np.ma.getmaskarray(value) & ~unloaded
        mask |= missing
        lives.append(np.where(unloaded | missing, np.inf, np.ma.getdata(value)))
        slopes.append(r.rows[0].weibull_slope)
    life = system_life(np.array(lives), np.array(slopes))
    mask |= ~np.isfinite(life)
    return np.where(mask, 0.0, life * a1), mask


@dataclass
class SystemRating:
    """Ratings of the bearings of a shaft over its load cases (leading axis C).

    Attributes
    ----------
    bearings : dict name → RatingResult
    life : numpy.ma.MaskedArray (C,) [rev]
        System L10 (90 % reliability) from the bearings' ISO/TS 16281 L10r; masked where a bearing has
        no life (a case that did not converge, a row without rating).
    speed : ndarray (C,) or None [rad/s]
    warnings : list of list of str
        Per case, each bearing's warnings prefixed by its name, and the system's.
    modified_life : numpy.ma.MaskedArray (C,) [rev]
        System modified life L_nm at the ratings' reliability (:func:`combine_ratings`); masked where
        a loaded row has no L_nm.
    iso281_life, iso281_modified_life : numpy.ma.MaskedArray (C,) [rev]
        System L10 and L_nm from the bearings' ISO 281 lives (:func:`iso281_system_life`).
    """

    bearings: dict
    life: np.ma.MaskedArray
    speed: np.ndarray | None
    warnings: list
    modified_life: np.ma.MaskedArray | None = None
    iso281_life: np.ma.MaskedArray | None = None
    iso281_modified_life: np.ma.MaskedArray | None = None

    def hours(self, life) -> np.ma.MaskedArray:
        """A life [rev] (C,) in hours at the cases' speed (masked without speed)."""
        if self.speed is None:
            return np.ma.masked_all(np.shape(life))
        return np.ma.masked_array(
            iso281.life_in_seconds(np.ma.filled(life, 0.0), self.speed) / HOUR,
            np.ma.getmaskarray(life),
        )

    def life_hours(self) -> np.ma.MaskedArray:
        """System life in hours (C,) at the cases' speed (masked without speed)."""
        return self.hours(self.life)

    def to_dict(self, case: int) -> dict:
        """JSON-ready summary of one case: each bearing's system values and the shaft's system life."""

        def val(a):
            a = np.ma.asarray(a)
            return None if np.ma.getmaskarray(a)[case] else float(np.ma.getdata(a)[case])

        def opt(a, hours=False):
            return None if a is None else val(self.hours(a) if hours else a)

        iso = {
            "L10_iso281_rev": opt(self.iso281_life),
            "L10h_iso281_h": opt(self.iso281_life, True),
            "Lnm_iso281_rev": opt(self.iso281_modified_life),
            "Lnm_iso281_h": opt(self.iso281_modified_life, True),
        }
        first = "ISO 281" if iso["L10_iso281_rev"] is not None else "ISO/TS 16281"
        return {
            "bearings": {name: r.to_dict(case)["system"] for name, r in self.bearings.items()},
            "system": {
                "headline": {"method": first, "why": SYSTEM_HEADLINE[first]},
                **iso,
                "weibull_rule": WEIBULL_RULE,
                "life_difference": SYSTEM_LIFE_DIFFERENCE if first == "ISO 281" else None,
                "L10r_rev": val(self.life),
                "L10h_h": val(self.life_hours()),
                "Lnmr_rev": None if self.modified_life is None else val(self.modified_life),
                "Lnmr_h": None if self.modified_life is None else val(self.hours(self.modified_life)),
            },
            "warnings": list(self.warnings[case]),
        }


def rate_system(result, **options) -> SystemRating:
    """Rate every bearing of a :class:`~bearingkit.systems.shaft.result.ShaftResult` and combine them.

    Parameters
    ----------
    result : ShaftResult
    **options
        Passed to :func:`bearingkit.analysis.rating.assembly.rate` (``reliability``, ``lubricant``,
        ``temperature_C``, ``contamination_factor``, ``load_ratings`` …). ``speed`` defaults to the
        load cases' shaft speed; ``rotating`` is "inner" (the shaft turns the inner rings).

    Returns
    -------
    SystemRating
    """
    from bearingkit.analysis.rating.assembly import rate

    if "rotating" in options:
        raise InputError("rotating: the shaft turns the inner rings; rotating is not an option here")
    speed = options.pop("speed", result.loads.speed)
    if speed is not None and not np.all(np.asarray(speed) > 0):
        speed = None  # a standstill case has no life in hours; revolutions are still given
    ratings = {}
    for b in result.system.bearings:
        if isinstance(b.bearing, BearingModel):
            ratings[b.name] = rate(result.bearing_result(b.name), speed=speed, rotating="inner", **options)
    return combine_ratings(ratings, result.converged, speed)


def _combined(ratings: dict, attr: str, mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """System life over the rows of every bearing from their ``attr`` lives, and its mask (C,)."""
    lives, slopes, mask = [], [], mask.copy()
    for r in ratings.values():
        for row in r.rows:
            unloaded = row.loaded_count == 0
            value = getattr(row, attr)
            missing = np.ma.getmaskarray(value) & ~unloaded
            mask |= missing
            lives.append(np.where(unloaded | missing, np.inf, np.ma.getdata(value)))
            slopes.append(row.weibull_slope)
    life = system_life(np.array(lives), np.array(slopes))
    mask |= ~np.isfinite(life)
    return np.where(mask, 0.0, life), mask


def combine_ratings(ratings: dict, converged, speed=None) -> SystemRating:
    """The system life of bearings already rated (module docstring), with each bearing's warnings.

    Parameters
    ----------
    ratings : dict name → RatingResult
        One rating per bearing over the same C load cases (linear bearings have none).
    converged : array_like (C,) of bool
        The system's convergence: a case that did not converge has no system life.
    speed : ndarray (C,) or None [rad/s]
        Shaft speed (lives in hours).

    Returns
    -------
    SystemRating
        ``life`` is the L10 from the rows' ISO/TS 16281 L10r; ``modified_life`` combines the rows'
        L_nm at 90 % reliability the same way and scales it by a1 (as ISO 281 does for one bearing),
        masked unless every loaded row has one (a lubricant, a given temperature, e_C and speed).
    """
    converged = np.asarray(converged, bool)
    n = converged.shape[0]
    notes = [[] for _ in range(n)]
    for name, r in ratings.items():
        for c in range(n):
            notes[c].extend(f"{name}: {w}" for w in r.warnings[c])
    if not ratings:
        none = np.ma.masked_all(n)
        return SystemRating(ratings, none, speed, notes, none, none, none)
    life, mask = _combined(ratings, "life", ~converged)
    for c in np.flatnonzero(mask):
        notes[c].append("system: no system life (a bearing has none, or the case did not converge)")
    a1 = float(next(iter(ratings.values())).a1)
    modified, mod_mask = _combined(ratings, "modified_life_90", ~converged)
    iso, iso_mask = iso281_system_life(ratings, "life", ~converged)
    iso_mod, iso_mod_mask = iso281_system_life(ratings, "modified_life", ~converged, a1)
    return SystemRating(
        ratings,
        np.ma.masked_array(life, mask),
        speed,
        notes,
        np.ma.masked_array(modified * a1, mod_mask),
        np.ma.masked_array(iso, iso_mask),
        np.ma.masked_array(iso_mod, iso_mod_mask),
    )


def friction_system(result, lubricant=None, temperature=None, **operating_point) -> tuple[dict, list]:
    """Friction torque of every bearing (:func:`bearingkit.analysis.friction.components.friction_torque`).

    Parameters
    ----------
    result : ShaftResult
        Needs the cases' shaft speed (the inner rings turn with the shaft, the outer rings stand).
    lubricant : Lubricant or str, optional
        Default: each bearing's own input file's ``[lubricant]``.
    temperature : float, optional [°C]
        Default: the cases' temperatures (cases are grouped by temperature), else the default of
        :class:`~bearingkit.analysis.friction.components.OperatingPoint`.
    **operating_point
        Further :class:`~bearingkit.analysis.friction.components.OperatingPoint` fields.

    Returns
    -------
    dict name → ndarray (C,) [N·m], list of str
        Total friction torque per bearing, and notes for the bearings without one (no lubricant, or
        a row kind the component model does not cover).
    """
    from bearingkit.analysis.friction.components import OperatingPoint, friction_torque

    n = result.n_cases
    if result.loads.speed is None:
        return {}, ["friction: the load cases give no speed"]
    temps = np.full(n, np.nan)
    if temperature is not None:
        temps[:] = temperature
    elif result.loads.temperature is not None:
        temps[:] = result.loads.temperature
    out, notes = {}, []
    for b in result.system.bearings:
        if not isinstance(b.bearing, BearingModel):
            continue
        lube = lubricant if lubricant is not None else getattr(b.source, "lubricant", None)
        if lube is None:
            notes.append(f"{b.name}: no friction (no [lubricant] in its file or in the shaft file)")
            continue
        torque = np.full(n, np.nan)
        full = result.bearing_result(b.name)
        groups = [np.flatnonzero(temps == t) for t in np.unique(temps[np.isfinite(temps)])]
        if not np.isfinite(temps).all():
            groups.append(np.flatnonzero(~np.isfinite(temps)))
        try:
            for cases in groups:
                t = temps[cases[0]]
                extra = {"temperature": float(t)} if np.isfinite(t) else {}
                op = OperatingPoint(
                    speed_inner=result.loads.speed[cases], lubricant=lube, **extra, **operating_point
                )
                torque[cases] = friction_torque(_cases_of(full, cases), op).total
        except InputError as exc:
            notes.append(f"{b.name}: no friction ({exc})")
            continue
        out[b.name] = torque
    return out, notes


def _cases_of(result, cases):
    """A QuasiStaticResult restricted to some cases (the per-element state is recomputed lazily)."""
    from bearingkit.analysis.solver.quasistatic import QuasiStaticResult

    return QuasiStaticResult(
        model=_model_of(result.model, cases, len(result.load)),
        load=result.load[cases],
        displacement=result.displacement[cases],
        converged=result.converged[cases],
        iterations=result.iterations[cases],
        residual_norm=result.residual_norm[cases],
        reason=[result.reason[i] for i in cases],
        stiffness=result.stiffness[cases],
        free=result.free,
        references=result.references,
    )


def _model_of(model, cases, n_cases: int):
    """A model whose per-case speeds (a ModelAtSpeed's) are restricted to ``cases`` of the batch."""
    import dataclasses

    from bearingkit.analysis.solver.speed import ModelAtSpeed, model_at_speed

    if not isinstance(model, ModelAtSpeed):
        return model
    sp = model.speed
    pick = lambda v: np.broadcast_to(v, (n_cases,))[cases]  # noqa: E731
    return model_at_speed(
        model, dataclasses.replace(sp, speed_inner=pick(sp.inner), speed_outer=pick(sp.outer))
    )
