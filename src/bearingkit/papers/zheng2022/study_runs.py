"""The §6 NSGA-II studies of Zheng et al. (2022): Pareto front, selections and the Table 6 comparison.

SI units (N, N·m, m, rad). ``examples/studies/seed004_{axial,radial}_nsga2.toml``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from bearingkit.papers.examples import run_example
from bearingkit.studies.run.cases import StudyResult


def seed004_optimize(case: str = "axial", *, pop_size=None, generations=None, **run) -> StudyResult:
    """Run the §6 NSGA-II study of ``case`` ("axial" or "radial"), optionally with a smaller size."""
    from bearingkit.errors import InputError

    if case not in ("axial", "radial"):
        raise InputError(f"case ({case!r}) must be 'axial' or 'radial'")
    return run_example(f"seed004_{case}_nsga2", pop_size=pop_size, generations=generations, **run)


def table6_comparison(result: StudyResult, case: str | None = None):
    """The selections nearest the Table 6 points beside the published design and performance.

    Parameters
    ----------
    result : StudyResult
        A :func:`seed004_optimize` result (its ``selections`` name the Table 6 points).
    case : {"axial", "radial"} or None
        Default: the study's fixed ``load_case``.

    Returns
    -------
    DataFrame
        One row per point: computed ``C0_N``, ``C_N``, ``mu`` and design (α [deg], n, R_rr [mm],
        d_R [mm]) of the selected front solution, the published values (``*_pub``), the relative errors
        ``C0_err``, ``C_err``, ``mu_err``, and ``nearest_distance`` — the distance of the front to the
        published point in (C0, C, μ) scaled by the published values
        (:func:`bearingkit.papers.zheng2022.studies.nearest_table6`).
    """
    import pandas as pd

    from bearingkit.papers.zheng2022.studies import TABLE6, TABLE6_OBJECTIVES, nearest_table6

    case = case or result.definition.fixed.get("load_case", "axial")
    s = "a" if case == "axial" else "r"
    front = result.pareto
    near = nearest_table6({"C0": front["C0_N"], "C": front["C_N"], "mu": front["mu"]}, case)
    near = near.set_index("point")
    rows = []
    for _, sel in result.selections.iterrows():
        name = sel["selection"]
        if name not in TABLE6_OBJECTIVES:
            continue
        pub, x = TABLE6_OBJECTIVES[name], TABLE6[name]
        c0p, cp, mup = pub[f"C0{s}_kN"] * 1e3, pub[f"C{s}_kN"] * 1e3, pub[f"mu_{s}_1e3"] * 1e-3
        rows.append(
            dict(
                point=name,
                C0_N=sel["C0_N"],
                C_N=sel["C_N"],
                mu=sel["mu"],
                M_Nm=sel["M_Nm"],
                alpha_deg=np.degrees(sel["contact_angle"]),
                n=int(np.rint(sel["n_teeth"])),
                R_rr_mm=sel["roller_contact_radius"] * 1e3,
                d_R_mm=sel["roller_pitch_diameter"] * 1e3,
                C0_pub_N=c0p,
                C_pub_N=cp,
                mu_pub=mup,
                alpha_deg_pub=x["alpha_deg"],
                n_pub=x["n"],
                R_rr_mm_pub=x["R_rr_mm"],
                d_R_mm_pub=x["d_R_mm"],
                C0_err=sel["C0_N"] / c0p - 1.0,
                C_err=sel["C_N"] / cp - 1.0,
                mu_err=sel["mu"] / mup - 1.0,
                nearest_distance=float(near.loc[name, "distance"]) if name in near.index else np.nan,
            )
        )
    return pd.DataFrame(rows)


def export_front(result: StudyResult, out_dir) -> dict:
    """Write the Pareto front, the selections and the Table 6 comparison (CSV) and a front plot (PNG)."""
    from bearingkit.studies.results import analysis

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    name = result.definition.name
    paths = {
        "pareto": out / f"{name}_pareto.csv",
        "selections": out / f"{name}_selections.csv",
        "table6": out / f"{name}_table6.csv",
        "plot": out / f"{name}_pareto.png",
    }
    result.pareto.to_csv(paths["pareto"], index=False)
    result.selections.to_csv(paths["selections"], index=False)
    table6_comparison(result).to_csv(paths["table6"], index=False)
    analysis.plot_pareto(result.pareto, ["C0_N", "M_Nm"], paths["plot"], result.selections)
    return paths
