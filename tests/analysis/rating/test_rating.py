"""Tests of bearingkit.analysis.rating.assembly (ratings and lives of whole bearings). SI units throughout.

Reference values are closed forms of the standards (ISO 281 L10 = (C/P)^p, thrust ball equal loads,
Weibull system life), invariants (scaling, system <= rows) and the warnings' triggering conditions.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingkit.analysis.rating.assembly import WEIBULL_SLOPES, rate, register_row_rater, system_life
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.quasistatic import SolverOptions, load_vector, solve
from bearingkit.bearings.common import eccentric_axial_load
from bearingkit.bearings.standard import (
    angular_contact_ball,
    cylindrical_roller,
    cylindrical_roller_thrust,
    thrust_ball,
)
from bearingkit.bearings.turntable import composite_turntable
from bearingkit.errors import InputError
from bearingkit.physics.contact.profiles import make_profile
from bearingkit.physics.life import iso281
from bearingkit.rows.ball.row import BallRow

INCH = 25.4e-3
# SKF 6205 internal geometry of the CWRU data set (see bearingkit.validation.literature_iso)
DW, DPW, Z = 0.3126 * INCH, 1.537 * INCH, 9


def _deep_groove(phase=0.0):
    row = BallRow(n_elements=Z, element_diameter=DW, pitch_diameter=DPW, azimuth_phase=phase, name="balls")
    return BearingModel((row,), name="6205")


RADIAL = [True, True, False, False, False]


@pytest.mark.parametrize("phase", [0.0, np.pi / Z])
def test_deep_groove_zero_clearance_matches_iso281(phase):
    """ISO/TS 16281 reproduces ISO 281 (C/P)^3 for zero clearance and pure radial load: its constants
    0.407/0.389 come from the continuous Stribeck integrals (Q = Q_max cos^1.5 ψ). With Z = 9 discrete balls
    the sums differ from the integrals by -1.2 % (ball on the load line) … +0.9 % (load between balls);
    the constants are rounded to 3 digits (0.05 %). Tolerance 1.5 %."""
    fr = np.array([1000.0, 3000.0])
    res = solve(_deep_groove(phase), load_vector(F_x=fr), free=RADIAL)
    out = rate(res)
    c = float(iso281.dynamic_rating_ball(DW, DPW, 0.0, Z))
    np.testing.assert_allclose(out.row("balls").load_rating, c, rtol=1e-12)
    np.testing.assert_allclose(out.life, 1e6 * (c / fr) ** 3, rtol=0.015)
    # one row: the system life is the row life
    np.testing.assert_allclose(out.life, out.row("balls").life, rtol=1e-12)
    assert out.row("balls").bearing_type == "deep_groove_ball"
    assert out.warnings == [[], []]


def _thrust(n=15, dw=0.008, dpw=0.06):
    return thrust_ball(n_elements=n, element_diameter=dw, pitch_diameter=dpw)


def test_thrust_ball_equal_loads_is_exact():
    """All balls carry F_a/Z: L10r = (Q_c/Q_e) combination collapses to (C_a/F_a)^3 exactly (the
    conformity term T cancels); both rotating rings give the same life."""
    fa = np.array([2e3, 5e3, 11e3])
    res = solve(_thrust(), load_vector(F_z=fa))
    ca = float(iso281.dynamic_rating_ball(0.008, 0.06, np.pi / 2, 15, bearing_type="thrust_ball"))
    for rotating in ("inner", "outer"):
        out = rate(res, rotating=rotating)
        np.testing.assert_allclose(out.life, 1e6 * (ca / fa) ** 3, rtol=1e-8)
    assert out.row("balls").bearing_type == "thrust_ball"


def test_life_scales_with_rating_over_load_power():
    """L ∝ (C/P)^p through solver + rating: p = 3 for balls; p = 4 for ISO/TS 16281 line contact
    (slice sums with exponent 9/2 and system exponent -8/9: 4.5 · 8/9 = 4; ISO 281 uses 10/3 as its
    point/line compromise). Zero clearance and straight rollers make the distributions homogeneous."""
    res = solve(_thrust(), load_vector(F_z=[3e3, 6e3]))
    life = rate(res).life
    assert life[0] / life[1] == pytest.approx(2.0**3, rel=1e-8)
    c = float(rate(res).row("balls").load_rating[0])
    doubled = rate(res, load_ratings={"balls": 2 * c}).life
    np.testing.assert_allclose(doubled / life, 2.0**3, rtol=1e-12)

    rollers = cylindrical_roller(
        n_elements=14, element_diameter=0.01, effective_length=0.01, pitch_diameter=0.065
    )
    res = solve(rollers, load_vector(F_x=[5e3, 10e3]), free=RADIAL)
    for mode in ("auto", "never"):
        life = rate(res, edge_stress_factor=mode).life
        assert life[0] / life[1] == pytest.approx(2.0**4, rel=1e-8)
    base = rate(res)
    c = float(base.row("rollers").load_rating[0])
    np.testing.assert_allclose(
        rate(res, load_ratings={"rollers": 3 * c}).life / base.life, 3.0**4, rtol=1e-12
    )


def test_edge_stress_factor_shortens_straight_roller_life():
    rollers = cylindrical_roller(
        n_elements=14, element_diameter=0.01, effective_length=0.01, pitch_diameter=0.065
    )
    res = solve(rollers, load_vector(F_x=8e3), free=RADIAL)
    assert rate(res, edge_stress_factor="auto").life[0] < rate(res, edge_stress_factor="never").life[0]


def _composite_case():
    model = composite_turntable()
    load = eccentric_axial_load(3000.0, np.array([0.0, 0.2]), radial_load=3000.0)  # M = 0 and 600 N·m
    return solve(model, load)


def test_composite_turntable_rates_all_five_rows():
    """Seed 000 composite turntable, F_a = F_r = 3 kN, M = 600 N·m: every row rated by ISO 281 / 16281,
    the thrust roller rows with the ISO/TR 1281-1 thrust f_c (no stand-in C)."""
    res = _composite_case()
    assert res.converged.all()
    out = rate(res, speed=2 * np.pi)
    d = out.to_dict(1)  # F_a = F_r = 3 kN, M = 600 N·m
    assert [r["name"] for r in d["rows"]] == [
        "roller_upper",
        "ball_upper",
        "roller_lower",
        "ball_lower",
        "roller_radial",
    ]
    rows = {r["name"]: r for r in d["rows"]}
    for name in ("roller_upper", "roller_lower"):
        row = res.model.row(name)
        ca = iso281.dynamic_rating_roller(
            row.element_diameter,
            row.effective_length,
            row.pitch_diameter,
            np.pi / 2,
            row.n_elements,
            bearing_type="thrust_cylindrical_roller",
        )
        assert rows[name]["C_N"] == pytest.approx(float(ca), rel=1e-12)
        assert rows[name]["bearing_type"] == "thrust_cylindrical_roller"
    for r in d["rows"]:
        assert r["loaded_count"] > 0
        assert r["L10r_rev"] is not None and np.isfinite(r["L10r_rev"]) and r["L10r_rev"] > 0
        # seed-000 loads are small against the ratings: 1 < s0 < 1000
        assert 1.0 < r["static_safety"] < 1e3
    assert not any("unavailable" in w for w in d["warnings"])
    lives = [r["L10r_rev"] for r in d["rows"]]
    assert d["system"]["L10r_rev"] is not None and np.isfinite(d["system"]["L10r_rev"])
    assert d["system"]["L10r_rev"] <= min(lives)
    # hours at 1 r/s: L / 3600
    assert d["system"]["L10h_h"] == pytest.approx(d["system"]["L10r_rev"] / 3600.0, rel=1e-12)
    assert d["system"]["static_safety"] == pytest.approx(min(r["static_safety"] for r in d["rows"]))
    json.dumps(out.to_dict(), allow_nan=False)  # JSON-ready, no NaN anywhere


def test_thrust_roller_equal_loads_is_exact():
    """Straight rollers on flat washers under a centric axial load: every slice carries F_a/(Z n_s), and
    ISO/TS 16281 (λν = 0.73 divided out, q_c = Q_c n_s^(-7/9), Q_c = C_a 2^(2/9)/(λν Z)) collapses to
    L10r = (C_a/(0.73 F_a))^4 — with C_a from the ISO/TR 1281-1 thrust f_c."""
    bearing = cylindrical_roller_thrust(
        n_elements=18, element_diameter=0.008, effective_length=0.008, pitch_diameter=0.07, n_slices=10
    )
    fa = np.array([4e3, 12e3])
    res = solve(bearing, load_vector(F_z=fa))
    ca = float(
        iso281.dynamic_rating_roller(
            0.008, 0.008, 0.07, np.pi / 2, 18, bearing_type="thrust_cylindrical_roller"
        )
    )
    for rotating in ("inner", "outer"):
        out = rate(res, rotating=rotating, edge_stress_factor="never")
        np.testing.assert_allclose(out.row("rollers").load_rating, ca, rtol=1e-12)
        np.testing.assert_allclose(out.life, 1e6 * (ca / (0.73 * fa)) ** 4, rtol=1e-8)


def test_unavailable_rating_masks_life_and_warns():
    """A thrust roller row outside the f_c range (γ = D_we/D_pw = 0.4 > 0.30): C masked, no NaN, warned."""
    bearing = cylindrical_roller_thrust(
        n_elements=6, element_diameter=0.02, effective_length=0.01, pitch_diameter=0.05, n_slices=4
    )
    d = rate(solve(bearing, load_vector(F_z=2e3))).to_dict(0)
    row = d["rows"][0]
    assert row["C_N"] is None and row["L10r_rev"] is None
    assert row["C0_N"] > 0 and row["static_safety"] > 0
    assert any(w.startswith("rollers: C (ISO 281) unavailable") and "gamma" in w for w in d["warnings"])
    assert d["system"]["L10r_rev"] is None
    assert any("system: no life" in w for w in d["warnings"])
    json.dumps(d, allow_nan=False)


def test_unloaded_rows_are_warned_and_excluded():
    res = _composite_case()
    out = rate(res)
    d = out.to_dict(0)  # no moment: the lower rows lift off
    rows = {r["name"]: r for r in d["rows"]}
    for name in ("roller_lower", "ball_lower"):
        assert rows[name]["loaded_count"] == 0 and rows[name]["flags"]["unloaded"]
        assert rows[name]["L10r_rev"] is None and rows[name]["static_safety"] is None
        assert any(w.startswith(f"{name}: no loaded element") for w in d["warnings"])
    loaded = [rows[n]["L10r_rev"] for n in ("roller_upper", "ball_upper", "roller_radial")]
    slopes = [WEIBULL_SLOPES[e] for e in ("roller", "ball", "roller")]
    assert d["system"]["L10r_rev"] == pytest.approx(float(system_life(np.array(loaded), slopes)), rel=1e-12)


def test_overload_warns_static_safety_and_truncation():
    bearing = angular_contact_ball(
        n_elements=12, element_diameter=DW, pitch_diameter=DPW, contact_angle=np.radians(25)
    )
    res = solve(bearing, load_vector(F_x=[1e3, 10e3], F_z=[2e3, 20e3]))
    out = rate(res)
    row = out.row("balls")
    assert row.bearing_type == "angular_contact_ball"
    assert out.warnings[0] == []
    assert row.static_safety[1] < 1 and row.flags["static_overload"][1] and row.flags["truncated_ellipse"][1]
    assert any("s0 =" in w and "< 1" in w for w in out.warnings[1])
    assert any("truncated" in w for w in out.warnings[1])
    # a rating is still returned, with its warnings
    assert not np.ma.getmaskarray(out.life)[1]
    # a deeper shoulder removes the truncation warning
    deep = rate(res, shoulder_height={"balls": 0.4})
    assert not deep.row("balls").flags["truncated_ellipse"][1]


def test_edge_loading_on_tilted_crowned_rollers():
    prof = make_profile("iso16281", effective_length=0.01, element_diameter=0.01)
    bearing = cylindrical_roller(
        n_elements=14, element_diameter=0.01, effective_length=0.01, pitch_diameter=0.065, profile=prof
    )
    res = solve(bearing, load_vector(F_x=[5e3, 5e3], M_y=[0.0, 60.0]))
    out = rate(res)
    flags = out.row("rollers").flags["edge_loading"]
    assert not flags[0] and flags[1]
    assert not any("edge loading" in w for w in out.warnings[0])
    assert any("edge loading" in w for w in out.warnings[1])


def test_straight_rollers_are_edge_loaded():
    bearing = cylindrical_roller(
        n_elements=14, element_diameter=0.01, effective_length=0.01, pitch_diameter=0.065
    )
    out = rate(solve(bearing, load_vector(F_x=5e3), free=RADIAL))
    assert out.row("rollers").flags["edge_loading"][0]


def test_non_converged_case_is_masked_and_warned():
    res = solve(
        _thrust(), load_vector(F_z=[1e3, 5e3]), options=SolverOptions(max_iterations=1, continuation_steps=0)
    )
    assert not res.converged.all()
    out = rate(res, speed=10.0)
    for c in np.flatnonzero(~res.converged):
        d = out.to_dict(int(c))
        assert d["system"]["L10r_rev"] is None and d["system"]["static_safety"] is None
        assert all(r["L10r_rev"] is None and r["static_safety"] is None for r in d["rows"])
        assert any("did not converge" in w for w in d["warnings"])


def test_modified_life():
    res = solve(_thrust(), load_vector(F_z=4e3))
    kw = dict(speed=2 * np.pi * 10, lubricant="ISO_VG68", temperature_C=50.0)
    clean = rate(res, contamination_factor=0.8, **kw)
    dirty = rate(res, contamination_factor=0.1, **kw)
    row = clean.row("balls")
    assert 0.1 <= row.life_modification[0] <= 50.0
    assert row.modified_life[0] == pytest.approx(row.life[0] * row.life_modification[0], rel=1e-12)
    assert dirty.modified_life[0] < clean.modified_life[0]
    r99 = rate(res, contamination_factor=0.8, reliability=0.99, **kw)
    assert r99.a1 == pytest.approx(0.25)  # ISO 281 Table 12
    assert r99.modified_life[0] == pytest.approx(0.25 * clean.modified_life[0], rel=1e-12)
    assert rate(res).to_dict(0)["system"]["Lnmr_rev"] is None
    with pytest.raises(InputError, match="contamination_factor"):
        rate(res, lubricant="ISO_VG68", temperature_C=50.0, speed=10.0)
    with pytest.raises(InputError, match="speed"):
        rate(res, lubricant="ISO_VG68", temperature_C=50.0, contamination_factor=0.5)


def test_outer_ring_rotation_shortens_radial_life():
    res = solve(_deep_groove(), load_vector(F_x=2e3), free=RADIAL)
    assert rate(res, rotating="outer").life[0] < rate(res, rotating="inner").life[0]


def test_bad_input():
    res = solve(_thrust(), load_vector(F_z=1e3))
    with pytest.raises(InputError, match="rotating"):
        rate(res, rotating="cage")
    with pytest.raises(InputError, match="load_ratings"):
        rate(res, load_ratings={"nope": 1e4})
    with pytest.raises(InputError, match="reliability"):
        rate(res, reliability=0.5)
    with pytest.raises(InputError, match="speed"):
        rate(res, speed=-1.0)


def test_row_rater_registry():
    res = solve(_thrust(), load_vector(F_z=1e3))
    calls = []

    def fake(row, state, ctx):
        calls.append(row.name)
        from bearingkit.analysis.rating.assembly import rate_ball_row

        return rate_ball_row(row, state, ctx)

    register_row_rater("ball", fake)
    try:
        rate(res)
    finally:
        from bearingkit.analysis.rating.assembly import rate_ball_row

        register_row_rater("ball", rate_ball_row)
    assert calls == ["balls"]
    with pytest.raises(InputError, match="kind"):
        register_row_rater("", fake)


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.floats(1e3, 1e12), min_size=1, max_size=6),
    st.lists(st.sampled_from([10 / 9, 9 / 8]), min_size=6, max_size=6),
)
def test_system_life_properties(lives, slopes):
    lives = np.array(lives)
    e = np.array(slopes[: len(lives)])
    l_sys = float(system_life(lives, e))
    assert l_sys <= lives.min() * (1 + 1e-12)
    assert np.sum((l_sys / lives) ** e) == pytest.approx(1.0, rel=1e-10)  # 90 % system reliability
    if np.all(e == e[0]):
        assert l_sys == pytest.approx(np.sum(lives ** -e[0]) ** (-1 / e[0]), rel=1e-12)
    # an unloaded (infinitely lived) row changes nothing
    assert float(system_life(np.append(lives, np.inf), np.append(e, 10 / 9))) == pytest.approx(
        l_sys, rel=1e-12
    )


# --- tapered rows (seed 001 TRB 32008J) -------------------------------------------------------------------

TRB_FREE = [True, True, True, False, False]


def _trb_closed_form(row, q_inner, q_outer, c):
    """ISO/TS 16281 radial roller life for equal rollers (per-roller loads; n_s cancels):
    L = [(Q_i/Q_ci)^(9/2) + (Q_e/Q_ce)^(9/2)]^(-8/9), Q_c from C with λν = 0.83, 0.378/0.364, T = 1.038 …"""
    a, z = row.contact_angle_outer, row.n_elements
    g = row.element_diameter * np.cos(a) / row.pitch_diameter
    t = 1.038 * ((1 - g) / (1 + g)) ** (143 / 108)
    qci = c * (1 + t**4.5) ** (2 / 9) / (0.83 * 0.378 * z * np.cos(a))
    qce = c * (1 + t**-4.5) ** (2 / 9) / (0.83 * 0.364 * z * np.cos(a))
    return 1e6 * ((q_inner / qci) ** 4.5 + (q_outer / qce) ** 4.5) ** (-8 / 9)


def test_tapered_pure_axial_matches_closed_form():
    """Centric axial load: every roller carries the cup load Q_e = F_a/(Z sin α_e); roller equilibrium
    Q_e n_e = Q_i n_i + Q_f n_f (no centrifugal force) gives the cone load. The rater must give the TS life
    of these equal loads exactly, whichever ring rotates."""
    from bearingkit.bearings.tapered import seed001_bearing
    from bearingkit.rows.tapered.row import TapGeometry

    model = seed001_bearing()
    row = model.rows[0]
    fa = np.array([2e3, 8e3])
    res = solve(model, load_vector(F_z=fa), free=TRB_FREE)
    assert res.converged.all()
    geo = TapGeometry(row)
    qi_per_qe = np.linalg.solve(np.stack([geo.n_i, geo.n_f], axis=1), geo.n_e)[0]
    q_e = fa / (row.n_elements * np.sin(row.contact_angle_outer))
    np.testing.assert_allclose(res.row("tapered").load, q_e[:, None] * np.ones(row.n_elements), rtol=1e-7)
    c = float(
        iso281.dynamic_rating_roller(
            row.element_diameter,
            row.effective_length,
            row.pitch_diameter,
            row.contact_angle_outer,
            row.n_elements,
            bearing_type="tapered_roller",
        )
    )
    expected = _trb_closed_form(row, qi_per_qe * q_e, q_e, c)
    for rotating in ("inner", "outer"):
        out = rate(res, rotating=rotating)
        r = out.row("tapered")
        assert r.bearing_type == "tapered_roller" and r.element == "roller"
        np.testing.assert_allclose(r.load_rating, c, rtol=1e-12)
        np.testing.assert_allclose(out.life, expected, rtol=1e-6)
        assert np.all(r.static_safety > 1) and np.all(r.static_rating > 0)
    # n_s = 1: the rater says what it could not assess
    assert any("edge loading not assessed" in w for w in out.warnings[0])


def test_tapered_combined_load():
    """Adding a radial load to an axial one shortens the life; L ∝ C^4 through the TS; a sliced, crowned
    row gives a finite life too and JSON has no NaN."""
    from bearingkit.bearings.tapered import seed001_bearing

    model = seed001_bearing()
    res = solve(model, load_vector(F_z=[5e3, 5e3], F_x=[0.0, 4e3]), free=TRB_FREE)
    assert res.converged.all()
    out = rate(res)
    assert out.life[1] < out.life[0]
    c = float(out.row("tapered").load_rating[0])
    np.testing.assert_allclose(rate(res, load_ratings={"tapered": 2 * c}).life / out.life, 2.0**4, rtol=1e-10)
    # a radial load makes the loads unequal: outer-ring rotation (stationary inner ring takes the
    # 9/2-power mean) is then shorter-lived
    assert rate(res, rotating="outer").life[1] < out.life[1]
    json.dumps(out.to_dict(), allow_nan=False)

    prof = make_profile("iso16281_tapered", effective_length=13.66e-3, element_diameter=6.4885e-3)
    sliced = seed001_bearing(n_slices=8, profile=prof, deviation_model="exact")
    res_s = solve(sliced, load_vector(F_z=5e3, F_x=4e3), free=TRB_FREE)
    out_s = rate(res_s)
    assert res_s.converged.all() and np.isfinite(out_s.life[0]) and out_s.life[0] > 0
    assert not any("not assessed" in w for w in out_s.warnings[0])


# --- threaded rows (seed 004 PTRB) ------------------------------------------------------------------------


def test_threaded_pure_axial_matches_closed_form():
    """Centric axial load on the PTRB prototype: every tooth of every roller carries Q = F_a/(Z n sin α)
    on one flank. The rater's C is Zheng et al.'s C_r; the TS life over the n loaded flank rows of Z
    equivalent balls (Q_c from C_r with i = 2n, flat flanks: conformity ratio 1) is
    L = [n((Q/Q_ci)^(10/3) + (Q/Q_ce)^(10/3))]^(-0.9)."""
    from bearingkit.bearings.ptrb import ptrb_model, ptrb_prototype, ptrb_ratings

    g = ptrb_prototype()
    ref = ptrb_ratings(g)
    fa = 10e3
    res = solve(ptrb_model(g), load_vector(F_z=fa))
    assert res.converged.all()
    z, n, a = g.n_elements, g.n_teeth, g.contact_angle
    q = fa / (z * n * np.sin(a))
    tooth = res.row("threaded").extras["tooth_load"][0]
    np.testing.assert_allclose(tooth.max(axis=-1), q, rtol=1e-7)
    assert np.all(tooth.min(axis=-1) == 0.0)
    gam = g.roller_pitch_diameter / g.pitch_diameter
    t = 1.044 * ((1 - gam) / (1 + gam)) ** 1.72
    base = ref.dynamic_radial / (z * (2 * n) ** 0.7 * np.cos(a))
    qci, qce = base / 0.407 * (1 + t ** (10 / 3)) ** 0.3, base / 0.389 * (1 + t ** (-10 / 3)) ** 0.3
    expected = 1e6 * (n * ((q / qci) ** (10 / 3) + (q / qce) ** (10 / 3))) ** -0.9
    for rotating in ("inner", "outer"):
        out = rate(res, rotating=rotating)
        r = out.row("threaded")
        assert r.bearing_type == "planetary_thread_roller" and r.element == "ball"
        assert float(r.load_rating[0]) == pytest.approx(ref.dynamic_radial, rel=1e-12)
        assert float(r.static_rating[0]) == pytest.approx(ref.static_radial, rel=1e-12)
        assert float(out.life[0]) == pytest.approx(expected, rel=1e-7)
    assert "zheng2022" in out.references


def test_threaded_static_safety_at_c0a_is_the_calibrated_fa_max():
    """At F_a = C0a (Zheng et al. 2022 eq. (2) with the calibrated f_amax) the equal-tooth model loads each
    contact with Q_0/f_amax, so s0 = (4200 MPa/p_max)^3 = f_amax."""
    from bearingkit.bearings.ptrb import ptrb_model, ptrb_prototype, ptrb_ratings
    from bearingkit.physics.life.ptrb_rating import F_AMAX_CALIBRATED

    g = ptrb_prototype()
    res = solve(ptrb_model(g), load_vector(F_z=ptrb_ratings(g).static_axial))
    out = rate(res)
    assert float(out.static_safety[0]) == pytest.approx(F_AMAX_CALIBRATED, rel=1e-6)
    assert out.warnings[0] == []


@pytest.mark.parametrize("fr", [2e3, 5e3])
def test_threaded_combined_load(fr):
    """A radial load added to an axial one shortens the life; an overload is rated with a warning.
    (Cases solved one by one: ThreadedKernel has no ``take`` for partially converged batches.)"""
    from bearingkit.bearings.ptrb import ptrb_model

    model = ptrb_model()
    axial = rate(solve(model, load_vector(F_z=10e3)))
    combined = rate(solve(model, load_vector(F_z=10e3, F_x=fr)))
    assert 0 < combined.life[0] < axial.life[0]
    assert combined.static_safety[0] < axial.static_safety[0]
    json.dumps(combined.to_dict(), allow_nan=False)
    over = rate(solve(model, load_vector(F_z=60e3)))
    assert over.row("threaded").flags["static_overload"][0]
    assert not np.ma.getmaskarray(over.life)[0]
    assert any("s0 =" in w for w in over.warnings[0])


def test_every_row_kind_has_a_rater():
    from bearingkit.analysis.rating.assembly import ROW_RATERS

    assert {"ball", "cylindrical", "tapered", "threaded"} <= set(ROW_RATERS)
