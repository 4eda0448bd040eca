"""The SKF friction model of a matched set of single bearings (DB, DF, DT): per bearing, then summed.

SI units (N, N·m, rad/s, W, °C). SKF's four-component model describes one bearing under its own radial
and axial load [SKF 17000 EN, "Friction"]; in a set each bearing carries a share of the external load
and the preload that only the paired solve knows (the axial load of a DB pair under F_a is the preload
plus most of F_a on one row, nearly nothing on the other). :func:`skf_per_bearing` therefore runs the
single bearing's model once per row — each row is one bearing of the set:

.. math::

    M_{set} = \\sum_j M_{SKF}\\bigl(F_{r,j}, F_{a,j}\\bigr),\\qquad
    F_{r,j} = \\sqrt{F_{x,j}^2 + F_{y,j}^2},\\quad F_{a,j} = |F_{z,j}|

with (F_x, F_y, F_z)_j the force row j carries in the solved set
(:meth:`~bearingkit.analysis.solver.solution.QuasiStaticResult.row_load`), and every other input that of
the single bearing (:func:`bearingkit.pipeline.friction.choice.skf_inputs`): the SKF constants of its
series (``7209 B DB`` → series 72), its seals, its width and the oil level of the drag term (both
bearings sit in the same bath), Y of a tapered bearing. The power loss is P = M_set |ω|.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from types import SimpleNamespace

import numpy as np

from bearingkit.errors import InputError
from bearingkit.pipeline.friction.models import FRICTION_MODELS, FrictionOutcome, register_friction_model

__all__ = ["SetFriction", "is_set", "per_bearing", "row_forces", "skf_per_bearing"]


@dataclass(frozen=True)
class SetFriction:
    """The SKF friction of every bearing of a set (arrays (C,), torques in N·m, forces in N).

    Attributes
    ----------
    by_row : dict row name → (C,) [N·m]
        Each bearing's total; sums to the set's.
    per_bearing : dict row name → EngineeringFrictionResult
        Each bearing's SKF result (components, factors, inputs with its loads).
    radial, axial : dict row name → (C,) [N]
        Each bearing's F_r and F_a from the paired solve.
    torque_inner, torque_outer : None
        A catalogue model has no split between the rings.
    """

    by_row: dict
    per_bearing: dict
    radial: dict
    axial: dict
    torque_inner: None = None
    torque_outer: None = None
    references: tuple = field(default_factory=tuple)


def is_set(analysis) -> bool:
    """Whether the analysed bearing is a matched set of single SKF-covered bearings (one bearing per row)."""
    from bearingkit.pipeline.bearing_facts import bearing_facts

    return bearing_facts(analysis.input).arrangement is not None  # a shaft's seat: its bearing file's


def row_forces(statics, name: str) -> tuple[np.ndarray, np.ndarray]:
    """(F_r, F_a) [N], arrays (C,), that row ``name`` carries in the solved set (module docstring)."""
    force = np.asarray(statics.row_load(name), dtype=float)
    return np.hypot(force[:, 0], force[:, 1]), np.abs(force[:, 2])


def skf_per_bearing(analysis) -> FrictionOutcome:
    """SKF four-component friction of a matched set: each row's bearing at its own loads, summed
    (:func:`per_bearing` with ``model="skf"``)."""
    return per_bearing(analysis, "skf")


def per_bearing(analysis, model: str = "skf") -> FrictionOutcome:
    """Friction of a matched set by a catalogue model (``"skf"`` or ``"palmgren"``): each row's bearing at
    its own loads, summed (module docstring; Palmgren's M0 + M1 likewise describes one bearing).

    Returns
    -------
    FrictionOutcome
        ``model``; ``components`` (SKF: rolling, sliding, seal, drag) and ``total`` summed over the
        bearings [N·m]; ``power_loss`` [W]; ``native`` a :class:`SetFriction` (``by_row`` per bearing);
        each case dict has ``rows_Nm`` and ``row_loads_N`` (F_r, F_a per bearing).
    """
    from bearingkit.analysis.friction.engineering import MODEL_COMPONENTS, engineering_friction_torque
    from bearingkit.pipeline.bearing_facts import bearing_facts
    from bearingkit.pipeline.friction.choice import skf_inputs

    bearing, op = analysis.input, analysis.operating
    if op.lubricant is None:
        raise InputError(f"{bearing.source}: lubricant: none given; the {model} model needs its viscosity")
    facts = bearing_facts(bearing, op.lubricant)
    if model == "skf":
        kw, used = analysis._in_file(skf_inputs, analysis)
    else:
        kw, used = {"bearing_type": facts.engineering_type}, []
        if facts.bore is not None and facts.outer_diameter is not None:
            kw.update(bore_diameter=facts.bore, outside_diameter=facts.outer_diameter)
    rows = list(bearing.model.rows)
    statics = analysis.statics
    n = op.n_cases
    comps = {k: np.zeros(n) for k in MODEL_COMPONENTS[model]}
    by_row, per_bearing, radial, axial = {}, {}, {}, {}
    notes: list[str] = []
    for row in rows:
        fr, fa = row_forces(statics, row.name)
        res = analysis._in_file(
            engineering_friction_torque,
            SimpleNamespace(rows=[row], name=row.name),
            load_radial=fr,
            load_axial=fa,
            speed=op.abs_speed,
            lubricant=op.lubricant,
            temperature=op.temperature,
            model=model,
            **kw,
        )
        for k in comps:
            comps[k] += np.broadcast_to(np.asarray(res.components[k], float), (n,))
        by_row[row.name] = np.broadcast_to(np.asarray(res.total, float), (n,)).copy()
        per_bearing[row.name], radial[row.name], axial[row.name] = res, fr, fa
        notes.extend(res.notes)
    total = sum(by_row.values())
    kind = facts.engineering_type.replace("_", " ")
    notes = [
        f"{model} per bearing: {len(rows)} {kind} bearings ({facts.arrangement}), each at the radial and "
        "axial load its row carries in the paired solve (preload included); the set's torque is their sum",
        *used,
        *notes,
    ]
    notes = list(dict.fromkeys(notes))
    first = next(iter(per_bearing.values()))
    dicts = []
    for i, c in enumerate(bearing.cases):
        dicts.append(
            {
                "case": c.name,
                "speed_rad_s": float(op.abs_speed[i]),
                "temperature_C": float(op.temperature[i]),
                "friction": {
                    "model": model,
                    "bearing_type": first.bearing_type,
                    "per_bearing": True,
                    "total_Nm": float(total[i]),
                    "components_Nm": {k: float(v[i]) for k, v in comps.items()},
                    "rows_Nm": {k: float(v[i]) for k, v in by_row.items()},
                    "row_loads_N": {
                        k: {"radial": float(radial[k][i]), "axial": float(axial[k][i])} for k in by_row
                    },
                    "references": list(first.references),
                    "notes": notes,
                },
            }
        )
    native = SetFriction(by_row, per_bearing, radial, axial, references=tuple(first.references))
    return FrictionOutcome(
        model, total, comps, total * op.abs_speed, dicts, native, notes, tuple(first.references)
    )


def _per_set(model: str, run_single):
    def run(analysis) -> FrictionOutcome:
        if is_set(analysis):  # a DB/DF/DT set: each bearing at its own loads, summed
            return per_bearing(analysis, model)
        return run_single(analysis)

    return run


for _name in ("skf", "palmgren"):
    register_friction_model(_name, _per_set(_name, FRICTION_MODELS[_name]))
