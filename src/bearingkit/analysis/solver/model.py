"""A bearing model: rows of rolling elements between a rigid inner ring and a fixed outer ring.

SI units. Builders in :mod:`bearingkit.bearings` return a :class:`BearingModel`; the solver in
:mod:`bearingkit.analysis.solver.quasistatic` consumes it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from bearingkit.errors import InputError
from bearingkit.lazy import cached_property


@dataclass(frozen=True)
class BearingModel:
    """Rows sharing one rigid inner ring (the loaded body) and one fixed outer ring.

    Parameters
    ----------
    rows : tuple
        Row objects (:class:`~bearingkit.rows.ball.row.BallRow`,
        :class:`~bearingkit.rows.cylindrical.row.CylindricalRow`, …).
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
        _check_overlap(self.rows)

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


def _check_overlap(rows) -> None:
    """Refuse two rows whose elements would occupy the same space (same radial and axial band).

    Rows interleaved on one cage circle (seed 000: rollers and balls alternating) sit on different
    pitch circles and pass this check; two rows on the same circle must be axially apart.
    """
    boxes = [(r.name, r.envelope()) for r in rows if hasattr(r, "envelope")]
    for i, (name_a, a) in enumerate(boxes):
        for name_b, b in boxes[i + 1 :]:
            radial = min(a[1], b[1]) - max(a[0], b[0])
            axial = min(a[3], b[3]) - max(a[2], b[2])
            if radial > 1e-9 and axial > 1e-9:
                raise InputError(
                    f"rows {name_a!r} and {name_b!r} overlap ({radial * 1e3:.3g} mm radially and "
                    f"{axial * 1e3:.3g} mm axially); expected rows separated by their element envelopes"
                )
