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

import numpy as np

from bearingkit.errors import InputError
from bearingkit.studies.definition.load import StudyDefinition, load_study
from bearingkit.studies.results import analysis
from bearingkit.studies.run import chunking, workers
from bearingkit.studies.run.cases import (
    INDEX_COLUMNS,
    StudyPlan,
    StudyResult,
    base_values,
    build_cases,
    plan_study,
)
from bearingkit.studies.run.executors import InProcessExecutor
from bearingkit.studies.run.optimize import run_optimization
from bearingkit.studies.run.store import MemoryStore, ParquetStore, advance, progress_bar

__all__ = [
    "INDEX_COLUMNS",
    "StudyPlan",
    "StudyResult",
    "base_values",
    "build_cases",
    "design_points",
    "plan_study",
    "run_study",
]


def _as_definition(definition) -> StudyDefinition:
    return definition if isinstance(definition, StudyDefinition) else load_study(definition)


def _as_store(store):
    if store is None:
        return MemoryStore()
    if isinstance(store, (str, bytes)) or hasattr(store, "__fspath__"):
        return ParquetStore(store)
    return store


def run_study(
    definition,
    executor=None,
    store=None,
    resume: bool = False,
    progress: bool | None = None,
    plan: StudyPlan | None = None,
):
    """Run a study and return a :class:`StudyResult`.

    Parameters
    ----------
    definition : StudyDefinition or path
        The study (or its TOML file).
    executor : executor or None
        :class:`~bearingkit.studies.run.executors.InProcessExecutor` (default), ``ProcessPoolExecutor``
        or ``DaskExecutor``; not closed here.
    store : ParquetStore, path or None
        Where finished chunks stream to (a directory path makes a :class:`ParquetStore`); None keeps
        them in memory. A directory is locked for the run (a second writer is refused) unless the
        caller locked it already, and is removed again if this run created it and failed before
        finishing a chunk.
    resume : bool
        Keep the chunks already in ``store`` (same study) and compute only the missing ones.
    progress : bool or None
        Show a rich progress bar (None: only on a terminal).
    plan : StudyPlan or None
        The study's :func:`~bearingkit.studies.run.cases.plan_study` when the caller made it already.
    """
    d = _as_definition(definition)
    store = _as_store(store)
    if resume and isinstance(store, MemoryStore):
        raise InputError("resume (True) needs a ParquetStore (an output directory)")
    plan = plan or plan_study(d)  # every check of the inputs, before the store is touched
    executor = executor or InProcessExecutor()
    own_lock = isinstance(store, ParquetStore) and not store.locked
    try:
        if own_lock:
            store.lock(d.name)
        if d.design == "optimize":
            return run_optimization(d, executor, store, resume, progress, plan)
        return _run_cases(plan, executor, store, resume, progress)
    except BaseException:
        if own_lock:
            store.discard_if_unused()
        raise
    finally:
        if own_lock:
            store.close()


def _run_cases(plan: StudyPlan, executor, store, resume: bool, progress) -> StudyResult:
    """Evaluate the case table of a non-optimisation study chunk by chunk into ``store``."""
    d, ev, cases = plan.definition, plan.evaluator, plan.cases
    t0 = time.perf_counter()
    inputs = cases[["case", *[c for c in cases.columns if c in ev.factors]]]
    index = [c for c in INDEX_COLUMNS if c in cases.columns]
    size, cost = chunk_size(plan, executor, store, resume, inputs)
    bounds = list(range(0, len(cases), size))
    done = store.open(plan.fingerprint, len(bounds), size, resume, study=d.name)
    todo = [i for i in range(len(bounds)) if i not in done]
    chunks = [inputs.iloc[bounds[i] : bounds[i] + size].reset_index(drop=True) for i in todo]
    # The workers send back numpy columns (the outputs the study keeps, selected there); the index
    # columns are added here by position, and the store writes the columns as they are.
    fn = functools.partial(workers.evaluate_columns, ev, outputs=d.outputs)
    index_values = {col: cases[col].to_numpy() for col in index}
    prog, task = progress_bar(len(cases), d.name, progress)
    with prog:
        advance(prog, task, sum(min(size, len(cases) - bounds[i]) for i in done))
        for pos, out in executor.map_unordered(fn, chunks):
            if index:  # the chunk files say which point and draw they hold
                ids = out["case"]
                out = {"case": ids, **{c: v[ids] for c, v in index_values.items()}, **out}
            store.write(todo[pos], out)
            advance(prog, task, len(out["case"]))
    outputs = store.read()
    got = np.sort(outputs["case"].to_numpy()) if len(outputs) else np.array([], int)
    if not np.array_equal(got, cases["case"].to_numpy()):
        raise RuntimeError(
            f"study {d.name!r}: the store holds {len(outputs)} result rows for {len(cases)} cases "
            "(a chunk file is missing or doubled); run again without --resume"
        )
    results = cases.merge(outputs, on=["case", *index], how="left", validate="one_to_one")
    stats = {
        "chunks": len(bounds),
        "chunk_size": size,
        "computed": len(todo),
        "reused": len(done),
        "seconds": time.perf_counter() - t0,
        "executor": getattr(executor, "name", type(executor).__name__),
    }
    if cost is not None:
        stats["chunk_cost"] = {
            "per_case_s": cost.per_case_s,
            "per_chunk_s": cost.per_chunk_s,
            "overhead_share": cost.overhead(size),
        }
    if getattr(store, "discarded", 0):
        stats["discarded"] = store.discarded
    result = StudyResult(d, cases, results, stats=stats)
    if d.monte_carlo is not None:
        _levels_by_samples_analysis(result, outputs.columns.difference(["case", *index], sort=False))
    elif d.design == "monte_carlo":  # one sample of the whole study: statistics of every output
        names = list(outputs.columns.difference(["case"], sort=False))
        table = analysis.point_statistics(results.assign(point=0), names, d.quantiles)
        result.analysis["statistics"] = table.drop(columns=["point"])
    elif d.response and d.design in ("orthogonal", "factorial"):
        names = [f.name for f in d.factors]
        result.analysis["main_effects"] = analysis.main_effects(results, names, d.response)
        labels = {f.name: f.label or f.name for f in d.factors}
        result.analysis["range"] = analysis.range_analysis(results, names, d.response, labels)
    return result


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


def chunk_size(plan: StudyPlan, executor, store, resume: bool, inputs) -> tuple[int, object]:
    """Cases per chunk and the measured :class:`~bearingkit.studies.run.chunking.ChunkCost` (or None).

    The study's number when it gives one; ``"auto"``: the size a resumed store recorded, else one
    chosen from the study's own measured costs (:mod:`bearingkit.studies.run.chunking`).
    """
    from bearingkit.studies.definition.schema import MAX_CHUNK_SIZE

    d = plan.definition
    if d.chunk_size != "auto":
        return int(d.chunk_size), None
    if resume:
        recorded = store.recorded_chunk_size(plan.fingerprint)
        if recorded is not None:
            return recorded, None
    n, slots = len(inputs), max(1, int(getattr(executor, "workers", 1) or 1))
    cost = None
    if n >= chunking.MEASURE_FROM_CASES:
        from bearingkit.analysis.solver.threads import thread_limit

        if hasattr(executor, "start"):  # a pool's workers load while this process measures
            executor.start()
        evaluate = functools.partial(workers.evaluate_columns, plan.evaluator, outputs=d.outputs)
        with thread_limit(1):  # as every chunk runs when there are several (one solver thread each)
            cost = chunking.measure(evaluate, inputs)
        overhead = getattr(executor, "task_overhead", None)
        if overhead is not None:
            cost = chunking.ChunkCost(cost.per_case_s, cost.per_chunk_s + overhead())
    return chunking.choose(n, slots, cost, MAX_CHUNK_SIZE), cost
