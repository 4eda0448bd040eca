"""Load ratings, static safety and fatigue life of whole bearings from a quasi-static solution.

SI units throughout: loads in N, pressures in Pa, lengths in m, speeds in rad/s, lives in revolutions
(``*_rev``) or hours (``*_h`` in the JSON output only), temperatures in °C (``temperature_C``, as in
:mod:`bearingkit.lubricants`).

:func:`rate` takes a :class:`~bearingkit.analysis.solver.quasistatic.QuasiStaticResult` and, for every row,

- rates the row as a single-row bearing of its own geometry: ISO 76 C0 and ISO 281 C (the row raters
  live in :mod:`bearingkit.analysis.rating.rows` and are re-exported here; :data:`ROW_RATERS` maps
  ``row.kind`` to a rater — ball, cylindrical, tapered, threaded — and new row kinds register themselves
  with :func:`register_row_rater`);
- computes the ISO/TS 16281 basic reference rating life L10r from the solved element loads (balls) or
  slice loads (rollers), with the rotating ring chosen by ``rotating``;
- computes the static safety s0 = (p_limit / p_max)^n from the largest contact pressure
  (:func:`bearingkit.physics.life.iso76.static_safety_from_pressure`);
- flags truncated contact ellipses (ball rows), edge loading (roller rows), stress above the ISO 76 limit,
  unloaded rows and non-converged cases as warnings;

and combines the rows into the system life of the bearing (:func:`system_life`). Values that cannot be
computed are *masked* (``numpy.ma``; ``None`` in :meth:`RatingResult.to_dict`) and explained by a warning —
never NaN.

References: ISO 76:2006, ISO 281:2007, ISO/TS 16281:2008, ISO/TR 1281-1; Lundberg & Palmgren (1947, 1952);
Harris & Kotzalas 2007 vol. 2 ch. 8; Zaretsky (2013) NASA/TP-2013-215305.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace

import numpy as np

from bearingkit import checks
from bearingkit.analysis.rating.compare import compare, headline, static_safety_difference
from bearingkit.analysis.rating.iso281 import (
    Iso281Life,
    bearing_life,
    catalogue_row_ratings,
    catalogue_row_static_ratings,
)
from bearingkit.analysis.rating.options import (
    DEFAULT_EDGE_PRESSURE_RATIO,
    DEFAULT_SHOULDER_HEIGHT,
    EDGE_STRESS_MODES,
    RatingOptions,
)
from bearingkit.analysis.rating.rows import (
    _REFERENCES,
    EDGE_FACTOR_KINDS,
    EDGE_FACTOR_MAX_MISALIGNMENT,
    ISO281_CONFORMITY_LIMITS,
    WEIBULL_SLOPES,
    RowContext,
    RowRating,
    _masked,
    rate_ball_row,
    rate_cylindrical_row,
    rate_tapered_row,
)
from bearingkit.analysis.rating.threaded import rate_threaded_row
from bearingkit.errors import InputError
from bearingkit.physics.life import iso281

__all__ = [
    "DEFAULT_EDGE_PRESSURE_RATIO",
    "DEFAULT_SHOULDER_HEIGHT",
    "EDGE_STRESS_MODES",
    "ISO281_CONFORMITY_LIMITS",
    "ROW_RATERS",
    "WEIBULL_SLOPES",
    "RatingOptions",
    "RatingResult",
    "RowContext",
    "RowRating",
    "rate",
    "rate_ball_row",
    "rate_cylindrical_row",
    "rate_tapered_row",
    "rate_threaded_row",
    "register_row_rater",
    "system_life",
]

#: Seconds per hour (L10h output).
HOUR = 3600.0
#: Newton iterations and relative tolerance of the mixed-slope system-life root.
_SYSTEM_ITERATIONS, _SYSTEM_TOL = 100, 1e-13


#: Row raters by ``row.kind``: ``rater(row, state: RowState, ctx: RowContext) -> RowRating``.
ROW_RATERS: dict[str, Callable] = {
    "ball": rate_ball_row,
    "cylindrical": rate_cylindrical_row,
    "tapered": rate_tapered_row,
    "threaded": rate_threaded_row,
}


def register_row_rater(kind: str, rater: Callable) -> Callable:
    """Register the rater of a row kind (new row kinds add themselves here); returns ``rater``."""
    if not isinstance(kind, str) or not kind:
        raise InputError(f"kind ({kind!r}) must be a non-empty row kind name")
    ROW_RATERS[kind] = rater
    return rater


def system_life(lives, slopes) -> np.ndarray:
    """L10 of a system of independently failing rows [same unit as ``lives``].

    With two-parameter Weibull survival S_i(L) = 0.9^((L/L_i)^{e_i}) per row, the system survives when all
    rows do, so its L10 solves

    .. math:: \\sum_i (L_{sys} / L_i)^{e_i} = 1,

    which for one common slope e is the Lundberg–Palmgren system life
    :math:`L_{sys} = (\\sum_i L_i^{-e})^{-1/e}`. Slopes: e = 10/9 for point contact (balls), 9/8 for line
    contact (rollers) — Lundberg & Palmgren 1947, 1952; Harris & Kotzalas 2007 vol. 2 ch. 8; Zaretsky 2013
    NASA/TP-2013-215305; they are the slopes behind ISO 281:2007 eq. (7) and (12) (exponents
    p·e = 3·10/9 = 10/3 and 4·9/8 = 9/2) and ISO/TS 16281 (raceway exponents −1/e = −0.9 and −8/9).
    Mixed slopes (ball–roller composites) are solved by Newton's method in ln L (the left side is convex
    and increasing in ln L; the start at min L_i lies right of the root, so the iteration is monotone).

    Parameters
    ----------
    lives : array_like (R, ...)
        Row lives L_i [rev] (> 0; +inf for rows that carry no load), rows on the first axis.
    slopes : array_like (R,)
        Weibull slopes e_i [-], > 0.

    Returns
    -------
    numpy.ndarray
        L_sys, shape ``lives.shape[1:]``; +inf where every row has an infinite life.
    """
    life = np.asarray(lives, dtype=float)
    e = np.asarray(slopes, dtype=float)
    checks.positive("slopes", e)
    if np.any(~(life > 0)):
        raise InputError(f"lives ({checks._fmt(life)}) must be positive (+inf for unloaded rows)")
    e = e.reshape((-1,) + (1,) * (life.ndim - 1))
    log_l = np.log(life)
    finite = np.isfinite(life).any(axis=0)
    if np.all(e == e.flat[0]):
        s = np.sum(np.exp(-e * log_l), axis=0)
        with np.errstate(divide="ignore"):
            return np.where(finite, s ** (-1.0 / e.flat[0]), np.inf)
    x = np.where(finite, np.min(np.where(np.isfinite(log_l), log_l, np.inf), axis=0), 0.0)
    for _ in range(_SYSTEM_ITERATIONS):
        terms = np.exp(e * (x - log_l))
        f = terms.sum(axis=0) - 1.0
        step = f / np.maximum((e * terms).sum(axis=0), 1e-300)
        x = np.where(finite, x - step, x)
        if np.all(np.abs(step) < _SYSTEM_TOL):
            break
    return np.where(finite, np.exp(x), np.inf)


def _combine(rows: list[RowRating], attr: str, n_cases: int) -> tuple[np.ma.MaskedArray, list[list[str]]]:
    """System life from the rows' ``attr`` lives; rows without load count as infinitely lived."""
    notes: list[list[str]] = [[] for _ in range(n_cases)]
    lives, slopes, mask = [], [], np.zeros(n_cases, bool)
    for r in rows:
        value = getattr(r, attr)
        unloaded = r.loaded_count == 0
        missing = np.ma.getmaskarray(value) & ~unloaded
        for c in np.flatnonzero(missing & r.valid):
            notes[c].append(f"system: no life because row {r.name!r} has none")
        mask |= missing | ~r.valid
        lives.append(np.where(unloaded | missing, np.inf, np.ma.getdata(value)))
        slopes.append(r.weibull_slope)
    life = system_life(np.array(lives), np.array(slopes))
    none_loaded = ~np.isfinite(life)
    for c in np.flatnonzero(none_loaded & ~mask):
        notes[c].append("system: no row carries load, no fatigue life")
    return _masked(np.where(mask | none_loaded, 0.0, life), mask | none_loaded), notes


@dataclass
class RatingResult:
    """Ratings and lives of a bearing over the load cases of a quasi-static result (leading axis C).

    Attributes
    ----------
    rows : list of RowRating
        Per-row ratings (C, C0, L10r, s0, …), arrays (C,) masked where not available.
    life : numpy.ma.MaskedArray (C,) [rev]
        System basic reference rating life L10r (90 % reliability).
    life_reliability : numpy.ma.MaskedArray (C,) [rev]
        L_nr = a1 · L10r at ``reliability``.
    modified_life : numpy.ma.MaskedArray (C,) [rev]
        L_nmr = a1 · L_sys(a_ISO,i · L10r,i); masked unless lubrication inputs were given.
    static_safety : numpy.ma.MaskedArray (C,) [-]
        Smallest static safety over the loaded rows.
    speed : ndarray (C,) or None [rad/s]
    reliability, a1 : float
    converged : ndarray (C,) of bool
    warnings : list of list of str
        Per case: every warning of the rows (prefixed by the row name) and of the system.
    references : tuple of str
        Keys of :mod:`bearingkit.references`.
    iso281 : Iso281Life or None
        ISO 281 P, C, L10 and L_nm of the whole bearing (:mod:`bearingkit.analysis.rating.iso281`).
    notes : list of str
        What holds for every case (e.g. the rows' C derived from the catalogue C).
    comparison : list of dict or None
        Per case, why L10r differs from ISO 281's L10 (:func:`bearingkit.analysis.rating.compare.compare`).
    """

    bearing: str
    rows: list
    life: np.ma.MaskedArray
    life_reliability: np.ma.MaskedArray
    modified_life: np.ma.MaskedArray
    static_safety: np.ma.MaskedArray
    speed: np.ndarray | None
    reliability: float
    a1: float
    rotating: str
    converged: np.ndarray
    warnings: list
    references: tuple = _REFERENCES
    iso281: Iso281Life | None = None
    notes: list = field(default_factory=list)
    comparison: list = field(default_factory=list)

    @property
    def n_cases(self) -> int:
        return len(self.converged)

    def row(self, name: str) -> RowRating:
        """The rating of the row called ``name``."""
        for r in self.rows:
            if r.name == name:
                return r
        raise InputError(f"row ({name!r}) not in rating; rows are {[r.name for r in self.rows]}")

    def hours(self, life) -> np.ma.MaskedArray:
        """A life [rev] (C,) in hours at ``speed`` (masked when no speed was given)."""
        life = np.ma.asarray(life)
        if self.speed is None:
            return _masked(np.zeros(life.shape), True)
        data = iso281.life_in_seconds(np.ma.filled(life.astype(float), 0.0), self.speed) / HOUR
        return _masked(data, np.ma.getmaskarray(life))

    def to_dict(self, case: int | None = None) -> dict | list[dict]:
        """JSON-ready dict for one case (list over cases when None); units in keys, masked → None."""
        if case is None:
            return [self.to_dict(c) for c in range(self.n_cases)]

        def val(a):
            a = np.ma.asarray(a)
            return None if np.ma.getmaskarray(a)[case] else float(np.ma.getdata(a)[case])

        rows = []
        for r in self.rows:
            rows.append(
                {
                    "name": r.name,
                    "kind": r.kind,
                    "bearing_type": r.bearing_type,
                    "element": r.element,
                    "weibull_slope": r.weibull_slope,
                    "C_N": val(r.load_rating),
                    "C0_N": val(r.static_rating),
                    "L10r_rev": val(r.life),
                    "L10r_h": val(self.hours(r.life)),
                    "Lnr_rev": val(r.life * self.a1),
                    "P_ref_N": val(r.reference_load),
                    "a_ISO": val(r.life_modification),
                    "Lnmr_rev": val(r.modified_life),
                    "Lnmr_h": val(self.hours(r.modified_life)),
                    "static_safety": val(r.static_safety),
                    "max_pressure_Pa": float(r.max_pressure[case]),
                    "loaded_count": int(r.loaded_count[case]),
                    "flags": {k: bool(v[case]) for k, v in r.flags.items()},
                }
            )
        return {
            "bearing": self.bearing,
            "converged": bool(self.converged[case]),
            "rotating": self.rotating,
            "speed_rad_s": None if self.speed is None else float(self.speed[case]),
            "reliability": self.reliability,
            "a1": self.a1,
            "rows": rows,
            "system": self._system_dict(case, val),
            "warnings": list(self.warnings[case]),
            "references": list(self.references),
        }

    def _system_dict(self, case: int, val) -> dict:
        """The bearing's lives of one case: the headline first (ISO 281 where it rates the bearing), the
        ISO 281 keys, the ISO/TS 16281 keys, and the line saying why the two differ."""
        system = {
            **self._iso281_dict(val),
            "L10r_rev": val(self.life),
            "L10h_h": val(self.hours(self.life)),
            "Lnr_rev": val(self.life_reliability),
            "Lnr_h": val(self.hours(self.life_reliability)),
            "Lnmr_rev": val(self.modified_life),
            "Lnmr_h": val(self.hours(self.modified_life)),
            "static_safety": val(self.static_safety),
        }
        diff = self.comparison[case] if case < len(self.comparison) else None
        system["life_difference"] = None if diff is None else diff["text"]
        system["static_safety_difference"] = static_safety_difference(
            system.get("s0_iso76"), system["static_safety"]
        )
        return {"headline": headline(system), **system}

    def _iso281_dict(self, val) -> dict:
        """The system's ISO 281 keys (P, C and its source, L10, L10h, L_nm; None where not given)."""
        b = self.iso281
        if b is None:
            return {}
        return {
            "P_iso281_N": val(b.load),
            "C_iso281_N": b.load_rating,
            "C_source": b.rating_source,
            "L10_iso281_rev": val(b.life),
            "L10h_iso281_h": val(self.hours(b.life)),
            "a_ISO_iso281": val(b.life_modification),
            "Lnm_iso281_rev": val(b.modified_life),
            "Lnm_iso281_h": val(self.hours(b.modified_life)),
            "iso281_note": b.note,
            "P0_iso76_N": None if b.static_load is None else val(b.static_load),
            "C0_iso76_N": b.static_rating,
            "C0_source": b.static_rating_source,
            "s0_iso76": None if b.static_safety is None else val(b.static_safety),
        }

    def to_pandas(self):
        """One line per case and row: C, C0, L10r, s0, max pressure (SI columns; masked → NaN)."""
        import pandas as pd

        frames = []
        for r in self.rows:
            frames.append(
                pd.DataFrame(
                    {
                        "case": np.arange(self.n_cases),
                        "row": r.name,
                        "C_N": np.ma.filled(r.load_rating, np.nan),
                        "C0_N": np.ma.filled(r.static_rating, np.nan),
                        "L10r_rev": np.ma.filled(r.life, np.nan),
                        "static_safety": np.ma.filled(r.static_safety, np.nan),
                        "max_pressure_Pa": r.max_pressure,
                    }
                )
            )
        return pd.concat(frames, ignore_index=True)


def _per_case(name, value, n_cases, unit=""):
    if value is None:
        return None
    arr = np.asarray(value, dtype=float)
    if arr.ndim > 1 or (arr.ndim == 1 and arr.shape[0] not in (1, n_cases)):
        raise InputError(
            f"{name} (shape {arr.shape}) must be a scalar or have one value per case ({n_cases})"
        )
    return np.broadcast_to(arr, (n_cases,)).copy()


def rate(
    result,
    *,
    speed=None,
    rotating: str = "inner",
    reliability: float = 0.9,
    lubricant=None,
    temperature_C=None,
    contamination_factor=None,
    shoulder_height=None,
    edge_pressure_ratio: float = DEFAULT_EDGE_PRESSURE_RATIO,
    edge_stress_factor: str = "auto",
    load_ratings: Mapping | None = None,
    catalogue_rating=None,
    static_limit_factor: float = 1.0,
) -> RatingResult:
    """Rate every row of a solved bearing and combine the rows into the system life.

    Per row (see :class:`RowRating` and :data:`ROW_RATERS`): ISO 76 C0 and ISO 281 C of the row as a
    single-row bearing; ISO/TS 16281 L10r from the solved loads,

    .. math::

        L_{10r} = \\Bigl[\\Bigl(\\frac{Q_{ci}}{Q_{ei}}\\Bigr)^{-10/3}
                  + \\Bigl(\\frac{Q_{ce}}{Q_{ee}}\\Bigr)^{-10/3}\\Bigr]^{-0.9}\\ \\text{(balls)},\\qquad
        L_{10r} = \\Bigl[\\sum_k \\Bigl(\\frac{q_{kei}}{q_{ci}}\\Bigr)^{9/2}
                  + \\Bigl(\\frac{q_{kee}}{q_{ce}}\\Bigr)^{9/2}\\Bigr]^{-8/9}\\ \\text{(rollers)};

    static safety s0 = (f p_limit/p_max)^n (4200 MPa, n = 3 ball; 4000 MPa, n = 2 roller; ISO 76:2006 4;
    f = ``static_limit_factor``, the raceway material's share, 1 for rings of at least 58 HRC);
    a_ISO (ISO 281:2007 9.3.2) at the reference load P_ref = C (L10r/10⁶)^(−1/p) when lubrication inputs
    are given. System: :func:`system_life`; L_nr = a1 L, L10h = L / (3600 ω/2π).

    Parameters
    ----------
    result : QuasiStaticResult
        Solved load cases (C of them).
    speed : float or array_like (C,), optional
        Relative speed of the rotating ring ω [rad/s].
    rotating : {"inner", "outer"}
        Ring rotating relative to the load.
    reliability : float
        Reliability for L_nr and L_nmr [-], 0.90 … 0.9995.
    lubricant : Lubricant or str, optional
        For a_ISO, with ``temperature_C`` [°C] and ``contamination_factor`` e_C [-] (all three, and speed).
    temperature_C, contamination_factor : float or array_like (C,), optional
    shoulder_height : None, float or Mapping[str, float or (float, float)]
        Groove shoulder height over ball diameter [-] for the truncation check: one value, or per row
        name a value or an (inner, outer) pair; None = the kind's default
        (:data:`~bearingkit.analysis.rating.options.DEFAULT_SHOULDER_HEIGHTS`).
    edge_pressure_ratio : float
        End-slice pressure over the row's maximum slice pressure that flags edge loading [-].
    edge_stress_factor : {"auto", "always", "never"}
        ISO/TS 16281 eq. (60) slice factor use ("auto": rollers without a profile).
    load_ratings : Mapping[str, float], optional
        C [N] per row name, replacing ISO 281 (catalogue values; thrust roller rows).
    catalogue_rating : (float, float or None[, str]), optional
        The published (C, C0) [N] of the bearing (a designation): the C of the whole-bearing ISO 281
        basic rating life :attr:`RatingResult.iso281` (otherwise computed from the rows' geometry) and,
        divided over the rows as ISO 281 combines them, the C the rows' ISO/TS 16281 raceway ratings start
        from (rows named in ``load_ratings`` keep theirs; :attr:`RatingResult.notes` says so). A third
        item (C's source, C0's source), ``("rating_C", "rating_C0")`` or ``("rating_C", "catalogue")``,
        says they are a maker's given in ``[bearing] rating_C``/``rating_C0`` (the notes and
        ``C_source``/``C0_source`` name them so).
    static_limit_factor : float
        Multiplies ISO 76's limit pressures in s0 [-] (the raceway material's; 1 for rings of ≥ 58 HRC).

    Returns
    -------
    RatingResult

    References
    ----------
    ISO 76:2006 clause 4; ISO 281:2007 eq. (2)-(12), (15), 9.3; ISO/TS 16281:2008 eq. (19)-(65);
    Lundberg & Palmgren 1947, 1952.
    """
    n_cases = result.n_cases
    opts = RatingOptions(
        rotating=rotating,
        reliability=reliability,
        speed=_per_case("speed", speed, n_cases, "rad/s"),
        lubricant=lubricant,
        temperature_C=_per_case("temperature_C", temperature_C, n_cases, "°C"),
        contamination_factor=_per_case("contamination_factor", contamination_factor, n_cases),
        shoulder_height=shoulder_height,
        edge_pressure_ratio=edge_pressure_ratio,
        edge_stress_factor=edge_stress_factor,
        load_ratings=dict(load_ratings or {}),
        static_limit_factor=static_limit_factor,
    )
    unknown = set(opts.load_ratings) - {r.name for r in result.model.rows}
    if unknown:
        raise InputError(
            f"load_ratings names rows {sorted(unknown)} not in the bearing; rows are "
            f"{[r.name for r in result.model.rows]}"
        )
    converged = np.asarray(result.converged, dtype=bool)
    rows = _rate_rows(result, RowContext(options=opts, converged=converged, n_cases=n_cases))
    rating_notes = []
    from_catalogue = {
        k: v
        for k, v in catalogue_row_ratings(result.model, rows, catalogue_rating).items()
        if k not in opts.load_ratings
    }
    if from_catalogue:  # ISO/TS 16281 starts from the bearing's C: the catalogue's, as ISO 281 does
        geometry_c = {
            r.name: np.ma.getdata(r.load_rating)[0] for r in rows if not np.ma.getmaskarray(r.load_rating)[0]
        }
        opts = replace(opts, catalogue_ratings=from_catalogue)
        rows = _rate_rows(result, RowContext(options=opts, converged=converged, n_cases=n_cases))
        per_row = ", ".join(f"{k} {v / 1e3:.4g} kN" for k, v in from_catalogue.items())
        computed = ", ".join(f"{k} {v / 1e3:.4g} kN" for k, v in geometry_c.items())
        rating_notes.append(
            f"ISO/TS 16281 raceway ratings from {_rating_label(catalogue_rating, 0)} C = "
            f"{float(catalogue_rating[0]) / 1e3:.4g} kN "
            f"(per row: {per_row}), the C ISO 281 uses; the estimated geometry's ISO 281 C would be "
            f"{computed or 'unavailable'}"
        )

    geometry_c0 = _catalogue_static(result.model, rows, catalogue_rating, rating_notes)
    a1 = float(iso281.reliability_factor(opts.reliability))
    life, sys_notes = _combine(rows, "life", n_cases)
    if opts.modified:
        modified, mod_notes = _combine(rows, "modified_life_90", n_cases)
        modified = modified * a1
    else:
        modified, mod_notes = _masked(np.zeros(n_cases), True), [[] for _ in range(n_cases)]
    safety = np.ma.min(np.ma.stack([r.static_safety for r in rows]), axis=0)
    safety = _masked(np.ma.getdata(safety), np.ma.getmaskarray(safety) | ~converged)

    beyond = _edge_factor_beyond_range(result, opts)
    warnings = []
    for c in range(n_cases):
        notes = []
        if beyond[c]:
            tilt = float(np.degrees(np.hypot(*np.asarray(result.displacement[c, 3:5], float))) * 60.0)
            notes.append(
                f"edge-stress factor f_k of ISO/TS 16281 eq. (60) used at a ring misalignment of "
                f"{tilt:.3g}′, above the 4′ the TS states it for: the roller-end slices' share of L10r is "
                "approximate"
            )
        if not converged[c]:
            notes.append(
                f"case {c} did not converge ({result.reason[c]}): no rating, life or static safety returned"
            )
        else:
            for r in rows:
                notes.extend(f"{r.name}: {w}" for w in r.warnings[c])
            notes.extend(sys_notes[c])
            notes.extend(
                m.replace("system:", "system (a_ISO):") for m in mod_notes[c] if m not in sys_notes[c]
            )
        warnings.append(notes)
    refs = tuple(dict.fromkeys(_REFERENCES + tuple(k for r in rows for k in r.references)))
    iso = bearing_life(result, rows, opts, catalogue_rating, geometry_c0)
    free = np.asarray(getattr(result, "free", np.ones(5, bool)), bool)
    return RatingResult(
        bearing=result.model.name,
        rows=rows,
        life=life,
        life_reliability=life * a1,
        modified_life=modified,
        static_safety=safety,
        speed=opts.speed,
        reliability=opts.reliability,
        a1=a1,
        rotating=opts.rotating,
        converged=converged,
        warnings=warnings,
        references=refs,
        iso281=iso,
        notes=rating_notes,
        comparison=compare(result, rows, life, iso, free),
    )


def _rating_label(catalogue_rating, which: int) -> str:
    """How the notes name the published C (``which`` 0) or C0 (1): a catalogue's, or a maker's given as
    [bearing] rating_C / rating_C0 (the rating's third item, :func:`rate`)."""
    source = catalogue_rating[2][which] if len(catalogue_rating) > 2 else "catalogue"
    return "the catalogue" if source == "catalogue" else f"the given {source}:"


def _catalogue_static(model, rows, catalogue_rating, notes) -> float | None:
    """Replace the rows' C0 by the catalogue's (ISO 76: C0_row = C0 / i) where it prints one; the first
    row's geometry C0 [N] before (the C0 C_u is estimated from), None when nothing was replaced."""
    per_row = catalogue_row_static_ratings(model, rows, catalogue_rating)
    if not per_row:
        return None
    first = rows[0].static_rating
    geometry = None if np.ma.getmaskarray(first)[0] else float(np.ma.getdata(first)[0])
    computed = ", ".join(
        f"{r.name} {np.ma.getdata(r.static_rating)[0] / 1e3:.4g} kN"
        for r in rows
        if not np.ma.getmaskarray(r.static_rating)[0]
    )
    for r in rows:
        if r.name in per_row:
            n = np.ma.getdata(r.static_rating).shape[0]
            r.static_rating = np.ma.masked_array(np.full(n, per_row[r.name]), mask=np.zeros(n, bool))
    text = ", ".join(f"{k} {v / 1e3:.4g} kN" for k, v in per_row.items())
    notes.append(
        f"C0 from {_rating_label(catalogue_rating, 1)} C0 = {float(catalogue_rating[1]) / 1e3:.4g} kN "
        f"(per row: {text}; ISO 76 "
        f"C0 is linear in the rows); the estimated geometry's ISO 76 C0 would be {computed or 'unavailable'}"
    )
    return geometry


def _edge_factor_beyond_range(result, opts: RatingOptions) -> np.ndarray:
    """Per case: a row applies eq. (60) (:func:`~bearingkit.analysis.rating.rows._edge_checks`) while the
    rings are misaligned beyond :data:`~bearingkit.analysis.rating.rows.EDGE_FACTOR_MAX_MISALIGNMENT`."""
    uses = opts.edge_stress_factor != "never" and any(
        r.kind in EDGE_FACTOR_KINDS and getattr(r, "n_slices", 1) >= 2 for r in result.model.rows
    )
    tilt = np.hypot(*np.asarray(result.displacement, float)[:, 3:5].T)
    return uses & (tilt > EDGE_FACTOR_MAX_MISALIGNMENT) & np.asarray(result.converged, bool)


def _rate_rows(result, ctx: RowContext) -> list[RowRating]:
    """Every row of ``result`` rated by the rater of its kind (:data:`ROW_RATERS`)."""
    rows = []
    for row, state in zip(result.model.rows, result.rows, strict=True):
        rater: Callable | None = ROW_RATERS.get(row.kind)
        if rater is None:
            raise InputError(f"row kind ({row.kind!r}) has no rater; known kinds: {sorted(ROW_RATERS)}")
        rows.append(rater(row, state, ctx))
    return rows
