"""Tables of the rating standards (ISO 76:2006, ISO 281:2007) shipped as CSV files in ``bearingkit/data``.

Each CSV file starts with ``# source: ...`` lines (standard, clause, table, how it was transcribed), then a
header row, then numbers. Tables are looked up with :func:`interp_strict`: linear interpolation inside the
tabulated range, and an :class:`~bearingkit.errors.InputError` naming the field, the value and the table's
range outside it — never extrapolation. The tables are dimensionless or in the standards' own units; the
physics modules convert to SI at their boundaries.
"""

from __future__ import annotations

import csv
import functools
import io
from importlib import resources

import numpy as np

from bearingkit.checks import _fmt, finite
from bearingkit.errors import InputError

#: Package holding the CSV files.
_DATA_PACKAGE = "bearingkit"
_DATA_DIR = "data"


@functools.cache
def _read(name: str) -> tuple[tuple[str, ...], tuple[str, ...], dict[str, tuple]]:
    text = resources.files(_DATA_PACKAGE).joinpath(_DATA_DIR, name).read_text(encoding="utf-8")
    source = tuple(ln[len("# source:") :].strip() for ln in text.splitlines() if ln.startswith("# source:"))
    body = "\n".join(ln for ln in text.splitlines() if ln.strip() and not ln.startswith("#"))
    rows = list(csv.reader(io.StringIO(body)))
    header = tuple(h.strip() for h in rows[0])
    columns: dict[str, list] = {h: [] for h in header}
    for row in rows[1:]:
        for h, cell in zip(header, row, strict=True):
            columns[h].append(cell.strip())
    return header, source, {h: tuple(v) for h, v in columns.items()}


def source(name: str) -> str:
    """The ``# source:`` lines of table ``name`` joined into one string.

    Parameters
    ----------
    name : str
        Table file stem in ``bearingkit/data``.
    """
    return " ".join(_read(name)[1])


def column(name: str, col: str) -> np.ndarray:
    """A numeric column of table ``name``; empty cells become NaN (outside the table).

    Parameters
    ----------
    name : str
        Table file stem in ``bearingkit/data`` (e.g. ``"iso281_fc_radial_ball"``).
    col : str
        Column header.
    """
    header, _, cols = _read(name)
    if col not in cols:
        raise InputError(f"column ({col!r}) must be one of {', '.join(header)} in table {name}")
    return np.array([float(c) if c else np.nan for c in cols[col]], dtype=float)


def text_column(name: str, col: str) -> tuple[str, ...]:
    """A text column of table ``name``.

    Parameters
    ----------
    name : str
        Table file stem in ``bearingkit/data``.
    col : str
        Column header.
    """
    return _read(name)[2][col]


def outside(x, xp: np.ndarray) -> np.ndarray:
    """Where ``x`` lies outside the table range ``[xp[0], xp[-1]]`` (what :func:`interp_strict` refuses).

    A tolerance of 1e-12 relative absorbs the rounding of values computed exactly at a table edge.

    Parameters
    ----------
    x : array_like
        Abscissae, in the table's unit.
    xp : numpy.ndarray
        Table abscissae (increasing, finite), in the same unit.
    """
    tol = 1e-12 * max(1.0, abs(xp[-1]))
    return (np.asarray(x, dtype=float) < xp[0] - tol) | (np.asarray(x, dtype=float) > xp[-1] + tol)


def interp_strict(field: str, x, xp: np.ndarray, fp: np.ndarray, unit: str = "") -> np.ndarray:
    """Linear interpolation of ``fp(xp)`` at ``x``; values outside ``[xp[0], xp[-1]]`` raise InputError.

    NaN entries of ``fp`` (empty table cells) shorten the range to the finite part.

    Parameters
    ----------
    field : str
        Name of the looked-up quantity, used in the error message.
    x : array_like
        Abscissae (broadcast freely).
    xp, fp : numpy.ndarray
        Table abscissae (increasing) and values.
    unit : str
        Unit of ``x`` for the message.
    """
    finite(field, x, unit)
    ok = np.isfinite(fp)
    xp, fp = xp[ok], fp[ok]
    arr = np.asarray(x, dtype=float)
    if np.any(outside(arr, xp)):
        shown = f"{_fmt(arr)} {unit}".strip()
        raise InputError(f"{field} ({shown}) must lie in the table range [{xp[0]:g}, {xp[-1]:g}]")
    return np.interp(np.clip(arr, xp[0], xp[-1]), xp, fp)
