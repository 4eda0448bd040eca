"""Coupled solve of a bearing with a flexible outer ring: contact equilibrium ↔ ring compliance.

SI units (m, N, rad). The engine (:func:`bearingkit.analysis.solver.quasistatic.solve`) solves the inner-
ring equilibrium for given outer-raceway offsets (``raceway_offsets``); the ring
(:class:`bearingkit.rings.FlexibleOuterRing`) maps the resulting element loads to new offsets. The
coupled state is the fixed point x = T(x) of the offsets x (all radial offsets of the carried
elements, then the raceway shifts of the rows, rotations scaled by the ring radius to metres).

Methods (``method``, :data:`METHODS`):

- ``"newton"`` (default): Newton on r(x) = T(x) − x, (I − ∂T/∂x) Δx = r, with a backtracking line
  search on ‖r‖₂. ∂T/∂x comes from the chain rule at the engine solution, without extra engine
  solves (:func:`_fixed_point_jacobian`): element loads re-evaluated at fixed q by central
  differences (7 batched evaluations), the contact symmetry ∂f/∂w_j = ∂P_j/∂q, the condensation
  dq/dx = K⁻¹ ∂f/∂x with the engine's tangent stiffness K, and the ring's own linear maps;
- ``"aitken"``: x_{k+1} = x_k + ω_k r_k with Aitken's adaptive Δ² relaxation per case (Irons &
  Tuck 1969; Küttler & Wall 2008), ω_k = −ω_{k−1} r_{k−1}·(r_k − r_{k−1}) / ‖r_k − r_{k−1}‖²,
  clipped to [:data:`AITKEN_MIN`, 1];
- ``"relaxed"``: the same with a constant ω.

Converged when max|r| ≤ atol + rtol·max|x| for that case; converged cases keep their offsets.

**Measured** on the seed-002 bearing (:func:`bearingkit.bearings.ball_column.outer_ring`, 74 + 78 + 74
elements, 20 slices; conditions 1–3 of Table 2 and radial-load sweeps 0.5–200 kN (15 loads) at zero
clearance and at ball 10 µm / roller 20 µm; compliance scales 0.5 and 1; 50 iterations allowed):

=====================  ==============================  ======================================
ring model             newton                          aitken / relaxed (ω = 0.5)
=====================  ==============================  ======================================
beam + ovalisation     66/66 converge, ≤ 10 its (~7)   0/66: offsets blow up in 2–3 steps
beam only              66/66 converge, 2–4 its         66/66, ≤ 6 its / ≤ 46 its
=====================  ==============================  ======================================

With ovalisation the in-plane ring (EI = 572 N·m² for the arc-backed section) is far softer than
the contacts: the spectral radius of ∂T/∂x at the solution is ≈ 2,900 (conditions 1 and 3; a real
negative eigenvalue), so every relaxed fixed point with ω > 2/2,900 diverges; Newton
converges quadratically at the end (residual 1e-5 → 1e-7 → 1e-10 → 1e-16 m). For the beam alone
the gain is small and Aitken converges in about as many engine solves as Newton at less cost per
iteration; Newton is the default because it converges in every case measured. Scales 3–12 (full
model) converge in 8–9 Newton iterations. A Newton iteration costs one engine solve per line-search
trial (one when the full step is accepted) plus the Jacobian; conditions 1–3 together take ≈ 0.5 s,
a 15-load sweep ≈ 1 s (2 shared cores). The table is for the free ring (no housing); a housing
(:attr:`~bearingkit.rings.FlexibleOuterRing.housing_stiffness`) stiffens the ovalisation and lowers
the gain: condition 1 at scale 0.5 takes 7 Newton iterations free, 3–5 with steel walls of 5–80 mm
and 3 with a rigid housing (measured, ``papers.li2025.studies.housing_study``).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np
from threadpoolctl import threadpool_limits

from bearingkit import checks, references
from bearingkit.analysis.solver.options import SolverOptions
from bearingkit.analysis.solver.quasistatic import QuasiStaticResult, solve
from bearingkit.rows.base import RacewayOffset

references.add(
    "kelley2003",
    "Kelley C.T. (2003) Solving Nonlinear Equations with Newton's Method. SIAM, Philadelphia, ch. 1-2 "
    "(Newton with a backtracking line search on the residual norm).",
)
references.add(
    "kuttler2008",
    "Küttler U., Wall W.A. (2008) Fixed-point fluid-structure interaction solvers with dynamic "
    "relaxation. Computational Mechanics 43:61-72. doi:10.1007/s00466-008-0255-5",
)
#: Coupling methods (documented names).
METHODS = ("newton", "aitken", "relaxed")
#: Central-difference step on raceway offsets and inner-ring translations [m] (≈ 1e-4 of a typical
#: contact approach of 10 µm: truncation ~1e-8, round-off ~1e-7 of the derivative).
FD_STEP = 1e-9
#: Largest number of step halvings of the Newton line search.
NEWTON_BACKTRACKS = 6
#: Azimuths (equally spaced, 5°) of the ring deflection shape in :meth:`FlexibleResult.to_dict`.
SHAPE_POINTS = 72


def _finite(value) -> float | None:
    """A float for JSON, None for an infinite or undefined value (a rigid ring's EI)."""
    v = float(value)
    return v if np.isfinite(v) else None


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
    method : str
        Coupling method used (:data:`METHODS`).
    """

    result: QuasiStaticResult
    ring: object
    converged: np.ndarray
    iterations: np.ndarray
    offset_change: np.ndarray
    history: list = field(default_factory=list)
    offsets: dict = field(default_factory=dict)
    method: str = "newton"

    @property
    def model(self):
        return self.result.model

    def row(self, name):
        return self.result.row(name)

    def row_load(self, name):
        return self.result.row_load(name)

    @property
    def n_cases(self) -> int:
        return self.result.n_cases

    def deflection_shape(self, theta) -> np.ndarray:
        """Thin-ring bending deflection (C, M) [m] at angles θ."""
        return self.ring.deflection_shape(self.result.model, self.result, theta)

    def shares(self) -> dict:
        """Per-row share of the radial and of the axial load {row: (radial (C,), axial (C,))} [–].

        Radial share: |F_r,row| / Σ_rows |F_r,row|; axial share: |F_a,row| / Σ_rows |F_a,row|
        (magnitudes: two O-arranged ball rows under a pure radial load carry equal and opposite axial
        forces and get 0.5 each; 0 only when no row carries axial force at all).
        """
        names = [r.name for r in self.model.rows]
        loads = {n: self.row_load(n) for n in names}
        radial = {n: np.hypot(v[:, 0], v[:, 1]) for n, v in loads.items()}
        axial = {n: np.abs(v[:, 2]) for n, v in loads.items()}
        tot_r = sum(radial.values())
        tot_a = sum(axial.values())
        safe = lambda a, t: np.where(t > 0, a / np.where(t > 0, t, 1.0), 0.0)  # noqa: E731
        return {n: (safe(radial[n], tot_r), safe(axial[n], tot_a)) for n in names}

    def to_dict(self, case: int | None = None) -> dict | list[dict]:
        """JSON-ready dict (SI values, units in keys); a list over cases when ``case`` is None.

        The engine's dict at the coupled solution (:meth:`QuasiStaticResult.to_dict`: loads, loaded
        counts, max contact load and pressure per row), with per row the radial and axial share and
        the outer-raceway radial offset at each element, the coupling diagnostics, and the ring:
        its model and the bending deflection shape on :data:`SHAPE_POINTS` azimuths, with the ring's
        bending moment ``bending_moment_Nm`` (outer fibre in tension > 0), hoop force ``hoop_force_N``
        (housing model: the uniform part of the element loads is the housing's) and, when the section
        knows its radii, the hoop stress at the inner and outer fibre and its largest magnitude.
        """
        if case is None:
            return [self.to_dict(c) for c in range(self.n_cases)]
        out = self.result.to_dict(case)
        out["engine_converged"] = out["converged"]
        out["converged"] = bool(self.converged[case])
        shares = self.shares()
        for entry in out["rows"]:
            radial, axial = shares[entry["name"]]
            entry["radial_share"] = float(radial[case])
            entry["axial_share"] = float(axial[case])
            off = self.offsets.get(entry["name"])
            if off is not None and off.radial is not None:
                entry["raceway_radial_offset_m"] = np.broadcast_to(
                    off.radial, (self.n_cases, off.radial.shape[-1])
                )[case].tolist()
        out["coupling"] = {
            "method": self.method,
            "iterations": int(self.iterations[case]),
            "offset_change_m": _finite(self.offset_change[case]),
        }
        theta = np.linspace(0.0, 2.0 * np.pi, SHAPE_POINTS, endpoint=False)
        ring = self.ring
        out["ring"] = {
            "rows": list(ring.rows) if ring.rows is not None else [r.name for r in self.model.rows],
            "compliance_scale": float(ring.compliance_scale),
            "bending": bool(ring.bending),
            "beam_mode": ring.beam_mode,
            "flexural_rigidity_Nm2": _finite(ring.flexural_rigidity),
            "housing_stiffness_N_per_m2": _finite(ring.housing_stiffness),
            "beam_rigidity_Nm2": _finite(ring.beam_rigidity),
            "support_positions_m": None
            if ring.support_positions is None
            else [float(v) for v in ring.support_positions],
            "centroid_radius_m": float(ring.section.centroid_radius),
            "shape_azimuth_rad": theta.tolist(),
            "bending_deflection_m": self.deflection_shape(theta)[case].tolist(),
        }
        forces = self.ring_forces(theta)
        out["ring"]["bending_moment_Nm"] = forces.moment[case].tolist()
        out["ring"]["hoop_force_N"] = forces.normal_force[case].tolist()
        stress = ring.fibre_stress(forces)
        if stress is not None:
            inner, outer = (s[case] for s in stress)
            out["ring"]["fibre_stress_inner_Pa"] = inner.tolist()
            out["ring"]["fibre_stress_outer_Pa"] = outer.tolist()
            out["ring"]["max_fibre_stress_Pa"] = float(max(np.abs(inner).max(), np.abs(outer).max()))
        return out

    def ring_forces(self, theta):
        """Ring bending moment M (outer fibre in tension > 0), hoop force and shear (C, M) at θ
        (:meth:`~bearingkit.rings.flexible.FlexibleOuterRing.ring_forces`)."""
        return self.ring.ring_forces(self.result.model, self.result, theta)


def _layout(ring, model) -> tuple[list, list, tuple]:
    """Carried row indices, their names and element counts."""
    idx = ring.carried(model)
    names = [model.rows[i].name for i in idx]
    sizes = tuple(int(model.rows[i].n_elements) for i in idx)
    return idx, names, sizes


def _pack(ring, names, offsets: dict, length: float, n_cases: int) -> np.ndarray:
    """Offsets → unknown vector x (C, n): all radial entries (rows concatenated), then 5 per row shift."""
    parts = []
    if ring.has_radial:
        for n in names:
            r = offsets[n].radial
            parts.append(np.broadcast_to(r, (n_cases, r.shape[-1])))
    if ring.has_shift:
        for n in names:
            s = offsets[n].shift
            parts += [s[:, :3], s[:, 3:] * length]
    return np.concatenate(parts, axis=-1) if parts else np.zeros((n_cases, 0))


def _unpack(ring, names, sizes, x: np.ndarray, length: float) -> dict:
    """Unknown vector x (C, n) → {row name: RacewayOffset} (inverse of :func:`_pack`)."""
    n_r = sum(sizes) if ring.has_radial else 0
    cuts = np.cumsum(sizes)[:-1]
    radial = np.split(x[:, :n_r], cuts, axis=-1) if ring.has_radial else [None] * len(names)
    shifts = [None] * len(names)
    if ring.has_shift:
        sh = x[:, n_r:].reshape(x.shape[0], len(names), 5)
        shifts = [np.concatenate([sh[:, k, :3], sh[:, k, 3:] / length], axis=-1) for k in range(len(names))]
    return {n: RacewayOffset(shift=s, radial=r) for n, r, s in zip(names, radial, shifts, strict=True)}


def _element_loads(model, ring, idx, names, q, offsets) -> np.ndarray:
    """Outward radial element loads (C, N) [N] of the carried rows at fixed q and offsets (no solve)."""
    states = [model.kernels[i].state(q, offsets[n]) for i, n in zip(idx, names, strict=True)]
    return ring.element_loads(states)[1]


def _shifted(offsets: dict, d_radial: float) -> dict:
    return {
        n: RacewayOffset(o.shift, None if o.radial is None else o.radial + d_radial)
        for n, o in offsets.items()
    }


def _fixed_point_jacobian(model, ring, res, x, layout, length, free, cmat) -> np.ndarray:
    """∂T/∂x (C, n, n) of the ring map x ↦ T(x) = ring(contact loads at the equilibrium for x).

    Chain rule at the engine solution q(x) (no engine solve: element loads are re-evaluated at fixed q):

    - P (element radial loads): ∂P/∂x|_q is diagonal for the radial entries (each element sees its
      own raceway offset) and −∂P/∂q for a row's shift entries; both by central differences;
    - contact force f on the inner ring: ∂f/∂w_j = ∂P_j/∂q (w_j opens the gap of element j, and
      ∂U/∂w_j = −P_j, so ∂f/∂w_j = −∂²U/∂q∂w_j = ∂P_j/∂q: Maxwell–Betti symmetry of the contacts);
    - equilibrium F + f(q, x) = 0 on the free DOFs: dq/dx = K_ff⁻¹ ∂f_f/∂x (K the tangent stiffness);
    - ring: ∂T/∂P is the thin-ring influence matrix, ∂T/∂(row forces) by central differences of the
      beam map (≤ 2 × rows evaluations of a closed form).
    """
    idx, names, sizes = layout
    q = res.displacement
    n_cases = q.shape[0]
    offsets = _unpack(ring, names, sizes, x, length)
    n_el = sum(sizes)
    n_r = n_el if ring.has_radial else 0
    n = x.shape[-1]
    scale = np.array([1.0, 1.0, 1.0, 1.0 / length, 1.0 / length])  # x-units → q-units per DOF
    h = FD_STEP
    # ∂P/∂q (C, N, 5) at fixed offsets, central differences per DOF (5 batched evaluations each way).
    dp_dq = np.empty((n_cases, n_el, 5))
    for k in range(5):
        dq = np.zeros(5)
        dq[k] = h * scale[k]
        plus = _element_loads(model, ring, idx, names, q + dq, offsets)
        minus = _element_loads(model, ring, idx, names, q - dq, offsets)
        dp_dq[..., k] = (plus - minus) / (2 * dq[k])
    jac_rows = [model.kernels[i].response(q, offsets[nm]).jacobian for i, nm in zip(idx, names, strict=True)]
    dp_dx = np.zeros((n_cases, n_el, n))
    df_dx = np.zeros((n_cases, 5, n))
    drl_dx = np.zeros((n_cases, len(idx), 2, n))  # row loads (x, y) carried by each row
    starts = np.concatenate([[0], np.cumsum(sizes)])
    if ring.has_radial:
        plus = _element_loads(model, ring, idx, names, q, _shifted(offsets, h))
        minus = _element_loads(model, ring, idx, names, q, _shifted(offsets, -h))
        diag = np.arange(n_el)
        dp_dx[:, diag, diag] = (plus - minus) / (2 * h)
        df_dx[:, :, :n_el] = np.swapaxes(dp_dq, 1, 2)
        for k in range(len(idx)):
            sl = slice(starts[k], starts[k + 1])
            drl_dx[:, k, :, sl] = -np.swapaxes(dp_dq[:, sl, :2], 1, 2)
    if ring.has_shift:
        for k in range(len(idx)):
            sl = slice(starts[k], starts[k + 1])
            cols = slice(n_r + 5 * k, n_r + 5 * k + 5)
            dp_dx[:, sl, cols] = -dp_dq[:, sl, :] * scale
            df_dx[:, :, cols] = -jac_rows[k] * scale
            drl_dx[:, k, :, cols] = jac_rows[k][:, :2, :] * scale
    fr = np.flatnonzero(np.asarray(free, dtype=bool)) if free is not None else np.arange(5)
    stiff = res.stiffness[:, fr][:, :, fr]
    reg = 1e-12 * np.abs(stiff).max(axis=(1, 2))[:, None, None] * np.eye(len(fr)) + 1e-300 * np.eye(len(fr))
    dq_dx = np.zeros((n_cases, 5, n))
    dq_dx[:, fr] = np.linalg.solve(stiff + reg, df_dx[:, fr])
    dp_dx = dp_dx + dp_dq @ dq_dx
    drl_dx = drl_dx + np.stack([-(j[:, :2, :] @ dq_dx) for j in jac_rows], axis=1)
    # Ring side.
    loads = ring.ring_loads(model, res)
    dt_dx = np.zeros((n_cases, n, n))
    if ring.bending:
        dt_dx[:, :n_el] += cmat @ dp_dx
    if ring.support_positions is not None:
        f0 = loads.row_forces
        step = 1e-7 * max(float(np.abs(f0).max()), 1.0)
        for k in range(len(idx)):
            for c in range(2):
                e = np.zeros_like(f0)
                e[:, k, c] = step
                plus = ring.offsets_from(model, replace(loads, row_forces=f0 + e), cmat)
                minus = ring.offsets_from(model, replace(loads, row_forces=f0 - e), cmat)
                tp = _pack(ring, names, plus, length, n_cases)
                tm = _pack(ring, names, minus, length, n_cases)
                dt_dx += ((tp - tm) / (2 * step))[:, :, None] * drl_dx[:, k, c][:, None, :]
    return dt_dx


def solve_flexible(
    model,
    load,
    ring,
    *,
    method: str = "newton",
    relaxation: float = 0.5,
    atol: float = 1e-11,
    rtol: float = 1e-8,
    max_iterations: int = 200,
    free=None,
    options: SolverOptions | None = None,
) -> FlexibleResult:
    r"""Solve the quasi-static equilibrium with the outer ring's compliance, batched over load cases.

    Parameters
    ----------
    model : BearingModel
    load : array_like (5,) or (C, 5) [N, N, N, N·m, N·m]
    ring : FlexibleOuterRing
    method : str
        ``"newton"`` (default), ``"aitken"`` (adaptive relaxation) or ``"relaxed"`` (constant ω), see
        :data:`METHODS` and the module docstring for what converges.
    relaxation : float
        ω of the relaxed method and the first Aitken step (0 < ω ≤ 1).
    atol : float [m]
        Absolute tolerance on the offset change.
    rtol : float [–]
        Relative tolerance on the offset change (times the largest offset of the case).
    max_iterations : int
        Largest number of coupling iterations.
    free : array_like of 5 bool, optional
        Free inner-ring DOFs (as in :func:`~bearingkit.analysis.solver.quasistatic.solve`).
    options : SolverOptions, optional
        Options of every engine solve.

    Returns
    -------
    FlexibleResult
        Never raises on non-convergence: ``converged`` is False with ``offset_change`` as diagnosis.

    Notes
    -----
    Newton on the fixed-point residual r(x) = T(x) − x of the offsets x:

    .. math:: (I - \partial T/\partial x)\,\Delta x = T(x) - x

    with the Jacobian of :func:`_fixed_point_jacobian` and a backtracking line search on ‖r‖₂
    (halving, at most :data:`NEWTON_BACKTRACKS` times). Reference: Kelley C.T. (2003) Solving
    Nonlinear Equations with Newton's Method, SIAM, ch. 1–2.
    """
    checks.one_of("method", method, METHODS)
    checks.in_range("relaxation", relaxation, 0.0, 1.0, closed=True)
    if relaxation == 0:
        raise checks.InputError("relaxation (0) must be positive (0 < ω ≤ 1)")
    checks.positive("atol", atol, "m")
    checks.non_negative("rtol", rtol)
    checks.integer("max_iterations", max_iterations, low=1)
    length = float(ring.section.centroid_radius)
    layout = _layout(ring, model)
    _, names, sizes = layout

    def engine(x, q):
        return solve(
            model,
            load,
            free=free,
            displacement=q if free is None else None,
            options=options,
            raceway_offsets=_unpack(ring, names, sizes, x, length),
        )

    res = solve(model, load, free=free, options=options)
    q = res.displacement
    n_cases = q.shape[0]
    # The element azimuths do not change: the thin-ring influence matrix is built once.
    cmat = ring.bending_matrix(ring.ring_loads(model, res).azimuth)

    def residual(res, x):
        tx = _pack(ring, names, ring.offsets_from(model, ring.ring_loads(model, res), cmat), length, n_cases)
        return tx - x

    x = np.zeros_like(residual(res, 0.0))  # start from the rigid ring
    done = np.zeros(n_cases, bool)
    iterations = np.zeros(n_cases, int)
    change = np.full(n_cases, np.inf)
    omega = np.full(n_cases, float(relaxation))
    r_prev = None
    history = []
    failed = ~res.converged
    r = residual(res, x)
    # max_iterations steps, each judged after it (the state returned is the state judged).
    for step_no in range(max_iterations + 1):
        r = np.where(failed[:, None], 0.0, r)  # a failed engine solve freezes its case
        change = np.where(done | failed, change, np.abs(r).max(axis=-1) if r.shape[-1] else 0.0)
        history.append(change.copy())
        size = np.abs(x).max(axis=-1) if x.shape[-1] else np.zeros(n_cases)
        done = done | ((change <= atol + rtol * size) & ~failed)
        active = ~(done | failed)
        if not active.any() or step_no == max_iterations:
            break
        iterations += active
        if method == "newton":
            # Single-threaded BLAS for these few hundred unknowns: measured 4x faster on the shared
            # 2-core machine than the default pool (the threads fight over the cores).
            with threadpool_limits(limits=1, user_api="blas"):
                dt_dx = _fixed_point_jacobian(model, ring, res, x, layout, length, free, cmat)
                step = np.linalg.solve(np.eye(x.shape[-1]) - dt_dx, r[..., None])[..., 0]
            step = np.where(active[:, None], step, 0.0)
            x, res, r = _line_search(engine, residual, x, res, r, step, active)
        else:
            if method == "aitken" and r_prev is not None:
                dr = r - r_prev
                den = np.einsum("ci,ci->c", dr, dr)
                num = np.einsum("ci,ci->c", r_prev, dr)
                new = np.where(den > 0, -omega * num / np.where(den > 0, den, 1.0), omega)
                omega = np.clip(new, AITKEN_MIN, 1.0)
            r_prev = r
            x = np.where(active[:, None], x + omega[:, None] * r, x)
            res = engine(x, q)
            r = residual(res, x)
        failed = failed | ~res.converged | ~np.isfinite(res.displacement).all(axis=-1)
        q = np.where(np.isfinite(res.displacement), res.displacement, 0.0)
    converged = done & res.converged & ~failed
    offsets = _unpack(ring, names, sizes, x, length)
    return FlexibleResult(res, ring, converged, iterations, change, history, offsets, method)


def _line_search(engine, residual, x, res, r, step, active):
    """Backtracking on ‖T(x) − x‖₂ per case; returns the accepted x, its engine result and residual.

    Every trial solves the whole batch with the cases already accepted held at their accepted
    offsets, so the last trial's result is the result of every case (no extra solve).
    """
    norm0 = np.linalg.norm(r, axis=-1)
    t = np.ones(x.shape[0])
    pending = active.copy()
    x_new = x.copy()
    for attempt in range(NEWTON_BACKTRACKS + 1):
        x_try = np.where(pending[:, None], x + t[:, None] * step, x_new)
        trial = engine(x_try, res.displacement)
        r_try = residual(trial, x_try)
        ok = trial.converged & (np.linalg.norm(r_try, axis=-1) <= (1.0 - 1e-4 * t) * norm0)
        # After the last halving the short step is taken anyway (the iteration must move).
        accept = pending & (ok | (attempt == NEWTON_BACKTRACKS))
        x_new = np.where(accept[:, None], x_try, x_new)
        pending &= ~accept
        if not pending.any():
            return x_new, trial, r_try
        t = np.where(pending, 0.5 * t, t)
    raise AssertionError("unreachable: the last attempt accepts every pending case")  # pragma: no cover
