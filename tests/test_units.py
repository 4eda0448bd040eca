"""Units at the edge: pint strings to SI floats, one-line errors naming field, value and dimension."""

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearingkit.errors import InputError
from bearingkit.units import ABSOLUTE_ZERO_C, COMMON_UNITS, parse


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
        ("5 kg", "force", "expected a force"),
        ("5", "length", "no unit"),
        (5.0, "length", "no unit"),
        ("5 furlongs_per_fortnight", "length", "unknown unit"),
        ("nan mm", "length", "finite"),
        (True, "force", "must be a quantity"),
        ("3 mm", "dimensionless", "pure number"),
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


@pytest.mark.parametrize(
    "value",
    [
        "9**9**9 N",  # pint's expression evaluator: minutes (issue 24)
        "10**400 N",  # OverflowError (issue 23)
        "1" * 100_000 + " N",  # quadratic in pint: 48 s (issue 24)
        "x" * 100_000,
        "a" * 30 + " N",  # a 30-letter nonsense unit
        "2 kN + 3 N",
        "0x10 N",
        "(((((N)))))",
        "5 N^999",
        "５ kN",  # fullwidth digit: Python's float() would read it
    ],
)
def test_only_number_and_unit_syntax_reaches_pint(value, monkeypatch):
    """Issue 24 item 5: text outside 'number [unit]' is refused before pint sees it (the syntax check
    is a bounded regular expression on at most MAX_VALUE_CHARS characters), in one short line."""
    import bearingkit.units as units_module

    seen = []
    real = units_module._unit.__wrapped__
    monkeypatch.setattr(units_module, "_unit", lambda text: seen.append(text) or real(text))
    with pytest.raises(InputError) as err:
        parse(value, "force", "load_cases[0].F_x")
    msg = str(err.value)
    assert msg.startswith("load_cases[0].F_x (") and "\n" not in msg and len(msg) <= 300, msg
    if len(value) > units_module.MAX_VALUE_CHARS or "**" in value or "+" in value or "x1" in value:
        assert seen == []  # refused by the syntax check alone


def test_nonsense_unit_names_within_the_syntax_are_one_line_errors():
    with pytest.raises(InputError, match="unknown unit 'aaaaaaaaaaaaaaaaaaaaaaaaaaaaaa'"):
        parse("1 " + "a" * 30, "force", "F_x")


@pytest.mark.parametrize(
    ("text", "dimension", "suggested"),
    [
        ("2 kn", "force", "'2 kN'"),  # knots (issue 23)
        ("2 KN", "force", "'2 kN'"),  # not a unit
        ("600 nM", "moment", "'600 N*m'"),  # nanomolar is no moment
        ("5 MM", "length", "'5 mm'"),
        ("208 gpa", "pressure", "'208 GPa'"),
        ("5 RPM", "angular_velocity", "'5 rpm'"),
    ],
)
def test_unit_lookalikes_of_the_expected_dimension_are_suggested(text, dimension, suggested):
    with pytest.raises(InputError) as err:
        parse(text, dimension, "F_x")
    assert f"did you mean {suggested}?" in str(err.value)


def test_no_suggestion_from_another_dimension():
    """'5 m' for a force is not a typo of 'mN': no look-alike is offered below the cutoff."""
    with pytest.raises(InputError) as err:
        parse("5 m", "force", "F_x")
    assert "did you mean" not in str(err.value)


def test_every_lookalike_converts_to_its_dimension():
    from bearingkit.units import SI_UNITS, UNIT_LOOKALIKES

    assert set(UNIT_LOOKALIKES) == set(SI_UNITS)
    for dimension, names in UNIT_LOOKALIKES.items():
        for name in names:
            assert math.isfinite(parse(f"1 {name}", dimension, "x")), (dimension, name)


@pytest.mark.parametrize(
    ("text", "dimension", "expected"),
    [
        ("5kN", "force", 5000.0),
        (".5 N", "force", 0.5),
        ("+3E3 N", "force", 3000.0),
        ("1e-6 m", "length", 1e-6),
        ("2e-8 1/Pa", "pressure_viscosity", 2e-8),
        ("0.04 W/(m*K)", "thermal_conductivity", 0.04),
        ("600 N·m", "moment", 600.0),
        ("600 N m", "moment", 600.0),
        ("2 mm^2/s", "kinematic_viscosity", 2e-6),
        ("2 mm**2/s", "kinematic_viscosity", 2e-6),
        ("5 µm", "length", 5e-6),
        ("5 μm", "length", 5e-6),
    ],
)
def test_accepted_syntax(text, dimension, expected):
    assert parse(text, dimension, "x") == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("value", ["1e400 N", "1e308 kN", 10**400, "-inf N", "NaN"])
def test_overflow_is_a_one_line_finite_error(value):
    dimension = "dimensionless" if not isinstance(value, str) or "N" not in value else "force"
    with pytest.raises(InputError, match="must be finite"):
        parse(value, dimension, "x")


def test_newton_metre_written_as_engineers_do():
    """'Nm' is the newton-metre (pint alone reads it as 'number metre', [length]/[mass])."""
    assert parse("5 Nm", "moment", "M_y") == 5.0
    assert parse("2 kNm", "moment", "M_y") == 2000.0
    assert parse("300 Nmm", "moment", "M_y") == pytest.approx(0.3, rel=1e-15)
    assert parse("1 nm", "length", "u") == pytest.approx(1e-9, rel=1e-15)  # nanometre unchanged
    with pytest.raises(InputError, match="M_y"):
        parse("5 Nm", "force", "M_y")


@pytest.mark.parametrize(
    "value, dimension, message",
    [
        # `--speed 3000` once suggested "a angular velocity such as '3000 rad/s'"
        ("3000", "angular_velocity", "expected an angular velocity such as '3000 rpm'"),
        (3000, "angular_velocity", "expected an angular velocity such as '3000 rpm'"),
        ("40", "angle", "expected an angle such as '40 deg'"),
        ("2000", "force", "expected a force such as '2000 N'"),
    ],
)
def test_a_missing_unit_suggests_the_unit_engineers_write(value, dimension, message):
    with pytest.raises(InputError) as err:
        parse(value, dimension, field="speed")
    assert message in str(err.value)
    # the suggestion parses to the value it names
    suggestion = str(err.value).split("such as '")[1].rstrip("'")
    assert parse(suggestion, dimension, "speed") == pytest.approx(
        {"angular_velocity": 3000 * math.pi / 30, "angle": math.radians(40), "force": 2000.0}[dimension]
    )


def _through_pint(number: float, unit_text: str, dimension: str) -> float:
    """``number unit_text`` converted by pint itself (the path every unit outside COMMON_UNITS takes)."""
    from bearingkit.units import SI_UNITS, _unit, registry

    unit = _unit(unit_text)
    assert not isinstance(unit, str), (unit_text, unit)
    return registry().Quantity(number, unit).to(SI_UNITS[dimension]).magnitude


_NUMBERS = (0.0, 1.0, -1.0, 2.0, 0.5, 3.7, -12.25, 25.0, 60.0, 1e-6, 123456.789, -7e5, 0.1, 1 / 3, 299.99)


@pytest.mark.parametrize(
    ("dimension", "unit_text"),
    [(dim, u) for dim, table in COMMON_UNITS.items() for u in table],
)
def test_common_units_are_pints_conversion_bit_for_bit(dimension, unit_text):
    """Issue 42: the units parsed without pint give exactly what pint gives (same float, every number);
    a temperature below absolute zero is refused on both paths (issue 41)."""
    for x in _NUMBERS:
        _same_as_pint(x, unit_text, dimension)


def _same_as_pint(x: float, unit_text: str, dimension: str) -> None:
    expected = _through_pint(x, unit_text, dimension)
    if dimension == "temperature" and expected < ABSOLUTE_ZERO_C:
        with pytest.raises(InputError, match="below absolute zero"):
            parse(f"{x!r} {unit_text}", dimension, "f")
        return
    assert parse(f"{x!r} {unit_text}", dimension, "f") == expected, x


@given(st.floats(min_value=-1e6, max_value=1e6, allow_nan=False))
def test_common_units_agree_with_pint_for_any_number(x):
    pairs = (("force", "kN"), ("length", "mm"), ("angular_velocity", "rpm"), ("temperature", "K"),
             ("angle", "deg"), ("length", "in"))  # fmt: skip
    for dimension, unit_text in pairs:
        _same_as_pint(x, unit_text, dimension)


def test_common_units_do_not_load_pint_and_the_rest_still_do():
    """A one-case analysis's options (``--load Fr=2kN --speed 3000rpm``) parse without importing pint
    (about a second of start-up); any other unit still goes through pint."""
    import subprocess
    import sys

    code = (
        "import sys; from bearingkit.units import parse\n"
        "assert parse('2kN', 'force', 'Fr') == 2000.0 and parse('3000rpm', 'angular_velocity', 's') > 0\n"
        "assert parse('60 degC', 'temperature', 't') == 60.0\n"
        "print('pint' in sys.modules)\n"
        "parse('2 lbf', 'force', 'Fr'); print('pint' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["False", "True"]


def test_a_common_unit_of_the_wrong_dimension_is_still_pints_error():
    """'5 mm' for a force is not in the force table: pint's path words the dimension error."""
    with pytest.raises(InputError, match=r"has dimension \[length\]; expected a force"):
        parse("5 mm", "force", "F_x")
