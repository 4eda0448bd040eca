"""Study evaluator ``seed004_ptrb`` (Zheng et al. 2022): the §6 PTRB objectives of a design population.

SI units: factor columns in SI, output columns name their unit.
"""

from __future__ import annotations

import numpy as np

from bearingkit.studies.evaluators import (
    Evaluator,
    Factor,
    assemble_arrays,
    group_cases,
    register,
)


# ------------------------------------------------------------------------------ seed 004 PTRB objectives
def _seed004_factors() -> dict[str, Factor]:
    from bearingkit.analysis.friction.threaded import RPM, TEST_TEMPERATURE_C
    from bearingkit.bearings.ptrb import ptrb_prototype

    p = ptrb_prototype()
    return {
        "contact_angle": Factor("contact_angle", "angle", p.contact_angle),
        "n_teeth": Factor("n_teeth", "count", p.n_teeth),
        "roller_contact_radius": Factor("roller_contact_radius", "length", p.roller_contact_radius),
        "roller_pitch_diameter": Factor("roller_pitch_diameter", "length", p.roller_pitch_diameter),
        "load_case": Factor("load_case", "text", "axial", batched=False),
        "load": Factor("load", "force", 20.0e3, batched=False),  # §6: 20 kN
        "speed": Factor("speed", "angular_velocity", 4000.0 * RPM, batched=False),  # §6: 4000 rpm
        "n_elements": Factor("n_elements", "count", 11, batched=False),  # §6: the maximum Z
        "lubricant": Factor("lubricant", "text", "L-AN", batched=False),
        "temperature": Factor("temperature", "temperature", TEST_TEMPERATURE_C, batched=False),
    }


def seed004_ptrb(cases):
    """Seed-004 PTRB §6 objectives of a design population (Zheng et al. 2022).

    Design variables α = ``contact_angle`` [rad], n = ``n_teeth`` [1], R_rr = ``roller_contact_radius``
    [m], d_R = ``roller_pitch_diameter`` [m] (D_pw and n·P held, Z = ``n_elements``) →
    :func:`bearingkit.papers.zheng2022.design.ptrb_objectives` under ``load`` [N] of ``load_case``
    (axial/radial) at ``speed`` [rad/s]. Outputs: ``C0_N``, ``C_N`` (ratings of the load case), ``M_Nm``,
    ``mu``, the four ratings, the Hertz-validity margin ``hertz_margin_m`` = 2 R_rr cos α − d_R (§5 (3)–(4),
    feasible ≥ 0) and ``feasible``.
    """
    import pandas as pd

    return pd.DataFrame(_seed004_columns(cases))


def _seed004_columns(cases) -> dict:
    """:func:`seed004_ptrb`'s outputs as numpy columns (name → (C,) array): what a study's workers send
    back, without a table built and taken apart again (issue 34)."""
    from bearingkit.papers.zheng2022.design import ptrb_objectives

    parts = []
    for idx, key in group_cases(cases, SEED004_FACTORS):
        sub = cases if len(idx) == len(cases) else cases.iloc[idx]  # one group: no copy
        alpha = sub["contact_angle"].to_numpy(float)
        r_rr = sub["roller_contact_radius"].to_numpy(float)
        d_r = sub["roller_pitch_diameter"].to_numpy(float)
        o = ptrb_objectives(
            alpha,
            sub["n_teeth"].to_numpy(float),
            r_rr,
            d_r,
            case=str(key["load_case"]),
            load=float(key["load"]),
            speed=float(key["speed"]),
            n_elements=int(key["n_elements"]),
            lubricant=str(key["lubricant"]),
            temperature_C=float(key["temperature"]),
        )
        table = {f"{k}_N": o[k] for k in ("C0", "C", "C0a", "Ca", "C0r", "Cr")}
        table.update(M_Nm=o["M"], mu=o["mu"], feasible=np.asarray(o["feasible"], bool))
        table["hertz_margin_m"] = 2.0 * r_rr * np.cos(alpha) - d_r
        parts.append((idx, table))
    return assemble_arrays(len(cases), parts)


seed004_ptrb.columns = _seed004_columns  # Evaluator.columns calls it instead of the function


SEED004_FACTORS = _seed004_factors()
PTRB = register(
    Evaluator(
        "seed004_ptrb",
        seed004_ptrb,
        SEED004_FACTORS,
        outputs=("C0_N", "C_N", "M_Nm"),
        description="seed-004 PTRB §6: load ratings C0, C and friction torque M of a design population",
        references=("zheng2022",),
    )
)
