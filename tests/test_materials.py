"""Tests of bearingkit.materials: presets against their published numbers, E′ closed forms, errors."""

from __future__ import annotations

import dataclasses
import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from bearingkit.errors import InputError
from bearingkit.materials import (
    MATERIALS,
    REFERENCE_KEYS,
    SEED000_MATERIAL,
    Material,
    as_material,
    e_reduced,
    elastic_compliance,
    get_material,
)
from bearingkit.references import REFERENCES

# Independent conversion factors (NIST SP 811, Appendix B.8), written out here on purpose.
NIST_PSI_TO_PA = 6.894757e3  # 1 psi = 6.894 757 E+03 Pa
NIST_LB_PER_IN3_TO_KG_PER_M3 = 2.767990e4  # 1 lb/in^3 = 2.767 990 E+04 kg/m^3


def test_every_preset_validates_again():
    for name, m in MATERIALS.items():
        again = Material(**dataclasses.asdict(m))
        assert again == m, name
        assert get_material(name) is m


def test_aisi52100_matches_its_specification_sheet():
    # AISI 52100 chrome steel sheet: E = 29,500,000 psi, density 0.283 lb/in^3, yield 295,000 psi.
    m = get_material("AISI52100")
    assert m.youngs_modulus == pytest.approx(29.5e6 * NIST_PSI_TO_PA, rel=1e-6)
    assert m.youngs_modulus == pytest.approx(203.4e9, rel=5e-4)
    assert m.density == pytest.approx(0.283 * NIST_LB_PER_IN3_TO_KG_PER_M3, rel=1e-6)
    assert m.yield_strength == pytest.approx(295e3 * NIST_PSI_TO_PA, rel=1e-6)
    assert m.poisson_ratio == 0.3


def test_seed_presets_reproduce_the_papers_tables():
    # Liu et al. 2022, Table 1: 2.1e5 N/mm^2, 0.278. Zheng et al. 2022, Table 1: 212,000 MPa, 0.29.
    s1 = get_material("seed001_steel")
    assert s1.youngs_modulus == pytest.approx(2.1e5 * 1e6, rel=1e-12)
    assert s1.poisson_ratio == 0.278
    s4 = get_material("seed004_steel")
    assert s4.youngs_modulus == pytest.approx(212_000 * 1e6, rel=1e-12)
    assert s4.poisson_ratio == 0.29
    # Seed 000 and 002 give no material: the documented choice is GCr15.
    assert SEED000_MATERIAL == "GCr15"
    assert get_material("seed002_steel") == get_material("GCr15")


def test_gcr15_and_si3n4_lie_in_the_published_ranges():
    g = get_material("GCr15")
    assert 200e9 <= g.youngs_modulus <= 212e9  # 52100 sheet 203 GPa … seed 004 212 GPa
    assert 7800 <= g.density <= 7850
    si = get_material("Si3N4")
    assert si.youngs_modulus == pytest.approx(304e9, rel=0.03)  # Callister Table B.2: 304 GPa
    assert 3150 <= si.density <= 3300


def test_e_reduced_steel_on_steel_closed_form():
    # Same material: eta = 2(1-nu^2)/E and E' = 2/eta = E/(1-nu^2).
    for name in ("AISI52100", "GCr15", "seed001_steel", "seed004_steel"):
        m = get_material(name)
        e, nu = m.youngs_modulus, m.poisson_ratio
        assert elastic_compliance(m, m) == pytest.approx(2 * (1 - nu**2) / e, rel=1e-14)
        assert e_reduced(m, m) == pytest.approx(e / (1 - nu**2), rel=1e-14)
    # Seed 001 by hand: 2.1e11 / (1 - 0.278^2) = 2.276e11 Pa.
    assert e_reduced(get_material("seed001_steel"), get_material("seed001_steel")) == pytest.approx(
        2.1e11 / (1 - 0.278**2), rel=1e-14
    )


def test_hybrid_contact_closed_form():
    s, c = get_material("GCr15"), get_material("Si3N4")
    eta = (1 - 0.3**2) / 208e9 + (1 - 0.26**2) / 310e9
    assert elastic_compliance(s, c) == pytest.approx(eta, rel=1e-14)
    assert e_reduced(c, s) == pytest.approx(2 / eta, rel=1e-14)
    assert e_reduced(s, s) < e_reduced(s, c) < e_reduced(c, c)


@given(
    e1=st.floats(1e9, 1e12),
    nu1=st.floats(0.0, 0.49),
    e2=st.floats(1e9, 1e12),
    nu2=st.floats(0.0, 0.49),
)
def test_compliance_symmetric_and_consistent(e1, nu1, e2, nu2):
    m1 = Material("a", e1, nu1, 7800.0)
    m2 = Material("b", e2, nu2, 7800.0)
    assert elastic_compliance(m1, m2) == pytest.approx(elastic_compliance(m2, m1), rel=1e-14)
    assert e_reduced(m1, m2) * elastic_compliance(m1, m2) == pytest.approx(2.0, rel=1e-14)
    # E' lies between the two bodies' own E/(1-nu^2) values.
    lo, hi = sorted((e1 / (1 - nu1**2), e2 / (1 - nu2**2)))
    assert lo * (1 - 1e-12) <= e_reduced(m1, m2) <= hi * (1 + 1e-12)


@pytest.mark.parametrize(
    "field, value",
    [
        ("youngs_modulus", 0.0),
        ("youngs_modulus", -2.0e11),
        ("youngs_modulus", math.nan),
        ("poisson_ratio", 0.5),
        ("poisson_ratio", -0.1),
        ("poisson_ratio", math.inf),
        ("density", 0.0),
        ("yield_strength", -1.0),
        ("hardness_hv", 0.0),
    ],
)
def test_bad_input_names_the_field(field, value):
    kwargs = dataclasses.asdict(get_material("GCr15")) | {field: value}
    with pytest.raises(InputError) as err:
        Material(**kwargs)
    msg = str(err.value)
    assert msg.startswith(field) and "\n" not in msg
    assert ("nan" in msg or "inf" in msg) if not math.isfinite(value) else f"{value:.6g}" in msg


def test_empty_name_rejected():
    with pytest.raises(InputError, match="name"):
        Material("", 2e11, 0.3, 7800.0)


def test_unknown_material_lists_valid_names():
    with pytest.raises(InputError) as err:
        get_material("unobtainium")
    msg = str(err.value)
    assert "unobtainium" in msg
    for name in MATERIALS:
        assert name in msg


def test_as_material():
    m = get_material("Si3N4")
    assert as_material(m) is m
    assert as_material("Si3N4") is m
    with pytest.raises(InputError, match="material"):
        as_material(3.0)


def test_reference_keys_registered():
    for key in REFERENCE_KEYS:
        assert key in REFERENCES
