"""ISO 76 C0, P0 and s0 = C0/P0 of the whole bearing beside ISO 281's C, P, L10
(bearingkit.analysis.rating.iso281), and the four-point (QJ) bearing rated as ISO's double-row angular
contact ball bearing (i = 2, the double-row X, Y and X0, Y0)."""

import numpy as np
import pytest

import bearingkit as bk
from bearingkit.analysis.rating.assembly import rate
from bearingkit.analysis.rating.iso281 import caption
from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings import slewing
from bearingkit.catalogue import tables
from bearingkit.catalogue.iso_ratings import axial_factors
from bearingkit.physics.life import iso76, iso281

DEG = np.pi / 180


def _system(designation, *load):
    a = bk.analyze(designation, load=list(load))
    return a.rating_dict()["cases"][0]


def test_6308_shows_the_catalogue_c0_and_the_iso76_static_safety():
    """6308 under F_r = 5 kN: C0 = 24 kN (NSK E1102 B10, the table's row), P0 = max(0.6 F_r + 0.5 F_a,
    F_r) = F_r (ISO 76:2006 6.2.1), s0 = C0/P0 = 4.8; the row's C0 is the catalogue's too."""
    entry = tables.entries("deep_groove_ball")["6308"]
    case = _system("6308", "F_x=5000N")
    s = case["system"]
    assert s["C0_iso76_N"] == pytest.approx(entry.C0, rel=1e-12) and s["C0_source"] == "catalogue"
    assert s["P0_iso76_N"] == pytest.approx(5000.0, rel=1e-9)
    assert s["s0_iso76"] == pytest.approx(entry.C0 / 5000.0, rel=1e-9)
    assert case["rows"][0]["C0_N"] == pytest.approx(entry.C0, rel=1e-12)
    assert f"C0 = {entry.C0 / 1e3:.4g} kN (catalogue)" in caption(s)


def test_combined_load_p0_follows_iso76_deep_groove_factors():
    """F_r = 2 kN, F_a = 3 kN: P0 = 0.6 F_r + 0.5 F_a = 2.7 kN > F_r (ISO 76 Table 1 X0, Y0)."""
    s = _system("6308", "F_x=2000N", "F_z=3000N")["system"]
    assert s["P0_iso76_N"] == pytest.approx(0.6 * 2000 + 0.5 * 3000, rel=1e-9)
    assert s["s0_iso76"] == pytest.approx(s["C0_iso76_N"] / 2700.0, rel=1e-9)


def test_qj_catalogue_axial_ratings_become_the_radial_double_row_ratings():
    """NSK prints C_a, C_0a of QJ 206; ISO 281's P = X F_r + Y F_a goes with the radial rating of the
    double-row angular contact bearing at 35°: C_r = 1.07 C_a, C_0r = 0.58 C_0a (ISO 281 Table 3 / ISO 76
    Table 2, double row, F_a/F_r > e: P = 0.6 F_r + 1.07 F_a; P0 = F_r + 0.58 F_a). F_a/F_r = 0.4 < e =
    0.95: P = F_r + 0.66 F_a (double-row column; the single-row one would give P = F_r)."""
    entry = tables.entries("four_point_contact_ball")["QJ206"]
    y, y0 = axial_factors(35 * DEG)
    s = _system("QJ206", "F_x=5000N", "F_z=2000N")["system"]
    assert s["C_iso281_N"] == pytest.approx(1.07 * entry.C, rel=1e-12) and y == pytest.approx(1.07)
    assert s["C0_iso76_N"] == pytest.approx(0.58 * entry.C0, rel=1e-12) and y0 == pytest.approx(0.58)
    assert s["P_iso281_N"] == pytest.approx(5000 + 0.66 * 2000, rel=1e-9)
    assert s["P0_iso76_N"] == pytest.approx(5000 + 0.58 * 2000, rel=1e-9)
    assert s["L10_iso281_rev"] == pytest.approx((1.07 * entry.C / 6320.0) ** 3 * 1e6, rel=1e-9)
    assert s["s0_iso76"] == pytest.approx(0.58 * entry.C0 / 6160.0, rel=1e-9)


def test_qj_pure_axial_load_gives_back_the_axial_ratings():
    """F_r = 0: P = 1.07 F_a, P0 = 0.58 F_a, so C_r/P = C_a/F_a and C_0r/P0 = C_0a/F_a — the axial
    ratings NSK prints are what the radial ones mean under pure axial load."""
    entry = tables.entries("four_point_contact_ball")["QJ206"]
    s = _system("QJ206", "F_z=4000N")["system"]
    assert s["L10_iso281_rev"] == pytest.approx((entry.C / 4000.0) ** 3 * 1e6, rel=1e-9)
    assert s["s0_iso76"] == pytest.approx(entry.C0 / 4000.0, rel=1e-9)


def test_qj_from_its_geometry_is_rated_with_two_rows():
    """Without a catalogue C the QJ bearing's ISO 281 C is the double-row formula: C = b_m f_c (2 cos α)^0.7
    Z^(2/3) D_w^1.8 (ISO 281:2007 eq. (2), i = 2), = 2^0.7 × the C of one diagonal; C0 = 2 f0 Z D_w² cos α
    (ISO 76 eq. (1)); and the double-row X, Y."""
    z, dw, dm = 16, 0.0127, 0.065
    model = slewing.four_point_contact_ball(n_elements=z, element_diameter=dw, pitch_diameter=dm)
    res = solve(model, load_vector(F_x=3e3, F_z=1e3), free=[True, True, True, False, False])
    b = rate(res, speed=100.0).iso281
    c2 = float(iso281.dynamic_rating_ball(dw, dm, 35 * DEG, z, 2, "angular_contact_ball"))
    c02 = float(iso76.static_rating_ball(dw, dm, 35 * DEG, z, 2, "radial"))
    assert b.load_rating == pytest.approx(c2, rel=1e-9)
    assert b.static_rating == pytest.approx(c02, rel=1e-9)
    assert float(b.load[0]) == pytest.approx(3e3 + 0.66 * 1e3, rel=1e-9)
    assert float(b.static_load[0]) == pytest.approx(3e3 + 0.58 * 1e3, rel=1e-9)


def test_select_screen_rates_qj_on_the_radial_basis():
    """The catalogue method of `select` uses the same radial C_r = 1.07 C_a, C_0r = 0.58 C_0a as the
    analysis: its L10 and s0 for QJ 206 equal the analysis's ISO 281 L10 and ISO 76 s0."""
    from bearingkit.catalogue.search import screen, search

    row = next(r for r in search("QJ206"))
    s = screen(row, 5000.0, 2000.0)
    sysd = _system("QJ206", "F_x=5000N", "F_z=2000N")["system"]
    assert s.P == pytest.approx(sysd["P_iso281_N"], rel=1e-9)
    assert s.life == pytest.approx(sysd["L10_iso281_rev"], rel=1e-9)
    assert s.static_safety == pytest.approx(sysd["s0_iso76"], rel=1e-9)
