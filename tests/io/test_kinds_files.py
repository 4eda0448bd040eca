"""Input files of the bearing kinds: JSON Schema with units, and bad input refused in one line."""

import json
from pathlib import Path

import pytest

from bearingkit.errors import InputError
from bearingkit.io.build.kinds import KINDS
from bearingkit.io.loader import loads

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_json_schema_has_every_kind_with_units():
    from typer.testing import CliRunner

    from bearingkit.cli import app

    result = CliRunner().invoke(app, ["schema"])
    assert result.exit_code == 0, result.output
    out = result.stdout
    schema = json.loads(out)
    assert set(KINDS) <= set(schema["$defs"]["BearingHeader"]["properties"]["type"]["enum"])
    srb = schema["$defs"]["geometry_spherical_roller"]["properties"]
    assert srb["contact_angle"]["x-si-unit"] == "rad" and srb["effective_length"]["x-si-unit"] == "m"
    assert "contact_angle" in schema["$defs"]["geometry_spherical_roller"]["required"]


def _file(kind: str, geometry: str, load: str = 'F_x = "1 kN"') -> str:
    return f'[bearing]\ntype = "{kind}"\n[geometry]\n{geometry}\n[[load_cases]]\nname = "a"\n{load}\n'


SRB = (
    'n_elements = 19\nelement_diameter = "21 mm"\neffective_length = "19 mm"\npitch_diameter = "140 mm"\n'
    'contact_angle = "10 deg"\n'
)
SLEW = 'n_elements = 100\nelement_diameter = "25 mm"\npitch_diameter = "1000 mm"\n'
CROSS = 'element_diameter = "16 mm"\neffective_length = "14 mm"\npitch_diameter = "800 mm"\n'

BAD = [
    (_file("slewing_ring_four_point", SLEW + "conformity_inner = 0.5"), "geometry.conformity_inner"),
    (_file("four_point_contact_ball", SLEW + 'contact_angle = "0 deg"'), "geometry.contact_angle"),
    (_file("spherical_roller", SRB + "osculation_outer = 1.0"), "geometry.osculation_outer"),
    (_file("spherical_roller", SRB.replace('"19 mm"', '"40 mm"')), "geometry.effective_length"),
    (_file("slewing_ring_crossed_roller", CROSS + "n_elements = 121"), "geometry.n_elements"),
    (_file("slewing_ring_crossed_roller", CROSS + "n_elements = 200"), "geometry.n_elements"),
    (
        _file(
            "self_aligning_ball",
            'n_elements = 15\nelement_diameter = "9.525 mm"\npitch_diameter = "65 mm"\n'
            'contact_angle = "12 deg"\nconformity_inner = 0.45',
        ),
        "geometry.conformity_inner",
    ),
    (
        _file(
            "needle_roller",
            'n_elements = 40\nelement_diameter = "4 mm"\neffective_length = "6 mm"\npitch_diameter = "61 mm"',
        ),
        "geometry.effective_length",
    ),
    (_file("spherical_roller", SRB, load='F_x = "1 kN"\nM_y = "100 N*m"'), "load M_y"),
    (_file("spherical_roller", SRB, load='F_x = "nan kN"'), "load_cases[0].F_x"),
]


@pytest.mark.parametrize("text,field", BAD, ids=[b[1] + f"-{i}" for i, b in enumerate(BAD)])
def test_bad_kind_input_is_one_line_naming_the_field(text, field):
    with pytest.raises(InputError) as err:
        bearing = loads(text, source="bad.toml")
        bearing.solve()
    message = str(err.value)
    assert "\n" not in message and field in message, message
