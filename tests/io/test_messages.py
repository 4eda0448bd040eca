"""One-line messages of malformed input files (issue 23): the unknown key and its nearest valid
key, strict number types, short quotes of long values, nothing over MAX_MESSAGE_CHARS."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from bearingkit.errors import MAX_MESSAGE_CHARS, InputError
from bearingkit.io.loader import load_file, loads

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
DGBB = (EXAMPLES / "dgbb_6209.toml").read_text(encoding="utf-8")
BALL_COLUMN = (EXAMPLES / "ball_column_condition1.toml").read_text(encoding="utf-8")
TRB = (EXAMPLES / "trb_32008.toml").read_text(encoding="utf-8")


def _error(text: str) -> str:
    with pytest.raises(InputError) as err:
        loads(text, "bad.toml")
    msg = str(err.value)
    assert msg.startswith("bad.toml: ") and "\n" not in msg and len(msg) <= MAX_MESSAGE_CHARS, msg
    return msg


def _edit(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


@pytest.mark.parametrize(
    ("old", "new", "expected"),
    [
        # a typo in a required key: the unknown key is the cause, not the 'missing' one
        (
            'pitch_diameter = "65 mm"',
            'pitch_diamter = "65 mm"',
            "geometry.pitch_diamter ('65 mm'): unknown field; did you mean 'pitch_diameter' "
            "(required, missing)?",
        ),
        (
            "clearance_radial =",
            "clearence_radial =",
            "geometry.clearence_radial ('15 um'): unknown field; did you mean 'clearance_radial'?",
        ),
        ("[geometry]", "[geometri]", "geometri (a table of "),
        ("[geometry]", "[geometri]", "unknown field; did you mean 'geometry'"),
        ('type = "deep_groove_ball"', 'type = "deep_grove_ball"', "did you mean 'deep_groove_ball'?"),
        ('F_x = "4 kN"', 'F_X = "4 kN"', "load_cases[1].F_X ('4 kN'): unknown field; did you mean 'F_x'?"),
    ],
)
def test_unknown_keys_name_the_nearest_valid_one(old, new, expected):
    assert expected in _error(_edit(DGBB, old, new))


def test_material_and_lubricant_names_suggest():
    text = _edit(DGBB, 'name = "AISI52100"', 'name = "GCR15"')
    assert "material.name ('GCR15') must be one of" in _error(text)
    assert "did you mean 'GCr15'?" in _error(text)


@pytest.mark.parametrize(
    ("text", "old", "new", "expected"),
    [
        (
            DGBB,
            "n_elements = 9",
            'n_elements = "9"',
            "geometry.n_elements ('9') must be an integer in [1, 2000], not a string: write n_elements = 9 "
            "without quotes",
        ),
        (DGBB, "n_elements = 9", "n_elements = 9.0", "geometry.n_elements (9.0) must be an integer"),
        (DGBB, "n_elements = 9", "n_elements = true", "geometry.n_elements (True) must be an integer"),
        (
            DGBB,
            "n_elements = 9",
            "n_elements = 2001",
            "geometry.n_elements (2001) must be an integer in [1, 2000]",
        ),
        (DGBB, "conformity_inner = 0.52", 'conformity_inner = "0.52"', "must be a number, not a string"),
        (
            BALL_COLUMN,
            "flexible = true",
            'flexible = "true"',
            "geometry.ring.flexible ('true'): Input should be",
        ),
        (
            BALL_COLUMN,
            "n_slices = 20",
            "n_slices = 201",
            "geometry.n_slices (201) must be an integer in [1, 200]",
        ),
    ],
)
def test_numbers_and_booleans_are_strictly_typed(text, old, new, expected):
    assert expected in _error(_edit(text, old, new))


def test_generator_seed_is_strictly_typed():
    text = _edit(TRB, "{ series = 1 }", '{ magnitude = "1 um", seed = "1" }')
    assert "seed" in _error(text)


@pytest.mark.parametrize(
    ("new", "expected"),
    [
        (
            "n_elements = [" + ", ".join(["13"] * 100_000) + "]",
            "geometry.n_elements ([13, 13, 13, … 100000 items])",
        ),
        ('n_elements = "' + "x" * 100_000 + '"', "(100000 characters)"),
        ("n_elements = " + "9" * 5000, "not valid TOML (a number of more than 4300 digits)"),
    ],
)
def test_long_values_are_quoted_short(new, expected):
    """49 messages of the fuzzer were over 2,000 characters, up to 12 MB (issue 23)."""
    msg = _error(_edit(DGBB, "n_elements = 9", new))
    assert expected in msg


def test_unknown_case_among_many_is_short():
    cases = "".join(f'[[load_cases]]\nname = "case_{i}"\nF_x = "1 kN"\n\n' for i in range(500))
    bearing = loads(DGBB.split("[[load_cases]]")[0] + cases, "many.toml")
    with pytest.raises(InputError) as err:
        bearing.select(["case_5000"])
    msg = str(err.value)
    assert len(msg) <= MAX_MESSAGE_CHARS and "did you mean 'case_500'" not in msg
    assert msg.startswith("many.toml: case ('case_5000') not in the file; cases are ['case_0', 'case_1',")


def test_examples_still_load():
    """The strict types refuse nothing the examples write (shaft files: tests/systems)."""
    for path in sorted(p for p in EXAMPLES.glob("*.toml") if not p.name.startswith("shaft_")):
        if "shafts" in tomllib.loads(path.read_text(encoding="utf-8")):  # a drivetrain file: tests/systems
            continue
        assert load_file(path).cases, path.name


def test_keys_with_control_characters_are_quoted():
    """A key holding a right-to-left override would reorder the terminal line (a spoofed message):
    keys that are not plain names are shown as Python string literals, escapes visible."""
    msg = _error(_edit(DGBB, "clearance_radial =", '"\\u202eclearance" ='))
    assert "\u202e" not in msg
    assert "geometry.'\\u202eclearance' ('15 um'): unknown field" in msg
