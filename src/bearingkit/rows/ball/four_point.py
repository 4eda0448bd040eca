"""Four-point contact ball rows: gothic-arch grooves on both rings, four possible contacts per ball.

SI units. Each ring's groove is a gothic arch: two circular arcs of radius r = f D_w whose curvature
centres sit on either side of the ball plane. In the element's radial–axial plane (local r, z, ball
centre at the origin when unloaded) with ρ = (f − ½) D_w, e_A = (cos α₀, sin α₀), e_B = (cos α₀, −sin α₀)
and g = P_d/4 (a quarter of the diametral clearance), the four arc centres are

    outer, contact up-out  (o+):  −ρ_o e_A + (g, 0)      inner, contact down-in (i−):  ρ_i e_A − (g, 0)
    outer, contact down-out (o−): −ρ_o e_B + (g, 0)      inner, contact up-in   (i+):  ρ_i e_B − (g, 0)

so that at zero clearance an unloaded ball touches all four arcs at the design contact angle α₀, and
the radial play of a ball is P_d/2 (the inner ring moves P_d from one side to the other). The pairs
(o+, i−) and (o−, i+) are the two diagonals of the ball.

Each ball is a free body (its two in-plane position coordinates x are internal DOFs, condensed per
call): contact k has the approach δ_k = |x − c_k| − ρ_k and the Hertz load Q_k = K_k ⟨δ_k⟩^1.5 along
n_k = (x − c_k)/|x − c_k|, so every contact closes or opens with the load and its operating angle follows
from the ball position. The ball takes the position that minimises its elastic energy
U_b = Σ_k K_k ⟨δ_k⟩^2.5 / 2.5 (Newton per ball, vectorised over cases and balls); the row energy is
U(q) = Σ_balls min_x U_b(x, q), convex in q (each term is jointly convex in x and the arc centres, which
move affinely with q). Its gradient is the envelope derivative (force on the inner ring Σ_inner Q_k B_kᵀ n_k)
and its Hessian the Schur complement H_qq − H_qx H_xx⁻¹ H_xq of the ball's 2 × 2 stiffness.

With one diagonal loaded the ball lies on the line between the two arc centres and this is exactly the
groove-centre model of :mod:`bearingkit.rows.ball.row` with the series stiffness of the two contacts
(Harris & Kotzalas 2007, §7 and §8; Jones). With both diagonals loaded (radial load, preload, tilting
moment over part of the circle) the two diagonals share one ball position, which a "two independent
diagonals" model does not enforce. Centrifugal force and gyroscopic moments are neglected (slow
slewing rings; the quasi-static engine). K_k is evaluated at α₀ (as ISO/TS 16281 does).

References: Harris & Kotzalas (2007) Rolling Bearing Analysis 5th ed., ch. 7-8 (groove-centre model,
Hertz point contact); Amasorrain J.I., Sagartzazu X., Damián J. (2003) Load distribution in a four
contact-point slewing bearing, Mech. Mach. Theory 38:479-496 (four-point geometry).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from bearingkit import checks, references
from bearingkit.rows.base import (
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
    validate_common,
)

references.add(
    "amasorrain2003",
    "Amasorrain J.I., Sagartzazu X., Damián J. (2003) Load distribution in a four contact-point slewing "
    "bearing. Mechanism and Machine Theory 38(6):479-496. doi:10.1016/S0094-114X(03)00003-X",
)

#: Hertz point-contact load exponent (Q = K δ^n), Harris & Kotzalas 2007 eq. 6.43.
POINT_EXPONENT = 1.5
#: Largest accepted conformity r/D_w [-] (as the ball rows: catches typing errors, real arches 0.52-0.56).
MAX_CONFORMITY = 10.0
#: Largest design contact angle of the arches [rad]: at 90° both arcs of an arch meet at the ball's pole
#: and the groove has no radial flank; real four-point rows use 30°-50° (QJ 35°, slewing rings 45°-50°).
MAX_CONTACT_ANGLE = np.radians(80.0)
#: Contact order in every per-contact array: outer up-out, outer down-out, inner down-in, inner up-in.
CONTACTS = ("outer_upper", "outer_lower", "inner_lower", "inner_upper")
#: The two diagonals (load lines through the ball): indices into CONTACTS, (outer, inner).
DIAGONALS = {"A": (0, 2), "B": (1, 3)}
#: Newton iterations of the ball sub-problem and its tolerance: the ball's force residual below this
#: fraction of its largest contact load (near round-off, so the condensed force is exact to ~1e-13).
BALL_ITERATIONS = 60
BALL_RTOL = 1e-13
#: Approach below which a contact counts as open, as a fraction of the ball diameter [-] (round-off of
#: the centre distances, ~1e-16 of d_m, with margin).
DELTA_FLOOR = 1e-12


@dataclass(frozen=True)
class FourPointRow:
    """A row of Z balls in gothic-arch grooves (four-point contact).

    Parameters
    ----------
    n_elements : int
        Number of balls Z.
    element_diameter : float [m]
        Ball diameter D_w.
    pitch_diameter : float [m]
        Pitch diameter d_m (ball centres).
    contact_angle : float [rad]
        Design contact angle α₀ of the arches (0 < α₀ < 80°): the angle at which an unloaded ball of a
        zero-clearance row touches each arc. QJ bearings 35°, slewing rings usually 45°.
    conformity_inner, conformity_outer : float
        Arc radius over ball diameter f = r/D_w (> 0.5), the same for both arcs of a ring.
    clearance : float [m]
        Radial internal clearance P_d (diametral; negative = preload). The axial play follows from the
        arch geometry (≈ P_d / tan α₀ for small clearances).
    axial_position : float [m]
        Axial position of the ball centres.
    azimuth_phase : float [rad]
        Azimuth of ball 0.
    e_reduced : float [Pa] or None
        Reduced modulus E′ of ball and rings (steel–steel by default).
    hertz_method : str
        ``"exact"`` or ``"hamrock_brewe"`` (see :mod:`bearingkit.physics.contact.hertz`).
    name : str

    Geometry fields may be arrays of shape (C,) to batch designs of the same topology.
    """

    kind: ClassVar[str] = "four_point"

    n_elements: int
    element_diameter: float
    pitch_diameter: float
    contact_angle: float = np.radians(45.0)
    conformity_inner: float = 0.52
    conformity_outer: float = 0.53
    clearance: float = 0.0
    axial_position: float = 0.0
    azimuth_phase: float = 0.0
    e_reduced: float | None = None
    hertz_method: str = "exact"
    name: str = "balls"

    def __post_init__(self):
        validate_common(self)
        alpha = np.asarray(self.contact_angle, dtype=float)
        checks.finite("contact_angle", alpha, "rad")
        if np.any(alpha <= 0.0):
            raise checks.InputError(
                f"contact_angle ({checks._fmt(alpha)} rad) must be positive: the two arc centres of each "
                "gothic arch sit ±(f − 0.5)·D_w·sin(contact_angle) off the ball plane, so a zero or "
                "negative angle makes them coincide or cross (a single groove: use a deep groove ball row)"
            )
        if np.any(alpha >= MAX_CONTACT_ANGLE):
            raise checks.InputError(
                f"contact_angle ({np.degrees(np.max(alpha)):.6g} deg) must be below "
                f"{np.degrees(MAX_CONTACT_ANGLE):.0f} deg: the arches of a four-point groove need a "
                "radial flank"
            )
        for f in ("conformity_inner", "conformity_outer"):
            val = np.asarray(getattr(self, f), dtype=float)
            checks.finite(f, val)
            if np.any(val <= 0.5):
                raise checks.InputError(
                    f"{f} ({np.min(val):.6g}) must exceed 0.5: each arc radius must exceed half the ball "
                    "diameter"
                )
            if np.any(val > MAX_CONFORMITY):
                raise checks.InputError(f"{f} ({np.max(val):.6g}) must be at most {MAX_CONFORMITY:g}")
        if self.e_reduced is not None:
            checks.positive("e_reduced", self.e_reduced, "Pa")
        from bearingkit.physics.contact.hertz import POINT_METHODS

        checks.one_of("hertz_method", self.hertz_method, POINT_METHODS)
        # A preload (negative clearance) moves each ring's arc centres towards the ball by |P_d|/4; past
        # ρ·cos α₀ an arc centre would cross the ball's radial line and the arch would turn inside out.
        d = np.asarray(self.element_diameter, dtype=float)
        rho = np.minimum(np.asarray(self.conformity_inner), np.asarray(self.conformity_outer)) - 0.5
        limit = 4.0 * rho * d * np.cos(alpha)
        if np.any(-np.asarray(self.clearance, dtype=float) >= limit):
            raise checks.InputError(
                f"clearance ({np.min(self.clearance):.6g} m) is a preload larger than the arches allow; "
                f"expected a clearance above {-np.min(limit):.6g} m (4·(f − 0.5)·D_w·cos α₀)"
            )

    @property
    def axial_play(self):
        """Total axial play of the row [m] from its radial clearance (exact arch geometry, rigid balls).

        The inner ring moves axially until one diagonal closes: with A₀ = (f_i + f_o − 1) D_w and
        2g = P_d/2 the radial shift of the arc centres, (A₀ cos α₀ − 2g)² + (A₀ sin α₀ + s)² = A₀², so
        the play 2s = 2[√(A₀² − (A₀ cos α₀ − P_d/2)²) − A₀ sin α₀] ≈ P_d / tan α₀ for small P_d.
        """
        a0 = (np.asarray(self.conformity_inner) + np.asarray(self.conformity_outer) - 1.0) * np.asarray(
            self.element_diameter
        )
        alpha = np.asarray(self.contact_angle, dtype=float)
        pd = np.asarray(self.clearance, dtype=float)
        inside = a0**2 - (a0 * np.cos(alpha) - pd / 2.0) ** 2
        return 2.0 * (np.sqrt(np.maximum(inside, 0.0)) - a0 * np.sin(alpha))

    def envelope(self) -> tuple[float, float, float, float]:
        """Space the balls sweep: (r_min, r_max, z_min, z_max) [m]."""
        r, d, z = np.max(self.pitch_diameter) / 2, np.max(self.element_diameter), np.max(self.axial_position)
        return (r - d / 2, r + d / 2, z - d / 2, z + d / 2)

    def kernel(self) -> FourPointKernel:
        """Precompute the arrays the solver needs (done once per solve)."""
        return FourPointKernel(self)


def _col(v):
    """(C,)|() -> (C|1, 1): per-case geometry broadcast over the balls."""
    return np.asarray(v, dtype=float).reshape(-1, 1)


class FourPointKernel(KernelBase):
    """Arc centres, contact stiffnesses and kinematics of a :class:`FourPointRow`."""

    _case_arrays = ("outer0", "inner0", "rho", "k", "B")

    def __init__(self, row: FourPointRow):
        from bearingkit.physics.contact import hertz

        self.row = row
        d, dm = _col(row.element_diameter), _col(row.pitch_diameter)
        alpha = _col(row.contact_angle)
        fi, fo = _col(row.conformity_inner), _col(row.conformity_outer)
        self.e_reduced = float(row.e_reduced) if row.e_reduced is not None else steel_e_reduced()
        self.psi = azimuths(row.n_elements, row.azimuth_phase)  # (C|1, Z)
        rho_i, rho_o = (fi - 0.5) * d, (fo - 0.5) * d
        g = _col(row.clearance) / 4.0
        e_a = np.stack([np.cos(alpha), np.sin(alpha)], axis=-1)  # (C|1, 1, 2)
        e_b = e_a * np.array([1.0, -1.0])
        shift = np.stack([g, np.zeros_like(g)], axis=-1)
        # Arc centres in the ball's local (r, z) frame, (C|1, 1, 2 arcs, 2).
        self.outer0 = np.stack([-rho_o[..., None] * e_a + shift, -rho_o[..., None] * e_b + shift], axis=-2)
        self.inner0 = np.stack([rho_i[..., None] * e_a - shift, rho_i[..., None] * e_b - shift], axis=-2)
        self.rho = np.concatenate([rho_o, rho_o, rho_i, rho_i], axis=-1)[:, None, :]  # (C|1, 1, 4)
        # Hertz stiffness of each single contact at the design angle (Harris & Kotzalas 2007 ch. 6).
        k_side = {}
        for side, f in (("inner", fi), ("outer", fo)):
            sr, fr = hertz.ball_raceway_curvature(d, dm, alpha, f * d, side)
            k_side[side] = hertz.point_stiffness(sr, fr, self.e_reduced, method=row.hertz_method)
        k_o, k_i = np.asarray(k_side["outer"]), np.asarray(k_side["inner"])
        self.k = np.concatenate([k_o, k_o, k_i, k_i], axis=-1)[:, None, :]  # (C|1, 1, 4)
        # Kinematics of the two inner arc centres: rows of B at their own radius and axial position.
        r_c = dm[..., None] / 2 + self.inner0[..., 0]  # (C|1, 1, 2)
        z_c = _col(row.axial_position)[..., None] + self.inner0[..., 1]
        psi = self.psi[..., None]  # (C|1, Z, 1)
        self.B = np.stack([radial_row(psi, z_c), axial_row(psi, r_c)], axis=-2)  # (C|1, Z, 2, 2, 5)
        # Contact directions for the solver's cone checks: a diagonal's inner contact pushes the inner ring
        # along −e, so the external load it balances lies along Bᵀe (the ball rows' convention).
        e_ab = np.stack([e_a, e_b], axis=-2)  # (C|1, 1, 2, 2)
        dirs = np.einsum("...kij,...ki->...kj", self.B, np.broadcast_to(e_ab, self.B.shape[:-1]))
        self.directions = dirs.reshape(dirs.shape[0], -1, 5)  # (C|1, 2Z, 5)
        self.reach = self.directions[0]
        k_pair = hertz.series_stiffness(k_i, k_o, exponent=POINT_EXPONENT)
        g0 = self.directions[0]
        self.start_matrix = float(np.ravel(k_pair)[0]) * g0.T @ g0
        self.start_exponent = POINT_EXPONENT
        self.char_length = float(np.max(dm) / 2)
        self.deflection_scale = float(np.min(d))
        self._ball_scale = float(np.min(d))

    # -- geometry ------------------------------------------------------------------------------------
    def _centres(self, q, offset: RacewayOffset | None):
        """Arc centres (C, Z, 4, 2): the outer ones fixed (or moved by a raceway offset), the inner ones
        displaced with the inner ring."""
        q = relative_displacement(q, offset)
        if self.B.shape[0] == 1:
            u = np.einsum("zkij,cj->czki", self.B[0], q)
        else:
            u = np.einsum("czkij,cj->czki", self.B, q)
        c, z = q.shape[0], self.psi.shape[-1]
        inner = self.inner0 + u  # (C, Z, 2, 2)
        outer = np.broadcast_to(self.outer0, (c, z, 2, 2))
        parts = element_offsets(offset, (c, z))
        if parts is not None:  # each outer arc centre moves with the raceway (radial, axial, tilt)
            radial, axial, tilt = (p[..., None] for p in parts)
            arm_r, arm_z = self.outer0[..., 0], self.outer0[..., 1]
            outer = outer + np.stack([radial - arm_z * tilt, axial + arm_r * tilt], axis=-1)
        return np.concatenate([outer, inner], axis=-2)

    def _contacts(self, x, centres):
        """Approach, load, stiffness and normals of the four contacts for ball positions x (C, Z, 2)."""
        d = x[..., None, :] - centres  # (C, Z, 4, 2)
        length = np.sqrt(d[..., 0] ** 2 + d[..., 1] ** 2)
        n = d / np.maximum(length, 1e-300)[..., None]
        delta = length - self.rho
        # Approaches below the round-off of the centre distances are no contact: a ball leaving its last
        # contact converges to it only geometrically (Newton on δ^2.5), and the 1e-20 N loads it would
        # keep make the condensed stiffness of a free ball round-off noise of either sign.
        delta = np.where(delta > DELTA_FLOOR * self._ball_scale, delta, 0.0)
        root = np.sqrt(delta)
        load = self.k * delta * root
        stiff = 1.5 * self.k * root
        return delta, load, stiff, n, length

    def _ball_hessians(self, load, stiff, n, length):
        """Per-contact 2 × 2 stiffness h_k = Q′ n nᵀ + (Q/L)(I − n nᵀ) (C, Z, 4, 2, 2)."""
        nn = n[..., :, None] * n[..., None, :]
        geo = (load / np.maximum(length, 1e-300))[..., None, None]
        return stiff[..., None, None] * nn + geo * (np.eye(2) - nn)

    def _initial_positions(self, centres):
        """Ball positions of the one-diagonal (groove-centre) model: exact when a single diagonal is
        closed, the mean of the two when both are, the unloaded position when none is."""
        x = np.zeros((*centres.shape[:2], 2))
        count = np.zeros(centres.shape[:2])
        # share of a diagonal's approach taken by its outer contact: δ_o/δ_i = (K_i/K_o)^(2/3)
        ratio = (self.k[..., 2] / self.k[..., 0]) ** (2.0 / 3.0)
        w_out = ratio / (1.0 + ratio)
        for k_out, k_in in DIAGONALS.values():
            s = centres[..., k_in, :] - centres[..., k_out, :]
            a = np.sqrt(s[..., 0] ** 2 + s[..., 1] ** 2)
            gap = a - self.rho[..., k_out] - self.rho[..., k_in]
            closed = gap > 0
            reach = self.rho[..., k_out] + w_out * np.maximum(gap, 0.0)
            on_line = centres[..., k_out, :] + (reach / np.maximum(a, 1e-300))[..., None] * s
            x += np.where(closed[..., None], on_line, 0.0)
            count += closed
        return x / np.maximum(count, 1.0)[..., None]

    def _solve_balls(self, centres):
        """Ball positions x (C, Z, 2) minimising each ball's elastic energy (damped Newton, Armijo).

        A ball stops when its force residual is below :data:`BALL_RTOL` of its largest contact load, or
        when its Newton step no longer changes its position representably (round-off floor, ~1e-12 of
        the load for balls squeezed between nearly opposite contacts), or when no step length decreases
        its energy or halves its residual (then it is already at the round-off floor).
        """
        shape = centres.shape[:2]
        x = self._initial_positions(centres)
        cap = 0.05 * self._ball_scale
        active = np.ones(shape, bool)
        for _ in range(BALL_ITERATIONS):
            delta, load, stiff, n, length = self._contacts(x, centres)
            grad = np.einsum("czk,czki->czi", load, n)
            scale = load.max(axis=-1)
            g_norm = np.hypot(grad[..., 0], grad[..., 1])
            active &= (g_norm > BALL_RTOL * scale) & (scale > 0)
            if not active.any():
                break
            h = self._ball_hessians(load, stiff, n, length).sum(axis=-3)
            mu = 1e-12 * (h[..., 0, 0] + h[..., 1, 1])
            a, b, c, e = h[..., 0, 0] + mu, h[..., 0, 1], h[..., 1, 0], h[..., 1, 1] + mu
            det = a * e - b * c
            det = np.where(det > 0, det, np.inf)  # a ball with no loaded contact does not move
            step = -np.stack([e * grad[..., 0] - b * grad[..., 1], a * grad[..., 1] - c * grad[..., 0]], -1)
            step /= det[..., None]
            # A ball pressed by a single contact cannot be in equilibrium: it leaves that contact, exactly
            # (Newton would only divide the approach by 3 per iteration).
            lone = (load > 0).sum(axis=-1) == 1
            if lone.any():
                k1 = np.argmax(load, axis=-1)[..., None, None]
                n1 = np.take_along_axis(n, np.broadcast_to(k1, (*shape, 1, 2)), axis=-2)[..., 0, :]
                d1 = np.take_along_axis(delta, k1[..., 0], axis=-1)
                step = np.where(lone[..., None], -d1 * n1, step)
            big = np.hypot(step[..., 0], step[..., 1])
            step *= np.minimum(1.0, cap / np.maximum(big, 1e-300))[..., None]
            active &= big > 1e-15 * self._ball_scale
            step[~active] = 0.0
            energy = (self.k * delta**2.5 / 2.5).sum(axis=-1)
            slope = np.einsum("czi,czi->cz", grad, step)
            t = np.ones(shape)
            pending = active.copy()
            for _ls in range(20):
                trial = x + t[..., None] * step
                d_t, l_t, _, n_t, _ = self._contacts(trial, centres)
                e_t = (self.k * d_t**2.5 / 2.5).sum(axis=-1)
                g_t = np.einsum("czk,czki->czi", l_t, n_t)
                # Armijo on the energy, or (near the solution, where the energy change is round-off) a
                # halved force residual: the outer solver needs the ball in equilibrium to ~1e-13.
                ok = (e_t <= energy + 1e-4 * t * slope) | (np.hypot(g_t[..., 0], g_t[..., 1]) < 0.5 * g_norm)
                accept = pending & ok
                x = np.where(accept[..., None], trial, x)
                pending &= ~ok
                if not pending.any():
                    break
                t = np.where(pending, 0.5 * t, t)
            active &= ~pending  # no acceptable step: the ball sits at its round-off floor
        return x

    # -- solver interface ----------------------------------------------------------------------------
    def _solution(self, q, offset):
        centres = self._centres(q, offset)
        x = self._solve_balls(centres)
        return x, centres, self._contacts(x, centres)

    def raceway_loads(self, q: np.ndarray, offset: RacewayOffset | None = None) -> np.ndarray:
        """Loads (F_r, F_z, M_t) (C, Z, 3) each ball puts on the outer raceway, −∂U/∂(radial, axial, tilt).

        Σ over the two outer contacts of Q n (n from the arc centre to the ball, outward on the ring),
        and their moment about the ball's nominal centre through each arc centre's arm (the balls are
        in equilibrium, so the derivative at fixed ball positions is the total one).
        """
        _, _, (_, load, _, n, _) = self._solution(q, offset)
        f = load[..., :2, None] * n[..., :2, :]  # (C, Z, 2 arcs, 2)
        arm = np.broadcast_to(self.outer0, f.shape)
        moment = (f[..., 1] * arm[..., 0] - f[..., 0] * arm[..., 1]).sum(-1)
        return np.concatenate([f.sum(-2), moment[..., None]], axis=-1)

    def response(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowResponse:
        """Generalised force, Jacobian (condensed over the ball positions) and energy for q (C, 5)."""
        _, _, (delta, load, stiff, n, length) = self._solution(q, offset)
        c = q.shape[0]
        B = np.broadcast_to(self.B, (c, *self.B.shape[1:]))  # (C, Z, 2, 2, 5)
        # Force on the inner ring: each inner contact pushes its arc centre along +n (away from the ball).
        f_local = load[..., 2:, None] * n[..., 2:, :]  # (C, Z, 2, 2)
        force = np.einsum("czki,czkij->cj", f_local, B)
        h = self._ball_hessians(load, stiff, n, length)  # (C, Z, 4, 2, 2)
        hxx = h.sum(axis=2)
        hin = h[:, :, 2:]  # inner contacts
        hxq = -np.einsum("czkab,czkbj->czaj", hin, B)  # (C, Z, 2, 5)
        hqq = np.einsum("czkai,czkab,czkbj->cij", B, hin, B)
        mu = 1e-14 * (hxx[..., 0, 0] + hxx[..., 1, 1]) + 1e-300
        a, b, cc, e = hxx[..., 0, 0] + mu, hxx[..., 0, 1], hxx[..., 1, 0], hxx[..., 1, 1] + mu
        det = a * e - b * cc
        det = np.where(det > 0, det, np.inf)[..., None]  # free balls: no stiffness to condense
        inv_hxq = (
            np.stack(
                [
                    e[..., None] * hxq[..., 0, :] - b[..., None] * hxq[..., 1, :],
                    a[..., None] * hxq[..., 1, :] - cc[..., None] * hxq[..., 0, :],
                ],
                axis=-2,
            )
            / det[..., None]
        )
        schur = np.einsum("czai,czaj->cij", hxq, inv_hxq)
        jac = -(hqq - schur)
        jac = 0.5 * (jac + np.swapaxes(jac, 1, 2))
        energy = (self.k * delta**2.5 / 2.5).sum(axis=(-2, -1))
        return RowResponse(force, jac, energy)

    def state(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowState:
        """Per-ball results: the largest contact load and its angle, and every contact in ``extras``.

        ``extras``: ``contact_load`` (C, Z, 4) [N] in the order of :data:`CONTACTS`, ``contact_angle_all``
        (C, Z, 4) [rad] (the angle of each contact's load line from the radial plane: +α on diagonal A,
        −α on diagonal B), ``ball_position`` (C, Z, 2) [m], per-contact ``semi_major``/``semi_minor``/
        ``max_pressure`` (C, Z, 4), and for the raters ``semi_major_inner``/``_outer`` and
        ``max_pressure_inner``/``_outer`` (C, Z) of the most loaded inner and outer contact.
        """
        from bearingkit.physics.contact import hertz

        row = self.row
        x, _, (delta, load, _, n, _) = self._solution(q, offset)
        line = np.concatenate([n[..., :2, :], -n[..., 2:, :]], axis=-2)  # load-line direction, outward
        angle = np.arctan2(line[..., 1], line[..., 0])  # (C, Z, 4)
        d, dm = _col(row.element_diameter)[..., None], _col(row.pitch_diameter)[..., None]
        f = np.concatenate([_col(row.conformity_outer)] * 2 + [_col(row.conformity_inner)] * 2, axis=-1)[
            :, None, :
        ]
        semi_a, semi_b, p = (np.zeros_like(load) for _ in range(3))
        for k, side in enumerate(("outer", "outer", "inner", "inner")):
            a_k = np.clip(np.abs(angle[..., k]), 0.0, np.pi / 2)
            sr, fr = hertz.ball_raceway_curvature(d[..., 0], dm[..., 0], a_k, f[..., k] * d[..., 0], side)
            contact = hertz.point_contact(load[..., k], sr, fr, self.e_reduced, method=row.hertz_method)
            semi_a[..., k], semi_b[..., k], p[..., k] = (
                contact.semi_major,
                contact.semi_minor,
                contact.max_pressure,
            )
        top = np.argmax(load, axis=-1)
        pick = lambda a: np.take_along_axis(a, top[..., None], axis=-1)[..., 0]  # noqa: E731
        extras = {
            "contact_load": load,
            "contact_angle_all": angle,
            "contact_deflection": delta,
            "ball_position": x,
            "semi_major": semi_a,
            "semi_minor": semi_b,
            "max_pressure_contact": p,
        }
        for side, ks in (("outer", slice(0, 2)), ("inner", slice(2, 4))):
            i = np.argmax(load[..., ks], axis=-1)[..., None]
            extras[f"semi_major_{side}"] = np.take_along_axis(semi_a[..., ks], i, axis=-1)[..., 0]
            extras[f"semi_minor_{side}"] = np.take_along_axis(semi_b[..., ks], i, axis=-1)[..., 0]
            extras[f"max_pressure_{side}"] = p[..., ks].max(axis=-1)
        psi = np.broadcast_to(self.psi, top.shape)
        return RowState(
            "four_point", row.name, psi, pick(load), pick(delta), pick(angle), p.max(axis=-1), None, extras
        )
