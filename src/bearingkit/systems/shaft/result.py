"""Results of a shaft system: reactions, seat states, every bearing's solution, shaft lines, lives.

SI units; keys of :meth:`ShaftResult.to_dict` carry their unit. Per bearing, in the shaft frame:
the reaction (force and moment of the bearing on the shaft, (F_x, F_y, F_z, M_x, M_y)), the seat
displacement and tilt, and the outer ring's. In the bearing's own frame: the load it carries
(= −contact force on its inner ring, the ``load`` of a single-bearing analysis), the relative
displacement q its rows see (its misalignment is the relative tilt |(θ_x, θ_y)|), its tangent
stiffness, and its full :class:`~bearingkit.analysis.solver.quasistatic.QuasiStaticResult` (element loads,
contact angles, pressures) from which ratings and friction follow through their usual API.

Shaft lines. Nodal displacements (C, N, 5) are exact (:mod:`bearingkit.systems.shaft.beam`). Internal
forces come from each element's end forces f_e = K_e u_e − f_e,eq (f_e,eq the consistent loads of its
line load): at an element's left end the internal moment (of the part z' > z on the part z' < z) is
−f_e(θ₁), at its right end +f_e(θ₂); so M_y = E I dθ_y/dz and M_x = E I dθ_x/dz, and a shaft resting
on end supports with a load towards −x bends with M_y > 0.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.linalg import cho_solve

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.lazy import cached_property
from bearingkit.rows.base import DOF_NAMES, LOAD_NAMES, N_DOF
from bearingkit.systems.shaft import beam
from bearingkit.systems.shaft.beam import NODE_DOF
from bearingkit.systems.shaft.shaft import element_line_loads

_LOAD_UNITS = ("N", "N", "N", "Nm", "Nm")
_DOF_UNITS = ("m", "m", "m", "rad", "rad")


def _named(names, units, values) -> dict:
    return {f"{n}_{u}": float(v) for n, u, v in zip(names, units, values, strict=True)}


@dataclass
class ShaftResult:
    """Solution of a shaft system over a batch of load cases (leading axis C).

    Attributes
    ----------
    system : ShaftSystem
    loads : ShaftLoads
    converged : ndarray (C,) of bool
    iterations : ndarray (C,) of int
    residual_norm : ndarray (C,)
        Max |scaled residual| of the condensed system over the load scale.
    reason : list of str or None
        Why a case did not converge.
    """

    system: object
    loads: object
    assembly: object = field(repr=False)
    unknowns: np.ndarray = field(repr=False)
    converged: np.ndarray = None
    iterations: np.ndarray = None
    residual_norm: np.ndarray = None
    reason: list = None
    laws: list = None
    _bearing_results: dict = field(default_factory=dict, repr=False)

    # -- shaft -------------------------------------------------------------------------------
    @property
    def n_cases(self) -> int:
        return self.unknowns.shape[0]

    @property
    def z(self) -> np.ndarray:
        """Node positions (N,) [m]."""
        return self.assembly.mesh.z

    @cached_property
    def displacement(self) -> np.ndarray:
        """Nodal displacements (C, N, 5) [m, m, m, rad, rad] of the shaft."""
        asm = self.assembly
        x_s = self.unknowns[:, : asm.n_seat]
        u = np.zeros((self.n_cases, asm.mesh.n_dof))
        u[:, asm.seat_dofs] = x_s
        if len(asm.interior):
            u[:, asm.interior] = cho_solve(asm.factor, asm.nodal[:, asm.interior].T).T - x_s @ asm.coupling.T
        return u.reshape(self.n_cases, asm.mesh.n_nodes, NODE_DOF)

    @cached_property
    def element_forces(self) -> np.ndarray:
        """End forces (C, E, 10) each element receives from its nodes, f_e = K_e u_e − f_e,eq."""
        mesh = self.assembly.mesh
        u = self.displacement.reshape(self.n_cases, -1)[:, mesh.element_dofs()]
        f = np.einsum("eij,cej->cei", mesh.element_stiffness, u)
        q = element_line_loads(mesh, self.loads)
        return f - beam.uniform_load_vector(q, mesh.length) if np.any(q) else f

    def moment_line(self) -> tuple[np.ndarray, np.ndarray]:
        """Bending moment along the shaft: z (2E,) [m] and (M_x, M_y) (C, 2E, 2) [N·m].

        Each element contributes its two ends (a point moment or a step shows as a jump between
        coincident z values); sign convention in the module docstring.
        """
        f = self.element_forces
        left = -f[..., [beam.TX, beam.TY]]
        right = f[..., [NODE_DOF + beam.TX, NODE_DOF + beam.TY]]
        z = np.stack([self.z[:-1], self.z[1:]], axis=1).ravel()
        return z, np.stack([left, right], axis=2).reshape(self.n_cases, -1, 2)

    def shear_line(self) -> tuple[np.ndarray, np.ndarray]:
        """Shear force (V_x, V_y) (C, 2E, 2) [N] on the same z (2E,) as :meth:`moment_line`."""
        f = self.element_forces
        left = -f[..., [beam.UX, beam.UY]]
        right = f[..., [NODE_DOF + beam.UX, NODE_DOF + beam.UY]]
        z = np.stack([self.z[:-1], self.z[1:]], axis=1).ravel()
        return z, np.stack([left, right], axis=2).reshape(self.n_cases, -1, 2)

    # -- bearings ------------------------------------------------------------------------------
    def _index(self, name: str) -> int:
        names = [b.name for b in self.system.bearings]
        if name not in names:
            raise InputError(f"bearing ({name!r}) not in the result; bearings are {names}")
        return names.index(name)

    def law(self, name: str):
        """The :class:`~bearingkit.systems.shaft.supports.BearingLaw` the bearing was solved with (its rows at
        the cases' shaft speed)."""
        i = self._index(name)
        return self.system.bearings[i].law if self.laws is None else self.laws[i]

    def model(self, name: str):
        """The bearing's model as solved: a :class:`~bearingkit.analysis.solver.speed.ModelAtSpeed` when the
        shaft turns, else the bearing's own model (LinearBearing for a linear stiffness)."""
        return self.law(name).bearing

    @cached_property
    def _bearing_states(self) -> list:
        asm = self.assembly
        out = []
        for b, p, c in zip(self.system.bearings, asm.projections, asm.offsets, strict=True):
            q = self.unknowns @ p.T + c
            out.append((q, self.law(b.name).response(q)))
        return out

    def relative_displacement(self, name: str) -> np.ndarray:
        """q (C, 5) of the inner ring relative to the outer ring, in the bearing frame [m, rad]."""
        return self._bearing_states[self._index(name)][0]

    def misalignment(self, name: str) -> np.ndarray:
        """Tilt of the inner ring relative to the outer ring |(θ_x, θ_y)| (C,) [rad]."""
        q = self.relative_displacement(name)
        return np.hypot(q[:, 3], q[:, 4])

    def bearing_load(self, name: str) -> np.ndarray:
        """Load (C, 5) the bearing carries in its frame, = −contact force on its inner ring [N, N·m]."""
        return -self._bearing_states[self._index(name)][1].force

    def reaction(self, name: str) -> np.ndarray:
        """Force and moment (C, 5) of the bearing on the shaft, shaft frame [N, N, N, N·m, N·m]."""
        b = self.system.bearings[self._index(name)]
        return self._bearing_states[self._index(name)][1].force @ b.transform

    def stiffness(self, name: str, frame: str = "shaft") -> np.ndarray:
        """Tangent stiffness K = −∂f/∂q (C, 5, 5) of the bearing, in the "shaft" or "bearing" frame."""
        b = self.system.bearings[self._index(name)]
        k = -self._bearing_states[self._index(name)][1].jacobian
        if frame == "bearing":
            return k
        if frame != "shaft":
            raise InputError(f"frame ({frame!r}) must be 'shaft' or 'bearing'")
        t = b.transform
        return t @ k @ t

    def seat_displacement(self, name: str) -> np.ndarray:
        """Displacement and tilt (C, 5) of the shaft at the bearing's seat, shaft frame [m, rad]."""
        i = self._index(name)
        return self.displacement[:, self.assembly.seat_nodes[i], :]

    def outer_displacement(self, name: str) -> np.ndarray:
        """Displacement (C, 5) of the bearing's outer ring in the shaft frame [m, rad]."""
        i = self._index(name)
        b, idx = self.system.bearings[i], self.assembly.outer_index[i]
        out = np.broadcast_to(b.outer_position, (self.n_cases, N_DOF)).copy()
        free = idx >= 0
        out[:, free] = self.unknowns[:, idx[free]]
        return out

    def bearing_result(self, name: str):
        """The bearing's :class:`~bearingkit.analysis.solver.quasistatic.QuasiStaticResult` at its seat state.

        Load = what the bearing carries (bearing frame), displacement = q; convergence and residual are
        the system's; its model has the rows at the cases' shaft speed (:meth:`model`). Not available
        for a :class:`~bearingkit.systems.shaft.supports.LinearBearing`.
        """
        from bearingkit.analysis.solver.quasistatic import QuasiStaticResult

        b = self.system.bearings[self._index(name)]
        if not isinstance(b.bearing, BearingModel):
            raise InputError(f"bearing {name!r} is a linear stiffness: it has no rows to report")
        if name in self._bearing_results:  # built once: its per-element state is computed lazily
            return self._bearing_results[name]
        q, resp = self._bearing_states[self._index(name)]
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
            references=tuple(b.bearing.references),
        )
        return self._bearing_results[name]

    # -- checks ----------------------------------------------------------------------------------
    def equilibrium_residual(self) -> np.ndarray:
        """Independent check on the full (uncondensed) shaft: max |K u − F − bearing reactions| (C,).

        Relative to the load scale (the largest nodal load or reaction; moments divided by the
        system's rotation scale L, as in the solver).
        """
        asm = self.assembly
        u = self.displacement.reshape(self.n_cases, -1)
        r = u @ asm.mesh.stiffness - asm.nodal
        react = np.zeros_like(r)
        for b, node in zip(self.system.bearings, asm.seat_nodes, strict=True):
            react[:, NODE_DOF * node : NODE_DOF * (node + 1)] += self.reaction(b.name)
        r -= react
        length = self.system.char_length
        s = np.tile(np.array([1.0, 1.0, 1.0, 1.0 / length, 1.0 / length]), asm.mesh.n_nodes)
        scale = np.maximum(np.abs(asm.nodal * s).max(axis=1), np.abs(react * s).max(axis=1))
        return np.abs(r * s).max(axis=1) / np.maximum(scale, 1e-300)

    # -- lives ----------------------------------------------------------------------------------
    def rating(self, **options):
        """Ratings of every bearing (:func:`bearingkit.analysis.rating.assembly.rate`) and the system life.

        ``options`` go to :func:`~bearingkit.analysis.rating.assembly.rate` (``reliability``, ``lubricant``,
        ``temperature_C``, ``contamination_factor`` …); the speed is the load cases' shaft speed and
        the inner rings rotate. Returns a :class:`bearingkit.systems.shaft.life.SystemRating`.
        """
        from bearingkit.systems.shaft.life import rate_system

        return rate_system(self, **options)

    # -- output ---------------------------------------------------------------------------------
    def bearing_dict(self, name: str, case: int) -> dict:
        """JSON-ready state of one bearing in one case (units in keys)."""
        b = self.system.bearings[self._index(name)]
        k = self.stiffness(name)[case]
        out = {
            "name": name,
            "bearing": getattr(b.bearing, "name", "linear bearing"),
            "position_m": b.position,
            "orientation": b.orientation,
            "axial": b.axial,
            "reaction_on_shaft": _named(LOAD_NAMES, _LOAD_UNITS, self.reaction(name)[case]),
            "load_on_bearing": _named(LOAD_NAMES, _LOAD_UNITS, self.bearing_load(name)[case]),
            "seat_displacement": _named(DOF_NAMES, _DOF_UNITS, self.seat_displacement(name)[case]),
            "outer_ring_displacement": _named(DOF_NAMES, _DOF_UNITS, self.outer_displacement(name)[case]),
            "relative_displacement": _named(DOF_NAMES, _DOF_UNITS, self.relative_displacement(name)[case]),
            "misalignment_rad": float(self.misalignment(name)[case]),
            "radial_load_N": float(np.hypot(*self.bearing_load(name)[case, :2])),
            "axial_load_N": float(self.bearing_load(name)[case, 2]),
            "stiffness_SI": k.tolist(),
            "radial_stiffness_N_per_m": k[:2, :2].tolist(),
        }
        if isinstance(b.bearing, BearingModel):
            rows = self.bearing_result(name).to_dict(case)["rows"]
            out["rows"] = rows
        return out

    def to_dict(self, case: int | None = None) -> dict | list[dict]:
        """JSON-ready dict of one case (a list over cases when None); SI values, units in keys."""
        if case is None:
            return [self.to_dict(c) for c in range(self.n_cases)]
        z_m, moment = self.moment_line()
        u = self.displacement[case]
        radial = np.hypot(u[:, 0], u[:, 1])
        bending = np.hypot(moment[case, :, 0], moment[case, :, 1])
        return {
            "case": self.loads.names[case],
            "converged": bool(self.converged[case]),
            "iterations": int(self.iterations[case]),
            "residual_norm": float(self.residual_norm[case]),
            "reason": self.reason[case],
            "speed_rad_s": None if self.loads.speed is None else float(self.loads.speed[case]),
            "bearings": [self.bearing_dict(b.name, case) for b in self.system.bearings],
            "shaft": {
                "max_radial_deflection_m": float(radial.max()),
                "max_radial_deflection_at_m": float(self.z[int(np.argmax(radial))]),
                "max_bending_moment_Nm": float(bending.max()),
                "max_bending_moment_at_m": float(z_m[int(np.argmax(bending))]),
                "deflection": {
                    "z_m": self.z.tolist(),
                    **{
                        f"{n}_{un}": u[:, i].tolist()
                        for i, (n, un) in enumerate(zip(DOF_NAMES, _DOF_UNITS, strict=True))
                    },
                },
                "bending_moment": {
                    "z_m": z_m.tolist(),
                    "M_x_Nm": moment[case, :, 0].tolist(),
                    "M_y_Nm": moment[case, :, 1].tolist(),
                },
            },
        }
