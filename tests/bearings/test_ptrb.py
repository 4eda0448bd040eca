"""PTRB prototype: published ratings (seed 004), model-based distribution, result dict, example file."""

from pathlib import Path

import numpy as np
import pytest

from bearingkit.bearings.ptrb import evaluate_ptrb, ptrb_prototype, ptrb_ratings
from bearingkit.errors import InputError
from bearingkit.validation.registry import all_cases, run_cases

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "ptrb_prototype.toml"


def test_seed004_rating_cases_pass():
    """The prototype ratings and the Table 4 rating sweeps (no friction case: those live beside it)."""
    results = run_cases(all_cases(["seed004/prototype/", "seed004/table4/"]))
    assert len(results) == 4 + 5 * 2 * 4
    bad = [(r.case.id, r.rel_error) for r in results if not r.passed]
    assert not bad


def test_uncalibrated_ratings_follow():
    """Ca and Cr do not depend on the C0a/C0r calibration beyond f_amax: Cr has no fitted number."""
    r = evaluate_ptrb()
    assert r.dynamic_radial == pytest.approx(30.26e3, rel=0.005)
    assert r.dynamic_axial == pytest.approx(33.20e3, rel=0.01)


def test_model_distribution_close_to_calibration():
    cal = ptrb_ratings(ptrb_prototype())
    mod = ptrb_ratings(ptrb_prototype(), distribution="model")
    assert 1.0 < mod.f_amax < 1.25
    assert mod.static_axial == pytest.approx(cal.static_axial, rel=0.10)
    assert mod.static_radial == pytest.approx(cal.static_radial, rel=0.10)
    assert mod.dynamic_radial == cal.dynamic_radial


def test_strength_at_static_rating():
    r = evaluate_ptrb()
    assert r.strength_ok
    d = r.to_dict()
    assert d["root_shear_stress_roller_Pa"] <= 208.8e6
    assert {"C0a_N", "C0r_N", "Ca_N", "Cr_N", "f_amax", "f_rmax"} <= set(d)


def test_ring_flank_sensitivity_raises_dynamic_ratings():
    flat = evaluate_ptrb()
    arc = evaluate_ptrb(ptrb_prototype(contact_radius_inner=75e-3, contact_radius_outer=75e-3))
    assert arc.dynamic_radial > flat.dynamic_radial
    assert arc.static_axial > flat.static_axial


def test_bad_distribution_name():
    with pytest.raises(InputError, match="distribution"):
        ptrb_ratings(ptrb_prototype(), distribution="guess")


def test_example_file_matches_builder():
    """The example file, read by the common loader, builds the Table 1 prototype's row."""
    from bearingkit.io.loader import load_file

    bearing = load_file(EXAMPLE)
    g = bearing.model.rows[0].geometry
    ref = ptrb_prototype()
    for field in ("pitch_diameter", "roller_pitch_diameter", "contact_angle", "n_elements", "n_teeth"):
        assert np.isclose(getattr(g, field), getattr(ref, field)), field
    assert evaluate_ptrb(g).static_axial == pytest.approx(38.36e3, rel=0.02)
