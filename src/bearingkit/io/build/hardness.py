"""The raceways' hardness profile of a bearing file: its ``[hardness]`` section over the material's.

SI units (m; hardness in HV). Built once the model exists, because a case deeper than the ring wall below
a raceway is refused (one line naming the field), and the wall comes from the rows' radial extent.
"""

from __future__ import annotations

import dataclasses

from bearingkit.errors import InputError, did_you_mean, quote
from bearingkit.io.build.envelope import _radial_extent
from bearingkit.io.schema_hardness import HardnessSpec


def _ring_wall(model, gdict: dict):
    """Thinnest ring wall below a raceway [m] from bore / outer_diameter and the rows, or None."""
    env = model.metadata.get("geometry", {})
    env = dataclasses.asdict(env) if dataclasses.is_dataclass(env) else dict(env)
    env.update({k: gdict[k] for k in ("bore", "outer_diameter") if gdict.get(k) is not None})
    bore, outer = env.get("bore"), env.get("outer_diameter")
    walls = []
    for row in model.rows:
        r_in, r_out = _radial_extent(row)
        if bore is not None:
            walls.append(r_in - bore / 2)
        if outer is not None:
            walls.append(outer / 2 - r_out)
    return min(walls) if walls else None


def hardness_of(source: str, spec: HardnessSpec | None, material, model, gdict: dict):
    """The raceways' :class:`~bearingkit.hardness.HardnessProfile` of a file (one-line InputError).

    No ``[hardness]``: the material's (:attr:`bearingkit.materials.Material.raceway_hardness`). Otherwise the
    preset (or that profile) with the fields given replaced.
    """
    from bearingkit.hardness import HARDNESS_PRESETS

    if spec is None:
        return material.raceway_hardness
    if spec.preset is not None:
        if spec.preset not in HARDNESS_PRESETS:
            raise InputError(
                f"{source}: hardness.preset ({quote(spec.preset)}) must be one of "
                f"{', '.join(HARDNESS_PRESETS)}"
                f"{did_you_mean(spec.preset, HARDNESS_PRESETS)}"
            )
        base = HARDNESS_PRESETS[spec.preset]
    else:
        base = material.raceway_hardness
    fields = {
        k: v
        for k, v in spec.model_dump().items()
        if v is not None and k not in ("preset", "through_hardened")
    }
    if spec.through_hardened:
        if "case_depth" in fields:
            raise InputError(f"{source}: hardness: give through_hardened = true or case_depth, not both")
        fields.update(case_depth=None, core_hardness=None, limit_hardness=None)
    elif "case_depth" in fields and base.through_hardened and "core_hardness" not in fields:
        raise InputError(
            f"{source}: hardness.core_hardness (not given) is needed with case_depth: give the core's "
            "hardness"
        )
    try:
        profile = dataclasses.replace(base, name="input", source=f"{source} [hardness]", **fields)
    except InputError as exc:
        raise InputError(f"{source}: hardness.{exc}") from None
    wall = _ring_wall(model, gdict)
    if profile.case_depth is not None and wall is not None and profile.case_depth >= wall:
        raise InputError(
            f"{source}: hardness.case_depth ({profile.case_depth * 1e3:.4g} mm) must be less than the ring "
            f"wall below the raceways ({wall * 1e3:.4g} mm, from bore/outer_diameter and the rows); a case "
            "that deep hardens the whole ring: write through_hardened = true"
        )
    return profile
