"""``system FILE --ross DIR`` and ``shaft FILE --ross DIR``: one ROSS rotor file per shaft that ROSS loads,
and a drivetrain's shaft gives the critical speeds of the same shaft exported by ``shaft --ross``.

The same shaft (a 40 mm bar on a 6208 and an NU 208, a 6 kg disc of 120 mm, a force at mid-span) is
written once as a shaft file and once as a one-shaft drivetrain; two load cases at 1000 and 6000 rpm give
speed-indexed bearing elements. Marked ``slow`` (``make test-slow``, CI): ~35 s with ROSS's start-up;
tests/systems/test_ross_export.py (also slow) checks the export of one shaft's critical speeds.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from bearingkit.cli.commands import app
from bearingkit.errors import InputError

# One test process runs every ROSS test (--dist loadgroup): importing ROSS takes 12-20 s, paid once instead
# of once per process. The two rotor tests are slow (make test-slow); the refusals and the speed table
# need no ROSS and run in make test.
pytestmark = [pytest.mark.ross, pytest.mark.xdist_group("ross")]
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

_SECTIONS = """sections = [{ start = "0 mm", length = "300 mm", outer_diameter = "40 mm" }]
bearings = [
  { name = "A", designation = "6208", position = "20 mm", axial = "locating" },
  { name = "B", designation = "NU 208", position = "280 mm", axial = "floating" },
]
"""
SHAFT = f"""[shaft]
name = "line"
max_element_length = "20 mm"
{_SECTIONS}gears = [{{ name = "disc", position = "150 mm", pitch_diameter = "120 mm", mass = "6 kg" }}]
[[load_cases]]
name = "slow"
speed = "1000 rpm"
forces = [{{ name = "F", position = "150 mm", F_y = "-4 kN", F_z = "300 N" }}]
[[load_cases]]
name = "fast"
speed = "6000 rpm"
forces = [{{ name = "F", position = "150 mm", F_y = "-8 kN", F_z = "300 N" }}]
"""
DRIVE = f"""[drivetrain]
name = "one shaft"
held = "line"
[[shafts]]
name = "line"
max_element_length = "20 mm"
{_SECTIONS}[[shafts.gears]]
name = "disc"
position = "150 mm"
teeth = 40
normal_module = "3 mm"
face_width = "20 mm"
mass = "6 kg"
[[load_cases]]
name = "slow"
speed = {{ line = "1000 rpm" }}
forces = [{{ shaft = "line", name = "F", position = "150 mm", F_y = "-4 kN", F_z = "300 N" }}]
[[load_cases]]
name = "fast"
speed = {{ line = "6000 rpm" }}
forces = [{{ shaft = "line", name = "F", position = "150 mm", F_y = "-8 kN", F_z = "300 N" }}]
"""


def _ross():
    from bearingkit.systems.ross import import_ross

    try:
        return import_ross()
    except InputError:
        if os.environ.get("CI"):
            pytest.fail("ross-rotordynamics must be installed in CI (make test-slow installs [ross])")
        pytest.skip("ross-rotordynamics not installed (pip install 'bearingkit[ross]')")


def _critical(rotor):
    return np.sort(rotor.run_critical_speed(num_modes=6).wn())[:2]


@pytest.mark.slow  # ROSS's start-up and two rotors: ~24 s; test_ross_export.py checks the export of one shaft
def test_system_ross_rotors_load_and_match_the_shaft_export(tmp_path):
    rs = _ross()
    (tmp_path / "shaft.toml").write_text(SHAFT, encoding="utf-8")
    (tmp_path / "drive.toml").write_text(DRIVE, encoding="utf-8")
    runner = CliRunner()
    out = runner.invoke(app, ["system", str(tmp_path / "drive.toml"), "--ross", str(tmp_path / "system")])
    assert out.exit_code == 0, out.output
    assert "wrote" in out.output and "ROSS rotor 'line'" in out.output
    out = runner.invoke(app, ["shaft", str(tmp_path / "shaft.toml"), "--ross", str(tmp_path / "shaft")])
    assert out.exit_code == 0, out.output
    from_system = rs.Rotor.load(tmp_path / "system" / "line.toml")
    from_shaft = rs.Rotor.load(tmp_path / "shaft" / "line.toml")
    for rotor in (from_system, from_shaft):
        assert len(rotor.bearing_elements) == 2 and len(rotor.disk_elements) == 1
        assert sum(e.L for e in rotor.shaft_elements) == pytest.approx(0.3, rel=1e-12)  # the 300 mm bar
        assert max(e.L for e in rotor.shaft_elements) <= 0.02 + 1e-12  # max_element_length
        # speed-indexed: the two cases' stiffness at their speeds (1000, 6000 rpm)
        for b in rotor.bearing_elements:
            axis = getattr(b, "speed", None)
            axis = b.frequency if axis is None else axis
            np.testing.assert_allclose(np.sort(axis), np.array([1000.0, 6000.0]) * np.pi / 30, rtol=1e-12)
    # the same shaft, the same bearing stiffness (two solvers: round-off apart) ...
    for a, b in zip(from_system.bearing_elements, from_shaft.bearing_elements, strict=True):
        assert a.tag == b.tag
        for k in ("kxx", "kyy", "kxy", "kzz"):
            np.testing.assert_allclose(
                np.asarray(getattr(a, k)), np.asarray(getattr(b, k)), rtol=1e-6, atol=1e-3
            )
    # ... so the same critical speeds
    np.testing.assert_allclose(_critical(from_system), _critical(from_shaft), rtol=1e-6)


def test_ross_folder_refusals_are_one_line_before_any_work(tmp_path):
    a_file = tmp_path / "taken.toml"
    a_file.write_text("x", encoding="utf-8")
    out = CliRunner().invoke(app, ["system", str(EXAMPLES / "planetary_stage.toml"), "--ross", str(a_file)])
    assert out.exit_code == 2 and "--ross" in out.output and "must name a folder, not a file" in out.output
    assert len(out.output.strip().splitlines()) == 1


def test_cases_by_speed_keeps_the_first_case_of_each_speed():
    from bearingkit.systems.ross import cases_by_speed

    assert cases_by_speed([10.0, 10.0, -20.0, 20.0, 0.0]) == [0, 2, 4]
    assert cases_by_speed([0.0, 0.0]) == [0]


@pytest.mark.slow  # four rotors loaded by ROSS: ~11 s
def test_every_shaft_of_the_two_stage_gearbox_becomes_a_rotor_ross_loads(tmp_path):
    rs = _ross()
    out = CliRunner().invoke(
        app, ["system", str(EXAMPLES / "gearbox_two_stage.toml"), "--ross", str(tmp_path / "r"), "--json"]
    )
    assert out.exit_code == 0, out.output
    import json

    data = json.loads(out.output)
    shafts = sorted(s["name"] for s in data["inputs"]["shafts"])
    assert sorted(p.stem for p in (tmp_path / "r").glob("*.toml")) == shafts
    bearings = {s: [b["name"] for b in data["inputs"]["bearings"] if b["inner"] == s] for s in shafts}
    for s in shafts:
        rotor = rs.Rotor.load(tmp_path / "r" / f"{s}.toml")
        assert sorted(b.tag for b in rotor.bearing_elements) == sorted(bearings[s])
    assert any("gear meshes' stiffness between the shafts is not in them" in n for n in data["notes"])
