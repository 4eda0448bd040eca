"""The FVA two-stage industrial gearbox against another tool's solution: FVA Workbench 8.1.

Reference: the results model ``fva_2-stage_industry-gearbox_1-4_results.rexsj`` (REXS 1.4, FVA Workbench
"8.1.0 - DEV", 2023-06-23) in the public repository fva-net/rexs-diff
(``Sample_Data/REXS-Database/01_Perfect/FVA_2-stage_industry-gearbox/``, commit ffff65a4b7e8); the
repository states no licence, so the file is not copied here and only the numbers below are quoted from
it. Its operating point: −1000 N·m at −1000 rpm into shaft [6], gravity along v, no other load.

bearingkit solves the same gearbox from its Apache-2.0 copy written by Bearinx
(examples/rexs/FVA-Industriegetriebe_2stufig_1-4.rexs) at that operating point. What must agree whatever
the two tools' bearing models: the speeds of the tooth counts, and the gear forces on the shafts, which
follow from the gear geometry (working pitch radii, pressure and helix angles and their signs, the axes)
and the torque each gear carries. FVA Workbench's gear torques include its losses (998.18 N·m at gear
[27], 1868.08 N·m at gear [44] against the lossless 1000 and 1888.89): bearingkit's lossless mesh forces
scaled by those torques equal FVA Workbench's to 1e-7 (7e-8 measured). The bearing reactions' sizes are
not compared: the two models differ there (docs/drivetrains.md gives the table and the causes); the one-way
bearings' push directions are, as they confirm how ``axial_force_absorption`` reads.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from bearingkit.io.rexs.reader import REXS_NOTES, read_rexs
from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
from bearingkit.systems.drivetrain.input import drivetrain_from_dict

FVA = Path(__file__).resolve().parents[2] / "examples" / "rexs" / "FVA-Industriegetriebe_2stufig_1-4.rexs"
#: FVA Workbench's force acting on the shaft (u, v, w) [N] of gears [27] and [44], and the torque that
#: gear carries [N·m] (its stage gear data [93], [95]), from the results model (module docstring).
FVA_WORKBENCH = {
    "Cylindrical stage [24]": (
        (-5888.341744216401, 15177.050018615802, 6381.791074791002),
        998.1829050686082,
    ),
    "Cylindrical stage [41]": (
        (-4339.655246403399, 24366.301576493104, -9733.5564355599),
        1868.0831208649224,
    ),
}
#: FVA Workbench's shaft speeds [rpm] for −1000 rpm at shaft [6].
FVA_SPEEDS = {"Shaft [6]": -1000.0, "Shaft [25]": 529.4117647058823, "Shaft [42]": -358.13148788927333}


@pytest.fixture(scope="module")
def solved():
    data = read_rexs(FVA)
    data.pop(REXS_NOTES, None)
    case = {
        "name": "FVA Workbench operating point",
        "torques": {"Shaft [6]": "-1000 N*m"},
        "speed": {"Shaft [6]": "-1000 rpm"},
        "temperature": "70 degC",
    }
    data["load_cases"] = [case]
    data["drivetrain"]["gravity"] = "+x"  # the results model: direction_vector_gravity (u, v, w) = (0, 1, 0)
    return DrivetrainAnalysis(drivetrain_from_dict(data, str(FVA), base=FVA.parent))


def test_the_shaft_speeds_are_fva_workbench_s(solved):
    for shaft, rpm in FVA_SPEEDS.items():
        assert solved.omega[shaft][0] * 60 / (2 * np.pi) == pytest.approx(rpm, rel=1e-12)


def test_the_gear_forces_are_fva_workbench_s_at_its_gear_torques(solved):
    res = solved.result
    lossless = {"Cylindrical stage [24]": 1000.0, "Cylindrical stage [41]": 1000.0 * 51 / 27}
    assert solved.to_dict()["cases"][0]["converged"]
    for mesh, (force, torque) in FVA_WORKBENCH.items():
        x, y, z = res.mesh_vector(mesh, "a")[0]  # on gear a ([27], [44]); bearingkit x, y, z = v, w, u
        ours = np.array([z, x, y]) * torque / lossless[mesh]
        assert np.linalg.norm(ours - force) < 1e-7 * np.linalg.norm(force)


def test_the_one_way_bearings_push_as_fva_workbench_s(solved):
    """REXS axial_force_absorption: FVA Workbench's solution pushes the countershaft back along −u at the
    'positive' 33016 [60] (−3669.7 N on the shaft) and along +u at the 'negative' [35] (+2121.1 N: the
    induced axial force of its tapered row). The Bearinx copy's concept bearings have no induced force:
    the gear forces (+1511 N along u on the shaft, net) press it against [60] alone, and [35], which can
    only push along +u, carries nothing where a both-way spring would pull."""
    res = solved.result
    names = {b.name.split("(")[-1].rstrip(")"): b.name for b in res.drivetrain.bearings}
    f35 = res.reaction(names["Rolling bearing [35]"])[0, 2]
    f60 = res.reaction(names["Rolling bearing [60]"])[0, 2]
    net = sum(
        res.mesh_vector(m, side)[0, 2]
        for m, side in (("Cylindrical stage [24]", "b"), ("Cylindrical stage [41]", "a"))
    )
    assert f35 == 0.0
    assert f60 == pytest.approx(-net, rel=1e-9) and f60 < 0  # as FVA Workbench's −3669.7 N: along −u
