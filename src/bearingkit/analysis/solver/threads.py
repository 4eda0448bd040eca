"""How many threads a batched solve uses, and how the compiled core splits a batch over them.

No physics and no units here: counts of threads and cases.

Three rules, each measured (issue 34):

- **The thread count** is ``$BEARINGKIT_THREADS`` or every core, unless the calling thread limits it
  with :func:`thread_limit`. The limit is per thread: a study that evaluates several chunks at once in
  threads of one process (:class:`bearingkit.studies.run.executors.InProcessExecutor`) gives each
  chunk one solver thread, while the rest of the program keeps its own count.
- **A small batch runs serially** (:data:`PARALLEL_MIN_CASES_PER_THREAD`): each parallel call of the
  compiled core wakes the threading layer's threads, which costs about what one case of a small
  bearing costs (below); a batch that cannot give every thread a few cases gains nothing from it.
- **Blocks fit the batch**: the parallel driver hands out blocks of at most :data:`PARALLEL_CHUNK`
  cases, and fewer for a batch too small to give each thread several blocks, so 100 cases on
  16 threads are not four blocks of 32 on four threads.

The threading layer itself (numba's OpenMP layer with ``OMP_WAIT_POLICY=PASSIVE``) is chosen where
numba is configured, before it is imported: :func:`bearingkit.rows.numba_cache.configure`.

Whether a case is solved in the serial or the parallel driver, in which block and by which thread,
changes no bit of its result: every case is solved alone from its own start with its own workspace
reset (``tests/analysis/test_solver_threads.py`` holds the two drivers to equality).
"""

from __future__ import annotations

import os
import threading
from contextlib import contextmanager

from bearingkit.errors import InputError

#: Environment variable that caps the solver's thread pool. Set it to 1 where the caller already
#: runs one solver per core (Dask workers, process pools): nested pools would oversubscribe them.
THREADS_ENV = "BEARINGKIT_THREADS"

#: Cases per block the compiled core's threads take at a time (dynamic scheduling of ``prange``
#: over blocks; one workspace per block).
PARALLEL_CHUNK = 32

#: A batch runs in the parallel driver only when every thread gets at least this many cases.
#: Measured on the 2-core machine (issue 34): a parallel call of an empty ``prange`` loop costs
#: 20 µs wall and 38 µs CPU with ``OMP_WAIT_POLICY=PASSIVE`` (55/80 µs with the workqueue layer,
#: 15 ms with OpenMP's default spinning policy on a loaded machine), while one case of the 6209
#: (9 balls, the cheapest bearing of the examples) costs 19-21 µs. Whole calls of the 6209 on the
#: shared machine (load 2.9, serial vs two threads, wall per case): 4 cases 22.7 vs 24.1 µs, 8 cases
#: 20.8 vs 20.4, 12 cases 19.4 vs 18.6, 16 cases 19.2 vs 17.2, 64 cases 18.7 vs 15.2. Below 8 cases
#: per thread the second thread saves at most a few per cent of the wall time for twice the CPU
#: time (a batch of 10 cases cost 2.0x the thread-seconds per case of a batch of 10⁴ with 2 cases
#: per thread); from 16 cases on two threads it saves 10 % or more.
PARALLEL_MIN_CASES_PER_THREAD = 8

#: Blocks each thread should get at least (dynamic scheduling evens out cases of unequal cost).
BLOCKS_PER_THREAD = 4

_LOCAL = threading.local()


def solver_threads() -> int:
    """Threads the solver uses: the calling thread's :func:`thread_limit`, else ``$BEARINGKIT_THREADS``,
    else the core count."""
    limit = getattr(_LOCAL, "limit", None)
    if limit is not None:
        return limit
    value = os.environ.get(THREADS_ENV, "").strip()
    if not value:
        return os.cpu_count() or 1
    try:
        n = int(value)
    except ValueError:
        raise InputError(f"{THREADS_ENV}={value!r}: expected a positive integer") from None
    if n < 1:
        raise InputError(f"{THREADS_ENV}={value!r}: expected a positive integer")
    return n


@contextmanager
def thread_limit(threads: int):
    """Solve with at most ``threads`` threads inside the body, in the calling thread only."""
    threads = int(threads)
    if threads < 1:
        raise InputError(f"solver threads ({threads}) must be >= 1")
    previous = getattr(_LOCAL, "limit", None)
    _LOCAL.limit = threads if previous is None else min(previous, threads)
    try:
        yield
    finally:
        _LOCAL.limit = previous


def parallel_split(n_cases: int, threads: int) -> tuple[int, int]:
    """(threads, block) for a compiled batch of ``n_cases``: threads 1 means the serial driver.

    Parallel only when every thread gets :data:`PARALLEL_MIN_CASES_PER_THREAD` cases; the block is
    :data:`PARALLEL_CHUNK` or smaller, so that each thread gets about :data:`BLOCKS_PER_THREAD` blocks.
    """
    threads = max(1, min(int(threads), n_cases // PARALLEL_MIN_CASES_PER_THREAD))
    if threads == 1:
        return 1, n_cases
    block = max(1, min(PARALLEL_CHUNK, n_cases // (threads * BLOCKS_PER_THREAD)))
    return threads, block
