"""Benchmark of the generic study evaluator: 10,000 load cases of a 6209 against the raw batched solve.

SI units (N, m); throughputs in cases/s. All numbers come from ONE run, in this order:

1. raw ``solve(model, loads, free=…)`` of the 6209 of ``examples/dgbb_6209.toml`` for N random radial
   and axial loads (F_x 1–15 kN, F_z 0–2 kN, seeded), nothing else — the reference rate;
2. the same N loads as a ``monte_carlo`` study on the generic evaluator (``bearing = dgbb_6209.toml``,
   factors ``load_cases.radial_4kN.F_x`` / ``.F_z``), in process (chunks side by side in one thread
   per core), ``chunk_size = "auto"`` (:data:`CHUNK`), three output sets:

   - ``statics``: displacements, stiffness terms, converged (the solve and what it returns) — the
     target: ≥ 50 % of the raw rate;
   - ``+ rows``: adds the largest ball load and contact pressure and the loaded count (the per-contact
     Hertz post-processing of :attr:`QuasiStaticResult.rows`, which the raw solve skips);
   - ``default``: every output a study gets without ``outputs`` (statics, rows, ratings; no lubricant
     in this file, so no κ).

The machine is shared: the 1-minute load average before and after each phase is printed in the notes
(compare ratios from one run, not absolute rates across runs).

``python -m benchmarks.bench_generic [--cases N]`` prints the records; ``run(quick)`` returns them for
``python -m benchmarks``.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

#: Load cases of the benchmark (the issue's 10,000).
CASES = 10_000
#: Cases per chunk of the study: "auto" (issue 34), the default a study gets — equal chunks, a
#: multiple of the threads that evaluate them side by side, sized from the study's measured costs.
CHUNK = "auto"
SEED = 6209
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "dgbb_6209.toml"
STATICS = ["u_x_m", "u_y_m", "u_z_m", "k_xx_N_per_m", "k_zz_N_per_m", "converged"]
ROWS = [*STATICS, "balls_max_load_N", "balls_max_pressure_Pa", "balls_loaded_count"]


def _load() -> float:
    return os.getloadavg()[0]


def _study(n: int, outputs):
    from bearingkit.studies.definition import load as sd

    head = {
        "name": "bench_6209",
        "design": "monte_carlo",
        "bearing": str(EXAMPLE),
        "load_case": "radial_4kN",
        "samples": n,
        "seed": SEED,
        "chunk_size": CHUNK,
    }
    if outputs is not None:
        head["outputs"] = outputs
    return sd.from_dict(
        {
            "study": head,
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
        source="bench_6209",
    )


def _raw_rate(definition) -> tuple[float, float]:
    """Cases/s of the bare batched solve of the study's own loads (same cases, same model)."""
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.io.loader import load_file
    from bearingkit.studies.run.cases import build_cases

    cases = build_cases(definition)
    bearing = load_file(EXAMPLE)
    loads = load_vector(
        F_x=cases["load_cases.radial_4kN.F_x"].to_numpy(float),
        F_z=cases["load_cases.radial_4kN.F_z"].to_numpy(float),
    )
    solve(bearing.model, loads[:200], free=bearing.free, options=bearing.options)  # warm-up
    t0 = time.perf_counter()
    res = solve(bearing.model, loads, free=bearing.free, options=bearing.options)
    dt = time.perf_counter() - t0
    assert res.converged.all()
    return len(loads) / dt, dt


def _study_rate(definition) -> tuple[float, float]:
    from bearingkit.studies.run.runner import run_study

    t0 = time.perf_counter()
    res = run_study(definition, progress=False)
    dt = time.perf_counter() - t0
    assert res.results["converged"].all() and len(res.results) == definition.samples
    return len(res.results) / dt, dt


def run(quick: bool = False, cases: int | None = None) -> list[dict]:
    n = cases or (CASES // 5 if quick else CASES)
    # warm-up: imports, the evaluator's input, numpy paths
    _study_rate(_study(256, STATICS))
    out = []
    load0 = _load()
    raw, t_raw = _raw_rate(_study(n, STATICS))
    load1 = _load()
    out.append(
        {
            "name": f"raw solve of {n} 6209 load cases",
            "value": raw,
            "unit": "cases/s",
            "note": f"{t_raw:.2f} s; load {load0:.1f} → {load1:.1f}",
        }
    )
    for label, outputs, target in (
        ("statics", STATICS, raw * 0.5),
        ("+ rows", ROWS, None),
        ("default", None, None),
    ):
        load0 = _load()
        rate, dt = _study_rate(_study(n, outputs))
        load1 = _load()
        out.append(
            {
                "name": f"generic evaluator, {label} outputs ({n} cases)",
                "value": rate,
                "unit": "cases/s",
                "target": "" if target is None else f">= {target:.6g}",
                "note": f"{rate / raw:.0%} of the raw solve rate; {dt:.2f} s; load {load0:.1f} → {load1:.1f}",
            }
        )
    return out


def main(argv=None) -> int:
    import argparse

    p = argparse.ArgumentParser(prog="python -m benchmarks.bench_generic")
    p.add_argument("--cases", type=int, default=CASES)
    a = p.parse_args(argv)
    for r in run(cases=a.cases):
        print(f"{r['name']:<58} {r['value']:>10.1f} {r['unit']:<8} {r.get('target', ''):<14} {r['note']}")
    print(f"cpus {os.cpu_count()}, 1-min load average now {_load():.1f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
