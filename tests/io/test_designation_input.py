"""Input files with ``[bearing] designation``: estimate, overrides, calibration and one-line errors."""

import pytest

from bearingkit.catalogue import resolve
from bearingkit.errors import InputError
from bearingkit.io.loader import loads

CASE = '\n[[load_cases]]\nname = "r"\nF_x = "2 kN"\n'


def test_designation_builds_the_estimated_bearing():
    b = loads('[bearing]\ndesignation = "6205-2RS C3"\n' + CASE)
    r = resolve("6205-2RS C3")
    row = b.model.rows[0]
    assert b.bearing_type == "deep_groove_ball" and b.model.name == "6205-2RS C3"
    assert row.n_elements == r.geometry["n_elements"]
    assert float(row.element_diameter) == pytest.approx(r.geometry["element_diameter"])
    assert "ESTIMATED" in b.spec.bearing.source
    assert b.solve().converged.all()


def test_explicit_geometry_overrides_the_estimate():
    b = loads(
        '[bearing]\ndesignation = "6205"\n[geometry]\nn_elements = 9\nelement_diameter = "7.938 mm"\n' + CASE
    )
    row = b.model.rows[0]
    assert row.n_elements == 9 and float(row.element_diameter) == pytest.approx(7.938e-3)
    assert float(row.pitch_diameter) == pytest.approx(resolve("6205").geometry["pitch_diameter"])
    assert "not estimated: element_diameter, n_elements" in b.spec.bearing.source


def test_catalogue_c_calibrates():
    b = loads('[bearing]\ndesignation = "6205"\nC = "14.8 kN"\n' + CASE)
    assert float(b.model.rows[0].element_diameter) == pytest.approx(
        resolve("6205", C=14.8e3).geometry["element_diameter"]
    )


@pytest.mark.parametrize(("position", "fraction"), [('"min"', 0.0), ('"max"', 1.0), ("90", 0.9), ("50", 0.5)])
def test_clearance_position_picks_a_point_of_the_class(position, fraction):
    """ISO 5753-1 C3 of a 25 mm bore deep groove ball bearing is 13-28 um (NSK E1102 Table 9.9)."""
    b = loads(f'[bearing]\ndesignation = "6205 C3"\nclearance_position = {position}\n' + CASE)
    expected = (13 + fraction * (28 - 13)) * 1e-6
    assert float(b.model.rows[0].clearance) == pytest.approx(expected, rel=1e-9)


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ('[bearing]\ndesignation = "6205"\nclearance_position = 120\n', "percentile 0 … 100"),
        ('[bearing]\ndesignation = "6205"\nclearance_position = "median"\n', "clearance_position"),
        ('[bearing]\ntype = "deep_groove_ball"\nclearance_position = 90\n', "give designation"),
        ('[bearing]\ndesignation = "6z05"\n', r"^f\.toml: bearing\.designation \('6z05'\).*nearest: "),
        ('[bearing]\ndesignation = "6205"\ntype = "thrust_ball"\n', "does not match designation"),
        ('[bearing]\ntype = "deep_groove_ball"\nC = "14 kN"\n', "give it together with designation"),
        ("[bearing]\n", "type: missing required field"),
    ],
)
def test_errors_are_one_line(text, match):
    with pytest.raises(InputError, match=match) as exc:
        loads(text + CASE, source="f.toml")
    assert "\n" not in str(exc.value)


@pytest.mark.parametrize(
    ("designation", "bearing_type", "load"),
    [
        ("QJ208", "four_point_contact_ball", 'F_z = "5 kN"'),
        ("1209", "self_aligning_ball", 'F_x = "2 kN"\nF_z = "0.2 kN"'),
        ("2209 K", "self_aligning_ball", 'F_x = "2 kN"'),
        ("22208 E C3", "spherical_roller", 'F_x = "10 kN"\nF_z = "1 kN"'),
        ("NA4906", "needle_roller", 'F_x = "5 kN"'),
        ("RNA4906", "needle_roller", 'F_x = "5 kN"'),
    ],
)
def test_designations_of_the_new_kinds_build_and_carry_the_load(designation, bearing_type, load):
    """Each kind's estimate goes through its io.kinds builder and the solved rows carry the applied load."""
    b = loads(f'[bearing]\ndesignation = "{designation}"\n[[load_cases]]\nname = "c"\n{load}\n')
    assert b.bearing_type == bearing_type and "ESTIMATED" in b.spec.bearing.source
    r = resolve(designation)
    assert sum(row.n_elements for row in b.model.rows) == r.geometry["n_elements"] * r.estimate.rows
    sol = b.solve()
    assert sol.converged.all()
