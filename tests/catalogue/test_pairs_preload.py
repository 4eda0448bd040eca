"""Preload classes of matched angular contact pairs: NSK's table (CAT. No. E1102e, Table 10.2, pp.
A98-A99) where it has the bearing, bearingkit's rule of thumb with a note saying so elsewhere."""

from __future__ import annotations

import pytest

from bearingkit.catalogue import resolve
from bearingkit.catalogue.pairs import PRELOAD_FRACTIONS, nsk_preloads, preload_force


@pytest.mark.parametrize(
    "text, preload, force",
    [
        # Table 10.2.1, series 79 (bearingkit 719xx): "7901 C  8.6  15  39  78"
        ("71901 C DB", "extra_light", 8.6),
        # "7917 C  145  290  640  1 270"
        ("71917 C DB", "heavy", 1270.0),
        # the same row in NSK's own spelling (series 79 = ISO 719, NSK A54 Table 7.5)
        ("7917 C DB", "heavy", 1270.0),
        # Table 10.2.2, series 70: "7014 C  145  290" | M, H "740  1 470"
        ("7014 C DB", "light", 290.0),
        ("7014 C DF", "medium", 740.0),
        # Table 10.2.3, series 72: "7220 C  490  980  2 350  4 710"
        ("7220 C DB", "heavy", 4710.0),
        # "7205 C  39  78  200  390"
        ("7205 C DB", "extra_light", 39.0),
    ],
)
def test_printed_nsk_preloads_are_reproduced(text, preload, force):
    r = resolve(text, preload=preload)
    assert r.preload_force == force
    note = next(n for n in r.notes if n.startswith("preload class"))
    assert f"{force:g} N" in note and "NSK Rolling Bearings CAT. No. E1102e, Table 10.2, pp. A98-A99" in note


def test_makers_codes_map_onto_nsk_classes_by_name():
    """NSK L, SKF B, FAG UL are all 'light': the 7014 C set gets NSK's L = 290 N, and the note says the
    mapping is by name only."""
    for text in ("7014CTYNDBLP4", "7014 CD/P4ADBB", "B7014-C-T-P4S-UL DB"):
        r = resolve(text)
        assert r.preload_force == 290.0, text
        note = next(n for n in r.notes if n.startswith("preload class"))
        assert "by name only" in note


@pytest.mark.parametrize(
    "text, why",
    [
        ("7024 C DB", "7024C is not in NSK's preload table"),  # bore number 24 > 20
        ("7208 A DB", "7208A is not in NSK's preload table"),  # 30°: the table is for 15° (C)
        ("7014 C DB P6", "precision better than P5, the set is P6"),
    ],
)
def test_outside_the_table_falls_back_with_its_note(text, why):
    r = resolve(text, preload="medium")
    note = next(n for n in r.notes if n.startswith("preload class"))
    assert "rule of thumb" in note and why in note
    assert "NSK Rolling Bearings CAT. No. E1102e, Table 10.2" in note  # names the source it fell out of
    c = float(note.split("(C = ")[1].split(" kN")[0]) * 1e3
    assert r.preload_force == pytest.approx(PRELOAD_FRACTIONS["medium"] * c, rel=1e-3)


def test_table_holds_what_nsk_prints_and_grows_with_class():
    table = nsk_preloads()
    assert len(table) == 63  # 21 bearings (bore numbers 00-20) in each of series 79, 70, 72
    assert table["71900C"]["maker_designation"] == "7900 C"
    for base, row in table.items():
        forces = [row[c] for c in PRELOAD_FRACTIONS]
        assert forces == sorted(forces), base
        assert row["source"].startswith("NSK-E1102:A98-A99 Table 10.2."), base


def test_a_given_force_is_unchanged():
    assert preload_force(480.0, 50e3, "7014C") == (480.0, "preload force 480 N (given)")
