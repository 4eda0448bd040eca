"""Shaft-in-shaft bearings and housing seat stiffness: an inner shaft on two bearings inside a hollow
shaft, the hollow shaft on two housing bearings (one through a seat spring); rigid-bearing reactions
against the hand balance."""

from __future__ import annotations

import numpy as np

from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
from bearingkit.systems.drivetrain.input import drivetrain_from_dict

RIGID = {"radial": "1e12 N/m", "axial": "1e12 N/m", "tilt": "0 N*m/rad"}
FREE_AXIAL = {"radial": "1e12 N/m", "axial": "0 N/m", "tilt": "0 N*m/rad"}


def _data(housing=None):
    outer_bearing = {"name": "outer_B", "stiffness": FREE_AXIAL, "position": "200 mm", "axial": "floating"}
    if housing is not None:
        outer_bearing["housing"] = housing
    return {
        "drivetrain": {"name": "coaxial", "held": "outer"},
        "shafts": [
            {
                "name": "outer",
                "sections": [
                    {
                        "start": "0 mm",
                        "length": "200 mm",
                        "outer_diameter": "80 mm",
                        "inner_diameter": "60 mm",
                    }
                ],
                "bearings": [{"name": "outer_A", "stiffness": RIGID, "position": "0 mm"}, outer_bearing],
            },
            {
                "name": "inner",
                "axial_offset": "20 mm",  # inner z = 0 at outer z = 20 mm
                "sections": [{"start": "0 mm", "length": "160 mm", "outer_diameter": "40 mm"}],
                "bearings": [
                    {
                        "name": "in_A",
                        "stiffness": RIGID,
                        "position": "10 mm",
                        "outer": "outer",
                        "outer_position": "30 mm",
                    },
                    {
                        "name": "in_B",
                        "stiffness": FREE_AXIAL,
                        "position": "150 mm",
                        "axial": "floating",
                        "outer": "outer",
                        "outer_position": "170 mm",
                    },
                ],
            },
        ],
        "load_cases": [
            {"name": "P", "forces": [{"shaft": "inner", "position": "45 mm", "F_y": "-3 kN", "F_z": "500 N"}]}
        ],
    }


def test_shaft_in_shaft_reactions_equal_the_hand_balance():
    for housing in (None, {"radial": "2e8 N/m"}):  # a seat spring does not change a determinate support
        res = DrivetrainAnalysis(drivetrain_from_dict(_data(housing), "coaxial")).result
        assert res.converged.all()
        # inner shaft: bearings at z 10 and 150, -3 kN at 45: R_A = 3000 (105/140), R_B = 3000 (35/140)
        ra, rb = 3000 * 105 / 140, 3000 * 35 / 140
        np.testing.assert_allclose(res.reaction("in_A")[0, :3], [0, ra, -500], atol=1e-9 * 3000)
        np.testing.assert_allclose(res.reaction("in_B")[0, :3], [0, rb, 0], atol=1e-9 * 3000)
        # outer shaft: the inner bearings push it down at 30 and 170 mm, housing bearings at 0 and 200 mm
        oa = (ra * (200 - 30) + rb * (200 - 170)) / 200
        ob = (ra * 30 + rb * 170) / 200
        np.testing.assert_allclose(res.reaction("outer_A")[0, :3], [0, oa, -500], atol=1e-9 * 3000)
        np.testing.assert_allclose(res.reaction("outer_B")[0, :3], [0, ob, 0], atol=1e-9 * 3000)
        assert res.equilibrium_residual().max() < 1e-9
