"""Benchmarks of the quasi-static engine on the seed-000 composite turntable bearing.

SI units (N, N·m, m, rad, s). Everything is measured in ONE run, so every ratio printed compares
numbers taken on the same machine under the same load:

1. one solve, equilibrium only (``solve(model, load)``) and with the per-element post-processing
   (``result.rows``): median over repeats after warm-up;
2. a batch of load cases in one vectorised call, and the same cases in chunks → cases/s;
3. a research-script baseline (:mod:`benchmarks.baseline_fsolve`: per-element Python loops +
   ``scipy.optimize.fsolve``) on a handful of the same cases → speed-up of bearingkit's single and
   batched solves, and the largest element-load difference between the two codes.

The bearing is :func:`bearingkit.bearings.turntable.composite_turntable` with its defaults
(Tian et al. 2025, Table 1: 221 elements, 20 slices per roller).
"""

from __future__ import annotations

import os
import platform
import resource
import sys
import time
from dataclasses import dataclass

import numpy as np

from bearingkit.analysis.quasistatic import load_vector, solve
from bearingkit.bearings.turntable import composite_turntable

#: Seed 000's planar model (u_x, u_z, θ_y free; u_y, θ_x held at 0), design.md §3.
PLANAR = (True, False, True, False, True)
#: Targets (from the benchmark brief).
TARGET_SINGLE_MS = 5.0
TARGET_BATCH_RATE = 2000.0
TARGET_SPEEDUP_BATCHED = 50.0
#: Random load ranges of the batch [N, N, N·m] and the generator seed.
LOAD_RANGES = {"F_z": (1000.0, 8000.0), "F_x": (0.0, 3000.0), "M_y": (-1800.0, 0.0)}
SEED = 20250588


@dataclass
class Record:
    """One line of the benchmark table.

    ``ratio`` is oriented so that ≥ 1 means the target is met (target/value for times,
    value/target for rates and speed-ups); None when the line has no target.
    """

    name: str
    value: float
    unit: str
    target: str = ""
    ratio: float | None = None
    note: str = ""


def random_loads(n: int, seed: int = SEED) -> np.ndarray:
    """``n`` load vectors (n, 5): F_z 1–8 kN, F_x 0–3 kN, M_y −1800…0 N·m, uniform, seeded."""
    rng = np.random.default_rng(seed)
    draw = {k: rng.uniform(lo, hi, n) for k, (lo, hi) in LOAD_RANGES.items()}
    return load_vector(F_x=draw["F_x"], F_z=draw["F_z"], M_y=draw["M_y"])


def median_time(fn, repeats: int, warmup: int = 3) -> float:
    """Median wall time [s] of ``fn()`` over ``repeats`` calls after ``warmup`` calls."""
    for _ in range(warmup):
        fn()
    times = np.empty(repeats)
    for i in range(repeats):
        t0 = time.perf_counter()
        fn()
        times[i] = time.perf_counter() - t0
    return float(np.median(times))


def machine_info() -> dict:
    """Python, numpy, scipy versions, CPU count, load average (the machine may be shared)."""
    import scipy

    try:
        usable = len(os.sched_getaffinity(0))
    except AttributeError:  # pragma: no cover - not on Linux
        usable = os.cpu_count()
    info = {
        "python": sys.version.split()[0],
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "nproc": usable,
        "machine": f"{platform.machine()} {platform.processor() or platform.system()}",
    }
    if hasattr(os, "getloadavg"):
        info["loadavg_1min"] = round(os.getloadavg()[0], 2)
    return info


def _peak_rss_mb() -> float:
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # Linux: kB


def _traced_peak_mb(model, loads: np.ndarray) -> float:
    """Peak traced allocation [MB] of one batched solve (numpy reports its buffers to tracemalloc)."""
    import tracemalloc

    tracemalloc.start()
    try:
        solve(model, loads)
        return tracemalloc.get_traced_memory()[1] / 2**20
    finally:
        tracemalloc.stop()


def bench_single(model, load: np.ndarray, repeats: int) -> tuple[list[Record], dict]:
    """Single-case solve times: equilibrium only, with ``result.rows``, and the planar 3-DOF solve."""
    eq = median_time(lambda: solve(model, load), repeats)
    full = median_time(lambda: solve(model, load).rows, repeats)
    planar = median_time(lambda: solve(model, load, free=PLANAR), repeats)
    res = solve(model, load)
    note = f"{int(res.iterations[0])} Newton it., converged={bool(res.converged[0])}"
    records = [
        Record(
            "single solve, equilibrium (5 DOF)",
            eq * 1e3,
            "ms",
            f"<= {TARGET_SINGLE_MS:g}",
            TARGET_SINGLE_MS / (eq * 1e3),
            note,
        ),
        Record("single solve + result.rows", full * 1e3, "ms", note="adds per-element Hertz post-processing"),
        Record("single solve, planar 3 DOF", planar * 1e3, "ms", note="free=(u_x, u_z, θ_y), seed 000"),
    ]
    return records, {"single_s": eq, "single_rows_s": full, "single_planar_s": planar}


def bench_batch(model, loads: np.ndarray, chunks: tuple[int, ...]) -> tuple[list[Record], dict]:
    """Throughput of one vectorised call on all cases, and of the same cases in chunks."""
    n = loads.shape[0]
    solve(model, loads[:8])  # warm-up
    rss0 = _peak_rss_mb()
    t0, c0 = time.perf_counter(), time.process_time()
    res = solve(model, loads)
    whole, cpu = time.perf_counter() - t0, time.process_time() - c0
    rss = _peak_rss_mb() - rss0
    conv = float(res.converged.mean())
    rates = {n: n / whole}
    note = (
        f"converged {conv:.1%}, max {int(res.iterations.max())} it., peak RSS +{rss:.0f} MB, "
        f"{n / cpu:.0f} cases per CPU-s"
    )
    records = [
        Record(
            f"batch of {n} in one call",
            n / whole,
            "cases/s",
            f">= {TARGET_BATCH_RATE:g}",
            n / whole / TARGET_BATCH_RATE,
            note,
        )
    ]
    for size in chunks:
        if size >= n:
            continue
        t0, c0 = time.perf_counter(), time.process_time()
        ok, fastest = 0, np.inf
        for i in range(0, n, size):
            t1 = time.perf_counter()
            ok += int(solve(model, loads[i : i + size]).converged.sum())
            fastest = min(fastest, (time.perf_counter() - t1) / len(loads[i : i + size]))
        dt, cpu = time.perf_counter() - t0, time.process_time() - c0
        rates[size] = n / dt
        target = f">= {TARGET_BATCH_RATE:g}"
        name = f"batch of {n} in chunks of {size}"
        records.append(
            Record(
                name,
                n / dt,
                "cases/s",
                target,
                n / dt / TARGET_BATCH_RATE,
                f"converged {ok / n:.1%}, {n / cpu:.0f} cases per CPU-s, "
                f"fastest chunk {1 / fastest:.0f} cases/s",
            )
        )
    best = max(rates, key=rates.get)
    records.append(
        Record(
            "batch memory (tracemalloc peak)",
            _traced_peak_mb(model, loads[:1000]) / 1000 * n,
            "MB",
            note=f"measured on 1000 cases, scaled to {n}",
        )
    )
    return records, {"batch_rates": rates, "best_chunk": best, "best_rate": rates[best]}


def bench_baseline(model, loads: np.ndarray, stats: dict, n_slices: int) -> list[Record]:
    """Research-script baseline vs bearingkit on the same cases (per-case times and agreement)."""
    from benchmarks.baseline_fsolve import BaselineTurntable

    base = BaselineTurntable(n_slices=n_slices)
    t_base, nfev, worst, ok = [], [], 0.0, 0
    for f in loads:
        t0 = time.perf_counter()
        sol = base.solve(f[0], f[2], f[4])
        t_base.append(time.perf_counter() - t0)
        nfev.append(sol["nfev"])
        if not sol["converged"]:
            continue
        ok += 1
        ref = solve(model, f, free=PLANAR)
        loads_b = base.element_loads(*sol["displacement"])
        for name, q in loads_b.items():
            q_ref = ref.row(name).load[0]
            worst = max(worst, float(np.abs(q - q_ref).max() / max(q_ref.max(), 1e-300)))
    per_case = float(np.median(t_base))
    # bearingkit single solves on the same cases (median per case).
    t_bk = float(np.median([median_time(lambda f=f: solve(model, f, free=PLANAR), 5, 1) for f in loads]))
    t_bk5 = float(np.median([median_time(lambda f=f: solve(model, f), 5, 1) for f in loads]))
    t_batch = 1.0 / stats["best_rate"]
    n = len(loads)
    return [
        Record(
            "baseline fsolve + loops, per case",
            per_case * 1e3,
            "ms",
            note=f"{ok}/{n} converged, median {int(np.median(nfev))} residual evaluations",
        ),
        Record(
            "baseline vs bearingkit: element loads",
            worst,
            "max |ΔQ|/Q_max",
            "<= 1e-6",
            1e-6 / max(worst, 1e-300),
            "same model, fsolve-converged cases",
        ),
        Record("bearingkit single planar, same cases", t_bk * 1e3, "ms"),
        Record("speed-up vs bearingkit single (planar)", per_case / t_bk, "x"),
        Record("speed-up vs bearingkit single (5 DOF)", per_case / t_bk5, "x"),
        Record(
            "speed-up vs bearingkit batched",
            per_case / t_batch,
            "x",
            f">= {TARGET_SPEEDUP_BATCHED:g}",
            per_case / t_batch / TARGET_SPEEDUP_BATCHED,
            f"batched = best rate (chunk {stats['best_chunk']})",
        ),
    ]


def run(quick: bool = False) -> tuple[list[Record], dict]:
    """Run every benchmark; ``quick`` shrinks repeats, batch size and baseline cases (≈ 20 s)."""
    info = machine_info()
    model = composite_turntable()
    n_slices = model.rows[0].n_slices
    info["bearing"] = f"{model.name}: {model.n_elements} elements, {n_slices} slices/roller"
    n_batch = 2000 if quick else 10000
    loads = random_loads(n_batch)
    t0 = time.perf_counter()
    records, stats = bench_single(model, loads[0], repeats=20 if quick else 60)
    rec, batch = bench_batch(model, loads, chunks=(250, 1000))
    records += rec
    stats.update(batch)
    records += bench_baseline(model, loads[: 3 if quick else 8], stats, n_slices)
    info["wall_s"] = round(time.perf_counter() - t0, 1)
    return records, info


def format_table(records: list[Record], info: dict) -> str:
    """The benchmark table and machine info as plain text."""
    head = ("benchmark", "value", "unit", "target", "ratio", "note")
    rows = [head]
    for r in records:
        ratio = "" if r.ratio is None else f"{r.ratio:.2f}" + (" ok" if r.ratio >= 1 else " MISS")
        rows.append((r.name, f"{r.value:.4g}", r.unit, r.target, ratio, r.note))
    widths = [max(len(row[i]) for row in rows) for i in range(len(head) - 1)]
    lines = [
        "  ".join([*(c.ljust(w) for c, w in zip(row[:-1], widths, strict=True)), row[-1]]) for row in rows
    ]
    lines.insert(1, "-" * len(lines[0]))
    lines.append("")
    lines.append("machine: " + ", ".join(f"{k}={v}" for k, v in info.items()))
    return "\n".join(lines)
