r"""A closed circular curved beam (a bearing ring) in and out of its plane, by Fourier harmonics.

SI units (m, N, N·m, Pa, rad). The ring has centroidal radius R, section area A and the rigidities
EA (stretching), EI_in (in-plane bending, I about the axis parallel to the bearing axis), EI_out
(out-of-plane bending, I about the radial axis: the axial extent of the section) and GJ (torsion).
At angle θ (counter-clockwise about +z) the section centroid moves by w (radial, outward), v
(tangential, +θ) and u (axial, +z) and the section rotates by φ about the tangent e_θ (right hand:
a section point at axial offset Δz moves radially by φΔz, one at radial offset Δr axially by −φΔr).

Strains of a thin curved beam (Timoshenko & Goodier 1951 §§ on rings; Roark & Young 2012 §9.2 for the
in-plane ring, Volterra & Chung 1955 / Timoshenko 1955 §§ on rings loaded perpendicular to their plane
for the out-of-plane ring; derived here from the displacements, ′ = d/dθ):

.. math::
    \varepsilon = \frac{v' + w}{R},\quad \kappa = \frac{v' - w''}{R^2},\quad
    \kappa_b = \frac{\varphi - u''/R}{R},\quad \kappa_t = \frac{\varphi' + u'/R}{R}

(hoop strain, in-plane curvature change, out-of-plane bending and twist rate). They vanish for the six
rigid-body motions (translations w = cos θ, v = −sin θ …; rotation about z v = R; about a diameter
u = −R cos θ, φ = cos θ …), which is the check that the kinematics are right. The energy is
½∫(EA ε² + EI_in κ² + EI_out κ_b² + GJ κ_t²) R dθ plus a bilateral Winkler foundation
½∫(k_r w² + k_t v² + k_a u² + k_φ φ²) R dθ (Hetényi 1946: a housing, a shaft seat or a flange face;
k per unit circumferential length: N/m² for the forces, N for the twist). The in-plane harmonics
w = a cos nθ, v = b sin nθ and the out-of-plane ones u = a cos nθ, φ = c cos nθ decouple; per
harmonic n ≥ 1 the stiffness is

.. math::
    K_n^{in} = \pi R\left(\frac{EA}{R^2}\begin{bmatrix}1 & n\\ n & n^2\end{bmatrix}
      + \frac{EI_{in} n^2}{R^4}\begin{bmatrix}n^2 & n\\ n & 1\end{bmatrix}
      + \begin{bmatrix}k_r & 0\\ 0 & k_t\end{bmatrix}\right),\quad
    K_n^{out} = \pi R\left(\frac{EI_{out}}{R^2}\begin{bmatrix}n^4/R^2 & n^2/R\\ n^2/R & 1\end{bmatrix}
      + \frac{GJ n^2}{R^2}\begin{bmatrix}1/R^2 & 1/R\\ 1/R & 1\end{bmatrix}
      + \begin{bmatrix}k_a & 0\\ 0 & k_\varphi\end{bmatrix}\right)

and for n = 0 it is 2πR diag(EA/R² + k_r, k_t) and 2πR diag(k_a, EI_out/R² + k_φ). Inextensible
(EA → ∞: b = −a/n), this is π[EI(n² − 1)² + k_r R⁴]/R³ for the radial amplitude, the kernel of
:mod:`bearingkit.physics.structure.thin_ring` (Li et al. 2025 eqs. 7–10 with Hetényi's foundation),
which the tests reproduce.

A point load at 0 excites one family per harmonic, so the response at angle Δ from a unit load is a
Fourier series of the harmonic compliances g_n = K_n⁻¹ (:func:`influence`): cos nΔ for radial→radial,
tangential→tangential and every out-of-plane pair, ±sin nΔ between radial and tangential. Where a
foundation term is zero the harmonics n = 0, 1 hold rigid-body modes; their K_n is singular and the
pseudo-inverse is used: the response then has no rigid-body part, which the supports
(:mod:`bearingkit.rings.supports`) fix. The series converge as n⁻² (tangential and twist), n⁻³ or
n⁻⁴; their tails past the last harmonic N are added in closed form (:func:`fourier_series`), so the
truncation error falls as N⁻³ or faster.

References: ``roark2012`` (§9.2), ``timoshenko1951rings``, ``volterra1955``, ``hetenyi1946``, ``li2025``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from bearingkit import checks, references

references.add(
    "timoshenko1951rings",
    "Timoshenko S.P., Goodier J.N. (1951) Theory of Elasticity, 2nd ed., McGraw-Hill (curved bars; "
    "torsion of prismatic bars, Prandtl's stress function, the rectangular section, §§ 99-109).",
)
references.add(
    "volterra1955",
    "Volterra E., Chung J.H. (1955) Constrained circular beam on elastic foundations. Transactions of "
    "the ASCE 120:301-310 (the circular ring loaded perpendicular to its plane on an elastic foundation).",
)
REFERENCES = ("roark2012", "timoshenko1951rings", "volterra1955", "hetenyi1946", "li2025")

#: Harmonics of the ring series by default (n = 0 … N): the radial kernels (n⁻⁴) are then exact to
#: ~1e-10 of their value and the twist and tangential ones (n⁻²) to ~1e-8 with the closed-form tails.
DEFAULT_HARMONICS = 512
#: Angles per block of a series sum (bounds the (angles × harmonics) temporary to ~32 MiB).
SERIES_BLOCK = 8192
#: Names of the four generalised displacements / loads at a section, in order.
COMPONENTS = ("radial", "tangential", "axial", "twist")
#: Names of the six rigid-body modes of a free ring.
RIGID_MODES = ("u_x", "u_y", "rot_z", "u_z", "rot_x", "rot_y")


class RingRigidities(NamedTuple):
    """Rigidities of a ring and its foundation (SI). np.inf for ``axial`` makes the ring inextensible;
    np.inf for both out-of-plane rigidities makes it rigid out of its plane.

    Attributes
    ----------
    radius : float [m]
        Centroidal radius R.
    axial : float [N]
        EA.
    in_plane : float [N·m²]
        EI_in (bending in the ring's plane).
    out_of_plane : float [N·m²]
        EI_out (bending out of the plane, and the ring's eversion).
    torsion : float [N·m²]
        GJ.
    foundation : tuple of 4 or 5 float
        Winkler stiffness (k_r, k_t, k_a [N/m²], k_φ [N], k_aφ [N/m]) per unit circumferential length;
        k_aφ couples the axial and twist motion of a foundation off the centroid (a flange face at
        radial offset e: k_aφ = −k_a e, k_φ = k_a e²; :mod:`bearingkit.rings.supports`).
    """

    radius: float
    axial: float
    in_plane: float
    out_of_plane: float
    torsion: float
    foundation: tuple = (0.0, 0.0, 0.0, 0.0, 0.0)

    @property
    def springs(self) -> tuple:
        """(k_r, k_t, k_a, k_φ, k_aφ) with a missing coupling term as 0."""
        k = tuple(float(v) for v in self.foundation)
        return k + (0.0,) * (5 - len(k))


def _check(ring: RingRigidities) -> None:
    checks.positive("radius", ring.radius, "m")
    for name, value in zip(("axial", "in_plane", "out_of_plane", "torsion"), ring[1:5], strict=True):
        v = float(value)
        if np.isnan(v) or v <= 0:
            raise checks.InputError(f"{name} rigidity ({v:.6g}) must be positive (np.inf: rigid)")
    k = np.asarray(ring.foundation, dtype=float)
    if k.shape not in ((4,), (5,)) or not np.all(np.isfinite(k)) or np.any(k[:4] < 0):
        raise checks.InputError(
            f"foundation ({ring.foundation!r}) must be finite stiffnesses (k_r, k_t, k_a, k_phi ≥ 0, k_a_phi)"
        )
    if k.shape == (5,) and k[4] ** 2 > k[2] * k[3] * (1 + 1e-12):
        raise checks.InputError(
            f"foundation coupling k_a_phi ({k[4]:.6g}) must satisfy k_a_phi² ≤ k_a k_phi "
            "(a positive foundation)"
        )


def harmonic_compliance(ring: RingRigidities, harmonics: int = DEFAULT_HARMONICS):
    r"""Compliance K_n⁻¹ of every harmonic n = 0 … N, in and out of the plane.

    Parameters
    ----------
    ring : RingRigidities
        Radius, rigidities and foundation (module docstring).
    harmonics : int
        N, the last harmonic.

    Returns
    -------
    (g_in, g_out) : ndarray (N+1, 2, 2) each [m/N, rad/N, rad/(N·m)]
        g_in over (a, b) of w = a cos nθ, v = b sin nθ; g_out over (a, c) of u = a cos nθ, φ = c cos nθ
        (the pseudo-inverse where a rigid-body mode makes K_n singular).

    Notes
    -----
    K_n of the module docstring (Roark & Young 2012 §9.2; Timoshenko & Goodier 1951; Hetényi 1946).
    EA = ∞ constrains b = −a/n (n ≥ 1) and a = 0 (n = 0); EI_out = GJ = ∞ gives g_out = 0.
    """
    _check(ring)
    checks.integer("harmonics", harmonics, low=2)
    r = float(ring.radius)
    ea, ei, eo, gj = (float(v) for v in ring[1:5])
    k_r, k_t, k_a, k_p, k_ap = ring.springs
    n = np.arange(harmonics + 1, dtype=float)
    g_in = _in_plane(n, r, ea, ei, k_r, k_t)
    if np.isinf(eo) and np.isinf(gj):
        g_out = np.zeros_like(g_in)
    else:
        e, g = eo / r**2, gj / r**2
        e = 0.0 if np.isinf(eo) else e
        g = 0.0 if np.isinf(gj) else g
        if np.isinf(eo) or np.isinf(gj):
            raise checks.InputError(
                "out_of_plane and torsion rigidities must both be finite or both np.inf (rigid out of plane)"
            )
        k = np.zeros((n.size, 2, 2))
        k[:, 0, 0] = e * n**4 / r**2 + g * n**2 / r**2 + k_a
        k[:, 0, 1] = k[:, 1, 0] = (e + g) * n**2 / r + k_ap
        k[:, 1, 1] = e + g * n**2 + k_p
        k[0] = [[k_a, k_ap], [k_ap, e + k_p]]
        scale = np.where(n == 0, 2.0, 1.0) * np.pi * r
        g_out = _inverse(k * scale[:, None, None])
    return g_in, g_out


def _in_plane(n, r, ea, ei, k_r, k_t):
    q = ei / r**4
    if np.isinf(ea):  # inextensible: one amplitude per harmonic along (1, −1/n); n = 0 only rotates
        g = np.zeros((n.size, 2, 2))
        m = n[1:]
        vec = np.stack([np.ones_like(m), -1.0 / m], axis=-1)
        stiff = np.pi * r * (q * (m * m - 1.0) ** 2 + k_r + k_t / (m * m))
        with np.errstate(divide="ignore"):
            comp = np.where(stiff > 0, 1.0 / np.where(stiff > 0, stiff, 1.0), 0.0)
        g[1:] = comp[:, None, None] * vec[:, :, None] * vec[:, None, :]
        g[0, 1, 1] = 0.0 if k_t == 0 else 1.0 / (2 * np.pi * r * k_t)
        return g
    p = ea / r**2
    k = np.zeros((n.size, 2, 2))
    k[:, 0, 0] = p + q * n**4 + k_r
    k[:, 0, 1] = k[:, 1, 0] = p * n + q * n**3
    k[:, 1, 1] = p * n**2 + q * n**2 + k_t
    k[0] = np.diag([p + k_r, k_t])
    scale = np.where(n == 0, 2.0, 1.0) * np.pi * r
    return _inverse(k * scale[:, None, None])


def _inverse(k):
    """Inverse of 2×2 stiffnesses (N, 2, 2); the pseudo-inverse of those that are singular."""
    det = k[:, 0, 0] * k[:, 1, 1] - k[:, 0, 1] * k[:, 1, 0]
    size = np.abs(k).max(axis=(1, 2))
    regular = np.abs(det) > 1e-12 * size**2
    out = np.zeros_like(k)
    d = np.where(regular, det, 1.0)
    out[:, 0, 0], out[:, 1, 1] = k[:, 1, 1] / d, k[:, 0, 0] / d
    out[:, 0, 1], out[:, 1, 0] = -k[:, 0, 1] / d, -k[:, 1, 0] / d
    for i in np.flatnonzero(~regular):  # a rigid-body mode (n = 0 or 1 without a foundation)
        out[i] = np.linalg.pinv(k[i], rcond=1e-12)
    return out


# -- series with closed-form tails -----------------------------------------------------------------
def _tail_sum(kind: str, power: int, t):
    """Σ_{n≥1} f(nt)/n^p in closed form on 0 ≤ t < 2π, or None when not elementary."""
    if kind == "cos" and power == 2:
        return np.pi**2 / 6 - np.pi * t / 2 + t * t / 4
    if kind == "cos" and power == 4:
        return np.pi**4 / 90 - np.pi**2 * t**2 / 12 + np.pi * t**3 / 12 - t**4 / 48
    if kind == "sin" and power == 1:
        return np.where(t == 0.0, 0.0, (np.pi - t) / 2)
    if kind == "sin" and power == 3:
        return np.pi**2 * t / 6 - np.pi * t**2 / 4 + t**3 / 12
    return None


def _decay(coef) -> int | None:
    """Integer p with coef_n ~ c/n^p over the last octave (1 … 4), None when not a clean power."""
    n = coef.size - 1
    a, b = abs(coef[n // 2]), abs(coef[n])
    if a == 0.0 or b == 0.0 or np.sign(coef[n // 2]) != np.sign(coef[n]):
        return None
    p = np.log(a / b) / np.log(n / (n // 2))
    q = round(float(p))
    return q if 1 <= q <= 4 and abs(p - q) < 0.15 else None


def fourier_series(coef, theta, kind: str = "cos"):
    r"""Σ_{n=0…N} c_n cos nθ (or sin nθ) plus the series' tail past N in closed form.

    Parameters
    ----------
    coef : array_like (N+1,) or (K, N+1)
        Coefficients c_0 … c_N (K series at once).
    theta : array_like (M,) [rad]
        Angles (any real value; 2π-periodic).
    kind : {"cos", "sin"}

    Returns
    -------
    ndarray (M,) or (K, M)

    Notes
    -----
    Where c_n ~ c/n^p over the last octave with p ∈ {1, 2, 4} (cos: 2, 4; sin: 1, 3), the tail
    Σ_{n>N} c cos nθ/n^p is added as c [S_p(θ) − Σ_{n≤N} cos nθ/n^p] with the closed forms
    S_2 = π²/6 − πθ/2 + θ²/4, S_4 = π⁴/90 − π²θ²/12 + πθ³/12 − θ⁴/48, Σ sin nθ/n = (π − θ)/2,
    Σ sin nθ/n³ = π²θ/6 − πθ²/4 + θ³/12 (0 ≤ θ < 2π; Gradshteyn & Ryzhik 2007, 1.443, the Bernoulli
    polynomial series), so the error falls from O(N^{1−p}) to O(N^{−1−p}).
    """
    c = np.atleast_2d(np.asarray(coef, dtype=float))
    t = np.mod(np.asarray(theta, dtype=float).reshape(-1), 2.0 * np.pi)
    n = np.arange(c.shape[-1], dtype=float)
    trig = np.cos if kind == "cos" else np.sin
    adjusted = c.copy()
    tails = []
    for i in range(c.shape[0]):
        p = _decay(c[i])
        closed = None if p is None else _tail_sum(kind, p, t)
        if closed is None:
            tails.append(None)
            continue
        amp = c[i, -1] * n[-1] ** p
        adjusted[i, 1:] -= amp / n[1:] ** p
        tails.append(amp * closed)
    out = np.empty((c.shape[0], t.size))
    for start in range(0, t.size, SERIES_BLOCK):
        block = slice(start, start + SERIES_BLOCK)
        out[:, block] = adjusted @ trig(np.outer(n, t[block]))
    for i, tail in enumerate(tails):
        if tail is not None:
            out[i] += tail
    return out[0] if np.ndim(coef) == 1 else out


def influence(delta, ring: RingRigidities, harmonics: int = DEFAULT_HARMONICS, first_harmonic: int = 0):
    r"""Response (w, v, u, φ) at angle Δ from a unit generalised load (F_r, F_t, F_z, M_t) at 0.

    Parameters
    ----------
    delta : array_like (M,) [rad]
        Angles from the load to the response (θ_response − θ_load).
    ring : RingRigidities
    harmonics : int
        Last harmonic N of the series.
    first_harmonic : int
        Harmonics below it are left out (2: seed 002's reading, whose housing carries n = 0, 1
        rigidly; 0: the whole ring, the default).

    Returns
    -------
    ndarray (M, 4, 4)
        [i, j]: displacement i per unit load j [m/N, m/(N·m), rad/N, rad/(N·m)]; symmetric under
        Δ → −Δ with the transpose (Maxwell–Betti).

    Notes
    -----
    G_rr = Σ g^in_aa cos nΔ, G_tt = Σ g^in_bb cos nΔ, G_tr = Σ g^in_ba sin nΔ = −G_rt, every
    out-of-plane pair Σ g^out cos nΔ (module docstring; Roark & Young 2012 §9.2, Hetényi 1946).
    """
    g_in, g_out = harmonic_compliance(ring, harmonics)
    if first_harmonic:
        g_in[:first_harmonic] = 0.0
        g_out[:first_harmonic] = 0.0
    d = np.asarray(delta, dtype=float).reshape(-1)
    cos = fourier_series(
        np.stack([g_in[:, 0, 0], g_in[:, 1, 1], g_out[:, 0, 0], g_out[:, 0, 1], g_out[:, 1, 1]]), d
    )
    sin = fourier_series(g_in[:, 1, 0], d, "sin")
    out = np.zeros((d.size, 4, 4))
    out[:, 0, 0], out[:, 1, 1] = cos[0], cos[1]
    out[:, 1, 0], out[:, 0, 1] = sin, -sin
    out[:, 2, 2], out[:, 2, 3], out[:, 3, 2], out[:, 3, 3] = cos[2], cos[3], cos[3], cos[4]
    return out


def rigid_modes(theta, radius):
    """The six rigid-body motions of a ring as (w, v, u, φ) at angles θ: (M, 6, 4).

    Parameters
    ----------
    theta : array_like (M,) [rad]
    radius : float [m]
        Centroidal radius R.

    Returns
    -------
    ndarray (M, 6, 4)
        Modes in the order of :data:`RIGID_MODES`: translations x, y (w = cos θ, v = −sin θ; w = sin θ,
        v = cos θ), rotation about z (v = R), translation z (u = 1), rotations about x (u = R sin θ,
        φ = −sin θ) and y (u = −R cos θ, φ = cos θ), unit rotation [rad] (Timoshenko & Goodier 1951).
    """
    t = np.asarray(theta, dtype=float).reshape(-1)
    c, s, z, one = np.cos(t), np.sin(t), np.zeros(t.size), np.ones(t.size)
    r = float(radius)
    return np.stack(
        [
            np.stack([c, -s, z, z], -1),
            np.stack([s, c, z, z], -1),
            np.stack([z, r * one, z, z], -1),
            np.stack([z, z, one, z], -1),
            np.stack([z, z, r * s, -s], -1),
            np.stack([z, z, -r * c, c], -1),
        ],
        axis=1,
    )


def free_modes(ring: RingRigidities, first_harmonic: int = 0) -> np.ndarray:
    """Which rigid-body modes (:data:`RIGID_MODES`) the foundation leaves free: (6,) bool.

    Parameters
    ----------
    ring : RingRigidities
    first_harmonic : int
        With first_harmonic ≥ 2 the harmonics n = 0, 1 are held elsewhere (no free mode).

    Returns
    -------
    ndarray (6,) of bool

    Notes
    -----
    Translations in the plane are held by k_r or k_t, the rotation about z by k_t, the axial
    translation by k_a, the rotations about diameters by k_a or k_φ (Hetényi 1946 foundation).
    """
    if first_harmonic >= 2:
        return np.zeros(6, bool)
    k_r, k_t, k_a, k_p = (v > 0 for v in ring.springs[:4])
    inplane = not (k_r or k_t)
    tilt = not (k_a or k_p)
    return np.array([inplane, inplane, not k_t, not k_a, tilt, tilt])


def resultants(delta, ring: RingRigidities, harmonics: int = DEFAULT_HARMONICS, first_harmonic: int = 0):
    r"""Stress resultants at angle Δ from a unit generalised load (F_r, F_t, F_z, M_t) at 0.

    Parameters
    ----------
    delta : array_like (M,) [rad]
        Angles from the load to the section.
    ring : RingRigidities
    harmonics : int
    first_harmonic : int
        As :func:`influence`.

    Returns
    -------
    ndarray (M, 4, 4)
        [i, j]: resultant i = (N hoop force [N], M in-plane moment [N·m], M_b out-of-plane moment
        [N·m], T torque [N·m]) per unit load j. M > 0 puts the outer fibre in tension (the sign of
        :mod:`bearingkit.physics.structure.thin_ring_forces`; Roark's M is −M), M_b > 0 the fibre at
        larger z.

    Notes
    -----
    N = EA ε, M = EI_in κ, M_b = EI_out κ_b, T = GJ κ_t with the strains of the module docstring
    evaluated on each harmonic's amplitudes (radial load: w = a cos, v = b sin; tangential: w = a sin,
    v = −b cos): N_n = EA(a + nb)/R, M_n = EI n(b + na)/R², M_b,n = EI_out(c + n²a/R)/R,
    T_n = −GJ n(c + a/R)/R (sin). Roark & Young 2012 §9.2; Timoshenko & Goodier 1951.
    """
    if np.isinf(float(ring.axial)):
        raise checks.InputError(
            "resultants need a finite axial rigidity EA (an inextensible ring's hoop force)"
        )
    g_in, g_out = harmonic_compliance(ring, harmonics)
    if first_harmonic:
        g_in[:first_harmonic] = 0.0
        g_out[:first_harmonic] = 0.0
    r = float(ring.radius)
    ea, ei, eo, gj = (float(v) for v in ring[1:5])
    n = np.arange(g_in.shape[0], dtype=float)
    d = np.asarray(delta, dtype=float).reshape(-1)
    out = np.zeros((d.size, 4, 4))
    # in plane: radial load (a, b) = g (1, 0) on cos/sin; tangential (a, b) = g (0, −1) on sin/−cos
    for j, (load, kind) in enumerate((((1.0, 0.0), "cos"), ((0.0, -1.0), "sin"))):
        a = g_in[:, 0, 0] * load[0] + g_in[:, 0, 1] * load[1]
        b = g_in[:, 1, 0] * load[0] + g_in[:, 1, 1] * load[1]
        hoop = ea * (a + n * b) / r
        moment = ei * n * (b + n * a) / r**2
        out[:, 0, j], out[:, 1, j] = fourier_series(np.stack([hoop, moment]), d, kind)
    for j, col in ((2, 0), (3, 1)):
        a, c = g_out[:, 0, col], g_out[:, 1, col]
        bend = np.zeros_like(a) if np.isinf(eo) else eo * (c + n * n * a / r) / r
        twist = np.zeros_like(a) if np.isinf(gj) else -gj * n * (c + a / r) / r
        out[:, 2, j] = fourier_series(bend, d)
        out[:, 3, j] = fourier_series(twist, d, "sin")
    return out
