"""The static load diagram of a slewing ring: allowable axial force versus tilting moment.

SI units (N, N·m, Pa, m). Slewing-ring makers select a bearing by plotting the application's
reference loads on the bearing's *static limiting load curve* (Rothe Erde, "Bearing selection – static
load capacity"): the loads, multiplied by an application factor f_stat, must lie below the curve. For
radial force they give two load combinations (Rothe Erde, single-row ball and crossed roller series):

    I:   F_a' = (F_a + 5.046 F_r) f_stat,            M_k' = M_k f_stat
    II:  F_a' = (1.225 F_a + 2.676 F_r) f_stat,      M_k' = 1.225 M_k f_stat

and the bearing is statically suitable if one of them lies below the curve.

The curve itself is the static capacity of the raceways: the combinations of axial force F_a and tilting
moment M at which the most heavily loaded contact reaches the static limit stress (ISO 76: 4200 MPa for
balls, 4000 MPa for rollers; makers use the permissible stress of their raceway hardening, which
``p_limit`` sets). :func:`static_load_diagram` finds it with the engine: along rays of the (F_a, M) plane
it scales the load until p_max = p_limit (a few batched solves), so clearance, the load-dependent contact
angle and the true load zone are in it. For comparison it returns the makers' closed form, a straight
line between the pure-axial capacity C0a = Z_a Q0 sin α and the pure-moment capacity C0a d_m / k:

    F_a / C0a + k M / (C0a d_m) = 1,    k = 1/J = 4.37 (point contact), 4.08 (line contact)

with J the Stribeck–Sjövall integral of the zero-clearance load zone (J = 0.2288 point, 0.2453 line,
Harris & Kotzalas 2007 Table 7.4; the makers' selection formula C_p = F_a + 4370 M/D + … for
single-row ball slewing rings, M in kN·m and D in mm, is the same 4.37), Q0 the element load of one
contact at p_limit and Z_a the elements carrying one axial direction (all balls of a four-point row, half
the crossed rollers, both rows of an eight-point ring).

References: Rothe Erde GmbH (thyssenkrupp), Slewing bearings catalogue, "Bearing selection – static
load capacity" (load combinations I/II, f_stat, static limiting load curves); ISO 76:2006 clause 4;
Harris & Kotzalas (2007) ch. 7.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks, references
from bearingkit.errors import InputError

references.add(
    "rotheerde_static",
    "Rothe Erde GmbH (thyssenkrupp rothe erde), Slewing bearings: Bearing selection - static load capacity "
    "(load combinations I/II with f_stat, static limiting load curves). rotheerde.com, technical guide.",
)

#: Rothe Erde load combinations (factor on F_a, factor on F_r, factor on M_k) for the static selection of
#: single-row ball (KD 210/KD 600) and crossed roller slewing rings.
LOAD_COMBINATIONS = {"I": (1.0, 5.046, 1.0), "II": (1.225, 2.676, 1.225)}
#: 1/J of the zero-clearance load zone under a tilting moment (Harris & Kotzalas 2007 Table 7.4:
#: J_r(ε = 0.5) = 0.2288 point contact, 0.2453 line contact) [-].
MOMENT_FACTOR = {"ball": 1.0 / 0.2288, "roller": 1.0 / 0.2453}
#: ISO 76:2006 clause 4 static limit stresses [Pa].
LIMIT_STRESS = {"ball": 4200e6, "roller": 4000e6}
#: Exponent n of p ∝ Q^(1/n): 3 point contact, 2 line contact (scaling of the ray search).
_PRESSURE_EXPONENT = {"ball": 3.0, "roller": 2.0}
#: Ray search: iterations and relative tolerance on p_max / p_limit.
RAY_ITERATIONS, RAY_RTOL = 30, 1e-5


@dataclass
class SlewingLoadDiagram:
    """Static limiting load curve of a slewing ring and its closed-form comparison.

    Attributes
    ----------
    axial_force : ndarray (N,) [N]
        Allowable axial force F_a along the curve (from F_a = capacity at M = 0 to F_a = 0).
    moment : ndarray (N,) [N·m]
        Allowable tilting moment on the curve.
    axial_capacity, moment_capacity : float [N], [N·m]
        The makers' closed-form capacities C0a and C0a d_m / k (the straight line).
    p_limit : float [Pa]
    element : {"ball", "roller"}
    converged : ndarray (N,) of bool
    references : tuple of str
    """

    axial_force: np.ndarray
    moment: np.ndarray
    axial_capacity: float
    moment_capacity: float
    p_limit: float
    element: str
    converged: np.ndarray
    references: tuple = field(default=("rotheerde_static", "iso76", "harris2007"))

    def allowable_moment(self, axial_force) -> np.ndarray:
        """Allowable tilting moment [N·m] at ``axial_force`` [N] (linear interpolation on the curve)."""
        order = np.argsort(self.axial_force)
        return np.interp(axial_force, self.axial_force[order], self.moment[order], right=0.0)

    def utilisation(self, axial_force, moment) -> np.ndarray:
        """Load point's distance along its ray from the origin over the curve's [-] (< 1: below the curve).

        Parameters
        ----------
        axial_force, moment : array_like [N], [N·m]
            Reference loads (already multiplied by f_stat and combined).
        """
        fa = np.abs(np.asarray(axial_force, float)) / self.axial_capacity
        m = np.abs(np.asarray(moment, float)) / self.moment_capacity
        theta = np.arctan2(m, fa)
        curve_theta = np.arctan2(self.moment / self.moment_capacity, self.axial_force / self.axial_capacity)
        curve_r = np.hypot(self.moment / self.moment_capacity, self.axial_force / self.axial_capacity)
        order = np.argsort(curve_theta)
        return np.hypot(fa, m) / np.interp(theta, curve_theta[order], curve_r[order])

    def to_dict(self) -> dict:
        """JSON-ready dict (units in keys)."""
        return {
            "axial_force_N": self.axial_force.tolist(),
            "moment_Nm": self.moment.tolist(),
            "axial_capacity_N": self.axial_capacity,
            "moment_capacity_Nm": self.moment_capacity,
            "p_limit_Pa": self.p_limit,
            "element": self.element,
            "converged": self.converged.tolist(),
            "references": list(self.references),
        }


def reference_loads(load, f_stat=1.0, combination="I"):
    """Rothe Erde reference loads (F_a', M_k') [N], [N·m] of loads (C, 5) for one load combination.

    Parameters
    ----------
    load : array_like (C, 5) [N, N, N, N·m, N·m]
        (F_x, F_y, F_z, M_x, M_y) on the rotating ring.
    f_stat : float
        Application factor f_stat of the makers' tables (≥ 1).
    combination : {"I", "II"}
    """
    checks.positive("f_stat", f_stat)
    checks.one_of("combination", combination, LOAD_COMBINATIONS)
    load = np.atleast_2d(np.asarray(load, float))
    a, r, m = LOAD_COMBINATIONS[combination]
    fr = np.hypot(load[:, 0], load[:, 1])
    mk = np.hypot(load[:, 3], load[:, 4])
    return (a * np.abs(load[:, 2]) + r * fr) * f_stat, m * mk * f_stat


def _kind(model) -> str:
    kinds = {r.kind for r in model.rows}
    if kinds <= {"four_point", "ball"}:
        return "ball"
    if kinds <= {"crossed_roller", "cylindrical"}:
        return "roller"
    raise InputError(
        f"rows of kinds {sorted(kinds)} have no slewing-ring load diagram; expected four-point ball or "
        "crossed roller rows"
    )


def closed_form_capacities(model, p_limit=None) -> tuple[float, float, str]:
    """(C0a [N], moment capacity [N·m], element kind) of the makers' straight line (module docstring)."""
    from bearingkit.physics.contact import hertz, line

    element = _kind(model)
    p_lim = LIMIT_STRESS[element] if p_limit is None else float(p_limit)
    axial, dm = 0.0, 0.0
    for row, kernel in zip(model.rows, model.kernels, strict=True):
        alpha = abs(float(np.max(row.contact_angle)))
        d, dm_row = float(np.max(row.element_diameter)), float(np.max(row.pitch_diameter))
        if element == "ball":
            q0 = np.inf
            for side, f in (("inner", row.conformity_inner), ("outer", row.conformity_outer)):
                s, fd = hertz.ball_raceway_curvature(d, dm_row, alpha, float(np.max(f)) * d, side)
                p1 = float(hertz.point_contact(1.0, s, fd, kernel.e_reduced).max_pressure)
                q0 = min(q0, (p_lim / p1) ** 3)
            z_axial = row.n_elements
        else:
            gamma = d * np.cos(alpha) / dm_row
            rx = d / 2 * (1 - gamma)  # the inner contact is the more stressed one
            q0 = float((p_lim / line.line_pressure_factor(row.effective_length, rx, kernel.e_reduced)) ** 2)
            z_axial = row.n_elements // 2
        axial += z_axial * q0 * np.sin(alpha)
        dm = max(dm, dm_row)
    return axial, axial * dm / MOMENT_FACTOR[element], element


def static_load_diagram(model, *, n_points=9, p_limit=None, solver_options=None) -> SlewingLoadDiagram:
    """Static limiting load curve (F_a, M) of a slewing ring from the engine (module docstring).

    Parameters
    ----------
    model : BearingModel
        A slewing ring (four-point ball rows or a crossed roller row).
    n_points : int
        Rays between pure axial force and pure moment (≥ 2).
    p_limit : float or None [Pa]
        Static limit stress; default ISO 76 (4200 MPa balls, 4000 MPa rollers).
    solver_options : SolverOptions or None

    Returns
    -------
    SlewingLoadDiagram
        The curve; a ray whose solve fails is marked ``converged = False`` (never NaN).
    """
    from bearingkit.analysis.solver.quasistatic import load_vector, solve

    n = checks.integer("n_points", n_points, low=2)
    c0a, m0, element = closed_form_capacities(model, p_limit)
    p_lim = LIMIT_STRESS[element] if p_limit is None else float(p_limit)
    checks.positive("p_limit", p_lim, "Pa")
    theta = np.linspace(0.0, np.pi / 2, n)
    direction = np.stack([np.cos(theta) * c0a, np.sin(theta) * m0], axis=-1)  # closed-form line at λ ≈ 1
    scale = 1.0 / (np.cos(theta) + np.sin(theta))  # the straight line's λ along each ray
    expo = _PRESSURE_EXPONENT[element]  # first step: p ∝ λ^(1/n); then secants in log λ, log p
    converged = np.zeros(n, bool)
    last = None
    for _ in range(RAY_ITERATIONS):
        fa, m = direction[:, 0] * scale, direction[:, 1] * scale
        res = solve(model, load_vector(F_z=fa, M_y=-m), options=solver_options)
        p = np.max([st.max_pressure.max(axis=-1) for st in res.rows], axis=0)
        ok = res.converged & (p > 0)
        log_p = np.log(np.where(ok, p, 1.0))
        converged = ok & (np.abs(p / p_lim - 1.0) <= RAY_RTOL)
        if converged.all():
            break
        slope = np.full(n, 1.0 / expo)
        if last is not None:
            d_log = np.log(scale) - last[0]
            measured = np.where(
                np.abs(d_log) > 1e-12, (log_p - last[1]) / np.where(d_log == 0, 1, d_log), 0.0
            )
            slope = np.where((measured > 0.05) & (measured < 2.0), measured, slope)
        last = (np.log(scale), log_p)
        step = np.clip((np.log(p_lim) - log_p) / slope, -3.0, 3.0)
        scale = np.where(converged, scale, scale * np.where(ok, np.exp(step), 0.5))
    return SlewingLoadDiagram(
        axial_force=direction[:, 0] * scale,
        moment=direction[:, 1] * scale,
        axial_capacity=float(c0a),
        moment_capacity=float(m0),
        p_limit=p_lim,
        element=element,
        converged=converged,
    )
