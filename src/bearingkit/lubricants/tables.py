"""The lubricant data tables of ``bearingkit/data`` (``# source:`` lines, a header row, then values).

The lubricant layer sits below ``physics/`` (whose table reader it may not import), so it reads its own
three small tables here: the ASTM D2270 L/H table, the base-oil types and the library of typical
lubricants.
"""

from __future__ import annotations

import csv
import functools
import io
from importlib import resources


@functools.cache
def rows(name: str) -> tuple[dict[str, str], ...]:
    """The rows of ``bearingkit/data/<name>`` as dicts of stripped text (header → cell)."""
    text = resources.files("bearingkit").joinpath("data", name).read_text(encoding="utf-8")
    body = "\n".join(ln for ln in text.splitlines() if ln.strip() and not ln.startswith("#"))
    return tuple(
        {k.strip(): (v or "").strip() for k, v in r.items()} for r in csv.DictReader(io.StringIO(body))
    )


def source(name: str) -> str:
    """The ``# source:`` lines of table ``name``, joined."""
    text = resources.files("bearingkit").joinpath("data", name).read_text(encoding="utf-8")
    return " ".join(ln[len("# source:") :].strip() for ln in text.splitlines() if ln.startswith("# source:"))
