"""Stresses below Hertz contacts (physics/contact/subsurface*.py) against closed forms, published values and
independent implementations written here (point-force solutions integrated over the contact)."""

import numpy as np
import pytest
from scipy.optimize import brentq

from bearingkit.errors import InputError
from bearingkit.physics.contact import subsurface as ss
from bearingkit.physics.contact import subsurface_line as sl

NU = 0.3


def _argmax(values, z):
    i = int(np.argmax(values))
    return float(values[i]), float(z[i])


# --------------------------------------------------------------------------- published values (1 %)
def test_circular_contact_max_shear_031_p0_at_048_a():
    """Johnson (1985) §3.4 / Fig. 3.9: ν = 0.3, τ_max = 0.31 p₀ at z = 0.48 a below the centre."""
    z = np.linspace(0.0, 2.0, 20001)
    tau, depth = _argmax(ss.tresca(*ss.axis_stresses(z, 1.0, 1.0, 1.0, NU)), z)
    assert tau == pytest.approx(0.31, rel=0.01)
    assert depth == pytest.approx(0.48, rel=0.01)


def test_line_contact_max_shear_0300_p0_at_0786_b():
    """Johnson (1985) §4.2: line contact τ_max = 0.300 p₀ at z = 0.786 b (0.30 p₀ at 0.78 b in handbooks)."""
    z = np.linspace(0.0, 2.0, 4001)
    s = sl.line_stresses(0.0, z, 1.0, 1.0, NU)
    tau, depth = _argmax(ss.tresca(s.sigma_y, s.sigma_x, s.sigma_z, s.tau_xz), z)
    assert tau == pytest.approx(0.300, rel=0.01)
    assert depth == pytest.approx(0.786, rel=0.01)
    _vm, tr = sl.line_stresses_over_position(z[::10], 1.0, 1.0, NU)
    assert tr.max() == pytest.approx(0.300, rel=0.01)  # without traction the maximum is on the axis


def test_line_contact_orthogonal_shear_025_p0_at_05_b():
    """Line contact orthogonal shear amplitude 0.25 p₀ at z = 0.5 b (x = ±0.866 b) — Johnson (1985) §4.2
    [from memory]; Lundberg & Palmgren's formula below gives the same in its b/a → 0 limit."""
    z = np.linspace(0.0, 1.5, 1501)
    tau, depth = _argmax(sl.line_orthogonal_shear_amplitude(z, 1.0, 1.0), z)
    assert tau == pytest.approx(0.25, rel=0.01)
    assert depth == pytest.approx(0.5, rel=0.01)


def _lundberg_palmgren(ratio):
    """τ₀/p₀ and z₀/b of Lundberg & Palmgren (1947) (Harris & Kotzalas 2007), b/a = √((t²−1)(2t−1))."""
    t = brentq(lambda t: np.sqrt((t * t - 1.0) * (2.0 * t - 1.0)) - ratio, 1.0, 10.0)
    return np.sqrt(2.0 * t - 1.0) / (2.0 * t * (t + 1.0)), 1.0 / ((t + 1.0) * np.sqrt(2.0 * t - 1.0))


@pytest.mark.parametrize("ratio", [1e-4, 0.1, 0.3, 0.6, 1.0])
def test_point_orthogonal_shear_amplitude_matches_lundberg_palmgren(ratio):
    tau0, z0 = _lundberg_palmgren(ratio)
    b = ratio
    z = np.linspace(0.01, 1.0, 991) * b
    tau, depth = _argmax(ss.orthogonal_shear_amplitude(z, 1.0, b, 1.0), z)
    assert tau == pytest.approx(tau0, rel=1e-3)
    assert depth / b == pytest.approx(z0, rel=0.01)


# --------------------------------------------------------------------------- closed forms
def test_circular_axis_equals_johnson_eq_345():
    z = np.linspace(0.0, 4.0, 81)
    s = ss.axis_stresses(z, 2.0, 2.0, 3.0, NU)
    zeta = np.maximum(z / 2.0, 1e-12)
    sr = 3.0 * (-(1 + NU) * (1 - zeta * np.arctan(1 / zeta)) + 0.5 / (1 + zeta**2))
    np.testing.assert_allclose(s.sigma_x, sr, atol=1e-12)
    np.testing.assert_allclose(s.sigma_y, sr, atol=1e-12)
    np.testing.assert_allclose(s.sigma_z, -3.0 / (1 + zeta**2), atol=1e-12)


def test_ellipse_surface_centre_and_axis_normal_stress():
    """σ_z = −p₀ / √((1+z²/a²)(1+z²/b²)) on the axis; at the surface σ_x = −p₀ [2ν + (1−2ν) b/(a+b)]."""
    a, b, z = 3.0, 1.0, np.linspace(0.0, 5.0, 11)
    s = ss.axis_stresses(z, a, b, 2.0, NU)
    np.testing.assert_allclose(s.sigma_z, -2.0 / np.sqrt((1 + (z / a) ** 2) * (1 + (z / b) ** 2)), rtol=1e-12)
    assert s.sigma_x[0] == pytest.approx(-2.0 * (2 * NU + (1 - 2 * NU) * b / (a + b)), rel=1e-8)
    assert s.sigma_y[0] == pytest.approx(-2.0 * (2 * NU + (1 - 2 * NU) * a / (a + b)), rel=1e-8)


def test_long_ellipse_tends_to_line_contact():
    z = np.linspace(0.0, 3.0, 31)
    pt = ss.axis_stresses(z, 1000.0, 1.0, 1.0, NU)
    ln = sl.line_stresses(0.0, z, 1.0, 1.0, NU)
    np.testing.assert_allclose(pt.sigma_y, ln.sigma_x, atol=2e-3)  # rolling direction
    np.testing.assert_allclose(pt.sigma_z, ln.sigma_z, atol=2e-3)
    np.testing.assert_allclose(pt.sigma_x, ln.sigma_y, atol=2e-3)  # plane strain σ = ν(σ_x + σ_z)


def test_long_ellipse_with_traction_tends_to_line_contact():
    for y, z in [(0.0, 0.02), (0.5, 0.3), (-0.8, 0.6), (1.5, 0.05)]:
        pt = ss.plane_stresses(y, z, 1000.0, 1.0, 1.0, NU, traction=0.3)
        ln = sl.line_stresses(y, z, 1.0, 1.0, NU, traction=0.3)
        np.testing.assert_allclose(
            [pt.sigma_y, pt.sigma_z, pt.tau_yz], [ln.sigma_x, ln.sigma_z, ln.tau_xz], atol=1e-3
        )


# --------------------------------------------------------------------------- independent implementations
def _ellipse_quadrature(a, b, n=300):
    """Nodes (ξ, η) and weights × p/p₀ of ∬ p dA over the ellipse (s = sin τ removes the √ at the edge)."""
    t, w = np.polynomial.legendre.leggauss(n)
    tau, wt = (t + 1) * np.pi / 4, w * np.pi / 4
    th, wth = (t + 1) * np.pi, w * np.pi
    tt, hh = np.meshgrid(tau, th, indexing="ij")
    s = np.sin(tt)
    weight = a * b * s * np.cos(tt) ** 2 * np.outer(wt, wth)
    return a * s * np.cos(hh), b * s * np.sin(hh), weight


def _displacement(x, y, z, force, nu):
    """Boussinesq (normal force into the body) and Cerruti (force along +y) point-force displacements × 4πG
    (Johnson 1985 §3.2, Love 1929); independent of the module, which uses potentials of the whole load."""
    r = np.sqrt(x * x + y * y + z * z)
    d, c = r + z, 1 - 2 * nu
    if force == "normal":
        ux = x * z / r**3 - c * x / (r * d)
        uy = y * z / r**3 - c * y / (r * d)
        uz = z * z / r**3 + 2 * (1 - nu) / r
    else:
        ux = x * y / r**3 - c * x * y / (r * d * d)
        uy = 1 / r + y * y / r**3 + c * (1 / d - y * y / (r * d * d))
        uz = y * z / r**3 + c * y / (r * d)
    return np.array([ux, uy, uz])


def _stress_by_integration(y0, z0, a, b, force, nu=NU, h=1e-4):
    """Stress at (0, y0, z0) from finite differences of the point-force displacement integrated over the
    contact (G = 1/(4π), p₀ = 1)."""
    xi, eta, wq = _ellipse_quadrature(a, b)
    grad = np.zeros((3, 3))
    for j in range(3):
        e = np.zeros(3)
        e[j] = h
        plus = _displacement(-xi + e[0], y0 - eta + e[1], z0 + e[2], force, nu)
        minus = _displacement(-xi - e[0], y0 - eta - e[1], z0 - e[2], force, nu)
        grad[:, j] = ((plus - minus) * wq).sum(axis=(1, 2)) / (2 * h)
    g = 1 / (4 * np.pi)  # shear modulus G chosen so that u = kernel / (4πG) = kernel
    eps = 0.5 * (grad + grad.T)
    lam = 2 * g * nu / (1 - 2 * nu)
    return 2 * g * eps + lam * np.trace(eps) * np.eye(3)


@pytest.mark.parametrize("y0,z0", [(0.15, 0.09), (0.36, 0.06), (0.27, 0.3)])
def test_plane_field_equals_integrated_point_force_solutions(y0, z0):
    a, b = 1.0, 0.3
    normal = _stress_by_integration(y0, z0, a, b, "normal")
    got = ss.plane_stresses(y0, z0, a, b, 1.0, NU)
    np.testing.assert_allclose(
        [got.sigma_x, got.sigma_y, got.sigma_z, got.tau_yz],
        [normal[0, 0], normal[1, 1], normal[2, 2], normal[1, 2]],
        atol=2e-5,
    )
    tangential = _stress_by_integration(y0, z0, a, b, "tangential")
    with_q = ss.plane_stresses(y0, z0, a, b, 1.0, NU, traction=0.25)
    np.testing.assert_allclose(
        [with_q.sigma_x - got.sigma_x, with_q.sigma_y - got.sigma_y, with_q.sigma_z - got.sigma_z],
        0.25 * np.array([tangential[0, 0], tangential[1, 1], tangential[2, 2]]),
        atol=2e-5,
    )
    assert with_q.tau_yz - got.tau_yz == pytest.approx(0.25 * tangential[1, 2], abs=2e-5)


_STRIP_NODES = np.polynomial.legendre.leggauss(600)


def _flamant(x, z, b, mu):
    """Line contact: Flamant's point-force solution integrated over the strip (Johnson 1985 eq. 2.15-2.16)."""
    t, w = _STRIP_NODES
    th, wt = t * np.pi / 2, w * np.pi / 2
    s, ds, p = b * np.sin(th), b * np.cos(th) * wt, np.cos(th)
    dx = x - s
    r4 = (dx * dx + z * z) ** 2
    k = -2 / np.pi
    sx = np.sum(ds * k * (p * dx * dx * z + mu * p * dx**3) / r4)
    sz = np.sum(ds * k * (p * z**3 + mu * p * dx * z * z) / r4)
    txz = np.sum(ds * k * (p * dx * z * z + mu * p * dx * dx * z) / r4)
    return sx, sz, txz


@pytest.mark.parametrize("mu", [0.0, 0.3, -0.2])
def test_line_field_equals_integrated_flamant(mu):
    for x, z in [(0.0, 0.5), (0.5, 0.3), (-0.8, 0.6), (1.5, 0.4), (-1.2, 0.2)]:
        got = sl.line_stresses(x, z, 1.0, 1.0, NU, traction=mu)
        np.testing.assert_allclose([got.sigma_x, got.sigma_z, got.tau_xz], _flamant(x, z, 1.0, mu), atol=1e-6)
        assert got.sigma_y == pytest.approx(NU * (got.sigma_x + got.sigma_z))


# --------------------------------------------------------------------------- symmetry, superposition
def test_plane_field_symmetry_in_rolling_direction():
    y, z = np.array([0.1, 0.4, 0.9]), np.array([0.2, 0.5, 0.1])
    plus, minus = ss.plane_stresses(y, z, 1.0, 0.4, 1.0, NU), ss.plane_stresses(-y, z, 1.0, 0.4, 1.0, NU)
    np.testing.assert_allclose(plus.sigma_x, minus.sigma_x, rtol=1e-12)
    np.testing.assert_allclose(plus.sigma_y, minus.sigma_y, rtol=1e-12)
    np.testing.assert_allclose(plus.sigma_z, minus.sigma_z, rtol=1e-12)
    np.testing.assert_allclose(plus.tau_yz, -minus.tau_yz, rtol=1e-12)


def test_exchanging_axes_exchanges_stresses_on_the_axis():
    z = np.linspace(0.0, 2.0, 21)
    s1, s2 = ss.axis_stresses(z, 2.0, 0.5, 1.0, NU), ss.axis_stresses(z, 0.5, 2.0, 1.0, NU)
    np.testing.assert_allclose(s1.sigma_x, s2.sigma_y, rtol=1e-12)
    np.testing.assert_allclose(s1.sigma_z, s2.sigma_z, rtol=1e-12)


def test_superposition_linear_in_pressure_and_traction():
    y, z = np.array([0.0, 0.3, -0.7]), np.array([0.1, 0.4, 0.2])
    base = np.array(ss.plane_stresses(y, z, 1.0, 0.5, 1.0, NU))
    np.testing.assert_allclose(np.array(ss.plane_stresses(y, z, 1.0, 0.5, 2.5, NU)), 2.5 * base, rtol=1e-12)
    q1 = np.array(ss.plane_stresses(y, z, 1.0, 0.5, 1.0, NU, 0.1)) - base
    q2 = np.array(ss.plane_stresses(y, z, 1.0, 0.5, 1.0, NU, 0.3)) - base
    np.testing.assert_allclose(q2, 3.0 * q1, rtol=1e-10, atol=1e-14)
    l0 = np.array(sl.line_stresses(y, z, 0.5, 1.0, NU))
    l1 = np.array(sl.line_stresses(y, z, 0.5, 1.0, NU, 0.2)) - l0
    l2 = np.array(sl.line_stresses(y, z, 0.5, 1.0, NU, -0.4)) - l0
    np.testing.assert_allclose(l2, -2.0 * l1, rtol=1e-10, atol=1e-14)


def test_plane_on_axis_equals_closed_form():
    z = np.array([0.0, 0.003, 0.03, 0.3, 1.0, 3.0])
    axis, plane = ss.axis_stresses(z, 1.0, 0.3, 1.0, NU), ss.plane_stresses(0.0, z, 1.0, 0.3, 1.0, NU)
    for k in range(3):
        np.testing.assert_allclose(plane[k], axis[k], atol=1e-10)
    np.testing.assert_allclose(plane.tau_yz, 0.0, atol=1e-14)


def test_depth_profile_with_traction_is_searched_off_axis():
    """Traction raises the von Mises maximum and moves it towards the surface (Hamilton 1983 trend)."""
    z = np.linspace(0.0, 2.0, 81)
    dry = ss.depth_profile(z, 1.0, 1.0, 1.0, NU)
    wet = ss.depth_profile(z, 1.0, 1.0, 1.0, NU, traction=0.1)
    assert wet.von_mises.max() > dry.von_mises.max()
    np.testing.assert_allclose(dry.von_mises.max(), 0.62, rtol=0.01)  # = 2 τ_max of the circle
    lwet = sl.line_depth_profile(z, 1.0, 1.0, NU, traction=0.3)
    assert z[np.argmax(lwet.von_mises)] < z[np.argmax(sl.line_depth_profile(z, 1.0, 1.0, NU).von_mises)]


def test_bad_input_one_line():
    with pytest.raises(InputError, match="semi_minor"):
        ss.axis_stresses([0.1], 1.0, -1.0, 1.0, NU)
    with pytest.raises(InputError, match="depth"):
        sl.line_stresses(0.0, -0.1, 1.0, 1.0, NU)
    with pytest.raises(InputError, match="poisson_ratio"):
        ss.plane_stresses(0.0, 0.1, 1.0, 1.0, 1.0, 0.5)


def test_frictionless_profiles_on_the_axis_hold_the_maxima_over_position():
    """Line: the axis von Mises is the largest over x at every depth; point: off-axis values only near the
    surface exceed the axis (≤ 0.035 p₀ for a circle), never the subsurface maximum."""
    z = np.linspace(0.0, 4.0, 41)
    vm_x, _ = sl.line_stresses_over_position(z, 1.0, 1.0, NU)
    np.testing.assert_allclose(sl.line_depth_profile(z, 1.0, 1.0, NU).von_mises, vm_x, atol=1e-12)
    axis = ss.depth_profile(z, 1.0, 1.0, 1.0, NU)
    searched = ss.depth_profile(z, 1.0, 1.0, 1.0, NU, traction=1e-12)
    assert np.max(searched.von_mises - axis.von_mises) < 0.036
    assert searched.von_mises.max() == pytest.approx(axis.von_mises.max(), rel=1e-6)
    deep = z >= 0.3
    np.testing.assert_allclose(searched.von_mises[deep], axis.von_mises[deep], atol=1e-6)
