"""Input files with units: parsing to SI, the builder registry, and one-line errors."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.io import schema
from bearingkit.io.loader import BUILDERS, from_dict, load_file, loads, parse_load_options

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

DGBB = """
[bearing]
type = "deep_groove_ball"
name = "test 209"

[geometry]
bore = "45 mm"
outer_diameter = "85 mm"
n_elements = 9
element_diameter = "0.5 in"
pitch_diameter = "65 mm"
conformity_inner = 0.52
conformity_outer = 0.52
clearance_radial = "15 um"

[[load_cases]]
name = "radial"
F_x = "8.9 kN"
speed = "300 rpm"
temperature = "40 degC"

[solver]
free = ["u_x", "u_y"]
rtol = 1e-11
"""


def test_units_become_si():
    b = loads(DGBB, "t.toml")
    g = b.geometry
    assert g.element_diameter == pytest.approx(0.0127, rel=1e-15)  # 0.5 in exactly
    assert g.clearance_radial == pytest.approx(15e-6, rel=1e-15)
    assert b.model.rows[0].clearance == pytest.approx(15e-6, rel=1e-15)
    case = b.cases[0]
    assert case.speed == pytest.approx(300 * 2 * math.pi / 60, rel=1e-12)
    assert case.temperature == pytest.approx(40.0)
    np.testing.assert_array_equal(case.load, [8900.0, 0, 0, 0, 0])
    np.testing.assert_array_equal(b.free, [True, True, False, False, False])
    assert b.options.rtol == 1e-11
    assert b.model.name == "test 209"


def test_registry_matches_schema_and_builders():
    from bearingkit.bearings import standard, turntable

    assert set(BUILDERS) == set(schema.GEOMETRY_MODELS)
    from bearingkit.io.build.kinds import KINDS  # issue 17: builders in bearings.slewing / self_aligning

    own_builders = {"tapered_roller", "ptrb", "ball_column"} | set(KINDS)  # loader functions over bearings.*
    for name in set(BUILDERS) - own_builders:
        assert hasattr(standard, name) or hasattr(turntable, name)


def test_eccentricity_adds_moment():
    text = DGBB.replace('free = ["u_x", "u_y"]', "").replace(
        'type = "deep_groove_ball"', 'type = "thrust_ball"'
    )
    text = re.sub(r"conformity_inner.*\n|conformity_outer.*\n|clearance_radial.*\n", "", text)
    text = text.replace('F_x = "8.9 kN"', 'F_z = "3 kN"\nM_y = "100 N*m"\neccentricity = "0.2 m"')
    text = text.replace('outer_diameter = "85 mm"', 'outer_diameter = "85 mm"\nconformity = 0.54')
    b = loads(text)
    # Tian et al. 2025 §6.1.3: 3 kN at 0.2 m ↔ 600 N·m; sign M_y = −e F_z (design.md §3)
    assert b.cases[0].load[4] == pytest.approx(100.0 - 0.2 * 3000.0)


def test_material_constants_and_preset_equivalent():
    from bearingkit.materials import get_material

    custom = DGBB + '\n[material]\nyoungs_modulus = "208 GPa"\npoisson_ratio = 0.3\ndensity = "7810 kg/m^3"\n'
    preset = DGBB + '\n[material]\nname = "GCr15"\n'
    a, b = loads(custom), loads(preset)
    gcr15 = get_material("GCr15")
    assert a.material.youngs_modulus == pytest.approx(gcr15.youngs_modulus)
    assert a.model.rows[0].e_reduced == pytest.approx(b.model.rows[0].e_reduced, rel=1e-12)


def test_lubricant_preset():
    b = loads(DGBB + '\n[lubricant]\nname = "ISO_VG100"\n')
    assert b.lubricant.name == "ISO_VG100"


def test_cli_load_aliases():
    c = parse_load_options(["Fa=5kN", "Fr=3 kN", "My=600N*m", "Mx=-2 kN*m", "Fy=1 lbf"])
    np.testing.assert_allclose(c.load, [3000.0, 4.4482216152605, 5000.0, -2000.0, 600.0], rtol=1e-12)
    c = parse_load_options(["F_z=2kN", "e=0.1m"])
    assert c.load[4] == pytest.approx(-200.0)


@pytest.mark.parametrize(
    "items, fragment",
    [
        (["Fa"], "NAME=VALUE"),
        (["Fq=5kN"], "unknown name"),
        (["Fa=5"], "no unit"),
        (["Fa=5 m"], "expected a force"),
        (["Fa=5kN", "Fz=1kN"], "given twice"),
    ],
)
def test_cli_load_errors(items, fragment):
    with pytest.raises(InputError, match=fragment):
        parse_load_options(items)


def _error(text: str) -> str:
    with pytest.raises(InputError) as info:
        loads(text, "bad.toml").solve()
    msg = str(info.value)
    assert "\n" not in msg and msg.startswith("bad.toml: ")
    return msg


@pytest.mark.parametrize(
    "old, new, expected",
    [
        ("[bearing]\n", "[bearing\n", "not valid TOML"),
        ("n_elements = 9\n", "", "geometry.n_elements: missing required field"),
        ("n_elements = 9", "n_elements = 9\nball_count = 9", "geometry.ball_count (9): unknown field"),
        ('"0.5 in"', '"12.7 N"', "geometry.element_diameter ('12.7 N')"),
        ('"0.5 in"', "12.7", "geometry.element_diameter (12.7) has no unit"),
        ('"0.5 in"', '"-12.7 mm"', "geometry.element_diameter ('-12.7 mm') must be positive"),
        ('"0.5 in"', '"twelve"', "geometry.element_diameter ('twelve')"),
        ('"deep_groove_ball"', '"needle"', "bearing.type ('needle') must be one of"),
        ('"85 mm"', '"75 mm"', "row 'balls' spans diameters"),
        (
            "conformity_inner = 0.52",
            "conformity_inner = 0.4",
            "geometry.conformity_inner (0.4) must exceed 0.5",
        ),
        ("n_elements = 9", "n_elements = 9.5", "geometry.n_elements (9.5) must be an integer in [1, 2000]"),
        ("n_elements = 9", "n_elements = 90", "n_elements (90) do not fit on the pitch circle"),
        ('F_x = "8.9 kN"', 'F_x = "8.9 kN*m"', "load_cases[0].F_x ('8.9 kN*m')"),
        ('F_x = "8.9 kN"', 'F_x = "1 kN"\nF_z = "1 kN"', "F_z (1000 N) acts on u_z"),
        ('"40 degC"', '"40"', "load_cases[0].temperature ('40') has no unit"),
        ('free = ["u_x", "u_y"]', 'free = ["u_q"]', "solver.free[0] ('u_q')"),
        ("rtol = 1e-11", "rtol = 2", "solver.rtol (2.0) must lie in (0, 1)"),
        ('name = "radial"', 'name = "radial"\nF_q = "1 N"', "load_cases[0].F_q ('1 N'): unknown field"),
    ],
)
def test_one_line_errors(old, new, expected):
    assert old in DGBB
    assert expected in _error(DGBB.replace(old, new, 1))


def test_material_errors():
    assert "material.name ('unobtainium') must be one of" in _error(
        DGBB + '[material]\nname = "unobtainium"\n'
    )
    msg = _error(DGBB + '[material]\nname = "GCr15"\nyoungs_modulus = "200 GPa"\n')
    assert "material: give either name" in msg
    msg = _error(
        DGBB + '[material]\nyoungs_modulus = "208 GPa"\npoisson_ratio = 0.7\ndensity = "7.8 g/cm^3"\n'
    )
    assert "material.poisson_ratio (0.7)" in msg


def test_profile_and_crowning_errors():
    crb = (EXAMPLES / "crb_nu209.toml").read_text()
    assert "geometry.profile ('banana') must be one of" in _error(crb.replace('"iso16281"', '"banana"'))
    bad = crb.replace('profile = "iso16281"', 'profile = { name = "full_crown", end_drop = "5 kN" }')
    assert "geometry.profile.end_drop ('5 kN')" in _error(bad)
    seed = (EXAMPLES / "seed000_composite.toml").read_text()
    assert "geometry.crowning ('z')" in _error(seed.replace('crowning = "a"', 'crowning = "z"'))
    moved = seed.replace('pitch_diameter_axial_ball = "177.8 mm"', 'pitch_diameter_axial_ball = "205 mm"')
    assert "row 'ball_upper' spans diameters 199–211 mm" in _error(moved)


def test_profile_table_and_string_are_the_same():
    crb = (EXAMPLES / "crb_nu209.toml").read_text()
    a = loads(crb)
    b = loads(crb.replace('profile = "iso16281"', 'profile = { name = "iso16281" }'))
    x = np.linspace(-0.005, 0.005, 7)
    np.testing.assert_array_equal(
        a.model.rows[0].profile.crown_drop(x), b.model.rows[0].profile.crown_drop(x)
    )


def test_unreadable_file(tmp_path):
    with pytest.raises(InputError, match="cannot read the file"):
        load_file(tmp_path / "missing.toml")


def test_select_and_unknown_case():
    b = load_file(EXAMPLES / "seed000_composite.toml")
    assert [c.name for c in b.select(["axial_5kN"]).cases] == ["axial_5kN"]
    with pytest.raises(InputError, match="case \\('nope'\\) not in the file"):
        b.select(["nope"])


def test_no_load_cases():
    text = DGBB.split("[[load_cases]]")[0]
    with pytest.raises(InputError, match="load_cases \\(none\\)"):
        loads(text).solve()


def test_engine_refusal_is_prefixed_with_the_file():
    # The engine refuses a load no row can carry (radial force on a thrust row); the message names the file.
    text = (
        (EXAMPLES / "thrust_ball_51209.toml").read_text().replace('free = ["u_z", "theta_x", "theta_y"]', "")
    )
    text = text.replace('F_z = "10 kN"\n', 'F_z = "10 kN"\nF_x = "1 kN"\n', 1)
    msg = _error(text)
    assert "F_x" in msg


def test_from_dict_rejects_non_tables():
    with pytest.raises(InputError, match="table of sections"):
        from_dict([1, 2], "x")


def test_json_schema_covers_every_type_and_dimension():
    s = schema.json_schema()
    assert s["$defs"]["BearingHeader"]["properties"]["type"]["enum"] == list(schema.GEOMETRY_MODELS)
    assert len(s["allOf"]) == len(schema.GEOMETRY_MODELS)
    dgbb = s["$defs"]["geometry_deep_groove_ball"]
    assert dgbb["properties"]["element_diameter"]["x-dimension"] == "length"
    assert set(dgbb["required"]) == {"n_elements", "element_diameter", "pitch_diameter"}
    assert dgbb["additionalProperties"] is False
    # the default of an optional field is the builder's (not repeated by hand)
    assert "0.52" in dgbb["properties"]["conformity_inner"]["description"]


def test_register_bearing_type_extends_the_format():
    from pydantic import BaseModel, ConfigDict

    from bearingkit.io import loader

    class Geometry(BaseModel):
        model_config = ConfigDict(extra="forbid")
        element_diameter: schema.PositiveLength

    def build(geometry, material, name):
        from bearingkit.bearings.standard import thrust_ball

        return thrust_ball(n_elements=12, element_diameter=geometry["element_diameter"], pitch_diameter=0.05)

    loader.register_bearing_type("test_only_type", Geometry, build)
    try:
        text = '[bearing]\ntype = "test_only_type"\n[geometry]\nelement_diameter = "5 mm"\n'
        b = loads(text)
        assert b.model.rows[0].element_diameter == pytest.approx(0.005)
        assert (
            "test_only_type" in schema.json_schema()["$defs"]["BearingHeader"]["properties"]["type"]["enum"]
        )
        with pytest.raises(InputError, match="already registered"):
            loader.register_bearing_type("test_only_type", Geometry, build)
    finally:
        del loader.BUILDERS["test_only_type"], schema.GEOMETRY_MODELS["test_only_type"]
