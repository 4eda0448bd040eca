"""Outer ring as a simply supported beam between two housing supports (seed 002 eqs. 4–6).

SI units (m, N, N·m², rad). Li et al. 2025 (Machines 13:785, §2.3.1) model the axial bending of the
arc-backed outer ring as a beam on two supports A (x = 0) and B (x = L) carrying the row forces
F_k at x_k (0 ≤ x_k ≤ L). For one force F at a (b = L − a), Euler–Bernoulli theory gives

.. math::

    u(x) = \\frac{F b x}{6 EI L}(L^2 - b^2 - x^2) \\quad (0 \\le x \\le a), \\qquad
    u(x) = \\frac{F a (L-x)}{6 EI L}(L^2 - a^2 - (L-x)^2) \\quad (a \\le x \\le L)

    \\theta_A = \\frac{F a b (L + b)}{6 EI L}, \\qquad \\theta_B = \\frac{F a b (L + a)}{6 EI L}

(seed 002 eqs. 4–6 with L₁ = a, L₂ = b; Roark & Young 2012 Table 8.1 case 1e). Several row forces
superpose. u is positive in the direction of the forces; θ_A, θ_B are the magnitudes of the end
rotations (θ_A turns the beam towards +u going from A, θ_B towards +u going from B).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks, references

references.add(
    "roark2012",
    "Young W.C., Budynas R.G., Sadegh A.M. (2012) Roark's Formulas for Stress and Strain, 8th ed., "
    "McGraw-Hill, §9.2 and Table 9.2 (circular rings).",
)
REFERENCES = ("roark2012", "li2025")


def _positions(x_eval, x_load, span):
    checks.positive("span", span, "m")
    xe = np.asarray(x_eval, dtype=float)
    xl = np.asarray(x_load, dtype=float)
    checks.finite("x_eval", xe, "m")
    checks.finite("x_load", xl, "m")
    tol = 1e-12 * float(np.max(span))
    for name, x in (("x_load", xl), ("x_eval", xe)):
        if np.any(x < -tol) or np.any(x > np.asarray(span) + tol):
            raise checks.InputError(
                f"{name} ({checks._fmt(x)} m) must lie between the supports, "
                f"in [0, span={float(np.max(span)):.6g}] m"
            )
    return xe, xl


def beam_influence(x_eval, x_load, span, flexural_rigidity):
    """Deflection and slope influence matrices of a simply supported beam.

    Parameters
    ----------
    x_eval : array_like (M,) [m]
        Evaluation points measured from support A.
    x_load : array_like (N,) [m]
        Load points measured from support A.
    span : float [m]
        Distance L between the supports A and B.
    flexural_rigidity : float [N·m²]
        EI of the beam (np.inf: rigid, all zero).

    Returns
    -------
    deflection : ndarray (M, N) [m/N]
        u(x_m) per unit force at x_n.
    slope : ndarray (M, N) [rad/N]
        du/dx at x_m per unit force at x_n.

    Notes
    -----
    .. math:: u = \\frac{b x (L^2-b^2-x^2)}{6 EI L}\\ (x\\le a),\\quad
              u = \\frac{a (L-x)(L^2-a^2-(L-x)^2)}{6 EI L}\\ (x \\ge a)

    Li et al. 2025 eqs. (4)–(6); Roark & Young 2012 Table 8.1 case 1e.
    """
    xe, xl = _positions(x_eval, x_load, span)
    ei = np.asarray(flexural_rigidity, dtype=float)
    if np.isnan(ei) or ei <= 0:
        raise checks.InputError(f"flexural_rigidity ({float(ei):.6g} N·m²) must be positive")
    big_l = float(span)
    x = xe[:, None]
    a = xl[None, :]
    b = big_l - a
    left = x <= a
    xr = big_l - x
    defl = np.where(left, b * x * (big_l**2 - b**2 - x**2), a * xr * (big_l**2 - a**2 - xr**2))
    slope = np.where(left, b * (big_l**2 - b**2 - 3 * x**2), -a * (big_l**2 - a**2 - 3 * xr**2))
    scale = 1.0 / (6.0 * ei * big_l)
    return defl * scale, slope * scale


def beam_deflection(x_eval, x_load, forces, span, flexural_rigidity):
    """Deflection u(x) and slope of the supported outer ring under row forces, batched over cases.

    Parameters
    ----------
    x_eval : array_like (M,) [m]
        Points from support A where u is wanted (e.g. the rows' axial positions).
    x_load : array_like (N,) [m]
        Axial positions of the row forces from support A.
    forces : array_like (C, N) or (N,) [N]
        Row forces normal to the beam (the radial force each row passes to the outer ring).
    span : float [m]
        Support distance L = L₁ + L₂.
    flexural_rigidity : float [N·m²]

    Returns
    -------
    deflection : ndarray (C, M) [m]
    slope : ndarray (C, M) [rad]

    Notes
    -----
    .. math:: u_s(x) = \\sum_k F_k\\,g(x, x_k)

    Li et al. 2025 eq. (4), superposed over the three rows.
    """
    f = np.atleast_2d(np.asarray(forces, dtype=float))
    checks.finite("forces", f, "N")
    d, s = beam_influence(x_eval, x_load, span, flexural_rigidity)
    return f @ d.T, f @ s.T


def end_rotations(x_load, forces, span, flexural_rigidity):
    """End-section rotations θ_A, θ_B [rad] of the supported ring (seed 002 eqs. 5–6), batched.

    Parameters
    ----------
    x_load : array_like (N,) [m]
    forces : array_like (C, N) [N]
    span : float [m]
    flexural_rigidity : float [N·m²]

    Returns
    -------
    theta_a, theta_b : ndarray (C,) [rad]

    Notes
    -----
    .. math:: \\theta_A = \\sum_k \\frac{F_k a_k b_k (L+b_k)}{6EIL},\\quad
              \\theta_B = \\sum_k \\frac{F_k a_k b_k (L+a_k)}{6EIL}
    """
    _, slope = beam_deflection(np.array([0.0, float(span)]), x_load, forces, span, flexural_rigidity)
    return slope[:, 0], -slope[:, 1]
