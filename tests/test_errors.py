"""InputError messages: one line, at most MAX_MESSAGE_CHARS, values quoted short (issue 23)."""

from bearingkit.errors import MAX_MESSAGE_CHARS, InputError, did_you_mean, quote


def test_long_values_are_quoted_short():
    assert quote([13] * 100_000) == "[13, 13, 13, … 100000 items]"
    assert quote("a" * 100_000) == repr("a" * 40) + "… (100000 characters)"
    assert quote(10**5000) == "an integer of about 5000 digits"  # repr would raise (4300-digit limit)
    assert quote({"a": 1, "b": 2}) == "a table of 2 keys"
    assert quote([[[[1]]]]) == "[[[… 1 items]]]"
    assert quote("5 kN") == "'5 kN'"


def test_messages_are_one_line_and_capped():
    msg = str(InputError("geometry.bore (" + "9" * 5000 + ")\nmust be\tpositive"))
    assert "\n" not in msg and "\t" not in msg
    assert len(msg) <= MAX_MESSAGE_CHARS
    assert msg.startswith("geometry.bore (999") and msg.endswith("must be positive")  # head and tail kept
    assert str(InputError("short")) == "short"


def test_did_you_mean_nearest_choice():
    fields = ["bore", "outer_diameter", "pitch_diameter", "element_diameter"]
    assert did_you_mean("pitch_diamter", fields) == "; did you mean 'pitch_diameter'?"
    assert did_you_mean("BORE", fields) == "; did you mean 'bore'?"
    assert did_you_mean("zzz", fields) == ""
    assert did_you_mean("x" * 10_000, fields) == ""
