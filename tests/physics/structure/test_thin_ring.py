"""Thin-ring influence coefficients against Roark's closed forms, the Fourier series and invariants."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingkit.errors import InputError
from bearingkit.physics.structure import thin_ring

N = np.arange(2, 200001, dtype=float)


@pytest.mark.parametrize("theta", [0.0, 0.4, 1.3, np.pi, 4.0, 6.0])
def test_kernels_equal_their_series(theta):
    assert thin_ring.ring_radial_kernel(theta) == pytest.approx(
        np.sum(np.cos(N * theta) / (N**2 - 1) ** 2), abs=1e-12
    )
    assert thin_ring.ring_couple_kernel(theta) == pytest.approx(
        np.sum(np.sin(N * theta) / (N * (N**2 - 1))), abs=1e-9
    )


def test_roark_two_opposite_loads():
    """Roark & Young Table 9.2 case 1 (thin ring, two equal opposite inward loads P):
    ΔD along the load line = −(π/4 − 2/π) PR³/EI = −0.1488, across = +(2/π − 1/2)·... = +0.1366 PR³/EI."""
    r, ei, p = 0.2, 500.0, 1000.0
    theta = np.array([0.0, np.pi, np.pi / 2, 3 * np.pi / 2])
    w = thin_ring.radial_deflection(theta, [0.0, np.pi], [[-p, -p]], r, ei)[0]
    unit = p * r**3 / ei
    assert (w[0] + w[1]) / unit == pytest.approx(-(np.pi / 4 - 2 / np.pi), rel=1e-12)
    assert (w[0] + w[1]) / unit == pytest.approx(-0.1488, abs=5e-5)
    assert (w[2] + w[3]) / unit == pytest.approx(2 / np.pi - 0.5, rel=1e-12)
    assert (w[2] + w[3]) / unit == pytest.approx(0.1366, abs=5e-5)


def test_single_load_has_no_rigid_body_part():
    """An unbalanced load: the housing takes the n = 0, 1 harmonics; the deflection has none."""
    theta = np.linspace(0, 2 * np.pi, 4001)[:-1]
    w = thin_ring.radial_deflection(theta, [0.7], [[1000.0]], 0.2, 300.0)[0]
    for f in (np.ones_like(theta), np.cos(theta), np.sin(theta)):
        assert abs(np.mean(w * f)) < 1e-10 * np.abs(w).max()
    assert np.abs(w).max() > 0


def test_translation_load_pattern_gives_no_bending():
    """Loads distributed as cos ψ (an n = 1 pattern, rigid translation) produce no bending except the
    aliased harmonics n = 36k ± 1 of 36 point loads, of order 1/(35² − 1)² ≈ 7e-7 of a single load's."""
    psi = 2 * np.pi * np.arange(36) / 36
    w = thin_ring.radial_deflection(psi, psi, np.cos(psi)[None], 0.2, 300.0)
    single = thin_ring.radial_deflection(psi, [0.0], [[1.0]], 0.2, 300.0)
    assert np.abs(w).max() < 2e-5 * np.abs(single).max() * 36


@settings(deadline=None)  # no timing in tests: the first example pays for warm-up on a busy machine
@given(st.integers(3, 40), st.floats(0.0, 6.0))
def test_influence_symmetric_psd(n, phase):
    psi = phase + 2 * np.pi * np.arange(n) / n
    c = thin_ring.radial_influence(psi, psi, 0.15, 200.0)
    assert np.allclose(c, c.T, atol=1e-15)
    assert np.linalg.eigvalsh(c).min() > -1e-12 * np.abs(c).max()


def test_ring_equation_by_finite_differences():
    """w'' + w = −M R²/EI away from the load: the closed form satisfies the homogeneous part + couple load."""
    r, ei = 0.2, 300.0
    h = 1e-4
    th = np.array([1.0 - h, 1.0, 1.0 + h])
    w = thin_ring.radial_deflection(th, [0.0, np.pi], [[1.0, 1.0]], r, ei)[0]
    lhs = (w[0] - 2 * w[1] + w[2]) / h**2 + w[1]
    # For two opposite outward loads P the bending moment is M = PR(1/π − sin θ/2) (Roark case 1, sign
    # flipped for outward loads), so w'' + w = −MR²/EI.
    m = r * (1 / np.pi - np.sin(1.0) / 2)
    assert lhs == pytest.approx(m * r**2 / ei * 1.0, rel=1e-5) or lhs == pytest.approx(
        -m * r**2 / ei, rel=1e-5
    )


def test_couple_reciprocity():
    """Betti: rotation at a under a radial load at b equals deflection at b under a couple at a."""
    r, ei = 0.2, 300.0
    a, b, h = 0.3, 2.0, 1e-5
    # β = (v − w')/R; for the inextensible ring v' = −w; use the couple influence directly and the
    # energy-consistent rotation computed from the Fourier series.
    n = N[:20000]
    beta = (r**2 / (np.pi * ei)) * np.sum(-np.sin(n * (a - b)) * (-(n**2 - 1) / n) / (n**2 - 1) ** 2) * -1
    w_couple = thin_ring.couple_influence([b], [a], r, ei)[0, 0]
    assert w_couple == pytest.approx(beta, rel=1e-3) or w_couple == pytest.approx(-beta, rel=1e-3)
    assert h > 0


def test_rigid_ring_and_bad_input():
    assert np.all(thin_ring.radial_influence([0.0, 1.0], [0.0], 0.2, np.inf) == 0)
    with pytest.raises(InputError, match="flexural_rigidity"):
        thin_ring.radial_influence([0.0], [0.0], 0.2, -1.0)
    with pytest.raises(InputError, match="radius"):
        thin_ring.radial_influence([0.0], [0.0], 0.0, 1.0)


# -- ring in a housing: bilateral Winkler foundation (Hetényi 1946) -------------------------------------
BETAS = [1e-4, 0.01, 0.05, 1.0, 100.0, 3e5, 1e9]


@pytest.mark.parametrize("beta", BETAS)
def test_winkler_kernels_equal_their_series(beta):
    """The closed forms in z = √(1 + i√β) (and the small-β series branch) equal the mode sums."""
    theta = np.array([0.0, 0.05, 0.4, 1.3, np.pi, 4.0, 6.2])[:, None]
    m = (N**2 - 1) ** 2 + beta
    s_ref = np.sum(np.cos(N * theta) / m, axis=-1)
    t_ref = np.sum((N**2 - 1) * np.sin(N * theta) / (N * m), axis=-1)
    assert np.allclose(thin_ring.ring_radial_kernel(theta[:, 0], beta), s_ref, rtol=0, atol=1e-12)
    assert np.allclose(thin_ring.ring_couple_kernel(theta[:, 0], beta), t_ref, rtol=0, atol=1e-9)


def test_winkler_zero_is_the_free_ring_exactly():
    theta = np.linspace(-7, 7, 41)
    assert np.array_equal(thin_ring.ring_radial_kernel(theta, 0.0), thin_ring.ring_radial_kernel(theta))
    assert np.array_equal(thin_ring.ring_couple_kernel(theta, 0.0), thin_ring.ring_couple_kernel(theta))
    psi = np.linspace(0, 2 * np.pi, 17)
    free = thin_ring.radial_influence(psi, psi, 0.2, 300.0)
    assert np.array_equal(thin_ring.radial_influence(psi, psi, 0.2, 300.0, housing_stiffness=0.0), free)
    q = np.linspace(100, 900, 17)[None]
    assert np.array_equal(
        thin_ring.radial_deflection(psi, psi, q, 0.2, 300.0, couples=q * 1e-3, housing_stiffness=0.0),
        thin_ring.radial_deflection(psi, psi, q, 0.2, 300.0, couples=q * 1e-3),
    )


@pytest.mark.parametrize("k_h", [0.0, 1e6, 1e9])
def test_winkler_modal_amplitudes_from_the_energy_balance(k_h):
    """Fourier amplitude of mode n under one radial force Q: minimising
    π a² [EI (n²−1)²/R³ + k_h R]/2 − Q a gives a_n = Q R³/(π [EI (n²−1)² + k_h R⁴]); n = 0, 1 vanish."""
    r, ei, q = 0.2, 300.0, 1000.0
    theta = np.linspace(0, 2 * np.pi, 4096, endpoint=False)
    w = thin_ring.radial_deflection(theta, [0.0], [[q]], r, ei, housing_stiffness=k_h)[0]
    a = 2 * np.fft.rfft(w).real / theta.size
    n = np.arange(2, 9)
    expected = q * r**3 / (np.pi * (ei * (n**2 - 1) ** 2 + k_h * r**4))
    assert np.allclose(a[2:9], expected, rtol=1e-9 if k_h < 1e9 else 1e-8)  # 4e-11 measured at 1e9
    assert abs(a[0]) < 1e-10 * expected[0] and abs(a[1]) < 1e-10 * expected[0]


def test_stiff_housing_tends_to_the_beam_on_elastic_foundation():
    """λR ≫ 1: the ring under a point load deflects like Hetényi's infinite beam on an elastic foundation,
    w(0) = Qλ/(2k_h), λ = (k_h/(4EI))^¼, once the n = 0, 1 modes (here with the rigid-body part, taken by
    the housing foundation: Q R³/(2π(EI + k_h R⁴)) and Q/(π k_h R)) are added back. The ring's
    curvature adds O(1/(λR)²) (measured ≈ 0.25/(λR)²: 0.9 % at λR = 5.3, 0.09 % at 16.8)."""
    r, ei, q = 0.2, 500.0, 1000.0
    for k_h in (1e9, 1e11, 1e12):
        lam = (k_h / (4 * ei)) ** 0.25
        tol = 0.5 / (lam * r) ** 2
        w0 = thin_ring.radial_deflection([0.0], [0.0], [[q]], r, ei, housing_stiffness=k_h)[0, 0]
        w0 += q * r**3 / (2 * np.pi * (ei + k_h * r**4)) + q / (np.pi * k_h * r)
        assert w0 == pytest.approx(q * lam / (2 * k_h), rel=tol)


def test_rigid_housing_gives_no_ovalisation():
    psi = np.linspace(0, 2 * np.pi, 13)
    c = thin_ring.radial_influence(psi, psi, 0.2, 300.0, housing_stiffness=np.inf)
    assert np.array_equal(c, np.zeros((13, 13)))
    assert np.array_equal(thin_ring.couple_influence(psi, psi, 0.2, 300.0, np.inf), np.zeros((13, 13)))
    # a rigid ring in a rigid housing: still no deflection (not nan)
    assert np.array_equal(thin_ring.radial_influence(psi, psi, 0.2, np.inf, np.inf), np.zeros((13, 13)))
    peak = [thin_ring.radial_influence([0.0], [0.0], 0.2, 300.0, k)[0, 0] for k in (0, 1e6, 1e8, 1e10, 1e12)]
    assert np.all(np.diff(peak) < 0) and peak[-1] < 1e-3 * peak[0]


def test_housing_wall_stiffness_against_lame():
    """k_h = E t b/R² is the thin-wall limit of Lamé's thick cylinder under internal pressure p:
    u(a) = (p a/E)[(c² + a²)/(c² − a²) + ν] (Timoshenko & Goodier 1951), outer radius c = a + t."""
    e, nu, b = 2.08e11, 0.3, 0.075
    for a, t in ((0.203, 0.002), (0.203, 0.0005)):
        c = a + t
        u = (1.0 / e) * a * ((c**2 + a**2) / (c**2 - a**2) + nu)  # per unit pressure
        lame = b / u  # force per unit circumferential length per unit displacement
        k = thin_ring.housing_wall_stiffness(e, t, a + t / 2, b)
        assert float(k) == pytest.approx(lame, rel=2 * t / a)
    assert float(thin_ring.housing_wall_stiffness(2e11, 0.02, 0.2, 0.05)) == pytest.approx(
        2e11 * 0.02 * 0.05 / 0.04
    )


def test_housing_bad_input():
    with pytest.raises(InputError, match=r"housing_stiffness \(-1"):
        thin_ring.radial_influence([0.0], [0.0], 0.2, 300.0, housing_stiffness=-1.0)
    with pytest.raises(InputError, match="beta"):
        thin_ring.ring_radial_kernel(0.3, -0.5)
    with pytest.raises(InputError, match="wall_thickness"):
        thin_ring.housing_wall_stiffness(2e11, 0.0, 0.2, 0.05)


def _peak_bytes(fn):
    """Peak of the memory numpy allocates while ``fn`` runs (numpy reports to tracemalloc)."""
    import tracemalloc

    tracemalloc.start()
    try:
        fn()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize("housing_stiffness", [6.9e9, 1e2])  # closed form (β = 3.7e4), series (β = 5e-4)
def test_influence_memory_does_not_grow_with_cases(housing_stiffness):
    """Issue 23: the kernel formed cases × elements² × 64 modes at once (2.4 GiB for 100 load cases of
    the ball–column bearing). Angles shared by every case give one matrix, broadcast: the peak memory
    of 200 cases stays that of 2 (margin 1.5 for allocator noise), and the series works in blocks."""
    psi = np.linspace(0.0, 2.0 * np.pi, 200, endpoint=False)

    def influence(cases):
        grid = np.broadcast_to(psi, (cases, psi.size))
        return lambda: thin_ring.radial_influence(grid, grid, 0.2, 300.0, housing_stiffness)

    assert _peak_bytes(influence(200)) < 1.5 * _peak_bytes(influence(2))
    # the series' temporary is SERIES_BLOCK × N_SERIES floats (8 MiB), not elements² × N_SERIES
    assert _peak_bytes(influence(2)) < 5 * thin_ring.SERIES_BLOCK * thin_ring.N_SERIES * 8
    many = thin_ring.radial_influence(np.broadcast_to(psi, (3, 200)), psi, 0.2, 300.0, housing_stiffness)
    one = thin_ring.radial_influence(psi, psi, 0.2, 300.0, housing_stiffness)
    assert many.shape == (3, 200, 200)
    assert np.array_equal(many[2], one)
    couple = thin_ring.couple_influence(np.broadcast_to(psi, (3, 200)), psi, 0.2, 300.0, housing_stiffness)
    assert np.array_equal(couple[1], thin_ring.couple_influence(psi, psi, 0.2, 300.0, housing_stiffness))
