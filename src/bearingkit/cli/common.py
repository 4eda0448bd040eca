"""What the ``bearingkit`` commands share between their options and the pipeline.

The consoles, one-line errors (:func:`one_line_errors`: ``error: …`` on stderr, exit 2), the
arguments and options of the commands that read a bearing file, the
:class:`~bearingkit.pipeline.Analysis` built from them, strict JSON on stdout, the bearing's header
line and the exit (code 1) when a load case does not converge.

It is apart from :mod:`bearingkit.cli.commands` so that module holds the commands alone, one
decorated function each; the commands import these names from here.
"""

from __future__ import annotations

import functools
import sys
from pathlib import Path

import typer
from rich.console import Console

from bearingkit.errors import InputError, one_line

# Piped output (CI logs, files) gets a wide console so table ids are not cut.
console = Console() if sys.stdout.isatty() else Console(width=200)
err_console = Console(stderr=True)


def _fail(message: str, code: int = 2):
    """One line on stderr (no rich wrapping or markup), then exit with ``code``."""
    sys.stderr.write("error: " + " ".join(str(message).split()) + "\n")
    raise typer.Exit(code)


def one_line_errors(fn):
    """Decorator for commands: an InputError becomes ``error: …`` on stderr and exit code 2."""

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        try:
            return fn(*args, **kwargs)
        except InputError as exc:
            message, file = str(exc), kwargs.get("file")
            if file is not None and not message.startswith(f"{file}:"):  # every error names the file
                message = f"{file}: {message}"
            _fail(message)

    return wrapper


#: Arguments and options shared by the commands that read a bearing file.
_FILE_ARGUMENT = typer.Argument(
    ...,
    help="Input file (TOML with units, docs/input-format.md) or a standard bearing designation such as "
    "6205-2RS C3 (docs/catalogue.md).",
)
_LOAD_OPTION = typer.Option(
    None,
    "--load",
    "-l",
    help="NAME=VALUE replacing the file's load cases, e.g. --load Fa=5kN --load My=600N*m.",
)
_CASE_OPTION = typer.Option(None, "--case", "-c", help="Only the load case(s) with this name.")
_HOLD_OPTION = typer.Option(
    None,
    "--hold",
    help="Hold an inner-ring DOF at 0 (u_x, u_y, u_z, theta_x, theta_y): its load becomes a reaction, e.g. "
    "--hold u_z for a single tapered bearing mounted against an opposite one.",
)
_FREE_OPTION = typer.Option(
    None, "--free", help="Free an inner-ring DOF the file or the defaults hold, e.g. --free theta_x."
)
_JSON_OPTION = typer.Option(False, "--json", help="Print JSON (SI values, units in keys).")
_SPEED_OPTION = typer.Option(
    None,
    "--speed",
    help="Speed of the rotating ring, e.g. 3000rpm; its sign is the direction of rotation "
    "(default: the cases').",
)
_TEMPERATURE_OPTION = typer.Option(
    None, "--temperature", help="Operating temperature, e.g. 60degC (default: the cases', else 25 °C)."
)
_ROTATING_OPTION = typer.Option(
    "inner", "--rotating", help="Ring rotating relative to the load: inner|outer."
)
_PRELOAD_OPTION = typer.Option(
    None,
    "--preload",
    help="Preload of a pair named by designation ('7014 C DB'): extra_light, light, medium, heavy (a rule "
    "on C, docs/catalogue.md) or a force such as 480N.",
)
_LUBRICANT_OPTION = typer.Option(
    None,
    "--lubricant",
    help="Lubricant: a name (ISO_VG68, VG68_PAO, SKF_LGMT2 …) or its data as text: 'VG68 ester', 'VG46 VI150 "
    "pao', 'nu_40=68mm^2/s nu_100=8.7mm^2/s' (docs/lubricants.md); default: the file's.",
)
_LUBRICANT_FILE_OPTION = typer.Option(
    None,
    "--lubricant-file",
    help="TOML file with a [lubricant] table (the fields of a bearing file's [lubricant]).",
)
_HEAT_OPTION = typer.Option(
    False,
    "--heat",
    help="Find the operating temperature by the heat balance (friction heat = heat carried away; the file's "
    "[thermal] or the ISO 15312 reference housing) and give everything at it.",
)
_CONTAMINATION_OPTION = typer.Option(
    None,
    "--contamination",
    help="ISO 281 e_C (0 … 1) or a level (normal_cleanliness, slight_contamination, …); with lubricant, "
    "speed and temperature gives a_ISO.",
)


#: Options parsed here (so a bad value names its option): option → (dimension, flag).
_OPTION_UNITS = {
    "speed": ("angular_velocity", "--speed"),
    "temperature": ("temperature", "--temperature"),
    "reliability": ("dimensionless", "--reliability"),
}


def _analysis(file: Path, load, case, hold=None, free=None, preload: str | None = None, **operating):
    """The Analysis of ``file`` with ``--load`` (replacing its cases) or ``--case`` (selecting some),
    ``--hold`` / ``--free`` over its DOFs and ``preload``, the ``--preload`` of a pair named by
    designation."""
    from bearingkit.io.loader import parse_load_options
    from bearingkit.pipeline import analyze, load_input
    from bearingkit.units import parse

    for key, (dimension, flag) in _OPTION_UNITS.items():
        if isinstance(operating.get(key), str):
            operating[key] = parse(operating[key], dimension, flag)
    if operating.get("rotating", "inner") not in ("inner", "outer"):
        raise InputError(f"--rotating ({operating['rotating']!r}) must be one of inner, outer")

    lubricant_file = operating.pop("lubricant_file", None)
    if lubricant_file is not None:
        if operating.get("lubricant") is not None:
            raise InputError("--lubricant and --lubricant-file both give the lubricant; give one")
        from bearingkit.io.loader import load_lubricant_file

        operating["lubricant"] = load_lubricant_file(lubricant_file)
    if operating.pop("heat", False):
        if operating.get("temperature") is not None:
            raise InputError(
                "--temperature and --heat both set the operating temperature; give one (--heat finds it)"
            )
        operating["thermal"] = True
    bearing = load_input(file, preload=preload)
    if load:
        if case:
            raise InputError("--case selects file load cases; it cannot be combined with --load")
        bearing = bearing.with_cases([parse_load_options(load)])
    else:
        bearing = bearing.select(case)
    if hold or free:
        bearing = bearing.with_dofs(hold or (), free or ())
    try:
        return analyze(bearing, **{k: v for k, v in operating.items() if v is not None})
    except InputError as exc:
        if str(exc).startswith(f"{file}:"):
            raise
        raise InputError(f"{file}: {exc}") from None


def _print_json(file, data: dict) -> None:
    """Strict JSON on stdout; a non-finite value is a one-line error with exit code 1."""
    from bearingkit.io.export import to_json

    try:
        text = to_json(data)
    except ValueError as exc:
        _fail(f"{file}: {exc}", 1)
    sys.stdout.write(text + "\n")


def _header(analysis, file) -> None:
    """The bearing's name and, for a designation, that (and how) its geometry is estimated."""
    bearing = analysis.input
    console.print(f"{bearing.model.name}  ({file})", markup=False, highlight=False)
    if bearing.spec.bearing.designation is not None:
        console.print(f"  note: {bearing.spec.bearing.source}", markup=False, highlight=False)


def _fail_unconverged(file, analysis) -> None:
    res = analysis.statics
    if not res.converged.all():
        i = int(next(i for i, ok in enumerate(res.converged) if not ok))
        # the file, then at most MAX_MESSAGE_CHARS (a long case name and the remedy must not overflow)
        what = f"load case {analysis.case_names[i]!r} did not converge: {res.reason[i]}"
        _fail(f"{file}: " + one_line(what), 1)
    flex = analysis.flexible
    if flex is not None and not flex.converged.all():
        i = int(next(i for i, ok in enumerate(flex.converged) if not ok))
        what = f"load case {analysis.case_names[i]!r}: the flexible-ring coupling did not converge"
        _fail(f"{file}: " + one_line(what), 1)


def _load_ratings(items: list[str] | None) -> dict:
    """``--load-rating ROW=C`` (C with a force unit) → {row name: C [N]}."""
    from bearingkit.units import parse

    out = {}
    for item in items or ():
        row, sep, value = item.partition("=")
        if not sep or not row.strip() or not value.strip():
            raise InputError(
                f"--load-rating ({item!r}) must look like ROW=VALUE with a unit, e.g. roller_upper=50kN"
            )
        out[row.strip()] = parse(value.strip(), "force", f"--load-rating {row.strip()}")
    return out
