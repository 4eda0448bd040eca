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
import dataclasses
import math
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from bearingkit import checks
from bearingkit.analysis.solver import backend, cone
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.newton import Effort, Problem, merge, newton, starting_point
from bearingkit.analysis.solver.options import (
    CASE_SECONDS_ENV,
    DEFAULT_OPTIONS,
    EVALUATIONS_PER_ITERATION,
    SolverOptions,
)
from bearingkit.analysis.solver.solution import QuasiStaticResult
from bearingkit.analysis.solver.threads import (  # noqa: F401 (re-exported: their old home)
    PARALLEL_CHUNK,
    THREADS_ENV,
    parallel_split,
    solver_threads,
    thread_limit,
)
from bearingkit.errors import ConvergenceError, InputError
from bearingkit.rows.base import N_DOF


def load_vector(F_x=0.0, F_y=0.0, F_z=0.0, M_x=0.0, M_y=0.0) -> np.ndarray:
    """External load on the inner ring (..., 5) [N, N, N, N·m, N·m] from named components (broadcast)."""
    parts = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (F_x, F_y, F_z, M_x, M_y)))
    return np.stack(parts, axis=-1)


#: Cases per chunk of a large batch (numpy reference): ~5 MB per slice array for a few thousand
#: slices per case, so the element-wise passes stay in cache; chunks run on a thread pool (numpy
#: releases the GIL). 256, not 512: issue 19 measured chunks of 512 at 1.8x the cost per case of 256
#: (their temporaries are trimmed by glibc and faulted back in every call).
CHUNK_CASES = 256
#: Batches above this many cases run with BLAS limited to one thread (numpy reference): the solver's
#: matrix products are small, and OpenBLAS threads on them cost more than they give (issue 19:
#: 6.7x slower per case at 256 cases with its threads).
BLAS_SERIAL_ABOVE = 8

_CONTROLLER: list = []


def _blas_serial():
    """Context limiting BLAS to one thread (a cached controller: ~0.1 ms, threadpool_limits ~2 ms)."""
    if not _CONTROLLER:
        from threadpoolctl import ThreadpoolController

        _CONTROLLER.append(ThreadpoolController())
    return _CONTROLLER[0].limit(limits=1, user_api="blas")


def _attempt(problem: Problem, q, load, iterations, effort: Effort | None = None):
    """One Newton attempt over every case: chunked and threaded for large batches."""
    n = len(q)
    everyone = np.ones(n, bool)
    if n <= BLAS_SERIAL_ABOVE:
        return newton(problem, q, load, everyone, iterations, effort)
    if n <= CHUNK_CASES:
        with _blas_serial():
            return newton(problem, q, load, everyone, iterations, effort)
    threads = solver_threads()
    chunks = [np.arange(i, min(i + CHUNK_CASES, n)) for i in range(0, n, CHUNK_CASES)]

    def run(cases):
        its = np.zeros(len(cases), int)
        part = None if effort is None else effort.take(cases)
        out = newton(problem.take(cases), q[cases], load[cases], np.ones(len(cases), bool), its, part)
        if part is not None:
            effort.put(cases, part)
        return cases, its, out

    # Our threads already fill the cores: BLAS threads on top would oversubscribe them (measured:
    # 1.7x more cases/s on 2 cores with BLAS limited to one thread inside the pool).
    with _blas_serial():
        if threads == 1:
            parts = [run(c) for c in chunks]
        else:
            with ThreadPoolExecutor(max_workers=threads) as pool:
                parts = list(pool.map(run, chunks))
    q_out = np.empty_like(q)
    conv, div, ref = np.zeros(n, bool), np.zeros(n, bool), np.zeros(n, bool)
    state = None
    for cases, its, (qc, cc, sc, dc, rc) in parts:
        q_out[cases], conv[cases], div[cases], ref[cases] = qc, cc, dc, rc
        iterations[cases] += its
        if state is None:
            state = {k: np.empty((n, *v.shape[1:]), v.dtype) for k, v in sc.items()}
        for k, v in sc.items():
            state[k][cases] = v
    return q_out, conv, state, div, ref


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
        Inner-ring speed per case (or an :class:`~bearingkit.analysis.solver.speed.OperatingSpeed`): the
        rows then include their elements' centrifugal force and gyroscopic moment
        (:mod:`bearingkit.analysis.solver.speed`). None or all zero: the zero-speed model, unchanged.

    Returns
    -------
    QuasiStaticResult
    """
    options = options or DEFAULT_OPTIONS
    base_model = model
    if speed is not None:  # speed hook: rows at speed (the model itself when nothing turns)
        from bearingkit.analysis.solver.speed import model_at_speed

        model = model_at_speed(model, speed)
    load = np.array(load, dtype=float, ndmin=2)  # a copy: the caller's array is never written to
    if load.shape[-1] != N_DOF:
        raise InputError(f"load (shape {load.shape}) must have 5 components (F_x, F_y, F_z, M_x, M_y)")
    if not _all_finite(load):
        checks.finite("load", load, "N")  # raises, naming the values
    free_key = _ALL_FREE if free is None else _free_key(free)
    n_cases = load.shape[0]
    if speed is not None:
        from bearingkit.analysis.solver.speed import check_case_count

        check_case_count(model, n_cases)
    if displacement is None:
        # The compiled core only reads q0: one zero start per plan serves every single solve.
        q0 = _ZERO_START if n_cases == 1 else np.zeros((n_cases, N_DOF))
    else:
        q0 = np.asarray(displacement, dtype=float)
        q0 = np.array(np.broadcast_to(q0, (max(n_cases, q0.shape[0] if q0.ndim == 2 else 1), N_DOF)))
        load = np.array(np.broadcast_to(load, q0.shape))
        if not np.isfinite(q0).all():
            checks.finite("displacement", q0, "m")
    offsets = _offsets_for(model, raceway_offsets) if raceway_offsets else None
    plan = _plan(model, free_key, options, offsets)
    free = plan.free  # read-only, shared by the results of this plan
    if plan.idle_free.size:
        _check_directions(plan, load)

    if plan.compiled_for(n_cases):
        out = _solve_compiled(plan, q0, load, options, displacement is not None)
        q, norm, force, stiffness, bad = out.q, out.norm, out.force, out.stiffness, out.bad
        converged, iterations = out.flags[0], out.counts[0]
        evaluations, coarse_evaluations = out.counts[1], out.counts[2]
        roller_x = out.roller_x if plan.tapered else None
        diverged, broken = (out.flags[1], out.flags[3]) if bad else (None, None)
        effort = _compiled_effort(out, options) if bad else None
    else:
        started = time.perf_counter()
        coarse_evaluations = roller_x = None
        iterations = np.zeros(q0.shape[0], int)
        q0 = q0.copy() if q0 is _ZERO_START else q0  # the shared start stays untouched
        problem = plan.problem(load)
        coarse = backend.coarse_of(model) if offsets is None else None
        q, converged, st, diverged, effort = _solve_numpy(
            problem, q0, load, free, options, displacement, iterations, coarse
        )
        evaluations = effort.evaluations
        norm, force, stiffness = st["norm"], st["force"], -st["jac"]
        # A case whose iterate or residual went non-finite failed numerically: report it, never NaN.
        broken = ~(np.isfinite(q).all(axis=1) & np.isfinite(norm))
        if broken.any():
            q = np.where(broken[:, None], q0, q)
            converged = converged & ~broken
        bad = q.shape[0] - int(np.count_nonzero(converged))
        if plan.mode == "auto":
            backend.spent_numpy(time.perf_counter() - started)
    reasons = [None] * q0.shape[0]
    if bad:
        problem = plan.problem(load)
        for c in np.flatnonzero(~converged):
            reasons[c] = (
                "numerical failure: the iterate became non-finite (load or offsets far beyond the contacts)"
                if broken[c]
                else cone.diagnose(
                    problem.kernels, problem.scale, problem.idx, load[c], bool(diverged[c]), norm[c]
                )
            )
            if effort is not None and effort.stopped[c] and not broken[c]:
                reasons[c] = _out_of_budget(effort, c, options, reasons[c])
    reaction = load
    if not plan.all_free:  # one masked ufunc: fancy indexing cost a single solve ~3 µs
        np.negative(force, out=reaction, where=plan.fixed)
    result = QuasiStaticResult(
        model=model,
        load=reaction,
        displacement=q,
        converged=converged,
        iterations=iterations,
        residual_norm=norm,
        reason=reasons,
        stiffness=stiffness,
        free=free,
        references=plan.references,
        offsets=offsets,
        evaluations=evaluations,
        coarse_evaluations=coarse_evaluations,
        _roller_x=roller_x,
    )
    if speed is not None:  # speed hook: a case beyond what the speed model holds is not converged
        from bearingkit.analysis.solver.speed import explain_at_rest, flag_beyond_model

        if bad and raceway_offsets is None:  # failed at speed: does it converge at rest?
            explain_at_rest(base_model, result, load, free, options, displacement, solve)
        flag_beyond_model(result)
        converged = result.converged
    if raise_on_failure and (bad or speed is not None) and not converged.all():
        bad_case = int(np.flatnonzero(~converged)[0])
        raise ConvergenceError(f"case {bad_case} did not converge: {reasons[bad_case]}", result)
    return result


def _solve_numpy(
    problem: Problem, q0, load, free, options: SolverOptions, displacement, iterations, coarse=None
):
    """The numpy reference: start, coarse stage, chunked attempt, load continuation of the failed cases.

    ``coarse``: the coarse model's kernels (:mod:`bearingkit.analysis.solver.coarse`) or None.
    """
    start = q0 if displacement is not None else starting_point(problem, load, q0)
    if coarse is not None and displacement is None and options.coarse_iterations > 0:
        start = _coarse_start(problem, coarse, start, load)
    from bearingkit.budget import max_work

    effort = Effort(len(q0), options.max_evaluations, options.seconds_per_case(), max_work())
    q, converged, st, diverged, refused = _attempt(problem, start, load, iterations, effort)
    if options.continuation_steps and not (converged | refused).all():
        # Load continuation from the unloaded start for the failed cases (a load outside the contact
        # cone stays refused: no ramp makes it carriable; a case out of budget is not retried).
        retry = ~converged & ~refused & (effort.stopped == 0)
        qc = np.where(retry[:, None], q0, q)
        st_c = st
        for frac in np.linspace(1.0 / options.continuation_steps, 1.0, options.continuation_steps):
            ramp = np.where(retry[:, None], load * frac, load)
            ramp[:, ~free] = load[:, ~free]
            qc, conv_c, st_c, div_c, _ = newton(problem, qc, ramp, retry, iterations, effort)
        if retry.any():
            q = np.where(retry[:, None], qc, q)
            st = merge(st, st_c, retry)
            converged = np.where(retry, conv_c, converged)
            diverged = np.where(retry, div_c, diverged)
    return q, converged, st, diverged, effort


def _compiled_effort(out, options: SolverOptions) -> Effort:
    """The compiled core's spending in the numpy reference's terms (evaluations, stopped by them)."""
    effort = Effort(out.q.shape[0], options.max_evaluations, np.inf)
    effort.evaluations = out.counts[1]
    effort.stopped = out.flags[4].astype(np.int8)
    return effort


def _out_of_budget(effort: Effort, c: int, options: SolverOptions, why: str) -> str:
    """The reason of a case stopped by its budget: what it spent, what it had reached, the remedy."""
    if effort.stopped[c] == 1:
        default = options.max_evaluations == EVALUATIONS_PER_ITERATION * options.max_iterations
        spent = f"stopped after {int(effort.evaluations[c])} row evaluations, the budget of one case " + (
            f"([solver] max_iterations {options.max_iterations} x {EVALUATIONS_PER_ITERATION})"
            if default  # the message named 60 x 50 for any SolverOptions.max_evaluations before
            else f"(SolverOptions.max_evaluations = {options.max_evaluations})"
        )
    elif effort.stopped[c] == 2:
        spent = (
            f"stopped after {effort.seconds[c]:.3g} s, the time budget of one case ({CASE_SECONDS_ENV}="
            f"{options.seconds_per_case():g})"
        )
    else:
        from bearingkit.budget import MAX_WORK_ENV

        spent = (
            f"stopped when the solve of all cases together had taken {effort.total[0]:.3g} s, the work "
            f"limit ({MAX_WORK_ENV}={effort.batch_seconds:g})"
        )
    return f"{spent}; {why}"


def _coarse_start(problem: Problem, coarse: list, start, load):
    """``coarse_iterations`` Newton iterations on the coarse model from ``start``, the last step taken
    without evaluating its end; a case that diverges or goes non-finite there keeps ``start`` (as the
    compiled core)."""
    rough = copy.copy(problem)
    rough.kernels = coarse
    rough.options = dataclasses.replace(problem.options, max_iterations=problem.options.coarse_iterations)
    rough.blind_last = True
    rough.outside_cone = None  # the cone check belongs to the full model's iterations (as compiled)
    q, _, st, diverged, _ = _attempt(rough, start, load, np.zeros(len(start), int))
    ok = np.isfinite(q).all(axis=1) & np.isfinite(st["norm"]) & ~diverged
    return np.where(ok[:, None], q, start)


def _compiled_pack(model: BearingModel, options: SolverOptions, offsets):
    """The model's compiled form when the compiled core is to run, else None (numpy reference)."""
    mode = backend.requested(options.backend)
    if mode == "numpy":
        return None
    module = backend.compiled_module()
    if module is None:  # numba unusable: warned once, numpy reference
        return None
    pack = backend.compiled_pack(model) if offsets is None else None
    if pack is None and mode == "compiled":
        kinds = sorted({r.kind for r in model.rows} - set(module.SUPPORTED_KINDS))
        why = f"row kinds {kinds} have no compiled kernel" if kinds else "raceway offsets are imposed"
        raise InputError(f"SolverOptions.backend ('compiled') cannot solve this bearing: {why}; use 'auto'")
    return pack


def _solve_compiled(plan, q0, load, options, given):
    """The compiled core over every case (one thread per core): its
    :data:`~bearingkit.analysis.solver.compiled_newton.PackedSolution`."""
    n = load.shape[0]
    if plan.lead:
        _check_case_axis(plan.lead, n)
    solve_packed = plan.solve_packed
    args = (plan.pack, q0, load, plan.free, plan.scale, plan.max_step, plan.limit, options)
    args += (plan.cone_matrix, given)
    threads, block = parallel_split(n, solver_threads()) if n > 1 else (1, n)
    if threads > 1:
        import numba

        # No BLAS limit here: the compiled core calls LAPACK on 5×5 systems only, which OpenBLAS
        # runs on the calling thread (and a limit costs ~0.1–2 ms per call).
        numba.set_num_threads(min(threads, numba.config.NUMBA_NUM_THREADS))
        # Cases handed out in small chunks as threads free up, not in one equal share per thread: on
        # a shared machine one thread is often descheduled, and cases differ in cost (continuation).
        previous = numba.set_parallel_chunksize(1)
        try:
            out = solve_packed(*args, parallel=True, cache=plan.compiled, block=block)
        finally:
            numba.set_parallel_chunksize(previous)
    else:  # one thread, or a batch too small to pay the threads' wake-up (threads.parallel_split)
        out = solve_packed(*args, False, plan.compiled)
    if plan.tapered:
        _record_inner(plan.kernels, out.inner)
    return out


#: The zero start of a single case (never written: the numpy path copies its start, the compiled
#: core reads it).
_ZERO_START = np.zeros((1, N_DOF))

#: Batches up to this many load values are checked for finiteness in Python (a numpy reduction costs
#: more than the whole check on a single case's five values).
_PY_CHECK_VALUES = 64


def _all_finite(a: np.ndarray) -> bool:
    """Whether every value of ``a`` is finite (cheap for a few values).

    For a few values, their sum is tested: it is finite when they all are, and a finite sum is
    never the sum of a non-finite value. An overflowing sum of finite values (beyond 1e308) tests the
    values one by one.
    """
    if a.size <= _PY_CHECK_VALUES:
        values = a.ravel().tolist()
        return math.isfinite(sum(values)) or all(map(math.isfinite, values))
    return bool(np.isfinite(a).all())


def _check_case_axis(lead: set, n_cases: int) -> None:
    """Per-case geometry (``lead``: the pack's case-axis lengths other than 1) must have one entry per
    load case (the compiled core does not broadcast)."""
    if lead and lead != {n_cases}:
        raise InputError(
            f"the bearing's per-case geometry has {sorted(lead)} cases but the load has {n_cases}; "
            "give one load case per geometry case"
        )


def _model_cache(model: BearingModel, key, compute):
    """A per-model constant of the solver (the model and its kernels are immutable geometry)."""
    cache = model.__dict__.setdefault("_solver_cache", {})
    if key not in cache:
        cache[key] = compute()
    return cache[key]


def _check_directions(plan, load: np.ndarray) -> None:
    """:func:`cone.check_directions` with the DOFs the rows reach computed once per model."""
    if plan.idle_free.size and np.any(load[:, plan.idle_free] != 0.0):
        problem = plan.problem(load)
        cone.check_directions(problem.kernels, problem.scale, problem.idx, load)  # raises, naming the DOF


#: The free-DOF key of a solve that frees all five.
_ALL_FREE = (True,) * N_DOF


def _free_key(free) -> tuple:
    """``free`` (None or 5 booleans) as a tuple of 5 bools (the key of the per-model solver plan)."""
    if free is None:
        return (True,) * N_DOF
    if isinstance(free, np.ndarray) and free.dtype == np.bool_ and free.shape == (N_DOF,):
        return tuple(free.tolist())  # the common case (a loaded bearing's ``free``): ~0.1 µs, not ~1.3
    arr = np.asarray(free, dtype=bool)
    if arr.shape != (N_DOF,):
        raise InputError(f"free (shape {arr.shape}) must be 5 booleans for u_x, u_y, u_z, theta_x, theta_y")
    return tuple(bool(v) for v in arr)


class _Plan:
    """The constants of one (model, free DOFs, options) solve, computed once and kept on the model.

    A single solve should cost what its Newton iterations cost: the scaling, step limits, the contact
    cone of the free DOFs, the DOFs no row reaches and the compiled core's argument arrays do not
    change from one call to the next (the model and its kernels are immutable geometry).
    """

    def __init__(self, model: BearingModel, free_key: tuple, options: SolverOptions, offsets):
        free = np.array(free_key, bool)
        free.flags.writeable = False  # shared by every result of this plan
        ref = Problem(model.kernels, np.zeros((1, N_DOF)), free, options, offsets)
        self.kernels = ref.kernels
        self.free, self.options, self.offsets = free, options, offsets
        self.all_free = bool(free.all())
        self.fixed = ~free  # the DOFs whose reaction a solve reports (read-only)
        self.fixed.flags.writeable = False
        self.scale, self.idx = ref.scale, ref.idx
        self.max_step, self.limit = ref.max_step, ref.limit
        reach = _model_cache(
            model, "reach", lambda: np.abs(cone.directions(ref.kernels) * ref.scale).max(axis=0)
        )
        idle = reach <= 1e-12 * reach.max()
        self.idle_free = np.flatnonzero(idle & free)
        self.references = tuple(model.references)
        self.tapered = any(hasattr(k, "inner_stats") for k in self.kernels)
        self._cone = None
        self.compiled = {}  # compiled core's constant arguments (compiled_newton.solve_packed)
        # The backend asked for is resolved once per plan (so $BEARINGKIT_BACKEND is read when a
        # bearing is first solved with these options); the compiled form is built on first use.
        self.mode = backend.requested(options.backend)
        self._model = model
        if self.mode == "compiled":
            self.compiled_for(1)  # a bearing the compiled core cannot take is an error now

    def compiled_for(self, n_cases: int) -> bool:
        """Whether a solve of ``n_cases`` runs on the compiled core (``auto``: when it pays for itself,
        :func:`bearingkit.analysis.solver.backend.wants_compiled`)."""
        if self.mode == "numpy" or (self.mode == "auto" and not backend.wants_compiled(n_cases)):
            return False
        if "pack" not in self.__dict__:
            # The compiled form, or None for the numpy reference (kinds without a compiled kernel).
            self.pack = pack = _compiled_pack(self._model, self.options, self.offsets)
            if pack is not None:
                self.solve_packed = backend.compiled_module().solve_packed
                # Case-axis lengths of per-case geometry (empty when every row's geometry is shared).
                self.lead = {pack.balls.B.shape[0], pack.rollers.Ga.shape[0], pack.tapered.d0i.shape[0]} - {1}
        return self.pack is not None

    @property
    def cone_matrix(self):
        if self._cone is None:
            self._cone = (_cone_matrix(self.problem(np.zeros((1, N_DOF)))),)
        return self._cone[0]

    def problem(self, load: np.ndarray) -> Problem:
        """The numpy reference's problem for these loads (cheap: the kernels are shared)."""
        return Problem(self.kernels, load, self.free, self.options, self.offsets)


def _plan(model: BearingModel, free_key: tuple, options: SolverOptions, offsets) -> _Plan:
    """The model's cached :class:`_Plan` (a new one when raceway offsets are imposed: they vary)."""
    if offsets is not None:
        return _Plan(model, free_key, options, offsets)
    # The last plan by identity first: hashing the options costs more than a small solve's Python.
    last = model.__dict__.get("_last_plan")
    if last is not None and last[0] is options and last[1] == free_key:
        return last[2]
    plan = _model_cache(model, ("plan", free_key, options), lambda: _Plan(model, free_key, options, None))
    model.__dict__["_last_plan"] = (options, free_key, plan)
    return plan


def _cone_matrix(problem: Problem):
    """Scaled contact directions on the free DOFs (n, M) for the cone check, or None (per-case geometry)."""
    g = cone.shared_directions(problem.kernels)
    if g is None or len(problem.idx) == 0:
        return None
    return np.ascontiguousarray(((g * problem.scale)[:, problem.idx]).T)


def _record_inner(kernels, inner: np.ndarray) -> None:
    """Roller sub-problem effort of a compiled solve into each tapered kernel's statistics."""
    stats = getattr(next((k for k in kernels if hasattr(k, "inner_stats")), None), "inner_stats", None)
    if stats is None or inner.size == 0:
        return
    for k in kernels:
        if hasattr(k, "inner_stats"):
            with k.inner_stats._lock:
                k.inner_stats.calls += int(inner[:, 0].sum())
                k.inner_stats.iterations_max = max(k.inner_stats.iterations_max, int(inner[:, 1].max()))
                k.inner_stats.unconverged += int(inner[:, 2].sum())


def _newton(problem, q, load, active, iterations):
    """The Newton attempt with its four outputs of before the solver split (for
    :mod:`bearingkit.systems.shaft.solver`, which drives it on its own condensed problem)."""
    q, converged, st, diverged, _ = newton(problem, q, load, active, iterations)
    return q, converged, st, diverged


#: Per-case merge of two solver states (for :mod:`bearingkit.systems.shaft.solver`).
_merge = merge


def _offsets_for(model: BearingModel, raceway_offsets: dict | None):
    """Raceway offsets as a list aligned with the model's rows (None when every ring is rigid)."""
    if not raceway_offsets:
        return None
    names = [r.name for r in model.rows]
    unknown = set(raceway_offsets) - set(names)
    if unknown:
        raise InputError(f"raceway_offsets names rows {sorted(unknown)} not in the bearing; rows are {names}")
    return [raceway_offsets.get(n) for n in names]


__all__ = [
    "CHUNK_CASES",
    "THREADS_ENV",
    "QuasiStaticResult",
    "SolverOptions",
    "load_vector",
    "solve",
    "solver_threads",
]
