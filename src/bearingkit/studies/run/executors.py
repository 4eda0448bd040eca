"""Executors of a study's chunks: in-process (default), local process pool, Dask distributed.

SI units are irrelevant here: an executor only maps a pure function over chunks of cases. Every
executor yields ``(position, result)`` pairs as chunks *finish* (so the store can write them at once),
keeps at most ``max_in_flight`` chunks submitted at a time, and computes each chunk with the same
function on the same data — so a study gives bit-identical results on all three; only the order in
which chunks finish differs, and the runner puts them back in order.

- :class:`InProcessExecutor` — sequential, in this process (each chunk is one batched solve).
- :class:`ProcessPoolExecutor` — ``workers`` local processes (``spawn`` start method: safe with threads).
- :class:`DaskExecutor` — a Dask ``distributed`` cluster: ``scheduler="tcp://host:8786"`` connects to a
  running scheduler, ``client=`` reuses a :class:`distributed.Client` (tests start a ``LocalCluster``),
  and neither starts a ``LocalCluster`` of ``workers`` single-threaded processes.

One solver thread per worker: the quasi-static solver splits a large batch over a thread pool of
:func:`bearingkit.analysis.solver.quasistatic.solver_threads` threads (all cores unless
``$BEARINGKIT_THREADS``
says otherwise). Inside a pool of worker processes that pool would put every core under every worker,
so two workers on two cores ran four busy threads and scaled 1.37× instead of ~2× (issue 9 note).
The process pool and the Dask executor therefore set ``BEARINGKIT_THREADS`` (and the BLAS thread
limits) in their workers: ``solver_threads=1`` by default, ``None`` leaves the workers untouched.
"""

from __future__ import annotations

import os
import threading
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager

import numpy as np

from bearingkit.analysis.solver.quasistatic import THREADS_ENV
from bearingkit.errors import InputError
from bearingkit.extras import require
from bearingkit.studies import evaluators
from bearingkit.studies.evaluators import is_default_index

#: Environment variables of the BLAS/OpenMP libraries numpy may load; set with ``THREADS_ENV`` so a
#: worker process started with this environment never spawns more threads than it is given.
BLAS_ENV = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


#: The interface a LocalCluster started by :class:`DaskExecutor` listens on.
LOOPBACK = "127.0.0.1"

#: Variables of Dask's default ``distributed.nanny.pre-spawn-environ`` that a LocalCluster started by
#: :class:`DaskExecutor` does NOT pass on. ``MALLOC_TRIM_THRESHOLD_=65536`` makes glibc hand freed
#: memory back to the OS at once (and fixes its mmap threshold at 128 KiB), so the solver's large
#: per-iteration temporaries are page-faulted in afresh every time: measured on the seed-000 sweep,
#: 8.6x the page faults and 30-40 % fewer cases/s per worker than glibc's default (issue 9 benchmark).
DASK_MALLOC_ENV = ("MALLOC_TRIM_THRESHOLD_",)


def worker_environment(threads: int = 1) -> dict[str, str]:
    """Environment variables that give a worker process ``threads`` solver and BLAS threads."""
    if int(threads) < 1:
        raise InputError(f"solver_threads ({threads}) must be >= 1")
    return {name: str(int(threads)) for name in (THREADS_ENV, *BLAS_ENV)}


# Worker state changed by :func:`limit_worker_threads`: one count per process, because in-process Dask
# workers (``LocalCluster(processes=False)``) share the process and must restore it only when the last
# of them closes.
_LIMIT_LOCK = threading.Lock()
_LIMIT_STATE: dict = {"users": 0, "environ": {}, "blas": None}


def limit_worker_threads(threads: int = 1) -> None:
    """Give this (worker) process ``threads`` solver threads and ``threads`` BLAS threads.

    Sets the variables of :func:`worker_environment` in ``os.environ`` (the solver reads
    ``BEARINGKIT_THREADS`` at every call) and limits the BLAS libraries already loaded (their thread
    count was fixed when numpy was imported, so the environment alone is too late). Undone by
    :func:`restore_worker_threads` once every caller has restored.
    """
    from threadpoolctl import threadpool_limits

    env = worker_environment(threads)
    with _LIMIT_LOCK:
        if _LIMIT_STATE["users"] == 0:
            _LIMIT_STATE["environ"] = {k: os.environ.get(k) for k in env}
            _LIMIT_STATE["blas"] = threadpool_limits(limits=int(threads), user_api="blas")
        else:
            threadpool_limits(limits=int(threads), user_api="blas")
        _LIMIT_STATE["users"] += 1
        os.environ.update(env)


def restore_worker_threads() -> None:
    """Undo :func:`limit_worker_threads` when its last caller in this process restores."""
    with _LIMIT_LOCK:
        if _LIMIT_STATE["users"] == 0:
            return
        _LIMIT_STATE["users"] -= 1
        if _LIMIT_STATE["users"]:
            return
        for k, v in _LIMIT_STATE["environ"].items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
        if _LIMIT_STATE["blas"] is not None:
            _LIMIT_STATE["blas"].restore_original_limits()
        _LIMIT_STATE.update(environ={}, blas=None)


# One BLAS thread while a chunk is evaluated, counted per process. Measured with numpy's OpenBLAS 0.3.31:
# - threadpoolctl's limit (``openblas_set_num_threads``) set from a thread other than the main one has
#   no effect on that thread's products, while ``openblas_set_num_threads_local`` (OpenBLAS >= 0.3.27)
#   does, from any thread;
# - the value the latter returns is shared between threads: two chunks restoring their "previous"
#   values in the wrong order left the process at one thread.
# So every chunk sets one thread in its own thread, the first chunk in remembers the previous count and
# the last one out restores it (the first out must not lift the limit of a chunk still running). For
# BLAS libraries without the thread-local call, threadpoolctl's process-wide limit, counted the same way.
_BLAS_LOCK = threading.Lock()
_BLAS_STATE: dict = {"users": 0, "limiter": None, "previous": None}
_LOCAL_SETTERS: list | None = None

#: Names of OpenBLAS's thread-local setter in the builds numpy and scipy ship (plain and prefixed).
_LOCAL_SETTER_NAMES = (
    "openblas_set_num_threads_local",
    "scipy_openblas_set_num_threads_local64_",
    "scipy_openblas_set_num_threads_local_64_",
    "scipy_openblas_set_num_threads_local",
)


def _thread_local_setters() -> list:
    """``openblas_set_num_threads_local`` of every loaded OpenBLAS that has it (looked up once)."""
    global _LOCAL_SETTERS
    if _LOCAL_SETTERS is None:
        import ctypes

        from threadpoolctl import threadpool_info

        setters = []
        for lib in threadpool_info():
            if lib.get("internal_api") != "openblas":
                continue
            try:
                handle = ctypes.CDLL(lib["filepath"])
            except OSError:  # pragma: no cover - a library threadpoolctl saw but ctypes cannot open
                continue
            for name in _LOCAL_SETTER_NAMES:
                fn = getattr(handle, name, None)
                if fn is not None:
                    fn.restype, fn.argtypes = ctypes.c_int, [ctypes.c_int]
                    setters.append(fn)
                    break
        _LOCAL_SETTERS = setters
    return _LOCAL_SETTERS


@contextmanager
def one_blas_thread():
    """Run the body with one BLAS thread (what every executor does around a chunk).

    Why: OpenBLAS partitions a matrix product (the row kernels' ``(C, N) @ (N, 5)`` products) by its
    thread count, and the edge blocks of a partition are summed in another order, so a case's last
    bits depended on the thread count: 32 of 3,000 seed-000 sweep cases (chunks of 250) differed by up
    to 8e-16 between the in-process run (2 BLAS threads) and the worker processes (1). The solver
    already runs large batches with one BLAS thread per solver thread, so this costs nothing there.
    """
    from threadpoolctl import threadpool_limits

    setters = _thread_local_setters()
    with _BLAS_LOCK:
        previous = [set_local(1) for set_local in setters]
        if _BLAS_STATE["users"] == 0:
            _BLAS_STATE["previous"] = previous
            if not setters:
                _BLAS_STATE["limiter"] = threadpool_limits(limits=1, user_api="blas")
        _BLAS_STATE["users"] += 1
    try:
        yield
    finally:
        with _BLAS_LOCK:
            _BLAS_STATE["users"] -= 1
            if _BLAS_STATE["users"] == 0:
                for set_local, old in zip(setters, _BLAS_STATE["previous"], strict=True):
                    set_local(old)
                if _BLAS_STATE["limiter"] is not None:
                    _BLAS_STATE["limiter"].restore_original_limits()
                _BLAS_STATE.update(limiter=None, previous=None)


def exit_with_parent() -> None:
    """End this worker process as soon as the process that started it ends, however it ends.

    A pool worker otherwise outlives a parent killed with SIGKILL (measured: over a minute, finishing
    the chunks it had queued). ``multiprocessing`` gives every spawned child a sentinel that becomes
    ready when its parent is gone (the pipe's other end closes with the parent); a daemon thread waits
    on it and exits the process at once. No polling, any platform, and it does not depend on which
    thread of the parent started the worker (Linux's ``PR_SET_PDEATHSIG`` would).
    """
    import multiprocessing
    from multiprocessing.connection import wait

    parent = multiprocessing.parent_process()
    if parent is None or getattr(parent, "sentinel", None) is None:
        return

    def watch():
        wait([parent.sentinel])
        os._exit(1)

    threading.Thread(target=watch, name="bearingkit-exit-with-parent", daemon=True).start()


def _init_pool_worker(threads: int | None) -> None:
    """Initializer of a process-pool worker (top-level: picklable under ``spawn``)."""
    exit_with_parent()
    if threads is not None:
        limit_worker_threads(threads)


def _make_plugin_class():
    from distributed.diagnostics.plugin import WorkerPlugin

    class SolverThreadsPlugin(WorkerPlugin):
        """Dask worker plugin: ``threads`` solver/BLAS threads in every worker (also later joiners)."""

        name = "bearingkit-solver-threads"
        idempotent = False

        def __init__(self, threads: int = 1):
            self.threads = int(threads)

        def setup(self, worker):
            limit_worker_threads(self.threads)

        def teardown(self, worker):
            restore_worker_threads()

    SolverThreadsPlugin.__module__ = __name__
    return SolverThreadsPlugin


def solver_threads_plugin(threads: int = 1):
    """A ``SolverThreadsPlugin`` giving every Dask worker ``threads`` solver and BLAS threads."""
    return __getattr__("SolverThreadsPlugin")(threads)


def __getattr__(name):
    # The plugin class subclasses distributed's WorkerPlugin; it is built on first use so that this
    # module (imported by every study run and every process-pool worker) does not import distributed.
    # Cached as a module attribute, it pickles by reference like any top-level class.
    if name == "SolverThreadsPlugin":
        cls = _make_plugin_class()
        globals()[name] = cls
        return cls
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def evaluate_chunk(evaluator, cases, with_ids: bool = True):
    """Evaluate one chunk (top-level, picklable: what executors send to workers).

    ``evaluator`` is the :class:`Evaluator` itself (resolved once, by the process that read the study
    file; a worker never resolves a name from data) or the name of a built-in. The chunk runs with
    one BLAS thread in every executor (:func:`one_blas_thread`): OpenBLAS
    splits a matrix product differently for another thread count and the last bits of a result
    depend on it, so this is what makes the executors agree bit for bit.

    Returns the cases' ``case`` ids (0… when ``cases`` has no ``case`` column) joined with the outputs;
    ``with_ids`` False: the outputs alone, row for row (a caller that keeps the order itself).
    """
    ev = evaluator if isinstance(evaluator, evaluators.Evaluator) else evaluators.get(evaluator)
    ids = cases["case"].to_numpy() if "case" in cases.columns else np.arange(len(cases))
    if len(cases.columns) and cases.columns[0] == "case":
        cases = cases.iloc[:, 1:]  # as drop(columns=["case"]), at a quarter of its cost in pandas 3
    elif "case" in cases.columns:
        cases = cases.drop(columns=["case"])
    with one_blas_thread():
        out = ev(cases)
    if not is_default_index(out.index, len(out)):
        out = out.reset_index(drop=True)
    if with_ids:
        out.insert(0, "case", ids)
    return out


class InProcessExecutor:
    """Evaluate chunks one after the other in this process."""

    name = "in-process"
    workers = 1

    def map_unordered(self, fn: Callable, items: Sequence) -> Iterator[tuple[int, object]]:
        for i, item in enumerate(items):
            yield i, fn(item)

    def close(self) -> None:
        pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


class ProcessPoolExecutor(InProcessExecutor):
    """Evaluate chunks on ``workers`` local processes.

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
        self.workers = int(workers)
        self.max_in_flight = max_in_flight or 2 * self.workers
        self.solver_threads = solver_threads
        self._pool = None

    def _ensure(self):
        if self._pool is None:
            import multiprocessing as mp
            from concurrent.futures import ProcessPoolExecutor as _Pool

            self._pool = _Pool(
                max_workers=self.workers,
                mp_context=mp.get_context("spawn"),
                initializer=_init_pool_worker,
                initargs=(self.solver_threads,),
            )
        return self._pool

    def map_unordered(self, fn, items):
        from concurrent.futures import FIRST_COMPLETED, wait

        pool = self._ensure()
        pending, nxt = {}, 0
        while nxt < len(items) or pending:
            while nxt < len(items) and len(pending) < self.max_in_flight:
                pending[pool.submit(fn, items[nxt])] = nxt
                nxt += 1
            done, _ = wait(pending, return_when=FIRST_COMPLETED)
            for fut in done:
                yield pending.pop(fut), fut.result()

    def close(self):
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None


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
                    http = {"scheduler_kwargs": {"dashboard": False, "dashboard_address": f"{LOOPBACK}:0"}}
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
        self.workers = threads
        self.max_in_flight = max_in_flight or 4 * threads

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
