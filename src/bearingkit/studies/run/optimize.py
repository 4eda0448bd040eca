"""Multi-objective optimisation of a study with pymoo (NSGA-II / NSGA-III), vectorised per generation.

SI units: variables, objectives and constraints carry the SI units of the evaluator's factors/outputs.

The whole population of a generation is one batch: pymoo's vectorised ``Problem._evaluate`` receives
the population matrix, which is evaluated as one chunk set on the study's executor (split into chunks
of ``chunk_size``) and stored as store chunk ``generation``. With a fixed seed the algorithm is
deterministic, so a resumed run replays the stored generations (checking that the requested points
are bit-identical) and continues where it stopped.

Integer variables are rounded by a repair operator (continuous SBX/PM underneath; Deb & Agrawal 1995
operators as pymoo implements them). Constraints ``output ≤ upper`` / ``output ≥ lower`` become
pymoo's inequality constraints G ≤ 0; a case whose solve did not converge (``converged`` False) or
whose objectives are not finite is infeasible.

Selection on the front: the knee (largest distance below the hyperplane through the normalised extreme
points; Das 1999 / Deb & Gupta 2011) and the point nearest a named target (Euclidean distance in
coordinates normalised by the front's range).
"""

from __future__ import annotations

import functools
import time

import numpy as np

from bearingkit import references
from bearingkit.errors import InputError
from bearingkit.extras import require
from bearingkit.studies.run import workers
from bearingkit.studies.run.cases import StudyResult, plan_study
from bearingkit.studies.run.store import advance, progress_bar

references.add(
    "deb2002",
    "Deb, K., Pratap, A., Agarwal, S., Meyarivan, T. (2002). A fast and elitist multiobjective genetic "
    "algorithm: NSGA-II. IEEE Trans. Evol. Comput. 6(2):182–197. doi:10.1109/4235.996017",
)
references.add(
    "deb2014",
    "Deb, K., Jain, H. (2014). An Evolutionary Many-Objective Optimization Algorithm Using Reference-Point-"
    "Based Nondominated Sorting Approach (NSGA-III). IEEE Trans. Evol. Comput. 18(4):577–601. "
    "doi:10.1109/TEVC.2013.2281535",
)
references.add(
    "blank2020",
    "Blank, J., Deb, K. (2020). pymoo: Multi-Objective Optimization in Python. IEEE Access 8:89497–89509. "
    "doi:10.1109/ACCESS.2020.2990567",
)
references.add(
    "deb2011knee",
    "Deb, K., Gupta, S. (2011). Understanding knee points in bicriteria problems and their implications "
    "as preferred solution principles. Engineering Optimization 43(11):1175–1204. "
    "doi:10.1080/0305215X.2010.548863",
)

#: Penalty objective value given to infeasible (non-converged / non-finite) cases.
PENALTY = 1e30


def knee_point(F: np.ndarray) -> int:
    """Index of the knee of a front F (n, m) of minimised objectives.

    Objectives are normalised to [0, 1] over the front; the knee maximises the distance below the
    hyperplane Σ f̂ = 1 through the normalised extreme points:

    .. math:: d = (1 - \\sum_k \\hat f_k) / \\sqrt{m}
    """
    F = np.asarray(F, float)
    lo, hi = F.min(axis=0), F.max(axis=0)
    fn = (F - lo) / np.where(hi > lo, hi - lo, 1.0)
    return int(np.argmax((1.0 - fn.sum(axis=1)) / np.sqrt(F.shape[1])))


def nearest(frame, target: dict) -> int:
    """Positional index of the row of ``frame`` nearest ``target`` (column → value), each column
    normalised by its range over ``frame``."""
    cols = list(target)
    missing = [c for c in cols if c not in frame.columns]
    if missing:
        raise InputError(f"target columns {missing} are neither variables nor outputs of the front")
    x = frame[cols].to_numpy(float)
    t = np.array([target[c] for c in cols], float)
    span = x.max(axis=0) - x.min(axis=0)
    d = (x - t) / np.where(span > 0, span, 1.0)
    return int(np.argmin(np.einsum("ij,ij->i", d, d)))


def non_dominated(F: np.ndarray) -> np.ndarray:
    """Indices of the non-dominated rows of F (minimisation)."""
    from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

    return np.asarray(NonDominatedSorting().do(np.asarray(F, float), only_non_dominated_front=True))


def _problem_class():
    from pymoo.core.problem import Problem

    class _StudyProblem(Problem):
        def __init__(self, definition, evaluate):
            d = definition
            self.d, self._batch = d, evaluate
            n_g = sum((c.upper is not None) + (c.lower is not None) for c in d.constraints) + 1
            super().__init__(
                n_var=len(d.variables),
                n_obj=len(d.objectives),
                n_ieq_constr=n_g,
                xl=np.array([v.low for v in d.variables]),
                xu=np.array([v.high for v in d.variables]),
            )

        def _evaluate(self, X, out, *args, **kwargs):
            out["F"], out["G"] = objectives_and_constraints(self.d, self._batch(X))

    return _StudyProblem


def objectives_and_constraints(d, frame):
    """pymoo's F (minimised) and G (≤ 0 feasible) arrays from an evaluated population.

    ``frame``: a DataFrame or a mapping column → array.
    """
    F = np.column_stack(
        [np.asarray(frame[o.output], float) * (1.0 if o.sense == "min" else -1.0) for o in d.objectives]
    )
    G = []
    for c in d.constraints:
        y = np.asarray(frame[c.output], float)
        if c.upper is not None:
            G.append(y - c.upper)
        if c.lower is not None:
            G.append(c.lower - y)
    ok = np.all(np.isfinite(F), axis=1)
    if "converged" in frame:
        ok &= np.asarray(frame["converged"], bool)
    G.append(np.where(ok, -1.0, 1.0))
    F = np.where(ok[:, None], F, PENALTY)
    G = np.column_stack([np.where(np.isfinite(g), g, PENALTY) for g in G])
    return F, G


def _repair_class(integer_mask):
    from pymoo.core.repair import Repair

    class _Round(Repair):
        def _do(self, problem, X, **kwargs):
            X = np.array(X, dtype=float, copy=True)
            X[:, integer_mask] = np.round(X[:, integer_mask])
            return X

    return _Round()


def algorithm_for(d):
    """The pymoo algorithm of the study (NSGA-II or NSGA-III with Das–Dennis reference directions)."""
    from pymoo.algorithms.moo.nsga2 import NSGA2
    from pymoo.algorithms.moo.nsga3 import NSGA3
    from pymoo.util.ref_dirs import get_reference_directions

    o = d.optimizer
    integer = np.array([v.integer for v in d.variables])
    kw = {"pop_size": o.pop_size, "eliminate_duplicates": True}
    if integer.any():
        kw["repair"] = _repair_class(integer)
    if o.algorithm == "nsga2":
        return NSGA2(**kw)
    ref = get_reference_directions("das-dennis", len(d.objectives), n_partitions=o.n_partitions)
    return NSGA3(ref_dirs=ref, **kw)


def _population_cases(X, names, integer, fixed):
    """The case table of a population X (P, n_var): the variables and the fixed factors."""
    import pandas as pd

    cols = {}
    for j, (name, is_int) in enumerate(zip(names, integer, strict=True)):
        cols[name] = np.round(X[:, j]).astype(int) if is_int else X[:, j]
    later = {}
    for k, val in fixed.items():
        (cols if pd.api.types.is_scalar(val) else later)[k] = val
    cases = pd.DataFrame(cols)
    for k, val in later.items():  # a non-scalar value (rare) is set as before, one column at a time
        cases[k] = val
    return cases


def run_optimization(d, executor, store, resume: bool, progress, plan=None):
    """Run an ``optimize`` study (called by :func:`bearingkit.studies.run.runner.run_study`)."""
    require("pymoo", "studies", "an optimisation study")  # one line naming the extra, not a traceback
    from pymoo.optimize import minimize

    t0 = time.perf_counter()
    plan = plan or plan_study(d)
    ev, base = plan.evaluator, plan.base
    names = [v.name for v in d.variables]
    o = d.optimizer
    done = store.open(plan.fingerprint, o.generations, d.chunk_size, resume, study=d.name)
    counts = {"computed": 0, "reused": 0, "generation": 0}
    fn = functools.partial(workers.evaluate_columns, ev)  # numpy columns: no DataFrame per chunk
    prog, task = progress_bar(o.pop_size * o.generations, d.name, progress)

    integer = [v.integer for v in d.variables]
    fixed = {k: val for k, val in base.items() if k not in names and k in ev.factors}

    def evaluate(X):
        # A generation costs pymoo ~10 ms; everything here is kept to a few whole-column pandas
        # operations (each costs 0.1-0.5 ms in pandas 3), never one per individual or per column edit.
        gen = counts["generation"]
        counts["generation"] += 1
        X = np.asarray(X, dtype=float)
        if gen in done:
            old = store.read_chunk(gen)
            if len(old) == len(X) and np.array_equal(old[names].to_numpy(float), X):
                counts["reused"] += 1
                advance(prog, task, len(X))
                return old
            raise InputError(f"resume: generation {gen} in the store does not match the replayed population")
        cases = _population_cases(X, names, integer, fixed)
        # "auto": one chunk per worker (a generation is small; one chunk on one worker leaves the
        # others idle, more chunks than workers only add their fixed cost)
        step = d.chunk_size if d.chunk_size != "auto" else -(-len(X) // max(1, executor.workers))
        chunks = [cases] if len(X) <= step else [cases.iloc[i : i + step] for i in range(0, len(X), step)]
        parts = dict(executor.map_unordered(fn, chunks))
        parts = [parts[i] for i in sorted(parts)]
        columns = {"generation": np.full(len(X), gen), **{n: X[:, j] for j, n in enumerate(names)}}
        for c in d.outputs or [k for k in parts[0] if k != "case"]:  # the study's output order
            if c not in names:
                columns[c] = parts[0][c] if len(parts) == 1 else np.concatenate([p[c] for p in parts])
        store.write(gen, columns)
        counts["computed"] += 1
        advance(prog, task, len(X))
        return columns  # pymoo's F and G come from the arrays, not from the frame

    problem = _problem_class()(d, evaluate)
    with prog:
        minimize(problem, algorithm_for(d), ("n_gen", o.generations), seed=o.seed, verbose=False)
    history = store.read()
    F, G = objectives_and_constraints(d, history)
    feasible = np.all(G <= 0, axis=1)
    idx = np.flatnonzero(feasible)
    front = history.iloc[idx[non_dominated(F[idx])]] if idx.size else history.iloc[[]]
    front = front.drop_duplicates(subset=names).sort_values(d.objectives[0].output).reset_index(drop=True)
    selections = select(front, d)
    return StudyResult(
        d,
        cases=history[["generation", *names]],
        results=history,
        stats={
            "chunks": o.generations,
            "computed": counts["computed"],
            "reused": counts["reused"],
            "evaluations": len(history),
            "seconds": time.perf_counter() - t0,
            "executor": getattr(executor, "name", type(executor).__name__),
        },
        pareto=front,
        selections=selections,
    )


def select(front, d):
    """Knee point and nearest-to-target rows of a front (a ``selection`` column names each)."""
    import pandas as pd

    if not len(front):
        return front.assign(selection=[])
    F = np.column_stack(
        [front[o.output].to_numpy(float) * (1.0 if o.sense == "min" else -1.0) for o in d.objectives]
    )
    rows = [front.iloc[[knee_point(F)]].assign(selection="knee")]
    for name, target in d.targets.items():
        rows.append(front.iloc[[nearest(front, target)]].assign(selection=name))
    return pd.concat(rows, ignore_index=True)
