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
import os
import sys
from pathlib import Path

import typer
from rich.console import Console
from typer import _click as click
from typer.core import TyperGroup

from bearingkit.errors import (
    RUN_INTERRUPTED_EXIT,
    InputError,
    RunInterrupted,
    error_line,
    one_line,
    os_error_text,
)

# Piped output (CI logs, files) gets a wide console so table ids are not cut.
console = Console() if sys.stdout.isatty() else Console(width=200)
err_console = Console(stderr=True)


class OneLineGroup(TyperGroup):
    """The ``bearingkit`` command group: a usage error (an unknown option, a missing argument, a
    value that is not an integer) is one line too, ``error: bearingkit CMD: … (see bearingkit CMD
    --help)``, exit code 2, not click's boxed usage text."""

    def main(self, args=None, prog_name=None, complete_var=None, standalone_mode=True, **extra):
        if not standalone_mode:
            return super().main(args, prog_name, complete_var, standalone_mode=False, **extra)
        try:
            code = super().main(args, prog_name, complete_var, standalone_mode=False, **extra)
        except click.exceptions.NoArgsIsHelpError as exc:  # `bearingkit` alone: its help, as before
            exc.show()
            sys.exit(exc.exit_code)
        except click.ClickException as exc:
            where = exc.ctx.command_path if getattr(exc, "ctx", None) is not None else "bearingkit"
            sys.stderr.write(error_line(f"{exc.format_message()} (see {where} --help)", where) + "\n")
            sys.exit(exc.exit_code)
        except typer.Abort:  # typer bundles its own click, which has no click.Abort
            sys.stderr.write("error: aborted\n")
            sys.exit(1)
        sys.exit(code if isinstance(code, int) else 0)


#: Exit code of a failure that is bearingkit's own (a bug): EX_SOFTWARE of sysexits.h.
INTERNAL_ERROR_EXIT = 70
#: Environment variable that lets an unexpected exception through with its traceback (debugging).
TRACEBACK_ENV = "BEARINGKIT_TRACEBACK"


def _fail(message: str, code: int = 2, source=None):
    """One line on stderr (no rich wrapping or markup, :func:`bearingkit.errors.error_line`), then
    exit with ``code``. ``source``: the file or designation the line is about (shown shortened)."""
    sys.stderr.write(error_line(message, source) + "\n")
    raise typer.Exit(code)


def one_line_errors(fn):
    """Decorator for commands: every failure is one line ``error: FILE: …`` on stderr.

    An InputError exits with code 2; an operating-system error (a full disk, a path the system
    refuses) names the path and the system's reason, exit code 2; a run stopped part-way by its
    environment (:class:`~bearingkit.errors.RunInterrupted`: a killed worker, a full disk during a
    study) says what is kept and how to resume, exit code 75; anything else is a bug of
    bearingkit: one line naming the exception type, exit code :data:`INTERNAL_ERROR_EXIT` (the
    traceback only with ``BEARINGKIT_TRACEBACK=1``). A user never sees a traceback.
    """

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        file = kwargs.get("file")
        try:
            return fn(*args, **kwargs)
        except (typer.Exit, typer.Abort, KeyboardInterrupt):
            raise
        except InputError as exc:
            _fail(str(exc), source=file)
        except OSError as exc:
            _fail(os_error_text(exc), source=file)
        except RunInterrupted as exc:  # a killed worker, a full disk mid-study: resumable, not a bug
            _fail(str(exc), RUN_INTERRUPTED_EXIT, source=file)
        except Exception as exc:
            if os.environ.get(TRACEBACK_ENV):
                raise
            _fail(
                f"internal error ({type(exc).__name__}: {one_line(str(exc), 120)}); this is a bug of "
                "bearingkit: please report it with the input",
                INTERNAL_ERROR_EXIT,
                source=file,
            )

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
_SHAFT_HEAT_OPTION = typer.Option(
    False,
    "--heat",
    help="Find each bearing's operating temperature by its own heat balance (friction heat = heat carried "
    "away; the system file's [thermal], else each bearing's ISO 15312 reference housing) and give "
    "everything at it.",
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


#: The one refusal of a command that needs a load case and was given none (``friction 6209``).
NO_LOAD_CASE = (
    "no load case: give --load, e.g. --load Fr=5kN --speed 3000rpm, or [[load_cases]] in the file "
    "(docs/input-format.md)"
)


def _analysis(
    file: Path,
    load,
    case,
    hold=None,
    free=None,
    preload: str | None = None,
    duty_cycle_alone: bool = False,
    **operating,
):
    """The Analysis of ``file`` with ``--load`` (replacing its cases) or ``--case`` (selecting some),
    ``--hold`` / ``--free`` over its DOFs and ``preload``, the ``--preload`` of a pair named by
    designation. A bearing without load cases is refused (:data:`NO_LOAD_CASE`) unless
    ``duty_cycle_alone`` and it has a ``[[duty_cycle]]``."""
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
    if not bearing.cases and not (duty_cycle_alone and getattr(bearing, "duty_cycle", None) is not None):
        raise InputError(NO_LOAD_CASE)
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
        _fail(str(exc), 1, source=file)
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
        _fail(what, 1, source=file)
    flex = analysis.flexible
    if flex is not None and not flex.converged.all():
        i = int(next(i for i, ok in enumerate(flex.converged) if not ok))
        what = f"load case {analysis.case_names[i]!r}: the flexible-ring coupling did not converge"
        _fail(what, 1, source=file)


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


#: Longest file name (bytes) an output option may give: the common file-system limit (NAME_MAX).
MAX_OUTPUT_NAME_BYTES = 255


def check_outputs(**paths) -> None:
    """Refuse, before any work, output paths that could only fail after something is written.

    ``paths`` maps an option's name (``report`` for ``--report``) to its path or None. Each must name a
    file (not ``.``, ``..`` or an existing folder) of at most :data:`MAX_OUTPUT_NAME_BYTES` bytes, and no
    two options may name the same file; ``stiffness`` must end in ``.csv`` or ``.json``; ``ross`` names a
    folder (not an existing file) and needs ROSS installed. A command that
    writes several files checks them all first, so a refusal leaves nothing half-written.
    """
    from bearingkit.errors import quote

    seen: dict = {}
    folders: set = set()  # the keys of ``seen`` that name a folder (--ross)
    for option, path in paths.items():
        if path is None:
            continue
        flag = f"--{option.replace('_', '-')}"
        path = Path(path)
        if len(os.fsencode(path.name)) > MAX_OUTPUT_NAME_BYTES:  # before any stat, which would fail
            raise InputError(
                f"{flag}: the file name is longer than {MAX_OUTPUT_NAME_BYTES} bytes; give a shorter one"
            )
        if option == "ross":  # a folder (made if missing): one rotor file per shaft; ROSS installed
            if path.exists() and not path.is_dir():
                raise InputError(f"{flag} ({quote(str(path))}) must name a folder, not a file")
            from bearingkit.extras import check

            check("ross", "--ross (ROSS rotors)")
            seen_as_folder = True
        else:
            seen_as_folder = False
        if not seen_as_folder and (path.name in ("", ".", "..") or path.is_dir()):
            raise InputError(f"{flag} ({quote(str(path))}) must name a file, not a folder")
        if option == "stiffness" and path.suffix not in (".csv", ".json"):
            raise InputError(f"{flag} ({quote(str(path))}) must end in .csv or .json")
        key = os.path.abspath(path)
        if key in seen:
            raise InputError(
                f"{flag} and {seen[key]} name the same file ({quote(str(path))}); give two names"
            )
        # a file written first where another option needs a folder (`--report out --ross out/rotors`,
        # or `--ross` the report's own name) failed only after the first file was written
        for other, other_flag in seen.items():
            inner, outer = (key, other) if len(key) > len(other) else (other, key)
            outer_is_folder = seen_as_folder if outer == key else outer in folders
            if inner.startswith(outer + os.sep) and not outer_is_folder:
                raise InputError(
                    f"{flag} and {other_flag} collide: one names a file the other needs as a folder "
                    f"({quote(str(path))}); give two separate names"
                )
        seen[key] = flag
        if seen_as_folder:
            folders.add(key)


class undo_outputs:
    """``with undo_outputs(paths):`` — a command's several output files, all or nothing.

    Each file is written whole or not at all (:func:`bearingkit.io.export.write_atomic`), but a command
    that writes a report, then a table, then rotor files failed on the last with the first ones left
    behind. On any error inside the block this removes every path of ``paths`` (files, or a folder such
    as ``--ross``'s) that did not exist before, and the folders made for them, then lets the error go on.
    """

    def __init__(self, paths):
        self.paths = [Path(p) for p in paths if p is not None]

    def __enter__(self):
        self.new = [p for p in self.paths if not p.exists()]
        self.new_folders = []
        for p in self.new:
            q = p.parent
            while not q.exists() and q not in self.new_folders:
                self.new_folders.append(q)
                q = q.parent
        return self

    def __exit__(self, kind, exc, tb):
        if kind is None:
            return False
        import shutil

        for p in self.new:
            if p.is_dir() and not p.is_symlink():
                shutil.rmtree(p, ignore_errors=True)
            else:
                p.unlink(missing_ok=True)
        for q in sorted(self.new_folders, key=lambda d: len(d.parts), reverse=True):
            try:
                q.rmdir()
            except OSError:
                pass
        return False


_ROSS_OPTION = typer.Option(
    None, "--ross", help="Write one ROSS rotor per shaft (ross-rotordynamics .toml) into this folder."
)


def write_ross(solved, folder: Path) -> tuple[list, list]:
    """ROSS rotors of a solved shaft (ShaftResult) or drivetrain (DrivetrainAnalysis) into ``folder``:
    the paths written and the notes (bearingkit.systems.ross)."""
    from bearingkit.systems import ross

    if hasattr(solved, "drivetrain"):
        rotors, notes = ross.drivetrain_rotors(solved)
    else:
        rotors, notes = ross.shaft_rotors(solved)
    return ross.write_rotors(rotors, folder), notes


def notes_on_stderr() -> None:
    """The solver's one-line notes (which core ran, a compile starting) as ``note: …`` on stderr."""
    import logging

    log = logging.getLogger("bearingkit.solver")
    if not any(getattr(h, "bearingkit_cli", False) for h in log.handlers):
        handler = logging.StreamHandler(sys.stderr)
        handler.setFormatter(logging.Formatter("note: %(message)s"))
        handler.bearingkit_cli = True
        log.addHandler(handler)
        log.setLevel(logging.INFO)
