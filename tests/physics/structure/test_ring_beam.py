"""Simply supported beam of seed 002 eqs. 4–6 against textbook closed forms and finite differences."""

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.physics.structure import ring_beam
from bearingkit.rings.section import RingSection


def test_central_load():
    """u_max = FL³/(48EI), θ_A = θ_B = FL²/(16EI) (Roark Table 8.1 case 1e, a = L/2)."""
    f, span, ei = 2000.0, 0.05, 1500.0
    d, _ = ring_beam.beam_deflection([span / 2], [span / 2], [[f]], span, ei)
    assert d[0, 0] == pytest.approx(f * span**3 / (48 * ei), rel=1e-12)
    ta, tb = ring_beam.end_rotations([span / 2], [[f]], span, ei)
    assert ta[0] == pytest.approx(f * span**2 / (16 * ei), rel=1e-12)
    assert tb[0] == pytest.approx(ta[0], rel=1e-12)


def test_offcentre_rotations_and_slope_by_fd():
    f, span, ei, a = 1000.0, 0.06, 900.0, 0.02
    b = span - a
    ta, tb = ring_beam.end_rotations([a], [[f]], span, ei)
    assert ta[0] == pytest.approx(f * a * b * (span + b) / (6 * ei * span), rel=1e-12)
    assert tb[0] == pytest.approx(f * a * b * (span + a) / (6 * ei * span), rel=1e-12)
    x = np.array([0.01, 0.035, 0.05])
    h = 1e-7
    _, s = ring_beam.beam_deflection(x, [a], [[f]], span, ei)
    dp, _ = ring_beam.beam_deflection(x + h, [a], [[f]], span, ei)
    dm, _ = ring_beam.beam_deflection(x - h, [a], [[f]], span, ei)
    assert np.allclose(s, (dp - dm) / (2 * h), rtol=1e-6)


def test_superposition_and_supports():
    span, ei = 0.05, 1000.0
    d, _ = ring_beam.beam_deflection([0.0, 0.05], [0.01, 0.03], [[100.0, 300.0]], span, ei)
    assert np.allclose(d, 0.0, atol=1e-20)  # supports do not move
    one, _ = ring_beam.beam_deflection([0.02], [0.01], [[100.0]], span, ei)
    two, _ = ring_beam.beam_deflection([0.02], [0.03], [[300.0]], span, ei)
    both, _ = ring_beam.beam_deflection([0.02], [0.01, 0.03], [[100.0, 300.0]], span, ei)
    assert both[0, 0] == pytest.approx(one[0, 0] + two[0, 0], rel=1e-12)


def test_bad_input():
    with pytest.raises(InputError, match="x_load"):
        ring_beam.beam_deflection([0.01], [0.07], [[1.0]], 0.05, 1.0)
    with pytest.raises(InputError, match="flexural_rigidity"):
        ring_beam.beam_deflection([0.01], [0.02], [[1.0]], 0.05, 0.0)
    with pytest.raises(InputError, match="span"):
        ring_beam.beam_deflection([0.0], [0.0], [[1.0]], -0.05, 1.0)


def test_sections():
    rect = RingSection.rectangular(0.075, 0.008, 0.195)
    assert rect.area_moment == pytest.approx(0.075 * 0.008**3 / 12)
    # A sphere so large the back is flat: the arc-backed section tends to the rectangle.
    flat = RingSection.arc_backed(0.075, 0.195, 1e3, beam_width=1.0)
    h = flat.mean_thickness
    assert flat.area_moment == pytest.approx(0.075 * h**3 / 12, rel=1e-6)
    arc = RingSection.arc_backed(0.075, 0.195, 0.203)
    assert arc.area < 0.075 * 0.008  # thinner at the edges
    with pytest.raises(InputError, match="area_moment"):
        RingSection(area_moment=0.0, area=1e-4, width=0.07, centroid_radius=0.2)
    with pytest.raises(InputError, match="sphere_radius"):
        RingSection.arc_backed(0.075, 0.195, 0.196)
