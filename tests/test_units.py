"""Units at the edge: pint strings to SI floats, one-line errors naming field, value and dimension."""

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearingkit.errors import InputError
from bearingkit.units import parse


@pytest.mark.parametrize(
    ("text", "dimension", "expected"),
    [
        ("5 kN", "force", 5000.0),
        ("-2 um", "length", -2e-6),
        ("600 N*m", "moment", 600.0),
        ("5 rpm", "angular_velocity", 5 * 2 * math.pi / 60),
        ("0.04 Pa*s", "dynamic_viscosity", 0.04),
        ("0.0246 mm^2/N", "compliance", 2.46e-8),
        ("0.0246 mm^2/N", "pressure_viscosity", 2.46e-8),
        ("4200 MPa", "pressure", 4.2e9),
        ("40 degC", "temperature", 40.0),
        ("90 deg", "angle", math.pi / 2),
        ("68 mm^2/s", "kinematic_viscosity", 68e-6),
    ],
)
def test_parse_to_si(text, dimension, expected):
    assert parse(text, dimension, "field") == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    ("value", "dimension", "match"),
    [
        ("5 kg", "force", "expected force"),
        ("5", "length", "no unit"),
        (5.0, "length", "no unit"),
        ("5 furlongs_per_fortnight", "length", "not a quantity"),
        ("nan mm", "length", "finite"),
        (True, "force", "must be a quantity"),
        ("3 mm", "dimensionless", "dimensionless"),
    ],
)
def test_bad_units_are_one_line_errors_naming_the_field(value, dimension, match):
    with pytest.raises(InputError, match=match) as err:
        parse(value, dimension, "geometry.ball_diameter")
    msg = str(err.value)
    assert "\n" not in msg and msg.startswith("geometry.ball_diameter")


def test_dimensionless_accepts_bare_numbers():
    assert parse(0.52, "dimensionless", "groove_curvature") == 0.52
    assert parse("0.52", "dimensionless", "groove_curvature") == 0.52


@given(st.floats(-1e6, 1e6, allow_nan=False))
def test_mm_round_trip(x):
    assert parse(f"{x!r} mm", "length", "x") == pytest.approx(x / 1000.0, rel=1e-12, abs=1e-300)
