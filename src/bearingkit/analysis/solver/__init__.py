"""The batched quasi-static solve: model, Newton (numpy reference and compiled core), results (SI units).

Layers inside, bottom first: ``model``, ``cone``, ``solution`` → ``newton``, ``coarse``, ``speed`` →
``compiled_linalg`` → ``compiled_newton`` → ``backend`` → ``options`` → ``quasistatic`` (the driver,
:func:`solve`).
The public names are importable from here: ``from bearingkit.analysis.solver import solve``.
"""

from bearingkit.lazy import exports

_EXPORTS = {
    "solve": "quasistatic",
    "load_vector": "quasistatic",
    "SolverOptions": "options",
    "solver_threads": "quasistatic",
    "QuasiStaticResult": "solution",
    "BearingModel": "model",
}
__all__ = sorted(_EXPORTS)

__getattr__ = exports(__name__, _EXPORTS)  # loaded on first use: importing the package stays cheap
