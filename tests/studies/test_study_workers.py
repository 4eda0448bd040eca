"""Executors give their workers one solver thread each (BEARINGKIT_THREADS = 1, BLAS limited to 1).

Without it every worker process ran the solver's thread pool over all cores, so 2 workers on 2 cores
ran 4 busy threads (issue 9: 1.37x instead of >= 1.6x for 2 Dask workers over 1).
"""

import os

import pytest
from threadpoolctl import threadpool_info, threadpool_limits

from bearingkit.analysis.solver.quasistatic import THREADS_ENV, solver_threads
from bearingkit.errors import InputError
from bearingkit.studies.run import executors as ex


def _blas_threads() -> set[int]:
    return {i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"}


@pytest.fixture
def clean_env(monkeypatch):
    """No BEARINGKIT_THREADS at the start; environment and BLAS limits restored afterwards."""
    monkeypatch.delenv(THREADS_ENV, raising=False)
    with threadpool_limits(limits=None):  # records the BLAS limits and restores them on exit
        yield


def test_worker_environment_names_every_thread_variable():
    env = ex.worker_environment(1)
    assert env[THREADS_ENV] == "1"
    assert {"OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"} <= set(env)
    assert set(ex.worker_environment(3).values()) == {"3"}
    with pytest.raises(InputError, match=r"solver_threads \(0\)"):
        ex.worker_environment(0)


def test_limit_and_restore_are_counted_per_process(clean_env):
    full = solver_threads()
    ex.limit_worker_threads(1)
    ex.limit_worker_threads(1)  # a second in-process worker
    assert solver_threads() == 1 and os.environ[THREADS_ENV] == "1"
    if _blas_threads():  # numpy linked to a BLAS that threadpoolctl sees
        assert _blas_threads() == {1}
    ex.restore_worker_threads()
    assert solver_threads() == 1, "one worker still runs: keep the limit"
    ex.restore_worker_threads()
    assert THREADS_ENV not in os.environ and solver_threads() == full
    ex.restore_worker_threads()  # nothing left to restore: a no-op
    assert THREADS_ENV not in os.environ


def test_dask_task_on_a_worker_sees_one_solver_thread(clean_env, thread_cluster):
    from distributed import Client

    full = solver_threads()
    with thread_cluster(2) as cluster:
        with Client(cluster) as client:
            dask_ex = ex.DaskExecutor(client=client)
            workers = list(client.scheduler_info()["workers"])
            assert len(workers) == 2
            futures = [client.submit(solver_threads, workers=[w], pure=False) for w in workers]
            assert client.gather(futures) == [1, 1]
            blas = client.gather([client.submit(_blas_threads, workers=[w], pure=False) for w in workers])
            assert all(b <= {1} for b in blas)
            # the executor's own path (what a study runs) sees the same
            got = dict(dask_ex.map_unordered(lambda _: solver_threads(), [0, 1, 2]))
            assert got == {0: 1, 1: 1, 2: 1}
    # in-process workers share this process: the limit is undone when the last of them closes
    assert THREADS_ENV not in os.environ and solver_threads() == full


def test_dask_executor_can_leave_workers_alone(clean_env, thread_cluster):
    from distributed import Client

    with thread_cluster(1) as cluster:
        with Client(cluster) as client:
            ex.DaskExecutor(client=client, solver_threads=None)
            assert client.submit(solver_threads, pure=False).result() == (os.cpu_count() or 1)


def test_process_pool_workers_get_one_solver_thread(clean_env):
    names = [THREADS_ENV, "OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS"]
    with ex.ProcessPoolExecutor(workers=2) as pool:
        got = dict(pool.map_unordered(os.getenv, names))
    assert [got[i] for i in range(3)] == ["1", "1", "1"]
    assert THREADS_ENV not in os.environ, "the parent process keeps its own setting"


def test_make_executor_rejects_bad_thread_counts():
    with pytest.raises(InputError, match="solver_threads"):
        ex.ProcessPoolExecutor(workers=2, solver_threads=0)


def test_own_local_cluster_workers_get_the_environment(clean_env, monkeypatch):
    """Real worker processes: one solver thread from their start, and no Dask malloc trimming."""
    import dask
    import distributed  # noqa: F401 (loads the distributed config)

    # Dask's nanny writes its pre-spawn variables into THIS process too: restore them afterwards
    for k in [*dask.config.get("distributed.nanny.pre-spawn-environ"), "PYTHONHASHSEED"]:
        if k in os.environ:
            monkeypatch.setenv(k, os.environ[k])
        else:
            monkeypatch.delenv(k, raising=False)
    monkeypatch.delenv("MALLOC_TRIM_THRESHOLD_", raising=False)
    names = [THREADS_ENV, "OPENBLAS_NUM_THREADS", *ex.DASK_MALLOC_ENV]
    dask_ex = ex.DaskExecutor(workers=1)
    try:
        # os.getenv pickles by reference (a function of this test module would not import there)
        env = {k: next(iter(dask_ex.client.run(os.getenv, k).values())) for k in names}
        threads = dask_ex.client.submit(solver_threads, pure=False).result()
    finally:
        dask_ex.close()
    assert env[THREADS_ENV] == "1" and env["OPENBLAS_NUM_THREADS"] == "1" and threads == 1
    assert all(env[k] is None for k in ex.DASK_MALLOC_ENV)
