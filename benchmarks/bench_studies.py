"""Benchmarks of the study machinery: Dask scaling of a seed-000 sweep, and an NSGA-II run.

SI units (N, m); times in s, throughputs in cases/s. All numbers come from one run:

1. a sweep of the seed-000 composite turntable bearing (Monte Carlo over F_a 1–8 kN, F_r 0–3 kN,
   e 0–0.4 m, axial ball clearance −6…−2 µm; 50,000 cases, 10,000 with ``quick``, or ``--cases N``)
   evaluated three ways, in this order:

   - in-process (:class:`~bearingkit.studies.run.executors.InProcessExecutor`): the solver's own thread
     pool over every core — the reference a single machine gets without Dask;
   - a Dask LocalCluster of 1 worker process, 1 thread, 1 solver thread;
   - a Dask LocalCluster of 2 worker processes, 1 thread and 1 solver thread each
     (``DaskExecutor(workers=n)``: ``BEARINGKIT_THREADS=1`` and BLAS limited to 1 thread per worker,
     glibc's default memory trimming instead of Dask's, see ``executors.DASK_MALLOC_ENV``).

   The target compares like with like — 2 single-threaded workers against 1 (≥ 1.6×). Cluster
   start-up and the workers' first import are excluded (one warm-up chunk per worker, pinned to it).
   Chunks of :data:`CHUNK` cases: a multiple of the solver's 256-case blocks (so the in-process
   thread pool splits a chunk evenly over 2 cores) and ~50 chunks at 50k cases (so the last chunk
   of one worker leaves the other idle for ≤ 1/25 of the run);
2. NSGA-II, population 100 × 100 generations on the vectorised ZDT1 objective → wall time (≤ 60 s);
3. the PTRB NSGA-II of seed 004 (``examples/studies/seed004_axial_nsga2.toml``: 100 × 100 = 10⁴
   evaluations of the PTRB objectives) → wall time (issue 19: ≤ 2 s), with in the note the time its
   evaluator alone takes on the same 100 populations of 100 designs and the time pymoo alone takes
   on the same run (every generation's F and G replayed: pymoo's own per-individual bookkeeping,
   the floor of any evaluator); the rest is the study runner;
4. the peak RSS of a fresh process running a 100,000-case seed-000 sweep through the study runner
   (in-process executor, results kept in memory; issue 19: < 2 GB).

``run(quick, cases)`` returns records with keys name, value, unit, target (and ratio: ≥ 1 meets the
target). ``python -m benchmarks.bench_studies [--quick] [--cases N] [--repeat K]`` prints them
(``--repeat`` reruns only the sweep, to see the spread on a shared machine).
"""

from __future__ import annotations

import os
import time

SWEEP_CASES = 50_000
SWEEP_CASES_QUICK = 10_000
#: Cases of the study-runner memory measurement (issue 19: 100,000 below 2 GB peak RSS).
MEMORY_CASES = 100_000
#: Cases per chunk: 4 × the numpy solver's CHUNK_CASES (256), see the module docstring.
CHUNK = 1024
SEED = 20250588
WARMUP_CASES = 200


def _sweep_definition(n: int, chunk: int = CHUNK):
    from bearingkit.studies.definition import load as sd

    return sd.from_dict(
        {
            "study": {
                "name": "seed000_sweep",
                "design": "monte_carlo",
                "evaluator": "seed000_statics",
                "samples": n,
                "seed": SEED,
                "chunk_size": chunk,
                "outputs": ["ball_axial_share", "max_roller_pressure_Pa", "converged"],
            },
            "factors": [
                {"name": "axial_load", "distribution": "uniform", "low": "1 kN", "high": "8 kN"},
                {"name": "radial_load", "distribution": "uniform", "low": "0 kN", "high": "3 kN"},
                {"name": "eccentricity", "distribution": "uniform", "low": "0 m", "high": "0.4 m"},
                {"name": "clearance_axial_ball", "distribution": "uniform", "low": "-6 um", "high": "-2 um"},
            ],
        }
    )


def _warm_inputs(definition):
    from bearingkit.studies import evaluators
    from bearingkit.studies.run.cases import build_cases

    warm = build_cases(definition).iloc[:WARMUP_CASES]
    ev = evaluators.get(definition.evaluator)
    return warm[["case", *[c for c in warm.columns if c in ev.factors]]]


def _timed(definition, executor) -> tuple[float, float]:
    from bearingkit.studies.run.runner import run_study

    t0 = time.perf_counter()
    res = run_study(definition, executor=executor, progress=False)
    dt = time.perf_counter() - t0
    assert res.results["converged"].all()
    return len(res.results) / dt, dt


def _note(seconds: float) -> str:
    # The 1-min load average just after a phase: above ~n_workers + 0.5 another process shared the
    # cores during it, and its rate (and any ratio using it) is disturbed.
    return f"{seconds:.1f} s, load after {os.getloadavg()[0]:.2f}"


def _inprocess_rate(definition) -> tuple[float, float]:
    from bearingkit.analysis.solver.quasistatic import solver_threads
    from bearingkit.studies.run.executors import InProcessExecutor, evaluate_chunk

    assert solver_threads() == (os.cpu_count() or 1), "the reference must use every core"
    evaluate_chunk(definition.evaluator, _warm_inputs(definition))
    return _timed(definition, InProcessExecutor())


def _solver_threads() -> int:
    from bearingkit.analysis.solver.quasistatic import solver_threads

    return solver_threads()


def _dask_rate(n_workers: int, definition) -> tuple[float, float]:
    from bearingkit.studies.run.executors import DaskExecutor, evaluate_chunk

    ex = DaskExecutor(workers=n_workers, solver_threads=1)
    try:
        client = ex.client
        threads = client.run(_solver_threads)
        assert set(threads.values()) == {1}, f"workers must run one solver thread each: {threads}"
        inputs = _warm_inputs(definition)
        warm = [
            client.submit(evaluate_chunk, definition.evaluator, inputs, workers=[addr], pure=False)
            for addr in client.scheduler_info()["workers"]
        ]
        client.gather(warm)
        return _timed(definition, ex)
    finally:
        ex.close()


def _nsga2_seconds(pop: int = 100, gen: int = 100) -> tuple[float, int]:
    from bearingkit.studies.definition import load as sd
    from bearingkit.studies.run.runner import run_study

    d = sd.from_dict(
        {
            "study": {"name": "zdt1", "design": "optimize", "evaluator": "zdt1", "chunk_size": pop},
            "optimizer": {"pop_size": pop, "generations": gen, "seed": 1},
            "variables": [{"name": f"x{i}", "low": 0.0, "high": 1.0} for i in range(1, 31)],
            "objectives": [{"output": "f1"}, {"output": "f2"}],
        }
    )
    t0 = time.perf_counter()
    res = run_study(d, progress=False)
    return time.perf_counter() - t0, res.stats["evaluations"]


def _pymoo_alone(res) -> float:
    """Wall time [s] of pymoo alone on an optimisation's problem: the same run, every generation's F
    and G replayed from ``res`` (no evaluator, no store) — the floor under the study runner."""
    import numpy as np
    from pymoo.optimize import minimize

    from bearingkit.studies.run import optimize as so

    d = res.definition
    names = [v.name for v in d.variables]
    gens = [g for _, g in res.results.groupby("generation", sort=True)]
    replay = [(g[names].to_numpy(float), *so.objectives_and_constraints(d, g)) for g in gens]

    class Replay(so._problem_class()):
        def _evaluate(self, X, out, *args, **kwargs):
            x, out["F"], out["G"] = replay[self.gen]
            assert np.array_equal(x, X), "the replay left the recorded run"
            self.gen += 1

    problem = Replay(d, None)
    problem.gen = 0
    t0 = time.perf_counter()
    minimize(problem, so.algorithm_for(d), ("n_gen", d.optimizer.generations), seed=d.optimizer.seed)
    assert problem.gen == len(gens)
    return time.perf_counter() - t0


def _ptrb_nsga2() -> tuple[float, int, float, float]:
    """Wall time [s] of the seed-004 PTRB NSGA-II, its evaluations, its evaluator's share [s] and the
    time pymoo alone takes on the same run [s]."""
    from bearingkit.papers.zheng2022.study_runs import seed004_optimize
    from bearingkit.studies import evaluators
    from bearingkit.studies.run import executors

    seed004_optimize("axial", pop_size=8, generations=2)  # imports, catalogue and unit tables
    t0 = time.perf_counter()
    res = seed004_optimize("axial")
    total = time.perf_counter() - t0
    # The evaluator alone on the populations the run evaluated (same chunks, no optimiser); the case
    # tables are built before the clock starts, so only evaluate_chunk is timed.
    history = res.results
    ev = evaluators.get(res.definition.evaluator)
    factors = [c for c in history.columns if c in ev.factors]
    fixed = {k: v for k, v in res.definition.fixed.items() if k in ev.factors}
    chunks = []
    for _, gen in history.groupby("generation"):
        cases = gen[factors].reset_index(drop=True).assign(**fixed)
        cases.insert(0, "case", range(len(cases)))
        chunks.append(cases)
    t0 = time.perf_counter()
    for cases in chunks:
        executors.evaluate_chunk(res.definition.evaluator, cases)
    evaluator_s = time.perf_counter() - t0
    return total, len(history), evaluator_s, _pymoo_alone(res)


def sweep_memory(n: int) -> float:
    """Peak RSS [MB] of a fresh process running an n-case seed-000 sweep through the study runner."""
    from benchmarks.bench_quasistatic import fresh_process_peak_rss_mb

    return fresh_process_peak_rss_mb(
        "from benchmarks.bench_studies import _sweep_definition\n"
        "from bearingkit.studies.run.runner import run_study\n"
        f"res = run_study(_sweep_definition({n}), progress=False)\n"
        "assert res.results['converged'].all()"
    )


def sweep_records(n: int) -> list[dict]:
    """The three sweep measurements of ``n`` cases and their ratios (one run)."""
    d = _sweep_definition(n)
    load = os.getloadavg()[0]
    rate_in, t_in = _inprocess_rate(d)
    note_in = _note(t_in)
    rate1, t1 = _dask_rate(1, d)
    note1 = _note(t1)
    rate2, t2 = _dask_rate(2, d)
    note2 = _note(t2)
    note = f"chunks of {CHUNK}, os.cpu_count()={os.cpu_count()}, 1-min load at start {load:.2f}"
    return [
        {
            "name": f"seed-000 sweep {n} cases, in-process (all cores)",
            "value": rate_in,
            "unit": "cases/s",
            "target": "",
            "note": note_in,
        },
        {
            "name": f"seed-000 sweep {n} cases, Dask 1 worker x 1 thread",
            "value": rate1,
            "unit": "cases/s",
            "target": "",
            "note": note1,
        },
        {
            "name": f"seed-000 sweep {n} cases, Dask 2 workers x 1 thread",
            "value": rate2,
            "unit": "cases/s",
            "target": "",
            "note": note2,
        },
        {
            "name": "Dask 2 workers / 1 worker throughput",
            "value": rate2 / rate1,
            "unit": "x",
            "target": ">= 1.6",
            "ratio": rate2 / rate1 / 1.6,
            "note": note,
        },
        {
            "name": "Dask 2 workers / in-process throughput",
            "value": rate2 / rate_in,
            "unit": "x",
            "target": "",
            "note": "reference: what Dask gains over the solver's own thread pool on this machine",
        },
    ]


def run(quick: bool = False, cases: int | None = None) -> list[dict]:
    """Measure and return the records (see the module docstring)."""
    n = int(cases) if cases else (SWEEP_CASES_QUICK if quick else SWEEP_CASES)
    records = sweep_records(n)
    nsga_s, n_eval = _nsga2_seconds()
    ptrb_s, ptrb_eval, ptrb_ev_s, ptrb_pymoo_s = _ptrb_nsga2()
    n_mem = SWEEP_CASES_QUICK if quick else MEMORY_CASES
    mem = sweep_memory(n_mem)
    return [
        *records,
        {
            "name": f"NSGA-II 100 x 100 ZDT1 ({n_eval} evaluations)",
            "value": nsga_s,
            "unit": "s",
            "target": "<= 60",
            "ratio": 60.0 / nsga_s,
        },
        {
            "name": f"PTRB NSGA-II seed 004 axial ({ptrb_eval} evaluations)",
            "value": ptrb_s,
            "unit": "s",
            "target": "<= 2",
            "note": (
                f"of which the PTRB evaluator {ptrb_ev_s:.2f} s; pymoo alone on the same run "
                f"{ptrb_pymoo_s:.2f} s; load {os.getloadavg()[0]:.2f}"
            ),
        },
        {
            "name": f"memory: {n_mem}-case seed-000 sweep through the study runner",
            "value": mem,
            "unit": "MB",
            "target": "<= 2000",
            "note": "peak RSS of a fresh process (in-process executor, results in memory)",
        },
    ]


def main(argv=None) -> int:
    import argparse

    p = argparse.ArgumentParser(
        prog="python -m benchmarks.bench_studies", description=__doc__.splitlines()[0]
    )
    p.add_argument("--quick", action="store_true", help=f"{SWEEP_CASES_QUICK} cases instead of {SWEEP_CASES}")
    p.add_argument("--cases", type=int, default=None, help="sweep size (overrides --quick)")
    p.add_argument("--repeat", type=int, default=1, help="repeat the sweep measurement K times")
    a = p.parse_args(argv)
    n = a.cases or (SWEEP_CASES_QUICK if a.quick else SWEEP_CASES)
    for k in range(a.repeat):
        print(f"--- sweep run {k + 1}/{a.repeat}")
        for r in sweep_records(n):
            print(r)
    nsga_s, n_eval = _nsga2_seconds()
    print({"name": f"NSGA-II 100 x 100 ZDT1 ({n_eval} evaluations)", "value": nsga_s, "unit": "s"})
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
