"""A bearing model: rows of rolling elements between a rigid inner ring and a fixed outer ring.

SI units. Builders in :mod:`bearingkit.bearings` return a :class:`BearingModel`; the solver in
:mod:`bearingkit.analysis.quasistatic` consumes it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

from bearingkit import checks
from bearingkit.errors import InputError


@dataclass(frozen=True)
class BearingModel:
    """Rows sharing one rigid inner ring (the loaded body) and one fixed outer ring.

    Parameters
    ----------
    rows : tuple
        Row objects (:class:`~bearingkit.rows.ball.BallRow`,
        :class:`~bearingkit.rows.cylindrical.CylindricalRow`, …).
    name : str
        Designation shown in results and reports.
    references : tuple of str
        Keys of :mod:`bearingkit.references` for the models the bearing uses.
    metadata : dict
        Free-form description (envelope, source of the geometry) carried into reports.
    """

    rows: tuple
    name: str = "bearing"
    references: tuple = ()
    metadata: dict = field(default_factory=dict)

    def __post_init__(self):
        if len(self.rows) == 0:
            raise InputError("rows (0 rows) must contain at least one row of rolling elements")
        names = [r.name for r in self.rows]
        if len(set(names)) != len(names):
            raise InputError(f"rows have duplicate names {names}; each row needs its own name")
        for r in self.rows:
            if not hasattr(r, "kernel"):
                raise InputError(f"rows entry {r!r} is not a row (expected BallRow, CylindricalRow, …)")
        checks.finite("n_rows", len(self.rows))

    @cached_property
    def kernels(self) -> tuple:
        """Precomputed solver kernels of the rows (built once per model; the model is immutable)."""
        return tuple(row.kernel() for row in self.rows)

    def row(self, name: str):
        """The row called ``name``."""
        for r in self.rows:
            if r.name == name:
                return r
        raise InputError(
            f"row ({name!r}) not in bearing {self.name!r}; rows are {[r.name for r in self.rows]}"
        )

    @property
    def n_elements(self) -> int:
        """Total number of rolling elements."""
        return sum(r.n_elements for r in self.rows)
