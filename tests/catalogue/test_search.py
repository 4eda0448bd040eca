"""Catalogue search by dimensions and ratings, the mass estimate, and the catalogue-method screen."""

from __future__ import annotations

import pytest

from bearingkit.catalogue import FAMILIES, entries, find
from bearingkit.catalogue.search import row_of, screen, search
from bearingkit.errors import InputError


def _row(name):
    return row_of(next(fam[name] for fam in (entries(f) for f in FAMILIES) if name in fam))


def test_search_by_bore_outside_diameter_kind_and_rating():
    """d = 40, D <= 80, deep groove: NSK E1102 lists 61808 (52), 61908 (62), 16008 (68), 6008 (68) and 6208
    (80, C = 29.1 kN); C >= 25 kN leaves the 6208 alone."""
    rows = search(kind="deep_groove", d=0.040, D_max=0.080)
    assert sorted(r.entry.designation for r in rows) == ["16008", "6008", "61808", "61908", "6208"]
    rows = search(kind="deep_groove", d=0.040, D_max=0.080, C_min=25e3)
    assert [r.entry.designation for r in rows] == ["6208"] and rows[0].rating_source == "catalogue"


def test_search_uses_the_estimate_where_the_table_prints_no_rating():
    row = _row("7314AC")  # dimensions only: NSK E1102 B56 prints the 7314 A and B, no 25° 7314
    assert row.entry.C is None and row.rating_source == "estimate" and row.C == row.C_estimate > 0
    assert any(r.entry.designation == "7314AC" for r in search(kind="angular_contact", d=0.070, C_min=row.C))
    assert not any(
        r.entry.designation == "7314AC" for r in search(kind="angular_contact", d=0.070, C_min=row.C + 1)
    )


def test_pattern_mode_kept_and_bounds_combine():
    assert [r.entry.designation for r in search("222*")] == [e.designation for e in find("222*")]
    assert all(r.entry.width <= 0.020 for r in search("62*", B_max=0.020))
    with pytest.raises(InputError, match="kind"):
        search(kind="sleeve")


#: SKF's printed masses [kg] (the SKF product data of github.com/gumyr/bd_warehouse, files
#: single_row_tapered_roller_bearing_parameters.csv and single_row_cylindrical_roller_bearing_parameters.csv:
#: 30204 J2/Q … 32306 J2/Q, NJ/NU …ECP).
SKF_MASS = {
    "30204": 0.12, "30304": 0.17, "30205": 0.15, "30305": 0.26, "30206": 0.23, "32206": 0.29,
    "30306": 0.38, "32306": 0.55, "NU205E": 0.13, "NU304E": 0.15,
}  # fmt: skip


@pytest.mark.parametrize("name", sorted(SKF_MASS))
def test_mass_estimate_against_skf(name):
    """The estimate leaves out chamfers, ribs' undercuts and cages: it lies 10-35 % above SKF's printed mass
    (found: +12…+32 %), the same direction for every size, so it orders bearings by mass."""
    ratio = _row(name).mass / SKF_MASS[name]
    assert 1.10 < ratio < 1.35, (name, ratio)


def test_screen_is_the_catalogue_method():
    """6208 under F_r alone: P = F_r, L10 = (C/P)^3 10^6 rev with NSK's C = 29.1 kN; P0 = F_r, s0 = C0/P0."""
    s = screen(_row("6208"), 5000.0, 0.0)
    assert s.P == pytest.approx(5000.0) and s.life == pytest.approx((29.1 / 5.0) ** 3 * 1e6, rel=1e-12)
    assert s.static_safety == pytest.approx(17.9 / 5.0, rel=1e-12)
    # a lone angular contact bearing cannot carry F_a below F_r tan α: screened out with the reason
    s = screen(_row("7208B"), 5000.0, 1000.0)
    assert s.life is None and "pair it" in s.reason
