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

from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings.turntable import composite_turntable

#: Seed 000's planar model (u_x, u_z, θ_y free; u_y, θ_x held at 0), design.md §3.
PLANAR = (True, False, True, False, True)
#: Targets (issue 19: compiled core).
TARGET_SINGLE_MS = 0.1
TARGET_BATCH_RATE = 20_000.0
TARGET_SPEEDUP_BATCHED = 1000.0
#: Peak RSS of a 100,000-case solve with its per-row statistics [MB].
TARGET_MEMORY_MB = 2000.0
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


def first_solve_time() -> tuple[float, float]:
    """Wall time of the first solve in a fresh process, with the disk cache and with it emptied [s]."""
    import subprocess
    import tempfile

    code = (
        "import time; from bearingkit.analysis.solver.quasistatic import solve, load_vector;"
        "from bearingkit.bearings.turntable import composite_turntable as c; m = c();"
        "t = time.perf_counter(); solve(m, load_vector(F_z=3000.0)); print(time.perf_counter() - t)"
    )
    # The compiled core asked for by name: a one-case job on "auto" runs on the numpy core (issue 42),
    # and these two lines time loading the compiled core from the disk cache and compiling it.
    compiled = dict(os.environ, BEARINGKIT_BACKEND="compiled")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=compiled)
    cached = float(out.stdout)
    with tempfile.TemporaryDirectory() as tmp:
        # No background build: a solve on "auto" with the core not built starts one, which outlived
        # this line and took a core from every benchmark after it (two minutes of compiling).
        env = dict(compiled, NUMBA_CACHE_DIR=tmp, BEARINGKIT_BACKGROUND_COMPILE="0")
        out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    return cached, float(out.stdout)


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
    t_batch = 1.0 / stats["best_rate"]  # wall time per case of the best batch
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
            f"batched = best rate (batch of {stats['best_chunk']})",
        ),
    ]


def _kernel_rates() -> tuple[float, float, float]:
    """CPU cost on this machine of one ninth root, one scalar flop and one vectorised flop [s].

    Issue 34: each price comes from a COMPUTE-bound loop (operands in registers or in an L1-resident
    array, results summed or written once), timed in CPU seconds (``time.process_time``, as the CPU
    per case it is compared with). The previous flop price came from a loop that read, updated and
    stored a 5×5 accumulator at every step (bound by stores and their latency: 0.56 ns per flop), so
    the "limit" it gave was above the measured CPU time (a ratio of 0.47).

    - root: :func:`bearingkit.rows.cylindrical.compiled.ninth_root` over blocks of 20 values of an
      L1-resident array (as the slice law calls it);
    - scalar flop: eight independent multiply-add chains held in registers (2 flops per step);
    - vectorised flop: a degree-16 Horner polynomial of each element of an L1-resident array
      (32 flops per element, elements independent: the compiler vectorises the loop).
    """
    from numba import njit

    from bearingkit.rows.cylindrical.compiled import ninth_root

    @njit(cache=False)
    def roots(d, y, reps):
        s = 0.0
        for _ in range(reps):
            for j in range(0, d.shape[0], 20):
                ninth_root(d[j:], y, 20)
                s += y[0]
        return s

    @njit(cache=False)
    def chains(x, reps):  # 8 chains × 2 flops per step, no memory traffic
        a0, a1, a2, a3, a4, a5, a6, a7 = x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]
        for _ in range(reps):
            a0 = a0 * 0.9999999 + 1e-9
            a1 = a1 * 0.9999998 + 2e-9
            a2 = a2 * 0.9999997 + 3e-9
            a3 = a3 * 0.9999996 + 4e-9
            a4 = a4 * 0.9999995 + 5e-9
            a5 = a5 * 0.9999994 + 6e-9
            a6 = a6 * 0.9999993 + 7e-9
            a7 = a7 * 0.9999992 + 8e-9
        return a0 + a1 + a2 + a3 + a4 + a5 + a6 + a7

    @njit(cache=False)
    def horner(x, y, reps):  # 16 multiply-adds per element, one load and one store
        for _ in range(reps):
            for i in range(x.shape[0]):
                v = x[i]
                p = 1.0
                for _c in range(16):
                    p = p * v + 0.5
                y[i] = p
        return y[0]

    rng = np.random.default_rng(1)
    d = rng.uniform(1e-9, 1e-5, 2000)  # 16 kB: in L1
    y = np.empty(20)
    x = rng.uniform(0.1, 0.9, 1024)
    out = np.empty(1024)
    roots(d, y, 1), chains(x, 1), horner(x, out, 1)  # compile

    def cpu(fn, *args) -> float:
        best = np.inf
        for _ in range(3):
            t0 = time.process_time()
            fn(*args)
            best = min(best, time.process_time() - t0)
        return best

    t_root = cpu(roots, d, y, 300) / (300 * d.size)
    t_scalar = cpu(chains, x, 10_000_000) / (10_000_000 * 16)
    t_vector = cpu(horner, x, out, 1000) / (1000 * x.size * 32)
    return t_root, t_scalar, t_vector


def arithmetic_limit(
    model, res, evaluations: float, coarse_evaluations: float = 0.0
) -> tuple[float, float, str]:
    """CPU time per case [s] the kernels' operation count allows: evaluations × (roots + flops).

    Operation count of one evaluation at the solution (compiled kernels): per loaded slice one
    ninth root and 12 flops; per roller 20 flops for its approach and slope, per touching roller
    230 for its force and 5×5 stiffness; per ball 30 flops, per loaded ball 170 and two square roots
    (counted as roots). A coarse evaluation (:mod:`bearingkit.analysis.solver.coarse`) counts the same with
    the loaded slices of a coarsened row scaled by COARSE_SLICES / n_slices, and its rollers, loaded
    slices and touching rollers by ⌈Z/2⌉ / Z where the row is thinned (COARSE_THIN_FROM). Prices:
    :func:`_kernel_rates` (compute-bound loops), measured in the same run.

    Returns the limit with vectorised flops, the limit with scalar flops [s per case] and a note.
    """
    from bearingkit.analysis.solver.coarse import COARSE_FROM_SLICES, COARSE_SLICES, COARSE_THIN_FROM

    t_root, t_scalar, t_vector = _kernel_rates()
    full, rough = np.zeros(2), np.zeros(2)  # (roots, flops) per full and per coarse evaluation
    for st, row in zip(res.rows, model.rows, strict=True):
        if row.kind == "cylindrical":
            loaded = (st.slice_load > 0).sum(axis=(1, 2)).mean()
            touching = (st.load > 0).sum(axis=1).mean()
            fixed = 20 * row.n_elements + 230 * touching
            full += (loaded, 12 * loaded + fixed)
            coarse = row.n_slices >= COARSE_FROM_SLICES
            share = COARSE_SLICES / row.n_slices if coarse else 1.0
            thinned = coarse and row.n_elements >= COARSE_THIN_FROM
            thin = -(-row.n_elements // 2) / row.n_elements if thinned else 1.0
            rough += (loaded * share * thin, (12 * loaded * share + fixed) * thin)
        elif row.kind == "ball":
            loaded = (st.load > 0).sum(axis=1).mean()
            ball = np.array([2 * loaded, 30 * row.n_elements + 170 * loaded])
            full += ball
            rough += ball
    roots = evaluations * full[0] + coarse_evaluations * rough[0]
    flops = evaluations * full[1] + coarse_evaluations * rough[1]
    vector = roots * t_root + flops * t_vector
    scalar = roots * t_root + flops * t_scalar
    note = (
        f"{roots:.0f} roots + {flops / 1e3:.0f} kflop per case ({evaluations:.1f} evaluations + "
        f"{coarse_evaluations:.1f} coarse); root {t_root * 1e9:.1f} ns, flop {t_vector * 1e9:.3f} ns "
        f"vectorised / {t_scalar * 1e9:.3f} ns scalar (CPU, compute-bound loops); with scalar flops "
        f"{scalar * 1e6:.1f} µs"
    )
    return vector, scalar, note


def bench_rates(model, loads: np.ndarray, sizes: tuple[int, ...]) -> tuple[list[Record], dict]:
    """Cases/s of one call on n cases for each n in ``sizes`` (compiled core, all cores)."""
    records, stats = [], {}
    solve(model, loads[:8])  # warm-up
    for n in sizes:
        rss0 = _peak_rss_mb()
        t0, c0 = time.perf_counter(), time.process_time()
        res = solve(model, loads[:n])
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
        rate = n / wall
        evals = float(np.mean(res.evaluations)) if res.evaluations is not None else float("nan")
        coarse = float(np.mean(res.coarse_evaluations)) if res.coarse_evaluations is not None else 0.0
        stats[n] = {"rate": rate, "cpu_per_case": cpu / n, "evaluations": evals, "coarse": coarse}
        stats[n]["result"] = res
        records.append(
            Record(
                f"batch of {n} in one call",
                rate,
                "cases/s",
                f">= {TARGET_BATCH_RATE:g}",
                rate / TARGET_BATCH_RATE,
                f"converged {res.converged.mean():.1%}, max {int(res.iterations.max())} it., "
                f"{evals:.2f} + {coarse:.2f} coarse evaluations/case, {cpu / n * 1e6:.0f} µs CPU/case, "
                "peak RSS "
                f"+{_peak_rss_mb() - rss0:.0f} MB, load {os.getloadavg()[0]:.1f}",
            )
        )
    return records, stats


def bench_numpy_reference(model, loads: np.ndarray) -> Record:
    """The numpy reference backend on the same cases (the compiled core's speed-up over it)."""
    from bearingkit.analysis.solver.quasistatic import SolverOptions

    opts = SolverOptions(backend="numpy")
    solve(model, loads[:8], options=opts)
    t0 = time.perf_counter()
    solve(model, loads, options=opts)
    rate = len(loads) / (time.perf_counter() - t0)
    return Record(f"numpy reference: batch of {len(loads)}", rate, "cases/s", note="BEARINGKIT_BACKEND=numpy")


def fresh_process_peak_rss_mb(code: str) -> float:
    """Peak RSS [MB] of a fresh interpreter that runs ``code`` from the repository root (NaN, with the
    child's last error line printed, if it fails)."""
    import subprocess

    code = f"import resource, sys; sys.path.insert(0, '.')\n{code}\n" + (
        "print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)"  # Linux: kB
    )
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=root)
    if out.returncode:
        print(f"memory probe failed: {(out.stderr.strip().splitlines() or ['?'])[-1]}", file=sys.stderr)
        return float("nan")
    return float(out.stdout.strip().splitlines()[-1])


def memory_100k(n: int) -> Record:
    """Peak RSS [MB] of a fresh process solving n cases and reading every row's max load/pressure/count."""
    value = fresh_process_peak_rss_mb(
        "from benchmarks.bench_quasistatic import random_loads\n"
        "from bearingkit.analysis.solver.quasistatic import solve\n"
        "from bearingkit.bearings.turntable import composite_turntable\n"
        f"res = solve(composite_turntable(), random_loads({n}))\n"
        "[(r.max_load, r.loaded_count, r.max_pressure.max(axis=-1)) for r in res.rows]"
    )
    return Record(
        f"memory: {n} cases solved + result.rows statistics",
        value,
        "MB",
        f"<= {TARGET_MEMORY_MB:g}",
        TARGET_MEMORY_MB / value if value == value else None,
        "peak RSS of a fresh process (interpreter and libraries included)",
    )


def run(quick: bool = False) -> tuple[list[Record], dict]:
    """Run every benchmark; ``quick`` shrinks repeats, batch sizes and baseline cases."""
    info = machine_info()
    model = composite_turntable()
    n_slices = model.rows[0].n_slices
    info["bearing"] = f"{model.name}: {model.n_elements} elements, {n_slices} slices/roller"
    sizes = (2_000, 10_000) if quick else (10_000, 100_000)
    loads = random_loads(max(sizes))
    t0 = time.perf_counter()
    records = []
    if not quick:
        cached, cold = first_solve_time()
        records.append(Record("first solve in a new process (disk cache)", cached, "s", note="cache load"))
        records.append(Record("first solve, empty cache (compilation)", cold, "s", note="once per machine"))
    rec, stats = bench_single(model, loads[0], repeats=20 if quick else 200)
    records += rec
    rec, rates = bench_rates(model, loads, sizes)
    records += rec
    stats["best_rate"] = max(r["rate"] for r in rates.values())
    stats["best_chunk"] = max(rates, key=lambda k: rates[k]["rate"])
    small = rates[sizes[0]]
    sample = solve(model, loads[:200])
    limit, limit_scalar, note = arithmetic_limit(model, sample, small["evaluations"], small["coarse"])
    records.append(Record("evaluations per case", small["evaluations"], "", note=f"batch of {sizes[0]}"))
    records.append(
        Record("coarse-model evaluations per case", small["coarse"], "", note="the first Newton iterations")
    )
    records.append(Record("arithmetic-limit estimate, CPU per case", limit * 1e6, "µs", note=note))
    records.append(
        Record(
            "CPU per case / arithmetic limit",
            small["cpu_per_case"] / limit,
            "x",
            note=f"1 = at the limit (vectorised flops); {small['cpu_per_case'] / limit_scalar:.2f}x of the "
            f"scalar-flop limit; ≥ 1 by construction of a limit",
        )
    )
    records.append(bench_numpy_reference(model, loads[: 500 if quick else 2000]))
    if not quick:
        records.append(memory_100k(100_000))
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
