"""ISO 281 / ISO 76 paired mounting: two similar single-row bearings mounted side by side as a unit."""

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.physics.life import iso281, iso281_load


def test_pair_ratings_are_the_row_count_law():
    # ISO 281:2007 eq. (2), (9) with i = 2: C_unit = 2^0.7 C (ball), 2^(7/9) C (roller); ISO 76: 2 C0
    c, c0 = iso281.paired_unit_ratings(20.0e3, 15.0e3, "ball")
    assert c == pytest.approx(20.0e3 * 1.6245047927, rel=1e-9) and c0 == pytest.approx(30.0e3)
    c, c0 = iso281.paired_unit_ratings(43.0e3, None, "roller")
    assert c == pytest.approx(43.0e3 * 1.7144879657, rel=1e-9) and c0 is None
    # one bearing is itself
    assert iso281.paired_unit_ratings(1.0e3, 2.0e3, "ball", 1) == pytest.approx((1.0e3, 2.0e3))


def test_pair_equals_a_two_row_bearing_of_the_same_rows():
    """The same law as ISO 281's i rows: a unit of two 25° rows rates as dynamic_rating_ball with i = 2."""
    one = iso281.dynamic_rating_ball(9e-3, 50e-3, np.radians(25), 14, 1, "angular_contact_ball")
    two = iso281.dynamic_rating_ball(9e-3, 50e-3, np.radians(25), 14, 2, "angular_contact_ball")
    assert iso281.paired_unit_ratings(one, None, "ball")[0] == pytest.approx(two, rel=1e-12)


def test_arrangement_chooses_the_xy_rows():
    assert iso281.PAIRED_UNIT_XY_ROWS == {"DB": 2, "DF": 2, "DT": 1}
    # a tandem pair keeps the single-row X, Y: 40°, F_a/F_r = 2 > e = 1.14 -> P = 0.35 F_r + 0.57 F_a
    p = iso281_load.equivalent_dynamic_load(1000.0, 2000.0, "angular_contact_ball", np.radians(40), 1)
    assert p == pytest.approx(0.35 * 1000.0 + 0.57 * 2000.0, rel=1e-9)


def test_bad_arguments_refused():
    with pytest.raises(InputError):
        iso281.paired_unit_ratings(-1.0, None, "ball")
    with pytest.raises(InputError):
        iso281.paired_unit_ratings(1.0, None, "needle")
    with pytest.raises(InputError):
        iso281.paired_unit_ratings(1.0, None, "ball", 0)
