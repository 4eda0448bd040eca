"""One global Newton over a drivetrain: every shaft condensed, every bearing's law, every gear mesh.

SI units (m, N, N·m, rad). Each shaft is condensed exactly onto its kept nodes (bearing seats, gears,
carrier plates) as in :mod:`bearingkit.systems.shaft.solver` (K_c = K_ss − K_si K_ii⁻¹ K_is); the unknowns x
are the kept nodes' five DOFs of every shaft, one rotation θ_z per shaft (none for the held shaft),
and the outer-ring DOFs held by a finite housing spring or free (a floating bearing's axial DOF).

A point on a body at node DOFs (u, θ) and θ_z, on a rigid arm r from the node, moves by u + θ × r
(θ = (θ_x, θ_y, θ_z)); its tilts are the node's. That gives each bearing ring, pin and gear contact a
linear map of x. Each bearing sees q_b = P_b x + c_b with P_b = T (A_inner − A_outer) and the constant
c_b from the housing's prescribed outer-ring position and a pin's position error; each mesh m a
deflection δ_m = g_m·x along its line of action n_m (the flank loaded in that case), energy ½ k_m δ_m².
Equilibrium is the stationary point of the convex potential

    Π(x) = ½ xᵀ K x + Σ_m ½ k_m (g_m·x)² − F·x + Σ_b U_b(P_b x + c_b),

so the damped Newton of the single bearing (:func:`bearingkit.analysis.solver.quasistatic._newton`) solves
all load cases in one batch, as for one shaft. The loaded flank of each mesh is found first from the
same system with every bearing linearised as a stiff spring (the torque flow fixes the sign of every
mesh force); a mesh that would pull (δ < 0) after the solve is reported (tooth contact lost).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.linalg import cho_factor, cho_solve

from bearingkit.analysis.solver.quasistatic import _blas_serial, _merge, _newton
from bearingkit.errors import InputError
from bearingkit.rows.base import N_DOF
from bearingkit.systems.drivetrain.model import HOUSING, Drivetrain
from bearingkit.systems.shaft.beam import NODE_DOF
from bearingkit.systems.shaft.shaft import nodal_loads

# The shaft's linearised start takes a stiffness per case (K (C, n, n): the meshes' loaded flanks) too.
from bearingkit.systems.shaft.solver import SystemOptions, _starting_point
from bearingkit.systems.shaft.supports import BearingLaw

#: Stiffness of the bearings in the flank pre-pass, relative to the stiffest mesh [-] (only the sign
#: of the mesh forces is used: they follow the torque flow).
PREPASS_STIFFNESS_FACTOR = 1e3


def point_map(theta_z_col: int | None, node_cols: np.ndarray | None, arm, n: int) -> np.ndarray:
    """Rows (5, n): (u_x, u_y, u_z, θ_x, θ_y) of a point on a rigid arm r from a node (module docstring).

    ``node_cols``: the 5 columns of the node's DOFs in x (None: the housing); ``theta_z_col``: the
    column of the body's rotation (None: held)."""
    a = np.zeros((N_DOF, n))
    if node_cols is None:
        return a
    rx, ry, rz = (float(v) for v in arm)
    a[:, node_cols] = np.eye(N_DOF)
    # u + θ × r with θ = (θ_x, θ_y, θ_z)
    a[0, node_cols[4]] += rz
    a[1, node_cols[3]] -= rz
    a[2, node_cols[3]] += ry
    a[2, node_cols[4]] -= rx
    if theta_z_col is not None:
        a[0, theta_z_col] -= ry
        a[1, theta_z_col] += rx
    return a


@dataclass
class ShaftBlock:
    """One shaft's mesh, condensation and place in x."""

    body: object
    mesh: object
    kept_nodes: np.ndarray
    seat_dofs: np.ndarray
    interior: np.ndarray
    factor: tuple | None
    coupling: np.ndarray
    k_c: np.ndarray
    nodal: np.ndarray  # (C, 5N)
    offset: int  # first column in x
    theta_z: int | None  # column of θ_z

    @property
    def n_seat(self) -> int:
        return len(self.seat_dofs)

    def node_cols(self, z: float) -> np.ndarray:
        node = self.mesh.node(z)
        k = int(np.searchsorted(self.kept_nodes, node))
        if k >= len(self.kept_nodes) or self.kept_nodes[k] != node:
            raise InputError(f"shaft {self.body.name!r}: position {z * 1e3:.6g} mm is not a kept node")
        return self.offset + NODE_DOF * k + np.arange(NODE_DOF)


@dataclass
class DrivetrainAssembly:
    """The drivetrain's unknowns, linear stiffness, loads, bearing maps and mesh rows."""

    blocks: dict
    n: int
    stiffness: np.ndarray  # (n, n) shafts + housing springs
    load: np.ndarray  # (C, n)
    projections: list  # per bearing (5, n)
    offsets: list  # per bearing (5,)
    outer_maps: list  # per bearing: (5, n) map of the outer ring in the gearbox frame, (5,) constant
    inner_maps: list
    mesh_rows: list  # per mesh: dict(g=(C, n), n=(C, 3), flank=(C,), k, geometry)
    scale: np.ndarray
    extras: dict = field(default_factory=dict)


def _kept_positions(dt: Drivetrain, body) -> list[float]:
    pts = [g.position for g in body.gears] + [m.position for m in body.masses]
    for b in dt.bearings:
        for att in (b.inner, b.outer):
            if att.body == body.name:
                pts.append(att.position)
    return pts


def assemble(dt: Drivetrain, loads: dict, flank=None) -> DrivetrainAssembly:
    """Mesh and condense every shaft, place the unknowns, the bearings' maps and the meshes' rows.

    ``loads``: per shaft a :class:`~bearingkit.systems.shaft.loads.ShaftLoads` (point and line loads, gravity)
    and ``"torques"`` {shaft: (C,) [N·m]} about +z. ``flank``: per mesh (C,) ±1 (None: +1).
    """
    blocks, col = {}, 0
    n_cases = loads["n_cases"]
    for body in dt.shafts:
        sl = loads["shafts"][body.name]
        kept_pts = _kept_positions(dt, body)
        extra = [f.position for f in sl.forces] + [x for q in sl.line_loads for x in (q.start, q.end)]
        mesh = body.shaft.mesh(kept_pts + extra, body.max_element_length)
        nodal = nodal_loads(mesh, sl, body.gears, body.masses)
        kept = np.unique([mesh.node(z) for z in kept_pts])
        seat_dofs = (NODE_DOF * kept[:, None] + np.arange(NODE_DOF)[None, :]).ravel()
        interior = np.setdiff1d(np.arange(mesh.n_dof), seat_dofs)
        k = mesh.stiffness
        k_ss = k[np.ix_(seat_dofs, seat_dofs)]
        if len(interior):
            factor = cho_factor(k[np.ix_(interior, interior)])
            k_is = k[np.ix_(interior, seat_dofs)]
            coupling = cho_solve(factor, k_is)
            k_c = k_ss - k_is.T @ coupling
        else:
            factor, coupling, k_c = None, np.zeros((0, len(seat_dofs))), k_ss
        blocks[body.name] = ShaftBlock(
            body, mesh, kept, seat_dofs, interior, factor, coupling, k_c, nodal, col, None
        )
        col += len(seat_dofs)
    # A rotation θ_z for the bodies whose rotation something resists or loads: gears in mesh, carriers
    # (pins on arms) and shafts with an input torque; another shaft's θ_z would be a free mode.
    turning = {ref[0] for m in dt.meshes for ref in (m.a, m.b)}
    turning |= {b.inner.body for b in dt.bearings if b.inner.arm[0] or b.inner.arm[1]}
    for name in loads["torques"]:
        if name not in turning:
            raise InputError(
                f"load_cases.torques.{name}: shaft {name!r} has no gear in mesh: nothing carries its torque; "
                "give the torque on a geared shaft"
            )
    for body in dt.shafts:
        if body.name != dt.held and body.name in turning:
            blocks[body.name].theta_z = col
            col += 1
    n_struct = col

    def att_map(att, n_total):
        if att.body == HOUSING:
            return np.zeros((N_DOF, n_total))
        blk = blocks[att.body]
        return point_map(blk.theta_z, blk.node_cols(att.position), att.arm, n_total)

    # Outer-ring unknowns (finite housing springs, floating axial DOFs).
    outer_index, springs = [], []
    n = n_struct
    for b in dt.bearings:
        kb = b.seat.outer_springs()
        idx = np.full(N_DOF, -1)
        for d in np.flatnonzero(np.isfinite(kb)):
            idx[d] = n
            springs.append((n, d, kb[d], b))
            n += 1
        outer_index.append(idx)
    stiffness = np.zeros((n, n))
    load = np.zeros((n_cases, n))
    for blk in blocks.values():
        sl = slice(blk.offset, blk.offset + blk.n_seat)
        stiffness[sl, sl] = 0.5 * (blk.k_c + blk.k_c.T)
        f = blk.nodal
        if len(blk.interior):
            f_c = f[:, blk.seat_dofs] - f[:, blk.interior] @ blk.coupling
        else:
            f_c = f[:, blk.seat_dofs]
        load[:, sl] = f_c
        if blk.theta_z is not None:
            load[:, blk.theta_z] = loads["torques"].get(blk.body.name, 0.0)
    projections, offsets, outer_maps, inner_maps = [], [], [], []
    for b, idx in zip(dt.bearings, outer_index, strict=True):
        host_out = att_map(b.outer, n)
        ref_out = b.seat.outer_position  # (0, 0, axial_offset, 0, 0) relative to the host point
        a_in = att_map(b.inner, n)
        c_in = np.array([b.inner.error[0], b.inner.error[1], 0.0, 0.0, 0.0])
        a_out = host_out.copy()
        c_out = ref_out.copy()
        for d in np.flatnonzero(idx >= 0):
            a_out[d] = 0.0
            a_out[d, idx[d]] = 1.0
            c_out[d] = 0.0
        t = b.seat.transform
        projections.append(t @ (a_in - a_out))
        offsets.append(t @ (c_in - c_out))
        outer_maps.append((a_out, c_out))
        inner_maps.append((a_in, c_in))
    for col_o, d, kd, b in springs:  # outer ring sprung to its host point + the reference
        i = dt.bearings.index(b)
        host = att_map(b.outer, n)[d]
        row = -host.copy()
        row[col_o] += 1.0
        stiffness += kd * np.outer(row, row)
        load[:, :] += kd * b.seat.outer_position[d] * row[None, :]
        del i
    mesh_rows = []
    for mi, m in enumerate(dt.meshes):
        geo = dt.mesh_geometry(m)
        s = np.ones(n_cases) if flank is None else np.asarray(flank[mi], dtype=float)
        nvec = m.pair.direction(geo["e"], s)  # (C, 3)
        ga, gb = (_gear_point(dt, blocks, ref, p, n) for ref, p in ((m.a, geo["p_a"]), (m.b, geo["p_b"])))
        g = np.einsum("ck,kn->cn", nvec, ga[:3] - gb[:3])
        mesh_rows.append({"g": g, "n": nvec, "flank": s, "k": m.k, "geometry": geo, "a_map": ga, "b_map": gb})
    rot = np.zeros(n, bool)
    for blk in blocks.values():
        rot[blk.offset : blk.offset + blk.n_seat] = np.tile(np.arange(NODE_DOF) >= 3, len(blk.kept_nodes))
        if blk.theta_z is not None:
            rot[blk.theta_z] = True
    for idx in outer_index:
        rot[idx[3:][idx[3:] >= 0]] = True
    scale = np.where(rot, 1.0 / dt.char_length, 1.0)
    return DrivetrainAssembly(
        blocks,
        n,
        stiffness,
        load,
        projections,
        offsets,
        outer_maps,
        inner_maps,
        mesh_rows,
        scale,
        {"outer_index": outer_index, "n_struct": n_struct},
    )


def _gear_point(dt, blocks, ref, arm_xy, n) -> np.ndarray:
    body, name = ref
    if body == HOUSING:
        return np.zeros((N_DOF, n))
    blk = blocks[body]
    g = blk.body.gear(name)
    return point_map(blk.theta_z, blk.node_cols(g.position), (arm_xy[0], arm_xy[1], 0.0), n)


def mesh_stiffness_matrix(asm: DrivetrainAssembly) -> np.ndarray:
    """K_c (C, n, n) = the shafts' and housing springs' K plus Σ_m k_m g_m g_mᵀ per case."""
    k = np.broadcast_to(asm.stiffness, (asm.load.shape[0], asm.n, asm.n)).copy()
    for row in asm.mesh_rows:
        k += row["k"] * np.einsum("ci,cj->cij", row["g"], row["g"])
    return k


class _Problem:
    """The scaled drivetrain for :func:`bearingkit.analysis.solver.quasistatic._newton` (K per case)."""

    def __init__(self, laws, projections, offsets, stiffness, scale, options, limit, max_step):
        self.laws, self.P, self.c = laws, projections, offsets
        self.K = stiffness  # (C, n, n)
        self.scale = scale
        self.idx = np.arange(len(scale))
        self.options, self.limit, self.max_step = options, limit, max_step

    def bearing_states(self, x):
        return [law.response(x @ P.T + c) for law, P, c in zip(self.laws, self.P, self.c, strict=True)]

    def state(self, x, load):
        s = self.scale
        kx = np.einsum("cij,cj->ci", self.K, x)
        residual = load - kx
        jac = -self.K.copy()
        potential = 0.5 * np.einsum("ci,ci->c", x, kx) - np.einsum("ci,ci->c", load, x)
        row_max = np.zeros(x.shape[0])
        for r, P in zip(self.bearing_states(x), self.P, strict=True):
            fg = r.force @ P
            residual += fg
            jac += np.einsum("ai,cab,bj->cij", P, r.jacobian, P)
            potential += r.energy
            row_max = np.maximum(row_max, np.abs(fg * s).max(axis=1))
        load_scale = np.maximum(np.maximum(np.abs(load * s).max(axis=1), row_max), 1e-12)
        norm = np.abs(residual * s).max(axis=1) / load_scale
        return dict(force=residual, jac=jac, potential=potential, residual=residual, norm=norm, q=x)

    def take(self, cases):
        out = object.__new__(_Problem)
        out.__dict__.update(self.__dict__)
        out.laws = [law.take(cases) for law in self.laws]
        out.K = self.K[cases]
        return out


def _linear_solve(k: np.ndarray, load: np.ndarray, scale: np.ndarray) -> np.ndarray:
    ks = k * scale[None, :, None] * scale[None, None, :]
    return np.linalg.solve(ks, (load * scale)[..., None])[..., 0] * scale


def _prepass_stiffness(dt: Drivetrain, asm: DrivetrainAssembly) -> np.ndarray:
    """K (C, n, n) with every bearing as a stiff isotropic spring on the DOFs its rows reach."""
    k = mesh_stiffness_matrix(asm)
    kb = PREPASS_STIFFNESS_FACTOR * max([r["k"] for r in asm.mesh_rows], default=1e9)
    length = dt.char_length
    for b, p in zip(dt.bearings, asm.projections, strict=True):
        reach = np.abs(b.seat.law.reach).max(axis=0, initial=0.0) > 0.0
        d = np.where(reach, kb, 0.0) * np.array([1, 1, 1, length**2, length**2])
        k += (p.T * d) @ p
    return k


def free_body(dt: Drivetrain, asm: DrivetrainAssembly) -> str | None:
    """The body a free mode of the drivetrain moves (stiff-bearing system singular), or None."""
    k = _prepass_stiffness(dt, asm)[0]
    s = asm.scale
    ks = k * s[:, None] * s[None, :]
    lam, vec = np.linalg.eigh(0.5 * (ks + ks.T))
    if lam[0] > 1e-10 * lam[-1]:
        return None
    v = np.abs(vec[:, 0])
    col = int(np.argmax(v))
    for blk in asm.blocks.values():
        if blk.offset <= col < blk.offset + blk.n_seat or col == blk.theta_z:
            what = "rotation about its axis" if col == blk.theta_z else "displacement"
            return f"shaft {blk.body.name!r} ({what})"
    for b, idx in zip(dt.bearings, asm.extras["outer_index"], strict=True):
        if col in idx:
            return f"the outer ring of bearing {b.name!r}"
    return "the drivetrain"


def loaded_flanks(dt: Drivetrain, asm: DrivetrainAssembly) -> list[np.ndarray]:
    """Per mesh (C,) the loaded flank ±1 from the stiff-bearing pre-pass (module docstring)."""
    x = _linear_solve(_prepass_stiffness(dt, asm), asm.load, asm.scale)
    out = []
    for row in asm.mesh_rows:
        force = row["k"] * np.einsum("ci,ci->c", row["g"], x)
        out.append(np.where(force < 0.0, -row["flank"], row["flank"]))
    return out


def solve(dt: Drivetrain, loads: dict, laws: list, options: SystemOptions | None = None):
    """Solve the drivetrain for a batch of load cases (one Newton); returns a DrivetrainResult.

    ``laws``: per bearing the :class:`~bearingkit.systems.shaft.supports.BearingLaw` at the cases' speeds.
    BLAS runs on one thread meanwhile: its threads on these small systems (50–100 unknowns) only wait for
    one another, and on a busy machine for a core (measured with two busy processes on this 2-core
    machine: the two-stage gearbox 2.4–3.1 s with OpenBLAS's threads, 1.0–1.4 s with one; the planetary
    stage 1.4–2.9 s against 0.5–0.7 s; idle, the same within the scatter of 0.7–1.0 s and 0.4–0.6 s).
    """
    with _blas_serial():
        return _solve(dt, loads, laws, options)


def _solve(dt: Drivetrain, loads: dict, laws: list, options: SystemOptions | None):
    from bearingkit.systems.drivetrain.result import DrivetrainResult

    options = options or SystemOptions()
    asm0 = assemble(dt, loads)
    where = free_body(dt, asm0)
    if where is not None:
        raise InputError(
            f"{where} is free: no bearing or mesh holds it (e.g. a shaft on one bearing without tilt "
            "stiffness, a floating shaft with no axial support, or no held shaft); add a bearing or set "
            "`held`"
        )
    asm = assemble(dt, loads, loaded_flanks(dt, asm0))
    d_min = min(law.deflection_scale for law in laws)
    problem = _Problem(
        laws,
        asm.projections,
        asm.offsets,
        mesh_stiffness_matrix(asm),
        asm.scale,
        options,
        options.divergence_limit * d_min,
        options.max_step if options.max_step is not None else 0.02 * d_min,
    )
    # The shafts' rotations about their axes (the gear train's wind-up) are not capped or watched by
    # the divergence test (analysis.solver.newton.newton): the ratios amplify them without bound.
    problem.bounded = np.ones(asm.n, bool)
    problem.bounded[[b.theta_z for b in asm.blocks.values() if b.theta_z is not None]] = False
    load = asm.load
    n_cases = load.shape[0]
    iterations = np.zeros(n_cases, int)
    everyone = np.ones(n_cases, bool)
    x, converged, st, diverged = _newton(problem, _starting_point(problem, load), load, everyone, iterations)
    if options.continuation_steps and not converged.all():
        retry = ~converged
        n_struct = asm.extras["n_struct"]
        fixed = np.zeros_like(load)
        fixed[:, n_struct:] = load[:, n_struct:]
        xc = np.where(retry[:, None], 0.0, x)
        for frac in np.linspace(1.0 / options.continuation_steps, 1.0, options.continuation_steps):
            ramp = np.where(retry[:, None], fixed + frac * (load - fixed), load)
            xc, conv_c, st_c, div_c = _newton(problem, xc, ramp, retry, iterations)
        x = np.where(retry[:, None], xc, x)
        st = _merge(st, st_c, retry)
        converged = np.where(retry, conv_c, converged)
        diverged = np.where(retry, div_c, diverged)
    broken = ~(np.isfinite(x).all(axis=1) & np.isfinite(st["norm"]))
    x = np.where(broken[:, None], 0.0, x)
    converged &= ~broken
    reasons = [None] * n_cases
    for c in np.flatnonzero(~converged):
        if broken[c]:
            reasons[c] = "numerical failure: the iterate became non-finite"
        elif diverged[c]:
            reasons[c] = "displacement diverged: the load exceeds what the bearings carry"
        else:
            reasons[c] = (
                f"Newton did not reach the tolerance (residual {float(st['norm'][c]):.3g} of the load scale)"
            )
    return DrivetrainResult(dt, loads, asm, x, converged, iterations, st["norm"], reasons, laws)


def law_for(bearing, inner_speed, outer_speed) -> BearingLaw:
    """The bearing's law with its rows at the ring speeds (C,) [rad/s] in its load frame, bearing axis."""
    from bearingkit.analysis.solver.model import BearingModel
    from bearingkit.analysis.solver.speed import OperatingSpeed, model_at_speed

    seat = bearing.seat
    if not isinstance(seat.bearing, BearingModel) or (inner_speed is None and outer_speed is None):
        return seat.law
    base = seat.speed_of(np.zeros(1))
    t = seat.transform[2, 2]
    speed = OperatingSpeed(
        t * np.asarray(inner_speed, float),
        t * np.asarray(outer_speed, float),
        base.element_density,
        base.raceway_control,
    )
    if not speed.moving:
        return seat.law
    try:
        return BearingLaw(model_at_speed(seat.bearing, speed))
    except InputError as exc:
        raise InputError(f"bearings.{seat.name}: {exc}") from None
