r"""Elliptic integrals in numpy: K, E and D = (K − E)/m for the Hertz contact, and Carlson's R_F, R_D.

Units: SI; every quantity here is dimensionless [1].

Why not ``scipy.special``: importing it costs ~0.3 s on this project's machines (scipy 1.17 loads its
array-API layer, which loads ``numpy.f2py`` and ``numpy.testing``), a third of a warm one-case
``bearingkit analyze`` (issue 42: < 1 s). Both methods agree with scipy to ~1e-15
(``tests/physics/contact/test_elliptic.py`` keeps scipy as the oracle).

- :func:`complete_integrals` (K, E, D of the contact ellipse): the arithmetic–geometric mean, 0.020 s
  against scipy's 0.062 s on 1.8·10⁵ arguments, 80 µs against 6 µs on 9 (numpy's cost per call).
- :func:`carlson_rf_rd` (the subsurface stresses' R_D of general arguments): Carlson's duplication
  (Carlson 1995; DLMF §19.36(i)): with λ = √x√y + √x√z + √y√z, (x, y, z) ← (x + λ, y + λ, z + λ)/4 until
  the spread of the arguments is small enough for the fifth-order series to reach the tolerance; R_D
  collects 3 Σ 4⁻ᵐ/(√z_m (z_m + λ_m)).

The two agree through DLMF 19.25.1 (p = 1 − m): K(m) = R_F(0, p, 1), E(m) = R_F(0, p, 1) − (m/3) R_D(0, p, 1)
(tested).

References: B. C. Carlson (1995), "Numerical computation of real or complex elliptic integrals",
Numerical Algorithms 10, 13–26; NIST DLMF §19.8, §19.25, §19.36; Abramowitz & Stegun (1964) §17.6.
"""

from __future__ import annotations

import numpy as np

#: Relative tolerance of the series (Carlson 1995: the error of the truncated series is below it).
TOLERANCE = 1e-16
#: Steps at most (a duplication divides the spread by 4, so 40 reach 4⁻⁴⁰ ≈ 1e-24 from any start; the
#: AGM converges quadratically, in 5–7).
MAX_DUPLICATIONS = 40


def carlson_rf_rd(x, y, z):
    r"""Carlson's symmetric integrals R_F(x, y, z) and R_D(x, y, z) [1] (x, y ≥ 0, z > 0, at most one of
    x, y zero), broadcast.

    Parameters
    ----------
    x, y, z : array_like [1]

    Returns
    -------
    (r_f, r_d) : ndarray
        .. math:: R_F = \tfrac12\int_0^\infty \frac{dt}{\sqrt{(t+x)(t+y)(t+z)}},\quad
                  R_D = \tfrac32\int_0^\infty \frac{dt}{\sqrt{(t+x)(t+y)}\,(t+z)^{3/2}}

    Notes
    -----
    Carlson (1995) duplication, both integrals from the same sequence; the loop runs until every element
    meets both stopping rules (Q_F = (3r)^{-1/6} max|A₀ − ·|, Q_D = (r/4)^{-1/6} max|A₀ − ·|,
    stop when 4⁻ⁿ Q < |Aₙ|), so it is a few vector steps for a whole batch (9 for 1e-12 ≤ p ≤ 1).
    """
    args = np.broadcast_arrays(*(np.asarray(v, float) for v in (x, y, z)))
    x, y, z = (np.array(a, dtype=float) for a in args)  # writable copies
    a0_f = (x + y + z) / 3.0
    a0_d = (x + y + 3.0 * z) / 5.0
    spread_f = np.maximum(np.abs(a0_f - x), np.maximum(np.abs(a0_f - y), np.abs(a0_f - z)))
    spread_d = np.maximum(np.abs(a0_d - x), np.maximum(np.abs(a0_d - y), np.abs(a0_d - z)))
    q_f = (3.0 * TOLERANCE) ** (-1.0 / 6.0) * spread_f
    q_d = (TOLERANCE / 4.0) ** (-1.0 / 6.0) * spread_d
    dx_f, dy_f = a0_f - x, a0_f - y  # A₀ − x, A₀ − y: the series' variables without cancellation
    dx_d, dy_d = a0_d - x, a0_d - y
    tail = np.zeros_like(x)
    scale = 1.0  # 4⁻ⁿ
    a_f, a_d = a0_f, a0_d
    for _ in range(MAX_DUPLICATIONS):
        if np.all((scale * q_f < np.abs(a_f)) & (scale * q_d < np.abs(a_d))):
            break
        sx, sy, sz = np.sqrt(x), np.sqrt(y), np.sqrt(z)
        lam = sx * sy + sx * sz + sy * sz
        tail += scale / (sz * (z + lam))
        scale *= 0.25
        x, y, z = 0.25 * (x + lam), 0.25 * (y + lam), 0.25 * (z + lam)
        a_f = (x + y + z) / 3.0
        a_d = (x + y + 3.0 * z) / 5.0
    # R_F: X, Y, Z with X + Y + Z = 0 (DLMF 19.36.1)
    big_x, big_y = scale * dx_f / a_f, scale * dy_f / a_f
    big_z = -(big_x + big_y)
    e2 = big_x * big_y - big_z * big_z
    e3 = big_x * big_y * big_z
    r_f = (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / np.sqrt(a_f)
    # R_D: X, Y, Z with X + Y + 3Z = 0 (DLMF 19.36.2)
    big_x, big_y = scale * dx_d / a_d, scale * dy_d / a_d
    big_z = -(big_x + big_y) / 3.0
    xy, zz = big_x * big_y, big_z * big_z
    e2 = xy - 6.0 * zz
    e3 = (3.0 * xy - 8.0 * zz) * big_z
    e4 = 3.0 * (xy - zz) * zz
    e5 = xy * zz * big_z
    series = (
        1.0
        - 3.0 * e2 / 14.0
        + e3 / 6.0
        + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0
    )
    r_d = scale * series / (a_d * np.sqrt(a_d)) + 3.0 * tail
    return r_f, r_d


def complete_integrals(p):
    r"""K, E and D = (K − E)/m of the complete elliptic integrals at parameter m = 1 − p [1].

    Parameters
    ----------
    p : array_like [1]
        The complementary parameter 1 − m (0 < p ≤ 1), given directly so that m → 1 (a long, thin
        contact ellipse) keeps its digits.

    Returns
    -------
    (K, E, D) : ndarray
        .. math:: K = \frac{\pi}{2\,\mathrm{AGM}(1, \sqrt{p})},\quad
                  D = K \sum_{n \ge 0} 2^{n-1} \frac{c_n^2}{m},\quad E = K - m D

    Notes
    -----
    The arithmetic–geometric mean (DLMF 19.8.1, 19.8.6; Abramowitz & Stegun 17.6): a₀ = 1, b₀ = √p,
    c₀² = m, a_{n+1} = (aₙ + bₙ)/2, b_{n+1} = √(aₙbₙ), c_{n+1} = cₙ²/(4a_{n+1}). The sum is carried as
    sₙ = cₙ²/m (s₀ = 1, s_{n+1} = sₙ² m/(16 a_{n+1}²)), so D has no cancellation as m → 0 and no
    division by m. Quadratic convergence: 5–7 vector steps for a batch down to p = 1e-14, three times
    faster than the duplication of :func:`carlson_rf_rd` (K, E, D agree with R_F(0, p, 1),
    R_F − (m/3)R_D and R_D/3 to ~1e-15).
    """
    p = np.asarray(p, float)
    m = 1.0 - p
    a, b = np.ones_like(p), np.sqrt(p)
    s = np.ones_like(p)
    total, weight = 0.5 * s, 0.5
    for _ in range(MAX_DUPLICATIONS):
        a, b = 0.5 * (a + b), np.sqrt(a * b)
        s = s * s * m / (16.0 * a * a)
        weight *= 2.0
        total += weight * s
        if np.all(weight * s <= TOLERANCE * total):
            break
    big_k = np.pi / (2.0 * a)
    d = big_k * total
    return big_k, big_k - m * d, d


def ellipe(m):
    """The complete elliptic integral of the second kind E(m) [1].

    Parameters
    ----------
    m : array_like [1]
        The parameter m = k² (0 ≤ m < 1).

    Returns
    -------
    ndarray [1]

    Notes
    -----
    :func:`complete_integrals` at p = 1 − m (DLMF 19.8.6).
    """
    m = np.asarray(m, float)
    return complete_integrals(1.0 - m)[1]
