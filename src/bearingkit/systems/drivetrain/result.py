"""Results of a drivetrain: every bearing's state, every mesh's force, every shaft's lines.

SI units, gearbox axes. Per bearing (as :class:`~bearingkit.systems.shaft.result.ShaftResult` gives them for
one shaft): the relative displacement q of its rings and the load it carries in its own frame, the
force and moment it puts on the body of its inner ring, its tangent stiffness and its full
QuasiStaticResult. Per mesh: the force F = k δ along the line of action n (positive: the teeth push),
its tangential, radial and axial parts on each gear and the torque it puts on each body. Per shaft: a
:class:`~bearingkit.systems.shaft.result.ShaftResult` view for the deflection, shear and bending-moment lines
(exact nodal values, as for one shaft).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from types import SimpleNamespace

import numpy as np

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.lazy import cached_property
from bearingkit.rows.base import DOF_NAMES, LOAD_NAMES, N_DOF
from bearingkit.systems.drivetrain.model import HOUSING
from bearingkit.systems.shaft.beam import NODE_DOF
from bearingkit.systems.shaft.result import ShaftResult

_LOAD_UNITS = ("N", "N", "N", "Nm", "Nm")
_DOF_UNITS = ("m", "m", "m", "rad", "rad")


def _named(names, units, values) -> dict:
    return {f"{n}_{u}": float(v) for n, u, v in zip(names, units, values, strict=True)}


@dataclass
class DrivetrainResult:
    """Solution of a drivetrain over a batch of load cases (leading axis C)."""

    drivetrain: object
    loads: dict
    assembly: object = field(repr=False)
    unknowns: np.ndarray = field(repr=False)
    converged: np.ndarray = None
    iterations: np.ndarray = None
    residual_norm: np.ndarray = None
    reason: list = None
    laws: list = None
    _bearing_results: dict = field(default_factory=dict, repr=False)

    @property
    def n_cases(self) -> int:
        return self.unknowns.shape[0]

    @property
    def case_names(self) -> tuple:
        return tuple(self.loads["names"])

    # -- bearings -------------------------------------------------------------------------------
    def _index(self, name: str) -> int:
        names = [b.name for b in self.drivetrain.bearings]
        if name not in names:
            raise InputError(f"bearing ({name!r}) not in the result; bearings are {names}")
        return names.index(name)

    @cached_property
    def _states(self) -> list:
        asm = self.assembly
        return [
            (q := self.unknowns @ p.T + c, law.response(q))
            for law, p, c in zip(self.laws, asm.projections, asm.offsets, strict=True)
        ]

    def law(self, name: str):
        return self.laws[self._index(name)]

    def model(self, name: str):
        """The bearing model as solved (rows at the cases' speeds)."""
        return self.law(name).bearing

    def relative_displacement(self, name: str) -> np.ndarray:
        """q (C, 5) of the inner ring relative to the outer ring, bearing frame [m, rad]."""
        return self._states[self._index(name)][0]

    def misalignment(self, name: str) -> np.ndarray:
        q = self.relative_displacement(name)
        return np.hypot(q[:, 3], q[:, 4])

    def bearing_load(self, name: str) -> np.ndarray:
        """Load (C, 5) the bearing carries in its frame [N, N·m]."""
        return -self._states[self._index(name)][1].force

    def reaction(self, name: str) -> np.ndarray:
        """Force and moment (C, 5) of the bearing on its inner ring's body, gearbox axes, at the ring."""
        i = self._index(name)
        return self._states[i][1].force @ self.drivetrain.bearings[i].seat.transform

    def stiffness(self, name: str) -> np.ndarray:
        """Tangent stiffness (C, 5, 5) in the gearbox axes."""
        i = self._index(name)
        t = self.drivetrain.bearings[i].seat.transform
        return t @ (-self._states[i][1].jacobian) @ t

    def ring_displacement(self, name: str, ring: str) -> np.ndarray:
        """Displacement (C, 5) of the ``"inner"`` or ``"outer"`` ring, gearbox axes [m, rad]."""
        i = self._index(name)
        a, c = (self.assembly.inner_maps if ring == "inner" else self.assembly.outer_maps)[i]
        return self.unknowns @ a.T + c

    def bearing_result(self, name: str):
        """The bearing's QuasiStaticResult at its state (as :meth:`ShaftResult.bearing_result`)."""
        from bearingkit.analysis.solver.quasistatic import QuasiStaticResult

        i = self._index(name)
        b = self.drivetrain.bearings[i]
        if not isinstance(b.seat.bearing, BearingModel):
            raise InputError(f"bearing {name!r} is a linear stiffness: it has no rows to report")
        if name not in self._bearing_results:
            q, resp = self._states[i]
            self._bearing_results[name] = QuasiStaticResult(
                model=self.model(name),
                load=-resp.force,
                displacement=q,
                converged=self.converged.copy(),
                iterations=self.iterations.copy(),
                residual_norm=self.residual_norm.copy(),
                reason=list(self.reason),
                stiffness=-resp.jacobian,
                free=np.ones(N_DOF, bool),
                references=tuple(b.seat.bearing.references),
            )
        return self._bearing_results[name]

    # -- meshes ---------------------------------------------------------------------------------
    def mesh_index(self, name: str) -> int:
        names = [m.name for m in self.drivetrain.meshes]
        if name not in names:
            raise InputError(f"mesh ({name!r}) not in the result; meshes are {names}")
        return names.index(name)

    def mesh_force(self, name: str) -> np.ndarray:
        """Normal force F = k δ (C,) [N] along the line of action (positive: the teeth push)."""
        row = self.assembly.mesh_rows[self.mesh_index(name)]
        return row["k"] * np.einsum("ci,ci->c", row["g"], self.unknowns)

    def mesh_deflection(self, name: str) -> np.ndarray:
        """δ (C,) [m] along the line of action."""
        row = self.assembly.mesh_rows[self.mesh_index(name)]
        return np.einsum("ci,ci->c", row["g"], self.unknowns)

    def mesh_vector(self, name: str, gear: str = "b") -> np.ndarray:
        """Force (C, 3) [N] of the mesh on gear ``"a"`` or ``"b"``, gearbox axes."""
        row = self.assembly.mesh_rows[self.mesh_index(name)]
        f = self.mesh_force(name)[:, None] * row["n"]
        return f if gear == "b" else -f

    def mesh_components(self, name: str, gear: str) -> dict:
        """Tangential, radial (+ towards the gear's axis is negative: outward positive) and axial force
        (C,) [N] of the mesh on a gear, and the torque about its axis (C,) [N·m]."""
        i = self.mesh_index(name)
        geo = self.assembly.mesh_rows[i]["geometry"]
        p = geo["p_a"] if gear == "a" else geo["p_b"]
        r = np.linalg.norm(p)
        e_r = p / r
        e_t = np.cross([0.0, 0.0, 1.0], e_r)
        f = self.mesh_vector(name, gear)
        return {
            "tangential_N": f @ e_t,
            "radial_N": f @ e_r,
            "axial_N": f[:, 2],
            "torque_Nm": r * (f @ e_t),
        }

    def separated_meshes(self) -> list[list[str]]:
        """Per case the meshes whose force would pull (tooth contact lost)."""
        out = [[] for _ in range(self.n_cases)]
        for m in self.drivetrain.meshes:
            for c in np.flatnonzero(self.mesh_force(m.name) < 0.0):
                out[c].append(m.name)
        return out

    # -- shafts ---------------------------------------------------------------------------------
    def rotation(self, shaft: str) -> np.ndarray:
        """θ_z (C,) [rad] of a shaft (0 for the held one)."""
        blk = self.assembly.blocks[shaft]
        return np.zeros(self.n_cases) if blk.theta_z is None else self.unknowns[:, blk.theta_z]

    def held_torque(self) -> np.ndarray:
        """Torque (C,) [N·m] about +z that holds the held shaft (the output reaction)."""
        held = self.drivetrain.held
        if held is None:
            return np.zeros(self.n_cases)
        total = np.zeros(self.n_cases)
        for m in self.drivetrain.meshes:
            for side in ("a", "b"):
                ref = m.a if side == "a" else m.b
                if ref[0] == held:
                    total += self.mesh_components(m.name, side)["torque_Nm"]
        # Pins on the held body carry planet forces on arms: their torque about the axis.
        blk = self.assembly.blocks[held]
        for b in self.drivetrain.bearings:
            if b.inner.body == held and (b.inner.arm[0] or b.inner.arm[1]):
                f = self.reaction(b.name)
                total += b.inner.arm[0] * f[:, 1] - b.inner.arm[1] * f[:, 0]
        total += self.loads["torques"].get(held, 0.0) if blk.theta_z is None else 0.0
        return -total

    def shaft_result(self, shaft: str) -> ShaftResult:
        """A ShaftResult view of one shaft: displacement, shear and bending-moment lines."""
        cache = self.__dict__.setdefault("_shaft_views", {})
        if shaft not in cache:
            blk = self.assembly.blocks[shaft]
            view = SimpleNamespace(
                mesh=blk.mesh,
                seat_dofs=blk.seat_dofs,
                interior=blk.interior,
                factor=blk.factor,
                coupling=blk.coupling,
                nodal=blk.nodal,
                n_seat=blk.n_seat,
            )
            system = SimpleNamespace(shaft=blk.body.shaft, bearings=(), gears=(), masses=(), name=shaft)
            cache[shaft] = ShaftResult(
                system=system,
                loads=self.loads["shafts"][shaft],
                assembly=view,
                unknowns=self.unknowns[:, blk.offset : blk.offset + blk.n_seat],
                converged=self.converged,
                iterations=self.iterations,
                residual_norm=self.residual_norm,
                reason=self.reason,
            )
        return cache[shaft]

    # -- checks ---------------------------------------------------------------------------------
    def equilibrium_residual(self) -> np.ndarray:
        """Independent check: on every full (uncondensed) shaft K u − F − bearing and mesh forces,
        plus every shaft's torque balance; max over the load scale (C,)."""
        dt = self.drivetrain
        nodal_res, scale = [], np.full(self.n_cases, 1e-300)
        length = dt.char_length
        extra = {s.name: np.zeros((self.n_cases, self.assembly.blocks[s.name].mesh.n_dof)) for s in dt.shafts}
        torque = {
            s.name: np.array(self.loads["torques"].get(s.name, np.zeros(self.n_cases)), float)
            * np.ones(self.n_cases)
            for s in dt.shafts
        }

        def put(body, z, arm, force6):  # force (C, 3) and moment (C, 3) at a point on an arm
            if body == HOUSING:
                return
            blk = self.assembly.blocks[body]
            node = blk.mesh.node(z)
            f, mom = force6[:, :3], force6[:, 3:]
            mom = mom + np.cross(np.asarray(arm, float), f)
            sl = slice(NODE_DOF * node, NODE_DOF * node + NODE_DOF)
            extra[body][:, sl] += np.concatenate([f, mom[:, :2]], axis=1)
            torque[body] += mom[:, 2]

        for b in dt.bearings:
            r = self.reaction(b.name)  # on the inner ring: force (3) and moment (θ_x, θ_y)
            six = np.concatenate([r[:, :3], r[:, 3:], np.zeros((self.n_cases, 1))], axis=1)
            put(b.inner.body, b.inner.position, b.inner.arm, six)
            put(b.outer.body, b.outer.position, b.outer.arm, -six)
        for m in dt.meshes:
            geo = self.assembly.mesh_rows[self.mesh_index(m.name)]["geometry"]
            for side, ref, p in (("a", m.a, geo["p_a"]), ("b", m.b, geo["p_b"])):
                if ref[0] == HOUSING:
                    continue
                f = self.mesh_vector(m.name, side)
                g = dt.body(ref[0]).gear(ref[1])
                put(ref[0], g.position, (p[0], p[1], 0.0), np.concatenate([f, np.zeros_like(f)], axis=1))
        for s in dt.shafts:
            blk = self.assembly.blocks[s.name]
            u = self.shaft_result(s.name).displacement.reshape(self.n_cases, -1)
            r = u @ blk.mesh.stiffness - blk.nodal - extra[s.name]
            w = np.tile([1.0, 1.0, 1.0, 1.0 / length, 1.0 / length], blk.mesh.n_nodes)
            nodal_res.append(np.abs(r * w).max(axis=1))
            scale = np.maximum(scale, np.abs(blk.nodal * w).max(axis=1))
            scale = np.maximum(scale, np.abs(extra[s.name] * w).max(axis=1))
            if blk.theta_z is not None:
                nodal_res.append(np.abs(torque[s.name]) / length)
        return np.max(nodal_res, axis=0) / scale

    # -- output ---------------------------------------------------------------------------------
    def bearing_dict(self, name: str, case: int) -> dict:
        b = self.drivetrain.bearing(name)
        k = self.stiffness(name)[case]
        load = self.bearing_load(name)[case]
        out = {
            "name": name,
            "bearing": getattr(b.seat.bearing, "name", "linear bearing"),
            "inner": b.inner.body,
            "outer": b.outer.body,
            "position_m": b.inner.position,
            "orientation": b.seat.orientation,
            "axial": b.seat.axial,
            "reaction_on_inner_body": _named(LOAD_NAMES, _LOAD_UNITS, self.reaction(name)[case]),
            "load_on_bearing": _named(LOAD_NAMES, _LOAD_UNITS, load),
            "inner_ring_displacement": _named(
                DOF_NAMES, _DOF_UNITS, self.ring_displacement(name, "inner")[case]
            ),
            "outer_ring_displacement": _named(
                DOF_NAMES, _DOF_UNITS, self.ring_displacement(name, "outer")[case]
            ),
            "relative_displacement": _named(DOF_NAMES, _DOF_UNITS, self.relative_displacement(name)[case]),
            "misalignment_rad": float(self.misalignment(name)[case]),
            "radial_load_N": float(np.hypot(load[0], load[1])),
            "axial_load_N": float(load[2]),
            "stiffness_SI": k.tolist(),
        }
        if isinstance(b.seat.bearing, BearingModel):
            out["rows"] = self.bearing_result(name).to_dict(case)["rows"]
        return out

    def mesh_dict(self, name: str, case: int) -> dict:
        m = self.drivetrain.meshes[self.mesh_index(name)]
        out = {
            "name": name,
            "gears": [list(m.a), list(m.b)],
            "normal_force_N": float(self.mesh_force(name)[case]),
            "deflection_m": float(self.mesh_deflection(name)[case]),
            "stiffness_N_per_m": float(m.k),
            "centre_distance_m": float(m.pair.centre_distance),
            "working_pressure_angle_rad": float(m.pair.working_pressure_angle),
            "contact_ratio": float(m.pair.contact_ratio),
            "ratio": float(m.pair.ratio),
        }
        for side in ("a", "b"):
            out[f"on_{side}"] = {k: float(v[case]) for k, v in self.mesh_components(name, side).items()}
        return out
