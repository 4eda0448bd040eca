"""bearingkit: open rolling-bearing mechanics.

Quasi-static load distribution of multi-row bearings, friction torque, load ratings and life,
manufacturing deviations, flexible rings and design studies. SI units everywhere inside
(m, N, Pa, rad, s, Pa·s, 1/Pa); units are parsed only at the edges (:mod:`bearingkit.units`).

>>> import bearingkit as bk
>>> a = bk.analyze("examples/dgbb_6209.toml", load={"F_x": "5 kN"}, speed="3000 rpm")  # doctest: +SKIP

:func:`analyze` and :class:`Analysis` come from :mod:`bearingkit.pipeline` (loaded on first use, so
``import bearingkit`` stays light).
"""

from typing import TYPE_CHECKING

from bearingkit.errors import ConvergenceError, InputError
from bearingkit.extras import MissingExtra

if TYPE_CHECKING:  # what __getattr__ loads on first use, visible to type checkers and the API reference
    from bearingkit.pipeline import Analysis, analyze, load_input

__version__ = "0.1.0"
__all__ = [
    "Analysis",
    "ConvergenceError",
    "InputError",
    "MissingExtra",
    "__version__",
    "analyze",
    "load_input",
]

#: Names this package re-exports from the pipeline on first access.
_PIPELINE_NAMES = ("Analysis", "analyze", "load_input")


def __getattr__(name: str):
    if name in _PIPELINE_NAMES:
        from bearingkit import pipeline

        return getattr(pipeline, name)
    raise AttributeError(f"module 'bearingkit' has no attribute {name!r}")


def __dir__() -> list[str]:
    """The public names (``analyze`` … loaded on first use) with the module's own: tab completion."""
    return sorted(set(globals()) | set(__all__))
