"""`bearingkit friction --model skf|palmgren` and `--compare` on the kind examples (issue 17 item 5)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.cli import app
from bearingkit.lubricants import as_lubricant
from bearingkit.physics.friction import palmgren, skf

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SRB, SABB, NEEDLE = (str(EXAMPLES / f) for f in ("srb_22220.toml", "sabb_1209.toml", "needle_na4910.toml"))
runner = CliRunner()


def _json(args):
    res = runner.invoke(app, args)
    assert res.exit_code == 0, res.stderr
    return json.loads(res.stdout)


def test_cli_skf_on_spherical_roller_equals_the_model_on_the_file_inputs():
    data = _json(["friction", SRB, "--model", "skf", "--temperature", "60degC", "--json"])
    nu = as_lubricant("ISO_VG68").kinematic_viscosity(60.0)
    expected = skf.skf_friction_moment(
        "spherical_roller",
        bore_diameter=0.1,
        outside_diameter=0.18,
        speed=1000 * 2 * np.pi / 60,
        kinematic_viscosity=nu,
        load_radial=np.array([60e3, 60e3]),
        load_axial=np.array([0.0, 15e3]),
    )["total_Nm"]
    got = [c["friction"]["total_Nm"] for c in data["cases"]]
    assert got == pytest.approx(list(expected), rel=1e-12)
    assert got[1] > got[0]  # the axial load adds friction


def test_cli_palmgren_on_needle_and_spherical_roller():
    needle = _json(["friction", NEEDLE, "--model", "palmgren", "--temperature", "60degC", "--json"])
    nu = as_lubricant("ISO_VG68").kinematic_viscosity(60.0)
    expected = palmgren.palmgren_friction_moment(
        "needle_roller",
        pitch_diameter=0.061,
        speed=2000 * 2 * np.pi / 60,
        kinematic_viscosity=nu,
        load_radial=10e3,
    )["total_Nm"]
    assert needle["cases"][0]["friction"]["total_Nm"] == pytest.approx(float(expected), rel=1e-12)
    srb = _json(["friction", SRB, "--model", "palmgren", "--json"])
    assert all(c["friction"]["total_Nm"] > 0 for c in srb["cases"])


def test_cli_refuses_a_model_without_constants_in_one_line():
    res = runner.invoke(app, ["friction", NEEDLE, "--model", "skf"])
    assert res.exit_code == 2 and res.stdout == ""
    line = res.stderr.strip()
    assert "\n" not in line and line.startswith("error:") and "needle_roller" in line and "SKF" in line
    res = runner.invoke(app, ["friction", SABB, "--model", "palmgren"])
    assert res.exit_code == 2 and "self_aligning_ball" in res.stderr and "\n" not in res.stderr.strip()


def test_compare_shows_the_models_that_apply_and_why_the_others_do_not():
    cases = {
        SRB: ("skf", "palmgren"),
        SABB: ("skf",),
        NEEDLE: ("palmgren",),
    }
    for path, applies in cases.items():
        data = _json(["friction", path, "--compare", "--json"])
        models = data["models"]
        for name in ("skf", "palmgren"):
            if name in applies:
                assert all(v > 0 for v in models[name]["total_Nm"]), (path, name)
            else:
                assert "refused" in models[name]["not_applicable"], (path, name)


@pytest.mark.parametrize(("path", "mu", "bore"), [(SRB, 0.0018, 0.1), (SABB, 0.0010, 0.045)])
def test_skf_near_the_catalogue_constant_friction_coefficient(path, mu, bore):
    """Published check: SKF's constant-μ estimate M = μ P d/2 (SKF catalogue 'Friction', Table 1: spherical
    roller 0.0018, self-aligning ball 0.0010) holds for P ≈ 0.1 C with good lubrication. SKF gives it as an
    estimate without a stated accuracy; the four-component model must agree within a factor 2 at such a
    point (1000 r/min, ISO VG 68 at 70 °C, C of the example's own ISO 281 rating)."""
    c = sum(r["C_N"] for r in bk.analyze(path, speed="1000 rpm").rating.to_dict(0)["rows"])
    p = 0.1 * c
    a = bk.analyze(path, load={"F_x": f"{p} N"}, speed="1000 rpm", temperature="70 degC")
    ratio = float(a.friction_by("skf").total[0]) / (0.5 * mu * p * bore)
    assert 0.5 < ratio < 2.0


def test_default_friction_on_a_new_kind_points_to_the_models_that_cover_it():
    """A spherical roller bearing gets the SKF model by default (issue 40); the component model has no
    spherical roller rows: asked for, its one-line refusal names the catalogue models."""
    res = runner.invoke(app, ["friction", SRB])
    assert res.exit_code == 0 and "friction model: skf (standard spherical roller bearing" in res.stdout
    res = runner.invoke(app, ["friction", SRB, "--model", "components"])
    assert res.exit_code == 2 and res.stdout == ""
    line = res.stderr.strip()
    assert "\n" not in line and "spherical_roller" in line and "'skf'" in line and "--compare" in line


def test_text_output_states_each_note_once_and_keeps_the_case_line_whole():
    res = runner.invoke(app, ["friction", SRB, "--model", "skf"])
    assert res.exit_code == 0, res.stderr
    assert res.stdout.count("SKF constants of series 222E ([bearing] series)") == 1  # run notes, not per case
    assert "case 'radial_60kN' (skf model): M = " in res.stdout  # not wrapped to the table's width
