"""Ring supports: the exact condensation of point springs against Woodbury's identity (written here),
stiff bolts that hold their points, a split housing, the rigid-body modes nothing holds."""

import numpy as np
import pytest

from bearingkit.physics.structure import curved_ring as cr
from bearingkit.rings.curved_beam import FlexibleRing
from bearingkit.rings.sections import rectangular_section
from bearingkit.rings.supports import BoltedFlange, Foundation, PointSupports, SplitHousing, condense

SEC = rectangular_section(0.20, 0.23, -0.02, 0.02)


def _blocks(theta_a, theta_b, ring, n=512):
    d = np.subtract.outer(theta_a, theta_b)
    g = cr.influence(d.ravel(), ring, n).reshape(*d.shape, 4, 4)
    return g.transpose(0, 2, 1, 3).reshape(4 * len(theta_a), 4 * len(theta_b))


def test_point_springs_on_a_held_ring_are_woodburys_identity():
    """Foundation holds every mode: C = C_ee − C_es (K⁻¹ + C_ss)⁻¹ C_se, the supports' Woodbury form."""
    ring = cr.RingRigidities(0.215, 2e9, 4e4, 9e4, 3e4, (2e8, 5e7, 1e8, 50.0, 0.0))
    theta = np.linspace(0, 2 * np.pi, 17, endpoint=False)
    psi_s = np.array([0.3, 1.9, 4.0])
    k = np.array([[3e8, 1e7, 2e7, 1e5], [1e7, 2e8, 0, 0], [2e7, 0, 4e8, -3e6], [1e5, 0, -3e6, 4e4]])
    sup = PointSupports(psi_s, np.stack([k, 2 * k, 0.5 * k]))
    got = condense(ring, 512, 0, theta, sup).compliance
    c_ee, c_es, c_ss = _blocks(theta, theta, ring), _blocks(theta, psi_s, ring), _blocks(psi_s, psi_s, ring)
    kinv = np.zeros((12, 12))
    for i, f in enumerate((1.0, 2.0, 0.5)):
        kinv[4 * i : 4 * i + 4, 4 * i : 4 * i + 4] = np.linalg.inv(f * k)
    ref = c_ee - c_es @ np.linalg.solve(kinv + c_ss, c_es.T)
    assert got == pytest.approx(ref, rel=1e-9, abs=1e-12 * np.abs(ref).max())


def test_stiff_bolts_hold_their_points_and_the_free_ring_floats_on_them():
    """No foundation: 12 bolts of 1e15 N/m in every direction at the bolt circle; the bolt points do not
    move under any load (≤ 1e-5 of the ring's own deflection: F/k of the bolts and the solve's round-off
    at K G ~ 1e7) and the compliance is symmetric, positive."""
    flange = BoltedFlange(12, 0.225, 1e15, 1e15, 1e15, face_z=-0.02)
    ring = FlexibleRing(SEC, flange=flange, harmonics=256)
    theta = np.concatenate([flange.azimuths(), flange.azimuths() + np.pi / 12])
    cond = ring.condensation(theta)
    c = cond.compliance
    assert np.allclose(c, c.T, rtol=0, atol=1e-14 * np.abs(c).max())
    assert np.linalg.eigvalsh(c).min() > -1e-12 * np.abs(c).max()
    loads = np.random.default_rng(2).normal(size=c.shape[0]) * 1e3
    u = (c @ loads).reshape(-1, 4)
    t = np.zeros((3, 4))
    t[0, 0], t[0, 3] = 1.0, flange.face_z - SEC.centroid_z
    t[1, 1] = 1.0
    t[2, 2], t[2, 3] = 1.0, -(flange.bolt_circle_radius - SEC.centroid_radius)
    at_bolts = u[:12] @ t.T
    assert np.abs(at_bolts).max() <= 1e-5 * np.abs(u[12:, :3]).max()
    assert cond.unheld == ()


def test_split_housing():
    seat = Foundation.seat(4e9, 0.04)
    theta = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    plain = FlexibleRing(SEC, foundation=seat + Foundation(tangential=1e8, axial=1e8, twist=10.0)).compliance(
        theta, 0.2, 0.0
    )
    same = FlexibleRing(
        SEC,
        foundation=seat + Foundation(tangential=1e8, axial=1e8, twist=10.0),
        split=SplitHousing(remaining=1.0),
    ).compliance(theta, 0.2, 0.0)
    assert same == pytest.approx(plain, rel=1e-12, abs=1e-20)
    split = FlexibleRing(
        SEC,
        foundation=seat + Foundation(tangential=1e8, axial=1e8, twist=10.0),
        split=SplitHousing(np.pi / 2),
    ).compliance(theta, 0.2, 0.0)
    at_joint, away = 3 * 6, 0  # element 6 sits at 90°, the joint; element 0 at 0°
    assert split[at_joint, at_joint] > 1.5 * plain[at_joint, at_joint]
    assert split[away, away] == pytest.approx(plain[away, away], rel=0.2)


def test_modes_nothing_holds_are_named():
    ring = FlexibleRing(SEC, foundation=Foundation.seat(4e9, 0.04))
    cond = ring.condensation(np.linspace(0, 2 * np.pi, 8, endpoint=False))
    assert set(cond.unheld) == {"rot_z", "u_z"}
    held = FlexibleRing(SEC, foundation=Foundation.seat(4e9, 0.04) + Foundation(tangential=1e7, axial=1e7))
    assert held.condensation(np.zeros(1)).unheld == ()
