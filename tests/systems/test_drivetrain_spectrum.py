"""A drivetrain with tapered roller bearings over a load spectrum at several speeds, in one run.

The output shaft of a one-stage helical gearbox sits on two 32008 facing each other; the three load
cases run at 300, 3000 and 300 r/min of the input (a duty cycle). The tapered rows take each case's
speed (their rollers' centrifugal force per case), so the whole spectrum is one solve: every case of
it equals the same case solved alone (``--case``) to 1e-9 (reactions, both lives, shaft speeds,
power), and the duty-cycle lives are Palmgren–Miner over the lives of those separate runs.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from typer.testing import CliRunner

from bearingkit.cli.commands import app

MODEL = """
[drivetrain]
name = "one-stage helical, tapered output shaft"
held = "output"

[[shafts]]
name = "input"
centre = ["0 mm", "0 mm"]
max_element_length = "5 mm"
sections = [
  { start = "0 mm", length = "20 mm", outer_diameter = "40 mm" },
  { length = "120 mm", outer_diameter = "48 mm" },
  { length = "20 mm", outer_diameter = "40 mm" },
]
bearings = [
  { name = "input_A", designation = "6208", position = "10 mm", axial = "locating" },
  { name = "input_B", designation = "NU 208", position = "150 mm", axial = "floating" },
]

[[shafts.gears]]
name = "pinion"
position = "60 mm"
teeth = 19
normal_module = "3 mm"
pressure_angle = "20 deg"
helix_angle = "15 deg"
hand = "right"
face_width = "40 mm"

[[shafts]]
name = "output"
centre = ["124.2331 mm", "0 mm"]
max_element_length = "5 mm"
sections = [
  { start = "0 mm", length = "20 mm", outer_diameter = "40 mm" },
  { length = "120 mm", outer_diameter = "50 mm" },
  { length = "20 mm", outer_diameter = "40 mm" },
]
bearings = [
  { name = "output_A", designation = "32008", position = "10 mm", orientation = "+z" },
  { name = "output_B", designation = "32008", position = "150 mm", orientation = "-z" },
]

[[shafts.gears]]
name = "wheel"
position = "60 mm"
teeth = 61
normal_module = "3 mm"
pressure_angle = "20 deg"
helix_angle = "15 deg"
hand = "left"
face_width = "40 mm"

[[meshes]]
name = "stage"
gears = ["pinion", "wheel"]

[[load_cases]]
name = "slow"
torques = { input = "150 N*m" }
speed = { input = "300 rpm" }
time_fraction = 0.5

[[load_cases]]
name = "fast"
torques = { input = "60 N*m" }
speed = { input = "3000 rpm" }
time_fraction = 0.3

[[load_cases]]
name = "slow_light"
torques = { input = "80 N*m" }
speed = { input = "300 rpm" }
time_fraction = 0.2

[lubricant]
name = "ISO_VG100"
"""
#: The cases' input speeds [rpm] and time fractions, as written above.
RPM = {"slow": 300.0, "fast": 3000.0, "slow_light": 300.0}
FRACTIONS = {"slow": 0.5, "fast": 0.3, "slow_light": 0.2}
RTOL = 1e-9


def _run(path, *args):
    out = CliRunner().invoke(app, ["system", str(path), "--json", *args])
    assert out.exit_code == 0, out.output
    return json.loads(out.output)


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    path = tmp_path_factory.mktemp("spectrum") / "spectrum.toml"
    path.write_text(MODEL, encoding="utf-8")
    full = _run(path)
    alone = {name: _run(path, "--case", name)["cases"][0] for name in RPM}
    return path, full, alone


def _close(a, b, scale=None):
    scale = max(abs(b), 1e-300) if scale is None else scale
    return abs(a - b) <= RTOL * scale


def test_the_whole_spectrum_is_one_run_and_each_case_equals_it_solved_alone(runs):
    _, full, alone = runs
    assert [c["case"] for c in full["cases"]] == list(RPM)
    for case in full["cases"]:
        one = alone[case["case"]]
        assert case["converged"] and one["converged"]
        # speeds: the input's from the file, the output's by the gear ratio 19/61 (negative: external mesh)
        w = RPM[case["case"]] * np.pi / 30.0
        speeds = case["power"]["speeds_rad_s"]
        assert speeds["input"] == pytest.approx(w, rel=1e-12)
        assert speeds["output"] == pytest.approx(-w * 19 / 61, rel=1e-12)
        for shaft, value in speeds.items():
            assert _close(value, one["power"]["speeds_rad_s"][shaft])
        for key in ("input_W", "output_W", "loss_W", "efficiency"):
            assert _close(case["power"][key], one["power"][key])
        for key in ("L10h_h", "L10h_iso281_h"):
            assert _close(case["system"][key], one["system"][key])
        for a, b in zip(case["bearings"], one["bearings"], strict=True):
            assert a["summary"]["name"] == b["summary"]["name"]
            forces = [a["reaction_on_inner_body"][k] for k in ("F_x_N", "F_y_N", "F_z_N")]
            ref = [b["reaction_on_inner_body"][k] for k in ("F_x_N", "F_y_N", "F_z_N")]
            scale = max(map(abs, ref))
            assert all(_close(x, y, scale) for x, y in zip(forces, ref, strict=True)), (
                a["summary"]["name"],
                forces,
                ref,
            )
            for key in ("radial_load_N", "axial_load_N", "L10h_h", "L10h_iso281_h", "power_loss_W"):
                assert _close(a["summary"][key], b["summary"][key]), (
                    key,
                    a["summary"][key],
                    b["summary"][key],
                )


def test_the_tapered_bearings_see_each_case_at_its_own_speed(runs):
    """The 'fast' case solved alone at the slow cases' speed differs (beyond the 1e-9 of the comparison
    above): the batched run used each case's speed, not one for all."""
    path, full, _ = runs
    slowed = path.with_name("slowed.toml")
    slowed.write_text(
        MODEL.replace('speed = { input = "3000 rpm" }', 'speed = { input = "300 rpm" }'), "utf-8"
    )
    fast = next(c for c in full["cases"] if c["case"] == "fast")
    other = _run(slowed, "--case", "fast")["cases"][0]
    tapered = [b for b in fast["bearings"] if b["summary"]["name"].startswith("output")]
    moved = max(
        abs(b["summary"]["axial_load_N"] - o["summary"]["axial_load_N"]) / abs(o["summary"]["axial_load_N"])
        for b, o in zip(tapered, other["bearings"][2:], strict=True)
    )
    assert moved > 1e3 * RTOL


def test_the_duty_cycle_is_palmgren_miner_over_the_cases_solved_alone(runs):
    _, full, alone = runs
    f = np.array([FRACTIONS[n] for n in RPM])
    duty = full["duty_cycle"]
    for key in ("L10h_h", "L10h_iso281_h"):
        system = np.array([alone[n]["system"][key] for n in RPM])
        assert duty["system"][key] == pytest.approx(1.0 / np.sum(f / system), rel=RTOL)
        for name, lives in duty["bearings"].items():
            per_case = np.array(
                [
                    next(b["summary"][key] for b in alone[n]["bearings"] if b["summary"]["name"] == name)
                    for n in RPM
                ]
            )
            assert lives[key] == pytest.approx(1.0 / np.sum(f / per_case), rel=RTOL)


def test_the_tables_and_the_report_show_every_case_and_the_duty_cycle(runs, tmp_path):
    path = runs[0]
    report = tmp_path / "spectrum.html"
    out = CliRunner().invoke(app, ["system", str(path), "--report", str(report)])
    assert out.exit_code == 0, out.output
    html = report.read_text(encoding="utf-8")
    for name in RPM:
        assert f"{name}: bearings" in out.output
        assert name in html
    duty = runs[1]["duty_cycle"]["system"]
    assert "duty cycle (Palmgren–Miner): system L10h" in out.output
    assert f"system L10h {duty['L10h_iso281_h']:.4g} h (ISO 281)" in out.output
    assert "Duty cycle (Palmgren–Miner over the time fractions)" in html


def test_a_speed_missing_from_one_case_is_one_line(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(MODEL.replace('speed = { input = "3000 rpm" }\n', ""), encoding="utf-8")
    out = CliRunner().invoke(app, ["system", str(bad)])
    assert out.exit_code == 2
    lines = [x for x in out.output.splitlines() if x.strip()]
    assert len(lines) == 1 and "load_cases" in lines[0], out.output
