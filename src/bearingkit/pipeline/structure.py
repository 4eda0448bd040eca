"""The coupled solve of an input's ``[structure]`` and what the flexibility changes (SI, units in keys).

:func:`solve_input` runs :func:`~bearingkit.analysis.structure.solve_structure` with what the statics
are solved with (:attr:`~bearingkit.pipeline.Analysis.setup`: load, held DOFs, speed, the offsets of
fits and preload, the rigid solve itself as its start). :func:`flexible_rating` rates the coupled
solution as the statics are rated, so the faces show the change in peak load, static safety s0 and
life beside the rigid rings' (:func:`change`). Which to use: the flexible one carries the structure
given; the rigid one is what the catalogue methods assume (rigid, round rings).
"""

from __future__ import annotations

import numpy as np

from bearingkit.errors import InputError

__all__ = ["change", "flexible_rating", "solve_input"]


def solve_input(analysis):
    """StructureResult of ``analysis``'s input with its [structure] (None without one)."""
    b = analysis.input
    structure = getattr(b, "structure", None)
    if structure is None:
        return None
    from bearingkit.analysis.structure import StructureResult, solve_structure

    setup = analysis.setup
    spec = b.sections.structure if b.sections is not None else None
    iterations = getattr(spec, "max_iterations", None) or 50
    coupled = analysis._in_file(
        solve_structure,
        b.model,
        setup.load,
        structure,
        free=setup.free,
        options=b.options,
        speed=setup.speed,
        base_offsets=setup.offsets,
        rigid=analysis.statics,
        max_iterations=iterations,
    )
    return StructureResult(coupled, structure)


def flexible_rating(analysis):
    """RatingResult of the coupled solution (None when it cannot be rated; the rigid one's reason)."""
    flex = analysis.flexible
    if flex is None or analysis.rating is None or not hasattr(flex, "rigid"):
        return None
    from bearingkit.analysis.rating.assembly import rate

    op = analysis.operating
    speed = op.abs_speed if np.all(op.abs_speed > 0) else None
    try:
        return rate(
            flex.result,
            speed=speed,
            rotating=op.rotating,
            reliability=op.reliability,
            load_ratings=analysis.load_ratings,
            shoulder_height=analysis._shoulder_heights(),
            catalogue_rating=analysis._catalogue_rating(),
        )
    except InputError:
        return None


def _value(a, case):
    v = np.ma.asarray(a)[case]
    return None if np.ma.is_masked(v) or not np.isfinite(float(v)) else float(v)


def change(analysis, case: int) -> dict:
    """Rigid against flexible for one case: peak element load, s0 and the basic rating life, and ratios."""
    flex = analysis.flexible
    out = {}
    if flex is None or not hasattr(flex, "rigid"):
        return out
    q_rigid = max(float(flex.rigid.row_stats(n).max_load[case]) for n in flex.points.rows)
    q_flex = max(float(flex.result.row_stats(n).max_load[case]) for n in flex.points.rows)
    out["max_load_rigid_N"], out["max_load_flexible_N"] = q_rigid, q_flex
    out["max_load_ratio"] = q_flex / q_rigid if q_rigid > 0 else None
    rigid, rated = analysis.rating, analysis.flexible_rating
    if rigid is not None and rated is not None:
        for key, attr in (("static_safety", "static_safety"), ("life_rev", "life")):
            a, b = _value(getattr(rigid, attr), case), _value(getattr(rated, attr), case)
            out[f"{key}_rigid"], out[f"{key}_flexible"] = a, b
            out[f"{key}_ratio"] = b / a if a and b is not None else None
    return out
