"""End-to-end tests of the command line (typer CliRunner)."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from bearingkit.cli import FLAGSHIP_SECTIONS, app

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SEED = str(EXAMPLES / "seed000_composite.toml")
runner = CliRunner()


def _json(result) -> dict:
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def test_analyze_json_seed000_keys_and_si_values():
    data = _json(runner.invoke(app, ["analyze", SEED, "--case", "flagship", "--json"]))
    assert data["bearing_type"] == "composite_turntable"
    (case,) = data["cases"]
    assert case["case"] == "flagship" and case["converged"] is True
    assert set(case["displacement"]) == {"u_x_m", "u_y_m", "u_z_m", "theta_x_rad", "theta_y_rad"}
    # SI: 3 kN, −600 N·m and 5 rpm in rad/s, displacements of micrometres in metres
    assert case["load"]["F_z_N"] == pytest.approx(3000.0)
    assert case["load"]["M_y_Nm"] == pytest.approx(-600.0)
    assert case["speed_rad_s"] == pytest.approx(5 * 2 * math.pi / 60)
    assert 1e-8 < abs(case["displacement"]["u_z_m"]) < 1e-4
    names = [r["name"] for r in case["rows"]]
    assert names == ["roller_upper", "ball_upper", "roller_lower", "ball_lower", "roller_radial"]
    for row in case["rows"]:
        for key in (
            "loads_N",
            "max_load_N",
            "max_pressure_Pa",
            "loaded_count",
            "axial_load_N",
            "radial_load_N",
        ):
            assert key in row
        assert row["max_load_N"] == pytest.approx(max(row["loads_N"]))
        assert row["loaded_count"] == sum(q > 0 for q in row["loads_N"])
        assert 1e8 < row["max_pressure_Pa"] < 1e10  # Pa, not MPa
    axial = sum(r["axial_load_N"] for r in case["rows"])
    assert axial == pytest.approx(3000.0, rel=1e-8)


def test_analyze_load_options_replace_the_cases():
    data = _json(runner.invoke(app, ["analyze", SEED, "--load", "Fa=5kN", "--json"]))
    (case,) = data["cases"]
    assert case["case"] == "command line"
    assert case["load"]["F_z_N"] == pytest.approx(5000.0) and case["load"]["F_x_N"] == pytest.approx(0.0)
    # the same load from the file gives the same answer
    ref = _json(runner.invoke(app, ["analyze", SEED, "--case", "axial_5kN", "--json"]))["cases"][0]
    assert case["displacement"]["u_z_m"] == pytest.approx(ref["displacement"]["u_z_m"], rel=1e-12)


def test_analyze_ball_column_carries_the_flexible_ring_solution():
    path = str(EXAMPLES / "ball_column_condition1.toml")
    (case,) = _json(runner.invoke(app, ["analyze", path, "--json"]))["cases"]
    flex = case["flexible"]
    assert flex["converged"] is True and flex["case"] == case["case"]
    # both solutions balance the external load (pure F_x; by symmetry every row's radial force lies
    # along +x and the two ball rows' axial forces cancel); the flexible ring moves load off the rollers
    for solution in (case, flex):
        radial = sum(r["radial_load_N"] for r in solution["rows"])
        axial = sum(r["axial_load_N"] for r in solution["rows"])
        assert radial == pytest.approx(case["load"]["F_x_N"], rel=1e-6)
        assert abs(axial) <= 1e-6 * case["load"]["F_x_N"]
    rigid = {r["name"]: r for r in case["rows"]}["roller_2"]["radial_load_N"]
    flexible = {r["name"]: r for r in flex["rows"]}["roller_2"]["radial_load_N"]
    assert flexible < rigid
    assert len(flex["ring"]["bending_deflection_m"]) == len(flex["ring"]["shape_azimuth_rad"])
    table = runner.invoke(app, ["analyze", path])
    assert table.exit_code == 0 and "flexible outer ring" in table.stdout


def test_analyze_table_output():
    result = runner.invoke(app, ["analyze", str(EXAMPLES / "dgbb_6209.toml")])
    assert result.exit_code == 0, result.stderr
    assert "radial_8.9kN" in result.stdout and "balls" in result.stdout


@pytest.mark.parametrize(
    "args, fragment",
    [
        (["analyze", "missing.toml"], "missing.toml: cannot read the file"),
        (["analyze", SEED, "--load", "Fa=5"], "no unit"),
        (["analyze", SEED, "--case", "nope"], "case ('nope') not in the file"),
        (["analyze", SEED, "--load", "Fy=1kN"], "F_y (1000 N) acts on u_y"),
    ],
)
def test_bad_input_exit_2_one_line(args, fragment):
    result = runner.invoke(app, args)
    assert result.exit_code == 2
    assert result.stdout == ""
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ")
    assert fragment in lines[0]


def test_bad_file_exit_2(tmp_path):
    bad = tmp_path / "bad.toml"
    text = (EXAMPLES / "dgbb_6209.toml").read_text().replace('"12.7 mm"', '"12.7 kg"')
    bad.write_text(text)
    result = runner.invoke(app, ["analyze", str(bad), "--json"])
    assert result.exit_code == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1
    assert "geometry.element_diameter ('12.7 kg')" in result.stderr


def test_schema_prints_valid_json_schema():
    result = runner.invoke(app, ["schema"])
    assert result.exit_code == 0
    s = json.loads(result.stdout)
    assert s["$schema"].startswith("https://json-schema.org/")
    assert {"bearing", "geometry", "load_cases"} <= set(s["properties"])
    # [geometry] may be omitted when [bearing] designation names a standard bearing (docs/catalogue.md)
    assert s["required"] == ["bearing"]
    assert "designation" in s["properties"]["geometry"]["description"]


def test_run_flagship_sections_and_hertz():
    result = runner.invoke(app, ["run-flagship", "--json", "--no-report"])
    data = _json(result)
    assert list(data) == [s.title for s in FLAGSHIP_SECTIONS]
    hertz = data[FLAGSHIP_SECTIONS[0].title]
    inner, outer = hertz["inner"], hertz["outer"]
    # α = 90°: γ = D cos α / d_m = 0, so both raceways have the same curvature (Harris ch. 2).
    for key in ("semi_major_m", "semi_minor_m", "deflection_m", "max_pressure_Pa"):
        assert inner[key] == pytest.approx(outer[key], rel=1e-12)
    # Σρ = (2/D)(2 − 1/(2f)), F(ρ) = (1/(2f)) / (2 − 1/(2f)) for γ = 0.
    d, f = 0.006, 0.52
    assert inner["curvature_sum_1_m"] == pytest.approx(2 / d * (2 - 1 / (2 * f)), rel=1e-12)
    assert inner["curvature_difference"] == pytest.approx((1 / (2 * f)) / (2 - 1 / (2 * f)), rel=1e-12)
    # p_max = 3Q/(2π a b) and κ = a/b (Hertz).
    q = hertz["load_N"]
    assert inner["max_pressure_Pa"] == pytest.approx(
        3 * q / (2 * math.pi * inner["semi_major_m"] * inner["semi_minor_m"]), rel=1e-9
    )
    assert inner["ellipticity"] == pytest.approx(inner["semi_major_m"] / inner["semi_minor_m"], rel=1e-9)
    dist = data[FLAGSHIP_SECTIONS[1].title]
    assert dist["case"] == "flagship" and dist["converged"]


def test_run_flagship_tables(tmp_path):
    path = tmp_path / "report.html"
    result = runner.invoke(app, ["run-flagship", "--report", str(path)])
    assert result.exit_code == 0, result.stderr
    assert "Hertz" in result.stdout and "roller_radial" in result.stdout
    assert "viscous_roller" in result.stdout and "L10r" in result.stdout
    assert path.exists() and "bearingkit flagship" in path.read_text(encoding="utf-8")


def test_validate_still_lists_json():
    result = runner.invoke(app, ["validate", "axial/", "--json"])
    assert result.exit_code == 0
    cases = json.loads(result.stdout)
    assert cases and all(c["id"].startswith("axial/") for c in cases)
    result = runner.invoke(app, ["validate", "no-such-prefix"])
    assert result.exit_code == 2


DGBB = str(EXAMPLES / "dgbb_6209.toml")


def _strict_json(result) -> dict:
    """JSON that refuses NaN/Infinity (json.loads accepts them by default)."""
    assert result.exit_code == 0, result.stderr

    def refuse(name):
        raise AssertionError(f"non-finite {name} in the output")

    return json.loads(result.stdout, parse_constant=refuse)


def test_rating_json_keys_and_si_values():
    data = _strict_json(runner.invoke(app, ["rating", DGBB, "--speed", "1000rpm", "--json"]))
    assert data["bearing_type"] == "deep_groove_ball"
    case = data["cases"][0]
    assert case["case"] == "radial_8.9kN" and case["converged"] is True
    assert case["speed_rad_s"] == pytest.approx(1000 * 2 * math.pi / 60)
    (row,) = case["rows"]
    for key in ("C_N", "C0_N", "L10r_rev", "L10r_h", "static_safety", "max_pressure_Pa", "flags"):
        assert key in row
    assert 1e3 < row["C_N"] < 1e6 and 1e3 < row["C0_N"] < 1e6  # newtons, not kN
    system = case["system"]
    # hours = revolutions / (revolutions per hour) at 1000 r/min
    assert system["L10h_h"] == pytest.approx(system["L10r_rev"] / (1000 * 60), rel=1e-12)
    assert system["Lnmr_rev"] is None  # no a_ISO without lubrication inputs


def test_rating_reliability_and_life_modification():
    args = ["rating", DGBB, "--case", "radial_8.9kN", "--speed", "1000rpm", "--json"]
    base = _strict_json(runner.invoke(app, args))["cases"][0]
    more = [*args, "--reliability", "0.95", "--contamination", "0.5", "--temperature", "60degC"]
    more += ["--lubricant", "ISO_VG68"]
    case = _strict_json(runner.invoke(app, more))["cases"][0]
    assert case["a1"] == pytest.approx(0.64)  # ISO 281:2007 Table 12, 95 %
    assert case["system"]["Lnr_rev"] == pytest.approx(0.64 * base["system"]["L10r_rev"], rel=1e-12)
    assert case["system"]["Lnmr_rev"] is not None and case["rows"][0]["a_ISO"] > 0


def test_rating_table_output():
    result = runner.invoke(app, ["rating", SEED, "--case", "flagship"])
    assert result.exit_code == 0, result.stderr
    assert "ball_upper" in result.stdout and "L10r" in result.stdout and "s0" in result.stdout


def test_friction_json_keys_and_invariants():
    data = _strict_json(
        runner.invoke(app, ["friction", SEED, "--case", "flagship", "--speed", "5rpm", "--json"])
    )
    case = data["cases"][0]
    assert case["speed_inner_rad_s"] == pytest.approx(5 * 2 * math.pi / 60)
    assert case["lubricant"] == "seed000_grease_assumed"  # the file's [lubricant]
    f = case["friction"]
    assert set(f) >= {"total_Nm", "components_Nm", "rows_Nm", "torque_inner_Nm", "torque_outer_Nm"}
    assert sum(f["components_Nm"].values()) == pytest.approx(f["total_Nm"], rel=1e-12)
    assert sum(f["rows_Nm"].values()) == pytest.approx(f["total_Nm"], rel=1e-12)
    # inner ring turning: the friction torque on it opposes the motion, the outer ring's balances it
    assert f["torque_inner_Nm"] == pytest.approx(-f["total_Nm"]) and f["torque_outer_Nm"] == pytest.approx(
        f["total_Nm"]
    )
    assert 1e-3 < f["total_Nm"] < 1e2  # N·m, not N·mm


def test_friction_options_speed_temperature_rotating():
    base = ["friction", SEED, "--load", "Fa=5kN", "--lubricant", "ISO_VG100", "--json"]
    slow = _strict_json(runner.invoke(app, [*base, "--speed", "5rpm", "--temperature", "40degC"]))["cases"][0]
    fast = _strict_json(runner.invoke(app, [*base, "--speed", "60rpm", "--temperature", "40degC"]))["cases"][
        0
    ]
    outer = _strict_json(
        runner.invoke(app, [*base, "--speed", "5rpm", "--temperature", "40degC", "--rotating", "outer"])
    )["cases"][0]
    assert slow["temperature_C"] == pytest.approx(40.0) and slow["lubricant"] == "ISO_VG100"
    # viscous rolling losses grow with speed (Tian et al. 2025 §5.3.2: torque rises with speed)
    assert fast["friction"]["total_Nm"] > slow["friction"]["total_Nm"]
    assert (
        outer["speed_outer_rad_s"] == pytest.approx(5 * 2 * math.pi / 60) and outer["speed_inner_rad_s"] == 0
    )
    assert outer["friction"]["torque_inner_Nm"] > 0 > slow["friction"]["torque_inner_Nm"]


@pytest.mark.parametrize(
    "args, fragment",
    [
        (["friction", DGBB, "--speed", "5rpm"], "dgbb_6209.toml: lubricant: none given"),
        (["friction", DGBB, "--lubricant", "ISO_VG68"], "has no speed"),
        (["friction", DGBB, "--speed", "5kN", "--lubricant", "ISO_VG68"], "--speed ('5kN')"),
        (["friction", DGBB, "--speed", "5rpm", "--lubricant", "nope"], "lubricant ('nope')"),
        (["friction", SEED, "--speed", "5rpm", "--rotating", "both"], "--rotating ('both')"),
        (["rating", DGBB, "--reliability", "2"], "reliability"),
        (["rating", DGBB, "--rotating", "middle"], "rotating ('middle')"),
        (["rating", DGBB, "--contamination", "0.5"], "lubricant: none given"),
        (["rating", DGBB, "--load-rating", "foo=3kN"], "['foo'] not in the bearing"),
        (["rating", DGBB, "--load-rating", "balls"], "--load-rating ('balls')"),
        (
            ["friction", str(EXAMPLES / "trb_32008.toml"), "--speed", "5rpm", "--model", "trb2"],
            "--model ('trb2')",
        ),
        (["rating", str(EXAMPLES / "trb_32008.toml"), "--load", "Fa=-1kN"], "must be positive"),
    ],
)
def test_rating_friction_bad_input_exit_2_one_line(args, fragment):
    result = runner.invoke(app, args)
    assert result.exit_code == 2, (result.stdout, result.stderr)
    assert result.stdout == ""
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), lines
    assert fragment in lines[0]


@pytest.mark.parametrize(
    "model, parts", [("skf", {"rolling", "sliding", "seal", "drag"}), ("palmgren", {"viscous", "load"})]
)
def test_friction_engineering_models(model, parts):
    args = ["friction", DGBB, "--speed", "1000rpm", "--lubricant", "ISO_VG68", "--model", model, "--json"]
    data = _strict_json(runner.invoke(app, args))
    for case in data["cases"]:
        f = case["friction"]
        assert f["model"] == model and set(f["components_Nm"]) == parts
        assert sum(f["components_Nm"].values()) == pytest.approx(f["total_Nm"], rel=1e-12)
    # the load-dependent part grows with the load: 8.9 kN above 4 kN
    totals = [c["friction"]["total_Nm"] for c in data["cases"]]
    assert totals[0] > totals[1] > 0


def test_friction_engineering_model_refuses_composite_bearing():
    result = runner.invoke(app, ["friction", SEED, "--model", "skf"])
    assert result.exit_code == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and "single-row standard bearing" in result.stderr


def test_report_command_writes_a_self_contained_page(tmp_path):
    from typer.testing import CliRunner

    from bearingkit.cli import app

    out = tmp_path / "r" / "report.html"
    res = CliRunner().invoke(app, ["report", "examples/crb_nu209.toml", "-o", str(out)])
    assert res.exit_code == 0, res.output
    html = out.read_text()
    assert "data:image/svg+xml;base64" in html and "<script" not in html


def test_study_command_runs_the_seed000_statics_l9(tmp_path):
    import pandas as pd
    from typer.testing import CliRunner

    from bearingkit.cli import app

    res = CliRunner().invoke(
        app, ["study", "examples/studies/seed000_l9_statics.toml", "--out", str(tmp_path)]
    )
    assert res.exit_code == 0, res.output
    results = pd.read_parquet(tmp_path / "results.parquet")
    assert len(results) == 9 and results.filter(like="share").notna().all().all()


def test_reaction_at_the_default_fixed_tilt_is_marked_and_free_dofs_say_so():
    """A single-row bearing under Fr + Fa is solved with its tilt fixed: the moment in the case line is
    the reaction holding it (marked), not a load the user applied, and the JSON lists the DOFs used."""
    args = ["analyze", "6205", "--load", "Fx=5kN", "--load", "Fz=1kN"]
    data = _json(runner.invoke(app, [*args, "--json"]))
    assert data["free_dofs"] == ["u_x", "u_y", "u_z"]
    reaction = data["cases"][0]["load"]["M_y_Nm"]
    assert abs(reaction) > 1.0  # the ball set's axial force acts off-centre: a moment holds the tilt
    text = runner.invoke(app, args, terminal_width=200).stdout
    line = next(s for s in text.splitlines() if "case 'command line'" in s)
    assert f"M = (0, {reaction:.6g}*) N·m" in line and "F = (5000, 0, 1000) N" in line
    assert "* reaction holding a fixed DOF" in text
    free = _json(runner.invoke(app, [*args, "--load", "My=0.1Nm", "--json"]))  # a moment frees the tilt
    assert free["free_dofs"] == ["u_x", "u_y", "u_z", "theta_x", "theta_y"]


def test_uncarriable_loads_say_what_to_do():
    """Too little axial load for a single tapered row, and a load on a DOF no row carries: the one-line
    message names the remedy, not only the failure."""
    r = runner.invoke(app, ["analyze", "32210", "--load", "Fx=5kN", "--load", "Fz=1kN"])
    assert r.exit_code == 1
    assert "unbalanced mainly in F_z" in r.stderr and "DB/DF pair" in r.stderr
    assert "F_r tan(alpha)" in r.stderr
    r = runner.invoke(app, ["analyze", "NU210", "--load", "Fz=1kN"])
    assert r.exit_code == 2
    assert "remove the load" in r.stderr and len(r.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("command", ["analyze", "rating", "friction"])
def test_a_shaft_file_given_to_a_bearing_command_names_the_shaft_command(command):
    path = str(EXAMPLES / "shaft_countershaft.toml")
    r = runner.invoke(app, [command, path])
    assert r.exit_code == 2
    assert "this is a shaft file" in r.stderr and f"bearingkit shaft {path}" in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1


def test_an_absurd_load_on_a_self_aligning_bearing_fails_in_one_line(tmp_path):
    """1e9 N on a 1209 emptied the cone check's active set (a numpy traceback; fuzz seed 2031)."""
    text = (EXAMPLES / "sabb_1209.toml").read_text(encoding="utf-8")
    path = tmp_path / "absurd.toml"
    path.write_text(re.sub(r"(?m)^F_x = .*$", 'F_x = "1e9 N"', text, count=1), encoding="utf-8")
    r = runner.invoke(app, ["analyze", str(path), "--json"])
    assert r.exception is None or isinstance(r.exception, SystemExit)
    assert r.exit_code == 1 and len(r.stderr.strip().splitlines()) == 1
    assert "did not converge" in r.stderr
