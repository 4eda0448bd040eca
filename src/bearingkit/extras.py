"""Optional parts of bearingkit and what they need installed (the extras of ``pyproject.toml``).

``pip install bearingkit`` gives everything ``analyze``, ``rating``, ``friction``, ``shaft``, ``report``,
``catalogue``, ``select`` and ``validate`` need. The rest comes as extras:

=========== ====================================== ==================================================
extra       modules                                for
=========== ====================================== ==================================================
``studies`` dask, distributed, pymoo, pyarrow      ``bearingkit study``, :mod:`bearingkit.studies`
``app``     fastapi, uvicorn, tomli_w              ``bearingkit serve``, :mod:`bearingkit.app`
``ross``    ross                                   :mod:`bearingkit.systems.ross` (ROSS export)
``all``     studies + app                          every command and the web app
=========== ====================================== ==================================================

A face that needs an extra calls :func:`check` (or :func:`require` for one module) before it imports
it: a missing extra is one line naming the extra to install (``bearingkit study needs the [studies]
extra: pip install 'bearingkit[studies]' (not installed: pymoo)``), raised as :class:`MissingExtra`,
which the command line prints as ``error: …`` with exit code 2 and which Python code can catch as the
``ImportError`` it also is. Nothing here imports an extra's module: presence is checked with
:func:`importlib.util.find_spec`.
"""

from __future__ import annotations

import sys
from importlib import import_module
from importlib.util import find_spec

from bearingkit.errors import InputError

#: Extra → the top-level modules it installs (the distribution names are in pyproject.toml).
EXTRAS: dict[str, tuple[str, ...]] = {
    "studies": ("dask", "distributed", "pymoo", "pyarrow"),
    "app": ("fastapi", "uvicorn", "tomli_w"),
    "ross": ("ross",),
}


class MissingExtra(InputError, ImportError):
    """An optional part of bearingkit is used without its extra installed (one line: which to install)."""


def _present(module: str) -> bool:
    if module in sys.modules:  # imported already, or hidden (None) by a caller
        return sys.modules[module] is not None
    try:
        return find_spec(module) is not None
    except (ImportError, ValueError):
        return False


def missing(extra: str) -> list[str]:
    """The modules of ``extra`` that are not installed (empty when it is complete)."""
    return [m for m in EXTRAS[extra] if not _present(m.partition(".")[0])]


def message(extra: str, what: str, absent) -> str:
    """The one line: ``<what> needs the [<extra>] extra: pip install 'bearingkit[<extra>]' (…)``."""
    return (
        f"{what} needs the [{extra}] extra: pip install 'bearingkit[{extra}]' "
        f"(not installed: {', '.join(absent)})"
    )


def check(extra: str, what: str) -> None:
    """Raise :class:`MissingExtra` naming ``extra`` if any of its modules is missing.

    Parameters
    ----------
    extra : str
        A key of :data:`EXTRAS`.
    what : str
        What needs it, for the message (``"bearingkit study"``, ``"the web app"``).
    """
    absent = missing(extra)
    if absent:
        raise MissingExtra(message(extra, what, absent))


def require(module: str, extra: str, what: str):
    """Import and return ``module``; :class:`MissingExtra` naming ``extra`` when it is not installed."""
    if not _present(module.partition(".")[0]):
        raise MissingExtra(message(extra, what, [module.partition(".")[0]]))
    try:
        return import_module(module)
    except ModuleNotFoundError as exc:  # a dependency of the module itself is missing
        raise MissingExtra(message(extra, what, [exc.name or module])) from None
