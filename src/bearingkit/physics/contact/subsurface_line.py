"""Stresses below a Hertz line contact (a roller or one roller slice), with surface traction (closed form).

SI units (m, Pa). Johnson's coordinates: x along the rolling direction, z into the body (depth), y along
the roller axis; the contact strip |x| ≤ b carries the Hertz pressure p = p₀ √(1 − x²/b²) and, with a
traction coefficient μ, the tangential traction q = μ p in +x (the traction the surface receives).
Plane strain: σ_y = ν (σ_x + σ_z). Stresses positive in tension. Vectorised numpy functions.

McEwen (1949) / Smith & Liu (1953) closed form (Johnson 1985 eq. 7.7 and 7.12 with the signs of this
module's traction): with m, n ≥ 0 given by

.. math::

    m^2 = \\tfrac12\\bigl[\\sqrt{(b^2-x^2+z^2)^2 + 4x^2z^2} + (b^2-x^2+z^2)\\bigr],\\quad
    n^2 = \\tfrac12\\bigl[\\sqrt{(b^2-x^2+z^2)^2 + 4x^2z^2} - (b^2-x^2+z^2)\\bigr],

n taking the sign of x, the normal pressure gives

.. math::

    \\sigma_x = -\\frac{p_0}{b}\\Bigl[m\\Bigl(1 + \\frac{z^2+n^2}{m^2+n^2}\\Bigr) - 2z\\Bigr],\\quad
    \\sigma_z = -\\frac{p_0}{b}\\, m\\Bigl(1 - \\frac{z^2+n^2}{m^2+n^2}\\Bigr),\\quad
    \\tau_{xz} = -\\frac{p_0}{b}\\, n\\,\\frac{m^2-z^2}{m^2+n^2}

and the traction q₀ = μ p₀

.. math::

    \\sigma_x = \\frac{q_0}{b}\\Bigl[n\\Bigl(2 - \\frac{z^2-m^2}{m^2+n^2}\\Bigr) - 2x\\Bigr],\\quad
    \\sigma_z = -\\frac{q_0}{b}\\, n\\,\\frac{m^2-z^2}{m^2+n^2},\\quad
    \\tau_{xz} = -\\frac{q_0}{b}\\Bigl[m\\Bigl(1 + \\frac{z^2+n^2}{m^2+n^2}\\Bigr) - 2z\\Bigr].

(The sign of τ_xz is that of Flamant's point-force solution integrated over the strip, which the tests do
independently.) Checks: τ_max = 0.300 p₀ at z = 0.786 b, the orthogonal shear amplitude 0.250 p₀ at
z = 0.500 b (x = ±0.866 b), σ_vM,max = 0.557 p₀ at 0.704 b for ν = 0.3 (Johnson 1985 §4.2, Fig. 4.5).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from bearingkit import checks, references
from bearingkit.physics.contact.subsurface import DepthProfile, _golden_max, _parabola_max, tresca, von_mises

__all__ = [
    "REFERENCE_KEYS",
    "LineStresses",
    "line_depth_profile",
    "line_orthogonal_shear_amplitude",
    "line_stresses",
    "line_stresses_over_position",
]

references.add(
    "mcewen1949",
    "McEwen E. (1949) Stresses in elastic cylinders in contact along a generatrix. Phil. Mag. 40:454-459.",
)
references.add(
    "smith1953",
    "Smith J.O., Liu C.K. (1953) Stresses due to tangential and normal loads on an elastic solid with "
    "application to some contact stress problems. J. Appl. Mech. 20:157-166.",
)

#: Keys of :data:`bearingkit.references.REFERENCES` this module implements.
REFERENCE_KEYS = ("mcewen1949", "smith1953", "johnson1985")

#: Samples over the rolling position x ∈ [−(2b + 2z), 2b + 2z] of the per-depth maxima
#: (:func:`line_stresses_over_position`, :func:`line_orthogonal_shear_amplitude`), refined by a parabola.
POSITION_SAMPLES = 401


class LineStresses(NamedTuple):
    """Stresses below a line contact [Pa]: σ_x (rolling), σ_y (roller axis, plane strain), σ_z, τ_xz."""

    sigma_x: np.ndarray
    sigma_y: np.ndarray
    sigma_z: np.ndarray
    tau_xz: np.ndarray


def _mn(x, z, b):
    c = b * b - x * x + z * z
    r = np.sqrt(c * c + 4.0 * x * x * z * z)
    m = np.sqrt(0.5 * (r + c))
    n = np.sign(x) * np.sqrt(np.maximum(0.5 * (r - c), 0.0))
    return m, n


def line_stresses(position, depth, half_width, max_pressure, poisson_ratio, traction=0.0) -> LineStresses:
    """Stress field below a Hertz line contact with surface traction q = μ p (module docstring).

    Parameters
    ----------
    position : array_like
        x along the rolling direction from the contact centre [m].
    depth : array_like
        z ≥ 0 [m].
    half_width : array_like
        Contact half-width b [m], > 0.
    max_pressure : array_like
        p₀ [Pa], ≥ 0.
    poisson_ratio : array_like
        ν [-] (plane strain σ_y), 0 ≤ ν < 0.5.
    traction : array_like
        μ = q/p [-] (0: frictionless; its sign is the direction of the traction along x).

    Returns
    -------
    LineStresses
        σ_x, σ_y, σ_z, τ_xz [Pa].

    References
    ----------
    McEwen (1949); Smith & Liu (1953); Johnson (1985) eq. 7.7, 7.12.
    """
    checks.positive("half_width", half_width, "m")
    checks.non_negative("max_pressure", max_pressure, "Pa")
    checks.in_range("poisson_ratio", poisson_ratio, 0.0, 0.5, closed=False)
    checks.non_negative("depth", depth, "m")
    checks.finite("traction", traction)
    x, z, b, p0, nu, mu = np.broadcast_arrays(
        *(np.asarray(v, float) for v in (position, depth, half_width, max_pressure, poisson_ratio, traction))
    )
    m, n = _mn(x, z, b)
    mn = m * m + n * n
    with np.errstate(invalid="ignore", divide="ignore"):
        r1 = np.where(mn > 0, (z * z + n * n) / mn, 0.0)
        r2 = np.where(mn > 0, (m * m - z * z) / mn, 0.0)
    k, q = p0 / b, mu * p0 / b
    sx = -k * (m * (1.0 + r1) - 2.0 * z) + q * (n * (2.0 + r2) - 2.0 * x)
    sz = -k * m * (1.0 - r1) - q * n * r2
    txz = -k * n * r2 - q * (m * (1.0 + r1) - 2.0 * z)
    return LineStresses(sx, nu * (sx + sz), sz, txz)


def _positions(depth, half_width):
    z, b = np.broadcast_arrays(np.asarray(depth, float), np.asarray(half_width, float))
    span = 2.0 * b + 2.0 * z
    return span[..., None] * np.linspace(-1.0, 1.0, POSITION_SAMPLES), z, b


def line_stresses_over_position(depth, half_width, max_pressure, poisson_ratio, traction=0.0):
    """Per depth, the largest von Mises and Tresca stress over the rolling position x [Pa].

    Without traction both lie on the axis x = 0; with traction they move ahead and towards the surface, so
    every depth is searched over x (:data:`POSITION_SAMPLES` points, refined by a parabola).

    Parameters
    ----------
    depth : array_like (..., N)
        z ≥ 0 [m].
    half_width, max_pressure, poisson_ratio, traction : array_like
        b [m], p₀ [Pa], ν [-], μ [-] (as in :func:`line_stresses`), broadcasting with ``depth``.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        max_x σ_vM(x, z), max_x τ_Tresca(x, z) [Pa], shape of ``depth`` broadcast with the contact.
    """
    xs, z, b = _positions(depth, half_width)
    p0 = np.asarray(max_pressure, float)[..., None] if np.ndim(max_pressure) else max_pressure
    nu = np.asarray(poisson_ratio, float)[..., None] if np.ndim(poisson_ratio) else poisson_ratio
    mu = np.asarray(traction, float)[..., None] if np.ndim(traction) else traction
    s = line_stresses(xs, z[..., None], b[..., None], p0, nu, mu)
    vm = von_mises(s.sigma_x, s.sigma_y, s.sigma_z, tau_xz=s.tau_xz)
    # (σ₁ − σ₃)/2 with the only shear in the (x, z) block: reuse tresca() with x and y swapped.
    tr = tresca(s.sigma_y, s.sigma_x, s.sigma_z, s.tau_xz)
    return _parabola_max(vm, xs), _parabola_max(tr, xs)


def line_orthogonal_shear_amplitude(depth, half_width, max_pressure, traction=0.0):
    """Half the range of the orthogonal shear τ_xz over the rolling position at each depth [Pa].

    (max_x τ_xz − min_x τ_xz)/2: without traction max_x |τ_xz| (0.25 p₀ at z = 0.5 b, x = ±0.866 b), found by
    a golden-section search over x ∈ [0, 2b + 2z] (|τ_xz| has one peak there); with traction by
    :data:`POSITION_SAMPLES` samples over ±(2b + 2z).

    Parameters
    ----------
    depth : array_like (..., N)
        z ≥ 0 [m].
    half_width, max_pressure, traction : array_like
        b [m], p₀ [Pa], μ [-], broadcasting with ``depth``.
    """
    if np.all(np.asarray(traction) == 0.0):
        z, b, p = np.broadcast_arrays(*(np.asarray(v, float) for v in (depth, half_width, max_pressure)))
        return _golden_max(
            lambda x: np.abs(line_stresses(x, z, b, p, 0.3).tau_xz), np.zeros(z.shape), 2.0 * b + 2.0 * z
        )
    xs, z, b = _positions(depth, half_width)
    p0 = np.asarray(max_pressure, float)[..., None] if np.ndim(max_pressure) else max_pressure
    mu = np.asarray(traction, float)[..., None] if np.ndim(traction) else traction
    t = line_stresses(xs, z[..., None], b[..., None], p0, 0.3, mu).tau_xz  # τ_xz does not depend on ν
    return 0.5 * (_parabola_max(t, xs) + _parabola_max(-t, xs))


def line_depth_profile(depth, half_width, max_pressure, poisson_ratio, traction=0.0) -> DepthProfile:
    """Von Mises, Tresca and orthogonal-shear amplitude at each depth below a line contact [Pa].

    With traction the maxima over the rolling position (:func:`line_stresses_over_position`); without, the
    axis values (the von Mises stress is largest there at every depth; the Tresca stress off the axis
    exceeds it by at most 0.005 p₀ near the surface). The orthogonal shear is half the range of τ_xz
    (:func:`line_orthogonal_shear_amplitude`). The same fields as the point contact's
    :func:`bearingkit.physics.contact.subsurface.depth_profile`.

    Parameters
    ----------
    depth : array_like (..., N)
        z ≥ 0 [m].
    half_width, max_pressure, poisson_ratio : array_like
        b [m], p₀ [Pa], ν [-], broadcasting with ``depth``.
    traction : array_like
        μ [-].
    """
    ortho = line_orthogonal_shear_amplitude(depth, half_width, max_pressure, traction)
    if np.all(np.asarray(traction) == 0.0):  # on the axis: the largest σ_vM over x at every depth (tests)
        s = line_stresses(0.0, depth, half_width, max_pressure, poisson_ratio)
        return DepthProfile(
            von_mises(s.sigma_x, s.sigma_y, s.sigma_z, tau_xz=s.tau_xz),
            tresca(s.sigma_y, s.sigma_x, s.sigma_z, s.tau_xz),
            ortho,
        )
    vm, tr = line_stresses_over_position(depth, half_width, max_pressure, poisson_ratio, traction)
    return DepthProfile(vm, tr, ortho)
