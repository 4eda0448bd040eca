"""Command line: ``bearingkit``. Faces only: parse, call the public API, print; never recompute physics.

SI inside; units only in the input file and in ``--load`` values (``Fa=5kN``). Commands:

- ``validate``      recompute every published number (validation registry);
- ``analyze FILE``  quasi-static load distribution of a TOML input file (``--json`` for machines);
- ``schema``        the JSON Schema of the input file;
- ``run-flagship``  the flagship demonstration (``make run``): a list of sections, see
  :data:`FLAGSHIP_SECTIONS`.

Adding a command is one decorated function (``@app.command()``); adding a flagship section is one
function decorated with :func:`flagship_section`. Bad input: one line ``error: …`` on stderr, exit 2.
"""

from __future__ import annotations

import contextlib
import functools
import json
import math
import sys
from pathlib import Path

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from bearingkit.errors import InputError
from bearingkit.flagship import (  # noqa: F401 - re-exported: the flagship API lives there
    EXAMPLES_DIR,
    FLAGSHIP_CASE,
    FLAGSHIP_FILE,
    FLAGSHIP_HERTZ_LOAD,
    FLAGSHIP_REPORT,
    FLAGSHIP_SECTIONS,
    FlagshipContext,
    Section,
    flagship_section,
    run_sections,
)

app = typer.Typer(add_completion=False, no_args_is_help=True, help="Rolling-bearing mechanics.")
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
            _fail(str(exc))

    return wrapper


@app.command()
def validate(
    prefixes: list[str] = typer.Argument(None, help="Only cases whose id starts with one of these."),
    as_json: bool = typer.Option(False, "--json", help="Print a JSON list instead of a table."),
):
    """Recompute every published number bearingkit reproduces; exit 1 on an unexplained failure."""
    from bearingkit.validation.registry import all_cases, failures, run_cases

    cases = all_cases(prefixes or ())
    if not cases:
        err_console.print(f"error: no validation case matches {prefixes}")
        raise typer.Exit(2)
    results = run_cases(cases)
    if as_json:
        sys.stdout.write(json.dumps([r.to_dict() for r in results], indent=1) + "\n")
    else:
        table = Table(title=f"bearingkit validate: {len(results)} cases")
        for col in ("id", "unit", "published", "computed", "rel. error", "tol.", "status"):
            table.add_column(col, justify="left" if col == "id" else "right")
        for r in results:
            status = (
                "[green]pass[/]"
                if r.passed
                else ("[yellow]known[/]" if r.case.known_deviation else f"[red]FAIL[/] {r.error or ''}")
            )
            table.add_row(
                r.case.id,
                r.case.unit,
                f"{r.case.published:.6g}",
                f"{r.computed:.6g}",
                f"{r.rel_error:+.3%}",
                f"{r.case.tolerance:.1%}",
                status,
            )
        console.print(table)
        n_known = sum(1 for r in results if not r.passed and r.case.known_deviation)
        console.print(
            f"{sum(r.passed for r in results)} passed, {len(failures(results))} failed, "
            f"{n_known} known deviations"
        )
    if failures(results):
        raise typer.Exit(1)


#: Arguments and options shared by the commands that read a bearing file.
_FILE_ARGUMENT = typer.Argument(..., help="Input file (TOML with units), see docs/input-format.md.")
_LOAD_OPTION = typer.Option(
    None,
    "--load",
    "-l",
    help="NAME=VALUE replacing the file's load cases, e.g. --load Fa=5kN --load My=600N*m.",
)
_CASE_OPTION = typer.Option(None, "--case", "-c", help="Only the load case(s) with this name.")
_JSON_OPTION = typer.Option(False, "--json", help="Print JSON (SI values, units in keys).")
_SPEED_OPTION = typer.Option(
    None, "--speed", help="Speed of the rotating ring, e.g. 5rpm (default: the cases')."
)


@app.command()
@one_line_errors
def analyze(
    file: Path = _FILE_ARGUMENT,
    load: list[str] = _LOAD_OPTION,
    case: list[str] = _CASE_OPTION,
    as_json: bool = _JSON_OPTION,
):
    """Quasi-static load distribution of every load case; exit 1 if a case does not converge."""
    from bearingkit.io import export

    bearing = _load_bearing(file, load, case)
    result = bearing.solve()
    data = export.analysis_dict(bearing, result)
    flex = _flexible_ring(bearing)
    if flex is not None:  # the flexible-ring solution beside the rigid-ring one, per case
        for i, c in enumerate(data["cases"]):
            c["flexible"] = flex.to_dict(i) | {"case": c["case"]}
    if as_json:
        _print_json(file, data)
    else:
        console.print(f"{bearing.model.name}  ({file})", markup=False, highlight=False)
        for c in data["cases"]:
            console.print(case_table(c))
            if "flexible" in c:
                how = c["flexible"]["coupling"]
                console.print(f"flexible outer ring ({how['method']}, {how['iterations']} iterations):")
                console.print(case_table(c["flexible"]))
    if not result.converged.all():
        bad = [c for c in data["cases"] if not c["converged"]]
        _fail(f"{file}: load case {bad[0]['case']!r} did not converge: {bad[0]['reason']}", 1)
    if flex is not None and not flex.converged.all():
        bad = [c for c in data["cases"] if not c["flexible"]["converged"]]
        _fail(f"{file}: load case {bad[0]['case']!r}: the flexible-ring coupling did not converge", 1)


def _flexible_ring(bearing):
    """The coupled flexible-ring solution of a ball–column file ([geometry.ring] flexible), else None."""
    if bearing.bearing_type != "ball_column":
        return None
    from bearingkit.bearings.ball_column import solve_flexible_input

    return solve_flexible_input(bearing)


def _load_bearing(file: Path, load: list[str] | None, case: list[str] | None):
    """The input file with ``--load`` (replacing its cases) or ``--case`` (selecting some) applied."""
    from bearingkit.io.loader import load_file, parse_load_options

    bearing = load_file(file)
    if load:
        if case:
            raise InputError("--case selects file load cases; it cannot be combined with --load")
        return bearing.with_cases([parse_load_options(load)])
    return bearing.select(case)


def _print_json(file, data: dict) -> None:
    """Strict JSON on stdout; a non-finite value is a one-line error with exit code 1."""
    from bearingkit.io.export import to_json

    try:
        text = to_json(data)
    except ValueError as exc:
        _fail(f"{file}: {exc}", 1)
    sys.stdout.write(text + "\n")


def _g(x: float) -> str:
    """Compact number without '-0' and without round-off noise below 1e-9 of a newton."""
    return f"{(x if abs(x) > 1e-9 else 0.0) + 0.0:.6g}"


def case_table(c: dict) -> Table:
    """A rich table of one case dict (from :func:`bearingkit.io.export.case_dict`)."""
    d = c["displacement"]
    status = "converged" if c["converged"] else f"NOT converged: {c['reason']}"
    caption = (
        f"u = ({d['u_x_m'] * 1e6:.4g}, {d['u_y_m'] * 1e6:.4g}, {d['u_z_m'] * 1e6:.4g}) µm, "
        f"θ = ({d['theta_x_rad'] * 1e3:.4g}, {d['theta_y_rad'] * 1e3:.4g}) mrad; {status}, "
        f"{c['iterations']} iterations"
    )
    ld = c["load"]
    title = (
        f"case {c['case']!r}: F = ({_g(ld['F_x_N'])}, {_g(ld['F_y_N'])}, {_g(ld['F_z_N'])}) N, "
        f"M = ({_g(ld['M_x_Nm'])}, {_g(ld['M_y_Nm'])}) N·m"
    )
    table = Table(title=escape(title), caption=escape(caption))
    for col in ("row", "loaded", "Q_max N", "p_max MPa", "F_axial N", "F_radial N"):
        table.add_column(col, justify="left" if col == "row" else "right", no_wrap=True)
    for r in c["rows"]:
        table.add_row(
            r["name"],
            f"{r['loaded_count']}/{len(r['loads_N'])}",
            f"{r['max_load_N']:.1f}",
            f"{r['max_pressure_Pa'] / 1e6:.1f}",
            f"{r['axial_load_N']:.1f}",
            f"{r['radial_load_N']:.1f}",
        )
    return table


@app.command()
def schema():
    """Print the JSON Schema of the input file."""
    from bearingkit.io import loader  # noqa: F401 - registers every bearing type (bearingkit.io.kinds)
    from bearingkit.io.schema import json_schema

    sys.stdout.write(json.dumps(json_schema(), indent=1) + "\n")


# ---------------------------------------------------------------------------------------------
# rating and friction: options with units, per-case operating points.
# ---------------------------------------------------------------------------------------------
def _quantity(value: str | None, dimension: str, option: str) -> float | None:
    """An option value with its unit (``5rpm``, ``40degC``) in SI, or None when not given."""
    from bearingkit.units import parse

    return None if value is None else parse(value, dimension, option)


def _case_values(
    bearing, attr: str, override: float | None, example: str, required: bool = False, default=None
):
    """Per-case ``attr`` (C,): the option's value, else each load case's, else ``default``.

    Returns None when no case has one (and no default); a value missing in some cases only (or in any
    case when ``required``) is an InputError.
    """
    import numpy as np

    values = [override if override is not None else getattr(c, attr) for c in bearing.cases]
    values = [default if v is None else v for v in values]
    missing = [c.name for c, v in zip(bearing.cases, values, strict=True) if v is None]
    if not missing:
        return np.array(values, dtype=float)
    if required or len(missing) < len(values):
        raise InputError(
            f"{bearing.source}: load case {missing[0]!r} has no {attr}; give --{attr} {example} or "
            f"{attr} in every [[load_cases]]"
        )
    return None


def _lubricant(bearing, name: str | None):
    """``--lubricant`` preset, else the file's ``[lubricant]``; InputError when neither is given."""
    from bearingkit.lubricants import get_lubricant

    if name is not None:
        return get_lubricant(name)
    if bearing.lubricant is None:
        raise InputError(
            f'{bearing.source}: lubricant: none given; add [lubricant] name = "ISO_VG100" (a preset of '
            "bearingkit.lubricants.LUBRICANTS) to the file or use --lubricant"
        )
    return bearing.lubricant


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


@contextlib.contextmanager
def _in_file(file):
    """Prefix an InputError raised by the analysis API with the input file's name."""
    try:
        yield
    except InputError as exc:
        if str(exc).startswith(f"{file}:"):
            raise
        raise InputError(f"{file}: {exc}") from None


def _fail_unconverged(file, bearing, result) -> None:
    if not result.converged.all():
        i = int(next(i for i, ok in enumerate(result.converged) if not ok))
        _fail(f"{file}: load case {bearing.cases[i].name!r} did not converge: {result.reason[i]}", 1)


@app.command()
@one_line_errors
def rating(
    file: Path = _FILE_ARGUMENT,
    load: list[str] = _LOAD_OPTION,
    case: list[str] = _CASE_OPTION,
    speed: str = _SPEED_OPTION,
    reliability: str = typer.Option("0.9", "--reliability", help="Reliability of L_nr, 0.9 … 0.9995."),
    rotating: str = typer.Option(
        "inner", "--rotating", help="Ring rotating relative to the load: inner|outer."
    ),
    lubricant: str = typer.Option(None, "--lubricant", help="Lubricant preset (default: the file's)."),
    temperature: str = typer.Option(
        None, "--temperature", help="Operating temperature for a_ISO, e.g. 60degC."
    ),
    contamination: str = typer.Option(
        None, "--contamination", help="ISO 281 e_C (0 … 1); with lubricant and temperature gives a_ISO."
    ),
    load_rating: list[str] = typer.Option(
        None, "--load-rating", help="ROW=C replacing the ISO 281 rating of a row, e.g. roller_upper=50kN."
    ),
    as_json: bool = _JSON_OPTION,
):
    """ISO 76 / ISO 281 / ISO/TS 16281 ratings, lives and static safety of every row and the bearing."""
    from bearingkit.analysis.rating import rate
    from bearingkit.io import export
    from bearingkit.units import parse

    bearing = _load_bearing(file, load, case)
    speeds = _case_values(bearing, "speed", _quantity(speed, "angular_velocity", "--speed"), "5rpm")
    life_inputs = {}
    if contamination is not None:
        life_inputs = {
            "lubricant": _lubricant(bearing, lubricant),
            "temperature_C": _case_values(
                bearing, "temperature", _quantity(temperature, "temperature", "--temperature"), "60degC", True
            ),
            "contamination_factor": parse(contamination, "dimensionless", "--contamination"),
        }
    reliability_value = parse(reliability, "dimensionless", "--reliability")
    ratings = _load_ratings(load_rating)
    result = bearing.solve()
    with _in_file(file):
        out = rate(
            result,
            speed=speeds,
            rotating=rotating,
            reliability=reliability_value,
            load_ratings=ratings,
            **life_inputs,
        )
    data = export.rating_dict(bearing, out)
    if as_json:
        _print_json(file, data)
    else:
        console.print(f"{bearing.model.name}  ({file})", markup=False, highlight=False)
        for c in data["cases"]:
            console.print(rating_table(c))
            _print_warnings(c["warnings"])
    _fail_unconverged(file, bearing, result)


def _num(x, scale: float = 1.0, fmt: str = ".4g") -> str:
    """A JSON value for a table: ``—`` for None (masked, not available)."""
    return "—" if x is None else format(x * scale, fmt)


def _compact(x, scale: float = 1.0) -> str:
    """Three significant digits, short exponent (``7.45e4``); ``—`` for None."""
    if x is None:
        return "—"
    text = f"{x * scale:.3g}"
    mantissa, e, exponent = text.partition("e")
    return f"{mantissa}e{int(exponent)}" if e else text


def rating_table(c: dict) -> Table:
    """A rich table of one case dict of :func:`bearingkit.io.export.rating_dict`."""
    speed = "speed not given" if c["speed_rad_s"] is None else f"{c['speed_rad_s'] * 30 / math.pi:.4g} r/min"
    title = f"case {c['case']!r}: {c['rotating']} ring rotating, {speed}, reliability {c['reliability']:g}"
    s = c["system"]
    caption = (
        f"bearing: L10r = {_num(s['L10r_rev'], 1e-6)} 10⁶ rev, L10h = {_num(s['L10h_h'])} h, "
        f"L_nr = {_num(s['Lnr_rev'], 1e-6)} 10⁶ rev, L_nmr = {_num(s['Lnmr_rev'], 1e-6)} 10⁶ rev, "
        f"s0 = {_num(s['static_safety'], fmt='.3g')}"
    )
    table = Table(title=escape(title), caption=escape(caption))
    for col in ("row", "C kN", "C0 kN", "L10r 10⁶rev", "L10h h", "s0", "flags"):
        justify = "left" if col in ("row", "flags") else "right"
        table.add_column(
            col,
            justify=justify,
            no_wrap=col != "flags",
            overflow="fold",
            min_width=9 if col == "flags" else None,
        )
    for r in c["rows"]:
        table.add_row(
            r["name"],
            _num(r["C_N"], 1e-3),
            _num(r["C0_N"], 1e-3),
            _compact(r["L10r_rev"], 1e-6),
            _compact(r["L10r_h"]),
            _num(r["static_safety"], fmt=".3g"),
            escape(", ".join(k for k, v in r["flags"].items() if v)),
        )
    return table


def _print_warnings(warnings: list[str]) -> None:
    for w in warnings:
        console.print(f"  warning: {w}", markup=False, highlight=False)


#: Friction models of ``friction --model``: the physics component model of
#: :mod:`bearingkit.analysis.friction` and the engineering models of
#: :mod:`bearingkit.analysis.engineering_friction` (standard single-row bearings only).
FRICTION_MODELS = ("components", "skf", "palmgren")


@app.command()
@one_line_errors
def friction(
    file: Path = _FILE_ARGUMENT,
    load: list[str] = _LOAD_OPTION,
    case: list[str] = _CASE_OPTION,
    speed: str = _SPEED_OPTION,
    rotating: str = typer.Option(
        "inner", "--rotating", help="Rotating ring: inner|outer (the other is at rest)."
    ),
    temperature: str = typer.Option(
        None, "--temperature", help="Operating temperature, e.g. 40degC (default: the cases', else 25 °C)."
    ),
    lubricant: str = typer.Option(
        None, "--lubricant", help="Lubricant preset (default: the file's [lubricant])."
    ),
    model: str = typer.Option(
        "components",
        "--model",
        help="components (physics, per contact) | skf | palmgren (standard bearings).",
    ),
    as_json: bool = _JSON_OPTION,
):
    """Friction torque of every load case, broken down by component and by row."""
    from bearingkit.analysis.friction import OperatingPoint
    from bearingkit.io import export

    bearing = _load_bearing(file, load, case)
    if rotating not in ("inner", "outer"):
        raise InputError(f"--rotating ({rotating!r}) must be one of inner, outer")
    if model not in FRICTION_MODELS:
        raise InputError(f"--model ({model!r}) must be one of {', '.join(FRICTION_MODELS)}")
    lube = _lubricant(bearing, lubricant)
    speeds = _case_values(bearing, "speed", _quantity(speed, "angular_velocity", "--speed"), "5rpm", True)
    temps = _case_values(
        bearing,
        "temperature",
        _quantity(temperature, "temperature", "--temperature"),
        "40degC",
        default=OperatingPoint.__dataclass_fields__["temperature"].default,
    )
    if model == "components":
        cases = friction_cases(file, bearing, speeds, temps, lube, rotating)
    else:
        cases = engineering_friction_cases(file, bearing, speeds, temps, lube, model)
    data = export.friction_dict(bearing, cases)
    if as_json:
        _print_json(file, data)
    else:
        console.print(f"{bearing.model.name}  ({file})", markup=False, highlight=False)
        for c in data["cases"]:
            console.print(friction_table(c))


def friction_cases(file, bearing, speeds, temperatures, lubricant, rotating: str = "inner") -> list[dict]:
    """Solve and compute the friction of every case (one solve per distinct temperature)."""

    from bearingkit.analysis.friction import OperatingPoint, friction_torque
    from bearingkit.io.export import friction_case_dict

    groups: dict[float, list[int]] = {}
    for i, t in enumerate(temperatures):
        groups.setdefault(float(t), []).append(i)
    out: list[dict | None] = [None] * len(bearing.cases)
    for temp, idx in groups.items():
        sub = bearing.with_cases([bearing.cases[i] for i in idx])
        result = sub.solve()
        _fail_unconverged(file, sub, result)
        ring = {"speed_inner" if rotating == "inner" else "speed_outer": speeds[idx]}
        with _in_file(file):
            op = OperatingPoint(**ring, lubricant=lubricant, temperature=temp)
            fr = friction_torque(result, op)
        for k, i in enumerate(idx):
            out[i] = friction_case_dict(bearing.cases[i].name, op, fr, k)
    return out


def engineering_friction_cases(file, bearing, speeds, temperatures, lubricant, model: str) -> list[dict]:
    """SKF or Palmgren friction of every case (catalogue formulas from F_r, F_a; no solve needed)."""
    import numpy as np

    from bearingkit.analysis.engineering_friction import engineering_friction_torque
    from bearingkit.io.export import engineering_friction_case_dict

    load = bearing.load_matrix()
    geometry = bearing.geometry.model_dump()
    envelope = {}
    if geometry.get("bore") is not None and geometry.get("outer_diameter") is not None:
        envelope = {"bore_diameter": geometry["bore"], "outside_diameter": geometry["outer_diameter"]}
    speed = np.abs(speeds)
    with _in_file(file):
        result = engineering_friction_torque(
            bearing.model,
            load_radial=np.hypot(load[:, 0], load[:, 1]),
            load_axial=np.abs(load[:, 2]),
            speed=speed,
            lubricant=lubricant,
            temperature=np.asarray(temperatures, dtype=float),
            model=model,
            **envelope,
        )
    return [
        engineering_friction_case_dict(c.name, result, i, speed, temperatures)
        for i, c in enumerate(bearing.cases)
    ]


def friction_table(c: dict):
    """Rich tables (components, rows) of one case dict of :func:`bearingkit.io.export.friction_case_dict`."""
    from rich.console import Group
    from rich.text import Text

    f = c["friction"]
    total = f["total_Nm"]
    if "speed_rad_s" in c:  # engineering model: relative speed only, no per-row breakdown
        rpm, lube, model = c["speed_rad_s"] * 30 / math.pi, "", f" ({f['model']} model)"
    else:
        rpm = (c["speed_inner_rad_s"] - c["speed_outer_rad_s"]) * 30 / math.pi
        lube, model = f", {c['lubricant']}", ""
    title = (
        f"case {c['case']!r}{model}: M = {total:.4g} N·m at {rpm:.4g} r/min{lube} at "
        f"{c['temperature_C']:g} °C"
    )
    parts = Table(title=escape(title))
    for col in ("component", "N·m", "share"):
        parts.add_column(col, justify="left" if col == "component" else "right", no_wrap=True)
    for name, value in f["components_Nm"].items():
        parts.add_row(name, f"{value:.4g}", f"{value / total:.1%}" if total > 0 else "—")
    if "rows_Nm" not in f:
        return Group(parts, *(Text(f"  note: {n}", style="dim") for n in f["notes"]))
    rows = Table(title="by row")
    for col in ("row", "N·m", "share"):
        rows.add_column(col, justify="left" if col == "row" else "right", no_wrap=True)
    for name, value in f["rows_Nm"].items():
        rows.add_row(name, f"{value:.4g}", f"{value / total:.1%}" if total > 0 else "—")
    return Group(parts, rows)


# ---------------------------------------------------------------------------------------------
# run-flagship: the sections live in bearingkit.flagship (FLAGSHIP_SECTIONS, @flagship_section).
# ---------------------------------------------------------------------------------------------
@app.command("run-flagship")
@one_line_errors
def run_flagship(
    as_json: bool = typer.Option(False, "--json", help="Print JSON instead of tables."),
    report: Path = typer.Option(
        FLAGSHIP_REPORT, "--report", help="HTML report written at the end (when bearingkit.report can)."
    ),
    no_report: bool = typer.Option(False, "--no-report", help="Do not write the HTML report."),
):
    """The flagship demonstration on seed 000 (what `make run` calls)."""
    run_sections(console, as_json=as_json, report_path=None if no_report else report)


@app.command()
@one_line_errors
def study(
    file: Path = typer.Argument(..., help="Study file (TOML), see examples/studies/."),
    scheduler: str = typer.Option(None, "--scheduler", help="Dask scheduler address, e.g. tcp://host:8786."),
    workers: int = typer.Option(None, "--workers", help="Local worker processes (> 1: process pool)."),
    resume: bool = typer.Option(False, "--resume", help="Reuse the finished chunks in --out."),
    out: Path = typer.Option(None, "--out", help="Output folder (default: out/<study name>)."),
):
    """Run a design study (sweep, orthogonal array, Monte Carlo, optimisation); results stream to Parquet."""
    from bearingkit.studies.__main__ import run_cli

    run_cli(file, scheduler=scheduler, workers=workers, resume=resume, out=out, echo=console.print)


@app.command()
@one_line_errors
def report(
    file: Path = _FILE_ARGUMENT,
    output: Path = typer.Option(Path("out/report.html"), "-o", "--output", help="HTML file to write."),
    speed: str = typer.Option(None, "--speed", help="Speed of the rotating ring, e.g. 5rpm."),
    temperature: str = typer.Option(None, "--temperature", help="Operating temperature, e.g. 40degC."),
):
    """Write a self-contained HTML report: inputs, load distributions, friction, ratings, warnings."""
    from bearingkit.report import report_file

    path = report_file(
        file,
        output,
        speed=_quantity(speed, "angular_velocity", "--speed"),
        temperature=_quantity(temperature, "temperature", "--temperature"),
    )
    console.print(f"wrote {path}")


def main() -> None:
    """Entry point: one-line errors for bad input, exit code 2."""
    try:
        app()
    except InputError as exc:
        sys.stderr.write("error: " + " ".join(str(exc).split()) + "\n")
        sys.exit(2)


if __name__ == "__main__":
    main()
