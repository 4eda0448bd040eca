"""Bearing stiffness at operating points, as tables over load and speed, for rotordynamics.

SI units. The stiffness is the tangent K = −∂f/∂q (5 × 5) of the bearing's contact force on its inner
ring at the solved operating point, in the order (u_x, u_y, u_z, θ_x, θ_y): K_ij = ∂F_i/∂q_j, so the
blocks are force/length [N/m], force/rotation [N/rad], moment/length [N·m/m = N] and moment/rotation
[N·m/rad]. The radial 2 × 2 block [[k_xx, k_xy], [k_yx, k_yy]] with its cross terms is what a
rotordynamics code's bearing element takes (ROSS: kxx, kxy, kyx, kyy, and kzz for the axial term;
:mod:`bearingkit.systems.ross`). K is symmetric for these conservative contact laws; the cross terms
k_xy come from a radial load that is not along x or y and from tilt coupling.

A table is a list of operating points (load (5,), speed) with their K: from a grid of loads × speeds
on one bearing (:func:`bearing_stiffness_table`, one batched solve per speed) or from the seats of a
solved shaft (:func:`shaft_stiffness_table`, one point per load case). Speed enters both as it enters
``bearingkit analyze --speed`` (:mod:`bearingkit.analysis.solver.speed`): ball rows with their balls'
centrifugal force and gyroscopic moment, cylindrical and tapered rows with the rollers' centrifugal
force; a shaft's table is the tangent of each bearing as the shaft solved it, at the case's speed.
"""

from __future__ import annotations

import dataclasses
import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from bearingkit.errors import InputError, quote
from bearingkit.rows.base import DOF_NAMES, LOAD_NAMES, N_DOF

#: Short names of the DOFs in column names (θ_x → thx).
_SHORT = ("ux", "uy", "uz", "thx", "thy")
#: Unit of K_ij by (row is a moment, column is a rotation).
_K_UNITS = {
    (False, False): "N_per_m",
    (False, True): "N_per_rad",
    (True, False): "N",
    (True, True): "Nm_per_rad",
}
_LOAD_UNITS = ("N", "N", "N", "Nm", "Nm")


def stiffness_column(i: int, j: int) -> str:
    """Column name of K_ij with its unit, e.g. ``K_ux_uy_N_per_m``, ``K_thx_thx_Nm_per_rad``."""
    return f"K_{_SHORT[i]}_{_SHORT[j]}_{_K_UNITS[(i >= 3, j >= 3)]}"


@dataclass(frozen=True)
class StiffnessTable:
    """Tangent stiffness of one bearing at P operating points.

    Attributes
    ----------
    bearing : str
    frame : str
        "bearing" (its own axes) or "shaft" (the shaft's axes, orientation applied).
    loads : ndarray (P, 5) [N, N, N, N·m, N·m]
        Load the bearing carries (its frame), (F_x, F_y, F_z, M_x, M_y).
    speeds : ndarray (P,) [rad/s]
    stiffness : ndarray (P, 5, 5) [N/m, N/rad, N, N·m/rad]
    converged : ndarray (P,) of bool
    labels : tuple of str
        A name per point (load case, or "load i, speed j" of a grid).
    """

    bearing: str
    frame: str
    loads: np.ndarray
    speeds: np.ndarray
    stiffness: np.ndarray
    converged: np.ndarray
    labels: tuple

    def __len__(self) -> int:
        return len(self.speeds)

    def radial(self) -> np.ndarray:
        """The radial block [[k_xx, k_xy], [k_yx, k_yy]] (P, 2, 2) [N/m]."""
        return self.stiffness[:, :2, :2]

    def select(self, points) -> StiffnessTable:
        """The table restricted to some points (indices or a boolean mask)."""
        idx = np.arange(len(self))[np.asarray(points)]
        return dataclasses.replace(
            self,
            loads=self.loads[idx],
            speeds=self.speeds[idx],
            stiffness=self.stiffness[idx],
            converged=self.converged[idx],
            labels=tuple(self.labels[i] for i in idx),
        )

    def to_pandas(self):
        """One line per point: label, load, speed, converged and the 25 entries of K (units in columns)."""
        import pandas as pd

        data = {"point": list(self.labels), "speed_rad_s": self.speeds, "converged": self.converged}
        for i, (name, unit) in enumerate(zip(LOAD_NAMES, _LOAD_UNITS, strict=True)):
            data[f"{name}_{unit}"] = self.loads[:, i]
        for i in range(N_DOF):
            for j in range(N_DOF):
                data[stiffness_column(i, j)] = self.stiffness[:, i, j]
        frame = pd.DataFrame(data)
        frame.attrs.update(bearing=self.bearing, frame=self.frame)
        return frame

    def to_dict(self) -> dict:
        """JSON-ready dict (SI, units in keys); K per point as a 5 × 5 list and its radial block."""
        return {
            "bearing": self.bearing,
            "frame": self.frame,
            "dofs": list(DOF_NAMES),
            "points": [
                {
                    "point": self.labels[p],
                    "speed_rad_s": float(self.speeds[p]),
                    "converged": bool(self.converged[p]),
                    "load": {
                        f"{n}_{u}": float(v)
                        for n, u, v in zip(LOAD_NAMES, _LOAD_UNITS, self.loads[p], strict=True)
                    },
                    "stiffness_SI": self.stiffness[p].tolist(),
                    "radial_N_per_m": {
                        "k_xx": float(self.stiffness[p, 0, 0]),
                        "k_xy": float(self.stiffness[p, 0, 1]),
                        "k_yx": float(self.stiffness[p, 1, 0]),
                        "k_yy": float(self.stiffness[p, 1, 1]),
                    },
                    "axial_N_per_m": float(self.stiffness[p, 2, 2]),
                }
                for p in range(len(self))
            ],
        }

    def write(self, path) -> Path:
        """Write the table as CSV (``.csv``) or JSON (``.json``); returns the path."""
        from bearingkit.io.export import write_atomic

        path = Path(path)
        if path.suffix == ".csv":
            return write_atomic(
                path, lambda tmp: self.to_pandas().to_csv(tmp, index=False), "stiffness table"
            )
        if path.suffix == ".json":
            text = json.dumps(self.to_dict(), indent=1) + "\n"
            return write_atomic(path, lambda tmp: tmp.write_text(text, encoding="utf-8"), "stiffness table")
        raise InputError(f"stiffness file ({quote(str(path))}) must end in .csv or .json")


def speed_dependent(model) -> bool:
    """Whether any row of the model changes with speed: the kinds with a speed kernel (ball
    centrifugal force and gyroscopic moment, cylindrical and tapered roller centrifugal force)."""
    from bearingkit.analysis.solver.speed import SPEED_KERNELS

    return any(r.kind in SPEED_KERNELS or hasattr(r, "speed") for r in model.rows)


def bearing_stiffness_table(model, loads, speeds=(0.0,), *, free=None, options=None, name=None):
    """Stiffness of one bearing over a grid of loads × speeds.

    Parameters
    ----------
    model : BearingModel
    loads : array_like (L, 5) [N, N, N, N·m, N·m]
        Loads on the bearing (its frame).
    speeds : array_like (S,) [rad/s]
        Inner-ring speeds; with no speed-dependent row the table is solved once and repeated.
    free : array_like of 5 bool, optional
        DOFs solved for (see :func:`bearingkit.analysis.solver.quasistatic.solve`); K is the full tangent
        stiffness either way.
    options : SolverOptions, optional
    name : str, optional
        Bearing name in the table (default the model's).

    Returns
    -------
    StiffnessTable
        L × S points, load-major (point l·S + s is load l at speed s).
    """
    from bearingkit.analysis.solver.quasistatic import solve

    loads = np.atleast_2d(np.asarray(loads, dtype=float))
    speeds = np.atleast_1d(np.asarray(speeds, dtype=float))
    if loads.shape[-1] != N_DOF:
        raise InputError(f"loads (shape {loads.shape}) must have 5 components (F_x, F_y, F_z, M_x, M_y)")
    n_l, n_s = len(loads), len(speeds)
    k = np.empty((n_l, n_s, N_DOF, N_DOF))
    conv = np.empty((n_l, n_s), bool)
    if speed_dependent(model):
        for j, w in enumerate(speeds):  # one batched solve over the loads per speed
            # the same speed hook as analyze --speed: every row kind with a speed kernel, not only
            # tapered rows (a spindle's ball rows soften by a factor of ~3 at 20,000 rpm)
            res = solve(model, loads, free=free, options=options, speed=float(w) if w else None)
            k[:, j], conv[:, j] = res.stiffness, res.converged
    else:
        res = solve(model, loads, free=free, options=options)
        k[:] = res.stiffness[:, None]
        conv[:] = res.converged[:, None]
    labels = tuple(f"load {i}, speed {j}" for i in range(n_l) for j in range(n_s))
    return StiffnessTable(
        bearing=name or model.name,
        frame="bearing",
        loads=np.repeat(loads, n_s, axis=0),
        speeds=np.tile(speeds, n_l),
        stiffness=k.reshape(-1, N_DOF, N_DOF),
        converged=conv.ravel(),
        labels=labels,
    )


def shaft_stiffness_table(result, name: str, frame: str = "shaft") -> StiffnessTable:
    """Stiffness of bearing ``name`` of a solved shaft: one point per load case (its speed, 0 if none).

    K is the tangent of the bearing's law as the shaft solved it, with its rows at the case's shaft
    speed (:meth:`~bearingkit.systems.shaft.supports.BearingSeat.law_at`).
    """
    speeds = result.loads.speed if result.loads.speed is not None else np.zeros(result.n_cases)
    return StiffnessTable(
        bearing=name,
        frame=frame,
        loads=result.bearing_load(name),
        speeds=np.asarray(speeds, dtype=float),
        stiffness=result.stiffness(name, frame),
        converged=np.asarray(result.converged, bool),
        labels=tuple(result.loads.names),
    )


def write_tables(tables, path) -> Path:
    """Write several bearings' tables to one file: CSV (a ``bearing`` column) or JSON (a list)."""
    from bearingkit.io.export import write_atomic

    path = Path(path)
    if path.suffix == ".csv":
        import pandas as pd

        frames = [t.to_pandas().assign(bearing=t.bearing, frame=t.frame) for t in tables]
        table = pd.concat(frames, ignore_index=True)
        return write_atomic(path, lambda tmp: table.to_csv(tmp, index=False), "stiffness table")
    if path.suffix == ".json":
        text = json.dumps({"bearings": [t.to_dict() for t in tables]}, indent=1) + "\n"
        return write_atomic(path, lambda tmp: tmp.write_text(text, encoding="utf-8"), "stiffness table")
    raise InputError(f"stiffness file ({quote(str(path))}) must end in .csv or .json")
