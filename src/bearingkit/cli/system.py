"""``bearingkit system FILE``: a drivetrain (docs/drivetrains.md) — meshes, bearings, lives, power flow.

The file is a drivetrain TOML file or a REXS model (.rexs, .rexsj, .rexs.json, .rexs.xml). Faces only:
SI values come from :meth:`bearingkit.systems.drivetrain.analysis.DrivetrainAnalysis.to_dict` and are
shown in N, MPa, h, W, rpm.
"""

from __future__ import annotations

from pathlib import Path

import typer

from bearingkit.cli.common import (
    _CASE_OPTION,
    _CONTAMINATION_OPTION,
    _JSON_OPTION,
    _ROSS_OPTION,
    _SHAFT_HEAT_OPTION,
    _fail,
    _print_json,
    check_outputs,
    console,
    one_line_errors,
    undo_outputs,
    write_ross,
)
from bearingkit.errors import one_line

RPM = 30.0 / 3.141592653589793


def case_tables(c: dict) -> list:
    """Renderables of one case: meshes, bearings, power flow, warnings."""
    from rich.table import Table

    from bearingkit.cli.shaft_tables import heat_balance_table
    from bearingkit.cli.tables import _num
    from bearingkit.systems.shaft.life import SYSTEM_LIFE_DIFFERENCE

    out = []
    meshes = Table(
        title=f"{c['case']}: meshes (held torque {c['held_torque_Nm']:.4g} N·m)", title_justify="left"
    )
    for col in (
        "mesh",
        "F_n [N]",
        "F_t on a [N]",
        "F_r on a [N]",
        "F_a on a [N]",
        "T_a [N·m]",
        "T_b [N·m]",
        "k [N/µm]",
    ):
        meshes.add_column(col, justify="right" if col != "mesh" else "left")
    for m in c["meshes"]:
        a, b = m["on_a"], m["on_b"]
        meshes.add_row(
            m["name"],
            f"{m['normal_force_N']:.1f}",
            f"{a['tangential_N']:.1f}",
            f"{a['radial_N']:.1f}",
            f"{a['axial_N']:.1f}",
            f"{a['torque_Nm']:.2f}",
            f"{b['torque_Nm']:.2f}",
            f"{m['stiffness_N_per_m'] / 1e6:.0f}",
        )
    out.append(meshes)
    bearings = Table(title=f"{c['case']}: bearings", title_justify="left")
    for col in (
        "bearing",
        "on",
        "F_r [N]",
        "F_a [N]",
        "p_max [MPa]",
        "s0",
        "L10h ISO 281 [h]",
        "L10h ISO/TS 16281 [h]",
        "P_loss [W]",
        "T [°C]",
        "warn",
    ):
        bearings.add_column(col, justify="left" if col in ("bearing", "on") else "right")
    for b in c["bearings"]:
        s = b["summary"]
        bearings.add_row(
            s["name"],
            f"{s['inner']}/{s['outer']}",
            f"{s['radial_load_N']:.1f}",
            f"{s['axial_load_N']:.1f}",
            _num(s["max_pressure_Pa"], 1e-6, ".0f"),
            _num(s["static_safety"], 1.0, ".3g"),
            _num(s["L10h_iso281_h"], 1.0, ".4g"),
            _num(s["L10h_h"], 1.0, ".4g"),
            _num(s["power_loss_W"], 1.0, ".3g"),
            # "given": the load case's temperature (no --heat), which a bare 70 read as a result
            _num(s["temperature_C"], 1.0, ".4g") + (" found" if s["temperature_found"] else " given"),
            str(s["warnings"]),
        )
    out.append(bearings)
    heat = heat_balance_table(c)
    if heat is not None:
        out.append(heat)
    life = c["system"]
    out.append(
        f"  system L10h: {_num(life['L10h_iso281_h'], 1.0, '.4g')} h (ISO 281), "
        f"{_num(life['L10h_h'], 1.0, '.4g')} h (ISO/TS 16281)"
    )
    out.append(f"  why they differ: {SYSTEM_LIFE_DIFFERENCE}")
    p = c["power"]
    if p is not None:
        speeds = ", ".join(f"{k} {v * RPM:.5g}" for k, v in p["speeds_rad_s"].items())
        out.append(f"  speeds [rpm]: {speeds}")
        meshes_loss = sum(m["loss_W"] for m in p["mesh"].values())
        out.append(
            f"  power: in {p['input_W']:.1f} W, out {_num(p['output_W'], 1.0, '.1f')} W, "
            f"losses {_num(p['loss_W'], 1.0, '.4g')} W "
            f"(bearings {_num(None if p['loss_W'] is None else p['loss_W'] - meshes_loss, 1.0, '.4g')}, "
            f"meshes {meshes_loss:.4g}), "
            f"efficiency {_num(p['efficiency'], 100.0, '.3f')} %"
        )
    for w in c["warnings"]:
        out.append(f"  warning: {w}")
    return out


def report_drivetrain(file: Path, output: Path, contamination, bearing_options, heat=False) -> bool:
    """``bearingkit report FILE`` for a drivetrain file or REXS model: write its report, True; False
    for any other file (the bearing report's)."""
    from bearingkit.errors import InputError
    from bearingkit.systems.drivetrain.input import is_drivetrain_file

    rexs = str(file).lower().endswith((".rexs", ".rexsj", ".rexs.json", ".rexs.xml"))
    if not rexs and not (Path(file).suffix.lower() == ".toml" and is_drivetrain_file(file)):
        return False
    if bearing_options:
        raise InputError(
            f"{file}: --load, --case, --speed, --temperature and --lubricant apply to a bearing file; a "
            "drivetrain file's [[load_cases]] and [lubricant] give them"
        )
    from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
    from bearingkit.systems.drivetrain.input import load_drivetrain_file

    inp = load_drivetrain_file(file)
    analysis = DrivetrainAnalysis(inp, contamination=contamination, thermal=heat or None)
    path = analysis.report(output)
    console.print(f"wrote {path}", markup=False, highlight=False)
    return True


def register(app: typer.Typer) -> None:
    """Add the ``system`` command to the CLI app."""

    @app.command()
    @one_line_errors
    def system(
        file: Path = typer.Argument(..., help="Drivetrain file (TOML, docs/drivetrains.md) or a REXS model."),
        as_json: bool = _JSON_OPTION,
        report: Path = typer.Option(
            None, "--report", help="Write the HTML report (layout, shafts, bearings, power) here."
        ),
        rexs: Path = typer.Option(
            None, "--rexs", help="Write the bearing results into a REXS JSON model here."
        ),
        stiffness: Path = typer.Option(
            None, "--stiffness", help="Write every bearing's 5x5 stiffness per case (.csv or .json) here."
        ),
        ross: Path = _ROSS_OPTION,
        case: list[str] = _CASE_OPTION,
        contamination: str = _CONTAMINATION_OPTION,
        model: str = typer.Option("components", "--friction-model", help="components | skf | palmgren."),
        heat: bool = _SHAFT_HEAT_OPTION,
    ):
        """A drivetrain: shafts joined by gear meshes and planetary stages, every bearing's lives and
        friction, the system life, the power flow; exit 1 if a case fails. With --heat (or [thermal]) each
        bearing's temperature is found by its heat balance."""
        from bearingkit.cli.tables import _num
        from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
        from bearingkit.systems.drivetrain.input import load_drivetrain_file

        check_outputs(report=report, rexs=rexs, stiffness=stiffness, ross=ross)  # before any work
        inp = load_drivetrain_file(file, cases=case)
        analysis = DrivetrainAnalysis(
            inp, friction_model=model, contamination=contamination, thermal=heat or None
        )
        data = analysis.to_dict()
        res = analysis.result
        # Files only from a solution that converged: a failed case prints its tables, writes nothing.
        written = []
        with undo_outputs([report, stiffness, rexs, ross]):  # one failing write undoes the others
            if res.converged.all() and report is not None:
                written.append(analysis.report(report))
            if res.converged.all() and stiffness is not None:
                from bearingkit.systems.drivetrain.output import stiffness_tables
                from bearingkit.systems.shaft.stiffness import write_tables

                written.append(write_tables(stiffness_tables(analysis), stiffness))
            if res.converged.all() and rexs is not None:
                from bearingkit.io.rexs.export import write_rexs_results

                written.append(write_rexs_results(data, rexs))
            if res.converged.all() and ross is not None:
                paths, ross_notes = write_ross(analysis, ross)
                written += paths
                data["notes"] += ross_notes
        if as_json:
            _print_json(file, data)
        else:
            console.print(f"{inp.drivetrain.name}  ({file})", markup=False, highlight=False)
            for c in data["cases"]:
                for part in case_tables(c):
                    console.print(part, markup=False, highlight=False) if isinstance(
                        part, str
                    ) else console.print(part)
            duty = data["duty_cycle"]
            if duty is not None:
                console.print(
                    "duty cycle (Palmgren–Miner): system L10h "
                    f"{_num(duty['system']['L10h_iso281_h'], 1.0, '.4g')} h "
                    f"(ISO 281), {_num(duty['system']['L10h_h'], 1.0, '.4g')} h (ISO/TS 16281)",
                    markup=False,
                    highlight=False,
                )
            for note in data["notes"]:
                console.print(f"  note: {note}", markup=False, highlight=False)
            for w in written:
                console.print(f"wrote {w}", markup=False, highlight=False)
        if not res.converged.all():
            bad = int(next(i for i, ok in enumerate(res.converged) if not ok))
            _fail(
                f"{file}: "
                + one_line(f"load case {analysis.case_names[bad]!r} did not converge: {res.reason[bad]}"),
                1,
            )
