"""Designation → input-format geometry: clearance class, notes, calibration to a user's C."""

import math

import pytest

from bearingkit.catalogue import clearance, entries, estimate, ratings, resolve
from bearingkit.errors import InputError


def test_deep_groove_geometry_and_clearance_class():
    r = resolve("6205-2RS C3")
    g = r.geometry
    assert r.bearing_type == "deep_groove_ball"
    assert g["bore"] == pytest.approx(0.025) and g["outer_diameter"] == pytest.approx(0.052)
    assert g["clearance_radial"] == pytest.approx(clearance("deep_groove_ball", 0.025, "C3"))
    assert "ESTIMATED" in r.source and "C3" in r.source and "2RS" in r.source


def test_large_spherical_takes_the_clearance_above_500_mm():
    """Spherical bores 500-1 400 mm (NSK E1102 B196-B200) take NSK Table 9.15's rows above 500 mm (A92)."""
    r = resolve("230/600 C3")
    assert r.bearing_type == "spherical_roller" and r.geometry["bore"] == pytest.approx(0.600)
    assert r.geometry["clearance_radial"] == pytest.approx(0.5 * (480 + 650) * 1e-6)
    e = entries("spherical_roller")["230/600"]
    assert (e.C, e.C0) == (5.45e6, 12.2e6) and "NSK-E1102:B198" in e.source


def test_default_clearance_is_cn_mean():
    r = resolve("6206")
    assert r.geometry["clearance_radial"] == pytest.approx(clearance("deep_groove_ball", 0.030, "CN", 0.5))


def test_calibration_reaches_the_given_c_and_keeps_count():
    base = resolve("6205")
    r = resolve("6205", C=14.8e3)
    assert r.C == pytest.approx(14.8e3, rel=1e-6)
    assert r.geometry["n_elements"] == base.geometry["n_elements"]
    assert r.geometry["element_diameter"] > base.geometry["element_diameter"]
    assert "user catalogue C" in r.source


def test_calibration_outside_band_refused():
    with pytest.raises(InputError, match="outside what 6205 can reach"):
        resolve("6205", C=60e3)


def test_clearance_class_on_type_without_group_refused():
    with pytest.raises(InputError, match="no ISO 5753-1 radial group"):
        resolve("7206B C3")


@pytest.mark.parametrize(
    ("text", "bearing_type"),
    [
        ("7206B", "angular_contact_ball"),
        ("3205", "angular_contact_pair"),
        ("NU206E", "cylindrical_roller"),
        ("30206", "tapered_roller"),
        ("51205", "thrust_ball"),
        ("81212", "cylindrical_roller_thrust"),
        ("QJ208", "four_point_contact_ball"),
        ("1205", "self_aligning_ball"),
        ("22208 E", "spherical_roller"),
        ("NA4906", "needle_roller"),
        ("RNA49/22", "needle_roller"),
    ],
)
def test_types(text, bearing_type):
    r = resolve(text)
    assert r.bearing_type == bearing_type
    c, _ = ratings(estimate(entries(r.designation.family)[r.designation.base]))
    assert r.C == c


def test_four_point_axial_clearance_class_becomes_the_rows_diametral_clearance():
    """QJ bearings are classed by axial clearance (SKF 6000 p. 453 Table 1; d = 40 mm: CN 56-106 um,
    C3 96-146 um); the row's arches give s_a = P_d / tan 35°, so P_d = s_a tan 35°."""
    r = resolve("QJ208")
    assert r.geometry["clearance_radial"] == pytest.approx(81e-6 * math.tan(math.radians(35)))
    r3 = resolve("QJ 208 C3")
    assert r3.geometry["clearance_radial"] == pytest.approx(121e-6 * math.tan(math.radians(35)))
    assert "axial clearance C3" in r3.source and "P_d = s_a tan(alpha)" in r3.source


def test_tapered_bore_takes_the_unmounted_tapered_bore_group():
    """K: SKF 6000 p. 706 Table 4 (spherical roller, d over 30 incl 40: CN 35-50 um) instead of the
    cylindrical-bore 30-45 um; the note says the clearance is the unmounted one."""
    assert resolve("22208 E").geometry["clearance_radial"] == pytest.approx(37.5e-6)
    r = resolve("22208 EK")
    assert r.geometry["clearance_radial"] == pytest.approx(42.5e-6)
    assert "UNMOUNTED" in r.source and "suffixes E noted" in r.source
    assert resolve("1209 K").geometry["clearance_radial"] == pytest.approx(30.5e-6)  # p. 477: 22-39 um


def test_needle_with_and_without_inner_ring():
    na, rna = resolve("NA4906"), resolve("RNA4906")
    assert na.geometry["inner_ring"] is True and rna.geometry["inner_ring"] is False
    assert na.geometry["bore"] == pytest.approx(0.030) and rna.geometry["bore"] is None
    assert na.geometry["construction"] == "machined" and "runs on the shaft" not in na.source
    assert "the needles run on the shaft" in rna.source
    # the clearance of the cylindrical roller group (NSK E1102 B245: Table 9.14 for needle bearings)
    assert na.geometry["clearance_radial"] == pytest.approx(clearance("cylindrical_roller", 0.030, "CN"))
