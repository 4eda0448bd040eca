"""Any bearing in its structure: flexible inner and outer rings or an imported FE matrix (SI units).

- :mod:`.coupling` — :class:`Structure` (what carries the raceways) and :func:`solve_structure`, Newton
  on the raceway offsets coupled to every row kind's contacts;
- :mod:`.result` — :class:`StructureResult`, the solution laid out for every face (rigid against
  flexible, the rings' deflection and stresses).
"""

from bearingkit.analysis.structure.coupling import ElementPoints, Structure, element_loads, solve_structure
from bearingkit.analysis.structure.result import StructureResult


def solve(model, load, structure, **kwargs) -> StructureResult:
    """:func:`solve_structure` wrapped as a :class:`StructureResult` (keyword arguments passed on)."""
    return StructureResult(solve_structure(model, load, structure, **kwargs), structure)


__all__ = ["ElementPoints", "Structure", "StructureResult", "element_loads", "solve", "solve_structure"]
