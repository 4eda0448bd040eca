"""Command line: ``bearingkit``. Faces only: parse, call the pipeline, print; never recompute physics.

SI inside; units only in the input file and in option values. :mod:`bearingkit.cli.commands` holds the
commands (:mod:`bearingkit.cli.catalogue_commands` the catalogue search and bearing selection),
:mod:`bearingkit.cli.common` the options and helpers they share, :mod:`bearingkit.cli.tables` the rich
tables, :mod:`bearingkit.cli.flagship` the flagship demonstration (``make run``).

**Start-up.** ``bearingkit --help`` and every ``bearingkit COMMAND --help`` load typer, rich and these
command modules only: a command module imports the pipeline, numpy, pint, pydantic, the tables … inside its
command function, never at module level, so a command costs its imports only when it runs
(``tests/test_startup.py`` runs every command's ``--help`` in a fresh interpreter and fails when one of the
heavy libraries appears in ``sys.modules``); typer's help formatter is imported here without the two rich
modules help never uses (:mod:`bearingkit.cli.help_imports`). The names below other than ``app`` and
``main`` load on first use.
"""

from bearingkit.cli import catalogue_commands  # noqa: F401  (registers catalogue, select)
from bearingkit.cli.commands import app, main
from bearingkit.cli.help_imports import import_typer_help
from bearingkit.lazy import exports

# typer's help formatter without rich.markdown / rich.traceback (~65 ms of every --help), for `main`
# and for `app` alike (cli/help_imports.py)
import_typer_help()

__all__ = [
    "FLAGSHIP_SECTIONS",
    "FlagshipContext",
    "app",
    "case_table",
    "flagship_section",
    "friction_table",
    "main",
    "rating_table",
    "run_sections",
]

__getattr__ = exports(
    __name__,
    {
        "FLAGSHIP_SECTIONS": "flagship",
        "FlagshipContext": "flagship",
        "flagship_section": "flagship",
        "run_sections": "flagship",
        "case_table": "tables",
        "friction_table": "tables",
        "rating_table": "tables",
    },
)
