"""Ratings, lives and friction of every bearing of a shaft, and the system life.

SI units; lives in revolutions of the shaft (``*_rev``) and hours (``*_h``, at the cases' speed).
Each bearing is rated at its seat state by the bearing API (:func:`bearingkit.analysis.rating.rate`,
ISO 76 / ISO 281 / ISO/TS 16281, inner ring rotating with the shaft). The system life combines the
bearings as independently failing Weibull members (ISO 281:2007 eq. (7) and (12) slopes; Lundberg &
Palmgren 1947, 1952; Harris & Kotzalas 2007 vol. 2 ch. 8):

    L_sys = (Σ_i L_i^(−e))^(−1/e)     (one slope e: 10/9 balls, 9/8 rollers),

computed by :func:`bearingkit.analysis.rating.system_life` over the rows of all bearings, which for
rows of one slope per bearing is exactly this formula over the bearings and solves the Weibull
equation Σ (L_sys/L_i)^e_i = 1 when ball and roller bearings are mixed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit.analysis.model import BearingModel
from bearingkit.analysis.rating import HOUR, system_life
from bearingkit.errors import InputError
from bearingkit.physics.life import iso281


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
    """

    bearings: dict
    life: np.ma.MaskedArray
    speed: np.ndarray | None
    warnings: list

    def life_hours(self) -> np.ma.MaskedArray:
        """System life in hours (C,) at the cases' speed (masked without speed)."""
        if self.speed is None:
            return np.ma.masked_all(self.life.shape)
        return np.ma.masked_array(
            iso281.life_in_seconds(np.ma.filled(self.life, 0.0), self.speed) / HOUR,
            np.ma.getmaskarray(self.life),
        )

    def to_dict(self, case: int) -> dict:
        """JSON-ready summary of one case: each bearing's system values and the shaft's system life."""

        def val(a):
            a = np.ma.asarray(a)
            return None if np.ma.getmaskarray(a)[case] else float(np.ma.getdata(a)[case])

        return {
            "bearings": {name: r.to_dict(case)["system"] for name, r in self.bearings.items()},
            "system": {"L10r_rev": val(self.life), "L10h_h": val(self.life_hours())},
            "warnings": list(self.warnings[case]),
        }


def rate_system(result, **options) -> SystemRating:
    """Rate every bearing of a :class:`~bearingkit.systems.result.ShaftResult` and combine them.

    Parameters
    ----------
    result : ShaftResult
    **options
        Passed to :func:`bearingkit.analysis.rating.rate` (``reliability``, ``lubricant``,
        ``temperature_C``, ``contamination_factor``, ``load_ratings`` …). ``speed`` defaults to the
        load cases' shaft speed; ``rotating`` is "inner" (the shaft turns the inner rings).

    Returns
    -------
    SystemRating
    """
    from bearingkit.analysis.rating import rate

    if "rotating" in options:
        raise InputError("rotating: the shaft turns the inner rings; rotating is not an option here")
    speed = options.pop("speed", result.loads.speed)
    if speed is not None and not np.all(np.asarray(speed) > 0):
        speed = None  # a standstill case has no life in hours; revolutions are still given
    ratings = {}
    for b in result.system.bearings:
        if isinstance(b.bearing, BearingModel):
            ratings[b.name] = rate(result.bearing_result(b.name), speed=speed, rotating="inner", **options)
    n = result.n_cases
    notes = [[] for _ in range(n)]
    lives, slopes, mask = [], [], ~np.asarray(result.converged, bool)
    for name, r in ratings.items():
        for c in range(n):
            notes[c].extend(f"{name}: {w}" for w in r.warnings[c])
        for row in r.rows:
            unloaded = row.loaded_count == 0
            missing = np.ma.getmaskarray(row.life) & ~unloaded
            mask |= missing
            lives.append(np.where(unloaded | missing, np.inf, np.ma.getdata(row.life)))
            slopes.append(row.weibull_slope)
    if not lives:
        return SystemRating(ratings, np.ma.masked_all(n), speed, notes)
    life = system_life(np.array(lives), np.array(slopes))
    mask |= ~np.isfinite(life)
    for c in np.flatnonzero(mask):
        notes[c].append("system: no system life (a bearing has none, or the case did not converge)")
    return SystemRating(ratings, np.ma.masked_array(np.where(mask, 0.0, life), mask), speed, notes)


def friction_system(result, lubricant=None, temperature=None, **operating_point) -> tuple[dict, list]:
    """Friction torque of every bearing (:func:`bearingkit.analysis.friction.friction_torque`).

    Parameters
    ----------
    result : ShaftResult
        Needs the cases' shaft speed (the inner rings turn with the shaft, the outer rings stand).
    lubricant : Lubricant or str, optional
        Default: each bearing's own input file's ``[lubricant]``.
    temperature : float, optional [°C]
        Default: the cases' temperatures (cases are grouped by temperature), else the default of
        :class:`~bearingkit.analysis.friction.OperatingPoint`.
    **operating_point
        Further :class:`~bearingkit.analysis.friction.OperatingPoint` fields.

    Returns
    -------
    dict name → ndarray (C,) [N·m], list of str
        Total friction torque per bearing, and notes for the bearings without one (no lubricant, or
        a row kind the component model does not cover).
    """
    from bearingkit.analysis.friction import OperatingPoint, friction_torque

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
    from bearingkit.analysis.quasistatic import QuasiStaticResult

    return QuasiStaticResult(
        model=result.model,
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
