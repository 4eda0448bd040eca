"""The L9 study of Tian et al. (2025) (Tables 2–3): Table 3 per run and the range ranking.

SI units (N·m, m). ``examples/studies/seed000_l9.toml`` run by the study machinery.
"""

from __future__ import annotations

import numpy as np

from bearingkit.studies.run.cases import StudyResult

#: Seed 000 §6.2 / Fig. 20: eccentricity D > axial roller clearance A > groove curvature C > ball clearance B.
SEED000_PUBLISHED_RANKING = ("D", "A", "C", "B")
#: Factor label of each Table 3 column (Table 2).
SEED000_LABELS = {
    "clearance_axial_roller": "A",
    "clearance_axial_ball": "B",
    "groove_curvature": "C",
    "eccentricity": "D",
}


def ranking(range_table) -> tuple[str, ...]:
    """Factor labels by decreasing range (the ``range`` table of a study's analysis)."""
    return tuple(range_table.sort_values("rank")["label"])


def _table3():
    from bearingkit.papers.tian2025.validation import TABLE3

    return TABLE3


def seed000_table3(result: StudyResult):
    """Table 3 run k (1–9) beside the study's case with the same factor values.

    Returns
    -------
    DataFrame
        ``run``, ``case``, the four factor values (SI), ``torque_Nm`` (computed), ``published_Nm``,
        ``rel_error``. Raises if a Table 3 run is missing from the study's design.
    """
    import pandas as pd

    from bearingkit.errors import InputError

    res = result.results
    rows = []
    for k, (a, b, c, e, m) in enumerate(_table3(), start=1):
        hit = (
            np.isclose(res["clearance_axial_roller"], a * 1e-6, rtol=0, atol=1e-9)
            & np.isclose(res["clearance_axial_ball"], b * 1e-6, rtol=0, atol=1e-9)
            & np.isclose(res["groove_curvature"], c, rtol=0, atol=1e-9)
            & np.isclose(res["eccentricity"], e, rtol=0, atol=1e-9)
        )
        if hit.sum() != 1:
            raise InputError(f"Table 3 run {k} ({a} um, {b} um, {c}, {e} m) is not one case of the study")
        row = res[hit].iloc[0]
        t = float(row["friction_torque_Nm"])
        rows.append(
            dict(
                run=k,
                case=int(row["case"]),
                clearance_axial_roller=a * 1e-6,
                clearance_axial_ball=b * 1e-6,
                groove_curvature=c,
                eccentricity=e,
                torque_Nm=t,
                published_Nm=m / 1e3,
                rel_error=t / (m / 1e3) - 1.0,
            )
        )
    return pd.DataFrame(rows)


def seed000_published_ranges() -> dict:
    """Range R [N·m] of each factor label computed from the published Table 3 torques (§6.2 method)."""
    import pandas as pd

    from bearingkit.studies.results import analysis

    t = pd.DataFrame(_table3(), columns=[*SEED000_LABELS, "torque_Nmm"])
    t["torque_Nm"] = t["torque_Nmm"] / 1e3
    r = analysis.range_analysis(t, list(SEED000_LABELS), "torque_Nm", SEED000_LABELS)
    return dict(zip(r["label"], r["range"].astype(float), strict=True))
