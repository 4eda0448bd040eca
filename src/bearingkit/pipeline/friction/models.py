"""Friction models of the pipeline, behind one registry keyed by a documented name.

SI units: torques in N·m, speeds in rad/s, power in W, temperatures in °C. Each model is
``run(analysis) -> FrictionOutcome`` and is chosen by name (``bearingkit friction --model``, the
``friction_model`` of :func:`bearingkit.pipeline.analyze`):

- ``"components"`` — the physical component model (hysteresis, differential sliding, viscous
  rolling, ball spin, cage; Tian et al. 2025 §4, :mod:`bearingkit.analysis.friction.components`) from the
  solved
  contact loads: per row and per element, for ball and cylindrical rows;
- ``"skf"`` — the SKF four-component catalogue model from F_r, F_a (single standard bearings), with the
  seals, the drag and the series constants of the bearing
  (:func:`bearingkit.pipeline.friction.choice.skf_inputs`); a matched set (DB/DF/DT) per bearing, each
  at the loads its row carries in the paired solve, summed (:mod:`bearingkit.pipeline.friction.paired`);
- ``"palmgren"`` — Palmgren's M0 + M1 (single-row standard bearings);
- ``"auto"`` — the default: the model :func:`bearingkit.pipeline.friction.choice.choose` picks for the
  bearing (SKF for standard bearings, the makers' formula for slewing rings, the component model for the
  seed composites and wherever SKF has no constants), with the reason in ``why``.

New models (another row kind, a paper's model) are added with :func:`register_friction_model`.
Power loss P = M |ω| [W].
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from bearingkit.errors import InputError

__all__ = ["FRICTION_MODELS", "FrictionOutcome", "register_friction_model"]


@dataclass
class FrictionOutcome:
    """Friction of every load case by one model.

    Attributes
    ----------
    model : str
    total : ndarray (C,) [N·m]
        Friction torque (magnitude).
    components : dict name → (C,) [N·m]
        Breakdown; sums to ``total``.
    power_loss : ndarray (C,) [W]
        M |ω|.
    case_dicts : list of dict
        One JSON-ready dict per case in the layout of :mod:`bearingkit.io.export`
        (``friction_case_dict`` / ``engineering_friction_case_dict``), for the faces.
    native : object
        The model's own result (``FrictionResult``, ``EngineeringFrictionResult``).
    notes : list of str
        Assumptions and limits, shown by every face.
    references : tuple of str
    why : str
        Why this model (the default's reason; ``"asked for"`` when named by the user).
    """

    model: str
    total: np.ndarray
    components: dict
    power_loss: np.ndarray
    case_dicts: list
    native: object = None
    notes: list = field(default_factory=list)
    references: tuple = ()
    why: str = "asked for"


def _components(analysis) -> FrictionOutcome:
    """Physical component model, one friction evaluation per distinct temperature."""
    from bearingkit.analysis.friction.components import FrictionResult, OperatingPoint, friction_torque
    from bearingkit.io.export import friction_case_dict

    op_in, bearing, result = analysis.operating, analysis.input, analysis.statics
    if op_in.lubricant is None:
        raise InputError(
            f'{bearing.source}: lubricant: none given; add [lubricant] name = "ISO_VG100" (a preset of '
            "bearingkit.lubricants.LUBRICANTS) to the file or pass lubricant=…"
        )
    ring = "speed_inner" if op_in.rotating == "inner" else "speed_outer"
    n = op_in.n_cases
    parts, dicts = [], [None] * n
    for temp in np.unique(op_in.temperature):
        mask = op_in.temperature == temp
        op = OperatingPoint(
            **{ring: op_in.speed},
            lubricant=op_in.lubricant,
            temperature=float(temp),
            **analysis.friction_options,
        )
        fr = friction_torque(result, op)
        parts.append((mask, fr))
        for i in np.flatnonzero(mask):
            dicts[i] = friction_case_dict(bearing.cases[i].name, op, fr, int(i))
            dicts[i]["friction"] = {"model": "components", **dicts[i]["friction"]}

    first = parts[0][1]

    def pick(get):
        out = np.array(get(first), dtype=float, copy=True)
        for mask, fr in parts[1:]:
            out[mask] = np.asarray(get(fr))[mask]
        return out

    native = FrictionResult(
        total=pick(lambda f: f.total),
        components={k: pick(lambda f, k=k: f.components[k]) for k in first.components},
        by_row={k: pick(lambda f, k=k: f.by_row[k]) for k in first.by_row},
        per_element={k: pick(lambda f, k=k: f.per_element[k]) for k in first.per_element},
        torque_inner=pick(lambda f: f.torque_inner),
        torque_outer=pick(lambda f: f.torque_outer),
        references=first.references,
    )
    notes = []
    if np.any(op_in.speed == 0):
        notes.append("friction at zero speed: only the load-dependent (Coulomb-type) part of the torque")
    return FrictionOutcome(
        "components",
        native.total,
        native.components,
        native.total * op_in.abs_speed,
        dicts,
        native,
        notes,
        native.references,
    )


def _engineering(model: str) -> Callable:
    def run(analysis) -> FrictionOutcome:
        from bearingkit.analysis.friction.engineering import engineering_friction_torque
        from bearingkit.io.export import engineering_friction_case_dict

        bearing, op = analysis.input, analysis.operating
        if op.lubricant is None:
            raise InputError(
                f"{bearing.source}: lubricant: none given; the {model} model needs its viscosity"
            )
        load = bearing.load_matrix()
        geometry = bearing.geometry.model_dump()
        envelope, used = {}, []
        if geometry.get("bore") is not None and geometry.get("outer_diameter") is not None:
            envelope = {"bore_diameter": geometry["bore"], "outside_diameter": geometry["outer_diameter"]}
        if model == "skf":
            from bearingkit.pipeline.friction.choice import skf_inputs

            more, used = analysis._in_file(skf_inputs, analysis)
            envelope.update(more)
        res = analysis._in_file(
            engineering_friction_torque,
            bearing.model,
            load_radial=np.hypot(load[:, 0], load[:, 1]),
            load_axial=np.abs(load[:, 2]),
            speed=op.abs_speed,
            lubricant=op.lubricant,
            temperature=op.temperature,
            model=model,
            **envelope,
        )
        dicts = [
            engineering_friction_case_dict(c.name, res, i, op.abs_speed, op.temperature)
            for i, c in enumerate(bearing.cases)
        ]
        total = np.broadcast_to(np.asarray(res.total, float), (op.n_cases,)).copy()
        comps = {
            k: np.broadcast_to(np.asarray(v, float), (op.n_cases,)).copy() for k, v in res.components.items()
        }
        notes = list(dict.fromkeys([*used, *res.notes]))
        for d in dicts:
            d["friction"]["notes"] = notes
        return FrictionOutcome(
            model, total, comps, total * op.abs_speed, dicts, res, notes, tuple(res.references)
        )

    return run


def _auto(analysis) -> FrictionOutcome:
    """The default model of the bearing (:func:`bearingkit.pipeline.friction.choice.choose`); where the SKF
    model was chosen and cannot run, the component model, with the reason."""
    import dataclasses

    from bearingkit.pipeline.friction.choice import choose

    model, why = choose(analysis)
    try:
        out = analysis.friction_by(model)
    except InputError as exc:
        if model == "components":
            raise
        why = f"{why}; it does not apply here ({exc}), so the component model is used"
        model = "components"
        out = analysis.friction_by(model)
    dicts = [{**d, "friction": {**d["friction"], "model_why": why}} for d in out.case_dicts]
    return dataclasses.replace(out, case_dicts=dicts, why=why)


#: Friction model name → ``run(analysis) -> FrictionOutcome`` (module docstring).
FRICTION_MODELS: dict[str, Callable] = {
    "components": _components,
    "skf": _engineering("skf"),
    "palmgren": _engineering("palmgren"),
    "auto": _auto,
}


def register_friction_model(name: str, run: Callable) -> Callable:
    """Add (or replace) a friction model of the pipeline; returns ``run``."""
    if not isinstance(name, str) or not name:
        raise InputError(f"friction model name ({name!r}) must be a non-empty string")
    FRICTION_MODELS[name] = run
    return run
