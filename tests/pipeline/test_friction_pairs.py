"""Matched sets (DB, DF, DT) of angular contact ball and tapered roller bearings get the SKF model by
default, per bearing at the loads each row carries in the paired solve, summed (issue 40).

The SKF torque of a single 7209 B is written out here from the catalogue's equations (SKF 17000 EN,
"Friction": φ_ish, φ_rs, G_rr/G_sl of angular contact ball bearings with F_g, μ_sl) with the constants of
series 72 B typed from the table (R1 4.33e-7, R2 2.02, R3 2.44e-12, S1 1.82e-2, S2 0.71, S3 2.44e-12,
K_Z 4.4), independent of bearingkit's code.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.cli import app
from bearingkit.lubricants import as_lubricant
from bearingkit.physics.friction import skf
from bearingkit.pipeline.friction.choice import choose
from bearingkit.pipeline.inputs import load_input

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
RPM = np.pi / 30.0
runner = CliRunner()
PAIR_CASE = [
    "7209 B DB",
    "--load",
    "Fr=3kN",
    "--load",
    "Fa=2kN",
    "--speed",
    "3000rpm",
    "--lubricant",
    "ISO_VG68",
    "--temperature",
    "70degC",
]


def _json(args):
    res = runner.invoke(app, args)
    assert res.exit_code == 0, res.stderr
    return json.loads(res.stdout)


def _skf_by_hand_7209b(fr, fa, n, nu):
    """SKF torque [N·m] of one 7209 B (d 45, D 85 mm) in an oil bath, no seals, no drag (SKF units:
    N·mm, mm, r/min, mm²/s); K_rs = 3e-8 (oil bath), μ_bl = 0.15, μ_EHL = 0.05 (mineral oil)."""
    d, big_d = 45.0, 85.0
    dm = 0.5 * (d + big_d)
    fg_rr = 2.44e-12 * dm**4 * n**2
    fg_sl = 2.44e-12 * dm**4 * n**2
    g_rr = 4.33e-7 * dm**1.97 * (fr + fg_rr + 2.02 * fa) ** 0.54
    g_sl = 1.82e-2 * dm**0.26 * ((fr + fg_sl) ** (4 / 3) + 0.71 * fa ** (4 / 3))
    phi_ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = 1 / np.exp(3e-8 * nu * n * (d + big_d) * np.sqrt(4.4 / (2 * (big_d - d))))
    m_rr = phi_ish * phi_rs * g_rr * (nu * n) ** 0.6
    phi_bl = 1 / np.exp(2.6e-8 * (n * nu) ** 1.4 * dm)
    m_sl = g_sl * (phi_bl * 0.15 + (1 - phi_bl) * 0.05)
    return (m_rr + m_sl) * 1e-3


def _row_loads(a, name):
    f = a.statics.row_load(name)
    return np.hypot(f[:, 0], f[:, 1]), np.abs(f[:, 2])


def test_db_pair_is_the_sum_of_its_two_bearings_by_hand():
    a = bk.analyze(
        "7209 B DB",
        load={"F_x": "3 kN", "F_z": "2 kN"},
        speed="3000 rpm",
        lubricant="ISO_VG68",
        temperature="70 degC",
    )
    assert a.friction.model == "skf" and "matched set (DB)" in a.friction.why
    nu = as_lubricant("ISO_VG68").kinematic_viscosity(70.0) * 1e6
    by_hand = {}
    for row in a.input.model.rows:
        fr, fa = _row_loads(a, row.name)
        by_hand[row.name] = _skf_by_hand_7209b(fr[0], fa[0], 3000.0, nu)
        assert a.friction.native.by_row[row.name][0] == pytest.approx(by_hand[row.name], rel=1e-9)
    assert a.friction.total[0] == pytest.approx(sum(by_hand.values()), rel=1e-9)
    a_fa, b_fa = (_row_loads(a, r.name)[1][0] for r in a.input.model.rows)
    assert abs(a_fa - b_fa) > 1000.0  # the external F_a sits on one bearing: the rows differ
    assert a.friction.power_loss[0] == pytest.approx(a.friction.total[0] * 3000 * RPM, rel=1e-12)
    assert a.friction.components["seal"][0] == 0.0 and a.friction.components["drag"][0] == 0.0
    # the whole pair's F_r, F_a on one bearing (what --model skf gave before) is another number
    nu_si = nu * 1e-6
    one = skf.skf_friction_moment(
        "angular_contact_ball",
        bore_diameter=0.045,
        outside_diameter=0.085,
        speed=3000 * RPM,
        kinematic_viscosity=nu_si,
        load_radial=3000.0,
        load_axial=2000.0,
        series="72_BECBP",
    )["total_Nm"]
    assert abs(a.friction.total[0] / float(one) - 1) > 0.2


def test_preloaded_pair_without_external_load_has_the_friction_of_its_preload():
    """At rest (n = 0: no rolling term, μ_sl = μ_bl) each bearing carries the preload alone:
    M = 2 μ_bl S1 d_m^0.26 S2 F_pr^(4/3)."""
    inp = load_input("7209 B DB", preload="480 N", load={"F_x": "0 N"})
    a = bk.analyze(inp, speed="0 rpm", lubricant="ISO_VG68", temperature="40 degC")
    assert a.friction.model == "skf"
    one = 0.15 * 1.82e-2 * 65.0**0.26 * 0.71 * 480.0 ** (4 / 3) * 1e-3
    assert a.friction.total[0] == pytest.approx(2 * one, rel=1e-9)
    cli = ["friction", "7209 B DB", "--preload", "480N", "--load", "Fr=0kN", "--speed", "0rpm"]
    data = _json([*cli, "--lubricant", "ISO_VG68", "--json"])
    assert data["cases"][0]["friction"]["total_Nm"] == pytest.approx(2 * one, rel=1e-9)
    loads = data["cases"][0]["friction"]["row_loads_N"]
    assert all(v["axial"] == pytest.approx(480.0, rel=1e-9) for v in loads.values())
    # at speed the preload of a set held by its setting rises (ball centrifugal force): each row's own load
    b = bk.analyze(inp, speed="3000 rpm", lubricant="ISO_VG68", temperature="70 degC")
    nu = as_lubricant("ISO_VG68").kinematic_viscosity(70.0) * 1e6
    fa = [_row_loads(b, r.name)[1][0] for r in b.input.model.rows]
    assert all(f > 480.0 for f in fa)
    hand = sum(_skf_by_hand_7209b(0.0, f, 3000.0, nu) for f in fa)
    assert b.friction.total[0] == pytest.approx(hand, rel=1e-9)


def test_cli_db_pair_defaults_to_skf_per_bearing_and_components_still_works():
    data = _json(["friction", *PAIR_CASE, "--json"])
    assert data["friction_model"] == "skf" and "per bearing" in data["friction_model_why"]
    f = data["cases"][0]["friction"]
    assert f["model"] == "skf" and f["model_why"] == data["friction_model_why"]
    assert sum(f["rows_Nm"].values()) == pytest.approx(f["total_Nm"], rel=1e-12)
    assert set(f["row_loads_N"]) == set(f["rows_Nm"]) == {"balls_A", "balls_B"}
    assert f["power_loss_W"] == pytest.approx(f["total_Nm"] * 3000 * RPM, rel=1e-12)
    text = runner.invoke(app, ["friction", *PAIR_CASE]).stdout
    assert "friction model: skf (matched set (DB) of 2 standard angular contact ball bearings" in text
    assert "by row" in text and " W at 3000 r/min" in text
    comp = _json(["friction", *PAIR_CASE, "--model", "components", "--json"])
    assert comp["friction_model"] == "components" and comp["friction_model_why"] == "asked for"
    assert comp["cases"][0]["friction"]["model"] == "components"
    assert comp["cases"][0]["friction"]["total_Nm"] != pytest.approx(f["total_Nm"], rel=1e-3)


@pytest.mark.parametrize(
    ("example", "series_note"),
    [
        ("acbb_7209_DB.toml", "SKF constants of series 72_BECBP (catalogue row 7209B (same d and D))"),
        ("trb_32008_DB.toml", "d and D match catalogue series 320, 330"),
    ],
)
def test_files_pairing_two_single_rows_get_skf_per_bearing(example, series_note):
    a = bk.analyze(EXAMPLES / example, speed="1000 rpm", lubricant="ISO_VG68", temperature="60 degC")
    assert a.friction.model == "skf" and "matched set (DB)" in a.friction.why
    assert any(series_note in n for n in a.friction.notes)
    rows = a.friction.native.by_row
    assert len(rows) == 2
    np.testing.assert_allclose(sum(rows.values()), a.friction.total, rtol=1e-12)


def test_tapered_df_pair_is_the_sum_of_single_bearings_at_their_row_loads():
    """32008 X DF: each bearing by the SKF tapered law with Y = 0.6/e of the catalogue row (e = 0.38) and
    the constants bearingkit has for tapered bearings (series 302; 320 has none: a note says so)."""
    a = bk.analyze(
        "32008 X DF",
        load={"F_x": "6 kN", "F_z": "3 kN"},
        speed="1500 rpm",
        lubricant="ISO_VG68",
        temperature="60 degC",
    )
    assert a.friction.model == "skf"
    assert any("series 320" in n and "302" in n for n in a.friction.notes)
    nu = as_lubricant("ISO_VG68").kinematic_viscosity(60.0)
    total = 0.0
    for row in a.input.model.rows:
        fr, fa = _row_loads(a, row.name)
        total += skf.skf_friction_moment(
            "tapered_roller",
            bore_diameter=0.040,
            outside_diameter=0.068,
            speed=1500 * RPM,
            kinematic_viscosity=nu,
            load_radial=fr,
            load_axial=fa,
            series="302",
            axial_factor=0.6 / 0.38,
        )["total_Nm"]
    np.testing.assert_allclose(a.friction.total, total, rtol=1e-9)


SEED_FILES = ["seed000_composite.toml", "ball_column_condition1.toml", "ptrb_prototype.toml", "yrt_120.toml"]


@pytest.mark.parametrize("example", SEED_FILES)
def test_seed_files_keep_the_component_model(example):
    a = bk.analyze(EXAMPLES / example, speed="5 rpm", lubricant="ISO_VG68", temperature="40 degC")
    model, why = choose(a)
    assert model == "components" and "not a catalogue bearing" in why
    if a.friction is not None:  # the PTRB's threaded rows have no component friction yet (a note says so)
        assert a.friction.model == "components" and a.friction.why == why


def test_double_row_designation_is_one_bearing_not_a_set():
    """3209 is one double row bearing (SKF constants of series 32 A), not a pair of 7209."""
    a = bk.analyze("3209", load={"F_x": "3 kN"}, speed="3000 rpm", lubricant="ISO_VG68")
    assert a.friction.model == "skf" and "standard angular contact ball double" in a.friction.why
    assert not hasattr(a.friction.native, "by_row")


def test_a_shaft_seat_holding_a_db_pair_gets_skf_per_bearing():
    """examples/shaft_spindle.toml: the front DB pair of 7209 B is a seat of the shaft; its friction is the
    sum of its two bearings at the row loads of the shaft's solution (as a pair analysed alone)."""
    from bearingkit.systems.shaft.input import load_shaft_file
    from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis

    sa = ShaftAnalysis(load_shaft_file(EXAMPLES / "shaft_spindle.toml"))
    a = sa.bearings["front_pair"]
    assert a.friction.model == "skf" and "matched set (DB)" in a.friction.why
    op = a.operating
    nu = op.lubricant.kinematic_viscosity(op.temperature)
    total = 0.0
    for row in a.input.model.rows:
        fr, fa = _row_loads(a, row.name)
        one = skf.skf_friction_moment(
            "angular_contact_ball",
            bore_diameter=0.045,
            outside_diameter=0.085,
            speed=op.abs_speed,
            kinematic_viscosity=nu,
            load_radial=fr,
            load_axial=fa,
            series="72_BECBP",
            lubrication="grease" if op.lubricant.base == "grease" else "oil_bath",
        )["total_Nm"]
        np.testing.assert_allclose(a.friction.native.by_row[row.name], one, rtol=1e-9)
        total = total + one
    np.testing.assert_allclose(a.friction.total, total, rtol=1e-9)
    d = sa.bearing_dict("front_pair", 0)["analysis"]["friction"]
    assert d["model"] == "skf" and set(d["rows_Nm"]) == {"balls_A", "balls_B"} and d["power_loss_W"] > 0


def test_drag_of_a_pair_in_an_oil_bath_is_that_of_each_bearing(tmp_path):
    """Both bearings sit in the same bath: each gets the single bearing's drag term at the oil level (with
    the 7209 B's width), and the set's drag is twice it (drag does not depend on the load)."""
    text = (EXAMPLES / "acbb_7209_DB.toml").read_text()
    path = tmp_path / "pair.toml"
    path.write_text(text.replace("[[load_cases]]", '[lubrication]\noil_level = "20 mm"\n\n[[load_cases]]', 1))
    a = bk.analyze(path, speed="3000 rpm", lubricant="ISO_VG68", temperature="60 degC")
    assert a.friction.model == "skf"
    nu = as_lubricant("ISO_VG68").kinematic_viscosity(60.0)
    one = skf.skf_friction_moment(
        "angular_contact_ball",
        bore_diameter=0.045,
        outside_diameter=0.085,
        speed=3000 * RPM,
        kinematic_viscosity=nu,
        load_radial=0.0,
        series="72_BECBP",
        lubrication="oil_bath",
        oil_level=0.020,
        width=0.019,
    )["drag_Nm"]
    assert float(one) > 0
    np.testing.assert_allclose(a.friction.components["drag"], 2 * float(one), rtol=1e-12)
    for res in a.friction.native.per_bearing.values():
        np.testing.assert_allclose(res.components["drag"], float(one), rtol=1e-12)


def test_rating_at_the_found_temperature_names_the_pair_model_and_why():
    args = ["rating", "7209 B DB", "--load", "Fr=3kN", "--load", "Fa=2kN", "--speed", "3000rpm"]
    data = _json([*args, "--lubricant", "ISO_VG68", "--heat", "--json"])
    f = data["cases"][0]["friction"]
    assert f["model"] == "skf" and "matched set (DB)" in f["model_why"] and f["power_loss_W"] > 0
    text = runner.invoke(app, [*args, "--lubricant", "ISO_VG68", "--heat"]).stdout
    assert "friction at the found temperature (skf: matched set (DB)" in " ".join(text.split())


def test_report_shows_the_pair_per_bearing_with_power_and_why(tmp_path):
    out = tmp_path / "r.html"
    res = runner.invoke(app, ["report", *PAIR_CASE, "-o", str(out)])
    assert res.exit_code == 0, res.stderr
    text = " ".join(out.read_text(encoding="utf-8").split())
    assert "skf catalogue model per bearing of the set" in text
    assert "Friction model: skf — matched set (DB) of 2 standard angular contact ball bearings" in text
    power = _json(["friction", *PAIR_CASE, "--json"])["cases"][0]["friction"]["power_loss_W"]
    shown = re.search(r"power loss P = <b>([\d.]+) W</b>", text)
    assert shown and float(shown.group(1)) == pytest.approx(power, rel=1e-3)  # 157.1 W
