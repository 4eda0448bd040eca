"""How a generic study scales here: ``python -m benchmarks.scale CORES [--cases N] [--dask-cases M]``.

SI units inside; rates in cases/s. The study is issue 34's: a Monte Carlo of the 6209 of
``examples/dgbb_6209.toml`` (F_x 1-15 kN, F_z 0-2 kN, seeded) on the generic evaluator with the
statics outputs (displacements, two stiffness terms, converged), ``chunk_size = "auto"``. Every
number comes from ONE run, in this order, with the 1-minute load average after each phase:

1. in process, one thread (``InProcessExecutor(threads=1)`` with one solver thread) and CORES
   threads (``InProcessExecutor(threads=CORES)``) on ``--cases`` cases (default 10⁵);
   target: CORES threads ≥ 0.8 × CORES × one thread;
2. a Dask LocalCluster of 1 worker and of CORES workers (1 thread and 1 solver thread each) on
   ``--dask-cases`` cases (default 10⁶); target: ≥ 0.8 × CORES × one worker (issue 34 asks ≥ 1.7× for
   2 workers on the 2-core machine). Cluster start-up and the workers' first import are excluded (one
   warm-up task per worker);
3. the fixed cost per chunk as a share of a chunk's time: as the runner measured it to choose the
   chunk size (``stats["chunk_cost"]``), and as observed: 1 − (cases × per-case cost / workers) / wall,
   which also counts the idle tail of the last chunks; target < 5 %.

Each rate's note gives the cores the run actually got: CPU seconds of this process and of the Dask
workers over the wall time. On a shared machine (Linux groups the threads and processes of one
session, ``sched_autogroup``) a run may get far less than CORES cores whatever its thread count: a
ratio is only meaningful where the cores obtained scale with the threads or workers.

``run(cores, cases, dask_cases)`` returns the records for ``python -m benchmarks`` (via
``bench_scale``); the command line prints them.
"""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "dgbb_6209.toml"
STATICS = ["u_x_m", "u_y_m", "u_z_m", "k_xx_N_per_m", "k_zz_N_per_m", "converged"]
CASES = 100_000
DASK_CASES = 1_000_000
SEED = 6209
#: The issue's efficiency target: N workers or threads ≥ 0.8 × N × one.
EFFICIENCY = 0.8
#: The issue's target on the 2-core machine for 2 Dask workers over 1.
TWO_WORKERS = 1.7
#: The issue's target for the fixed cost per chunk.
OVERHEAD = 0.05


def load_average() -> float:
    return os.getloadavg()[0]


def definition(n: int, chunk_size="auto"):
    """The benchmark study of ``n`` cases (see the module docstring)."""
    from bearingkit.studies.definition import load as sd

    return sd.from_dict(
        {
            "study": {
                "name": "scale_6209",
                "design": "monte_carlo",
                "bearing": str(EXAMPLE),
                "load_case": "radial_4kN",
                "samples": n,
                "seed": SEED,
                "chunk_size": chunk_size,
                "outputs": STATICS,
            },
            "factors": [
                {
                    "name": "load_cases.radial_4kN.F_x",
                    "distribution": "uniform",
                    "low": "1 kN",
                    "high": "15 kN",
                },
                {
                    "name": "load_cases.radial_4kN.F_z",
                    "distribution": "uniform",
                    "low": "0 kN",
                    "high": "2 kN",
                },
            ],
        },
        source="scale_6209",
    )


def _cpu(executor) -> float:
    """CPU seconds used so far by this process and, for Dask, by every worker process."""
    used = time.process_time()
    client = getattr(executor, "client", None)
    if client is not None:
        used += sum(client.run(time.process_time).values())
    return used


def _run(d, executor) -> dict:
    from bearingkit.studies.run.runner import run_study

    c0, t0 = _cpu(executor), time.perf_counter()
    res = run_study(d, executor=executor, progress=False)
    wall = time.perf_counter() - t0
    cores = (_cpu(executor) - c0) / wall  # the cores the run actually got (a loaded machine gives fewer)
    assert res.results["converged"].all() and len(res.results) == d.samples
    s = res.stats
    cost = s.get("chunk_cost") or {}
    slots = max(1, int(getattr(executor, "workers", 1)))
    observed = None
    if cost:
        observed = max(0.0, 1.0 - d.samples * cost["per_case_s"] / slots / wall)
    return {
        "rate": d.samples / wall,
        "wall": wall,
        "chunks": s["chunks"],
        "chunk_size": s["chunk_size"],
        "measured_overhead": cost.get("overhead_share"),
        "observed_overhead": observed,
        "per_chunk_ms": 1e3 * cost["per_chunk_s"] if cost else None,
        "cores": cores,
        "load": load_average(),
        "results": res.results,
    }


def in_process(cores: int, n: int) -> tuple[dict, dict]:
    """One thread and ``cores`` threads on the same ``n`` cases (results compared bit for bit)."""
    from bearingkit.analysis.solver.threads import thread_limit
    from bearingkit.studies.run.executors import InProcessExecutor

    _run(definition(3_000), InProcessExecutor(threads=1))  # warm-up: imports, the compiled core
    d = definition(n)
    with thread_limit(1):
        one = _run(d, InProcessExecutor(threads=1))
    many = _run(d, InProcessExecutor(threads=cores))
    cols = list(one["results"].columns)
    assert one["results"][cols].equals(many["results"][cols]), "threads changed a result"
    return one, many


def dask(workers: int, n: int) -> dict:
    """A LocalCluster of ``workers`` single-threaded workers on ``n`` cases (start-up excluded)."""
    from bearingkit.studies.run.executors import DaskExecutor
    from bearingkit.studies.run.workers import evaluate_chunk

    ex = DaskExecutor(workers=workers, solver_threads=1)
    try:
        d = definition(n)
        from bearingkit.studies.run.cases import build_cases

        warm = build_cases(definition(200)).iloc[:200]
        warm = warm[["case", "load_cases.radial_4kN.F_x", "load_cases.radial_4kN.F_z"]]
        from bearingkit.studies.definition.choice import evaluator_of

        ev = evaluator_of(d)
        futures = [
            ex.client.submit(evaluate_chunk, ev, warm, workers=[addr], pure=False)
            for addr in ex.client.scheduler_info()["workers"]
        ]
        ex.client.gather(futures)
        return _run(d, ex)
    finally:
        ex.close()


def _pct(x) -> str:
    return "–" if x is None else f"{100 * x:.1f} %"


def run(cores: int | None = None, cases: int = CASES, dask_cases: int = DASK_CASES) -> list[dict]:
    """Measure and return the records (name, value, unit, target, note)."""
    cores = int(cores or os.cpu_count() or 1)
    out = []
    load0 = load_average()
    one, many = in_process(cores, cases)
    ratio = many["rate"] / one["rate"]
    out += [
        {
            "name": f"scale: generic 6209 statics, {cases} cases, in process 1 thread",
            "value": one["rate"],
            "unit": "cases/s",
            "note": f"{one['chunks']} chunks of {one['chunk_size']}, {one['cores']:.2f} cores obtained, "
            f"load {load0:.2f} → {one['load']:.2f}",
        },
        {
            "name": f"scale: same, in process {cores} threads",
            "value": many["rate"],
            "unit": "cases/s",
            "note": f"{many['chunks']} chunks of {many['chunk_size']}, {many['cores']:.2f} cores obtained, "
            f"load after {many['load']:.2f}",
        },
        {
            "name": f"scale: in process {cores} threads / 1 thread",
            "value": ratio,
            "unit": "x",
            "target": f">= {EFFICIENCY * cores:.3g}",
            "note": f"{ratio / cores:.0%} efficiency; the machine gave "
            f"{many['cores'] / one['cores']:.2f}x the cores (CPU-s / wall); results equal bit for bit",
        },
        {
            "name": f"scale: fixed cost per chunk, in process {cores} threads",
            "value": 100 * (many["measured_overhead"] or 0.0),
            "unit": "%",
            "target": f"<= {100 * OVERHEAD:g}",
            "note": f"{many['per_chunk_ms'] or 0:.1f} ms per chunk measured by the runner; observed "
            f"(with the last chunks' idle tail) {_pct(many['observed_overhead'])}",
        },
    ]
    w1 = dask(1, dask_cases)
    wn = dask(cores, dask_cases)
    ratio = wn["rate"] / w1["rate"]
    target = TWO_WORKERS if cores == 2 else EFFICIENCY * cores
    out += [
        {
            "name": f"scale: Dask LocalCluster 1 worker, {dask_cases} cases",
            "value": w1["rate"],
            "unit": "cases/s",
            "note": f"{w1['chunks']} chunks of {w1['chunk_size']}, {w1['cores']:.2f} cores obtained, "
            f"load after {w1['load']:.2f}",
        },
        {
            "name": f"scale: Dask LocalCluster {cores} workers, {dask_cases} cases",
            "value": wn["rate"],
            "unit": "cases/s",
            "note": f"{wn['chunks']} chunks of {wn['chunk_size']}, {wn['cores']:.2f} cores obtained, "
            f"load after {wn['load']:.2f}",
        },
        {
            "name": f"scale: Dask {cores} workers / 1 worker",
            "value": ratio,
            "unit": "x",
            "target": f">= {target:.3g}",
            "note": f"{ratio / cores:.0%} efficiency; the machine gave {wn['cores'] / w1['cores']:.2f}x the "
            f"cores; vs in process {cores} threads {wn['rate'] / many['rate']:.2f}x",
        },
        {
            "name": f"scale: fixed cost per chunk, Dask {cores} workers",
            "value": 100 * (wn["measured_overhead"] or 0.0),
            "unit": "%",
            "target": f"<= {100 * OVERHEAD:g}",
            "note": f"{wn['per_chunk_ms'] or 0:.1f} ms per chunk (evaluator + a task's round trip); "
            f"observed {_pct(wn['observed_overhead'])}",
        },
    ]
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m benchmarks.scale", description=__doc__.splitlines()[0])
    p.add_argument("cores", type=int, nargs="?", default=os.cpu_count(), help="threads and workers to use")
    p.add_argument("--cases", type=int, default=CASES, help=f"in-process cases (default {CASES})")
    p.add_argument("--dask-cases", type=int, default=DASK_CASES, help=f"Dask cases (default {DASK_CASES})")
    a = p.parse_args(argv)
    print(f"cpus {os.cpu_count()}, cores used {a.cores}, 1-min load average {load_average():.2f}")
    for r in run(a.cores, a.cases, a.dask_cases):
        target = r.get("target", "")
        print(f"{r['name']:<62} {r['value']:>12.4g} {r['unit']:<8} {target:<10} {r.get('note', '')}")
    print(f"1-min load average at the end {load_average():.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
