"""Stiffness tables over load and speed: tangent property, speed dependence, CSV/JSON files."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bearingkit.analysis.solver.quasistatic import solve
from bearingkit.errors import InputError
from bearingkit.io.loader import load_file
from bearingkit.systems.shaft.stiffness import bearing_stiffness_table, stiffness_column

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
RADIAL = np.array([[1e3, 0, 0, 0, 0], [2e3, 1e3, 0, 0, 0], [4e3, 0, 0, 0, 0]])


def test_ball_bearing_table_is_the_tangent_and_follows_speed():
    bearing = load_file(EXAMPLES / "dgbb_6209.toml")
    speeds = np.array([0.0, 100.0, 1000.0])
    table = bearing_stiffness_table(bearing.model, RADIAL, speeds, free=bearing.free)
    assert len(table) == 9 and table.converged.all()
    k = table.stiffness.reshape(3, 3, 5, 5)
    # speed enters through the balls' centrifugal force (as in analyze --speed): the outer contacts
    # carry more, and the stiffness changes, little at 100 rad/s and more at 1000 rad/s
    change = np.abs(k[:, 1:, 0, 0] / k[:, :1, 0, 0] - 1)
    assert (change[:, 0] < change[:, 1]).all() and (change[:, 1] > 1e-3).all()
    # Tangent: a small load step moves the ring by K⁻¹ ΔF (radial block; the other DOFs are held).
    step = np.array([5.0, -3.0, 0, 0, 0])
    a = solve(bearing.model, RADIAL[1], free=bearing.free)
    b = solve(bearing.model, RADIAL[1] + step, free=bearing.free)
    du = (b.displacement - a.displacement)[0, :2]
    kr = table.radial()[3]  # load 1, speed 0
    assert np.allclose(kr @ du, step[:2], rtol=2e-3, atol=1e-3 * np.abs(step).max())
    assert kr[0, 1] == pytest.approx(kr[1, 0], rel=1e-9) and abs(kr[0, 1]) > 1e-3 * kr[0, 0]
    # Hertz contacts stiffen with load.
    assert k[0, 0, 0, 0] < k[2, 0, 0, 0]


def test_tapered_table_changes_with_speed():
    """Roller centrifugal force (TaperedRow.speed) changes the tapered bearing's stiffness."""
    bearing = load_file(EXAMPLES / "trb_32008.toml")
    loads = np.array([[2e3, 0, 5e3, 0, 0]])
    table = bearing_stiffness_table(bearing.model, loads, [0.0, 2000.0], free=bearing.free)
    assert table.converged.all()
    k0, k1 = table.stiffness
    assert abs(k1[2, 2] / k0[2, 2] - 1) > 1e-4


def test_table_files(tmp_path):
    bearing = load_file(EXAMPLES / "dgbb_6209.toml")
    table = bearing_stiffness_table(bearing.model, RADIAL[:2], [0.0, 50.0], free=bearing.free)
    table.write(tmp_path / "k.csv")
    table.write(tmp_path / "k.json")
    csv = pd.read_csv(tmp_path / "k.csv")
    assert len(csv) == 4
    assert np.allclose(csv[stiffness_column(0, 1)], table.stiffness[:, 0, 1], rtol=1e-12)
    assert stiffness_column(3, 0) == "K_thx_ux_N" and stiffness_column(4, 3) == "K_thy_thx_Nm_per_rad"
    data = json.loads((tmp_path / "k.json").read_text())
    assert data["points"][1]["speed_rad_s"] == 50.0
    assert data["points"][2]["radial_N_per_m"]["k_xx"] == pytest.approx(table.stiffness[2, 0, 0])
    with pytest.raises(InputError, match=r"must end in \.csv or \.json"):
        table.write(tmp_path / "k.txt")


def test_ball_rows_soften_at_speed_in_the_table_as_in_analyze():
    """The stiffness table takes the same speed effects as ``analyze --speed`` (ball centrifugal force
    and gyroscopic moment), not only tapered rows': a 7209 B at 20,000 rpm is far softer radially."""
    import bearingkit as bk

    path = Path(__file__).resolve().parents[2] / "examples" / "acbb_7209.toml"
    model = load_file(path).model
    load = np.array([[1000.0, 0.0, 2000.0, 0.0, 0.0]])
    w = 20_000 * 2 * np.pi / 60
    grid = bearing_stiffness_table(model, load, speeds=[0.0, w], free=[True, True, True, False, False])
    assert grid.converged.all()
    at_rest, at_speed = grid.stiffness[0], grid.stiffness[1]
    ref = bk.analyze(str(path), load={"F_x": "1 kN", "F_z": "2 kN"}, speed="20000 rpm").statics
    assert at_speed == pytest.approx(ref.stiffness[0], rel=1e-9, abs=1e-6 * np.abs(ref.stiffness[0]).max())
    assert at_speed[0, 0] < 0.5 * at_rest[0, 0]  # centrifugal force unloads the inner contacts
