"""The compiled core's small dense linear algebra: 5×5 solves, the idle-mechanism test, the cone NNLS,
the starting point.

Written out in numba because the systems are at most 5×5: a LAPACK call from numba (argument
copies, finiteness checks, workspace queries) costs ~1–2 µs where these cost ~0.1 µs, several
times per Newton iteration. Each mirrors the numpy reference it replaces (named in its docstring).
"""

from __future__ import annotations

import numpy as np

from bearingkit.analysis.solver.cone import NNLS_STALL_RTOL
from bearingkit.analysis.solver.newton import MECHANISM_RTOL
from bearingkit.rows.numba_cache import configure

configure()  # before numba reads its configuration: the cache follows the compiled sources
from numba import njit  # noqa: E402


@njit(cache=True, error_model="numpy")
def mirror_upper(jac):
    """Copy the upper triangle of the 5×5 ``jac`` to its lower one (the contact Jacobians are
    symmetric, sums of g gᵀ-type products: the responses accumulate only 15 of 25 entries)."""
    for i in range(5):
        for j in range(i + 1, 5):
            jac[j, i] = jac[i, j]


@njit(cache=True, error_model="numpy")
def lu_solve(a, b):
    """x with a x = b (n ≤ 5) by LU with partial pivoting (LAPACK gesv's algorithm); a, b untouched.

    Raises ZeroDivisionError on an exactly singular matrix (where gesv reports a zero pivot).
    """
    n = a.shape[0]
    m = a.copy()
    x = b.copy()
    for col in range(n):
        piv = col
        big = abs(m[col, col])
        for r in range(col + 1, n):
            if abs(m[r, col]) > big:
                big = abs(m[r, col])
                piv = r
        if big == 0.0:
            raise ZeroDivisionError("singular matrix")
        if piv != col:
            for j in range(n):
                m[col, j], m[piv, j] = m[piv, j], m[col, j]
            x[col], x[piv] = x[piv], x[col]
        inv = 1.0 / m[col, col]
        for r in range(col + 1, n):
            f = m[r, col] * inv
            if f != 0.0:
                for j in range(col + 1, n):
                    m[r, j] -= f * m[col, j]
                x[r] -= f * x[col]
    for col in range(n - 1, -1, -1):
        s = x[col]
        for j in range(col + 1, n):
            s -= m[col, j] * x[j]
        x[col] = s / m[col, col]
    return x


#: Safety factor of :func:`surely_regular` on the eigenvalue ratio (covers the rounding of the
#: computed inverse, relative ~ cond × eps ≤ 1e-7 where the test can pass) [-].
REGULAR_SAFETY = 10.0


@njit(cache=True, error_model="numpy")
def surely_regular(h):
    """True when the symmetric h (n ≤ 5) certainly has no eigenvalue ≤ MECHANISM_RTOL × the largest.

    λ_max ≤ ‖h‖_F and λ_min ≥ 1/‖L⁻¹‖_F² (h = L Lᵀ positive definite, shown by its Cholesky factor);
    when 1/‖L⁻¹‖_F² > REGULAR_SAFETY · MECHANISM_RTOL · ‖h‖_F no direction is a mechanism and the
    eigen-decomposition of :func:`without_idle` would change nothing. False (decompose) otherwise.
    """
    n = h.shape[0]
    lo = np.zeros((n, n))
    fro = 0.0
    for i in range(n):
        for j in range(n):
            fro += h[i, j] * h[i, j]
        for j in range(i + 1):
            s = h[i, j]
            for k in range(j):
                s -= lo[i, k] * lo[j, k]
            if i == j:
                if not s > 0.0:
                    return False
                lo[i, i] = np.sqrt(s)
            else:
                lo[i, j] = s / lo[j, j]
    # h⁻¹ = L⁻ᵀ L⁻¹: 1/λ_min = ‖h⁻¹‖₂ = ‖L⁻¹‖₂² ≤ ‖L⁻¹‖_F² = li.
    inv = np.zeros((n, n))
    for j in range(n):
        inv[j, j] = 1.0 / lo[j, j]
        for i in range(j + 1, n):
            s = 0.0
            for k in range(j, i):
                s -= lo[i, k] * inv[k, j]
            inv[i, j] = s / lo[i, i]
    li = 0.0
    for i in range(n):
        for j in range(i + 1):
            li += inv[i, j] * inv[i, j]
    if not np.isfinite(li) or not np.isfinite(fro):
        return False
    return 1.0 / li > REGULAR_SAFETY * MECHANISM_RTOL * np.sqrt(fro)


@njit(cache=True, error_model="numpy")
def without_idle(h, g, step, tol):
    """``step`` without its components along mechanisms of h the gradient does not load (in place)."""
    if surely_regular(h):
        return
    lam, vec = np.linalg.eigh(h)
    n = h.shape[0]
    top = 0.0
    for i in range(n):
        top = max(top, abs(lam[i]))
    top = max(top, 1e-300)
    any_idle = False
    idle = np.zeros(n, np.bool_)
    for j in range(n):
        if lam[j] <= MECHANISM_RTOL * top:
            cg = 0.0
            for i in range(n):
                cg += vec[i, j] * g[i]
            if abs(cg) <= tol:
                idle[j] = True
                any_idle = True
    if not any_idle:
        return
    comp = np.zeros(n)
    for j in range(n):
        if not idle[j]:
            for i in range(n):
                comp[j] += vec[i, j] * step[i]
    for i in range(n):
        s = 0.0
        for j in range(n):
            s += vec[i, j] * comp[j]
        step[i] = s


@njit(cache=True, error_model="numpy")
def nnls_misfit(a, b):
    """‖a x − b‖ at the non-negative least-squares solution (Lawson–Hanson; as cone.nnls, with its
    stall stop)."""
    m, n = a.shape
    x = np.zeros(n)
    passive = np.zeros(n, np.bool_)
    colsum = 0.0
    for j in range(n):
        s = 0.0
        for i in range(m):
            s += abs(a[i, j])
        colsum = max(colsum, s)
    tol = 10.0 * np.finfo(np.float64).eps * colsum * max(m, n)
    w = a.T @ b
    s_vec = np.zeros(n)
    x_prev = np.zeros(n)
    misfit = np.sqrt(np.sum(b * b))
    stall = NNLS_STALL_RTOL * misfit
    for _ in range(3 * n + 10):
        best = -np.inf
        jbest = -1
        for j in range(n):
            if not passive[j] and w[j] > best:
                best = w[j]
                jbest = j
        if jbest < 0 or best <= tol:
            break
        passive[jbest] = True
        x_prev[:] = x
        for _inner in range(3 * n + 10):
            if not passive.any():  # every column left (round-off at extreme loads), as cone.nnls
                s_vec[:] = 0.0
                break
            cols = np.flatnonzero(passive)
            sub = np.empty((m, cols.shape[0]))
            for k in range(cols.shape[0]):
                sub[:, k] = a[:, cols[k]]
            sol = np.linalg.lstsq(sub, b, -1.0)[0]
            s_vec[:] = 0.0
            smin = np.inf
            for k in range(cols.shape[0]):
                s_vec[cols[k]] = sol[k]
                smin = min(smin, sol[k])
            if smin > 0.0:
                break
            alpha = np.inf
            for j in range(n):
                if passive[j] and s_vec[j] <= 0.0:
                    den = x[j] - s_vec[j]  # x = s = 0 at round-off: no step (cone.nnls's NaN → 0)
                    alpha = min(alpha, x[j] / den if den != 0.0 else 0.0)
            for j in range(n):
                x[j] = x[j] + alpha * (s_vec[j] - x[j])
                if passive[j] and not x[j] > tol:
                    passive[j] = False
        x[:] = s_vec
        res = b - a @ x
        w = a.T @ res
        previous = misfit
        misfit = np.sqrt(np.sum(res * res))
        if not previous - misfit > stall:  # no progress: round-off (cone.NNLS_STALL_RTOL)
            if not misfit <= previous:  # worse: keep the previous solution
                x[:] = x_prev
            break
    r = a @ x - b
    return np.sqrt(np.sum(r * r))


@njit(cache=True, error_model="numpy")
def start_point(q, load, start_mats, start_exps, scale, idx, max_step):
    """As :func:`bearingkit.analysis.solver.newton.starting_point` for one case; returns the start (5,).

    ``start_mats`` (G, 5, 5) the rows' start matrices summed per start exponent, ``start_exps`` (G,).
    """
    n = idx.shape[0]
    out = q.copy()
    if n == 0:
        return out
    f = np.empty(n)
    fmax = 0.0
    for a in range(n):
        f[a] = load[idx[a]] * scale[idx[a]]
        fmax = max(fmax, abs(f[a]))
    delta = 1e-4 * max_step / 0.02
    k = np.zeros((n, n))
    qt = np.zeros(n)
    n_g = start_mats.shape[0]
    sm = np.empty((n_g, n, n))  # the scaled start matrices on the free DOFs
    for r in range(n_g):
        for a in range(n):
            for b in range(n):
                i, j = idx[a], idx[b]
                sm[r, a, b] = start_mats[r, i, j] * scale[i] * scale[j]
    for _ in range(6):
        k[:, :] = 0.0
        for r in range(n_g):
            ex = start_exps[r]
            fac = ex * delta ** (ex - 1.0)
            for a in range(n):
                for b in range(n):
                    k[a, b] += fac * sm[r, a, b]
        kmax = 0.0
        for a in range(n):
            for b in range(n):
                kmax = max(kmax, abs(k[a, b]))
        for a in range(n):
            k[a, a] += 1e-12 * kmax
        for a in range(n):
            for b in range(n):
                if not np.isfinite(k[a, b]):
                    k[a, b] = 0.0
            k[a, a] += 1e-300
        try:
            qt = lu_solve(k, f)
        except Exception:  # degenerate stiffness: start from the given point
            return out
        approach = 0.0
        for a in range(n):
            approach = max(approach, abs(qt[a]))
        delta = np.sqrt(delta * max(approach, 1e-3 * delta))
    without_idle(k, -f, qt, 1e-10 * fmax)
    big = 0.0
    for a in range(n):
        big = max(big, abs(qt[a]))
    if np.isfinite(big):
        fac = min(1.0, max_step / max(big, 1e-300))
        for a in range(n):
            qt[a] *= fac
    for a in range(n):
        out[idx[a]] = q[idx[a]] + qt[a] * scale[idx[a]]
    for i in range(5):
        if not np.isfinite(out[i]):
            return q.copy()
    return out


__all__ = ["REGULAR_SAFETY", "lu_solve", "nnls_misfit", "start_point", "surely_regular", "without_idle"]
