"""Studies (issue 35): contamination by ISO 281 level name, factors on any lubricant field, [thermal]."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import bearingkit as bk
from bearingkit.errors import InputError
from bearingkit.studies.definition import load as sd
from bearingkit.studies.run.runner import run_study

DGBB = Path(__file__).resolve().parents[2] / "examples" / "dgbb_6209.toml"
FIXED = {"operating.speed": "3000 rpm", "operating.temperature": "70 degC", "lubricant.name": "ISO_VG68"}


def _run(factors, outputs, fixed=FIXED):
    data = {
        "study": {
            "name": "lube",
            "design": "factorial",
            "bearing": str(DGBB),
            "outputs": outputs,
            "load_case": "radial_4kN",
        },
        "factors": factors,
        "fixed": fixed,
    }
    return run_study(sd.from_dict(data, source="study.toml"), progress=False).results


def test_a_study_takes_contamination_levels_by_name():
    res = _run(
        [{"name": "operating.contamination", "levels": ["normal_cleanliness", "typical_contamination", 0.3]}],
        ["Lnmr_h"],
    )
    # the level's e_C for this bearing (D_pw < 100 mm: the middle of the small-bearing range) …
    np.testing.assert_allclose(res["operating.contamination"], [0.55, 0.2, 0.3])
    # … and the same L_nmr as the command line's level name gives
    for level, lnm in zip(("normal_cleanliness", "typical_contamination"), res["Lnmr_h"], strict=False):
        a = bk.analyze(
            DGBB,
            cases=["radial_4kN"],
            speed="3000 rpm",
            temperature="70 degC",
            lubricant="ISO_VG68",
            contamination=level,
        )
        hours = np.ma.getdata(a.rating.hours(a.rating.modified_life))[0]
        assert lnm == pytest.approx(float(hours), rel=1e-12)
    assert np.all(np.diff(res["Lnmr_h"].to_numpy()[:2]) < 0)


def test_an_unknown_level_name_is_one_line():
    with pytest.raises(InputError) as err:
        _run([{"name": "operating.contamination", "levels": ["normal_cleanlines"]}], ["Lnmr_h"])
    msg = str(err.value)
    assert "normal_cleanlines" in msg and "did you mean 'normal_cleanliness'" in msg and "\n" not in msg


def test_factors_on_lubricant_fields():
    # the base oil changes α_p hence the film, not ν hence not κ
    res = _run(
        [{"name": "lubricant.base_oil", "levels": ["mineral", "ester"]}], ["kappa", "balls_film_min_m"]
    )
    assert res["kappa"].iloc[0] == pytest.approx(res["kappa"].iloc[1], rel=1e-12)
    assert res["balls_film_min_m"].iloc[1] < 0.9 * res["balls_film_min_m"].iloc[0]
    # the viscosity index of an oil given by its data: at 70 °C a VG 68 of VI 150 is thicker than one of VI 95
    fixed = {**{k: v for k, v in FIXED.items() if k != "lubricant.name"}, "lubricant.iso_vg": 68}
    res = _run([{"name": "lubricant.vi", "levels": [95, 150]}], ["kappa"], fixed)
    assert res["kappa"].iloc[1] > 1.1 * res["kappa"].iloc[0]
    ref = bk.analyze(
        DGBB,
        cases=["radial_4kN"],
        speed="3000 rpm",
        temperature="70 degC",
        lubricant={"iso_vg": 68, "vi": 150},
    )
    assert res["kappa"].iloc[1] == pytest.approx(float(ref.lubrication.result.kappa["balls"][0]), rel=1e-12)


def test_a_study_finds_the_temperature_with_a_thermal_section(tmp_path):
    f = tmp_path / "hot.toml"
    f.write_text(DGBB.read_text() + '\n[thermal]\nheat_dissipation = "2 W/K"\n')
    data = {
        "study": {
            "name": "heat",
            "design": "factorial",
            "bearing": str(f),
            "outputs": ["kappa", "power_loss_W"],
            "load_case": "radial_4kN",
        },
        "factors": [{"name": "operating.speed", "levels": ["1500 rpm", "3000 rpm"]}],
        "fixed": {"lubricant.name": "ISO_VG68"},
    }
    res = run_study(sd.from_dict(data, source="study.toml"), progress=False).results
    a = bk.analyze(f, cases=["radial_4kN"], speed="3000 rpm", lubricant="ISO_VG68")
    assert a.thermal is not None
    assert res["power_loss_W"].iloc[1] == pytest.approx(float(a.friction.power_loss[0]), rel=1e-9)
    assert res["kappa"].iloc[1] < res["kappa"].iloc[0]  # faster: warmer, thinner oil and a larger ν1
