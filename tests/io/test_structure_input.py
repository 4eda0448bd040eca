"""[structure] in input files: every bearing type takes it, the CLI shows rigid beside flexible, bad
matrices and a [geometry.ring] on another bearing are one line (exit 2), its numbers are study factors."""

import tomllib
from pathlib import Path

import numpy as np
import pytest
import scipy.io
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.errors import InputError
from bearingkit.io.loader import from_dict, load_file, loads

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
HOUSED = EXAMPLES / "dgbb_6209_thin_housing.toml"
runner = CliRunner()


def _data(name="dgbb_6209.toml") -> dict:
    return tomllib.loads((EXAMPLES / name).read_text())


def test_the_example_builds_a_grooved_ring_on_its_housing():
    b = load_file(HOUSED)
    ring = b.structure.outer
    assert b.structure.inner is None
    assert ring.section.centroid_radius == pytest.approx(0.0397, abs=1e-3)
    # the seat: E t b / R_h² of a 3 mm steel wall around 85 mm, 19 mm wide, with its twist k_r b²/12
    k_h = 2.08e11 * 0.003 * 0.019 / (0.0425 + 0.0015) ** 2
    assert ring.foundation.radial == pytest.approx(k_h, rel=1e-12)
    assert ring.foundation.twist == pytest.approx(k_h * 0.019**2 / 12, rel=1e-9)
    assert (ring.foundation.axial, ring.foundation.tangential) == (1e9, 1e8)


def test_cli_shows_the_flexible_distribution_beside_the_rigid_one():
    out = runner.invoke(app, ["analyze", str(HOUSED)])
    assert out.exit_code == 0, out.output
    assert "rigid → flexible rings" in out.output and "3 → 5" in out.output
    js = runner.invoke(app, ["analyze", str(HOUSED), "--json"])
    import json

    case = json.loads(js.output)["cases"][1]["flexible"]
    comp = case["rigid_vs_flexible"]["balls"]
    assert comp["loaded_count_rigid"] == 3 and comp["loaded_count_flexible"] == 5
    assert comp["max_load_flexible_N"] < comp["max_load_rigid_N"]
    ring = case["structure"]["rings"][0]
    assert len(ring["radial_deflection_m"]) == 72 and ring["max_fibre_stress_Pa"] > 0
    assert case["change"]["static_safety_flexible"] > case["change"]["static_safety_rigid"]
    assert 0 <= case["coupling"]["force_balance"] <= 1e-9  # Σ element forces = the load
    assert "equilibrium" in out.output


def test_geometry_ring_on_another_bearing_points_to_structure(tmp_path):
    data = (EXAMPLES / "dgbb_6209.toml").read_text() + "\n[geometry.ring]\nflexible = true\n"
    path = tmp_path / "ring.toml"
    path.write_text(data.replace("[solver]", "[solver]", 1))
    out = runner.invoke(app, ["analyze", str(path)])
    assert out.exit_code == 2
    assert "[structure.outer]" in out.output and "\n" not in out.output.strip()


def _imported(tmp_path, matrix, nodes, **fields):
    data = _data()
    scipy.io.mmwrite(str(tmp_path / "k.mtx"), matrix, precision=17)
    np.savetxt(tmp_path / "nodes.csv", nodes, delimiter=",")
    data["structure"] = {"imported": {"matrix": "k.mtx", "nodes": "nodes.csv", **fields}}
    path = tmp_path / "imported.toml"
    import tomli_w

    path.write_bytes(tomli_w.dumps(data).encode())
    return path


def _ring_nodes(n=9, r=0.0325):
    psi = 2 * np.pi * np.arange(n) / n
    return np.stack([r * np.cos(psi), r * np.sin(psi), 0 * psi], -1)


@pytest.mark.parametrize(
    "matrix,nodes,message",
    [
        (np.eye(27) * 1e9 + np.triu(np.ones((27, 27)), 1) * 1e7, _ring_nodes(), "not symmetric"),
        (np.diag(np.r_[np.ones(26), 0.0]) * 1e9, _ring_nodes(), "singular"),
        (np.eye(24) * 1e9, _ring_nodes(8), "8 nodes for 9 elements"),
        (np.eye(27) * 1e9, _ring_nodes(10), "does not match the nodes"),
    ],
    ids=["non-symmetric", "singular", "node-count", "size"],
)
def test_bad_matrices_are_one_line_exit_2(tmp_path, matrix, nodes, message):
    path = _imported(tmp_path, matrix, nodes)
    out = runner.invoke(app, ["analyze", str(path)])
    assert out.exit_code == 2
    text = out.output.strip()
    assert message in text and "\n" not in text and str(path) in text


def test_structure_fields_are_checked():
    base = (EXAMPLES / "dgbb_6209.toml").read_text()
    for extra, message in (
        ('[structure.outer]\nsection = "grooved"\nwidth = "19 mm"\n', "groove_depth"),
        ('[structure.outer]\nseat_stiffness = "1e9 N/m^2"\n', "width"),
        ("[structure]\n", "structure (empty)"),
        ('[structure.outer]\nwidth = "19 mm"\nstiffness_scale = -1\n', "stiffness_scale"),
    ):
        with pytest.raises(InputError, match=message.replace("(", r"\(").replace(")", r"\)")):
            loads(base + "\n" + extra, "f.toml")


def test_structure_numbers_are_study_factors():
    from bearingkit.studies.generic.paths import apply, input_paths

    b = load_file(HOUSED)
    paths = input_paths(b)
    for p in (
        "structure.outer.stiffness_scale",
        "structure.outer.seat_wall_thickness",
        "structure.outer.width",
    ):
        assert paths[p].kind == "file", p
    assert paths["structure.outer.seat_wall_thickness"].dimension == "length"
    flange = input_paths(load_file(EXAMPLES / "slewing_four_point_flange.toml"))
    assert flange["structure.inner.flange.bolt_stiffness"].dimension == "stiffness"
    assert flange["structure.outer.flange.face_stiffness"].dimension == "pressure"
    data = apply(_data("dgbb_6209_thin_housing.toml"), {"structure.outer.stiffness_scale": 1e6}, paths)
    stiff = from_dict(data, "study")
    assert stiff.structure.outer.stiffness_scale == 1e6


@pytest.mark.slow  # ~8 s; make test keeps the factor parsing (test_structure_numbers_are_study_factors)
def test_a_study_over_the_housing_wall(tmp_path):
    """examples/studies/dgbb_6209_housing_wall.toml: the peak ball load rises with the wall's thickness
    towards the rigid solve's (2084.5 N at 4 kN), s0 and the life fall with it (the flexible rating)."""
    import pandas as pd

    out = runner.invoke(
        app, ["study", str(EXAMPLES / "studies" / "dgbb_6209_housing_wall.toml"), "--out", str(tmp_path)]
    )
    assert out.exit_code == 0, out.output
    d = pd.read_parquet(tmp_path / "results.parquet").sort_values("structure.outer.seat_wall_thickness")
    q = d["balls_max_load_N"].to_numpy()
    assert d["converged"].all() and np.all(np.diff(q) > 0)
    assert q[-1] == pytest.approx(2084.46, rel=0.02) and q[0] < 0.9 * 2084.46
    assert np.all(np.diff(d["s0"].to_numpy()) < 0) and np.all(np.diff(d["L10r_h"].to_numpy()) < 0)


@pytest.mark.parametrize(
    "name,message",
    [
        ("/etc/passwd", "lies outside this file's folder"),
        ("../../k.mtx", "lies outside this file's folder"),
        ("~/k.mtx", "'~' is not expanded"),
        (".hidden/k.mtx", "names a hidden file or folder"),
    ],
    ids=["absolute", "two-folders-up", "home", "hidden"],
)
def test_imported_files_are_confined_to_the_input_files_folder(tmp_path, name, message):
    """A data file may come from someone else: the FE export it names is confined as a study's bearing
    path is (docs/security.md) — refused in one line before it is opened, even where the file exists
    and holds a good matrix (``../../k.mtx`` here)."""
    nodes = _ring_nodes()
    scipy.io.mmwrite(str(tmp_path / "k.mtx"), np.eye(27) * 1e9, precision=17)
    folder = tmp_path / "a" / "b"
    (folder / ".hidden").mkdir(parents=True)
    scipy.io.mmwrite(str(folder / ".hidden" / "k.mtx"), np.eye(27) * 1e9, precision=17)
    np.savetxt(folder / "nodes.csv", nodes, delimiter=",")
    data = _data()
    data["structure"] = {"imported": {"matrix": name, "nodes": "nodes.csv"}}
    import tomli_w

    path = folder / "imported.toml"
    path.write_bytes(tomli_w.dumps(data).encode())
    out = runner.invoke(app, ["analyze", str(path)])
    assert out.exit_code == 2
    text = " ".join(out.output.split())
    assert text.startswith(f"error: {path}: structure.imported.matrix ({name!r})")
    assert message in text and "--allow-path" not in text
    # the same export beside the input file is read (the confinement refuses only what lies outside)
    scipy.io.mmwrite(str(folder / "k.mtx"), np.eye(27) * 1e9, precision=17)
    data["structure"]["imported"]["matrix"] = "k.mtx"
    path.write_bytes(tomli_w.dumps(data).encode())
    out = runner.invoke(app, ["analyze", str(path)])
    assert out.exit_code == 0 and "rigid → flexible rings" in out.output
