"""Make the study-test helpers importable (``--import-mode=importlib`` does not touch sys.path)."""

import sys
from pathlib import Path

HERE = str(Path(__file__).resolve().parent)
if HERE not in sys.path:
    sys.path.insert(0, HERE)


import pytest  # noqa: E402


@pytest.fixture
def thread_cluster():
    """Builds a Dask LocalCluster of n single-thread workers in this process, its scheduler's HTTP server
    on a random loopback port (the executor's own setting: two xdist workers would collide on 8787)."""
    from distributed import LocalCluster

    from bearingkit.studies.run.executors import QUIET_SCHEDULER

    def make(n_workers: int):
        return LocalCluster(
            n_workers=n_workers,
            threads_per_worker=1,
            processes=False,
            dashboard_address=None,
            scheduler_kwargs=dict(QUIET_SCHEDULER),
        )

    return make
