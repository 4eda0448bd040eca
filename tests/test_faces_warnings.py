"""Every face shows the warnings an analysis carries, speed has one sign rule, no rounding noise.

Issue #23 (hardening), the face items: each test here fails on the code before the pipeline.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.pipeline import analyze

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
DGBB = str(EXAMPLES / "dgbb_6209.toml")
runner = CliRunner()


def _free_all(tmp_path) -> str:
    """The 6209 example with every DOF free (the default when a file gives no [solver] free)."""
    text = (EXAMPLES / "dgbb_6209.toml").read_text()
    text = re.sub(r"free = \[[^\]]*\]", 'free = ["u_x", "u_y", "u_z", "theta_x", "theta_y"]', text)
    path = tmp_path / "dgbb_free.toml"
    path.write_text(text)
    return str(path)


def test_analyze_prints_overload_warnings():
    """200 kN on a 6209: s0 < 1 and p_max above 4200 MPa are printed by analyze, not only by rating."""
    result = runner.invoke(app, ["analyze", DGBB, "--load", "Fr=200kN"])
    assert result.exit_code == 0
    text = " ".join(result.stdout.split())
    assert "warning: balls: static safety s0 = 0.12 < 1" in text
    assert "exceeds the ISO 76 limit 4200 MPa" in text


def test_analyze_json_carries_the_warnings():
    result = runner.invoke(app, ["analyze", DGBB, "--load", "Fr=200kN", "--json"])
    case = json.loads(result.stdout)["cases"][0]
    assert any("static safety s0" in w for w in case["warnings"])
    light = json.loads(runner.invoke(app, ["analyze", DGBB, "--load", "Fr=2kN", "--json"]).stdout)
    assert light["cases"][0]["warnings"] == []


def test_free_tilt_of_a_single_row_bearing_is_flagged(tmp_path):
    """Fr + Fa with free tilts: the 6209 tilts under no moment, and every face says so."""
    path = _free_all(tmp_path)
    a = analyze(path, load={"F_x": "5 kN", "F_z": "1 kN"})
    assert abs(a.statics.displacement[0, 4]) > 1e-4  # it does tilt (mrad), which a shaft would prevent
    assert any("free tilt of a single-row bearing" in w for w in a.warnings[0])
    text = " ".join(runner.invoke(app, ["analyze", path, "-l", "Fr=5kN", "-l", "Fa=1kN"]).stdout.split())
    assert "warning: free tilt of a single-row bearing" in text
    rating = json.loads(runner.invoke(app, ["rating", path, "-l", "Fr=5kN", "-l", "Fa=1kN", "--json"]).stdout)
    assert any("free tilt" in w for w in rating["cases"][0]["warnings"])
    html = a.report(tmp_path / "r.html").read_text(encoding="utf-8")
    assert "free tilt of a single-row bearing" in html
    # a pure radial load does not tilt it: no warning
    assert analyze(path, load={"F_x": "5 kN"}).warnings[0] == []


def test_negative_speed_means_the_other_direction_everywhere(tmp_path):
    """rating, friction and report take a negative speed as the other direction of rotation."""
    pos = analyze(DGBB, load={"F_x": "5 kN"}, speed="3000 rpm", lubricant="ISO_VG68")
    neg = analyze(DGBB, load={"F_x": "5 kN"}, speed="-3000 rpm", lubricant="ISO_VG68")
    assert neg.rating.to_dict(0)["system"]["L10h_h"] == pytest.approx(
        pos.rating.to_dict(0)["system"]["L10h_h"]
    )
    assert neg.friction.total[0] == pytest.approx(pos.friction.total[0])
    torque = (neg.friction_by("components").native.torque_inner[0], pos.friction_by("components").native)
    assert torque[0] == pytest.approx(-torque[1].torque_inner[0])
    assert neg.friction.power_loss[0] == pytest.approx(pos.friction.power_loss[0])
    assert pos.friction.power_loss[0] > 0
    result = runner.invoke(app, ["rating", DGBB, "-l", "Fr=5kN", "--speed=-3000rpm"])
    assert result.exit_code == 0, result.stderr
    out = tmp_path / "r.html"
    result = runner.invoke(app, ["report", DGBB, "-o", str(out), "-l", "Fr=5kN", "--speed=-3000rpm"])
    assert result.exit_code == 0, result.stderr
    html = out.read_text(encoding="utf-8")
    assert "-3000 r/min (sign = direction of rotation)" in html and "no speed" not in html


def test_no_rounding_noise_in_the_tables():
    result = runner.invoke(app, ["analyze", DGBB, "--load", "Fr=4kN"])
    assert re.search(r"\de-1\d", result.stdout) is None  # no "-2.738e-15 µm"
    assert "-0.0" not in result.stdout and "-0 " not in result.stdout


def test_report_numbers_its_sections_once_and_shows_friction_in_newton_metres(tmp_path):
    a = analyze(DGBB, speed="1000 rpm", lubricant="ISO_VG68")
    html = a.report(tmp_path / "r.html").read_text(encoding="utf-8")
    headings = re.findall(r"<h[24]>([\d.]+)\. ", html)
    assert len(headings) == len(set(headings))  # "5. Warnings" never followed by "3. Warnings"
    assert "N·mm" not in html and "friction [N·m]" in html


def test_life_chart_labels_decades_only():
    """One row spans ~1.3 decades on the life axis: only decade labels, no crowded minor labels."""
    import xml.etree.ElementTree as ET

    from bearingkit.report import plots

    a = analyze(DGBB, cases=["radial_4kN"], speed="1000 rpm")
    root = ET.fromstring(plots.rating_figure(a.rating, 0).to_svg())
    # the tick labels: centred under the axis, 7 pt (the bar values are left-aligned beside the bars)
    from bearingkit.report import svg

    tick_size = svg._n(7 * svg.PT)
    ticks = [
        t.text
        for t in root.iter("{http://www.w3.org/2000/svg}text")
        if t.get("text-anchor") == "middle" and t.get("font-size") == tick_size
    ]
    assert len(ticks) >= 2  # a decade on each panel at least
    # every one a power of ten (1, 10, 10², …): no "3×10⁴"-style minor labels
    assert all(t in ("1", "10") or (t[:2] == "10" and set(t[2:]) <= set("⁻⁰¹²³⁴⁵⁶⁷⁸⁹")) for t in ticks), ticks
    # placed as a log axis places them: the life panel's decades evenly spaced, growing to the right
    sup = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")
    life = [
        (float(t.get("x")), t.text)
        for t in root.iter("{http://www.w3.org/2000/svg}text")
        if t.get("text-anchor") == "middle" and t.get("font-size") == tick_size and float(t.get("x")) > 550
    ]
    exps = [0 if s == "1" else 1 if s == "10" else int(s[2:].translate(sup)) for _, s in sorted(life)]
    xs = [x for x, _ in sorted(life)]
    assert exps == sorted(exps) and len(set(exps)) == len(exps)
    if len(xs) >= 3:
        steps = np.diff(xs) / np.diff(exps)
        assert np.ptp(steps) < 0.5, steps
