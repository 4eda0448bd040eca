"""Operating conditions end to end: speed, fits and temperatures, tilt, preload, lubrication, bad input."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.pipeline import analyze

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
ACBB = str(EXAMPLES / "acbb_7209.toml")
FITS = str(EXAMPLES / "dgbb_6209_fits.toml")
runner = CliRunner()


def _json(result) -> dict:
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def test_acbb_at_20000_rpm_inner_and_outer_angles_part_and_are_equal_at_rest():
    fast = _json(runner.invoke(app, ["analyze", ACBB, "--speed", "20000rpm", "--json"]))
    rest = _json(runner.invoke(app, ["analyze", ACBB, "--json"]))
    alpha0 = math.radians(40.0)
    for case in fast["cases"]:
        row = case["rows"][0]
        a_i, a_o = np.array(row["contact_angle_inner_rad"]), np.array(row["contact_angle_outer_rad"])
        loaded = np.array(row["loads_N"]) > 0
        assert np.all(a_o[loaded] < a_i[loaded])  # the centrifugal force lowers the outer angle
        assert np.all(a_o[loaded] < alpha0)
        assert min(row["centrifugal_force_N"]) > 0 and row["cage_speed_rad_s"] > 0
    for case in rest["cases"]:
        row = case["rows"][0]
        # at rest: the same keys (issue 40), one contact angle per ball (inner = outer = the statics')
        assert row["contact_angle_inner_rad"] == row["contact_angle_outer_rad"] == row["contact_angle_rad"]
        assert row["cage_speed_rad_s"] is None and max(row["centrifugal_force_N"]) == 0.0
    # The same file solved at 0 rpm through the speed path gives the same angles to 1e-12.
    zero = analyze(ACBB, speed=0.0)
    plain = analyze(ACBB)
    np.testing.assert_allclose(zero.statics.displacement, plain.statics.displacement, rtol=0, atol=0)


def test_6209_k5_fit_and_20K_show_the_clearance_chain():
    """examples/dgbb_6209_fits.toml: k5 shaft, H7 housing, inner ring 60 °C, outer ring 40 °C."""
    data = _json(runner.invoke(app, ["analyze", FITS, "--json"]))
    chain = data["cases"][0]["clearance"]["rows"][0]
    # By hand: mean interference 13.5 µm (k5 +13/+2, bore 0/−12) + 45 mm · (12.0 − 11.9)e-6 · 40 K at 60 °C;
    # Lamé on a solid steel shaft (E 210 GPa, ν 0.3) under an AISI 52100 ring (E 203.4 GPa, ν 0.3)
    # expanding the 52.3 mm raceway; thermal ΔP = α (77.7·20 − 52.3·40 − 2·12.7·30) mm with α 11.9e-6.
    d, d_r, e_r, e_s, nu = 45e-3, 52.3e-3, 29.5e6 * 6894.757293168361, 210e9, 0.3

    def expansion(delta):
        p = delta / (d * ((d_r**2 + d**2) / (d_r**2 - d**2) + nu) / e_r + d * (1 - nu) / e_s)
        return 2 * p * d**2 * d_r / (e_r * (d_r**2 - d**2))

    delta_20 = 13.5e-6
    delta_60 = delta_20 + d * (12.0e-6 - 11.9e-6) * 40.0
    thermal = 11.9e-6 * (77.7e-3 * 20 - 52.3e-3 * 40 - 2 * 12.7e-3 * 30)
    assert chain["mounted_m"] == pytest.approx(15e-6 - expansion(delta_20), rel=1e-10)
    assert chain["operating_m"] == pytest.approx(15e-6 - expansion(delta_60) + thermal, rel=1e-10)
    assert chain["operating_m"] < 0  # the fit and the 20 K take the clearance away: a preload
    warnings = data["cases"][0]["warnings"]
    assert any("clearance lost" in w for w in warnings)
    table = runner.invoke(app, ["analyze", FITS])
    assert table.exit_code == 0 and "mounted" in table.stdout and "operating" in table.stdout


def test_rating_prints_kappa_a_iso_and_lnm():
    result = runner.invoke(app, ["rating", FITS])
    assert result.exit_code == 0, result.stderr
    for word in ("κ", "a_ISO", "L_nm", "normal_cleanliness"):
        assert word in result.stdout
    data = _json(runner.invoke(app, ["rating", FITS, "--json"]))
    lub = data["cases"][0]["lubrication"]
    row = lub["rows"][0]
    assert row["kappa"] > 0 and row["a_ISO"] > 0 and lub["Lnm_rev"] > 0
    # κ = ν/ν1 with ν1 of ISO 281 eq. (27) at 3000 r/min and D_pw = 65 mm: 4500 n^-0.5 D_pw^-0.5 mm²/s.
    nu1 = 4500 * 3000**-0.5 * 65**-0.5 * 1e-6
    assert row["reference_viscosity_m2_s"] == pytest.approx(nu1, rel=1e-12)
    assert row["kappa"] == pytest.approx(lub["viscosity_m2_s"] / nu1, rel=1e-12)


def test_report_shows_the_operating_conditions(tmp_path):
    out = tmp_path / "r.html"
    assert runner.invoke(app, ["report", FITS, "-o", str(out)]).exit_code == 0
    html = out.read_text()
    for word in ("Clearance chain", "a_ISO", "L_nm", "κ"):
        assert word in html


@pytest.mark.parametrize(
    "edit, fragment",
    [
        (('shaft = "k5"', 'shaft = "k55"'), "tolerance field ('k55')"),
        (('temperature = "50 degC"', 'temperature = "-60 degC"'), "below the range of lubricant"),
    ],
)
def test_bad_operating_input_is_one_line(tmp_path, edit, fragment, monkeypatch):
    # a short relative path: the message names the file and is cut at MAX_MESSAGE_CHARS, and the
    # temporary folders of parallel runs (pytest-xdist) are long enough to push the field out
    bad = tmp_path / "bad.toml"
    bad.write_text(Path(FITS).resolve().read_text().replace(*edit))
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, ["rating", "bad.toml"])
    assert result.exit_code == 2, result.stdout
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and fragment in lines[0]


def test_speed_above_the_model_is_a_flagged_non_convergence():
    result = runner.invoke(app, ["analyze", ACBB, "--speed", "60000rpm"])
    assert result.exit_code == 1
    assert "above what the high-speed ball model holds" in result.stderr


def test_single_row_tilt_is_fixed_by_default_and_a_tilt_can_be_imposed(tmp_path):
    a = analyze(ACBB)
    assert not a.setup.free[3] and not a.setup.free[4]
    assert any("tilt fixed" in n for n in a.notes)
    assert np.all(a.statics.displacement[:, 3:] == 0.0)
    tilted = tmp_path / "tilt.toml"
    tilted.write_text(Path(ACBB).read_text() + '\n[operating]\ntilt_y = "0.5 mrad"\n')
    b = analyze(str(tilted))
    assert np.all(b.statics.displacement[:, 4] == pytest.approx(5e-4))
    assert b.statics.converged.all()
    # The moment that holds the misalignment is the reaction on theta_y.
    assert np.all(np.abs(b.statics.load[:, 4]) > 0)


def test_preload_force_of_a_db_pair_is_carried_by_each_row(tmp_path):
    text = (EXAMPLES / "acbb_7209_DB.toml").read_text()
    text = text.replace('clearance_axial = "-5 um"', 'clearance_axial = "0 um"')
    path = tmp_path / "db.toml"
    path.write_text(text + '\n[operating]\npreload_force = "800 N"\n')
    a = analyze(str(path))
    assert a.preload is not None
    for force in a.preload.values():
        assert force == pytest.approx(800.0, rel=1e-6)
    rows = a.statics_dict()["cases"][0]["rows"]
    assert all(r["preload_N"] == pytest.approx(800.0, rel=1e-6) for r in rows)


def test_contamination_level_names_on_a_threaded_roller_bearing():
    """A level name needs the bearing's d_m (ISO 281 Table 13); a threaded roller row keeps it in its
    geometry (the fuzz's `study --list-outputs` on the PTRB ended in an internal error)."""
    from pathlib import Path

    from bearingkit.io.loader import load_file
    from bearingkit.physics.life.iso281_contamination import contamination_factor
    from bearingkit.pipeline.operating_output import contamination_values

    bearing = load_file(Path(__file__).resolve().parents[2] / "examples" / "ptrb_prototype.toml")
    dm = float(bearing.model.rows[0].geometry.pitch_diameter)
    values = contamination_values(bearing)
    assert values["normal_cleanliness"] == contamination_factor("normal_cleanliness", dm)
    assert 0 < values["severe_contamination"] < values["normal_cleanliness"] < 1


def test_a_tapered_bearing_whose_cases_run_at_different_speeds_is_one_analysis(tmp_path):
    """The 32008 with its two load cases at 500 and 8000 r/min: one `analyze` run (formerly refused: a
    tapered row took one speed per solve); each case equals the file run with only that case
    (displacement and roller loads to 1e-9); the speed shows in the rollers' centrifugal force."""
    text = (EXAMPLES / "trb_32008.toml").read_text(encoding="utf-8")
    text = text.replace('F_z = "10 kN"\n', 'F_z = "10 kN"\nspeed = "500 rpm"\n')
    text = text.replace('F_z = "2 kN"\n', 'F_z = "2 kN"\nspeed = "8000 rpm"\n')
    both = tmp_path / "both.toml"
    both.write_text(text, encoding="utf-8")
    full = _json(runner.invoke(app, ["analyze", str(both), "--json"]))
    assert [c["case"] for c in full["cases"]] == ["axial_10kN", "axial_2kN"]
    for case in full["cases"]:
        one = _json(runner.invoke(app, ["analyze", str(both), "--case", case["case"], "--json"]))["cases"][0]
        assert case["converged"] and one["converged"]
        u, ref = np.array(list(case["displacement"].values())), np.array(list(one["displacement"].values()))
        assert np.abs(u - ref).max() <= 1e-9 * np.abs(ref).max()
        q, q_ref = np.array(case["rows"][0]["loads_N"]), np.array(one["rows"][0]["loads_N"])
        assert np.abs(q - q_ref).max() <= 1e-9 * q_ref.max()
    # 500 vs 8000 r/min at the same load: the 8000 r/min case's axial deflection differs
    fast_file = tmp_path / "fast.toml"
    fast_file.write_text(text.replace('"500 rpm"', '"8000 rpm"'), encoding="utf-8")
    out = runner.invoke(app, ["analyze", str(fast_file), "--case", "axial_10kN", "--json"])
    fast = _json(out)["cases"][0]
    slow = full["cases"][0]["displacement"]["u_z_m"]
    assert abs(fast["displacement"]["u_z_m"] - slow) > 1e-6 * abs(slow)
