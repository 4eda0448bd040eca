"""Result of a quasi-static solve: displacements, convergence, stiffness and lazy per-element states.

SI units, units in the keys of every export. See :class:`QuasiStaticResult`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit.analysis.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.rows.base import DOF_NAMES, LOAD_NAMES, RowState


@dataclass
class QuasiStaticResult:
    """Solution of a batch of load cases (leading axis C).

    Attributes
    ----------
    model : BearingModel
    load : ndarray (C, 5) [N, N, N, N·m, N·m]
        External load on the inner ring (for fixed DOFs: the reaction needed to hold them).
    displacement : ndarray (C, 5) [m, m, m, rad, rad]
    converged : ndarray (C,) of bool
    iterations : ndarray (C,) of int
    residual_norm : ndarray (C,)
        Max |residual| over the free DOFs divided by the load scale (dimensionless).
    reason : list of str or None
        Why a case did not converge.
    rows : list of RowState
        Per-row, per-element results (computed on first access: studies that need only the
        displacement or the row forces skip the per-contact Hertz post-processing).
    stiffness : ndarray (C, 5, 5)
        Tangent stiffness −∂(contact force)/∂q [N/m, N, N·m/rad …] at the solution.
    free : ndarray (5,) of bool
    """

    model: BearingModel
    load: np.ndarray
    displacement: np.ndarray
    converged: np.ndarray
    iterations: np.ndarray
    residual_norm: np.ndarray
    reason: list
    stiffness: np.ndarray
    free: np.ndarray
    references: tuple = field(default_factory=tuple)
    offsets: list | None = field(default=None, repr=False)
    _rows: list | None = field(default=None, repr=False)
    _row_loads: dict = field(default_factory=dict, repr=False)

    @property
    def rows(self) -> list[RowState]:
        if self._rows is None:
            offs = self.offsets or [None] * len(self.model.kernels)
            self._rows = [
                k.state(self.displacement, o) for k, o in zip(self.model.kernels, offs, strict=True)
            ]
        return self._rows

    @property
    def n_cases(self) -> int:
        return self.displacement.shape[0]

    def row(self, name: str) -> RowState:
        """The row state called ``name``."""
        for r in self.rows:
            if r.name == name:
                return r
        raise InputError(f"row ({name!r}) not in result; rows are {[r.name for r in self.rows]}")

    def to_dict(self, case: int | None = None) -> dict | list[dict]:
        """JSON-ready dict (SI values, units in keys); a list over cases when ``case`` is None."""
        if case is None:
            return [self.to_dict(c) for c in range(self.n_cases)]
        out = {
            "bearing": self.model.name,
            "converged": bool(self.converged[case]),
            "iterations": int(self.iterations[case]),
            "residual_norm": float(self.residual_norm[case]),
            "reason": self.reason[case],
            "load": {
                f"{n}_{u}": float(v)
                for n, u, v in zip(LOAD_NAMES, ("N",) * 3 + ("Nm",) * 2, self.load[case], strict=True)
            },
            "displacement": {
                f"{n}_{u}": float(v)
                for n, u, v in zip(DOF_NAMES, ("m",) * 3 + ("rad",) * 2, self.displacement[case], strict=True)
            },
            "stiffness_SI": self.stiffness[case].tolist(),
            "rows": [],
        }
        for r in self.rows:
            row_force = self.row_load(r.name)[case]
            entry = {
                "name": r.name,
                "kind": r.kind,
                "azimuth_rad": np.broadcast_to(r.azimuth, r.load.shape)[case].tolist(),
                "loads_N": r.load[case].tolist(),
                "contact_angle_rad": r.contact_angle[case].tolist(),
                "max_load_N": float(r.max_load[case]),
                "max_pressure_Pa": float(r.max_pressure[case].max()),
                "loaded_count": int(r.loaded_count[case]),
                "axial_load_N": float(row_force[2]),
                "radial_load_N": float(np.hypot(*row_force[:2])),
            }
            out["rows"].append(entry)
        out["references"] = list(self.references)
        return out

    def row_load(self, name: str) -> np.ndarray:
        """Force and moment (C, 5) the row carries (= −contact force on the inner ring), SI."""
        if name not in self._row_loads:  # computed once per row: to_dict asks per case
            names = [r.name for r in self.model.rows]
            if name not in names:
                raise InputError(f"row ({name!r}) not in result; rows are {names}")
            i = names.index(name)
            offset = self.offsets[i] if self.offsets else None
            self._row_loads[name] = -self.model.kernels[i].response(self.displacement, offset).force
        return self._row_loads[name]

    def to_pandas(self):
        """One line per case, row and element: load, contact angle, max pressure (SI columns)."""
        import pandas as pd

        frames = []
        for r in self.rows:
            c, z = r.load.shape
            frames.append(
                pd.DataFrame(
                    {
                        "case": np.repeat(np.arange(c), z),
                        "row": r.name,
                        "kind": r.kind,
                        "element": np.tile(np.arange(z), c),
                        "azimuth_rad": np.broadcast_to(r.azimuth, r.load.shape).ravel(),
                        "load_N": r.load.ravel(),
                        "deflection_m": r.deflection.ravel(),
                        "contact_angle_rad": r.contact_angle.ravel(),
                        "max_pressure_Pa": r.max_pressure.ravel(),
                    }
                )
            )
        return pd.concat(frames, ignore_index=True)
