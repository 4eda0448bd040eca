"""Groove shoulder heights (issue 23): file input → rating, the truncation flag at its closed-form edge,
the kinds' defaults (a 7206 pair at ~1.95 GPa is not flagged, a deep groove under a large axial load is),
four-point arches, and one-line refusals of bad heights."""

from __future__ import annotations

import copy
import tomllib

import numpy as np
import pytest

import bearingkit as bk
from bearingkit.analysis.rating.assembly import rate
from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings.self_aligning import self_aligning_ball
from bearingkit.bearings.slewing import four_point_contact_ball
from bearingkit.bearings.standard import deep_groove_ball
from bearingkit.errors import InputError
from bearingkit.io.loader import from_dict

DW = 10.56e-3
# A 7206 B (40°) back-to-back pair with the catalogue's estimated internal geometry (7206B: 11 balls of
# 0.33 (D - d), d_m = (d + D)/2), 10 µm axial preload, at rest: 1.95 GPa on the loaded row.
PAIR = tomllib.loads(
    """
[bearing]
type = "angular_contact_pair"
name = "7206 B DB"
[geometry]
bore = "30 mm"
outer_diameter = "62 mm"
arrangement = "DB"
n_elements = 11
element_diameter = "10.56 mm"
pitch_diameter = "46 mm"
contact_angle = "40 deg"
row_spacing = "16 mm"
clearance_axial = "-10 um"
[[load_cases]]
name = "combined"
F_z = "3.2 kN"
F_x = "2 kN"
"""
)
FI, FO = 0.52, 0.53  # the builder's default conformities


def _pair(**geometry):
    data = copy.deepcopy(PAIR)
    data["geometry"].update(geometry)
    return from_dict(data, "pair.toml")


def _edge_height(state, dw, f, side, case=0):
    """Smallest shoulder height / D_w holding every loaded ellipse of one ring, by hand:
    h* = f (1 − cos(α + arcsin(a/(f D_w)))) over the loaded balls."""
    alpha = np.abs(state.contact_angle[case])
    a = state.extras[f"semi_major_{side}"][case]
    loaded = state.load[case] > 0
    edge = alpha + np.arcsin(a / (f * dw))
    return float(np.max(f * (1.0 - np.cos(edge[loaded]))))


def test_hertz_semi_axis_agrees_with_hamrock_brewe():
    """The semi-major axes the edge angle uses, checked against Hamrock & Brewe's (1983) closed-form
    approximation (their stated accuracy: a few per cent) for the most loaded inner contact."""
    a = bk.analyze(_pair())
    st = a.statics.row("balls_A")
    k = int(np.argmax(st.load[0]))
    q, alpha = st.load[0, k], st.contact_angle[0, k]
    gamma = DW * np.cos(alpha) / 46e-3
    rx, ry = DW / 2 * (1 - gamma), FI * DW / (2 * FI - 1)
    e_prime = 208e9 / (1 - 0.3**2)
    kappa = 1.0339 * (ry / rx) ** 0.636
    ell = 1.0003 + 0.5968 * rx / ry
    r_eff = 1 / (1 / rx + 1 / ry)
    a_hb = (6 * kappa**2 * ell * q * r_eff / (np.pi * e_prime)) ** (1 / 3)
    assert st.extras["semi_major_inner"][0, k] == pytest.approx(a_hb, rel=0.03)


def test_flag_fires_exactly_at_the_closed_form_edge():
    a = bk.analyze(_pair())
    res = a.statics
    st = res.row("balls_A")
    assert st.max_pressure[0].max() == pytest.approx(1.95e9, rel=0.01)
    h_star = max(_edge_height(st, DW, FI, "inner"), _edge_height(st, DW, FO, "outer"))
    assert 0.20 < h_star < 0.35  # the old default 0.20 D_w cuts it, the angular contact default holds it
    for factor, flagged in ((1 - 1e-6, True), (1 + 1e-6, False)):
        out = rate(res, shoulder_height={"balls_A": factor * h_star, "balls_B": 0.45})
        assert bool(out.row("balls_A").flags["truncated_ellipse"][0]) is flagged


def test_file_heights_reach_the_rating_as_lengths_or_fractions():
    # the rating reads the cases solved with the TS's pitch-radius tilt arm (the pair tilts under its
    # moment; pipeline.rating.statics): the edge heights by hand from that solve
    from bearingkit.pipeline.rating.statics import ts_statics

    st = ts_statics(bk.analyze(_pair()))[0].row("balls_A")
    h_i = _edge_height(st, DW, FI, "inner")
    h_o = _edge_height(st, DW, FO, "outer")
    hi_mm = f"{h_i * DW * 1e3 * (1 - 1e-6)!r} mm"  # just below the inner edge: flagged, by the inner ring
    low = bk.analyze(_pair(shoulder_height_inner=hi_mm, shoulder_height_outer=0.45))
    assert low.rating.row("balls_A").flags["truncated_ellipse"][0]
    assert any("inner" in w and "given" in w for w in low.rating.warnings[0])
    # the warning names the height that would hold the ellipses: the closed-form edge h_i (inner only:
    # the outer shoulder 0.45 D_w holds)
    text = next(w for w in low.rating.warnings[0] if "truncated" in w)
    assert f"the loaded ellipses need inner {h_i:.3g} D_w)" in text, text
    high = bk.analyze(_pair(shoulder_height_inner=h_i * (1 + 1e-6), shoulder_height_outer=h_o * (1 + 1e-6)))
    assert not high.rating.row("balls_A").flags["truncated_ellipse"][0]
    # only the outer ring given: the inner ring keeps the angular contact default (0.35 > h_i)
    outer = bk.analyze(_pair(shoulder_height_outer=h_o * (1 - 1e-6)))
    assert outer.rating.row("balls_A").flags["truncated_ellipse"][0]


def test_7206_pair_at_1_95_gpa_is_held_by_its_high_shoulders_by_default():
    a = bk.analyze(_pair())
    assert not any(a.rating.row(r).flags["truncated_ellipse"][0] for r in ("balls_A", "balls_B"))
    assert not any("truncated" in w for w in a.warnings[0])
    # the former kind-blind default (0.20 D_w) flagged it — the report
    assert rate(a.statics, shoulder_height=0.20).row("balls_A").flags["truncated_ellipse"][0]


def test_deep_groove_under_a_large_axial_load_is_still_flagged():
    """6209-size (9 balls 12.7 mm, d_m 65 mm, f 0.52, 15 µm): F_a = 30 kN drives the contact to ~30° and
    its ellipse over the 0.20 D_w shoulder, below the ISO 76 stress limit (so not an overload flag)."""
    b = deep_groove_ball(
        n_elements=9,
        element_diameter=12.7e-3,
        pitch_diameter=65e-3,
        conformity_inner=0.52,
        conformity_outer=0.52,
        clearance_radial=15e-6,
    )
    res = solve(b, load_vector(F_x=[1e3, 1e3], F_z=[3e3, 30e3]), free=[True, True, True, False, False])
    out = rate(res)
    st = res.row("balls")
    assert st.max_pressure[1].max() < 4.2e9
    h_star = [_edge_height(st, 12.7e-3, 0.52, "inner", case=c) for c in (0, 1)]
    assert h_star[0] < 0.20 < h_star[1]  # the edge angle by hand puts the 0.20 D_w shoulder between them
    assert list(out.row("balls").flags["truncated_ellipse"]) == [False, True]


def test_self_aligning_inner_grooves_are_checked():
    b = self_aligning_ball(
        n_elements=15, element_diameter=9.525e-3, pitch_diameter=65e-3, contact_angle=np.radians(12)
    )
    res = solve(b, load_vector(F_x=[3e3]), free=[True, True, True, False, False])
    assert not rate(res).row("row_A").flags["truncated_ellipse"][0]
    assert rate(res, shoulder_height=0.02).row("row_A").flags["truncated_ellipse"][0]


def test_four_point_arcs_flag_the_seam_and_the_shoulder():
    # 15° arches under radial load: both diagonals carry near the groove bottom, the ellipses cross the seam
    low = four_point_contact_ball(
        n_elements=12, element_diameter=11.906e-3, pitch_diameter=60e-3, contact_angle=np.radians(15)
    )
    res = solve(low, load_vector(F_x=[20e3]), free=[True, True, False, False, False])
    out = rate(res)
    assert out.row("balls").flags["truncated_ellipse"][0]
    assert any("arch (shoulder or seam)" in w for w in out.warnings[0])
    # it is the seam: no shoulder height, however high, holds these ellipses
    assert rate(res, shoulder_height=0.45).row("balls").flags["truncated_ellipse"][0]
    # the QJ example's axial load is held by its 0.40 D_w arches, not by a 0.15 D_w one
    qj = bk.analyze("examples/qj_208.toml")
    assert not qj.rating.row("balls").flags["truncated_ellipse"][0]
    assert rate(qj.statics, shoulder_height=0.15).row("balls").flags["truncated_ellipse"][0]


@pytest.mark.parametrize(
    ("geometry", "words"),
    [
        ({"shoulder_height_inner": "-1 mm"}, ("geometry.shoulder_height_inner", "positive")),
        ({"shoulder_height_inner": "6 mm"}, ("geometry.shoulder_height_inner", "groove depth", "0.52 D_w")),
        ({"shoulder_height_outer": 1.2}, ("geometry.shoulder_height_outer", "(0, 1)")),
        ({"shoulder_height_outer": "abc"}, ("geometry.shoulder_height_outer",)),
        # a number in quotes is neither a length nor, silently, a fraction (strict numbers, io.fields)
        ({"shoulder_height_inner": "0.35"}, ("geometry.shoulder_height_inner", "in quotes", "= 0.35")),
        ({"shoulder_height_inner": True}, ("geometry.shoulder_height_inner", "fraction of D_w")),
        (
            {"shoulder_height_inner": 0.5, "shoulder_height_outer": 0.5},
            ("shoulder_height_inner + shoulder_height_outer", "overlap"),
        ),
    ],
)
def test_bad_heights_are_refused_in_one_line(geometry, words):
    with pytest.raises(InputError) as exc:
        _pair(**geometry)
    msg = str(exc.value)
    assert "\n" not in msg and msg.startswith("pair.toml: ")
    assert all(w in msg for w in words), msg


def test_no_outer_groove_on_a_self_aligning_ball_bearing():
    data = tomllib.loads(open("examples/sabb_1209.toml").read())
    data["geometry"]["shoulder_height_outer"] = 0.3
    with pytest.raises(InputError, match="shoulder_height_outer") as exc:
        from_dict(data, "sabb.toml")
    assert "\n" not in str(exc.value)
    data["geometry"].pop("shoulder_height_outer")
    data["geometry"]["shoulder_height_inner"] = "2 mm"
    assert from_dict(data, "sabb.toml").model.rows[0].kind == "self_aligning_ball"
