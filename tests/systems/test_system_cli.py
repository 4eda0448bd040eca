"""``bearingkit system``: the tables, the JSON, the report, the REXS export, and bad input as one line."""

from __future__ import annotations

import json
from pathlib import Path

from typer.testing import CliRunner

from bearingkit.cli.commands import app

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_system_json_tables_report_and_rexs(tmp_path):
    runner = CliRunner()
    out = runner.invoke(app, ["system", str(EXAMPLES / "planetary_stage.toml"), "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.output)
    case = data["cases"][0]
    forces = [m["normal_force_N"] for m in case["meshes"]]
    assert max(forces) - min(forces) < 1e-6 * max(forces)
    assert case["power"]["output_W"] < case["power"]["input_W"]
    report, rexs = tmp_path / "r.html", tmp_path / "r.rexsj"
    out = runner.invoke(
        app, ["system", str(EXAMPLES / "planetary_stage.toml"), "--report", str(report), "--rexs", str(rexs)]
    )
    assert out.exit_code == 0, out.output
    assert "stage.sun-planet1" in out.output and "efficiency" in out.output
    html = report.read_text(encoding="utf-8")
    assert 'data-section="layout"' in html and html.count('data-section="bearing"') == 10
    # the report shows the JSON's efficiency (display rounding)
    eff = case["power"]["efficiency"] * 100
    assert f"{eff:.5g}"[:5] in html
    model = json.loads(rexs.read_text(encoding="utf-8-sig"))["model"]
    assert len(model["load_spectrum"]["load_cases"]) == 2
    # planet bearings below ISO 281 Table 3 (a ~0.1 N axial load) have their ISO 281 life on every face
    planet = next(b for b in case["bearings"] if b["name"] == "stage.planet1.bearing_1")
    life = planet["summary"]["L10h_iso281_h"]
    assert life is not None and life > 0 and case["system"]["L10h_iso281_h"] < life
    note = next(n for n in data["notes"] if n.startswith("stage.planet1.bearing_1: ISO 281: "))
    assert "below ISO 281 Table 3's first row" in note
    assert f"{life:.4g}" in out.output and f"{case['system']['L10h_iso281_h']:.4g} h (ISO 281)" in out.output
    assert "below ISO 281 Table 3" in out.output.replace("\n", " ")
    html_text = html.replace("&#39;", "'").replace("&#x27;", "'")
    assert f"{life:.4g}" in html and "below ISO 281 Table 3's first row" in html_text


def test_system_lives_lead_with_iso281_on_every_face(tmp_path):
    """The drivetrain's ISO 281 system L10h comes before the ISO/TS 16281 one (CLI, JSON, report), with
    the line on why they differ."""
    runner = CliRunner()
    path = EXAMPLES / "gearbox_two_stage.toml"
    data = json.loads(runner.invoke(app, ["system", str(path), "--json"]).output)
    system = data["cases"][0]["system"]
    assert list(system)[:2] == ["L10h_iso281_h", "L10h_h"] and system["L10h_iso281_h"] > 0
    assert "ISO/TS 16281" in system["life_difference"]
    report = tmp_path / "r.html"
    out = runner.invoke(app, ["system", str(path), "--report", str(report)])
    assert out.exit_code == 0, out.output
    text = " ".join(out.output.split())
    first = text.index("system L10h:")
    assert text.index("(ISO 281)", first) < text.index("(ISO/TS 16281)", first)
    assert "why they differ:" in text
    html = report.read_text(encoding="utf-8")
    assert html.index("system L10h ISO 281 [h]") < html.index("system L10h ISO/TS 16281 [h]")
    assert "Why they differ:" in html


def test_bad_input_is_one_line_exit_2(tmp_path):
    text = (
        (EXAMPLES / "gearbox_two_stage.toml").read_text(encoding="utf-8").replace("teeth = 61", "teeth = 62")
    )
    bad = tmp_path / "bad.toml"
    bad.write_text(text, encoding="utf-8")
    out = CliRunner().invoke(app, ["system", str(bad)])
    assert out.exit_code == 2
    lines = [x for x in out.output.splitlines() if x.strip()]
    assert len(lines) == 1 and "meshes.stage_1" in lines[0] and "a_w" in lines[0]


def test_the_report_command_takes_a_drivetrain_file(tmp_path):
    out_file = tmp_path / "p.html"
    out = CliRunner().invoke(app, ["report", str(EXAMPLES / "planetary_stage.toml"), "-o", str(out_file)])
    assert out.exit_code == 0, out.output
    assert 'data-section="layout"' in out_file.read_text(encoding="utf-8")
    out = CliRunner().invoke(app, ["report", str(EXAMPLES / "planetary_stage.toml"), "--speed", "5rpm"])
    assert out.exit_code == 2 and "apply to a bearing file" in out.output


def test_output_paths_are_checked_before_any_work_and_nothing_is_half_written(tmp_path, monkeypatch):
    """The 10^4-mutant fuzz found `system` writing its report, then failing on a later output path
    (`--rexs .`, a 300-character name, `--stiffness x.html`, the same file twice): every output path is
    now checked before the drivetrain is solved, and a refusal leaves the folder empty."""
    from bearingkit.systems.drivetrain import analysis as drivetrain_analysis

    def never(*args, **kwargs):
        raise AssertionError("the drivetrain was solved before the outputs were checked")

    monkeypatch.setattr(drivetrain_analysis, "DrivetrainAnalysis", never)
    monkeypatch.chdir(tmp_path)
    runner = CliRunner()
    model = str(EXAMPLES / "planetary_stage.toml")
    bad = [
        (["--report", "o", "--rexs", "."], "--rexs ('.') must name a file"),
        (["--report", "s.csv", "--rexs", "a" * 300], "longer than 255 bytes"),
        (["--report", "o", "--stiffness", "o/report.html"], "must end in .csv or .json"),
        (["--report", "x.csv", "--stiffness", "x.csv"], "name the same file"),
    ]
    for options, fragment in bad:
        out = runner.invoke(app, ["system", model, *options])
        assert out.exit_code == 2, (options, out.output)
        assert out.stderr.count("\n") == 1 and fragment in out.stderr, out.stderr
        assert list(tmp_path.iterdir()) == [], options
    # the guard is live: good outputs reach the solve (the stand-in's error, as an internal one)
    out = runner.invoke(app, ["system", model, "--report", "r.html"])
    assert out.exit_code == 70 and "solved before the outputs were checked" in out.stderr


def test_case_keeps_the_named_load_cases_and_refuses_an_unknown_one(tmp_path):
    """``--case`` solves only the named case(s); its results equal that case in the full run; an unknown
    name is one line."""
    runner = CliRunner()
    model = str(EXAMPLES / "gearbox_two_stage.toml")
    full = json.loads(runner.invoke(app, ["system", model, "--json"]).output)
    out = runner.invoke(app, ["system", model, "--json", "--case", "peak"])
    assert out.exit_code == 0, out.output
    one = json.loads(out.output)
    assert [c["case"] for c in one["cases"]] == ["peak"] and one["duty_cycle"] is None
    peak = next(c for c in full["cases"] if c["case"] == "peak")
    for a, b in zip(one["cases"][0]["bearings"], peak["bearings"], strict=True):
        assert abs(a["summary"]["radial_load_N"] - b["summary"]["radial_load_N"]) <= 1e-9 * max(
            1.0, b["summary"]["radial_load_N"]
        )
    out = runner.invoke(app, ["system", model, "--case", "nope"])
    assert out.exit_code == 2 and "no load case 'nope'" in out.output and "'peak'" in out.output
    assert len(out.output.strip().splitlines()) == 1


def test_the_bearing_table_says_whether_a_temperature_is_given_or_found():
    """Without --heat the column shows the load case's temperature marked "given" (a bare 70 read as a
    computed temperature); the JSON says the same with temperature_found."""
    runner = CliRunner()
    args = ["system", str(EXAMPLES / "gearbox_two_stage.toml"), "--case", "rated"]
    out = runner.invoke(app, args, env={"COLUMNS": "220"})
    assert out.exit_code == 0, out.output
    rows = [line for line in out.output.splitlines() if line.startswith("│ input_A")]
    assert len(rows) == 1 and rows[0].rstrip(" │").split("│")[-2].strip().endswith("given")
    data = json.loads(runner.invoke(app, [*args, "--json"]).stdout)
    summaries = [b["summary"] for b in data["cases"][0]["bearings"]]
    assert summaries and not any(s["temperature_found"] for s in summaries)
