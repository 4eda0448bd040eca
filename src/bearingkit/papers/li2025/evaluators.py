"""Study evaluator ``seed002_clearance`` (Li et al. 2025): radial-load shares of the ball–column rows.

SI units: factor columns in SI, output columns name their unit.
"""

from __future__ import annotations

import numpy as np

from bearingkit.studies.evaluators import (
    Evaluator,
    Factor,
    assemble_columns,
    group_cases,
    register,
)

# ------------------------------------------------------------------------------ seed 002 clearance map
#: Rows of the seed-002 ball–column bearing (:data:`bearingkit.bearings.ball_column.ROWS`).
SEED002_ROWS = ("ball_1", "roller_2", "ball_3")


def _seed002_factors() -> dict[str, Factor]:
    from bearingkit.papers.li2025.studies import paper_geometry

    g = paper_geometry()
    return {
        "clearance_ball": Factor("clearance_ball", "length", g.clearance_ball),
        "clearance_roller": Factor("clearance_roller", "length", g.clearance_roller),
        "radial_load": Factor("radial_load", "force", 20_000.0),  # condition 1 of Li et al. Table 2
        "axial_load": Factor("axial_load", "force", 0.0),
        "compliance_scale": Factor("compliance_scale", "dimensionless", 0.0, batched=False),
        "contact_angle": Factor("contact_angle", "angle", g.contact_angle, batched=False),
        "n_balls": Factor("n_balls", "count", g.n_balls, batched=False),
        "n_rollers": Factor("n_rollers", "count", g.n_rollers, batched=False),
    }


def seed002_clearance(cases):
    """Seed-002 ball–column bearing: radial-load share of each row vs clearances and load.

    ``clearance_ball`` / ``clearance_roller`` [m] are the radial (diametral) clearances of the ball rows
    and of the roller row (batched along the case axis with the loads), ``radial_load`` [N] acts along
    +x and ``axial_load`` [N] along +z. ``compliance_scale`` 0 solves with rigid rings
    (:func:`bearingkit.analysis.solver.quasistatic.solve`); > 0 couples the flexible outer ring of
    :func:`bearingkit.bearings.ball_column.outer_ring` (:func:`bearingkit.analysis.flexible.solve_flexible`,
    via :func:`bearingkit.papers.li2025.studies.solve_case`: beam + ovalisation, the paper's free ring). The
    share of row r is |F_r,radial| / Σ_rows.
    """
    from bearingkit.analysis.solver.quasistatic import load_vector
    from bearingkit.papers.li2025.studies import paper_geometry, solve_case

    parts = []
    for idx, key in group_cases(cases, SEED002_FACTORS):
        sub = cases.iloc[idx]
        geom = paper_geometry(
            clearance_ball=sub["clearance_ball"].to_numpy(float),
            clearance_roller=sub["clearance_roller"].to_numpy(float),
            contact_angle=float(key["contact_angle"]),
            n_balls=int(key["n_balls"]),
            n_rollers=int(key["n_rollers"]),
        )
        load = load_vector(F_x=sub["radial_load"].to_numpy(float), F_z=sub["axial_load"].to_numpy(float))
        res, flex = solve_case(geom, load, float(key["compliance_scale"]))
        radial = {n: np.hypot(*res.row_load(n)[:, :2].T) for n in SEED002_ROWS}
        total = sum(radial.values())
        table = {}
        for n in SEED002_ROWS:
            table[f"{n}_radial_N"] = radial[n]
            table[f"{n}_radial_share"] = np.divide(
                radial[n], total, out=np.zeros_like(total), where=total > 0
            )
            table[f"{n}_loaded_count"] = res.row(n).loaded_count
            table[f"{n}_max_load_N"] = res.row(n).max_load
            table[f"{n}_max_pressure_Pa"] = res.row(n).max_pressure.max(axis=-1)
        table["roller_radial_share"] = table["roller_2_radial_share"]
        table["converged"] = np.asarray(res.converged if flex is None else flex.converged, bool)
        parts.append((idx, table))
    return assemble_columns(len(cases), parts)


SEED002_FACTORS = _seed002_factors()
CLEARANCE = register(
    Evaluator(
        "seed002_clearance",
        seed002_clearance,
        SEED002_FACTORS,
        outputs=("roller_radial_share",),
        description="seed-002 ball–column bearing: radial-load shares of the rows vs clearances and load",
        references=("li2025",),
    )
)
