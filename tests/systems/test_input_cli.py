"""The [shaft] file, the examples, bad input (one line naming the field), the CLI and the plot."""

from __future__ import annotations

import copy
import json
import tomllib
from pathlib import Path

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.systems.shaft.input import load_shaft_file, shaft_dict, shaft_from_dict
from bearingkit.systems.shaft.loads import Gear

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SHAFT_FILES = sorted(EXAMPLES.glob("shaft_*.toml"))
COUNTERSHAFT = EXAMPLES / "shaft_countershaft.toml"


def _data(path=COUNTERSHAFT) -> dict:
    return tomllib.loads(path.read_text())


def _error(data: dict) -> str:
    with pytest.raises(InputError) as info:
        shaft_from_dict(data, "bad.toml", base=EXAMPLES)
    message = str(info.value)
    assert "\n" not in message and message.startswith("bad.toml: ")
    return message


def test_there_are_both_example_shafts():
    assert {p.name for p in SHAFT_FILES} >= {"shaft_countershaft.toml", "shaft_spindle.toml"}


@pytest.mark.parametrize("path", SHAFT_FILES, ids=[p.stem for p in SHAFT_FILES])
def test_example_shafts_converge_in_equilibrium_with_lives(path):
    inp = load_shaft_file(path)
    res = inp.solve()
    assert res.converged.all(), res.reason
    assert np.all(res.equilibrium_residual() <= 1e-9)
    data = json.loads(json.dumps(shaft_dict(inp, res)))  # strict JSON
    for case in data["cases"]:
        assert case["rating"]["system"]["L10r_rev"] > 0
        lives = [b["L10r_rev"] for b in case["rating"]["bearings"].values()]
        assert case["rating"]["system"]["L10r_rev"] < min(lives)  # a system outlives none of its bearings
        assert all(v is not None and v > 0 for v in case["friction_Nm"].values())


def test_countershaft_reactions_balance_the_gear_forces():
    inp = load_shaft_file(COUNTERSHAFT)
    res = inp.solve()
    gears = {g.name: g for g in inp.system.gears}
    for c in range(res.n_cases):
        applied = sum(gears[n].load(t[c] if np.ndim(t) else t)[0] for n, t in inp.loads.gear_torques.items())
        weight = (res.assembly.mesh.mass + sum(g.mass for g in gears.values())) * inp.loads.gravity
        applied[:3] += weight
        for f in inp.loads.forces:
            applied += f.load[c]
        reactions = sum(res.reaction(b.name)[c] for b in inp.system.bearings)
        assert np.allclose(reactions[:3], -applied[:3], rtol=0, atol=1e-8 * np.abs(applied).max())


def test_gear_mesh_forces():
    """Shigley ch. 13: F_t = 2T/d, F_r = F_t tan α_n / cos β, F_a = F_t tan β; moment (d/2) F_a."""
    d, t, alpha, beta = 0.2, 300.0, np.deg2rad(20.0), np.deg2rad(15.0)
    g = Gear("g", 0.0, d, alpha, beta, mesh_angle=0.0)
    f = g.load([t])[0]
    ft = 2 * t / d
    assert f[1] == pytest.approx(ft)  # tangential at φ = 0 is +y
    assert f[0] == pytest.approx(-ft * np.tan(alpha) / np.cos(beta))  # radial towards the centre
    assert f[2] == pytest.approx(ft * np.tan(beta))
    assert f[4] == pytest.approx(-d / 2 * f[2]) and f[3] == pytest.approx(0.0, abs=1e-12)


def test_bearing_outside_the_shaft():
    data = _data()
    data["shaft"]["bearings"][1]["position"] = "300 mm"
    message = _error(data)
    assert "bearings[1].position" in message and "outside the shaft" in message


def test_overlapping_sections():
    data = _data()
    data["shaft"]["sections"][1]["start"] = "20 mm"
    message = _error(data)
    assert "shaft.sections[1].start" in message and "overlaps" in message


def test_no_axial_locating_bearing():
    data = _data()
    data["shaft"]["bearings"][0]["axial"] = "floating"
    message = _error(data)
    assert "no axial locating bearing" in message and "bearings" in message


def test_other_bad_fields_name_themselves():
    cases = {
        ("shaft", "bearings", 0, "orientation"): ("up", "shaft.bearings[0].orientation"),
        ("shaft", "gears", 0, "pitch_diameter"): ("180", "shaft.gears[0].pitch_diameter"),
        ("shaft", "sections", 0, "outer_diameter"): ("-45 mm", "shaft.sections[0].outer_diameter"),
        ("shaft", "bearings", 0, "file"): ("missing.toml", "shaft.bearings[0] (A).file"),
        ("shaft", "bearings", 0, "colour"): ("red", "shaft.bearings[0].colour"),
    }
    for path, (value, field) in cases.items():
        data = copy.deepcopy(_data())
        node = data
        for p in path[:-1]:
            node = node[p]
        node[path[-1]] = value
        assert field in _error(data), field
    data = _data()
    data["load_cases"][0]["gears"] = {"no_such_gear": "10 N*m"}
    assert "gears.no_such_gear" in _error(data)


def _cli(*args):
    """The command run in-process by typer's CliRunner (the code path of a subprocess without Python's
    start-up, which the start-up tests cover): returncode, stdout and stderr as a subprocess gives them."""
    from types import SimpleNamespace

    from typer.testing import CliRunner

    from bearingkit.cli import app

    result = CliRunner().invoke(app, [str(a) for a in args])
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise result.exception
    return SimpleNamespace(returncode=result.exit_code, stdout=result.stdout, stderr=result.stderr)


def test_cli_shaft_json_plot_and_stiffness(tmp_path):
    out = _cli(
        "shaft",
        str(COUNTERSHAFT),
        "--json",
        "--plot",
        str(tmp_path / "cs.png"),
        "--stiffness",
        str(tmp_path / "k.csv"),
    )
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert [c["case"] for c in data["cases"]] == ["rated", "half_load", "rated_with_coupling_misalignment"]
    case = data["cases"][0]
    assert {b["name"] for b in case["bearings"]} == {"A", "B"}
    assert set(case["bearings"][0]["reaction_on_shaft"]) == {"F_x_N", "F_y_N", "F_z_N", "M_x_Nm", "M_y_Nm"}
    assert (tmp_path / "cs_rated.png").stat().st_size > 10_000
    import pandas as pd

    table = pd.read_csv(tmp_path / "k.csv")
    assert len(table) == 2 * 3 and set(table["bearing"]) == {"A", "B"}
    row = table[(table["bearing"] == "A") & (table["point"] == "rated")].iloc[0]
    assert row["K_ux_uy_N_per_m"] == pytest.approx(row["K_uy_ux_N_per_m"], rel=1e-6)  # symmetric K
    assert row["K_ux_ux_N_per_m"] == pytest.approx(case["bearings"][0]["stiffness_SI"][0][0], rel=1e-12)


def test_cli_shaft_bad_file_is_one_line(tmp_path):
    data = COUNTERSHAFT.read_text().replace('position = "237.5 mm"', 'position = "400 mm"')
    bad = tmp_path / "bad_shaft.toml"
    bad.write_text(data)
    (tmp_path / "dgbb_6209.toml").write_text((EXAMPLES / "dgbb_6209.toml").read_text())
    (tmp_path / "crb_nu209.toml").write_text((EXAMPLES / "crb_nu209.toml").read_text())
    out = _cli("shaft", str(bad))
    assert out.returncode == 2
    assert out.stderr.count("\n") == 1 and "bearings[1].position" in out.stderr


def test_plot_draws_the_lines():
    from bearingkit.report.systems.shaft_plots import shaft_figure

    res = load_shaft_file(COUNTERSHAFT).solve()
    fig = shaft_figure(res, 0)
    deflection, moment = fig.axes[1], fig.axes[2]
    _z, m = res.moment_line()
    assert np.allclose(moment.lines[2].get_ydata(), np.hypot(m[0, :, 0], m[0, :, 1]))
    assert np.allclose(deflection.lines[0].get_ydata(), res.displacement[0, :, 0] * 1e6)
    assert shaft_figure(res, 1).axes[1].get_title().endswith("deflection of the shaft axis")


def test_bearing_by_designation_equals_its_catalogue_input():
    """A seat given by designation uses the catalogue's estimated bearing, as a file would."""
    from bearingkit.io.loader import from_dict

    data = _data()
    del data["shaft"]["bearings"][0]["file"]
    data["shaft"]["bearings"][0]["designation"] = "6209"
    inp = shaft_from_dict(data, "designation.toml", base=EXAMPLES)
    assert inp.system.bearing("A").bearing.name == from_dict({"bearing": {"designation": "6209"}}).model.name
    res = inp.solve()
    assert res.converged.all()
    data["shaft"]["bearings"][0]["file"] = "dgbb_6209.toml"
    assert "exactly one of file" in _error(data)


def test_a_tiny_element_length_is_refused_before_meshing():
    """max_element_length = 1e-9 mm asked for 2.5e8 elements (the fuzz found 9 TiB allocations)."""
    data = _data()
    data["shaft"]["max_element_length"] = "1e-9 mm"
    message = _error(data)
    assert "shaft.max_element_length" in message and "more than 5000 elements" in message
    data["shaft"]["max_element_length"] = "0.1 mm"  # 2,500 elements of a 250 mm shaft: allowed
    assert shaft_from_dict(data, "fine.toml", base=EXAMPLES).system.max_element_length == pytest.approx(1e-4)
