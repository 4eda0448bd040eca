"""A study's first cases, evaluated in this process before anything is written or started.

SI units as the evaluators'. Two things about a study are known only once its evaluator has run:
which output columns it gives, and what one case costs. Both used to surface at the end: a plot,
``response`` or objective naming a column the results lack was refused after every chunk was
computed (leaving chunks that the corrected file's fingerprint no longer matches), and a study of
ten thousand slow cases simply ran for hours. :func:`probe_study` evaluates the study's first
:data:`PROBE_CASES` cases (an optimisation: as many points spread over its variables' box) and

- refuses every name the definition gives that is neither a factor nor a column of those results;
- estimates the whole study's processor time from them, chunk overhead and per-case cost apart, and
  refuses it in one line, with how to raise the limit, when it passes
  :func:`bearingkit.budget.max_work` (divided among the workers).

The probe's results are not kept: the run computes every case, the probed ones included, so a
resumed or distributed run stays bit-identical to a plain one.
"""

from __future__ import annotations

import math
import time

import numpy as np

from bearingkit.budget import check_work
from bearingkit.errors import InputError, quote
from bearingkit.studies.run import executors

#: Cases the probe evaluates (after a warm-up of the same two calls: their first evaluation carries
#: the one-time costs of building the input and loading compiled code).
PROBE_CASES = 4


def probe_study(plan, workers: int = 1) -> None:
    """Evaluate the first cases of ``plan`` (a :class:`~bearingkit.studies.run.cases.StudyPlan`) and
    refuse unknown output names and a study estimated past the work limit (module docstring)."""
    d, ev = plan.definition, plan.evaluator
    if d.design == "optimize":
        n_total = d.optimizer.pop_size * d.optimizer.generations
        inputs = _box_points(d, plan.base, min(PROBE_CASES, n_total))
    else:
        cases = plan.cases
        n_total = len(cases)
        if n_total == 0:
            return
        inputs = cases[["case", *[c for c in cases.columns if c in ev.factors]]].iloc[
            : min(PROBE_CASES, n_total)
        ]
    k = len(inputs)
    one = inputs.iloc[:1]
    # Warm-up of both timed calls: a chunk of one case and a chunk of several take different compiled
    # drivers (the serial one below two cases per thread: bearingkit.analysis.solver.threads), and the
    # first call of each loads it (~70 ms for the tapered core); timed, that load made seed 001's
    # 6,000-case study look 100x dearer than it is (23 ms a case, not 0.25) and refused it.
    executors.evaluate_chunk(ev, one)
    executors.evaluate_chunk(ev, inputs)
    started = time.process_time()
    executors.evaluate_chunk(ev, one)
    t_one = time.process_time() - started
    started = time.process_time()
    out = executors.evaluate_chunk(ev, inputs)
    t_k = time.process_time() - started
    per_case = max(t_k - t_one, 0.0) / (k - 1) if k > 1 else t_one
    per_chunk = max(t_one - per_case, 0.0)
    # chunk_size "auto" is chosen later from a measured per-chunk cost (run/chunking.py): estimate with
    # one chunk per worker, the least overhead it can choose (the budget check refuses only clear excess)
    size = d.chunk_size if d.chunk_size != "auto" else -(-n_total // max(1, int(workers or 1)))
    chunks = math.ceil(n_total / max(1, int(size)))
    seconds = (chunks * per_chunk + n_total * per_case) / max(1, int(workers or 1))
    check_work(
        seconds,
        f"study {d.name!r}: {n_total:,} {'evaluations' if d.design == 'optimize' else 'cases'} at "
        f"{per_case * 1e3:.3g} ms each{f' on {workers} workers' if (workers or 1) > 1 else ''}",
        "give fewer levels, samples or generations",
    )
    _check_names(d, plan, set(out.columns))


def _check_names(d, plan, columns: set) -> None:
    """Every output the definition names is a column of the evaluated cases (or a factor)."""
    factors = set(plan.evaluator.factors) | {f.name for f in d.factors} | set(d.fixed)
    if d.monte_carlo is not None:
        factors |= {f.name for f in d.monte_carlo.factors}
    have = columns | factors
    named = [("study.outputs", o) for o in d.outputs or ()]
    if d.response is not None:
        named.append(("study.response", d.response))
    named += [(f"objectives ({o.output})", o.output) for o in d.objectives]
    named += [(f"constraints ({c.output})", c.output) for c in d.constraints]
    for i, p in enumerate(d.plots):
        named += [(f"plots[{i}]", n) for n in (p.x, p.series, *p.y) if n is not None]
    kept = set(d.outputs) if d.outputs else None
    for where, name in named:
        if name not in have:
            raise InputError(
                f"{d.source}: {where} ({quote(name)}) is not an output of the study's evaluator; it gives "
                f"{quote(sorted(columns - {'case'}))}"
            )
        if kept is not None and where != "study.outputs" and name in columns and name not in kept:
            raise InputError(
                f"{d.source}: {where} ({quote(name)}) is not among study.outputs; add it there "
                "(only the listed outputs are kept)"
            )


def _box_points(d, base: dict, k: int):
    """``k`` points spread over the optimisation's variable box (a case table as the optimiser's)."""
    from bearingkit.studies.run.optimize import _population_cases

    low = np.array([v.low for v in d.variables], float)
    high = np.array([v.high for v in d.variables], float)
    spread = (np.arange(k)[:, None] + 0.5) / k
    x = low + (high - low) * spread
    names = [v.name for v in d.variables]
    fixed = {k: val for k, val in base.items() if k not in names and k in ev_factors(d)}
    cases = _population_cases(x, names, [v.integer for v in d.variables], fixed)
    cases.insert(0, "case", np.arange(k))
    return cases


def ev_factors(d) -> dict:
    from bearingkit.studies.definition.load import evaluator_of

    return evaluator_of(d).factors
