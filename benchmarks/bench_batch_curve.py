"""The batch-size curve (issue 34): cost per case of one ``solve`` call of 1, 10, 100 and 10⁴ cases.

SI units; times in µs per case. Before issue 34, numba's OpenMP layer spun ~8 ms in every parallel
call, so batches of 2-100 cases were 20-60x slower per case than batches of 10⁴ (6209 at 10 cases:
798 µs per case). Each point here is the median wall time of one call over repeats (enough calls
for ~2,000 cases per point), turned into **thread-seconds per case**: wall × the solver threads the
call used ÷ cases. A call of one case uses one thread (and the serial driver below 2 cases per
thread, :func:`bearingkit.analysis.solver.threads.parallel_split`), a call of 10⁴ every thread; in
thread-seconds a small batch is as cheap as a large one when nothing is lost to starting threads.
Target: no point above 2× the 10⁴ point. Bearings: the 6209 of ``examples/dgbb_6209.toml`` (the
cheapest case, where a fixed cost shows most) and the seed-000 turntable of
:mod:`benchmarks.bench_quasistatic`. The note gives the plain wall time per case too.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import numpy as np

SIZES = (1, 10, 100, 10_000)
#: The target: no point above this multiple of the 10⁴ point's cost per case.
CLIFF = 2.0
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "dgbb_6209.toml"


def _bearings():
    from bearingkit.analysis.solver.quasistatic import load_vector
    from bearingkit.bearings.turntable import composite_turntable
    from bearingkit.io.loader import load_file
    from benchmarks.bench_quasistatic import random_loads

    b = load_file(EXAMPLE)
    rng = np.random.default_rng(6209)
    loads = load_vector(F_x=rng.uniform(1e3, 15e3, max(SIZES)), F_z=rng.uniform(0.0, 2e3, max(SIZES)))
    yield "6209", b.model, loads, {"free": b.free, "options": b.options}
    yield "seed-000", composite_turntable(), random_loads(max(SIZES)), {}


def curve(model, loads, kw, sizes=SIZES) -> dict[int, tuple[float, float, int]]:
    """{n: (thread-seconds per case, wall per case, threads used)} of one call of n cases."""
    from bearingkit.analysis.solver import backend
    from bearingkit.analysis.solver.quasistatic import solve
    from bearingkit.analysis.solver.threads import parallel_split, solver_threads

    # The compiled core, also when this module runs alone ("auto" would solve the first small
    # batches of a fresh process on the numpy core, :func:`backend.wants_compiled`).
    backend.for_batches()
    solve(model, loads[:64], **kw)  # warm-up: the compiled core, the model's plan
    out = {}
    for n in sizes:
        calls = max(3, 2_000 // n) if n < max(sizes) else 3
        times = []
        for _ in range(calls):
            t0 = time.perf_counter()
            solve(model, loads[:n], **kw)
            times.append(time.perf_counter() - t0)
        wall = float(np.median(times)) / n
        threads = parallel_split(n, solver_threads())[0] if n > 1 else 1
        out[n] = (wall * threads, wall, threads)
    return out


def run(quick: bool = False) -> list[dict]:
    records = []
    for name, model, loads, kw in _bearings():
        load = os.getloadavg()[0]
        points = curve(model, loads, kw)
        big = points[max(SIZES)][0]
        for n, (cost, wall, threads) in points.items():
            records.append(
                {
                    "name": f"batch-size curve {name}: {n} cases per call",
                    "value": cost * 1e6,
                    "unit": "µs/case",
                    "target": "" if n == max(SIZES) else f"<= {CLIFF * big * 1e6:.4g}",
                    "note": f"{cost / big:.2f}x the 10⁴ point; wall {wall * 1e6:.1f} µs/case on {threads} "
                    f"thread(s); load {load:.2f}",
                }
            )
    return records


if __name__ == "__main__":
    for r in run():
        print(f"{r['name']:<48} {r['value']:>9.1f} {r['unit']:<8} {r['target']:<12} {r['note']}")
