"""Lubricants as data (issue 35): ASTM D2270 viscosity index, the base-oil pressure–viscosity law, the one
builder of names / fields / text forms, the library, and their one-line errors."""

from __future__ import annotations

import csv
import io
from importlib import resources

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingkit.errors import InputError
from bearingkit.lubricants import (
    BASE_OILS,
    LIBRARY,
    LUBRICANTS,
    as_lubricant,
    fields_from_text,
    lubricant_from_fields,
    named_lubricant,
    nu100_from_vi,
    pressure_viscosity,
    viscosity_index,
)
from bearingkit.lubricants.base_oils import pressure_viscosity_law
from bearingkit.lubricants.viscosity_index import H_ABOVE_70, L_ABOVE_70, reference_viscosities

MM2 = 1e-6  # m²/s per mm²/s, written out independently of the package


def _rows(name: str) -> list[dict]:
    text = resources.files("bearingkit").joinpath("data", name).read_text(encoding="utf-8")
    return list(
        csv.DictReader(io.StringIO("\n".join(ln for ln in text.splitlines() if not ln.startswith("#"))))
    )


# --- ASTM D2270 ----------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("nu40", "nu100", "published"),
    [
        # The example oils of sherzodr/libvisc (an independent C++ implementation of ASTM D2270, README):
        # its VI is truncated to an int by `int vi()`.
        (30.0, 5.23, 104),  # paraffinic spindle oil
        (30.0, 4.24, -25),  # naphthenic spindle oil
        (120.0, 8.0, -49),  # medium solvent extract
        (120.0, 20.9, 200),  # medium polyglycol
        (70.0, 11.1, 150),  # multigrade motor oil
        (30.0, 5.81, 139),  # ester oil
        (68.0, 8.6, 96),
    ],
)
def test_viscosity_index_matches_an_independent_implementation(nu40, nu100, published):
    vi = float(viscosity_index(nu40 * MM2, nu100 * MM2))
    assert int(vi) == published  # the same truncation toward zero as libvisc's int()


def test_viscosity_index_of_the_standards_examples():
    # ASTM D2270-10 worked examples (from memory of the standard [M]): procedure B, 22.83/5.05 -> VI 156;
    # procedure A, 73.30/8.86 -> VI 92.5 (rounded in the standard to 92 or 93 by its rounding rule).
    assert float(viscosity_index(22.83 * MM2, 5.05 * MM2)) == pytest.approx(156, abs=0.5)
    assert float(viscosity_index(73.30 * MM2, 8.86 * MM2)) == pytest.approx(92.5, abs=0.5)


def test_l_and_h_rise_and_meet_the_closed_forms_above_70():
    rows = _rows("astm_d2270_lh.csv")
    y = np.array([float(r["nu100_mm2_s"]) for r in rows])
    big_l = np.array([float(r["L_mm2_s"]) for r in rows])
    big_h = np.array([float(r["H_mm2_s"]) for r in rows])
    assert np.all(np.diff(y) > 0) and np.all(np.diff(big_l) > 0) and np.all(np.diff(big_h) > 0)
    assert np.all(big_h < big_l)
    # the closed forms of the standard (used above 70 mm²/s) continue the table's last row
    assert np.polyval(L_ABOVE_70, 70.0) == pytest.approx(big_l[-1], rel=1e-3)
    assert np.polyval(H_ABOVE_70, 70.0) == pytest.approx(big_h[-1], rel=1e-3)
    lo, hi = reference_viscosities(np.array([70.0, 70.001]))
    assert lo[1] == pytest.approx(lo[0], rel=1e-3) and hi[1] == pytest.approx(hi[0], rel=1e-3)


@settings(deadline=None, max_examples=40)
@given(st.sampled_from((10, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680)), st.floats(-20.0, 220.0))
def test_nu100_from_vi_inverts_the_viscosity_index(grade, vi):
    try:
        nu100 = nu100_from_vi(grade * MM2, vi)
    except InputError:  # no ν100 ≥ 2 mm²/s below ν40 has that VI: refused, never extrapolated
        return
    assert float(viscosity_index(grade * MM2, nu100)) == pytest.approx(vi, abs=1e-6)


def test_nu100_from_vi_refuses_an_impossible_pair_in_one_line():
    with pytest.raises(InputError) as err:
        nu100_from_vi(5 * MM2, 100.0)  # VI 178 already at the smallest nu100 of the standard (2 mm²/s)
    assert "vi (100)" in str(err.value) and "\n" not in str(err.value)


# --- the base-oil pressure–viscosity law ---------------------------------------------------------
def test_mineral_law_is_the_least_squares_fit_of_stachowiak_table_2_3():
    rows = _rows("stachowiak_table_2_3.csv")
    eta, alpha = [], []
    for r in rows:
        for t in ("30", "60", "100"):
            if r[f"alpha_{t}"]:
                eta.append(float(r[f"eta_{t}"]) * 1e-3)  # mPa·s -> Pa·s
                alpha.append(float(r[f"alpha_{t}"]) * 1e-9)  # 1e-9 m²/N -> 1/Pa
    a = np.vstack([np.ones(len(eta)), np.log(eta)]).T
    (log_s, t_fit), *_ = np.linalg.lstsq(a, np.log(alpha), rcond=None)
    s, t = pressure_viscosity_law("mineral")
    assert len(eta) == 38
    assert s == pytest.approx(np.exp(log_s), rel=2e-3) and t == pytest.approx(t_fit, rel=2e-3)


@pytest.mark.parametrize(
    ("base", "eta_mpas", "alpha_e8"),
    [
        # Jones et al. (1975) NASA TN D-8005 as tabulated by Hamrock: 38, 99, 149 °C (data/base_oils.csv)
        ("pao", (414.0, 34.3, 10.9), (1.77, 1.51, 1.09)),
        ("ester", (25.3, 4.75, 2.06), (1.28, 0.987, 0.851)),
    ],
)
def test_synthetic_laws_follow_their_measurements(base, eta_mpas, alpha_e8):
    got = pressure_viscosity(np.array(eta_mpas) * 1e-3, base)
    np.testing.assert_allclose(got, np.array(alpha_e8) * 1e-8, rtol=0.12)  # the 3-point fits' residual


def test_pag_law_passes_through_its_one_measurement():
    # Stachowiak & Batchelor Table 2.3: ethylene oxide-propylene oxide copolymer, 0.204 Pa·s, 17.6e-9 1/Pa
    assert float(pressure_viscosity(0.204, "pag")) == pytest.approx(17.6e-9, rel=2e-3)


def test_synthetic_oils_have_a_lower_alpha_than_mineral_at_equal_viscosity():
    eta = np.array([0.005, 0.06, 0.5])
    mineral = pressure_viscosity(eta, "mineral")
    for base in ("pao", "ester", "pag"):
        assert np.all(pressure_viscosity(eta, base) < mineral)
    assert set(BASE_OILS) == {"mineral", "pao", "ester", "pag"}


# --- one builder for every form --------------------------------------------------------------------
def test_the_same_oil_from_nu100_and_from_its_vi():
    a = lubricant_from_fields({"nu_40": "68 mm^2/s", "nu_100": "8.7 mm^2/s"})
    b = lubricant_from_fields({"iso_vg": 68, "vi": a.viscosity_index})
    assert b.kinematic_viscosity_100 == pytest.approx(8.7 * MM2, rel=1e-9)
    t = np.array([20.0, 40.0, 70.0, 100.0, 130.0])
    np.testing.assert_allclose(a.kinematic_viscosity(t), b.kinematic_viscosity(t), rtol=1e-9)
    np.testing.assert_allclose(
        a.kinematic_viscosity(t), LUBRICANTS["ISO_VG68"].kinematic_viscosity(t), rtol=1e-12
    )


def test_an_ester_of_the_same_viscosity_has_another_pressure_viscosity_coefficient():
    mineral = lubricant_from_fields({"nu_40": "68 mm^2/s", "nu_100": "8.7 mm^2/s"})
    ester = lubricant_from_fields({"nu_40": "68 mm^2/s", "nu_100": "8.7 mm^2/s", "base_oil": "ester"})
    t = np.array([40.0, 80.0])
    np.testing.assert_allclose(mineral.kinematic_viscosity(t), ester.kinematic_viscosity(t), rtol=1e-12)
    # α(T) = s (η(T)/1 Pa·s)^t of each base oil, with η = ν ρ written out here
    for lub, base in ((mineral, "mineral"), (ester, "ester")):
        s, e = pressure_viscosity_law(base)
        eta = lub.kinematic_viscosity(t) * lub.density(t)
        np.testing.assert_allclose(lub.pressure_viscosity_at(t), s * eta**e, rtol=1e-12)
    assert np.all(ester.pressure_viscosity_at(t) < 0.75 * mineral.pressure_viscosity_at(t))
    assert ester.pressure_viscosity_at(80.0) < ester.pressure_viscosity_at(40.0)  # α falls as the oil thins


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("VG68 ester", {"iso_vg": 68.0, "base_oil": "ester"}),
        ("ISO VG 46 PAO VI 150", {"iso_vg": 46.0, "base_oil": "pao", "vi": 150.0}),
        (
            "nu_40=68mm^2/s nu_100=8.7mm^2/s pag",
            {"nu_40": "68mm^2/s", "nu_100": "8.7mm^2/s", "base_oil": "pag"},
        ),
        ("VG100 lithium NLGI2", {"iso_vg": 100.0, "thickener": "lithium", "nlgi": "2"}),
        ("VG68", {"name": "ISO_VG68"}),  # a grade alone is the preset of that grade
        ("ISO VG 220", {"name": "ISO_VG220"}),
        ("ISO_VG68 ester", {"iso_vg": 68.0, "base_oil": "ester"}),  # a VG 68 ester (its typical VI)
    ],
)
def test_text_forms_become_fields(text, expected):
    assert fields_from_text(text) == expected


def test_names_and_overrides():
    assert as_lubricant("ISO_VG68") is LUBRICANTS["ISO_VG68"]
    assert as_lubricant({"name": "ISO_VG68"}) is LUBRICANTS["ISO_VG68"]
    ester = as_lubricant({"name": "ISO_VG68", "base_oil": "ester"})
    assert (
        ester.base_oil == "ester"
        and ester.kinematic_viscosity_100 == LUBRICANTS["ISO_VG68"].kinematic_viscosity_100
    )
    assert ester.pressure_viscosity != LUBRICANTS["ISO_VG68"].pressure_viscosity  # the ester's own law
    hotter = as_lubricant({"name": "ISO_VG68", "vi": 140})
    assert hotter.kinematic_viscosity_40 == pytest.approx(
        68 * MM2
    ) and hotter.viscosity_index == pytest.approx(140)
    # the presets keep their constant α (the seeds' validations rest on it)
    assert (
        float(LUBRICANTS["ISO_VG68"].pressure_viscosity_at(100.0))
        == LUBRICANTS["ISO_VG68"].pressure_viscosity
    )


def test_every_library_entry_builds_with_its_source():
    for name in LIBRARY:
        lub = named_lubricant(name)
        assert lub.name == name and "bearingkit library [" in lub.source
        assert lub.kinematic_viscosity_100 < lub.kinematic_viscosity_40
    lgmt2 = named_lubricant("SKF_LGMT2")
    assert lgmt2.is_grease and lgmt2.grease.thickener == "lithium" and lgmt2.base == "grease"
    assert lgmt2.kinematic_viscosity_40 == pytest.approx(110 * MM2)
    pao = named_lubricant("VG68_PAO")
    assert pao.base_oil == "pao" and pao.viscosity_index == pytest.approx(145, abs=1e-6)


@pytest.mark.parametrize(
    ("form", "shown"),
    [
        ({"nu_40": "68 mm^2/s", "nu_100": "68 mm^2/s"}, "lubricant.nu_100 (68 mm^2/s) must be below nu_40"),
        ({"nu_40": "68 mm^2/s", "nu_100": "80 mm^2/s"}, "lubricant.nu_100 (80 mm^2/s) must be below nu_40"),
        ({"nu_40": "-68 mm^2/s", "nu_100": "8 mm^2/s"}, "lubricant.nu_40 ('-68 mm^2/s') must be positive"),
        (
            {"nu_40": "68 mm^2/s", "vi": 95, "base_oil": "vegetable"},
            "lubricant.base_oil ('vegetable') must be one of",
        ),
        ({"iso_vg": 69}, "lubricant.iso_vg (69) must be an ISO 3448 grade"),
        ({"iso_vg": 68, "nu_40": "68 mm^2/s"}, "give iso_vg or nu_40, not both"),
        ({"iso_vg": 68, "vi": 100, "nu_100": "8 mm^2/s"}, "give nu_100 or vi, not both"),
        ({"iso_vg": 68, "nlgi": "2"}, "lubricant.thickener: missing"),
        ({"iso_vg": 68, "thickener": "lithum"}, "did you mean 'lithium'?"),
        ({"viscosity_40": "68 mm^2/s"}, "lubricant.viscosity_40: unknown field"),
        ({"name": "ISO_VG69"}, "lubricant.name ('ISO_VG69') must be one of"),
        ("VG68 estr", "unknown word 'estr'"),
    ],
)
def test_bad_lubricants_are_one_line(form, shown):
    with pytest.raises(InputError) as err:
        as_lubricant(form)
    msg = str(err.value)
    assert shown in msg and "\n" not in msg


# --- the must-show of issue 35 through a file ---------------------------------------------------------
def _rating(lubricant_table: str):
    import bearingkit as bk
    from bearingkit.io.loader import loads

    text = f'[bearing]\ndesignation = "6208"\n[lubricant]\n{lubricant_table}\n'
    return bk.analyze(loads(text, "oil.toml"), load={"F_x": "4 kN"}, speed="6000 rpm", temperature="70 degC")


def test_a_file_with_nu40_and_nu100_gives_the_kappa_of_the_preset_of_that_vi():
    preset = LUBRICANTS["ISO_VG68"]
    vi = float(viscosity_index(preset.kinematic_viscosity_40, preset.kinematic_viscosity_100))
    by_data = _rating('nu_40 = "68 mm^2/s"\nnu_100 = "8.7 mm^2/s"')
    by_vi = _rating(f"iso_vg = 68\nvi = {vi!r}")
    by_name = _rating('name = "ISO_VG68"')
    k = [float(a.lubrication.result.kappa["balls"][0]) for a in (by_data, by_vi, by_name)]
    assert k[0] == pytest.approx(k[2], rel=0.01) and k[1] == pytest.approx(k[2], rel=0.01)
    assert k[0] == pytest.approx(k[2], rel=1e-9)  # the same ν(T): the same Walther line


def test_an_ester_of_the_same_viscosity_gives_another_film():
    mineral = _rating('nu_40 = "68 mm^2/s"\nnu_100 = "8.7 mm^2/s"')
    ester = _rating('nu_40 = "68 mm^2/s"\nnu_100 = "8.7 mm^2/s"\nbase_oil = "ester"')
    km, ke = (float(a.lubrication.result.kappa["balls"][0]) for a in (mineral, ester))
    assert km == pytest.approx(ke, rel=1e-12)  # κ rests on ν only
    hm = mineral.lubrication.result.film("balls").film_minimum_inner.max()
    he = ester.lubrication.result.film("balls").film_minimum_inner.max()
    # Hamrock–Dowson h_min ∝ U^0.68 G^0.49 at equal load: (η_e/η_m)^0.68 (α_e/α_m)^0.49 (equal ν, but the
    # ester is denser, so its η is higher)
    lm, le = mineral.operating.lubricant, ester.operating.lubricant
    am, ae = float(lm.pressure_viscosity_at(70.0)), float(le.pressure_viscosity_at(70.0))
    em, ee = float(lm.viscosity(70.0)), float(le.viscosity(70.0))
    assert ae < 0.75 * am
    assert he / hm == pytest.approx((ee / em) ** 0.68 * (ae / am) ** 0.49, rel=2e-3)
