"""Friction of slewing rings in the pipeline: the makers' formula as friction model ``"slewing"``.

SI units (N, N·m, m, rad/s, W). The model reads the load cases (F_a = |F_z|, F_r = |(F_x, F_y)|,
M_k = |(M_x, M_y)|) and the model's pitch diameter and element kind, and returns M_r
(:func:`bearingkit.physics.friction.slewing.slewing_friction_moment`) with the power M_r |ω|. Registered
on import (:mod:`bearingkit.pipeline` imports this module).
"""

from __future__ import annotations

import numpy as np

from bearingkit.errors import InputError
from bearingkit.physics.friction import slewing as makers
from bearingkit.pipeline.friction.models import FrictionOutcome, register_friction_model

#: Row kind → element of the makers' formula.
ELEMENTS = {"four_point": "ball", "crossed_roller": "roller"}


def slewing_friction(analysis, mu=None) -> FrictionOutcome:
    """Friction model ``"slewing"`` of :data:`bearingkit.pipeline.FRICTION_MODELS` (module docstring)."""
    bearing, op = analysis.input, analysis.operating
    kinds = {r.kind for r in bearing.model.rows}
    if not kinds or not kinds <= set(ELEMENTS) or len({ELEMENTS[k] for k in kinds}) != 1:
        raise InputError(
            f"{bearing.source}: friction model 'slewing' applies to slewing rings of four-point ball or "
            f"crossed roller rows, not {sorted(kinds)}"
        )
    element = ELEMENTS[kinds.pop()]
    load = bearing.load_matrix()
    dm = max(float(np.max(r.pitch_diameter)) for r in bearing.model.rows)
    total = makers.slewing_friction_moment(
        load[:, 2], np.hypot(load[:, 0], load[:, 1]), np.hypot(load[:, 3], load[:, 4]), dm, element, mu
    )
    used = makers.DEFAULT_MU[element] if mu is None else mu
    notes = [
        f"slewing-ring makers' formula (Rothe Erde), {element} rings, mu = {used:g}, pitch diameter "
        f"{dm * 1e3:.6g} mm: start-up torque of a loaded bearing without seals, scatter about ±25 %"
    ]
    dicts = [  # the layout of bearingkit.io.export.engineering_friction_case_dict
        {
            "case": c.name,
            "speed_rad_s": float(op.abs_speed[i]),
            "temperature_C": float(op.temperature[i]),
            "friction": {
                "model": "slewing",
                "bearing_type": f"slewing_ring_{element}",
                "total_Nm": float(total[i]),
                "components_Nm": {"slewing": float(total[i])},
                "references": list(makers.REFERENCE_KEYS),
                "notes": notes,
            },
        }
        for i, c in enumerate(bearing.cases)
    ]
    return FrictionOutcome(
        "slewing",
        total,
        {"slewing": total},
        total * op.abs_speed,
        dicts,
        None,
        notes,
        makers.REFERENCE_KEYS,
    )


register_friction_model("slewing", slewing_friction)
