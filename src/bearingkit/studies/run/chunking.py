"""How many cases a chunk of a study holds when the study says ``chunk_size = "auto"`` (the default).

Units: seconds and case counts.

A chunk is the unit of parallel work and of resume. Each one pays a fixed cost besides its cases:
the evaluator's set-up (an Analysis built, its arrays allocated, a DataFrame made), the executor's
round trip (a Dask task is scheduled, sent and gathered; a pool task pickled) and the store's write.
Issue 34 measured that cost at about a chunk's own work on a 16-core machine (chunks of 1,024 cases
of a 6209, +16 ms per chunk with 1 Dask worker, +90 ms with 16), which is why a cluster scaled 3.9×
instead of ~16×. :func:`choose` therefore sizes chunks from costs measured on the study itself
(:func:`measure`): the study is cut into a multiple of the workers' count of equal chunks (no worker
waits for another's extra chunk), up to :data:`TASKS_PER_WORKER` per worker while each chunk stays
large enough that its fixed cost is at most :data:`OVERHEAD_SHARE` of its time, and more when a
chunk would take longer than :data:`MAX_CHUNK_SECONDS` (what a killed worker loses). A number in
the study file overrides all of this.

The size chosen is recorded in the store's manifest, and a resumed run keeps it (the chunks on
disk must be the same chunks). With the compiled solver core, the chunking changes no bit of a
result (every case is solved alone); with the numpy reference it may change the last bits
(``docs/studies.md``, executors and threads).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

#: The largest share of a chunk's wall time its fixed cost may take (the issue's target: < 5 %).
OVERHEAD_SHARE = 0.025
#: Chunks each worker should get at least: the last chunks of a run leave workers idle, for at most
#: about 1/TASKS_PER_WORKER of the run.
TASKS_PER_WORKER = 4
#: The longest a chunk should take [s]: the work a killed worker or an interrupted run loses.
MAX_CHUNK_SECONDS = 60.0
#: Studies with fewer cases than this are not measured: one chunk per worker.
MEASURE_FROM_CASES = 2_000
#: Cases of the larger probe (the smaller one is a single case).
PROBE_CASES = 64
#: A case that alone takes longer than this [s] makes the fixed cost negligible: no larger probe.
SLOW_CASE_S = 0.02


@dataclass(frozen=True)
class ChunkCost:
    """Measured costs of a study's evaluation [s]: per case, fixed per chunk (evaluator + executor)."""

    per_case_s: float
    per_chunk_s: float

    def overhead(self, size: int) -> float:
        """The fixed cost's share of a chunk of ``size`` cases (0 … 1)."""
        work = self.per_case_s * max(int(size), 1)
        return self.per_chunk_s / (self.per_chunk_s + work) if self.per_chunk_s + work > 0 else 0.0


def _timed(fn, arg) -> float:
    t0 = time.perf_counter()
    fn(arg)
    return time.perf_counter() - t0


def measure(evaluate, cases, executor_overhead_s: float = 0.0) -> ChunkCost:
    """Time ``evaluate`` on one case and on :data:`PROBE_CASES` cases of ``cases`` (best of two each).

    ``evaluate(frame)`` is what a worker runs on a chunk; ``executor_overhead_s`` the executor's own
    round trip per chunk (``executor.task_overhead()``). The first call warms up (imports, the
    bearing's model, the compiled core's cache) and is not counted. The fit is t(n) = a + b·n.
    """
    one = cases.iloc[:1].reset_index(drop=True)
    _timed(evaluate, one)  # warm-up
    t1 = min(_timed(evaluate, one) for _ in range(2))
    m = min(PROBE_CASES, len(cases))
    if t1 >= SLOW_CASE_S or m < 8:
        return ChunkCost(per_case_s=t1, per_chunk_s=executor_overhead_s)
    probe = cases.iloc[:m].reset_index(drop=True)
    tm = min(_timed(evaluate, probe) for _ in range(2))
    per_case = max((tm - t1) / (m - 1), 1e-9)
    return ChunkCost(per_case_s=per_case, per_chunk_s=max(t1 - per_case, 0.0) + executor_overhead_s)


def choose(n_cases: int, workers: int, cost: ChunkCost | None, cap: int) -> int:
    """Cases per chunk for ``n_cases`` on ``workers`` parallel workers (see the module docstring).

    The study is cut into a multiple of ``workers`` chunks of equal size (so no worker is left with
    one chunk more than the others): k chunks per worker, k as large as :data:`TASKS_PER_WORKER`
    while a chunk keeps the fixed cost under :data:`OVERHEAD_SHARE`, at least 1, and larger when a
    chunk would exceed :data:`MAX_CHUNK_SECONDS`. ``cost`` None (a small study, not measured): one
    chunk per worker. ``cap``: the largest size a study file may give
    (:data:`bearingkit.studies.definition.schema.MAX_CHUNK_SIZE`).
    """
    n_cases, workers = max(int(n_cases), 1), max(int(workers), 1)
    k = 1
    if cost is not None:
        floor = cost.per_chunk_s * (1.0 - OVERHEAD_SHARE) / (OVERHEAD_SHARE * cost.per_case_s)
        k = int(min(TASKS_PER_WORKER, max(1, n_cases // (workers * max(floor, 1.0)))))
        longest = max(1, math.floor(MAX_CHUNK_SECONDS / cost.per_case_s))
        k = max(k, math.ceil(n_cases / (workers * longest)))
    size = math.ceil(n_cases / (workers * k))
    return int(min(max(size, 1), n_cases, cap))
