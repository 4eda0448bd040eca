"""The curved ring in and out of its plane against Roark's ring cases, Hetényi's foundation, the seed-002
thin ring and an independent least-work (Castigliano) solution written here.

Roark & Young (2012) Table 9.2, case 2 (two equal and opposite forces W along a chord at ±θ from the top
A, as reproduced by engineersedge.com "Circular Ring Analysis Roarks Formulas 2"): M_A, M_C, N_A of the
thin ring (α = β = 0). Case 1 (ΔD = −(π/4 − 2/π) PR³/EI along the loads), case 15 (own weight on a
point support) and the uniform pressure (Δr = pR²/EA, Roark Table 13.1 thin ring) likewise; in-plane
couples against a least-work closed form (validation/literature_rings.py). Roark's
hoop-deformation factor α = I/(AR²) (the coupling of M and N in a curved bar) is NOT in this model;
its size is measured in :func:`test_roark_hoop_factor_is_left_out`.
"""

import numpy as np
import pytest

from bearingkit.physics.structure import curved_ring as cr
from bearingkit.physics.structure import thin_ring
from bearingkit.validation import literature_rings as lr

R, EI, W = 0.2, 500.0, 1000.0


def _ring(ea=np.inf, foundation=(0.0, 0.0, 0.0, 0.0), eo=np.inf, gj=np.inf):
    return cr.RingRigidities(R, ea, EI, eo, gj, foundation)


# -- the seed-002 thin ring and Hetényi ------------------------------------------------------------
@pytest.mark.parametrize("k_h", [0.0, 3e7, 3e9])
def test_inextensible_ring_without_n0_n1_is_the_thin_ring(k_h):
    """EA = ∞, harmonics from 2: the closed-form kernel of thin_ring (Li et al. 2025 eqs. 8–10 with the
    Winkler housing), to 1e-10."""
    d = np.linspace(0.0, 2 * np.pi, 37)
    g = cr.influence(d, _ring(foundation=(k_h, 0, 0, 0)), 1024, first_harmonic=2)
    ref = thin_ring.radial_influence(d, [0.0], R, EI, k_h)[:, 0]
    assert g[:, 0, 0] == pytest.approx(ref, rel=1e-10, abs=1e-10 * np.abs(ref).max())


def test_ring_on_a_foundation_tends_to_hetenyis_infinite_beam():
    """A point load on a ring on a Winkler foundation with λR ≫ 1 (every harmonic, the foundation holding
    n = 0, 1): w(0) = Qλ/(2k), λ = (k/4EI)^(1/4) (Hetényi 1946, the infinite beam)."""
    k = 4.0 * EI * (60.0 / R) ** 4  # λR = 60
    lam = (k / (4 * EI)) ** 0.25
    g = cr.influence([0.0], _ring(ea=1e6 * EI / R**2, foundation=(k, 0, 0, 0)), 4096)
    assert g[0, 0, 0] == pytest.approx(lam / (2 * k), rel=2e-3)


# -- Roark's in-plane cases ------------------------------------------------------------------------
def _chord_loads(theta):
    a1, a2 = np.pi / 2 - theta, np.pi / 2 + theta  # bearingkit angles of x = +θ, −θ from the top
    return [(a1, -W * np.cos(a1), W * np.sin(a1)), (a2, W * np.cos(a2), -W * np.sin(a2))]


def _resultants_at(ring, at, loads, n=2048):
    out = np.zeros((len(at), 4))
    for ang, f_r, f_t in loads:
        k = cr.resultants(np.asarray(at) - ang, ring, n)
        out += k[:, :, 0] * f_r + k[:, :, 1] * f_t
    return out


@pytest.mark.parametrize("theta", [np.pi / 6, np.pi / 3, np.pi / 2, 2 * np.pi / 3])
def test_roark_case2_forces_along_a_chord(theta):
    """Table 9.2 case 2, thin ring: M_A = −(WR/π)[(π − θ)(1 − c) − s(1 − c)], M_C = −(WR/π)[θ(1 + c) −
    s(1 + c)], N_A = −(W/π)(π − θ + sc). Roark's M is −M here (tension inside)."""
    ring = _ring(ea=1e9 * EI / R**2)  # α = 1e-9: the thin ring
    f = _resultants_at(ring, [np.pi / 2, -np.pi / 2], _chord_loads(theta))
    s, c = np.sin(theta), np.cos(theta)
    m_a = -W * R / np.pi * ((np.pi - theta) * (1 - c) - s * (1 - c))
    m_c = -W * R / np.pi * (theta * (1 + c) - s * (1 + c))
    n_a = -W / np.pi * (np.pi - theta + s * c)
    assert -f[:, 1] == pytest.approx([m_a, m_c], rel=1e-6, abs=1e-9 * W * R)
    assert f[0, 0] == pytest.approx(n_a, rel=1e-6)


@pytest.mark.parametrize("theta", [np.pi / 6, np.pi / 3, np.pi / 2, 2 * np.pi / 3])
def test_in_plane_couples_against_least_work(theta):
    """The moment load of Roark's Table 9.2: couples ∓M0 at x = ±θ from the top of a free thin ring, each
    as three point forces of zero resultant (the ring takes forces only), against the least-work closed
    form (validation/literature_rings.couples_closed_form): M_A, M_C and N_A to 1e-6 (measured ≤ 5.4e-8)."""
    gap, m0 = 1e-3, W * R
    triple = lr.couple_loads(0.7, m0, R, gap)
    force = sum(
        np.array([fr * np.cos(a) - ft * np.sin(a), fr * np.sin(a) + ft * np.cos(a)]) for a, fr, ft in triple
    )
    assert np.abs(force).max() < 1e-9 * m0 / R  # a couple: no resultant force
    assert sum(ft * R for _, _, ft in triple) == pytest.approx(m0, rel=1e-12)  # radial forces: no moment
    ring = _ring(ea=1e9 * EI / R**2)
    f = [
        _resultants_at(
            ring,
            [np.pi / 2, -np.pi / 2],
            lr.couple_loads(np.pi / 2 - theta, -m0, R, g) + lr.couple_loads(np.pi / 2 + theta, m0, R, g),
        )
        for g in (2 * gap, gap)
    ]
    f = (4 * f[1] - f[0]) / 3  # the gap's error is in its square
    m_a, m_c, n_a = lr.couples_closed_form(theta, m0, R)
    assert f[:, 1] == pytest.approx([m_a, m_c], rel=1e-6)
    assert f[0, 0] == pytest.approx(n_a, rel=1e-6)
    # the closed form itself: the moment jumps by M0 across the couple (M_C − M_A + 2N_A R = M0 in
    # Roark's signs), and the two couples cancel as θ → 0
    assert -(m_c - m_a) + 2 * n_a * R == pytest.approx(m0, rel=1e-12)
    assert lr.couples_closed_form(1e-9, m0, R)[2] == pytest.approx(0.0, abs=1e-8 * m0 / R)


def test_roark_hoop_factor_is_left_out():
    """With α = I/(AR²) = 0.01 Roark's M_A of case 2 at θ = 90° is −(WR/π)(π/2 − 1 + α); this model keeps
    −(WR/π)(π/2 − 1): the curved bar's M–N coupling is not in it (an O(α) term: 1.7 % of this M_A at
    α = 0.01; bearing rings have α ~ 1e-4 to 1e-3)."""
    ring = _ring(ea=EI / (0.01 * R**2))
    f = _resultants_at(ring, [np.pi / 2], _chord_loads(np.pi / 2))
    ours = -f[0, 1]
    thin = -W * R / np.pi * (np.pi / 2 - 1)
    roark = -W * R / np.pi * (np.pi / 2 - 1 + 0.01)
    assert ours == pytest.approx(thin, rel=1e-6)
    assert abs(ours / roark - 1) == pytest.approx(0.01 / (np.pi / 2 - 1 + 0.01), rel=1e-3)


def test_roark_case1_diameter_changes():
    """Table 9.2 case 1 (thin ring, two opposite inward loads P): ΔD along the loads −(π/4 − 2/π)PR³/EI,
    across +(2/π − 1/2)PR³/EI; the free ring's rigid modes left out (pseudo-inverse)."""
    ring = _ring(ea=1e9 * EI / R**2)
    g = cr.influence([0.0, np.pi, np.pi / 2, -np.pi / 2], ring, 1024)[:, 0, 0]
    gp = cr.influence([-np.pi, 0.0, -np.pi / 2, -3 * np.pi / 2], ring, 1024)[:, 0, 0]
    w = -W * (g + gp)  # inward loads at 0 and π
    unit = W * R**3 / EI
    assert (w[0] + w[1]) / unit == pytest.approx(-(np.pi / 4 - 2 / np.pi), rel=1e-7)
    assert (w[2] + w[3]) / unit == pytest.approx(2 / np.pi - 0.5, rel=1e-7)


def test_uniform_pressure_stretches_the_ring():
    """Uniform outward pressure q [N/m] on the centroid: pure hoop tension N = qR and Δr = qR²/EA (thin
    ring; Roark & Young 2012 Table 13.1 case 1a), here as 4096 point loads (more than the 2048 harmonics:
    only n = 0 sees them)."""
    ea, q = 4e8, 2e5
    ring = _ring(ea=ea, foundation=(0.0, 0.0, 0.0, 0.0))
    phi = np.linspace(0, 2 * np.pi, 4096, endpoint=False)
    p = q * R * (2 * np.pi / phi.size)
    g = cr.influence(-phi, ring, 2048)[:, 0, 0]
    assert p * g.sum() == pytest.approx(q * R**2 / ea, rel=1e-9)
    n = _resultants_at(ring, [0.3], [(a, p, 0.0) for a in phi])[0]
    assert n[0] == pytest.approx(q * R, rel=1e-6)
    assert abs(n[1]) < 1e-6 * q * R * R


def test_roark_case15_own_weight():
    """Table 9.2 case 15 (thin ring on a point support at the bottom, weight w per length) as 1440 point
    loads: M_A = wR²/2 (top), M_B = 3wR²/2 (bottom), M_C = −(π/2 − 1)wR² (side), Roark's sign; the
    midpoint rule of the weight leaves 1.6e-6."""
    w = 50.0
    ring = _ring(ea=1e9 * EI / R**2)
    phi = np.linspace(0, 2 * np.pi, 1440, endpoint=False) + np.pi / 1440
    dl = w * R * 2 * np.pi / phi.size
    loads = [(a, -dl * np.sin(a), -dl * np.cos(a)) for a in phi]  # gravity −y: radial −sin, tangential −cos
    loads.append((-np.pi / 2, -2 * np.pi * R * w, 0.0))  # the support pushes up: inward radial at the bottom
    f = _resultants_at(ring, [np.pi / 2, -np.pi / 2 + 1e-9, 0.0], loads, 4096)
    m = -f[:, 1]
    assert m == pytest.approx([w * R**2 / 2, 1.5 * w * R**2, -(np.pi / 2 - 1) * w * R**2], rel=1e-5)


# -- out of plane: least work written here ---------------------------------------------------------
def _least_work_out_of_plane(loads, ei_o, gj, n_grid=4000):
    """Complementary energy of a free ring under self-equilibrated axial point forces (φ, P): the cut at
    θ = 0⁺ carries the redundants (F_z, M_x, M_y); each section's bending moment about e_r and torque about
    e_θ from the statics of the arc (0, θ); U minimised (linear least squares on its quadrature)."""
    th = (np.arange(n_grid) + 0.5) * 2 * np.pi / n_grid
    p = np.stack([R * np.cos(th), R * np.sin(th), 0 * th], -1)
    e_r = np.stack([np.cos(th), np.sin(th), 0 * th], -1)
    e_t = np.stack([-np.sin(th), np.cos(th), 0 * th], -1)
    z = np.array([0.0, 0.0, 1.0])
    m_load = np.zeros((n_grid, 3))
    for phi, f in loads:
        q = np.array([R * np.cos(phi), R * np.sin(phi), 0.0])
        inside = th > phi
        m_load[inside] += np.cross(q - p[inside], f * z)
    p0 = np.array([R, 0.0, 0.0])
    m_red = np.stack(
        [np.cross(p0 - p, z), np.tile([1.0, 0, 0], (n_grid, 1)), np.tile([0, 1.0, 0], (n_grid, 1))], -1
    )
    w = np.sqrt(R * 2 * np.pi / n_grid)
    rows = []
    for e, k in ((e_r, ei_o), (e_t, gj)):
        rows.append(
            (
                np.einsum("ni,nij->nj", e, m_red) * w / np.sqrt(k),
                np.einsum("ni,ni->n", e, m_load) * w / np.sqrt(k),
            )
        )
    a = np.concatenate([r[0] for r in rows])
    b = np.concatenate([r[1] for r in rows])
    x = np.linalg.lstsq(a, -b, rcond=None)[0]
    res = a @ x + b
    return 0.5 * float(res @ res)


@pytest.mark.parametrize("ratio", [0.5, 2.0])
def test_out_of_plane_alternating_forces_against_least_work(ratio):
    """Four axial forces ±P alternating at 90°: Clapeyron's ½ΣP u from the ring's out-of-plane kernels
    equals the least-work energy of bending and torsion (the independent solution above)."""
    ei_o, gj = 800.0, 800.0 * ratio
    ring = cr.RingRigidities(R, 1e9 * EI / R**2, EI, ei_o, gj)
    angles = np.array([0.0, np.pi / 2, np.pi, 1.5 * np.pi])
    forces = W * np.array([1.0, -1.0, 1.0, -1.0])
    g = cr.influence(np.subtract.outer(angles, angles).ravel(), ring, 1024)[:, 2, 2].reshape(4, 4)
    u = g @ forces
    assert 0.5 * forces @ u == pytest.approx(
        _least_work_out_of_plane(list(zip(angles, forces, strict=True)), ei_o, gj), rel=2e-4
    )
    assert u == pytest.approx(u[0] * np.array([1, -1, 1, -1]), rel=1e-12)


def test_uniform_twisting_moment_everts_the_ring():
    """A uniform twisting moment m [N·m/m] rotates every section by φ = mR²/EI_out (eversion: the energy
    πEI_out φ²/R against the work 2πR m φ; Timoshenko & Goodier 1951, rings under distributed couples)."""
    ei_o, m = 900.0, 40.0
    ring = cr.RingRigidities(R, 1e9 * EI / R**2, EI, ei_o, 300.0, (0.0, 0.0, 1e12, 0.0))
    phi = np.linspace(0, 2 * np.pi, 4096, endpoint=False)  # more loads than harmonics: only n = 0
    g = cr.influence(-phi, ring, 1024)[:, 3, 3]
    assert m * R * (2 * np.pi / phi.size) * g.sum() == pytest.approx(m * R**2 / ei_o, rel=1e-6)


def test_rigid_body_motions_strain_nothing():
    """The six rigid motions are in the null space of every harmonic's stiffness (the kinematics): a free
    ring's compliance has no rigid part, a held one is regular; free_modes names what the foundation
    leaves."""
    ring = cr.RingRigidities(R, 1e6, EI, 700.0, 400.0)
    assert cr.free_modes(ring).all()
    held = cr.RingRigidities(R, 1e6, EI, 700.0, 400.0, (1e8, 0.0, 1e8, 0.0))
    assert list(cr.free_modes(held)) == [False, False, True, False, False, False]
    g_in, g_out = cr.harmonic_compliance(ring, 8)
    assert g_in[1] @ np.array([1.0, -1.0]) == pytest.approx(
        [0.0, 0.0], abs=1e-18
    )  # translation: w = cos, v = −sin
    assert g_out[1] @ np.array([-R, 1.0]) == pytest.approx([0.0, 0.0], abs=1e-18)  # tilt: u = −R cos, φ = cos
    assert g_out[0, 0, 0] == 0.0 and g_in[0, 1, 1] == 0.0


def test_reciprocity_and_series_tails():
    """G(Δ)ᵀ = G(−Δ) (Maxwell–Betti); the closed-form tails make N = 256 agree with N = 8192."""
    ring = cr.RingRigidities(R, 3e7, EI, 700.0, 400.0, (2e7, 1e6, 5e6, 10.0, -2e3))
    d = np.linspace(0.05, 6.2, 11)
    g = cr.influence(d, ring, 256)
    assert g == pytest.approx(np.swapaxes(cr.influence(-d, ring, 256), 1, 2), rel=1e-10, abs=1e-22)
    fine = cr.influence(d, ring, 8192)
    assert np.abs(g - fine).max() <= 1e-7 * np.abs(fine).max()
    n = np.arange(41.0)
    coef = np.where(n > 0, 1.0 / np.maximum(n, 1.0) ** 2, 0.0)  # exactly 1/n²: the tail is exact
    t = np.array([0.3, 2.0, 5.5])
    assert cr.fourier_series(coef, t) == pytest.approx(np.pi**2 / 6 - np.pi * t / 2 + t * t / 4, rel=1e-13)
