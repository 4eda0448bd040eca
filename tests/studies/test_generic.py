"""The generic evaluator: paths into any bearing file, outputs of the Analysis, one batch per geometry."""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.cli import app
from bearingkit.errors import InputError
from bearingkit.studies.definition import load as sd
from bearingkit.studies.run.runner import run_study

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DGBB = EXAMPLES / "dgbb_6209.toml"
OUTPUTS = ["u_x_m", "u_z_m", "balls_max_load_N", "balls_contact_angle_rad", "k_xx_N_per_m", "L10r_rev", "s0"]


def _study(factors, fixed=None, outputs=OUTPUTS, bearing=DGBB, **head):
    data = {
        "study": {
            "name": "generic_probe",
            "design": "factorial",
            "bearing": str(bearing),
            "chunk_size": 100,
            **head,
        },
        "factors": factors,
    }
    if outputs is not None:
        data["study"]["outputs"] = outputs
    if fixed:
        data["fixed"] = fixed
    return data


def _run(data, **kw):
    return run_study(sd.from_dict(data, source="study.toml"), progress=False, **kw)


def test_a_clearance_path_gives_exactly_the_result_of_editing_the_file(tmp_path):
    """geometry.clearance_radial = 23 um in the study ≡ "23 um" in the file, bit for bit."""
    text = DGBB.read_text().replace('clearance_radial = "15 um"', 'clearance_radial = "23 um"')
    assert '"23 um"' in text
    edited = tmp_path / "edited.toml"
    edited.write_text(text)
    res = _run(
        _study([{"name": "geometry.clearance_radial", "levels": ["23 um"]}], load_case="radial_8.9kN")
    ).results
    a = bk.analyze(edited, cases=["radial_8.9kN"])
    rating = a.rating
    assert res["u_x_m"].iloc[0] == a.statics.displacement[0, 0]
    assert res["u_z_m"].iloc[0] == a.statics.displacement[0, 2]
    assert res["k_xx_N_per_m"].iloc[0] == a.statics.stiffness[0, 0, 0]
    assert res["balls_max_load_N"].iloc[0] == a.statics.row("balls").max_load[0]
    assert res["L10r_rev"].iloc[0] == float(rating.life[0])
    assert res["s0"].iloc[0] == float(rating.static_safety[0])
    # and it differs from the file's own 15 um (the path did something)
    own = bk.analyze(DGBB, cases=["radial_8.9kN"]).statics.displacement[0, 0]
    assert res["u_x_m"].iloc[0] != own


def test_load_and_speed_paths_equal_the_analysis_of_those_loads():
    res = _run(
        _study(
            [{"name": "load_cases.radial_4kN.F_x", "levels": ["2 kN", "6 kN"]}],
            fixed={"operating.speed": "1500 rpm"},
            outputs=["u_x_m", "L10r_h"],
        )
    ).results
    for k, f_x in enumerate(("2 kN", "6 kN")):
        a = bk.analyze(DGBB, load={"F_x": f_x}, speed="1500 rpm")
        assert res["u_x_m"].iloc[k] == pytest.approx(a.statics.displacement[0, 0], rel=1e-12)
        assert res["L10r_h"].iloc[k] == pytest.approx(float(a.rating.hours(a.rating.life)[0]), rel=1e-12)


def test_material_constant_of_a_preset_is_set_with_the_others_from_the_preset(tmp_path):
    from bearingkit.materials import MATERIALS

    m = MATERIALS["AISI52100"]
    text = DGBB.read_text().replace(
        'name = "AISI52100"',
        f'youngs_modulus = "190 GPa"\npoisson_ratio = {m.poisson_ratio!r}\ndensity = "{m.density!r} kg/m^3"',
    )
    edited = tmp_path / "e.toml"
    edited.write_text(text)
    res = _run(
        _study([{"name": "material.youngs_modulus", "levels": ["190 GPa"]}], load_case="radial_4kN")
    ).results
    a = bk.analyze(edited, cases=["radial_4kN"])
    assert res["u_x_m"].iloc[0] == a.statics.displacement[0, 0]


def test_cases_sharing_geometry_are_one_analysis(monkeypatch):
    """3 clearances × 4 loads in one chunk: 3 analyses of 4 load cases each, not 12."""
    from bearingkit import pipeline

    calls = []
    real = pipeline.analyze

    def counting(source, **kw):
        calls.append(len(source.cases))
        return real(source, **kw)

    monkeypatch.setattr(pipeline, "analyze", counting)
    res = _run(
        _study(
            [
                {"name": "geometry.clearance_radial", "levels": ["0 um", "15 um", "30 um"]},
                {"name": "load_cases.radial_4kN.F_x", "levels": ["2 kN", "4 kN", "8 kN", "12 kN"]},
            ],
            outputs=["u_x_m"],
        )
    )
    assert sorted(calls) == [4, 4, 4]
    assert len(res.results) == 12


def test_a_group_beyond_the_run_caps_streams_in_runs_with_the_same_results(monkeypatch):
    """The loader caps one run (1,000 cases, 2e6 contact points); a larger group is solved in runs of
    at most that many: 9 balls × 4 = 36 points → runs of 4 cases, the results those of one batch."""
    from bearingkit import pipeline
    from bearingkit.io import loader

    factors = [{"name": "load_cases.design_point.F_x", "levels": [f"{f} kN" for f in range(1, 11)]}]
    outputs, path = [*OUTPUTS, "duty_L10r_rev"], EXAMPLES / "dgbb_6209_duty_cycle.toml"
    whole = _run(_study(factors, outputs=outputs, bearing=path))
    calls = []
    real = pipeline.analyze

    def counting(source, **kw):
        calls.append(len(source.cases))
        return real(source, **kw)

    monkeypatch.setattr(pipeline, "analyze", counting)
    monkeypatch.setattr(loader, "MAX_CASE_POINTS", 36)
    runs = _run(_study(factors, outputs=outputs, bearing=path))
    # 4 bins per case: runs of 36 // 9 // 4 = 1 case, each with its 4 bins (one more analysis)
    assert calls == [1, 4] * 10
    assert (runs.results["error"] == "").all()
    for name in outputs:
        np.testing.assert_allclose(runs.results[name], whole.results[name], rtol=1e-9, err_msg=name)
    calls.clear()
    monkeypatch.setattr(loader, "MAX_CASE_POINTS", 108)  # 3 cases and their bins: 10 cases in 4 runs
    _run(_study(factors, outputs=outputs, bearing=path))
    assert calls == [2, 8, 3, 12, 2, 8, 3, 12]  # of equal sizes, not 3 + 3 + 3 + 1


def test_text_levels_group_the_cases_and_change_the_result():
    res = _run(
        _study(
            [{"name": "lubricant.name", "levels": ["ISO_VG32", "ISO_VG220"]}],
            fixed={"operating.speed": "3000 rpm", "operating.temperature": "70 degC"},
            outputs=["kappa", "friction_torque_Nm"],
            load_case="radial_4kN",
        )
    ).results
    assert res["kappa"].iloc[1] > 4 * res["kappa"].iloc[0]  # VG 220 vs VG 32 at the same temperature


def test_duty_cycle_outputs_equal_the_files_duty_cycle(tmp_path):
    path = EXAMPLES / "dgbb_6209_duty_cycle.toml"
    res = _run(
        _study(
            [{"name": "geometry.clearance_radial", "levels": ["15 um", "30 um"]}],
            fixed={"operating.contamination": 0.5},
            outputs=["duty_L10r_h", "duty_Lnmr_rev", "duty_peak_damage_share"],
            bearing=path,
        )
    ).results
    d = bk.analyze(path, contamination=0.5).duty_cycle  # the file has 15 um
    assert res["duty_L10r_h"].iloc[0] == pytest.approx(d.life_hours, rel=1e-12)
    assert res["duty_Lnmr_rev"].iloc[0] == pytest.approx(d.modified_life, rel=1e-12)
    assert res["duty_peak_damage_share"].iloc[0] == pytest.approx(d.damage_share[2], rel=1e-12)
    assert res["duty_L10r_h"].iloc[1] != res["duty_L10r_h"].iloc[0]


def test_iso281_outputs_come_first_and_equal_the_analysis(tmp_path):
    """ISO 281 lives lead ``--list-outputs`` and equal the bearing's and the duty cycle's ISO 281 lives."""
    path = EXAMPLES / "dgbb_6209_duty_cycle.toml"
    res = CliRunner().invoke(app, ["study", str(path), "--list-outputs"])
    assert res.exit_code == 0, res.stderr
    names = [ln.split()[0] for ln in res.stdout.splitlines()[1:] if ln.strip()]
    assert names[:4] == ["L10_iso281_rev", "L10h_iso281_h", "Lnm_iso281_rev", "Lnm_iso281_h"]
    assert names.index("duty_L10_iso281_rev") < names.index("duty_L10r_rev")
    assert names.index("duty_peak_damage_share_iso281") < names.index("duty_peak_damage_share")
    outputs = ["L10_iso281_rev", "duty_L10h_iso281_h", "duty_Lnm_iso281_rev", "duty_peak_damage_share_iso281"]
    res = _run(
        _study(
            [{"name": "geometry.clearance_radial", "levels": ["15 um", "30 um"]}],
            fixed={"operating.contamination": 0.5},
            outputs=outputs,
            bearing=path,
        )
    ).results
    a = bk.analyze(path, contamination=0.5)  # the file has 15 um
    d = a.duty_cycle
    assert res["L10_iso281_rev"].iloc[0] == pytest.approx(float(a.rating.iso281.life[0]), rel=1e-12)
    assert res["duty_L10h_iso281_h"].iloc[0] == pytest.approx(d.iso281["life_hours"], rel=1e-12)
    assert res["duty_Lnm_iso281_rev"].iloc[0] == pytest.approx(d.iso281["modified_life"], rel=1e-12)
    assert res["duty_peak_damage_share_iso281"].iloc[0] == pytest.approx(
        d.iso281["damage_share"][2], rel=1e-12
    )
    # ISO 281's P does not see the clearance: the ISO 281 lives stay, the TS's would move
    assert res["duty_L10h_iso281_h"].iloc[1] == pytest.approx(res["duty_L10h_iso281_h"].iloc[0], rel=1e-9)


def test_designation_study_adds_a_load_case():
    res = _run(
        _study(
            [{"name": "load_cases.load.F_x", "levels": ["1 kN", "2 kN"]}],
            outputs=["balls_max_load_N", "converged"],
            bearing="6205 C3",
        )
    ).results
    assert res["converged"].all() and res["balls_max_load_N"].iloc[1] > res["balls_max_load_N"].iloc[0]


def test_a_refused_group_gives_nan_and_its_reason_and_the_study_goes_on():
    """A combination only the loader refuses (envelope) fails its group alone, with the reason."""
    res = _run(
        _study(
            [
                {"name": "geometry.element_diameter", "levels": ["12.7 mm", "19 mm"]},
                {"name": "geometry.pitch_diameter", "levels": ["65 mm", "70 mm"]},
            ],
            outputs=["u_x_m", "converged"],
            load_case="radial_4kN",
        )
    ).results
    bad = res["error"] != ""
    assert bad.sum() == 1 and np.isnan(res.loc[bad, "u_x_m"]).all() and not res.loc[bad, "converged"].any()
    assert res.loc[~bad, "converged"].all()
    assert "must lie strictly between bore" in res.loc[bad, "error"].iloc[0]


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (
            {"factors": [{"name": "geometry.clearence_radial", "levels": ["1 um"]}]},
            r"study.toml: factors\[0\].name \('geometry.clearence_radial'\) is not a path of dgbb_6209.toml "
            r"\(bearingkit study --list-factors lists them\); nearest: geometry.clearance_radial",
        ),
        (
            {"factors": [{"name": "geometry.clearance_radial", "levels": ["1 kN"]}]},
            r"factors\[0\] \(geometry.clearance_radial\).levels \('1 kN'\) has dimension .*; expected a len",
        ),
        (
            {"factors": [{"name": "geometry.clearance_radial", "levels": []}]},
            r"factors\[0\] \(geometry.clearance_radial\).levels \(\[\]\) must list at least one value",
        ),
        (
            {"outputs": ["balls_max_lod_N"]},
            r"study.outputs \('balls_max_lod_N'\) is not an output of dgbb_6209.toml; "
            r"nearest: balls_max_load_N",
        ),
        (
            {"load_case": "radial_5kN"},
            r"study.load_case \('radial_5kN'\) is not a load case of the bearing; "
            r"it has radial_8.9kN, radial_4kN",
        ),
        (
            {"load_case": None},
            r"study.load_case: missing; the bearing has load cases radial_8.9kN, radial_4kN",
        ),
        (
            {"fixed": {"operating": {"rotating": "middle"}}},
            r"fixed \('middle'\) must be one of inner, outer for operating.rotating",
        ),
    ],
)
def test_bad_generic_study_files_are_one_line_naming_the_field(tmp_path, change, message):
    data = _study([{"name": "geometry.clearance_radial", "levels": ["1 um"]}], load_case="radial_4kN")
    for key, value in change.items():
        if key in ("outputs", "load_case"):
            if value is None:
                data["study"].pop(key, None)
            else:
                data["study"][key] = value
        else:
            data[key] = value
    with pytest.raises(InputError, match=message) as err:
        sd.from_dict(data, source="study.toml")
    assert "\n" not in str(err.value)


def test_bad_study_on_the_command_line_exits_2_and_writes_no_folder(tmp_path):
    study = tmp_path / "bad.toml"
    study.write_text(
        f'[study]\nname = "bad"\ndesign = "factorial"\nbearing = "{DGBB}"\nload_case = "radial_4kN"\n'
        '[[factors]]\nname = "geometry.clearance_radial"\nlevels = ["5 kg"]\n'
    )
    out = tmp_path / "out"
    res = CliRunner().invoke(app, ["study", str(study), "--out", str(out), "--allow-path", str(DGBB.parent)])
    assert res.exit_code == 2
    assert res.stderr.startswith("error: ") and res.stderr.count("\n") == 1
    assert "factors[0] (geometry.clearance_radial).levels ('5 kg')" in res.stderr
    assert not out.exists()


def test_list_outputs_and_factors_name_units():
    res = CliRunner().invoke(app, ["study", str(EXAMPLES / "crb_nu209.toml"), "--list-outputs"])
    assert res.exit_code == 0, res.stderr
    lines = {ln.split()[0]: ln.split()[1] for ln in res.stdout.splitlines()[1:] if ln.strip()}
    assert lines["k_xx_N_per_m"] == "N/m" and lines["k_thy_thy_Nm_per_rad"] == "N·m/rad"
    assert lines["rollers_max_load_N"] == "N" and lines["L10r_h"] == "h" and lines["s0"] == "-"
    assert "rollers_edge_pressure_ratio" in lines and lines["converged"] == "bool"
    res = CliRunner().invoke(app, ["study", str(DGBB), "--list-factors"])
    assert res.exit_code == 0, res.stderr
    rows = {ln.split()[0]: ln.split()[1:] for ln in res.stdout.splitlines()[1:] if ln.strip()}
    assert rows["geometry.clearance_radial"] == ["m", "file", "1.5e-05"]  # the file's "15 um", 6 digits
    assert rows["lubricant.name"][:2] == ["text", "file"] and "ISO_VG68" in rows["lubricant.name"][-1]
    assert rows["load_cases.radial_4kN.F_x"][:2] == ["N", "case"]
    assert rows["operating.speed"][:2] == ["rad/s", "case"]


def test_study_file_names_a_bearing_relative_to_itself(tmp_path):
    data = tomllib.loads(DGBB.read_text())
    assert data["geometry"]["clearance_radial"] == "15 um"
    (tmp_path / "b.toml").write_text(DGBB.read_text())
    study = tmp_path / "s.toml"
    study.write_text(
        '[study]\nname = "rel"\ndesign = "sweep"\nbearing = "b.toml"\noutputs = ["u_x_m"]\n'
        '[[factors]]\nname = "load_cases.radial_4kN.F_x"\nlevels = ["3 kN"]\n'
    )
    d = sd.load_study(study)
    assert d.bearing == str((tmp_path / "b.toml").resolve()) and d.load_case == "radial_4kN"
    assert d.evaluator == "generic"
    res = run_study(d, progress=False).results
    assert isinstance(res, pd.DataFrame) and len(res) == 1
