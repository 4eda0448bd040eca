"""What a study's worker does: evaluate a chunk under the thread limits every executor shares.

SI units are irrelevant here: a worker runs an evaluator (a pure function of a case table) on one
chunk and hands back its outputs. Kept apart from :mod:`bearingkit.studies.run.executors` (which
only decide where chunks run) because everything here runs *inside* a worker — a thread of this
process, a pool process or a Dask worker — and must behave the same in all of them:

- :func:`evaluate_chunk` / :func:`evaluate_columns`: one chunk with one BLAS thread
  (:func:`one_blas_thread`, the condition of bit-identical results across executors); the second
  returns plain numpy columns (case ids first), what the executors send back: a dict of arrays
  pickles without pandas and the store writes it as it is (issue 34: the parent's pandas work per
  chunk had become the limit of a 16-worker cluster);
- :func:`worker_environment`, :func:`limit_worker_threads`, :func:`restore_worker_threads` and the
  Dask plugin ``SolverThreadsPlugin``: one solver thread (and one BLAS thread) per worker process;
- :func:`exit_with_parent`: a pool worker ends with the process that started it.
"""

from __future__ import annotations

import os
import threading
from contextlib import contextmanager

import numpy as np

from bearingkit.analysis.solver import backend
from bearingkit.analysis.solver.threads import THREADS_ENV
from bearingkit.errors import InputError
from bearingkit.studies import evaluators
from bearingkit.studies.evaluators import is_default_index

#: Environment variables of the BLAS/OpenMP libraries numpy may load; set with ``THREADS_ENV`` so a
#: worker process started with this environment never spawns more threads than it is given.
BLAS_ENV = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


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
    backend.for_batches()  # one solver core for every chunk, whatever ran before in this process
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


def evaluate_columns(evaluator, cases, outputs=None) -> dict[str, np.ndarray]:
    """One chunk's outputs as numpy columns: ``case`` (the chunk's case ids) first, then the outputs.

    ``outputs``: keep only these (in this order), plus ``error`` where the evaluator gave one (why a
    group failed); None keeps every output. What the executors send back from their workers: a dict
    of arrays, no DataFrame to pickle, select and insert into on the study's side. Runs with one BLAS
    thread, as :func:`evaluate_chunk`.
    """
    backend.for_batches()  # one solver core for every chunk, whatever ran before in this process
    ev = evaluator if isinstance(evaluator, evaluators.Evaluator) else evaluators.get(evaluator)
    ids = cases["case"].to_numpy() if "case" in cases.columns else np.arange(len(cases))
    if len(cases.columns) and cases.columns[0] == "case":
        cases = cases.iloc[:, 1:]
    elif "case" in cases.columns:
        cases = cases.drop(columns=["case"])
    with one_blas_thread():
        out = ev.columns(cases)
    names = list(out)
    if outputs:
        missing = [o for o in outputs if o not in out]
        if missing:
            raise InputError(f"study.outputs {missing} are not outputs of the evaluator; it gives {names}")
        names = [*outputs, *(["error"] if "error" in out and "error" not in outputs else [])]
    return {"case": np.asarray(ids), **{name: out[name] for name in names}}
