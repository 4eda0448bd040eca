"""Which life is shown first, the line saying why ISO/TS 16281 differs, and the TS's tilt arm for the rating
(issue #40 item 2)."""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.cli import app

ROOT = Path(__file__).resolve().parents[2]
runner = CliRunner()


def _system(analysis, case=0):
    return analysis.rating.to_dict(case)["system"]


def test_iso281_is_the_headline_of_a_catalogue_bearing():
    s = _system(bk.analyze("6208", load={"F_x": "5 kN"}, speed="1500 rpm"))
    keys = list(s)
    assert keys[0] == "headline" and s["headline"]["method"] == "ISO 281"
    assert keys.index("L10_iso281_rev") < keys.index("L10r_rev")
    assert s["headline"]["L10_rev"] == s["L10_iso281_rev"] and s["headline"]["L10h_h"] == s["L10h_iso281_h"]


def test_with_lubrication_the_headline_carries_l_nmh():
    a = bk.analyze(
        "6208",
        load={"F_x": "5 kN"},
        speed="1500 rpm",
        lubricant="ISO_VG68",
        temperature="60 degC",
        contamination=0.5,
    )
    h = _system(a)["headline"]
    assert h["Lnm_rev"] is not None and h["Lnmh_h"] == pytest.approx(h["Lnm_rev"] / 1500 / 60, rel=1e-9)


def test_a_slewing_ring_heads_with_the_ts_life():
    s = _system(bk.analyze(ROOT / "examples" / "slewing_four_point.toml"))
    assert s["headline"]["method"] == "ISO/TS 16281" and "slewing" in s["headline"]["why"]
    assert s["life_difference"] is None


def test_the_difference_line_names_what_the_case_has():
    """Computed from the case: the clearance appears only when there is one; a roller's line gives the
    method factor λν^-4 (C/P)^(2/3) with the case's C/P."""
    base = {"bearing": {"designation": "NU 208"}}
    with_clearance = _system(bk.analyze(base, load={"F_x": "5.55 kN"}))["life_difference"]
    assert "clearance 37.5 µm" in with_clearance and "C/P = 10" in with_clearance
    zero = _system(bk.analyze({**base, "geometry": {"clearance_radial": "0 um"}}, load={"F_x": "5.55 kN"}))
    assert "clearance" not in zero["life_difference"]
    assert "roller profile and edge-stress factor" in zero["life_difference"]
    ball = _system(bk.analyze("6208", load={"F_x": "3 kN", "F_z": "1 kN"}))["life_difference"]
    assert ball.startswith("ISO/TS 16281 L10r = ") and "combined load" in ball and "exponent 4" not in ball


def test_cli_and_report_show_iso281_first_and_the_reason(tmp_path):
    args = ["rating", "NU 208", "--load", "Fr=5kN", "--speed", "1500rpm"]
    out = runner.invoke(app, args, terminal_width=200).stdout
    flat = " ".join(out.split())
    assert (
        flat.index("ISO 281: P = 5 kN") < flat.index("ISO/TS 16281: L10r =") < flat.index("why they differ:")
    )
    data = json.loads(runner.invoke(app, [*args, "--json"]).stdout)
    why = data["cases"][0]["system"]["life_difference"]
    assert " ".join(why.split()) in flat
    path = tmp_path / "r.html"
    bk.analyze("NU 208", load={"F_x": "5 kN"}, speed="1500 rpm").report(path)
    text = " ".join(re.sub(r"<[^>]+>", " ", path.read_text()).split())
    assert text.index("ISO 281: P = 5 kN") < text.index("system (ISO/TS 16281)")
    assert "Why they differ: ISO/TS 16281 L10r =" in text


def test_the_ts_rating_reads_the_pitch_radius_tilt_arm():
    """A DB pair under a moment: statics on the file's groove-centre arm, rating as if the file had said
    tilt_arm = "pitch_radius" (the TS's moment equation) — identical lives, different statics, a note."""
    data = tomllib.loads((ROOT / "examples" / "acbb_7209_DB.toml").read_text())
    load = {"F_x": "3 kN", "M_y": "60 N*m"}
    groove = bk.analyze(data, load=load)
    data["geometry"]["tilt_arm"] = "pitch_radius"
    pitch = bk.analyze(data, load=load)
    assert groove.statics.displacement[0, 4] != pytest.approx(pitch.statics.displacement[0, 4], rel=1e-6)
    np.testing.assert_allclose(groove.rating.life, pitch.rating.life, rtol=1e-9)
    assert any("pitch-radius tilt arm" in n for n in groove.notes)
    assert not any("pitch-radius tilt arm" in n for n in pitch.notes)
    # no moment, no tilt: the statics are rated as they are
    plain = bk.analyze(
        tomllib.loads((ROOT / "examples" / "acbb_7209_DB.toml").read_text()), load={"F_x": "3 kN"}
    )
    assert not any("pitch-radius tilt arm" in n for n in plain.notes)


def test_the_ts_arm_solve_at_speed():
    """At speed the statics' model is a speed wrapper: the TS-arm solve starts from the built model."""
    a = bk.analyze(
        ROOT / "examples" / "seed000_composite.toml", load={"F_z": "5 kN", "M_y": "500 N*m"}, speed="5 rpm"
    )
    assert a.rating is not None and any("pitch-radius tilt arm" in n for n in a.rating.notes)
    assert a.rating.life[0] > 0
