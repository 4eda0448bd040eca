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

import functools
import json
import math
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import typer
from rich.console import Console
from rich.markup import escape
from rich.table import Table

from bearingkit.errors import InputError

app = typer.Typer(add_completion=False, no_args_is_help=True, help="Rolling-bearing mechanics.")
console = Console()
err_console = Console(stderr=True)

#: Repository examples (src/bearingkit/cli.py → ../../examples).
EXAMPLES_DIR = Path(__file__).resolve().parents[2] / "examples"
#: The flagship input file and load case (seed 000, sections 6.1.4–6.1.5: F_a = F_r = 3 kN, M = 600 N·m).
FLAGSHIP_FILE = EXAMPLES_DIR / "seed000_composite.toml"
FLAGSHIP_CASE = "flagship"
#: Ball load of the flagship Hertz summary [N] (one axial ball of seed 000 at 1 kN).
FLAGSHIP_HERTZ_LOAD = 1000.0


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


@app.command()
@one_line_errors
def analyze(
    file: Path = typer.Argument(..., help="Input file (TOML with units), see docs/input-format.md."),
    load: list[str] = typer.Option(
        None,
        "--load",
        "-l",
        help="NAME=VALUE replacing the file's load cases, e.g. --load Fa=5kN --load My=600N*m.",
    ),
    case: list[str] = typer.Option(None, "--case", "-c", help="Only the load case(s) with this name."),
    as_json: bool = typer.Option(False, "--json", help="Print JSON (SI values, units in keys)."),
):
    """Quasi-static load distribution of every load case; exit 1 if a case does not converge."""
    from bearingkit.io import export
    from bearingkit.io.loader import load_file, parse_load_options

    bearing = load_file(file)
    if load:
        if case:
            raise InputError("--case selects file load cases; it cannot be combined with --load")
        bearing = bearing.with_cases([parse_load_options(load)])
    else:
        bearing = bearing.select(case)
    result = bearing.solve()
    data = export.analysis_dict(bearing, result)
    if as_json:
        try:
            sys.stdout.write(export.to_json(data) + "\n")
        except ValueError as exc:
            _fail(f"{file}: {exc}", 1)
    else:
        console.print(f"{bearing.model.name}  ({file})", markup=False, highlight=False)
        for c in data["cases"]:
            console.print(case_table(c))
    if not result.converged.all():
        bad = [c for c in data["cases"] if not c["converged"]]
        _fail(f"{file}: load case {bad[0]['case']!r} did not converge: {bad[0]['reason']}", 1)


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
    from bearingkit.io.schema import json_schema

    sys.stdout.write(json.dumps(json_schema(), indent=1) + "\n")


# ---------------------------------------------------------------------------------------------
# run-flagship: a list of sections; each is a function of the shared context.
# ---------------------------------------------------------------------------------------------
@dataclass
class FlagshipContext:
    """What flagship sections share: the seed-000 input (loaded once) and its solved flagship case."""

    file: Path = FLAGSHIP_FILE
    case: str = FLAGSHIP_CASE
    _bearing: object = None
    _result: object = None
    data: dict = field(default_factory=dict)

    @property
    def bearing(self):
        """The flagship :class:`~bearingkit.io.loader.BearingInput`, only the flagship case."""
        if self._bearing is None:
            from bearingkit.io.loader import load_file

            self._bearing = load_file(self.file).select([self.case])
        return self._bearing

    @property
    def result(self):
        """The solved flagship case (QuasiStaticResult, one case)."""
        if self._result is None:
            self._result = self.bearing.solve()
        return self._result


@dataclass(frozen=True)
class Section:
    """A flagship section: a title and ``run(ctx) -> (rich renderable, JSON-ready dict)``."""

    title: str
    run: Callable


#: Sections printed by ``bearingkit run-flagship``, in order. Friction, ratings and the report
#: add theirs with :func:`flagship_section`.
FLAGSHIP_SECTIONS: list[Section] = []


def flagship_section(title: str):
    """Register ``fn(ctx: FlagshipContext) -> (renderable, dict)`` as a run-flagship section."""

    def register(fn):
        FLAGSHIP_SECTIONS.append(Section(title, fn))
        return fn

    return register


@flagship_section("Hertz contact of one seed-000 axial ball")
def _hertz_section(ctx: FlagshipContext):
    from bearingkit.io.export import hertz_ball_summary
    from bearingkit.materials import e_reduced

    g = ctx.bearing.geometry
    f = g.groove_curvature
    data = hertz_ball_summary(
        FLAGSHIP_HERTZ_LOAD,
        g.ball_diameter,
        g.pitch_diameter_axial_ball,
        math.pi / 2,
        f,
        f,
        e_reduced(ctx.bearing.material, ctx.bearing.material),
    )
    data.update(
        element_diameter_m=g.ball_diameter,
        pitch_diameter_m=g.pitch_diameter_axial_ball,
        contact_angle_rad=math.pi / 2,
        conformity=f,
        material=ctx.bearing.material.name,
    )
    table = Table(
        title=escape(
            f"ball Ø {g.ball_diameter * 1e3:g} mm, α = 90°, f = {f:g}, "
            f"d_m = {g.pitch_diameter_axial_ball * 1e3:g} mm, {ctx.bearing.material.name}, "
            f"Q = {FLAGSHIP_HERTZ_LOAD / 1e3:g} kN"
        )
    )
    for col in ("contact", "a mm", "b mm", "δ µm", "p_max MPa", "κ = a/b"):
        table.add_column(col, justify="left" if col == "contact" else "right", no_wrap=True)
    for side in ("inner", "outer"):
        s = data[side]
        table.add_row(
            side,
            f"{s['semi_major_m'] * 1e3:.4f}",
            f"{s['semi_minor_m'] * 1e3:.4f}",
            f"{s['deflection_m'] * 1e6:.3f}",
            f"{s['max_pressure_Pa'] / 1e6:.0f}",
            f"{s['ellipticity']:.3f}",
        )
    return table, data


@flagship_section("Load distribution of the seed-000 composite bearing (flagship case)")
def _load_distribution_section(ctx: FlagshipContext):
    from bearingkit.io.export import case_dict

    data = case_dict(ctx.bearing, ctx.result, 0)
    return case_table(data), data


@app.command("run-flagship")
@one_line_errors
def run_flagship(as_json: bool = typer.Option(False, "--json", help="Print JSON instead of tables.")):
    """The flagship demonstration on seed 000 (what `make run` calls)."""
    from bearingkit.io.export import to_json

    ctx = FlagshipContext()
    out = {}
    for i, section in enumerate(FLAGSHIP_SECTIONS, 1):
        renderable, data = section.run(ctx)
        out[section.title] = data
        if not as_json:
            console.rule(f"{i}. {section.title}")
            console.print(renderable)
    if as_json:
        sys.stdout.write(to_json(out) + "\n")


def main() -> None:
    """Entry point: one-line errors for bad input, exit code 2."""
    try:
        app()
    except InputError as exc:
        sys.stderr.write("error: " + " ".join(str(exc).split()) + "\n")
        sys.exit(2)


if __name__ == "__main__":
    main()
