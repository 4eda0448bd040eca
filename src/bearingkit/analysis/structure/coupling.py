r"""The coupled solve of any bearing with flexible rings or an imported structure.

SI units (m, N, rad). A :class:`Structure` holds what carries the raceways: an outer and/or an inner
ring, each a curved beam on its supports (:class:`~bearingkit.rings.curved_beam.FlexibleRing`) or a
condensed matrix from an FE model (:class:`~bearingkit.rings.imported.ImportedStructure`). Both give a
linear compliance G (3N × 3N) of the raceway offsets x = (radial, axial, tilt) of the N elements
(:class:`~bearingkit.rows.base.RacewayOffset`, outer raceway relative to inner) per the loads
f = (F_r, F_z, M_t) the elements put on the outer raceway; an inner ring's compliance adds to the
outer one's (its loads and its motion both enter reversed).

The coupled state is the fixed point x = G f(x), f the element loads of the engine's equilibrium
solved with the offsets x (every row kind's ``raceway_loads``). Newton on r(x) = G f(x) − x:

.. math:: (I - G\,\mathrm{d}f/\mathrm{d}x)\,\Delta x = r,\qquad
          \frac{\mathrm{d}f}{\mathrm{d}x} = D + A K_{ff}^{-1} A^T

with D = ∂f/∂x at fixed q (block diagonal: each element sees its own offsets), A = ∂f/∂q, K the
engine's tangent stiffness on the free DOFs, and the contact symmetry ∂F/∂x = Aᵀ (f = −∂U/∂x,
F = −∂U/∂q): no engine solve beyond the one per line-search trial. D and A by central differences of
the row kernels at fixed q (6 + 10 batched evaluations). A backtracking line search on ‖r‖₂ as in
:mod:`bearingkit.analysis.flexible` (Kelley 2003). The rigid ring (G = 0) is the first iterate's
solution: x = 0, the engine's rigid solve, exactly.

What the seed-002 bearing does (:mod:`bearingkit.analysis.flexible`, beam + ovalisation of one outer
ring) stays there unchanged; with its in-plane thin ring alone the two give the same solution
(tests/analysis/test_structure_seed002.py).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from threadpoolctl import threadpool_limits

from bearingkit import checks
from bearingkit.analysis.solver.options import SolverOptions
from bearingkit.analysis.solver.quasistatic import solve
from bearingkit.rows.base import RacewayOffset

#: Central-difference steps: offsets and translations [m], rotations [rad] per metre of arm.
FD_STEP = 1e-9
#: Largest number of step halvings of the Newton line search.
NEWTON_BACKTRACKS = 6


@dataclass(frozen=True)
class ElementPoints:
    """The reference points of the elements of a bearing's rows (SI).

    Attributes
    ----------
    rows : tuple of str
        Row names, in the model's order.
    sizes : tuple of int
        Elements per row.
    azimuth, radius, z : ndarray (N,)
        Element centre: azimuth [rad], pitch radius [m], axial position [m].
    """

    rows: tuple
    sizes: tuple
    azimuth: np.ndarray
    radius: np.ndarray
    z: np.ndarray

    @classmethod
    def of(cls, model) -> ElementPoints:
        psi, r, z = [], [], []
        for row, kernel in zip(model.rows, model.kernels, strict=True):
            a = np.asarray(kernel.psi, dtype=float)
            a = a.reshape(-1, a.shape[-1])
            if a.shape[0] > 1 and not np.allclose(a, a[0]):
                raise checks.InputError(
                    f"row {row.name!r}: its element azimuths vary per case; a structure needs one layout"
                )
            a = a[0]
            if getattr(row, "kind", "") == "threaded":
                rad, pos = row.geometry.pitch_diameter / 2, row.axial_position
            else:
                rad = np.asarray(row.pitch_diameter, dtype=float) / 2
                pos = np.asarray(row.axial_position, dtype=float)
                if rad.size > 1 or pos.size > 1:
                    if np.ptp(rad) > 0 or np.ptp(pos) > 0:
                        raise checks.InputError(
                            f"row {row.name!r}: its pitch diameter or position varies per case; a structure "
                            "needs one layout"
                        )
                    rad, pos = rad.ravel()[0], pos.ravel()[0]
            psi.append(a)
            r.append(np.full(a.size, float(rad)))
            z.append(np.full(a.size, float(pos)))
        return cls(
            tuple(row.name for row in model.rows),
            tuple(len(a) for a in psi),
            np.concatenate(psi),
            np.concatenate(r),
            np.concatenate(z),
        )

    @property
    def n(self) -> int:
        return int(sum(self.sizes))

    def indices(self, rows) -> np.ndarray:
        """Element indices (into the N) of the rows named (all rows when None)."""
        starts = np.concatenate([[0], np.cumsum(self.sizes)])
        names = list(self.rows)
        pick = names if rows is None else list(rows)
        return np.concatenate([np.arange(starts[names.index(n)], starts[names.index(n) + 1]) for n in pick])


@dataclass(frozen=True)
class Structure:
    """What carries the raceways: an outer and/or an inner ring model (None: rigid).

    Parameters
    ----------
    outer, inner : FlexibleRing, ImportedStructure or None
        Objects with ``rows`` (names carried, None: all), ``side`` and
        ``compliance(azimuth, radius, z)`` → (3N, 3N).
    """

    outer: object | None = None
    inner: object | None = None

    @property
    def parts(self) -> list:
        return [p for p in (self.outer, self.inner) if p is not None]

    def compliance(self, points: ElementPoints) -> np.ndarray:
        """G (3N, 3N): the raceway offsets (outer relative to inner) per element loads, both rings."""
        n = points.n
        g = np.zeros((3 * n, 3 * n))
        for part in self.parts:
            idx = points.indices(part.rows)
            c = part.compliance(points.azimuth[idx], points.radius[idx], points.z[idx])
            dof = (3 * idx[:, None] + np.arange(3)).ravel()
            g[np.ix_(dof, dof)] += c
        return g


@dataclass
class Coupled:
    """Raw outcome of :func:`solve_structure` (:class:`~bearingkit.analysis.structure.result.StructureResult`
    wraps it for the faces)."""

    result: object
    rigid: object
    converged: np.ndarray
    iterations: np.ndarray
    offset_change: np.ndarray
    history: list
    x: np.ndarray
    loads: np.ndarray
    compliance: np.ndarray
    points: ElementPoints


def _combine(base: dict | None, names, sizes, x, n_cases) -> dict:
    """{row: RacewayOffset}: the structure's offsets x (C, 3N) on top of ``base`` (fits, preload)."""
    out = dict(base or {})
    cuts = np.cumsum(sizes)[:-1]
    parts = np.split(x.reshape(n_cases, -1, 3), cuts, axis=1)
    for name, p in zip(names, parts, strict=True):
        old = out.get(name)
        radial = p[..., 0] if old is None or old.radial is None else p[..., 0] + old.radial
        out[name] = RacewayOffset(
            shift=None if old is None else old.shift,
            radial=radial,
            axial=p[..., 1] if old is None or old.axial is None else p[..., 1] + old.axial,
            tilt=p[..., 2] if old is None or old.tilt is None else p[..., 2] + old.tilt,
        )
    return out


def element_loads(model, q, offsets: dict | None) -> np.ndarray:
    """(C, 3N) loads (F_r, F_z, M_t) of every element on the outer raceway at fixed q (no solve)."""
    out = []
    for row, kernel in zip(model.rows, model.kernels, strict=True):
        if not hasattr(kernel, "raceway_loads"):
            raise checks.InputError(f"row {row.name!r} ({row.kind}) has no raceway loads for a structure")
        out.append(kernel.raceway_loads(q, None if offsets is None else offsets.get(row.name)))
    return np.concatenate(out, axis=1).reshape(q.shape[0], -1)


def _jacobian(model, res, offsets, free, length) -> np.ndarray:
    """df/dx (C, 3N, 3N) at the engine solution (module docstring)."""
    q = res.displacement
    n_cases = q.shape[0]
    h = FD_STEP
    scale = np.array([1.0, 1.0, 1.0, 1.0 / length, 1.0 / length])
    a = []
    for k in range(5):
        dq = np.zeros(5)
        dq[k] = h * scale[k]
        a.append(
            (element_loads(model, q + dq, offsets) - element_loads(model, q - dq, offsets)) / (2 * dq[k])
        )
    a = np.stack(a, axis=-1)  # (C, 3N, 5)
    m = a.shape[1]
    d = np.zeros((n_cases, m // 3, 3, 3))
    steps = (h, h, h / length)
    for c in range(3):
        plus, minus = _bumped(offsets, c, steps[c]), _bumped(offsets, c, -steps[c])
        diff = (element_loads(model, q, plus) - element_loads(model, q, minus)) / (2 * steps[c])
        d[:, :, :, c] = diff.reshape(n_cases, -1, 3)
    dfdx = np.zeros((n_cases, m, m))
    idx = np.arange(m // 3)
    for i in range(3):
        for j in range(3):
            dfdx[:, 3 * idx + i, 3 * idx + j] = d[:, :, i, j]
    fr = np.flatnonzero(free)
    stiff = res.stiffness[:, fr][:, :, fr]
    reg = 1e-12 * np.abs(stiff).max(axis=(1, 2))[:, None, None] * np.eye(fr.size) + 1e-300 * np.eye(fr.size)
    af = a[:, :, fr]
    dfdx += af @ np.linalg.solve(stiff + reg, np.swapaxes(af, 1, 2))
    return dfdx


def _bumped(offsets: dict, component: int, h: float) -> dict:
    key = ("radial", "axial", "tilt")[component]
    out = {}
    for name, o in offsets.items():
        fields = {"shift": o.shift, "radial": o.radial, "axial": o.axial, "tilt": o.tilt}
        fields[key] = fields[key] + h
        out[name] = RacewayOffset(**fields)
    return out


def solve_structure(
    model,
    load,
    structure: Structure,
    *,
    free=None,
    options: SolverOptions | None = None,
    speed=None,
    base_offsets: dict | None = None,
    rigid=None,
    atol: float = 1e-11,
    rtol: float = 1e-8,
    max_iterations: int = 50,
) -> Coupled:
    r"""Solve the quasi-static equilibrium with the structure's compliance, batched over load cases.

    Parameters
    ----------
    model : BearingModel
    load : array_like (5,) or (C, 5) [N, N, N, N·m, N·m]
    structure : Structure
    free : array_like of 5 bool, optional
    options : SolverOptions, optional
    speed : optional
        As :func:`~bearingkit.analysis.solver.quasistatic.solve`.
    base_offsets : dict, optional
        Offsets already imposed (fits, preload), kept under the structure's.
    rigid : QuasiStaticResult, optional
        The rigid solve of the same cases (computed when not given).
    atol : float [m]
        Absolute tolerance on max |G f − x| (tilts times the pitch radius).
    rtol : float [–]
        Relative tolerance (times the largest offset of the case).
    max_iterations : int

    Returns
    -------
    Coupled
        Never raises on non-convergence: ``converged`` is False per case.

    Notes
    -----
    Newton on r(x) = G f(x) − x with the Jacobian of the module docstring and a backtracking line
    search on ‖r‖₂ (halving, at most :data:`NEWTON_BACKTRACKS` times; Kelley 2003, ch. 1–2).
    """
    checks.positive("atol", atol, "m")
    checks.non_negative("rtol", rtol)
    checks.integer("max_iterations", max_iterations, low=1)
    free = np.ones(5, bool) if free is None else np.asarray(free, dtype=bool)
    points = ElementPoints.of(model)
    g = structure.compliance(points)
    length = float(np.max(points.radius))
    unit = np.tile([1.0, 1.0, length], points.n)  # tilts to metres in the convergence test

    def engine(x, q0):
        offs = _combine(base_offsets, points.rows, points.sizes, x, x.shape[0])
        return solve(
            model, load, free=free, displacement=q0, options=options, raceway_offsets=offs, speed=speed
        )

    if rigid is None:
        rigid = solve(model, load, free=free, options=options, raceway_offsets=base_offsets, speed=speed)
    res = rigid
    n_cases = res.displacement.shape[0]
    x = np.zeros((n_cases, 3 * points.n))
    offsets = _combine(base_offsets, points.rows, points.sizes, x, n_cases)

    def residual(res, offsets, x):
        f = element_loads(res.model, res.displacement, offsets)
        return np.einsum("ij,cj->ci", g, f) - x, f

    r, f = residual(res, offsets, x)
    failed = ~res.converged
    done = np.zeros(n_cases, bool)
    iterations = np.zeros(n_cases, int)
    change = np.full(n_cases, np.inf)
    history = []
    for step_no in range(max_iterations + 1):
        r = np.where(failed[:, None], 0.0, r)
        change = np.where(done | failed, change, np.abs(r * unit).max(axis=-1))
        history.append(change.copy())
        size = np.abs(x * unit).max(axis=-1)
        done |= (change <= atol + rtol * size) & ~failed
        active = ~(done | failed)
        if not active.any() or step_no == max_iterations:
            break
        iterations += active
        with threadpool_limits(limits=1, user_api="blas"):
            dfdx = _jacobian(res.model, res, offsets, free, length)
            jac = np.eye(x.shape[-1]) - np.einsum("ij,cjk->cik", g, dfdx)
            step = np.linalg.solve(jac, r[..., None])[..., 0]
        step = np.where(active[:, None], step, 0.0)
        x, res, r, f = _line_search(engine, residual, points, base_offsets, x, res, r, step, active)
        offsets = _combine(base_offsets, points.rows, points.sizes, x, n_cases)
        failed = failed | ~res.converged | ~np.isfinite(res.displacement).all(axis=-1)
    converged = done & res.converged & ~failed
    return Coupled(res, rigid, converged, iterations, change, history, x, f, g, points)


def _line_search(engine, residual, points, base, x, res, r, step, active):
    """Backtracking on ‖G f − x‖₂ per case; returns x, its engine result, residual and loads."""
    norm0 = np.linalg.norm(r, axis=-1)
    t = np.ones(x.shape[0])
    pending = active.copy()
    x_new = x.copy()
    for attempt in range(NEWTON_BACKTRACKS + 1):
        x_try = np.where(pending[:, None], x + t[:, None] * step, x_new)
        trial = engine(x_try, res.displacement)
        offs = _combine(base, points.rows, points.sizes, x_try, x.shape[0])
        r_try, f_try = residual(trial, offs, x_try)
        ok = trial.converged & (np.linalg.norm(r_try, axis=-1) <= (1.0 - 1e-4 * t) * norm0)
        accept = pending & (ok | (attempt == NEWTON_BACKTRACKS))
        x_new = np.where(accept[:, None], x_try, x_new)
        pending &= ~accept
        if not pending.any():
            return x_new, trial, r_try, f_try
        t = np.where(pending, 0.5 * t, t)
    raise AssertionError("unreachable: the last attempt accepts every pending case")  # pragma: no cover
