"""Radial cylindrical roller rows at speed: each roller's equilibrium under its centrifugal force.

SI units. At rest a roller carries the same load on both raceways and the row uses the two line
contacts in series (:mod:`bearingkit.rows.cylindrical.row`). At speed the centrifugal force
F_c = m (d_m/2) ω_c² presses the roller onto the outer raceway, so Q_o = Q_i + F_c: the outer
contact carries more, the inner less, and unloaded rollers still press on the outer ring (Harris &
Kotzalas 2007, Advanced Concepts ch. 3). Each roller gets two unknowns, its radial displacement X
and tilt φ in its radial–axial plane, and each slice k at x_k has its two contacts

    inner  δ_i,k = a + b x_k − X − φ x_k + δ₀,k/2
    outer  δ_o,k = X + φ x_k + δ₀,k/2

with a, b the ring's approach and tilt at the roller (the zero-speed row's δ_k = a + b x_k + δ₀,k is
δ_i,k + δ_o,k: half the gap and one crown drop on each side) and the single-contact slice law
q = c₁⟨δ⟩^(10/9), c₁ = 2^(10/9) c_s, so that equal approaches reproduce the series law exactly. The
roller minimises Φ = Σ_k [E(δ_i,k) + E(δ_o,k)] − F_c X (convex: a bounded Newton iteration with
Armijo steps), and the ring sees the condensed force, stiffness K_i (K_i + K_o)⁻¹ K_o per roller
and energy min Φ. At ω = 0 the split is symmetric and the row equals the zero-speed row to round-off.

Thrust cylindrical rows are unchanged at speed: the centrifugal force is perpendicular to their
contact normals and is carried by the cage or a flange, not by the raceway contacts. The roller mass
is that of a cylinder of the roller diameter and the effective length (the overall length is not
a row field; the chamfers make it slightly high).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.physics.dynamics import centrifugal
from bearingkit.rows.base import InnerStats, RacewayOffset, RowResponse, RowState
from bearingkit.rows.cylindrical.row import LINE_EXPONENT, CylindricalKernel, CylindricalRow

#: Roller sub-problem: Newton iterations, relative tolerance of the roller's force balance, step
#: halvings and the largest step as a fraction of the roller diameter.
ROLLER_MAX_ITER = 50
ROLLER_RTOL = 1e-12
ROLLER_MAX_HALVINGS = 20
ROLLER_STEP_CAP = 0.02
#: One contact of a slice against the two in series at equal approaches: q₁(δ/2) = q_series(δ).
SINGLE_CONTACT_FACTOR = 2.0**LINE_EXPONENT


class CylindricalSpeedKernel(CylindricalKernel):
    """Kernel of a radial :class:`~bearingkit.rows.cylindrical.row.CylindricalRow` at speed.

    Parameters
    ----------
    row : CylindricalRow
        A radial row (``orientation = "radial"``).
    speed_inner, speed_outer : float or array (C,) [rad/s]
        Ring speeds per load case.
    density : float [kg/m³]
        Roller density.
    """

    _case_arrays = (*CylindricalKernel._case_arrays, "f_c", "c_1", "cage_speed")

    def __init__(self, row: CylindricalRow, speed_inner, speed_outer=0.0, density=7810.0):
        super().__init__(row)
        if row.direction != 0:
            raise checks.InputError(
                f"row {row.name!r}: a thrust cylindrical row has no speed kernel (its contacts do not carry "
                "the centrifugal force); use the row's own kernel"
            )
        checks.finite("speed_inner", speed_inner, "rad/s")
        checks.finite("speed_outer", speed_outer, "rad/s")
        col = lambda v: np.asarray(v, dtype=float).reshape(-1, 1)  # noqa: E731
        w_i, w_o = col(speed_inner), col(speed_outer)
        d, dm = col(row.element_diameter), col(row.pitch_diameter)
        gamma = d / dm
        self.cage_speed = 0.5 * (w_i * (1.0 - gamma) + w_o * (1.0 + gamma))  # (C|1, 1)
        self.mass = centrifugal.roller_mass(d, col(row.effective_length), density)
        self.f_c = centrifugal.centrifugal_force(self.mass, dm / 2.0, self.cage_speed)  # (C|1, 1)
        self.c_1 = SINGLE_CONTACT_FACTOR * self.c_s  # (C|1, 1)
        approach = 1e-4 * float(np.min(row.element_diameter))
        self.stiffness_floor = (
            1e-12 * float(np.max(self.c_1)) * row.n_slices * approach ** (LINE_EXPONENT - 1)
        )
        self.force_floor = ROLLER_RTOL * float(np.max(self.c_1)) * row.n_slices * approach**LINE_EXPONENT
        self._cache = None
        self.inner_stats = InnerStats()

    def take(self, cases):
        """A copy restricted to ``cases``; the warm start follows them."""
        out = super().take(cases)
        cache = self._cache
        if cache is not None and np.shape(cases) != () and cache[0].shape[0] > np.max(cases, initial=-1):
            out._cache = tuple(a[cases] for a in cache)
        else:
            out._cache = None
        return out

    def _law(self, delta):
        d = np.maximum(delta, 0.0)
        t = np.cbrt(np.cbrt(d))  # δ^(1/9)
        c = self.c_1[..., None]
        return c * d * t, (10.0 / 9.0) * c * t, c * d * d * t / (1.0 + LINE_EXPONENT)

    def _eval(self, a, b, y):
        """Φ, gradient (C,Z,2), the inner and outer slice laws, for roller DOFs y = (X, φ)."""
        x = self.x[:, None, :]  # (C|1, 1, n_s)
        half = 0.5 * self.delta0[:, None, :]
        shift = y[..., 0, None] + y[..., 1, None] * x
        d_i = a[..., None] + b[..., None] * x - shift + half
        d_o = shift + half
        q_i, k_i, e_i = self._law(d_i)
        q_o, k_o, e_o = self._law(d_o)
        f_c = self.f_c  # (C|1, 1)
        diff = q_o - q_i
        grad = np.stack([diff.sum(-1) - f_c, (diff * x).sum(-1)], axis=-1)
        phi = (e_i + e_o).sum(-1) - f_c * y[..., 0]
        return phi, grad, (q_i, k_i, e_i, d_i), (q_o, k_o, e_o, d_o)

    def _sums(self, k):
        x = self.x[:, None, :]
        s0, s1, s2 = k.sum(-1), (k * x).sum(-1), (k * x * x).sum(-1)
        return np.stack([np.stack([s0, s1], -1), np.stack([s1, s2], -1)], -2)  # (C, Z, 2, 2)

    def _solve_rollers(self, a, b):
        """Roller DOFs (C, Z, 2) minimising Φ; start from the equal split (exact at rest) or the last
        solution moved to first order."""
        y = np.stack([0.5 * a, 0.5 * b], axis=-1)
        cache = self._cache
        if cache is not None and cache[0].shape == a.shape:
            a_c, b_c, y_c, sens = cache
            warm = y_c + np.einsum("czij,czj->czi", sens, np.stack([a - a_c, b - b_c], -1))
            use = np.isfinite(warm).all(-1) & (self._eval(a, b, warm)[0] <= self._eval(a, b, y)[0])
            y = np.where(use[..., None], warm, y)
        phi, grad, ins, outs = self._eval(a, b, y)
        cap = ROLLER_STEP_CAP * float(np.min(self.row.element_diameter))
        length = float(np.max(self.row.effective_length))
        done = np.zeros(a.shape, bool)
        # A roller whose line search found no decrease keeps its position, and its next step (a
        # function of that roller alone) would fail the same way: it is stalled and left alone (as
        # the balls at speed, rows.ball.speed); light loads used to run every roller to
        # ROLLER_MAX_ITER x ROLLER_MAX_HALVINGS evaluations.
        stalled = np.zeros(a.shape, bool)
        used = 0
        for _ in range(ROLLER_MAX_ITER):
            scale = ins[0].sum(-1) + outs[0].sum(-1) + np.abs(self.f_c)
            gnorm = np.abs(grad[..., 0]) + np.abs(grad[..., 1]) / length
            done |= gnorm <= ROLLER_RTOL * scale + self.force_floor
            if (done | stalled).all():
                break
            used += 1
            h = self._sums(ins[1] + outs[1])
            tr = h[..., 0, 0] + h[..., 1, 1] / length**2
            mu = 1e-12 * tr + 1e-6 * gnorm / cap + self.stiffness_floor
            scale_m = np.array([1.0, 1.0 / length**2])
            step = -np.linalg.solve(h + mu[..., None, None] * np.diag(scale_m), grad[..., None])[..., 0]
            big = np.abs(step[..., 0]) + np.abs(step[..., 1]) * length
            step *= np.minimum(1.0, cap / np.maximum(big, 1e-300))[..., None]
            step[done | stalled] = 0.0
            slope = (grad * step).sum(-1)
            t = np.ones(a.shape)
            pending = ~done & ~stalled
            new = (y, phi, grad, ins, outs)
            for _ls in range(ROLLER_MAX_HALVINGS):
                trial = y + t[..., None] * step
                ev = self._eval(a, b, trial)
                ok = pending & (ev[0] <= phi + 1e-4 * t * slope + 1e-14 * np.abs(phi))
                new = _pick(ok, (trial, *ev), new)
                pending &= ~ok
                if not pending.any():
                    break
                t = np.where(pending, 0.5 * t, t)
            if pending.any():  # no decrease along a descent direction: round-off
                done |= pending & (gnorm <= 1e-9 * scale + self.force_floor)
                stalled |= pending & ~done
            y, phi, grad, ins, outs = new
        self.inner_iterations = used
        self.inner_stats.record(used, int(np.count_nonzero(~done)))
        return y, phi, ins, outs

    def _rollers(self, q, offset):
        a, b = self._ab(q, offset)
        y, phi, ins, outs = self._solve_rollers(a, b)
        return a, b, y, phi, ins, outs

    def response(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowResponse:
        """Condensed generalised force, stiffness and energy for displacements q (C, 5)."""
        q = np.asarray(q, dtype=float)
        a, b, y, phi, ins, outs = self._rollers(q, offset)
        x = self.x[:, None, :]
        q_i = ins[0]
        f_sum = np.stack([q_i.sum(-1), (q_i * x).sum(-1)], axis=-1)  # Σq_i, Σq_i x (C, Z, 2)
        k_i, k_o = self._sums(ins[1]), self._sums(outs[1])
        h = k_i + k_o + self.stiffness_floor * np.eye(2)
        sens = np.linalg.solve(h, k_i)  # d(X, φ)/d(a, b)
        k_cond = k_i - k_i @ sens  # = K_i H⁻¹ K_o
        self._cache = (a, b, y, sens)
        if self.Ga.shape[0] == 1:
            force = -(f_sum[..., 0] @ self.Ga[0] + f_sum[..., 1] @ self.Gb[0])
            jac = -(
                k_cond[..., 0, 0] @ self.GaGa[0]
                + k_cond[..., 0, 1] @ self.GaGb[0]
                + k_cond[..., 1, 1] @ self.GbGb[0]
            )
        else:
            force = -(
                np.einsum("cz,czd->cd", f_sum[..., 0], self.Ga)
                + np.einsum("cz,czd->cd", f_sum[..., 1], self.Gb)
            )
            jac = -(
                np.einsum("cz,czk->ck", k_cond[..., 0, 0], self.GaGa)
                + np.einsum("cz,czk->ck", k_cond[..., 0, 1], self.GaGb)
                + np.einsum("cz,czk->ck", k_cond[..., 1, 1], self.GbGb)
            )
        return RowResponse(force, jac.reshape(q.shape[0], 5, 5), phi.sum(-1))

    def raceway_loads(self, q: np.ndarray, offset: RacewayOffset | None = None) -> np.ndarray:
        """Loads (F_r, 0, M_t) (C, Z, 3) the rollers' OUTER contacts put on the outer raceway: Σq_o and
        −Σq_o x (the outer contact carries the centrifugal force on top of the inner one)."""
        q_o = self._rollers(np.asarray(q, dtype=float), offset)[5][0]
        total, moment = q_o.sum(-1), (q_o * self.x[:, None, :]).sum(-1)
        return np.stack([total, np.zeros_like(total), -moment], axis=-1)

    def state(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowState:
        """Per-roller results: ``load``/``slice_load`` are the inner contact's; extras add the outer
        contact's slice loads and pressures, the centrifugal force and the cage speed."""
        from bearingkit.physics.contact import line

        row = self.row
        q = np.asarray(q, dtype=float)
        _, _, y, _, ins, outs = self._rollers(q, offset)
        q_i, q_o = ins[0], outs[0]
        d = np.asarray(row.element_diameter, dtype=float).reshape(-1, 1, 1)
        dm = np.asarray(row.pitch_diameter, dtype=float).reshape(-1, 1, 1)
        width = np.asarray(row.effective_length, dtype=float).reshape(-1, 1, 1) / row.n_slices
        radius_x = {"inner": d / 2 * (1 - d / dm), "outer": d / 2 * (1 + d / dm)}
        extras = {}
        p_max = np.zeros_like(q_i)
        for side, qs in (("inner", q_i), ("outer", q_o)):
            pressure = np.sqrt(qs) * line.line_pressure_factor(width, radius_x[side], self.e_reduced)
            extras[f"slice_pressure_{side}"] = pressure
            p_max = np.maximum(p_max, pressure)
        shape = q_i.shape[:2]
        extras.update(
            slice_position=np.broadcast_to(self.x[:, None, :], q_i.shape),
            slice_load_outer=q_o,
            load_inner=q_i.sum(-1),
            load_outer=q_o.sum(-1),
            roller_displacement=y,
            centrifugal_force=np.broadcast_to(self.f_c, shape).copy(),
            cage_speed=np.broadcast_to(self.cage_speed, shape).copy(),
        )
        load = q_i.sum(-1)
        deflection = (np.maximum(ins[3], 0.0) + np.maximum(outs[3], 0.0)).max(-1)
        psi = np.broadcast_to(self.psi, load.shape)
        return RowState(
            "cylindrical", row.name, psi, load, deflection, np.zeros(load.shape), p_max.max(-1), q_i, extras
        )


def _pick(mask, new, old):
    """Per roller (C, Z): the tuple ``new`` where ``mask``, ``old`` elsewhere (nested tuples too)."""
    if mask.all():
        return new
    if not mask.any():
        return old
    out = []
    for n, o in zip(new, old, strict=True):
        if isinstance(n, tuple):
            out.append(_pick(mask, n, o))
        else:
            m = mask.reshape(mask.shape + (1,) * (np.ndim(n) - mask.ndim))
            out.append(np.where(m, n, o))
    return tuple(out)
