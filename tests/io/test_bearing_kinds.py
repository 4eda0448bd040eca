"""Input files of tapered roller, PTRB and ball–column bearings: published geometry in SI, deviations."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.io.loader import from_dict, load_file, loads

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
TRB = (EXAMPLES / "trb_32008.toml").read_text()


def _trb(replace: dict | None = None) -> str:
    text = TRB
    for old, new in (replace or {}).items():
        assert old in text, old
        text = text.replace(old, new)
    return text


def test_trb_example_is_seed001_table_1():
    """Liu et al. (2022) Table 1 in SI; E′ = E/(1 − ν²) with E = 2.1e5 N/mm², ν = 0.278."""
    row = load_file(EXAMPLES / "trb_32008.toml").model.rows[0]
    table1 = {
        "n_elements": 23,
        "small_diameter": 6.131e-3,
        "large_diameter": 6.846e-3,
        "effective_length": 13.66e-3,
        "contact_angle_outer": 0.2473,
        "contact_angle_inner": 0.1949,
        "roller_angle": 0.0262,
        "flange_angle": 1.5621,
        "n_slices": 1,
    }
    for key, value in table1.items():
        assert getattr(row, key) == pytest.approx(value, rel=1e-12), key
    assert row.deviation_model == "taylor"
    assert row.kernel().e_reduced == pytest.approx(2.1e11 / (1 - 0.278**2), rel=1e-12)


def test_trb_series_is_table_2():
    from bearingkit.physics.deviations import seed001_series

    row = load_file(EXAMPLES / "trb_32008.toml").model.rows[0]
    np.testing.assert_array_equal(row.diameter_deviation, seed001_series(1))


def test_deviation_list_with_units():
    values = [f'"{0.1 * (j % 5) - 0.2:.1f} um"' for j in range(23)]
    text = _trb({"diameter_deviation = { series = 1 }": f"diameter_deviation = [{', '.join(values)}]"})
    row = loads(text).model.rows[0]
    expected = np.array([(0.1 * (j % 5) - 0.2) * 1e-6 for j in range(23)])
    np.testing.assert_allclose(row.diameter_deviation, expected, rtol=0, atol=1e-18)


def test_deviation_generator_is_reproducible_and_scaled():
    """ΔD = S_d z with z ~ N(0, 1) (Liu et al. 2022 eq. 14): the same seed scales exactly with S_d."""
    gen = 'diameter_deviation = {{ magnitude = "{m} um", arrangement = "{a}", seed = 7 }}'

    def dev(m, a="random"):
        text = _trb({"diameter_deviation = { series = 1 }": gen.format(m=m, a=a)})
        return loads(text).model.rows[0].diameter_deviation

    one, again, three = dev(1), dev(1), dev(3)
    np.testing.assert_array_equal(one, again)
    np.testing.assert_allclose(three, 3 * one, rtol=1e-12)
    assert one.shape == (23,)
    desc = dev(1, "descending")
    np.testing.assert_array_equal(desc, np.sort(one)[::-1])


@pytest.mark.parametrize(
    "spec, fragment",
    [
        ('["1 um", "2 um"]', "one value per roller"),
        ("[" + ", ".join(['"1 kg"'] * 23) + "]", "diameter_deviation[0]"),
        ('{ magnitude = "1 um" }', "seed is required"),
        ('{ magnitude = "1 um", seed = 1, series = 2 }', "either magnitude"),
        ("{ series = 9 }", "series"),
        ('"1 um"', "must be a list of lengths"),
        ('{ magnitude = "-1 um", seed = 1 }', "non-negative"),
    ],
)
def test_bad_deviation_one_line(spec, fragment):
    text = _trb({"diameter_deviation = { series = 1 }": f"diameter_deviation = {spec}"})
    with pytest.raises(InputError) as err:
        loads(text, "t.toml")
    msg = str(err.value)
    assert "\n" not in msg and msg.startswith("t.toml: geometry"), msg
    assert "diameter_deviation" in msg
    assert fragment in msg


def test_single_tapered_row_refuses_lift_off_load():
    text = _trb({'F_z = "2 kN"': 'F_z = "-2 kN"'})
    with pytest.raises(InputError, match=r"t.toml: load case 'axial_2kN': F_z \(-2000 N\) must be positive"):
        loads(text, "t.toml")


def test_tapered_pair_builds_mirrored_rows():
    """arrangement DB: two rows at ∓row_spacing/2, the −z row resisting +F_z (bearings.tapered)."""
    text = _trb(
        {
            "n_elements = 23": 'arrangement = "DB"\nrow_spacing = "30 mm"\nn_elements = 23',
            'F_z = "2 kN"': 'F_z = "-2 kN"',  # reversing loads are allowed for a pair
        }
    )
    rows = loads(text).model.rows
    assert [r.direction for r in rows] == [1, -1]
    assert [r.axial_position for r in rows] == pytest.approx([-0.015, 0.015], rel=1e-12)
    with pytest.raises(InputError, match="row_spacing"):
        loads(_trb({"n_elements = 23": 'arrangement = "DF"\nn_elements = 23'}))


def test_ptrb_example_is_seed004_table_1():
    from bearingkit.bearings.ptrb import ptrb_prototype

    g = load_file(EXAMPLES / "ptrb_prototype.toml").model.rows[0].geometry
    assert g == ptrb_prototype()  # Table 1 (E = 212 GPa, ν = 0.29 from [material] seed004_steel)


def test_ptrb_envelope_names_map_to_geometry():
    text = (EXAMPLES / "ptrb_prototype.toml").read_text().replace('bore = "30 mm"', 'bore = "37 mm"')
    with pytest.raises(InputError, match="inner_pitch_diameter"):
        loads(text, "p.toml")


def test_ball_column_type_builds_the_seed002_bearing():
    from bearingkit.bearings.ball_column import ROWS, BallColumnGeometry

    data = {
        "bearing": {"type": "ball_column", "name": "seed 002"},
        "geometry": {"contact_angle": "40 deg", "clearance_ball": "10 um", "n_slices": 6},
        "load_cases": [{"name": "radial", "F_x": "20 kN"}],
    }
    b = from_dict(data, "bc.toml")
    assert {r.name for r in b.model.rows} == set(ROWS)
    g = dataclasses.asdict(b.model.metadata["geometry"])
    ref = dataclasses.asdict(
        BallColumnGeometry(contact_angle=math.radians(40.0), clearance_ball=1e-5, n_slices=6)
    )
    for key, value in ref.items():
        assert g[key] == (
            value if value is None or isinstance(value, str) else pytest.approx(value, rel=1e-12)
        ), key
    res = b.solve()
    assert res.converged.all()
    total = sum(res.row_load(n) for n in ROWS)
    assert total[0, 0] == pytest.approx(20e3, rel=1e-9)
    assert b.model.name == "seed 002"


def test_json_schema_lists_the_new_types():
    from bearingkit.io.schema import json_schema

    s = json_schema()
    assert {"tapered_roller", "ptrb", "ball_column"} <= set(
        s["$defs"]["BearingHeader"]["properties"]["type"]["enum"]
    )
    dev = s["$defs"]["geometry_tapered_roller"]["properties"]["diameter_deviation"]
    assert "oneOf" in str(dev)
