"""The ``shaft`` study evaluator: load level, speed level, bearing choice, spacing and axial adjustment of a
shaft file, one shaft solve per study case; checked against the statics of a shaft on two supports."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bearingkit.errors import InputError
from bearingkit.studies.generic.shaft import SHAFT, edit

ROOT = Path(__file__).resolve().parents[2]
COUNTERSHAFT = ROOT / "examples" / "shaft_countershaft.toml"
#: A weightless shaft on two linear bearings without tilt stiffness (statically determinate): a radial
#: force of 1 kN at z = 50 mm between supports at 0 and 200 mm.
TWO_SUPPORTS = """
[shaft]
name = "two supports"
[[shaft.sections]]
start = "0 mm"
length = "200 mm"
outer_diameter = "40 mm"
[[shaft.bearings]]
name = "A"
position = "0 mm"
stiffness = { radial = "2e8 N/m", axial = "1e8 N/m" }
[[shaft.bearings]]
name = "B"
position = "200 mm"
axial = "floating"
stiffness = { radial = "2e8 N/m" }
[[load_cases]]
name = "radial"
forces = [{ name = "F", position = "50 mm", F_x = "1 kN" }]
"""


def _cases(path, **columns) -> pd.DataFrame:
    n = max(len(v) for v in columns.values())
    return pd.DataFrame({"file": [str(path)] * n, **columns})


def test_load_scale_and_spacing_follow_the_lever_rule(tmp_path):
    path = tmp_path / "two_supports.toml"
    path.write_text(TWO_SUPPORTS, encoding="utf-8")
    out = SHAFT(
        _cases(path, load_scale=[1.0, 2.0, 1.0], bearing=["", "", "B"], position_change=[0.0, 0.0, -0.1])
    )
    assert out["converged"].all()
    # lever rule (no moments at the supports): R_A = F (z_B - z_F) / (z_B - z_A), the larger reaction
    f, z_f = 1000.0, 0.05
    expected = [f * (0.2 - z_f) / 0.2, 2 * f * (0.2 - z_f) / 0.2, f * (0.1 - z_f) / 0.1]
    assert out["max_bearing_radial_load_N"].to_numpy() == pytest.approx(expected, rel=1e-9)
    # linear bearings have no rows: no lives or pressures (NaN), not a made-up number
    assert out[["system_L10h_h", "min_bearing_L10h_h", "max_pressure_Pa"]].isna().all().all()
    assert out[["system_L10h_iso281_h", "system_Lnmh_iso281_h"]].isna().all().all()


def test_heavier_load_shortens_and_a_bigger_bearing_lengthens_the_life():
    out = SHAFT(
        _cases(
            COUNTERSHAFT,
            load_scale=[1.0, 1.5, 1.0],
            bearing=["", "", "A"],
            designation=["", "", "6309"],
        )
    )
    assert out["converged"].all()
    base, heavy, bigger = out["min_bearing_L10h_h"]
    assert heavy < base / 1.5**3 * 1.2  # ball life ∝ P^-3 (the gears' weight is not scaled: a bit above)
    assert heavy < base and bigger > base  # the 6309 (C 53 kN) for the 6209 (C 31.5 kN) at bearing A
    assert np.all(out["system_L10h_h"] <= out["min_bearing_L10h_h"] * (1 + 1e-12))  # a system of bearings
    # ISO 281 first: its system life is the shaft analysis's, and shorter than its shortest bearing's
    assert list(out.columns[:2]) == ["system_L10h_iso281_h", "system_Lnmh_iso281_h"]
    assert np.all(out["system_L10h_iso281_h"] <= out["min_bearing_L10h_iso281_h"] * (1 + 1e-12))
    from bearingkit.systems.shaft.input import load_shaft_file
    from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis

    cases = ShaftAnalysis(load_shaft_file(COUNTERSHAFT)).to_dict()["cases"]
    ref = min(c["rating"]["system"]["L10h_iso281_h"] for c in cases)
    assert out["system_L10h_iso281_h"].iloc[0] == pytest.approx(ref, rel=1e-12)


def test_edit_scales_every_load_and_refuses_an_unknown_bearing():
    from bearingkit.io.reading import load_toml

    data = load_toml(COUNTERSHAFT)
    row = {"load_scale": 2.0, "speed_scale": 0.5, "bearing": "", "designation": "", "position_change": 0.0,
           "axial_offset_change": 0.0}  # fmt: skip
    edited = edit(data, row)
    assert edited["load_cases"][0]["gears"]["input_gear"] == f"{500.0!r} N*m"
    assert edited["load_cases"][2]["forces"][0]["F_x"] == f"{600.0!r} N"
    assert edited["load_cases"][2]["forces"][0]["M_y"] == f"{30.0!r} N*m"
    assert edited["load_cases"][0]["speed"] == f"{1000 * np.pi / 30 * 0.5!r} rad/s"
    assert data["load_cases"][0]["gears"]["input_gear"] == "250 N*m"  # the parsed file is left as it was
    with pytest.raises(InputError, match=r"bearing \('C'\) is no bearing of the shaft file"):
        edit(data, {**row, "bearing": "C", "designation": "6309"})
    with pytest.raises(InputError, match="give the bearing"):
        edit(data, {**row, "designation": "6309"})
