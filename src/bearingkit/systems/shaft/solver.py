"""A shaft on several bearings: the system, its checks, and one global Newton over all bearings.

SI units (m, N, N·m, rad). The shaft is linear (Timoshenko elements, :mod:`bearingkit.systems.shaft.shaft`)
and the bearings are not (their rows' contact laws). Static condensation removes every shaft DOF that
no bearing touches, exactly (the shaft is linear): with seat DOFs s and interior DOFs i,

    K_c = K_ss − K_si K_ii⁻¹ K_is,    F_c = F_s − K_si K_ii⁻¹ F_i,    x_i = K_ii⁻¹ (F_i − K_is x_s),

K_ii is positive definite because fixing one seat node's five DOFs fixes the shaft (torsion is not
modelled). The unknowns are then x = (x_s, x_o): the seat DOFs and the outer-ring DOFs that a housing
spring (or nothing, for a floating bearing's axial DOF) holds. Each bearing b sees q_b = P_b x + c_b
in its own frame (:mod:`bearingkit.systems.shaft.supports`) and returns its contact force f_b(q_b), the
analytic Jacobian J_b and energy U_b. Equilibrium

    R(x) = F − K x + Σ_b P_bᵀ f_b(P_b x + c_b) = 0

is the stationary point of the convex potential Π = ½ xᵀ K x − F·x + Σ_b U_b, so the damped Newton
of the single-bearing solver (:mod:`bearingkit.analysis.solver.quasistatic`) applies unchanged: a vanishing
Levenberg term (no contact closed at the start), steps capped to 2 % of the smallest element diameter,
Armijo backtracking on the cases still backtracking only, steps never along unloaded zero-stiffness
mechanisms (an unloaded floating bearing's outer ring), load continuation for the cases that fail;
every step is one batched solve over the load cases. Rotations are scaled by the largest bearing
pitch radius L so the residual is one relative number: max |R| (moments / L) ≤ rtol × the load scale
(the largest external or bearing force).

Speed: each bearing's law has its rows at the load case's shaft speed
(:meth:`~bearingkit.systems.shaft.supports.BearingSeat.law_at`, per case), and a case where a bearing at
speed is beyond what the speed model holds is marked not converged with the reason, as a
single-bearing solve at speed (:func:`bearingkit.analysis.solver.speed.flag_beyond_model`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.linalg import cho_factor, cho_solve

from bearingkit import checks
from bearingkit.analysis.solver.quasistatic import _merge, _newton
from bearingkit.errors import ConvergenceError, InputError
from bearingkit.lazy import cached_property
from bearingkit.rows.base import LOAD_NAMES, N_DOF
from bearingkit.systems.shaft.beam import NODE_DOF
from bearingkit.systems.shaft.loads import ShaftLoads
from bearingkit.systems.shaft.shaft import Shaft, nodal_loads
from bearingkit.systems.shaft.supports import BearingSeat

#: Names of the shaft's rigid-body modes, in the order of :func:`rigid_modes`.
MODE_NAMES = (
    "translation along x",
    "translation along y",
    "translation along z",
    "tilt about x",
    "tilt about y",
)
#: Relative singular value below which the bearings leave a rigid-body mode of the shaft free [-].
SUPPORT_RTOL = 1e-9


@dataclass(frozen=True)
class SystemOptions:
    """Tolerances and limits of the system Newton (see the single-bearing ``SolverOptions``).

    Parameters
    ----------
    rtol : float
        Converged when max |scaled residual| ≤ rtol × load scale.
    max_iterations : int
        Newton iterations per attempt.
    max_step : float or None [m]
        Largest change of any scaled DOF in one step; default 2 % of the smallest element diameter.
    continuation_steps : int
        Load fractions tried for cases that fail the plain attempt (0 disables continuation).
    divergence_limit : float
        A case whose scaled displacement exceeds this fraction of the smallest element diameter is
        declared diverged.
    """

    rtol: float = 1e-10
    max_iterations: int = 80
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


def rigid_modes(z: float, length: float = 1.0) -> np.ndarray:
    """Rigid-body modes (5, 5) of the shaft evaluated at axial position z [m] (rows: :data:`MODE_NAMES`).

    A tilt about x by θ moves the axis point at z by u_y = −θ z and rotates it by θ_x = θ; a tilt
    about y by u_x = θ z, θ_y = θ (module docstring of :mod:`bearingkit.systems.shaft.beam`). The tilt rows
    are per unit of θ·``length`` so every row is a displacement of the same size.
    """
    m = np.eye(N_DOF)
    m[3, 1], m[4, 0] = -z, z
    m[3:] /= length
    return m


@dataclass(frozen=True, eq=False)
class ShaftSystem:
    """A shaft, its bearings and what it carries.

    Parameters
    ----------
    shaft : Shaft
    bearings : tuple of BearingSeat
    gears : tuple of Gear
        Gears (geometry; their torques are given per load case in :class:`ShaftLoads`).
    masses : tuple of PointMass
    max_element_length : float or None [m]
        Mesh refinement (nodal results are exact; this only draws the lines). Default length/60.
    name : str
    """

    shaft: Shaft
    bearings: tuple
    gears: tuple = ()
    masses: tuple = ()
    max_element_length: float | None = None
    name: str = "shaft"

    def __post_init__(self):
        for attr in ("bearings", "gears", "masses"):
            object.__setattr__(self, attr, tuple(getattr(self, attr)))
        if not self.bearings:
            raise InputError("bearings (none): a shaft needs at least one bearing")
        for i, b in enumerate(self.bearings):
            if not isinstance(b, BearingSeat):
                raise InputError(f"bearings[{i}] ({b!r}) is not a BearingSeat")
            self.shaft.check_position(f"bearings[{i}].position", b.position, f"bearing {b.name!r}")
        for kind, items in (("bearings", self.bearings), ("gears", self.gears)):
            names = [x.name for x in items]
            if len(set(names)) != len(names):
                raise InputError(f"{kind} names ({names}) must be unique")
        for i, g in enumerate(self.gears):
            self.shaft.check_position(f"gears[{i}].position", g.position, f"gear {g.name!r}")
        for i, m in enumerate(self.masses):
            self.shaft.check_position(f"masses[{i}].position", m.position, f"mass {m.name!r}")
        if self.max_element_length is not None:
            self.shaft.check_element_length(self.max_element_length)  # before any mesh is built
        self._check_supports()

    @cached_property
    def char_length(self) -> float:
        """L [m]: largest pitch radius of the bearings (rotation scale), else the largest shaft radius."""
        radii = [b.law.char_length for b in self.bearings]
        return max([*radii, max(s.outer_diameter for s in self.shaft.sections) / 2])

    def bearing(self, name: str) -> BearingSeat:
        """The bearing seat called ``name``."""
        for b in self.bearings:
            if b.name == name:
                return b
        raise InputError(
            f"bearing ({name!r}) not in the system; bearings are {[b.name for b in self.bearings]}"
        )

    def _check_supports(self) -> None:
        """Refuse a shaft the bearings cannot hold: no axial locating bearing, or a free rigid-body mode."""
        axial = [b for b in self.bearings if np.abs(b.global_reach[:, 2]).max(initial=0.0) > 0.0]
        if not axial:
            located = [b.name for b in self.bearings if b.axial == "locating"]
            hint = (
                f"the locating bearing(s) {located} carry no axial load (e.g. NU cylindrical rollers)"
                if located
                else "every bearing is floating"
            )
            raise InputError(
                f'bearings: no axial locating bearing ({hint}); set axial = "locating" on a bearing that '
                "carries axial load (deep groove, angular contact, tapered)"
            )
        rows = [b.global_reach @ rigid_modes(b.position, self.char_length).T for b in self.bearings]
        g = np.concatenate(rows, axis=0)
        _, sv, vt = np.linalg.svd(g, full_matrices=True)
        sv = np.concatenate([sv, np.zeros(N_DOF - len(sv))])
        free = sv <= SUPPORT_RTOL * max(sv.max(), 1e-300)
        if free.any():
            mode = vt[int(np.flatnonzero(free)[0])]
            worst = MODE_NAMES[int(np.argmax(np.abs(mode)))]
            raise InputError(
                f"bearings: the bearings leave the shaft free in {worst} (e.g. a single bearing without tilt "
                "stiffness, or every bearing at one position); add a bearing or a tilt-stiff bearing"
            )

    def positions(self, loads: ShaftLoads | None = None) -> list[float]:
        """Positions that must be mesh nodes: seats, gears, masses and the loads' positions [m]."""
        pts = [b.position for b in self.bearings] + [g.position for g in self.gears]
        pts += [m.position for m in self.masses]
        if loads is not None:
            pts += [f.position for f in loads.forces]
            pts += [x for q in loads.line_loads for x in (q.start, q.end)]
        return pts

    def check_loads(self, loads: ShaftLoads) -> None:
        """InputError naming the field for a load outside the shaft or an unknown gear."""
        for i, f in enumerate(loads.forces):
            self.shaft.check_position(f"forces[{i}].position", f.position, f"force {f.name!r}")
        for i, q in enumerate(loads.line_loads):
            self.shaft.check_position(f"line_loads[{i}].start", q.start, f"line load {q.name!r}")
            self.shaft.check_position(f"line_loads[{i}].end", q.end, f"line load {q.name!r}")
        known = [g.name for g in self.gears]
        for name in loads.gear_torques:
            if name not in known:
                raise InputError(f"gears.{name}: no gear of that name on the shaft; gears are {known}")


class _Problem:
    """The condensed, scaled system for the Newton of :mod:`bearingkit.analysis.solver.quasistatic`."""

    def __init__(self, laws, projections, offsets, stiffness, scale, options, limit, max_step):
        self.laws = laws
        self.P = projections  # list of (5, n)
        self.c = offsets  # list of (5,)
        self.K = stiffness  # (n, n)
        self.scale = scale  # (n,)
        self.idx = np.arange(len(scale))
        self.options = options
        self.limit = limit
        self.max_step = max_step

    def bearing_states(self, x):
        return [law.response(x @ P.T + c) for law, P, c in zip(self.laws, self.P, self.c, strict=True)]

    def state(self, x, load):
        s = self.scale
        resp = self.bearing_states(x)
        kx = x @ self.K
        residual = load - kx
        jac = np.broadcast_to(-self.K, (x.shape[0], *self.K.shape)).copy()
        potential = 0.5 * np.einsum("ci,ci->c", x, kx) - np.einsum("ci,ci->c", load, x)
        row_max = np.zeros(x.shape[0])
        for r, P in zip(resp, self.P, strict=True):
            fg = r.force @ P  # (C, n): P_bᵀ f_b
            residual += fg
            jac += np.einsum("ai,cab,bj->cij", P, r.jacobian, P)
            potential += r.energy
            row_max = np.maximum(row_max, np.abs(fg * s).max(axis=1))
        load_scale = np.maximum(np.maximum(np.abs(load * s).max(axis=1), row_max), 1e-12)
        norm = np.abs(residual * s).max(axis=1) / load_scale
        return dict(force=residual, jac=jac, potential=potential, residual=residual, norm=norm, q=x)

    def take(self, cases: np.ndarray) -> _Problem:
        out = object.__new__(_Problem)
        out.__dict__.update(self.__dict__)
        out.laws = [law.take(cases) for law in self.laws]
        return out


@dataclass
class _Assembly:
    """Mesh, condensation and the system's unknowns for one batch of loads."""

    mesh: object
    seat_nodes: np.ndarray  # (B,) node of each bearing
    seat_dofs: np.ndarray  # (n_s,) global shaft DOFs kept
    interior: np.ndarray  # (n_i,) condensed out
    factor: tuple | None  # Cholesky of K_ii
    coupling: np.ndarray  # K_ii⁻¹ K_is (n_i, n_s)
    stiffness: np.ndarray  # (n, n) condensed + housing springs
    load: np.ndarray  # (C, n)
    nodal: np.ndarray  # (C, 5N) nodal loads of the full shaft
    projections: list  # per bearing (5, n)
    offsets: list  # per bearing (5,)
    outer_index: list  # per bearing: (5,) index into x of each outer DOF, −1 where held
    scale: np.ndarray  # (n,)
    n_seat: int = 0
    extras: dict = field(default_factory=dict)


def assemble(system: ShaftSystem, loads: ShaftLoads) -> _Assembly:
    """Mesh the shaft, condense it onto the seats and set up the unknowns (module docstring)."""
    system.check_loads(loads)
    mesh = system.shaft.mesh(system.positions(loads), system.max_element_length)
    nodal = nodal_loads(mesh, loads, system.gears, system.masses)
    seat_nodes = np.array([mesh.node(b.position) for b in system.bearings])
    kept = np.unique(seat_nodes)
    seat_dofs = (NODE_DOF * kept[:, None] + np.arange(NODE_DOF)[None, :]).ravel()
    interior = np.setdiff1d(np.arange(mesh.n_dof), seat_dofs)
    k = mesh.stiffness
    k_ss = k[np.ix_(seat_dofs, seat_dofs)]
    if len(interior):
        k_ii = k[np.ix_(interior, interior)]
        k_is = k[np.ix_(interior, seat_dofs)]
        factor = cho_factor(k_ii)
        coupling = cho_solve(factor, k_is)
        k_c = k_ss - k_is.T @ coupling
        f_c = nodal[:, seat_dofs] - nodal[:, interior] @ coupling
    else:
        factor, coupling = None, np.zeros((0, len(seat_dofs)))
        k_c, f_c = k_ss, nodal[:, seat_dofs]
    n_s = len(seat_dofs)
    # Outer-ring unknowns: every DOF held by a finite spring (0 for a floating axial DOF).
    outer_index, springs, refs = [], [], []
    n = n_s
    for b in system.bearings:
        kb = b.outer_springs()
        idx = np.full(N_DOF, -1)
        for d in np.flatnonzero(np.isfinite(kb)):
            idx[d] = n
            springs.append(kb[d])
            refs.append(b.outer_position[d])
            n += 1
        outer_index.append(idx)
    stiffness = np.zeros((n, n))
    stiffness[:n_s, :n_s] = 0.5 * (k_c + k_c.T)  # symmetric to round-off
    stiffness[np.arange(n_s, n), np.arange(n_s, n)] = springs
    load = np.zeros((loads.n_cases, n))
    load[:, :n_s] = f_c
    load[:, n_s:] = np.asarray(springs) * np.asarray(refs)  # a sprung housing pulls to its reference
    projections, offsets = [], []
    for b, node, idx in zip(system.bearings, seat_nodes, outer_index, strict=True):
        t = b.transform
        p = np.zeros((N_DOF, n))
        col = np.searchsorted(kept, node) * NODE_DOF
        p[:, col : col + NODE_DOF] = t
        held = idx < 0
        c = -t @ np.where(held, b.outer_position, 0.0)
        for d in np.flatnonzero(~held):
            p[:, idx[d]] -= t[:, d]
        projections.append(p)
        offsets.append(c)
    rot = np.zeros(n, bool)
    rot[:n_s] = np.tile(np.arange(NODE_DOF) >= 3, len(kept))
    for idx in outer_index:
        rot[idx[3:][idx[3:] >= 0]] = True
    scale = np.where(rot, 1.0 / system.char_length, 1.0)
    return _Assembly(
        mesh=mesh,
        seat_nodes=seat_nodes,
        seat_dofs=seat_dofs,
        interior=interior,
        factor=factor,
        coupling=coupling,
        stiffness=stiffness,
        load=load,
        nodal=nodal,
        projections=projections,
        offsets=offsets,
        outer_index=outer_index,
        scale=scale,
        n_seat=n_s,
    )


def _starting_point(problem: _Problem, load: np.ndarray) -> np.ndarray:
    """A start from the linearised system with every contact closed at a common approach per bearing.

    K(δ) = K + Σ_b P_bᵀ (Σ_rows n δ_b^(n−1) M) P_b, solved for the load; δ_b is updated to the largest
    relative displacement of bearing b (a few fixed-point sweeps, as the single-bearing start). The
    estimate is kept per case only where it lowers the potential below the unloaded start's.
    """
    n_cases, n = load.shape
    delta = [np.full(n_cases, 1e-4 * law.deflection_scale) for law in problem.laws]
    x = np.zeros_like(load)
    for _ in range(6):
        k = np.broadcast_to(problem.K, (n_cases, n, n)).copy()
        for law, P, d in zip(problem.laws, problem.P, delta, strict=True):
            kb = sum(e * d[:, None, None] ** (e - 1) * m for m, e in law.start_terms)
            k += np.einsum("ai,cab,bj->cij", P, kb, P)
        s = problem.scale
        ks = k * s[:, None] * s[None, :]
        ks += 1e-12 * np.abs(ks).max(axis=(1, 2))[:, None, None] * np.eye(n)
        try:
            x = np.linalg.solve(ks, (load * s)[..., None])[..., 0] * s
        except np.linalg.LinAlgError:
            return np.zeros_like(load)
        for i, (P, c) in enumerate(zip(problem.P, problem.c, strict=True)):
            q = x @ P.T + c
            approach = np.abs(q[:, :3]).max(axis=1)
            delta[i] = np.sqrt(delta[i] * np.maximum(approach, 1e-3 * delta[i]))
    x = np.where(np.isfinite(x).all(axis=1, keepdims=True), x, 0.0)
    better = problem.state(x, load)["potential"] < problem.state(np.zeros_like(x), load)["potential"]
    return np.where(better[:, None], x, 0.0)


def solve(
    system: ShaftSystem,
    loads: ShaftLoads,
    options: SystemOptions | None = None,
    raise_on_failure: bool = False,
):
    """Solve the shaft on its bearings for a batch of load cases.

    Parameters
    ----------
    system : ShaftSystem
    loads : ShaftLoads
        The load cases (leading axis C).
    options : SystemOptions, optional
    raise_on_failure : bool
        Raise :class:`~bearingkit.errors.ConvergenceError` (carrying the result) if a case fails.

    Returns
    -------
    bearingkit.systems.shaft.result.ShaftResult
    """
    from bearingkit.systems.shaft.result import ShaftResult

    options = options or SystemOptions()
    asm = assemble(system, loads)
    # Rows at the cases' shaft speed (the zero-speed laws themselves when nothing turns).
    laws = [b.law_at(loads.speed) for b in system.bearings]
    d_min = min(law.deflection_scale for law in laws)
    problem = _Problem(
        laws,
        asm.projections,
        asm.offsets,
        asm.stiffness,
        asm.scale,
        options,
        options.divergence_limit * d_min,
        options.max_step if options.max_step is not None else 0.02 * d_min,
    )
    load = asm.load
    n_cases = load.shape[0]
    iterations = np.zeros(n_cases, int)
    start = _starting_point(problem, load)
    everyone = np.ones(n_cases, bool)
    x, converged, st, diverged = _newton(problem, start, load, everyone, iterations)
    if options.continuation_steps and not converged.all():
        retry = ~converged
        fixed = np.zeros_like(load)
        fixed[:, asm.n_seat :] = load[:, asm.n_seat :]  # housing references are geometry, not load
        xc = np.where(retry[:, None], 0.0, x)
        for frac in np.linspace(1.0 / options.continuation_steps, 1.0, options.continuation_steps):
            ramp = np.where(retry[:, None], fixed + frac * (load - fixed), load)
            xc, conv_c, st_c, div_c = _newton(problem, xc, ramp, retry, iterations)
        x = np.where(retry[:, None], xc, x)
        st = _merge(st, st_c, retry)
        converged = np.where(retry, conv_c, converged)
        diverged = np.where(retry, div_c, diverged)
    broken = ~(np.isfinite(x).all(axis=1) & np.isfinite(st["norm"]))
    if broken.any():
        x = np.where(broken[:, None], 0.0, x)
        converged &= ~broken
    reasons = [None] * n_cases
    for c in np.flatnonzero(~converged):
        reasons[c] = (
            "numerical failure: the iterate became non-finite"
            if broken[c]
            else _diagnose(system, asm, c, bool(diverged[c]), float(st["norm"][c]))
        )
    result = ShaftResult(
        system=system,
        loads=loads,
        assembly=asm,
        unknowns=x,
        converged=converged,
        iterations=iterations,
        residual_norm=st["norm"],
        reason=reasons,
        laws=laws,
    )
    _flag_beyond_model(result)
    if raise_on_failure and not converged.all():
        bad = int(np.flatnonzero(~converged)[0])
        raise ConvergenceError(f"load case {loads.names[bad]!r} did not converge: {reasons[bad]}", result)
    return result


def _flag_beyond_model(result) -> None:
    """Cases where a bearing at speed is beyond what the speed model holds: not converged, with the
    reason (:func:`bearingkit.analysis.solver.speed.flag_beyond_model` on each bearing's state), in place."""
    from bearingkit.analysis.solver.speed import ModelAtSpeed, flag_beyond_model

    for b, law in zip(result.system.bearings, result.laws, strict=True):
        if not isinstance(law.bearing, ModelAtSpeed):
            continue
        state = result.bearing_result(b.name)
        before = state.converged.copy()
        flag_beyond_model(state)
        for c in np.flatnonzero(before & ~state.converged):
            result.converged[c] = False
            result.reason[c] = f"bearing {b.name!r}: {state.reason[c]}"
    for state in result._bearing_results.values():  # the system's final convergence (states kept)
        state.converged = result.converged.copy()
        state.reason = list(result.reason)


def _diagnose(system: ShaftSystem, asm: _Assembly, case: int, diverged: bool, norm: float) -> str:
    """One-line reason: an external load no combination of bearing contacts balances, or divergence."""
    from scipy.optimize import nnls

    # Resultant of the external loads on the rigid-body modes (about z = 0), against the cone of the
    # bearings' contact directions on the same modes.
    nodal = asm.nodal[case].reshape(-1, NODE_DOF)
    f = sum(rigid_modes(z, system.char_length) @ fz for z, fz in zip(asm.mesh.z, nodal, strict=True))
    g = np.concatenate(
        [b.global_reach @ rigid_modes(b.position, system.char_length).T for b in system.bearings]
    )
    # Contacts resist the directions g: the load must be a non-negative combination of them.
    _, miss = nnls(g.T, f)
    size = max(np.linalg.norm(f), 1e-300)
    if miss > 1e-3 * size:
        comp = f - g.T @ nnls(g.T, f)[0]
        worst = LOAD_NAMES[int(np.argmax(np.abs(comp)))]
        return (
            "the load cannot be carried: no combination of the bearings' contact forces balances it "
            f"(unbalanced mainly in {worst} of the shaft)"
        )
    if diverged:
        return (
            "displacement diverged beyond half an element diameter: the load exceeds what the bearings carry"
        )
    return f"Newton did not reach the tolerance (residual {norm:.3g} of the load scale)"
