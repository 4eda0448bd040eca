"""Thin-ring stress resultants against Roark's ring cases, a least-work (Castigliano) solution, the
Fourier series and the deflection of thin_ring.

References: Roark & Young (2012), Table 9.2 — case 1 (two equal and opposite radial loads), case 2 (two
equal and opposite forces W along a chord at ±θ from A; M_A, M_C, N_A, V_A as reproduced by
engineersedge.com, "Circular Ring Analysis Roarks Formulas 2"), case 15 (ring on a point support under
its own weight; M_A = wR²/2, M_B = 3wR²/2, M_C = −(π/2 − 1)wR², N_A = wR/2 for a thin ring, recalled
[from memory] and re-derived below by least work). Roark's M is positive for tension on the INNER
fibre, bearingkit's for tension on the outer fibre: M_Roark = −M. Tangential point loads and the
uniform pressure over an arc are checked against the least-work solution of the free ring
(Castigliano's theorem with the redundants M₀, N₀, V₀ at a cut, bending energy only), written here
independently of the library's modal kernels. Tolerance 0.1 % as the issue asks.
"""

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.physics.structure import thin_ring
from bearingkit.physics.structure import thin_ring_forces as trf

R, W = 0.2, 1000.0
N_SERIES = np.arange(2, 400001, dtype=float)


# --- an independent reference: least work on the free ring --------------------------------------------
def _castigliano(theta_eval, radius, point_forces=(), line_loads=(), n_grid=1500):
    """M, N, V of a free ring under self-equilibrated loads by least work (cut at θ = cut).

    point_forces: (φ, F_x, F_y); line_loads: (a, b, f) with f(φ) -> (q_x, q_y) [N/m] on a < φ < b
    (vectorised in φ). The energy integral is a midpoint rule over n_grid points: M² is piecewise smooth,
    so its error is O((2π/n_grid)²) ~ 2e-5 relative, far inside the 0.1 % of the tests.
    """
    cut = 1e-3  # away from every load of the tests
    gl_x, gl_w = np.polynomial.legendre.leggauss(48)

    def statics(x):  # loads on (cut, x): force sum and moment about P(x)
        p = radius * np.array([np.cos(x), np.sin(x)])
        f, m = np.zeros(2), 0.0
        for phi, fx, fy in point_forces:
            phi = cut + np.mod(phi - cut, 2 * np.pi)
            if phi < x:
                r = radius * np.array([np.cos(phi), np.sin(phi)]) - p
                f += (fx, fy)
                m += r[0] * fy - r[1] * fx
        for a, b, fun in line_loads:
            start = cut + np.mod(a - cut, 2 * np.pi)
            end = start + (b - a)
            pieces = [(start, min(end, cut + 2 * np.pi))]
            if end > cut + 2 * np.pi:  # the arc wraps past the cut
                pieces.append((cut, end - 2 * np.pi))
            for lo, hi in pieces:
                hi = min(hi, x)
                if hi <= lo:
                    continue
                ph = 0.5 * (hi - lo) * gl_x + 0.5 * (hi + lo)
                q = np.stack([np.broadcast_to(c, ph.shape) for c in fun(ph)], -1)
                r = radius * np.stack([np.cos(ph), np.sin(ph)], -1) - p
                w = 0.5 * (hi - lo) * gl_w * radius
                f += (q * w[:, None]).sum(0)
                m += np.sum((r[:, 0] * q[:, 1] - r[:, 1] * q[:, 0]) * w)
        return f, m

    def resultants(x, red):
        m0, n0, v0 = red
        f0 = n0 * np.array([-np.sin(cut), np.cos(cut)]) + v0 * np.array([np.cos(cut), np.sin(cut)])
        r0 = radius * (np.array([np.cos(cut), np.sin(cut)]) - np.array([np.cos(x), np.sin(x)]))
        fl, ml = statics(x)
        m = m0 + (r0[0] * f0[1] - r0[1] * f0[0]) - ml
        fi = f0 - fl
        return m, fi @ np.array([-np.sin(x), np.cos(x)]), fi @ np.array([np.cos(x), np.sin(x)])

    grid = cut + (np.arange(n_grid) + 0.5) * 2 * np.pi / n_grid
    base = np.array([resultants(x, (0, 0, 0))[0] for x in grid])
    cols = [np.array([resultants(x, e)[0] for x in grid]) - base for e in np.eye(3)]
    a = np.array([[ci @ cj for cj in cols] for ci in cols])
    red = np.linalg.lstsq(a, -np.array([ci @ base for ci in cols]), rcond=None)[0]
    theta = cut + np.mod(np.asarray(theta_eval) - cut, 2 * np.pi)
    return np.array([resultants(x, red) for x in theta]).T


THETA = np.array([0.31, 0.9, 1.75, 2.6, 3.3, 4.1, 4.9, 5.8])


def _close(ours, ref, scale):
    assert np.max(np.abs(np.asarray(ours) - np.asarray(ref))) <= 1e-3 * scale


# --- kernels ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("theta", [0.0, 0.4, 1.3, np.pi, 4.0, 6.0])
@pytest.mark.parametrize("beta", [0.0, 1e-3, 0.5, 37.0, 2.0e4])
def test_moment_kernel_equals_its_series(theta, beta):
    m = N_SERIES**2 - 1
    series = np.sum(m * np.cos(N_SERIES * theta) / (m * m + beta))
    # the series' tail is bounded by Σ_{n>N} 1/n² < 1/N = 2.5e-6 (terms ~ cos nθ/n²)
    assert trf.moment_kernel(theta, beta) == pytest.approx(series, abs=3e-6)


@pytest.mark.parametrize("beta", [0.0, 1e-3, 0.5, 37.0, 2.0e4])
def test_moment_kernel_slope_is_the_derivative(beta):
    t, h = np.array([0.2, 1.1, 2.9, 3.6, 5.5]), 1e-6
    fd = (trf.moment_kernel(t + h, beta) - trf.moment_kernel(t - h, beta)) / (2 * h)
    assert trf.moment_kernel_slope(t, beta) == pytest.approx(fd, abs=1e-7)
    # the jump of the shear kernel across the load in +θ: −π (V′ = N − R q_r: V drops by Q at Q)
    assert trf.moment_kernel_slope(1e-12, beta) - trf.moment_kernel_slope(-1e-12, beta) == pytest.approx(
        -np.pi, abs=1e-6
    )


@pytest.mark.parametrize("k_h", [0.0, 3.0e7, 6.9e9])
def test_moment_is_curvature_change_of_the_deflection(k_h):
    """M = −EI (w″ + w)/R² with w from thin_ring.radial_deflection (finite differences, away from loads)."""
    ei = 2.0e3
    phi, q = [0.3, 2.0, 4.4], [[1500.0, -700.0, 300.0]]
    t, h = np.array([1.0, 3.1, 5.5]), 1e-4
    w = [thin_ring.radial_deflection(t + d, phi, q, R, ei, housing_stiffness=k_h)[0] for d in (-h, 0, h)]
    m_fd = -ei * ((w[0] - 2 * w[1] + w[2]) / h**2 + w[1]) / R**2
    m = trf.ring_forces(t, R, radial=(phi, q), flexural_rigidity=ei, housing_stiffness=k_h).moment[0]
    assert m == pytest.approx(m_fd, rel=1e-5, abs=1e-6 * W * R)


# --- Roark's ring cases --------------------------------------------------------------------------------
def test_roark_case1_two_opposite_radial_loads():
    """Table 9.2 case 1 (thin ring): M at the loads WR/π, at 90° −(1/2 − 1/π)WR (Roark's sign),
    N = 0 at the loads and −W/2 at 90°; beside the inward load at θ = 0 the shear is ±W/2 (the element
    at the load is in equilibrium: V(0⁺) − V(0⁻) = W)."""
    f = trf.ring_forces([1e-12, np.pi / 2, -1e-12], R, radial=([0.0, np.pi], [-W, -W]), support="free")
    m_roark = -f.moment[0]
    assert m_roark[0] == pytest.approx(W * R / np.pi, rel=1e-3)
    assert m_roark[1] == pytest.approx(-(0.5 - 1 / np.pi) * W * R, rel=1e-3)
    assert f.normal_force[0] == pytest.approx([0.0, -W / 2, 0.0], abs=1e-3 * W)
    assert f.shear_force[0, [0, 2]] == pytest.approx([W / 2, -W / 2], rel=1e-3)


@pytest.mark.parametrize("theta", [np.pi / 6, np.pi / 3, np.pi / 2, 2 * np.pi / 3, 5 * np.pi / 6])
def test_roark_case2_two_forces_along_a_chord(theta):
    """Table 9.2 case 2, thin ring (k2 = 1): two equal and opposite forces W along the horizontal chord at
    x = ±θ from the top A (x clockwise), pressing the ring together:
    M_A = −(WR/π)[(π − θ)(1 − c) − s(1 − c)], M_C = −(WR/π)[θ(1 + c) − s(1 + c)] (C at the bottom),
    N_A = −(W/π)(π − θ + sc), V_A = 0 (s = sin θ, c = cos θ). The forces are not radial: this checks the
    radial and the tangential point-load kernels together."""
    a1, a2 = np.pi / 2 - theta, np.pi / 2 + theta  # bearingkit angles of x = +θ, −θ
    radial = ([a1, a2], [-W * np.cos(a1), W * np.cos(a2)])
    tangential = ([a1, a2], [W * np.sin(a1), -W * np.sin(a2)])
    f = trf.ring_forces([np.pi / 2, -np.pi / 2], R, radial=radial, tangential=tangential, support="free")
    s, c = np.sin(theta), np.cos(theta)
    m_a = -W * R / np.pi * ((np.pi - theta) * (1 - c) - s * (1 - c))
    m_c = -W * R / np.pi * (theta * (1 + c) - s * (1 + c))
    n_a = -W / np.pi * (np.pi - theta + s * c)
    assert -f.moment[0] == pytest.approx([m_a, m_c], rel=1e-3, abs=1e-6 * W * R)
    assert f.normal_force[0, 0] == pytest.approx(n_a, rel=1e-3)
    assert f.shear_force[0, 0] == pytest.approx(0.0, abs=1e-9 * W)


def test_roark_case15_own_weight():
    """Table 9.2 case 15 (thin ring on a point support at the bottom B, weight w per unit length): Roark's
    M_A = wR²/2 (top), M_B = 3wR²/2, M_C = −(π/2 − 1)wR² (side), N_A = wR/2; and the whole ring against
    least work."""
    w = 50.0
    f = trf.own_weight_forces([np.pi / 2, -np.pi / 2, 0.0], w, R)
    m_roark = -f.moment[0]
    assert m_roark == pytest.approx([w * R**2 / 2, 1.5 * w * R**2, -(np.pi / 2 - 1) * w * R**2], rel=1e-3)
    assert f.normal_force[0, 0] == pytest.approx(w * R / 2, rel=1e-3)
    ref = _castigliano(
        THETA, R, [(-np.pi / 2, 0.0, 2 * np.pi * R * w)], [(-np.pi, np.pi, lambda p: (0.0, -w))]
    )
    f = trf.own_weight_forces(THETA, w, R)
    for ours, theirs, scale in zip(f, ref, (w * R**2, w * R, w * R), strict=True):
        _close(ours[0], theirs, 1.5 * scale)


# --- tangential loads and arc pressure against least work ----------------------------------------------
def test_tangential_point_loads_against_least_work():
    """Two opposite pairs of tangential forces (zero net force and moment)."""
    phi = np.array([0.4, 0.4 + np.pi, 2.0, 2.0 + np.pi])
    p = np.array([W, W, -W, -W])
    et = np.stack([-np.sin(phi), np.cos(phi)], -1) * p[:, None]
    ref = _castigliano(THETA, R, [(a, fx, fy) for a, (fx, fy) in zip(phi, et, strict=True)])
    f = trf.ring_forces(THETA, R, tangential=(phi, p), support="free")
    for ours, theirs, scale in zip(f, ref, (W * R, W, W), strict=True):
        _close(ours[0], theirs, scale)


def test_mixed_point_loads_against_least_work():
    """A radial and a tangential force balanced by two radial reactions (solved for balance)."""
    q1, p1, phi_q, phi_p = 800.0, 500.0, 0.7, 2.3
    f_load = q1 * np.array([np.cos(phi_q), np.sin(phi_q)]) + p1 * np.array([-np.sin(phi_p), np.cos(phi_p)])
    # reactions: radial forces at 3.6 and 5.2 with the torque p1·R balanced by a tangential force at 4.4
    phi_r = np.array([3.6, 5.2])
    e = np.stack([np.cos(phi_r), np.sin(phi_r)], -1)
    t_react = -p1  # tangential reaction at 4.4 (torque)
    f_t = t_react * np.array([-np.sin(4.4), np.cos(4.4)])
    q_r = np.linalg.solve(e.T, -(f_load + f_t))
    radial = (np.r_[phi_q, phi_r], np.r_[q1, q_r])
    tangential = ([phi_p, 4.4], [p1, t_react])
    f = trf.ring_forces(THETA, R, radial=radial, tangential=tangential, support="free")
    pts = [(phi_q, *(q1 * np.array([np.cos(phi_q), np.sin(phi_q)])))]
    pts += [(a, *(q * np.array([np.cos(a), np.sin(a)]))) for a, q in zip(phi_r, q_r, strict=True)]
    pts += [(phi_p, *(p1 * np.array([-np.sin(phi_p), np.cos(phi_p)]))), (4.4, *f_t)]
    ref = _castigliano(THETA, R, pts)
    for ours, theirs, scale in zip(f, ref, (W * R, W, W), strict=True):
        _close(ours[0], theirs, scale)


@pytest.mark.parametrize("arc", [(0.5, 1.6), (2.0, 2.0 + np.pi), (-0.3, 4.5)])
def test_arc_pressure_against_least_work(arc):
    """Uniform radial pressure p over an arc, balanced by a radial point force opposite its bisector."""
    a, b = arc
    p = 3000.0
    mid, force = (a + b) / 2, 2 * p * R * np.sin((b - a) / 2)
    f = trf.ring_forces(THETA, R, radial=([mid + np.pi], [force]), arcs=([a], [b], [p]), support="free")
    ref = _castigliano(
        THETA,
        R,
        [(mid + np.pi, -force * np.cos(mid), -force * np.sin(mid))],
        [(a, b, lambda ph: (p * np.cos(ph), p * np.sin(ph)))],
    )
    scale = p * R * (b - a)
    for ours, theirs, s in zip(f, ref, (scale * R, scale, scale), strict=True):
        _close(ours[0], theirs, s)


def test_full_circle_pressure_is_pure_hoop_tension():
    """p all round: M = V = 0, N = pR (free ring; the housing model hands the n = 0 load to the housing)."""
    p = 2500.0
    f = trf.ring_forces(THETA, R, arcs=([0.0], [2 * np.pi], [p]), support="free")
    assert f.moment == pytest.approx(0.0, abs=1e-9 * p * R * R)
    assert f.shear_force == pytest.approx(0.0, abs=1e-9 * p * R)
    assert f.normal_force == pytest.approx(p * R, rel=1e-12)
    h = trf.ring_forces(THETA, R, arcs=([0.0], [2 * np.pi], [p]))
    assert h.normal_force == pytest.approx(0.0, abs=1e-9 * p * R)


# --- the housed ring: equilibrium with the housing and Winkler reactions --------------------------------
@pytest.mark.parametrize("k_h", [0.0, 6.9e9])
def test_housed_ring_equilibrium(k_h):
    """M′ = RV and V′ = N − R q_r with q_r = housing reaction (n = 0, 1 harmonics) − k_h w, off the load."""
    ei, phi, q = 2.0e3, 0.0, 1200.0
    t, h = np.array([0.8, 2.2, 3.9, 5.1]), 1e-5
    kw = dict(radial=([phi], [q]), flexural_rigidity=ei, housing_stiffness=k_h)
    f = [trf.ring_forces(t + d, R, **kw) for d in (-h, 0.0, h)]
    assert (f[2].moment - f[0].moment)[0] / (2 * h) == pytest.approx(R * f[1].shear_force[0], rel=1e-6)
    w = thin_ring.radial_deflection(t, [phi], [[q]], R, ei, housing_stiffness=k_h)[0]
    q_r = -q * (1 + 2 * np.cos(t - phi)) / (2 * np.pi * R) - k_h * w
    dv = (f[2].shear_force - f[0].shear_force)[0] / (2 * h)
    assert dv == pytest.approx(f[1].normal_force[0] - R * q_r, rel=1e-5, abs=1e-6 * q)


@pytest.mark.parametrize("k_h", [0.0, 6.9e9])
def test_housed_ring_equilibrium_tangential(k_h):
    """A tangential force P: M′ = RV and N′ = −V − R q_t with the housing's q_t = −P(1 + 2 cos t)/(2πR)
    (the Winkler foundation acts radially only), off the load."""
    ei, phi, p = 2.0e3, 0.5, 900.0
    t, h = np.array([0.9, 2.2, 3.9, 5.1]), 1e-5
    kw = dict(tangential=([phi], [p]), flexural_rigidity=ei, housing_stiffness=k_h)
    f = [trf.ring_forces(t + d, R, **kw) for d in (-h, 0.0, h)]
    assert (f[2].moment - f[0].moment)[0] / (2 * h) == pytest.approx(R * f[1].shear_force[0], rel=1e-6)
    q_t = -p * (1 + 2 * np.cos(t - phi)) / (2 * np.pi * R)
    dn = (f[2].normal_force - f[0].normal_force)[0] / (2 * h)
    assert dn == pytest.approx(-f[1].shear_force[0] - R * q_t, rel=1e-5, abs=1e-6 * p)


def test_batched_cases_and_superposition():
    phi = [0.2, 1.9, 4.0]
    loads = np.array([[100.0, -40.0, 10.0], [-5.0, 300.0, 70.0]])
    f = trf.ring_forces(THETA, R, radial=(phi, loads), flexural_rigidity=500.0, housing_stiffness=1e7)
    for c in range(2):
        one = trf.ring_forces(
            THETA, R, radial=(phi, loads[c]), flexural_rigidity=500.0, housing_stiffness=1e7
        )
        assert f.moment[c] == pytest.approx(one.moment[0], rel=1e-12)
    parts = [
        trf.ring_forces(THETA, R, radial=([a], loads[:, [k]]), flexural_rigidity=500.0, housing_stiffness=1e7)
        for k, a in enumerate(phi)
    ]
    total = parts[0] + parts[1] + parts[2]
    assert total.normal_force == pytest.approx(f.normal_force, rel=1e-12, abs=1e-9)


def test_fibre_stress():
    inner, outer = trf.fibre_stress(
        moment=[0.0, 10.0],
        normal_force=[500.0, 0.0],
        area=1e-4,
        area_moment=2e-9,
        inner_fibre=0.004,
        outer_fibre=0.006,
    )
    assert inner == pytest.approx([5.0e6, -10.0 * 0.004 / 2e-9])
    assert outer == pytest.approx([5.0e6, 10.0 * 0.006 / 2e-9])  # M > 0: outer fibre in tension


def test_bad_input():
    with pytest.raises(InputError, match="self-equilibrated"):
        trf.ring_forces(THETA, R, radial=([0.0], [W]), support="free")
    with pytest.raises(InputError, match="housing_stiffness"):
        trf.ring_forces(THETA, R, radial=([0.0, np.pi], [W, W]), support="free", housing_stiffness=1e6)
    with pytest.raises(InputError, match="support"):
        trf.ring_forces(THETA, R, radial=([0.0], [W]), support="glued")
    with pytest.raises(InputError, match="arc end"):
        trf.ring_forces(THETA, R, arcs=([1.0], [0.5], [10.0]))
    with pytest.raises(InputError, match="at least one"):
        trf.ring_forces(THETA, R)
