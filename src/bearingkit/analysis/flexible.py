"""Coupled solve of a bearing with a flexible outer ring: contact equilibrium ↔ ring compliance.

SI units (m, N, rad). The engine (:func:`bearingkit.analysis.quasistatic.solve`) solves the inner-
ring equilibrium for given outer-raceway offsets (``raceway_offsets``); the ring
(:class:`bearingkit.rings.FlexibleOuterRing`) maps the resulting element loads to new offsets. The
coupled state is the fixed point x = T(x) of the offsets x (all radial deflections and raceway
shifts of all rows, rotations scaled by the ring radius to metres). Iteration k:

.. math:: x_{k+1} = x_k + \\omega_k \\,(T(x_k) - x_k)

with a constant relaxation ω (``method="relaxed"``) or Aitken's adaptive Δ² relaxation per case
(``method="aitken"``, Irons & Tuck 1969; Küttler & Wall 2008):

.. math:: \\omega_{k} = -\\omega_{k-1}\\,\\frac{r_{k-1}\\cdot(r_k - r_{k-1})}{\\lVert r_k - r_{k-1}\\rVert^2},
          \\qquad r_k = T(x_k) - x_k

clipped to [ω_min, 1]. Converged when max|r_k| ≤ atol + rtol·max|x_k| for that case; converged
cases keep their offsets. Every iteration is one batched engine solve warm-started at the previous
displacement. Measured on the seed-002 bearing: see :mod:`bearingkit.studies.seed002`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks, references
from bearingkit.analysis.quasistatic import QuasiStaticResult, SolverOptions, solve
from bearingkit.rows.base import RacewayOffset

references.add(
    "kuttler2008",
    "Küttler U., Wall W.A. (2008) Fixed-point fluid-structure interaction solvers with dynamic "
    "relaxation. Computational Mechanics 43:61-72. doi:10.1007/s00466-008-0255-5",
)
#: Coupling methods (documented names).
METHODS = ("relaxed", "aitken")
#: Smallest Aitken relaxation factor allowed [–] (keeps the iteration moving).
AITKEN_MIN = 0.05


@dataclass
class FlexibleResult:
    """Coupled solution. ``result`` is the engine result at the final offsets.

    Attributes
    ----------
    result : QuasiStaticResult
    ring : FlexibleOuterRing
    converged : ndarray (C,) of bool
        Offsets converged *and* the last engine solve converged.
    iterations : ndarray (C,) of int
        Coupling iterations (engine solves) used per case.
    offset_change : ndarray (C,) [m]
        Last max |T(x) − x| (rotations scaled by the ring radius).
    history : list of ndarray (C,)
        offset_change per iteration (convergence history).
    offsets : dict of str to RacewayOffset
    """

    result: QuasiStaticResult
    ring: object
    converged: np.ndarray
    iterations: np.ndarray
    offset_change: np.ndarray
    history: list = field(default_factory=list)
    offsets: dict = field(default_factory=dict)

    @property
    def model(self):
        return self.result.model

    def row(self, name):
        return self.result.row(name)

    def row_load(self, name):
        return self.result.row_load(name)

    def deflection_shape(self, theta) -> np.ndarray:
        """Thin-ring bending deflection (C, M) [m] at angles θ."""
        return self.ring.deflection_shape(self.result.model, self.result, theta)


def _pack(model, offsets: dict, length: float, n_cases: int) -> np.ndarray:
    parts = []
    for r in model.rows:
        o = offsets.get(r.name)
        if o is None:
            continue
        if o.radial is not None:
            parts.append(np.broadcast_to(o.radial, (n_cases, o.radial.shape[-1])))
        if o.shift is not None:
            parts.append(o.shift[:, :3])
            parts.append(o.shift[:, 3:] * length)
    return np.concatenate(parts, axis=-1) if parts else np.zeros((n_cases, 0))


def _unpack(model, template: dict, x: np.ndarray, length: float) -> dict:
    out, i = {}, 0
    for r in model.rows:
        o = template.get(r.name)
        if o is None:
            continue
        radial = shift = None
        if o.radial is not None:
            n = o.radial.shape[-1]
            radial, i = x[:, i : i + n], i + n
        if o.shift is not None:
            shift = np.concatenate([x[:, i : i + 3], x[:, i + 3 : i + 5] / length], axis=-1)
            i += 5
        out[r.name] = RacewayOffset(shift=shift, radial=radial)
    return out


def solve_flexible(
    model,
    load,
    ring,
    *,
    method: str = "aitken",
    relaxation: float = 0.5,
    atol: float = 1e-11,
    rtol: float = 1e-8,
    max_iterations: int = 200,
    free=None,
    options: SolverOptions | None = None,
) -> FlexibleResult:
    """Solve the quasi-static equilibrium with the outer ring's compliance, batched over load cases.

    Parameters
    ----------
    model : BearingModel
    load : array_like (5,) or (C, 5) [N, N, N, N·m, N·m]
    ring : FlexibleOuterRing
    method : str
        ``"aitken"`` (default, adaptive relaxation) or ``"relaxed"`` (constant ω), see :data:`METHODS`.
    relaxation : float
        ω of the relaxed method and the first Aitken step (0 < ω ≤ 1).
    atol : float [m]
        Absolute tolerance on the offset change.
    rtol : float [–]
        Relative tolerance on the offset change (times the largest offset of the case).
    max_iterations : int
        Largest number of coupling iterations (engine solves).
    free : array_like of 5 bool, optional
        Free inner-ring DOFs (as in :func:`~bearingkit.analysis.quasistatic.solve`).
    options : SolverOptions, optional
        Options of every engine solve.

    Returns
    -------
    FlexibleResult
        Never raises on non-convergence: ``converged`` is False with ``offset_change`` as diagnosis.
    """
    checks.one_of("method", method, METHODS)
    checks.in_range("relaxation", relaxation, 0.0, 1.0, closed=True)
    if relaxation == 0:
        raise checks.InputError("relaxation (0) must be positive (0 < ω ≤ 1)")
    checks.positive("atol", atol, "m")
    checks.non_negative("rtol", rtol)
    checks.integer("max_iterations", max_iterations, low=1)
    length = float(ring.section.centroid_radius)

    res = solve(model, load, free=free, options=options)
    q = res.displacement
    n_cases = q.shape[0]
    template = ring.offsets(model, res)
    x = np.zeros_like(_pack(model, template, length, n_cases))
    offsets = _unpack(model, template, x, length)
    done = np.zeros(n_cases, bool)
    iterations = np.zeros(n_cases, int)
    change = np.full(n_cases, np.inf)
    omega = np.full(n_cases, float(relaxation))
    r_prev = None
    history = []
    failed = ~res.converged
    for _ in range(max_iterations):
        tx = _pack(model, ring.offsets(model, res), length, n_cases)
        r = np.where(failed[:, None], 0.0, tx - x)  # a failed engine solve freezes its case
        change = np.where(done | failed, change, np.abs(r).max(axis=-1) if r.shape[-1] else 0.0)
        history.append(change.copy())
        scale = np.abs(x).max(axis=-1) if x.shape[-1] else np.zeros(n_cases)
        done = done | ((change <= atol + rtol * scale) & ~failed)
        if (done | failed).all():
            break
        if method == "aitken" and r_prev is not None:
            dr = r - r_prev
            den = np.einsum("ci,ci->c", dr, dr)
            num = np.einsum("ci,ci->c", r_prev, dr)
            new = np.where(den > 0, -omega * num / np.where(den > 0, den, 1.0), omega)
            omega = np.clip(new, AITKEN_MIN, 1.0)
        r_prev = r
        x = np.where((done | failed)[:, None], x, x + omega[:, None] * r)
        iterations += ~(done | failed)
        offsets = _unpack(model, template, x, length)
        res = solve(
            model,
            load,
            free=free,
            displacement=q if free is None else None,
            options=options,
            raceway_offsets=offsets,
        )
        failed = failed | ~res.converged | ~np.isfinite(res.displacement).all(axis=-1)
        q = np.where(np.isfinite(res.displacement), res.displacement, 0.0)
    converged = done & res.converged & ~failed
    return FlexibleResult(res, ring, converged, iterations, change, history, offsets)
