"""Validation cases computed through the study machinery (issue 9): seed 000 Table 3, seed 004 Table 6.

SI values (N·m, N, dimensionless). Each group of cases runs ONE study (the example file through
:func:`bearingkit.studies.runner.run_study`, in process, memory store), cached per process:

* ``seed000/study/table3/run<k>/friction-torque`` (k = 1..9) — Table 3 of Tian et al. (2025) from the
  L9 study ``examples/studies/seed000_l9.toml``; published values, tolerance and known deviations are
  those of the direct cases ``seed000/table3/run<k>/friction-torque``
  (:mod:`bearingkit.validation.seed000_friction`), so the two paths must agree;
* ``seed000/study/table3/range-ranking`` — indicator: 1 if the study's range ranking equals the
  published D > A > C > B (§6.2, Fig. 20), else 0;
* ``seed000/study/table3/range/<A|B|C|D>`` — each factor's range R (max − min level mean) [N·m]; the
  published R is computed from the published Table 3 torques by the paper's §6.2 definition;
* ``seed004/study/table6/<point>/<C0a|Ca|mu_a|C0r|Cr|mu_r>`` — the §6 NSGA-II studies
  ``examples/studies/seed004_{axial,radial}_nsga2.toml`` (100 × 100): the Pareto solution nearest each
  Table 6 point in load ratings (C0, C; range-normalised, the study's ``[targets]``), its ratings and
  friction coefficient vs Table 6 of Zheng et al. (2022). The ratings are the selection coordinates,
  so their cases test whether the front REACHES the published point; μ is the independent check.

Tolerances. Table 3 runs: 0.25 (as the direct cases). Ranges: 0.25 (differences of those torques).
Table 6 ratings: 0.10 — the rating model reproduces Table 4's sweep endpoints to 3.5 %, and a selected
front point differs from the published one by the front's spacing and its C0–C coupling; Table 6 μ:
0.10 (μ printed to 2 digits, ±2–5 %, plus the friction model's Table 5 accuracy).
"""

from __future__ import annotations

from bearingkit.validation import seed000_friction as _direct
from bearingkit.validation.registry import _REGISTRY, Case, register

SOURCE_000 = _direct.SOURCE
SOURCE_004 = "Zheng et al. (2022) Machines 10:1051, doi:10.3390/machines10111051"
TOL_TABLE3 = 0.25
TOL_RANGE = 0.25
TOL_TABLE6_RATING = 0.10
TOL_TABLE6_MU = 0.10

_CACHE: dict = {}


# ------------------------------------------------------------------------------------------ seed 000
def _l9():
    if "l9" not in _CACHE:
        from bearingkit.studies.seed_studies import run_example, seed000_table3

        res = run_example("seed000_l9")
        _CACHE["l9"] = (res, seed000_table3(res))
    return _CACHE["l9"]


def study_torque(k: int) -> float:
    """Friction torque [N·m] of Table 3 run k (1..9), taken from the L9 study's results."""
    _, table = _l9()
    return float(table.loc[table["run"] == k, "torque_Nm"].item())


def study_ranking() -> tuple[str, ...]:
    """Factor labels of the L9 study ranked by decreasing range of the friction torque."""
    from bearingkit.studies.seed_studies import ranking

    res, _ = _l9()
    return ranking(res.analysis["range"])


def ranking_matches() -> float:
    """1.0 if the study's range ranking is the published D > A > C > B, else 0.0."""
    from bearingkit.studies.seed_studies import SEED000_PUBLISHED_RANKING

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
    from bearingkit.studies.seed_studies import seed000_published_ranges

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


# ------------------------------------------------------------------------------------------ seed 004
def _table6(case: str):
    key = f"table6-{case}"
    if key not in _CACHE:
        from bearingkit.studies.seed_studies import seed004_optimize, table6_comparison

        _CACHE[key] = table6_comparison(seed004_optimize(case)).set_index("point")
    return _CACHE[key]


def table6_value(point: str, quantity: str) -> float:
    """``C0_N``, ``C_N`` or ``mu`` of the front solution selected nearest Table 6 point ``point``."""
    case = "axial" if point.startswith("xa") else "radial"
    return float(_table6(case).loc[point, quantity])


MU_DEVIATION = (
    "the radial front sits at alpha ~ 30-33 deg, where bearingkit's radial torque is low (Table 5 "
    "contact-angle row: alpha acts too strongly under radial load, +174 % vs +67 % over 30-60 deg); at "
    "the published designs mu_a is within -2.5...+10 % and mu_r within -10...+27 % "
    "(bearingkit.studies.seed004.table6_at_published_designs)"
)
#: Table 6 quantities that the studies are known to miss (point → quantities).
_KNOWN = {
    "xa1": {},
    "xa2": {},
    "xr1": {"mu_r": MU_DEVIATION},
    "xr2": {"mu_r": MU_DEVIATION},
}


def _register_seed004() -> None:
    from bearingkit.studies.seed004 import TABLE6_OBJECTIVES

    for point in ("xa1", "xa2", "xr1", "xr2"):
        s = "a" if point.startswith("xa") else "r"
        pub = TABLE6_OBJECTIVES[point]
        items = (
            (f"C0{s}", "C0_N", pub[f"C0{s}_kN"] * 1e3, "N", TOL_TABLE6_RATING, "basic static load rating"),
            (f"C{s}", "C_N", pub[f"C{s}_kN"] * 1e3, "N", TOL_TABLE6_RATING, "basic dynamic load rating"),
            (f"mu_{s}", "mu", pub[f"mu_{s}_1e3"] * 1e-3, "1", TOL_TABLE6_MU, "friction coefficient"),
        )
        load = "axial" if s == "a" else "radial"
        for name, column, published, unit, tol, what in items:
            register(
                Case(
                    id=f"seed004/study/table6/{point}/{name}",
                    source=f"{SOURCE_004}, Table 6 ({point}); NSGA-II 100 x 100 of "
                    f"examples/studies/seed004_{load}_nsga2.toml",
                    quantity=f"{what} ({load}) of the Pareto solution nearest {point} in (C0, C), "
                    "20 kN, 4000 rpm",
                    unit=unit,
                    published=published,
                    compute=lambda p=point, c=column: table6_value(p, c),
                    tolerance=tol,
                    known_deviation=_KNOWN[point].get(name),
                )
            )


_register_seed000()
_register_seed004()
