"""End-to-end tests of the command line (typer CliRunner)."""

from __future__ import annotations

import json
import math
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
    assert s["required"] == ["bearing", "geometry"]


def test_run_flagship_sections_and_hertz():
    result = runner.invoke(app, ["run-flagship", "--json"])
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


def test_run_flagship_tables():
    result = runner.invoke(app, ["run-flagship"])
    assert result.exit_code == 0, result.stderr
    assert "Hertz" in result.stdout and "roller_radial" in result.stdout


def test_validate_still_lists_json():
    result = runner.invoke(app, ["validate", "axial/", "--json"])
    assert result.exit_code == 0
    cases = json.loads(result.stdout)
    assert cases and all(c["id"].startswith("axial/") for c in cases)
    result = runner.invoke(app, ["validate", "no-such-prefix"])
    assert result.exit_code == 2
