"""The compiled solver core: the whole Newton solve of one case in numba, ``prange`` over the cases.

SI units, scaled DOFs as in :mod:`bearingkit.analysis.solver.quasistatic`. The algorithm is the numpy
reference's (:mod:`bearingkit.analysis.solver.newton` and the driver in :mod:`~bearingkit.analysis.solver.
quasistatic`), case by case and step by step: the starting point (fixed-point sizing with the rows'
start matrices, idle mechanisms removed, capped), the first iterations on the coarse model
(:mod:`bearingkit.analysis.solver.coarse`), damped Newton with the vanishing Levenberg term,
idle-mechanism removal, the step cap, Armijo backtracking, the contact-cone check at
:data:`~bearingkit.analysis.solver.newton.CONE_CHECK_ITERATION`, the divergence limit, load continuation
and the non-finite check. Rows are evaluated by the compiled row functions
(:mod:`bearingkit.rows.ball.compiled`, :mod:`~bearingkit.rows.cylindrical.compiled`,
:mod:`~bearingkit.rows.threaded.compiled`, :mod:`bearingkit.rows.tapered.compiled`); a case
allocates only a few small arrays, so memory is O(cases) for the outputs alone. Compilation is
cached on disk (``cache=True``): the first call on a machine compiles (tens of seconds), later
processes load the cache.
"""

from __future__ import annotations

from collections import namedtuple

import numpy as np

from bearingkit.analysis.solver.compiled_linalg import (
    lu_solve,
    mirror_upper,
    nnls_misfit,
    start_point,
    without_idle,
)
from bearingkit.analysis.solver.cone import CONE_MISS_RTOL
from bearingkit.analysis.solver.newton import CONE_CHECK_ITERATION, MAX_HALVINGS
from bearingkit.rows.ball.compiled import BallPack, ball_response, pack_balls
from bearingkit.rows.ball.row import BallKernel
from bearingkit.rows.cylindrical.compiled import RollerPack, pack_rollers, roller_buffers, roller_response
from bearingkit.rows.cylindrical.row import CylindricalKernel
from bearingkit.rows.numba_cache import configure
from bearingkit.rows.tapered.compiled import TaperedPack, pack_tapered, tapered_response
from bearingkit.rows.tapered.kernel import TaperedKernel
from bearingkit.rows.threaded.compiled import PointPack, pack_points, point_response
from bearingkit.rows.threaded.row import ThreadedKernel

configure()  # before numba reads its configuration: the cache follows the compiled sources
from numba import njit, prange  # noqa: E402
from numba.typed import List  # noqa: E402

#: A bearing in compiled form: the packed rows of each kind, the start matrices summed over the rows
#: of one start exponent (G, 5, 5) and those exponents (G,), the row count, the cylindrical rows of
#: the coarse model (:mod:`bearingkit.analysis.solver.coarse`) and whether it differs from the full one (1/0).
ModelPack = namedtuple(
    "ModelPack", "balls rollers points tapered start_mats start_exps n_rows coarse has_coarse"
)
#: The raw outputs of :func:`solve_packed` (see there).
PackedSolution = namedtuple("PackedSolution", "q force stiffness flags counts norm bad inner roller_x")
#: Kernel classes the compiled core can evaluate, by their ``row.kind``.
SUPPORTED_KINDS = ("ball", "cylindrical", "tapered", "threaded")
#: The numpy kernel class each compiled group mirrors. Matched by exact class: a subclass (a kernel at
#: speed, :mod:`bearingkit.rows.ball.speed`, :mod:`bearingkit.rows.cylindrical.speed`) adds physics the
#: compiled group does not have, so its bearing runs the numpy path.
KERNEL_GROUPS = {
    BallKernel: "ball",
    CylindricalKernel: "cylindrical",
    TaperedKernel: "tapered",
    ThreadedKernel: "threaded",
}


def pack_model(kernels, coarse=None) -> ModelPack | None:
    """The compiled form of a bearing's row kernels, or None if a row kind has no compiled core.

    ``coarse``: the kernels of the coarse model (:func:`bearingkit.analysis.solver.coarse.coarse_kernels`,
    row for row; only its cylindrical rows differ), or None for no coarse stage.
    """
    groups = {kind: ([], []) for kind in SUPPORTED_KINDS}
    for r, k in enumerate(kernels):
        kind = KERNEL_GROUPS.get(type(k))
        if kind is None:
            return None
        groups[kind][0].append(k)
        groups[kind][1].append(r)
    if groups["threaded"][0] and any(np.shape(k.G)[0] != 1 for k in groups["threaded"][0]):
        return None
    # Rows sharing a start exponent share the power of δ: summed once here, the starting point
    # takes one power per exponent per sweep instead of one per row.
    exps = sorted({float(k.start_exponent) for k in kernels})
    mats = [
        sum(np.asarray(k.start_matrix, float) for k in kernels if float(k.start_exponent) == e) for e in exps
    ]
    rollers = pack_rollers(*groups["cylindrical"])
    if coarse is None:
        coarse_rollers, has_coarse = rollers, 0
    else:
        coarse_rollers = pack_rollers([coarse[r] for r in groups["cylindrical"][1]], groups["cylindrical"][1])
        has_coarse = 1
    return ModelPack(
        pack_balls(*groups["ball"]),
        rollers,
        pack_points(*groups["threaded"]),
        pack_tapered(*groups["tapered"]),
        np.ascontiguousarray(np.stack(mats)),
        np.array(exps),
        len(kernels),
        coarse_rollers,
        has_coarse,
    )


# -- one evaluation ---------------------------------------------------------------------------------
# Numba counts references: a function takes a reference to every array of every argument on entry
# and drops it on exit (atomic operations). The ModelPack holds ~45 arrays, so an evaluation takes
# only the row packs and the scratch it needs, unpacked once per Newton call. Passing (mp, ws) through
# two levels per evaluation had made 3,867 such operations per seed-000 single solve (1,800 of them in
# those two functions; a quarter of the profile's samples); now 1,964.
@njit(cache=True, error_model="numpy")
def _state(c, q, load, balls, rollers, points, tapered, tws, fbuf, ibuf, inner, scale, idx, force, jac,
           rowf, residual):  # fmt: skip
    """Evaluate case c at q under ``load``: fills force, Jacobian, per-row force and residual; returns
    (potential, norm).

    ``balls`` … ``tapered``: the row packs of the model evaluated (full or coarse); ``tws``: the tapered
    rows' warm start (the workspace's first four arrays), ``fbuf``, ``ibuf``: the cylindrical rows'
    scratch (:func:`_workspace`).
    """
    force[:] = 0.0
    jac[:, :] = 0.0
    rowf[:, :] = 0.0
    energy = ball_response(c, q, balls, force, jac, rowf)
    energy += roller_response(c, q, rollers, force, jac, rowf, fbuf, ibuf)
    energy += point_response(q, points, force, jac, rowf)
    mirror_upper(jac)  # the three above accumulate the upper triangle only
    if tapered.gf.shape[0] > 0:
        e, used, unconv = tapered_response(c, q, tapered, tws[0], tws[1], tws[2], tws[3], force, jac, rowf)
        energy += e
        inner[0] += 1.0
        inner[1] = max(inner[1], used)
        inner[2] += unconv
    pot = energy
    for i in idx:
        pot -= load[i] * q[i]
    lscale = 0.0
    for i in range(5):
        residual[i] = load[i] + force[i]
        lscale = max(lscale, abs(load[i] * scale[i]))
    for i in range(5):
        rmax = 0.0
        for r in range(rowf.shape[0]):
            rmax = max(rmax, abs(rowf[r, i]))
        lscale = max(lscale, rmax * scale[i])
    lscale = max(lscale, 1e-12)
    norm = 0.0
    for i in idx:
        norm = max(norm, abs(residual[i] * scale[i]))
    return pot, norm / lscale if idx.shape[0] > 0 else 0.0


# -- Newton for one case -----------------------------------------------------------------------------
@njit(cache=True, error_model="numpy")
def _outside(cone, load, scale, idx):
    """Whether ``load`` lies outside the contact cone (as :func:`~bearingkit.analysis.solver.cone.
    outside_cone`)."""
    n = idx.shape[0]
    f = np.empty(n)
    size = 0.0
    for a in range(n):
        f[a] = load[idx[a]] * scale[idx[a]]
        size += f[a] * f[a]
    size = np.sqrt(size)
    return size > 0.0 and nnls_misfit(cone, f) > CONE_MISS_RTOL * size


@njit(cache=True, error_model="numpy")
def _newton_case(c, q, load, mp, ws, inner, scale, idx, p, cone, stats):
    """Damped Newton from q (updated in place) under ``load``; returns (converged, diverged, refused,
    stopped).

    ``p`` = (rtol, max_iterations, max_step, limit, cone check on, coarse iterations, last step
    unevaluated, evaluation budget of the case), ``cone`` the scaled contact directions (n, M) on the
    free DOFs; ``stats`` (iterations, evaluations) are accumulated. As the numpy reference's
    :func:`~bearingkit.analysis.solver.newton.newton` with its ``Effort``: a case that has spent its
    budget of row evaluations (stats[1] ≥ p[7], every attempt and continuation step together) stops
    at the start of an iteration (``stopped``); a case whose line search finds no decrease stops its
    attempt (its next step would be the same one), refused first if its load is outside the cone.
    The last state is left in ws[4:] (force, jac, residual) and ws[8] (norm).
    """
    force, jac, rowf, residual, tmp = ws[4], ws[5], ws[6], ws[7], ws[8]
    rtol, max_it, max_step, limit, cone_on, blind = p[0], int(p[1]), p[2], p[3], p[4], p[6] > 0.0
    n = idx.shape[0]
    balls, rollers, points, tapered = mp.balls, mp.rollers, mp.points, mp.tapered
    tws, fbuf, ibuf = (ws[0], ws[1], ws[2], ws[3]), ws[9], ws[10]
    pot, norm = _state(
        c, q, load, balls, rollers, points, tapered, tws, fbuf, ibuf, inner, scale, idx, force, jac, rowf,
        residual,
    )  # fmt: skip
    stats[1] += 1.0
    converged = norm <= rtol
    diverged = False
    refused = False
    stopped = False
    g = np.empty(n)
    mg = np.empty(n)
    h = np.empty((n, n))
    hm = np.empty((n, n))
    cand = np.empty(5)
    t_force = np.empty(5)
    t_jac = np.empty((5, 5))
    t_rowf = np.empty_like(rowf)
    t_res = np.empty(5)
    for it in range(max_it):
        if converged or diverged:
            break
        if stats[1] >= p[7]:  # the case's budget of row evaluations is spent
            stopped = True
            break
        if it == CONE_CHECK_ITERATION and cone_on > 0.0 and _outside(cone, load, scale, idx):
            refused = True
            diverged = True
            break
        stats[0] += 1.0
        gmax = 0.0
        diag = 0.0
        for a in range(n):
            g[a] = -(residual[idx[a]] * scale[idx[a]])
            gmax = max(gmax, abs(g[a]))
            for b in range(n):
                h[a, b] = -(jac[idx[a], idx[b]] * scale[idx[a]] * scale[idx[b]])
            diag = max(diag, abs(h[a, a]))
        mu = 1e-12 * diag + gmax / (1e6 * max_step) + 1e-300
        for a in range(n):
            hm[a, :] = h[a, :]
            hm[a, a] += mu
            mg[a] = -g[a]
        step = lu_solve(hm, mg)
        noise = rtol * gmax / max(norm, 1e-300)
        without_idle(h, g, step, noise)
        big = 0.0
        for a in range(n):
            big = max(big, abs(step[a]))
        fac = min(1.0, max_step / max(big, 1e-300))
        slope = 0.0
        for a in range(n):
            step[a] *= fac
            slope += g[a] * step[a]
        if blind and it == max_it - 1:
            # The coarse stage's last step is taken unevaluated: the full model evaluates its end.
            for a in range(n):
                q[idx[a]] += step[a] * scale[idx[a]]
            qmax = 0.0
            for i in range(5):
                qmax = max(qmax, abs(q[i] / scale[i]))
            diverged = qmax > limit
            break
        t = 1.0
        moved = False
        for _ls in range(MAX_HALVINGS):
            cand[:] = q
            for a in range(n):
                cand[idx[a]] += (t * step[a]) * scale[idx[a]]
            t_pot, t_norm = _state(
                c, cand, load, balls, rollers, points, tapered, tws, fbuf, ibuf, inner, scale, idx, t_force,
                t_jac, t_rowf, t_res,
            )  # fmt: skip
            stats[1] += 1.0
            slack = 1e-12 * (abs(pot) + 1e-30)
            if (t_pot <= pot + 1e-4 * t * slope + slack) or (t_norm < 0.5 * norm):
                q[:] = cand
                pot, norm = t_pot, t_norm
                force[:] = t_force
                jac[:, :] = t_jac
                rowf[:, :] = t_rowf
                residual[:] = t_res
                moved = True
                break
            t *= 0.5
        converged = norm <= rtol
        qmax = 0.0
        for i in range(5):
            qmax = max(qmax, abs(q[i] / scale[i]))
        diverged = qmax > limit
        if not (moved or converged or diverged):  # stalled: the same step would fail again
            if it < CONE_CHECK_ITERATION and cone_on > 0.0 and _outside(cone, load, scale, idx):
                refused = True
                diverged = True
            break
    tmp[0] = norm
    return converged, diverged, refused, stopped


@njit(cache=True, error_model="numpy")
def _coarse_stage(c, q, load, mp, ws, inner, scale, idx, p, cone, stats):
    """The first Newton iterations on the coarse model from q (:mod:`bearingkit.analysis.solver.coarse`).

    The last coarse step is taken without evaluating the coarse model: the full model's first
    evaluation is at its end. Returns the coarse iterate, or q itself where the coarse attempt
    diverged or went non-finite (as the numpy reference's ``_coarse_start``). Its evaluations are
    counted in stats[2].
    """
    # The same field types as mp (no literal), so _newton_case is compiled once for both models.
    cm = ModelPack(
        mp.balls, mp.coarse, mp.points, mp.tapered, mp.start_mats, mp.start_exps, mp.n_rows, mp.coarse,
        mp.has_coarse,
    )  # fmt: skip
    pc = p.copy()
    pc[1] = p[5]
    pc[4] = 0.0  # the cone check belongs to the full model's iterations
    pc[6] = 1.0  # the last coarse step is evaluated by the full model
    pc[7] = np.inf  # the coarse stage is not charged to the case's budget (as numpy's _coarse_start)
    qc = q.copy()
    own = np.zeros(2)
    _, div, _, _ = _newton_case(c, qc, load, cm, ws, inner, scale, idx, pc, cone, own)
    stats[2] += own[1]
    if div or not np.isfinite(ws[8][0]):
        return q
    for i in range(5):
        if not np.isfinite(qc[i]):
            return q
    return qc


@njit(cache=True, error_model="numpy")
def _workspace(mp):
    """Scratch of one thread, reused case after case (:func:`_solve_case` resets the warm start)."""
    t = mp.tapered.gf.shape[0]
    fbuf, ibuf = roller_buffers(mp.rollers)
    return (
        np.zeros((t, 2)),
        np.zeros((t, 5, 2)),
        np.zeros(5),
        np.zeros(1),
        np.zeros(5),
        np.zeros((5, 5)),
        np.zeros((mp.n_rows, 5)),
        np.zeros(5),
        np.zeros(1),
        fbuf,
        ibuf,
    )


@njit(cache=True, error_model="numpy")
def _solve_case(
    c, q0, load, free, mp, ws, scale, idx, p, fracs, cone, given, out_q, out_f, out_k, out_b, out_n, out_r,
    inner, out_x,
):  # fmt: skip
    """Whole solve of case c: start, attempt, continuation, non-finite check. Fills the outputs.

    ``ws``: the thread's workspace (:func:`_workspace`). out_k[c] the stiffness (−Jacobian);
    out_b[:, c] = (converged, diverged, refused, broken, stopped by its budget), out_n[:, c] =
    (iterations, evaluations, coarse evaluations), out_r[c] the residual norm. Returns 1 if the case
    did not converge, else 0.
    """
    ws[0][:, :] = 0.0  # the tapered warm start never crosses from one case to the next
    ws[1][:, :, :] = 0.0
    ws[2][:] = 0.0
    ws[3][:] = 0.0
    stats = np.zeros(3)
    q = q0.copy() if given else start_point(q0, load, mp.start_mats, mp.start_exps, scale, idx, p[2])
    if mp.has_coarse > 0 and p[5] > 0.0 and not given:
        q = _coarse_stage(c, q, load, mp, ws, inner, scale, idx, p, cone, stats)
    conv, div, ref, stop = _newton_case(c, q, load, mp, ws, inner, scale, idx, p, cone, stats)
    if fracs.shape[0] > 0 and not conv and not ref and not stop:  # a case out of budget is not retried
        qc = q0.copy()
        ramp = np.empty(5)
        for frac in fracs:
            for i in range(5):
                ramp[i] = load[i] * frac if free[i] else load[i]
            conv, div, _, out = _newton_case(c, qc, ramp, mp, ws, inner, scale, idx, p, cone, stats)
            stop = stop or out
        q[:] = qc
    norm = ws[8][0]
    broken = not (np.all(np.isfinite(q)) and np.isfinite(norm))
    if broken:
        q[:] = q0
        conv = False
    out_q[c] = q
    out_f[c] = ws[4]
    jac = ws[5]
    for i in range(5):
        for j in range(5):
            out_k[c, i, j] = -jac[i, j]
    out_b[0, c] = conv
    out_b[1, c] = div
    out_b[2, c] = ref
    out_b[3, c] = broken
    out_b[4, c] = stop
    out_n[0, c] = np.int64(stats[0])
    out_n[1, c] = np.int64(stats[1])
    out_n[2, c] = np.int64(stats[2])
    out_r[c] = norm
    # The tapered rollers' positions X at the returned q (NaN when the last evaluation was at
    # another point): the start of the per-roller loads (compiled_tapered.roller_loads).
    same = ws[3][0] > 0.0
    for i in range(5):
        same = same and ws[2][i] == q[i]
    for t in range(out_x.shape[1]):
        out_x[c, t, 0] = ws[0][t, 0] if same else np.nan
        out_x[c, t, 1] = ws[0][t, 1] if same else np.nan
    return 0 if conv else 1


# The parfor wrapper of ``prange`` takes arrays and scalars only, not namedtuples of arrays: the
# parallel driver receives the packed rows flattened (order of :func:`_flat`) and rebuilds the pack
# inside the loop body. The loop runs over blocks of ``block`` cases, one workspace per block.
# Both drivers release the GIL (nogil): a program that solves in several threads at once (a study's
# chunks evaluated side by side, issue 34) runs their compiled solves on as many cores.
@njit(cache=True, parallel=True, error_model="numpy", nogil=True)
def _solve_batch(
    q0, load, free,
    b_B, b_s0, b_a0, b_kn, b_side, b_row,
    r_Ga, r_Gb, r_x, r_d0, r_cs, r_ns, r_row, r_reach,
    p_G, p_d0, p_k, p_row,
    t_gi, t_gf, t_d0i, t_d0e, t_dev, t_ns, t_bi, t_be, t_bf, t_cs, t_kf, t_fc, t_floor, t_ffloor, t_cap,
    t_taylor, t_row, t_lc,
    start_mats, start_exps, n_rows,
    c_Ga, c_Gb, c_x, c_d0, c_cs, c_ns, c_row, c_reach, has_coarse,
    scale, idx, p, fracs, cone, given, out_q, out_f, out_k, out_b, out_n, out_r, inner, out_x, block,
):  # fmt: skip
    n_cases = load.shape[0]
    for i in prange((n_cases + block - 1) // block):
        first = np.int64(i) * block  # the parfor index may be unsigned: int64 keeps indices integers
        balls = BallPack(b_B, b_s0, b_a0, b_kn, b_side, b_row)
        rollers = RollerPack(r_Ga, r_Gb, r_x, r_d0, r_cs, r_ns, r_row, r_reach)
        points = PointPack(p_G, p_d0, p_k, p_row)
        tapered = TaperedPack(
            t_gi, t_gf, t_d0i, t_d0e, t_dev, t_ns, t_bi, t_be, t_bf, t_cs, t_kf, t_fc, t_floor,
            t_ffloor, t_cap, t_taylor, t_row, t_lc
        )  # fmt: skip
        coarse = RollerPack(c_Ga, c_Gb, c_x, c_d0, c_cs, c_ns, c_row, c_reach)
        mp = ModelPack(balls, rollers, points, tapered, start_mats, start_exps, n_rows, coarse, has_coarse)
        ws = _workspace(mp)
        for c in range(first, min(first + block, n_cases)):
            _solve_case(c, q0[c], load[c], free, mp, ws, scale, idx, p, fracs, cone, given,
                        out_q, out_f, out_k, out_b, out_n, out_r, inner[c], out_x)  # fmt: skip


def _flat(mp: ModelPack) -> tuple:
    """The pack's arrays in the parallel driver's argument order."""
    return (
        *mp.balls, *mp.rollers, *mp.points, *mp.tapered, mp.start_mats, mp.start_exps, mp.n_rows, *mp.coarse,
        mp.has_coarse,
    )  # fmt: skip


@njit(cache=True, nogil=True)
def _held(mp):
    """The pack in a one-item typed list (:func:`_solve_held`): built once per model and plan."""
    held = List()
    held.append(mp)
    return held


@njit(cache=True, error_model="numpy", nogil=True)
def _solve_held(
    q0, load, free, held, scale, idx, p, fracs, cone, given, out_q, out_f, out_k, out_b, out_n, out_r, inner,
    out_x,
):  # fmt: skip
    """Every case on the calling thread, the pack held in a typed list (:func:`_held`); returns the number
    of cases that did not converge.

    Entering a compiled function converts every array argument (~0.1 µs each, a memory block per
    array); the pack holds 48 of them, 5 µs of a single 6209 solve's ~30 µs in the compiled core
    (issue 34). A typed list is converted as one object, and its item is the pack already converted.
    The loop is written here, not in a serial driver this one calls: numba optimises each function's
    module again with its callees linked in, and that extra level cost ~10 s of the core's compile
    (the first solve's entry point 99 → 90 s, measured on the 2-core machine).
    """
    mp = held[0]
    ws = _workspace(mp)
    bad = 0
    for c in range(load.shape[0]):
        bad += _solve_case(c, q0[c], load[c], free, mp, ws, scale, idx, p, fracs, cone, given,
                           out_q, out_f, out_k, out_b, out_n, out_r, inner[c], out_x)  # fmt: skip
    return bad


def _constants(mp: ModelPack, free, max_step, limit, options, cone) -> dict:
    """The arguments of a solve that do not depend on the loads (kept by the caller per model)."""
    idx = np.flatnonzero(free).astype(np.int64)
    cone_on = 0.0 if cone is None else 1.0
    steps = options.continuation_steps
    return {
        "idx": idx,
        "p": np.array(
            [
                options.rtol,
                options.max_iterations,
                max_step,
                limit,
                cone_on,
                options.coarse_iterations,
                0.0,
                options.max_evaluations,
            ],
            dtype=np.float64,
        ),
        "fracs": np.linspace(1.0 / steps, 1.0, steps) if steps else np.zeros(0),
        "cone": np.zeros((len(idx), 0)) if cone is None else np.ascontiguousarray(cone, dtype=np.float64),
        "flat": _flat(mp),
        "held": _held(mp),
    }


def _entry(driver, args):
    """The compiled driver for these argument types, without the dispatcher's type resolution.

    Resolving the types of a ModelPack (a namedtuple of ~45 arrays) costs the dispatcher ~10 µs per
    call, a tenth of a whole single solve (and ~12 µs for the parallel driver's 66 arguments); the
    argument types of one model never change, so the compiled entry point is looked up once (None:
    let the dispatcher compile or choose).
    """
    try:
        sig = tuple(driver.typeof_pyval(a) for a in args)
        return driver.overloads[sig].entry_point
    except Exception:  # not compiled for these types yet, or a numba without this API
        return None


#: The float64 dtype (compared by identity: the inputs' dtype is tested on every call).
_F64 = np.dtype(np.float64)


def solve_packed(
    mp: ModelPack, q0, load, free, scale, max_step, limit, options, cone, given, parallel, cache=None,
    block=32,
):  # fmt: skip
    """Run the compiled solve of every case (C, 5 arrays in SI); returns the raw per-case outputs.

    ``cache`` (a dict kept by the caller per model, free DOFs and options) holds the arguments that do
    not depend on the loads. ``parallel``: blocks of ``block`` cases are handed to the threads, each
    block solved with one workspace.

    Returns a :data:`PackedSolution`: ``q``, ``force`` (C, 5), ``stiffness`` (C, 5, 5), ``flags``
    (5, C) bool (converged, diverged, refused, broken, stopped by the case's evaluation budget),
    ``counts`` (3, C) int (Newton iterations,
    evaluations, coarse evaluations), ``norm`` (C,), ``bad`` the number of unconverged cases,
    ``inner`` (C, 3): roller solves, most roller Newton steps, unconverged rollers; ``roller_x``
    (C, T, 2): the tapered rollers' positions at q (NaN where unknown; T = 0 without tapered rows).
    """
    n = load.shape[0]
    cache = {} if cache is None else cache
    if "idx" not in cache:
        cache.update(_constants(mp, free, max_step, limit, options, cone))
        cache["scale"] = np.ascontiguousarray(scale, dtype=np.float64)
        cache["free"] = np.ascontiguousarray(free, dtype=np.bool_)
        cache["const"] = (cache["scale"], cache["idx"], cache["p"], cache["fracs"], cache["cone"])
        cache["n_t"] = mp.tapered.gf.shape[0]
    n_t = cache["n_t"]
    if n == 1 and "untouched" in cache:
        # Written by nothing without tapered rows: one shared pair, not two allocations per solve.
        inner, out_x = cache["untouched"]
    else:
        inner, out_x = np.zeros((n, 3)), np.empty((n, n_t, 2))
        if n_t == 0 and n == 1:
            cache["untouched"] = (inner, out_x)
    q, force, stiffness = np.empty((n, 5)), np.empty((n, 5)), np.empty((n, 5, 5))
    flags, counts, norm = np.empty((5, n), np.bool_), np.empty((3, n), np.int64), np.empty(n)
    # The serial entry point skips numba's type checks: its arguments must keep their exact types.
    if load.dtype is not _F64 or not load.flags.c_contiguous:
        load = np.ascontiguousarray(load, dtype=np.float64)
    if q0.dtype is not _F64 or not q0.flags.c_contiguous:
        q0 = np.ascontiguousarray(q0, dtype=np.float64)
    if parallel:
        args = (q0, load, cache["free"], *cache["flat"], *cache["const"], bool(given))
        args += (q, force, stiffness, flags, counts, norm, inner, out_x, np.int64(block))
        entry = cache.get("batch")
        if entry is None:
            _solve_batch(*args)
            cache["batch"] = _entry(_solve_batch, args)
        else:  # ~12 µs less per call than the dispatcher's type resolution of its 66 arguments
            entry(*args)
        bad = n - int(np.count_nonzero(flags[0]))
    else:
        entry = cache.get("serial")
        args = (q0, load, cache["free"], cache["held"], *cache["const"], bool(given))
        args += (q, force, stiffness, flags, counts, norm, inner, out_x)
        if entry is None:
            bad = _solve_held(*args)
            cache["serial"] = _entry(_solve_held, args)
        else:
            bad = entry(*args)
    return PackedSolution(q, force, stiffness, flags, counts, norm, bad, inner, out_x)


__all__ = [
    "SUPPORTED_KINDS",
    "BallPack",
    "ModelPack",
    "PackedSolution",
    "PointPack",
    "RollerPack",
    "TaperedPack",
    "pack_model",
    "solve_packed",
]
