"""Study evaluators of the seed-000 composite turntable bearing (Tian et al. 2025): statics, friction.

SI units: factor columns in SI, output columns name their unit. Registered under the names
``seed000_statics`` and ``seed000_friction`` (entry points of the group ``bearingkit.evaluators``).
"""

from __future__ import annotations

import dataclasses

import numpy as np

from bearingkit.studies.evaluators import (
    Evaluator,
    Factor,
    assemble_columns,
    group_cases,
    python_value,
    register,
)


# ------------------------------------------------------------------------------ seed 000 bearing
def _turntable_factors() -> dict[str, Factor]:
    from bearingkit.bearings.turntable import CompositeTurntableGeometry

    dims = {
        "groove_curvature": "dimensionless",
        "crowning": "text",
        "pairing": "text",
    }
    batched = {"clearance_axial_roller", "clearance_axial_ball", "clearance_radial", "groove_curvature"}
    out = {}
    for f in dataclasses.fields(CompositeTurntableGeometry):
        dim = dims.get(f.name, "count" if f.name.startswith("n_") else "length")
        out[f.name] = Factor(f.name, dim, f.default, f.name in batched)
    out["axial_load"] = Factor("axial_load", "force", 0.0)
    out["radial_load"] = Factor("radial_load", "force", 0.0)
    out["eccentricity"] = Factor("eccentricity", "length", 0.0)
    return out


#: Rows of the composite bearing (:func:`bearingkit.bearings.turntable.composite_turntable`).
TURNTABLE_ROWS = ("roller_upper", "ball_upper", "roller_lower", "ball_lower", "roller_radial")
#: Speed used when a friction study does not give one [rad/s]: 5 r/min, the test speed of seed 000 §5.
DEFAULT_SPEED = 5.0 * 2.0 * np.pi / 60.0


def _analyses(cases, factors, **operating):
    """Yield (idx, Analysis, group key) for every group of cases: one pipeline analysis (one batched
    solve) per group; ``operating(sub, key) -> dict`` gives each group's operating conditions."""
    from bearingkit.bearings.common import eccentric_axial_load
    from bearingkit.bearings.turntable import CompositeTurntableGeometry, composite_turntable
    from bearingkit.pipeline import ModelInput, analyze

    geom = {f.name for f in dataclasses.fields(CompositeTurntableGeometry)}
    for idx, key in group_cases(cases, factors):
        sub = cases.iloc[idx]
        kw = {k: python_value(v, factors[k]) for k, v in key.items() if k in geom}
        for name in geom - set(key):
            kw[name] = sub[name].to_numpy(dtype=float)
        model = composite_turntable(**kw)
        load = eccentric_axial_load(
            sub["axial_load"].to_numpy(float),
            sub["eccentricity"].to_numpy(float),
            sub["radial_load"].to_numpy(float),
        )
        conditions = operating["conditions"](sub, key) if operating else {}
        yield idx, analyze(ModelInput(model, load, source="seed000 study"), **conditions), key


def _statics_table(res) -> dict:
    out = {}
    for name in TURNTABLE_ROWS:
        row, force = res.row(name), res.row_load(name)
        out[f"{name}_axial_N"] = np.abs(force[:, 2])
        out[f"{name}_radial_N"] = np.hypot(force[:, 0], force[:, 1])
        out[f"{name}_max_load_N"] = row.max_load
        out[f"{name}_loaded_count"] = row.loaded_count
        out[f"{name}_max_pressure_Pa"] = row.max_pressure.max(axis=-1)
    balls = out["ball_upper_axial_N"] + out["ball_lower_axial_N"]
    rollers = out["roller_upper_axial_N"] + out["roller_lower_axial_N"]
    total = balls + rollers
    out["ball_axial_share"] = np.divide(balls, total, out=np.zeros_like(total), where=total > 0)
    out["max_ball_pressure_Pa"] = np.maximum(
        out["ball_upper_max_pressure_Pa"], out["ball_lower_max_pressure_Pa"]
    )
    out["max_roller_pressure_Pa"] = np.maximum.reduce(
        [out[f"{r}_max_pressure_Pa"] for r in ("roller_upper", "roller_lower", "roller_radial")]
    )
    for k, lab in enumerate(("u_x_m", "u_y_m", "u_z_m", "theta_x_rad", "theta_y_rad")):
        out[lab] = res.displacement[:, k]
    out["converged"] = np.asarray(res.converged, bool)
    out["iterations"] = np.asarray(res.iterations, int)
    return out


def seed000_statics(cases):
    """Statics of the seed-000 composite turntable bearing for a batch of cases.

    Loads: an axial force ``axial_load`` [N] at ``eccentricity`` [m] along +x (M_y = −e·F_a) and a
    radial force ``radial_load`` [N] along +x (:func:`bearingkit.bearings.common.eccentric_axial_load`).
    Geometry factors are the fields of :class:`~bearingkit.bearings.turntable.CompositeTurntableGeometry`.
    Clearances and groove curvature batch along the case axis; other geometry groups the cases.
    """
    parts = [(idx, _statics_table(a.statics)) for idx, a, _ in _analyses(cases, SEED000_FACTORS)]
    return assemble_columns(len(cases), parts)


SEED000_FACTORS = _turntable_factors()
STATICS = register(
    Evaluator(
        "seed000_statics",
        seed000_statics,
        SEED000_FACTORS,
        outputs=("ball_axial_share", "max_ball_pressure_Pa", "max_roller_pressure_Pa"),
        bearing_type="composite_turntable",
        description="seed-000 composite turntable bearing: row loads, ball share, max loads and pressures",
        references=("tian2025",),
    )
)


# ------------------------------------------------------------------------------ seed 000 friction
def _friction_factors() -> dict[str, Factor]:
    from bearingkit.analysis.friction.components import OperatingPoint

    defaults = {f.name: f.default for f in dataclasses.fields(OperatingPoint)}
    out = dict(SEED000_FACTORS)
    out["speed"] = Factor("speed", "angular_velocity", DEFAULT_SPEED)
    out["temperature"] = Factor("temperature", "temperature", defaults["temperature"], batched=False)
    out["lubricant"] = Factor("lubricant", "text", defaults["lubricant"], batched=False)
    out["viscosity_factor"] = Factor("viscosity_factor", "dimensionless", 1.0, batched=False)
    out["cage_mass"] = Factor("cage_mass", "mass", defaults["cage_mass"], batched=False)
    out["roller_sliding"] = Factor(
        "roller_sliding", "dimensionless", defaults["roller_sliding"], batched=False
    )
    return out


def seed000_friction(cases):
    """Statics (:func:`seed000_statics`) plus the friction torque of the seed-000 bearing [N·m].

    Operating point: inner ring at ``speed`` [rad/s], outer ring fixed, ``lubricant`` at ``temperature``
    [°C], ``viscosity_factor``, ``cage_mass`` [kg] and ``roller_sliding`` [1] as
    :class:`bearingkit.analysis.friction.components.OperatingPoint`.
    """

    def conditions(sub, key) -> dict:
        return {
            "speed": sub["speed"].to_numpy(float),
            "lubricant": str(key["lubricant"]),
            "temperature": float(key["temperature"]),
            "friction_options": {
                "viscosity_factor": float(key["viscosity_factor"]),
                "cage_mass": float(key["cage_mass"]),
                "roller_sliding": float(key["roller_sliding"]),
            },
        }

    parts = []
    for idx, a, _ in _analyses(cases, FRICTION_FACTORS, conditions=conditions):
        fr = a.friction_by("components").native
        table = _statics_table(a.statics)
        table["friction_torque_Nm"] = fr.total
        for name, v in fr.components.items():
            table[f"torque_{name}_Nm"] = v
        parts.append((idx, table))
    return assemble_columns(len(cases), parts)


FRICTION_FACTORS = _friction_factors()
FRICTION = register(
    Evaluator(
        "seed000_friction",
        seed000_friction,
        FRICTION_FACTORS,
        outputs=("friction_torque_Nm",),
        bearing_type="composite_turntable",
        description="seed-000 composite turntable bearing: statics + friction torque",
        references=("tian2025",),
    )
)
