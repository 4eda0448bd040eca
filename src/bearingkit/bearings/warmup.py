"""Build the compiled solver core once: solve one bearing of every compiled row kind (``bearingkit compile``).

numba compiles a function the first time it is called with a type signature and caches the machine
code on disk (:mod:`bearingkit.rows.numba_cache`). The compiled core has two entry points (one case
on the calling thread, a batch on every core) and four row kinds (ball, cylindrical with its coarse
stage, tapered, threaded); :func:`build` calls each entry point with a bearing of each kind and of
two kinds together, and the threaded rollers' tooth load sharing of the PTRB design studies, then
marks the cache built, after which the solver's ``auto`` backend may load the
compiled core for a large job (:mod:`bearingkit.analysis.solver.backend`).

A build takes about a minute on an idle 2-core machine. One build runs at a time per cache directory
(a lock file); a second :func:`build` waits for the first or, with ``wait=0``, leaves it alone.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np

from bearingkit.analysis.solver import SolverOptions, solve
from bearingkit.analysis.solver.threads import PARALLEL_MIN_CASES_PER_THREAD
from bearingkit.errors import InputError
from bearingkit.rows import numba_cache

#: Cases of the batched solve: enough for two threads to take the parallel entry point
#: (:data:`~bearingkit.analysis.solver.threads.PARALLEL_MIN_CASES_PER_THREAD` each), so it is compiled.
BATCH_CASES = 2 * PARALLEL_MIN_CASES_PER_THREAD


def warmup_bearings() -> dict[str, tuple]:
    """Name → (model, load (5,) [N, N·m]) of the bearings whose solves compile every kernel."""
    from bearingkit.bearings.ptrb import ptrb_model
    from bearingkit.bearings.standard import cylindrical_roller, deep_groove_ball
    from bearingkit.bearings.tapered import seed001_pair
    from bearingkit.bearings.turntable import composite_turntable

    return {
        "ball (deep groove 6205)": (
            deep_groove_ball(
                n_elements=9, element_diameter=7.94e-3, pitch_diameter=38.5e-3, clearance_radial=1e-5
            ),
            np.array([2000.0, 0.0, 0.0, 0.0, 0.0]),
        ),
        "cylindrical (NU 209)": (
            cylindrical_roller(
                n_elements=14, element_diameter=11e-3, effective_length=11e-3, pitch_diameter=65e-3,
                clearance_radial=2e-5,
            ),
            np.array([10000.0, 0.0, 0.0, 0.0, 0.0]),
        ),
        "tapered (32008 pair DB)": (seed001_pair(), np.array([2000.0, 0.0, 1000.0, 0.0, 0.0])),
        "threaded (PTRB)": (ptrb_model(), np.array([0.0, 0.0, 5000.0, 0.0, 0.0])),
        "ball + cylindrical (composite turntable)": (
            composite_turntable(),
            np.array([3000.0, 0.0, 3000.0, 0.0, -600.0]),
        ),
    }  # fmt: skip


def warm_tooth_sharing() -> bool:
    """Compile the threaded rollers' tooth load sharing (:mod:`bearingkit.rows.threaded.compiled_sharing`,
    the PTRB design optimisation's kernel) on two small designs; whether both converged."""
    from bearingkit.rows.threaded import compiled_sharing

    ones = np.ones(2)
    fa, conv = compiled_sharing.max_tooth_share(
        np.array([500.0, 2000.0]), np.array([4, 6]), 1e-7 * ones, 1.2e-7 * ones, 1e-9 * ones, 1e-9 * ones,
        1e-9 * ones, 2e-9 * ones, 3e-9 * ones, "opposite", 60, 1e-10,
    )  # fmt: skip
    return bool(conv.all() and np.all(fa >= 1.0))


#: What ``bearingkit compile`` says when another process holds the build (exit code 1).
BUSY = (
    "the compiled solver core is being built by another process; give --wait SECONDS to wait for it or "
    "run again later (small jobs run on the numpy core meanwhile)"
)


def build(wait: float = 600.0, echo: Callable[[str], None] | None = None) -> str:
    """Compile and cache the core; what was done: ``"built"``, ``"already built"`` or ``"busy"``.

    Parameters
    ----------
    wait : float [s]
        How long to wait for another process's build to finish before giving up (``"busy"``).
    echo : callable, optional
        Called with one line per bearing solved (``bearingkit compile`` prints them).
    """
    if not 0.0 <= wait < float("inf"):  # NaN fails too
        raise InputError(
            f"wait ({wait:g} s) must be 0 or more seconds to wait for a build already running "
            "(bearingkit compile --wait), e.g. 60"
        )
    if numba_cache.is_built():
        return "already built"
    with numba_cache.build_lock(wait=wait) as mine:
        if numba_cache.is_built():
            return "already built"
        if not mine:
            return "busy"
        from bearingkit.analysis.solver import backend

        if backend.compiled_module() is None:  # numba missing: nothing to build
            return "no numba"
        options = SolverOptions(backend="compiled")
        for name, (model, load) in warmup_bearings().items():
            t0 = time.perf_counter()
            scale = np.linspace(0.5, 1.0, BATCH_CASES)[:, None]
            for loads in (load[None, :], load[None, :] * scale):  # serial, then batched
                res = solve(model, loads, options=options)
                if not res.converged.all():
                    raise RuntimeError(f"compile warm-up: {name} did not converge ({res.reason})")
            if echo is not None:
                echo(f"  {name}: {time.perf_counter() - t0:.1f} s")
        t0 = time.perf_counter()
        if not warm_tooth_sharing():
            raise RuntimeError("compile warm-up: the threaded tooth load sharing did not converge")
        if echo is not None:
            echo(f"  threaded tooth load sharing (PTRB designs): {time.perf_counter() - t0:.1f} s")
        numba_cache.mark_built()
    return "built"
