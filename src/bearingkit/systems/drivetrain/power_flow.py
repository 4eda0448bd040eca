"""Speeds of every shaft from the gear ratios, and the power flow and losses of a drivetrain.

SI units (rad/s, N·m, W). Kinematics: at the pitch point P of every mesh the two gears' tangential
velocities are equal (rolling without slip):

    t·(v_a(P) − v_b(P)) = 0,   v(P) = v_centre + ω ẑ × (P − centre),

with v_centre = 0 for a shaft on the housing and ω_carrier ẑ × (centre − carrier centre) for a planet.
With the given speeds of some shafts (the inputs) these equations fix every speed; a drivetrain whose
speeds they leave open (a differential with one speed given) is refused with one line.

Power flow. The power each input torque delivers is P_in = Σ T_i ω_i. The static solve is lossless,
so the torque that holds the output shaft returns P_in exactly (T_held ω_held = −P_in: a check of the
ratios against the statics). The losses are the bearings' friction power (each bearing's pipeline
Analysis, at its ring speeds) and, where a mesh gives a mean coefficient of friction μ_mz, the mesh
loss P = μ_mz H_V P_mesh (:mod:`bearingkit.systems.drivetrain.gearing`) with P_mesh = F_t r_w |ω_a −
ω_frame| the
power the mesh transmits relative to its frame (the carrier for a planetary mesh). The output power
is P_out = P_in − Σ losses (the losses are taken from the output; their effect on the load
distribution is neglected: a few per cent of the mesh forces) and the efficiency η = P_out / P_in.
"""

from __future__ import annotations

import numpy as np

from bearingkit.errors import InputError
from bearingkit.systems.drivetrain.model import HOUSING

#: Relative residual of the kinematic equations above which the given speeds contradict the gear
#: ratios [-].
KINEMATIC_RTOL = 1e-9


def _carrier_of(dt) -> dict:
    out = {}
    for st in dt.stages:
        for p in st["planets"]:
            out[p] = st["carrier"]
    return out


def speeds(dt, given: dict) -> dict:
    """Angular velocity (C,) [rad/s] of every shaft from ``given`` {shaft: (C,) [rad/s]}.

    Raises InputError (one line) when the given speeds do not determine every shaft's speed or
    contradict the ratios.
    """
    names = [s.name for s in dt.shafts]
    if not given:
        return {}
    n_cases = len(np.atleast_1d(next(iter(given.values()))))
    col = {n: i for i, n in enumerate(names)}
    carrier = _carrier_of(dt)
    rows = []

    def tangential_row(ref, arm, t):
        # the gear's own arm to the pitch point (the statics' geometry) and, for a planet, the
        # carrier's arm to the planet's centre
        row = np.zeros(len(names))
        body = ref[0]
        if body == HOUSING:
            return row
        row[col[body]] += t @ np.cross([0.0, 0.0, 1.0], arm)
        if body in carrier:
            s, cb = dt.body(body), dt.body(carrier[body])
            rc = np.array([s.centre[0] - cb.centre[0], s.centre[1] - cb.centre[1], 0.0])
            row[col[cb.name]] += t @ np.cross([0.0, 0.0, 1.0], rc)
        return row

    for m in dt.meshes:
        geo = dt.mesh_geometry(m)
        t = np.cross([0.0, 0.0, 1.0], geo["e"])
        rows.append(tangential_row(m.a, geo["p_a"], t) - tangential_row(m.b, geo["p_b"], t))
    a = np.array(rows) if rows else np.zeros((0, len(names)))
    for n in given:
        if n not in col:
            raise InputError(f"load_cases.speed: {n!r} is not a shaft; shafts are {names}")
    sel = np.zeros((len(given), len(names)))
    for i, n in enumerate(given):
        sel[i, col[n]] = 1.0
    lhs = np.concatenate([a, sel])
    if np.linalg.matrix_rank(lhs) < len(names):
        free = [n for n in names if n not in given]
        raise InputError(
            f"load_cases.speed: the speeds of {list(given)} do not determine every shaft's speed through "
            f"the gear ratios (shafts {free} are left free); give the speed of another shaft"
        )
    rhs = np.zeros((len(lhs), n_cases))
    for i, n in enumerate(given):
        rhs[len(a) + i] = np.broadcast_to(np.asarray(given[n], float), (n_cases,))
    w, *_ = np.linalg.lstsq(lhs, rhs, rcond=None)
    scale = max(np.abs(rhs).max(), 1e-300)
    if np.abs(lhs @ w - rhs).max() > KINEMATIC_RTOL * scale * max(1.0, np.abs(lhs).max()):
        raise InputError(
            f"load_cases.speed: the given speeds of {list(given)} contradict the gear ratios; give one "
            "shaft's speed"
        )
    return {n: w[col[n]] for n in names}


def mesh_frame_speed(dt, mesh, omega: dict, n_cases: int) -> np.ndarray:
    """Speed (C,) of the frame a mesh rolls in: its stage's carrier, else 0 (the housing)."""
    if mesh.frame_body is None:
        return np.zeros(n_cases)
    return np.asarray(omega[mesh.frame_body], float)


def mesh_losses(result, omega: dict) -> dict:
    """Mesh power loss (C,) [W] of every mesh with a friction coefficient, and its transmitted power."""
    dt, n = result.drivetrain, result.n_cases
    out = {}
    for m in dt.meshes:
        geo = result.assembly.mesh_rows[result.mesh_index(m.name)]["geometry"]
        comp = result.mesh_components(m.name, "a")
        w_a = np.zeros(n) if m.a[0] == HOUSING else np.asarray(omega[m.a[0]], float)
        power = np.abs(comp["tangential_N"]) * geo["r_a"] * np.abs(w_a - mesh_frame_speed(dt, m, omega, n))
        loss = np.zeros(n) if m.friction is None else m.friction * m.pair.loss_factor() * power
        out[m.name] = {
            "transmitted_W": power,
            "loss_W": loss,
            "H_V": m.pair.loss_factor(),
            "mu_mz": m.friction,
        }
    return out
