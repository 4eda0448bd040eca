"""A straightforward research-script baseline: per-element Python loops + ``scipy.optimize.fsolve``.

SI units (m, N, Pa, rad). This is how the seed-000 statics are typically coded (Tian et al. 2025,
Machines 13:588, §3.4: equilibrium of the inner ring in (δa, δr, θ) solved by Newton–Raphson in
MATLAB): for each trial displacement, loop over every roller and every slice, and over every ball,
sum the contact forces, and hand the residual to a general root finder that differentiates it by
finite differences (no analytic Jacobian). It exists only to be timed against bearingkit's
vectorised, analytic-Jacobian solver in :mod:`benchmarks.bench_quasistatic` and to check that both
compute the same element loads (``tests/test_benchmark_baseline.py``).

The model is bearingkit's, written out element by element (design.md §3 kinematics, planar case
q = (u_x, u_z, θ_y), u_y = θ_x = 0):

- thrust roller row, direction σ = ±1, slice k at radius R + x_k:
  δ_jk = σ (u_z − (R + x_k) θ_y cos ψ_j) − c − 2 C(x_k), q_jk = c_s ⟨δ_jk⟩^(10/9);
- radial roller row, slice k at axial position x_k: δ_jk = (u_x + x_k θ_y) cos ψ_j − c − 2 C(x_k);
- thrust ball row (α₀ = σ π/2), groove-centre model (Jones; Harris & Kotzalas 2007 §7): the inner
  groove centre sits at radius r_c = d_m/2, height z_c = z + σ (f − ½) D_w; it moves by
  u_r = (u_x + θ_y z_c) cos ψ, u_a = u_z − r_c θ_y cos ψ; the centre separation is
  s = (u_r, σ (A₀ − c) + u_a), A = |s|, δ = ⟨A − A₀⟩, Q = K_n δ^1.5 along −s/A (zero if the
  one-sided thrust groove would be loaded from the wrong side, σ s_a < 0, as in rows/ball.py);

with c = clearance/2, A₀ = (2f − 1) D_w, K_n from :func:`bearingkit.physics.contact.hertz.point_stiffness`
(both contacts in series), c_s = c_l w / l from :func:`bearingkit.physics.contact.line.line_stiffness`
(paired as the geometry's ``pairing`` says: two contacts in series or the one-contact law on the
total approach) and C(x) from :mod:`bearingkit.physics.contact.profiles` — so both codes
solve the identical problem. Constants are computed once per bearing (as any script would), and the
loops use :mod:`math` scalars, so this is a fair, not a deliberately slow, baseline.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import fsolve

from bearingkit.bearings.common import e_reduced_of
from bearingkit.bearings.turntable import AXIAL_ROW_OFFSET, CompositeTurntableGeometry, _profile
from bearingkit.physics.contact import hertz, line

#: Exponent of the line law q = c_s δ^(10/9) (Kunert 1961).
LINE_EXP = 10.0 / 9.0
#: Exponent of the Hertz point law Q = K δ^1.5.
POINT_EXP = 1.5
#: fsolve's relative tolerance on the displacement (MINPACK ``xtol``); tighter than scipy's default
#: 1.49e-8 so the element loads agree with bearingkit's 1e-10 residual to ~1e-8 of the largest load.
XTOL = 1e-12


@dataclass
class _RollerRow:
    n: int
    radius: float  # pitch radius R [m]
    sigma: int  # +1 / −1 thrust, 0 radial
    gap: float  # c = clearance/2 [m]
    x: list  # slice centres [m]
    drop: list  # 2 C(x_k) [m]
    c_s: float  # slice stiffness [N/m^(10/9)]


@dataclass
class _BallRow:
    n: int
    r_c: float  # radius of the inner groove centre [m]
    z_c: float  # height of the inner groove centre [m]
    sigma: int
    a0: float  # A₀ [m]
    s0: float  # A₀ − c [m]
    k_n: float  # [N/m^1.5]
    phase: float  # azimuth of ball 0 [rad]


class BaselineTurntable:
    """The seed-000 composite turntable bearing as plain per-element loops (planar, 3 DOF).

    Parameters
    ----------
    geometry : CompositeTurntableGeometry, optional
        Same dataclass as :func:`bearingkit.bearings.turntable.composite_turntable` (Table 1 defaults).
    **overrides
        Fields of the geometry to replace (``n_slices=5`` …).
    """

    def __init__(self, geometry: CompositeTurntableGeometry | None = None, **overrides):
        g = geometry or CompositeTurntableGeometry()
        if overrides:
            g = CompositeTurntableGeometry(**{**g.__dict__, **overrides})
        self.geometry = g
        e_red = e_reduced_of(None)
        self.rollers = []
        self.balls = []
        for sigma, z in ((+1, AXIAL_ROW_OFFSET), (-1, -AXIAL_ROW_OFFSET)):
            self.rollers.append(
                self._roller_row(
                    g.n_axial_rollers,
                    g.axial_roller_diameter,
                    g.axial_roller_length,
                    g.pitch_diameter_axial_roller,
                    sigma,
                    g.clearance_axial_roller,
                    g,
                    e_red,
                )
            )
            d, dm, f = g.ball_diameter, g.pitch_diameter_axial_ball, g.groove_curvature
            k = []
            for side in ("inner", "outer"):
                sr, fr = hertz.ball_raceway_curvature(d, dm, math.pi / 2, f * d, side)
                k.append(hertz.point_stiffness(sr, fr, e_red, method="exact"))
            k_n = float(hertz.series_stiffness(k[0], k[1], exponent=POINT_EXP))
            a0 = (2 * f - 1) * d
            self.balls.append(
                _BallRow(
                    n=g.n_axial_balls,
                    r_c=dm / 2,
                    z_c=z + sigma * (f - 0.5) * d,
                    sigma=sigma,
                    a0=a0,
                    s0=a0 - g.clearance_axial_ball / 2,
                    k_n=k_n,
                    phase=math.pi / g.n_axial_balls,
                )
            )
        self.rollers.append(
            self._roller_row(
                g.n_radial_rollers,
                g.radial_roller_diameter,
                g.radial_roller_length,
                g.pitch_diameter_radial_roller,
                0,
                g.clearance_radial,
                g,
                e_red,
            )
        )

    @staticmethod
    def _roller_row(n, diameter, length, pitch_diameter, sigma, clearance, g, e_red) -> _RollerRow:
        x, width = line.slice_grid(length, g.n_slices)
        profile = _profile(g.crowning, length, diameter)
        drop = [2.0 * float(profile.crown_drop(xk)) for xk in x]
        k_contact = float(line.line_stiffness(length, e_red, law="kunert"))
        # Both raceway contacts in series ("series"), or the one-contact law on the total approach as
        # Tian et al. 2025 write eqs. 3–5 ("total_approach", the seed-000 builder's default).
        if getattr(g, "pairing", "series") == "series":
            k_pair = float(hertz.series_stiffness(k_contact, k_contact, exponent=LINE_EXP))
        else:
            k_pair = k_contact
        return _RollerRow(n, pitch_diameter / 2, sigma, clearance / 2, [float(v) for v in x], drop,
                          k_pair * float(width) / length)  # fmt: skip

    # -- the research-script part: loops over rollers, slices and balls ------------------------------
    def contact_force(self, u_x: float, u_z: float, theta_y: float) -> tuple[float, float, float]:
        """Sum of the contact forces on the inner ring (F_x [N], F_z [N], M_y [N·m])."""
        fx = fz = my = 0.0
        for row in self.rollers:
            for j in range(row.n):
                cos_psi = math.cos(2.0 * math.pi * j / row.n)
                for k in range(len(row.x)):
                    xk = row.x[k]
                    if row.sigma == 0:  # radial roller, slice at axial position x_k
                        delta = (u_x + xk * theta_y) * cos_psi - row.gap - row.drop[k]
                    else:  # thrust roller, slice at radius R + x_k
                        delta = row.sigma * (u_z - (row.radius + xk) * theta_y * cos_psi)
                        delta -= row.gap + row.drop[k]
                    if delta > 0.0:
                        q = row.c_s * delta**LINE_EXP
                        if row.sigma == 0:
                            fx -= q * cos_psi
                            my -= q * xk * cos_psi
                        else:
                            fz -= row.sigma * q
                            my += row.sigma * q * (row.radius + xk) * cos_psi
        for row in self.balls:
            for j in range(row.n):
                cos_psi = math.cos(row.phase + 2.0 * math.pi * j / row.n)
                u_r = (u_x + theta_y * row.z_c) * cos_psi
                u_a = u_z - row.r_c * theta_y * cos_psi
                s_r, s_a = u_r, row.sigma * row.s0 + u_a
                a = math.sqrt(s_r * s_r + s_a * s_a)
                delta = a - row.a0
                if delta > 0.0 and row.sigma * s_a >= 0.0:  # one-sided thrust groove
                    q = row.k_n * delta**POINT_EXP
                    f_r, f_a = -q * s_r / a, -q * s_a / a
                    fx += f_r * cos_psi
                    fz += f_a
                    my += f_r * row.z_c * cos_psi - f_a * row.r_c * cos_psi
        return fx, fz, my

    def element_loads(self, u_x: float, u_z: float, theta_y: float) -> dict[str, np.ndarray]:
        """Element loads [N] per row, keyed like bearingkit's rows (same loops as the residual)."""
        out = {}
        names = ("roller_upper", "roller_lower", "roller_radial")
        for name, row in zip(names, self.rollers, strict=True):
            loads = []
            for j in range(row.n):
                cos_psi = math.cos(2.0 * math.pi * j / row.n)
                total = 0.0
                for k in range(len(row.x)):
                    xk = row.x[k]
                    if row.sigma == 0:
                        delta = (u_x + xk * theta_y) * cos_psi - row.gap - row.drop[k]
                    else:
                        delta = row.sigma * (u_z - (row.radius + xk) * theta_y * cos_psi)
                        delta -= row.gap + row.drop[k]
                    if delta > 0.0:
                        total += row.c_s * delta**LINE_EXP
                loads.append(total)
            out[name] = np.array(loads)
        for name, row in zip(("ball_upper", "ball_lower"), self.balls, strict=True):
            loads = []
            for j in range(row.n):
                cos_psi = math.cos(row.phase + 2.0 * math.pi * j / row.n)
                s_r = (u_x + theta_y * row.z_c) * cos_psi
                s_a = row.sigma * row.s0 + u_z - row.r_c * theta_y * cos_psi
                delta = math.sqrt(s_r * s_r + s_a * s_a) - row.a0
                loaded = delta > 0.0 and row.sigma * s_a >= 0.0
                loads.append(row.k_n * delta**POINT_EXP if loaded else 0.0)
            out[name] = np.array(loads)
        return out

    def solve(self, load_radial_x: float, load_axial: float, moment_y: float, guess=None) -> dict:
        """Equilibrium for F_x [N], F_z [N], M_y [N·m] by ``fsolve`` (finite-difference Jacobian).

        Returns a dict with ``displacement`` (u_x, u_z, θ_y) [m, m, rad], ``converged``, ``nfev`` and
        ``message``. Unknowns are passed to fsolve in µm and µrad (the obvious rescaling a script
        makes so MINPACK's finite-difference steps are sensible); nothing else is tuned.
        """
        scale = np.array([1e-6, 1e-6, 1e-6])

        def residual(v):
            u_x, u_z, th = v * scale
            fx, fz, my = self.contact_force(u_x, u_z, th)
            return [load_radial_x + fx, load_axial + fz, moment_y + my]

        x0 = np.zeros(3) if guess is None else np.asarray(guess, float) / scale
        sol, info, ier, msg = fsolve(residual, x0, full_output=True, xtol=XTOL)
        return {"displacement": sol * scale, "converged": ier == 1, "nfev": int(info["nfev"]), "message": msg}
