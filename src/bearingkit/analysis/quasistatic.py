"""Quasi-static equilibrium of the inner ring: batched, damped Newton–Raphson on up to 5 DOF.

SI units. For a displacement q = (u_x, u_y, u_z, θ_x, θ_y) of the inner ring every row returns the
generalised contact force f(q), its Jacobian and its elastic energy U(q). Equilibrium with the
external load F is R(q) = F + Σ f(q) = 0 on the free DOFs; fixed DOFs keep prescribed values
(displacement control) and report the reaction.

Every contact law here (Hertz δ^1.5, line δ^(10/9), applied to affine or norm-convex approaches)
makes U convex, so R = 0 is the minimum of the potential Π(q) = U(q) − F·q. The solver takes
Newton steps on Π with a tiny Levenberg term (the Hessian is singular while no contact is closed),
caps the step length (so a bearing with clearance first closes its gaps in bounded steps), and
backtracks until Π decreases (Armijo). This is globally convergent for a convex Π; a load that no
combination of contacts can carry makes Π unbounded, which is detected and reported. Cases that
still fail are retried with load continuation (the load ramped in steps from the last iterate).

Rotations are scaled by the largest pitch radius L (θ·L in metres, M/L in newtons) so the Newton
system is well conditioned and the tolerance is one relative number: the residual must fall below
``rtol`` times the load scale (the largest of the external load and the row forces).
"""

from __future__ import annotations

import copy
import os
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

import numpy as np
from threadpoolctl import threadpool_limits

from bearingkit import checks
from bearingkit.analysis.model import BearingModel
from bearingkit.errors import ConvergenceError, InputError
from bearingkit.rows.base import DOF_NAMES, LOAD_NAMES, N_DOF, RowState


@dataclass(frozen=True)
class SolverOptions:
    """Tolerances and limits of the Newton solver.

    Parameters
    ----------
    rtol : float
        Converged when max |residual| ≤ rtol × load scale (scaled units, see module docstring).
    max_iterations : int
        Newton iterations per attempt.
    max_step : float or None [m]
        Largest change of any scaled DOF in one step; default 2 % of the smallest element diameter.
    continuation_steps : int
        Load fractions tried for cases that fail the plain attempt (0 disables continuation).
    divergence_limit : float
        A case whose scaled displacement exceeds this fraction of the smallest element diameter is
        declared diverged (the load cannot be carried).
    """

    rtol: float = 1e-10
    max_iterations: int = 60
    max_step: float | None = None
    continuation_steps: int = 4
    divergence_limit: float = 0.5

    def __post_init__(self):
        checks.positive("rtol", self.rtol)
        checks.integer("max_iterations", self.max_iterations, low=1)
        if self.max_step is not None:
            checks.positive("max_step", self.max_step, "m")
        checks.integer("continuation_steps", self.continuation_steps, low=0)
        checks.positive("divergence_limit", self.divergence_limit)


def load_vector(F_x=0.0, F_y=0.0, F_z=0.0, M_x=0.0, M_y=0.0) -> np.ndarray:
    """External load on the inner ring (..., 5) [N, N, N, N·m, N·m] from named components (broadcast)."""
    parts = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (F_x, F_y, F_z, M_x, M_y)))
    return np.stack(parts, axis=-1)


@dataclass
class QuasiStaticResult:
    """Solution of a batch of load cases (leading axis C).

    Attributes
    ----------
    model : BearingModel
    load : ndarray (C, 5) [N, N, N, N·m, N·m]
        External load on the inner ring (for fixed DOFs: the reaction needed to hold them).
    displacement : ndarray (C, 5) [m, m, m, rad, rad]
    converged : ndarray (C,) of bool
    iterations : ndarray (C,) of int
    residual_norm : ndarray (C,)
        Max |residual| over the free DOFs divided by the load scale (dimensionless).
    reason : list of str or None
        Why a case did not converge.
    rows : list of RowState
        Per-row, per-element results (computed on first access: studies that need only the
        displacement or the row forces skip the per-contact Hertz post-processing).
    stiffness : ndarray (C, 5, 5)
        Tangent stiffness −∂(contact force)/∂q [N/m, N, N·m/rad …] at the solution.
    free : ndarray (5,) of bool
    """

    model: BearingModel
    load: np.ndarray
    displacement: np.ndarray
    converged: np.ndarray
    iterations: np.ndarray
    residual_norm: np.ndarray
    reason: list
    stiffness: np.ndarray
    free: np.ndarray
    references: tuple = field(default_factory=tuple)
    offsets: list | None = field(default=None, repr=False)
    _rows: list | None = field(default=None, repr=False)
    _row_loads: dict = field(default_factory=dict, repr=False)

    @property
    def rows(self) -> list[RowState]:
        if self._rows is None:
            offs = self.offsets or [None] * len(self.model.kernels)
            self._rows = [
                k.state(self.displacement, o) for k, o in zip(self.model.kernels, offs, strict=True)
            ]
        return self._rows

    @property
    def n_cases(self) -> int:
        return self.displacement.shape[0]

    def row(self, name: str) -> RowState:
        """The row state called ``name``."""
        for r in self.rows:
            if r.name == name:
                return r
        raise InputError(f"row ({name!r}) not in result; rows are {[r.name for r in self.rows]}")

    def to_dict(self, case: int | None = None) -> dict | list[dict]:
        """JSON-ready dict (SI values, units in keys); a list over cases when ``case`` is None."""
        if case is None:
            return [self.to_dict(c) for c in range(self.n_cases)]
        out = {
            "bearing": self.model.name,
            "converged": bool(self.converged[case]),
            "iterations": int(self.iterations[case]),
            "residual_norm": float(self.residual_norm[case]),
            "reason": self.reason[case],
            "load": {
                f"{n}_{u}": float(v)
                for n, u, v in zip(LOAD_NAMES, ("N",) * 3 + ("Nm",) * 2, self.load[case], strict=True)
            },
            "displacement": {
                f"{n}_{u}": float(v)
                for n, u, v in zip(DOF_NAMES, ("m",) * 3 + ("rad",) * 2, self.displacement[case], strict=True)
            },
            "stiffness_SI": self.stiffness[case].tolist(),
            "rows": [],
        }
        for r in self.rows:
            row_force = self.row_load(r.name)[case]
            entry = {
                "name": r.name,
                "kind": r.kind,
                "azimuth_rad": np.broadcast_to(r.azimuth, r.load.shape)[case].tolist(),
                "loads_N": r.load[case].tolist(),
                "contact_angle_rad": r.contact_angle[case].tolist(),
                "max_load_N": float(r.max_load[case]),
                "max_pressure_Pa": float(r.max_pressure[case].max()),
                "loaded_count": int(r.loaded_count[case]),
                "axial_load_N": float(row_force[2]),
                "radial_load_N": float(np.hypot(*row_force[:2])),
            }
            out["rows"].append(entry)
        out["references"] = list(self.references)
        return out

    def row_load(self, name: str) -> np.ndarray:
        """Force and moment (C, 5) the row carries (= −contact force on the inner ring), SI."""
        if name not in self._row_loads:  # computed once per row: to_dict asks per case
            names = [r.name for r in self.model.rows]
            if name not in names:
                raise InputError(f"row ({name!r}) not in result; rows are {names}")
            i = names.index(name)
            offset = self.offsets[i] if self.offsets else None
            self._row_loads[name] = -self.model.kernels[i].response(self.displacement, offset).force
        return self._row_loads[name]

    def to_pandas(self):
        """One line per case, row and element: load, contact angle, max pressure (SI columns)."""
        import pandas as pd

        frames = []
        for r in self.rows:
            c, z = r.load.shape
            frames.append(
                pd.DataFrame(
                    {
                        "case": np.repeat(np.arange(c), z),
                        "row": r.name,
                        "kind": r.kind,
                        "element": np.tile(np.arange(z), c),
                        "azimuth_rad": np.broadcast_to(r.azimuth, r.load.shape).ravel(),
                        "load_N": r.load.ravel(),
                        "deflection_m": r.deflection.ravel(),
                        "contact_angle_rad": r.contact_angle.ravel(),
                        "max_pressure_Pa": r.max_pressure.ravel(),
                    }
                )
            )
        return pd.concat(frames, ignore_index=True)


def _evaluate(kernels, q, offsets=None):
    """Sum of row responses: contact force (C,5), Jacobian (C,5,5), energy (C,), largest row force."""
    force = np.zeros_like(q)
    jac = np.zeros((*q.shape, N_DOF))
    energy = np.zeros(q.shape[0])
    row_max = np.zeros_like(q)
    for i, k in enumerate(kernels):
        resp = k.response(q, offsets[i]) if offsets else k.response(q)
        force += resp.force
        jac += resp.jacobian
        energy += resp.energy
        row_max = np.maximum(row_max, np.abs(resp.force))
    return force, jac, energy, row_max


class _Problem:
    """The scaled equilibrium problem of a batch; holds kernels, loads and scaling."""

    def __init__(
        self, model: BearingModel, load: np.ndarray, free: np.ndarray, options: SolverOptions, offsets=None
    ):
        self.kernels = model.kernels
        self.offsets = offsets
        self.length = max(k.char_length for k in self.kernels)
        self.scale = np.array([1.0, 1.0, 1.0, 1.0 / self.length, 1.0 / self.length])  # q = scale·q̃
        self.free = free
        self.idx = np.flatnonzero(free)
        d_min = min(k.deflection_scale for k in self.kernels)
        self.max_step = options.max_step if options.max_step is not None else 0.02 * d_min
        self.limit = options.divergence_limit * d_min
        self.options = options
        self.load = load

    def state(self, q, load):
        force, jac, energy, row_max = _evaluate(self.kernels, q, self.offsets)
        residual = load + force
        potential = energy - np.einsum("ci,ci->c", load[:, self.idx], q[:, self.idx])
        s = self.scale
        r_scaled = residual * s
        load_scale = np.maximum(np.abs(load * s).max(axis=1), (row_max * s).max(axis=1))
        load_scale = np.maximum(load_scale, 1e-12)
        norm = np.abs(r_scaled[:, self.idx]).max(axis=1) / load_scale if len(self.idx) else np.zeros(len(q))
        return dict(force=force, jac=jac, potential=potential, residual=residual, norm=norm, q=q)

    def take(self, cases: np.ndarray) -> _Problem:
        """The same problem restricted to some cases (kernels and offsets sliced where per-case)."""
        out = copy.copy(self)
        out.kernels = [k.take(cases) for k in self.kernels]
        if self.offsets:
            out.offsets = [None if o is None else o.take(cases) for o in self.offsets]
        return out


#: Eigenvalues of a (scaled) stiffness matrix below this fraction of its largest one are mechanisms:
#: directions the contacts do not resist (e.g. a single whole-roller tapered or angular-contact row
#: tilting about its pressure centre) [-].
MECHANISM_RTOL = 1e-9


def _without_idle_mechanisms(h, g, step, tol):
    """``step`` (C, n) without its components along mechanisms of h that the gradient g does not load.

    h (C, n, n) symmetric positive semi-definite, g (C, n) the gradient, tol (C,) the size below
    which a component of g is round-off. Along a mechanism the regularised solve divides by a
    Levenberg term ~1e-12 of the stiffness, so round-off there would become a finite displacement
    (a symmetric row drifting in tilt). A mechanism the load does push (an unbalanced load, or
    contacts still open) keeps its component: the capped step then proceeds as before.
    """
    lam, vec = np.linalg.eigh(h)
    null = lam <= MECHANISM_RTOL * np.maximum(np.abs(lam).max(axis=1, keepdims=True), 1e-300)
    idle = null & (np.abs(np.einsum("cij,ci->cj", vec, g)) <= tol[:, None])
    if not idle.any():
        return step
    comp = np.einsum("cij,ci->cj", vec, step)
    return np.einsum("cij,cj->ci", vec, np.where(idle, 0.0, comp))


def _starting_point(problem: _Problem, load: np.ndarray, q: np.ndarray) -> np.ndarray:
    """A starting displacement of the right size: every contact closed with one common approach δ.

    With all contacts closed, the tangent stiffness is Σ_rows n c δ^(n−1) Σ g gᵀ; solve K(δ) q = F on
    the free DOFs and update δ to the largest contact approach q produces (a few fixed-point sweeps
    of a 5×5 system). Clearances and crowning are ignored: this only sizes the first Newton step.
    """
    idx = problem.idx
    if len(idx) == 0:
        return q
    s = problem.scale
    mats = [(k.start_matrix * s[:, None] * s[None, :], k.start_exponent) for k in problem.kernels]
    f = (load * s)[:, idx]
    delta = np.full(load.shape[0], 1e-4 * problem.max_step / 0.02)  # 1e-4 D: a typical approach
    qt = np.zeros_like(f)
    for _ in range(6):
        k = sum(n * delta[:, None, None] ** (n - 1) * m[idx][:, idx] for m, n in mats)
        k = k + 1e-12 * np.abs(k).max(axis=(1, 2))[:, None, None] * np.eye(len(idx))
        k = np.where(np.isfinite(k), k, 0.0) + 1e-300 * np.eye(len(idx))
        try:
            qt = np.linalg.solve(k, f[..., None])[..., 0]
        except np.linalg.LinAlgError:  # degenerate stiffness: start from the given point
            return q
        approach = np.abs(qt).max(axis=1)
        delta = np.sqrt(delta * np.maximum(approach, 1e-3 * delta))
    # A mechanism (zero stiffness, e.g. a single whole-roller tapered row tilting about its pressure
    # centre) that the load does not push on must not move: the 1e-12 regularisation above would
    # turn round-off in the solve into a finite displacement along it.
    qt = _without_idle_mechanisms(k, -f, qt, 1e-10 * np.abs(f).max(axis=1))
    # Never start farther than one capped Newton step: a near-singular estimate (a DOF the rows barely
    # reach, e.g. the tilt of a single tapered row) would otherwise throw the start far away.
    big = np.abs(qt).max(axis=1, keepdims=True)
    qt = np.where(np.isfinite(big), qt * np.minimum(1.0, problem.max_step / np.maximum(big, 1e-300)), qt)
    out = q.copy()
    out[:, idx] = q[:, idx] + qt * s[idx]
    # A singular or overflowing estimate must not poison the solve: keep the given start there.
    return np.where(np.isfinite(out).all(axis=1, keepdims=True), out, q)


def _newton(problem: _Problem, q, load, active, iterations):
    """Damped Newton on the active cases; returns q, converged, last state, diverged mask.

    Each iteration works on the cases still running only (kernels and loads restricted to them), so
    a batch costs what its unconverged cases cost.
    """
    opts = problem.options
    idx, s = problem.idx, problem.scale
    n = len(idx)
    q = q.copy()
    st = {k: v.copy() for k, v in problem.state(q, load).items()}
    converged = st["norm"] <= opts.rtol
    diverged = np.zeros_like(converged)
    for _ in range(opts.max_iterations):
        work = active & ~converged & ~diverged
        if not work.any():
            break
        cases = np.flatnonzero(work)
        iterations[cases] += 1
        sp = problem if len(cases) == len(q) else problem.take(cases)
        qw, lw = q[cases], load[cases]
        stw = {k: v[cases] for k, v in st.items()}
        # Scaled gradient g̃ = −S R and Hessian H̃ = −S J S on the free DOFs.
        g = -(stw["residual"] * s)[:, idx]
        h = -(stw["jac"] * s[:, None] * s[None, :])[:, idx][:, :, idx]
        diag = np.abs(np.diagonal(h, axis1=1, axis2=2)).max(axis=1)
        # Levenberg term: negligible once contacts are closed; while none is, it turns the step into
        # a (capped) move along the load.
        mu = 1e-12 * diag + np.abs(g).max(axis=1) / (1e6 * problem.max_step) + 1e-300
        step = np.linalg.solve(h + mu[:, None, None] * np.eye(n), -g[..., None])[..., 0]
        # norm = max|g| / load scale: components of g below rtol × load scale are round-off.
        noise = opts.rtol * np.abs(g).max(axis=1) / np.maximum(stw["norm"], 1e-300)
        step = _without_idle_mechanisms(h, g, step, noise)
        big = np.abs(step).max(axis=1)
        step *= np.minimum(1.0, problem.max_step / np.maximum(big, 1e-300))[:, None]
        slope = np.einsum("ci,ci->c", g, step)  # < 0 for a descent direction
        t = np.ones(len(cases))
        pending = np.ones(len(cases), bool)
        new_q, trial = qw, stw
        for _ls in range(40):
            cand = qw.copy()
            cand[:, idx] += (t[:, None] * step) * s[idx]
            trial_state = sp.state(cand, lw)
            slack = 1e-12 * (np.abs(stw["potential"]) + 1e-30)
            ok = (trial_state["potential"] <= stw["potential"] + 1e-4 * t * slope + slack) | (
                trial_state["norm"] < 0.5 * stw["norm"]
            )
            accept = pending & ok
            if accept.all():  # the usual Newton step: nothing to mix
                new_q, trial = cand, trial_state
                break
            new_q = np.where(accept[:, None], cand, new_q)
            trial = _merge(trial, trial_state, accept)
            pending &= ~ok
            if not pending.any():
                break
            t = np.where(pending, 0.5 * t, t)
        q[cases] = new_q
        for k in st:
            st[k][cases] = trial[k]
        converged[cases] |= trial["norm"] <= opts.rtol
        diverged[cases] |= np.abs(new_q / s).max(axis=1) > problem.limit
    return q, converged, st, diverged


#: Cases per chunk of a large batch: ~10 MB per slice array for a few thousand slices per case, so
#: the element-wise passes stay in cache; chunks run on a thread pool (numpy releases the GIL).
CHUNK_CASES = 512

#: Environment variable that caps the solver's thread pool. Set it to 1 where the caller already
#: runs one solver per core (Dask workers, process pools): nested pools would oversubscribe them.
THREADS_ENV = "BEARINGKIT_THREADS"


def solver_threads() -> int:
    """Threads the solver uses for a chunked batch: ``$BEARINGKIT_THREADS`` or the core count."""
    value = os.environ.get(THREADS_ENV, "").strip()
    if not value:
        return os.cpu_count() or 1
    try:
        n = int(value)
    except ValueError:
        raise InputError(f"{THREADS_ENV}={value!r}: expected a positive integer") from None
    if n < 1:
        raise InputError(f"{THREADS_ENV}={value!r}: expected a positive integer")
    return n


def _attempt(problem: _Problem, q, load, iterations):
    """One Newton attempt over every case: chunked and threaded for large batches."""
    n = len(q)
    everyone = np.ones(n, bool)
    if n <= CHUNK_CASES:
        return _newton(problem, q, load, everyone, iterations)
    threads = solver_threads()
    chunks = [np.arange(i, min(i + CHUNK_CASES, n)) for i in range(0, n, CHUNK_CASES)]

    def run(cases):
        its = np.zeros(len(cases), int)
        out = _newton(problem.take(cases), q[cases], load[cases], np.ones(len(cases), bool), its)
        return cases, its, out

    # Our threads already fill the cores: BLAS threads on top would oversubscribe them (measured:
    # 1.7x more cases/s on 2 cores with BLAS limited to one thread inside the pool).
    with threadpool_limits(limits=1, user_api="blas"):
        if threads == 1:
            parts = [run(c) for c in chunks]
        else:
            with ThreadPoolExecutor(max_workers=threads) as pool:
                parts = list(pool.map(run, chunks))
    q_out = np.empty_like(q)
    conv, div = np.zeros(n, bool), np.zeros(n, bool)
    state = None
    for cases, its, (qc, cc, sc, dc) in parts:
        q_out[cases], conv[cases], div[cases] = qc, cc, dc
        iterations[cases] += its
        if state is None:
            state = {k: np.empty((n, *v.shape[1:]), v.dtype) for k, v in sc.items()}
        for k, v in sc.items():
            state[k][cases] = v
    return q_out, conv, state, div


def _merge(old: dict, new: dict, mask: np.ndarray) -> dict:
    """Take ``new`` where ``mask`` (per case), ``old`` elsewhere."""
    if mask.all():
        return new
    if not mask.any():
        return old
    out = {}
    for key, a in old.items():
        m = mask.reshape((-1,) + (1,) * (a.ndim - 1))
        out[key] = np.where(m, new[key], a)
    return out


def solve(
    model: BearingModel,
    load,
    *,
    free=None,
    displacement=None,
    options: SolverOptions | None = None,
    raise_on_failure: bool = False,
    raceway_offsets: dict | None = None,
    speed=None,
) -> QuasiStaticResult:
    """Solve the quasi-static equilibrium of a batch of load cases.

    Parameters
    ----------
    model : BearingModel
    load : array_like (5,) or (C, 5) [N, N, N, N·m, N·m]
        External load (F_x, F_y, F_z, M_x, M_y) on the inner ring; use :func:`load_vector`.
    free : array_like of 5 bool, optional
        Which DOFs are solved for (default all). Fixed DOFs keep ``displacement``; e.g. seed 000's
        planar model (δ_a, δ_r, θ) is ``free=[True, False, True, False, True]``.
    displacement : array_like (5,) or (C, 5) [m, m, m, rad, rad], optional
        Prescribed values of fixed DOFs and the starting point of free ones (default 0).
    options : SolverOptions, optional
    raise_on_failure : bool
        Raise :class:`~bearingkit.errors.ConvergenceError` (carrying the result) if any case fails;
        studies leave this False and read ``result.converged``.
    raceway_offsets : dict of str to RacewayOffset, optional
        Imposed outer-raceway deflections per row name (flexible rings; see
        :mod:`bearingkit.analysis.flexible`). Rows not named are rigid.
    speed : float, array (C,) [rad/s] or OperatingSpeed, optional
        Inner-ring speed per case (or an :class:`~bearingkit.analysis.speed.OperatingSpeed`): the
        rows then include their elements' centrifugal force and gyroscopic moment
        (:mod:`bearingkit.analysis.speed`). None or all zero: the zero-speed model, unchanged.

    Returns
    -------
    QuasiStaticResult
    """
    options = options or SolverOptions()
    if speed is not None:  # speed hook: rows at speed (the model itself when nothing turns)
        from bearingkit.analysis.speed import model_at_speed

        model = model_at_speed(model, speed)
    load = np.atleast_2d(np.asarray(load, dtype=float))
    if load.shape[-1] != N_DOF:
        raise InputError(f"load (shape {load.shape}) must have 5 components (F_x, F_y, F_z, M_x, M_y)")
    checks.finite("load", load, "N")
    free = np.ones(N_DOF, bool) if free is None else np.asarray(free, dtype=bool)
    if free.shape != (N_DOF,):
        raise InputError(f"free (shape {free.shape}) must be 5 booleans for u_x, u_y, u_z, theta_x, theta_y")
    n_cases = load.shape[0]
    q0 = np.zeros((n_cases, N_DOF)) if displacement is None else np.asarray(displacement, dtype=float)
    q0 = np.array(np.broadcast_to(q0, (max(n_cases, q0.shape[0] if q0.ndim == 2 else 1), N_DOF)))
    load = np.array(np.broadcast_to(load, q0.shape))
    checks.finite("displacement", q0, "m")
    n_cases = q0.shape[0]
    offsets = _offsets_for(model, raceway_offsets)
    problem = _Problem(model, load, free, options, offsets)
    _check_directions(problem, load)

    iterations = np.zeros(n_cases, int)
    start = q0 if displacement is not None else _starting_point(problem, load, q0)
    q, converged, st, diverged = _attempt(problem, start, load, iterations)
    if options.continuation_steps and not converged.all():
        # Load continuation from the unloaded start for the failed cases.
        retry = ~converged
        qc = np.where(retry[:, None], q0, q)
        for frac in np.linspace(1.0 / options.continuation_steps, 1.0, options.continuation_steps):
            ramp = np.where(retry[:, None], load * frac, load)
            ramp[:, ~free] = load[:, ~free]
            qc, conv_c, st_c, div_c = _newton(problem, qc, ramp, retry, iterations)
        q = np.where(retry[:, None], qc, q)
        st = _merge(st, st_c, retry)
        converged = np.where(retry, conv_c, converged)
        diverged = np.where(retry, div_c, diverged)

    # A case whose iterate or residual went non-finite failed numerically: report it, never return NaN.
    broken = ~(np.isfinite(q).all(axis=1) & np.isfinite(st["norm"]))
    if broken.any():
        q = np.where(broken[:, None], q0, q)
        converged = converged & ~broken
    reasons = [None] * n_cases
    for c in np.flatnonzero(~converged):
        reasons[c] = (
            "numerical failure: the iterate became non-finite (load or offsets far beyond the contacts)"
            if broken[c]
            else _diagnose(problem, load[c], bool(diverged[c]), st["norm"][c])
        )
    reaction = load.copy()
    reaction[:, ~free] = -st["force"][:, ~free]
    result = QuasiStaticResult(
        model=model,
        load=reaction,
        displacement=q,
        converged=converged,
        iterations=iterations,
        residual_norm=st["norm"],
        reason=reasons,
        stiffness=-st["jac"],
        free=free,
        references=tuple(model.references),
        offsets=offsets,
    )
    if speed is not None:  # speed hook: a case beyond what the speed model holds is not converged
        from bearingkit.analysis.speed import flag_beyond_model

        flag_beyond_model(result)
        converged = result.converged
    if raise_on_failure and not converged.all():
        bad = int(np.flatnonzero(~converged)[0])
        raise ConvergenceError(f"case {bad} did not converge: {reasons[bad]}", result)
    return result


def _offsets_for(model: BearingModel, raceway_offsets: dict | None):
    """Raceway offsets as a list aligned with the model's rows (None when every ring is rigid)."""
    if not raceway_offsets:
        return None
    names = [r.name for r in model.rows]
    unknown = set(raceway_offsets) - set(names)
    if unknown:
        raise InputError(f"raceway_offsets names rows {sorted(unknown)} not in the bearing; rows are {names}")
    return [raceway_offsets.get(n) for n in names]


def _directions(problem: _Problem) -> np.ndarray:
    """Contact directions (M, 5) at the unloaded geometry: columns a contact can push on."""
    parts = []
    for k in problem.kernels:
        reach = getattr(k, "reach", None)
        parts.append(reach if reach is not None else (k.G[0] if hasattr(k, "G") else k.directions[0]))
    return np.concatenate(parts, axis=0)


def _check_directions(problem: _Problem, load: np.ndarray) -> None:
    """Refuse, before solving, a load on a free DOF that no contact acts on at all."""
    g = _directions(problem) * problem.scale
    reach = np.abs(g).max(axis=0)
    for i in problem.idx:
        if reach[i] <= 1e-12 * reach.max() and np.any(np.abs(load[:, i]) > 0):
            raise InputError(
                f"load {LOAD_NAMES[i]} ({np.abs(load[:, i]).max():.6g}) acts on a DOF no row of this bearing "
                f"can carry ({DOF_NAMES[i]}); fix that DOF or remove the load"
            )


def _diagnose(problem: _Problem, load: np.ndarray, diverged: bool, norm: float) -> str:
    """One-line reason for a failed case, using the cone of contact directions."""
    from scipy.optimize import nnls

    g = (_directions(problem) * problem.scale)[:, problem.idx]
    f = (load * problem.scale)[problem.idx]
    _, miss = nnls(g.T, f)
    size = max(np.linalg.norm(f), 1e-300)
    if miss > 1e-3 * size:
        comp = (f - g.T @ nnls(g.T, f)[0]) / size
        worst = LOAD_NAMES[problem.idx[int(np.argmax(np.abs(comp)))]]
        return (
            f"the load cannot be carried: no combination of contact forces balances it (unbalanced mainly in "
            f"{worst})"
        )
    if diverged:
        return (
            "displacement diverged beyond half an element diameter: the load exceeds what the contacts carry"
        )
    return f"Newton did not reach the tolerance (residual {norm:.3g} of the load scale)"
