"""The coupled solution of a bearing in its structure, laid out for every face (SI, units in keys).

:class:`StructureResult` has the interface of :class:`~bearingkit.analysis.flexible.FlexibleResult`
(``result``, ``converged``, ``to_dict(case)``, ``row``, ``row_load``), so the pipeline, the CLI tables,
the studies' quantities and the report read either. ``to_dict`` adds, beside the engine's dict at the
coupled solution: the rigid solve's peak load and loaded count per row and their change, the raceway
offsets per element, the coupling diagnostics, and per ring its deflection around the circumference
(radial, axial, twist on :data:`SHAPE_POINTS` azimuths), its stress resultants and the largest hoop
fibre stress of its section (curved-beam rings; an imported structure gives its raceway nodes only).
"""

from __future__ import annotations

import numpy as np

from bearingkit.analysis.structure.coupling import Coupled, Structure, _combine
from bearingkit.lazy import cached_property

#: Azimuths (equally spaced, 5°) of the ring shapes in :meth:`StructureResult.to_dict`.
SHAPE_POINTS = 72


def _finite(value) -> float | None:
    v = float(value)
    return v if np.isfinite(v) else None


class StructureResult:
    """The coupled solve of a bearing in its :class:`Structure` (see the module docstring).

    Attributes
    ----------
    result : QuasiStaticResult
        The engine's solution at the coupled offsets.
    rigid : QuasiStaticResult
        The same cases on rigid rings.
    converged : ndarray (C,) of bool
        The coupling converged and its last engine solve did.
    iterations : ndarray (C,) of int
    offset_change : ndarray (C,) [m]
        Last max |G f − x| (tilts times the pitch radius).
    offsets : dict of str to RacewayOffset
        What the structure imposed (on top of any base offsets).
    structure : Structure
    """

    method = "newton"

    def __init__(self, coupled: Coupled, structure: Structure):
        self._c = coupled
        self.structure = structure
        self.result = coupled.result
        self.rigid = coupled.rigid
        self.converged = coupled.converged
        self.iterations = coupled.iterations
        self.offset_change = coupled.offset_change
        self.history = coupled.history
        p = coupled.points
        self.points = p
        self.offsets = _combine(None, p.rows, p.sizes, coupled.x, coupled.x.shape[0])

    @property
    def model(self):
        return self.result.model

    @property
    def n_cases(self) -> int:
        return self.result.n_cases

    def row(self, name):
        return self.result.row(name)

    def row_load(self, name):
        return self.result.row_load(name)

    @property
    def element_loads(self) -> np.ndarray:
        """(C, N, 3) loads (F_r, F_z, M_t) of the elements on the outer raceway at the solution."""
        return self._c.loads.reshape(self.n_cases, -1, 3)

    @property
    def raceway_offsets(self) -> np.ndarray:
        """(C, N, 3) (radial, axial, tilt) of the outer raceway relative to the inner one."""
        return self._c.x.reshape(self.n_cases, -1, 3)

    @cached_property
    def force_balance(self) -> np.ndarray:
        """(C,) largest miss of Σ (F_r e_r + F_z e_z) of the elements on the outer raceway against the load's
        forces (free DOFs), as a share of the largest load force: the equilibrium of the coupled solution."""
        f = self.element_loads
        p = self.points
        c, s = np.cos(p.azimuth), np.sin(p.azimuth)
        total = np.stack([(f[..., 0] * c).sum(-1), (f[..., 0] * s).sum(-1), f[..., 1].sum(-1)], -1)
        load = np.asarray(self.result.load, dtype=float)[:, :3]
        free = np.asarray(self.result.free, dtype=bool).reshape(-1)[:3]
        scale = np.maximum(np.abs(load).max(-1), 1e-300)
        miss = np.abs(total - load)[:, free]
        return miss.max(-1) / scale if miss.size else np.zeros(self.n_cases)

    # -- the rings ---------------------------------------------------------------------------------
    @cached_property
    def rings(self) -> list[dict]:
        """Per ring part: its deflection and resultants on :data:`SHAPE_POINTS` azimuths (every case)."""
        theta = np.linspace(0.0, 2.0 * np.pi, SHAPE_POINTS, endpoint=False)
        out = []
        p = self.points
        for part in self.structure.parts:
            idx = p.indices(part.rows)
            loads = self.element_loads[:, idx]
            if part.side == "inner":
                loads = -loads  # the elements push the inner ring the other way
            entry = {"side": part.side, "part": part, "theta": theta, "elements": idx}
            if hasattr(part, "response"):
                disp, forces = part.response(theta, p.azimuth[idx], loads, p.radius[idx], p.z[idx])
                entry.update(displacement=disp, forces=forces, stress=part.fibre_stress(forces))
                entry["unheld"] = part.condensation(p.azimuth[idx]).unheld if not part.rigid else ()
            out.append(entry)
        return out

    @property
    def warnings(self) -> list[str]:
        """What the structure's model leaves out or assumes (not per case)."""
        out = []
        for part in self.structure.parts:
            out.extend(getattr(part, "warnings", []))
        for ring in self.rings:
            if ring.get("unheld"):
                out.append(
                    f"{ring['side']} ring: nothing given holds its rigid-body motion "
                    f"{', '.join(ring['unheld'])}: the frame holds it (its share of the load reacted in "
                    "that mode's shape)"
                )
        return out

    def comparison(self, case: int) -> dict:
        """Rigid against flexible per row: peak element load, loaded count and their change."""
        out = {}
        for name in self.points.rows:
            rigid, flex = self.rigid.row_stats(name), self.result.row_stats(name)
            q_r, q_f = float(rigid.max_load[case]), float(flex.max_load[case])
            out[name] = {
                "max_load_rigid_N": q_r,
                "max_load_flexible_N": q_f,
                "max_load_change": _finite(q_f / q_r - 1.0) if q_r > 0 else None,
                "loaded_count_rigid": int(rigid.loaded_count[case]),
                "loaded_count_flexible": int(flex.loaded_count[case]),
                "max_pressure_rigid_Pa": float(rigid.max_pressure[case]),
                "max_pressure_flexible_Pa": float(flex.max_pressure[case]),
            }
        return out

    def to_dict(self, case: int | None = None) -> dict | list[dict]:
        """JSON-ready dict (SI, units in keys); a list over cases when ``case`` is None (module docstring)."""
        if case is None:
            return [self.to_dict(c) for c in range(self.n_cases)]
        out = self.result.to_dict(case)
        out["engine_converged"] = out["converged"]
        out["converged"] = bool(self.converged[case])
        comp = self.comparison(case)
        starts = np.concatenate([[0], np.cumsum(self.points.sizes)])
        x = self.raceway_offsets[case]
        for k, entry in enumerate(out["rows"]):
            entry.update(comp[entry["name"]])
            sl = slice(starts[k], starts[k + 1])
            entry["raceway_offset"] = {
                "radial_m": x[sl, 0].tolist(),
                "axial_m": x[sl, 1].tolist(),
                "tilt_rad": x[sl, 2].tolist(),
            }
        out["coupling"] = {
            "method": self.method,
            "iterations": int(self.iterations[case]),
            "offset_change_m": _finite(self.offset_change[case]),
            "force_balance": _finite(self.force_balance[case]),
        }
        out["rigid_vs_flexible"] = comp
        out["structure"] = {"rings": [self._ring_dict(r, case) for r in self.rings]}
        return out

    def _ring_dict(self, ring: dict, case: int) -> dict:
        part = ring["part"]
        d = {
            "side": ring["side"],
            "rows": list(part.rows) if part.rows is not None else list(self.points.rows),
        }
        d.update(part.describe() if hasattr(part, "describe") else {})
        if "displacement" not in ring:
            return d
        disp, forces = ring["displacement"][case], ring["forces"][case]
        stress = None if ring["stress"] is None else ring["stress"][case]
        d.update(
            shape_azimuth_rad=ring["theta"].tolist(),
            radial_deflection_m=disp[:, 0].tolist(),
            tangential_deflection_m=disp[:, 1].tolist(),
            axial_deflection_m=disp[:, 2].tolist(),
            twist_rad=disp[:, 3].tolist(),
            hoop_force_N=forces[:, 0].tolist(),
            bending_moment_Nm=forces[:, 1].tolist(),
            out_of_plane_moment_Nm=forces[:, 2].tolist(),
            torque_Nm=forces[:, 3].tolist(),
            unheld_modes=list(ring.get("unheld", ())),
        )
        if stress is not None:  # a section given by its properties has no outline to stress
            d["max_fibre_stress_Pa"] = float(np.abs(stress).max())
        return d
