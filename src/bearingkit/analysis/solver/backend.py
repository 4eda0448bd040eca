"""Which solver core runs: the compiled one (numba) or the numpy reference.

``SolverOptions(backend=…)`` or the environment variable ``BEARINGKIT_BACKEND`` chooses:

* ``"auto"`` (default): the compiled core when numba imports and every row of the bearing has a
  compiled kernel and no raceway offsets are imposed; the numpy reference otherwise;
* ``"compiled"``: the same, but a bearing the compiled core cannot take is an error;
* ``"numpy"``: always the numpy reference (the test oracle of the compiled core).

If numba is not installed (or fails to import), ``auto`` and ``compiled`` fall back to numpy with one
warning per process. The choice is made once per bearing and solver options (the solver keeps it
in its per-model plan, :mod:`bearingkit.analysis.solver.quasistatic`): the environment variable is read
when a bearing is first solved with those options, not at every solve.
"""

from __future__ import annotations

import os
import warnings

from bearingkit.analysis.solver.coarse import coarse_kernels
from bearingkit.errors import InputError

#: Environment variable naming the default backend.
BACKEND_ENV = "BEARINGKIT_BACKEND"
#: Accepted backend names.
BACKENDS = ("auto", "compiled", "numpy")

_STATE: dict = {}


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
