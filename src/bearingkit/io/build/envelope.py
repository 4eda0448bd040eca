"""Checks that the built rows fit the bearing: between the bore and the outside diameter, and
shoulders no higher than the grooves (:mod:`bearingkit.io.build.shoulders`).

They run on the built :class:`~bearingkit.analysis.solver.model.BearingModel` and the validated geometry
(SI), and raise :class:`bearingkit.errors.InputError` with one line naming the file.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError


def check_shoulders(source: str, model, gdict: dict) -> None:
    """Refuse shoulder heights above the groove depth (one line; :mod:`bearingkit.io.build.shoulders`)."""
    from bearingkit.io.build.shoulders import shoulder_fractions

    try:
        shoulder_fractions(gdict, model)
    except InputError as exc:
        raise InputError(f"{source}: {exc}") from None


def _radial_extent(row) -> tuple[float, float]:
    """Smallest and largest radius [m] a row's elements occupy."""
    if row.kind == "threaded":  # PTRB: rollers of pitch diameter d_R on the pitch circle D_pw
        g = row.geometry
        return (g.pitch_diameter - g.roller_pitch_diameter) / 2, (
            g.pitch_diameter + g.roller_pitch_diameter
        ) / 2
    radius = float(np.max(row.pitch_diameter)) / 2
    if row.kind == "tapered":
        half = float(row.large_diameter) / 2
    elif getattr(row, "orientation", "radial") != "radial":
        half = float(np.max(row.effective_length)) / 2  # thrust roller: its axis is radial
    else:
        half = float(np.max(row.element_diameter)) / 2
    return radius - half, radius + half


def check_envelope(source: str, model: BearingModel, geometry: dict) -> None:
    """Rows must lie strictly between the bore and the outside diameter, when they are known."""
    env = model.metadata.get("geometry", {})
    env = dataclasses.asdict(env) if dataclasses.is_dataclass(env) else dict(env)
    env.update({k: geometry[k] for k in ("bore", "outer_diameter") if geometry.get(k) is not None})
    bore, outer = env.get("bore"), env.get("outer_diameter")
    if bore is not None and outer is not None and not bore < outer:
        raise InputError(f"{source}: geometry.outer_diameter ({outer:.6g} m) must exceed bore ({bore:.6g} m)")
    for row in model.rows:
        r_in, r_out = _radial_extent(row)
        if (bore is not None and r_in <= bore / 2) or (outer is not None and r_out >= outer / 2):
            raise InputError(
                f"{source}: geometry: row {row.name!r} spans diameters {2 * r_in * 1e3:.6g}–"
                f"{2 * r_out * 1e3:.6g} mm, which must lie strictly between bore ({_mm(bore)}) "
                f"and outer_diameter ({_mm(outer)})"
            )


def _mm(x) -> str:
    return "not given" if x is None else f"{x * 1e3:.6g} mm"
