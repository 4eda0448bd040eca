"""Validation cases of Tian et al. (2025) computed through the study machinery: Table 3 and its ranges.

SI values (N·m). The group runs ONE study (``examples/studies/seed000_l9.toml`` through
:func:`bearingkit.studies.run.runner.run_study`, in process, memory store), cached per process:

* ``seed000/study/table3/run<k>/friction-torque`` (k = 1..9) — Table 3 from the L9 study; published
  values, tolerance and known deviations are those of the direct cases
  ``seed000/table3/run<k>/friction-torque`` (:mod:`bearingkit.papers.tian2025.validation`), so the two
  paths must agree;
* ``seed000/study/table3/range-ranking`` — indicator: 1 if the study's range ranking equals the
  published D > A > C > B (§6.2, Fig. 20), else 0;
* ``seed000/study/table3/range/<A|B|C|D>`` — each factor's range R (max − min level mean) [N·m]; the
  published R is computed from the published Table 3 torques by the paper's §6.2 definition.

Tolerances: Table 3 runs 0.25 (as the direct cases); ranges 0.25 (differences of those torques).
"""

from __future__ import annotations

from bearingkit.papers.tian2025 import validation as _direct
from bearingkit.validation.registry import _REGISTRY, Case, register

SOURCE_000 = _direct.SOURCE
TOL_TABLE3 = 0.25
TOL_RANGE = 0.25

_CACHE: dict = {}


def _l9():
    if "l9" not in _CACHE:
        from bearingkit.papers.examples import run_example
        from bearingkit.papers.tian2025.study_runs import seed000_table3

        res = run_example("seed000_l9")
        _CACHE["l9"] = (res, seed000_table3(res))
    return _CACHE["l9"]


def study_torque(k: int) -> float:
    """Friction torque [N·m] of Table 3 run k (1..9), taken from the L9 study's results."""
    _, table = _l9()
    return float(table.loc[table["run"] == k, "torque_Nm"].item())


def study_ranking() -> tuple[str, ...]:
    """Factor labels of the L9 study ranked by decreasing range of the friction torque."""
    from bearingkit.papers.tian2025.study_runs import ranking

    res, _ = _l9()
    return ranking(res.analysis["range"])


def ranking_matches() -> float:
    """1.0 if the study's range ranking is the published D > A > C > B, else 0.0."""
    from bearingkit.papers.tian2025.study_runs import SEED000_PUBLISHED_RANKING

    return float(study_ranking() == SEED000_PUBLISHED_RANKING)


def study_range(label: str) -> float:
    """Range R [N·m] of the factor labelled ``label`` in the L9 study."""
    res, _ = _l9()
    r = res.analysis["range"]
    return float(r.loc[r["label"] == label, "range"].item())


RANKING_DEVIATION = (
    "computed D > A > B > C: D and A lead as published, but B and C swap; their ranges are both small "
    "(computed R_B ~ 0.06, R_C ~ 0.05 N*m vs the paper's 0.10 and 0.26 N*m from Table 3). In bearingkit a "
    "looser groove (larger C) shifts load to the rollers (+torque) but lowers the ball spin loss (narrower "
    "ellipse), and the two nearly cancel (see seed000/conclusion/groove-steep-rise)"
)
RANGE_DEVIATION = (
    "every range is smaller than the paper's: the computed torques grow with the roller load ~3x slower "
    "than the published ones (runs 3, 4, 7, 8 are 30-38 % low, see seed000/table3/run*/friction-torque), "
    "which compresses the level means of each factor"
)


def _register_seed000() -> None:
    for k, (a, b, c, e, _m) in enumerate(_direct.TABLE3, start=1):
        direct = _REGISTRY[f"seed000/table3/run{k}/friction-torque"]
        register(
            Case(
                id=f"seed000/study/table3/run{k}/friction-torque",
                source=f"{SOURCE_000}, Table 3 run {k} (A={a} um, B={b} um, C={c}, D={e} m), "
                "computed through the L9 study examples/studies/seed000_l9.toml",
                quantity="bearing friction torque at F_a = F_r = 3 kN, M = -e F_a, 5 r/min (study path)",
                unit="N*m",
                published=direct.published,
                compute=lambda k=k: study_torque(k),
                tolerance=max(TOL_TABLE3, direct.tolerance),
                known_deviation=direct.known_deviation,
            )
        )
    register(
        Case(
            id="seed000/study/table3/range-ranking",
            source=f"{SOURCE_000}, §6.2 and Fig. 20 (range analysis of Table 3)",
            quantity="indicator: range ranking of the friction torque equals D > A > C > B",
            unit="1",
            published=1.0,
            compute=ranking_matches,
            tolerance=0.0,
            known_deviation=RANKING_DEVIATION,
        )
    )
    from bearingkit.papers.tian2025.study_runs import seed000_published_ranges

    for label, published in seed000_published_ranges().items():
        register(
            Case(
                id=f"seed000/study/table3/range/{label}",
                source=f"{SOURCE_000}, §6.2: R = max - min level mean of the published Table 3 torques",
                quantity=f"range of the friction torque over the levels of factor {label} (L9 study)",
                unit="N*m",
                published=published,
                compute=lambda label=label: study_range(label),
                tolerance=TOL_RANGE,
                known_deviation=RANGE_DEVIATION,
            )
        )


_register_seed000()
