"""The contact cone of a bearing: which loads some combination of its contacts can balance at all.

SI units. Every contact pushes the inner ring along one generalised direction g (a row of the
kernel's ``G``, ``directions`` or ``reach``, (5,) in [1, 1, 1, m, m]); a load F can be carried only
if F = Σ λ g with λ ≥ 0, i.e. if F lies in the cone the directions span. The check is a
non-negative least-squares fit (Lawson & Hanson 1974, Solving Least Squares Problems, ch. 23): its
misfit is zero inside the cone and grows with the distance outside. The directions are those of the
unloaded geometry: a load the contacts can reach only after large contact-angle changes is judged
by the unloaded cone (the check only labels or stops cases the solver is failing on).
"""

from __future__ import annotations

import numpy as np

from bearingkit.errors import InputError
from bearingkit.rows.base import DOF_NAMES, LOAD_NAMES

#: A load is outside the contact cone when the NNLS misfit exceeds this fraction of its size [-].
CONE_MISS_RTOL = 1e-3
#: :func:`nnls` stops when an outer step lowers the misfit by less than this fraction of the load's
#: size [-]. In exact arithmetic every outer step of Lawson–Hanson lowers it; at round-off (a load
#: inside a cone of thousands of nearly parallel slice directions, misfit ~1e-15 of the load) the
#: entering column left again at once and the loop ran to its 3n + 10 cap: 0.3 s compiled, 2 s
#: numpy, for one case of the seed-000 bearing (issue 19). Far below CONE_MISS_RTOL: no decision
#: changes.
NNLS_STALL_RTOL = 1e-12


def nnls(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, float]:
    """Non-negative least squares min ‖a x − b‖, x ≥ 0 (Lawson–Hanson active set).

    Parameters
    ----------
    a : ndarray (m, n)
    b : ndarray (m,)

    Returns
    -------
    x : ndarray (n,)
    misfit : float
        ‖a x − b‖ at the solution.

    Notes
    -----
    Lawson & Hanson (1974), Algorithm NNLS, ch. 23. Written here (numpy only) so the solver's
    diagnosis does not import :mod:`scipy.optimize` (several seconds on a busy machine); the
    problems are small (m ≤ 5 rows, a few thousand columns at most) and the passive set holds at
    most m columns at a basic solution, so the loops are short.
    """
    m, n = a.shape
    x = np.zeros(n)
    if not (np.isfinite(a).all() and np.isfinite(b).all()):  # nothing to fit: say it misses
        return x, float("inf")
    passive = np.zeros(n, bool)
    tol = 10.0 * np.finfo(float).eps * np.abs(a).sum(axis=0).max(initial=0.0) * max(m, n)
    w = a.T @ b
    stall = NNLS_STALL_RTOL * float(np.linalg.norm(b))
    misfit = float(np.linalg.norm(b))
    for _ in range(3 * n + 10):
        if passive.all() or np.where(passive, -np.inf, w).max() <= tol:
            break
        passive[int(np.argmax(np.where(passive, -np.inf, w)))] = True
        x_prev = x
        for _inner in range(3 * n + 10):
            s = np.zeros(n)
            if not passive.any():  # every column left the passive set (round-off at extreme loads)
                break
            s[passive] = np.linalg.lstsq(a[:, passive], b, rcond=None)[0]
            if s[passive].min() > 0.0:
                break
            shrink = passive & (s <= 0.0)
            with np.errstate(divide="ignore", invalid="ignore"):  # x = s = 0 at round-off: no step
                ratio = x[shrink] / (x[shrink] - s[shrink])
            alpha = float(np.min(np.nan_to_num(ratio, nan=0.0)))
            x = x + alpha * (s - x)
            passive &= x > tol
        x = s
        r = b - a @ x
        w = a.T @ r
        previous, misfit = misfit, float(np.linalg.norm(r))
        if not previous - misfit > stall:  # no progress: round-off (see NNLS_STALL_RTOL)
            if not misfit <= previous:  # worse (round-off in the inner loop): keep the previous x
                x = x_prev
            break
    return x, float(np.linalg.norm(a @ x - b))


def directions(kernels) -> np.ndarray:
    """Contact directions (M, 5) at the unloaded geometry of case 0: columns a contact can push on."""
    parts = []
    for k in kernels:
        reach = getattr(k, "reach", None)
        parts.append(reach if reach is not None else (k.G[0] if hasattr(k, "G") else k.directions[0]))
    return np.concatenate(parts, axis=0)


def shared_directions(kernels) -> np.ndarray | None:
    """The contact directions (M, 5) when every case shares the geometry, else None."""
    for k in kernels:
        per_case = k.G if hasattr(k, "G") else k.directions
        if np.shape(per_case)[0] != 1:
            return None
    return directions(kernels)


#: What a user can do when the load lies outside the contacts' reach, by the worst component.
_CONE_HINTS = {
    "F_z": "; check the sign of F_z, raise it (to F_r tan(alpha) or more) or use a DB/DF pair",
    "M_x": "; fix the tilt ([solver] free) or use more rows",
    "M_y": "; fix the tilt ([solver] free) or use more rows",
}


def outside_cone(kernels, scale: np.ndarray, idx: np.ndarray, load: np.ndarray) -> np.ndarray:
    """Which loads (C, 5) no non-negative combination of the unloaded contact directions balances (C,).

    Only for geometries shared by every case (otherwise nothing is flagged). One NNLS per case:
    meant for the few cases a solve is struggling with. ``scale`` (5,) makes moments forces (M/L),
    ``idx`` the free DOFs.
    """
    g = shared_directions(kernels)
    out = np.zeros(len(load), bool)
    if g is None:
        return out
    g = (g * scale)[:, idx]
    f = (load * scale)[:, idx]
    for c in range(len(f)):
        size = np.linalg.norm(f[c])
        out[c] = size > 0.0 and nnls(g.T, f[c])[1] > CONE_MISS_RTOL * size
    return out


def check_directions(kernels, scale: np.ndarray, idx: np.ndarray, load: np.ndarray) -> None:
    """Refuse, before solving, a load on a free DOF that no contact acts on at all."""
    g = directions(kernels) * scale
    reach = np.abs(g).max(axis=0)
    for i in idx:
        if reach[i] <= 1e-12 * reach.max() and np.any(np.abs(load[:, i]) > 0):
            raise InputError(
                f"load {LOAD_NAMES[i]} ({np.abs(load[:, i]).max():.6g}) acts on a DOF no row of this bearing "
                f"can carry ({DOF_NAMES[i]}); remove the load, or fix that DOF (leave {DOF_NAMES[i]} out "
                "of [solver] free in a bearing file)"
            )


#: A residual below this fraction of the load scale is round-off-limited rather than failed (the
#: light-load cases of issue 41 stopped between 2e-10 and 7e-8 with the tolerance at 1e-10).
NEAR_CONVERGED = 1e-6


def diagnose(kernels, scale, idx, load: np.ndarray, diverged: bool, norm: float) -> str:
    """One-line reason for a failed case (load (5,)), using the cone of contact directions."""
    g = (directions(kernels) * scale)[:, idx]
    f = (load * scale)[idx]
    lam, miss = nnls(g.T, f)
    size = max(np.linalg.norm(f), 1e-300)
    if miss > CONE_MISS_RTOL * size:
        comp = (f - g.T @ lam) / size
        worst = LOAD_NAMES[idx[int(np.argmax(np.abs(comp)))]]
        return (
            f"the load cannot be carried: no combination of contact forces balances it (unbalanced mainly in "
            f"{worst}){_CONE_HINTS.get(worst, '')}"
        )
    if diverged:
        return (
            "displacement diverged beyond half an element diameter: the load exceeds what the contacts "
            "carry; give a smaller load, or free the DOF it pushes along"
        )
    if norm < NEAR_CONVERGED:
        # Light loads: the contact approaches are tiny differences of displacements and clearances
        # (round-off ~1e-16 of the clearance), so the force balance cannot get much closer.
        return (
            f"Newton stopped at a residual of {norm:.3g} of the load scale, above the tolerance: the load "
            "is so light that round-off of the contact approaches limits the balance; give a larger load "
            "or accept it with [solver] rtol = 1e-8"
        )
    return (
        f"Newton did not reach the tolerance (residual {norm:.3g} of the load scale); raise [solver] "
        "max_iterations, or check the load (far below the elements' centrifugal forces at speed it has "
        "no balance)"
    )
