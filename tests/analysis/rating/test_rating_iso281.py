"""ISO 281:2007 basic rating life of the whole bearing beside L10r: hand calculations per bearing type.

Hand values: P = X F_r + Y F_a with X, Y, e typed in here from ISO 281:2007 Table 3 (deep groove: [from
memory of the standard], the same values as every maker's catalogue table; angular contact 40°: e = 1.14,
X = 0.35, Y = 0.57, formulas.md D1) and 7.2 (radial roller: e = 1.5 tan α, X = 0.4, Y = 0.4 cot α);
L10 = (C/P)^p 10⁶ with the catalogue C of the designation. Tolerance 1e-12 relative: the same closed
forms in double precision.
"""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.analysis.rating.iso281 import caption
from bearingkit.catalogue import find
from bearingkit.cli import app
from bearingkit.physics.life import iso76

REL = 1e-12
# ISO 281:2007 Table 3, single-row radial contact groove ball bearings: f0 Fa/C0r, e, Y (Fa/Fr > e, X = 0.56)
TABLE3 = np.array(
    [
        [0.172, 0.19, 2.30],
        [0.345, 0.22, 1.99],
        [0.689, 0.26, 1.71],
        [1.03, 0.28, 1.55],
        [1.38, 0.30, 1.45],
        [2.07, 0.34, 1.31],
        [3.45, 0.38, 1.15],
        [5.17, 0.42, 1.04],
        [6.89, 0.44, 1.00],
    ]
)


def _system(a, case=0):
    return a.rating_dict()["cases"][case]["system"]


def _catalogue(designation):
    (entry,) = find(designation)
    return entry


def test_6205_combined_load_table3_by_hand():
    # Fa/Fr = 0.25 (below e: P = Fr) and 0.75 (above e: P = 0.56 Fr + Y Fa)
    a = bk.analyze("6205", load=[{"F_x": "2 kN", "F_z": "0.5 kN"}, {"F_x": "2 kN", "F_z": "1.5 kN"}])
    entry = _catalogue("6205")
    row = a.input.model.rows[0]
    f0 = float(iso76.f0_radial_ball(row.element_diameter / row.pitch_diameter))
    for case, (fr, fa) in enumerate(((2000.0, 500.0), (2000.0, 1500.0))):
        rel = f0 * fa / entry.C0
        e = np.interp(rel, TABLE3[:, 0], TABLE3[:, 1])
        y = np.interp(rel, TABLE3[:, 0], TABLE3[:, 2])
        p = fr if fa / fr <= e else 0.56 * fr + y * fa
        s = _system(a, case)
        assert s["C_source"] == "catalogue"
        assert s["C_iso281_N"] == entry.C
        assert s["P_iso281_N"] == pytest.approx(p, rel=REL)
        assert s["L10_iso281_rev"] == pytest.approx((entry.C / p) ** 3 * 1e6, rel=REL)
    assert _system(a, 0)["P_iso281_N"] == pytest.approx(2000.0, rel=REL)  # below e
    assert _system(a, 1)["P_iso281_N"] > 2000.0 * 1.2  # above e: the axial load counts


def test_nu209e_pure_radial_roller_exponent_and_hours():
    a = bk.analyze("NU 209 E", load={"F_x": "10 kN"}, speed="1500 rpm")
    s = _system(a)
    c = _catalogue("NU209E").C
    l10 = (c / 10e3) ** (10.0 / 3.0) * 1e6
    assert s["P_iso281_N"] == pytest.approx(10e3, rel=REL)
    assert s["L10_iso281_rev"] == pytest.approx(l10, rel=REL)
    assert s["L10h_iso281_h"] == pytest.approx(l10 / (1500.0 * 60.0), rel=1e-12)
    # the point of the feature: ISO/TS 16281 from the load distribution differs (here ~2x longer)
    assert 1.5 < s["L10r_rev"] / s["L10_iso281_rev"] < 3.0


def test_7206b_angular_40deg_both_branches():
    a = bk.analyze("7206 B", load=[{"F_x": "4 kN", "F_z": "3 kN"}, {"F_x": "2 kN", "F_z": "4 kN"}])
    c = _catalogue("7206B").C
    assert _system(a, 0)["P_iso281_N"] == pytest.approx(4000.0, rel=REL)  # Fa/Fr = 0.75 <= e = 1.14
    p = 0.35 * 2000.0 + 0.57 * 4000.0  # Fa/Fr = 2 > 1.14
    assert _system(a, 1)["P_iso281_N"] == pytest.approx(p, rel=REL)
    assert _system(a, 1)["L10_iso281_rev"] == pytest.approx((c / p) ** 3 * 1e6, rel=REL)


def test_32210_tapered_y_from_contact_angle():
    a = bk.analyze("32210", load={"F_x": "4 kN", "F_z": "3 kN"})
    alpha = float(a.input.model.rows[0].contact_angle_outer)
    entry = _catalogue("32210")
    e = 1.5 * math.tan(alpha)
    assert e == pytest.approx(float(entry.extra["e"]), rel=0.02)  # the catalogue prints e = 0.42
    assert 3.0 / 4.0 > e
    p = 0.4 * 4000.0 + 0.4 / math.tan(alpha) * 3000.0
    s = _system(a)
    assert s["P_iso281_N"] == pytest.approx(p, rel=REL)
    assert s["L10_iso281_rev"] == pytest.approx((entry.C / p) ** (10.0 / 3.0) * 1e6, rel=REL)


def test_geometry_input_uses_computed_c_and_thrust_equals_l10r():
    # a file without a designation: C is ISO 281 of the geometry, the row's C
    a = bk.analyze("examples/thrust_ball_51209.toml")
    d = a.rating_dict()["cases"]
    assert d[0]["system"]["C_source"] == "computed"
    assert d[0]["system"]["C_iso281_N"] == pytest.approx(d[0]["rows"][0]["C_N"], rel=REL)
    # centric axial load on a 90° thrust bearing: every ball carries Fa/Z, ISO/TS 16281 gives ISO 281 L10
    assert d[0]["system"]["L10_iso281_rev"] == pytest.approx(d[0]["system"]["L10r_rev"], rel=1e-9)
    # case 1 (eccentric): the rating reads the TS's pitch-radius tilt arm, under which the held radial
    # DOFs take no reaction (the groove-centre arm's tangential term gave 0.65 N, which made ISO 281
    # refuse a P for "a radial load on a 90° thrust bearing"): P = F_a, the moment noted as not in P
    assert a.statics.load[1, 0] != 0.0
    assert d[1]["system"]["P_iso281_N"] == pytest.approx(10e3, rel=REL)
    assert "tilting moment of case(s) 1 is not in P" in d[1]["system"]["iso281_note"]


@pytest.mark.parametrize(
    ("source", "words"),
    [("examples/seed000_composite.toml", "5-row"), ("examples/slewing_four_point.toml", "slewing")],
)
def test_no_iso281_xy_gives_note(source, words):
    s = _system(bk.analyze(source))
    assert s["P_iso281_N"] is None and s["L10_iso281_rev"] is None and s["C_iso281_N"] is None
    assert words in s["iso281_note"] and "no X, Y" in s["iso281_note"]


def test_modified_life_a_iso_at_p():
    kw = dict(speed="3000 rpm", lubricant="ISO_VG68", temperature="60 degC", contamination=0.5)
    a = bk.analyze("6205", load=[{"F_x": "2 kN"}, {"F_x": "4 kN"}], **kw)
    s0, s1 = _system(a, 0), _system(a, 1)
    for s in (s0, s1):
        assert 0.1 <= s["a_ISO_iso281"] <= 50.0
        assert s["Lnm_iso281_rev"] == pytest.approx(s["a_ISO_iso281"] * s["L10_iso281_rev"], rel=REL)
    assert s0["a_ISO_iso281"] > s1["a_ISO_iso281"]  # a_ISO falls with P (e_C C_u / P)


def _plain(text):
    return " ".join(text.split())


def test_json_cli_and_report_show_the_same_numbers(tmp_path):
    args = ["rating", "7206 B", "--load", "Fr=2kN", "--load", "Fa=4kN", "--speed", "1500rpm"]
    runner = CliRunner()
    out = runner.invoke(app, [*args, "--json"])
    assert out.exit_code == 0, out.output
    system = json.loads(out.output)["cases"][0]["system"]
    assert system["P_iso281_N"] == pytest.approx(2980.0, rel=REL)
    line = caption(system)
    assert line.startswith("ISO 281: P = 2.98 kN, C = 20.5 kN (catalogue), L10 = 325.5 10⁶ rev")
    table = runner.invoke(app, args, env={"COLUMNS": "200"})
    assert table.exit_code == 0, table.output
    assert _plain(line) in _plain(table.output)
    path = tmp_path / "r.html"
    bk.analyze("7206 B", load={"F_x": "2 kN", "F_z": "4 kN"}, speed="1500 rpm").report(path)
    html = path.read_text()
    assert _plain(line) in _plain(re.sub(r"<[^>]+>", " ", html))


def test_a_batch_with_refused_cases_gives_what_each_case_gives_alone():
    """Cases without an ISO 281 P (here f0 Fa/C0r below Table 3) leave the others' P as computed alone;
    each refused case gets its note; the valid cases are computed together, not one by one."""
    from bearingkit.analysis.rating import iso281 as rating_iso281
    from bearingkit.physics.life import iso281_load

    c0, f0 = 20_400.0, 13.9
    fr = np.array([500.0, 10e3, 4e3, 0.0, 2e3, 1e3])
    # 0, 5: below Table 3 with F_r < (0.172/0.19) C0r/f0 = 1329 N (no P); 4: above it
    fa = np.array([100.0, 1e3, 0.0, 3e3, 12e3, 50.0])
    notes = []
    calls = []
    law = iso281_load.equivalent_dynamic_load

    def counted(*args, **kwargs):
        calls.append(np.size(args[0]))
        return law(*args, **kwargs)

    iso281_load.equivalent_dynamic_load = counted
    try:
        p, failed = rating_iso281._equivalent_load(fr, fa, "deep_groove_ball", 0.0, 1, c0, f0, notes)
    finally:
        iso281_load.equivalent_dynamic_load = law
    np.testing.assert_array_equal(failed, [True, False, False, False, True, True])
    for c in np.flatnonzero(~failed):
        assert p[c] == law(fr[c], fa[c], "deep_groove_ball", static_rating=c0, f0=f0)
    assert [n.split(":")[0] for n in notes] == ["case 0", "case 4", "case 5"]
    assert "table range [0.172, 6.89]" in notes[0] and "table range" in notes[1]
    assert sorted(calls) == [1, 1, 1, 3, 6]  # the batch, the 3 valid cases together, each refused one


def test_6209_with_a_small_axial_load_keeps_the_other_cases_rated():
    a = bk.analyze(
        "6209",
        load=[
            {"F_x": "10 kN", "F_z": "100 N"},
            {"F_x": "10 kN", "F_z": "5 kN"},
            {"F_x": "300 N", "F_z": "100 N"},
        ],
    )
    s0, s1, s2 = _system(a, 0), _system(a, 1), _system(a, 2)
    # case 0: f0 F_a/C0r below Table 3, but F_r = 10 kN >= (0.172/0.19) C0r/f0: P = F_r (docs/ratings.md)
    assert s0["P_iso281_N"] == pytest.approx(10e3, rel=1e-12)
    assert "case(s) 0: f0 F_a/C0r below ISO 281 Table 3's first row" in s0["iso281_note"]
    assert s1["P_iso281_N"] > 10e3  # F_a/F_r = 0.5 > e: the axial load counts
    # case 2: below Table 3 with a small F_r: F_a/F_r = 1/3 may exceed e there, ISO 281 gives no Y
    assert s2["P_iso281_N"] is None and "case 2: no ISO 281 basic rating life" in s2["iso281_note"]
