"""ISO 281:2007 Table 3 for angular contact ball bearings below 20° (5°, 10°, 15°: the spindle bearings):
e, X, Y as functions of the relative axial load i f0 Fa/C0r, checked against values interpolated by hand
from the table as printed (the numbers below are typed from the standard's rows, not read from the data
file), the 5° single-row rule (the radial contact rows), continuity towards 20°, the refusal outside the
grid and the batch screen."""

from __future__ import annotations

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.physics.life import iso281_load

A15, A10, A5 = np.radians(15.0), np.radians(10.0), np.radians(5.0)
C0, F0 = 40_000.0, 15.0  # N, MPa: i f0 Fa/C0r = Fa · 15/40000 per row


def _fa(rel, i=1):
    """Fa [N] giving i f0 Fa/C0r = rel."""
    return rel * C0 / (i * F0)


def _p(fr, fa, alpha, i=1):
    return float(iso281_load.equivalent_dynamic_load(fr, fa, "angular_contact_ball", alpha, i, C0, F0))


def test_15_degrees_single_row_at_a_grid_point():
    """i f0 Fa/C0r = 1.07 (4th row of the 15° block): e = 0.46, X = 0.44, Y = 1.23."""
    fa = _fa(1.07)
    assert _p(fa / 0.50, fa, A15) == pytest.approx(0.44 * fa / 0.50 + 1.23 * fa, rel=1e-12)  # Fa/Fr > e
    assert _p(fa / 0.45, fa, A15) == pytest.approx(fa / 0.45, rel=1e-12)  # Fa/Fr = 0.45 <= 0.46: P = Fr


def test_15_degrees_single_row_between_grid_points():
    """i f0 Fa/C0r = 0.5, between 0.357 (e 0.40, Y 1.40) and 0.714 (e 0.43, Y 1.30), by hand."""
    t = (0.5 - 0.357) / (0.714 - 0.357)
    e = 0.40 + t * (0.43 - 0.40)
    y = 1.40 + t * (1.30 - 1.40)
    fa = _fa(0.5)
    fr = fa / (1.01 * e)
    assert _p(fr, fa, A15) == pytest.approx(0.44 * fr + y * fa, rel=1e-12)
    assert _p(fa / (0.99 * e), fa, A15) == pytest.approx(fa / (0.99 * e), rel=1e-12)


def test_15_degrees_double_row_both_sides_of_e():
    """Double row (i = 2) at i f0 Fa/C0r = 2.14: e 0.50; Y 1.26 below e; X 0.72, Y 1.82 above."""
    fa = _fa(2.14, i=2)
    assert _p(fa / 0.45, fa, A15, 2) == pytest.approx(fa / 0.45 + 1.26 * fa, rel=1e-12)
    assert _p(fa / 0.55, fa, A15, 2) == pytest.approx(0.72 * fa / 0.55 + 1.82 * fa, rel=1e-12)


def test_i_enters_the_relative_axial_load():
    """The same Fa on a double row (i = 2) reads the table at twice the single row's i f0 Fa/C0r."""
    fa = _fa(0.357)  # single row: 0.357; double row: 0.714 → e 0.43, X 0.72, Y 2.11
    assert iso281_load.relative_axial_load(fa, C0, F0, 2) == pytest.approx(0.714)
    assert _p(fa / 0.5, fa, A15, 2) == pytest.approx(0.72 * fa / 0.5 + 2.11 * fa, rel=1e-12)


def test_10_degrees_both_row_counts():
    """10°, i f0 Fa/C0r = 3.50: e 0.49; single X 0.46, Y 1.10; double Y 1.27 below e, X 0.75, Y 1.79."""
    fa1, fa2 = _fa(3.50), _fa(3.50, i=2)
    assert _p(fa1, fa1, A10) == pytest.approx(0.46 * fa1 + 1.10 * fa1, rel=1e-12)
    assert _p(fa2 / 0.4, fa2, A10, 2) == pytest.approx(fa2 / 0.4 + 1.27 * fa2, rel=1e-12)
    assert _p(fa2, fa2, A10, 2) == pytest.approx(0.75 * fa2 + 1.79 * fa2, rel=1e-12)


def test_5_degrees_single_row_uses_the_radial_contact_rows():
    """ISO's 5° single-row cells say "use the values of single-row radial contact ball bearings": at each
    row of the table (same Fa/(Z Dw²)) the 5° single row equals the deep groove law."""
    grid5 = [0.173, 0.346, 0.692, 1.04, 1.38, 2.08, 3.46, 5.19, 6.92]
    grid0 = [0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89]
    for r5, r0 in zip(grid5, grid0, strict=True):
        fa5 = _fa(r5)
        fa0 = r0 * C0 / F0
        for ratio in (0.1, 0.25, 0.5, 2.0):  # both sides of e
            p5 = _p(fa5 / ratio, fa5, A5) / fa5
            p0 = (
                float(
                    iso281_load.equivalent_dynamic_load(fa0 / ratio, fa0, "deep_groove_ball", 0.0, 1, C0, F0)
                )
                / fa0
            )
            assert p5 == pytest.approx(p0, rel=1e-12), (r5, ratio)


def test_5_degrees_double_row_column():
    """5° double row at i f0 Fa/C0r = 0.692: e 0.30; Y 2.07 below e; X 0.78, Y 2.78 above."""
    fa = _fa(0.692, i=2)
    assert _p(fa / 0.25, fa, A5, 2) == pytest.approx(fa / 0.25 + 2.07 * fa, rel=1e-12)
    assert _p(fa, fa, A5, 2) == pytest.approx(0.78 * fa + 2.78 * fa, rel=1e-12)


def test_between_two_angles_linear_in_each_grid_then_in_alpha():
    """12.5°, single row, Fa/Fr large: each block at the given i f0 Fa/C0r in its own grid, then halfway.
    i f0 Fa/C0r = 1.40: the 10° row 5 (X 0.46, Y 1.34); the 15° block between 1.07 (Y 1.23) and 1.43
    (Y 1.19)."""
    y15 = 1.23 + (1.40 - 1.07) / (1.43 - 1.07) * (1.19 - 1.23)
    x, y = (0.46 + 0.44) / 2, (1.34 + y15) / 2
    fa = _fa(1.40)
    assert _p(fa / 5, fa, np.radians(12.5)) == pytest.approx(x * fa / 5 + y * fa, rel=1e-12)


def test_towards_20_degrees_the_20_degree_row():
    """17.5°: halfway between the 15° block and the 20° row (e 0.57, X 0.43, Y 1.00); 19.999999° is the
    20° row within round-off, and 20° itself is the constant row (no C0r needed)."""
    fa = _fa(0.178)
    x, y = (0.44 + 0.43) / 2, (1.47 + 1.00) / 2
    assert _p(fa / 3, fa, np.radians(17.5)) == pytest.approx(x * fa / 3 + y * fa, rel=1e-12)
    near = _p(1000.0, 2000.0, np.radians(20.0 - 1e-6))
    at20 = float(iso281_load.equivalent_dynamic_load(1000.0, 2000.0, "angular_contact_ball", np.radians(20)))
    assert at20 == pytest.approx(0.43 * 1000 + 1.00 * 2000, rel=1e-12)
    assert near == pytest.approx(at20, rel=1e-6)


def test_outside_the_grid_one_clear_refusal():
    """Below 0.178 (15°) the standard has no value: an error naming the value and the range."""
    with pytest.raises(InputError, match=r"i\*f0\*Fa/C0r \(0\.17\d*\).*\[0\.178, 7\.14\].*15 deg"):
        _p(1000.0, _fa(0.17), A15)
    with pytest.raises(InputError, match=r"\[0\.178, 7\.14\]"):
        _p(1000.0, _fa(7.2), A15)
    with pytest.raises(InputError, match="static_rating and f0"):
        iso281_load.equivalent_dynamic_load(1000.0, 500.0, "angular_contact_ball", A15)
    with pytest.raises(InputError, match="contact_angle"):
        iso281_load.equivalent_dynamic_load(1000.0, 0.0, "angular_contact_ball", np.radians(4.0))


def test_radial_load_alone_needs_no_static_rating():
    assert float(iso281_load.equivalent_dynamic_load(1000.0, 0.0, "angular_contact_ball", A15)) == 1000.0


def test_cases_of_mixed_angles_in_one_call():
    """A 15° case (table by load) and a 40° case (constant row) side by side."""
    fa = _fa(1.07)
    p = iso281_load.equivalent_dynamic_load(
        [fa / 0.5, 1000.0], [fa, 2000.0], "angular_contact_ball", [A15, np.radians(40)], 1, C0, F0
    )
    np.testing.assert_allclose(p, [0.44 * fa / 0.5 + 1.23 * fa, 0.35 * 1000 + 0.57 * 2000], rtol=1e-12)


@pytest.mark.parametrize("deg, i", [(15.0, 1), (15.0, 2), (12.5, 1), (5.0, 2), (17.0, 1)])
def test_refused_cases_are_exactly_the_cases_the_law_refuses(deg, i):
    """The batch screen flags a case iff the law, asked for that case alone, raises — edges included."""
    alpha = np.radians(deg)
    rng = np.random.default_rng(15)
    fr = np.concatenate([rng.uniform(0.0, 20e3, 200), [1e3] * 6])
    fa = rng.uniform(0.0, _fa(8.0, i), 200) * rng.integers(0, 2, 200)
    lo, hi = iso281_load._low_range(deg)
    edges = np.array([lo, hi, lo * (1 - 1e-9), hi * (1 + 1e-9), lo * 0.5, 0.0])
    fa = np.concatenate([fa, _fa(edges, i)])
    refused = iso281_load.refused_cases(fr, fa, "angular_contact_ball", alpha, C0, F0, n_rows=i)
    alone = np.zeros(fr.shape, bool)
    for c in range(fr.size):
        try:
            iso281_load.equivalent_dynamic_load(fr[c], fa[c], "angular_contact_ball", alpha, i, C0, F0)
        except InputError:
            alone[c] = True
    np.testing.assert_array_equal(refused, alone)
    assert 0 < alone.sum() < fr.size
    np.testing.assert_array_equal(alone[-6:], [False, False, True, True, True, False])
