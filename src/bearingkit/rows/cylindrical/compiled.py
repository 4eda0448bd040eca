"""Compiled per-case response of cylindrical (sliced line-contact) rows (numba) and their packing.

SI units. The numpy kernel (:mod:`bearingkit.rows.cylindrical.row`) stays the reference; this computes
the same generalised force, Jacobian and energy for ONE case, roller by roller and slice by slice, so
the compiled Newton loop (:mod:`bearingkit.analysis.solver.compiled_newton`) runs per case without
temporaries over the batch. Every cylindrical row is packed into one flat set of arrays
(:func:`pack_rollers`) with a leading case axis of length 1 or C, and the index of each roller's row.
:func:`ninth_root` serves the line law δ^(10/9) = δ·δ^(1/9).

Raceway offsets (flexible rings) are not handled here: the solver runs the numpy kernels for them.
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np

from bearingkit.rows.base import concat_cases
from bearingkit.rows.numba_cache import configure

configure()  # before numba reads its configuration: the cache follows the compiled sources
from numba import njit  # noqa: E402

#: Packed cylindrical rows (R rollers, S ≥ n_s slots): Ga, Gb (Cc, R, 5), x, d0 (Cc, R, S),
#: c_s (Cc, R), ns (R,) int slices per roller, row (R,) int; reach (Cc, R, 2): the largest δ0_k and
#: the largest |x_k| of each roller (a roller whose a + max δ0 + |b| max|x| is below zero has no
#: loaded slice and is skipped without visiting its slices).
RollerPack = namedtuple("RollerPack", "Ga Gb x d0 cs ns row reach")

LINE_EXPONENT = 10.0 / 9.0


def pack_rollers(kernels, rows) -> RollerPack:
    """Flatten the :class:`~bearingkit.rows.cylindrical.row.CylindricalKernel` s (row indices ``rows``)."""
    if not kernels:
        return RollerPack(
            np.zeros((1, 0, 5)), np.zeros((1, 0, 5)), np.zeros((1, 0, 1)), np.zeros((1, 0, 1)),
            np.zeros((1, 0)), np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros((1, 0, 2)),
        )  # fmt: skip
    s_max = max(k.shape[1] for k in kernels)
    ga, gb, xs, d0, cs, ns, row = [], [], [], [], [], [], []
    for kern, r in zip(kernels, rows, strict=True):
        z, n_s = kern.shape
        lead = max(np.shape(getattr(kern, a))[0] for a in ("Ga", "Gb", "x", "delta0", "c_s"))
        ga.append(np.broadcast_to(kern.Ga, (lead, z, 5)))
        gb.append(np.broadcast_to(kern.Gb, (lead, z, 5)))
        x = np.zeros((lead, z, s_max))
        x[:, :, :n_s] = np.broadcast_to(kern.x, (lead, n_s))[:, None, :]
        d = np.zeros((lead, z, s_max))
        d[:, :, :n_s] = np.broadcast_to(kern.delta0, (lead, n_s))[:, None, :]
        xs.append(x)
        d0.append(d)
        cs.append(np.broadcast_to(kern.c_s, (lead, 1)) * np.ones((1, z)))
        ns.append(np.full(z, n_s, np.int64))
        row.append(np.full(z, r, np.int64))
    ga, gb, xs, d0, cs = (concat_cases(a) for a in (ga, gb, xs, d0, cs))
    # Padded slots hold x = δ0 = 0: they can only raise the bounds (the skip stays conservative).
    reach = np.ascontiguousarray(np.stack([d0.max(axis=2), np.abs(xs).max(axis=2)], axis=-1))
    return RollerPack(ga, gb, xs, d0, cs, np.concatenate(ns), np.concatenate(row), reach)


#: Bits of the double 1.0 (exponent bias), for the first guess of a ninth root.
_ONE_BITS = np.int64(1023) << np.int64(52)
#: Range where :func:`ninth_root`'s guess and Halley steps are exact to rounding (outside: ``**``) [m].
_ROOT_RANGE = (1e-200, 1e10)


@njit(cache=True, error_model="numpy")
def ninth_root(d, y, n):
    """y[k] = d[k]^(1/9) for k < n (0 where d ≤ 0); d, y float64 arrays (y may not alias d).

    A bit-level first guess (the exponent divided by 9, in floating point so that it vectorises:
    relative error ≤ 3.4 %) and three Halley steps y ← y (8 y⁹ + 10 d)/(10 y⁹ + 8 d) (cubic
    convergence: 2e-4, 5e-11, below rounding) give the root to ~1 ulp — within 2 ulp of the
    reference's two cube roots — in straight-line arithmetic the compiler pipelines (3x faster than
    two libm cube roots here). Values outside ``_ROOT_RANGE`` (never a contact approach) take ``**``.
    """
    db = d.view(np.int64)
    yb = y.view(np.int64)
    outside = 0
    for k in range(n):
        yb[k] = np.int64(np.float64(db[k] - _ONE_BITS) * (1.0 / 9.0)) + _ONE_BITS
        x = d[k]
        outside += 0 if (x <= 0.0 or (_ROOT_RANGE[0] < x < _ROOT_RANGE[1])) else 1
    for k in range(n):
        v = y[k]
        x = d[k]
        v2 = v * v
        v4 = v2 * v2
        v9 = v4 * v4 * v
        v = v * (8.0 * v9 + 10.0 * x) / (10.0 * v9 + 8.0 * x)
        v2 = v * v
        v4 = v2 * v2
        v9 = v4 * v4 * v
        v = v * (8.0 * v9 + 10.0 * x) / (10.0 * v9 + 8.0 * x)
        v2 = v * v
        v4 = v2 * v2
        v9 = v4 * v4 * v
        v = v * (8.0 * v9 + 10.0 * x) / (10.0 * v9 + 8.0 * x)
        y[k] = v if x > 0.0 else 0.0
    if outside:
        for k in range(n):
            x = d[k]
            if x > 0.0 and not (_ROOT_RANGE[0] < x < _ROOT_RANGE[1]):
                y[k] = x ** (1.0 / 9.0)


#: Relative margin of the unloaded-roller test of :func:`roller_response` (far above rounding: a
#: roller is skipped only when no slice approach can be positive).
SKIP_MARGIN = 1e-12


@njit(cache=True, error_model="numpy")
def roller_buffers(rp):
    """Scratch arrays of :func:`roller_response` for one thread: slice values (2, R·S), indices (3R+1,).

    Allocated once per thread and reused by every evaluation: a fresh ~75 kB per evaluation is handed
    back to the system by glibc's heap trimming and faulted in again each time, which cost more
    than the arithmetic (issue 19's "glibc trims them").
    """
    n_r = rp.Ga.shape[1]
    return np.empty((2, max(n_r * rp.x.shape[2], 1))), np.empty(3 * n_r + 1, np.int64)


@njit(cache=True, error_model="numpy", inline="always")
def roller_response(c, q, rp, force, jac, rowf, fbuf, ibuf):
    """Add the cylindrical rows' force, Jacobian (upper triangle) and per-row force of case c.

    Returns the energy. Same model as :meth:`bearingkit.rows.cylindrical.row.CylindricalKernel.response`:
    slice approach δ_k = a + b x_k + δ0_k with a = Ga·q, b = Gb·q, slice load c_s δ^(10/9) (δ^(1/9)
    by :func:`ninth_root`), reduced per roller to Σq, Σqx (force) and Σq′, Σq′x, Σq′x² (stiffness).
    Only the upper triangle of ``jac`` is accumulated (the caller mirrors it once per evaluation).

    Three passes. (1) Each roller's slices from its first to its last touching one are copied into
    one buffer (a roller no slice of which can touch, by its ``reach`` bound, is skipped unvisited);
    for a crowned or straight profile that range is exactly the touching set, and a slice inside it
    that does not touch has δ^(1/9) = 0 and adds exact zeros, as in the reference's sums over every
    slice. (2) Their roots are taken in one long loop the compiler vectorises. (3) Each roller's
    sums are formed in slice order. ``fbuf``, ``ibuf``: scratch from :func:`roller_buffers`.
    """
    cc = c if rp.Ga.shape[0] > 1 else 0
    n_r = rp.Ga.shape[1]
    dbuf = fbuf[0]
    ybuf = fbuf[1]
    rid = ibuf[:n_r]
    first = ibuf[n_r : 2 * n_r]
    seg = ibuf[2 * n_r :]
    n = 0
    m = 0
    for r in range(n_r):
        a = 0.0
        b = 0.0
        for i in range(5):
            a += rp.Ga[cc, r, i] * q[i]
            b += rp.Gb[cc, r, i] * q[i]
        top = a + rp.reach[cc, r, 0] + abs(b) * rp.reach[cc, r, 1]
        if top < -SKIP_MARGIN * (abs(a) + abs(rp.reach[cc, r, 0]) + abs(b) * rp.reach[cc, r, 1]):
            continue
        ns = rp.ns[r]
        lo = 0
        while lo < ns and not (b * rp.x[cc, r, lo] + a + rp.d0[cc, r, lo] > 0.0):
            lo += 1
        if lo == ns:
            continue
        hi = ns - 1
        while not (b * rp.x[cc, r, hi] + a + rp.d0[cc, r, hi] > 0.0):
            hi -= 1
        for k in range(lo, hi + 1):
            dbuf[n + k - lo] = b * rp.x[cc, r, k] + a + rp.d0[cc, r, k]
        rid[m] = r
        first[m] = lo
        seg[m] = n
        n += hi + 1 - lo
        m += 1
    seg[m] = n
    ninth_root(dbuf, ybuf, n)
    energy = 0.0
    for j in range(m):
        r = rid[j]
        off = first[j] - seg[j]
        cs = rp.cs[cc, r]
        f0 = 0.0
        f1 = 0.0
        k0 = 0.0
        k1 = 0.0
        k2 = 0.0
        e = 0.0
        for k in range(seg[j], seg[j + 1]):
            x = rp.x[cc, r, k + off]
            d = dbuf[k]
            t = ybuf[k]
            dt = d * t
            f0 += dt
            f1 += dt * x
            k0 += t
            k1 += t * x
            k2 += t * (x * x)
            e += dt * d
        # c_s is one per roller: applied to the sums, not to every slice.
        f0 *= cs
        f1 *= cs
        ck = (10.0 / 9.0) * cs
        k0 *= ck
        k1 *= ck
        k2 *= ck
        row = rp.row[r]
        # Roller stiffness [Ga Gb] [[k0, k1], [k1, k2]] [Ga Gb]ᵀ, upper triangle.
        for i in range(5):
            gai = rp.Ga[cc, r, i]
            gbi = rp.Gb[cc, r, i]
            fi = -(f0 * gai + f1 * gbi)
            force[i] += fi
            rowf[row, i] += fi
            ui = k0 * gai + k1 * gbi
            wi = k1 * gai + k2 * gbi
            for jj in range(i, 5):
                jac[i, jj] -= ui * rp.Ga[cc, r, jj] + wi * rp.Gb[cc, r, jj]
        energy += cs * e / (1.0 + LINE_EXPONENT)
    return energy
