"""JSON-ready output of a solved drivetrain (SI, units in keys): what ``bearingkit system --json`` prints,
the HTML report and the REXS export read."""

from __future__ import annotations

import numpy as np

from bearingkit.systems.drivetrain.model import HOUSING
from bearingkit.systems.shaft.life import SYSTEM_LIFE_DIFFERENCE


def _f(v):
    v = float(v)
    return None if not np.isfinite(v) else v


def bearing_summary(da, name: str, case: int) -> dict:
    """The per-bearing line of the tables: loads, p_max, both lives, κ, friction and power loss."""
    res = da.result
    b = da.drivetrain.bearing(name)
    load = res.bearing_load(name)[case]
    out = {
        "name": name,
        "inner": b.inner.body,
        "outer": b.outer.body,
        "radial_load_N": float(np.hypot(load[0], load[1])),
        "axial_load_N": float(load[2]),
        "misalignment_rad": float(res.misalignment(name)[case]),
        "max_pressure_Pa": None,
        "static_safety": None,
        "L10h_iso281_h": None,
        "L10h_h": None,
        "Lnmr_h": None,
        "friction_torque_Nm": None,
        "power_loss_W": None,
        "temperature_C": None,
        "temperature_found": False,
        "warnings": len([w for w in da.warnings[case] if w.startswith(f"{name}: ")]),
    }
    a = da.bearings.get(name)
    if a is None:
        return out
    out["max_pressure_Pa"] = max(float(np.max(r.max_pressure[case])) for r in a.statics.rows)
    if a.rating is not None:
        system = a.rating.to_dict(case)["system"]
        out["static_safety"] = system.get("static_safety")
        out["Lnmr_h"] = system.get("Lnmr_h")
        lives = da.bearing_lives(name)
        out["L10h_h"] = _f(lives["L10h_h"][case])
        out["L10h_iso281_h"] = _f(lives["L10h_iso281_h"][case])
    if a.friction is not None:
        out["friction_torque_Nm"] = float(a.friction.total[case])
        out["power_loss_W"] = float(a.friction.power_loss[case])
    if a.operating.temperature is not None:
        out["temperature_C"] = float(np.broadcast_to(a.operating.temperature, (da.n_cases,))[case])
    out["temperature_found"] = a.thermal is not None
    return out


def power_dict(da, case: int) -> dict | None:
    p = da.power
    if p is None:
        return None
    return {
        "input_W": float(p["input_W"][case]),
        "output_W": _f(p["output_W"][case]),  # unknown (None) where a bearing has no friction model
        "output_lossless_W": float(p["output_lossless_W"][case]),
        "loss_W": _f(p["loss_W"][case]),
        "efficiency": _f(p["efficiency"][case]),
        "bearing_loss_W": {k: _f(v[case]) for k, v in p["bearing_loss_W"].items()},
        "mesh": {
            k: {
                "transmitted_W": float(v["transmitted_W"][case]),
                "loss_W": float(v["loss_W"][case]),
                "H_V": float(v["H_V"]),
                "mu_mz": v["mu_mz"],
            }
            for k, v in p["mesh"].items()
        },
        "speeds_rad_s": {k: float(v[case]) for k, v in p["speeds_rad_s"].items()},
    }


def inputs_dict(da) -> dict:
    dt = da.drivetrain
    return {
        "held": dt.held,
        "shafts": [
            {
                "name": s.name,
                "centre_m": list(s.centre),
                "axial_offset_m": s.axial_offset,
                "sections": [
                    {
                        "start_m": x.start,
                        "end_m": x.end,
                        "outer_diameter_m": x.outer_diameter,
                        "inner_diameter_m": x.inner_diameter,
                    }
                    for x in s.shaft.sections
                ],
                "gears": [
                    {
                        "name": g.name,
                        "position_m": g.position,
                        "teeth": g.geometry.teeth,
                        "normal_module_m": g.geometry.normal_module,
                        "helix_angle_rad": g.geometry.helix_angle,
                        "pressure_angle_rad": g.geometry.pressure_angle,
                        "face_width_m": g.geometry.face_width,
                        "internal": g.geometry.internal,
                        "reference_diameter_m": g.geometry.reference_diameter,
                    }
                    for g in s.gears
                ],
            }
            for s in dt.shafts
        ],
        "bearings": [
            {
                "name": b.name,
                "bearing": getattr(b.seat.bearing, "name", "linear bearing"),
                "inner": b.inner.body,
                "inner_position_m": b.inner.position,
                "outer": b.outer.body,
                "outer_position_m": None if b.outer.body == HOUSING else b.outer.position,
                "axial": b.seat.axial,
                "orientation": b.seat.orientation,
            }
            for b in dt.bearings
        ],
        "meshes": [
            {"name": m.name, "a": list(m.a), "b": list(m.b), "stiffness_N_per_m": m.k, "friction": m.friction}
            for m in dt.meshes
        ],
        "planetary": [
            {k: (list(v) if isinstance(v, tuple) else v) for k, v in st.items()} for st in dt.stages
        ],
        "load_cases": list(da.case_names),
    }


def analysis_dict(da) -> dict:
    res = da.result
    cases = []
    for c in range(da.n_cases):
        bearings = []
        for b in da.drivetrain.bearings:
            d = res.bearing_dict(b.name, c)
            d["summary"] = bearing_summary(da, b.name, c)
            a = da.bearings.get(b.name)
            if a is not None:
                part = {"operating": a.operating.to_dict(c), "warnings": list(a.warnings[c])}
                if a.rating is not None:
                    part["rating"] = a.rating.to_dict(c)
                if a.friction is not None:
                    part["friction"] = {
                        "torque_Nm": float(a.friction.total[c]),
                        "power_loss_W": float(a.friction.power_loss[c]),
                    }
                if a.thermal is not None:
                    part["thermal"] = a.thermal.to_dict(c)
                d["analysis"] = part
            bearings.append(d)
        shafts = {}
        for s in da.drivetrain.shafts:
            sr = res.shaft_result(s.name)
            z_m, moment = sr.moment_line()
            u = sr.displacement[c]
            radial = np.hypot(u[:, 0], u[:, 1])
            bending = np.hypot(moment[c, :, 0], moment[c, :, 1])
            shafts[s.name] = {
                "rotation_rad": float(res.rotation(s.name)[c]),
                "max_radial_deflection_m": float(radial.max()),
                "max_bending_moment_Nm": float(bending.max()),
                "deflection": {"z_m": sr.z.tolist(), "u_x_m": u[:, 0].tolist(), "u_y_m": u[:, 1].tolist()},
                "bending_moment": {
                    "z_m": z_m.tolist(),
                    "M_x_Nm": moment[c, :, 0].tolist(),
                    "M_y_Nm": moment[c, :, 1].tolist(),
                },
            }
        sys = da.system_lives
        cases.append(
            {
                "case": da.case_names[c],
                "converged": bool(res.converged[c]),
                "iterations": int(res.iterations[c]),
                "residual_norm": float(res.residual_norm[c]),
                "reason": res.reason[c],
                "held_torque_Nm": float(res.held_torque()[c]),
                "meshes": [res.mesh_dict(m.name, c) for m in da.drivetrain.meshes],
                "bearings": bearings,
                "shafts": shafts,
                "system": {
                    "L10h_iso281_h": _f(sys["L10h_iso281_h"][c]),
                    "L10h_h": _f(sys["L10h_h"][c]),
                    "life_difference": SYSTEM_LIFE_DIFFERENCE,
                },
                "power": power_dict(da, c),
                "warnings": list(da.warnings[c]),
            }
        )
    return {
        "file": da.input.source,
        "drivetrain": da.drivetrain.name,
        "friction_model": da.friction_model,
        "heat_balance": da.heat_balance,
        "inputs": inputs_dict(da),
        "duty_cycle": da.duty_cycle(),
        "notes": da.notes,
        "cases": cases,
    }


def stiffness_tables(da) -> list:
    """Every bearing's tangent stiffness per load case (gearbox axes, ``frame = "shaft"``) as
    :class:`~bearingkit.systems.shaft.stiffness.StiffnessTable` s: CSV/JSON (``write_tables``) and ROSS
    bearing elements (:func:`bearingkit.systems.ross.ross_bearing`) per shaft. Speeds: the relative
    speed of the bearing's rings (0 without speeds)."""
    from bearingkit.systems.shaft.stiffness import StiffnessTable

    res = da.result
    out = []
    for b in da.drivetrain.bearings:
        speeds = da.ring_speeds(b.name)
        rel = np.zeros(da.n_cases) if speeds is None else np.abs(speeds[0] - speeds[1])
        out.append(
            StiffnessTable(
                bearing=b.name,
                frame="shaft",
                loads=res.bearing_load(b.name),
                speeds=np.asarray(rel, float),
                stiffness=res.stiffness(b.name),
                converged=np.asarray(res.converged, bool),
                labels=tuple(da.case_names),
            )
        )
    return out
