"""Designation parsing: bore codes, suffixes, clearance classes and one-line errors with suggestions."""

import pytest

from bearingkit.catalogue import parse
from bearingkit.catalogue.designation import bore_from_code
from bearingkit.errors import InputError


@pytest.mark.parametrize(
    ("code", "bore"),
    [("00", 10), ("01", 12), ("02", 15), ("03", 17), ("04", 20), ("05", 25), ("20", 100), ("/22", 22)],
)
def test_bore_codes(code, bore):
    # ISO 15 bore codes: 00-03 are 10, 12, 15, 17 mm; from 04 on code x 5
    assert bore_from_code(code) == bore


@pytest.mark.parametrize(
    ("text", "family", "base", "clearance", "suffixes"),
    [
        ("6205", "deep_groove_ball", "6205", None, ()),
        ("6205-2RS C3", "deep_groove_ball", "6205", "C3", ("2RS",)),
        ("6205 ZZ/C4", "deep_groove_ball", "6205", "C4", ("ZZ",)),
        ("61805-2RS1", "deep_groove_ball", "61805", None, ("2RS1",)),
        ("16008", "deep_groove_ball", "16008", None, ()),
        ("7206B", "angular_contact_ball", "7206B", None, ()),
        ("7206 BECBP", "angular_contact_ball", "7206B", None, ("E", "CB", "P")),
        ("7308AC", "angular_contact_ball", "7308AC", None, ()),
        ("3205 A", "double_row_angular_contact_ball", "3205", None, ()),
        ("QJ 308", "four_point_contact_ball", "QJ308", None, ()),
        ("1206", "self_aligning_ball", "1206", None, ()),
        ("NU 2206 ECP", "cylindrical_roller", "NU2206E", None, ("ECP",)),
        ("NJ206E", "cylindrical_roller", "NU206E", None, ()),
        ("NU1008", "cylindrical_roller", "NU1008", None, ()),
        ("32206 J2", "tapered_roller", "32206", None, ("J2",)),
        ("32008 X", "tapered_roller", "32008X", None, ()),
        ("51205", "thrust_ball", "51205", None, ()),
        ("81212", "thrust_cylindrical_roller", "81212", None, ()),
        ("QJ 208 N2MA C3", "four_point_contact_ball", "QJ208", "C3", ("N2", "MA")),
        ("1209 EKTN9/C3", "self_aligning_ball", "1209", "C3", ("E", "K", "TN9")),
        ("2209", "self_aligning_ball", "2209", None, ()),
        ("22209", "spherical_roller", "22209", None, ()),
        ("22208 EK C3", "spherical_roller", "22208", "C3", ("E", "K")),
        ("22308 CCK/W33", "spherical_roller", "22308", None, ("CC", "K", "W33")),
        ("22210EAKE4", "spherical_roller", "22210", None, ("EA", "K", "E4")),
        ("22220", "spherical_roller", "22220", None, ()),
        ("23940 CA", "spherical_roller", "23940", None, ("CA",)),
        ("230/600 CAE4 C3", "spherical_roller", "230/600", "C3", ("CA", "E4")),
        ("240/1400", "spherical_roller", "240/1400", None, ()),
        ("2220", "self_aligning_ball", "2220", None, ()),
        ("NA 4906", "needle_roller", "NA4906", None, ()),
        ("RNA4906", "needle_roller", "RNA4906", None, ()),
        ("NA49/22 C3", "needle_roller", "NA49/22", "C3", ()),
        ("NA4822", "needle_roller", "NA4822", None, ()),
        ("302/22", "tapered_roller", "302/22", None, ()),
        ("NU 10/500 M C3", "cylindrical_roller", "NU10/500", "C3", ("M",)),
        ("320/28 XJ", "tapered_roller", "320/28X", None, ("J",)),
        ("6406 ZZ", "deep_groove_ball", "6406", None, ("ZZ",)),
    ],
)
def test_parse(text, family, base, clearance, suffixes):
    d = parse(text)
    assert (d.family, d.base, d.clearance_class, d.suffixes) == (family, base, clearance, suffixes)


def test_unknown_type_suggests_nearest():
    with pytest.raises(InputError) as exc:
        parse("6z05")
    msg = str(exc.value)
    assert "\n" not in msg and "nearest:" in msg and "6205" in msg


def test_unknown_suffix_is_kept_and_named():
    # a maker's code bearingkit does not know is not refused: it is kept and named in a note
    d = parse("6205-XYZ")
    assert d.base == "6205" and d.unknown == ("XYZ",)
    assert any("XYZ" in n and "not known" in n for n in d.notes)


@pytest.mark.parametrize(
    ("text", "kind", "nearest"),
    [
        ("6308-2RS1/C7", "clearance class", "C5"),
        ("6205-P3", "tolerance class", "P4"),
        ("6205-2RX", "seal", "2RS"),
    ],
)
def test_wrong_enumerated_suffix_answers_nearest_spellings(text, kind, nearest):
    with pytest.raises(InputError) as exc:
        parse(text)
    msg = str(exc.value)
    assert "\n" not in msg and kind in msg and "nearest valid spellings" in msg and nearest in msg


def test_bore_outside_table_names_range_and_nearest():
    with pytest.raises(InputError) as exc:
        parse("6299")
    msg = str(exc.value)
    assert "bore 495 mm" in msg and "10–360 mm of series 62" in msg and "nearest: 6272" in msg


def test_angular_contact_needs_angle_suffix():
    with pytest.raises(InputError, match="contact angle suffix"):
        parse("7206")


def test_two_clearance_classes_refused():
    with pytest.raises(InputError, match="two clearance classes"):
        parse("6205 C3 C4")


def test_needle_bore_outside_table_names_the_series_range():
    with pytest.raises(InputError) as exc:
        parse("NA4999")
    msg = str(exc.value)
    assert "bore 495 mm" in msg and "10–140 mm of series NA49" in msg and "nearest: NA4928" in msg
