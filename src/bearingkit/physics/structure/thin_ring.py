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
housing supports) is the beam model of :mod:`bearingkit.physics.structure.ring_beam`. For a self-equilibrated
set of loads (e.g. two opposite forces) the result is the free-ring solution of Roark.

**Housing as a Winkler foundation (optional).** A ring fitted in a housing bore is also held by
the housing wall. We model the wall as a bilateral elastic (Winkler) foundation of radial stiffness
k_h per unit circumferential length [N/m²] acting on the ring's outer surface at radius ≈ R: it
pushes back on inward *and* outward radial motion, i.e. the ring stays in contact with the bore all
round. That is a ring fitted without radial play: an interference or tight transition fit (with
a loose fit the ring could lift off the bore on the unloaded side, a unilateral foundation that is
not modelled here). The foundation
stores k_h ∫ w² R dθ/2, i.e. π k_h R a_n²/2 per mode, so the potential of mode n under a radial
force Q at φ is Π_n = π a_n² [EI (n² − 1)²/R³ + k_h R]/2 − Q a_n cos n(θ−φ) and

.. math:: a_n = \\frac{Q R^3}{\\pi\\,[EI (n^2-1)^2 + k_h R^4]}, \\qquad n \\ge 2

(energy method as for the beam on an elastic foundation, Hetényi 1946; derived here and checked in
the tests: modal amplitudes by FFT, and the λR ≫ 1 limit against Hetényi's infinite beam). The
modes n = 0, 1 stay with the beam / rigid-body model exactly as for the free ring, so k_h = 0 is
the free ring above and k_h → ∞ removes the ovalisation. With β = k_h R⁴/EI the kernels become
S_β(θ) = Σ_{n≥2} cos nθ/((n²−1)² + β) and
T_β(θ) = Σ_{n≥2} (n²−1) sin nθ /(n((n²−1)² + β)), summed in closed form
(:func:`ring_radial_kernel`, :func:`ring_couple_kernel`). A housing wall of thickness t_h, modulus
E_h and mean radius R_h has the hoop (membrane) stiffness E_h t_h/R_h² per unit area, i.e.
k_h = E_h t_h b/R_h² over the ring width b (:func:`housing_wall_stiffness`).

Closed forms of the free ring (0 ≤ θ < 2π; verified against the series in the tests):

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
references.add(
    "hetenyi1946",
    "Hetényi M. (1946) Beams on Elastic Foundation. University of Michigan Press, Ann Arbor.",
)
REFERENCES = ("roark2012", "cavallaro2005", "li2025", "hetenyi1946")

#: β = k_h R⁴/EI up to which the Winkler kernels are the free closed form minus a fast series (the
#: closed form in z = √(1 + i√β) loses ~eps/β to cancellation there; the series' truncation is
#: < β/(6·N_SERIES⁶) ≈ 2e-13·β for T, < 4e-15·β for S). Chosen so both errors stay below 1e-13.
BETA_SERIES = 0.01
#: Number of modes (n = 2 … N_SERIES + 1) of that correction series.
N_SERIES = 64
#: Constant of the n = 1-free closed form of S(θ): C₁ = −(3/16 + π²/24) (derived, see module docstring).
_S_COS = -(3.0 / 16.0 + np.pi**2 / 24.0)


def _rigidity(flexural_rigidity) -> np.ndarray:
    """EI > 0 (np.inf allowed: a rigid ring)."""
    ei = np.asarray(flexural_rigidity, dtype=float)
    if np.any(np.isnan(ei)) or np.any(ei <= 0):
        raise checks.InputError(f"flexural_rigidity ({checks._fmt(ei)} N·m²) must be positive")
    return ei


def _beta(beta) -> np.ndarray:
    """β ≥ 0 (np.inf allowed: rigid housing)."""
    b = np.asarray(beta, dtype=float)
    if np.any(np.isnan(b)) or np.any(b < 0):
        raise checks.InputError(f"beta ({checks._fmt(b)}) must be non-negative (β = k_h R⁴/EI)")
    return b


def _stiffness(housing_stiffness) -> np.ndarray:
    """k_h ≥ 0 (np.inf allowed: rigid housing)."""
    k = np.asarray(housing_stiffness, dtype=float)
    if np.any(np.isnan(k)) or np.any(k < 0):
        raise checks.InputError(f"housing_stiffness ({checks._fmt(k)} N/m²) must be non-negative")
    return k


def stiffness_ratio(radius, flexural_rigidity, housing_stiffness):
    """Housing-to-ring stiffness ratio β = k_h R⁴ / EI (0 for a free ring, ∞ for a rigid housing).

    Parameters
    ----------
    radius : float or array_like [m]
        Centroidal radius R of the ring.
    flexural_rigidity : float or array_like [N·m²]
        In-plane EI of the ring (np.inf: rigid ring, β = 0 unless k_h is infinite too).
    housing_stiffness : float or array_like [N/m²]
        Winkler stiffness k_h of the housing (np.inf: rigid housing).

    Returns
    -------
    ndarray [–]

    Notes
    -----
    .. math:: \\beta = \\frac{k_h R^4}{EI}

    The mode-n stiffness of the housed ring is π [EI (n²−1)² + k_h R⁴]/R³ (Hetényi 1946): β compares
    the two; the housing dominates the modes n ≲ β^{1/4}.
    """
    r = np.asarray(radius, dtype=float)
    ei = np.asarray(flexural_rigidity, dtype=float)
    k = _stiffness(housing_stiffness)
    with np.errstate(invalid="ignore", divide="ignore"):
        b = np.where(np.isinf(k), np.inf, np.where(np.isinf(ei), 0.0, k * r**4 / ei))
    return b


def _wrap(theta):
    """Angle in [0, 2π)."""
    return np.mod(np.asarray(theta, dtype=float), 2.0 * np.pi)


def _winkler_z(beta):
    """z = √(1 + i√β) (principal root, Re z > 0, Im z ≥ 0): (n² − 1)² + β = (n² − z²)(n² − z̄²)."""
    return np.sqrt(1.0 + 1j * np.sqrt(beta))


def _modes_n():
    return np.arange(2, N_SERIES + 2, dtype=float)


#: Angles per block of the correction series: the (block, N_SERIES) temporary stays at 8 MiB
#: whatever the number of cases and elements (the series used to be formed for every angle at once,
#: cases × elements² × N_SERIES floats: 2.4 GiB for 100 load cases of the ball–column bearing).
SERIES_BLOCK = 16384


def _series(t, b, term):
    """Σ_n term(n, θ, β) over the modes n = 2 … N_SERIES + 1, only where 0 < β ≤ :data:`BETA_SERIES`.

    ``t`` and ``b`` are broadcast arrays of one shape; the sum is formed in blocks of
    :data:`SERIES_BLOCK` angles, so the temporary does not grow with the number of angles.
    """
    out = np.zeros(t.shape)
    where = np.flatnonzero((b > 0) & (b <= BETA_SERIES))
    flat_t, flat_b, flat_out = t.reshape(-1), b.reshape(-1), out.reshape(-1)
    n = _modes_n()
    for start in range(0, where.size, SERIES_BLOCK):
        k = where[start : start + SERIES_BLOCK]
        flat_out[k] = np.sum(term(n, flat_t[k, None], flat_b[k, None]), axis=-1)
    return out


def ring_radial_kernel(theta, beta=0.0):
    """Dimensionless radial-load kernel S_β(θ) = Σ_{n≥2} cos nθ / ((n² − 1)² + β).

    Parameters
    ----------
    theta : array_like [rad]
        Angle from the load point (any real value; 2π-periodic).
    beta : float or array_like [–]
        Housing-to-ring stiffness ratio β = k_h R⁴/EI (≥ 0; broadcast against ``theta``; 0 = free
        ring, np.inf = rigid housing: S = 0).

    Returns
    -------
    ndarray
        S_β(θ) [–]; even and 2π-periodic, S_0(0) = π²/12 − 11/16 ≈ 0.13497.

    Notes
    -----
    Free ring (β = 0):

    .. math:: S_0(\\theta) = -\\tfrac12 + \\tfrac14(\\pi-\\theta)\\sin\\theta
              + \\tfrac18(\\pi-\\theta)^2\\cos\\theta - (\\tfrac{3}{16}+\\tfrac{\\pi^2}{24})\\cos\\theta

    derived from w'' + w = −MR²/EI with the n = 0, 1 modes removed (Roark & Young 2012 §9.2;
    Li et al. 2025, eq. 9). Ring on a Winkler foundation (Hetényi 1946): with z² = 1 + i√β,
    1/((n²−1)² + β) = Im[1/(n² − z²)]/√β and Σ_{n≥1} cos nθ/(n² − z²) = 1/(2z²) −
    π cos z(π − θ)/(2z sin πz) (0 ≤ θ ≤ 2π), so

    .. math:: S_\\beta(\\theta) = \\frac{1}{\\sqrt\\beta}\\left(\\mathrm{Im}\\left[\\frac{1}{2z^2}
              - \\frac{\\pi\\cos z(\\pi-\\theta)}{2z\\sin\\pi z}\\right]
              - \\frac{\\cos\\theta}{\\sqrt\\beta}\\right)

    evaluated with decaying exponentials only (no overflow for large β). For β ≤ :data:`BETA_SERIES`
    (where that difference cancels) S_β = S_0 − β Σ cos nθ/((n²−1)²((n²−1)² + β)), n = 2 …
    :data:`N_SERIES` + 1 (terms ~ β/n⁸: truncation < 1e-15).
    """
    t = _wrap(theta)
    u = np.pi - t
    free = -0.5 + 0.25 * u * np.sin(t) + 0.125 * u * u * np.cos(t) + _S_COS * np.cos(t)
    b = _beta(beta)
    if not np.any(b):
        return free + np.zeros_like(b)
    t, b, free = np.broadcast_arrays(t, b, free)

    def term(n, t, b):
        m = (n * n - 1.0) ** 2
        return np.cos(n * t) / (m * (m + b))

    # the series is used where β ≤ BETA_SERIES only
    series = free - np.where(b <= BETA_SERIES, b, 0.0) * _series(t, b, term)
    big = np.where(b > BETA_SERIES, b, 1.0)  # the closed-form branch, on a safe β
    big = np.where(np.isinf(big), 1.0, big)
    z = _winkler_z(big)
    e2 = np.exp(2j * np.pi * z)
    ratio = 1j * (np.exp(1j * z * (2 * np.pi - t)) + np.exp(1j * z * t)) / (e2 - 1.0)  # cos zu / sin πz
    f = 1.0 / (2 * z * z) - np.pi * ratio / (2 * z)
    root = np.sqrt(big)
    closed = (f.imag - np.cos(t) / root) / root
    out = np.where(b > BETA_SERIES, closed, series)
    return np.where(np.isinf(b), 0.0, out)


def ring_couple_kernel(theta, beta=0.0):
    """Dimensionless couple kernel T_β(θ) = Σ_{n≥2} (n² − 1) sin nθ / (n((n² − 1)² + β)).

    Parameters
    ----------
    theta : array_like [rad]
        Angle from the couple (any real value; 2π-periodic).
    beta : float or array_like [–]
        Housing-to-ring stiffness ratio β = k_h R⁴/EI (≥ 0; 0 = free ring, np.inf: T = 0).

    Returns
    -------
    ndarray
        T_β(θ) [–]; odd and 2π-periodic (continuous, zero at θ = 0).

    Notes
    -----
    .. math:: T_0(\\theta) = \\tfrac12(\\pi-\\theta)(\\cos\\theta - 1) + \\tfrac34\\sin\\theta

    (Li et al. 2025, eq. 10; partial fractions of 1/(n(n²−1)) and Σ sin nθ/n = (π − θ)/2.) On a
    Winkler foundation (Hetényi 1946), with z² = 1 + i√β, (n²−1)/((n²−1)² + β) = Re[1/(n² − z²)],
    1/(n(n² − z²)) = (n/(n² − z²) − 1/n)/z² and Σ n sin nθ/(n² − z²) = π sin z(π−θ)/(2 sin πz):

    .. math:: T_\\beta(\\theta) = \\mathrm{Re}\\,\\frac{1}{z^2}\\left[\\frac{\\pi\\sin z(\\pi-\\theta)}
              {2\\sin\\pi z} - \\frac{\\pi-\\theta}{2}\\right]

    (the n = 1 term is purely imaginary). For β ≤ :data:`BETA_SERIES`: T_0 minus the series
    β Σ sin nθ/(n(n²−1)((n²−1)² + β)) (terms ~ β/n⁷).
    """
    t = _wrap(theta)
    free = 0.5 * (np.pi - t) * (np.cos(t) - 1.0) + 0.75 * np.sin(t)
    b = _beta(beta)
    if not np.any(b):
        return free + np.zeros_like(b)
    t, b, free = np.broadcast_arrays(t, b, free)

    def term(n, t, b):
        m = n * n - 1.0
        return np.sin(n * t) / (n * m * (m * m + b))

    series = free - np.where(b <= BETA_SERIES, b, 0.0) * _series(t, b, term)
    big = np.where(b > BETA_SERIES, b, 1.0)
    big = np.where(np.isinf(big), 1.0, big)
    z = _winkler_z(big)
    e2 = np.exp(2j * np.pi * z)
    ratio = (np.exp(1j * z * (2 * np.pi - t)) - np.exp(1j * z * t)) / (e2 - 1.0)  # sin zu / sin πz
    closed = ((np.pi * ratio / 2 - (np.pi - t) / 2) / (z * z)).real
    out = np.where(b > BETA_SERIES, closed, series)
    return np.where(np.isinf(b), 0.0, out)


def housing_wall_stiffness(youngs_modulus, wall_thickness, radius, width):
    """Winkler stiffness of a housing wall from its hoop (membrane) stiffness, k_h = E_h t_h b / R_h².

    Parameters
    ----------
    youngs_modulus : float or array_like [Pa]
        E_h of the housing material.
    wall_thickness : float or array_like [m]
        Radial wall thickness t_h of the housing around the bore (> 0).
    radius : float or array_like [m]
        Mean radius R_h of the housing wall.
    width : float or array_like [m]
        Axial width b over which the wall holds the ring (the ring width).

    Returns
    -------
    ndarray [N/m²]
        k_h: radial force per unit circumferential length of the ring per unit radial displacement.

    Notes
    -----
    A thin-walled cylinder under a radial pressure p has hoop stress pR/t and radial displacement
    Δr = p R²/(E t) (Roark & Young 2012, Table 13.1 case 1a: thin-walled vessel under uniform
    pressure). The ring feels the force p b per unit circumferential length, so

    .. math:: k_h = \\frac{p\\,b}{\\Delta r} = \\frac{E_h t_h b}{R_h^2}

    (E_h t_h/R_h² alone is the foundation modulus per unit *area*, N/m³). This is the breathing
    (n = 0) stiffness of the wall. Using it for every mode n ≥ 2 assumes the wall is held against its
    own inextensional bending (a wall backed by the machine frame); a free thin housing ring adds
    only its bending stiffness E_h I_h (n² − 1)²/R⁴, far less. It is an estimate, not a bound, for
    a massive housing (a bore in an infinite plate: k_h = E_h b/((1 + ν)R_h), Timoshenko & Goodier
    1951 §29).
    """
    checks.positive("youngs_modulus", youngs_modulus, "Pa")
    checks.positive("wall_thickness", wall_thickness, "m")
    checks.positive("radius", radius, "m")
    checks.positive("width", width, "m")
    e, t = np.asarray(youngs_modulus, float), np.asarray(wall_thickness, float)
    return e * t * np.asarray(width, float) / np.asarray(radius, float) ** 2


def _shared_angles(theta_eval, theta_load, *params):
    """(θ_eval, θ_load, leading shape) when every case has the same angles and the parameters are scalars.

    Returns None otherwise. The element azimuths of a bearing are the same in every load case, so the
    influence matrix is formed once and broadcast over the cases: memory O(elements²), not
    O(cases × elements²).
    """
    te, tl = np.asarray(theta_eval, dtype=float), np.asarray(theta_load, dtype=float)
    if te.ndim < 1 or tl.ndim < 1 or any(np.ndim(p) for p in params):
        return None
    try:
        lead = np.broadcast_shapes(te.shape[:-1], tl.shape[:-1])
    except ValueError:
        return None
    if not lead:
        return None
    te2, tl2 = te.reshape(-1, te.shape[-1]), tl.reshape(-1, tl.shape[-1])
    if np.array_equal(te2, np.broadcast_to(te2[0], te2.shape)) and np.array_equal(
        tl2, np.broadcast_to(tl2[0], tl2.shape)
    ):
        return te2[0], tl2[0], lead
    return None


def radial_influence(theta_eval, theta_load, radius, flexural_rigidity, housing_stiffness=0.0):
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
    housing_stiffness : float or array (...) [N/m²]
        Winkler stiffness k_h of a bilateral housing (0: free ring, the default; np.inf: rigid
        housing, C = 0).

    Returns
    -------
    ndarray (..., M, N) [m/N]

    Notes
    -----
    .. math:: C_{mn} = \\frac{R^3}{\\pi EI} S_\\beta(\\theta_m - \\varphi_n), \\quad
              \\beta = k_h R^4/EI

    Symmetric for coincident point sets (Maxwell–Betti reciprocity) and positive semi-definite.
    Reference: Roark & Young 2012 §9.2; Li et al. 2025 (doi:10.3390/machines13090785) eq. 8.

    When every case (leading index) has the same angles and the parameters are scalars, the matrix
    is formed once and returned as a read-only broadcast view (memory of one M × N matrix).
    """
    checks.positive("radius", radius, "m")
    ei = _rigidity(flexural_rigidity)
    shared = _shared_angles(theta_eval, theta_load, radius, flexural_rigidity, housing_stiffness)
    if shared is not None:
        te, tl, lead = shared
        one = radial_influence(te, tl, radius, flexural_rigidity, housing_stiffness)
        return np.broadcast_to(one, (*lead, *one.shape))
    te = np.asarray(theta_eval, dtype=float)[..., :, None]
    tl = np.asarray(theta_load, dtype=float)[..., None, :]
    r = np.asarray(radius, dtype=float)[..., None, None]
    factor = r**3 / (np.pi * ei[..., None, None])
    beta = stiffness_ratio(radius, ei, housing_stiffness)[..., None, None]
    return factor * ring_radial_kernel(te - tl, beta)


def couple_influence(theta_eval, theta_load, radius, flexural_rigidity, housing_stiffness=0.0):
    """Influence matrix [m/(N·m)]: outward deflection at θ_eval per unit in-plane couple at θ_load.

    Parameters
    ----------
    theta_eval : array_like (..., M) [rad]
    theta_load : array_like (..., N) [rad]
    radius : float [m]
    flexural_rigidity : float [N·m²]
    housing_stiffness : float [N/m²]
        Winkler stiffness k_h of the housing (0: free ring).

    Returns
    -------
    ndarray (..., M, N) [m/(N·m)]

    Notes
    -----
    .. math:: C^{M}_{mn} = -\\frac{R^2}{\\pi EI} T_\\beta(\\theta_m - \\varphi_n)

    The couple is positive counter-clockwise about +z (the bearing axis); section rotation
    β = (v − w′)/R. Li et al. 2025 eq. (8), second sum. Angles shared by every case: a read-only
    broadcast view, as :func:`radial_influence`.
    """
    checks.positive("radius", radius, "m")
    _rigidity(flexural_rigidity)
    shared = _shared_angles(theta_eval, theta_load, radius, flexural_rigidity, housing_stiffness)
    if shared is not None:
        te, tl, lead = shared
        one = couple_influence(te, tl, radius, flexural_rigidity, housing_stiffness)
        return np.broadcast_to(one, (*lead, *one.shape))
    te = np.asarray(theta_eval, dtype=float)[..., :, None]
    tl = np.asarray(theta_load, dtype=float)[..., None, :]
    r = np.asarray(radius, dtype=float)[..., None, None]
    ei = np.asarray(flexural_rigidity, dtype=float)
    beta = stiffness_ratio(radius, ei, housing_stiffness)[..., None, None]
    return -(r**2) / (np.pi * ei[..., None, None]) * ring_couple_kernel(te - tl, beta)


def radial_deflection(
    theta_eval, theta_load, loads, radius, flexural_rigidity, couples=None, housing_stiffness=0.0
):
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
    housing_stiffness : float [N/m²]
        Winkler stiffness k_h of a bilateral housing (0: free ring; np.inf: no bending deflection).

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
    c = radial_influence(theta_eval, theta_load, radius, flexural_rigidity, housing_stiffness)
    w = np.einsum("...mn,...n->...m", c, q)
    if couples is not None:
        m = np.atleast_2d(np.asarray(couples, dtype=float))
        checks.finite("couples", m, "N·m")
        w = w + np.einsum(
            "...mn,...n->...m",
            couple_influence(theta_eval, theta_load, radius, flexural_rigidity, housing_stiffness),
            m,
        )
    return w
