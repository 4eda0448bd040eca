"""The case registry and runner behind ``bearingkit validate``. SI values throughout."""

from __future__ import annotations

import importlib
import math
import pkgutil
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

from bearingkit.errors import InputError

_REGISTRY: dict[str, Case] = {}


@dataclass(frozen=True)
class Case:
    """One published number and how to recompute it.

    Attributes
    ----------
    id : str
        Hierarchical id, e.g. ``"harris/table6.1/F0.9100/a_star"``.
    source : str
        Citation of the published value (author, year, table/equation, DOI where there is one).
    quantity : str
        What the number is.
    unit : str
        Its SI unit (``"1"`` for dimensionless).
    published : float
        The published value in SI.
    compute : Callable[[], float]
        Recomputes the value in SI with bearingkit.
    tolerance : float
        Relative tolerance, justified by the source's precision.
    known_deviation : str or None
        Why the case is allowed to miss its tolerance (stated openly), or None.
    """

    id: str
    source: str
    quantity: str
    unit: str
    published: float
    compute: Callable[[], float]
    tolerance: float
    known_deviation: str | None = None

    def __post_init__(self):
        if not self.id or " " in self.id:
            raise InputError(f"id ({self.id!r}) must be a non-empty path without spaces")
        if not (self.tolerance >= 0):
            raise InputError(f"tolerance ({self.tolerance!r}) of case {self.id} must be >= 0")


@dataclass(frozen=True)
class CaseResult:
    """The outcome of one case; :meth:`to_dict` has exactly the keys of ``validate --json``."""

    case: Case
    computed: float
    rel_error: float
    passed: bool
    error: str | None = None

    def to_dict(self) -> dict:
        c = self.case
        return {
            "id": c.id,
            "source": c.source,
            "quantity": c.quantity,
            "unit": c.unit,
            "published": c.published,
            "computed": _json_float(self.computed),
            "rel_error": _json_float(self.rel_error),
            "tolerance": c.tolerance,
            "passed": self.passed,
            "known_deviation": c.known_deviation,
        }


def _json_float(x: float):
    return None if (x is None or not math.isfinite(x)) else float(x)


def register(case: Case) -> Case:
    """Add a case; ids are unique."""
    if case.id in _REGISTRY:
        raise InputError(f"validation case id {case.id!r} is registered twice")
    _REGISTRY[case.id] = case
    return case


#: Entry-point group of packages that register validation cases on import (the paper reproductions of
#: :mod:`bearingkit.papers` declare theirs): ``name = "package.module"``.
ENTRY_POINT_GROUP = "bearingkit.validation"


def _load_all() -> None:
    """Import every case module: the literature cases of this package, then the declared ones."""
    from importlib.metadata import entry_points

    for mod in pkgutil.iter_modules([str(Path(__file__).parent)]):
        if mod.name != "registry":
            importlib.import_module(f"bearingkit.validation.{mod.name}")
    for ep in entry_points(group=ENTRY_POINT_GROUP):
        ep.load()


def all_cases(prefixes: Iterable[str] = ()) -> list[Case]:
    """All registered cases (importing every case module), filtered by id prefix, sorted by id."""
    _load_all()
    prefixes = tuple(prefixes)
    cases = [c for c in _REGISTRY.values() if not prefixes or c.id.startswith(prefixes)]
    return sorted(cases, key=lambda c: c.id)


def quick_cases(cases: Iterable[Case]) -> list[Case]:
    """``validate --quick``: the first case (by id) of every source (the id's first segment: ``harris``,
    ``iso281``, ``seed000`` …), a few seconds that touch every group of the registry. Each paper and
    standard is represented once; the full run remains the validation."""
    first: dict[str, Case] = {}
    for case in sorted(cases, key=lambda c: c.id):
        first.setdefault(case.id.partition("/")[0], case)
    return list(first.values())


def relative_error(computed: float, published: float) -> float:
    """``(computed - published) / |published|``; absolute difference when published is 0."""
    if published == 0:
        return abs(computed)
    return (computed - published) / abs(published)


def run_case(case: Case) -> CaseResult:
    """Compute one case; an exception becomes a failed result with its message."""
    try:
        computed = float(case.compute())
    except Exception as exc:  # a broken case must show up as failed, not crash the whole run
        return CaseResult(case, math.nan, math.nan, False, f"{type(exc).__name__}: {exc}")
    if not math.isfinite(computed):
        return CaseResult(case, computed, math.nan, False, "non-finite result")
    err = relative_error(computed, case.published)
    return CaseResult(case, computed, err, abs(err) <= case.tolerance)


def run_cases(cases: Iterable[Case]) -> list[CaseResult]:
    """Run every case in order."""
    return [run_case(c) for c in cases]


def failures(results: Iterable[CaseResult]) -> list[CaseResult]:
    """Results that failed without a stated known deviation (these make ``validate`` exit 1)."""
    return [r for r in results if not r.passed and r.case.known_deviation is None]
