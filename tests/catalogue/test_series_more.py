"""Rows added in issue 33 (third part): deep groove 64 above d = 90 mm (6419-6430; 6419 and 6420 KRW's,
6422 ZVL's rated rows since), double-row cylindrical
NN49 (NN4910-NN4928) and tapered 332 (33205-33218). Dimensions only: no stored catalogue prints their
ratings, so the estimate rates them; each row names its source, the dimensions are consistent with the
rows they were taken from, and the estimates are checked against their rated siblings. (33205-33217 were
since replaced by NSK's rated HR 332xx J rows, E1102 B112-B122; NSK prints no 33218, rated later with
KOYO's 33218JR, B2001RUS p. 214, whose d, D, T, B, C, r and e equal the row's: no 332 row is unrated now.)"""

from __future__ import annotations

import numpy as np
import pytest

from bearingkit.catalogue import entries, estimate, parse, ratings, resolve


def _rows(family, series):
    return sorted((e for e in entries(family).values() if e.series == series), key=lambda e: e.bore)


NEW = [
    ("deep_groove_ball", "64", 4),  # 6419, 6420 KRW's, 6422 ZVL's rated rows since (test_estimate_kinds)
    ("double_row_cylindrical_roller", "NN49", 15),
]


@pytest.mark.parametrize("family, series, count", NEW)
def test_new_rows_name_a_source_and_carry_no_invented_rating(family, series, count):
    rows = [e for e in _rows(family, series) if e.C is None]
    assert len(rows) == count
    for e in rows:
        assert e.C0 is None and "no rating" in e.source
        assert e.source.startswith(("ISO 15 dimension series", "ISO 355 series")), e.source
        read = "NSK-E1102" in e.source or "mbp-bearings.com" in e.source
        assert read or "[from memory" in e.source, e.source
        assert 0 < e.width <= e.outer_diameter - e.bore + 1e-9 and e.outer_diameter > e.bore


@pytest.mark.parametrize("family, series, count", NEW)
def test_new_rows_grow_with_size_and_resolve(family, series, count):
    rows = _rows(family, series)
    c = np.array([ratings(estimate(e))[0] for e in rows])
    assert np.all(np.diff([e.bore for e in rows]) > 0)
    assert np.all(np.diff([e.outer_diameter for e in rows]) > 0)
    assert np.all(np.diff(c) > 0), [e.designation for e in rows]
    b = resolve(rows[-1].designation)
    assert b.C > 0 and b.C0 > 0 and any("ESTIMATED" in n for n in b.notes)


def test_nn49_rows_share_the_boundary_dimensions_of_na49():
    """ISO 15 dimension series 49: NN49xx and NA49xx have the same d, D, B, r_s min."""
    na = entries("needle_roller")
    for e in _rows("double_row_cylindrical_roller", "NN49"):
        n = na["NA49" + e.designation[4:]]
        dims = (e.bore, e.outer_diameter, e.width, e.chamfer)
        assert dims == (n.bore, n.outer_diameter, n.width, n.chamfer)
        assert parse(e.designation).family == "double_row_cylindrical_roller"


def test_nn49_rollers_are_those_of_nu19():
    """No stored catalogue rates NN49 and no constant was chosen for it: dimension series 49 has the
    diameter series 9 of NU19, so each row gets the NU19 roller (D_w, Z, d_m) of the same bore; only the
    length differs (the NN30 rule's half width per row)."""
    nu = entries("cylindrical_roller")
    for e in _rows("double_row_cylindrical_roller", "NN49"):
        n = nu.get("NU19" + e.designation[4:])
        if n is None:
            continue
        a, b = estimate(e), estimate(n)
        assert a.element_diameter == pytest.approx(b.element_diameter, rel=1e-12), e.designation
        assert a.n_elements == b.n_elements and a.pitch_diameter == pytest.approx(b.pitch_diameter)


def test_332_rows_match_their_322_siblings():
    """332 and 322 share d, D and r (diameter series 2), the 332 is wider: T = B; C < B. The estimate's C
    and C0 over the 322 sibling's follow the roller length (L_we ∝ B): C ∝ L^(7/9) (ISO 281 eq. (9)),
    C0 ∝ L (ISO 76 eq. (3)), within 6 %."""
    tr = entries("tapered_roller")
    for e in _rows("tapered_roller", "332"):
        s = tr["322" + e.designation[3:]]
        assert (e.bore, e.outer_diameter, e.chamfer) == (s.bore, s.outer_diameter, s.chamfer)
        t, b, c_cup = e.number("T_mm", 1e-3), e.width, e.number("C_cup_mm", 1e-3)
        assert t == pytest.approx(b) and c_cup < b and b > s.width
        (c, c0), (cs, c0s) = ratings(estimate(e)), ratings(estimate(s))
        width = b / s.width
        assert c / cs == pytest.approx(width ** (7 / 9), rel=0.06), e.designation
        assert c0 / c0s == pytest.approx(width, rel=0.06), e.designation


def test_64_rows_above_90_continue_the_rated_rows():
    """6419-6430: D - d and B grow, r_s min not below 6418's; the estimate at the last rated rows
    (6414-6418, SKF 6000) is within 7 % of the catalogue (C -4...+1 %, C0 -6...+1 %), so the rule the new
    rows use holds there."""
    rows = _rows("deep_groove_ball", "64")
    rated = [e for e in rows if e.C is not None and e.source.startswith("SKF-6000RU")][-5:]
    for e in rated:
        c, c0 = ratings(estimate(e))
        assert abs(c / e.C - 1) < 0.07 and abs(c0 / e.C0 - 1) < 0.07, e.designation
    new = [e for e in rows if e.bore > 0.0905]  # 6419-6430 (6419, 6420, 6422 rated later)
    assert new[0].designation == "6419" and all(e.chamfer >= rated[-1].chamfer for e in new)
    assert np.all(np.diff([e.width for e in new]) > 0)
