"""``make bench`` lines of :mod:`benchmarks.scale` on every core of this machine (issue 34).

In-process threads vs one thread on 10⁵ cases (quick: 2·10⁴), a Dask LocalCluster of every core vs
one worker on 10⁶ cases (quick: 10⁵), and the fixed cost per chunk. ``python -m benchmarks.scale
CORES`` measures the same for another core count.
"""

from __future__ import annotations

import os


def run(quick: bool = False) -> list[dict]:
    from benchmarks import scale

    cases, dask_cases = (20_000, 100_000) if quick else (scale.CASES, scale.DASK_CASES)
    return scale.run(os.cpu_count() or 1, cases, dask_cases)
