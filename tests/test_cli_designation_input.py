"""Designations on the command line: slashes are designations, not paths; any string is answered in one
line with nothing written; pairs with a preload class; the must-show commands of issue 33."""

from __future__ import annotations

import json
import os
import tempfile

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from bearingkit.cli import app

runner = CliRunner()


def test_designation_with_slash_is_not_a_file():
    """'6308-2RS1/C3' used to answer "cannot read the file": it is SKF's slash syntax."""
    result = runner.invoke(app, ["rating", "6308-2RS1/C3", "--load", "Fr=5kN", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    system = data["cases"][0]["system"]
    assert data["bearing_type"] == "deep_groove_ball" and "C3" in data["source"]
    # ISO 281 with the catalogue C of the 6308 (NSK E1102 B10: 40.5 kN) and P = F_r (no axial load)
    assert system["C_iso281_N"] == 40500.0 and system["P_iso281_N"] == pytest.approx(5000.0)
    assert system["L10_iso281_rev"] == pytest.approx((40.5 / 5.0) ** 3 * 1e6, rel=1e-9)


def test_a_toml_path_that_does_not_exist_is_still_a_file_error():
    result = runner.invoke(app, ["analyze", "nowhere/bearing.toml", "--load", "Fr=1kN"])
    assert result.exit_code == 2 and "cannot read the file" in result.stderr


def test_pair_with_light_preload_gives_stiffness_and_contact_angles():
    """`bearingkit analyze "7014 C DB" --preload light --speed 12000rpm --load Fr=1kN --json`."""
    args = ["analyze", "7014 C DB", "--preload", "light", "--speed", "12000rpm", "--load", "Fr=1kN", "--json"]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    case = data["cases"][0]
    assert data["bearing_type"] == "angular_contact_pair" and case["converged"]
    k = np.array(case["stiffness_SI"])
    assert k.shape == (5, 5) and (np.diag(k)[:3] > 1e7).all()  # N/m: radial and axial stiffness of a set
    # the light class of a 7014 C set is NSK's: L = 290 N (NSK E1102e Table 10.2.2, pp. A98-A99); both
    # rows carry it
    rows = case["rows"]
    assert [r["name"] for r in rows] == ["balls_A", "balls_B"]
    for r in rows:
        assert r["preload_N"] == pytest.approx(290.0, rel=1e-6)
        inner = np.abs(np.degrees(r["contact_angle_inner_rad"]))
        outer = np.abs(np.degrees(r["contact_angle_outer_rad"]))
        # at 12000 r/min the centrifugal force opens the inner and closes the outer contact angle
        assert (inner > 15.0).all() and (outer < 15.0).all()
    assert "NSK Rolling Bearings CAT. No. E1102e, Table 10.2" in data["source"]


def test_preload_on_a_single_bearing_refused():
    result = runner.invoke(app, ["analyze", "7014 C", "--preload", "light", "--load", "Fa=1kN"])
    assert result.exit_code == 2 and result.stdout == ""
    assert "a preload is set on a pair" in result.stderr and len(result.stderr.strip().splitlines()) == 1


def test_tapered_pair_from_a_designation_has_an_iso281_life():
    """30206 DF: ISO 281's paired unit, C = 2^(7/9) C of one 30206 (NSK E1102 B114: 43.0 kN), double-row
    X, Y: F_a/F_r = 0.2 <= e = 0.37, so P = F_r + 0.45 cot α F_a with cot α = 1.5/e."""
    args = ["rating", "30206 DF", "--load", "Fr=5kN", "--load", "Fa=1kN", "--speed", "1000rpm", "--json"]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    system = json.loads(result.stdout)["cases"][0]["system"]
    c = 2 ** (7 / 9) * 43.0e3
    p = 5.0e3 + 0.45 * (1.5 / 0.37) * 1.0e3
    assert system["C_iso281_N"] == pytest.approx(c, rel=1e-12)
    assert system["P_iso281_N"] == pytest.approx(p, rel=1e-9)
    assert system["L10_iso281_rev"] == pytest.approx((c / p) ** (10 / 3) * 1e6, rel=1e-9)
    assert system["L10h_iso281_h"] > 0 and system["iso281_note"] is None


def _one_line_no_output(result) -> None:
    assert result.exit_code == 2, (result.exit_code, result.output)
    assert result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), result.stderr


@pytest.mark.parametrize("text", ["6308-2RS1/C7", "6205-P3", "62/", "///", "7014 Z DB", "xyz", "6205 C3 C4"])
def test_bad_designations_one_line_nothing_written(text, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    _one_line_no_output(runner.invoke(app, ["rating", text, "--load", "Fr=1kN"]))
    assert os.listdir(tmp_path) == []


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.text(max_size=40).filter(lambda s: not s.startswith("-") and "\x00" not in s))
def test_any_string_as_designation_one_line_nothing_written(text):
    """Whatever the string (not an option), `bearingkit analyze TEXT` answers in one line and writes no file.
    A string that happens to be a valid designation is analysed (exit 0)."""
    with tempfile.TemporaryDirectory() as tmp:
        cwd = os.getcwd()
        os.chdir(tmp)
        try:
            result = runner.invoke(app, ["analyze", text, "--load", "Fr=1kN"])
        finally:
            os.chdir(cwd)
        assert os.listdir(tmp) == []
    if result.exit_code != 0:
        assert result.exception is None or isinstance(result.exception, SystemExit)
        _one_line_no_output(result)
