"""Axial load sharing over the teeth of a planetary thread roller, batched over designs (f_amax).

SI units (N, m). The maximum axial load-distribution coefficient f_amax of Zheng et al. (2022, eqs. 2
and 11) is the largest tooth load of a roller over the mean tooth load. Zheng et al. take it from their
load-distribution model (Zheng et al. 2020) without printing it; their Table 4 implies it varies with
the design (from C0a and Ca alike, to 0.4 %: 1.035 at α = 30° … 1.096 at n = 16). This module computes it
from a thread-connection model — Hertz approach and tooth bending of every ITP/OTP contact, axial
compression of roller and ring cores between the teeth — for a whole population of designs at once
(the design optimisation evaluates thousands), grouped by the tooth count n.

The per-geometry model of the same equations, :func:`bearingkit.rows.threaded.distribution.
axial_tooth_distribution`, is this function's test oracle.

References: ``zheng2022`` (doi:10.3390/machines10111051), ``zheng2020`` (doi:10.1155/2020/9593051).
"""

from __future__ import annotations

import functools

import numpy as np

from bearingkit import checks

__all__ = ["SUPPORTS", "max_tooth_share", "tooth_load_shares"]

#: Outer-ring support relative to the end where the inner ring is loaded (tooth 0): "opposite" (both
#: rings in compression, the usual shaft/housing shoulders) or "same" (outer ring in tension).
SUPPORTS = ("opposite", "same")


def _arr(x, c):
    return np.broadcast_to(np.asarray(x, dtype=float), (c,)).astype(float)


#: The coefficient arrays of :func:`tooth_load_shares`, in the order of its signature.
_COEFFICIENTS = (
    "hertz_inner",
    "hertz_outer",
    "tooth_inner",
    "tooth_outer",
    "body_roller",
    "body_inner",
    "body_outer",
)


def _checked(coefficients: dict, c: int) -> tuple:
    """The (C,) coefficient arrays in :data:`_COEFFICIENTS` order, checked: a_H > 0, compliances ≥ 0."""
    out = []
    for k in _COEFFICIENTS:
        v = coefficients[k]
        ok = checks.positive(k, v, "m/N^(2/3)") if k.startswith("hertz") else checks.non_negative(k, v, "m/N")
        out.append(_arr(ok, c))
    return tuple(out)


def tooth_load_shares(
    roller_load,
    n_teeth: int,
    hertz_inner,
    hertz_outer,
    tooth_inner,
    tooth_outer,
    body_roller,
    body_inner,
    body_outer,
    support: str = "opposite",
    max_iter: int = 60,
    tol: float = 1e-10,
):
    """Axial tooth loads of one roller for a batch of designs with the same tooth count.

    Parameters
    ----------
    roller_load : array_like (C,) [N]
        Axial load of one roller F_a/Z, > 0.
    n_teeth : int
        Teeth per roller n (≥ 1).
    hertz_inner, hertz_outer : array_like (C,) [m/N^(2/3)]
        Axial Hertz approach coefficient a_H of an ITP / OTP contact: g = a_H F^(2/3) for the axial force
        F (a_H = (K sin α)^(−2/3) / sin α with the normal stiffness K, Q = K δ^1.5).
    tooth_inner, tooth_outer : array_like (C,) [m/N]
        Axial compliance of the roller tooth plus the ring tooth of an ITP / OTP contact.
    body_roller, body_inner, body_outer : array_like (C,) [m/N]
        Axial compliance of one thread pitch of the roller core, and of the inner / outer ring core per
        roller (P/(E A), the ring's for Z rollers multiplied by Z).
    support : {"opposite", "same"}
        :data:`SUPPORTS`.
    max_iter : int
    tol : float
        Convergence on the relative Newton step of y = F^(1/3).

    Returns
    -------
    load_inner, load_outer : ndarray (C, n) [N]
        Axial forces of the ITP and OTP contacts, tooth 0 at the loaded end.
    fa_max : ndarray (C,) [1]
        f_amax = max over both contact rows of F_i / (F_a/(Z n)).
    converged : ndarray (C,) bool

    Notes
    -----
    Compatibility at tooth i with roller displacement w_i and ring displacements u_I,i, u_O,i:

    .. math::
        g_I(F_{I,i}) = u_{I,i} - w_i,\\qquad g_O(F_{O,i}) = w_i - u_{O,i},\\qquad
        \\sum_i F_{I,i} = \\sum_i F_{O,i} = F_a/Z

    g(F) = a_H F^{2/3} + c F; u_I,i = U − λ_I Σ_j min(i, j) F_I,j; u_O,i = λ_O Σ_j min(e_i, e_j) F_O,j
    (e_i pitches from the outer-ring support); w_i = w_0 − λ_R Σ_j max(i − j, 0)(F_I,j − F_O,j). Newton in
    y = F^(1/3). A thread-connection model after Zheng et al. (2020) (bolt–nut analogue); the same
    equations as :func:`bearingkit.rows.threaded.distribution.axial_tooth_distribution`.
    """
    checks.one_of("support", support, SUPPORTS)
    n = checks.integer("n_teeth", n_teeth, low=1)
    f_roller = np.atleast_1d(np.asarray(checks.positive("roller_load", roller_load, "N"), dtype=float))
    given = dict(
        hertz_inner=hertz_inner, hertz_outer=hertz_outer, tooth_inner=tooth_inner, tooth_outer=tooth_outer,
        body_roller=body_roller, body_inner=body_inner, body_outer=body_outer,
    )  # fmt: skip
    return _shares(f_roller, n, *_checked(given, f_roller.size), support, max_iter, tol)


@functools.cache
def _coupling(n: int, support: str):
    """The (n, n) coupling patterns min(i, j), min(e_i, e_j) and max(i − j, 0) [1] (read-only)."""
    idx = np.arange(n)
    dist_o = (n - 1 - idx) if support == "opposite" else idx
    out = (
        np.minimum.outer(idx, idx).astype(float),
        np.minimum.outer(dist_o, dist_o).astype(float),
        np.maximum(idx[:, None] - idx[None, :], 0).astype(float),
    )
    for m in out:
        m.flags.writeable = False
    return out


def _shares(f_roller, n, ai, ao, ci, co, lr, li, lo, support, max_iter, tol):
    """The Newton loop of :func:`tooth_load_shares` on checked (C,) float arrays (SI, see there)."""
    c = f_roller.size
    m_i, m_o, m_t = _coupling(n, support)
    a_i = li[:, None, None] * m_i  # (C, n, n)
    a_o = lo[:, None, None] * m_o
    t = lr[:, None, None] * m_t
    y = np.repeat((f_roller / n)[:, None] ** (1.0 / 3.0), 2 * n, axis=1)
    w0 = ao * y[:, 0] ** 2 + co * y[:, 0] ** 3
    u = w0 + ai * y[:, 0] ** 2 + ci * y[:, 0] ** 3
    scale = ai / f_roller ** (1.0 / 3.0)  # equation scaling of the two sums (lengths, like the others)
    converged = np.zeros(c, dtype=bool)
    # What does not change between iterations is formed once (issue 34: this loop was half of the
    # PTRB design optimisation's evaluator): the coupling matrices, the Jacobian's constant entries
    # (±1 columns, zeros), the views of its blocks and of its diagonal. Every value is computed as
    # before, bit for bit: the same products and sums of the same numbers, each y-block entry one
    # product as before, the diagonal terms added to the diagonal in place instead of adding a
    # diagonal matrix (whose zeros leave the other entries as they are), y² formed once for the
    # residual and the Jacobian (a square is exact whatever the array's layout).
    m = 2 * n + 2
    jac = np.zeros((c, m, m))
    jac[:, :n, 2 * n] = 1.0
    jac[:, :n, 2 * n + 1] = -1.0
    jac[:, n : 2 * n, 2 * n] = -1.0
    # The y-block of the Jacobian is [[a_i − t, t], [t, a_o − t]] times 3y² column by column, its
    # diagonal plus 2 a_H y + c 3y² (a_H, c of the ITP for the first n, of the OTP for the last n).
    coupling = np.empty((c, 2 * n, 2 * n))
    coupling[:, :n, :n] = a_i - t
    coupling[:, :n, n:] = t
    coupling[:, n:, :n] = t
    coupling[:, n:, n:] = a_o - t
    j_yy = jac[:, : 2 * n, : 2 * n]
    diag = jac.reshape(c, m * m)[:, : 2 * n * (m + 1) : m + 1]  # a view: entry (k, k) is k (m + 1)
    row_i, row_o = jac[:, 2 * n, :n], jac[:, 2 * n + 1, n : 2 * n]
    ai_, ci_, ao_, co_, scale_ = ai[:, None], ci[:, None], ao[:, None], co[:, None], scale[:, None]
    two_a = np.concatenate([np.repeat(2 * ai_, n, axis=1), np.repeat(2 * ao_, n, axis=1)], axis=1)
    c_io = np.concatenate([np.repeat(ci_, n, axis=1), np.repeat(co_, n, axis=1)], axis=1)
    w0, u = w0[:, None], u[:, None]
    r = np.empty((c, m, 1))
    r_i, r_o, r_si, r_so = r[:, :n, 0], r[:, n : 2 * n, 0], r[:, 2 * n, 0], r[:, 2 * n + 1, 0]
    for _ in range(max_iter):
        yi, yo = y[:, :n], y[:, n:]
        fi, fo = yi**3, yo**3
        y2 = y**2
        w = w0 - np.einsum("cij,cj->ci", t, fi - fo)
        r_i[...] = ai_ * y2[:, :n] + ci_ * fi - (u - np.einsum("cij,cj->ci", a_i, fi) - w)
        r_o[...] = ao_ * y2[:, n:] + co_ * fo - (w - np.einsum("cij,cj->ci", a_o, fo))
        r_si[...] = (fi.sum(axis=1) - f_roller) * scale
        r_so[...] = (fo.sum(axis=1) - f_roller) * scale
        d = 3 * y2
        np.multiply(coupling, d[:, None, :], out=j_yy)
        diag += two_a * y + c_io * d
        np.multiply(d[:, :n], scale_, out=row_i)
        np.multiply(d[:, n:], scale_, out=row_o)
        step = np.linalg.solve(jac, np.negative(r))[..., 0]
        dy = step[:, : 2 * n]
        y = np.maximum(y + dy, 0.2 * y)  # damped: loads stay positive
        w0 = w0 + step[:, 2 * n : 2 * n + 1]
        u = u + step[:, 2 * n + 1 :]
        converged = np.max(np.abs(dy) / y, axis=1) < tol
        if converged.all():
            break
    fi, fo = y[:, :n] ** 3, y[:, n:] ** 3
    mean = (f_roller / n)[:, None]
    fa_max = np.maximum((fi / mean).max(axis=1), (fo / mean).max(axis=1))
    return fi, fo, fa_max, converged


def _grouped_shares(f_roller, n_all, ai, ao, ci, co, lr, li, lo, support, max_iter, tol):
    """f_amax (C,) and converged (C,) of designs with any tooth counts: :func:`_shares` per group of equal
    n (the numpy solver of :func:`max_tooth_share`; the oracle of the compiled one)."""
    fa = np.empty(f_roller.size)
    conv = np.empty(f_roller.size, dtype=bool)
    coefs = (ai, ao, ci, co, lr, li, lo)
    for n in np.unique(n_all):
        sel = n_all == n
        _, _, fa[sel], conv[sel] = _shares(
            f_roller[sel], int(n), *(v[sel] for v in coefs), support, max_iter, tol
        )
    return fa, conv


def max_tooth_share(roller_load, n_teeth, *, solver=None, **coefficients):
    """f_amax [1] (C,) of designs that may differ in n: :func:`tooth_load_shares` per group of equal n.

    Parameters
    ----------
    roller_load : array_like (C,) [N]
    n_teeth : array_like (C,) int
    solver : callable, optional
        What solves the checked arrays: ``solver(f_roller, n_teeth, a_H,I, a_H,O, c_I, c_O, λ_R, λ_I, λ_O,
        support, max_iter, tol) -> (f_amax, converged)``. Default: the numpy Newton per tooth count;
        :func:`bearingkit.rows.threaded.compiled_sharing.max_tooth_share` is the compiled one (the
        same equations, agreeing to 1e-10: tests/rows/test_compiled_sharing.py).
    **coefficients
        The (C,) coefficient arrays of :func:`tooth_load_shares` (and ``support``).
    """
    n_all = np.rint(np.atleast_1d(np.asarray(n_teeth, dtype=float))).astype(int)
    c = n_all.size
    support = coefficients.pop("support", "opposite")
    max_iter, tol = coefficients.pop("max_iter", 60), coefficients.pop("tol", 1e-10)
    if set(coefficients) != set(_COEFFICIENTS):
        raise TypeError(
            f"max_tooth_share() takes the coefficients {', '.join(_COEFFICIENTS)}; got {list(coefficients)}"
        )
    # The checks of tooth_load_shares, made once for all designs (a group passes them iff all do).
    checks.one_of("support", support, SUPPORTS)
    for n in np.unique(n_all):
        checks.integer("n_teeth", int(n), low=1)
    f_roller = _arr(checks.positive("roller_load", _arr(roller_load, c), "N"), c)
    coefs = _checked(coefficients, c)
    fa, conv = (solver or _grouped_shares)(f_roller, n_all, *coefs, support, max_iter, tol)
    if not conv.all():
        bad = np.unique(n_all[~conv])
        raise checks.InputError(
            f"the tooth load sharing of {int((~conv).sum())} design(s) with n = "
            f"{', '.join(str(int(n)) for n in bad)} did not converge; check the geometry (positive "
            "stiffnesses and areas)"
        )
    return fa


#: Timoshenko shear coefficient of a rectangular tooth section [1] (as rows.threaded_distribution).
SHEAR_COEFFICIENT = 5.0 / 6.0


def _tooth_compliance(e, nu, h, width, thickness):
    """Axial compliance of one tooth under its contact load [m/N]: cantilever bending + shear."""
    g = e / (2.0 * (1.0 + nu))
    return 4.0 * h**3 / (e * width * thickness**3) + h / (SHEAR_COEFFICIENT * g * width * thickness)


def design_f_amax(
    axial_load,
    *,
    n_elements,
    n_teeth,
    contact_angle,
    roller_pitch_diameter,
    inner_pitch_diameter,
    outer_pitch_diameter,
    roller_contact_radius,
    contact_radius_inner,
    contact_radius_outer,
    thread_pitch,
    dedendum,
    bottom_thickness_roller,
    bottom_thickness_inner,
    bottom_thickness_outer,
    bore_diameter,
    outside_diameter,
    youngs_modulus,
    poisson_ratio,
    body_compliance_factor=1.0,
    support="opposite",
    solver=None,
):
    """f_amax [1] of PTRB designs (arrays broadcast to (C,)) under the bearing axial load ``axial_load``.

    Parameters
    ----------
    axial_load : array_like [N]
        Bearing axial load F_a (each roller carries F_a/Z).
    n_elements, n_teeth : array_like
        Z and n [1].
    contact_angle : array_like [rad]
    roller_pitch_diameter, inner_pitch_diameter, outer_pitch_diameter : array_like [m]
        d_R, d_I, d_O.
    roller_contact_radius, contact_radius_inner, contact_radius_outer : array_like [m]
        R_rr, r_I, r_O (inf: flat ring flank).
    thread_pitch, dedendum : array_like [m]
        P and the tooth dedendum h.
    bottom_thickness_roller, bottom_thickness_inner, bottom_thickness_outer : array_like [m]
        B_R, B_I, B_O.
    bore_diameter, outside_diameter : array_like [m]
        d_0, D_0 (the ring cores run from the bore to the inner thread root and from the outer thread
        root to the outside).
    youngs_modulus, poisson_ratio : array_like
        E [Pa], ν [1] of all parts.
    body_compliance_factor : array_like [1]
        Multiplier of the core compliances P/(E A) (1: the bare core sections).
    support : {"opposite", "same"}
    solver : callable, optional
        :func:`max_tooth_share`'s ``solver`` (default: numpy).

    Notes
    -----
    Coefficients of :func:`tooth_load_shares`: K of each contact from Hertz (Zheng et al. 2022 eq. 2
    curvatures, :func:`bearingkit.physics.life.ptrb_rating.thread_contact_curvature`), a_H =
    (K sin α)^(−2/3)/sin α; tooth compliance 4h³/(E w B³) + h/(κ G w B) with w = π d_R/2 (roller tooth:
    one ITP and one OTP contact) and π d_X/Z (ring tooth shared by Z rollers); core compliances
    P/(E A) with A_R = π(d_R − 2h)²/4, A_I = π((d_I − 2h)² − d_0²)/4, A_O = π(D_0² − (d_O + 2h)²)/4, the
    ring cores per roller ×Z. Identical to :func:`bearingkit.rows.threaded.distribution.
    axial_tooth_distribution` (tested) with the body compliances multiplied by the factor.
    """
    from bearingkit.physics.contact import hertz
    from bearingkit.physics.life.ptrb_rating import thread_contact_curvature

    arrays = np.broadcast_arrays(
        *(
            np.atleast_1d(np.asarray(v, dtype=float))
            for v in (
                axial_load,
                n_elements,
                n_teeth,
                contact_angle,
                roller_pitch_diameter,
                inner_pitch_diameter,
                outer_pitch_diameter,
                roller_contact_radius,
                contact_radius_inner,
                contact_radius_outer,
                thread_pitch,
                dedendum,
                bottom_thickness_roller,
                bottom_thickness_inner,
                bottom_thickness_outer,
                bore_diameter,
                outside_diameter,
                youngs_modulus,
                poisson_ratio,
                body_compliance_factor,
            )
        )
    )
    (fa, z, n, alpha, d_r, d_i, d_o, r_rr, r_i, r_o, p, h, b_r, b_i, b_o, d0, dd0, e, nu, kb) = arrays
    checks.non_negative("body_compliance_factor", kb)
    e_red = e / (1.0 - nu**2)
    sa = np.sin(alpha)
    a_h = {}
    for side, d_x, r_x in (("inner", d_i, r_i), ("outer", d_o, r_o)):
        srho, frho, _, _ = thread_contact_curvature(d_r, d_x, r_rr, r_x, alpha, side)
        k = hertz.point_stiffness(srho, frho, e_red)
        a_h[side] = (1.0 / (k * sa)) ** (2.0 / 3.0) / sa
    c_roller = _tooth_compliance(e, nu, h, np.pi * d_r / 2.0, b_r)
    c_inner = _tooth_compliance(e, nu, h, np.pi * d_i / z, b_i)
    c_outer = _tooth_compliance(e, nu, h, np.pi * d_o / z, b_o)
    area_r = np.pi / 4.0 * (d_r - 2 * h) ** 2
    area_i = np.pi / 4.0 * ((d_i - 2 * h) ** 2 - d0**2)
    area_o = np.pi / 4.0 * (dd0**2 - (d_o + 2 * h) ** 2)
    if np.any(area_i <= 0) or np.any(area_o <= 0) or np.any(area_r <= 0):
        raise checks.InputError(
            "the core sections of roller and rings (bore to inner thread root, outer thread root to outside) "
            "must have positive area"
        )
    return max_tooth_share(
        fa / z,
        n,
        hertz_inner=a_h["inner"],
        hertz_outer=a_h["outer"],
        tooth_inner=c_roller + c_inner,
        tooth_outer=c_roller + c_outer,
        body_roller=kb * p / (e * area_r),
        body_inner=kb * z * p / (e * area_i),
        body_outer=kb * z * p / (e * area_o),
        support=support,
        solver=solver,
    )
