"""The ``bearingkit`` commands. Faces only: parse, call :func:`bearingkit.pipeline.analyze`, print.

SI inside; units only in the input file and in option values (``--load Fa=5kN``, ``--speed 3000rpm``).
Every command that reads a bearing builds ONE :class:`~bearingkit.pipeline.Analysis` and prints the
parts it is about, with every warning the analysis carries. Bad input: one line ``error: …`` on
stderr, exit 2; a case that does not converge: its tables, then ``error: …``, exit 1.
Adding a command is one decorated function (``@app.command()``); the options, consoles and helpers the
commands share are in :mod:`bearingkit.cli.common`.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import typer

from bearingkit.cli.common import (
    _CASE_OPTION,
    _CONTAMINATION_OPTION,
    _FILE_ARGUMENT,
    _FREE_OPTION,
    _HEAT_OPTION,
    _HOLD_OPTION,
    _JSON_OPTION,
    _LOAD_OPTION,
    _LUBRICANT_FILE_OPTION,
    _LUBRICANT_OPTION,
    _PRELOAD_OPTION,
    _ROSS_OPTION,
    _ROTATING_OPTION,
    _SHAFT_HEAT_OPTION,
    _SPEED_OPTION,
    _TEMPERATURE_OPTION,
    OneLineGroup,
    _analysis,
    _fail,
    _fail_unconverged,
    _header,
    _load_ratings,
    _print_json,
    check_outputs,
    console,
    notes_on_stderr,
    one_line_errors,
    undo_outputs,
    write_ross,
)
from bearingkit.cli.flagship import FLAGSHIP_REPORT
from bearingkit.cli.system import register as _register_system
from bearingkit.errors import InputError, error_line, quote

app = typer.Typer(
    add_completion=False, no_args_is_help=True, help="Rolling-bearing mechanics.", cls=OneLineGroup
)


@app.command()
@one_line_errors
def validate(
    prefixes: list[str] = typer.Argument(None, help="Only cases whose id starts with one of these."),
    as_json: bool = typer.Option(False, "--json", help="Print a JSON list of the cases (with their role)."),
    table: bool = typer.Option(False, "--table", help="Print the row table of the cases, then the summary."),
    everything: bool = typer.Option(
        False, "--all", help="Include the diagnostic cases (derived values, duplicates, alternative models)."
    ),
    quick: bool = typer.Option(
        False, "--quick", help="Only the first case of every source (paper, standard): a few seconds."
    ),
):
    """Recompute the published numbers bearingkit reproduces; print per paper predictions passing / total,
    calibrations and deviations; exit 1 on an unexplained failure."""
    from bearingkit.cli.validate_tables import case_table, not_computable_table, summary_table
    from bearingkit.validation.registry import (
        all_cases,
        failures,
        not_computable,
        quick_cases,
        run_cases,
        summarize,
    )

    cases = all_cases(prefixes or (), diagnostics=everything)
    if quick:
        cases = quick_cases(cases)
    if not cases:
        raise InputError(f"no validation case matches {quote(list(prefixes or ()))}")
    results = run_cases(cases)
    if as_json:
        sys.stdout.write(json.dumps([r.to_dict() for r in results], indent=1) + "\n")
    else:
        if table:
            console.print(case_table(results))
            missing = not_computable(prefixes or ())
            if everything and missing:
                console.print(not_computable_table(missing))
        console.print(summary_table(summarize(results, prefixes or ()), everything))
    if failures(results):
        raise typer.Exit(1)


@app.command()
@one_line_errors
def analyze(
    file: Path = _FILE_ARGUMENT,
    load: list[str] = _LOAD_OPTION,
    case: list[str] = _CASE_OPTION,
    speed: str = _SPEED_OPTION,
    preload: str = _PRELOAD_OPTION,
    hold: list[str] = _HOLD_OPTION,
    free: list[str] = _FREE_OPTION,
    as_json: bool = _JSON_OPTION,
    subsurface: bool = typer.Option(
        False,
        "--subsurface",
        help="Stresses below the most loaded contact of every row (von Mises, Tresca, orthogonal shear vs "
        "depth) and the check of the raceways' hardened layer (docs/subsurface.md).",
    ),
    traction: float = typer.Option(
        0.0, "--traction", help="Surface traction coefficient q/p for --subsurface (default 0: frictionless)."
    ),
):
    """Quasi-static load distribution of every load case with its warnings; exit 1 if one diverges."""
    a = _analysis(file, load, case, hold, free, preload=preload, speed=speed)
    if traction != 0.0 and not subsurface:
        raise InputError(f"--traction ({traction:g}) applies to --subsurface; add --subsurface")
    sub = a.subsurface_by(traction=traction) if subsurface else None
    data = a.statics_dict(subsurface=sub)
    if as_json:
        _print_json(file, data)
    else:
        from bearingkit.cli.operating_tables import limits_text, operating_text
        from bearingkit.cli.tables import case_table, warnings_text

        _header(a, file)

        for c in data["cases"]:
            console.print(case_table(c, data["free_dofs"]))
            console.print(operating_text(c))
            console.print(limits_text(c))
            if sub is not None:
                from bearingkit.cli.subsurface_tables import subsurface_table

                console.print(subsurface_table(c, data["subsurface"]))
            if "flexible" in c and "rigid_vs_flexible" in c["flexible"]:  # a [structure]
                from bearingkit.cli.tables import structure_table

                console.print(structure_table(c["flexible"]))
            elif "flexible" in c:
                how = c["flexible"]["coupling"]
                console.print(f"flexible outer ring ({how['method']}, {how['iterations']} iterations):")
                console.print(case_table(c["flexible"], data["free_dofs"]))
            console.print(warnings_text(c["warnings"]))
        console.print(warnings_text([], data["notes"]))
    _fail_unconverged(file, a)


@app.command()
def schema():
    """Print the JSON Schema of the input file."""
    from bearingkit.io import loader  # noqa: F401 - registers every bearing type (bearingkit.io.build.kinds)
    from bearingkit.io.optional_sections.cycle import json_schema  # with [[duty_cycle]], [[tolerances]]

    sys.stdout.write(json.dumps(json_schema(), indent=1) + "\n")


@app.command()
@one_line_errors
def rating(
    file: Path = _FILE_ARGUMENT,
    load: list[str] = _LOAD_OPTION,
    case: list[str] = _CASE_OPTION,
    speed: str = _SPEED_OPTION,
    reliability: str = typer.Option("0.9", "--reliability", help="Reliability of L_nr, 0.9 … 0.9995."),
    rotating: str = _ROTATING_OPTION,
    lubricant: str = _LUBRICANT_OPTION,
    lubricant_file: Path = _LUBRICANT_FILE_OPTION,
    temperature: str = _TEMPERATURE_OPTION,
    heat: bool = _HEAT_OPTION,
    contamination: str = _CONTAMINATION_OPTION,
    load_rating: list[str] = typer.Option(
        None, "--load-rating", help="ROW=C replacing the ISO 281 rating of a row, e.g. roller_upper=50kN."
    ),
    preload: str = _PRELOAD_OPTION,
    hold: list[str] = _HOLD_OPTION,
    free: list[str] = _FREE_OPTION,
    as_json: bool = _JSON_OPTION,
):
    """ISO 76 / ISO 281 / ISO/TS 16281 ratings, lives and static safety of every row and the bearing.

    With --heat (or a [thermal] section) the operating temperature is found by the heat balance and
    κ, a_ISO, the lives and the friction are those at it."""
    a = _analysis(
        file,
        load,
        case,
        hold,
        free,
        preload=preload,
        speed=speed,
        temperature=temperature,
        rotating=rotating,
        lubricant=lubricant,
        lubricant_file=lubricant_file,
        heat=heat,
        contamination=contamination,
        reliability=reliability,
        load_ratings=_load_ratings(load_rating),
        duty_cycle_alone=True,
    )
    if a.operating.contamination is not None and a.operating.lubricant is None:
        raise InputError(
            f'{file}: lubricant: none given; add [lubricant] name = "ISO_VG100" (a preset of '
            "bearingkit.lubricants.LUBRICANTS) to the file or use --lubricant"
        )
    if a.operating.contamination is not None and not a.operating.temperature_given.all():
        raise InputError(
            f"{file}: --contamination needs a temperature: give --temperature 60degC (or --heat to find it)"
        )
    data = a.rating_dict()
    if as_json:
        _print_json(file, data)
    else:
        from bearingkit.cli.operating_tables import limits_text, lubrication_table, thermal_text
        from bearingkit.cli.tables import duty_cycle_table, rating_table, warnings_text

        _header(a, file)

        for c in data["cases"]:
            if "thermal" in c:
                console.print(thermal_text(c["thermal"]))
            console.print(rating_table(c))
            console.print(lubrication_table(c))
            if "friction" in c:
                f = c["friction"]
                console.print(
                    f"  friction at the found temperature ({f['model']}: {f['model_why']}): "
                    f"M = {f['torque_Nm']:.4g} N·m, P = {f['power_loss_W']:.4g} W",
                    markup=False,
                    highlight=False,
                )
            console.print(limits_text(c))
            console.print(warnings_text(c["warnings"]))
        console.print(warnings_text([], data["notes"]))
        if "duty_cycle" in data:
            cycle = data["duty_cycle"]
            console.print(duty_cycle_table(cycle))
            for b in cycle["bins"]:
                console.print(warnings_text([f"{b['bin']}: {w}" for w in b["warnings"]]))
            console.print(warnings_text([], cycle["notes"]))
    if a.n_cases:
        _fail_unconverged(file, a)


#: Friction models of ``friction --model`` (:data:`bearingkit.pipeline.FRICTION_MODELS`).
FRICTION_MODELS = ("auto", "components", "skf", "palmgren")


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
    temperature: str = _TEMPERATURE_OPTION,
    lubricant: str = _LUBRICANT_OPTION,
    lubricant_file: Path = _LUBRICANT_FILE_OPTION,
    model: str = typer.Option(
        "auto",
        "--model",
        help="auto (default: skf for standard bearings, per bearing for DB/DF/DT sets, slewing for slewing "
        "rings, components for the seed composites; the output says which and why) | components (physics, "
        "per contact) | skf | palmgren (standard and self-aligning bearings) | trb (tapered rows) | slewing "
        "(slewing rings).",
    ),
    compare: bool = typer.Option(
        False, "--compare", help="Every model that applies side by side, with when each applies."
    ),
    heat: bool = typer.Option(
        False,
        "--heat",
        help="Find the operating temperature by the heat balance (friction heat = heat carried away), give "
        "the friction at it, with the thermal reference speed (ISO 15312 method).",
    ),
    preload: str = _PRELOAD_OPTION,
    as_json: bool = _JSON_OPTION,
):
    """Friction torque and power loss of every load case, broken down by component and by row."""
    from bearingkit.pipeline import FRICTION_MODELS as MODELS

    if model not in MODELS:
        raise InputError(f"--model ({model!r}) must be one of {', '.join(MODELS)}")
    a = _analysis(
        file,
        load,
        case,
        speed=speed,
        temperature=temperature,
        rotating=rotating,
        lubricant=lubricant,
        lubricant_file=lubricant_file,
        heat=heat,
        friction_model=model,
        preload=preload,
    )
    if not (a.operating.speed != 0).any() and speed is None:
        raise InputError(
            f"{file}: every load case has no speed; give --speed 3000rpm or speed in the [[load_cases]]"
        )
    from bearingkit.pipeline.friction.choice import AUTO, choose
    from bearingkit.pipeline.friction.paired import is_set

    used = choose(a)[0] if model == AUTO else model
    if used == "components" or (used in ("skf", "palmgren") and is_set(a)):  # loads from the solve
        _fail_unconverged(file, a)
    from bearingkit.cli.operating_tables import comparison_text, heat_text, thermal_text
    from bearingkit.cli.tables import friction_table, warnings_text

    if compare:
        data = a.friction_comparison()
        if heat:
            data["heat"] = a.heat_dict(model)
        if as_json:
            _print_json(file, data)
            return
        _header(a, file)
        console.print(comparison_text(data))
        if heat:
            console.print(heat_text(data["heat"]))
        return
    data = a.friction_dict(model)
    if heat:
        data["heat"] = a.heat_dict(model)
    if as_json:
        _print_json(file, data)
    else:
        _header(a, file)
        console.print(
            f"friction model: {data['friction_model']} ({data['friction_model_why']})", markup=False
        )
        for c in data["cases"]:
            if "thermal" in c:
                console.print(thermal_text(c["thermal"]))
            console.print(friction_table(c))
            console.print(warnings_text(c["warnings"]))
        if heat:
            console.print(heat_text(data["heat"]))
        console.print(warnings_text([], data["notes"]))


@app.command("run-flagship")
@one_line_errors
def run_flagship(
    as_json: bool = typer.Option(False, "--json", help="Print JSON instead of tables."),
    report: Path = typer.Option(FLAGSHIP_REPORT, "--report", help="HTML report written at the end."),
    no_report: bool = typer.Option(False, "--no-report", help="Do not write the HTML report."),
):
    """The flagship demonstration on seed 000 (what `make run` calls)."""
    from bearingkit.cli.flagship import run_sections

    run_sections(console, as_json=as_json, report_path=None if no_report else report)


@app.command()
@one_line_errors
def study(
    file: Path = typer.Argument(..., help="Study file (TOML), see examples/studies/; or a bearing file."),
    list_outputs: bool = typer.Option(
        False, "--list-outputs", help="List the outputs of FILE's bearing (generic evaluator) with units."
    ),
    list_factors: bool = typer.Option(
        False, "--list-factors", help="List the factor paths of FILE's bearing with units and values."
    ),
    scheduler: str = typer.Option(None, "--scheduler", help="Dask scheduler address, e.g. tcp://host:8786."),
    workers: int = typer.Option(None, "--workers", help="Local worker processes (> 1: process pool)."),
    resume: bool = typer.Option(False, "--resume", help="Reuse the finished chunks in --out."),
    out: Path = typer.Option(None, "--out", help="Output folder (default: study-<study name>)."),
    allow_plugin: list[str] = typer.Option(
        [], "--allow-plugin", help="Evaluator plugin module:attr the study may use (files cannot import)."
    ),
    allow_path: list[Path] = typer.Option(
        [],
        "--allow-path",
        help="A folder the study's bearing file may lie in, beyond the study's folder and the one above it.",
    ),
):
    """Run a design study (sweep, orthogonal array, Monte Carlo, optimisation); results stream to Parquet."""
    from bearingkit.extras import check

    check("studies", "bearingkit study")
    from bearingkit.studies.__main__ import FACTOR_COLUMNS, print_table, run_cli
    from bearingkit.studies.__main__ import list_factors as factors_of
    from bearingkit.studies.__main__ import list_outputs as outputs_of

    if list_outputs or list_factors:
        if list_outputs:
            print_table(outputs_of(file, allow_path), ("output", "unit", "meaning"), echo=typer.echo)
        if list_factors:
            print_table(factors_of(file, allow_path), FACTOR_COLUMNS, echo=typer.echo)
        return

    run_cli(
        file,
        scheduler=scheduler,
        workers=workers,
        resume=resume,
        out=out,
        echo=console.print,
        allow_plugins=allow_plugin,
        allowed_paths=allow_path,
    )


@app.command()
@one_line_errors
def report(
    file: Path = _FILE_ARGUMENT,
    output: Path = typer.Option(Path("out/report.html"), "-o", "--output", help="HTML file to write."),
    load: list[str] = _LOAD_OPTION,
    case: list[str] = _CASE_OPTION,
    speed: str = _SPEED_OPTION,
    temperature: str = _TEMPERATURE_OPTION,
    lubricant: str = _LUBRICANT_OPTION,
    lubricant_file: Path = _LUBRICANT_FILE_OPTION,
    heat: bool = _HEAT_OPTION,
    contamination: str = _CONTAMINATION_OPTION,
):
    """Write a self-contained HTML report: inputs, load distributions, friction, ratings, warnings.

    A shaft file (docs/systems.md) gets the shaft report (as ``bearingkit shaft FILE --report``), a
    drivetrain file or REXS model (docs/drivetrains.md) the drivetrain report."""
    from bearingkit.cli.shaft_tables import is_shaft_file

    if is_shaft_file(file):
        given = [f for f, v in (("--load", load), ("--case", case), ("--speed", speed)) if v]
        given += [f for f, v in (("--temperature", temperature), ("--lubricant", lubricant)) if v]
        given += [f for f, v in (("--lubricant-file", lubricant_file),) if v]
        if given:
            raise InputError(
                f"{file}: {', '.join(given)} apply to a bearing file; a shaft file's [[load_cases]] and "
                "[lubricant] give them"
            )
        from bearingkit.systems.shaft.input import load_shaft_file
        from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis

        inp = load_shaft_file(file)
        inp.check_work(report=True)  # before anything is solved
        path = ShaftAnalysis(inp, contamination=contamination, thermal=heat or None).report(output)
        console.print(f"wrote {path}")
        return
    from bearingkit.cli.system import report_drivetrain

    bearing_options = load or case or speed or temperature or lubricant
    if report_drivetrain(file, output, contamination, bearing_options, heat):
        return
    a = _analysis(
        file,
        load,
        case,
        speed=speed,
        temperature=temperature,
        lubricant=lubricant,
        lubricant_file=lubricant_file,
        heat=heat,
        contamination=contamination,
    )
    path = a.report(output)
    console.print(f"wrote {path}")


@app.command()
@one_line_errors
def shaft(
    file: Path = typer.Argument(..., help="Shaft file (TOML with units), see docs/systems.md."),
    as_json: bool = _JSON_OPTION,
    report: Path = typer.Option(
        None, "--report", help="Write the HTML report (shaft lines, every bearing, system life) here."
    ),
    plot: Path = typer.Option(None, "--plot", help="Write deflection and moment lines (PNG) per case here."),
    stiffness: Path = typer.Option(
        None, "--stiffness", help="Write every bearing's 5x5 stiffness per case to this .csv or .json."
    ),
    ross: Path = _ROSS_OPTION,
    contamination: str = _CONTAMINATION_OPTION,
    model: str = typer.Option(
        "auto",
        "--friction-model",
        help="Friction model of every bearing: auto (the model of each bearing's kind) | components | skf | "
        "palmgren.",
    ),
    heat: bool = _SHAFT_HEAT_OPTION,
):
    """A shaft on several bearings: reactions, seat tilts, shaft lines, every bearing's pressures, lives and
    friction, system life; exit 1 if a case fails. With --heat (or [thermal]) each bearing's temperature
    is found by its heat balance."""
    from bearingkit.cli.shaft_tables import shaft_case_tables
    from bearingkit.systems.shaft.input import load_shaft_file
    from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis
    from bearingkit.systems.shaft.stiffness import shaft_stiffness_table, write_tables

    check_outputs(report=report, stiffness=stiffness, plot=plot, ross=ross)  # refused before any work
    inp = load_shaft_file(file)
    inp.check_work(report=report is not None or plot is not None)  # before anything is solved
    analysis = ShaftAnalysis(inp, friction_model=model, contamination=contamination, thermal=heat or None)
    result = analysis.result
    data = analysis.to_dict()
    # Files only from a solution that converged: a failed case prints its tables, writes nothing.
    converged = bool(result.converged.all())
    names = result.loads.names
    figures = [plot.with_name(f"{plot.stem}_{n}{plot.suffix or '.png'}") for n in names] if plot else []
    with undo_outputs([stiffness, *figures, ross, report]):  # one failing write undoes the others
        if converged and stiffness is not None:
            write_tables([shaft_stiffness_table(result, b.name) for b in inp.system.bearings], stiffness)
        if converged and plot is not None:
            from bearingkit.report.systems.shaft_plots import write_shaft_figure

            for c, figure in enumerate(figures):
                write_shaft_figure(result, figure, c)
        rotors = write_ross(result, ross) if converged and ross is not None else ([], [])
        data["notes"] += rotors[1]
        if converged and report is not None:
            written = analysis.report(report)
    if as_json:
        _print_json(file, data)
    else:
        console.print(f"{inp.system.name}  ({file})", markup=False, highlight=False)
        for c in data["cases"]:
            for part in shaft_case_tables(c):
                console.print(part)
        for note in data["notes"]:
            console.print(f"  note: {note}", markup=False, highlight=False)
        for path in ([written] if converged and report is not None else []) + rotors[0]:
            console.print(f"wrote {path}", markup=False, highlight=False)
    if not converged:
        bad = int(next(i for i, ok in enumerate(result.converged) if not ok))
        what = f"load case {result.loads.names[bad]!r} did not converge: {result.reason[bad]}"
        _fail(what, 1, source=file)


@app.command()
@one_line_errors
def serve(
    port: int = typer.Option(8765, "--port", help="Port to listen on."),
    open_browser: bool = typer.Option(False, "--open", help="Open the page in the default browser."),
    host: str = typer.Option(
        "127.0.0.1", "--host", help="Address to bind; anything but loopback exposes the app (no login)."
    ),
):
    """Local web app (http://127.0.0.1:8765/): a bearing, the catalogue and comparisons, shafts, drivetrains,
    studies and duty cycles in the browser."""
    from bearingkit.extras import check

    check("app", "bearingkit serve")
    from bearingkit.app import serve as run_server

    run_server(host=host, port=port, open_browser=open_browser, echo=console.print)


@app.command("compile")
@one_line_errors
def compile_core(
    quiet: bool = typer.Option(False, "--quiet", help="Print nothing (the background build runs this)."),
    wait: float = typer.Option(600.0, "--wait", help="Seconds to wait for a build already running."),
):
    """Build the compiled solver core once (about a minute); large jobs load it from then on.

    Until then small jobs run on the numpy core (`make run` and `make test` build it first)."""
    import time

    from bearingkit.bearings.warmup import BUSY, build
    from bearingkit.rows.numba_cache import cache_dir

    t0 = time.perf_counter()
    if not quiet:
        console.print(f"compiled solver core: {cache_dir()}", markup=False, highlight=False)
    done = build(wait=wait, echo=None if quiet else lambda line: console.print(line, highlight=False))
    if not quiet:
        console.print(f"compiled solver core {done} ({time.perf_counter() - t0:.1f} s)", highlight=False)
    if done == "busy":  # not bad input (exit 2): the core exists soon, the command may be run again
        sys.stderr.write(error_line(BUSY) + "\n")
        raise typer.Exit(1)


# ``bearingkit system``: drivetrains (its own module, docs/drivetrains.md)
_register_system(app)


def main() -> None:
    """Entry point: one-line errors for bad input, exit code 2; the solver's notes on stderr."""
    notes_on_stderr()
    try:
        app()
    except InputError as exc:
        sys.stderr.write(error_line(exc) + "\n")
        sys.exit(2)
