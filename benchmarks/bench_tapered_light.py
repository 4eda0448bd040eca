"""Benchmark: time per case of 1,000 random light/combined loads on the TRB 32008J and its pairs.

Issue 24 item 6: every case must converge or be refused as uncarriable in under 1 s, none over 2 s.
The cases are :mod:`benchmarks.tapered_light_cases` (250 per variant: the example, DB, DF, DB
preloaded), each solved alone (``solve(model, one_load)``, the way a CLI or app call runs), on the
default backend. Alone: ``python -m benchmarks.bench_tapered_light [--quick]``.
"""

from __future__ import annotations

import os
import sys
import time

import numpy as np


def run(quick: bool) -> list[dict]:
    """Per-case time statistics; quick: 40 cases per variant."""
    from bearingkit.analysis.solver.quasistatic import solve
    from benchmarks.tapered_light_cases import cases

    per_variant = 40 if quick else 250
    batches = cases(per_variant, seed=1024)
    for b in batches:  # warm-up: compilation / cache load and first-call costs are not per-case costs
        solve(b.input.model, b.loads[0], free=b.input.free, options=b.input.options)
    times, wrong = [], 0
    for b in batches:
        for c in range(len(b.loads)):
            t0 = time.perf_counter()
            res = solve(b.input.model, b.loads[c], free=b.input.free, options=b.input.options)
            times.append(time.perf_counter() - t0)
            wrong += int(bool(res.converged[0]) != bool(b.carriable[c]))
    times = np.array(times)
    n = len(times)
    load = f"load {os.getloadavg()[0]:.2f}" if hasattr(os, "getloadavg") else ""
    name = "tapered light loads: "

    def entry(what, value, unit, target=None, note=""):
        return {"name": name + what, "value": value, "unit": unit, "target": target, "note": note}

    return [
        entry(f"slowest of {n} cases", times.max(), "s", 1.0, load),
        entry(f"median of {n} cases", 1e3 * np.median(times), "ms"),
        entry("cases over 1 s", int((times > 1.0).sum()), "cases", "<= 0"),
        entry("cases over 2 s", int((times > 2.0).sum()), "cases", "<= 0"),
        entry("wrong outcome (converged vs carriable)", wrong, "cases", "<= 0"),
    ]


if __name__ == "__main__":
    for r in run(quick="--quick" in sys.argv):
        print(r)
