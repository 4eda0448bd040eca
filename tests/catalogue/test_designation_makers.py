"""The makers' designation syntaxes parsed into fields (SKF, FAG, NSK), unknown suffixes kept, wrong ones
answered, and any string at all answered in one line (hypothesis)."""

from __future__ import annotations

import difflib
import string

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from bearingkit.catalogue import parse, tables
from bearingkit.catalogue.designation import close_matches, nearest
from bearingkit.errors import InputError


@pytest.mark.parametrize(
    ("text", "base", "fields"),
    [
        # SKF deep groove: seal 2RS1 (contact seals both sides), clearance after a slash
        (
            "6308-2RS1/C3",
            "6308",
            dict(seal="2RS1", seal_kind="contact_seal", seal_sides=2, clearance_class="C3"),
        ),
        ("6205-2Z/C3", "6205", dict(seal="2Z", seal_kind="shield", seal_sides=2, clearance_class="C3")),
        ("6203-2RSH", "6203", dict(seal="2RSH", seal_kind="contact_seal", seal_sides=2)),
        ("6205-RZ", "6205", dict(seal="RZ", seal_kind="low_friction_seal", seal_sides=1)),
        ("6205 DDU", "6205", dict(seal="DDU", seal_kind="contact_seal", seal_sides=2)),  # NSK
        ("6205LLB", "6205", dict(seal="LLB", seal_kind="low_friction_seal", seal_sides=2)),  # NTN
        ("E2.6205-2Z/C3", "6205", dict(prefix="E2.", seal="2Z", clearance_class="C3")),
        # SKF super-precision: CD = 15 deg D design, tolerance P4A, set DB with preload class B (light)
        ("7014 CD/P4A", "7014C", dict(contact_angle_code="CD", tolerance_class="P4A", arrangement=None)),
        (
            "7014 ACD/P4ADBB",
            "7014AC",
            dict(tolerance_class="P4A", arrangement="DB", preload_class="light", preload_code="B"),
        ),
        ("71914 CE/HCP4A", "71914C", dict(contact_angle_code="CE", tolerance_class="P4A")),
        # SKF general angular contact: B 40 deg, E design, CB universally matchable, P polyamide cage
        ("7209 BECBP", "7209B", dict(matching="universal", cage="P", design=["E"])),
        ("7206 B/GA", "7206B", dict(preload_class="light", preload_code="GA", arrangement=None)),
        # FAG spindle bearing: prefix B, C 15 deg, T cage, P4S, UL universal light preload; E = 25 deg
        (
            "B7014-C-T-P4S-UL",
            "7014C",
            dict(prefix="B", cage="T", tolerance_class="P4S", preload_class="light"),
        ),
        ("HCB7014-E-T-P4S-DUL", "7014AC", dict(prefix="HCB", matching="universal", preload_class="light")),
        # NSK: TYN cage, DB pair, L light preload, P4
        (
            "7014CTYNDBLP4",
            "7014C",
            dict(cage="TYN", arrangement="DB", preload_class="light", tolerance_class="P4"),
        ),
        ("7014A5TYNDBMP4", "7014AC", dict(arrangement="DB", preload_class="medium", tolerance_class="P4")),
        ("7014 C DB", "7014C", dict(arrangement="DB", preload_class=None)),
        # NSK's series 79 is ISO 719 (NSK E1102 A54, Table 7.5): 7914 C = 71914 C
        ("7914 C", "71914C", dict(series="719", bore_code="14", contact_angle_code="C")),
        ("7914 A5 DBL P4", "71914AC", dict(series="719", arrangement="DB", preload_class="light")),
        # tapered: X (ISO 355 dimensions), Q (SKF contact geometry), J2 cage, DF/DB pairs
        ("32008 X/Q", "32008X", dict(design=["Q"], arrangement=None)),
        ("30206 J2/Q", "30206", dict(cage="J2", design=["Q"])),
        ("30206 DF", "30206", dict(arrangement="DF")),
        ("32008 X/QDB", "32008X", dict(arrangement="DB", design=["Q"])),
        ("HR30206J", "30206", dict(prefix="HR", cage="J")),
        # cylindrical and spherical
        ("NU 208 ECP", "NU208E", dict(design=["ECP"])),
        ("NJ 206 ECP/C3", "NU206E", dict(design=["ECP"], clearance_class="C3")),
        ("22208 E", "22208", dict(design=["E"])),
        ("22208 EK C3", "22208", dict(design=["E"], tapered_bore="K", clearance_class="C3")),
    ],
)
def test_makers_syntax_parsed_into_fields(text, base, fields):
    d = parse(text).fields()
    assert d["base"] == base
    for key, value in fields.items():
        assert d[key] == value, (text, key, d[key])


def test_seal_field_is_there_for_friction():
    """The seal of the designation is a field (issue 40 takes its friction from it): kind and sides."""
    d = parse("6308-2RS1/C3")
    assert (d.seal, d.seal_kind, d.seal_sides) == ("2RS1", "contact_seal", 2)
    assert parse("6308").seal is None and parse("6308").seal_sides == 0


def test_unknown_suffix_kept_in_a_note_not_refused():
    d = parse("6205-2RS1/C3GJNXQ7")
    assert d.clearance_class == "C3" and d.seal == "2RS1" and d.unknown == ("XQ7",)
    assert any("XQ7" in n for n in d.notes)


def test_ceramic_balls_named_as_not_modelled():
    assert any("ceramic balls are not modelled" in n for n in parse("HCB7014-C-T-P4S-UL").notes)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("7014 C DT", None),  # tandem angular contact pairs are modelled
        ("30206 DT", "only DB, DF pairs are modelled"),
        ("7014", "contact angle suffix"),
        ("7014 C3", "contact angle suffix"),
    ],
)
def test_pairs_and_angles(text, message):
    if message is None:
        assert parse(text).arrangement == "DT"
        return
    with pytest.raises(InputError, match=message):
        parse(text)


def _one_line(exc: InputError) -> bool:
    msg = str(exc)
    # the message quotes the text given, which may be the word "Traceback" itself (hypothesis found it):
    # what must not appear is a Python traceback's header
    return "\n" not in msg and 0 < len(msg) < 2000 and "Traceback (most recent call last)" not in msg


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.text(max_size=80))
@example("Traceback")  # quoted back in the message: not a crash
def test_any_text_parses_or_is_one_line_error(text):
    """Any string at all: a Designation or one InputError line, never another exception."""
    try:
        d = parse(text)
    except InputError as exc:
        assert _one_line(exc)
    else:
        assert d.base and d.family


_DESIGNATION_LIKE = st.text(alphabet=string.ascii_uppercase + string.digits + " -/.", max_size=30)


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    st.sampled_from(["62", "63", "70", "72", "302", "320", "NU2", "222", "12", "QJ3", "NA49", "719"]),
    _DESIGNATION_LIKE,
)
def test_designation_like_text_parses_or_is_one_line_error(head, tail):
    """Strings that start like a series and continue with random codes (the parser's hard cases)."""
    try:
        parse(head + tail)
    except InputError as exc:
        assert _one_line(exc)


@settings(max_examples=150, deadline=None)
@given(
    st.text(alphabet="AB12 ", max_size=6),
    st.lists(st.text(alphabet="AB12", max_size=5), max_size=12),
    st.integers(1, 4),
)
def test_close_matches_are_difflibs_ties_included(word, names, n):
    """The pruned search answers what difflib.get_close_matches(cutoff=0) answers (a small alphabet makes
    many equal ratios and repeated names)."""
    assert close_matches(word, names, n) == difflib.get_close_matches(word, names, n=n, cutoff=0.0)


def test_nearest_designations_are_difflibs():
    names = [e.designation for e in tables.all_entries()]
    for text in ("6205-2RSX", "NU2", "62", "7205 BECBP", "QJ3ZZ", "", "ZZZZ", "32210J", "23"):
        key = text.replace(" ", "").replace("-", "")
        assert nearest(text) == difflib.get_close_matches(key, names, n=3, cutoff=0.0), text
