"""Run a study: generate its cases, evaluate them in chunks on an executor, stream them to a store.

SI units throughout (factor values and outputs as the evaluator defines them, units in output names).

:func:`run_study` is the one entry point (the CLI's ``bearingkit study`` calls it through
:func:`bearingkit.studies.__main__.run_cli`). The cases are fixed before anything runs (Monte Carlo
samples come from the study's seed) and split into chunks of ``chunk_size`` cases; a chunk is the unit
of parallel work and of resume. Each chunk is one call of the evaluator (one batched solve per group
of cases), so results do not depend on the executor. A study with a ``[monte_carlo]`` section is a
levels × samples design: every point of its sweep/factorial/orthogonal design is repeated with
``per_point`` random draws (cases ``point``-major, indexed by ``point`` and ``draw``), and its
analysis gives the statistics of every output per design point. Optimisation studies evaluate one population
per generation through the same machinery (chunk id = generation) and replay deterministically on
resume.
"""

from __future__ import annotations

import functools
import time
from dataclasses import dataclass, field

import numpy as np

from bearingkit.errors import InputError
from bearingkit.studies import analysis, evaluators, generators
from bearingkit.studies.definition import StudyDefinition, load_study
from bearingkit.studies.executors import InProcessExecutor
from bearingkit.studies.store import MemoryStore, ParquetStore, advance, progress_bar


@dataclass
class StudyResult:
    """Outcome of :func:`run_study`.

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
        ``chunks`` (total), ``computed`` (this run), ``reused`` (found in the store), ``seconds``.
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


def base_values(definition: StudyDefinition) -> dict:
    """Value of every factor not varied by the design: evaluator default < bearing file < [fixed]."""
    ev = evaluators.get(definition.evaluator)
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
    for k, v in base.items():
        if k not in design.columns:
            design[k] = v
    design.insert(0, "case", np.arange(len(design)))
    return design


def _fingerprint(definition: StudyDefinition, cases=None) -> str:
    import hashlib

    import pandas as pd

    h = hashlib.sha256(definition.fingerprint().encode())
    if cases is not None:
        h.update(pd.util.hash_pandas_object(cases, index=False).to_numpy().tobytes())
    return h.hexdigest()


def _as_definition(definition) -> StudyDefinition:
    return definition if isinstance(definition, StudyDefinition) else load_study(definition)


def _as_store(store):
    if store is None:
        return MemoryStore()
    if isinstance(store, (str, bytes)) or hasattr(store, "__fspath__"):
        return ParquetStore(store)
    return store


def run_study(definition, executor=None, store=None, resume: bool = False, progress: bool | None = None):
    """Run a study and return a :class:`StudyResult`.

    Parameters
    ----------
    definition : StudyDefinition or path
        The study (or its TOML file).
    executor : executor or None
        :class:`~bearingkit.studies.executors.InProcessExecutor` (default), ``ProcessPoolExecutor``
        or ``DaskExecutor``; not closed here.
    store : ParquetStore, path or None
        Where finished chunks stream to (a directory path makes a :class:`ParquetStore`); None keeps
        them in memory.
    resume : bool
        Keep the chunks already in ``store`` (same study) and compute only the missing ones.
    progress : bool or None
        Show a rich progress bar (None: only on a terminal).
    """
    d = _as_definition(definition)
    executor = executor or InProcessExecutor()
    store = _as_store(store)
    if resume and isinstance(store, MemoryStore):
        raise InputError("resume (True) needs a ParquetStore (an output directory)")
    if d.design == "optimize":
        from bearingkit.studies.optimize import run_optimization

        return run_optimization(d, executor, store, resume, progress)
    t0 = time.perf_counter()
    cases = build_cases(d)
    ev = evaluators.get(d.evaluator)
    inputs = cases[["case", *[c for c in cases.columns if c in ev.factors]]]
    index = [c for c in INDEX_COLUMNS if c in cases.columns]
    bounds = list(range(0, len(cases), d.chunk_size))
    done = store.open(_fingerprint(d, cases), len(bounds), d.chunk_size, resume)
    todo = [i for i in range(len(bounds)) if i not in done]
    chunks = [inputs.iloc[bounds[i] : bounds[i] + d.chunk_size].reset_index(drop=True) for i in todo]
    fn = functools.partial(evaluators.evaluate_chunk, d.evaluator)
    prog, task = progress_bar(len(cases), d.name, progress)
    with prog:
        advance(prog, task, sum(min(d.chunk_size, len(cases) - bounds[i]) for i in done))
        for pos, out in executor.map_unordered(fn, chunks):
            out = _select(out, d.outputs)
            for k, col in enumerate(index):  # the chunk files say which point and draw they hold
                out.insert(1 + k, col, cases[col].to_numpy()[out["case"].to_numpy()])
            store.write(todo[pos], out)
            advance(prog, task, len(out))
    outputs = store.read()
    results = cases.merge(outputs, on=["case", *index], how="left", validate="one_to_one")
    result = StudyResult(
        d,
        cases,
        results,
        stats={
            "chunks": len(bounds),
            "computed": len(todo),
            "reused": len(done),
            "seconds": time.perf_counter() - t0,
            "executor": getattr(executor, "name", type(executor).__name__),
        },
    )
    if d.monte_carlo is not None:
        _levels_by_samples_analysis(result, outputs.columns.difference(["case", *index], sort=False))
    elif d.response and d.design in ("orthogonal", "factorial"):
        names = [f.name for f in d.factors]
        result.analysis["main_effects"] = analysis.main_effects(results, names, d.response)
        labels = {f.name: f.label or f.name for f in d.factors}
        result.analysis["range"] = analysis.range_analysis(results, names, d.response, labels)
    return result


#: Index columns of a levels × samples study: design point and draw (also kept in the chunk files).
INDEX_COLUMNS = ("point", "draw")


def design_points(cases, factors):
    """The design points of a levels × samples case table: one row per ``point``.

    Columns: ``point``, the design columns (``level_<factor>``, ``swept``) and the design ``factors``
    at their levels (a toleranced factor shows its level, ``nominal_<factor>``, not a draw).
    """
    import pandas as pd

    first = cases.groupby("point", sort=True).first()
    cols = {"point": first.index.to_numpy()}
    for c in cases.columns:
        if c.startswith("level_") or c == "swept":
            cols[c] = first[c].to_numpy()
    for f in factors:
        cols[f] = first[f"nominal_{f}" if f"nominal_{f}" in first.columns else f].to_numpy()
    return pd.DataFrame(cols)


def _levels_by_samples_analysis(result: StudyResult, outputs) -> None:
    d = result.definition
    stats = analysis.point_statistics(result.results, list(outputs), d.monte_carlo.quantiles)
    names = [f.name for f in d.factors]
    table = design_points(result.cases, names).merge(stats, on="point", validate="one_to_one")
    result.analysis["point_statistics"] = table
    if d.response and d.design in ("orthogonal", "factorial"):
        labels = {f.name: f.label or f.name for f in d.factors}
        mean, std = f"{d.response}_mean", f"{d.response}_std"
        result.analysis["main_effects"] = analysis.main_effects(table, names, mean)
        result.analysis["range"] = analysis.range_analysis(table, names, mean, labels)
        if d.monte_carlo.per_point > 1:
            result.analysis["range_std"] = analysis.range_analysis(table, names, std, labels)


def _select(frame, outputs):
    if not outputs:
        return frame
    missing = [o for o in outputs if o not in frame.columns]
    if missing:
        raise InputError(
            f"study.outputs {missing} are not outputs of the evaluator; it gives {list(frame.columns)}"
        )
    return frame[["case", *outputs]]
