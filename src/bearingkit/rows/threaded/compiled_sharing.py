"""Compiled axial tooth-load sharing of threaded rollers for a population of designs (numba).

SI units (N, m). The same equations as :func:`bearingkit.physics.life.ptrb_load_sharing.tooth_load_shares`
(its numpy version, grouped by tooth count and solved by dense Newton steps, is this kernel's test oracle:
tests/rows/test_compiled_sharing.py), solved design by design in O(n) per Newton step instead of
O(n³): the PTRB design optimisation (Zheng et al. 2022, §6) evaluates 10⁴ designs, and the dense
Newton steps of the numpy version were 1.3 s of its ~2 s evaluator (issue 34).

The tooth equations written as differences between neighbouring teeth
--------------------------------------------------------------------
With the ring and roller displacements of the numpy version (u_I,i = U − λ_I Σ_j min(i, j) F_I,j,
u_O,i = λ_O Σ_j min(e_i, e_j) F_O,j, w_i = w_0 − λ_R Σ_j max(i − j, 0)(F_I,j − F_O,j)), the difference of
the compatibility equations of teeth k and k − 1 (k = 1 … n − 1) needs only the head sums
S_I,k = Σ_{j<k} F_I,j, S_O,k = Σ_{j<k} F_O,j (the tail sums are F_r − S, F_r = F_a/Z, by the sum
equations):

.. math::
    g_I(F_{I,k}) - g_I(F_{I,k-1}) &= -λ_I (F_r - S_{I,k}) + λ_R (S_{I,k} - S_{O,k}) \\\\
    g_O(F_{O,k}) - g_O(F_{O,k-1}) &= -λ_R (S_{I,k} - S_{O,k}) + λ_O S_{O,k}
        \\quad (\\text{same support: } - λ_O (F_r - S_{O,k}))

and S_I,n = S_O,n = F_r; the equations of tooth 0 only give U and w_0. With the head sums as unknowns
beside y = F^(1/3) (S_k+1 − S_k − y_k³ = 0), tooth by tooth, every equation reaches the unknowns of its
own tooth and the one before: a banded Jacobian (2 below the diagonal, 2 above), solved by Gaussian
elimination with partial pivoting within the band in O(n). The head sums are formed from y before each
step, so each step in y is the numpy version's Newton step (equations combined linearly, the same
root), damped alike.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.rows.numba_cache import configure

configure()  # before numba reads its configuration: the cache follows the compiled sources
from numba import njit  # noqa: E402

__all__ = ["max_tooth_share"]


@njit(cache=True, error_model="numpy")
def _one_design(f_r, n, ai, ao, ci, co, lr, li, lo, same, max_iter, tol, y, jac, rhs, x):
    """Newton iterations of one design; returns (f_amax, converged).

    Work arrays: ``y`` (≥ 2n,), y[2k] of tooth k's ITP contact and y[2k + 1] of its OTP contact;
    ``jac`` (≥ 4n, ≥ 4n), ``rhs`` and ``x`` (≥ 4n,). Unknowns in the order y_I,k, y_O,k, S_I,k+1, S_O,k+1
    per tooth; equations: the head sums of tooth 0, then per tooth k ≥ 1 its ITP and OTP difference
    equations and head sums, then the two sum equations (row − column within −2 … +2).
    """
    m = 4 * n
    y0 = (f_r / n) ** (1.0 / 3.0)
    for k in range(2 * n):
        y[k] = y0
    for _ in range(max_iter):
        for i in range(m):  # the band, and the fill of partial pivoting (up to 4 above)
            for col in range(max(0, i - 2), min(m, i + 5)):
                jac[i, col] = 0.0
            rhs[i] = 0.0
        s_i = 0.0
        s_o = 0.0
        g_i_prev = g_o_prev = p_i_prev = p_o_prev = 0.0
        for k in range(n):
            yi, yo = y[2 * k], y[2 * k + 1]
            d_i, d_o = 3.0 * yi * yi, 3.0 * yo * yo
            g_i = ai * yi * yi + ci * yi**3
            g_o = ao * yo * yo + co * yo**3
            p_i = 2.0 * ai * yi + ci * d_i
            p_o = 2.0 * ao * yo + co * d_o
            c = 4 * k  # this tooth's first unknown (y_I,k), and its head-sum rows 4k, 4k + 1
            if k > 0:  # the difference equations, rows 4k − 2 and 4k − 1 (S_I,k, S_O,k at c − 2, c − 1)
                r = c - 2
                jac[r, c - 4] = -p_i_prev
                jac[r, c - 2] = -(li + lr)
                jac[r, c - 1] = lr
                jac[r, c] = p_i
                rhs[r] = -(g_i - g_i_prev + li * (f_r - s_i) - lr * (s_i - s_o))
                r = c - 1
                jac[r, c - 3] = -p_o_prev
                jac[r, c - 2] = lr
                jac[r, c - 1] = -(lr + lo)
                jac[r, c + 1] = p_o
                if same:
                    rhs[r] = -(g_o - g_o_prev + lr * (s_i - s_o) + lo * (f_r - s_o))
                else:
                    rhs[r] = -(g_o - g_o_prev + lr * (s_i - s_o) - lo * s_o)
                jac[c, c - 2] = -1.0
                jac[c + 1, c - 1] = -1.0
            # head sums S_k+1 − S_k − y_k³ = 0: zero residual (the sums are formed from y)
            jac[c, c] = -d_i
            jac[c, c + 2] = 1.0
            jac[c + 1, c + 1] = -d_o
            jac[c + 1, c + 3] = 1.0
            s_i += yi**3
            s_o += yo**3
            g_i_prev, g_o_prev, p_i_prev, p_o_prev = g_i, g_o, p_i, p_o
        jac[m - 2, m - 2] = 1.0  # S_I,n = F_r
        jac[m - 1, m - 1] = 1.0  # S_O,n = F_r
        rhs[m - 2] = f_r - s_i
        rhs[m - 1] = f_r - s_o
        # Gaussian elimination with partial pivoting within the band: the pivot among the 2 rows below,
        # a row's entries then reach at most 4 columns right of the diagonal
        for j in range(m):
            last = min(m - 1, j + 2)
            piv = j
            for r in range(j + 1, last + 1):
                if abs(jac[r, j]) > abs(jac[piv, j]):
                    piv = r
            right = min(m, j + 5)
            if piv != j:
                for col in range(j, right):
                    jac[j, col], jac[piv, col] = jac[piv, col], jac[j, col]
                rhs[j], rhs[piv] = rhs[piv], rhs[j]
            for r in range(j + 1, last + 1):
                f = jac[r, j] / jac[j, j]
                if f != 0.0:
                    for col in range(j, right):
                        jac[r, col] -= f * jac[j, col]
                    rhs[r] -= f * rhs[j]
        for i in range(m - 1, -1, -1):
            acc = rhs[i]
            for col in range(i + 1, min(m, i + 5)):
                acc -= jac[i, col] * x[col]
            x[i] = acc / jac[i, i]
        small = True
        for k in range(n):
            for side in range(2):
                dy = x[4 * k + side]
                old = y[2 * k + side]
                new = max(old + dy, 0.2 * old)  # damped as the numpy version: loads stay positive
                if not abs(dy) < tol * new:  # NaN compares False: a failed step is not small
                    small = False
                y[2 * k + side] = new
        if small:
            break
    mean = f_r / n
    fa = 0.0
    for k in range(2 * n):
        fa = max(fa, y[k] ** 3 / mean)
    return fa, small


@njit(cache=True, error_model="numpy")
def _batch(f_roller, n_teeth, ai, ao, ci, co, lr, li, lo, same, max_iter, tol):
    c = f_roller.size
    fa = np.empty(c)
    conv = np.zeros(c, dtype=np.bool_)
    n_max = 1
    for j in range(c):
        n_max = max(n_max, n_teeth[j])
    y = np.empty(2 * n_max)
    jac = np.empty((4 * n_max, 4 * n_max))
    rhs = np.empty(4 * n_max)
    x = np.empty(4 * n_max)
    for j in range(c):
        fa[j], conv[j] = _one_design(
            f_roller[j], n_teeth[j], ai[j], ao[j], ci[j], co[j], lr[j], li[j], lo[j], same, max_iter, tol,
            y, jac, rhs, x,
        )  # fmt: skip
    return fa, conv


def max_tooth_share(f_roller, n_teeth, ai, ao, ci, co, lr, li, lo, support, max_iter, tol):
    """f_amax [1] (C,) and converged (C,) bool of designs with any tooth counts, on checked (C,) arrays.

    The solver protocol of :func:`bearingkit.physics.life.ptrb_load_sharing.max_tooth_share`
    (``solver=``): roller load F_a/Z [N], teeth n, then the coefficients a_H,I, a_H,O [m/N^(2/3)], the
    tooth compliances c_I, c_O and the core compliances λ_R, λ_I, λ_O [m/N], the support
    ("opposite" or "same"), the iteration cap and the tolerance on the relative Newton step of
    y = F^(1/3) — as :func:`~bearingkit.physics.life.ptrb_load_sharing.tooth_load_shares`.
    """
    checks.one_of("support", support, ("opposite", "same"))  # a misspelt one would solve as "opposite"
    arrays = [np.ascontiguousarray(a, dtype=float) for a in (f_roller, ai, ao, ci, co, lr, li, lo)]
    n = np.ascontiguousarray(n_teeth, dtype=np.int64)
    f, a_i, a_o, c_i, c_o, l_r, l_i, l_o = arrays
    return _batch(f, n, a_i, a_o, c_i, c_o, l_r, l_i, l_o, support == "same", int(max_iter), float(tol))
