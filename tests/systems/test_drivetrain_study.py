"""The ``drivetrain`` study evaluator: gear ratio, bearing choice, preload and duty-cycle level of a
drivetrain file, one solve per study case."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bearingkit.studies.generic.drivetrain import DRIVETRAIN

GEARBOX = Path(__file__).resolve().parents[2] / "examples" / "gearbox_two_stage.toml"


@pytest.mark.slow
def test_torque_scale_and_bearing_choice_move_the_lives_the_right_way():
    cases = pd.DataFrame(
        {
            "file": [str(GEARBOX)] * 3,
            "torque_scale": [1.0, 2.0, 1.0],
            "bearing": ["", "", "intermediate_A"],
            "designation": ["", "", "6310"],
        }
    )
    out = DRIVETRAIN(cases)
    assert out["converged"].all()
    base, double, bigger = out["system_L10h_h"]
    assert double < base / 4  # life ∝ P^-3 for balls: twice the load, about an eighth of the life
    assert bigger > base  # a 6310 for the 6210 carrying the intermediate shaft's thrust
    assert np.all((out["efficiency"] > 0.9) & (out["efficiency"] < 1.0))


def test_a_ratio_change_keeps_the_centre_distance_and_refuses_an_unknown_gear():
    from bearingkit.errors import InputError
    from bearingkit.io.reading import load_toml
    from bearingkit.studies.generic.drivetrain import _edit

    row = {
        "torque_scale": 1.0,
        "speed_scale": 1.0,
        "ratio_gear": "pinion_1",
        "ratio_teeth": 20,
        "bearing": "",
        "designation": "",
        "axial_offset": 0.0,
    }
    data = _edit(load_toml(GEARBOX), row)
    teeth = {g["name"]: g["teeth"] for s in data["shafts"] for g in s["gears"]}
    assert (teeth["pinion_1"], teeth["wheel_1"]) == (20, 60)
    with pytest.raises(InputError, match="ratio_gear"):
        _edit(load_toml(GEARBOX), {**row, "ratio_gear": "nope"})
