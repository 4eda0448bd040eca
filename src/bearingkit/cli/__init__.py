"""Command line: ``bearingkit``. Faces only: parse, call the pipeline, print; never recompute physics.

SI inside; units only in the input file and in option values. :mod:`bearingkit.cli.commands` holds the
commands (:mod:`bearingkit.cli.catalogue_commands` the catalogue search and bearing selection),
:mod:`bearingkit.cli.common` the options and helpers they share, :mod:`bearingkit.cli.tables` the rich
tables, :mod:`bearingkit.cli.flagship` the flagship demonstration (``make run``).
"""

from bearingkit.cli import catalogue_commands  # noqa: F401  (registers catalogue, select)
from bearingkit.cli.commands import app, main
from bearingkit.cli.flagship import FLAGSHIP_SECTIONS, FlagshipContext, flagship_section, run_sections
from bearingkit.cli.tables import case_table, friction_table, rating_table

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
