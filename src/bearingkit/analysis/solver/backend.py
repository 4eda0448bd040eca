"""Which solver core runs: the compiled one (numba) or the numpy reference.

``SolverOptions(backend=…)`` or the environment variable ``BEARINGKIT_BACKEND`` chooses:

* ``"auto"`` (default): the compiled core where it applies (numba imports, every row of the bearing
  has a compiled kernel, no raceway offsets are imposed) AND pays for itself (:func:`wants_compiled`);
  the numpy reference otherwise;
* ``"compiled"``: the compiled core; a bearing it cannot take is an error;
* ``"numpy"``: always the numpy reference (the test oracle of the compiled core).

**When the compiled core pays for itself** (measured, ``benchmarks/bench_startup.py``): loading it from
its disk cache costs 0.5–1.5 s (numba's import and the cached machine code), compiling it ~1 min
(:mod:`bearingkit.rows.numba_cache`), while the numpy core solves a case in 2–15 ms alone and
0.05–0.6 ms in a batch. So ``auto`` runs a job of at most :data:`SMALL_JOB_CASES` cases on the numpy
core unless the compiled core is already loaded in this process; a larger job, or a process that has
spent :data:`LOAD_BUDGET_S` in numpy solves (many small ones: a shaft, a study's single cases), loads
the compiled core — from the cache when it is built, else compiling it there and then. While it is not
built, a small job logs one note (logger ``bearingkit.solver``; the CLI prints it) and starts the build
in the background, after which later processes use it. Both cores agree to 1e-12
(``tests/analysis/solver/test_compiled.py``).

If numba is not installed (or fails to import), ``auto`` and ``compiled`` fall back to numpy with one
warning per process. The backend asked for is resolved once per bearing and solver options (the solver
keeps it in its per-model plan, :mod:`bearingkit.analysis.solver.quasistatic`): the environment
variable is read when a bearing is first solved with those options, not at every solve.
"""

from __future__ import annotations

import logging
import os
import warnings

from bearingkit.analysis.solver.coarse import coarse_kernels
from bearingkit.errors import InputError
from bearingkit.rows import numba_cache

#: Environment variable naming the default backend.
BACKEND_ENV = "BEARINGKIT_BACKEND"
#: Accepted backend names.
BACKENDS = ("auto", "compiled", "numpy")

#: Largest job [cases] that ``auto`` runs on the numpy core in a process that has not loaded the
#: compiled core: the numpy core's batch costs ≤ ~0.15 s there (0.05–0.6 ms per case measured on the
#: example bearings, 2 cores), less than loading the compiled core (0.5–1.5 s).
SMALL_JOB_CASES = 256
#: Numpy solve time [s] after which ``auto`` loads the compiled core in this process (when it is built):
#: the lower end of its load time, so a process of many small solves pays at most about twice the
#: best choice made in hindsight.
LOAD_BUDGET_S = 0.5
#: What ``auto`` logs when a job ran on the numpy core because the compiled one is not built.
NOT_BUILT_NOTE = (
    "solved on the numpy core: the compiled core is not built yet (building it in the background; "
    "`bearingkit compile` builds it now)"
)
#: The same when ``BEARINGKIT_BACKGROUND_COMPILE=0`` stops the background build (it said "building it in
#: the background" there too, and nothing was building).
NOT_BUILT_NO_BACKGROUND_NOTE = (
    "solved on the numpy core: the compiled core is not built yet (no background build: "
    "BEARINGKIT_BACKGROUND_COMPILE=0; `bearingkit compile` builds it)"
)
#: What ``auto`` logs before it compiles the core in the foreground for a large job.
COMPILING_NOTE = (
    "compiling the solver core once for this {n}-case job (about a minute; `bearingkit compile` does it "
    "ahead of time)"
)

log = logging.getLogger("bearingkit.solver")
_STATE: dict = {"numpy_seconds": 0.0}


def loaded() -> bool:
    """Whether this process has loaded the compiled core already (numba imported and working)."""
    return _STATE.get("module") is not None


def wants_compiled(n_cases: int) -> bool:
    """``auto``: whether a job of ``n_cases`` cases should run on the compiled core (see the module doc).

    A small job on the numpy core while the core is not built logs :data:`NOT_BUILT_NOTE` once (or
    :data:`NOT_BUILT_NO_BACKGROUND_NOTE` where the background build is switched off) and starts
    :func:`bearingkit.rows.numba_cache.start_background_build`.
    """
    if loaded():
        return True
    if "module" in _STATE:  # numba tried and unusable: warned once already
        return False
    built = numba_cache.is_built()
    if n_cases > SMALL_JOB_CASES:
        if not built and not _STATE.get("compiling_noted"):
            _STATE["compiling_noted"] = True
            log.info(COMPILING_NOTE.format(n=n_cases))
        return True
    if built:
        return _STATE["numpy_seconds"] > LOAD_BUDGET_S
    if not _STATE.get("noted") and numba_cache.numba_installed():
        _STATE["noted"] = True
        log.info(NOT_BUILT_NOTE if numba_cache.background_allowed() else NOT_BUILT_NO_BACKGROUND_NOTE)
        numba_cache.start_background_build()
    return False


def for_batches() -> None:
    """Run every later ``auto`` solve of this process on the compiled core where it applies (a study's
    chunks: :mod:`bearingkit.studies.run.workers`); loads the core now, compiling it if it is not built.

    ``auto`` chooses the core by the job's size and by the numpy time the process has spent
    (:func:`wants_compiled`), and the two cores agree to 1e-12, not bit for bit. A study's results must
    not depend on what its process solved before, on its chunk size or on its executor (resume, workers
    and Dask give the same bits), so every chunk of a study runs on the one core. Does nothing when
    another backend is asked for or numba is not installed.
    """
    if requested(None) == "auto" and numba_cache.numba_installed():
        compiled_module()


def spent_numpy(seconds: float) -> None:
    """Add the time of a numpy solve that ``auto`` chose (the budget of :data:`LOAD_BUDGET_S`)."""
    _STATE["numpy_seconds"] += seconds


def requested(option: str | None) -> str:
    """The backend asked for: the option if given, else ``$BEARINGKIT_BACKEND``, else ``"auto"``."""
    name = option if option is not None else os.environ.get(BACKEND_ENV, "").strip() or "auto"
    if name not in BACKENDS:
        where = "SolverOptions.backend" if option is not None else BACKEND_ENV
        raise InputError(f"{where} ({name!r}) must be one of {', '.join(BACKENDS)}")
    return name


def compiled_module():
    """:mod:`bearingkit.analysis.solver.compiled_newton`, or None (with one warning) if numba is unusable."""
    if "module" not in _STATE:
        try:
            from bearingkit.analysis.solver import compiled_newton
        except Exception as exc:  # numba missing or broken: the numpy reference still works
            warnings.warn(
                f"bearingkit: the compiled solver core is unavailable ({type(exc).__name__}: {exc}); "
                "using the numpy reference solver (install numba for the fast core)",
                RuntimeWarning,
                stacklevel=3,
            )
            compiled_newton = None
        _STATE["module"] = compiled_newton
    return _STATE["module"]


def coarse_of(model):
    """The model's coarse kernels (:func:`bearingkit.analysis.solver.coarse.coarse_kernels`, cached on it)."""
    cache = model.__dict__.setdefault("_coarse_kernels", [])
    if not cache:
        cache.append(coarse_kernels(model.kernels))
    return cache[0]


def compiled_pack(model):
    """The model's packed arrays for the compiled core (cached on the model), or None if it has none."""
    cache = model.__dict__.setdefault("_compiled_pack", {})
    if "pack" not in cache:
        module = compiled_module()
        cache["pack"] = None if module is None else module.pack_model(model.kernels, coarse_of(model))
    return cache["pack"]
