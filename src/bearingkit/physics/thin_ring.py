"""In-plane bending of a thin circular ring under radial point loads and couples (influence coefficients).

SI units (m, N, N·m, Pa, rad). Curved-beam theory of an inextensible thin ring of centroidal radius R
and in-plane flexural rigidity EI (Timoshenko; Roark & Young 2012, §9.2): the radial deflection w
(outward positive) obeys

.. math:: \\frac{d^2 w}{d\\theta^2} + w = -\\frac{M(\\theta) R^2}{EI}

(seed 002, Li et al. 2025, eq. 7). Expanding loads and deflection in Fourier modes cos nθ, sin nθ,
the strain energy of mode n is π EI a_n² (n² − 1)² / (2R³); modes n = 0 (uniform stretching: zero
for an inextensible ring) and n = 1 (rigid-body translation) store no bending energy.

**Support (the decision documented here).** A free ring under an unbalanced set of element loads is
not in equilibrium. The outer ring of seed 002 sits with its arc back in the housing; we model the
housing reaction as the n = 0 and n = 1 harmonics of the load (a uniform plus a cosine-distributed
radial pressure, which balance the net force and produce no bending). The ring then bends only in
the modes n ≥ 2, and the deflection returned here contains **no rigid-body component**: its
n = 0 and n = 1 Fourier coefficients vanish. The rigid translation of the ring (and its tilt between
housing supports) is the beam model of :mod:`bearingkit.physics.ring_beam`. For a self-equilibrated
set of loads (e.g. two opposite forces) the result is the free-ring solution of Roark.

Closed forms (0 ≤ θ < 2π; verified against the series in the tests):

.. math::

    S(\\theta) = \\sum_{n\\ge 2} \\frac{\\cos n\\theta}{(n^2-1)^2}
      = -\\tfrac12 + \\tfrac14(\\pi-\\theta)\\sin\\theta + \\tfrac18(\\pi-\\theta)^2\\cos\\theta
        - \\left(\\tfrac{3}{16} + \\tfrac{\\pi^2}{24}\\right)\\cos\\theta

    T(\\theta) = \\sum_{n\\ge 2} \\frac{\\sin n\\theta}{n(n^2-1)}
      = \\tfrac12(\\pi-\\theta)(\\cos\\theta - 1) + \\tfrac34\\sin\\theta

An outward radial force Q at φ gives w(θ) = Q R³ S(θ − φ)/(π EI); an in-plane couple C (counter-
clockwise, about the bearing axis) at φ gives w(θ) = −C R² T(θ − φ)/(π EI). These are seed 002
eqs. (8)–(10) (written there with the prefactor R³/(4πEI) and f_Q = 4S, f_M = 2T up to the n = 1
terms, which that paper's reading of the support fixes differently; Cavallaro et al. 2005).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks, references

references.add(
    "roark2012",
    "Young W.C., Budynas R.G., Sadegh A.M. (2012) Roark's Formulas for Stress and Strain, 8th ed., "
    "McGraw-Hill, §9.2 and Table 9.2 (circular rings).",
)
references.add(
    "cavallaro2005",
    "Cavallaro G., Nelias D., Bon F. (2005) Analysis of high-speed intershaft cylindrical roller bearing "
    "with flexible rings. Tribology Transactions 48(2):154-164. doi:10.1080/05698190590923040",
)
REFERENCES = ("roark2012", "cavallaro2005", "li2025")

#: Constant of the n = 1-free closed form of S(θ): C₁ = −(3/16 + π²/24) (derived, see module docstring).
_S_COS = -(3.0 / 16.0 + np.pi**2 / 24.0)


def _rigidity(flexural_rigidity) -> np.ndarray:
    """EI > 0 (np.inf allowed: a rigid ring)."""
    ei = np.asarray(flexural_rigidity, dtype=float)
    if np.any(np.isnan(ei)) or np.any(ei <= 0):
        raise checks.InputError(f"flexural_rigidity ({checks._fmt(ei)} N·m²) must be positive")
    return ei


def _wrap(theta):
    """Angle in [0, 2π)."""
    return np.mod(np.asarray(theta, dtype=float), 2.0 * np.pi)


def ring_radial_kernel(theta):
    """Dimensionless radial-load kernel S(θ) = Σ_{n≥2} cos nθ / (n² − 1)².

    Parameters
    ----------
    theta : array_like [rad]
        Angle from the load point (any real value; 2π-periodic).

    Returns
    -------
    ndarray
        S(θ) [–]; even and 2π-periodic, S(0) = π²/12 − 11/16 ≈ 0.13497.

    Notes
    -----
    .. math:: S(\\theta) = -\\tfrac12 + \\tfrac14(\\pi-\\theta)\\sin\\theta
              + \\tfrac18(\\pi-\\theta)^2\\cos\\theta - (\\tfrac{3}{16}+\\tfrac{\\pi^2}{24})\\cos\\theta

    Derived from w'' + w = −MR²/EI with the n = 0, 1 modes removed (Roark & Young 2012 §9.2;
    Li et al. 2025, eq. 9).
    """
    t = _wrap(theta)
    u = np.pi - t
    return -0.5 + 0.25 * u * np.sin(t) + 0.125 * u * u * np.cos(t) + _S_COS * np.cos(t)


def ring_couple_kernel(theta):
    """Dimensionless couple kernel T(θ) = Σ_{n≥2} sin nθ / (n(n² − 1)).

    Parameters
    ----------
    theta : array_like [rad]

    Returns
    -------
    ndarray
        T(θ) [–]; odd and 2π-periodic (continuous, zero at θ = 0).

    Notes
    -----
    .. math:: T(\\theta) = \\tfrac12(\\pi-\\theta)(\\cos\\theta - 1) + \\tfrac34\\sin\\theta

    (Li et al. 2025, eq. 10; partial fractions of 1/(n(n²−1)) and Σ sin nθ/n = (π − θ)/2.)
    """
    t = _wrap(theta)
    return 0.5 * (np.pi - t) * (np.cos(t) - 1.0) + 0.75 * np.sin(t)


def radial_influence(theta_eval, theta_load, radius, flexural_rigidity):
    """Influence matrix C [m/N]: outward deflection at θ_eval per unit outward radial force at θ_load.

    Parameters
    ----------
    theta_eval : array_like (..., M) [rad]
        Where the deflection is wanted.
    theta_load : array_like (..., N) [rad]
        Where the radial point loads act.
    radius : float or array (...) [m]
        Centroidal radius R of the ring.
    flexural_rigidity : float or array (...) [N·m²]
        In-plane bending rigidity EI (np.inf gives a rigid ring: C = 0).

    Returns
    -------
    ndarray (..., M, N) [m/N]

    Notes
    -----
    .. math:: C_{mn} = \\frac{R^3}{\\pi EI} S(\\theta_m - \\varphi_n)

    Symmetric for coincident point sets (Maxwell–Betti reciprocity) and positive semi-definite.
    Reference: Roark & Young 2012 §9.2; Li et al. 2025 (doi:10.3390/machines13090785) eq. 8.
    """
    checks.positive("radius", radius, "m")
    ei = _rigidity(flexural_rigidity)
    te = np.asarray(theta_eval, dtype=float)[..., :, None]
    tl = np.asarray(theta_load, dtype=float)[..., None, :]
    r = np.asarray(radius, dtype=float)[..., None, None]
    factor = r**3 / (np.pi * ei[..., None, None])
    return factor * ring_radial_kernel(te - tl)


def couple_influence(theta_eval, theta_load, radius, flexural_rigidity):
    """Influence matrix [m/(N·m)]: outward deflection at θ_eval per unit in-plane couple at θ_load.

    Parameters
    ----------
    theta_eval : array_like (..., M) [rad]
    theta_load : array_like (..., N) [rad]
    radius : float [m]
    flexural_rigidity : float [N·m²]

    Returns
    -------
    ndarray (..., M, N) [m/(N·m)]

    Notes
    -----
    .. math:: C^{M}_{mn} = -\\frac{R^2}{\\pi EI} T(\\theta_m - \\varphi_n)

    The couple is positive counter-clockwise about +z (the bearing axis); section rotation
    β = (v − w′)/R. Li et al. 2025 eq. (8), second sum.
    """
    checks.positive("radius", radius, "m")
    _rigidity(flexural_rigidity)
    te = np.asarray(theta_eval, dtype=float)[..., :, None]
    tl = np.asarray(theta_load, dtype=float)[..., None, :]
    r = np.asarray(radius, dtype=float)[..., None, None]
    ei = np.asarray(flexural_rigidity, dtype=float)[..., None, None]
    return -(r**2) / (np.pi * ei) * ring_couple_kernel(te - tl)


def radial_deflection(theta_eval, theta_load, loads, radius, flexural_rigidity, couples=None):
    """Outward bending deflection W = C·Q of a thin ring at θ_eval, batched over cases.

    Parameters
    ----------
    theta_eval : array_like (M,) or (C, M) [rad]
    theta_load : array_like (N,) or (C, N) [rad]
    loads : array_like (C, N) or (N,) [N]
        Outward radial point forces on the ring (rolling elements pushing the outer ring out are
        positive; on an inner ring the element loads act inward, i.e. negative).
    radius : float [m]
    flexural_rigidity : float [N·m²]
    couples : array_like (C, N) [N·m], optional
        In-plane couples at the same points (counter-clockwise positive).

    Returns
    -------
    ndarray (C, M) [m]
        Outward radial deflection with the rigid-body (n = 0, 1) part removed.

    Notes
    -----
    .. math:: W(\\theta) = \\frac{R^3}{\\pi EI}\\sum_j Q_j S(\\theta-\\varphi_j)
              - \\frac{R^2}{\\pi EI}\\sum_j M_j T(\\theta-\\varphi_j)

    Li et al. 2025, eq. (8); Roark & Young 2012 §9.2.
    """
    q = np.atleast_2d(np.asarray(loads, dtype=float))
    checks.finite("loads", q, "N")
    c = radial_influence(theta_eval, theta_load, radius, flexural_rigidity)
    w = np.einsum("...mn,...n->...m", c, q)
    if couples is not None:
        m = np.atleast_2d(np.asarray(couples, dtype=float))
        checks.finite("couples", m, "N·m")
        w = w + np.einsum(
            "...mn,...n->...m", couple_influence(theta_eval, theta_load, radius, flexural_rigidity), m
        )
    return w
