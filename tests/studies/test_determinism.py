"""Bit-identical results on every executor (issue 24, item 9).

The audit found 431 of 40,000 rows differing in the last bits (<= 1.5e-15) between the in-process
run and the process pool / Dask. The cause, measured here: the BLAS thread count. OpenBLAS splits the
row kernels' matrix products by its thread count and sums the edge blocks in another order; the
in-process run had every core, the workers one. Every executor now evaluates a chunk with one BLAS
thread (``executors.one_blas_thread``), so the same chunk gives the same bits everywhere.
"""

import threading

import numpy as np
import pandas as pd
import pytest
from threadpoolctl import threadpool_info, threadpool_limits

from bearingkit.studies import evaluators
from bearingkit.studies.definition import load as sd
from bearingkit.studies.run import executors
from bearingkit.studies.run.cases import build_cases
from bearingkit.studies.run.executors import DaskExecutor, ProcessPoolExecutor
from bearingkit.studies.run.runner import run_study

#: The seed-000 sweep of benchmarks/bench_studies.py (its first 250 cases differed in 3 rows).
SWEEP = {
    "study": {
        "name": "seed000_sweep",
        "design": "monte_carlo",
        "evaluator": "seed000_statics",
        "samples": 250,
        "seed": 20250588,
        "chunk_size": 250,
    },
    "factors": [
        {"name": "axial_load", "distribution": "uniform", "low": "1 kN", "high": "8 kN"},
        {"name": "radial_load", "distribution": "uniform", "low": "0 kN", "high": "3 kN"},
        {"name": "eccentricity", "distribution": "uniform", "low": "0 m", "high": "0.4 m"},
        {"name": "clearance_axial_ball", "distribution": "uniform", "low": "-6 um", "high": "-2 um"},
    ],
}


def _blas_threads() -> set[int]:
    return {i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas"}


def _chunk(n_samples=250):
    d = sd.from_dict({**SWEEP, "study": {**SWEEP["study"], "samples": n_samples}})
    cases = build_cases(d)
    ev = evaluators.get("seed000_statics")
    return d, cases[["case", *[c for c in cases.columns if c in ev.factors]]]


def test_a_chunk_gives_the_same_bits_whatever_the_callers_blas_threads():
    """In-process (BLAS on every core) vs a worker (one BLAS thread): the same chunk, the same bits."""
    _, chunk = _chunk()
    with threadpool_limits(limits=2, user_api="blas"):
        many = executors.evaluate_chunk("seed000_statics", chunk)
    with threadpool_limits(limits=1, user_api="blas"):
        one = executors.evaluate_chunk("seed000_statics", chunk)
    assert many["converged"].all()
    pd.testing.assert_frame_equal(many, one, check_exact=True)


def test_chunks_in_other_threads_side_by_side_give_the_workers_bits():
    """A study run from a thread (a web app) and two chunks at once (a Dask worker with two threads).

    OpenBLAS ignores a global thread count set from a non-main thread, so the limit must be the
    thread-local one there; and the first chunk to finish must not lift the other's limit.
    """
    _, chunk = _chunk()
    with threadpool_limits(limits=1, user_api="blas"):  # what a worker process computes
        worker = executors.evaluate_chunk("seed000_statics", chunk)
    got, start = {}, threading.Barrier(2)

    def run(key):
        start.wait(10)
        got[key] = executors.evaluate_chunk("seed000_statics", chunk)

    with threadpool_limits(limits=2, user_api="blas"):  # the caller's process: BLAS on two cores
        threads = [threading.Thread(target=run, args=(k,)) for k in ("a", "b")]
        for t in threads:
            t.start()
        for t in threads:
            t.join(120)
        assert _blas_threads() <= {2}, "the caller's own setting is back"
    for key in ("a", "b"):
        pd.testing.assert_frame_equal(got[key], worker, check_exact=True)


@pytest.mark.slow
def test_in_process_pool_and_dask_agree_bit_for_bit():
    """The three executors on 1,000 sweep cases in chunks of 250 (the audit compared 40,000 rows)."""
    d = sd.from_dict({**SWEEP, "study": {**SWEEP["study"], "samples": 1000}})
    ref = run_study(d, progress=False).results
    with ProcessPoolExecutor(workers=2) as ex:
        pool = run_study(d, executor=ex, progress=False).results
    dask_ex = DaskExecutor(workers=2)
    try:
        dask = run_study(d, executor=dask_ex, progress=False).results
    finally:
        dask_ex.close()
    assert ref["converged"].all() and np.isfinite(ref["ball_axial_share"]).all()
    pd.testing.assert_frame_equal(pool, ref, check_exact=True)
    pd.testing.assert_frame_equal(dask, ref, check_exact=True)


@pytest.mark.slow  # ~12 s; the two determinism tests above stay in make test
def test_a_chunk_runs_on_one_core_whatever_the_process_solved_before():
    """``auto`` runs a small job on the numpy core and switches to the compiled one after 0.5 s of numpy
    solves (issue 42); the cores agree to 1e-12, not bit for bit. A chunk therefore loads the compiled
    core first, in a fresh process as after many small solves, and gives the same bits either way."""
    import os
    import subprocess
    import sys

    code = (
        "import sys, numpy as np\n"
        "from bearingkit.analysis.solver import backend\n"
        "from bearingkit.analysis.solver.quasistatic import solve, load_vector\n"
        "from bearingkit.bearings.turntable import composite_turntable\n"
        f"sys.path.insert(0, {os.path.dirname(__file__)!r})\n"
        "from test_determinism import _chunk\n"
        "from bearingkit.studies.run import executors\n"
        "_, chunk = _chunk(6)\n"
        "if sys.argv[1] == 'after':  # many small numpy solves first, as a notebook or the app does\n"
        "    m = composite_turntable()\n"
        "    for f in np.linspace(1e3, 4e3, 8): solve(m, load_vector(F_z=f))\n"
        "first = backend.loaded()\n"
        "out = executors.evaluate_chunk('seed000_statics', chunk)\n"
        "print(first, backend.loaded())\n"
        "np.save(sys.argv[2], out.select_dtypes('number').to_numpy(float))\n"
    )
    env = {**os.environ, "BEARINGKIT_BACKGROUND_COMPILE": "0"}
    env.pop("BEARINGKIT_BACKEND", None)
    results = {}
    for when in ("fresh", "after"):
        path = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"bk_chunk_{os.getpid()}_{when}.npy")
        run = subprocess.run(
            [sys.executable, "-c", code, when, path], capture_output=True, text=True, env=env
        )
        assert run.returncode == 0, run.stderr
        assert run.stdout.split() == ["False", "True"], run.stdout  # numpy before, compiled for the chunk
        results[when] = np.load(path)
        os.remove(path)
    np.testing.assert_array_equal(results["fresh"], results["after"])
