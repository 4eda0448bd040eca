"""ISO 286 tolerance fields and ISO 492 ring deviations against tabulated limit deviations, fit statistics."""

import pytest

from bearingkit.errors import InputError
from bearingkit.physics.structure import tolerances as tol

UM = 1e-6

# Limit deviations [µm] as ISO 286-2 tabulates them (k5/k6/m6/n6/p6/g6/h6 for shafts, H7/K7/M7/N7/P7/G7 for
# holes), checked against public ISO 286 transcriptions; J7 and K6/M6 use the from-memory J and Δ tables.
CASES = [
    ("k5", 45, 13, 2),
    ("k6", 45, 18, 2),
    ("m6", 45, 25, 9),
    ("n6", 60, 39, 20),
    ("p6", 100, 59, 37),
    ("g6", 45, -9, -25),
    ("h6", 45, 0, -16),
    ("js6", 45, 8, -8),
    ("H7", 85, 35, 0),
    ("G7", 85, 47, 12),
    ("K7", 85, 10, -25),
    ("M7", 85, 0, -35),
    ("N7", 85, -10, -45),
    ("P7", 85, -24, -59),
    ("K6", 40, 3, -13),
    ("M6", 40, -4, -20),
    ("J7", 85, 22, -13),
]


@pytest.mark.parametrize("code, size_mm, upper, lower", CASES)
def test_tolerance_fields(code, size_mm, upper, lower):
    u, low = tol.tolerance_field(code, size_mm * 1e-3)
    assert u == pytest.approx(upper * UM, abs=1e-12) and low == pytest.approx(lower * UM, abs=1e-12)


def test_ring_deviations_normal_class():
    assert tol.ring_deviation("inner", 0.045) == (0.0, pytest.approx(-12 * UM))
    assert tol.ring_deviation("outer", 0.085) == (0.0, pytest.approx(-15 * UM))
    assert tol.ring_deviation("outer", 0.160) == (0.0, pytest.approx(-25 * UM))


def test_fit_statistics():
    shaft, bore = tol.tolerance_field("k5", 0.045), tol.ring_deviation("inner", 0.045)
    assert tol.fit_interference(shaft, bore, "min") == pytest.approx(2 * UM)
    assert tol.fit_interference(shaft, bore, "max") == pytest.approx(25 * UM)
    assert tol.fit_interference(shaft, bore, "mean") == pytest.approx(13.5 * UM)
    assert tol.fit_interference(shaft, bore, 50.0) == pytest.approx(13.5 * UM)
    # ±3σ fields: σ = √((11/6)² + (12/6)²) µm; the 99.865 % point is the mean + 3σ (below the 25 µm limit).
    sigma = ((11 / 6) ** 2 + 2.0**2) ** 0.5 * UM
    assert tol.fit_interference(shaft, bore, 99.865) == pytest.approx(13.5 * UM + 3 * sigma, rel=1e-4)


@pytest.mark.parametrize("code", ["k55", "q6", "x7", "J9", "kk5", ""])
def test_unknown_fields_are_one_line_errors(code):
    with pytest.raises(InputError, match="tolerance field") as err:
        tol.tolerance_field(code, 0.045)
    assert "\n" not in str(err.value)


def test_size_outside_the_tables():
    with pytest.raises(InputError, match="500"):
        tol.tolerance_field("k5", 0.6)
