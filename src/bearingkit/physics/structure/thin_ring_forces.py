"""Stress resultants of a thin circular ring: bending moment, normal (hoop) force, shear, fibre stress.

SI units (m, N, N·m, Pa, rad). Same ring as :mod:`bearingkit.physics.structure.thin_ring`: an
inextensible thin ring of centroidal radius R and in-plane rigidity EI, angles θ counter-clockwise.
Sign conventions (Roark & Young 2012 §9.2 use the opposite moment sign, see below):

* radial line load q_r [N/m] outward positive, tangential line load q_t [N/m] counter-clockwise
  positive; point forces likewise (Q radial, P tangential);
* on the section at θ, the part at larger θ acts on the part at smaller θ with the normal force N
  along e_θ (tension positive), the shear V along e_r (outward positive) and the moment M about +z;
  **M > 0 puts the outer fibre in tension** (the curvature increases): M = −EI (w″ + w)/R², the
  equation of :mod:`~bearingkit.physics.structure.thin_ring` (Roark's M, positive for tension on the
  inner fibre, is −M);
* equilibrium of an element: M′ = R V, N′ = −V − R q_t, V′ = N − R q_r (′ = d/dθ).

**Supports** (:data:`SUPPORTS`). ``"housing"`` is the model of the thin-ring deflection: the n = 0
and n = 1 Fourier harmonics of the load (q_r and q_t each) are carried by a distributed housing
reaction, and a bilateral Winkler housing (k_h, β = k_h R⁴/EI) pushes back on the ovalisation modes
n ≥ 2. ``"free"`` is a free ring under a self-equilibrated load set (Roark's ring cases): nothing is
removed, so N gains R(q_r⁽⁰⁾ + q_r⁽¹⁾) (the radial n = 0, 1 harmonics of the applied load; M and V
are the same, since modes n ≤ 1 do not bend the ring). The free ring needs k_h = 0 and the net force
and moment of the loads to vanish (checked by :func:`ring_forces`).

**Kernels.** The mode-n amplitude of the ring under a radial load harmonic F_n is
a_n = F_n R³/(π EI D_n), D_n = (n² − 1)² + β (thin_ring). A radial force Q at φ then gives, with
t = θ − φ,

.. math::
    M = \\frac{QR}{\\pi} K_\\beta(t),\\quad V = \\frac{Q}{\\pi} K_\\beta'(t),\\quad
    N = -\\frac{Q}{\\pi} K_\\beta(t),\\qquad K_\\beta(t) = \\sum_{n\\ge2}\\frac{(n^2-1)\\cos nt}{D_n}

(N from V′ − N + R q_r = 0 with the housing and Winkler reactions; the Dirac part of V′ cancels the
point force.) A tangential force P at φ (generalised force −P sin nφ/n on the cos mode) gives

.. math::
    M = \\frac{PR}{\\pi} T_\\beta(t),\\quad V = \\frac{P}{\\pi} K_\\beta(t),\\quad
    N = \\frac{P}{\\pi}\\Big[\\sin t - \\frac{\\pi - t}{2} - T_\\beta(t)\\Big]

with T_β the couple kernel of :func:`~bearingkit.physics.structure.thin_ring.ring_couple_kernel`
(N: V′ − R k_h w reduces with Σ_{n≥2} sin nt/n = (π − t)/2 − sin t). A uniform radial pressure p
over the arc φ₁ … φ₂ integrates the point kernels in closed form (∫K_β(θ − φ) dφ = T_β(θ − φ₁) −
T_β(θ − φ₂), ∫K_β′ dφ = K_β(θ − φ₁) − K_β(θ − φ₂)):

.. math::
    M = \\frac{pR^2}{\\pi}[T_\\beta]_{2}^{1},\\quad V = \\frac{pR}{\\pi}[K_\\beta]_{2}^{1},\\quad
    N = -\\frac{pR}{\\pi}[T_\\beta]_{2}^{1},\\qquad [f]_2^1 = f(\\theta-\\varphi_1) - f(\\theta-\\varphi_2)

Derived here (modal superposition, the energy method of thin_ring); checked in the tests against
Roark & Young (2012) Table 9.2 and against an independent least-work (Castigliano) solution of the
free ring (tests/physics/structure/test_thin_ring_forces.py).

References: ``roark2012`` (§9.2, Table 9.2), ``hetenyi1946`` (elastic foundation).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from bearingkit import checks
from bearingkit.physics.structure import thin_ring
from bearingkit.physics.structure.thin_ring import (
    BETA_SERIES,
    N_SERIES,
    ring_couple_kernel,
    stiffness_ratio,
)

__all__ = [
    "SUPPORTS",
    "RingForces",
    "fibre_stress",
    "moment_kernel",
    "moment_kernel_slope",
    "own_weight_forces",
    "ring_forces",
]

REFERENCES = ("roark2012", "hetenyi1946")
#: Ring supports of the stress resultants (module docstring).
SUPPORTS = ("housing", "free")
#: Relative residual of net force and moment [–] above which a "free" load set is not self-equilibrated.
BALANCE_TOLERANCE = 1e-9


class RingForces(NamedTuple):
    """Stress resultants of a thin ring on the evaluation angles (arrays (C, M), SI).

    Attributes
    ----------
    moment : ndarray [N·m]
        Bending moment M, positive for tension on the outer fibre.
    normal_force : ndarray [N]
        Hoop force N, tension positive.
    shear_force : ndarray [N]
        Radial shear V (outward on the face towards larger θ).
    """

    moment: np.ndarray
    normal_force: np.ndarray
    shear_force: np.ndarray

    def __add__(self, other):  # superposition of load sets
        return RingForces(*(a + b for a, b in zip(self, other, strict=True)))


def _wrap(theta):
    return np.mod(np.asarray(theta, dtype=float), 2.0 * np.pi)


def _split_beta(t, beta):
    """Broadcast t, β and give the safe β of the closed form and of the series branch."""
    b = thin_ring._beta(beta)
    t, b = np.broadcast_arrays(t, b)
    big = np.where((b > BETA_SERIES) & np.isfinite(b), b, 1.0)
    small = np.minimum(b, BETA_SERIES)
    return t, b, big, small


def moment_kernel(theta, beta=0.0):
    """Moment kernel K_β(θ) = Σ_{n≥2} (n² − 1) cos nθ / ((n² − 1)² + β) [–].

    Parameters
    ----------
    theta : array_like [rad]
        Angle from the radial point force (2π-periodic).
    beta : float or array_like [–]
        β = k_h R⁴/EI ≥ 0 (0: free ring; np.inf: rigid housing, K = 0).

    Returns
    -------
    ndarray
        K_β(θ); even, continuous, K_0(0) = 3/4.

    Notes
    -----
    Free ring (0 ≤ θ < 2π):

    .. math:: K_0(\\theta) = \\tfrac12 + \\tfrac14\\cos\\theta - \\tfrac12(\\pi-\\theta)\\sin\\theta

    (partial fractions of 1/(n² − 1) and Σ cos nθ/n² … ; derived). With z² = 1 + i√β,
    (n² − 1)/D_n = Re[1/(n² − z²)] and Σ_{n≥1} cos nθ/(n² − z²) = 1/(2z²) − π cos z(π − θ)/(2z sin πz),
    whose n = 1 term is purely imaginary:

    .. math::
        K_\\beta(\\theta) = \\mathrm{Re}\\Big[\\frac{1}{2z^2}
        - \\frac{\\pi\\cos z(\\pi-\\theta)}{2z\\sin\\pi z}\\Big]

    For β ≤ :data:`~bearingkit.physics.structure.thin_ring.BETA_SERIES`: K_0 − β Σ cos nθ/((n²−1) D_n)
    (terms ~ β/n⁶).
    """
    t = _wrap(theta)
    free = 0.5 + 0.25 * np.cos(t) - 0.5 * (np.pi - t) * np.sin(t)
    if not np.any(thin_ring._beta(beta)):
        return free + np.zeros(np.shape(beta))
    t, b, big, small = _split_beta(t, beta)
    free = 0.5 + 0.25 * np.cos(t) - 0.5 * (np.pi - t) * np.sin(t)
    n = np.arange(2, N_SERIES + 2, dtype=float)
    m = n * n - 1.0
    series = free - small * np.sum(np.cos(n * t[..., None]) / (m * (m * m + small[..., None])), axis=-1)
    z = thin_ring._winkler_z(big)
    e2 = np.exp(2j * np.pi * z)
    ratio = 1j * (np.exp(1j * z * (2 * np.pi - t)) + np.exp(1j * z * t)) / (e2 - 1.0)  # cos zu / sin πz
    closed = (1.0 / (2 * z * z) - np.pi * ratio / (2 * z)).real
    out = np.where(b > BETA_SERIES, closed, series)
    return np.where(np.isinf(b), 0.0, out)


def moment_kernel_slope(theta, beta=0.0):
    """K_β′(θ) = −Σ_{n≥2} n(n² − 1) sin nθ / ((n² − 1)² + β) [–] (the shear kernel of a radial force).

    Parameters
    ----------
    theta : array_like [rad]
        Angle from the radial point force (2π-periodic); θ = 0 is taken as 0⁺.
    beta : float or array_like [–]
        β = k_h R⁴/EI ≥ 0.

    Returns
    -------
    ndarray
        K_β′(θ); odd, with the jump −π across θ = 0 (V drops by Q across a radial force Q).

    Notes
    -----
    .. math:: K_0'(\\theta) = \\tfrac14\\sin\\theta - \\tfrac12(\\pi-\\theta)\\cos\\theta,\\qquad
              K_\\beta'(\\theta) = -\\mathrm{Re}\\,\\frac{\\pi\\sin z(\\pi-\\theta)}{2\\sin\\pi z}

    (Σ_{n≥1} n sin nθ/(n² − z²) = π sin z(π − θ)/(2 sin πz) on 0 < θ < 2π; the n = 1 term is imaginary).
    Small β: K_0′ + β Σ n sin nθ/((n²−1) D_n) (terms ~ β/n⁵).
    """
    t = _wrap(theta)
    free = 0.25 * np.sin(t) - 0.5 * (np.pi - t) * np.cos(t)
    if not np.any(thin_ring._beta(beta)):
        return free + np.zeros(np.shape(beta))
    t, b, big, small = _split_beta(t, beta)
    free = 0.25 * np.sin(t) - 0.5 * (np.pi - t) * np.cos(t)
    n = np.arange(2, N_SERIES + 2, dtype=float)
    m = n * n - 1.0
    series = free + small * np.sum(n * np.sin(n * t[..., None]) / (m * (m * m + small[..., None])), axis=-1)
    z = thin_ring._winkler_z(big)
    e2 = np.exp(2j * np.pi * z)
    ratio = (np.exp(1j * z * (2 * np.pi - t)) - np.exp(1j * z * t)) / (e2 - 1.0)  # sin zu / sin πz
    closed = -(np.pi * ratio / 2).real
    out = np.where(b > BETA_SERIES, closed, series)
    return np.where(np.isinf(b), 0.0, out)


def _angles(theta_eval, theta_load):
    te = np.asarray(theta_eval, dtype=float)[..., :, None]
    tl = np.asarray(theta_load, dtype=float)[..., None, :]
    return te - tl


def _radial(t, q, radius, beta, free):
    k, dk = moment_kernel(t, beta), moment_kernel_slope(t, beta)
    r = np.asarray(radius, float)[..., None]
    m = np.einsum("...mn,...n->...m", k, q) * r / np.pi
    v = np.einsum("...mn,...n->...m", dk, q) / np.pi
    n = -np.einsum("...mn,...n->...m", k, q) / np.pi
    if free:  # the radial n = 0, 1 harmonics stay in the ring: N += R q_r^(0,1) = Q(1 + 2 cos t)/(2π)
        n = n + np.einsum("...mn,...n->...m", 1.0 + 2.0 * np.cos(t), q) / (2.0 * np.pi)
    return RingForces(m, n, v)


def _tangential(t, p, radius, beta):
    tw = _wrap(t)
    tk, k = ring_couple_kernel(tw, beta), moment_kernel(tw, beta)
    r = np.asarray(radius, float)[..., None]
    m = np.einsum("...mn,...n->...m", tk, p) * r / np.pi
    v = np.einsum("...mn,...n->...m", k, p) / np.pi
    n = np.einsum("...mn,...n->...m", np.sin(tw) - 0.5 * (np.pi - tw) - tk, p) / np.pi
    return RingForces(m, n, v)


def _arc(theta_eval, start, end, pressure, radius, beta, free):
    te = np.asarray(theta_eval, dtype=float)[..., :, None]
    a = np.asarray(start, dtype=float)[..., None, :]
    b = np.asarray(end, dtype=float)[..., None, :]
    p = np.asarray(pressure, dtype=float)
    dt = ring_couple_kernel(te - a, beta) - ring_couple_kernel(te - b, beta)
    dk = moment_kernel(te - a, beta) - moment_kernel(te - b, beta)
    r = np.asarray(radius, float)[..., None]
    m = np.einsum("...mn,...n->...m", dt, p) * r**2 / np.pi
    v = np.einsum("...mn,...n->...m", dk, p) * r / np.pi
    n = -m / r
    if free:  # R (q_r^(0) + q_r^(1)) of the arc load: (pR/2π)[Δ + 2 (sin(θ−a) − sin(θ−b))]
        harm = (b - a) + 2.0 * (np.sin(te - a) - np.sin(te - b))
        n = n + np.einsum("...mn,...n->...m", harm, p) * r / (2.0 * np.pi)
    return RingForces(m, n, v)


def _net(radial, tangential, arcs, radius_of_arcs=1.0):
    """Net force (x, y) and moment about the centre divided by R, per case (C, 3) [N]."""
    out = 0.0
    if radial is not None:
        phi, q = radial
        out = out + np.stack([np.sum(q * np.cos(phi), -1), np.sum(q * np.sin(phi), -1), 0.0 * q.sum(-1)], -1)
    if tangential is not None:
        phi, p = tangential
        out = out + np.stack([-np.sum(p * np.sin(phi), -1), np.sum(p * np.cos(phi), -1), np.sum(p, -1)], -1)
    if arcs is not None:
        a, b, p = arcs
        # ∫ p e_r R dφ = pR (sin b − sin a, cos a − cos b); R is factored out by the caller's scale
        fx = np.sum(p * (np.sin(b) - np.sin(a)), -1)
        fy = np.sum(p * (np.cos(a) - np.cos(b)), -1)
        out = out + radius_of_arcs * np.stack([fx, fy, 0.0 * fx], -1)
    return out


def ring_forces(
    theta_eval,
    radius,
    radial=None,
    tangential=None,
    arcs=None,
    flexural_rigidity=np.inf,
    housing_stiffness=0.0,
    support="housing",
) -> RingForces:
    """Bending moment, hoop force and shear of a thin ring at θ_eval under point and arc loads.

    Parameters
    ----------
    theta_eval : array_like (M,) or (C, M) [rad]
        Where the resultants are wanted.
    radius : float [m]
        Centroidal radius R.
    radial : tuple (theta (N,) or (C, N) [rad], loads (C, N) or (N,) [N]) or None
        Outward radial point forces Q_j at φ_j.
    tangential : tuple (theta, loads [N]) or None
        Counter-clockwise tangential point forces P_j at φ_j.
    arcs : tuple (start (K,) [rad], end (K,) [rad], pressure (C, K) or (K,) [N/m]) or None
        Uniform outward radial line loads p_k over the arcs start_k … end_k (counter-clockwise, end > start).
    flexural_rigidity : float [N·m²]
        In-plane EI; only needed with a housing (β = k_h R⁴/EI); np.inf gives β = 0.
    housing_stiffness : float [N/m²]
        Winkler stiffness k_h of the housing (``support="housing"`` only).
    support : {"housing", "free"}
        :data:`SUPPORTS` (module docstring). ``"free"`` requires a self-equilibrated load set.

    Returns
    -------
    RingForces
        ``moment`` [N·m] (tension outside +), ``normal_force`` [N] (tension +), ``shear_force`` [N],
        each (C, M).

    Notes
    -----
    Superposition of the point- and arc-load kernels of the module docstring. At a point force the
    shear (radial force) or the hoop force (tangential force) jumps; the value returned exactly at
    the load point is that of the side θ → φ⁺.
    """
    checks.one_of("support", support, SUPPORTS)
    checks.positive("radius", radius, "m")
    free = support == "free"
    if free and np.any(np.asarray(housing_stiffness, float) != 0):
        raise checks.InputError(
            f"housing_stiffness ({checks._fmt(housing_stiffness)} N/m²) must be 0 with support='free' "
            "(a free ring has no housing); use support='housing'"
        )
    beta = stiffness_ratio(radius, flexural_rigidity, housing_stiffness)
    te = np.atleast_1d(np.asarray(theta_eval, dtype=float))
    parts, loads = [], {}
    if radial is not None:
        phi, q = (np.asarray(x, float) for x in radial)
        q = np.atleast_2d(checks.finite("radial loads", q, "N"))
        loads["radial"] = (np.broadcast_to(phi, q.shape), q)
        parts.append(_radial(_angles(te, phi), q, radius, beta, free))
    if tangential is not None:
        phi, p = (np.asarray(x, float) for x in tangential)
        p = np.atleast_2d(checks.finite("tangential loads", p, "N"))
        loads["tangential"] = (np.broadcast_to(phi, p.shape), p)
        parts.append(_tangential(_angles(te, phi), p, radius, beta))
    if arcs is not None:
        a, b, p = (np.asarray(x, float) for x in arcs)
        p = np.atleast_2d(checks.finite("arc pressures", p, "N/m"))
        if np.any(np.broadcast_to(b, p.shape) <= np.broadcast_to(a, p.shape)):
            raise checks.InputError(
                f"arc end ({checks._fmt(b)} rad) must exceed its start ({checks._fmt(a)} rad) "
                "(arcs run counter-clockwise)"
            )
        loads["arcs"] = (np.broadcast_to(a, p.shape), np.broadcast_to(b, p.shape), p)
        parts.append(_arc(te, a, b, p, radius, beta, free))
    if not parts:
        raise checks.InputError("ring_forces needs at least one of radial, tangential or arcs")
    if free:
        net = _net(loads.get("radial"), loads.get("tangential"), loads.get("arcs"), float(radius))
        scale = sum(float(np.abs(v[-1]).sum()) for k, v in loads.items() if k != "arcs")
        if "arcs" in loads:
            a, b, p = loads["arcs"]
            scale += float(np.sum(np.abs(p) * (b - a))) * float(np.max(radius))
        if np.max(np.abs(net)) > BALANCE_TOLERANCE * max(scale, np.finfo(float).tiny):
            raise checks.InputError(
                f"loads are not self-equilibrated (net F_x, F_y, M/R = {np.round(net, 6).tolist()} N) but "
                "support='free' needs a balanced load set; add the reactions or use support='housing'"
            )
    out = parts[0]
    for part in parts[1:]:
        out = out + part
    return out


def own_weight_forces(theta_eval, weight_per_length, radius, support_angle=-np.pi / 2) -> RingForces:
    """Resultants of a free ring under its own weight, resting on a point support (Roark Table 9.2 case 15).

    Parameters
    ----------
    theta_eval : array_like (M,) [rad]
    weight_per_length : float or array_like (C,) [N/m]
        w = ρ g A; gravity points from the centre towards the support point (the lowest point).
    radius : float [m]
        Centroidal radius R.
    support_angle : float [rad]
        Angle of the support point (default −π/2: gravity along −y).

    Returns
    -------
    RingForces (C, M)

    Notes
    -----
    The weight field (q_r = w cos t, q_t = −w sin t with t measured from the support point) is a
    pure n = 1 load: it bends nothing, and with the point reaction F = 2πRw (inward) the set is
    self-equilibrated. M and V are those of the reaction alone; N adds the field's R q_r:

    .. math:: M = -2wR^2 K_0(t),\\quad V = -2wR K_0'(t),\\quad
              N = -wR\\Big[\\tfrac12\\cos t + (\\pi - t)\\sin t\\Big]

    i.e. M = −wR²/2 at the top (t = π), −3wR²/2 at the support and +(π/2 − 1)wR² at the sides
    (Roark: M_A = wR²/2, M_B = 3wR²/2, M_C = −(π/2 − 1)wR², N_A = wR/2 for α = β = 0; with Roark's
    opposite moment sign).
    """
    checks.positive("radius", radius, "m")
    w = np.atleast_1d(checks.non_negative("weight_per_length", weight_per_length, "N/m"))
    t = _wrap(np.atleast_1d(np.asarray(theta_eval, dtype=float)) - support_angle)
    r = float(radius)
    k0 = 0.5 + 0.25 * np.cos(t) - 0.5 * (np.pi - t) * np.sin(t)
    dk0 = 0.25 * np.sin(t) - 0.5 * (np.pi - t) * np.cos(t)
    n = -(0.5 * np.cos(t) + (np.pi - t) * np.sin(t))
    return RingForces(-2.0 * r * r * w[:, None] * k0, r * w[:, None] * n, -2.0 * r * w[:, None] * dk0)


def fibre_stress(moment, normal_force, area, area_moment, inner_fibre, outer_fibre):
    """Hoop stress at the inner and outer fibre of a thin ring, σ = N/A ∓ M c/I [Pa].

    Parameters
    ----------
    moment : array_like [N·m]
        M, positive for tension on the outer fibre (this module's sign).
    normal_force : array_like [N]
        N, tension positive.
    area : float [m²]
        Section area A.
    area_moment : float [m⁴]
        In-plane second moment I about the centroidal axis.
    inner_fibre, outer_fibre : float [m]
        Distances c_i, c_o of the inner and outer surface from the centroid (> 0).

    Returns
    -------
    sigma_inner, sigma_outer : ndarray [Pa]

    Notes
    -----
    .. math:: \\sigma_i = \\frac{N}{A} - \\frac{M c_i}{I},\\qquad \\sigma_o = \\frac{N}{A} + \\frac{M c_o}{I}

    The straight-beam (thin-ring) formula; for R/h ≳ 5 the curved-beam (Winkler–Bach) correction
    at the inner fibre is below ~7 % (Roark & Young 2012, §9.1 and Table 9.1).
    """
    checks.positive("area", area, "m^2")
    checks.positive("area_moment", area_moment, "m^4")
    checks.positive("inner_fibre", inner_fibre, "m")
    checks.positive("outer_fibre", outer_fibre, "m")
    m = np.asarray(moment, float)
    s = np.asarray(normal_force, float) / area
    return s - m * inner_fibre / area_moment, s + m * outer_fibre / area_moment
