"""Estimates of the kinds of issue 17 (four-point, self-aligning ball, spherical roller, needle roller)
and series 64: the checks beyond "within 10 % of the catalogue" (test_estimate.py) — where the rule
constants come from, what a catalogue's rating basis is, and the stated deviations.

Catalogues: NSK *Rolling Bearings* CAT. No. E1102e (NSK-E1102) and SKF *General Catalogue* 6000, Russian
edition, data of 2006 (SKF-6000RU); the page of every number is in the data files' ``source`` column.
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from bearingkit.catalogue import basis, entries, estimate, find, four_point_radial, internal, ratings
from bearingkit.catalogue.iso_ratings import axial_factors
from bearingkit.catalogue.tables import reference_ratings, reference_table
from bearingkit.physics.life import iso76, iso281

DEG = math.pi / 180


def errors(rows):
    """(C, C0) relative errors of the estimate against each row's catalogue ratings."""
    out = np.array([ratings(estimate(e)) for e in rows]) / np.array([(e.C, e.C0) for e in rows]) - 1.0
    return out[:, 0], out[:, 1]


# --- four-point contact ball (QJ) ---------------------------------------------------------------------
def test_qj_contact_angle_is_35_deg_by_nsk_load_centre_spacing():
    """NSK E1102 B68-B70 print the load-centre spacing a0 of every QJ bearing: a0 = d_m tan α with
    d_m = (d + D)/2 gives α = 35.0° for all 30 rows (a0 printed to 0.1 mm), the angle the estimate uses."""
    for e in entries("four_point_contact_ball").values():
        alpha = math.atan(e.number("a0_mm", 1e-3) / (0.5 * (e.bore + e.outer_diameter)))
        assert alpha == pytest.approx(35 * DEG, abs=0.2 * DEG), e.designation
        assert estimate(e).contact_angle == pytest.approx(35 * DEG)


def test_qj_axial_factors_are_the_double_row_angular_contact_ones():
    """Pure axial load on a QJ bearing: P = 1.07 F_a, P0 = 0.58 F_a — the values SKF 6000 p. 455 prints
    for four-point bearings (P = 0.6 F_r + 1.07 F_a, P0 = F_r + 0.58 F_a) and ISO 281 Table 3 / ISO 76
    Table 2 give for a double-row angular contact bearing at 35° (physics.life.kinds)."""
    y, y0 = axial_factors(35 * DEG)
    assert y == pytest.approx(1.07, abs=1e-12) and y0 == pytest.approx(0.58, abs=1e-12)
    assert basis("four_point_contact_ball").startswith("axial")


def test_qj_nsk_axial_and_skf_radial_ratings_are_one_bearing_on_two_bases():
    """The same QJ sizes in two catalogues: NSK prints C_a, C_0a (P_a = F_a), SKF C_r, C_0r with the
    double-row factors. C_a = C_r/1.07 and C_0a = C_0r/0.58 connect them: NSK · Y / SKF lies at 0.88–1.05
    (C) and 0.85–1.09 (C0) for all 30 common sizes, median 0.94 and 0.92 — the remaining few per cent are
    the makers' own (several SKF rows are SKF Explorer, rated above ISO's b_m)."""
    skf = reference_ratings("four_point_radial_skf")
    y, y0 = axial_factors(35 * DEG)
    rc, r0 = [], []
    for e in entries("four_point_contact_ball").values():
        c_r, c0_r, _ = skf[e.designation]
        rc.append(e.C * y / c_r)
        r0.append(e.C0 * y0 / c0_r)
    assert len(rc) == 30
    assert 0.85 < min(rc) and max(rc) < 1.05 and 0.90 < np.median(rc) < 0.97
    assert 0.85 < min(r0) and max(r0) < 1.10 and 0.90 < np.median(r0) < 0.97


def test_qj_radial_ratings_against_skf():
    """The radial C_r, C_0r (i = 2, α = 35°) of the estimate against SKF 6000 pp. 456-458. The estimate
    follows NSK's (axial) ratings (median −1 % C, −3 % C0, docs/catalogue.md); SKF rates the same sizes
    6–8 % above NSK (test above: NSK · Y / SKF median 0.94 and 0.92; SKF Explorer is above ISO's b_m). So
    against SKF the estimate's median is that offset: −6 % (C), −10 % (C0), every size within −21…+1 %."""
    skf = reference_ratings("four_point_radial_skf")
    rows = entries("four_point_contact_ball")
    err = np.array([np.array(four_point_radial(estimate(e))) / skf[e.designation][:2] for e in rows.values()])
    err -= 1.0
    assert err.shape == (30, 2)
    assert -0.09 < np.median(err[:, 0]) < -0.03 and -0.13 < np.median(err[:, 1]) < -0.07
    assert err.min() > -0.22 and err.max() < 0.02


def test_qj_rule_is_the_angular_contact_rule_unchanged():
    """No constant was chosen for QJ bearings: they use the single-row angular contact rule (k_w, width cap,
    the machined cage pitch of their brass cages: SKF QJ … MA), and the axial equivalents then follow NSK
    within 10 % for every size."""
    assert internal.RULES["four_point_contact_ball"] == internal.RULES["angular_contact_ball"]
    ec, e0 = errors(list(entries("four_point_contact_ball").values()))
    assert np.mean(np.abs(ec) < 0.10) == 1.0 and np.mean(np.abs(e0) < 0.10) == 1.0
    assert abs(np.median(ec)) < 0.05 and abs(np.median(e0)) < 0.05
    assert all(internal.cage_type(e) == "machined" for e in entries("four_point_contact_ball").values())


# --- self-aligning ball ----------------------------------------------------------------------------------
def test_self_aligning_angle_from_published_e_and_balls_within_the_rings():
    """α = atan(e/1.5) from NSK's e (ISO 281 Table 3: e = 1.5 tan α); the rows sit on the sphere at
    z = ±(d_m/2) tan α, and the estimate keeps each ball within the ring width and on its side of the
    centre plane (the engine refuses crossing rows)."""
    for e in entries("self_aligning_ball").values():
        est = estimate(e)
        if e.extra["e"]:
            assert math.tan(est.contact_angle) * 1.5 == pytest.approx(float(e.extra["e"]))
        else:  # series 13, 23: no printed e; the rows fill the width, B = 0.25 (D - d) + d_m tan α
            ball = internal.SELF_ALIGNING_E_BALL_SHARE * (e.outer_diameter - e.bore)
            assert est.pitch_diameter * math.tan(est.contact_angle) == pytest.approx(e.width - ball)
        z_c = 0.5 * est.pitch_diameter * math.tan(est.contact_angle)
        assert z_c + 0.5 * est.element_diameter <= 0.5 * e.width + 1e-12, e.designation
        assert z_c > 0.5 * est.element_diameter, e.designation


def test_self_aligning_derived_factors_against_nsk():
    """ISO 281 Table 2 column 3 and ISO 76 Table 1 column 2 (self-aligning) are not shipped; f_c and f0 are
    DERIVED in physics.life.kinds (f_c: column 1 × the ISO/TR 1281-1 conformity ratio for the sphere;
    f0: the ISO 76 stress definition at 4600 MPa). With the estimated geometry (cage pitch 1.20, the
    angular contact value; ball size set by the ring width) C and C0 follow NSK E1102 B74-B79 over all 46
    sizes of the 12/22 series (42 to 100 mm; 1221, 1222, 2221, 2222 rated later from B78) with median
    errors within ±3 % and at least 3 sizes in 4 within 10 % — the
    comparison that supports the derived columns (no constant was chosen to match C0). The 13/23 rows,
    rated later from the same pages, are low (docs/catalogue.md accuracy table; named in
    test_accuracy_named): they do not support the columns, and are not counted here."""
    ec, e0 = errors(
        [
            e
            for e in entries("self_aligning_ball").values()
            if e.C is not None and e.designation[:2] in ("12", "22")
        ]
    )
    assert len(ec) == 46
    assert abs(np.median(ec)) < 0.03 and abs(np.median(e0)) < 0.03
    assert np.mean(np.abs(ec) < 0.10) >= 0.75 and np.mean(np.abs(e0) < 0.10) >= 0.75


# --- spherical roller --------------------------------------------------------------------------------------
def _spherical_implied(e) -> tuple[float, float]:
    """(D_we/(D − d), L_we/(B/2)) for which ISO 281 eq. (9) and ISO 76 eq. (7) give exactly NSK's C and C0
    at the printed e's α, d_m = (d + D)/2 and Z = π d_m/(1.15 D_we) (Z continuous): the roller the maker's
    two ratings imply, independent of the estimation rules."""
    d_m = 0.5 * (e.bore + e.outer_diameter)
    a = math.atan(float(e.extra["e"]) / 1.5)

    def count(d_w):
        return math.pi * d_m / (1.15 * d_w)

    def length(d_w):  # C0 is linear in L_we
        return e.C0 / float(iso76.static_rating_roller(d_w, 1.0, d_m, a, count(d_w), 2, "radial"))

    def gap(d_w):
        c = iso281.dynamic_rating_roller(d_w, length(d_w), d_m, a, count(d_w), 2, "spherical_roller")
        return float(c) - e.C

    d_w = brentq(gap, 0.03 * d_m, 0.29 * d_m / math.cos(a))
    return d_w / (e.outer_diameter - e.bore), length(d_w) / (0.5 * e.width)


def test_spherical_rules_are_the_medians_of_the_implied_rollers():
    """The calibration of internal.SPHERICAL_RULES, recomputed: the standard rule is the median over the 230
    series (41 sizes), the EA rule over the 22208-22226 EA sizes (16); and the claim of docs/catalogue.md that
    the other designs imply the same roller: per series and design with two sizes or more, over 222 CA/CD,
    223 CA/C and 230-241, D_we 0.246-0.254 (D - d) and L_we 0.70-0.74 B/2."""
    groups: dict = {}
    for e in entries("spherical_roller").values():
        groups.setdefault((e.series, e.extra["design"]), []).append(_spherical_implied(e))
    std = np.array([x for (series, _), v in groups.items() if series == "230" for x in v])
    ea = np.array(groups[("222", "EA")])
    assert len(std) == 41 and len(ea) == 16
    for rule, implied in ((internal.SPHERICAL_RULES[""], std), (internal.SPHERICAL_RULES["EA"], ea)):
        assert (rule.k_w, rule.length) == pytest.approx(tuple(np.median(implied, axis=0)), abs=6e-4)
    others = {
        k: np.median(v, axis=0)
        for k, v in groups.items()
        if len(v) >= 2 and k[1] != "EA" and k[0] != "213" and k != ("222", "C")
    }
    assert len(others) == 15  # 222 CA, CD; 223 C, CA; 230 CA, CD; 231, 232, 240, 241 C, CA; 239 CA
    for k, (k_w, k_l) in others.items():
        assert 0.246 < k_w < 0.254 and 0.70 < k_l < 0.745, k
    # NSK's EA rollers are longer: 223 EA longer still (the cause of the 223 EA deviations)
    assert np.median(groups[("223", "EA")], axis=0)[1] > 0.80


def test_spherical_rows_fit_radially_and_axially():
    for e in entries("spherical_roller").values():
        est = estimate(e)
        assert est.rows == 2
        if e.extra["e"]:
            assert math.tan(est.contact_angle) * 1.5 == pytest.approx(float(e.extra["e"]))
            # every row within the ring faces (232/530, which reached 0.22 mm past them under the rule of
            # 0.24 (D - d) and 0.80 B/2, fits with the calibrated one) and on its side of the centre plane
            assert internal.axial_margin(est) > 0, e.designation
            a = est.contact_angle
            inner = est.extra["row_offset"] - 0.5 * (
                est.effective_length * math.cos(a) + est.element_diameter * math.sin(a)
            )
            assert inner > 0, e.designation
        else:  # no printed e: the rows reach the faces less the chamfer (the angle is the geometry's)
            assert e.chamfer - 1e-9 <= internal.axial_margin(est) < e.chamfer + 1e-3 * e.width, e.designation
            # and the rollers (their full diameter) stay on their side of the centre plane
            a = est.contact_angle
            inner = est.extra["row_offset"] - 0.5 * (
                est.effective_length * math.cos(a) + est.element_diameter * math.sin(a)
            )
            assert inner > 0, e.designation


def test_spherical_given_angle_keeps_the_rule_roller():
    """The centre-plane trim of D_we serves the printed e only: at an angle the user gives, the rule's roller
    stays (a review found that at 8.2° on a 22208 the trim left a 0.5 mm roller, 315 per row)."""
    e = entries("spherical_roller")["22208"]
    rule = internal.SPHERICAL_RULES["EA"]
    for deg in (8.0, 8.2, 9.0, 12.0):
        est = estimate(e, contact_angle=math.radians(deg))
        assert est.element_diameter == pytest.approx(rule.k_w * (e.outer_diameter - e.bore), rel=1e-12)
        assert est.contact_angle == pytest.approx(math.radians(deg)) and "(given)" in est.notes[-1]


def test_spherical_small_sizes_are_nsk_older_c_design():
    """NSK E1102 lists 22205-22207 in its design C (B178: "type EA has especially high load capacity"); the
    standard rule (calibrated on the 230 series, NSK's CA/CD designs) rates them between NSK's design C and
    SKF's E design of the same size (SKF 6000 p. 716: 49, 64, 86.5 kN): C +5…+14 % over NSK's, −13…−16 %
    under SKF's (the old single rule, EA-like, was 17-26 % over NSK's and within 10 % of SKF's). That is
    the stated mechanism of these three deviations; no constant was changed for them."""
    skf = reference_ratings("spherical_roller_skf")
    rows = entries("spherical_roller")
    for name in ["22205", "22206", "22207"]:
        e = rows[name]
        assert e.extra["design"] == "C"
        c, _ = ratings(estimate(e))
        assert 0.05 < c / e.C - 1 < 0.15 and -0.17 < c / skf[name][0] - 1 < -0.12, name
    # for the sizes NSK makes in its high-capacity EA design the two makers differ by SKF Explorer's uplift
    # only (SKF/NSK 1.05-1.16), and the estimate (the EA rule) follows NSK: −6.0…+2.0 % (the 223 EA run low,
    # Known deviations; 22309 −6.0 %, 22310 −5.7 %, so this is no longer the 5 % it was with the old rule)
    for name in ["22208", "22209", "22210", "22211", "22308", "22309", "22310", "22311"]:
        e = rows[name]
        c, _ = ratings(estimate(e))
        assert e.extra["design"] == "EA" and 1.0 < skf[name][0] / e.C < 1.17
        assert -0.06 < c / e.C - 1 < 0.03, name


# --- needle roller -----------------------------------------------------------------------------------------
def test_needle_cage_pitch_and_length_from_nsk_cage_assemblies():
    """Where the needle size is published: NSK's cage & needle assemblies (E1102 B248-B251) give F_w and
    E_w, so D_w = (E_w - F_w)/2. With L_we = 0.80 B_c (the estimate's length ratio, assumed; C0 fixes only
    Z L_we and C then varies as L_we^(1/36), so the C check hardly depends on it) the needle count that
    gives the published C0 (ISO 76) makes ISO 281 give the published C within 2 % for every assembly, and
    the pitch ratio π d_m/(Z D_w) of those sets lies at 1.5-2.1 with median 1.7 — where the rule's
    cage pitch 1.80 comes from (needle cages are stout: a roller pitch of ~1.8 D_w)."""
    rule = internal.RULES["needle_roller"]
    pitches = []
    for r in reference_table("needle_cage_assemblies_nsk"):
        fw, ew, bc = (float(r[k]) * 1e-3 for k in ("F_w_mm", "E_w_mm", "B_c_mm"))
        dw, length = 0.5 * (ew - fw), rule.length * bc
        dm = fw + dw
        z = float(r["C0r_N"]) / float(iso76.static_rating_roller(dw, length, dm, 0.0, 1))
        c = float(iso281.dynamic_rating_roller(dw, length, dm, 0.0, z, 1, "needle_roller_machined"))
        assert c == pytest.approx(float(r["Cr_N"]), rel=0.02), r["designation"]
        pitches.append(math.pi * dm / (z * dw))
    assert 1.5 < min(pitches) and max(pitches) < 2.15
    assert abs(np.median(pitches) - rule.pitch) < 0.1


def test_needle_ratings_follow_without_tuning_c0():
    """With the pitch and length from the assemblies, only k_w (needle share of the section) was chosen,
    by C over the NA table; C0 then follows NSK E1102 B260-B269 with a median error within ±5 %."""
    rows = [e for e in entries("needle_roller").values() if not e.designation.startswith("R")]
    ec, e0 = errors(rows)
    assert len(rows) == 46
    assert abs(np.median(ec)) < 0.05 and abs(np.median(e0)) < 0.05
    assert np.mean(np.abs(ec) < 0.10) >= 0.8 and np.mean(np.abs(e0) < 0.10) >= 0.75


def test_rna_twin_runs_on_the_shaft():
    """RNA = NA without inner ring: bore = F_w, same outer ring, same needle set and NSK rating."""
    rows = entries("needle_roller")
    na, rna = rows["NA4906"], rows["RNA4906"]
    assert rna.bore == pytest.approx(na.number("F_w_mm", 1e-3)) and rna.outer_diameter == na.outer_diameter
    assert (rna.C, rna.C0) == (na.C, na.C0)
    a, b = estimate(na), estimate(rna)
    assert (a.n_elements, a.element_diameter, a.pitch_diameter) == (
        b.n_elements,
        b.element_diameter,
        b.pitch_diameter,
    )
    assert a.extra["inner_ring"] and not b.extra["inner_ring"]
    assert [e.designation for e in find("RNA49*")][:2] == ["RNA4900", "RNA4901"]


# --- deep groove series 64 ----------------------------------------------------------------------------------
def test_series_64_against_skf():
    """Series 64 (not in NSK E1102) against SKF 6000 pp. 304-312: C and C0 within 10 % for the listed
    sizes; the heavy section makes the width cap decide the ball size (0.80 B, the angular contact cap)."""
    rated = {e.designation: e for e in find("64*") if e.C is not None}  # 6419, 6424-6430: dimensions only
    rows = {k: e for k, e in rated.items() if e.source.startswith("SKF-6000RU")}
    assert len(rows) == 16
    # the rest: KRW's 6419, 6420 (Lieferprogramm 2006 p. 148) and ZVL's 6422 (p. 089), rated later
    assert {k: e.source.split(" ")[0] for k, e in rated.items() if k not in rows} == {
        "6419": "KRW-2006:148",
        "6420": "KRW-2006:148",
        "6422": "ZVL-BearingCatalogue:89",
    }
    for name in ["6403", "6406", "6407", "6408", "6413", "6416", "6417", "6418"]:
        c, c0 = ratings(estimate(rows[name]))
        assert c == pytest.approx(rows[name].C, rel=0.10), name
        assert c0 == pytest.approx(rows[name].C0, rel=0.10), name
    assert "D_w capped at 0.8 B/1" in estimate(rows["6406"]).notes[1]
