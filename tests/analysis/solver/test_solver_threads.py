"""The compiled core's serial and parallel drivers give the same bits; small batches run serially.

Issue 34: numba's OpenMP layer cost ~8 ms of spinning per parallel call, so batches of 2-100 cases
were 20-60x slower per case than large ones. Small batches now take the serial driver
(``threads.parallel_split``), blocks shrink to fit the batch, and OpenMP waits passively
(``numba_cache.THREAD_ENV``). None of this may change a result: every case is solved alone, so the
two drivers, any block size and any thread count must agree bit for bit.
"""

import dataclasses
import os
import subprocess
import sys
import threading

import numpy as np
import pytest

from bearingkit.analysis.solver import quasistatic as qs
from bearingkit.analysis.solver import threads
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings.tapered import seed001_pair, seed001_row
from bearingkit.bearings.turntable import composite_turntable
from bearingkit.errors import InputError
from bearingkit.io.loader import load_file
from bearingkit.physics.deviations import seed001_series

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))


def _drivers(model, load, free=None):
    """The compiled outputs of the serial driver and of the parallel one at three block sizes."""
    free_key = qs._ALL_FREE if free is None else qs._free_key(free)
    # The compiled core asked for by name: "auto" runs small batches on the numpy core (issue 42).
    options = dataclasses.replace(qs.DEFAULT_OPTIONS, backend="compiled")
    plan = qs._plan(model, free_key, options, None)
    assert plan.pack is not None, "the compiled core covers this bearing"
    q0 = np.zeros_like(load)
    args = (plan.pack, q0, load, plan.free, plan.scale, plan.max_step, plan.limit, options)
    args += (plan.cone_matrix, False)
    serial = plan.solve_packed(*args, False, {})
    parallel = [plan.solve_packed(*args, True, {}, block=b) for b in (1, 3, 32)]
    return serial, parallel


def _same(a, b):
    for name in ("q", "force", "stiffness", "flags", "counts", "norm", "inner"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)
    np.testing.assert_array_equal(a.roller_x, b.roller_x)  # NaN where unknown: equal NaN positions


@pytest.mark.parametrize(
    "case",
    ["6209", "seed000", "seed001_scatter", "seed001_pair"],
)
def test_serial_and_parallel_drivers_agree_bit_for_bit(case):
    rng = np.random.default_rng(34)
    free = None
    if case == "6209":
        inp = load_file(os.path.join(ROOT, "examples", "dgbb_6209.toml"))
        model, free = inp.model, inp.free
        load = load_vector(F_x=rng.uniform(1e3, 15e3, 40), F_z=rng.uniform(0.0, 2e3, 40))
    elif case == "seed000":
        model = composite_turntable()
        n = 24
        load = load_vector(
            F_z=rng.uniform(1e3, 8e3, n), F_x=rng.uniform(0, 3e3, n), M_y=-rng.uniform(0, 1.8e3, n)
        )
    elif case == "seed001_scatter":  # per-case geometry: roller-diameter scatter, one series per case
        table2 = np.stack([seed001_series(k) for k in range(1, 7)])
        dev = np.concatenate([table2, rng.normal(0.0, 1e-6, table2.shape)])
        model = BearingModel((seed001_row(diameter_deviation=dev),))
        load = load_vector(F_z=np.full(len(dev), 10_000.0))
        free = [True, True, True, False, False]
    else:  # tapered pair: the roller sub-problems' warm starts must not cross cases
        model = seed001_pair(arrangement="DB", spacing=0.04, clearance=-10e-6)
        load = load_vector(
            F_x=rng.uniform(-3e3, 3e3, 12), F_z=rng.uniform(200.0, 5e3, 12), M_y=rng.uniform(-60, 5, 12)
        )
    serial, parallel = _drivers(model, np.ascontiguousarray(load), free)
    assert serial.flags[0].all()
    for out in parallel:
        _same(serial, out)


def test_the_cached_entry_points_give_the_dispatchers_bits():
    """solve_packed calls each driver through numba's dispatcher once, then through the compiled entry
    point it kept (no type resolution; the serial driver gets the pack held in a typed list): the
    later calls must give the first call's bits."""
    inp = load_file(os.path.join(ROOT, "examples", "dgbb_6209.toml"))
    rng = np.random.default_rng(3)
    load = np.ascontiguousarray(load_vector(F_x=rng.uniform(1e3, 15e3, 20), F_z=rng.uniform(0.0, 2e3, 20)))
    options = dataclasses.replace(qs.DEFAULT_OPTIONS, backend="compiled")
    plan = qs._plan(inp.model, qs._free_key(inp.free), options, None)
    args = (plan.pack, np.zeros_like(load), load, plan.free, plan.scale, plan.max_step, plan.limit, options)
    args += (plan.cone_matrix, False)
    for parallel, key in ((False, "serial"), (True, "batch")):
        cache = {}
        first = plan.solve_packed(*args, parallel, cache, block=3)
        assert cache[key] is not None, "the entry point was found"
        again = plan.solve_packed(*args, parallel, cache, block=3)
        _same(first, again)
        assert first.flags[0].all()
    one = [
        plan.solve_packed(plan.pack, np.zeros((1, 5)), load[c : c + 1], *args[3:], False, cache)
        for c in (0, 1, 0)
    ]
    _same(one[0], one[2])
    assert not np.array_equal(one[0].q, one[1].q)  # another load, another answer


def test_a_batch_too_small_for_the_threads_runs_serially():
    m = threads.PARALLEL_MIN_CASES_PER_THREAD
    assert m >= 2
    assert threads.parallel_split(1, 16) == (1, 1)
    assert threads.parallel_split(2 * m - 1, 2) == (1, 2 * m - 1)  # two threads need m cases each
    assert threads.parallel_split(2 * m, 2) == (2, max(1, 2 * m // 8))
    assert threads.parallel_split(10, 2) == (1, 10)  # a batch of 10 is serial (issue 34's curve)
    t = 100 // m  # 100 cases on 16 threads: m cases per thread at least, ~4 blocks per thread
    assert threads.parallel_split(100, 16) == (t, max(1, 100 // (t * 4)))
    assert threads.parallel_split(100, 2) == (2, 12)  # ~4 blocks per thread
    assert threads.parallel_split(10_000, 2) == (2, threads.PARALLEL_CHUNK)
    assert threads.parallel_split(10_000, 1) == (1, 10_000)


def test_solve_results_do_not_depend_on_the_thread_count():
    """The public solve at 1, 2 and the default threads, batch sizes around the serial threshold."""
    model = composite_turntable()
    rng = np.random.default_rng(7)
    n_max = 2 * threads.PARALLEL_MIN_CASES_PER_THREAD + 1  # the largest batch runs on two threads
    load = load_vector(
        F_z=rng.uniform(1e3, 8e3, n_max), F_x=rng.uniform(0, 3e3, n_max), M_y=-rng.uniform(0, 1.8e3, n_max)
    )
    ref = solve(model, load)
    for n_threads in (1, 2):
        with threads.thread_limit(n_threads):
            for n in (1, 3, 9, 2 * threads.PARALLEL_MIN_CASES_PER_THREAD + 1):
                got = solve(model, load[:n])
                np.testing.assert_array_equal(got.displacement, ref.displacement[:n])
                np.testing.assert_array_equal(got.stiffness, ref.stiffness[:n])


def test_the_thread_limit_belongs_to_the_calling_thread(monkeypatch):
    monkeypatch.delenv(threads.THREADS_ENV, raising=False)
    full = threads.solver_threads()
    seen = {}
    with threads.thread_limit(1):
        assert threads.solver_threads() == 1
        with threads.thread_limit(3):  # a nested limit never raises an outer one
            assert threads.solver_threads() == 1
        other = threading.Thread(target=lambda: seen.update(n=threads.solver_threads()))
        other.start()
        other.join()
    assert seen["n"] == full, "another thread keeps its own count"
    assert threads.solver_threads() == full
    with pytest.raises(InputError, match="must be >= 1"):
        with threads.thread_limit(0):
            pass


def test_openmp_waits_passively_unless_the_user_says_otherwise():
    code = (
        "import os; from bearingkit.analysis.solver import compiled_newton; "
        "print(os.environ.get('OMP_WAIT_POLICY'))"
    )
    env = {k: v for k, v in os.environ.items() if k != "OMP_WAIT_POLICY"}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert out.stdout.split()[-1] == "PASSIVE"
    env["OMP_WAIT_POLICY"] = "ACTIVE"
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert out.stdout.split()[-1] == "ACTIVE"


def test_single_solves_in_several_threads_share_the_held_pack():
    """Threads of one process (the web app, a study's chunks) solving single cases at once all read the
    one typed list that holds the model's pack (compiled_newton._held): the same bits as one by one."""
    from concurrent.futures import ThreadPoolExecutor

    inp = load_file(os.path.join(ROOT, "examples", "dgbb_6209.toml"))
    options = dataclasses.replace(inp.options, backend="compiled")
    rng = np.random.default_rng(11)
    load = load_vector(F_x=rng.uniform(1e3, 15e3, 64), F_z=rng.uniform(0.0, 2e3, 64))

    def one(c):
        return solve(inp.model, load[c], free=inp.free, options=options).displacement[0]

    alone = np.array([one(c) for c in range(len(load))])
    with ThreadPoolExecutor(max_workers=4) as pool:
        together = np.array(list(pool.map(one, range(len(load)))))
    np.testing.assert_array_equal(together, alone)
    assert len({tuple(r) for r in alone}) == len(load)  # every load its own answer
