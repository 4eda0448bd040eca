"""The case registry and runner behind ``bearingkit validate``. SI values throughout.

Every case has a **role** (:data:`ROLES`):

* ``prediction`` — a published number recomputed with nothing fitted to it; only predictions count as
  passes;
* ``calibration`` — the published number a stated constant was identified on (it is met by
  construction; counted apart, never as a pass);
* ``diagnostic`` — a derived value (e.g. a range computed from a published table), a number the paper
  prints twice for one state, the project's own alternative readings or models: shown by
  ``validate --all``, never counted and never failing ``validate`` (unless it crashes).

Cases are grouped by the id's first segment: ``seed000`` … ``seed004`` are the four seed papers
(:data:`PAPERS`); every other prefix (Harris, ISO, …) is the ``literature`` group, counted apart from
the papers. Published numbers of a paper that cannot be computed are registered with
:func:`register_not_computable` (what and why), so the count of a paper is complete.
"""

from __future__ import annotations

import importlib
import math
import pkgutil
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

from bearingkit.errors import InputError

_REGISTRY: dict[str, Case] = {}
_NOT_COMPUTABLE: dict[str, NotComputable] = {}

#: Roles of a case (module docstring).
ROLES = ("prediction", "calibration", "diagnostic")
#: Roles that are counted in the per-paper summary.
COUNTED_ROLES = ("prediction", "calibration")
#: The seed papers, by id prefix → citation shown in the summary.
PAPERS = {
    "seed000": "Tian et al. 2025 (seed 000, turntable)",
    "seed001": "Liu et al. 2022 (seed 001, tapered roller)",
    "seed002": "Li et al. 2025 (seed 002, ball-column)",
    "seed004": "Zheng et al. 2022 (seed 004, PTRB)",
}
#: Group of the cases that are not from the seed papers (textbooks, standards, catalogues).
LITERATURE = "literature"
#: Widest relative tolerance of a counted value case without a stated reason [1] (issue 32: the paper's
#: own stated accuracy where it states one, else at most 10 %).
DEFAULT_MAX_TOLERANCE = 0.10


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
    role : str
        One of :data:`ROLES`.
    note : str or None
        Required for a calibration (which constant is identified on this number) and a diagnostic (why
        it is not counted: derived from which published numbers, duplicate of which case, which
        alternative).
    tolerance_reason : str or None
        Why the tolerance is wider than :data:`DEFAULT_MAX_TOLERANCE` (the paper's stated accuracy, an
        order of magnitude, a printed band); required for such a counted case.
    """

    id: str
    source: str
    quantity: str
    unit: str
    published: float
    compute: Callable[[], float]
    tolerance: float
    known_deviation: str | None = None
    role: str = "prediction"
    note: str | None = None
    tolerance_reason: str | None = None

    def __post_init__(self):
        if not self.id or " " in self.id:
            raise InputError(f"id ({self.id!r}) must be a non-empty path without spaces")
        if not (self.tolerance >= 0):
            raise InputError(f"tolerance ({self.tolerance!r}) of case {self.id} must be >= 0")
        if self.role not in ROLES:
            raise InputError(f"role ({self.role!r}) of case {self.id} must be one of {', '.join(ROLES)}")
        if self.role != "prediction" and not self.note:
            raise InputError(f"case {self.id} ({self.role}) needs a note saying what it is and why")

    @property
    def group(self) -> str:
        """The paper prefix (``seed000`` …) or :data:`LITERATURE`."""
        head = self.id.split("/", 1)[0]
        return head if head in PAPERS else LITERATURE

    @property
    def counted(self) -> bool:
        """True for predictions and calibrations (diagnostics are never counted)."""
        return self.role in COUNTED_ROLES


@dataclass(frozen=True)
class NotComputable:
    """A published number of a seed paper that bearingkit cannot compute, with the reason.

    Attributes
    ----------
    id : str
        Hierarchical id as a case's (``seed004/section7.2.4/shock-pulse-before``).
    published : str
        The number as printed, with its unit (``"≈ 10 dB"``).
    why : str
        Why it cannot be computed (what the paper does not give, what is not modelled).
    """

    id: str
    published: str
    why: str

    @property
    def group(self) -> str:
        return self.id.split("/", 1)[0]


def register_not_computable(item: NotComputable) -> NotComputable:
    """Record a published number that cannot be computed (ids unique, shared with the cases)."""
    if item.group not in PAPERS:
        raise InputError(f"not-computable item {item.id!r} must belong to a seed paper ({', '.join(PAPERS)})")
    if item.id in _NOT_COMPUTABLE or item.id in _REGISTRY:
        raise InputError(f"validation id {item.id!r} is registered twice")
    _NOT_COMPUTABLE[item.id] = item
    return item


def not_computable(prefixes: Iterable[str] = ()) -> list[NotComputable]:
    """Every registered not-computable number (importing every case module), by id."""
    _load_all()
    prefixes = tuple(prefixes)
    items = [i for i in _NOT_COMPUTABLE.values() if not prefixes or i.id.startswith(prefixes)]
    return sorted(items, key=lambda i: i.id)


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
            "group": c.group,
            "role": c.role,
            "source": c.source,
            "quantity": c.quantity,
            "unit": c.unit,
            "published": float(c.published),
            "computed": _json_float(self.computed),
            "rel_error": _json_float(self.rel_error),
            "tolerance": float(c.tolerance),
            "tolerance_reason": c.tolerance_reason,
            "passed": bool(self.passed),
            "known_deviation": c.known_deviation,
            "note": c.note,
            "error": self.error,
        }

    @property
    def status(self) -> str:
        """``pass`` / ``calibrated`` (a met calibration) / ``known`` / ``FAIL`` / ``diagnostic``."""
        if self.error is not None:
            return "FAIL"
        if self.case.role == "diagnostic":
            return "diagnostic"
        if self.passed:
            return "calibrated" if self.case.role == "calibration" else "pass"
        return "known" if self.case.known_deviation else "FAIL"


def _json_float(x: float):
    return None if (x is None or not math.isfinite(x)) else float(x)


def register(case: Case) -> Case:
    """Add a case; ids are unique (also against the not-computable numbers)."""
    if case.id in _REGISTRY or case.id in _NOT_COMPUTABLE:
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


def all_cases(prefixes: Iterable[str] = (), diagnostics: bool = True) -> list[Case]:
    """All registered cases (importing every case module), filtered by id prefix, sorted by id.

    ``diagnostics=False`` leaves the diagnostic cases out (the counted ones only).
    """
    _load_all()
    prefixes = tuple(prefixes)
    cases = [
        c
        for c in _REGISTRY.values()
        if (not prefixes or c.id.startswith(prefixes)) and (diagnostics or c.counted)
    ]
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
    # bool(): a numpy published value or tolerance makes a numpy bool, which `validate --json` cannot write
    return CaseResult(case, computed, float(err), bool(abs(err) <= case.tolerance))


def run_cases(cases: Iterable[Case]) -> list[CaseResult]:
    """Run every case in order."""
    return [run_case(c) for c in cases]


def failures(results: Iterable[CaseResult]) -> list[CaseResult]:
    """Results that make ``validate`` exit 1: a counted case missing its tolerance without a stated
    known deviation, or any case (diagnostics too) whose computation raised."""
    return [r for r in results if r.status == "FAIL"]


@dataclass(frozen=True)
class GroupSummary:
    """Counts of one paper (or of the literature group)."""

    group: str
    title: str
    predictions: int
    passing: int
    calibrations: int
    calibrations_met: int
    deviations: int
    failures: int
    diagnostics: int
    not_computable: int

    def to_dict(self) -> dict:
        return dict(self.__dict__)


def summarize(results: Iterable[CaseResult], prefixes: Iterable[str] = ()) -> list[GroupSummary]:
    """Per paper (then the literature group): predictions passing / total, calibrations, deviations.

    Known deviations and failures are counted over the predictions; a calibration that is not met is a
    failure. ``not_computable`` counts the registered not-computable numbers of the paper.
    """
    results = list(results)
    groups = [g for g in (*PAPERS, LITERATURE) if any(r.case.group == g for r in results)]
    missing = not_computable(prefixes)
    out = []
    for g in groups:
        rs = [r for r in results if r.case.group == g]
        pred = [r for r in rs if r.case.role == "prediction"]
        cal = [r for r in rs if r.case.role == "calibration"]
        out.append(
            GroupSummary(
                group=g,
                title=PAPERS.get(g, "textbooks, standards, catalogues (not from the papers)"),
                predictions=len(pred),
                passing=sum(r.status == "pass" for r in pred),
                calibrations=len(cal),
                calibrations_met=sum(r.status == "calibrated" for r in cal),
                deviations=sum(r.status == "known" for r in pred + cal),
                failures=sum(r.status == "FAIL" for r in rs),
                diagnostics=sum(r.case.role == "diagnostic" for r in rs),
                not_computable=sum(i.group == g for i in missing),
            )
        )
    return out
