"""High-speed ball rows: each ball's own equilibrium under centrifugal force and gyroscopic moment.

SI units. At speed the inner and outer contacts of a ball no longer carry the same load along one
line: the centrifugal force F_c presses the ball outward and the gyroscopic moment M_g has to be
reacted by friction, so the ball centre moves off the line joining the groove curvature centres
and the inner and outer contact angles part (Jones 1960; Harris & Kotzalas 2007, Advanced
Concepts ch. 3). Each ball gets two unknowns, the position X = (X_r, X_a) of its centre relative to
the outer groove centre in its radial–axial plane, solved per ball and condensed into the ring's
5-DOF force, stiffness and energy (as the tapered rollers' sub-problem in
:mod:`bearingkit.rows.tapered.kernel`).

Per ball, with the inner groove centre at s (from :class:`~bearingkit.rows.ball.row.BallKernel`: the
unloaded separation s₀ plus the ring displacement), r′_k = (f_k − ½)D, and K_k the Hertz constant
of ONE contact at the free contact angle:

    outer  d_o = |X|,      n_o = X/d_o,          δ_o = d_o − r′_o,  Q_o = K_o ⟨δ_o⟩^1.5
    inner  d_i = |s − X|,  n_i = (s − X)/d_i,    δ_i = d_i − r′_i,  Q_i = K_i ⟨δ_i⟩^1.5
    α_k = atan2(n_k,a, n_k,r)

and the ball's balance (t_k = (−n_k,a, n_k,r), the in-plane tangent)

    −Q_o n_o + Q_i n_i + F_c r̂ + (λ_o M_g/D) t_o − (λ_i M_g/D) t_i = 0

with F_c = ½ m d_m ω_m², M_g = J ω_R ω_m sin β from the raceway-control kinematics at the current
angles (:mod:`bearingkit.physics.dynamics`), λ = (0, 2) for outer- and (2, 0) for inner-raceway
control. The inner ring receives −Q_i n_i + (λ_i M_g/D) t_i at the inner groove centre; the moment of
that friction force about the groove centre (Harris's λ_i f_i M_g term, zero under outer control) is
neglected. At ω = 0 the balance puts X on the line of centres with Q_i = Q_o, which is the
zero-speed row exactly (tested to 1e-12).

The ball's equations are solved by a bounded, damped Newton iteration over all balls at once;
∂F_c/∂α and ∂M_g/∂α come from the complex step, the Hertz parts are analytic. The condensed
stiffness K = ∂f/∂s − ∂f/∂X (∂R/∂X)⁻¹ ∂R/∂s is exact but not symmetric (the gyroscopic friction is
a follower force). The energy returned is that of the conservative part, U_i + U_o − F_c X_r, which
the solver uses only for its line search.

K_i and K_o are evaluated at the free contact angle, as the zero-speed row does (their change with
the operating angle is of second order, ISO/TS 16281 keeps it constant); the ellipse and pressure of
each contact use its own operating angle. The ball orbits on the pitch circle (F_c uses d_m/2).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.physics.dynamics import ball_kinematics, centrifugal
from bearingkit.rows.ball.row import POINT_EXPONENT, BallKernel, BallRow
from bearingkit.rows.base import InnerStats, RacewayOffset, RowResponse, RowState

#: Ball sub-problem: Newton iterations, relative force tolerance (of the ball's summed forces),
#: step halvings, and the largest step as a fraction of the ball diameter.
BALL_MAX_ITER = 50
BALL_RTOL = 1e-12
BALL_MAX_HALVINGS = 20
BALL_STEP_CAP = 0.02
#: Complex-step size for ∂(F_c, M_g)/∂α [rad] (exact to round-off for analytic functions).
COMPLEX_STEP = 1e-30
#: Default ball density when none is given [kg/m³]: GCr15 / AISI 52100 (bearingkit.materials).
STEEL_DENSITY = 7810.0
#: Largest contact angle magnitude the ball kinematics are evaluated at [rad] (just below 90°). A
#: contact past it is beyond the model (the ball would ride over the raceway's crown: at 90° the
#: contact normal is axial and the raceway geometry of the row ends); the kinematics hold their
#: value there so that the solver stays finite, and :func:`beyond_model` flags the case.
ANGLE_LIMIT = np.radians(89.5)
#: Free contact angle above which a row is a thrust row [rad]: its contacts sit near 90° by design; it is
#: beyond the model when a loaded contact turns more than :data:`THRUST_SWING` from the free angle.
THRUST_ANGLE = np.radians(60.0)
THRUST_SWING = np.radians(45.0)


def _rot(n):
    """In-plane tangent t = (−n_a, n_r) of unit vectors n (..., 2)."""
    return np.stack([-n[..., 1], n[..., 0]], axis=-1)


def _outer(a, b):
    return a[..., :, None] * b[..., None, :]


class BallSpeedKernel(BallKernel):
    """Kernel of a :class:`~bearingkit.rows.ball.row.BallRow` at speed (module docstring).

    Parameters
    ----------
    row : BallRow
    speed_inner, speed_outer : float or array (C,) [rad/s]
        Ring speeds about the bearing axis, per load case.
    density : float [kg/m³]
        Ball density (default steel, :data:`STEEL_DENSITY`).
    raceway_control : {"outer", "inner"}
        :data:`bearingkit.physics.dynamics.ball_kinematics.RACEWAY_CONTROLS`.
    """

    _case_arrays = (
        *BallKernel._case_arrays,
        "w_i",
        "w_o",
        "d",
        "dm",
        "r_i",
        "r_o",
        "k_i",
        "k_o",
        "mass",
        "inertia",
    )

    def __init__(
        self, row: BallRow, speed_inner, speed_outer=0.0, density=STEEL_DENSITY, raceway_control="outer"
    ):
        from bearingkit.physics.contact import hertz

        super().__init__(row)
        checks.finite("speed_inner", speed_inner, "rad/s")
        checks.finite("speed_outer", speed_outer, "rad/s")
        checks.positive("density", density, "kg/m^3")
        checks.one_of("raceway_control", raceway_control, ball_kinematics.RACEWAY_CONTROLS)
        col = lambda v: np.asarray(v, dtype=float).reshape(-1, 1)  # noqa: E731
        self.w_i, self.w_o = col(speed_inner), col(speed_outer)
        n = max(len(self.w_i), len(self.w_o))
        self.w_i = np.broadcast_to(self.w_i, (n, 1)).copy()
        self.w_o = np.broadcast_to(self.w_o, (n, 1)).copy()
        self.control = raceway_control
        self.lam_i, self.lam_o = ball_kinematics.GYROSCOPIC_SHARE[raceway_control]
        d, dm = col(row.element_diameter), col(row.pitch_diameter)
        self.d, self.dm = d, dm
        fi, fo = col(row.conformity_inner), col(row.conformity_outer)
        self.r_i, self.r_o = (fi - 0.5) * d, (fo - 0.5) * d
        alpha0 = col(row.contact_angle)
        k = {}
        for side, f in (("inner", fi), ("outer", fo)):
            sr, fr = hertz.ball_raceway_curvature(d, dm, np.abs(alpha0), f * d, side)
            k[side] = hertz.point_stiffness(sr, fr, self.e_reduced, method=row.hertz_method)
        self.k_i, self.k_o = k["inner"], k["outer"]
        self.mass = centrifugal.ball_mass(d, density)
        self.inertia = centrifugal.ball_inertia(d, density)
        self.density = float(density)
        # Tolerance floor of a ball's balance [N]: BALL_RTOL of a contact's load at 1e-4 D approach.
        # Angular rows: the kinematics are held below 90° (past it the ball rides over the raceway);
        # thrust rows (|α₀| > 60°) turn about 90° by design and keep their angles.
        self.angle_cap = ANGLE_LIMIT if float(np.max(np.abs(row.contact_angle))) <= THRUST_ANGLE else np.pi
        self.force_floor = BALL_RTOL * float(np.max(self.k_o * (1e-4 * d) ** POINT_EXPONENT))
        # Regularisation of a ball's 2×2 system [N/m]: 1e-12 of a contact's stiffness at 1e-4 D, far
        # below any closed contact, never zero (a ball with both contacts open at zero speed).
        self.stiffness_floor = 1e-12 * float(np.max(1.5 * self.k_o * np.sqrt(1e-4 * d)))
        self._cache = None
        self.inner_stats = InnerStats()

    def take(self, cases):
        """A copy restricted to ``cases``; the warm start follows them, the statistics stay shared."""
        out = super().take(cases)
        cache = self._cache
        if cache is not None and np.shape(cases) != () and cache[1].shape[0] > np.max(cases, initial=-1):
            out._cache = tuple(a[cases] for a in cache)
        else:
            out._cache = None
        return out

    # -- one ball's forces -----------------------------------------------------------------------
    def _speed_terms(self, alpha_i, alpha_o):
        """F_c and M_g (C, Z) at the contact angles, with their derivatives by the complex step."""
        h = COMPLEX_STEP
        # Hold the kinematics at the limit angle beyond it (finite, zero derivative there).
        cap = self.angle_cap
        in_i, in_o = np.abs(alpha_i) < cap, np.abs(alpha_o) < cap
        alpha_i = np.where(in_i, alpha_i, np.sign(alpha_i) * cap)
        alpha_o = np.where(in_o, alpha_o, np.sign(alpha_o) * cap)

        def terms(a_i, a_o):
            sp = ball_kinematics.ball_speeds(self.w_i, self.w_o, a_i, a_o, self.d, self.dm, self.control)
            f_c = self.mass * (self.dm / 2.0) * sp.cage_speed**2
            m_g = centrifugal.gyroscopic_moment(self.inertia, sp.spin_speed, sp.cage_speed, sp.attitude_angle)
            return f_c, m_g

        f_c, m_g = terms(alpha_i, alpha_o)
        fci, mgi = terms(alpha_i + 1j * h, alpha_o)
        fco, mgo = terms(alpha_i, alpha_o + 1j * h)
        return (
            np.real(f_c),
            np.real(m_g),
            np.imag(fci) / h * in_i,
            np.imag(fco) / h * in_o,
            np.imag(mgi) / h * in_i,
            np.imag(mgo) / h * in_o,
        )

    def _ball_eval(self, x, s):
        """Residual R (C,Z,2) of each ball, ∂R/∂X, ∂R/∂s, ring force f, ∂f/∂X, ∂f/∂s and details."""
        v_o, v_i = x, s - x
        d_o = np.sqrt((v_o**2).sum(-1))
        d_i = np.sqrt((v_i**2).sum(-1))
        n_o, n_i = v_o / d_o[..., None], v_i / d_i[..., None]
        t_o, t_i = _rot(n_o), _rot(n_i)
        delta_o = np.maximum(d_o - self.r_o, 0.0)
        delta_i = np.maximum(d_i - self.r_i, 0.0)
        # A one-sided groove has no inner contact on its relieved side (as the zero-speed row).
        delta_i = np.where(self.side * n_i[..., 1] < 0.0, 0.0, delta_i)
        root_o, root_i = np.sqrt(delta_o), np.sqrt(delta_i)
        q_o, q_i = self.k_o * delta_o * root_o, self.k_i * delta_i * root_i
        dq_o, dq_i = 1.5 * self.k_o * root_o, 1.5 * self.k_i * root_i
        alpha_o = np.arctan2(n_o[..., 1], n_o[..., 0])
        alpha_i = np.arctan2(n_i[..., 1], n_i[..., 0])
        f_c, m_g, dfc_i, dfc_o, dmg_i, dmg_o = self._speed_terms(alpha_i, alpha_o)
        dd = self.d  # (C|1, 1)
        g_o, g_i = self.lam_o / dd, self.lam_i / dd  # friction force per unit M_g at each contact
        # d(Q n)/dv = Q' n nᵀ + (Q/d) t tᵀ for v the centre-to-centre vector of that contact.
        k_ov = dq_o[..., None, None] * _outer(n_o, n_o) + (q_o / d_o)[..., None, None] * _outer(t_o, t_o)
        k_iv = dq_i[..., None, None] * _outer(n_i, n_i) + (q_i / d_i)[..., None, None] * _outer(t_i, t_i)
        # Angles: dα_o/dX = t_o/d_o; dα_i/dX = −t_i/d_i, dα_i/ds = +t_i/d_i.
        da_o = t_o / d_o[..., None]
        da_i = t_i / d_i[..., None]
        dfc_dx = dfc_o[..., None] * da_o - dfc_i[..., None] * da_i
        dfc_ds = dfc_i[..., None] * da_i
        dmg_dx = dmg_o[..., None] * da_o - dmg_i[..., None] * da_i
        dmg_ds = dmg_i[..., None] * da_i
        e_r = np.array([1.0, 0.0])
        # Tangent derivatives: dt/dv = −n tᵀ/d; v_o = X, v_i = s − X.
        dto_dx = -_outer(n_o, t_o) / d_o[..., None, None]
        dti_dv = -_outer(n_i, t_i) / d_i[..., None, None]
        m = m_g[..., None, None]
        resid = (
            -q_o[..., None] * n_o
            + q_i[..., None] * n_i
            + f_c[..., None] * e_r
            + (g_o * m_g)[..., None] * t_o
            - (g_i * m_g)[..., None] * t_i
        )
        r_x = (
            -k_ov
            - k_iv
            + e_r[:, None] * dfc_dx[..., None, :]
            + g_o[..., None, None] * (_outer(t_o, dmg_dx) + m * dto_dx)
            - g_i[..., None, None] * (_outer(t_i, dmg_dx) - m * dti_dv)
        )
        r_s = (
            k_iv
            + e_r[:, None] * dfc_ds[..., None, :]
            + g_o[..., None, None] * _outer(t_o, dmg_ds)
            - g_i[..., None, None] * (_outer(t_i, dmg_ds) + m * dti_dv)
        )
        # Force on the inner ring (local radial, axial): −Q_i n_i + (λ_i M_g/D) t_i.
        f = -q_i[..., None] * n_i + (g_i * m_g)[..., None] * t_i
        f_x = k_iv + g_i[..., None, None] * (_outer(t_i, dmg_dx) - m * dti_dv)
        f_s = -k_iv + g_i[..., None, None] * (_outer(t_i, dmg_ds) + m * dti_dv)
        scale = q_i + q_o + np.abs(f_c) + np.abs(g_o * m_g) + np.abs(g_i * m_g)
        # Potential of the conservative part (merit of the line search): U_o + U_i − F_c X_r.
        phi = (self.k_o * delta_o**2 * root_o + self.k_i * delta_i**2 * root_i) / 2.5 - f_c * x[..., 0]
        return dict(
            phi=phi,
            resid=resid,
            r_x=r_x,
            r_s=r_s,
            f=f,
            f_x=f_x,
            f_s=f_s,
            scale=scale,
            q_i=q_i,
            q_o=q_o,
            delta_i=delta_i,
            delta_o=delta_o,
            alpha_i=alpha_i,
            alpha_o=alpha_o,
            f_c=f_c,
            m_g=m_g,
        )

    # -- the ball sub-problem ----------------------------------------------------------------------
    def _guess(self, s, a):
        """Start: X on the line of centres, the approach split as two equal loads in series, and at
        least the outer approach that carries F_c at the cage speed of the free contact angle."""
        n = s / a[..., None]
        delta = np.maximum(a - self.a0, 0.0)
        ki, ko = self.k_i ** (-2.0 / 3.0), self.k_o ** (-2.0 / 3.0)
        share_o = ko / (ki + ko)  # δ_o/δ at equal loads
        alpha0 = np.arctan2(n[..., 1], n[..., 0])
        sp = ball_kinematics.ball_speeds(self.w_i, self.w_o, alpha0, alpha0, self.d, self.dm, self.control)
        f_c = self.mass * (self.dm / 2.0) * sp.cage_speed**2
        delta_fc = (f_c / self.k_o) ** (2.0 / 3.0)
        delta_o = np.maximum(delta * share_o, delta_fc * np.abs(n[..., 0]))
        return (self.r_o + delta_o)[..., None] * n

    def _solve_balls(self, s, a):
        """Ball-centre positions X (C, Z, 2) and their evaluation; bounded damped Newton.

        A thrust row's angles may swing to where the kinematics divide by zero (an iterate far from
        any equilibrium, e.g. a milli-newton load at speed): its values are then NaN, which the line
        searches reject and the solver reports as not converged, without numpy's warnings."""
        with np.errstate(divide="ignore", invalid="ignore"):
            return self._solve_balls_raw(s, a)

    def _solve_balls_raw(self, s, a):
        shape = s.shape
        guess = self._guess(s, a)
        x = guess
        cache = self._cache
        if cache is not None and cache[1].shape == shape:
            s_c, x_c, sens = cache
            warm = x_c + np.einsum("czab,czb->cza", sens, s - s_c)
            ev_w = self._ball_eval(warm, s)
            ev_g = self._ball_eval(guess, s)
            nw = np.sqrt((ev_w["resid"] ** 2).sum(-1))
            ng = np.sqrt((ev_g["resid"] ** 2).sum(-1))
            use = np.isfinite(nw) & (nw <= ng)
            x = np.where(use[..., None], warm, guess)
        ev = self._ball_eval(x, s)
        cap = BALL_STEP_CAP * self.d[..., None]
        done = np.zeros(shape[:-1], bool)
        # A ball whose line search found no decrease keeps its position; its next step (a function of
        # that ball's position alone) would be the same, and fail the same way: it is stalled, and no
        # further iteration is spent on it (they used to run to BALL_MAX_ITER × BALL_MAX_HALVINGS
        # evaluations per call under milli-newton loads at speed, ~1 s per outer evaluation).
        stalled = np.zeros(shape[:-1], bool)
        used = 0
        for _ in range(BALL_MAX_ITER):
            norm = np.sqrt((ev["resid"] ** 2).sum(-1))
            done |= norm <= BALL_RTOL * ev["scale"] + self.force_floor
            if (done | stalled).all():
                break
            used += 1
            jac = ev["r_x"]
            # Levenberg term: the ball is held by its contacts (∂R/∂X negative definite); a ball with
            # both contacts open has ∂R/∂X = 0 and moves along its residual (F_c) by a capped step.
            tr = np.abs(jac[..., 0, 0]) + np.abs(jac[..., 1, 1])
            mu = 1e-12 * tr + 1e-6 * norm / cap[..., 0] + 1e-300
            mu = mu + self.stiffness_floor
            step = -np.linalg.solve(jac - mu[..., None, None] * np.eye(2), ev["resid"][..., None])[..., 0]
            big = np.sqrt((step**2).sum(-1))
            step *= np.minimum(1.0, cap[..., 0] / np.maximum(big, 1e-300))[..., None]
            step[done | stalled] = 0.0
            slope = -(ev["resid"] * step).sum(-1)  # dΦ/dt of the conservative part along the step
            t = np.ones(shape[:-1])
            pending = ~done & ~stalled
            new_x, new_ev = x, ev
            for _ls in range(BALL_MAX_HALVINGS):
                trial = x + t[..., None] * step
                ev_t = self._ball_eval(trial, s)
                n_t = np.sqrt((ev_t["resid"] ** 2).sum(-1))
                # Either the potential decreases (Armijo; it ranks contacts opening and closing,
                # where the residual norm jumps) or the residual does (the gyroscopic part has no
                # potential).
                armijo = ev_t["phi"] <= ev["phi"] + 1e-4 * t * np.minimum(slope, 0.0) + 1e-14 * np.abs(
                    ev["phi"]
                )
                ok = pending & ((armijo & (slope < 0.0)) | (n_t <= (1.0 - 1e-4 * t) * norm))
                new_x = np.where(ok[..., None], trial, new_x)
                new_ev = _merge(new_ev, ev_t, ok)
                pending &= ~ok
                if not pending.any():
                    break
                t = np.where(pending, 0.5 * t, t)
            if pending.any():  # no decrease: round-off where the balance is already tight
                done |= pending & (norm <= 1e-9 * ev["scale"] + self.force_floor)
                stalled |= pending & ~done
            x, ev = new_x, new_ev
        else:
            norm = np.sqrt((ev["resid"] ** 2).sum(-1))
            done |= norm <= BALL_RTOL * ev["scale"] + self.force_floor
        self.inner_iterations = used
        self.inner_stats.record(used, int(np.count_nonzero(~done)))
        return x, ev, done

    def _local(self, q, offset):
        _, s, a = self._geometry(q, offset)
        return s, a

    def response(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowResponse:
        """Condensed generalised force, stiffness and energy for displacements q (C, 5)."""
        q = np.asarray(q, dtype=float)
        s, a = self._local(q, offset)
        x, ev, _ = self._solve_balls(s, a)
        # dX/ds = −(∂R/∂X)⁻¹ ∂R/∂s; df/ds = ∂f/∂s + ∂f/∂X dX/ds.
        # The floor keeps a ball with both contacts open (zero speed) regular; it is left out where
        # a contact holds the ball, so the condensation is exact there.
        tr = -(ev["r_x"][..., 0, 0] + ev["r_x"][..., 1, 1])
        floor = np.where(tr > 1e6 * self.stiffness_floor, 0.0, self.stiffness_floor)
        sens = -np.linalg.solve(ev["r_x"] - floor[..., None, None] * np.eye(2), ev["r_s"])
        k_local = ev["f_s"] + ev["f_x"] @ sens
        self._cache = (s, x, sens)
        c = q.shape[0]
        if self.Bf.shape[0] == 1:
            force = ev["f"].reshape(c, -1) @ self.Bf[0]
            jac = (k_local.reshape(c, -1) @ self.BB[0]).reshape(c, 5, 5)
        else:
            force = np.einsum("czi,czij->cj", ev["f"], self.B)
            jac = np.einsum("cm,cmk->ck", k_local.reshape(c, -1), self.BB).reshape(c, 5, 5)
        energy = (
            self.k_o * ev["delta_o"] ** 2.5 / 2.5
            + self.k_i * ev["delta_i"] ** 2.5 / 2.5
            - ev["f_c"] * x[..., 0]
        ).sum(-1)
        return RowResponse(force, jac, energy)

    def raceway_loads(self, q: np.ndarray, offset: RacewayOffset | None = None) -> np.ndarray:
        """Loads (F_r, F_z, M_t) (C, Z, 3) each ball's OUTER contact puts on the outer raceway: Q_o along
        its contact angle α_o, and its moment about the ball centre through the outer groove centre's arm
        (the outer contact carries the centrifugal force too)."""
        st = self.ball_state(q, offset)
        load, alpha = st["load_outer"], st["contact_angle_outer"]
        n_r, n_z = np.cos(alpha), np.sin(alpha)
        arm_r, arm_z = self.outer_arm[..., 0], self.outer_arm[..., 1]
        moment = load * (n_z * arm_r - n_r * arm_z)
        return np.stack([load * n_r, load * n_z, moment], axis=-1)

    def ball_state(self, q: np.ndarray, offset: RacewayOffset | None = None) -> dict:
        """Per-ball loads, angles, speeds and inertia forces at displacements q (C, 5), SI arrays."""
        q = np.asarray(q, dtype=float)
        s, a = self._local(q, offset)
        x, ev, done = self._solve_balls(s, a)
        clip = lambda a: np.clip(a, -self.angle_cap, self.angle_cap)  # noqa: E731
        sp = ball_kinematics.ball_speeds(
            self.w_i, self.w_o, clip(ev["alpha_i"]), clip(ev["alpha_o"]), self.d, self.dm, self.control
        )
        # An open contact (a ball off the inner ring at speed, or touching neither raceway at rest) has
        # no contact angle of its own: report the line of the groove centres, as the zero-speed row does.
        line = np.arctan2(s[..., 1], s[..., 0])
        ev = dict(
            ev,
            alpha_i=np.where(ev["q_i"] == 0.0, line, ev["alpha_i"]),
            alpha_o=np.where(ev["q_o"] == 0.0, line, ev["alpha_o"]),
        )
        shape = ev["q_i"].shape
        with np.errstate(divide="ignore", invalid="ignore"):
            sr_i = np.where(sp.roll_inner != 0, sp.spin_inner / sp.roll_inner, 0.0)
            sr_o = np.where(sp.roll_outer != 0, sp.spin_outer / sp.roll_outer, 0.0)
        b = lambda v: np.broadcast_to(v, shape).copy()  # noqa: E731
        return dict(
            ball_position=x,
            load_inner=ev["q_i"],
            load_outer=ev["q_o"],
            deflection_inner=ev["delta_i"],
            deflection_outer=ev["delta_o"],
            contact_angle_inner=ev["alpha_i"],
            contact_angle_outer=ev["alpha_o"],
            centrifugal_force=b(ev["f_c"]),
            gyroscopic_moment=b(ev["m_g"]),
            cage_speed=b(sp.cage_speed),
            ball_spin_speed=b(sp.spin_speed),
            attitude_angle=b(sp.attitude_angle),
            spin_to_roll_inner=b(sr_i),
            spin_to_roll_outer=b(sr_o),
            ball_converged=done,
        )

    def state(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowState:
        """Per-ball results: ``load`` and ``contact_angle`` are the inner contact's; extras hold both
        contacts' loads, angles, ellipses and pressures and the ball's speeds and inertia forces."""
        from bearingkit.physics.contact import hertz

        row = self.row
        st = self.ball_state(q, offset)
        extras = dict(st)
        p_max = np.zeros_like(st["load_inner"])
        for side, f in (("inner", row.conformity_inner), ("outer", row.conformity_outer)):
            f = np.asarray(f, dtype=float).reshape(-1, 1)
            alpha = st[f"contact_angle_{side}"]
            alpha_geo = np.arccos(np.clip(np.abs(np.cos(alpha)), 0.0, 1.0))
            sr, fr = hertz.ball_raceway_curvature(self.d, self.dm, alpha_geo, f * self.d, side)
            contact = hertz.point_contact(st[f"load_{side}"], sr, fr, self.e_reduced, method=row.hertz_method)
            extras[f"semi_major_{side}"] = contact.semi_major
            extras[f"semi_minor_{side}"] = contact.semi_minor
            extras[f"max_pressure_{side}"] = contact.max_pressure
            p_max = np.maximum(p_max, contact.max_pressure)
        load = st["load_inner"]
        psi = np.broadcast_to(self.psi, load.shape)
        deflection = st["deflection_inner"] + st["deflection_outer"]
        return RowState(
            "ball", row.name, psi, load, deflection, st["contact_angle_inner"], p_max, None, extras
        )


def _merge(old: dict, new: dict, mask: np.ndarray) -> dict:
    """Per ball: ``new`` where ``mask`` (C, Z), ``old`` elsewhere."""
    if mask.all():
        return new
    if not mask.any():
        return old
    out = {}
    for k, v in old.items():
        m = mask.reshape(mask.shape + (1,) * (np.ndim(v) - mask.ndim)) if np.ndim(v) >= mask.ndim else mask
        out[k] = np.where(m, new[k], v) if np.ndim(v) >= mask.ndim else v
    return out


def beyond_model(state: RowState, free_angle) -> np.ndarray:
    """Cases (C,) where the speed is above what the model holds for a row at speed: a loaded ball of an
    angular row with a contact angle past :data:`ANGLE_LIMIT`, a loaded ball of a thrust row turned
    more than :data:`THRUST_SWING` from its free angle ``free_angle`` [rad], or a ball sub-problem that
    did not converge."""
    ex = state.extras
    if "contact_angle_outer" not in ex:
        return np.zeros(state.load.shape[0], bool)
    thrust = float(np.max(np.abs(free_angle))) > THRUST_ANGLE
    steep = np.zeros(state.load.shape, bool)
    for side in ("inner", "outer"):
        angle, loaded = ex[f"contact_angle_{side}"], ex[f"load_{side}"] > 0.0
        if thrust:
            steep |= (np.abs(angle - np.asarray(free_angle).reshape(-1, 1)) >= THRUST_SWING) & loaded
        else:
            steep |= (np.abs(angle) >= ANGLE_LIMIT) & loaded
    return steep.any(-1) | ~ex["ball_converged"].all(-1)
