"""Solver kernel of a tapered roller row: the roller sub-problem, condensed into the engine.

The model (per-roller 2-DOF equilibrium under cone, cup and rib contacts, condensation by the
implicit-function theorem) is described in :mod:`bearingkit.rows.tapered.row`, which also holds the row's
data (:class:`~bearingkit.rows.tapered.row.TaperedRow`) and meridian geometry. This module holds what
the solver calls: the batched, bounded roller Newton iteration and the condensed force, stiffness
and energy.
"""

from __future__ import annotations

import numpy as np

from bearingkit.rows.base import (
    InnerStats,
    KernelBase,
    RacewayOffset,
    RowResponse,
    RowState,
    axial_row,
    azimuths,
    element_offsets,
    radial_row,
    relative_displacement,
    steel_e_reduced,
)
from bearingkit.rows.tapered.geometry import DEFAULT_END_RADIUS_RATIO, LINE_EXPONENT, TapGeometry
from bearingkit.rows.tapered.laws import kunert_law, rib_law, taylor_law

#: Inner Newton iteration of the roller equilibrium: iteration cap, relative tolerance on each roller's
#: force balance (of its summed contact loads), step halvings per line search, the largest step as a
#: fraction of the roller diameter, and the balance below which a line search that finds no decrease
#: is taken as round-off (double precision sums of slice loads stall near 1e-14 relative).
ROLLER_MAX_ITER = 40
ROLLER_RTOL = 1e-12
ROLLER_MAX_HALVINGS = 16
ROLLER_STEP_CAP = 0.02
ROLLER_STALL_RTOL = 1e-9
#: Resolution of an approach relative to the displacements it is computed from (4 ulp) [-].
ROLLER_NOISE_EPS = 4.0 * np.finfo(float).eps
#: Approach at which the stiffness floor of the roller sub-problem is set, as a fraction of the mean
#: roller diameter [-] (1e-4 D: a typical working approach); the floor is 1e-12 of that stiffness.
STIFFNESS_FLOOR_APPROACH = 1e-4


class TaperedKernel(KernelBase):
    """Solver kernel of a :class:`TaperedRow`: roller DOFs condensed inside :meth:`response`.

    ``response(q, offset)`` and ``state(q, offset)`` accept a :class:`~bearingkit.rows.base.RacewayOffset`
    (cup shift and per-roller outward radial deflection of the cup, which opens the cup contacts by
    its component along n_e).

    The roller sub-problem is warm-started from the previous call (the last roller positions moved
    to first order with the ring, dX = −K_XX⁻¹ K_Xq dq) and bounded; its effort is recorded in
    ``inner_iterations`` (Newton steps of this object's last call) and in :class:`InnerStats`
    shared with the per-case copies the solver makes (:meth:`take`): ``inner_iterations_max`` and
    ``inner_unconverged`` (rollers that reached the cap without meeting the tolerance; their forces
    are those of the last iterate).
    """

    _case_arrays = ("d0_i", "d0_e", "delta_dev", "deviation", "f_c", "omega_cage")

    def __init__(self, row):
        from bearingkit.physics.contact import hertz, line

        self.row = row
        geo = TapGeometry(row)
        self.geo = geo
        z_el, n_s = row.n_elements, row.n_slices
        self.e_reduced = float(row.e_reduced) if row.e_reduced is not None else steel_e_reduced()
        sigma = float(row.direction)
        x, width = line.slice_grid(geo.length, n_s)
        x = np.asarray(x, dtype=float).reshape(n_s)
        self.x = x
        psi = azimuths(z_el, row.azimuth_phase)[0]  # (Z,)
        self.psi = psi
        z0 = float(row.axial_position)

        def ring_dirs(p, n):  # generalised direction g with δ = n·w(p): (Z, …, 5)
            r_glob = p[..., 0]
            z_glob = z0 + sigma * p[..., 1]
            ps = psi.reshape((-1,) + (1,) * (np.ndim(r_glob)))
            return n[0] * radial_row(ps, z_glob) + sigma * n[1] * axial_row(ps, r_glob)

        p_i = geo.centre - geo.r_m * geo.e + x[:, None] * geo.t_i  # (n_s, 2)
        self.p_i = p_i
        self.g_i = ring_dirs(p_i, geo.n_i)  # (Z, n_s, 5)
        self.g_f = ring_dirs(geo.p_f, geo.n_f)  # (Z, 5)
        # Stiffness constants.
        k_line = (
            float(line.line_stiffness(geo.length, self.e_reduced, law=row.line_law))
            if row.raceway_stiffness is None
            else float(row.raceway_stiffness)
        )
        self.k_line = k_line
        self.c_s = k_line * float(width) / geo.length
        end_r = (
            DEFAULT_END_RADIUS_RATIO * geo.apex_distance if row.end_radius is None else float(row.end_radius)
        )
        self.end_radius = end_r
        self.k_f = float(hertz.point_stiffness(2.0 / end_r, 0.0, self.e_reduced))
        # Regularisation floor of the 2×2 roller systems [N/m]: 1e-12 of a line's stiffness at a
        # typical approach, far below any closed contact, never zero (an all-open roller).
        approach = STIFFNESS_FLOOR_APPROACH * row.element_diameter
        self.stiffness_floor = 1e-12 * LINE_EXPONENT * k_line * approach ** (LINE_EXPONENT - 1.0)
        # Absolute force tolerance of a roller's balance [N]: ROLLER_RTOL of a line's load at that
        # approach (an unloaded roller's rib touching at 1e-22 m has no relative accuracy to reach).
        self.force_floor = ROLLER_RTOL * k_line * approach**LINE_EXPONENT
        # Constant parts of the approaches (C|1, Z, n_s) with the deviation.
        drop = np.zeros(n_s) if row.profile is None else np.asarray(row.profile.crown_drop(x), dtype=float)
        dev = (
            np.zeros((1, z_el))
            if row.diameter_deviation is None
            else np.asarray(row.diameter_deviation, float)
        )
        dev = dev.reshape(-1, z_el)
        self.deviation = dev
        self.delta_dev = 0.5 * dev * np.cos(geo.eps)  # Δ_j (C|1, Z)
        self.taylor = row.deviation_model == "taylor"
        base = -drop[None, None, :]
        shift = 0.0 if self.taylor else self.delta_dev[..., None]
        self.d0_i = base + shift
        self.d0_e = base + shift - 0.5 * float(row.clearance)
        # Centrifugal force (radial, outward) at the pure-rolling cage speed, per case (C|1, 1): a
        # row at one speed has one value, a row whose load cases run at several speeds one per case.
        speed = np.asarray(row.speed, dtype=float).reshape(-1, 1)
        omega_c = speed * geo.radius_inner / (geo.radius_inner + geo.radius_outer)
        self.omega_cage = omega_c
        self.f_c = float(row.density) * geo.volume * omega_c**2 * geo.centre[0]
        # Local roller-DOF directions: cone −n_i, cup +n_e, rib −n_f; outer contacts have no ring part.
        self.b_i, self.b_e, self.b_f = -geo.n_i, geo.n_e, -geo.n_f
        # Directions for the solver: per roller the cone + rib load that balances a unit cup load.
        m = np.stack([geo.n_i, geo.n_f], axis=1)
        qi, qf = np.linalg.solve(m, geo.n_e)
        g_mid = self.g_i.mean(axis=1)
        self.directions = (qi * g_mid + qf * self.g_f)[None]  # (1, Z, 5)
        # Contact cone for the solver's diagnosis: the cone load may sit on any slice, so every slice
        # gives a direction (a sliced row can shift its load along the roller and carry some moment).
        self.reach = (qi * self.g_i + qf * self.g_f[:, None, :]).reshape(z_el * n_s, 5)
        self.G_flat_i = self.g_i.reshape(z_el * n_s, 5)
        self.GG_i = (self.g_i[..., :, None] * self.g_i[..., None, :]).reshape(z_el * n_s, 25)
        self.GG_f = (self.g_f[:, :, None] * self.g_f[:, None, :]).reshape(z_el, 25)
        # Starting matrix: condensed stiffness with unit-exponent laws (every contact closed).
        kq = self._condense(
            np.full((1, z_el, n_s), self.c_s), np.full((1, z_el, n_s), self.c_s), np.full((1, z_el), self.k_f)
        )
        self.start_matrix = kq[0]
        self.start_exponent = LINE_EXPONENT
        self.char_length = float(max(geo.centre[0], abs(z0)) + geo.length / 2)
        self.deflection_scale = float(row.element_diameter)
        self._cache = None
        self.inner_iterations = 0
        self.inner_stats = InnerStats()

    @property
    def inner_iterations_max(self) -> int:
        """Most Newton steps one roller sub-problem took since the kernel was built (all copies)."""
        return self.inner_stats.iterations_max

    @property
    def inner_unconverged(self) -> int:
        """Rollers that reached :data:`ROLLER_MAX_ITER` without meeting the tolerance (all calls)."""
        return self.inner_stats.unconverged

    def take(self, cases: np.ndarray):
        """A copy restricted to ``cases``; the warm start follows them, the statistics stay shared."""
        out = super().take(cases)
        cache = self._cache
        if cache is not None and np.shape(cases) != () and cache[1].shape[0] > np.max(cases, initial=-1):
            out._cache = tuple(None if a is None else a[cases] for a in cache)
        else:
            out._cache = None
        return out

    # -- contact laws ------------------------------------------------------------------------------
    def _line_law(self, delta):
        """Slice load, stiffness and energy of the raceway slices (C, Z, n_s)."""
        if self.taylor:
            return taylor_law(delta, self.delta_dev[..., None], self.c_s)
        return kunert_law(delta, self.c_s)

    def _point_law(self, delta):
        return rib_law(delta, self.k_f)

    # -- roller equilibrium ------------------------------------------------------------------------
    def _ring_parts(self, q, offset=None):
        q = relative_displacement(q, offset)
        c = q.shape[0]
        z_el, n_s = self.row.n_elements, self.row.n_slices
        a_i = (q @ self.G_flat_i.T).reshape(c, z_el, n_s) + self.d0_i
        a_f = q @ self.g_f.T  # (C, Z)
        d0_e = self.d0_e
        parts = element_offsets(offset, (c, z_el))
        if parts is not None:  # the cup moved: each cup slice opens by n_e·(its displacement)
            d0_e = d0_e - self._cup_opening(*parts)
        return a_i, a_f, d0_e

    def _cup_weights(self):
        """∂(opening of cup slice k)/∂(radial, axial, tilt) (3, n_s): the slice point p_k = centre + r_m e
        + x_k t_e in the meridian frame (r, s = σ(z − z_e)), moved by (radial − (z − z_e) tilt,
        axial + (r − r_e) tilt) (RacewayOffset)."""
        geo, sigma = self.geo, float(self.row.direction)
        arm = geo.r_m * geo.e + self.x[:, None] * geo.t_e  # (n_s, 2): (r − r_e, s)
        n0, n1 = geo.n_e
        ones = np.ones_like(self.x)
        return np.stack([n0 * ones, sigma * n1 * ones, sigma * (n1 * arm[:, 0] - n0 * arm[:, 1])])

    def _cup_opening(self, radial, axial, tilt):
        w = self._cup_weights()
        n0, n1 = self.geo.n_e
        sigma = float(self.row.direction)
        # radial first, as the radial-only offset always did (same floating-point sum)
        return (n0 * radial)[..., None] + (sigma * n1 * axial)[..., None] + tilt[..., None] * w[2]

    def raceway_loads(self, q: np.ndarray, offset: RacewayOffset | None = None) -> np.ndarray:
        """Loads (F_r, F_z, M_t) (C, Z, 3) each roller's cup contact puts on the outer raceway,
        −∂U/∂(radial, axial, tilt) = Σ_k q_e,k ∂(opening_k)/∂(…) (rollers in equilibrium: the derivative
        at fixed roller positions is the total one)."""
        qe = self.roller_state(q, offset)["slice_load_outer"]  # (C, Z, n_s)
        return np.einsum("czk,ak->cza", qe, self._cup_weights())

    def _approaches(self, a_i, a_f, xr, d0_e):
        d_i = a_i + (xr @ self.b_i)[..., None]
        d_e = d0_e + (xr @ self.b_e)[..., None]
        d_f = a_f + xr @ self.b_f
        return d_i, d_e, d_f

    def _roller_eval(self, a_i, a_f, xr, d0_e):
        """Φ (C, Z), ∂Φ/∂X (C, Z, 2), load scale (C, Z) and summed stiffnesses of the rollers at X = xr."""
        d_i, d_e, d_f = self._approaches(a_i, a_f, xr, d0_e)
        qi, ki, ei = self._line_law(d_i)
        qe, ke, ee = self._line_law(d_e)
        qf, kf, ef = self._point_law(d_f)
        si, se = qi.sum(-1), qe.sum(-1)
        grad = si[..., None] * self.b_i + se[..., None] * self.b_e + qf[..., None] * self.b_f
        grad[..., 0] -= self.f_c
        phi = ei.sum(-1) + ee.sum(-1) + ef - self.f_c * xr[..., 0]
        scale = si + se + qf + abs(self.f_c)
        return phi, grad, scale, ki.sum(-1), ke.sum(-1), kf

    def _start(self, q_rel, a_i, a_f, d0_e, shape):
        """Starting roller positions and their evaluation.

        The last solution, moved to first order to the new ring position (dX = −K_XX⁻¹ K_Xq dq, the
        sensitivity kept by :meth:`response`), is the warm start; the closed-form guess replaces it
        for rollers where it is lower in Φ (a contact opened or closed in between) or not finite.
        """
        guess = self._guess(a_i, a_f, d0_e)
        ev_g = self._roller_eval(a_i, a_f, guess, d0_e)
        cache = self._cache
        if cache is None or cache[1].shape != shape or cache[0].shape != q_rel.shape:
            return guess, ev_g
        q_c, x_c, sens = cache
        warm = x_c if sens is None else x_c - np.einsum("czda,cd->cza", sens, q_rel - q_c)
        ev_w = self._roller_eval(a_i, a_f, warm, d0_e)
        use = np.isfinite(ev_w[0]) & np.isfinite(warm).all(-1) & (ev_w[0] <= ev_g[0])
        return _pick(use, warm, guess), tuple(_pick(use, w, g) for w, g in zip(ev_w, ev_g, strict=True))

    def _solve_rollers(self, q, offset=None):
        """Roller displacements X (C, Z, 2) minimising Φ; damped Newton over all rollers at once.

        Bounded: at most :data:`ROLLER_MAX_ITER` Newton steps, each with at most
        :data:`ROLLER_MAX_HALVINGS` step halvings. A roller whose line search finds no decrease of Φ
        although its force balance is within :data:`ROLLER_STALL_RTOL` is at round-off and stops.
        Rollers with every contact open (zero load, no centrifugal force) have ∂Φ/∂X = 0 and keep
        their start; their loads, energy and stiffness are then exactly zero. The result is finite
        for any finite q: when the cap is reached the forces and energy of the last iterate are
        returned (counted in :attr:`inner_unconverged`).
        """
        q = np.asarray(q, dtype=float)
        q_rel = relative_displacement(q, offset)
        a_i, a_f, d0_e = self._ring_parts(q, offset)
        shape = (q.shape[0], self.row.n_elements, 2)
        xr, ev = self._start(q_rel, a_i, a_f, d0_e, shape)
        bb_i, bb_e, bb_f = (
            np.outer(self.b_i, self.b_i),
            np.outer(self.b_e, self.b_e),
            np.outer(self.b_f, self.b_f),
        )
        step_cap = ROLLER_STEP_CAP * self.row.element_diameter
        done = np.zeros(shape[:2], bool)
        # Round-off of the approaches: they are differences of ring and roller displacements.
        ring_size = np.abs(a_i).max(-1) + np.abs(a_f) + np.abs(d0_e).max(-1)
        used = 0
        for _ in range(ROLLER_MAX_ITER):
            phi, grad, scale, k_i, k_e, k_f = ev
            gnorm = np.sqrt((grad**2).sum(-1))
            done |= gnorm <= ROLLER_RTOL * scale + self.force_floor
            if done.all():
                break
            used += 1
            h = k_i[..., None, None] * bb_i + k_e[..., None, None] * bb_e + k_f[..., None, None] * bb_f
            # Levenberg term: negligible against closed contacts; with all contacts open it turns the
            # step into a capped move along −∂Φ/∂X (centrifugal force), and the floor keeps the 2×2
            # system regular when nothing acts on the roller at all.
            mu = 1e-12 * (h[..., 0, 0] + h[..., 1, 1]) + 1e-6 * gnorm / step_cap + self.stiffness_floor
            step = -_solve2(h + mu[..., None, None] * np.eye(2), grad)
            big = np.sqrt((step**2).sum(-1))
            step *= np.minimum(1.0, step_cap / np.maximum(big, 1e-300))[..., None]
            # A Newton step below the resolution of the approaches cannot improve the balance: the
            # remaining imbalance is round-off (lightly loaded rollers, a rib barely touching).
            x_noise = ROLLER_NOISE_EPS * (ring_size + np.abs(xr).max(-1))
            done |= big <= x_noise
            if done.all():
                break
            step[done] = 0.0
            slope = (grad * step).sum(-1)
            t = np.ones(shape[:2])
            pending = ~done
            new_x, new_ev = xr, ev
            for _ls in range(ROLLER_MAX_HALVINGS):
                trial = xr + t[..., None] * step
                ev_t = self._roller_eval(a_i, a_f, trial, d0_e)
                g_t = np.sqrt((ev_t[1] ** 2).sum(-1))
                ok = pending & (
                    (ev_t[0] <= phi + 1e-4 * t * slope + 1e-14 * np.abs(phi)) | (g_t <= 0.5 * gnorm)
                )
                new_x = _pick(ok, trial, new_x)
                new_ev = tuple(_pick(ok, a, b) for a, b in zip(ev_t, new_ev, strict=True))
                pending &= ~ok
                if not pending.any():
                    break
                t = np.where(pending, 0.5 * t, t)
            if pending.any():
                # No decrease along a descent direction: round-off where the balance is already
                # close (stop there); elsewhere take the shortest trial and go on.
                done |= pending & (gnorm <= ROLLER_STALL_RTOL * scale)
                late = pending & ~done
                new_x = _pick(late, trial, new_x)
                new_ev = tuple(_pick(late, a, b) for a, b in zip(ev_t, new_ev, strict=True))
            xr, ev = new_x, new_ev
        else:
            phi, grad, scale = ev[:3]
            done |= np.sqrt((grad**2).sum(-1)) <= ROLLER_RTOL * scale + self.force_floor
        self.inner_iterations = used
        self.inner_stats.record(used, int(np.count_nonzero(~done)))
        self._cache = (q_rel, xr, None)
        return xr, a_i, a_f, d0_e

    def _guess(self, a_i, a_f, d0_e):
        """Closed-form start X: equal cone and cup approaches (most compressed slices), rib touching.

        Where those approaches are negative (the raceways open: zero load, ring pulled away) the rib
        approach is set to the same negative value instead, so the roller starts clear of every
        contact with exactly zero load rather than a rib touching at round-off.
        """
        geo = self.geo
        lead_i, lead_e = a_i.max(-1), d0_e.max(-1) * np.ones_like(a_f)
        m = np.stack([geo.n_i + geo.n_e, geo.n_f])  # (n_i + n_e)·X = a_i − d0_e ; n_f·X = a_f
        x = np.linalg.solve(m, np.stack([lead_i - lead_e, a_f], axis=-1)[..., None])[..., 0]
        gap = lead_i - x @ geo.n_i
        m_open = np.stack([geo.n_i + geo.n_e, geo.n_f - geo.n_i])  # … ; δ_f = δ_i
        x_open = np.linalg.solve(m_open, np.stack([lead_i - lead_e, a_f - lead_i], axis=-1)[..., None])[
            ..., 0
        ]
        return np.where((gap < 0.0)[..., None], x_open, x)

    # -- condensation ----------------------------------------------------------------------------
    def _condense(self, ki, ke, kf, sensitivity=False):
        """Σ_rollers of the Schur complement K_qq − K_qX K_XX⁻¹ K_Xq (C, 5, 5) for slice stiffnesses.

        With ``sensitivity`` also returns K_XX⁻¹ K_Xq per roller (C, Z, 5, 2): dX/dq = −its transpose.
        """
        c = ki.shape[0]
        z_el, n_s = self.row.n_elements, self.row.n_slices
        kqq = (ki.reshape(c, z_el * n_s) @ self.GG_i + kf @ self.GG_f).reshape(c, 5, 5)
        v_i = np.einsum("czk,zkd->czd", ki, self.g_i)  # Σ_k k g (C, Z, 5)
        v_f = kf[..., None] * self.g_f
        kqx = v_i[..., :, None] * self.b_i + v_f[..., :, None] * self.b_f  # (C, Z, 5, 2)
        bi, be, bf = self.b_i, self.b_e, self.b_f
        kxx = (
            ki.sum(-1)[..., None, None] * np.outer(bi, bi)
            + ke.sum(-1)[..., None, None] * np.outer(be, be)
            + kf[..., None, None] * np.outer(bf, bf)
        )
        # A roller with every contact open has K_XX = 0 and K_Xq = 0: the floor keeps the solve
        # regular and its (zero) contribution exact.
        tr = kxx[..., 0, 0] + kxx[..., 1, 1]
        kxx = kxx + (1e-13 * tr + self.stiffness_floor)[..., None, None] * np.eye(2)
        sol = _solve2(kxx[:, :, None], kqx)  # K_XX⁻¹ K_Xq rows: (C, Z, 5, 2)
        schur = kqq - np.einsum("czia,czja->cij", kqx, sol)
        return (schur, sol) if sensitivity else schur

    def response(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowResponse:
        """Condensed generalised force, stiffness and energy for displacements q (C, 5)."""
        q = np.asarray(q, dtype=float)
        xr, a_i, a_f, d0_e = self._solve_rollers(q, offset)
        d_i, d_e, d_f = self._approaches(a_i, a_f, xr, d0_e)
        qi, ki, ei = self._line_law(d_i)
        _, ke, ee = self._line_law(d_e)
        qf, kf, ef = self._point_law(d_f)
        c = q.shape[0]
        force = -(qi.reshape(c, -1) @ self.G_flat_i + qf @ self.g_f)
        schur, sens = self._condense(ki, ke, kf, sensitivity=True)
        # Keep the roller sensitivity: the next call (a Newton or line-search trial nearby) starts
        # from the first-order prediction of its roller positions. Built from this call's own values
        # and stored in one assignment, so a concurrent call on the same kernel (a user's threads)
        # can only replace the warm start, never mix two calls' arrays.
        self._cache = (relative_displacement(q, offset), xr, sens)
        energy = ei.sum((-1, -2)) + ee.sum((-1, -2)) + ef.sum(-1) - self.f_c[:, 0] * xr[..., 0].sum(-1)
        return RowResponse(force, -schur, energy)

    def warm_start(self, q: np.ndarray, x: np.ndarray | None, offset: RacewayOffset | None = None) -> None:
        """Start the next roller sub-problem at q (C, 5) from the rollers' positions x (C, Z, 2).

        The compiled core solves the rollers inside its own Newton and leaves their positions
        (``QuasiStaticResult._roller_x``); the per-roller outputs must start there. From the
        closed-form guess, a lightly loaded roller may need more than :data:`ROLLER_MAX_ITER` steps
        and its reported loads would then not balance the ring (a 32008 under 0.49 N reported 7.5 N).
        NaN entries of x, or a shape that does not match, fall back to the guess (:meth:`_start`).
        """
        if x is None:
            return
        x = np.asarray(x, dtype=float)
        q = np.asarray(q, dtype=float)
        if x.shape != (q.shape[0], self.row.n_elements, 2):
            return
        # One assignment, as in :meth:`response`: a concurrent call replaces it whole or not at all.
        self._cache = (relative_displacement(q, offset), x, None)

    def roller_state(self, q: np.ndarray, offset: RacewayOffset | None = None) -> dict:
        """Per-roller contact loads and approaches at displacements q (C, 5) (SI arrays)."""
        q = np.asarray(q, dtype=float)
        xr, a_i, a_f, d0_e = self._solve_rollers(q, offset)
        d_i, d_e, d_f = self._approaches(a_i, a_f, xr, d0_e)
        qi = self._line_law(d_i)[0]
        qe = self._line_law(d_e)[0]
        qf = self._point_law(d_f)[0]
        return dict(
            roller_displacement=xr,
            slice_load_inner=qi,
            slice_load_outer=qe,
            load_inner=qi.sum(-1),
            load_outer=qe.sum(-1),
            load_flange=qf,
            deflection_inner=d_i,
            deflection_outer=d_e,
            deflection_flange=d_f,
        )

    def state(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowState:
        """Per-roller results: ``load`` is the cup (outer raceway) contact force Q_e (seed 001 Fig. 4)."""
        from bearingkit.physics.contact import line

        row, geo = self.row, self.geo
        st = self.roller_state(q, offset)
        width = geo.length / row.n_slices
        extras = dict(st)
        p_max = np.zeros_like(st["load_outer"])
        for side, rx in (("inner", geo.radius_x_inner), ("outer", geo.radius_x_outer)):
            contact = line.line_contact(st[f"slice_load_{side}"], width, rx, self.e_reduced)
            extras[f"slice_pressure_{side}"] = contact.max_pressure
            extras[f"half_width_{side}"] = contact.half_width
            p_max = np.maximum(p_max, contact.max_pressure.max(-1))
        extras["slice_position"] = np.broadcast_to(self.x, st["slice_load_outer"].shape)
        load = st["load_outer"]
        psi = np.broadcast_to(self.psi, load.shape)
        alpha = np.full(load.shape, row.direction * float(row.contact_angle_outer))
        return RowState(
            "tapered",
            row.name,
            psi,
            load,
            np.maximum(st["deflection_outer"], 0.0).max(-1),
            alpha,
            p_max,
            st["slice_load_outer"],
            extras,
        )


def _pick(mask, a, b):
    """``a`` where ``mask`` (per roller, (C, Z)), ``b`` elsewhere; trailing axes broadcast."""
    return np.where(mask.reshape(mask.shape + (1,) * (np.ndim(a) - mask.ndim)), a, b)


def _solve2(h, b):
    """Solve 2×2 systems h x = b, h (..., 2, 2), b (..., 2) or (..., k, 2) rows (Cramer's rule).

    The callers pass symmetric positive definite systems; a zero or non-finite determinant (which a
    regularised system cannot have) gives x = 0 rather than 0/0.
    """
    a11, a12, a21, a22 = h[..., 0, 0], h[..., 0, 1], h[..., 1, 0], h[..., 1, 1]
    det = a11 * a22 - a12 * a21
    regular = np.isfinite(det) & (det > 0.0)
    det = np.where(regular, det, np.inf)
    if b.ndim == h.ndim - 1:
        x0 = (a22 * b[..., 0] - a12 * b[..., 1]) / det
        x1 = (-a21 * b[..., 0] + a11 * b[..., 1]) / det
    else:
        x0 = (a22[..., None] * b[..., 0] - a12[..., None] * b[..., 1]) / det[..., None]
        x1 = (-a21[..., None] * b[..., 0] + a11[..., None] * b[..., 1]) / det[..., None]
    return np.stack([x0, x1], axis=-1)
