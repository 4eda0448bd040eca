"""Tests of bearingkit.physics.contact.profiles (roller crowning profiles). SI units throughout.

Expected values are computed here from the geometry (circles through given points) or from the
published formulas written out independently, never copied from the code's output.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingkit.errors import InputError
from bearingkit.physics.contact import profile_base as pr
from bearingkit.physics.contact.profiles import PROFILES, SEED000_CROWNING, make_profile, seed000_profile
from bearingkit.references import cite

# Seed 000 rollers: axial 4 mm x 4.8 mm, radial 5 mm x 8 mm (Tian et al. 2025, Table 1).
SEED_ROLLERS = [(4.8e-3, 4e-3), (8e-3, 5e-3)]
STEEL_E, STEEL_NU = 2.08e11, 0.3
E_RED = STEEL_E / (1 - STEEL_NU**2)  # Hamrock E' for two identical steel bodies


def _all_profiles(length, diameter):
    """One instance of every registered profile (load-based ones with a plausible design load)."""
    out = []
    for name in sorted(PROFILES):
        if name in ("lundberg", "logarithmic"):
            out.append(make_profile(name, length, diameter, design_load=2e3, e_reduced=E_RED))
        elif name == "johns_gohar":
            out.append(
                make_profile(name, length, diameter, design_load=2e3, e_reduced=E_RED, curvature_sum=1 / 2e-3)
            )
        else:
            out.append(make_profile(name, length, diameter))
    return out


ALL = [p for L, D in SEED_ROLLERS for p in _all_profiles(L, D)] + _all_profiles(20e-3, 5e-3)


# ------------------------------------------------------------------------------------------------
# Invariants for every profile
# ------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("profile", ALL, ids=lambda p: f"{p.name}-{p.effective_length * 1e3:g}mm")
def test_invariants(profile):
    h = profile.half_length
    x = np.linspace(0.0, h, 401)
    c = profile.crown_drop(x)
    assert c.shape == x.shape
    assert np.all(np.isfinite(c))
    assert profile.crown_drop(0.0) == pytest.approx(0.0, abs=1e-15)
    assert np.all(c >= 0.0)
    assert np.all(np.diff(c) >= -1e-18), "non-decreasing in |x|"
    np.testing.assert_array_equal(profile.crown_drop(-x), c)  # symmetric
    # physically small: below the roller radius
    assert profile.end_drop_value() < 0.5 * profile.element_diameter


@settings(max_examples=40, deadline=None)
@given(
    name=st.sampled_from(
        ["full_crown", "arc_slope_sides", "arc_slope_midline", "iso16281", "iso16281_tapered"]
    ),
    length=st.floats(1e-3, 0.1),
    ratio=st.floats(0.3, 5.0),
    u=st.lists(st.floats(-1.0, 1.0), min_size=1, max_size=20),
)
def test_invariants_hypothesis(name, length, ratio, u):
    p = make_profile(name, length, length / ratio)
    x = np.asarray(u) * p.half_length
    c = p.crown_drop(x)
    assert np.all(np.isfinite(c)) and np.all(c >= 0)
    np.testing.assert_allclose(p.crown_drop(-x), c, rtol=0, atol=0)
    order = np.argsort(np.abs(x))
    assert np.all(np.diff(c[order]) >= -1e-18)


def test_broadcasting_cases_elements_slices():
    p = make_profile("arc_slope_sides", 8e-3, 5e-3)
    ns = 10
    centres = (np.arange(ns) + 0.5) / ns * 8e-3 - 4e-3
    x = np.broadcast_to(centres, (3, 7, ns)) * np.linspace(0.5, 1.0, 3)[:, None, None]
    c = p.crown_drop(x)
    assert c.shape == (3, 7, ns)
    np.testing.assert_allclose(c[1, 4], p.crown_drop(x[1, 4]))
    assert np.ndim(p.crown_drop(1e-3)) == 0


def test_straight_is_zero():
    p = make_profile("straight", 4.8e-3, 4e-3)
    np.testing.assert_array_equal(p.crown_drop(np.linspace(-2.4e-3, 2.4e-3, 11)), 0.0)


# ------------------------------------------------------------------------------------------------
# Circular-arc profiles from the geometry
# ------------------------------------------------------------------------------------------------


def test_full_crown_is_circle_through_end_drop():
    L, D, drop = 4.8e-3, 4e-3, 3e-6
    p = make_profile("full_crown", L, D, end_drop=drop)
    # circle through (0, 0) and (+-L/2, drop), centre on x = 0 at height k:
    # (L/2)^2 + (drop - k)^2 = k^2  ->  k = ((L/2)^2 + drop^2) / (2 drop)
    k = ((L / 2) ** 2 + drop**2) / (2 * drop)
    assert p.radius == pytest.approx(k, rel=1e-12)
    assert p.crown_drop(L / 2) == pytest.approx(drop, rel=1e-9)
    x = np.linspace(-L / 2, L / 2, 13)
    c = p.crown_drop(x)
    np.testing.assert_allclose(x**2 + (k - c) ** 2, k**2, rtol=1e-12)


def test_full_crown_hand_value():
    # R = 0.5 m, x = 1 mm: C = 0.5 - sqrt(0.25 - 1e-6) = 1.000001e-6 m (binomial: x^2/2R + x^4/8R^3)
    p = make_profile("full_crown", 4.8e-3, 4e-3, crown_radius=0.5)
    assert p.crown_drop(1e-3) == pytest.approx(1e-6 + 1e-12 / (8 * 0.125), rel=1e-9)


def test_arc_slope_sides_geometry():
    L, D, Lf, R = 10e-3, 5e-3, 4e-3, 0.1
    p = make_profile("arc_slope_sides", L, D, flat_length=Lf, crown_radius=R)
    xf = Lf / 2
    x = np.linspace(0, xf, 7)
    np.testing.assert_array_equal(p.crown_drop(x), 0.0)  # flat
    # end arc: circle of radius R centred at (xf, R) -> (x - xf)^2 + (R - C)^2 = R^2
    xe = np.linspace(xf, L / 2, 9)
    c = p.crown_drop(xe)
    np.testing.assert_allclose((xe - xf) ** 2 + (R - c) ** 2, R**2, rtol=1e-13)
    # hand value at x = 4 mm (s = 2 mm): R - sqrt(R^2 - s^2) = 0.1 - sqrt(0.01 - 4e-6)
    assert p.crown_drop(4e-3) == pytest.approx(0.1 - math.sqrt(0.01 - 4e-6), rel=1e-9)
    assert p.crown_drop(-4e-3) == pytest.approx(0.1 - math.sqrt(0.01 - 4e-6), rel=1e-9)


def test_arc_slope_sides_tangent_at_junction():
    p = make_profile("arc_slope_sides", 8e-3, 5e-3, flat_length=4e-3, end_drop=5e-6)
    xf, eps = 2e-3, 1e-7
    c0 = p.crown_drop(xf)
    assert c0 == pytest.approx(0.0, abs=1e-18)  # continuous value
    slope_right = (p.crown_drop(xf + eps) - c0) / eps
    # tangent arc: slope ~ eps / (2R) -> 0
    assert abs(slope_right) < 2 * eps / p.radius
    assert p.crown_drop(4e-3) == pytest.approx(5e-6, rel=1e-9)
    # radius from the geometry: (L/2 - xf)^2 + (R - C)^2 = R^2
    assert p.radius == pytest.approx(((2e-3) ** 2 + (5e-6) ** 2) / (2 * 5e-6), rel=1e-12)


def test_arc_slope_midline_geometry_and_kink():
    L, D, Lf, drop = 8e-3, 5e-3, 4e-3, 5e-6
    p = make_profile("arc_slope_midline", L, D, flat_length=Lf, end_drop=drop)
    xf, xe = Lf / 2, L / 2
    # circle centred on x = 0 at depth h below the flat through (xf, 0) and (xe, -drop):
    # xf^2 + h^2 = xe^2 + (h - drop)^2  ->  h = (xe^2 + drop^2 - xf^2) / (2 drop)
    h = (xe**2 + drop**2 - xf**2) / (2 * drop)
    r = math.sqrt(xf**2 + h**2)
    assert p.radius == pytest.approx(r, rel=1e-12)
    x = np.linspace(xf, xe, 11)
    c = p.crown_drop(x)
    np.testing.assert_allclose(x**2 + (h - c) ** 2, r**2, rtol=1e-12)
    assert p.crown_drop(xe) == pytest.approx(drop, rel=1e-9)
    np.testing.assert_array_equal(p.crown_drop(np.linspace(0, xf, 5)), 0.0)
    # continuity of value and a slope kink xf/h at the junction
    eps = 1e-8
    assert p.crown_drop(xf) == pytest.approx(0.0, abs=1e-18)
    slope_right = (p.crown_drop(xf + eps) - p.crown_drop(xf)) / eps
    assert slope_right == pytest.approx(xf / h, rel=1e-3)
    assert slope_right > 100 * eps / p.radius  # clearly not tangent


def test_arc_slope_midline_crown_radius_hand_value():
    # R = 1 m, xf = 1 mm, x = 2 mm: C = sqrt(1 - 1e-6) - sqrt(1 - 4e-6) ~= (4e-6 - 1e-6)/2 = 1.5e-6
    p = make_profile("arc_slope_midline", 6e-3, 5e-3, flat_length=2e-3, crown_radius=1.0)
    assert p.crown_drop(2e-3) == pytest.approx(math.sqrt(1 - 1e-6) - math.sqrt(1 - 4e-6), rel=1e-9)
    assert p.crown_drop(2e-3) == pytest.approx(1.5e-6, rel=1e-5)


@pytest.mark.parametrize("name", ["arc_slope_sides", "arc_slope_midline"])
def test_arc_slope_without_flat_is_full_crown(name):
    full = make_profile("full_crown", 8e-3, 5e-3, end_drop=4e-6)
    p = make_profile(name, 8e-3, 5e-3, flat_length=0.0, end_drop=4e-6)
    x = np.linspace(-4e-3, 4e-3, 17)
    np.testing.assert_allclose(p.crown_drop(x), full.crown_drop(x), rtol=1e-12, atol=1e-20)


# ------------------------------------------------------------------------------------------------
# Logarithmic profiles against their published formulas
# ------------------------------------------------------------------------------------------------


def test_lundberg_formula_and_identical_material_form():
    Q, length = 2e3, 4.8e-3
    p = make_profile("lundberg", length, 4e-3, design_load=Q, e_reduced=E_RED)
    # Lundberg for identical bodies: 2 Q (1 - nu^2) / (pi l E) ln[1/(1 - (2x/l)^2)]
    x = 0.6e-3  # 2x/length = 0.25
    expected = 2 * Q * (1 - STEEL_NU**2) / (math.pi * length * STEEL_E) * math.log(1 / (1 - 0.25**2))
    assert p.crown_drop(x) == pytest.approx(expected, rel=1e-12)
    assert make_profile("logarithmic", length, 4e-3, design_load=Q, e_reduced=E_RED).crown_drop(
        x
    ) == pytest.approx(expected, rel=1e-12)


def test_lundberg_clip_keeps_end_finite():
    length = 4.8e-3
    p = make_profile("lundberg", length, 4e-3, design_load=2e3, e_reduced=E_RED, clip=0.99)
    coeff = 2 * 2e3 / (math.pi * length * E_RED)
    assert p.crown_drop(length / 2) == pytest.approx(coeff * math.log(1 / (1 - 0.99**2)), rel=1e-12)
    assert p.crown_drop(length / 2) == p.crown_drop(0.995 * length / 2)


def test_johns_gohar_formula():
    Q, length, b = 2e3, 4.8e-3, 0.1e-3
    p = make_profile("johns_gohar", length, 4e-3, design_load=Q, e_reduced=E_RED, semi_minor=b)
    coeff = 2 * Q / (math.pi * length * E_RED)
    # end: argument 0.3033 * 2b/l -> C(l/2) = coeff * ln(l / (0.6066 b))
    assert p.crown_drop(length / 2) == pytest.approx(coeff * math.log(length / (0.6066 * b)), rel=1e-12)
    # interior point 2x/length = 0.5
    k = 1 - 0.3033 * 2 * b / length
    assert p.crown_drop(length / 4) == pytest.approx(coeff * math.log(1 / (1 - k * 0.25)), rel=1e-12)
    # below Lundberg everywhere (its log argument is larger)
    lund = make_profile("lundberg", length, 4e-3, design_load=Q, e_reduced=E_RED)
    x = np.linspace(1e-4, 0.99 * length / 2, 20)
    assert np.all(p.crown_drop(x) < lund.crown_drop(x))


def test_johns_gohar_half_width_from_curvature():
    Q, length, rx = 2e3, 4.8e-3, 2e-3
    p = make_profile("johns_gohar", length, 4e-3, design_load=Q, e_reduced=E_RED, curvature_sum=1 / rx)
    # Johnson (1985): b = sqrt(4 w R / (pi E*)), w = Q/length, E* = E'/2
    b = math.sqrt(4 * (Q / length) * rx / (math.pi * E_RED / 2))
    assert p.half_width == pytest.approx(b, rel=1e-12)


def test_iso16281_short_roller_hand_value():
    # L = 4.8 mm <= 2.5 D = 10 mm: C(1.2 mm) = 0.00035 * 4 mm * ln(1/(1 - 0.25)) = 4.0276e-7 m
    p = make_profile("iso16281", 4.8e-3, 4e-3)
    assert p.crown_drop(1.2e-3) == pytest.approx(0.00035 * 4e-3 * math.log(4 / 3), rel=1e-12)
    assert p.crown_drop(1.2e-3) == pytest.approx(4.0276e-7, rel=1e-4)
    t = make_profile("iso16281_tapered", 4.8e-3, 4e-3)
    assert t.crown_drop(1.2e-3) == pytest.approx(0.00045 * 4e-3 * math.log(4 / 3), rel=1e-12)


def test_iso16281_long_roller_flat_middle():
    # L = 20 mm > 2.5 D = 12.5 mm: flat for |x| <= 3.75 mm; at x = 6.875 mm the ratio is
    # (13.75 - 7.5) / 12.5 = 0.5 -> 0.0005 * 5 mm * ln(4/3)
    p = make_profile("iso16281", 20e-3, 5e-3)
    np.testing.assert_array_equal(p.crown_drop(np.linspace(-3.75e-3, 3.75e-3, 9)), 0.0)
    assert p.crown_drop(6.875e-3) == pytest.approx(0.0005 * 5e-3 * math.log(4 / 3), rel=1e-12)
    assert p.crown_drop(-6.875e-3) == pytest.approx(0.0005 * 5e-3 * math.log(4 / 3), rel=1e-12)


def test_iso16281_clip_default_only_at_the_very_end():
    p = make_profile("iso16281", 4.8e-3, 4e-3)
    u = 1 - 1 / 200  # outermost slice centre of 200 slices: not clipped
    assert p.crown_drop(u * 2.4e-3) == pytest.approx(0.00035 * 4e-3 * -math.log(1 - u * u), rel=1e-12)
    u_clip = pr.LOG_CLIP_DEFAULT
    assert p.crown_drop(2.4e-3) == pytest.approx(0.00035 * 4e-3 * -math.log(1 - u_clip**2), rel=1e-12)


# ------------------------------------------------------------------------------------------------
# Seed 000 mapping and defaults
# ------------------------------------------------------------------------------------------------


def test_seed000_mapping():
    assert set(SEED000_CROWNING) == set("abcde")
    assert all(v in PROFILES for v in SEED000_CROWNING.values())
    assert SEED000_CROWNING["b"] == "arc_slope_sides"
    assert SEED000_CROWNING["c"] == "arc_slope_midline"
    assert SEED000_CROWNING["d"] == "full_crown"
    assert SEED000_CROWNING["e"] == "straight"


@pytest.mark.parametrize(("length", "diameter"), SEED_ROLLERS)
def test_seed000_defaults_have_comparable_end_drops(length, diameter):
    target = pr.DEFAULT_END_DROP_RATIO * diameter
    for letter in "bcd":
        p = seed000_profile(letter, length, diameter)
        assert p.crown_drop(length / 2) == pytest.approx(target, rel=1e-9)
        assert 1e-6 < target < 10e-6  # "a few um"
    # type a (ISO log) reaches the same drop at 2|x|/L = 0.971, near the outermost slice centres
    a = seed000_profile("a", length, diameter)
    assert a.crown_drop(0.971 * length / 2) == pytest.approx(target, rel=0.01)
    # same flat length for b and c
    b, c = seed000_profile("b", length, diameter), seed000_profile("c", length, diameter)
    assert b.flat_half_length == c.flat_half_length == pytest.approx(pr.DEFAULT_FLAT_FRACTION * length / 2)


def test_references_registered():
    for cls in set(PROFILES.values()):
        for key in cls.references:
            assert cite(key)


# ------------------------------------------------------------------------------------------------
# Errors
# ------------------------------------------------------------------------------------------------


def test_unknown_name_lists_valid_names():
    with pytest.raises(InputError, match=r"profile \('barrel'\).*arc_slope_sides.*straight"):
        make_profile("barrel", 4.8e-3, 4e-3)


def test_unknown_parameter():
    with pytest.raises(InputError, match=r"crown_radius is not a parameter of profile 'straight'"):
        make_profile("straight", 4.8e-3, 4e-3, crown_radius=1.0)
    with pytest.raises(InputError, match=r"radius_crown .*valid: crown_radius, end_drop"):
        make_profile("full_crown", 4.8e-3, 4e-3, radius_crown=1.0)


@pytest.mark.parametrize(
    ("name", "length", "diameter", "params", "field"),
    [
        ("straight", -4.8e-3, 4e-3, {}, "effective_length"),
        ("straight", 4.8e-3, 0.0, {}, "element_diameter"),
        ("full_crown", float("nan"), 4e-3, {}, "effective_length"),
        ("full_crown", 4.8e-3, 4e-3, {"crown_radius": 2e-3}, "crown_radius"),  # < L/2
        ("full_crown", 4.8e-3, 4e-3, {"end_drop": -1e-6}, "end_drop"),
        ("full_crown", 4.8e-3, 4e-3, {"end_drop": 1e-6, "crown_radius": 1.0}, "crown_radius"),
        ("arc_slope_sides", 4.8e-3, 4e-3, {"flat_length": 5e-3}, "flat_length"),  # > L
        ("arc_slope_sides", 4.8e-3, 4e-3, {"flat_length": -1e-3}, "flat_length"),
        ("arc_slope_sides", 8e-3, 5e-3, {"flat_length": 4e-3, "crown_radius": 1.5e-3}, "crown_radius"),
        ("arc_slope_midline", 8e-3, 5e-3, {"flat_length": 8e-3}, "flat_length"),
        ("arc_slope_midline", 8e-3, 5e-3, {"crown_radius": 3.9e-3}, "crown_radius"),  # < L/2
        ("arc_slope_midline", 8e-3, 5e-3, {"flat_length": 4e-3, "end_drop": 3.5e-3}, "end_drop"),
        ("lundberg", 8e-3, 5e-3, {"e_reduced": E_RED}, "design_load"),
        ("lundberg", 8e-3, 5e-3, {"design_load": 1e3}, "e_reduced"),
        ("lundberg", 8e-3, 5e-3, {"design_load": 1e3, "e_reduced": E_RED, "clip": 1.0}, "clip"),
        ("johns_gohar", 8e-3, 5e-3, {"design_load": 1e3, "e_reduced": E_RED}, "semi_minor"),
        (
            "johns_gohar",
            8e-3,
            5e-3,
            {"design_load": 1e3, "e_reduced": E_RED, "semi_minor": -1.0},
            "semi_minor",
        ),
        ("iso16281", 8e-3, 5e-3, {"clip": 0.0}, "clip"),
    ],
)
def test_bad_input_names_field(name, length, diameter, params, field):
    with pytest.raises(InputError, match=field):
        make_profile(name, length, diameter, **params)


def test_bad_positions():
    p = make_profile("full_crown", 4.8e-3, 4e-3)
    with pytest.raises(InputError, match=r"^x \("):
        p.crown_drop(np.array([0.0, 2.5e-3]))
    with pytest.raises(InputError, match=r"^x \("):
        p.crown_drop(np.array([0.0, np.nan]))
    # round-off at the ends is accepted
    assert np.isfinite(p.crown_drop(2.4e-3 * (1 + 1e-12)))


def test_profiles_are_frozen():
    p = make_profile("full_crown", 4.8e-3, 4e-3)
    with pytest.raises(AttributeError):
        p.crown_radius = 1.0  # type: ignore[misc]
