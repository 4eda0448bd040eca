"""Contact laws of a tapered roller: raceway slices (Kunert, seed 001 eq. 4) and the rib (Hertz).

SI units (m, N, N/m, J). Each law returns load, stiffness dq/dδ and energy (∫ q dδ) for approaches
δ of any shape; an open contact (δ ≤ 0) carries nothing and has zero stiffness.

The seed-001 deviation law near contact opening
-----------------------------------------------
Seed 001 eq. (4) adds a roller diameter deviation to the line law by a first-order Taylor expansion
in Δ = ½ ΔD cos ε (Liu et al. 2022): q = c [δ^(10/9) + (10/9) δ^(1/9) Δ]. For Δ > 0 its stiffness
c [(10/9) δ^(1/9) + (10/81) Δ δ^(−8/9)] is unbounded as δ → 0⁺ and its load rises from zero like
δ^(1/9): a roller with Δ = 0.25 µm of the 32008J carries ~2 N at δ = 10⁻²⁴ m. Under a light load
the equilibrium approach of such a roller is ~(Q / (c (10/9) Δ))⁹ — 10⁻²⁴ m at F_a = 10 N — while
the ring and roller displacements it is the difference of are ~10⁻⁸ m: the equilibrium is not
representable in double precision, and neither the roller Newton iteration nor the global one can
reach its tolerance (issue 24: F_a = 10 N ran 343 s and did not converge). The expansion itself
needs |Δ| ≪ δ; its δ^(1/9) term there is an artefact of the linearisation.

bearingkit therefore applies eq. (4) as printed for δ ≥ :data:`TAYLOR_REGULAR_APPROACH` (1 nm) and
continues it below by the quadratic q = a δ + b δ² that matches its load and stiffness at 1 nm
(C¹, monotone, bounded stiffness ≈ 1.9 q(1 nm)/1 nm). Under a light axial load the rollers with
Δ > 0 then share it nearly in proportion to Δ_j, as under eq. (4) itself: at their common approach
δ < 1 nm each carries ≈ c (10/9)(3 − 10/9) Δ_j δ / (1 nm)^(8/9) (for Δ_j ≫ 1 nm), against eq. (4)'s
c (10/9) Δ_j δ^(1/9); the law changes only where a roller carries less than c (10/9) Δ (1 nm)^(1/9)
(≈ 49 N for Δ = 0.25 µm on the 32008J; the seed's own cases at 10 kN have δ ≈ 4 µm). The energy
is ∫₀^δ q: above 1 nm eq. (4)'s expression plus a constant per Δ > 0 contact.
Rollers with Δ ≤ 0 are unchanged (their eq. (4) load is zero up to δ = −(10/9) Δ and has a finite
stiffness from there).
"""

from __future__ import annotations

import numpy as np

from bearingkit.rows.tapered.geometry import LINE_EXPONENT

#: Approach below which seed 001 eq. (4) is continued quadratically for rollers with Δ > 0 [m].
#: Choice (bearingkit; the paper uses eq. 4 at 10 kN only, where δ ≈ 4 µm): 1 nm is a few atomic
#: spacings, below any meaning of a continuum contact law and far below every approach eq. (4) is
#: applied at in seed 001; above it the equilibrium of the δ^(1/9) law is representable and the
#: roller Newton converges in ≤ 10 steps (at 1 pm: up to its 40-step cap).
TAYLOR_REGULAR_APPROACH = 1e-9
#: Floor of the approach in the eq. (4) stiffness for Δ ≤ 0 (its δ^(−8/9) term) [m].
TAYLOR_DELTA_FLOOR = 1e-12


def kunert_law(delta, c):
    """Slice law q = c δ^(10/9) (Kunert 1961; seed 001 eq. 3) → (load [N], dq/dδ [N/m], energy [J])."""
    d = np.maximum(delta, 0.0)
    t = d ** (1.0 / 9.0)
    return c * d * t, (10.0 / 9.0) * c * t, c * d * d * t / (1.0 + LINE_EXPONENT)


def taylor_law(delta, dev, c):
    """Seed 001 eq. (4) with its continuation below :data:`TAYLOR_REGULAR_APPROACH` (module docstring).

    q = c [δ^(10/9) + (10/9) δ^(1/9) Δ] for δ ≥ δ_T or Δ ≤ 0 (clipped at 0), q = a δ + b δ² below δ_T
    for Δ > 0, with a = (2 q_T − k_T δ_T)/δ_T, b = (k_T δ_T − q_T)/δ_T² (q_T, k_T eq. (4)'s load and
    stiffness at δ_T).

    Parameters
    ----------
    delta : array [m]
        Approach δ of the nominal roller.
    dev : array broadcasting against delta [m]
        Δ = ½ ΔD cos ε of the roller.
    c : float [N/m^(10/9)]
        Slice stiffness constant.

    Returns
    -------
    load [N], stiffness [N/m], energy [J]
    """
    n = LINE_EXPONENT
    dv = dev
    d = np.maximum(delta, 0.0)
    q = c * d ** (n - 1.0) * (d + n * dv)
    on = (d > 0) & (q > 0)
    q = np.where(on, q, 0.0)
    df = np.maximum(d, TAYLOR_DELTA_FLOOR)
    k = np.where(on, c * (n * df ** (n - 1.0) + n * (n - 1.0) * dv * df ** (n - 2.0)), 0.0)
    ds = np.maximum(-n * dv, 0.0)
    e = np.where(on, c * ((d ** (n + 1) - ds ** (n + 1)) / (n + 1) + dv * (d**n - ds**n)), 0.0)
    d_t = TAYLOR_REGULAR_APPROACH
    low = (dv > 0.0) & (d < d_t)
    if not np.any(low):
        return q, k, e
    q_t = c * d_t ** (n - 1.0) * (d_t + n * dv)
    k_t = c * (n * d_t ** (n - 1.0) + n * (n - 1.0) * dv * d_t ** (n - 2.0))
    e_t = c * (d_t ** (n + 1) / (n + 1) + dv * d_t**n)
    a = (2.0 * q_t - k_t * d_t) / d_t
    b = (k_t * d_t - q_t) / (d_t * d_t)
    dl = np.minimum(d, d_t)
    q = np.where(low, a * dl + b * dl * dl, q)
    k = np.where(low, np.where(delta > 0.0, a + 2.0 * b * dl, 0.0), k)
    # Energy ∫₀^δ q: the continuation's own integral below δ_T; above, eq. (4)'s expression shifted
    # by the difference of the two integrals up to δ_T (so an open contact has exactly zero energy).
    e_low = a * d_t * d_t / 2.0 + b * d_t**3 / 3.0
    e = np.where(low, a * dl * dl / 2.0 + b * dl**3 / 3.0, np.where(dv > 0.0, e + (e_low - e_t), e))
    return q, k, e


def rib_law(delta, k_f):
    """Rib (sphere-on-plane Hertz) law Q = K_f δ^1.5 → (load [N], dQ/dδ [N/m], energy [J])."""
    d = np.maximum(delta, 0.0)
    r = np.sqrt(d)
    return k_f * d * r, 1.5 * k_f * r, k_f * d * d * r / 2.5
