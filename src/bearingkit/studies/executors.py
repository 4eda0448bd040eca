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
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence

from bearingkit.errors import InputError


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
    """

    name = "process-pool"

    def __init__(self, workers: int = 2, max_in_flight: int | None = None):
        if int(workers) < 1:
            raise InputError(f"workers ({workers}) must be >= 1")
        self.workers = int(workers)
        self.max_in_flight = max_in_flight or 2 * self.workers
        self._pool = None

    def _ensure(self):
        if self._pool is None:
            import multiprocessing as mp
            from concurrent.futures import ProcessPoolExecutor as _Pool

            self._pool = _Pool(max_workers=self.workers, mp_context=mp.get_context("spawn"))
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
    """

    name = "dask"

    def __init__(
        self, scheduler: str | None = None, client=None, workers: int | None = None, max_in_flight=None
    ):
        self._own = client is None
        self._cluster = None
        if client is None:
            from distributed import Client

            if scheduler:
                client = Client(scheduler)
            else:
                from distributed import LocalCluster

                self._cluster = LocalCluster(
                    n_workers=int(workers or 2), threads_per_worker=1, processes=True, dashboard_address=None
                )
                client = Client(self._cluster)
        self.client = client
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
