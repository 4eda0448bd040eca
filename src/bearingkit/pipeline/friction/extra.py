"""More friction in the pipeline: tapered rows from a file (seed 001), the side-by-side comparison.

SI units (N·m, W, rad/s, °C). :func:`tapered` is the friction model of tapered-roller bearings
(Liu et al. 2022, :mod:`bearingkit.analysis.friction.tapered`), registered as ``"trb"`` and used by
``"components"`` when every row is tapered. :func:`compare` runs every model that applies to a bearing
and says in one sentence when each applies (:data:`WHEN`).
"""

from __future__ import annotations

import numpy as np

from bearingkit.errors import InputError
from bearingkit.pipeline.friction.models import FRICTION_MODELS, FrictionOutcome, register_friction_model

__all__ = ["COMPONENT_MODEL_GAPS", "WHEN", "compare", "tapered"]

#: When each model applies (the sentence ``friction --compare`` prints).
WHEN = {
    "components": (
        "physical model per contact (hysteresis, EHL rolling, ball spin, thrust-roller differential sliding, "
        "cage weight; Tian et al. 2025): use it for non-standard and multi-row bearings and a breakdown by "
        "contact; it has no Heathcote sliding of balls in their grooves, no cage pocket or seal friction, "
        "so on a standard radial ball bearing it gives the rolling part only"
    ),
    "skf": (
        "SKF four-component catalogue model, fitted to measured torque of standard single-row bearings "
        "(rolling + sliding + seals + drag): use it for catalogue bearings in their normal load and speed "
        "range, it is the reference for power loss there"
    ),
    "palmgren": (
        "Palmgren's M0 + M1 (viscous + load term, older catalogue fit): a quick estimate for standard "
        "bearings, less accurate than SKF at light loads and high speeds"
    ),
    "trb": (
        "seed-001 tapered roller model (Liu et al. 2022): EHL rolling and sliding traction on cone and cup, "
        "rib friction in mixed lubrication at a given cage slip: use it for tapered rows and roller-"
        "diameter studies"
    ),
}
#: Why the component model reads low on a standard radial ball bearing (shown with the comparison).
COMPONENT_MODEL_GAPS = (
    "the component model comes from a turntable bearing turning at ≤ 90 rpm: on a radial ball row it "
    "sums hysteresis and EHL rolling only — its 'differential_sliding' is that of thrust rollers, ball "
    "spin is zero at a 0° contact angle and the cage term is the cage's weight on its guide (zero unless "
    "cage_mass is given) — while SKF's sliding term M_sl carries the Heathcote slip in the conforming "
    "groove and the cage pocket friction; that difference, not an error, is why the component model "
    "reads about half of SKF's torque or less on a deep groove ball bearing"
)


def tapered(analysis) -> FrictionOutcome:
    """Friction of a bearing of tapered rows (seed 001 model), per distinct speed and temperature.

    Torque = M_ir of every row (the torque on the cone, seed 001 eq. 12), broken down into rolling
    (Σ F_ro,i R_i), sliding (Σ F_rs,i R_i) and rib (F_fs × arm). Power loss = M_ir |ω| (an upper
    bound: the sliding traction dissipates F_rs v_s, far less, see the notes).
    """
    from bearingkit.analysis.friction.tapered import TRBOperatingPoint, friction_from_state

    op, res = analysis.operating, analysis.statics
    rows = [(r, k) for r, k in zip(res.model.rows, res.model.kernels, strict=True) if r.kind == "tapered"]
    if not rows or len(rows) != len(res.model.rows):
        raise InputError("the tapered-roller friction model (trb) takes bearings of tapered rows only")
    if op.lubricant is None:
        raise InputError('lubricant: none given; add [lubricant] name = "ISO_VG46" or pass lubricant=…')
    n = op.n_cases
    comps = {k: np.zeros(n) for k in ("rolling", "sliding", "rib")}
    by_row = {r.name: np.zeros(n) for r, _ in rows}
    notes, dicts = [], [None] * n
    keys = {(float(s), float(t)) for s, t in zip(op.abs_speed, op.temperature, strict=True)}
    for speed, temp in sorted(keys):
        mask = (op.abs_speed == speed) & (op.temperature == temp)
        top = TRBOperatingPoint(speed=speed, lubricant=op.lubricant, temperature_C=temp)
        res.seed_rollers()  # the per-roller loads start where the compiled solve left them
        for row, kernel in rows:
            fr = friction_from_state(kernel, kernel.roller_state(res.displacement), top, res.converged)
            geo = kernel.geo
            arm = geo.radius_flange if top.flange_arm == "geometric" else geo.radius_inner + geo.flange_height
            rolling = fr.rolling_inner.sum(-1) * geo.radius_inner
            sliding = fr.sliding_inner.sum(-1) * geo.radius_inner
            rib = fr.flange.sum(-1) * arm
            comps["rolling"][mask] += rolling[mask]
            comps["sliding"][mask] += sliding[mask]
            comps["rib"][mask] += rib[mask]
            by_row[row.name][mask] += np.asarray(fr.torque_inner)[mask]
            for i in np.flatnonzero(mask):
                notes.extend(fr.warnings[i])
    total = comps["rolling"] + comps["sliding"] + comps["rib"]
    for i, c in enumerate(analysis.input.cases):
        dicts[i] = {
            "case": c.name,
            "speed_rad_s": float(op.abs_speed[i]),
            "temperature_C": float(op.temperature[i]),
            "friction": {
                "model": "trb",
                "total_Nm": float(total[i]),
                "components_Nm": {k: float(v[i]) for k, v in comps.items()},
                "rows_Nm": {k: float(v[i]) for k, v in by_row.items()},
                "notes": [],
            },
        }
    notes.append("power loss M_ir·|ω| is an upper bound: the cone sliding traction dissipates F_rs·v_s only")
    return FrictionOutcome(
        "trb", total, comps, total * op.abs_speed, dicts, None, list(dict.fromkeys(notes)), ("liu2022",)
    )


register_friction_model("trb", tapered)


def _all_tapered(analysis) -> bool:
    rows = analysis.input.model.rows
    return bool(rows) and all(r.kind == "tapered" for r in rows)


def _components_or_tapered(run_components):
    def run(analysis) -> FrictionOutcome:
        if _all_tapered(analysis):
            out = tapered(analysis)
            out.notes.insert(0, "components: tapered rows use the seed-001 tapered roller model (trb)")
            return out
        return run_components(analysis)

    return run


register_friction_model("components", _components_or_tapered(FRICTION_MODELS["components"]))


def compare(analysis) -> dict:
    """Every friction model that applies, side by side per case, with when each applies.

    Returns
    -------
    dict
        ``models``: name → ``{"when": sentence, "total_Nm": [..], "power_loss_W": [..]}`` or
        ``{"when": …, "not_applicable": reason}``; ``notes``: why models differ.
    """
    out = {}
    for name in ("components", "skf", "palmgren", "trb"):
        if name == "trb" and not _all_tapered(analysis):
            continue
        if name == "components" and _all_tapered(analysis):
            continue
        try:
            f = analysis.friction_by(name)
        except InputError as exc:
            out[name] = {"when": WHEN[name], "not_applicable": str(exc)}
            continue
        out[name] = {
            "when": WHEN[name],
            "total_Nm": [float(v) for v in f.total],
            "power_loss_W": [float(v) for v in f.power_loss],
            "components_Nm": {k: [float(x) for x in v] for k, v in f.components.items()},
        }
    notes = []
    kinds = {r.kind for r in analysis.input.model.rows}
    if "ball" in kinds and "components" in out and "skf" in out and "total_Nm" in out["skf"]:
        notes.append(COMPONENT_MODEL_GAPS)
    return {"cases": analysis.case_names, "models": out, "notes": notes}
