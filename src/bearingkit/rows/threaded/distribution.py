"""Load shares of a planetary thread roller bearing (PTRB): over its rollers and over the teeth of a roller.

SI units (m, N, Pa, rad). The distribution factors of Zheng et al. (2022): f_r,i and f_rmax (radial
share of each roller) and f_a,i and f_amax (axial share of each tooth of one roller).

This module holds

* :func:`radial_roller_distribution` — the closed form of the radial share for rigid rings without
  clearance (what the row kernel :class:`~bearingkit.rows.threaded.row.ThreadedRow` gives for a pure radial
  load), giving f_r,i and f_rmax;
* :func:`axial_tooth_distribution` — the axial share of the teeth of one roller from Hertz contact,
  tooth bending/shear (:func:`tooth_compliance`) and axial compression of roller and rings (a
  thread-connection model in the spirit of Zheng et al. 2020 / Yamamoto), giving f_a,i and f_amax.

It is apart from the row kernel (:mod:`bearingkit.rows.threaded.row`) because these are models of their own
that the ratings and the friction model use without the quasi-static solve (the kernel takes equal tooth
shares, f_a,i = 1). :mod:`bearingkit.rows.threaded.row` re-exports these names.

References: ``zheng2022``, ``zheng2020``, ``stribeck1901``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.rows.base import azimuths
from bearingkit.rows.threaded.geometry import PTRBGeometry, contact_pairs

__all__ = [
    "RING_SUPPORTS",
    "SHEAR_COEFFICIENT",
    "ToothDistribution",
    "axial_tooth_distribution",
    "radial_roller_distribution",
    "tooth_compliance",
]

#: Timoshenko shear coefficient of a rectangular tooth section [1] (5/6 → factor 6/5 on shear).
SHEAR_COEFFICIENT = 5.0 / 6.0
#: How the rings are held axially in :func:`axial_tooth_distribution`: the inner ring is pushed at the
#: tooth-0 end; the outer ring is supported at the far end ("opposite", the usual shaft/housing shoulder
#: arrangement: both rings in compression) or at the same end ("same": outer ring in tension).
RING_SUPPORTS = ("opposite", "same")


# ---------------------------------------------------------------------------------------------
# Radial distribution over the rollers (rigid rings, no clearance)
# ---------------------------------------------------------------------------------------------
def radial_roller_distribution(n_elements, azimuth_phase=0.0):
    """Share of a radial load carried by each roller, rigid rings and zero clearance.

    Parameters
    ----------
    n_elements : int
        Z.
    azimuth_phase : array_like
        Azimuth of roller 0 from the load direction [rad], shape (C,) or scalar.

    Returns
    -------
    f_r : ndarray (C, Z)
        F_r,j / F_r, the radial force of roller j over the bearing's radial load [1].
    f_rmax : ndarray (C,)
        Largest share [1].

    Notes
    -----
    Every equivalent ball of roller j approaches by δ cos α cos ψ_j; Q ∝ δ^1.5, so (Stribeck 1901)

    .. math:: f_{r,j} = \\frac{\\cos^{1.5}\\psi_j}{\\sum_{\\cos\\psi_k > 0}\\cos^{2.5}\\psi_k}

    (f_rmax → 4.37/Z for many rollers with ψ_0 = 0).
    """
    psi = azimuths(checks.integer("n_elements", n_elements, low=1), azimuth_phase)
    c = np.clip(np.cos(psi), 0.0, None)
    share = c**1.5 / (c**2.5).sum(axis=-1, keepdims=True)
    return share, share.max(axis=-1)


# ---------------------------------------------------------------------------------------------
# Axial distribution over the teeth of one roller
# ---------------------------------------------------------------------------------------------
class ToothDistribution(NamedTuple):
    """Axial tooth loads of one roller (leading axis: load cases)."""

    load_inner: np.ndarray  #: (C, n) axial force of the ITP contacts [N]
    load_outer: np.ndarray  #: (C, n) axial force of the OTP contacts [N]
    fa_inner: np.ndarray  #: (C, n) f_Ia,i = ITP axial force / mean [1]
    fa_outer: np.ndarray  #: (C, n) f_Oa,i [1]
    fa_max: np.ndarray  #: (C,) max of f_Ia,i and f_Oa,i [1]
    converged: np.ndarray  #: (C,) bool
    iterations: int


def tooth_compliance(geometry: PTRBGeometry, part: str):
    """Axial compliance of one thread tooth under one contact load [m/N] (cantilever, bending + shear).

    Parameters
    ----------
    geometry : PTRBGeometry
    part : {"roller", "inner", "outer"}

    Notes
    -----
    A tooth is a cantilever of length h (dedendum), root thickness B_X and width w loaded axially at
    its tip (Timoshenko beam):

    .. math:: c = \\frac{4h^3}{E w B_X^3} + \\frac{h}{\\kappa G w B_X},\\qquad G = \\frac{E}{2(1+\\nu)}

    w = π d_X / Z for a ring tooth (Z contacts share it), π d_R / 2 for a roller tooth (one ITP and one
    OTP contact). An assumption of bearingkit (Zheng et al. 2020 use a thread-tooth model after
    Yamamoto, not printed); the teeth are short (h ≪ B), so this term is small beside Hertz.
    """
    g = geometry
    e, nu, h = g.youngs_modulus, g.poisson_ratio, g.dedendum
    width = {
        "roller": np.pi * g.roller_pitch_diameter / 2.0,
        "inner": np.pi * g.d_inner / g.n_elements,
        "outer": np.pi * g.d_outer / g.n_elements,
    }
    thick = {
        "roller": g.bottom_thickness_roller,
        "inner": g.bottom_thickness_inner,
        "outer": g.bottom_thickness_outer,
    }
    checks.one_of("part", part, width)
    w, b = width[part], thick[part]
    shear_mod = e / (2.0 * (1.0 + nu))
    return 4.0 * h**3 / (e * w * b**3) + h / (SHEAR_COEFFICIENT * shear_mod * w * b)


def _body_compliances(g: PTRBGeometry):
    """Axial compliance of one pitch of roller, inner and outer ring, per roller [m/N]."""
    e, h, p = g.youngs_modulus, g.dedendum, g.thread_pitch
    area_r = np.pi / 4.0 * (g.roller_pitch_diameter - 2 * h) ** 2
    area_i = np.pi / 4.0 * ((g.d_inner - 2 * h) ** 2 - g.bore_diameter**2)
    area_o = np.pi / 4.0 * (g.outside_diameter**2 - (g.d_outer + 2 * h) ** 2)
    if area_i <= 0 or area_o <= 0:
        raise InputError(
            "the ring sections (bore to thread root, thread root to outside) must have positive area"
        )
    # a ring section carries the teeth loads of all Z rollers
    return p / (e * area_r), g.n_elements * p / (e * area_i), g.n_elements * p / (e * area_o)


def axial_tooth_distribution(
    geometry: PTRBGeometry, load_axial, ring_support: str = "opposite", max_iter: int = 60, tol: float = 1e-10
) -> ToothDistribution:
    """Axial load shares of the n teeth of a roller under a centric axial load.

    Parameters
    ----------
    geometry : PTRBGeometry
    load_axial : array_like
        Bearing axial load F_a [N], > 0, shape (C,) or scalar; each roller carries F_a / Z.
    ring_support : {"opposite", "same"}
        Where the outer ring is held (:data:`RING_SUPPORTS`); the inner ring is loaded at the tooth-0 end.
    max_iter : int
        Newton iterations.
    tol : float
        Convergence on the relative Newton step of y = F^(1/3) [1].

    Returns
    -------
    ToothDistribution

    Notes
    -----
    Unknowns: ITP and OTP axial forces F_I,i, F_O,i, the roller displacement w_0 and the inner-ring
    displacement U. Compatibility at tooth i (axial approaches):

    .. math::
        g_I(F_{I,i}) = u_{I,i} - w_i,\\qquad g_O(F_{O,i}) = w_i - u_{O,i},\\qquad
        \\sum_i F_{I,i} = \\sum_i F_{O,i} = F_a/Z

    with g(F) = (F/(K\\sin\\alpha))^{2/3}/\\sin\\alpha + (c_{tooth,R} + c_{tooth,X}) F (Hertz approach
    projected on the axis, tooth bending/shear), u_I,i = U − λ_I Σ_j min(i, j) F_I,j,
    u_O,i = λ_O Σ_j min(e_i, e_j) F_O,j (e_i pitches from the outer-ring support) and
    w_i = w_0 − λ_R Σ_j max(i − j, 0)(F_I,j − F_O,j) (axial compression of ring and roller cores, λ = P/(EA)).
    Solved by Newton's method in y = F^{1/3} (smooth at small loads), batched over the load cases.
    Follows the thread-connection approach of Zheng et al. (2020) (doi:10.1155/2020/9593051).
    """
    g = geometry
    checks.one_of("ring_support", ring_support, RING_SUPPORTS)
    fa = np.atleast_1d(np.asarray(checks.positive("load_axial", load_axial, "N"), dtype=float))
    n, sa = g.n_teeth, np.sin(g.contact_angle)
    pairs = contact_pairs(g)
    coef = {}
    for side in ("inner", "outer"):
        a_h = (1.0 / (pairs[side].stiffness_point * sa)) ** (2.0 / 3.0) / sa
        coef[side] = (float(a_h), float(tooth_compliance(g, "roller") + tooth_compliance(g, side)))
    lam_r, lam_i, lam_o = _body_compliances(g)
    idx = np.arange(n)
    dist_i = idx
    dist_o = (n - 1 - idx) if ring_support == "opposite" else idx
    a_i = lam_i * np.minimum.outer(dist_i, dist_i)
    a_o = lam_o * np.minimum.outer(dist_o, dist_o)
    t = lam_r * np.maximum(idx[:, None] - idx[None, :], 0)
    f_roller = fa / g.n_elements  # (C,)
    c = fa.size
    y = np.repeat((f_roller / n)[:, None] ** (1.0 / 3.0), 2 * n, axis=1)  # (C, 2n)
    (ai, ci), (ao, co) = coef["inner"], coef["outer"]
    w0 = ao * y[:, 0] ** 2 + co * y[:, 0] ** 3
    u = w0 + ai * y[:, 0] ** 2 + ci * y[:, 0] ** 3
    converged = np.zeros(c, dtype=bool)
    iterations = 0
    for it in range(1, max_iter + 1):
        iterations = it
        yi, yo = y[:, :n], y[:, n:]
        fi, fo = yi**3, yo**3
        w = w0[:, None] - (fi - fo) @ t.T
        r = np.concatenate(
            [
                ai * yi**2 + ci * fi - (u[:, None] - fi @ a_i.T - w),
                ao * yo**2 + co * fo - (w - fo @ a_o.T),
                (fi.sum(axis=1) - f_roller)[:, None] * (ai / f_roller[:, None] ** (1 / 3)),
                (fo.sum(axis=1) - f_roller)[:, None] * (ai / f_roller[:, None] ** (1 / 3)),
            ],
            axis=1,
        )
        di, do = 3 * yi**2, 3 * yo**2
        jac = np.zeros((c, 2 * n + 2, 2 * n + 2))
        jac[:, :n, :n] = (a_i - t)[None] * di[:, None, :] + np.einsum(
            "ci,ij->cij", 2 * ai * yi + ci * di, np.eye(n)
        )
        jac[:, :n, n : 2 * n] = t[None] * do[:, None, :]
        jac[:, :n, 2 * n] = 1.0
        jac[:, :n, 2 * n + 1] = -1.0
        jac[:, n : 2 * n, :n] = t[None] * di[:, None, :]
        jac[:, n : 2 * n, n : 2 * n] = (a_o - t)[None] * do[:, None, :] + np.einsum(
            "ci,ij->cij", 2 * ao * yo + co * do, np.eye(n)
        )
        jac[:, n : 2 * n, 2 * n] = -1.0
        scale = ai / f_roller ** (1 / 3)
        jac[:, 2 * n, :n] = di * scale[:, None]
        jac[:, 2 * n + 1, n : 2 * n] = do * scale[:, None]
        step = np.linalg.solve(jac, -r[..., None])[..., 0]
        dy = step[:, : 2 * n]
        y = np.maximum(y + dy, 0.2 * y)  # damped: loads stay positive
        w0 = w0 + step[:, 2 * n]
        u = u + step[:, 2 * n + 1]
        converged = np.max(np.abs(dy) / y, axis=1) < tol
        if converged.all():
            break
    fi, fo = y[:, :n] ** 3, y[:, n:] ** 3
    mean = (f_roller / n)[:, None]
    fai, fao = fi / mean, fo / mean
    return ToothDistribution(
        fi, fo, fai, fao, np.maximum(fai.max(axis=1), fao.max(axis=1)), converged, iterations
    )
