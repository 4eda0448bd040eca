"""The batched quasi-static solve: model, Newton (numpy reference and compiled core), results (SI units).

Layers inside, bottom first: ``model``, ``cone``, ``solution`` → ``newton``, ``coarse``, ``speed`` →
``compiled_linalg`` → ``compiled_newton`` → ``backend`` → ``quasistatic`` (the driver, :func:`solve`).
The public names are importable from here: ``from bearingkit.analysis.solver import solve``.
"""

from importlib import import_module

_EXPORTS = {
    "solve": "quasistatic",
    "load_vector": "quasistatic",
    "SolverOptions": "quasistatic",
    "solver_threads": "quasistatic",
    "QuasiStaticResult": "solution",
    "BearingModel": "model",
}
__all__ = sorted(_EXPORTS)


def __getattr__(name):  # the re-exports load on first use: importing the package stays cheap
    if name in _EXPORTS:
        return getattr(import_module(f"{__name__}.{_EXPORTS[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
