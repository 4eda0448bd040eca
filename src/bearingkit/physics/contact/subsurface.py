"""Stresses below an elliptical Hertz contact: along the axis, in the rolling plane, orthogonal shear.

SI units (m, Pa). The contact centre is the origin; x runs along the semi-major axis a (across the
rolling direction: along a ball groove's profile), y along the semi-minor axis b (the rolling
direction), z into the body (depth, z ≥ 0). The Hertz pressure p = p₀ √(1 − x²/a² − y²/b²) acts on
the half-space z ≥ 0; stresses are positive in tension (the surface stress under the pressure is
σ_z = −p). Every function is a pure, vectorised numpy function broadcasting over its arguments.

Method
------
Boussinesq's potentials (Love 1929; Johnson 1985, §3.2): with V = ∬ p/ρ dA and H = ∬ p ln(ρ + z) dA
(ρ the distance from a loaded surface point; ∂H/∂z = V, both harmonic) the displacements are
4πG u_x = −z V_x − (1−2ν) H_x, 4πG u_z = 2(1−ν) V − z V_z, and Hooke's law gives

.. math::

    \\sigma_x = \\tfrac{1}{2\\pi}[2\\nu V_z - z V_{xx} - (1-2\\nu) H_{xx}],\\quad
    \\sigma_z = \\tfrac{1}{2\\pi}[V_z - z V_{zz}],\\quad
    \\tau_{yz} = -\\tfrac{1}{2\\pi} z V_{yz}

(σ_y, τ_xy, τ_xz alike). For the Hertz pressure V is the potential of a flattened ellipsoid
(Johnson 1985 eq. 3.57; Kellogg 1929),

.. math:: V = \\frac{\\pi a b p_0}{2}\\int_\\lambda^\\infty
          \\Bigl(1 - \\frac{x^2}{a^2+w} - \\frac{y^2}{b^2+w} - \\frac{z^2}{w}\\Bigr)
          \\frac{dw}{\\sqrt{(a^2+w)(b^2+w)w}},

λ the positive root of x²/(a²+λ) + y²/(b²+λ) + z²/λ = 1, and its second derivatives are Carlson's
symmetric elliptic integral R_D (Carlson 1995) plus a term at w = λ — in closed form everywhere. H's
derivatives follow from H_xx(z) = −∫_z^∞ V_xx dt; with the order of integration swapped this is one
integral over w, in closed form on the axis (:func:`axis_stresses`: Thomas & Hoersch 1930; Sackfield &
Hills 1983, in Carlson's form as Greenwood 2022 suggests) and by Gauss–Legendre quadrature in the plane
x = 0 (:func:`plane_stresses`, :data:`PLANE_NODES` nodes, ~1e-8 relative). H_yy = −V_z − H_xx (H is
harmonic and H_zz = V_z). The orthogonal shear τ_yz needs V only: :func:`orthogonal_shear` is closed form.

Checks (tests/physics/contact/test_subsurface.py): the circular contact's axis stresses of Johnson
(1985) eq. 3.45 to round-off (τ_max = 0.31 p₀ at z = 0.48 a for ν = 0.3); an elongated ellipse tends to the
line contact (:mod:`bearingkit.physics.contact.subsurface_line`); the amplitude of τ_yz and its depth
equal Lundberg & Palmgren's closed form (Harris & Kotzalas 2007) for every b/a; the plane field equals
a direct quadrature of Boussinesq's point-force solution.

Surface traction (a coefficient μ, q = μ p in +y): :mod:`bearingkit.physics.contact.subsurface_traction`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from bearingkit import checks, references
from bearingkit.physics.contact.elliptic import carlson_rf_rd

__all__ = [
    "PLANE_NODES",
    "REFERENCE_KEYS",
    "AxisStresses",
    "DepthProfile",
    "PlaneStresses",
    "axis_stresses",
    "depth_profile",
    "orthogonal_shear",
    "orthogonal_shear_amplitude",
    "plane_stresses",
    "principal_stresses",
    "tresca",
    "von_mises",
]

references.add(
    "thomas1930",
    "Thomas H.R., Hoersch V.A. (1930) Stresses due to the pressure of one elastic solid upon another. "
    "Univ. Illinois Eng. Exp. Station Bull. 212.",
)
references.add(
    "sackfield1983",
    "Sackfield A., Hills D.A. (1983) Some useful results in the classical Hertz contact problem. "
    "J. Strain Anal. 18(2):101-105.",
)
references.add(
    "greenwood2022",
    "Greenwood J.A. (2022) Stresses below elliptical Hertzian contacts, using Carlson elliptic integrals. "
    "J. Strain Anal. doi:10.1177/03093247211060288.",
)
references.add(
    "carlson1995",
    "Carlson B.C. (1995) Numerical computation of real or complex elliptic integrals. Numer. Algorithms "
    "10:13-26.",
)

#: Keys of :data:`bearingkit.references.REFERENCES` this module implements.
REFERENCE_KEYS = (
    "johnson1985",
    "thomas1930",
    "sackfield1983",
    "greenwood2022",
    "carlson1995",
    "lundberg1947",
)

#: Gauss–Legendre nodes of the H_xx integral in :func:`plane_stresses` (mapped to [λ, ∞)); 96 nodes give
#: ~1e-8 relative error down to z = 0.01 b (tests compare with the closed form on the axis).
PLANE_NODES = 96
#: Smallest depth used, as a fraction of the semi-minor axis [-]: z = 0 is replaced by it (the closed
#: forms hold in the limit; 1e-9 b changes no stress by more than ~1e-9 p₀).
_Z_FLOOR = 1.0e-9
#: Golden-section steps of the y search of the orthogonal-shear amplitude: the bracket shrinks 0.618³⁶
#: ≈ 3e-8 (the maximum of |τ_yz| at one depth to round-off).
_GOLDEN_STEPS = 36


class AxisStresses(NamedTuple):
    """Principal stresses on the contact axis x = y = 0 [Pa] (σ_x across, σ_y along rolling, σ_z depth)."""

    sigma_x: np.ndarray
    sigma_y: np.ndarray
    sigma_z: np.ndarray


class PlaneStresses(NamedTuple):
    """Stresses in the plane x = 0 (the rolling plane through the centre) [Pa]; τ_xy = τ_xz = 0 there."""

    sigma_x: np.ndarray
    sigma_y: np.ndarray
    sigma_z: np.ndarray
    tau_yz: np.ndarray


class DepthProfile(NamedTuple):
    """Per depth, the largest stresses over the rolling position [Pa] (the profiles a bearing check uses)."""

    von_mises: np.ndarray
    tresca: np.ndarray
    orthogonal_shear: np.ndarray


#: Samples of the rolling position y ∈ [−(2b + 2z), 2b + 2z] searched per depth when a traction moves the
#: maxima off the axis (:func:`depth_profile`), refined by a parabola.
TRACTION_SAMPLES = 161


def _check(semi_major, semi_minor, max_pressure, poisson_ratio):
    checks.positive("semi_major", semi_major, "m")
    checks.positive("semi_minor", semi_minor, "m")
    checks.non_negative("max_pressure", max_pressure, "Pa")
    checks.in_range("poisson_ratio", poisson_ratio, 0.0, 0.5, closed=False)


def _rd(x, y, z):
    """(2/3) R_D(x, y, z) = ∫₀^∞ dt / ((t+x)^½ (t+y)^½ (t+z)^{3/2})."""
    return (2.0 / 3.0) * carlson_rf_rd(x, y, z)[1]


def axis_stresses(depth, semi_major, semi_minor, max_pressure, poisson_ratio) -> AxisStresses:
    """Principal stresses on the axis below the centre of an elliptical Hertz contact (closed form).

    With A = a² + z², B = b² + z² and the integrals J = (2/3) R_D(A, B, z²), I_a = (2/3) R_D(B, z², A),
    K_a = 2 / (√A (√A + √B)) (I_b, K_b with a and b exchanged):

    .. math::

        \\sigma_x = \\frac{a b p_0}{2}\\,[2(1-\\nu) z I_a - (1-2\\nu) K_a - 2\\nu z J],\\qquad
        \\sigma_z = -\\frac{p_0\\, a b}{\\sqrt{A B}}

    At the surface σ_x = −p₀ [2ν + (1−2ν) b/(a+b)]; for a = b, σ_x = σ_y = p₀ [−(1+ν)(1 − (z/a)
    arctan(a/z)) + a²/(2(a²+z²))] (Johnson 1985 eq. 3.45).

    Parameters
    ----------
    depth : array_like
        z ≥ 0 [m].
    semi_major, semi_minor : array_like
        a (along x) and b (along y) [m], > 0 (either may be the larger: the formulas are symmetric).
    max_pressure : array_like
        p₀ [Pa], ≥ 0.
    poisson_ratio : array_like
        ν [-], 0 ≤ ν < 0.5.

    Returns
    -------
    AxisStresses
        σ_x, σ_y, σ_z [Pa] (broadcast shape).

    References
    ----------
    Thomas & Hoersch (1930); Sackfield & Hills (1983); Johnson (1985) §3.5, eq. 3.45; Greenwood (2022).
    """
    _check(semi_major, semi_minor, max_pressure, poisson_ratio)
    a, b = np.asarray(semi_major, float), np.asarray(semi_minor, float)
    p0, nu = np.asarray(max_pressure, float), np.asarray(poisson_ratio, float)
    checks.non_negative("depth", depth, "m")
    z = np.maximum(np.asarray(depth, float), _Z_FLOOR * np.minimum(a, b))
    aa, bb, zz = a * a + z * z, b * b + z * z, z * z
    sa, sb = np.sqrt(aa), np.sqrt(bb)
    zj = z * _rd(aa, bb, zz)
    ia, ib = _rd(bb, zz, aa), _rd(aa, zz, bb)
    ka, kb = 2.0 / (sa * (sa + sb)), 2.0 / (sb * (sa + sb))
    scale = 0.5 * a * b * p0
    sx = scale * (2.0 * (1.0 - nu) * z * ia - (1.0 - 2.0 * nu) * ka - 2.0 * nu * zj)
    sy = scale * (2.0 * (1.0 - nu) * z * ib - (1.0 - 2.0 * nu) * kb - 2.0 * nu * zj)
    sz = -p0 * a * b / (sa * sb)
    return AxisStresses(sx, sy, sz)


def _lambda_plane(y, z, b):
    """λ at x = 0: the positive root of y²/(b²+λ) + z²/λ = 1 (a quadratic)."""
    c = b * b - y * y - z * z
    root = np.sqrt(c * c + 4.0 * z * z * b * b)
    # the two algebraically equal forms, each free of cancellation on its side of c = 0
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(c > 0.0, 2.0 * z * z * b * b / (c + root), 0.5 * (root - c))


def _h_integrals(y, z, a, b, lam):
    """The w-integrals of H_xx, H_xxy and Ω_xxy at x = 0, each divided by π a b p₀ (module docstring).

    With f(w) = 1 / ((a²+w)^{3/2} (b²+w)^{1/2} w^{1/2}) and T(w) = √(w (1 − y²/(b²+w))) (the depth at which
    λ = w), swapping the order of the depth and w integrations gives

        H_xx = 2C ∫ f (T − z) dw,   H_xxy = 2C ∫ f T_y dw,   Ω_xxy = −2C ∫ f (T − z) T_y dw,

    C = π a b p₀ / 2, over w ∈ [λ, ∞), T_y = −y w / ((b²+w) T). Gauss–Legendre in u ∈ (0, 1) with
    w = λ + L (u/(1−u))², L = max(λ, b²): the integrands are smooth, vanish or stay finite at w = λ
    (T = z there) and decay as w⁻² or faster; the map spreads the nodes over both scales.
    """
    t, wt = np.polynomial.legendre.leggauss(PLANE_NODES)
    u, wu = 0.5 * (t + 1.0), 0.5 * wt
    s = u / (1.0 - u)
    scale = np.maximum(lam, b * b)[..., None]
    w = lam[..., None] + scale * s * s
    dw = wu * scale * 2.0 * s / (1.0 - u) ** 2
    yy, zz, bb, aa = y[..., None], z[..., None], b[..., None] ** 2, a[..., None] ** 2
    tw = np.sqrt(np.maximum(w * (bb + w - yy * yy) / (bb + w), 0.0))
    f = dw / ((aa + w) ** 1.5 * np.sqrt((bb + w) * w))
    with np.errstate(divide="ignore", invalid="ignore"):
        ty = np.where(tw > 0.0, -yy * w / ((bb + w) * tw), 0.0)
    gap = tw - zz
    return np.sum(f * gap, axis=-1), np.sum(f * ty, axis=-1), np.sum(f * gap * ty, axis=-1)


def _v_terms(y, z, a, b, lam):
    """(V_z, V_xx, V_yy, V_zz, V_yz, V_y) / C at x = 0, C = π a b p₀ / 2 (module docstring)."""
    al, bl = a * a + lam, b * b + lam
    g = 1.0 / np.sqrt(al * bl * lam)
    qy, qz = -2.0 * y / bl, -2.0 * z / lam
    qw = (y / bl) ** 2 + (z / lam) ** 2
    rd_z = _rd(al, bl, lam)
    v_z = -2.0 * z * rd_z
    v_xx = -2.0 * _rd(bl, lam, al)
    v_yy = -2.0 * _rd(al, lam, bl) + g * qy * qy / qw
    v_zz = -2.0 * rd_z + g * qz * qz / qw
    v_yz = g * qy * qz / qw
    v_y = -2.0 * y * _rd(al, lam, bl)
    return v_z, v_xx, v_yy, v_zz, v_yz, v_y


def plane_stresses(
    y, depth, semi_major, semi_minor, max_pressure, poisson_ratio, traction=0.0
) -> PlaneStresses:
    """Stresses in the rolling plane x = 0 below an elliptical Hertz contact, with surface traction.

    Normal pressure (Boussinesq; module docstring): σ_x, σ_y, σ_z and τ_yz from V's derivatives in closed
    form and H_xx by quadrature of one integral, H_yy = −V_z − H_xx. Traction q = μ p along +y (Cerruti's
    solution, Johnson 1985 §3.2, written with the potentials V, H and Ω = ∬ p (z ln(ρ+z) − ρ) dA,
    ∂Ω/∂z = H, all harmonic):

    .. math::

        \\sigma_x = \\tfrac{\\mu}{2\\pi}[2\\nu V_y - z H_{xxy} + 2\\nu\\Omega_{xxy}],\\quad
        \\sigma_y = \\tfrac{\\mu}{2\\pi}[2(1+\\nu) V_y - z H_{yyy} + 2\\nu\\Omega_{yyy}],\\quad
        \\sigma_z = -\\tfrac{\\mu}{2\\pi} z V_{yz},\\quad
        \\tau_{yz} = \\tfrac{\\mu}{2\\pi}[V_z - z V_{yy}]

    with H_yyy = −V_yz − H_xxy and Ω_yyy = −V_y − Ω_xxy (harmonic), H_xxy and Ω_xxy by the same quadrature
    (:func:`_h_integrals`). At x = 0 τ_xy = τ_xz = 0 (the field is even in x).

    Parameters
    ----------
    y : array_like
        Position along the rolling direction [m] (without traction σ is even in y, τ_yz odd).
    depth : array_like
        z ≥ 0 [m].
    semi_major, semi_minor, max_pressure, poisson_ratio
        As in :func:`axis_stresses`.
    traction : array_like
        μ = q/p [-], the surface traction along +y over the pressure (0: frictionless).

    Returns
    -------
    PlaneStresses
        σ_x, σ_y, σ_z, τ_yz [Pa].

    References
    ----------
    Love (1929); Johnson (1985) §3.2-3.5; Sackfield & Hills (1983); Hamilton (1983) for the circular
    sliding contact.
    """
    _check(semi_major, semi_minor, max_pressure, poisson_ratio)
    checks.non_negative("depth", depth, "m")
    checks.finite("y", y, "m")
    checks.finite("traction", traction)
    y, z, a, b, p0, nu, mu = np.broadcast_arrays(
        *(
            np.asarray(v, float)
            for v in (y, depth, semi_major, semi_minor, max_pressure, poisson_ratio, traction)
        )
    )
    z = np.maximum(z, _Z_FLOOR * np.minimum(a, b))
    lam = _lambda_plane(y, z, b)
    v_z, v_xx, v_yy, v_zz, v_yz, v_y = _v_terms(y, z, a, b, lam)
    i_h, i_hy, i_oy = _h_integrals(y, z, a, b, lam)
    h_xx, h_xxy, o_xxy = 2.0 * i_h, 2.0 * i_hy, -2.0 * i_oy
    h_yy = -v_z - h_xx
    c = 0.25 * a * b * p0  # C / (2π), C = π a b p₀ / 2
    sx = c * (2.0 * nu * v_z - z * v_xx - (1.0 - 2.0 * nu) * h_xx)
    sy = c * (2.0 * nu * v_z - z * v_yy - (1.0 - 2.0 * nu) * h_yy)
    sz = c * (v_z - z * v_zz)
    tyz = -c * z * v_yz
    if np.any(mu != 0.0):
        h_yyy, o_yyy = -v_yz - h_xxy, -v_y - o_xxy
        cq = c * mu
        sx = sx + cq * (2.0 * nu * v_y - z * h_xxy + 2.0 * nu * o_xxy)
        sy = sy + cq * (2.0 * (1.0 + nu) * v_y - z * h_yyy + 2.0 * nu * o_yyy)
        sz = sz - cq * z * v_yz
        tyz = tyz + cq * (v_z - z * v_yy)
    return PlaneStresses(sx, sy, sz, tyz)


def orthogonal_shear(y, depth, semi_major, semi_minor, max_pressure):
    """Orthogonal shear stress τ_yz in the rolling plane x = 0 [Pa] (closed form).

    .. math:: \\tau_{yz} = -\\frac{a b p_0}{4} \\frac{z}{\\sqrt{(a^2+\\lambda)(b^2+\\lambda)\\lambda}}
              \\frac{Q_y Q_z}{Q_w},\\quad Q_y = -\\frac{2y}{b^2+\\lambda},\\ Q_z = -\\frac{2z}{\\lambda},\\
              Q_w = \\frac{y^2}{(b^2+\\lambda)^2} + \\frac{z^2}{\\lambda^2}

    It does not depend on ν. Its amplitude over y at each depth is Lundberg & Palmgren's τ₀
    (:func:`orthogonal_shear_amplitude`).

    Parameters
    ----------
    y : array_like
        Position along the rolling direction [m].
    depth : array_like
        z ≥ 0 [m].
    semi_major, semi_minor : array_like
        a, b [m].
    max_pressure : array_like
        p₀ [Pa].
    """
    _check(semi_major, semi_minor, max_pressure, 0.3)
    checks.non_negative("depth", depth, "m")
    y, z, a, b, p0 = np.broadcast_arrays(
        *(np.asarray(v, float) for v in (y, depth, semi_major, semi_minor, max_pressure))
    )
    z = np.maximum(z, _Z_FLOOR * np.minimum(a, b))
    lam = _lambda_plane(y, z, b)
    bl = b * b + lam
    # V_yz = C g Q_y Q_z / Q_w (module docstring), without the R_D terms the other derivatives need
    qw = (y / bl) ** 2 + (z / lam) ** 2
    v_yz = 4.0 * y * z / (bl * lam * qw * np.sqrt((a * a + lam) * bl * lam))
    return -0.25 * a * b * p0 * z * v_yz


def orthogonal_shear_amplitude(depth, semi_major, semi_minor, max_pressure):
    """Amplitude τ₀(z) = max_y |τ_yz(0, y, z)| of the orthogonal shear at each depth [Pa].

    A rolling element passing over a raceway point reverses τ_yz (it is odd in y): the range is 2 τ₀.
    |τ_yz| rises from 0 at y = 0 to one peak and decays: a golden-section search over y ∈ [0, 2b + 2z]
    (:data:`_GOLDEN_STEPS` steps, vectorised over every depth and contact) finds it to ~1e-7 of the span.
    Lundberg & Palmgren's closed form of its maximum over depth: τ₀ = p₀ √(2t−1) / (2t(t+1)) at
    z₀ = b / ((t+1) √(2t−1)), with b/a = √((t²−1)(2t−1)) — 0.25 p₀ at 0.5 b for line contact, 0.214 p₀
    at 0.351 b for a circle (tests compare).

    Parameters
    ----------
    depth : array_like (..., N)
        z ≥ 0 [m].
    semi_major, semi_minor, max_pressure : array_like
        a, b [m], p₀ [Pa], broadcasting with ``depth``.

    Returns
    -------
    numpy.ndarray
        τ₀ [Pa], the broadcast shape.
    """
    z, a, b, p0 = np.broadcast_arrays(
        *(np.asarray(v, float) for v in (depth, semi_major, semi_minor, max_pressure))
    )
    return _golden_max(
        lambda y: np.abs(orthogonal_shear(y, z, a, b, p0)), np.zeros(z.shape), 2.0 * b + 2.0 * z
    )


def _golden_max(f, lo, hi):
    """Max of a unimodal f over [lo, hi] (arrays: one search per element), :data:`_GOLDEN_STEPS` steps."""
    g = 0.5 * (np.sqrt(5.0) - 1.0)
    c, d = hi - g * (hi - lo), lo + g * (hi - lo)
    fc, fd = f(c), f(d)
    for _ in range(_GOLDEN_STEPS):
        left = fc > fd  # the peak lies in [lo, d]: drop (d, hi]; else drop [lo, c)
        lo, hi = np.where(left, lo, c), np.where(left, d, hi)
        c, d = np.where(left, hi - g * (hi - lo), d), np.where(left, c, lo + g * (hi - lo))
        f_new = f(np.where(left, c, d))
        fc, fd = np.where(left, f_new, fd), np.where(left, fc, f_new)
    return np.maximum(fc, fd)


def _parabola_max(values, positions):
    """Max over the last axis, refined by the parabola through the best sample and its neighbours."""
    k = np.clip(np.argmax(values, axis=-1), 1, values.shape[-1] - 2)[..., None]
    f0, f1, f2 = (np.take_along_axis(values, k + d, axis=-1)[..., 0] for d in (-1, 0, 1))
    step = np.take_along_axis(positions, k + 1, axis=-1) - np.take_along_axis(positions, k, axis=-1)
    h = step[..., 0]
    den = f0 - 2.0 * f1 + f2
    with np.errstate(divide="ignore", invalid="ignore"):
        shift = np.where(den < 0.0, 0.5 * (f0 - f2) / den, 0.0)
    best = f1 - 0.25 * (f0 - f2) * shift
    best = np.where(np.isfinite(best) & (h > 0), best, f1)
    return np.maximum(best, values.max(axis=-1))


def principal_stresses(sigma_x, sigma_y, sigma_z, tau_yz=0.0):
    """Principal stresses σ₁ ≥ σ₂ ≥ σ₃ [Pa] (on a new last axis) of a state whose only shear is τ_yz.

    σ_x is principal; the (y, z) block has σ = (σ_y+σ_z)/2 ± √(((σ_y−σ_z)/2)² + τ_yz²).

    Parameters
    ----------
    sigma_x, sigma_y, sigma_z : array_like
        Normal stresses [Pa] (σ_x principal).
    tau_yz : array_like
        The only shear stress [Pa].
    """
    sx, sy, sz, t = np.broadcast_arrays(*(np.asarray(v, float) for v in (sigma_x, sigma_y, sigma_z, tau_yz)))
    mid, rad = 0.5 * (sy + sz), np.sqrt((0.5 * (sy - sz)) ** 2 + t * t)
    return np.sort(np.stack([sx, mid + rad, mid - rad], axis=-1), axis=-1)[..., ::-1]


def von_mises(sigma_x, sigma_y, sigma_z, tau_yz=0.0, tau_xz=0.0, tau_xy=0.0):
    """Von Mises equivalent stress [Pa].

    .. math:: \\sigma_{vM} = \\sqrt{\\tfrac12[(\\sigma_x-\\sigma_y)^2 + (\\sigma_y-\\sigma_z)^2
              + (\\sigma_z-\\sigma_x)^2] + 3(\\tau_{yz}^2 + \\tau_{xz}^2 + \\tau_{xy}^2)}

    Parameters
    ----------
    sigma_x, sigma_y, sigma_z : array_like
        Normal stresses [Pa].
    tau_yz, tau_xz, tau_xy : array_like
        Shear stresses [Pa].
    """
    sx, sy, sz = (np.asarray(v, float) for v in (sigma_x, sigma_y, sigma_z))
    shear = np.asarray(tau_yz, float) ** 2 + np.asarray(tau_xz, float) ** 2 + np.asarray(tau_xy, float) ** 2
    return np.sqrt(0.5 * ((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) + 3.0 * shear)


def tresca(sigma_x, sigma_y, sigma_z, tau_yz=0.0):
    """Maximum shear stress (σ₁ − σ₃)/2 [Pa] (Tresca) of a state whose only shear is τ_yz.

    Parameters
    ----------
    sigma_x, sigma_y, sigma_z : array_like
        Normal stresses [Pa] (σ_x principal).
    tau_yz : array_like
        The only shear stress [Pa].
    """
    p = principal_stresses(sigma_x, sigma_y, sigma_z, tau_yz)
    return 0.5 * (p[..., 0] - p[..., 2])


def depth_profile(depth, semi_major, semi_minor, max_pressure, poisson_ratio, traction=0.0) -> DepthProfile:
    """Von Mises, Tresca and orthogonal-shear amplitude at each depth below an elliptical contact [Pa].

    Without traction the von Mises and Tresca stresses are those on the axis below the contact centre
    (:func:`axis_stresses`, closed form), where their maxima over depth lie; closer to the surface than
    ~0.3 b the contact's edge can exceed the axis value (by up to 0.035 p₀ for a circle, none for a long
    ellipse), far below the subsurface maximum. The orthogonal shear is :func:`orthogonal_shear_amplitude`.
    With a traction μ ≠ 0 each depth is searched over y (:data:`TRACTION_SAMPLES` points of
    :func:`plane_stresses`, parabola-refined); the orthogonal shear is then half the range of τ_yz over y.

    Parameters
    ----------
    depth : array_like (..., N)
        z ≥ 0 [m].
    semi_major, semi_minor, max_pressure, poisson_ratio : array_like
        a, b [m], p₀ [Pa], ν [-], broadcasting with ``depth`` (give (..., 1) for per-contact values).
    traction : float
        μ [-] (one value).

    Returns
    -------
    DepthProfile
        max_y σ_vM, max_y (σ₁−σ₃)/2, τ₀ [Pa], the broadcast shape.
    """
    checks.finite("traction", traction)
    if float(traction) == 0.0:
        s = axis_stresses(depth, semi_major, semi_minor, max_pressure, poisson_ratio)
        return DepthProfile(
            von_mises(*s),
            tresca(*s),
            orthogonal_shear_amplitude(depth, semi_major, semi_minor, max_pressure),
        )
    z, a, b, p0, nu = np.broadcast_arrays(
        *(np.asarray(v, float) for v in (depth, semi_major, semi_minor, max_pressure, poisson_ratio))
    )
    ys = (2.0 * b + 2.0 * z)[..., None] * np.linspace(-1.0, 1.0, TRACTION_SAMPLES)
    s = plane_stresses(ys, z[..., None], a[..., None], b[..., None], p0[..., None], nu[..., None], traction)
    t = s.tau_yz
    return DepthProfile(
        _parabola_max(von_mises(*s), ys),
        _parabola_max(tresca(*s), ys),
        0.5 * (_parabola_max(t, ys) + _parabola_max(-t, ys)),
    )
