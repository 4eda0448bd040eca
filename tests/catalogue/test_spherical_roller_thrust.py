"""Spherical roller thrust bearings 292, 293, 294 by designation: NSK E1102 B224-B229 (the stored text's
pages 186-188), the estimate of the internal geometry and its ratings against NSK's, the designation path
of the command line.

Published values: NSK *Rolling Bearings* CAT. No. E1102e, "Spherical thrust roller bearings", B225
(60-200 mm), B227 (220-420 mm), B229 (440-500 mm): d, D, T, r_min, C_a, C_0a in N and {kgf}. Calibration
sets of the estimate's roller rules (catalogue.internal.SPHERICAL_THRUST_RULES): the 294 series (its E and
its standard sizes); 293 and 292 are predictions.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.catalogue import entries, estimate, internal, parse, ratings
from bearingkit.catalogue.designation import bore_from_code
from bearingkit.cli import app

KGF = 9.80665
#: designation → (d, D, T, r_min [mm], C_a, C_0a [N], C_a, C_0a [kgf], NSK page and printed name).
NSK = {
    "29412": (60, 130, 42, 1.5, 330000, 885000, 33500, 90000, "B225 29412 E"),
    "29317": (85, 150, 39, 1.5, 330000, 1040000, 34000, 106000, "B225 29317 E"),
    "29240": (200, 280, 48, 2, 540000, 2310000, 55000, 236000, "B225 29240"),
    "29444": (220, 420, 122, 6, 2350000, 8650000, 240000, 880000, "B227 29444"),
    "29384": (420, 650, 140, 6, 3500000, 15700000, 355000, 1600000, "B227 29384"),
    "294/500": (500, 870, 224, 9.5, 7850000, 33000000, 800000, 3350000, "B229 294/500"),
}
#: Rows per page of the transcription (B225: 32, B227: 33, B229: 12).
PAGES = {"B225": 32, "B227": 33, "B229": 12}
#: Estimate/NSK − 1 of C and C0 per (series, design) as measured, bounds rounded outwards to the percent:
#: (C min, C max, C0 min, C0 max).
BOUNDS = {
    ("294", "E"): (-0.06, 0.03, -0.09, 0.03),
    ("293", "E"): (-0.03, 0.10, -0.04, 0.07),
    ("294", ""): (-0.06, 0.08, -0.07, 0.06),
    ("293", ""): (-0.02, 0.07, -0.03, 0.09),
    ("292", ""): (0.06, 0.12, 0.08, 0.15),
}
TABLE = entries("spherical_roller_thrust")


@pytest.mark.parametrize("name", sorted(NSK))
def test_nsk_rows_as_printed(name):
    d, big_d, t, r, ca, c0a, ca_kgf, c0a_kgf, where = NSK[name]
    e = TABLE[name]
    page, printed = where.split(" ", 1)
    assert e.source == f"NSK-E1102:{page} (NSK {printed})"
    assert (e.bore, e.outer_diameter, e.width, e.chamfer) == pytest.approx(
        (d * 1e-3, big_d * 1e-3, t * 1e-3, r * 1e-3), rel=1e-12
    )
    assert (e.C, e.C0) == (ca, c0a)
    assert e.C / KGF == pytest.approx(ca_kgf, rel=0.02) and e.C0 / KGF == pytest.approx(c0a_kgf, rel=0.02)
    assert e.extra.get("design") == ("E" if printed.endswith(" E") else "")


def test_table_counts_and_bore_codes():
    pages = [e.source.split(":")[1].split()[0] for e in TABLE.values()]
    assert {p: pages.count(p) for p in PAGES} == PAGES and len(TABLE) == sum(PAGES.values())
    for e in TABLE.values():
        assert e.bore == pytest.approx(bore_from_code(e.designation[3:]) * 1e-3, rel=1e-12)
        assert e.series == e.designation[:3] and e.series in ("292", "293", "294")
        assert e.width == pytest.approx(0.6 * (e.outer_diameter - e.bore), rel=0.035)  # ISO 104 plan


def test_estimate_fits_the_section_at_nsk_angle():
    for e in TABLE.values():
        est = estimate(e)
        a = est.contact_angle
        assert math.tan(a) == pytest.approx(1.2, rel=1e-12) and est.rows == 1 and est.n_elements >= 3
        assert (internal.envelope_margins(est) > 0).all(), e.designation
        axial = est.element_diameter * math.sin(a) + est.effective_length * math.cos(a)
        assert axial < e.width, e.designation


def test_estimate_accuracy_as_measured():
    errors: dict = {}
    for e in TABLE.values():
        c, c0 = ratings(estimate(e))
        errors.setdefault((e.series, e.extra.get("design", "")), []).append((c / e.C - 1, c0 / e.C0 - 1))
    assert set(errors) == set(BOUNDS)
    for key, (c_lo, c_hi, c0_lo, c0_hi) in BOUNDS.items():
        err = np.array(errors[key])
        assert c_lo <= err[:, 0].min() and err[:, 0].max() <= c_hi, key
        assert c0_lo <= err[:, 1].min() and err[:, 1].max() <= c0_hi, key


def test_designations_with_suffixes():
    assert parse("29412 E").family == "spherical_roller_thrust" and parse("29412 E").base == "29412"
    assert parse("292/500").base == "292/500"


def test_analyze_by_designation_pure_axial():
    a = bk.analyze("29412", load={"F_z": "100 kN"})
    st = a.statics.rows[0]
    est = estimate(TABLE["29412"])
    assert st.load.shape == (1, est.n_elements)
    np.testing.assert_allclose(st.load[0] * est.n_elements * np.sin(st.contact_angle[0]), 100e3, rtol=1e-9)


def test_cli_analyze_and_rating():
    runner = CliRunner()
    res = runner.invoke(app, ["analyze", "29412", "--load", "Fa=100kN"])
    assert res.exit_code == 0, res.output
    res = runner.invoke(
        app, ["rating", "29412", "--load", "Fa=100kN", "--load", "Fr=20kN", "--speed", "1000rpm"]
    )
    assert res.exit_code == 0, res.output
    text = " ".join(res.output.split())
    # ISO 281 8.2: P = tan α F_r + F_a = 1.2 · 20 + 100 kN; ISO 76: P0 = 2.3 tan α F_r + F_a = 155.2 kN
    assert "P = 124 kN, C = 330 kN (catalogue)" in text and "P0 = 155.2 kN, C0 = 885 kN" in text


def test_radial_load_beyond_the_makers_limit_has_no_iso281_life():
    """F_r/F_a <= 0.55 (NSK B225) is ISO 281's F_a/F_r > e = 1.5 tan α = 1.8: at F_r = 0.6 F_a the bearing
    still solves (the row carries it) but has no ISO 281 P; at 0.5 F_a it has P = 1.2 F_r + F_a."""
    cases = [{"F_z": "100 kN", "F_x": "50 kN"}, {"F_z": "100 kN", "F_x": "60 kN"}]
    a = bk.analyze("29412", load=cases, speed="1000 rpm")
    assert a.statics.converged.all()
    life = a.rating.iso281
    assert float(life.load[0]) == pytest.approx(160e3, rel=1e-12) and not np.ma.getmaskarray(life.life)[0]
    assert np.ma.getmaskarray(life.life)[1]
    assert "must exceed e" in (life.note or "")
