"""Names a package re-exports from its sub-modules, loaded on first use (PEP 562).

A package face such as ``bearingkit.analysis.solver`` offers ``solve`` without importing its modules
when the package itself is imported: importing a sub-module stays cheap, and a module that needs only
``solver.model`` does not pull in the whole solver.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from importlib import import_module


def exports(package: str, names: Mapping[str, str]) -> Callable[[str], object]:
    """A module ``__getattr__`` that loads ``names[attr]`` (a sub-module of ``package``) on first use.

    Parameters
    ----------
    package : str
        The package's ``__name__``.
    names : mapping of str to str
        Attribute name → sub-module name (relative to ``package``) that defines it.
    """

    def __getattr__(attr: str):
        if attr in names:
            return getattr(import_module(f"{package}.{names[attr]}"), attr)
        raise AttributeError(f"module {package!r} has no attribute {attr!r}")

    return __getattr__
