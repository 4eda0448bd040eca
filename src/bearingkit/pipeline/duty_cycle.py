"""Life over a duty cycle: the bins of a load spectrum rated in one batch and combined (Palmgren–Miner).

SI units: lives in revolutions (``*_rev``) and hours (``*_h``), speeds in rad/s, temperatures in °C.

A bearing file's ``[[duty_cycle]]`` (:mod:`bearingkit.io.optional_sections.cycle`) lists bins: load, speed,
temperature and a time or revolution fraction each. :attr:`bearingkit.pipeline.Analysis.duty_cycle`
solves and rates every bin as a load case of ONE batched Analysis (same bearing, operating settings
of the parent analysis) and combines the bins' system lives by linear damage summation
(:func:`bearingkit.physics.life.duty_cycle.miner_life`): L = (Σ U_i / L_i)^(−1) with U_i the
revolution fractions. ISO 281 first (as for a single case: the catalogue method, the life shown first
where ISO 281 rates the bearing): the basic rating life L10 and, where every turning bin has a_ISO, the
modified rating life L_nm (ISO 281:2007 with the variable-load Miner rule of ISO 281 / ISO/TS 16281);
beside them the ISO/TS 16281 basic and modified reference rating lives L10r and L_nmr from the bins'
load distributions. :func:`combine` does the same for G designs at
once (a study: the (G, B) bins of G bearings in one analysis).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from bearingkit.physics.life import duty_cycle as miner

__all__ = ["DutyCycleResult", "bin_lives", "bins_input", "combine", "summarise"]

#: Seconds per hour.
HOUR = 3600.0


def bin_lives(rating, attr: str = "life", iso281: bool = False) -> np.ndarray:
    """System lives (C,) [rev] of a rating for Miner's sum: NaN where unknown, +inf where no row is loaded.

    ``attr`` of the rating (ISO/TS 16281: ``life``, ``modified_life``) or, with ``iso281``, of its ISO 281
    life (:class:`bearingkit.analysis.rating.iso281.Iso281Life`: ``life``, ``modified_life``; all NaN where
    ISO 281 does not rate the bearing). A bin whose bearing carries no load does no fatigue damage (ISO 281
    gives it no finite life); a bin that did not converge, or whose life is masked for another reason, has
    no known life.
    """
    source = getattr(rating, "iso281", None) if iso281 else rating
    if source is None:
        return np.full(np.shape(rating.converged), np.nan)
    life = getattr(source, attr)
    out = np.ma.filled(np.ma.asarray(life).astype(float), np.nan)
    unloaded = np.all([np.asarray(r.loaded_count) == 0 for r in rating.rows], axis=0)
    return np.where(unloaded & np.asarray(rating.converged, bool), np.inf, out)


def combine(lives, fractions, kind: str, speeds) -> dict:
    """Combined lives of G duty cycles of B bins each.

    Parameters
    ----------
    lives : dict name → ndarray (G, B) [rev]
        Bin lives to combine (e.g. ``{"L10r": …, "Lnmr": …}``), from :func:`bin_lives`.
    fractions : array_like (B,) or (G, B) [-]
        Time or revolution fractions.
    kind : {"time", "revolutions"}
    speeds : array_like (G, B) [rad/s]
        Bin speeds (sign ignored).

    Returns
    -------
    dict
        ``U`` (G, B) revolution fractions; per life name: ``<name>_rev`` (G,), ``<name>_h`` (G,)
        (NaN without a mean revolution rate) and ``<name>_damage_share`` (G, B).
    """
    speeds = np.asarray(speeds, dtype=float)
    frac = np.broadcast_to(np.asarray(fractions, dtype=float), speeds.shape)
    u = miner.revolution_fractions(frac, speeds, kind)
    rate = miner.mean_revolution_rate(frac, speeds, kind)  # rev/s
    out = {"U": u}
    for name, life in lives.items():
        total = miner.miner_life(life, u)
        with np.errstate(divide="ignore", invalid="ignore"):
            hours = np.where(rate > 0.0, total / np.where(rate > 0.0, rate, 1.0) / HOUR, np.nan)
        out[f"{name}_rev"] = total
        out[f"{name}_h"] = hours
        out[f"{name}_damage_share"] = miner.damage_shares(life, u)
    return out


@dataclass
class DutyCycleResult:
    """Every bin's life and the life over the duty cycle.

    Attributes
    ----------
    names : list of str
        Bin names.
    kind : {"time", "revolutions"}
    fractions : ndarray (B,) [-]
        As given.
    revolution_fractions : ndarray (B,) [-]
        U_i (what Miner's sum weighs).
    speeds : ndarray (B,) [rad/s]
    analysis : Analysis
        The bins solved and rated as load cases (statics, rating, warnings per bin).
    bin_life, bin_modified_life : ndarray (B,) [rev]
        ISO/TS 16281 L10r and L_nmr of each bin (NaN: not available, +inf: no load).
    life, modified_life : float [rev]
        Combined L10r and L_nmr (NaN when a turning bin has none).
    life_hours, modified_life_hours : float [h]
        At the cycle's mean revolution rate (NaN without speeds).
    damage_share : ndarray (B,) [-]
        Share of the L10r damage each bin does.
    notes : list of str
    iso281 : dict
        ISO 281 (listed first by every face where it rates the bearing): ``bin_life``, ``bin_modified_life``
        (B,) [rev] (L10, L_nm per bin), ``life``, ``modified_life`` [rev], ``life_hours``,
        ``modified_life_hours`` [h] (Miner-combined), ``damage_share`` (B,) [-] (share of the ISO 281 L10
        damage) and ``note`` (why there is none, else None).
    """

    names: list
    kind: str
    fractions: np.ndarray
    revolution_fractions: np.ndarray
    speeds: np.ndarray
    analysis: object
    bin_life: np.ndarray
    bin_modified_life: np.ndarray
    life: float
    modified_life: float
    life_hours: float
    modified_life_hours: float
    damage_share: np.ndarray
    notes: list = field(default_factory=list)
    references: tuple = ("palmgren1924", "miner1945", "iso281", "iso16281")
    iso281: dict = field(default_factory=dict)

    def to_dict(self) -> dict:
        """JSON-ready (units in keys; None where not available, ``"inf"`` lives written as None too)."""

        def num(x):
            x = float(x)
            return x if np.isfinite(x) else None

        rating = self.analysis.rating
        iso = self.iso281 or _no_iso281(len(self.names), "ISO 281 was not computed")
        bins = []
        for i, name in enumerate(self.names):
            case = self.analysis.input.cases[i]
            bins.append(
                {
                    "bin": name,
                    f"{self.kind}_fraction": float(self.fractions[i]),
                    "revolution_fraction": num(self.revolution_fractions[i]),
                    "speed_rad_s": float(self.speeds[i]),
                    "temperature_C": float(self.analysis.operating.temperature[i]),
                    "load": {
                        f"{n}_{u}": float(v)
                        for n, u, v in zip(
                            ("F_x", "F_y", "F_z", "M_x", "M_y"),
                            ("N",) * 3 + ("Nm",) * 2,
                            case.load,
                            strict=True,
                        )
                    },
                    "L10_iso281_rev": num(iso["bin_life"][i]),
                    "Lnm_iso281_rev": num(iso["bin_modified_life"][i]),
                    "damage_share_iso281": num(iso["damage_share"][i]),
                    "L10r_rev": num(self.bin_life[i]),
                    "Lnmr_rev": num(self.bin_modified_life[i]),
                    "static_safety": None if rating is None else _masked(rating.static_safety, i),
                    "damage_share": num(self.damage_share[i]),
                    "no_load": bool(np.isposinf(self.bin_life[i])),
                    "warnings": self.analysis.warnings[i],
                }
            )
        return {
            "fraction_kind": self.kind,
            "rule": "Palmgren-Miner: L = 1 / sum(U_i / L_i), U_i = revolution fractions",
            "headline": _headline(iso),
            "L10_iso281_rev": num(iso["life"]),
            "L10h_iso281_h": num(iso["life_hours"]),
            "Lnm_iso281_rev": num(iso["modified_life"]),
            "Lnm_iso281_h": num(iso["modified_life_hours"]),
            "iso281_note": iso["note"],
            "life_difference": LIFE_DIFFERENCE if np.isfinite(iso["life"]) else None,
            "L10r_rev": num(self.life),
            "L10r_h": num(self.life_hours),
            "Lnmr_rev": num(self.modified_life),
            "Lnmr_h": num(self.modified_life_hours),
            "bins": bins,
            "notes": list(self.notes),
            "references": list(self.references),
        }


#: Why the two combined lives differ (one line on every face that shows both).
LIFE_DIFFERENCE = (
    "ISO 281 rates each bin from its equivalent load P = X F_r + Y F_a and the bearing's C (nominal load "
    "zone, no clearance or tilt); ISO/TS 16281 from the bin's solved load distribution (clearance, tilt, "
    "contact angles, roller profile), so the two Miner sums differ as the bins' two lives do"
)


def _headline(iso: dict) -> dict:
    """Which combined life the faces show first: ISO 281's where every bin has one, else ISO/TS 16281's."""
    if np.isfinite(iso["life"]):
        return {"method": "ISO 281", "why": "ISO 281 rating life, as catalogues and calculators give it"}
    return {
        "method": "ISO/TS 16281",
        "why": f"ISO/TS 16281 reference rating life from the load distribution ({iso['note']})",
    }


def _no_iso281(n: int, note: str) -> dict:
    nan = np.full(n, np.nan)
    return {
        "bin_life": nan,
        "bin_modified_life": nan,
        "life": np.nan,
        "modified_life": np.nan,
        "life_hours": np.nan,
        "modified_life_hours": np.nan,
        "damage_share": nan,
        "note": note,
    }


def _masked(a, i):
    a = np.ma.asarray(a)
    return None if np.ma.getmaskarray(a)[i] else float(np.ma.getdata(a)[i])


def bins_input(analysis, index=None):
    """The bins of ``analysis.input``'s duty cycle (those at ``index``, default all) as load cases:
    (BearingInput, Operating).

    The bins run with the parent analysis's rotating ring, lubricant, contamination and reliability;
    each bin at its own speed, and its own temperature (else the parent's temperature override, else
    25 °C).
    """
    from bearingkit.pipeline.operating import Operating

    cycle = analysis.input.duty_cycle
    op = analysis.operating
    given_t = bool(np.all(op.temperature_given)) and np.unique(op.temperature).size == 1
    bins = [
        dataclasses.replace(b, temperature=float(op.temperature[0]))
        if b.temperature is None and given_t
        else b
        for b in cycle.bins
    ]
    if index is not None:
        bins = [bins[i] for i in index]
    bearing = analysis.input.with_cases(bins)
    operating = Operating.of(
        bearing,
        rotating=op.rotating,
        lubricant=op.lubricant,
        contamination=op.contamination,
        reliability=op.reliability,
    )
    return bearing, operating


def at_rest(cycle) -> np.ndarray:
    """(B,) bool: bins at rest in a time-fraction cycle (they do no fatigue damage and are rated apart:
    a_ISO and lives in hours need a speed)."""
    speeds = np.array([b.speed or 0.0 for b in cycle.bins])
    return (speeds == 0.0) if cycle.kind == "time" else np.zeros(len(cycle.bins), bool)


def summarise(cycle, sub, turning=None) -> DutyCycleResult:
    """Combine the bins of ``cycle`` (a :class:`~bearingkit.io.optional_sections.cycle.DutyCycle`)
    rated in ``sub`` (the Analysis of :func:`bins_input`) into a :class:`DutyCycleResult`.

    ``turning``: when some bins are at rest (:func:`at_rest`), the Analysis of the other bins alone,
    whose ratings give the lives (the bins at rest keep their statics and static safety from ``sub``).
    """
    speeds = sub.operating.speed
    names = sub.case_names
    notes = []
    n = len(names)
    life = np.full(n, np.nan)
    modified = np.full(n, np.nan)
    iso_life = np.full(n, np.nan)
    iso_modified = np.full(n, np.nan)
    iso_note = None
    rest = at_rest(cycle)
    rated = turning if turning is not None else sub
    idx = np.flatnonzero(~rest) if turning is not None else np.arange(n)
    if rated.rating is None:
        notes.append(rated.notes[0] if rated.notes else "the bins could not be rated")
    else:
        life[idx] = bin_lives(rated.rating, "life")
        modified[idx] = bin_lives(rated.rating, "modified_life")
        iso_life[idx] = bin_lives(rated.rating, "life", iso281=True)
        iso_modified[idx] = bin_lives(rated.rating, "modified_life", iso281=True)
        iso = getattr(rated.rating, "iso281", None)
        iso_note = "ISO 281 was not computed" if iso is None else iso.note
    lives = {"L10r": life, "Lnmr": modified, "L10": iso_life, "Lnm": iso_modified}
    combined = combine(
        {k: v[None, :] for k, v in lives.items()},
        cycle.fractions,
        cycle.kind,
        speeds[None, :],
    )
    u = combined["U"][0]
    for i in np.flatnonzero((u == 0) & (np.abs(speeds) == 0)):
        notes.append(f"bin {names[i]!r} is at rest: it does no fatigue damage (its static safety is shown)")
    if np.isnan(combined["Lnmr_rev"][0]) and not np.isnan(combined["L10r_rev"][0]):
        notes.append(
            "no combined L_nmr: a turning bin has no a_ISO (it needs a lubricant, e_C, a temperature and a "
            "speed in every bin)"
        )
    if np.isnan(combined["L10_rev"][0]):
        iso_note = iso_note or "a turning bin has no ISO 281 life"
        notes.append(f"no combined ISO 281 life ({iso_note}): the ISO/TS 16281 life is shown first")
    if np.isnan(combined["L10r_h"][0]) and not np.isnan(combined["L10r_rev"][0]):
        notes.append("no life in hours: the bins give no speed (revolution fractions without speeds)")
    return DutyCycleResult(
        names=names,
        kind=cycle.kind,
        fractions=np.asarray(cycle.fractions, float),
        revolution_fractions=u,
        speeds=np.asarray(speeds, float),
        analysis=sub,
        bin_life=life,
        bin_modified_life=modified,
        life=float(combined["L10r_rev"][0]),
        modified_life=float(combined["Lnmr_rev"][0]),
        life_hours=float(combined["L10r_h"][0]),
        modified_life_hours=float(combined["Lnmr_h"][0]),
        damage_share=combined["L10r_damage_share"][0],
        notes=notes,
        iso281={
            "bin_life": iso_life,
            "bin_modified_life": iso_modified,
            "life": float(combined["L10_rev"][0]),
            "modified_life": float(combined["Lnm_rev"][0]),
            "life_hours": float(combined["L10_h"][0]),
            "modified_life_hours": float(combined["Lnm_h"][0]),
            "damage_share": combined["L10_damage_share"][0],
            "note": iso_note,
        },
    )
