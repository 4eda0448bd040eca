"""What the machine gives two threads: the compiled solve alone, in one thread and split over several.

SI units. The 6209 of ``examples/dgbb_6209.toml`` under 2 × 10⁴ seeded radial and axial loads: first
all of them in one call on one thread, then the same cases split in equal parts, one part per Python
thread, each call with one solver thread (:func:`bearingkit.analysis.solver.threads.thread_limit`), the
threads started together. Nothing but the compiled solve runs (it releases the GIL), so the ratio of
the two wall rates is the most a study's in-process threads can gain on this machine, and the CPU
seconds per case show whether a busy core slows the other (shared physical cores, frequency, memory).
The issue-34 line ``scale: in process N threads / 1 thread`` is to be read against it.

``python -m benchmarks.bench_machine_threads [THREADS]``; ``run(quick)`` returns the records.
"""

from __future__ import annotations

import itertools
import os
import resource
import threading
import time
from pathlib import Path

import numpy as np

CASES = 20_000
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "dgbb_6209.toml"


def _cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def measure(threads: int, cases: int = CASES, repeats: int = 3) -> dict:
    """Best-of-``repeats`` wall and CPU seconds of the cases on one thread and split over ``threads``."""
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.analysis.solver.threads import thread_limit
    from bearingkit.io.loader import load_file

    b = load_file(EXAMPLE)
    rng = np.random.default_rng(6209)
    loads = load_vector(F_x=rng.uniform(1e3, 15e3, cases), F_z=rng.uniform(0.0, 2e3, cases))

    def part(lo, hi):
        with thread_limit(1):
            solve(b.model, loads[lo:hi], free=b.free, options=b.options)

    part(0, 300)  # warm-up: the compiled core loaded, the model packed
    bounds = np.linspace(0, cases, threads + 1).astype(int)

    def timed(fn):
        t, c = time.perf_counter(), _cpu()
        fn()
        return time.perf_counter() - t, _cpu() - c

    def together():
        ts = [threading.Thread(target=part, args=(lo, hi)) for lo, hi in itertools.pairwise(bounds)]
        for t in ts:
            t.start()
        for t in ts:
            t.join()

    one = min((timed(lambda: part(0, cases)) for _ in range(repeats)), key=lambda x: x[0])
    many = min((timed(together) for _ in range(repeats)), key=lambda x: x[0])
    return {"threads": threads, "cases": cases, "one": one, "many": many}


def run(quick: bool = False, threads: int | None = None) -> list[dict]:
    n = threads or os.cpu_count() or 1
    m = measure(n, CASES // 4 if quick else CASES)
    (w1, c1), (wn, cn) = m["one"], m["many"]
    load = os.getloadavg()[0]
    return [
        {
            "name": f"machine: compiled solve alone, {n} threads / 1 thread (wall rate)",
            "value": w1 / wn,
            "unit": "x",
            "note": f"{m['cases']} 6209 cases: 1 thread {w1:.3f} s wall, {n} threads {wn:.3f} s; the most "
            f"in-process threads can gain here; load {load:.2f}",
        },
        {
            "name": f"machine: CPU seconds per case, {n} threads / 1 thread",
            "value": cn / c1,
            "unit": "x",
            "note": f"1 thread {c1 / m['cases'] * 1e6:.1f} µs, {n} threads {cn / m['cases'] * 1e6:.1f} µs "
            "CPU per case (1 = a busy core does not slow the others)",
        },
    ]


def main(argv=None) -> int:
    import argparse

    p = argparse.ArgumentParser(prog="python -m benchmarks.bench_machine_threads")
    p.add_argument("threads", type=int, nargs="?", default=os.cpu_count())
    a = p.parse_args(argv)
    for r in run(threads=a.threads):
        print(f"{r['name']:<66} {r['value']:>7.3f} {r['unit']:<3} {r['note']}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
