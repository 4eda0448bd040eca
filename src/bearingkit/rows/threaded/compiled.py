"""Compiled per-case response of threaded rows' affine point contacts (numba) and their packing.

SI units. The numpy kernel (:mod:`bearingkit.rows.threaded.row`) stays the reference; this computes the
same generalised force, Jacobian and energy for ONE case, contact by contact, so the compiled Newton
loop (:mod:`bearingkit.analysis.solver.compiled_newton`) runs per case without temporaries over the
batch. Only the shared geometry is packed (:func:`pack_points`).
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np

from bearingkit.rows.numba_cache import configure

configure()  # before numba reads its configuration: the cache follows the compiled sources
from numba import njit  # noqa: E402

#: Packed affine point contacts (threaded rows; P contacts): G (P, 5), d0, k (P,), row (P,) int.
PointPack = namedtuple("PointPack", "G d0 k row")

POINT_EXPONENT = 1.5


def pack_points(kernels, rows) -> PointPack:
    """Flatten the :class:`~bearingkit.rows.threaded.row.ThreadedKernel` s (shared geometry only)."""
    if not kernels:
        return PointPack(np.zeros((0, 5)), np.zeros(0), np.zeros(0), np.zeros(0, np.int64))
    g, d0, k, row = [], [], [], []
    for kern, r in zip(kernels, rows, strict=True):
        m = kern.G.shape[1]
        g.append(kern.G[0])
        d0.append(np.full(m, float(kern.delta0)))
        k.append(np.full(m, float(kern.k)))
        row.append(np.full(m, r, np.int64))
    return PointPack(
        np.ascontiguousarray(np.concatenate(g)), np.concatenate(d0), np.concatenate(k), np.concatenate(row)
    )


@njit(cache=True, error_model="numpy", inline="always")
def point_response(q, pp, force, jac, rowf):
    """Add the affine Hertz point contacts (threaded rows: δ = G·q + δ0, Q = k δ^1.5); return energy.

    Only the upper triangle of ``jac`` is accumulated (the caller mirrors it).
    """
    energy = 0.0
    ju = jac  # upper triangle only: the caller mirrors it once per evaluation
    for m in range(pp.G.shape[0]):
        d = pp.d0[m]
        for i in range(5):
            d += pp.G[m, i] * q[i]
        if d <= 0.0:
            continue
        root = np.sqrt(d)
        load = pp.k[m] * d * root
        stiff = 1.5 * pp.k[m] * root
        row = pp.row[m]
        for i in range(5):
            gi = pp.G[m, i]
            force[i] -= load * gi
            rowf[row, i] -= load * gi
            for j in range(i, 5):
                ju[i, j] -= stiff * gi * pp.G[m, j]
        energy += load * d / (1.0 + POINT_EXPONENT)
    return energy
