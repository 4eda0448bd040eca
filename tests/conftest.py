"""Session-wide settings of the test suite.

``BEARINGKIT_BACKGROUND_COMPILE=0``: a small solve while the compiled core is not built would start
``bearingkit compile`` in the background (:func:`bearingkit.rows.numba_cache.start_background_build`);
the tests never leave such a process behind (``make test`` builds the core first, in the foreground).
Subprocesses started by tests inherit the setting.

One BLAS thread per test process: ``make test`` already runs one pytest-xdist process per core, and
OpenBLAS threads on top of that (numpy's and scipy's libraries, each with a thread per core) spin
waiting for one another on a busy machine: ``leggauss(600)`` took 1.1 s of processor time with two
BLAS threads and 0.04 s with one. The limit is set at run time (threadpoolctl), so subprocesses keep
their own defaults and a test that sets its own limit (``threadpool_limits(limits=2)``) still gets it;
``BEARINGKIT_TEST_BLAS_THREADS`` sets another count (``0``: no limit).
"""

import os

os.environ.setdefault("BEARINGKIT_BACKGROUND_COMPILE", "0")


def _limit_blas() -> None:
    threads = int(os.environ.get("BEARINGKIT_TEST_BLAS_THREADS", "1"))
    if threads <= 0:
        return
    import numpy  # noqa: F401  (load numpy's and scipy's BLAS first: only loaded libraries are limited)
    import scipy.linalg  # noqa: F401
    from threadpoolctl import threadpool_limits

    threadpool_limits(limits=threads, user_api="blas")


_limit_blas()
