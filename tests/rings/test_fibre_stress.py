"""The hoop fibre stress the faces print (FlexibleRing.fibre_stress over the section's outline) against
Roark & Young (2012) Table 9.2 case 1 (thin ring, two equal and opposite radial loads P, here outward):
at the loads N = 0 and |M| = PR/π; at 90° from them N = P/2 and |M| = PR(1/2 − 1/π). The largest
|σ| of a rectangle (h × b, faces at ±h/2 from the centroid) is |N|/A + |M|(h/2)/I. The thin-ring
formulas are the reference: the model leaves Roark's hoop factor α = I/(AR²) (2e-4 here) out by design
(docs/structure.md)."""

import numpy as np
import pytest

from bearingkit.rings.curved_beam import FlexibleRing
from bearingkit.rings.sections import rectangular_section


def test_fibre_stress_of_roarks_case1():
    r_in, r_out, b, p = 0.195, 0.205, 0.03, 1e4
    ring = FlexibleRing(rectangular_section(r_in, r_out, -b / 2, b / 2))
    sec = ring.section
    r, h = sec.centroid_radius, r_out - r_in
    area, inertia = h * b, b * h**3 / 12
    assert sec.area == pytest.approx(area, rel=1e-9) and sec.inertia_in == pytest.approx(inertia, rel=1e-9)
    loads = np.array([[[p, 0.0, 0.0], [p, 0.0, 0.0]]])  # (C, N, 3): F_r outward at 0 and π
    _, forces = ring.response([0.0, np.pi / 2], np.array([0.0, np.pi]), loads, np.full(2, r), np.zeros(2))
    sigma = np.abs(ring.fibre_stress(forces)[0]).max(-1)
    at_load = p * r / np.pi * (h / 2) / inertia
    across = p / 2 / area + p * r * (0.5 - 1 / np.pi) * (h / 2) / inertia
    assert sigma == pytest.approx([at_load, across], rel=1e-6)
