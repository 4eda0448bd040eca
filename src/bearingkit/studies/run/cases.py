"""The cases of a study, its fingerprint and its result object (shared by the runner and the optimiser).

SI units throughout (factor values as the evaluator declares them, outputs with units in their names).

Kept apart from :mod:`bearingkit.studies.run.runner` so that the runner and
:mod:`bearingkit.studies.run.optimize` both import downward from here and never from each other.

The **fingerprint** identifies a study in a store: the definition (without its file name), the
evaluator's identity (name, the function's module and qualified name, declared factors and
outputs), the bearingkit version, and the inputs derived from outside the file (the case table
with every factor value, so the geometry read from ``study.bearing`` counts; for an optimisation
the base values). Every chunk file carries it, so a chunk of another study is never reused.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass, field

import numpy as np

from bearingkit.errors import InputError
from bearingkit.studies import evaluators
from bearingkit.studies.definition.load import StudyDefinition, evaluator_of
from bearingkit.studies.designs import generators

#: Index columns of a levels × samples study: design point and draw (also kept in the chunk files).
INDEX_COLUMNS = ("point", "draw")


@dataclass
class StudyResult:
    """Outcome of :func:`bearingkit.studies.run.runner.run_study`.

    Attributes
    ----------
    definition : StudyDefinition
    cases : DataFrame
        The generated cases (``case`` id, design columns such as ``level_<factor>`` or ``swept``, and
        every factor value in SI); levels × samples designs add ``point``, ``draw`` and
        ``nominal_<factor>`` for toleranced design factors.
    results : DataFrame
        ``cases`` joined with the evaluator's outputs (one row per case, ordered by ``case``); for an
        optimisation, every evaluated point with its ``generation``.
    stats : dict
        ``chunks`` (total), ``computed`` (this run), ``reused`` (found in the store), ``seconds``,
        ``executor``; ``discarded`` (chunk files of another study or damaged, recomputed) when a
        resumed store held any.
    analysis : dict of DataFrame
        ``main_effects`` and ``range`` (designs with levels and a ``response``); levels × samples:
        ``point_statistics`` (one row per design point) and, with a response, the main effects and
        ranges of its per-point mean and of its per-point standard deviation (``range_std``).
    pareto : DataFrame or None
        Non-dominated feasible points of an optimisation.
    selections : DataFrame or None
        The knee point and the points nearest each named target, one row each (``selection`` column).
    """

    definition: StudyDefinition
    cases: object
    results: object
    stats: dict = field(default_factory=dict)
    analysis: dict = field(default_factory=dict)
    pareto: object = None
    selections: object = None

    def __repr__(self) -> str:
        d = self.definition
        head = ", ".join(map(str, list(self.results.columns)[:6]))
        return f"<StudyResult {d.name!r} ({d.design}): {len(self.results)} rows; columns {head} …>"

    def _repr_html_(self) -> str:
        """The notebook view (:mod:`bearingkit.display`): the first rows of :attr:`results` in display
        units named in the headers (``max_load [kN]``), the run's counts, the cases with warnings."""

        from bearingkit.display import MAX_ROWS, html_table, number
        from bearingkit.studies.results.display import display

        frame, d = self.results, self.definition
        try:
            dims = {name: f.dimension for name, f in evaluator_of(d).factors.items()}
        except Exception:  # a plugin evaluator that cannot be resolved here: SI columns, suffix units
            dims = {}
        head = frame.head(MAX_ROWS)
        columns, cells = [], []
        for name in frame.columns:
            values = head[name].to_numpy()
            if values.dtype.kind in "biuf" and name != "case":
                shown, label = display(str(name), values.astype(float), dims.get(name))
                columns.append(label)
                cells.append([number(v) for v in shown])
            else:
                columns.append(str(name))
                cells.append([str(v) for v in values])
        rows = [list(r) for r in zip(*cells, strict=True)] if cells else []
        warned = []
        if "warnings_count" in frame.columns:
            counts = zip(frame["case"], frame["warnings_count"], strict=True)
            warned = [f"case {c}: {int(n)} warning(s)" for c, n in counts if n > 0][:MAX_ROWS]
        stats = ", ".join(
            f"{k} {v:.3g}" if isinstance(v, float) else f"{k} {v}" for k, v in self.stats.items()
        )
        footer = f"{len(frame)} rows ({max(len(frame) - MAX_ROWS, 0)} not shown); {stats}"
        return html_table(f"study {d.name} ({d.design})", columns, rows, warnings=warned, footer=footer)


def base_values(definition: StudyDefinition) -> dict:
    """Value of every factor not varied by the design: evaluator default < bearing file < [fixed]."""
    ev = evaluator_of(definition)
    if not ev.fill_defaults:  # the evaluator reads the rest from its input: only what the study sets
        base = {f.name: ev.factors[f.name].default for f in definition.factors}
        base.update(definition.fixed)
        return base
    base = {k: f.default for k, f in ev.factors.items()}
    if definition.bearing:
        from bearingkit.io.loader import load_file

        bearing = load_file(definition.bearing)
        if ev.bearing_type and bearing.bearing_type != ev.bearing_type:
            raise InputError(
                f"{definition.source}: study.bearing ({definition.bearing}) is a {bearing.bearing_type!r} "
                f"bearing; evaluator {ev.name!r} needs a {ev.bearing_type!r}"
            )
        for k, v in bearing.geometry.model_dump().items():
            if k in ev.factors and v is not None:
                base[k] = v
    base.update(definition.fixed)
    return base


def build_cases(definition: StudyDefinition):
    """The cases of a non-optimisation study (DataFrame with a ``case`` id column first)."""
    d = definition
    base = base_values(d)
    try:
        design = _design(d, base)
    except InputError as exc:  # a generator's message names the factor; say which file and section
        raise InputError(f"{d.source}: factors: {exc}") from None
    for k, v in base.items():
        if k not in design.columns:
            design[k] = v
    design.insert(0, "case", np.arange(len(design)))
    return design


def _design(d: StudyDefinition, base: dict):
    """The design columns of the cases (before the base values and the ``case`` id)."""
    levels = {f.name: list(f.levels or ()) for f in d.factors}
    if d.design == "orthogonal":
        cols = [f.column for f in d.factors]
        design = generators.orthogonal_design(levels, d.array, None if None in cols else cols)
    elif d.design == "factorial":
        design = generators.full_factorial(levels)
    elif d.design == "sweep":
        sweep_base = {f.name: (f.base if f.base is not None else base[f.name]) for f in d.factors}
        design = generators.sweep(levels, sweep_base)
    elif d.design == "monte_carlo":
        dists = {
            f.name: generators.Distribution(f.distribution, f.mean, f.std, f.low, f.high) for f in d.factors
        }
        design = generators.monte_carlo(dists, d.samples, d.seed, d.sampler)
    else:
        raise InputError(f"{d.source}: design ({d.design!r}) has no case table (use run_study)")
    if d.monte_carlo is not None:
        mc = d.monte_carlo
        dists = {
            f.name: generators.Distribution(f.distribution, f.mean, f.std, f.low, f.high) for f in mc.factors
        }
        design = generators.levels_by_samples(
            design,
            dists,
            mc.per_point,
            d.seed if mc.seed is None else mc.seed,
            mc.sampler,
            mc.common,
            deviations=[f.name for f in mc.factors if f.deviation],
        )
    return design


@dataclass
class StudyPlan:
    """What a study will run, known before anything is written: every check of the inputs is done.

    Attributes
    ----------
    definition : StudyDefinition
    evaluator : Evaluator
        Resolved once here (workers receive this object, never a name to resolve).
    cases : DataFrame or None
        The case table (None for an optimisation, whose cases come per generation).
    base : dict
        The value of every factor not varied (evaluator default < bearing file < [fixed]).
    fingerprint : str
        The study's identity in a store (:func:`fingerprint`).
    """

    definition: StudyDefinition
    evaluator: evaluators.Evaluator
    cases: object
    base: dict
    fingerprint: str


def plan_study(definition: StudyDefinition) -> StudyPlan:
    """Resolve the evaluator, read the bearing file, build the cases and the fingerprint.

    Everything that can refuse a study happens here, before a study touches its output folder.
    """
    ev = evaluator_of(definition)
    base = base_values(definition)
    if definition.design == "optimize":
        return StudyPlan(definition, ev, None, base, fingerprint(definition, base=base))
    cases = build_cases(definition)
    return StudyPlan(definition, ev, cases, base, fingerprint(definition, cases))


def evaluator_identity(evaluator: evaluators.Evaluator) -> str:
    """What identifies an evaluator's code: name, function, declared factors and outputs."""
    fn = evaluator.function
    factors = [(f.name, f.dimension, repr(f.default), f.batched) for f in evaluator.factors.values()]
    return json.dumps(
        {
            "name": evaluator.name,
            "function": f"{getattr(fn, '__module__', '?')}:{getattr(fn, '__qualname__', repr(fn))}",
            "factors": factors,
            "outputs": list(evaluator.outputs),
            "bearing_type": evaluator.bearing_type,
        },
        sort_keys=True,
    )


def fingerprint(definition: StudyDefinition, cases=None, base: dict | None = None) -> str:
    """SHA-256 identifying a study in a store (see the module docstring)."""
    import pandas as pd

    import bearingkit

    h = hashlib.sha256(definition.fingerprint().encode())
    h.update(evaluator_identity(evaluator_of(definition)).encode())
    h.update(f"bearingkit {bearingkit.__version__}".encode())
    if cases is not None:
        h.update(pd.util.hash_pandas_object(cases, index=False).to_numpy().tobytes())
    if base is not None:
        h.update(json.dumps(base, sort_keys=True, default=repr).encode())
    return h.hexdigest()
