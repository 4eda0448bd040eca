"""Damped Newton–Raphson on the potential of a batch of load cases (the numpy reference solver).

SI units; scaled DOFs as in :mod:`bearingkit.analysis.solver.quasistatic` (rotations × L, moments / L). For
every case the potential Π(q) = U(q) − F·q (U the contact energy, convex for every contact law of
bearingkit) is minimised by Newton steps with a vanishing Levenberg term, a step cap, removal of idle
mechanisms and Armijo backtracking; the cases of a batch advance together as arrays, but each
backtracking halving re-evaluates only the cases still backtracking. A case still running after
:data:`CONE_CHECK_ITERATION` iterations whose load lies outside the contact cone is refused there
(:mod:`bearingkit.analysis.solver.cone`). :mod:`bearingkit.analysis.solver.quasistatic` drives this (start,
chunks, continuation, results).
"""

from __future__ import annotations

import copy
import time

import numpy as np

from bearingkit.analysis.solver.cone import outside_cone
from bearingkit.rows.base import N_DOF

#: Iteration of a Newton attempt at which the cases still running are checked against the contact
#: cone (:func:`bearingkit.analysis.solver.cone.outside_cone`); carriable cases converge in 3–13 iterations
#: (seed-000 composite, tapered rows and pairs under random loads), so a case still running here is
#: either hard (it goes on) or cannot be carried at all (it stops).
CONE_CHECK_ITERATION = 8
#: Halvings of one Armijo backtracking line search.
MAX_HALVINGS = 40


class Effort:
    """What each case of a solve has spent, against its budget (the numpy reference's cases).

    A case may use at most ``max_evaluations`` row evaluations (every Newton attempt, line-search
    trial and continuation step together) and ``max_seconds`` of processor time, counted as its
    share of each batched evaluation (an evaluation of k cases that takes t seconds of the thread's
    time charges t/k to each; the time of the evaluating thread, so a loaded machine does not stop
    cases early). A case past either is stopped where it stands (not converged, :attr:`stopped`
    says which budget): the rest of its batch goes on at its usual speed. The evaluation count is
    deterministic; the time is the backstop for evaluations far more costly than usual.
    """

    def __init__(self, n: int, max_evaluations: int, max_seconds: float, batch_seconds: float = np.inf):
        self.evaluations = np.zeros(n, np.int64)
        self.seconds = np.zeros(n)
        self.stopped = np.zeros(n, np.int8)  # 0 running, 1 evaluations, 2 its time, 3 the batch's time
        self.max_evaluations = int(max_evaluations)
        self.max_seconds = float(max_seconds)
        # The whole batch's time (shared by the parts of a chunked batch): a thousand cases that each
        # stay within their own budget must not add up to hours.
        self.batch_seconds = float(batch_seconds)
        self.total = [0.0]

    def charge(self, cases: np.ndarray, seconds: float) -> None:
        """One evaluation of ``cases`` (indices) that took ``seconds`` in all."""
        if len(cases):
            self.evaluations[cases] += 1
            self.seconds[cases] += seconds / len(cases)
            self.total[0] += seconds

    def exhausted(self, cases: np.ndarray) -> np.ndarray:
        """Which of ``cases`` have spent their budget (marked in :attr:`stopped`)."""
        over_n = self.evaluations[cases] >= self.max_evaluations
        over_t = self.seconds[cases] >= self.max_seconds
        over = over_n | over_t | (self.total[0] >= self.batch_seconds)
        hit = cases[over & (self.stopped[cases] == 0)]
        self.stopped[hit] = np.where(
            self.evaluations[hit] >= self.max_evaluations,
            1,
            np.where(self.seconds[hit] >= self.max_seconds, 2, 3),
        )
        return over

    def take(self, cases: np.ndarray) -> Effort:
        out = Effort(len(cases), self.max_evaluations, self.max_seconds, self.batch_seconds)
        out.evaluations, out.seconds, out.stopped = (
            self.evaluations[cases],
            self.seconds[cases],
            self.stopped[cases],
        )
        out.total = self.total  # one running total for the whole batch
        return out

    def put(self, cases: np.ndarray, part: Effort) -> None:
        self.evaluations[cases], self.seconds[cases], self.stopped[cases] = (
            part.evaluations,
            part.seconds,
            part.stopped,
        )


def evaluate(kernels, q, offsets=None):
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


class Problem:
    """The scaled equilibrium problem of a batch; holds kernels, loads and scaling."""

    def __init__(self, kernels, load: np.ndarray, free: np.ndarray, options, offsets=None):
        self.kernels = list(kernels)
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
        force, jac, energy, row_max = evaluate(self.kernels, q, self.offsets)
        residual = load + force
        potential = energy - np.einsum("ci,ci->c", load[:, self.idx], q[:, self.idx])
        s = self.scale
        r_scaled = residual * s
        load_scale = np.maximum(np.abs(load * s).max(axis=1), (row_max * s).max(axis=1))
        load_scale = np.maximum(load_scale, 1e-12)
        norm = np.abs(r_scaled[:, self.idx]).max(axis=1) / load_scale if len(self.idx) else np.zeros(len(q))
        return dict(force=force, jac=jac, potential=potential, residual=residual, norm=norm, q=q)

    def outside_cone(self, load: np.ndarray) -> np.ndarray:
        """Which loads (C, 5) lie outside the bearing's contact cone (:func:`cone.outside_cone`)."""
        return outside_cone(self.kernels, self.scale, self.idx, load)

    def take(self, cases: np.ndarray) -> Problem:
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


def without_idle_mechanisms(h, g, step, tol):
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


def starting_point(problem: Problem, load: np.ndarray, q: np.ndarray) -> np.ndarray:
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
    qt = without_idle_mechanisms(k, -f, qt, 1e-10 * np.abs(f).max(axis=1))
    # Never start farther than one capped Newton step: a near-singular estimate (a DOF the rows barely
    # reach, e.g. the tilt of a single tapered row) would otherwise throw the start far away.
    big = np.abs(qt).max(axis=1, keepdims=True)
    qt = np.where(np.isfinite(big), qt * np.minimum(1.0, problem.max_step / np.maximum(big, 1e-300)), qt)
    out = q.copy()
    out[:, idx] = q[:, idx] + qt * s[idx]
    # A singular or overflowing estimate must not poison the solve: keep the given start there.
    return np.where(np.isfinite(out).all(axis=1, keepdims=True), out, q)


def newton(problem: Problem, q, load, active, iterations, effort: Effort | None = None):
    """Damped Newton on the active cases; returns q, converged, last state, diverged and refused masks.

    ``refused`` marks the cases stopped because their load lies outside the contact cone (they are
    also ``diverged``). A problem with ``blind_last`` set (the coarse stage,
    :mod:`bearingkit.analysis.solver.coarse`) takes its last iteration's step without evaluating its end.

    Each iteration works on the cases still running only (kernels and loads restricted to them), so
    a batch costs what its unconverged cases cost. A case whose line search finds no decrease stops
    here: its next step, a function of its own iterate alone, would be the same one (it used to
    repeat :data:`MAX_HALVINGS` evaluations per iteration to the iteration cap). ``effort``
    (:class:`Effort`, aligned with ``q``) charges every evaluation to its cases and stops a case that
    has spent its budget.
    """
    opts = problem.options
    idx, s = problem.idx, problem.scale
    # DOFs the step cap and the divergence test watch (None: all). A drivetrain leaves out each shaft's
    # rotation about its axis: the wind-up of the gear train, which the gear ratios amplify (a 0.1 mm
    # deflection at a 100:1 output turns the input shaft by ~0.2 rad) and no bearing limits.
    bounded = getattr(problem, "bounded", None)
    n = len(idx)
    q = q.copy()
    started = time.thread_time()
    st = {k: v.copy() for k, v in problem.state(q, load).items()}
    if effort is not None:
        effort.charge(np.flatnonzero(active), time.thread_time() - started)
    converged = st["norm"] <= opts.rtol
    diverged = np.zeros_like(converged)
    refused = np.zeros_like(converged)
    stalled = np.zeros_like(converged)
    for it in range(opts.max_iterations):
        work = active & ~converged & ~diverged & ~stalled
        if effort is not None and work.any():
            running = np.flatnonzero(work)
            work[running[effort.exhausted(running)]] = False
        if it == CONE_CHECK_ITERATION and work.any():
            # A case still running here is checked against the contact cone: a load no combination
            # of contact forces balances is refused now instead of walking to the divergence limit
            # (and through the load continuation) one capped step at a time.
            slow = np.flatnonzero(work)
            check = getattr(problem, "outside_cone", None)  # problems without a contact cone skip it
            outside = check(load[slow]) if check is not None else np.zeros(len(slow), bool)
            refused[slow[outside]] = True
            diverged |= refused
            work &= ~refused
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
        step = without_idle_mechanisms(h, g, step, noise)
        big = np.abs(step if bounded is None else step[:, bounded[idx]]).max(axis=1, initial=0.0)
        step *= np.minimum(1.0, problem.max_step / np.maximum(big, 1e-300))[:, None]
        if it == opts.max_iterations - 1 and getattr(problem, "blind_last", False):
            # The coarse stage's last step is taken unevaluated (the full model evaluates its end).
            new_q = q[cases].copy()
            new_q[:, idx] += step * s[idx]
            q[cases] = new_q
            diverged[cases] |= _excursion(new_q / s, bounded) > problem.limit
            break
        slope = np.einsum("ci,ci->c", g, step)  # < 0 for a descent direction
        new_q, trial, moved = _line_search(sp, qw, lw, stw, step, slope, effort, cases)
        q[cases] = new_q
        for k in st:
            st[k][cases] = trial[k]
        converged[cases] |= trial["norm"] <= opts.rtol
        diverged[cases] |= _excursion(new_q / s, bounded) > problem.limit
        stuck = cases[~moved & ~converged[cases] & ~diverged[cases]]
        if len(stuck) and it < CONE_CHECK_ITERATION:
            # It would have met the cone check still stuck: a load outside the cone is refused as then.
            check = getattr(problem, "outside_cone", None)
            if check is not None:
                outside = stuck[check(load[stuck])]
                refused[outside] = diverged[outside] = True
        stalled[stuck] = True
    return q, converged, st, diverged, refused


def _excursion(scaled_q: np.ndarray, bounded) -> np.ndarray:
    """Largest scaled displacement (C,) over the DOFs the divergence test watches (all when None)."""
    return np.abs(scaled_q if bounded is None else scaled_q[:, bounded]).max(axis=1, initial=0.0)


def _line_search(sp: Problem, qw, lw, stw, step, slope, effort: Effort | None = None, cases=None):
    """Armijo backtracking along ``step`` from ``qw``; returns the accepted iterates, their states
    and which cases moved.

    The full step is tried for every case at once; each halving then re-evaluates only the cases
    still backtracking (a case accepted at t = 1 is not evaluated again while another one halves:
    in a batch most cases take the full Newton step). A case that finds no decrease in
    :data:`MAX_HALVINGS` halvings keeps its iterate (it is then judged by the convergence and
    divergence tests as before) and is reported as not moved. ``effort``: every trial evaluation is
    charged to its cases (``cases``: the positions of ``qw`` in the effort's arrays).
    """
    idx, s = sp.idx, sp.scale
    n_c = len(qw)
    t = np.ones(n_c)
    new_q, trial = qw, stw
    moved = np.zeros(n_c, bool)
    pending = np.arange(n_c)  # cases still backtracking (positions in qw)
    sub = sp
    for _ls in range(MAX_HALVINGS):
        cand = qw[pending].copy()
        cand[:, idx] += (t[pending, None] * step[pending]) * s[idx]
        started = time.thread_time()
        trial_state = sub.state(cand, lw[pending])
        if effort is not None:
            effort.charge(cases[pending], time.thread_time() - started)
        base = stw["potential"][pending]
        slack = 1e-12 * (np.abs(base) + 1e-30)
        ok = (trial_state["potential"] <= base + 1e-4 * t[pending] * slope[pending] + slack) | (
            trial_state["norm"] < 0.5 * stw["norm"][pending]
        )
        if ok.all() and len(pending) == n_c:  # the usual Newton step: nothing to mix
            return cand, trial_state, np.ones(n_c, bool)
        if ok.any():
            hit = pending[ok]
            moved[hit] = True
            new_q = new_q.copy() if new_q is qw else new_q
            new_q[hit] = cand[ok]
            trial = {k: v.copy() for k, v in trial.items()} if trial is stw else trial
            for k, v in trial_state.items():
                trial[k][hit] = v[ok]
        pending = pending[~ok]
        if len(pending) == 0:
            break
        t[pending] *= 0.5
        sub = sp.take(pending) if len(pending) < n_c else sp
    return new_q, trial, moved


def merge(old: dict, new: dict, mask: np.ndarray) -> dict:
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
