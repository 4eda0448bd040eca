"""Raceway hardness profiles (bearingkit.hardness) and the case check (physics/structure/case_depth.py)."""

import dataclasses

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.hardness import (
    HARDNESS_PRESETS,
    HardnessProfile,
    get_hardness,
    hrc_to_hv,
    hv_to_hrc,
    tensile_strength,
    yield_strength,
)
from bearingkit.materials import get_material
from bearingkit.physics.structure import case_depth as cd


def test_hrc_to_hv_by_schlecht_and_round_trip():
    # HV = (223 HRC + 14500) / (100 - HRC), hand-computed: 58 HRC -> 27434/42 = 653.19; 50 -> 25650/50 = 513
    assert float(hrc_to_hv(58.0)) == pytest.approx(27434.0 / 42.0)
    assert float(hrc_to_hv(50.0)) == pytest.approx(513.0)
    # the ASTM E140 table gives 653 HV at 58 HRC and 513 HV at 50 HRC [from memory]: the formula within 0.1 %
    assert float(hrc_to_hv(58.0)) == pytest.approx(653.0, rel=1e-3)
    np.testing.assert_allclose(hv_to_hrc(hrc_to_hv(np.array([25.0, 40.0, 62.0]))), [25.0, 40.0, 62.0])
    with pytest.raises(InputError, match="HRC"):
        hrc_to_hv(75.0)


def test_strength_from_hardness_pavlina_and_tabor():
    # Pavlina & Van Tyne (2008) Table 1: σ_y = -90.7 + 2.876 HV, R_m = -99.8 + 3.734 HV [MPa]
    assert float(yield_strength(300.0)) == pytest.approx((-90.7 + 2.876 * 300.0) * 1e6)
    assert float(tensile_strength(300.0)) == pytest.approx((-99.8 + 3.734 * 300.0) * 1e6)
    # Tabor: H = 3 σ_y with H = 9.80665 HV MPa
    assert float(yield_strength(300.0, "tabor")) == pytest.approx(9.80665 * 100.0 * 1e6)
    with pytest.raises(InputError, match="strength_model"):
        yield_strength(300.0, "brinell")


def test_profile_passes_the_limit_hardness_at_the_case_depth():
    p = get_hardness("42CrMo4_induction")
    assert p.limit == pytest.approx(0.8 * p.surface_hardness)  # SHD: 0.8 × surface
    assert float(p.hardness(p.case_depth)) == pytest.approx(p.limit)
    start, end = p.transition()
    assert end - start == pytest.approx(0.5 * p.case_depth)  # the default transition width
    z = np.linspace(0.0, 3 * p.case_depth, 301)
    hv = p.hardness(z)
    assert hv[0] == p.surface_hardness and hv[-1] == p.core_hardness
    assert np.all(np.diff(hv) <= 0)
    chd = dataclasses.replace(p, depth_definition="CHD", surface_hardness=700.0)
    assert float(chd.hardness(chd.case_depth)) == pytest.approx(550.0)  # ISO 2639: 550 HV


def test_through_hardened_material_profile():
    p = get_material("GCr15").raceway_hardness
    assert p.through_hardened and p.surface_hardness == 700.0
    np.testing.assert_allclose(p.hardness([0.0, 1.0]), 700.0)
    assert get_material("42CrMo4").raceway_hardness is HARDNESS_PRESETS["42CrMo4_induction"]


def test_static_limit_factor_from_surface_hardness():
    assert HARDNESS_PRESETS["through_hardened"].limit_factor() == 1.0
    p = HardnessProfile(surface_hardness=float(hrc_to_hv(56.0)))
    ref = float(hrc_to_hv(58.0))
    expected = (-90.7 + 2.876 * p.surface_hardness) / (-90.7 + 2.876 * ref)  # yield-strength ratio
    assert p.limit_factor() == pytest.approx(expected)
    assert dataclasses.replace(p, static_limit_factor=0.9).limit_factor() == 0.9


@pytest.mark.parametrize(
    "fields,match",
    [
        ({"surface_hardness": 1200.0}, "surface_hardness"),
        ({"surface_hardness": 600.0, "case_depth": 3e-3}, "core_hardness"),
        ({"surface_hardness": 600.0, "case_depth": 3e-3, "core_hardness": 650.0}, "below surface"),
        ({"surface_hardness": 600.0, "core_hardness": 250.0}, "case_depth"),
        ({"surface_hardness": 600.0, "case_depth": -1e-3, "core_hardness": 250.0}, "case_depth"),
        (
            {
                "surface_hardness": 500.0,
                "case_depth": 3e-3,
                "core_hardness": 250.0,
                "depth_definition": "CHD",
            },
            "limit",
        ),
    ],
)
def test_bad_profiles_are_one_line(fields, match):
    with pytest.raises(InputError, match=match) as info:
        HardnessProfile(**fields)
    assert "\n" not in str(info.value)


# --------------------------------------------------------------------------- case check
def test_case_check_finds_the_weakest_point_below_the_plateau():
    p = get_hardness("42CrMo4_induction")
    z = np.linspace(0.0, 8e-3, 801)
    vm = np.full(z.shape, 600e6)  # a uniform stress: the weakest point is where the strength is least
    check = cd.case_check(z, vm, p)
    start, end = p.transition()
    assert check.depth_case_safety == pytest.approx(end, abs=2e-5)
    assert check.case_safety == pytest.approx(float(p.strength(end)) / 600e6)
    assert check.zone == "core"
    np.testing.assert_allclose(check.safety, p.strength(z) / 600e6)
    # a stress that vanishes below the transition's start: only the transition counts
    vm2 = np.where(z < start + 1e-4, 1500e6, 0.0)
    c2 = cd.case_check(z, vm2, p)
    assert c2.zone == "transition" and start <= c2.depth_case_safety < end


def test_required_case_depth_reaches_the_target_and_no_less():
    p = get_hardness("42CrMo4_induction")
    z = np.linspace(0.0, 12e-3, 1201)
    vm = 2000e6 * np.exp(-z / 1.5e-3)  # a stress decaying below the surface
    need = float(cd.required_case_depth(z, vm, p, target=1.2))
    assert 0 < need < 12e-3
    ok = cd.case_check(z, vm, p.with_case_depth(need * 1.001)).case_safety
    short = cd.case_check(z, vm, p.with_case_depth(need * 0.98)).case_safety
    assert ok >= 1.2 > short
    # monotone in the target; through-hardened: not defined; a weak stress needs none
    assert float(cd.required_case_depth(z, vm, p, target=1.5)) > need
    assert np.isnan(cd.required_case_depth(z, vm, HARDNESS_PRESETS["through_hardened"]))
    assert float(cd.required_case_depth(z, vm * 0.1, p)) == 0.0
    # a stress above the surface's strength down to the deepest depth: no case depth reaches the target
    assert np.isinf(cd.required_case_depth(z, np.full(z.shape, 2000e6), p))
    assert np.isnan(cd.case_check(z, vm, HARDNESS_PRESETS["through_hardened"]).case_safety)
