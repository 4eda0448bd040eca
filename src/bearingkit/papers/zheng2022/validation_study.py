"""Validation cases of Zheng et al. (2022) computed through the study machinery: Table 6.

SI values (N, dimensionless, m, rad). The §6 NSGA-II studies ``examples/studies/seed004_{axial,
radial}_nsga2.toml`` (100 × 100), run once per process, give a Pareto front per load case; the front
solution nearest each Table 6 point in (C0, C) (range-normalised, the study's ``[targets]``) is selected.

* ``seed004/table6/<point>/<P|d_R|R_rr|alpha|n>`` — predictions (issue 32): Table 6's DESIGN VARIABLES
  against those of the selected front solution. The paper picked "two non-inferior solutions" per
  front; its objectives locate them, so the design the front puts there is bearingkit's prediction of
  the printed design. P = 12 mm / n (the study holds n·P, as the Table 4 sweeps). Tolerances 10 %
  (values) and exact for the tooth count n.
* ``seed004/study/table6/<point>/<C0a|Ca|mu_a|C0r|Cr|mu_r>`` — diagnostics: Table 6's performance
  indices at the selected front solution. The same numbers are counted at the PUBLISHED designs
  (``seed004/table6-design/*``, :mod:`bearingkit.papers.zheng2022.validation_designs`); here they show
  how far the front reaches the published point (the ratings are the selection coordinates) and what the
  selected design gives for the other load case.
"""

from __future__ import annotations

import numpy as np

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


def table6_cross_value(point: str, quantity: str) -> float:
    """The OTHER load case's ``C0_N``, ``C_N`` or ``mu`` of the front solution selected nearest ``point``.

    The axial study selects xa1/xa2 by (C0a, Ca); Table 6 also prints their C0r, Cr, μ_r (and C0a, Ca,
    μ_a of xr1/xr2): the selected design (α, n, R_rr, d_R; Z = 11 as in the study) evaluated with the
    other case of :func:`bearingkit.papers.zheng2022.design.ptrb_objectives`.
    """
    import numpy as np

    from bearingkit.papers.zheng2022.design import ptrb_objectives

    own = "axial" if point.startswith("xa") else "radial"
    other = "radial" if own == "axial" else "axial"
    sel = _table6(own).loc[point]
    o = ptrb_objectives(
        np.radians(sel["alpha_deg"]), sel["n"], sel["R_rr_mm"] * 1e-3, sel["d_R_mm"] * 1e-3, case=other
    )
    return float(np.asarray(o[quantity.removesuffix("_N")])[0])


MU_DEVIATION = (
    "the radial front sits at alpha ~ 30-33 deg, where bearingkit's radial torque is low (Table 5 "
    "contact-angle row: alpha acts too strongly under radial load, +174 % vs +67 % over 30-60 deg); at "
    "the published designs mu_a is within -1.3...+10.1 % and mu_r within -10.3...+28.8 % "
    "(seed004/table6-design/*)"
)
CROSS_DEVIATION = (
    "the front reaches the point's own (C0, C) with another design than the paper's: bearingkit's axial "
    "torque falls with alpha and its radial torque rises strongly with it (Table 5 contact-angle row, "
    "known deviation), so the axial front runs to the alpha bound (xa1: 60 deg, d_R 5.25 mm, n 16; xa2: "
    "57.6 deg, n 9 vs published 53.5 / 47.6 deg) and the radial front to the lower bound (xr1, xr2: 30 deg "
    "vs 52.5 / 39.3 deg). The own objectives do not determine the other case's: at such alpha C0r, Cr "
    "come out 25-34 % low and C0a, Ca 27-53 % low. At the PUBLISHED designs the cross quantities are "
    "compared in seed004/table6-design/*"
)
#: Table 6 quantities that the studies are known to miss (point → quantities).
_KNOWN = {
    "xa1": dict.fromkeys(("C0r", "Cr", "mu_r"), CROSS_DEVIATION),
    "xa2": dict.fromkeys(("C0r", "Cr", "mu_r"), CROSS_DEVIATION),
    "xr1": {"mu_r": MU_DEVIATION, **dict.fromkeys(("C0a", "Ca", "mu_a"), CROSS_DEVIATION)},
    "xr2": {"mu_r": MU_DEVIATION, **dict.fromkeys(("C0a", "Ca", "mu_a"), CROSS_DEVIATION)},
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
            _register_case(point, name, column, published, unit, tol, what, load, own=True)
        x = "r" if s == "a" else "a"
        cross = (
            (f"C0{x}", "C0_N", pub[f"C0{x}_kN"] * 1e3, "N", TOL_TABLE6_RATING, "basic static load rating"),
            (f"C{x}", "C_N", pub[f"C{x}_kN"] * 1e3, "N", TOL_TABLE6_RATING, "basic dynamic load rating"),
            (f"mu_{x}", "mu", pub[f"mu_{x}_1e3"] * 1e-3, "1", TOL_TABLE6_MU, "friction coefficient"),
        )
        for name, column, published, unit, tol, what in cross:
            _register_case(point, name, column, published, unit, tol, what, load, own=False)


def _register_case(point, name, column, published, unit, tol, what, load, own):
    other = "radial" if load == "axial" else "axial"
    if own:
        quantity = f"{what} ({load}) of the Pareto solution nearest {point} in (C0, C), 20 kN, 4000 rpm"

        def compute(p=point, c=column):
            return table6_value(p, c)
    else:
        quantity = (
            f"{what} ({other}) of the {load} study's Pareto solution nearest {point} in (C0, C), "
            "20 kN, 4000 rpm (Table 6 cross quantity)"
        )

        def compute(p=point, c=column):
            return table6_cross_value(p, c)

    register(
        Case(
            id=f"seed004/study/table6/{point}/{name}",
            source=f"{SOURCE_004}, Table 6 ({point}); NSGA-II 100 x 100 of "
            f"examples/studies/seed004_{load}_nsga2.toml",
            quantity=quantity,
            unit=unit,
            published=published,
            compute=compute,
            tolerance=tol,
            known_deviation=_KNOWN[point].get(name),
            role="diagnostic",
            note=f"the counted Table 6 value is seed004/table6-design/{point}/{name} (at the published "
            "design); this is the nearest front solution's",
        )
    )


_register_seed004()


#: Table 6 design variables: key → (column of the selection, TABLE6 key, SI factor, unit, what).
DESIGN_VARIABLES = {
    "P": (None, "P_mm", 1e-3, "m", "distance between adjacent threads P"),
    "d_R": ("d_R_mm", "d_R_mm", 1e-3, "m", "pitch diameter of the threaded roller d_R"),
    "R_rr": ("R_rr_mm", "R_rr_mm", 1e-3, "m", "contact radius of the threaded roller R_rr"),
    "alpha": ("alpha_deg", "alpha_deg", np.pi / 180.0, "rad", "contact angle alpha"),
    "n": ("n", "n", 1.0, "1", "number of thread teeth per roller n"),
}
TOL_DESIGN = 0.10


def design_variable(point: str, key: str) -> float:
    """The selected front solution's design variable ``key`` (:data:`DESIGN_VARIABLES`) in SI."""
    from bearingkit.papers.zheng2022.design import PROTOTYPE_THREAD_LENGTH

    case = "axial" if point.startswith("xa") else "radial"
    sel = _table6(case).loc[point]
    column, _, factor, _, _ = DESIGN_VARIABLES[key]
    if column is None:  # P = n·P / n
        return float(PROTOTYPE_THREAD_LENGTH / sel["n"])
    return float(sel[column]) * factor


DESIGN_DEVIATION = (
    "the front puts the point's (C0, C) at another design than the paper: bearingkit's axial torque falls "
    "with alpha and its radial torque rises strongly with it (Table 5 contact-angle row, a row "
    "inconsistent with the paper's own load exponent: seed004/table5/contact_angle/*), so the axial front "
    "runs towards the upper alpha bound and the radial front to the lower one, and d_R, R_rr and n follow "
    "to reach the ratings there"
)


#: Design variables the selected solutions miss (NSGA-II with the studies' fixed seed): point → keys.
DESIGN_KNOWN = {
    "xa1": ("R_rr", "alpha", "d_R", "n"),
    "xa2": ("P", "alpha", "d_R", "n"),
    "xr1": ("R_rr", "alpha", "n"),
    "xr2": ("alpha", "n"),
}


def _register_design_variables() -> None:
    from bearingkit.papers.zheng2022.studies import TABLE6

    for point in ("xa1", "xa2", "xr1", "xr2"):
        load = "axial" if point.startswith("xa") else "radial"
        for key, (_, tkey, factor, unit, what) in DESIGN_VARIABLES.items():
            published = TABLE6[point][tkey] * factor
            register(
                Case(
                    id=f"seed004/table6/{point}/{key}",
                    source=f"{SOURCE_004}, Table 6 ({point}, structure parameter); NSGA-II 100 x 100 of "
                    f"examples/studies/seed004_{load}_nsga2.toml",
                    quantity=f"{what} of the {load} Pareto solution nearest {point} in (C0, C)",
                    unit=unit,
                    published=published,
                    compute=lambda p=point, k=key: design_variable(p, k),
                    tolerance=0.0 if key == "n" else TOL_DESIGN,
                    known_deviation=DESIGN_DEVIATION if key in DESIGN_KNOWN[point] else None,
                )
            )


_register_design_variables()
