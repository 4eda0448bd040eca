"""Every example file loads, solves, converges and is in equilibrium; published geometry is exact.

No example is skipped: every file is in the common input format and its bearing type has a builder.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np
import pytest

from bearingkit.io import export
from bearingkit.io.loader import BUILDERS, load_file

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
# Shaft files (examples/shaft_*.toml) and drivetrain files (a [[shafts]] array: gearbox_two_stage,
# planetary_stage) are systems of several bearings: tests/systems runs them.
FILES = sorted(
    p
    for p in EXAMPLES.glob("*.toml")
    if not p.name.startswith("shaft_") and "shafts" not in tomllib.loads(p.read_text(encoding="utf-8"))
)


def _data(path: Path) -> dict:
    return tomllib.loads(path.read_text())


def _bearing(path: Path):
    return load_file(path)


def _pitch_radius(row) -> float:
    if row.kind == "threaded":
        return row.geometry.pitch_diameter / 2
    return float(np.max(row.pitch_diameter)) / 2


def test_every_example_has_a_registered_type():
    for path in FILES:
        kind = _data(path).get("bearing", {}).get("type")
        assert kind in BUILDERS, f"{path.name}: bearing type {kind!r} has no builder"


def test_there_are_examples_of_every_kind():
    kinds = {_data(f)["bearing"]["type"] for f in FILES}
    assert kinds == set(BUILDERS)


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_example_converges_in_equilibrium(path):
    bearing = _bearing(path)
    assert bearing.cases, "every example carries at least one load case"
    result = bearing.solve()
    assert result.converged.all(), result.reason
    # Sum of the forces the rows carry = the external load (contact forces on the ring = −load).
    carried = sum(result.row_load(row.name) for row in bearing.model.rows)
    load = bearing.load_matrix()
    length = max(_pitch_radius(r) for r in bearing.model.rows)
    scale = np.array([1, 1, 1, 1 / length, 1 / length])  # moments as forces at the pitch radius
    free = bearing.free
    err = np.abs((carried - load) * scale)[:, free].max(axis=1)
    size = np.abs(load * scale).max(axis=1)
    assert np.all(err <= 1e-8 * size), err / size
    data = export.analysis_dict(bearing, result)
    assert export.non_finite_paths(data) == []
    export.to_json(data)  # strict JSON: raises on NaN


def test_seed000_example_is_table_1():
    """Tian et al. (2025) Table 1 and the §6.1.1 clearances, in SI."""
    b = load_file(EXAMPLES / "seed000_composite.toml")
    g = b.model.metadata["geometry"]
    table1 = {
        "bore": 0.120,
        "outer_diameter": 0.210,
        "pitch_diameter_axial_roller": 0.167,
        "pitch_diameter_axial_ball": 0.1778,
        "pitch_diameter_radial_roller": 0.15525,
        "n_axial_rollers": 31,
        "n_axial_balls": 31,
        "n_radial_rollers": 97,
        "axial_roller_diameter": 0.004,
        "axial_roller_length": 0.0048,
        "ball_diameter": 0.006,
        "radial_roller_diameter": 0.005,
        "radial_roller_length": 0.008,
        "groove_curvature": 0.52,
        "clearance_axial_roller": -1e-6,
        "clearance_axial_ball": -5e-6,
    }
    for key, value in table1.items():
        assert g[key] == pytest.approx(value, rel=1e-12), key
    flagship = b.select(["flagship"]).cases[0]
    np.testing.assert_allclose(flagship.load, [3000.0, 0.0, 3000.0, 0.0, -600.0])
    # §6.1.3: 3 kN at e = 0.4 m ↔ 1200 N·m
    assert b.select(["eccentric_0.4m"]).cases[0].load[4] == pytest.approx(-1200.0)


def test_flagship_case_loads_both_axial_rows_and_the_radial_row():
    b = load_file(EXAMPLES / "seed000_composite.toml").select(["flagship"])
    res = b.solve()
    # The negative clearances preload both axial rows; the radial row alone carries F_x.
    for name in ("roller_upper", "ball_upper", "roller_lower", "ball_lower", "roller_radial"):
        assert res.row(name).loaded_count[0] > 0, name
    assert res.row_load("roller_radial")[0, 0] == pytest.approx(3000.0, rel=0.01)
    up = res.row_load("roller_upper")[0, 2] + res.row_load("ball_upper")[0, 2]
    down = res.row_load("roller_lower")[0, 2] + res.row_load("ball_lower")[0, 2]
    assert up > 3000.0 and down < 0.0 and up + down == pytest.approx(3000.0, rel=1e-8)


def test_dgbb_clearance_narrows_the_load_zone():
    """209 DGBB at 8.9 kN: clearance narrows the load zone and raises Q_max above the zero-clearance
    value, which Stribeck's rule puts near 4.37 F_r / Z (Harris & Kotzalas 2007 §7.2)."""
    from bearingkit.io.loader import loads

    text = (EXAMPLES / "dgbb_6209.toml").read_text()
    assert 'clearance_radial = "15 um"' in text
    tight = loads(text.replace('clearance_radial = "15 um"', 'clearance_radial = "0 um"')).solve()
    loose = load_file(EXAMPLES / "dgbb_6209.toml").solve()
    z, f_r = 9, 8900.0
    q_tight, q_loose = tight.rows[0].max_load[0], loose.rows[0].max_load[0]
    assert q_tight * z / f_r == pytest.approx(4.37, rel=0.03)
    assert q_loose > q_tight
    assert loose.rows[0].loaded_count[0] <= tight.rows[0].loaded_count[0]
