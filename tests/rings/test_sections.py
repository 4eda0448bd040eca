"""Ring sections: polygon properties against closed forms, the torsion constant against Saint-Venant's
rectangle series and the circle, grooves against the circular segment, smeared bolt holes."""

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.rings import sections as S


def test_rectangle_properties_are_exact():
    sec = S.rectangular_section(0.10, 0.14, -0.02, 0.03)
    b, h = 0.04, 0.05  # radial, axial
    assert sec.area == pytest.approx(b * h, rel=1e-14)
    assert sec.centroid_radius == pytest.approx(0.12, rel=1e-14)
    assert sec.centroid_z == pytest.approx(0.005, rel=1e-12)
    assert sec.inertia_in == pytest.approx(h * b**3 / 12, rel=1e-12)
    assert sec.inertia_out == pytest.approx(b * h**3 / 12, rel=1e-12)
    assert abs(sec.product) < 1e-12 * sec.inertia_in


@pytest.mark.parametrize("b,h", [(0.04, 0.05), (0.06, 0.01), (0.02, 0.02)])
def test_torsion_by_prandtl_against_the_rectangle_series(b, h):
    """Timoshenko & Goodier (1951) §109: J/(b h³) → 0.1406 for a square, → 1/3 (1 − 0.63 h/b) thin;
    the finite-difference Prandtl solve within 2e-4."""
    series = S.rectangular_torsion(b, h)
    if b == h:
        assert series / b**4 == pytest.approx(0.1406, rel=2e-3)
    fd = S.torsion_constant([S.rectangle(0.1, 0.1 + b, 0.0, h)])
    assert fd == pytest.approx(series, rel=2e-4)


def test_torsion_of_a_circle():
    r = 0.01
    t = np.linspace(0, 2 * np.pi, 720, endpoint=False)
    circle = np.stack([0.2 + r * np.cos(t), r * np.sin(t)], -1)
    assert S.torsion_constant([circle]) == pytest.approx(np.pi * r**4 / 2, rel=3e-3)


@pytest.mark.parametrize("side", ["inner", "outer"])
def test_groove_removes_a_circular_segment(side):
    """A groove of radius ρ cut to depth d: the segment area ρ² acos(1 − d/ρ) − (ρ − d)√(2ρd − d²)."""
    r_in, r_out, rho, d = 0.10, 0.13, 0.0133, 0.006
    sec = S.grooved_section(r_in, r_out, -0.015, 0.015, rho, d, side)
    segment = rho**2 * np.arccos(1 - d / rho) - (rho - d) * np.sqrt(2 * rho * d - d * d)
    assert sec.area == pytest.approx((r_out - r_in) * 0.03 - segment, rel=2e-4)
    plain = S.rectangular_section(r_in, r_out, -0.015, 0.015)
    # the groove takes material from the raceway side: the centroid moves away from it
    assert (sec.centroid_radius - plain.centroid_radius) * (1 if side == "inner" else -1) > 0
    assert abs(sec.centroid_z) < 1e-12 and sec.torsion < plain.torsion


def test_smeared_bolt_holes_take_their_share_of_the_band():
    n, d, rb = 24, 0.014, 0.14
    parts, w = S.smear_bolt_holes([S.rectangle(0.10, 0.16, 0.0, 0.05)], n, d, rb)
    sec = S.section_of(parts, w)
    f = n * d / (2 * np.pi * rb)
    assert sec.area == pytest.approx(0.06 * 0.05 - f * d * 0.05, rel=1e-12)
    whole = S.rectangular_section(0.10, 0.16, 0.0, 0.05)
    band_i = d**3 * 0.05 / 12 + d * 0.05 * (rb - sec.centroid_radius) ** 2
    expected = whole.inertia_in + whole.area * (whole.centroid_radius - sec.centroid_radius) ** 2 - f * band_i
    assert sec.inertia_in == pytest.approx(expected, rel=1e-12)
    assert sec.torsion < whole.torsion


def test_stepped_section_is_the_union_of_its_rectangles():
    a, b = S.rectangle(0.10, 0.12, 0.0, 0.04), S.rectangle(0.12, 0.16, 0.0, 0.01)
    sec = S.stepped_section([(0.10, 0.12, 0.0, 0.04), (0.12, 0.16, 0.0, 0.01)])
    assert sec.area == pytest.approx(0.02 * 0.04 + 0.04 * 0.01, rel=1e-14)
    assert sec.centroid_radius == pytest.approx((0.11 * 0.0008 + 0.14 * 0.0004) / 0.0012, rel=1e-12)
    assert sec.coupling > 0.1  # an L: its principal axes are off r and z
    del a, b
    with pytest.raises(InputError, match="overlap"):
        S.stepped_section([(0.10, 0.12, 0.0, 0.04), (0.11, 0.16, 0.0, 0.01)])


def test_bad_sections():
    with pytest.raises(InputError, match="rectangle"):
        S.rectangle(0.12, 0.10, 0.0, 0.01)
    with pytest.raises(InputError, match="groove_depth"):
        S.grooved_section(0.10, 0.13, -0.015, 0.015, 0.005, 0.006)
    with pytest.raises(InputError, match="no material"):
        S.smear_bolt_holes([S.rectangle(0.10, 0.16, 0.0, 0.05)], 200, 0.014, 0.14)


@pytest.mark.parametrize(("b", "t"), [(1e9, 0.02), (0.02, 1e9), (1e3, 0.01)])
def test_the_prandtl_grid_stays_bounded_for_any_proportions(b, t):
    """A wall of 1e12 mm by 20 mm (a mutated file: tests/io/test_mutations.py) made a grid of 1.5e8 cells
    and 23 GB before the cells were bounded where the thin side is floored at 2 cells; now at most
    TORSION_MAX_CELLS, and J finite and positive (2 cells across: J = 1.5 × the thin strip's b t³/3 —
    such a section is far outside what the grid resolves)."""
    rect = np.array([[0.0, 0.0], [b, 0.0], [b, t], [0.0, t]])
    w, _, _ = S._weight_grid([rect], [1.0], S.TORSION_GRID)
    assert w.size <= S.TORSION_MAX_CELLS
    j = S.torsion_constant([rect])
    thin = min(b, t) ** 3 * max(b, t) / 3.0
    assert np.isfinite(j) and 0.5 * thin < j < 2.0 * thin
