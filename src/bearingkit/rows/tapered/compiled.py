"""Compiled per-case response of tapered roller rows (numba): the roller sub-problem and condensation.

SI units. The same model and algorithm as :class:`bearingkit.rows.tapered.kernel.TaperedKernel`
(the reference): per roller, a bounded damped Newton iteration on its 2 DOF X minimising
Φ = Σ E_c(δ_c) − F_c·X (cone slices, cup slices, rib; :mod:`bearingkit.rows.tapered.laws`), warm
started from the case's previous call (X moved to first order with the ring) or the closed-form
guess, whichever is lower in Φ; then the condensed force, the Schur-complement stiffness and the
energy. Here one case is computed roller by roller, so a compiled Newton loop over the ring DOF can
call it without batch temporaries. Every tapered row of a bearing is packed into one set of arrays
(:func:`pack_tapered`); the per-case warm start lives in a small workspace (:func:`workspace`).
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np

from bearingkit.rows.numba_cache import configure
from bearingkit.rows.tapered.kernel import (
    ROLLER_MAX_HALVINGS,
    ROLLER_MAX_ITER,
    ROLLER_NOISE_EPS,
    ROLLER_RTOL,
    ROLLER_STALL_RTOL,
    ROLLER_STEP_CAP,
)
from bearingkit.rows.tapered.laws import TAYLOR_DELTA_FLOOR, TAYLOR_REGULAR_APPROACH

configure()  # before numba reads its configuration: the cache follows the compiled sources
from numba import njit, prange  # noqa: E402

#: Packed tapered rows (T rollers, S ≥ n_s slots): cone directions gi (T, S, 5), rib gf (T, 5); constant
#: approach parts d0i, d0e (Ct, T, S), Δ dev (Ct, T) and the centrifugal force fc (Ct, T): a row whose
#: load cases run at several speeds has one per case; slices ns (T,); local directions bi, be, bf
#: (T, 2); per-roller constants cs, kf, floor (stiffness floor), ffloor (force floor), cap (step
#: cap), taylor (1.0 for seed 001 eq. 4); row (T,) the row index; lc (Ct, T, 5) the constants of the
#: eq. (4) law of each roller and case (:func:`_consts`; zeros for the Kunert law), computed once.
TaperedPack = namedtuple(
    "TaperedPack", "gi gf d0i d0e dev ns bi be bf cs kf fc floor ffloor cap taylor row lc"
)

N_LINE = 10.0 / 9.0


def pack_tapered(kernels, rows) -> TaperedPack:
    """Flatten :class:`~bearingkit.rows.tapered.kernel.TaperedKernel` s (their row indices ``rows``)."""
    if not kernels:
        z2 = np.zeros((0, 2))
        z0 = np.zeros(0)
        return TaperedPack(
            np.zeros((0, 1, 5)), np.zeros((0, 5)), np.zeros((1, 0, 1)), np.zeros((1, 0, 1)), np.zeros((1, 0)),
            np.zeros(0, np.int64), z2, z2, z2, z0, z0, np.zeros((1, 0)), z0, z0, z0, z0,
            np.zeros(0, np.int64),
            np.zeros((1, 0, 5)),
        )  # fmt: skip
    s_max = max(k.row.n_slices for k in kernels)
    lead = max(max(k.d0_i.shape[0], k.d0_e.shape[0], k.delta_dev.shape[0], k.f_c.shape[0]) for k in kernels)
    parts = {f: [] for f in TaperedPack._fields if f != "lc"}
    for kern, r in zip(kernels, rows, strict=True):
        z, n_s = kern.row.n_elements, kern.row.n_slices
        gi = np.zeros((z, s_max, 5))
        gi[:, :n_s] = kern.g_i
        parts["gi"].append(gi)
        parts["gf"].append(kern.g_f)
        for name, attr in (("d0i", "d0_i"), ("d0e", "d0_e")):
            a = np.zeros((lead, z, s_max))
            a[:, :, :n_s] = np.broadcast_to(getattr(kern, attr), (lead, z, n_s))
            parts[name].append(a)
        parts["dev"].append(np.broadcast_to(kern.delta_dev, (lead, z)))
        parts["fc"].append(np.broadcast_to(kern.f_c, (lead, z)))
        parts["ns"].append(np.full(z, n_s, np.int64))
        for name in ("bi", "be", "bf"):
            parts[name].append(np.broadcast_to(getattr(kern, "b_" + name[1]), (z, 2)))
        scalars = {
            "cs": kern.c_s,
            "kf": kern.k_f,
            "floor": kern.stiffness_floor,
            "ffloor": kern.force_floor,
            "cap": ROLLER_STEP_CAP * kern.row.element_diameter,
            "taylor": 1.0 if kern.taylor else 0.0,
        }
        for name, value in scalars.items():
            parts[name].append(np.full(z, float(value)))
        parts["row"].append(np.full(z, r, np.int64))
    out = {}
    for name, arrays in parts.items():
        axis = 1 if name in ("d0i", "d0e", "dev", "fc") else 0
        out[name] = np.ascontiguousarray(np.concatenate(arrays, axis=axis))
    out["lc"] = _consts_table(out["dev"], out["cs"], out["taylor"])
    return TaperedPack(**out)


def workspace(pack: TaperedPack):
    """Per-case warm-start storage: X (T, 2), sensitivity (T, 5, 2), previous q (5,), flag (1,)."""
    t = pack.gf.shape[0]
    return np.zeros((t, 2)), np.zeros((t, 5, 2)), np.zeros(5), np.zeros(1)


@njit(cache=True, error_model="numpy")
def _consts(dv, c):
    """Per-roller constants of the eq. (4) law: continuation a, b, energy shift, ds^(n+1), ds^n."""
    n = N_LINE
    d_t = TAYLOR_REGULAR_APPROACH
    ds = max(-n * dv, 0.0)
    if dv <= 0.0:
        return 0.0, 0.0, 0.0, ds ** (n + 1), ds**n
    q_t = c * d_t ** (n - 1.0) * (d_t + n * dv)
    k_t = c * (n * d_t ** (n - 1.0) + n * (n - 1.0) * dv * d_t ** (n - 2.0))
    e_t = c * (d_t ** (n + 1) / (n + 1) + dv * d_t**n)
    a = (2.0 * q_t - k_t * d_t) / d_t
    b = (k_t * d_t - q_t) / (d_t * d_t)
    return a, b, (a * d_t * d_t / 2.0 + b * d_t**3 / 3.0) - e_t, 0.0, 0.0


@njit(cache=True, error_model="numpy")
def _consts_table(dev, cs, taylor):
    """:func:`_consts` of every roller and case (Ct, T, 5): constant for the whole solve."""
    out = np.zeros((dev.shape[0], dev.shape[1], 5))
    for c in range(dev.shape[0]):
        for t in range(dev.shape[1]):
            if taylor[t] != 0.0:
                a, b, e, p1, p0 = _consts(dev[c, t], cs[t])
                out[c, t, 0] = a
                out[c, t, 1] = b
                out[c, t, 2] = e
                out[c, t, 3] = p1
                out[c, t, 4] = p0
    return out


@njit(cache=True, error_model="numpy")
def _row_consts(tp, cc, t):
    """The roller's :func:`_consts` as a tuple of scalars (an array view passed down to every slice
    law call costs a reference count each time: twice the cost of the law itself)."""
    return (tp.lc[cc, t, 0], tp.lc[cc, t, 1], tp.lc[cc, t, 2], tp.lc[cc, t, 3], tp.lc[cc, t, 4])


@njit(cache=True, error_model="numpy")
def _line(d_raw, dv, c, taylor, lc):
    """Slice law (load, stiffness, energy): Kunert, or seed 001 eq. (4) with its continuation.

    ``lc`` = :func:`_consts` of the roller (constant per roller and case): one power per call.
    """
    d = max(d_raw, 0.0)
    if taylor == 0.0:
        t = d ** (1.0 / 9.0)
        return c * d * t, (10.0 / 9.0) * c * t, c * d * d * t / (1.0 + N_LINE)
    n = N_LINE
    if dv > 0.0 and d < TAYLOR_REGULAR_APPROACH:
        a, b = lc[0], lc[1]
        k = a + 2.0 * b * d if d_raw > 0.0 else 0.0
        return a * d + b * d * d, k, a * d * d / 2.0 + b * d**3 / 3.0
    if not d > 0.0:
        return 0.0, 0.0, 0.0
    t = d ** (n - 1.0)  # d^(1/9); d^(10/9) = d t, d^(19/9) = d² t, d^(−8/9) = t / d
    q = c * t * (d + n * dv)
    if not q > 0.0:
        return 0.0, 0.0, 0.0
    if d >= TAYLOR_DELTA_FLOOR:
        k = c * (n * t + n * (n - 1.0) * dv * (t / d))
    else:
        df = TAYLOR_DELTA_FLOOR
        k = c * (n * df ** (n - 1.0) + n * (n - 1.0) * dv * df ** (n - 2.0))
    e = c * ((d * d * t - lc[3]) / (n + 1) + dv * (d * t - lc[4]))
    if dv > 0.0:  # eq. (4)'s energy shifted to the continuation's integral up to δ_T
        e = e + lc[2]
    return q, k, e


@njit(cache=True, error_model="numpy")
def _rib(d_raw, kf):
    d = max(d_raw, 0.0)
    r = np.sqrt(d)
    return kf * d * r, 1.5 * kf * r, kf * d * d * r / 2.5


@njit(cache=True, error_model="numpy")
def _eval(tp, t, ai, af, d0e, dv, lc, fc, x0, x1):
    """Φ, ∂Φ/∂X, load scale and summed stiffnesses of roller t at X = (x0, x1) (fc: its centrifugal
    force in this case [N])."""
    ns = tp.ns[t]
    cs, tay = tp.cs[t], tp.taylor[t]
    xi = x0 * tp.bi[t, 0] + x1 * tp.bi[t, 1]
    xe = x0 * tp.be[t, 0] + x1 * tp.be[t, 1]
    si = 0.0
    se = 0.0
    ki = 0.0
    ke = 0.0
    ei = 0.0
    ee = 0.0
    for k in range(ns):
        q, kk, e = _line(ai[k] + xi, dv, cs, tay, lc)
        si += q
        ki += kk
        ei += e
        q, kk, e = _line(d0e[k] + xe, dv, cs, tay, lc)
        se += q
        ke += kk
        ee += e
    qf, kf, ef = _rib(af + (x0 * tp.bf[t, 0] + x1 * tp.bf[t, 1]), tp.kf[t])
    g0 = si * tp.bi[t, 0] + se * tp.be[t, 0] + qf * tp.bf[t, 0] - fc
    g1 = si * tp.bi[t, 1] + se * tp.be[t, 1] + qf * tp.bf[t, 1]
    phi = ei + ee + ef - fc * x0
    scale = si + se + qf + abs(fc)
    return phi, g0, g1, scale, ki, ke, kf


@njit(cache=True, error_model="numpy")
def _lu2(m00, m01, m10, m11, b0, b1):
    """Solve a 2×2 system by LU with partial pivoting (as LAPACK gesv)."""
    if abs(m10) > abs(m00):
        m00, m01, m10, m11 = m10, m11, m00, m01
        b0, b1 = b1, b0
    l = m10 * (1.0 / m00)  # noqa: E741
    u11 = m11 - l * m01
    y1 = b1 - l * b0
    x1 = y1 / u11
    return (b0 - m01 * x1) / m00, x1


@njit(cache=True, error_model="numpy")
def _solve2(a11, a12, a21, a22, b0, b1):
    """Cramer's rule; a zero or non-finite determinant gives 0 (as the reference ``_solve2``)."""
    det = a11 * a22 - a12 * a21
    if not (np.isfinite(det) and det > 0.0):
        return 0.0, 0.0
    return (a22 * b0 - a12 * b1) / det, (-a21 * b0 + a11 * b1) / det


@njit(cache=True, error_model="numpy")
def _guess(tp, t, ai, af, d0e):
    ns = tp.ns[t]
    lead_i = ai[0]
    lead_e = d0e[0]
    for k in range(1, ns):
        lead_i = max(lead_i, ai[k])
        lead_e = max(lead_e, d0e[k])
    ni0, ni1 = -tp.bi[t, 0], -tp.bi[t, 1]
    ne0, ne1 = tp.be[t, 0], tp.be[t, 1]
    nf0, nf1 = -tp.bf[t, 0], -tp.bf[t, 1]
    x0, x1 = _lu2(ni0 + ne0, ni1 + ne1, nf0, nf1, lead_i - lead_e, af)
    if lead_i - (x0 * ni0 + x1 * ni1) < 0.0:
        x0, x1 = _lu2(ni0 + ne0, ni1 + ne1, nf0 - ni0, nf1 - ni1, lead_i - lead_e, af - lead_i)
    return x0, x1


@njit(cache=True, error_model="numpy")
def _ring(tp, t, cc, q, ai, d0e):
    """Ring parts of roller t: cone approaches ai (S,), cup constants d0e (S,); returns the rib part."""
    for k in range(tp.ns[t]):
        s = 0.0
        for i in range(5):
            s += q[i] * tp.gi[t, k, i]
        ai[k] = s + tp.d0i[cc, t, k]
        d0e[k] = tp.d0e[cc, t, k]
    af = 0.0
    for i in range(5):
        af += q[i] * tp.gf[t, i]
    return af


@njit(cache=True, error_model="numpy")
def _solve_roller(tp, t, ai, af, d0e, dv, lc, fc, x0, x1):
    """Bounded damped Newton for roller t from (x0, x1); returns X, its evaluation, iterations, done."""
    ev = _eval(tp, t, ai, af, d0e, dv, lc, fc, x0, x1)
    ns = tp.ns[t]
    ring = 0.0
    re = 0.0
    for k in range(ns):
        ring = max(ring, abs(ai[k]))
        re = max(re, abs(d0e[k]))
    ring = ring + abs(af) + re
    bi0, bi1, be0, be1 = tp.bi[t, 0], tp.bi[t, 1], tp.be[t, 0], tp.be[t, 1]
    bf0, bf1 = tp.bf[t, 0], tp.bf[t, 1]
    cap, floor, ffloor = tp.cap[t], tp.floor[t], tp.ffloor[t]
    used = 0
    for _ in range(ROLLER_MAX_ITER):
        phi, g0, g1, scale, ki, ke, kf = ev
        gnorm = np.sqrt(g0 * g0 + g1 * g1)
        if gnorm <= ROLLER_RTOL * scale + ffloor:
            return x0, x1, ev, used, True
        used += 1
        h00 = ki * bi0 * bi0 + ke * be0 * be0 + kf * bf0 * bf0
        h01 = ki * bi0 * bi1 + ke * be0 * be1 + kf * bf0 * bf1
        h11 = ki * bi1 * bi1 + ke * be1 * be1 + kf * bf1 * bf1
        mu = 1e-12 * (h00 + h11) + 1e-6 * gnorm / cap + floor
        s0, s1 = _solve2(h00 + mu, h01, h01, h11 + mu, g0, g1)
        s0, s1 = -s0, -s1
        big = np.sqrt(s0 * s0 + s1 * s1)
        f = min(1.0, cap / max(big, 1e-300))
        s0 *= f
        s1 *= f
        if big <= ROLLER_NOISE_EPS * (ring + max(abs(x0), abs(x1))):
            return x0, x1, ev, used, True
        slope = g0 * s0 + g1 * s1
        step_t = 1.0
        accepted = False
        for _ls in range(ROLLER_MAX_HALVINGS):
            tx0 = x0 + step_t * s0
            tx1 = x1 + step_t * s1
            ev_t = _eval(tp, t, ai, af, d0e, dv, lc, fc, tx0, tx1)
            g_t = np.sqrt(ev_t[1] * ev_t[1] + ev_t[2] * ev_t[2])
            if (ev_t[0] <= phi + 1e-4 * step_t * slope + 1e-14 * abs(phi)) or (g_t <= 0.5 * gnorm):
                x0, x1, ev = tx0, tx1, ev_t
                accepted = True
                break
            step_t *= 0.5
        if not accepted:
            if gnorm <= ROLLER_STALL_RTOL * scale:
                return x0, x1, ev, used, True
            x0, x1, ev = tx0, tx1, ev_t
    g0, g1, scale = ev[1], ev[2], ev[3]
    return x0, x1, ev, used, np.sqrt(g0 * g0 + g1 * g1) <= ROLLER_RTOL * scale + ffloor


@njit(cache=True, error_model="numpy")
def tapered_response(c, q, tp, ws_x, ws_sens, ws_q, ws_flag, force, jac, rowf):
    """Add the tapered rows' condensed force, stiffness and per-row force of case c (q (5,)).

    Returns (energy, most roller Newton steps, rollers that reached the cap). The workspace (one per
    case, :func:`workspace`) carries the warm start from one call to the next.
    """
    n_t = tp.gf.shape[0]
    cc = c if tp.d0i.shape[0] > 1 else 0
    s_max = tp.gi.shape[1]
    ai = np.empty(s_max)
    d0e = np.empty(s_max)
    energy = 0.0
    used_max = 0
    unconverged = 0
    warm = ws_flag[0] > 0.0
    dq = np.empty(5)
    kqq = np.empty((5, 5))
    vi = np.empty(5)
    for i in range(5):
        dq[i] = q[i] - ws_q[i]
    for t in range(n_t):
        dv = tp.dev[cc, t]
        lc = _row_consts(tp, cc, t)
        fc = tp.fc[cc, t]
        af = _ring(tp, t, cc, q, ai, d0e)
        x0, x1 = _guess(tp, t, ai, af, d0e)
        if warm:
            w0 = ws_x[t, 0]
            w1 = ws_x[t, 1]
            for d in range(5):
                w0 -= ws_sens[t, d, 0] * dq[d]
                w1 -= ws_sens[t, d, 1] * dq[d]
            phi_g = _eval(tp, t, ai, af, d0e, dv, lc, fc, x0, x1)[0]
            phi_w = _eval(tp, t, ai, af, d0e, dv, lc, fc, w0, w1)[0]
            if np.isfinite(phi_w) and np.isfinite(w0) and np.isfinite(w1) and phi_w <= phi_g:
                x0, x1 = w0, w1
        x0, x1, _, used, done = _solve_roller(tp, t, ai, af, d0e, dv, lc, fc, x0, x1)
        used_max = max(used_max, used)
        if not done:
            unconverged += 1
        ws_x[t, 0] = x0
        ws_x[t, 1] = x1
        # Contacts at the solution: force, condensed stiffness, energy.
        cs, tay = tp.cs[t], tp.taylor[t]
        xi = x0 * tp.bi[t, 0] + x1 * tp.bi[t, 1]
        xe = x0 * tp.be[t, 0] + x1 * tp.be[t, 1]
        kqq[:, :] = 0.0
        vi[:] = 0.0
        ki_sum = 0.0
        ke_sum = 0.0
        row = tp.row[t]
        for k in range(tp.ns[t]):
            qi, ki, ei = _line(ai[k] + xi, dv, cs, tay, lc)
            _, ke, ee = _line(d0e[k] + xe, dv, cs, tay, lc)
            energy += ei + ee
            ki_sum += ki
            ke_sum += ke
            for i in range(5):
                g = tp.gi[t, k, i]
                force[i] -= qi * g
                rowf[row, i] -= qi * g
                vi[i] += ki * g
                for j in range(5):
                    kqq[i, j] += ki * g * tp.gi[t, k, j]
        qf, kf, ef = _rib(af + (x0 * tp.bf[t, 0] + x1 * tp.bf[t, 1]), tp.kf[t])
        energy += ef - fc * x0
        for i in range(5):
            g = tp.gf[t, i]
            force[i] -= qf * g
            rowf[row, i] -= qf * g
            for j in range(5):
                kqq[i, j] += kf * g * tp.gf[t, j]
        bi0, bi1, be0, be1 = tp.bi[t, 0], tp.bi[t, 1], tp.be[t, 0], tp.be[t, 1]
        bf0, bf1 = tp.bf[t, 0], tp.bf[t, 1]
        k00 = ki_sum * bi0 * bi0 + ke_sum * be0 * be0 + kf * bf0 * bf0
        k01 = ki_sum * bi0 * bi1 + ke_sum * be0 * be1 + kf * bf0 * bf1
        k10 = ki_sum * bi1 * bi0 + ke_sum * be1 * be0 + kf * bf1 * bf0
        k11 = ki_sum * bi1 * bi1 + ke_sum * be1 * be1 + kf * bf1 * bf1
        reg = 1e-13 * (k00 + k11) + tp.floor[t]
        k00 += reg
        k11 += reg
        for i in range(5):
            vf = kf * tp.gf[t, i]
            kx0 = vi[i] * bi0 + vf * bf0
            kx1 = vi[i] * bi1 + vf * bf1
            s0, s1 = _solve2(k00, k01, k10, k11, kx0, kx1)
            ws_sens[t, i, 0] = s0
            ws_sens[t, i, 1] = s1
        for i in range(5):
            vfi = kf * tp.gf[t, i]
            kx0 = vi[i] * bi0 + vfi * bf0
            kx1 = vi[i] * bi1 + vfi * bf1
            for j in range(5):
                jac[i, j] -= kqq[i, j] - (kx0 * ws_sens[t, j, 0] + kx1 * ws_sens[t, j, 1])
    for i in range(5):
        ws_q[i] = q[i]
    ws_flag[0] = 1.0
    return energy, used_max, unconverged


# -- per-roller contact loads at given ring displacements (post-processing) --------------------------
@njit(cache=True, error_model="numpy")
def _case_roller_loads(c, q, tp, out, start):
    """Roller contact loads of case c at ring displacement q (5,): out[c, t] = (Q_i, Q_e, Q_f) [N].

    The roller sub-problem of :func:`tapered_response` solved from ``start[c, t]`` (the roller's
    position the solve left at this q) or, where that is NaN or ``start`` has no rollers, from the
    closed-form guess, as :meth:`bearingkit.rows.tapered.kernel.TaperedKernel.roller_state` does
    without a warm start.
    """
    cc = c if tp.d0i.shape[0] > 1 else 0
    s_max = tp.gi.shape[1]
    ai = np.empty(s_max)
    d0e = np.empty(s_max)
    for t in range(tp.gf.shape[0]):
        dv = tp.dev[cc, t]
        lc = _row_consts(tp, cc, t)
        af = _ring(tp, t, cc, q, ai, d0e)
        if start.shape[1] > t and np.isfinite(start[c, t, 0]) and np.isfinite(start[c, t, 1]):
            x0, x1 = start[c, t, 0], start[c, t, 1]
        else:
            x0, x1 = _guess(tp, t, ai, af, d0e)
        x0, x1, _, _, _ = _solve_roller(tp, t, ai, af, d0e, dv, lc, tp.fc[cc, t], x0, x1)
        cs, tay = tp.cs[t], tp.taylor[t]
        xi = x0 * tp.bi[t, 0] + x1 * tp.bi[t, 1]
        xe = x0 * tp.be[t, 0] + x1 * tp.be[t, 1]
        si = 0.0
        se = 0.0
        for k in range(tp.ns[t]):
            si += _line(ai[k] + xi, dv, cs, tay, lc)[0]
            se += _line(d0e[k] + xe, dv, cs, tay, lc)[0]
        out[c, t, 0] = si
        out[c, t, 1] = se
        out[c, t, 2] = _rib(af + (x0 * tp.bf[t, 0] + x1 * tp.bf[t, 1]), tp.kf[t])[0]


@njit(cache=True, parallel=True, error_model="numpy")
def _roller_loads_batch(
    q, gi, gf, d0i, d0e, dev, ns, bi, be, bf, cs, kf, fc, floor, ffloor, cap, taylor, row, lc, out, start
):
    for i in prange(q.shape[0]):
        c = np.int64(i)
        tp = TaperedPack(
            gi, gf, d0i, d0e, dev, ns, bi, be, bf, cs, kf, fc, floor, ffloor, cap, taylor, row, lc
        )  # fmt: skip
        _case_roller_loads(c, q[c], tp, out, start)


def roller_loads(kernel, q: np.ndarray, start: np.ndarray | None = None, pack=None) -> np.ndarray:
    """Contact loads (C, Z, 3) [N] — cone, cup, rib — of a tapered kernel's rollers at q (C, 5).

    The compiled counterpart of the loads of :meth:`TaperedKernel.roller_state` (same roller
    sub-problem; agreement to the sub-problem's tolerance), over the cases in parallel: a Monte
    Carlo of 10⁴ realisations needs only these three loads per roller. ``start`` (C, Z, 2): the
    rollers' positions a compiled solve left at these q (``QuasiStaticResult._roller_x``); the
    sub-problem then starts converged and only confirms it (NaN entries start from the guess).
    ``pack``: the kernel's :func:`pack_tapered` when the caller has it (the solve's own: packing the
    per-roller constants of 10⁴ realisations again cost a tenth of the Monte Carlo's solve).
    """
    pack = pack_tapered([kernel], [0]) if pack is None else pack
    q = np.ascontiguousarray(q, dtype=np.float64)
    n_z = kernel.row.n_elements
    out = np.empty((q.shape[0], n_z, 3))
    if start is None or np.shape(start) != (q.shape[0], n_z, 2):
        start = np.empty((q.shape[0], 0, 2))
    _roller_loads_batch(q, *pack, out, np.ascontiguousarray(start, dtype=np.float64))
    return out
