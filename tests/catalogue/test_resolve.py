"""Designation → input-format geometry: clearance class, notes, calibration to a user's C."""

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
        ("QJ208", None),
        ("1205", None),
    ],
)
def test_types(text, bearing_type):
    r = resolve(text)
    assert r.bearing_type == bearing_type
    c, _ = ratings(estimate(entries(r.designation.family)[r.designation.base]))
    assert r.C == c
