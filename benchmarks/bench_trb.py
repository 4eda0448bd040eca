"""Benchmark: Monte Carlo of seed 001's 23-roller TRB under F_a = 10 kN (one batched solve)."""

from __future__ import annotations

import os
import time


def run(quick: bool) -> list[dict]:
    """Time a 10,000-realisation (quick: 1,000) Monte Carlo; target ≤ 1 s on 2 cores (issue 19)."""
    from bearingkit.analysis.scatter import monte_carlo
    from bearingkit.bearings.tapered import seed001_row

    n = 1_000 if quick else 10_000
    monte_carlo(seed001_row(), 10_000.0, 1e-6, 8, seed=1)  # warm-up: compiled-core cache load
    t0, c0 = time.perf_counter(), time.process_time()
    res = monte_carlo(seed001_row(), 10_000.0, 1e-6, n, seed=2022)
    dt, cpu = time.perf_counter() - t0, time.process_time() - c0
    note = f"{cpu / n * 1e6:.0f} µs CPU per realisation, load {os.getloadavg()[0]:.2f}"
    return [
        {"name": f"trb_monte_carlo_{n}", "value": dt, "unit": "s", "target": 1.0 * n / 10_000, "note": note},
        {
            "name": f"trb_monte_carlo_{n}_converged_fraction",
            "value": float(res.stats.converged.mean()),
            "unit": "1",
            "target": 1.0,
        },
    ]


if __name__ == "__main__":
    for r in run(quick=False):
        print(r)
