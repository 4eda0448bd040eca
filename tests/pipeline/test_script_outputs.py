"""Outputs a script relies on (issue 40 item 6): to_pandas with every headline quantity, the same JSON keys
at every speed, rounded inputs, one copy of each warning, reactions apart from loads."""

from __future__ import annotations

import io
import re

import numpy as np
import pytest
from rich.console import Console

import bearingkit as bk
from bearingkit.catalogue import tables

RPM = np.pi / 30.0


def test_to_pandas_has_both_lives_friction_and_power():
    """Must-show: bk.analyze("6208", load={"F_x": "5 kN"}, speed="1000 rpm").to_pandas()."""
    df = bk.analyze("6208", load={"F_x": "5 kN"}, speed="1000 rpm").to_pandas()
    for col in ("L10h_iso281_h", "L10r_h", "friction_torque_Nm", "power_loss_W", "friction_model"):
        assert col in df.columns, col
    # ISO 281 by hand: L10 = (C/P)^3 with the catalogue C of 6208 and P = F_r (F_a = 0), in hours at n.
    c = tables.entries("deep_groove_ball")["6208"].C
    assert df["L10h_iso281_h"][0] == pytest.approx((c / 5000.0) ** 3 * 1e6 / (60 * 1000), rel=1e-9)
    assert np.isfinite(df["L10r_h"][0]) and df["friction_model"][0] == "skf"
    assert np.isnan(df["friction_torque_Nm"][0])  # no lubricant given: the notes say why


def test_to_pandas_with_a_lubricant_carries_every_headline_quantity():
    a = bk.analyze(
        "6208",
        load={"F_x": "5 kN"},
        speed="1000 rpm",
        lubricant="ISO_VG68",
        temperature="60 degC",
        contamination=0.5,
    )
    df = a.to_pandas()
    d = a.rating.to_dict(0)["system"]
    assert df["L10_iso281_rev"][0] == d["L10_iso281_rev"] and df["Lnm_iso281_h"][0] == d["Lnm_iso281_h"]
    assert df["L10r_rev"][0] == d["L10r_rev"] and df["Lnmr_h"][0] == d["Lnmr_h"]
    assert df["a_ISO_iso281"][0] == d["a_ISO_iso281"] and df["a_ISO"][0] > 0
    assert df["kappa"][0] == pytest.approx(float(a.lubrication.result.kappa["balls"][0]))
    assert df["static_safety"][0] == d["static_safety"]
    assert df["p_max_Pa"][0] == pytest.approx(float(a.statics.rows[0].max_pressure.max()))
    assert df["friction_torque_Nm"][0] == a.friction.total[0] > 0
    assert df["power_loss_W"][0] == pytest.approx(a.friction.total[0] * 1000 * RPM, rel=1e-12)
    for k, name in enumerate(("k_xx_N_per_m", "k_yy_N_per_m", "k_zz_N_per_m")):
        assert df[name][0] == a.statics.stiffness[0, k, k]
    assert "balls_operating_clearance_m" in df.columns
    assert df["limiting_speed_rad_s"][0] == pytest.approx(a.limits.limiting_speed)
    assert not df["above_limiting_speed"][0]


def test_json_row_keys_are_the_same_at_every_speed():
    keys, angles = [], []
    for speed in ("0 rpm", "10 rpm", "3000 rpm"):
        row = bk.analyze("7209 B", load={"F_z": "3 kN"}, speed=speed).statics_dict()["cases"][0]["rows"][0]
        keys.append(set(row))
        angles.append(row)
    assert keys[0] == keys[1] == keys[2]
    rest = angles[0]
    assert rest["contact_angle_inner_rad"] == rest["contact_angle_outer_rad"] == rest["contact_angle_rad"]
    assert angles[2]["contact_angle_inner_rad"] != angles[2]["contact_angle_outer_rad"]  # parted at speed


def test_estimated_inputs_are_written_rounded():
    a = bk.analyze("6308-2RS C3", load={"F_x": "1 kN"})
    geometry = a.input.spec.geometry
    assert geometry["element_diameter"] == "0.0155 m" and geometry["clearance_radial"] == "2.4e-05 m"
    assert not any(re.search(r"\d{13,}", str(v)) for v in geometry.values())
    assert bk.analyze("7209 B", load={"F_z": "1 kN"}).input.spec.geometry["contact_angle"] == "40 deg"


def test_run_flagship_prints_each_warning_once():
    from bearingkit.cli.flagship import run_sections

    out = io.StringIO()
    run_sections(Console(file=out, width=200), report_path=None)
    lines = [ln.strip() for ln in out.getvalue().splitlines() if ln.strip().startswith("warning:")]
    assert lines and len(lines) == len(set(lines))


def test_the_report_lists_the_reaction_of_a_fixed_tilt_apart_from_the_load(tmp_path):
    a = bk.analyze("7209 B", load={"F_x": "3 kN", "F_z": "2 kN"})
    assert not a.statics.free[4] and abs(a.statics.load[0, 4]) > 1.0  # a reaction moment holds the tilt
    html = a.report(tmp_path / "r.html").read_text(encoding="utf-8")
    load_table = html.split("Load and displacement of the inner ring</h4>")[1].split("</table>")[0]
    assert "held" in load_table
    assert 'class="fixed-dof-reactions"' in html and "Reaction at the fixed DOFs" in html
