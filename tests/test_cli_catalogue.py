"""Command line with designations instead of files, and ``bearingkit catalogue``."""

from __future__ import annotations

import json

from typer.testing import CliRunner

from bearingkit.cli import app

runner = CliRunner()


def test_analyze_designation_prints_estimated_geometry():
    result = runner.invoke(app, ["analyze", "6205", "--load", "Fr=2kN"])
    assert result.exit_code == 0, result.output
    assert "6205" in result.output and "ESTIMATED" in result.output
    assert "converged" in result.output


def test_analyze_designation_json_has_source_and_balance():
    result = runner.invoke(
        app, ["analyze", "6205-2RS C3", "--load", "Fr=2kN", "--load", "Fa=0.5kN", "--json"]
    )
    data = json.loads(result.stdout)
    assert data["bearing_type"] == "deep_groove_ball" and "ESTIMATED" in data["source"]
    case = data["cases"][0]
    assert case["converged"]
    # equilibrium: the row carries the applied axial and radial load
    row = case["rows"][0]
    assert abs(row["axial_load_N"] - 500.0) < 1e-6 * 500 and abs(row["radial_load_N"] - 2000.0) < 1e-6 * 2000


def test_rating_angular_contact_designation():
    result = runner.invoke(app, ["rating", "7206B", "--load", "Fa=3kN", "--speed", "1000rpm", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    row = data["cases"][0]["rows"][0]
    assert row["C_N"] > 0 and row["L10r_h"] > 0


def test_bad_designation_one_line_error_nothing_on_stdout():
    for text in ("6z05", "6205-C7", "6299"):
        result = runner.invoke(app, ["analyze", text, "--load", "Fr=1kN"])
        assert result.exit_code == 2
        assert result.stdout == ""
        lines = result.stderr.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith(f"error: {text}:")


def test_catalogue_lists_pattern_with_ratings():
    result = runner.invoke(app, ["catalogue", "620*", "--json"])
    rows = json.loads(result.stdout)
    names = [r["designation"] for r in rows]
    assert names[:2] == ["6200", "6201"] and "6205" in names and all(n.startswith("620") for n in names)
    row = next(r for r in rows if r["designation"] == "6205")
    assert row["d_m"] == 0.025 and row["C_catalogue_N"] == 14000.0 and row["C_estimate_N"] > 0


def test_catalogue_pattern_without_match():
    result = runner.invoke(app, ["catalogue", "9999*"])
    assert result.exit_code == 2 and "no designation matches pattern '9999*'" in result.stderr


def test_bounds_without_match_name_what_was_typed():
    """The issue's own search (6208 C = 29.1 kN; 6308 has D = 90 mm): the message names the bounds given,
    not the pattern '*' the user never typed."""
    args = ["catalogue", "--d", "40", "--D-max", "80", "--kind", "deep_groove", "--C-min", "30kN"]
    result = runner.invoke(app, args)
    assert result.exit_code == 2
    line = result.stderr.strip()
    assert line == (
        "error: catalogue: no designation matches --kind deep_groove, --d 40, --D-max 80, --C-min 30kN; "
        "widen a bound or the pattern (e.g. '62*')"
    )
    assert "'*'" not in line and result.stdout == ""


def test_catalogue_series_patterns_list_the_new_series():
    """'222*' names a series: the spherical roller bearings only (not the self-aligning 2220, 2222 that
    the glob also matches); 'NA49*' the needle bearings with inner ring; 'QJ2*' with the axial basis."""
    rows = json.loads(runner.invoke(app, ["catalogue", "222*", "--json"]).stdout)
    assert rows and {r["family"] for r in rows} == {"spherical_roller"}
    assert [r["designation"] for r in rows][:2] == ["22205", "22206"] and "2220" not in [
        r["designation"] for r in rows
    ]
    rows = json.loads(runner.invoke(app, ["catalogue", "NA49*", "--json"]).stdout)
    assert len(rows) == 28 and all(r["designation"].startswith("NA49") for r in rows)
    result = runner.invoke(app, ["catalogue", "QJ2*"])
    assert result.exit_code == 0 and "QJ208" in result.output and "C, C0 are axial" in result.output
    rows = json.loads(runner.invoke(app, ["catalogue", "QJ2*", "--json"]).stdout)
    assert rows[0]["rating_basis"].startswith("axial") and rows[0]["C_estimate_N"] > 0


def test_analyze_four_point_designation_axial_load():
    result = runner.invoke(app, ["analyze", "QJ208", "--load", "Fa=5kN", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["bearing_type"] == "four_point_contact_ball"
    row = data["cases"][0]["rows"][0]
    assert abs(row["axial_load_N"] - 5000.0) < 1e-6 * 5000


def test_catalogue_table_shows_the_from_memory_tag():
    """A row's source "[from memory; …]" is text: the table prints it (rich would take it for a style)."""
    result = runner.invoke(app, ["catalogue", "6420"], env={"COLUMNS": "400"})
    assert result.exit_code == 0, result.output
    assert "[from memory" in result.output
