"""A command-line app with one planted failure per finding class: the fuzz must find each of them.

Each command breaks one promise the fuzz checks (tests/fuzz/test_fuzz.py runs the fuzz over this
app instead of bearingkit's).
"""

from __future__ import annotations

import sys
import time
import warnings
from pathlib import Path

import typer

app = typer.Typer(add_completion=False)
_FILE = typer.Argument(..., help="Input file")
_JSON = typer.Option(True, "--json")


@app.command()
def boom(file: Path = _FILE):
    """An exception escapes (a traceback)."""
    raise IndexError("list index out of range")


@app.command()
def sleepy(file: Path = _FILE):
    """Runs past the hang limit."""
    time.sleep(60)


@app.command()
def badjson(file: Path = _FILE, as_json: bool = _JSON):
    """Prints JSON with NaN."""
    sys.stdout.write('{"x": NaN}\n')


@app.command()
def chatty(file: Path = _FILE):
    """Fails with two lines on stderr."""
    sys.stderr.write("error: first line\nsecond line\n")
    raise typer.Exit(2)


@app.command()
def litter(file: Path = _FILE):
    """Leaves a file behind, then fails."""
    Path("half-written.html").write_text("<html>")
    sys.stderr.write("error: refused after writing\n")
    raise typer.Exit(2)


@app.command()
def warny(file: Path = _FILE):
    """Computes a NaN on the way (numpy warns)."""
    import numpy as np

    with warnings.catch_warnings():
        warnings.simplefilter("always")
        np.array([0.0]) / np.array([0.0])


@app.command()
def fine(file: Path = _FILE):
    """Keeps every promise."""
    typer.echo("ok")
