"""Tests of bearingkit.analysis.rating (ratings and lives of whole bearings). SI units throughout.

Reference values are closed forms of the standards (ISO 281 L10 = (C/P)^p, thrust ball equal loads,
Weibull system life), invariants (scaling, system <= rows) and the warnings' triggering conditions.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingkit.analysis.model import BearingModel
from bearingkit.analysis.quasistatic import SolverOptions, load_vector, solve
from bearingkit.analysis.rating import (
    WEIBULL_SLOPES,
    rate,
    register_row_rater,
    system_life,
)
from bearingkit.bearings.common import eccentric_axial_load
from bearingkit.bearings.standard import angular_contact_ball, cylindrical_roller, thrust_ball
from bearingkit.bearings.turntable import composite_turntable
from bearingkit.errors import InputError
from bearingkit.physics import iso281
from bearingkit.physics.profiles import make_profile
from bearingkit.rows.ball import BallRow

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


THRUST_ROLLER_C = 2.0e4  # a stand-in C [N] for the thrust roller rows: this test checks the assembly


def test_composite_turntable_rates_all_five_rows():
    res = _composite_case()
    assert res.converged.all()
    out = rate(
        res, speed=2 * np.pi, load_ratings={"roller_upper": THRUST_ROLLER_C, "roller_lower": THRUST_ROLLER_C}
    )
    d = out.to_dict(1)  # F_a = F_r = 3 kN, M = 600 N·m
    assert [r["name"] for r in d["rows"]] == [
        "roller_upper",
        "ball_upper",
        "roller_lower",
        "ball_lower",
        "roller_radial",
    ]
    for r in d["rows"]:
        assert r["loaded_count"] > 0
        assert r["L10r_rev"] is not None and np.isfinite(r["L10r_rev"]) and r["L10r_rev"] > 0
        # seed-000 loads are small against the ratings: 1 < s0 < 1000
        assert 1.0 < r["static_safety"] < 1e3
    lives = [r["L10r_rev"] for r in d["rows"]]
    assert d["system"]["L10r_rev"] <= min(lives)
    # hours at 1 r/s: L / 3600
    assert d["system"]["L10h_h"] == pytest.approx(d["system"]["L10r_rev"] / 3600.0, rel=1e-12)
    assert d["system"]["static_safety"] == pytest.approx(min(r["static_safety"] for r in d["rows"]))
    json.dumps(out.to_dict(), allow_nan=False)  # JSON-ready, no NaN anywhere


def test_composite_turntable_without_thrust_roller_rating_warns():
    res = _composite_case()
    d = rate(res).to_dict(1)
    rows = {r["name"]: r for r in d["rows"]}
    for name in ("roller_upper", "roller_lower"):
        assert rows[name]["C_N"] is None and rows[name]["L10r_rev"] is None
        assert rows[name]["C0_N"] > 0 and rows[name]["static_safety"] > 1
        assert any(w.startswith(f"{name}: C (ISO 281) unavailable") for w in d["warnings"])
    assert rows["ball_upper"]["L10r_rev"] > 0 and rows["roller_radial"]["L10r_rev"] > 0
    assert d["system"]["L10r_rev"] is None
    assert any("system: no life" in w for w in d["warnings"])


def test_unloaded_rows_are_warned_and_excluded():
    res = _composite_case()
    out = rate(res, load_ratings={"roller_upper": THRUST_ROLLER_C, "roller_lower": THRUST_ROLLER_C})
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
        from bearingkit.analysis.rating import rate_ball_row

        return rate_ball_row(row, state, ctx)

    register_row_rater("ball", fake)
    try:
        rate(res)
    finally:
        from bearingkit.analysis.rating import rate_ball_row

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
