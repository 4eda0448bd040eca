"""Executors of a study's chunks: in process (threads), local process pool, Dask distributed.

SI units are irrelevant here: an executor only maps a pure function over chunks of cases. Every
executor yields ``(position, result)`` pairs as chunks *finish* (so the store can write them at once),
keeps at most ``max_in_flight`` chunks submitted at a time, and computes each chunk with the same
function on the same data — so a study gives bit-identical results on all three; only the order in
which chunks finish differs, and the runner puts them back in order.

- :class:`InProcessExecutor` — in this process: ``threads`` chunks at once (default: one per core),
  each with one solver thread; a lone chunk gets every solver thread instead.
- :class:`ProcessPoolExecutor` — ``workers`` local processes (``spawn`` start method: safe with threads).
- :class:`DaskExecutor` — a Dask ``distributed`` cluster: ``scheduler="tcp://host:8786"`` connects to a
  running scheduler, ``client=`` reuses a :class:`distributed.Client` (tests start a ``LocalCluster``),
  and neither starts a ``LocalCluster`` of ``workers`` single-threaded processes.

**Threads in one process (issue 34).** The compiled solve releases the GIL, so chunks evaluated in
threads side by side run their solves on as many cores, and the post-processing of one chunk (Hertz,
lives, outputs: numpy) overlaps the solves of the others. Before, a chunk was solved on every core
and then post-processed on one, and an in-process study scaled 3.2x on 16 cores while its solve
alone scaled 9.9x. Each chunk's thread gets one solver thread
(:func:`bearingkit.analysis.solver.threads.thread_limit`, per thread).

**One solver thread per worker process.** The solver splits a large batch over
:func:`bearingkit.analysis.solver.threads.solver_threads` threads (all cores unless
``$BEARINGKIT_THREADS`` says otherwise). Inside a pool of worker processes that would put every core
under every worker, so two workers on two cores ran four busy threads and scaled 1.37× instead of
~2× (issue 9 note). The process pool and the Dask executor therefore set ``BEARINGKIT_THREADS`` (and
the BLAS thread limits) in their workers: ``solver_threads=1`` by default, ``None`` leaves the
workers untouched (:mod:`bearingkit.studies.run.workers`).

**Workers never outlive the run.** A process pool starts its workers once and reuses them for every
chunk and every generation of an optimisation; :meth:`ProcessPoolExecutor.close` ends them, and
kills them at once when chunks are still pending (an error, Ctrl-C): no worker finishes abandoned
chunks after the command has ended. A pool left open is closed when the interpreter exits, and a
worker whose parent dies exits by itself (:func:`~bearingkit.studies.run.workers.exit_with_parent`).
"""

from __future__ import annotations

import atexit
import time
import weakref
from collections.abc import Callable, Iterator, Sequence

from bearingkit.analysis.solver.threads import solver_threads, thread_limit
from bearingkit.errors import InputError
from bearingkit.extras import require
from bearingkit.studies.run.workers import (  # noqa: F401 (their home before issue 34; tests import them here)
    BLAS_ENV,
    _init_pool_worker,
    evaluate_chunk,
    evaluate_columns,
    exit_with_parent,
    limit_worker_threads,
    one_blas_thread,
    restore_worker_threads,
    solver_threads_plugin,
    worker_environment,
)

#: The interface a LocalCluster started by :class:`DaskExecutor` listens on.
LOOPBACK = "127.0.0.1"
#: Scheduler keyword arguments of a LocalCluster without a dashboard: Dask's scheduler binds its HTTP server
#: to 8787 even with ``dashboard_address=None``, so two clusters on one machine collide (a warning, and the
#: second one moves to a random port); a random loopback port from the start avoids both.
QUIET_SCHEDULER = {"dashboard": False, "dashboard_address": f"{LOOPBACK}:0"}

#: Variables of Dask's default ``distributed.nanny.pre-spawn-environ`` that a LocalCluster started by
#: :class:`DaskExecutor` does NOT pass on. ``MALLOC_TRIM_THRESHOLD_=65536`` makes glibc hand freed
#: memory back to the OS at once (and fixes its mmap threshold at 128 KiB), so the solver's large
#: per-iteration temporaries are page-faulted in afresh every time: measured on the seed-000 sweep,
#: 8.6x the page faults and 30-40 % fewer cases/s per worker than glibc's default (issue 9 benchmark).
DASK_MALLOC_ENV = ("MALLOC_TRIM_THRESHOLD_",)


def _noop(x):
    """A task that does nothing (top-level, picklable): an executor's round trip is timed with it."""
    return x


class InProcessExecutor:
    """Evaluate chunks in this process, ``threads`` at once.

    Parameters
    ----------
    threads : int or None
        Chunks evaluated at the same time, each in its own thread with one solver thread (the
        compiled solve releases the GIL). None: :func:`~bearingkit.analysis.solver.threads.solver_threads`
        (every core unless ``$BEARINGKIT_THREADS`` says otherwise). 1: one chunk after the other,
        each solved on every solver thread (the behaviour before issue 34). Fewer chunks than
        threads share the solver threads among them.
    max_in_flight : int or None
        Chunks handed to the threads at once (default 2 × threads).
    """

    name = "in-process"

    def __init__(self, threads: int | None = None, max_in_flight: int | None = None):
        if threads is not None and int(threads) < 1:
            raise InputError(f"threads ({threads}) must be >= 1")
        self.threads = None if threads is None else int(threads)
        self.max_in_flight = max_in_flight

    @property
    def workers(self) -> int:
        """Chunks evaluated at once."""
        return self.threads or solver_threads()

    def task_overhead(self) -> float:
        """The executor's own cost per chunk [s] beyond the evaluation (none in this process)."""
        return 0.0

    def map_unordered(self, fn: Callable, items: Sequence) -> Iterator[tuple[int, object]]:
        n = self.workers
        side_by_side = min(n, len(items))
        if side_by_side <= 1:
            for i, item in enumerate(items):
                yield i, fn(item)
            return
        from concurrent.futures import FIRST_COMPLETED, wait
        from concurrent.futures import ThreadPoolExecutor as _Threads

        each = max(1, n // side_by_side)  # solver threads per chunk

        def run(item):
            with thread_limit(each):
                return fn(item)

        limit = self.max_in_flight or 2 * side_by_side
        pool = _Threads(max_workers=side_by_side, thread_name_prefix="bearingkit-chunk")
        pending, nxt = {}, 0
        try:
            while nxt < len(items) or pending:
                while nxt < len(items) and len(pending) < limit:
                    pending[pool.submit(run, items[nxt])] = nxt
                    nxt += 1
                done, _ = wait(pending, return_when=FIRST_COMPLETED)
                for fut in sorted(done, key=pending.get):  # a fixed order among those done together
                    yield pending.pop(fut), fut.result()
        finally:  # an error or an abandoned run: queued chunks are dropped, running ones finish
            pool.shutdown(wait=True, cancel_futures=True)

    def close(self) -> None:
        pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


#: Process pools not closed yet: closed (their workers ended) when the interpreter exits.
_OPEN_POOLS: weakref.WeakSet = weakref.WeakSet()


@atexit.register
def _close_open_pools() -> None:
    for ex in list(_OPEN_POOLS):
        ex.close()


class ProcessPoolExecutor(InProcessExecutor):
    """Evaluate chunks on ``workers`` local processes.

    The processes start once (at the first chunk, or at :meth:`start`) and serve every chunk and
    every generation of an optimisation until :meth:`close`; a chunk still pending at ``close`` (an
    error, Ctrl-C) is abandoned and the workers are killed at once rather than left to finish it.

    Parameters
    ----------
    workers : int
        Number of processes (≥ 1).
    max_in_flight : int or None
        Chunks submitted at once (default 2 × workers).
    solver_threads : int or None
        Solver and BLAS threads in each process (default 1: the processes already use the cores);
        None leaves the solver its default (every core per process).
    """

    name = "process-pool"

    def __init__(self, workers: int = 2, max_in_flight: int | None = None, solver_threads: int | None = 1):
        if int(workers) < 1:
            raise InputError(f"workers ({workers}) must be >= 1")
        if solver_threads is not None:
            worker_environment(solver_threads)  # validates
        self.threads = int(workers)
        self.max_in_flight = max_in_flight or 2 * self.threads
        self.solver_threads = solver_threads
        self._pool = None
        self._pending: dict = {}

    def start(self):
        """Start the worker processes now (they load bearingkit while the caller does other work)."""
        if self._pool is None:
            import multiprocessing as mp
            from concurrent.futures import ProcessPoolExecutor as _Pool

            self._pool = _Pool(
                max_workers=self.threads,
                mp_context=mp.get_context("spawn"),
                initializer=_init_pool_worker,
                initargs=(self.solver_threads,),
            )
            _OPEN_POOLS.add(self)
            for _ in range(self.threads):  # concurrent.futures spawns its processes on demand
                self._pool.submit(_noop, None)
        return self._pool

    _ensure = start

    def task_overhead(self) -> float:
        """A no-op task's round trip [s] (pickling, the pipe, the worker's loop), workers started."""
        pool = self.start()
        pool.submit(_noop, None).result()
        t0 = time.perf_counter()
        pool.submit(_noop, None).result()
        return time.perf_counter() - t0

    def worker_pids(self) -> list[int]:
        """Process ids of the pool's workers (empty before :meth:`start`)."""
        procs = getattr(self._pool, "_processes", None) or {}
        return sorted(int(pid) for pid in procs)

    def map_unordered(self, fn, items):
        from concurrent.futures import FIRST_COMPLETED, wait

        pool = self.start()
        pending, nxt = self._pending, 0
        pending.clear()
        while nxt < len(items) or pending:
            while nxt < len(items) and len(pending) < self.max_in_flight:
                pending[pool.submit(fn, items[nxt])] = nxt
                nxt += 1
            done, _ = wait(pending, return_when=FIRST_COMPLETED)
            for fut in sorted(done, key=pending.get):
                yield pending.pop(fut), fut.result()

    def close(self):
        """End the workers: after their chunks when none is pending, else at once (killed)."""
        pool, self._pool = self._pool, None
        _OPEN_POOLS.discard(self)
        if pool is None:
            return
        abandoned = any(not f.done() for f in self._pending)
        self._pending.clear()
        if abandoned:  # an error or an interrupt: the chunks still running are not wanted
            for proc in list((getattr(pool, "_processes", None) or {}).values()):
                proc.kill()
        pool.shutdown(wait=True, cancel_futures=True)


class DaskExecutor(InProcessExecutor):
    """Evaluate chunks on a Dask distributed cluster.

    Parameters
    ----------
    scheduler : str or None
        Address of a running scheduler (``"tcp://host:8786"``).
    client : distributed.Client or None
        An existing client (takes precedence over ``scheduler``); not closed by :meth:`close`.
    workers : int or None
        Without ``scheduler``/``client``: start a LocalCluster of this many single-threaded worker
        processes (default 2).
    max_in_flight : int or None
        Chunks submitted at once (default 4 × the cluster's thread count).
    solver_threads : int or None
        Solver and BLAS threads per worker (default 1). A LocalCluster started here gets them in its
        worker processes' environment; every cluster also gets a worker plugin
        (``SolverThreadsPlugin``) that sets them in running and later workers. None: leave workers as
        they are.
    dashboard : str or None
        A LocalCluster started here serves Dask's dashboard only when asked: ``"127.0.0.1:8787"``
        (or any address you choose). Default None: no dashboard and no HTTP endpoint at all.

    Notes
    -----
    A LocalCluster started here listens on the loopback interface only (127.0.0.1, random ports for
    the scheduler and workers). Dask's servers start an HTTP server even with
    ``dashboard_address=None`` (the scheduler then binds the default 8787 and serves its health,
    info, JSON and proxy routes; each worker serves its own on a random port), so without
    ``dashboard`` the executor gives those servers no routes (``distributed.scheduler.http.routes``
    and ``distributed.worker.http.routes`` empty: every request is a 404) and binds them to a random
    loopback port. The scheduler's comm port has no authentication: any local user can connect to it
    (Dask's own model; use TLS through ``distributed.Security`` on shared machines, or the process
    pool, which opens no port).

    A LocalCluster started here keeps glibc's default memory trimming in its workers (Dask's
    ``MALLOC_TRIM_THRESHOLD_`` is left out, see :data:`DASK_MALLOC_ENV`). Workers of a cluster started
    elsewhere keep their own settings; remove that variable from their
    ``distributed.nanny.pre-spawn-environ`` for the same speed.
    """

    name = "dask"

    def __init__(
        self,
        scheduler: str | None = None,
        client=None,
        workers: int | None = None,
        max_in_flight=None,
        solver_threads: int | None = 1,
        dashboard: str | None = None,
    ):
        require("distributed", "studies", "the Dask executor")  # one line naming the extra
        env = worker_environment(solver_threads) if solver_threads is not None else {}
        self._own = client is None
        self._cluster = None
        if client is None:
            from distributed import Client

            if scheduler:
                client = Client(scheduler)
            else:
                import dask
                from distributed import LocalCluster

                pre_spawn = {
                    k: v
                    for k, v in dask.config.get("distributed.nanny.pre-spawn-environ", {}).items()
                    if k not in DASK_MALLOC_ENV
                }
                config = {"distributed.nanny.pre-spawn-environ": pre_spawn}
                http = {}
                if dashboard is None:  # no dashboard, no HTTP routes (see Notes)
                    config.update(
                        {"distributed.scheduler.http.routes": [], "distributed.worker.http.routes": []}
                    )
                    http = {"scheduler_kwargs": dict(QUIET_SCHEDULER)}
                with dask.config.set(config):
                    self._cluster = LocalCluster(
                        n_workers=int(workers or 2),
                        threads_per_worker=1,
                        processes=True,
                        host=LOOPBACK,
                        dashboard_address=dashboard,
                        worker_dashboard_address=None,
                        env=env,  # set in the worker process before it runs any task
                        **http,
                    )
                client = Client(self._cluster)
        self.client = client
        if solver_threads is not None:
            client.register_plugin(solver_threads_plugin(solver_threads))
        info = client.scheduler_info()
        threads = sum(w.get("nthreads", 1) for w in info.get("workers", {}).values()) or 1
        self.threads = threads
        self.max_in_flight = max_in_flight or 4 * threads

    def task_overhead(self) -> float:
        """A no-op task's round trip [s] through the scheduler to a worker and back."""
        self.client.submit(_noop, 0, pure=False).result()
        t0 = time.perf_counter()
        self.client.submit(_noop, 1, pure=False).result()
        return time.perf_counter() - t0

    def map_unordered(self, fn, items):
        from distributed import as_completed

        futures = {}
        it = iter(range(len(items)))

        def submit(i):
            fut = self.client.submit(fn, items[i], pure=False)
            futures[fut] = i
            return fut

        first = [submit(i) for _, i in zip(range(self.max_in_flight), it, strict=False)]
        ac = as_completed(first, with_results=True)
        for fut, result in ac:
            i = futures.pop(fut)
            nxt = next(it, None)
            if nxt is not None:
                ac.add(submit(nxt))
            yield i, result

    def close(self):
        if self._own:
            self.client.close()
            if self._cluster is not None:
                self._cluster.close()


def make_executor(kind: str | None = None, workers: int | None = None, scheduler: str | None = None):
    """Executor from CLI-style options: ``scheduler`` → Dask; ``workers > 1`` → process pool (or a Dask
    LocalCluster when ``kind="dask"``); otherwise in-process."""
    if scheduler or kind == "dask":
        return DaskExecutor(scheduler=scheduler, workers=workers)
    if kind in (None, "auto"):
        kind = "process" if workers and workers > 1 else "inprocess"
    if kind == "process":
        return ProcessPoolExecutor(workers or 2)
    if kind == "inprocess":
        return InProcessExecutor()
    raise InputError(f"executor ({kind!r}) must be one of inprocess, process, dask")
