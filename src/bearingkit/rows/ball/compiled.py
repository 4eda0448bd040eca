"""Compiled per-case response of ball rows (numba) and their packing.

SI units. The numpy kernel (:mod:`bearingkit.rows.ball.row`) stays the reference; this computes the
same generalised force, Jacobian and energy for ONE case, element by element, so the compiled Newton
loop (:mod:`bearingkit.analysis.solver.compiled_newton`) runs per case without temporaries over the
batch. Every ball row is packed into one flat set of arrays (:func:`pack_balls`) with a leading case
axis of length 1 (geometry shared by every case) or C (per-case geometry), and the index of the row
each element belongs to (for the per-row force the solver's load scale needs).

Raceway offsets (flexible rings) are not handled here: the solver runs the numpy kernels for them.
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np

from bearingkit.rows.base import concat_cases
from bearingkit.rows.numba_cache import configure

configure()  # before numba reads its configuration: the cache follows the compiled sources
from numba import njit  # noqa: E402

#: Packed ball rows (E balls): B (Cb, E, 2, 5), s0 (Cb, E, 2), a0, k_n, side (Cb, E), row (E,) int.
BallPack = namedtuple("BallPack", "B s0 a0 kn side row")


def pack_balls(kernels, rows) -> BallPack:
    """Flatten the :class:`~bearingkit.rows.ball.row.BallKernel` s (their row indices ``rows``)."""
    if not kernels:
        return BallPack(
            np.zeros((1, 0, 2, 5)), np.zeros((1, 0, 2)), np.zeros((1, 0)), np.zeros((1, 0)),
            np.zeros((1, 0)), np.zeros(0, np.int64),
        )  # fmt: skip
    parts = {k: [] for k in BallPack._fields}
    for kern, r in zip(kernels, rows, strict=True):
        z = kern.row.n_elements
        lead = max(kern.B.shape[0], kern.s0.shape[0], kern.a0.shape[0], kern.k_n.shape[0], kern.side.shape[0])
        parts["B"].append(np.broadcast_to(kern.B, (lead, z, 2, 5)))
        parts["s0"].append(np.broadcast_to(kern.s0, (lead, z, 2)))
        parts["a0"].append(np.broadcast_to(kern.a0, (lead, z)))
        parts["kn"].append(np.broadcast_to(kern.k_n, (lead, z)))
        parts["side"].append(np.broadcast_to(kern.side, (lead, z)))
        parts["row"].append(np.full(z, r, np.int64))
    out = {name: concat_cases(parts[name]) for name in ("B", "s0", "a0", "kn", "side")}
    out["row"] = np.concatenate(parts["row"])
    return BallPack(**out)


# The row responses (this one, the cylindrical and the point one) are inlined into the solver's one
# evaluation (numba IR inlining; each has one
# call site there): measured 48.5 -> 47.3 µs per seed-000 single solve.
@njit(cache=True, error_model="numpy", inline="always")
def ball_response(c, q, bp, force, jac, rowf):
    """Add the ball rows' force (5,), Jacobian (upper triangle) and per-row force (rows, 5) of case c.

    Returns the energy.

    Same model as :meth:`bearingkit.rows.ball.row.BallKernel.response`: groove-centre separation
    s = s0 + B q, δ = |s| − A0 (zero on the relieved side of a one-sided groove), Q = K δ^1.5 along s.
    """
    cb = c if bp.B.shape[0] > 1 else 0
    energy = 0.0
    ju = jac  # upper triangle only: the caller mirrors it once per evaluation
    for e in range(bp.B.shape[1]):
        u0 = 0.0
        u1 = 0.0
        for i in range(5):
            u0 += bp.B[cb, e, 0, i] * q[i]
            u1 += bp.B[cb, e, 1, i] * q[i]
        s0 = bp.s0[cb, e, 0] + u0
        s1 = bp.s0[cb, e, 1] + u1
        a = np.sqrt(s0 * s0 + s1 * s1)
        d = a - bp.a0[cb, e]
        if d <= 0.0 or bp.side[cb, e] * s1 < 0.0:
            continue
        root = np.sqrt(d)
        kn = bp.kn[cb, e]
        load = kn * d * root
        stiff = 1.5 * kn * root
        n0 = s0 / a
        n1 = s1 / a
        f0 = -load * n0
        f1 = -load * n1
        la = load / a
        k00 = -(stiff * n0 * n0 + la * (1.0 - n0 * n0))
        k01 = -(stiff * n0 * n1 - la * n0 * n1)
        k11 = -(stiff * n1 * n1 + la * (1.0 - n1 * n1))
        r = bp.row[e]
        for i in range(5):
            b0i = bp.B[cb, e, 0, i]
            b1i = bp.B[cb, e, 1, i]
            fi = b0i * f0 + b1i * f1
            force[i] += fi
            rowf[r, i] += fi
            t0 = b0i * k00 + b1i * k01
            t1 = b0i * k01 + b1i * k11
            for j in range(i, 5):
                ju[i, j] += t0 * bp.B[cb, e, 0, j] + t1 * bp.B[cb, e, 1, j]
        energy += kn * d * d * root / 2.5
    return energy
