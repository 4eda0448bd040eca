"""Result of a quasi-static solve: displacements, convergence, stiffness and lazy per-element states.

SI units, units in the keys of every export. See :class:`QuasiStaticResult`.

Per-element results are post-processing (Hertz ellipses, slice pressures) and are computed only when
asked for, in chunks of :data:`STATE_CHUNK` cases so their temporaries stay bounded: for a large
batch ``rows`` keeps the per-element arrays (C, Z) and computes the per-slice arrays (C, Z, n_s) and
the contact extras only when one of them is read; :meth:`QuasiStaticResult.row_stats` gives the
per-case maxima and loaded counts without keeping any per-element array.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.rows.base import DOF_NAMES, LOAD_NAMES, RowState

#: Cases per chunk of the per-element post-processing and of ``row_load`` (bounded temporaries:
#: ~25 MB per slice array of the seed-000 bearing, 159 rollers × 20 slices).
STATE_CHUNK = 512


def _chunks(n: int, size: int = STATE_CHUNK):
    return [slice(i, min(i + size, n)) for i in range(0, n, size)]


def _take(offset, cases: slice):
    return None if offset is None else offset.take(np.arange(cases.start, cases.stop))


def _part(kernel, n: int, cases: slice):
    """The kernel restricted to ``cases`` of n (per-case geometry, e.g. a clearance varied in a study,
    must follow the displacements it is evaluated with; shared geometry is left as is)."""
    if cases.start == 0 and cases.stop >= n:
        return kernel
    return kernel.take(np.arange(cases.start, cases.stop))


@dataclass(frozen=True)
class RowStats:
    """Per-case statistics of one row, computed without keeping per-element arrays (SI).

    Attributes
    ----------
    name, kind : str
    max_load : ndarray (C,) [N]
        Largest element load.
    max_pressure : ndarray (C,) [Pa]
        Largest contact pressure over all elements and contacts.
    loaded_count : ndarray (C,) of int
        Elements carrying load.
    max_deflection : ndarray (C,) [m]
        Largest element approach.
    """

    name: str
    kind: str
    max_load: np.ndarray
    max_pressure: np.ndarray
    loaded_count: np.ndarray
    max_deflection: np.ndarray


class StreamedRowState(RowState):
    """A :class:`RowState` of a large batch, filled chunk by chunk.

    The per-element arrays (``load``, ``deflection``, ``contact_angle``, ``max_pressure``, (C, Z))
    are kept; ``slice_load`` and ``extras`` (per slice and per contact, the bulk of the memory) are
    computed again, chunk by chunk, the first time one of them is read.
    """

    def __init__(self, kernel, displacement: np.ndarray, offset=None):
        n = displacement.shape[0]
        first = None
        parts = {}
        for cases in _chunks(n):
            st = _part(kernel, n, cases).state(displacement[cases], _take(offset, cases))
            if first is None:
                first = st
                z = st.load.shape[1]
                parts = {k: np.empty((n, z)) for k in ("load", "deflection", "contact_angle", "max_pressure")}
                azimuth = st.azimuth if np.shape(st.azimuth)[0] == 1 else np.empty((n, z))
            for key, arr in parts.items():
                arr[cases] = getattr(st, key)
            if np.shape(st.azimuth)[0] != 1:
                azimuth[cases] = np.broadcast_to(st.azimuth, st.load.shape)
        self._source = (kernel, displacement, offset, first.slice_load is not None)
        self._lazy = {}
        super().__init__(first.kind, first.name, azimuth, **parts, slice_load=None, extras=None)

    def _full(self):
        if not self._lazy:
            kernel, q, offset, has_slices = self._source
            n = q.shape[0]
            states = [_part(kernel, n, c).state(q[c], _take(offset, c)) for c in _chunks(n)]
            self._lazy["slice_load"] = np.concatenate([s.slice_load for s in states]) if has_slices else None
            extras = {}
            for key in states[0].extras:
                extras[key] = np.concatenate(
                    [
                        np.broadcast_to(s.extras[key], (s.load.shape[0], *np.shape(s.extras[key])[1:]))
                        for s in states
                    ]
                )
            self._lazy["extras"] = extras
        return self._lazy

    @property
    def slice_load(self):
        return self._full()["slice_load"] if self.__dict__.get("_source") else None

    @slice_load.setter
    def slice_load(self, value):  # set by the dataclass __init__ (to None)
        pass

    @property
    def extras(self):
        return self._full()["extras"] if self.__dict__.get("_source") else {}

    @extras.setter
    def extras(self, value):
        pass


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
        displacement or the row forces skip the per-contact Hertz post-processing; above
        :data:`STATE_CHUNK` cases streamed, see the module docstring).
    evaluations : ndarray (C,) of int or None
        Row evaluations (force and stiffness of every row) the solve took per case (compiled core).
    coarse_evaluations : ndarray (C,) of int or None
        Evaluations of the coarse model in the first Newton iterations
        (:mod:`bearingkit.analysis.solver.coarse`; compiled core), not counted in ``evaluations``.
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
    evaluations: np.ndarray | None = field(default=None, repr=False)
    coarse_evaluations: np.ndarray | None = field(default=None, repr=False)
    _rows: list | None = field(default=None, repr=False)
    _row_loads: dict = field(default_factory=dict, repr=False)
    #: Tapered rollers' positions X (C, T, 2) at the solution from the compiled core (NaN where
    #: unknown), the warm start of the per-roller loads; None otherwise.
    _roller_x: np.ndarray | None = field(default=None, repr=False)

    def seed_rollers(self) -> None:
        """Give each tapered row's kernel the rollers' positions the compiled solve left at the
        solution (its warm start), so that per-roller outputs start converged (see
        :meth:`bearingkit.rows.tapered.kernel.TaperedKernel.warm_start`). A no-op without them."""
        x = self._roller_x
        if x is None or x.shape[1] == 0:
            return
        at = 0
        for k, o in zip(self.model.kernels, self.offsets or [None] * len(self.model.kernels), strict=True):
            if hasattr(k, "warm_start"):
                z = k.row.n_elements
                k.warm_start(self.displacement, x[:, at : at + z], o)
                at += z

    @property
    def rows(self) -> list[RowState]:
        if self._rows is None:
            self.seed_rollers()
            offs = self.offsets or [None] * len(self.model.kernels)
            small = self.n_cases <= STATE_CHUNK
            self._rows = [
                k.state(self.displacement, o) if small else StreamedRowState(k, self.displacement, o)
                for k, o in zip(self.model.kernels, offs, strict=True)
            ]
        return self._rows

    def row_stats(self, name: str) -> RowStats:
        """Max load, max pressure, loaded count and max deflection per case of row ``name`` (SI).

        Chunk by chunk, without keeping per-element arrays (the ``rows`` already computed are
        reused).
        """
        i = self._row_index(name)
        if self._rows is not None:
            st = self._rows[i]
            return RowStats(
                st.name, st.kind, st.max_load, st.max_pressure.max(axis=-1), st.loaded_count,
                st.deflection.max(axis=-1),
            )  # fmt: skip
        self.seed_rollers()
        kernel = self.model.kernels[i]
        offset = self.offsets[i] if self.offsets else None
        n = self.n_cases
        out = {k: np.empty(n) for k in ("max_load", "max_pressure", "max_deflection")}
        count = np.empty(n, int)
        for cases in _chunks(n):
            st = _part(kernel, n, cases).state(self.displacement[cases], _take(offset, cases))
            out["max_load"][cases] = st.max_load
            out["max_pressure"][cases] = st.max_pressure.max(axis=-1)
            out["max_deflection"][cases] = st.deflection.max(axis=-1)
            count[cases] = st.loaded_count
        return RowStats(st.name, st.kind, out["max_load"], out["max_pressure"], count, out["max_deflection"])

    def _row_index(self, name: str) -> int:
        names = [r.name for r in self.model.rows]
        if name not in names:
            raise InputError(f"row ({name!r}) not in result; rows are {names}")
        return names.index(name)

    def _case_rows(self, case: int) -> list[RowState]:
        """Row states of one case (from ``rows`` if computed, else computed for that case only)."""
        if self._rows is not None or self.n_cases <= STATE_CHUNK:
            return self.rows
        self.seed_rollers()
        offs = self.offsets or [None] * len(self.model.kernels)
        one = slice(case, case + 1)
        n = self.n_cases
        return [
            _part(k, n, one).state(self.displacement[one], _take(o, one))
            for k, o in zip(self.model.kernels, offs, strict=True)
        ]

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
        one = self._rows is None and self.n_cases > STATE_CHUNK
        for r in self._case_rows(case):
            row_force = self.row_load(r.name)[case]
            c = 0 if one else case
            entry = {
                "name": r.name,
                "kind": r.kind,
                "azimuth_rad": np.broadcast_to(r.azimuth, r.load.shape)[c].tolist(),
                "loads_N": r.load[c].tolist(),
                "contact_angle_rad": r.contact_angle[c].tolist(),
                "max_load_N": float(r.max_load[c]),
                "max_pressure_Pa": float(r.max_pressure[c].max()),
                "loaded_count": int(r.loaded_count[c]),
                "axial_load_N": float(row_force[2]),
                "radial_load_N": float(np.hypot(*row_force[:2])),
            }
            contacts = _contacts(r, c)
            if contacts is not None:
                entry["contacts"] = contacts
            out["rows"].append(entry)
        out["references"] = list(self.references)
        return out

    def row_load(self, name: str) -> np.ndarray:
        """Force and moment (C, 5) the row carries (= −contact force on the inner ring), SI."""
        if name not in self._row_loads:  # computed once per row: to_dict asks per case
            i = self._row_index(name)
            offset = self.offsets[i] if self.offsets else None
            kernel, q = self.model.kernels[i], self.displacement
            force = np.empty_like(q)
            n = q.shape[0]
            for cases in _chunks(n):
                force[cases] = -_part(kernel, n, cases).response(q[cases], _take(offset, cases)).force
            self._row_loads[name] = force
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


def _contacts(state: RowState, c: int) -> dict | None:
    """Every contact of every element of a row whose elements touch the inner ring at more than one
    point, else None: a four-point ball (``outer_upper``, ``outer_lower``, ``inner_lower``,
    ``inner_upper``) and a threaded roller (each engaged tooth on both flanks, ``tooth_1_plus``,
    ``tooth_1_minus`` …; the flank σ = +1 at +α, σ = −1 at −α).

    ``loads_N`` and ``contact_angle_rad`` of the row entry give one value per element (a four-point
    ball's most loaded contact, a threaded roller's sum over its teeth at +α); under a radial load or
    a moment both diagonals or both flanks carry, so only the contacts here add up to the row's load:
    the inner ring's contacts (``ring``) of element j push it along (cos α cos ψ_j, cos α sin ψ_j,
    sin α) with load Q (docs/input-format.md, "Output").
    """
    extras = state.extras or {}
    if "contact_load" in extras and "contact_angle_all" in extras:
        from bearingkit.rows.ball.four_point import CONTACTS

        return {
            "names": list(CONTACTS),
            "ring": [n.split("_")[0] for n in CONTACTS],
            "loads_N": np.asarray(extras["contact_load"])[c].tolist(),
            "contact_angle_rad": np.asarray(extras["contact_angle_all"])[c].tolist(),
        }
    if "tooth_load" in extras:
        teeth = np.asarray(extras["tooth_load"])[c]  # (Z, n, 2): flank σ = +1, −1
        z, n, _ = teeth.shape
        alpha = np.broadcast_to(np.asarray(state.contact_angle), np.shape(state.load))[c][:, None, None]
        angle = np.broadcast_to(alpha * np.array([1.0, -1.0]), teeth.shape)
        return {
            "names": [f"tooth_{i + 1}_{side}" for i in range(n) for side in ("plus", "minus")],
            "ring": ["inner"] * (2 * n),
            "loads_N": teeth.reshape(z, 2 * n).tolist(),
            "contact_angle_rad": angle.reshape(z, 2 * n).tolist(),
        }
    return None
