"""Bearing selection: the catalogue bearings that meet a required life and static safety under a load.

SI inside: loads in N, speed in rad/s, lives in s (hours only in the output keys ``…_h``). What
``bearingkit select --load Fr=5kN --load Fa=1kN --speed 3000rpm --life 20000h`` and :func:`select` do:

1. **screen** every catalogue row of the kinds asked for by the catalogue method
   (:func:`bearingkit.catalogue.search.screen`: ISO 281 P = X F_r + Y F_a with the row's C — the
   catalogue's, else the estimate's — and ISO 76 P0 with C0);
2. sort the rows that pass by estimated mass (then outside diameter): the lightest first;
3. run the **full analysis** (:func:`bearingkit.pipeline.analyze`: load distribution of the estimated
   geometry, ISO 281 life of the whole bearing and ISO/TS 16281 life of the rows, static safety from the
   contact pressures) on them in that order, one bearing after another (each is a different model),
   until ``count`` meet the life by BOTH ISO 281 and ISO/TS 16281 and the static safety.

The two lives differ: ISO 281 is the catalogue calculation (P from fixed X, Y factors that assume a
load zone), ISO/TS 16281 follows the computed load distribution of the estimated internal geometry (the
load zone the clearance and the load produce). A candidate must meet both; the table shows both so the
user sees which one decides. Single angular contact and tapered bearings are analysed alone: one that
cannot carry the load without an opposing bearing (F_a below its induced axial force) fails the full
analysis and is left out, with the reason in ``rejected``.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from bearingkit.budget import MAX_WORK_ENV, max_work
from bearingkit.errors import InputError

#: Default static safety s0 a candidate must reach (ISO 76 annex: ≥ 1 for normal operation) [-].
DEFAULT_STATIC_SAFETY = 1.0
#: Candidates fully analysed at most per requested candidate (the screen passes many more).
EVALUATIONS_PER_CANDIDATE = 6
#: Most candidates one selection may ask for: a table longer than this is a search, not a choice
#: (``bearingkit catalogue`` lists rows by bounds), and 6 × 100 full analyses take about a minute.
MAX_COUNT = 100


@dataclass
class Selection:
    """The result of :func:`select`.

    Attributes
    ----------
    candidates : list of dict
        JSON-ready rows (SI, units in keys), lightest first.
    rejected : list of dict
        Rows fully analysed that failed, with the reason.
    screened, passed_screen : int
        Rows screened by the catalogue method and rows that passed it.
    seconds : float
        Wall time of the selection.
    notes : list of str
    """

    candidates: list = field(default_factory=list)
    rejected: list = field(default_factory=list)
    screened: int = 0
    passed_screen: int = 0
    seconds: float = 0.0
    notes: list = field(default_factory=list)

    def to_dict(self) -> dict:
        """JSON-ready."""
        return {
            "candidates": self.candidates,
            "rejected": self.rejected,
            "screened": self.screened,
            "passed_screen": self.passed_screen,
            "seconds": self.seconds,
            "notes": self.notes,
        }


def _quantity(value, dimension: str, name: str) -> float:
    from bearingkit.units import parse

    if isinstance(value, str):
        return parse(value, dimension, name)
    x = float(value)
    if not np.isfinite(x):
        raise InputError(f"{name} ({value!r}) must be a finite number")
    return x


def select(
    load,
    speed,
    life,
    *,
    kind: str | None = None,
    static_safety: float = DEFAULT_STATIC_SAFETY,
    count: int = 5,
    pattern: str | None = None,
    d_min=None,
    d_max=None,
    D_max=None,
    B_max=None,
) -> Selection:
    """Catalogue bearings that meet ``life`` at ``speed`` under ``load`` (module docstring).

    Parameters
    ----------
    load : Mapping or sequence of str
        One load case as :func:`bearingkit.pipeline.load_input` takes it: ``["Fr=5kN", "Fa=1kN"]`` or
        ``{"F_x": "5 kN", "F_z": "1 kN"}`` (F_x, F_y radial, F_z axial; no moments).
    speed : float [rad/s] or str
        E.g. ``"3000 rpm"``.
    life : float [s] or str
        Required L10 life, e.g. ``"20000 h"`` (ISO 281 and ISO/TS 16281).
    kind : str, optional
        A kind of :data:`bearingkit.catalogue.search.KINDS` (``"deep_groove"``, ``"tapered"``, ``"ball"`` …).
    static_safety : float
        Smallest s0 accepted (catalogue method and full analysis).
    count : int
        Candidates wanted (≥ 1).
    pattern : str, optional
        Only designations matching this shell pattern (``"62*"``).
    d_min, d_max, D_max, B_max : float [m] or str, optional
        Bounds on bore, outside diameter and width.

    Returns
    -------
    Selection
    """
    from bearingkit.catalogue.search import screen, search
    from bearingkit.pipeline.inputs import load_cases_from

    start = time.perf_counter()
    omega = abs(_quantity(speed, "angular_velocity", "speed"))
    required = _quantity(life, "time", "life")
    if not omega > 0 or not required > 0:
        raise InputError(f"speed ({speed!r}) and life ({life!r}) must be positive")
    count = int(count)
    if not 1 <= count <= MAX_COUNT:
        raise InputError(
            f"count ({count}) must be 1 to {MAX_COUNT}; `bearingkit catalogue` with bounds lists more rows"
        )
    case = load_cases_from(load, "select")[0]
    f = np.asarray(case.load, float)
    if np.any(np.abs(f[3:]) > 0):
        raise InputError("load: select takes forces only (F_r, F_a); a tilting moment needs a shaft model")
    fr, fa = float(np.hypot(f[0], f[1])), float(abs(f[2]))
    if not fr + fa > 0:
        raise InputError("load: give a radial or an axial force, e.g. Fr=5kN")
    bounds = {k: None if v is None else _quantity(v, "length", k) for k, v in
              (("d_min", d_min), ("d_max", d_max), ("D_max", D_max), ("B_max", B_max))}  # fmt: skip
    rows = search(pattern, kind=kind, **bounds)
    revs = required * omega / (2.0 * np.pi)
    out = Selection(screened=len(rows))
    passing = []
    for row in rows:
        s = screen(row, fr, fa)
        if s.life is not None and s.life >= revs and s.static_safety >= static_safety:
            passing.append(s)
    passing.sort(key=lambda s: (s.row.mass if s.row.mass is not None else np.inf, s.row.entry.outer_diameter))
    out.passed_screen = len(passing)
    items = [f"F_x={fr!r} N", f"F_z={fa!r} N"]
    # The full analyses run one after another until `count` meet the life: when few can, up to 6 ×
    # count of them. The work limit stops the loop (a note says so) rather than letting a selection
    # run for minutes unasked (the fuzz: --count 10^20 with a life few rows reach ran 32 s).
    limit, stopped = max_work(), False
    for s in passing[: EVALUATIONS_PER_CANDIDATE * count]:
        if time.perf_counter() - start > limit:
            stopped = True
            break
        verdict = _evaluate(s, items, omega, required, static_safety)
        (out.candidates if "reason" not in verdict else out.rejected).append(verdict)
        if len(out.candidates) >= count:
            break
    out.seconds = time.perf_counter() - start
    out.notes = [
        f"load F_r = {fr:.6g} N, F_a = {fa:.6g} N at {omega * 30 / np.pi:.6g} r/min; required L10 = "
        f"{required / 3600:.6g} h by ISO 281 and ISO/TS 16281, s0 >= {static_safety:g}",
        "internal geometries and masses are ESTIMATED from the boundary dimensions (docs/catalogue.md); C is "
        "the catalogue's where the table prints one (C_source), else the estimate's",
        "ISO 281 uses fixed X, Y (a catalogue calculation); ISO/TS 16281 the computed load distribution of "
        "the estimated geometry: both must meet the life",
        f"{out.screened} rows screened, {out.passed_screen} passed the catalogue method, "
        f"{len(out.candidates) + len(out.rejected)} analysed in full ({out.seconds:.3g} s)",
    ]
    if stopped:
        done = len(out.candidates) + len(out.rejected)
        out.notes.append(
            f"stopped after {done} full {'analysis' if done == 1 else 'analyses'}: the work limit "
            f"({limit:g} s, {MAX_WORK_ENV}) was reached before {count} candidates met the life; ask for "
            "fewer (--count), narrow the search (--kind, bounds) or raise the limit"
        )
    return out


def _evaluate(s, items, omega: float, required: float, static_safety: float) -> dict:
    """The full analysis of one screened row: its candidate dict, with ``reason`` when it fails."""
    from bearingkit.pipeline.analysis import analyze

    row = s.row
    e = row.entry
    base = row.to_dict()
    base.update(
        {
            "P_catalogue_method_N": s.P,
            "L10h_catalogue_method_h": s.life / (omega / (2 * np.pi)) / 3600.0,
            "s0_catalogue_method": s.static_safety,
        }
    )
    try:
        a = analyze(e.designation, load=items, speed=float(omega))
        data = a.rating_dict()
    except InputError as exc:
        return {**base, "reason": str(exc)}
    c = data["cases"][0]
    sysd = c["system"]
    if not c["converged"]:
        return {**base, "reason": "the bearing alone cannot carry this load (no equilibrium)"}
    base.update(
        {
            "C_iso281_N": sysd["C_iso281_N"],
            "C_source": sysd["C_source"],
            "P_iso281_N": sysd["P_iso281_N"],
            "C0_iso76_N": sysd.get("C0_iso76_N"),
            "C0_source": sysd.get("C0_source"),
            "s0_iso76": sysd.get("s0_iso76"),
            "L10h_iso281_h": sysd["L10h_iso281_h"],
            "L10h_iso16281_h": sysd["L10h_h"],
            "static_safety": sysd["static_safety"],
            "warnings": c["warnings"],
        }
    )
    need = required / 3600.0
    lives = (sysd["L10h_iso281_h"], sysd["L10h_h"])
    if any(x is None for x in lives):
        return {**base, "reason": f"no life: {sysd.get('iso281_note') or 'see the rating notes'}"}
    if min(lives) < need:
        which = "ISO 281" if lives[0] < need else "ISO/TS 16281"
        return {**base, "reason": f"{which} L10h {min(lives):.4g} h below {need:.6g} h"}
    if sysd["static_safety"] is not None and sysd["static_safety"] < static_safety:
        return {**base, "reason": f"static safety {sysd['static_safety']:.3g} below {static_safety:g}"}
    return base
