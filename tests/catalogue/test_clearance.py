"""ISO 5753-1 radial internal clearance groups (as reproduced in NSK E1102, Tables 9.9, 9.14, 9.15), the
tapered-bore groups and the QJ axial group (SKF General Catalogue 6000, Russian edition 2006)."""

import itertools

import pytest

from bearingkit.catalogue import clearance, clearance_range, resolve
from bearingkit.errors import InputError

UM = 1e-6


@pytest.mark.parametrize(
    ("group", "bore_mm", "cls", "expected_um"),
    [
        # NSK E1102 Table 9.9 (deep groove ball), rows "10 only", "10-18", "24-30", "40-50"
        ("deep_groove_ball", 10, "CN", (2, 13)),
        ("deep_groove_ball", 12, "C3", (11, 25)),
        ("deep_groove_ball", 25, "C3", (13, 28)),
        ("deep_groove_ball", 45, "C2", (1, 11)),
        ("deep_groove_ball", 50, "C5", (45, 73)),  # d = 50 belongs to "over 40 incl. 50"
        # Table 9.9 rows above 500 mm: "500-560", "630-710", "710-800" (the table ends at 800 mm)
        ("deep_groove_ball", 530, "C2", (10, 100)),
        ("deep_groove_ball", 670, "CN", (110, 260)),
        ("deep_groove_ball", 800, "C5", (600, 840)),
        # Table 9.14 (cylindrical roller, cylindrical bore, interchangeable), rows "24-30", "40-50"
        ("cylindrical_roller", 30, "CN", (20, 45)),
        ("cylindrical_roller", 45, "C4", (70, 100)),
        # SKF's cylindrical-bore table (same groups), rows "500-560", "900-1 000"
        ("cylindrical_roller", 530, "CN", (240, 360)),
        ("cylindrical_roller", 1000, "C5", (1215, 1405)),
        # Table 9.15 (spherical roller, cylindrical bore), rows "40-50", "560-630", "1 250-1 400"
        ("spherical_roller", 45, "C3", (55, 75)),
        ("spherical_roller", 600, "C3", (480, 650)),
        ("spherical_roller", 1400, "C4", (1240, 1620)),
        # SKF 6000 p. 706 Table 4 (spherical roller, TAPERED bore), row "40-50"; p. 477 Table 5
        # (self-aligning ball, tapered bore), row "65-80"
        ("spherical_roller_tapered_bore", 45, "C3", (60, 80)),
        ("self_aligning_ball_tapered_bore", 70, "C4", (69, 98)),
        # NSK E1102 A92 Table 9.15 (spherical roller, TAPERED bore), rows "225-250", "1 250-1 400"
        ("spherical_roller_tapered_bore", 240, "CN", (200, 270)),
        ("spherical_roller_tapered_bore", 1300, "C4", (1560, 2000)),
        # SKF 6000 p. 453 Table 1: AXIAL clearance of QJ bearings, row "40-60"
        ("four_point_contact_ball_axial", 50, "CN", (76, 126)),
    ],
)
def test_published_groups(group, bore_mm, cls, expected_um):
    lo, hi = clearance_range(group, bore_mm * 1e-3, cls)
    assert (lo / UM, hi / UM) == pytest.approx(expected_um)


def test_deep_groove_designations_above_500_mm_get_a_clearance():
    """The catalogue's deep groove rows reach 800 mm (618/800, 619/800; 60/670): NSK Table 9.9 prints the
    ISO 5753-1 groups to 800 mm, so a designation there is resolved with its CN mean (it was refused,
    "outside the deep_groove_ball clearance table (0-500 mm)", while the table stopped at 500 mm)."""
    for name, bore in (("60/670", 0.670), ("618/800", 0.800), ("619/530", 0.530)):
        r = resolve(name)
        assert r.geometry["clearance_radial"] == pytest.approx(clearance("deep_groove_ball", bore, "CN", 0.5))
    assert resolve("60/670").geometry["clearance_radial"] == pytest.approx(185e-6)  # (110 + 260)/2 um


def test_spherical_tapered_bore_above_225_mm_gets_nsk_groups():
    """23048 CAK (d = 240 mm): the tapered-bore groups stopped at 225 mm (SKF 6000 p. 706), so the K
    variant was refused; NSK Table 9.15 prints them to 1 400 mm (CN 200-270 um for 225-250 mm)."""
    r = resolve("23048 CAK")
    assert r.geometry["clearance_radial"] == pytest.approx(235e-6)  # (200 + 270)/2 um
    assert r.geometry["clearance_radial"] > resolve("23048 CA").geometry["clearance_radial"]


def test_default_is_class_mean_and_position_interpolates():
    lo, hi = clearance_range("deep_groove_ball", 0.025, "CN")
    assert clearance("deep_groove_ball", 0.025) == pytest.approx(0.5 * (lo + hi))
    assert clearance("deep_groove_ball", 0.025, "CN", 0.0) == pytest.approx(lo)
    assert clearance("deep_groove_ball", 0.025, "CN", 1.0) == pytest.approx(hi)


def test_cylindrical_groups_grow_with_the_bore_and_the_class():
    """Every class's limits grow with the bore, the rows above 500 mm included, and within a row each
    class starts above the one before (the cylindrical classes overlap: C2 5-30, CN 25-50 um at 30-40)."""
    from bearingkit.catalogue.clearances import clearance_rows

    rows = [r for r in clearance_rows() if r.element == "cylindrical_roller"]
    assert rows[-1].bore_incl == pytest.approx(1.0)
    for cls in ("C2", "CN", "C3", "C4", "C5"):
        limits = [r.groups[cls] for r in rows if cls in r.groups]
        assert all(a[0] <= b[0] and a[1] <= b[1] for a, b in itertools.pairwise(limits)), cls
    for r in rows:
        starts = [r.groups[c][0] for c in ("C2", "CN", "C3", "C4", "C5") if c in r.groups]
        assert all(a < b for a, b in itertools.pairwise(starts)), r


def test_classes_grow_from_c2_to_c5():
    means = [clearance("deep_groove_ball", 0.060, c) for c in ("C2", "CN", "C3", "C4", "C5")]
    assert all(a < b for a, b in itertools.pairwise(means))


@pytest.mark.parametrize(
    ("args", "match"),
    [
        (("deep_groove_ball", 0.025, "C7"), "must be one of C2"),
        (("deep_groove_ball", 0.9, "CN"), "outside the deep_groove_ball clearance table"),
        (("cylindrical_roller", 1.05, "CN"), r"outside the cylindrical_roller clearance table \(0–1000 mm\)"),
        (("needle", 0.025, "CN"), "clearance group"),
        # SKF 6000 p. 477 lists no C5 for tapered-bore self-aligning ball bearings: say which classes exist
        # (nor NSK E1102 Table 9.15 for spherical roller bearings above 1 000 mm)
        (("spherical_roller", 1.06, "C5"), r"not defined .* classes there: C2, CN, C3, C4$"),
        (("self_aligning_ball_tapered_bore", 0.05, "C5"), r"not defined .* classes there: C2, CN, C3, C4$"),
    ],
)
def test_bad_requests(args, match):
    with pytest.raises(InputError, match=match):
        clearance_range(*args)


def test_tapered_bore_groups_exceed_the_cylindrical_ones():
    """An unmounted tapered-bore bearing has more clearance than its cylindrical-bore twin (the drive-up
    takes it up), class by class — SKF p. 706 Table 4 against NSK Table 9.15 / SKF Table 3."""
    for cls in ("C2", "CN", "C3", "C4", "C5"):
        cyl = clearance("spherical_roller", 0.100, cls)
        tap = clearance("spherical_roller_tapered_bore", 0.100, cls)
        assert tap > cyl
