"""``bearingkit --help`` without rich.markdown and rich.traceback (bearingkit/cli/help_imports.py): the
help is the same character for character, and what typer keeps of the two modules still builds the real
rich objects (an uncaught exception still prints rich's traceback). Each check runs a fresh interpreter:
the deferral only acts before typer.rich_utils is first imported."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

_HELP = """
import json, sys
{prelude}
from bearingkit.cli import main
sys.argv = ["bearingkit", *{argv!r}]
try:
    main()
except SystemExit:
    pass
sys.stderr.write("\\nSEEN " + json.dumps(sorted(m for m in {watch!r} if m in sys.modules)) + "\\n")
"""
WATCH = ("markdown_it", "rich.markdown", "rich.traceback", "rich.pretty", "typer.rich_utils")


def _python(code: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "COLUMNS": "100", "TERM": "dumb"}
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)


def _help(argv, prelude=""):
    out = _python(_HELP.format(prelude=prelude, argv=list(argv), watch=WATCH))
    marker = out.stderr.rindex("\nSEEN ")
    return out.stdout, json.loads(out.stderr[marker + 6 :])


@pytest.mark.parametrize("argv", [["--help"], ["analyze", "--help"], ["catalogue", "--help"]])
def test_help_is_unchanged_and_loads_neither_module(argv):
    deferred, seen = _help(argv)
    real, seen_real = _help(argv, prelude="import rich.markdown, rich.traceback")
    assert "Usage: bearingkit" in deferred
    assert deferred == real
    assert seen == ["typer.rich_utils"]  # help used typer's formatter, and loaded neither module
    assert {"rich.markdown", "rich.traceback", "typer.rich_utils"} <= set(seen_real)  # the check can fail


def test_what_typer_keeps_builds_the_real_objects():
    code = """
import sys
from bearingkit.cli.help_imports import import_typer_help
import_typer_help()
assert "rich.traceback" not in sys.modules and "rich.markdown" not in sys.modules
import typer.rich_utils as ru
from rich.console import Console
try:
    1 / 0
except ZeroDivisionError as exc:
    tb = ru.Traceback.from_exception(type(exc), exc, exc.__traceback__)
md = ru.Markdown("# Title\\n\\nsome *text*")
import rich.markdown, rich.traceback
assert type(tb) is rich.traceback.Traceback and type(md) is rich.markdown.Markdown
assert sys.modules["rich.traceback"] is rich.traceback and hasattr(rich.traceback, "install")
import io
c = Console(record=True, width=80, file=io.StringIO())
c.print(tb)
c.print(md)
text = c.export_text()
assert "ZeroDivisionError" in text and "Title" in text, text
print("OK")
"""
    out = _python(code)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "OK"


def test_an_uncaught_exception_still_prints_richs_traceback():
    code = """
import typer
from bearingkit.cli.help_imports import import_typer_help
import_typer_help()
app = typer.Typer()
@app.command()
def boom():
    raise ZeroDivisionError("planted")
@app.command()
def other():
    pass
app(["boom"])
"""
    out = _python(code)
    assert out.returncode == 1
    assert "ZeroDivisionError: planted" in out.stderr
    assert "Traceback (most recent call last)" in out.stderr  # rich's panel title
