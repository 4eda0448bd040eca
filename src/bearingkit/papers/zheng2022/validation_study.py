"""Validation cases of Zheng et al. (2022) computed through the study machinery: Table 6.

SI values (N, dimensionless). ``seed004/study/table6/<point>/<C0a|Ca|mu_a|C0r|Cr|mu_r>`` — the §6 NSGA-II
studies ``examples/studies/seed004_{axial,radial}_nsga2.toml`` (100 × 100), run once per process: the
Pareto solution nearest each Table 6 point in load ratings (C0, C; range-normalised, the study's
``[targets]``), its ratings and friction coefficient vs Table 6. The ratings are the selection
coordinates, so their cases test whether the front REACHES the published point; μ is the independent
check.

Tolerances. Table 6 ratings: 0.10 — the rating model reproduces Table 4's sweep endpoints to 3.5 %, and a
selected front point differs from the published one by the front's spacing and its C0–C coupling; Table 6
μ: 0.10 (μ printed to 2 digits, ±2–5 %, plus the friction model's Table 5 accuracy).
"""

from __future__ import annotations

from bearingkit.validation.registry import Case, register

SOURCE_004 = "Zheng et al. (2022) Machines 10:1051, doi:10.3390/machines10111051"
TOL_TABLE6_RATING = 0.10
TOL_TABLE6_MU = 0.10

_CACHE: dict = {}


def _table6(case: str):
    key = f"table6-{case}"
    if key not in _CACHE:
        from bearingkit.papers.zheng2022.study_runs import seed004_optimize, table6_comparison

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
    "(bearingkit.papers.zheng2022.studies.table6_at_published_designs)"
)
#: Table 6 quantities that the studies are known to miss (point → quantities).
_KNOWN = {
    "xa1": {},
    "xa2": {},
    "xr1": {"mu_r": MU_DEVIATION},
    "xr2": {"mu_r": MU_DEVIATION},
}


def _register_seed004() -> None:
    from bearingkit.papers.zheng2022.studies import TABLE6_OBJECTIVES

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


_register_seed004()
