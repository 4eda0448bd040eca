"""Study evaluator ``seed001_scatter`` (Liu et al. 2022): the TRB 32008J with roller-diameter scatter.

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


# ------------------------------------------------------------------------------ seed studies (issue 9)
# ``seed001_scatter``: seed-001 TRB 32008J (Liu et al. 2022) with Gaussian roller-diameter scatter,
# ΔD_j = S_d z_j (eq. 14): the study samples the unit draws z1…zZ, the evaluator solves every
# realisation plus the ideal bearing in one batch → max contact force and sliding-friction increment.
# ``seed002_clearance``: seed-002 ball–column bearing (Li et al. 2025) → radial-load shares of the rows
# for ball-row / roller-row radial clearances and loads (rigid, or flexible outer ring).
# ``seed004_ptrb``: seed-004 PTRB §6 objectives (Zheng et al. 2022) C0, C, M of a design population.
def _seed001_factors() -> dict[str, Factor]:
    from bearingkit.analysis.friction.tapered import (
        DEFAULT_LUBRICANT,
        DEFAULT_TEMPERATURE_C,
        SEED001_SPEED,
        TRBOperatingPoint,
    )
    from bearingkit.bearings.tapered import SEED001_GEOMETRY

    out = {
        f"z{j}": Factor(f"z{j}", "dimensionless", 0.0) for j in range(1, SEED001_GEOMETRY["n_elements"] + 1)
    }
    out["magnitude"] = Factor("magnitude", "length", 1.0e-6)
    out["arrangement"] = Factor("arrangement", "text", "random", batched=False)
    out["axial_load"] = Factor("axial_load", "force", SEED001_AXIAL_LOAD, batched=False)
    out["speed"] = Factor("speed", "angular_velocity", SEED001_SPEED, batched=False)
    out["cage_slip"] = Factor("cage_slip", "dimensionless", 1.0e-4, batched=False)
    out["lubricant"] = Factor("lubricant", "text", DEFAULT_LUBRICANT, batched=False)
    out["temperature"] = Factor("temperature", "temperature", DEFAULT_TEMPERATURE_C, batched=False)
    # Reading of seed 001 eq. (8) (bearingkit.physics.friction.trb.SLIDING_MODELS), so a study can
    # compare the capped default with the equation as printed ("newtonian").
    out["sliding_model"] = Factor("sliding_model", "text", TRBOperatingPoint().sliding_model, batched=False)
    return out


#: Axial load of seed 001 §3 (Figs. 5–7: F_a = 10 kN) [N].
SEED001_AXIAL_LOAD = 10_000.0


def _ratio(x, ref):
    return np.divide(x - ref, ref, out=np.full(np.shape(x), np.nan), where=np.asarray(ref) != 0)


def seed001_scatter(cases):
    """Seed-001 TRB with roller-diameter scatter: contact and sliding-friction response per realisation.

    Roller j of a case gets ΔD_j = S_d z_j (Liu et al. 2022, eq. 14: ΔD ~ N(0, S_d²)) with ``magnitude``
    S_d [m] and the unit draws ``z1…zZ`` [1] (sampled by the study), arranged by ``arrangement``
    (:data:`bearingkit.physics.deviations.ARRANGEMENTS`). Each group of cases is one batched solve
    (:func:`bearingkit.analysis.friction.tapered.tapered_friction`) with the ideal bearing as an extra case,
    at ``axial_load`` [N], ``speed`` [rad/s], ``cage_slip`` [1], ``lubricant`` at ``temperature`` [°C],
    with eq. (8) read as ``sliding_model`` (default: the capped ``"limiting_shear"``).

    Outputs: ``max_contact_force_N`` (max_j Q_e,j), its ``contact_force_increment_ratio`` over the ideal
    bearing's, ``contact_force_variance_N2``, ``max_sliding_inner_N`` (max_j F_rs,i), the
    ``sliding_increment_N`` = max_j F_rs,i − F_rs,i(ideal) and its ratio, the ring torques [N·m] and their
    change ratios ΔM/M_ideal (as :func:`~bearingkit.analysis.friction.tapered.friction_monte_carlo`).
    """
    from bearingkit import checks
    from bearingkit.analysis.friction.tapered import TRBOperatingPoint, tapered_friction
    from bearingkit.papers.liu2022.calibration import seed001_row_identified as seed001_row
    from bearingkit.physics.deviations import arrange

    row = seed001_row()
    zcols = [f"z{j}" for j in range(1, row.n_elements + 1)]
    parts = []
    for idx, key in group_cases(cases, SEED001_FACTORS):
        sub = cases.iloc[idx]
        s_d = checks.non_negative("magnitude", sub["magnitude"].to_numpy(float), "m")
        dev = arrange(s_d[:, None] * sub[zcols].to_numpy(float), str(key["arrangement"]))
        dev = np.concatenate([np.zeros((1, row.n_elements)), dev])  # case 0: ideal rollers
        op = TRBOperatingPoint(
            speed=float(key["speed"]),
            cage_slip=float(key["cage_slip"]),
            lubricant=str(key["lubricant"]),
            temperature_C=float(key["temperature"]),
            sliding_model=str(key["sliding_model"]),
        )
        res = tapered_friction(row, float(key["axial_load"]), op, dev)
        q_max = res.load_outer.max(axis=-1)
        f_rs = res.max_sliding_inner
        parts.append(
            (
                idx,
                {
                    "max_contact_force_N": q_max[1:],
                    "ideal_max_contact_force_N": np.full(idx.size, q_max[0]),
                    "contact_force_increment_ratio": _ratio(q_max[1:], q_max[0]),
                    "contact_force_variance_N2": res.load_outer[1:].var(axis=-1),
                    "max_sliding_inner_N": f_rs[1:],
                    "ideal_max_sliding_inner_N": np.full(idx.size, f_rs[0]),
                    "sliding_increment_N": f_rs[1:] - f_rs[0],
                    "sliding_increment_ratio": _ratio(f_rs[1:], f_rs[0]),
                    "torque_inner_Nm": res.torque_inner[1:],
                    "torque_outer_Nm": res.torque_outer[1:],
                    "torque_inner_change_ratio": _ratio(res.torque_inner[1:], res.torque_inner[0]),
                    "torque_outer_change_ratio": _ratio(res.torque_outer[1:], res.torque_outer[0]),
                    "converged": np.asarray(res.converged[1:], bool) & bool(res.converged[0]),
                },
            )
        )
    return assemble_columns(len(cases), parts)


SEED001_FACTORS = _seed001_factors()
SCATTER = register(
    Evaluator(
        "seed001_scatter",
        seed001_scatter,
        SEED001_FACTORS,
        outputs=("max_contact_force_N", "sliding_increment_N", "sliding_increment_ratio"),
        description="seed-001 TRB 32008J: roller-diameter scatter → max contact force, sliding increment",
        references=("liu2022",),
    )
)
