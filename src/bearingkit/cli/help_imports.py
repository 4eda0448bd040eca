"""typer's help formatter without the two rich modules it imports at load time and help never uses.

``typer.rich_utils`` (loaded by the first ``--help`` or usage error) imports ``rich.markdown`` (which loads
markdown-it-py, ~40 ms) and ``rich.traceback`` (which loads ``rich.pretty``, ~25 ms) at module level. In the
markup mode the command line uses ("rich") help renders neither: ``Markdown`` only formats the "markdown"
mode's text, ``Traceback`` only an uncaught exception. Those ~65 ms were a fifth of ``bearingkit --help``
(issue 42: < 0.3 s; ``benchmarks/bench_startup.py``).

:func:`import_typer_help` (called when :mod:`bearingkit.cli` is imported) imports ``typer.rich_utils`` while
the two modules are stand-ins whose ``Markdown`` and ``Traceback`` import the real module on first use, then
removes the stand-ins from ``sys.modules``: a later ``import rich.traceback`` anywhere gets the real module,
and ``typer.rich_utils`` keeps two names that build real rich objects when called (the help text is the same
character for character, and an uncaught exception still prints rich's traceback:
``tests/test_cli_help_imports.py``).
"""

from __future__ import annotations

import importlib
import sys
import types

#: Module → the one name typer.rich_utils takes from it.
DEFERRED = {"rich.markdown": "Markdown", "rich.traceback": "Traceback"}


def _real(module: str, name: str):
    return getattr(importlib.import_module(module), name)


def deferred_class(module: str, name: str) -> type:
    """A class standing for ``module.name``: calling it, or any attribute of it (a classmethod such as
    ``Traceback.from_exception``), imports the real module and answers with the real class."""

    class _Deferred(type):
        def __getattr__(cls, attr):
            return getattr(_real(module, name), attr)

    def __new__(cls, *args, **kwargs):  # the real instance; its own __init__ has run
        return _real(module, name)(*args, **kwargs)

    doc = f"{module}.{name}, imported when first used (bearingkit.cli.help_imports)."
    return _Deferred(name, (), {"__new__": __new__, "__module__": module, "__doc__": doc})


def import_typer_help() -> None:
    """Import ``typer.rich_utils`` without loading :data:`DEFERRED`'s modules (no-op once it is loaded,
    or where typer has no rich formatter)."""
    if "typer.rich_utils" in sys.modules:
        return
    stand_ins = {}
    for module, name in DEFERRED.items():
        if module not in sys.modules:
            stand_in = types.ModuleType(module)
            setattr(stand_in, name, deferred_class(module, name))
            stand_ins[module] = stand_in
    sys.modules.update(stand_ins)
    try:
        importlib.import_module("typer.rich_utils")
    except ImportError:  # a typer without rich: nothing to defer
        pass
    finally:
        for module, stand_in in stand_ins.items():
            if sys.modules.get(module) is stand_in:
                del sys.modules[module]
