"""Benchmarks of the study machinery: Dask scaling of a seed-000 sweep, and an NSGA-II run.

SI units (N, m); times in s, throughputs in cases/s. All numbers come from one run:

1. a sweep of the seed-000 composite turntable bearing (Monte Carlo over F_a 1–8 kN, F_r 0–3 kN,
   e 0–0.4 m, axial ball clearance −6…−2 µm; 50,000 cases, 10,000 with ``quick``) on a Dask
   LocalCluster of 1 and of 2 single-threaded worker processes → throughput ratio (target ≥ 1.6);
   cluster start-up and the workers' first import are excluded (one warm-up chunk each);
2. NSGA-II, population 100 × 100 generations on the vectorised ZDT1 objective → wall time (≤ 60 s).

``run(quick)`` returns records with keys name, value, unit, target (and ratio: ≥ 1 meets the target).
"""

from __future__ import annotations

import os
import time

SWEEP_CASES = 50_000
SWEEP_CASES_QUICK = 10_000
CHUNK = 2_500
SEED = 20250588


def _sweep_definition(n: int):
    from bearingkit.studies import definition as sd

    return sd.from_dict(
        {
            "study": {
                "name": "seed000_sweep",
                "design": "monte_carlo",
                "evaluator": "seed000_statics",
                "samples": n,
                "seed": SEED,
                "chunk_size": CHUNK,
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


def _dask_rate(n_workers: int, definition) -> tuple[float, float]:
    from distributed import Client, LocalCluster

    from bearingkit.studies.executors import DaskExecutor
    from bearingkit.studies.runner import build_cases, run_study

    warm = build_cases(definition).iloc[:200]
    with (
        LocalCluster(
            n_workers=n_workers, threads_per_worker=1, processes=True, dashboard_address=None
        ) as cluster,
        Client(cluster) as client,
    ):
        from bearingkit.studies.evaluators import evaluate_chunk

        inputs = warm.drop(columns=[c for c in warm.columns if c.startswith("level_")])
        client.gather(
            [client.submit(evaluate_chunk, "seed000_statics", inputs, pure=False) for _ in range(n_workers)]
        )
        t0 = time.perf_counter()
        res = run_study(definition, executor=DaskExecutor(client=client), progress=False)
        dt = time.perf_counter() - t0
    assert res.results["converged"].all()
    return len(res.results) / dt, dt


def _nsga2_seconds(pop: int = 100, gen: int = 100) -> tuple[float, int]:
    from bearingkit.studies import definition as sd
    from bearingkit.studies.runner import run_study

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


def run(quick: bool = False) -> list[dict]:
    """Measure and return the records (see the module docstring)."""
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    n = SWEEP_CASES_QUICK if quick else SWEEP_CASES
    d = _sweep_definition(n)
    rate1, t1 = _dask_rate(1, d)
    rate2, t2 = _dask_rate(2, d)
    nsga_s, n_eval = _nsga2_seconds()
    return [
        {"name": f"seed-000 sweep {n} cases, Dask 1 worker", "value": rate1, "unit": "cases/s", "target": ""},
        {
            "name": f"seed-000 sweep {n} cases, Dask 2 workers",
            "value": rate2,
            "unit": "cases/s",
            "target": "",
        },
        {
            "name": "Dask 2 workers / 1 worker throughput",
            "value": rate2 / rate1,
            "unit": "x",
            "target": ">= 1.6",
            "ratio": rate2 / rate1 / 1.6,
            "note": f"{t1:.1f} s vs {t2:.1f} s, chunks of {CHUNK}, os.cpu_count()={os.cpu_count()}",
        },
        {
            "name": f"NSGA-II 100 x 100 ZDT1 ({n_eval} evaluations)",
            "value": nsga_s,
            "unit": "s",
            "target": "<= 60",
            "ratio": 60.0 / nsga_s,
        },
    ]


if __name__ == "__main__":
    import sys

    for r in run(quick="--quick" in sys.argv):
        print(r)
