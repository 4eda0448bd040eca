"""Groove shoulder heights from an input file: ``shoulder_height_inner`` / ``_outer`` → per-row fractions.

SI units. The ``[geometry]`` of the ball-bearing types may give each ring's shoulder height above its groove
bottom (for angular contact rings: the high shoulder, on the side the contact runs to) as a length or as a
fraction of the ball diameter. :func:`shoulder_fractions` turns them into the ``shoulder_height`` mapping of
:func:`bearingkit.analysis.rating.assembly.rate` (row name → (inner, outer) / D_w) and refuses, in one line
naming the field, a height at or above the groove depth (the arc radius f D_w above the bottom, or
f D_w cos θ_b above a gothic arch's seam) or a pair whose shoulders would overlap (h_i + h_o ≥ D_w).
Fields not given take the kind's default in the rating
(``bearingkit.analysis.rating.options.DEFAULT_SHOULDER_HEIGHTS``).
"""

from __future__ import annotations

import numpy as np

from bearingkit.errors import InputError
from bearingkit.io.geometries import SHOULDER_FIELDS

__all__ = ["shoulder_fractions"]

#: Row kinds with ball grooves whose shoulders the input may set, and their conformity attributes
#: (inner, outer); None = no groove (the spherical outer raceway of a self-aligning ball row).
_GROOVES = {
    "ball": ("conformity_inner", "conformity_outer"),
    "four_point": ("conformity_inner", "conformity_outer"),
    "self_aligning_ball": ("conformity_inner", None),
}


def _fraction(spec: dict, dw: float) -> float:
    return float(spec["fraction"]) if "fraction" in spec else float(spec["length"]) / dw


def _fmt(spec: dict) -> str:
    return f"{spec['fraction']:.6g} D_w" if "fraction" in spec else f"{spec['length'] * 1e3:.6g} mm"


def shoulder_fractions(geometry: dict, model) -> dict | None:
    """Per-row (inner, outer) shoulder heights / D_w from a validated ``[geometry]`` dict, or None.

    Parameters
    ----------
    geometry : dict
        ``model_dump()`` of the geometry model (shoulder fields ``{"length": m}`` / ``{"fraction": x}``).
    model : BearingModel
        The built bearing (its ball rows give D_w and the groove conformities).

    Returns
    -------
    dict or None
        Row name → (h_i, h_o) / D_w (None for a side not given: the kind's default), or None when the
        file gives no shoulder height.
    """
    from bearingkit.physics.contact.truncation import seam_angle

    given = {k: geometry.get(k) for k in SHOULDER_FIELDS}
    if all(v is None for v in given.values()):
        return None
    out = {}
    for row in model.rows:
        grooves = _GROOVES.get(row.kind)
        if grooves is None:
            continue
        dw = float(np.max(row.element_diameter))
        fractions = []
        for (field, spec), attr in zip(given.items(), grooves, strict=True):
            if spec is None:
                fractions.append(None)
                continue
            if attr is None:
                raise InputError(f"geometry.{field} ({_fmt(spec)}): row {row.name!r} has no groove there")
            f = float(np.min(getattr(row, attr)))
            seam = float(seam_angle(f, float(np.max(row.contact_angle)))) if row.kind == "four_point" else 0.0
            depth = f * np.cos(seam)
            h = _fraction(spec, dw)
            if not h < depth:
                raise InputError(
                    f"geometry.{field} ({_fmt(spec)} = {h:.4g} D_w) must be below the groove depth "
                    f"{depth:.4g} D_w = {depth * dw * 1e3:.4g} mm of row {row.name!r} (the groove radius "
                    "above its bottom); give a smaller height"
                )
            fractions.append(h)
        h_i, h_o = fractions
        if h_i is not None and h_o is not None and h_i + h_o >= 1.0:
            raise InputError(
                f"geometry.shoulder_height_inner + shoulder_height_outer ({h_i:.4g} + {h_o:.4g} D_w) must "
                f"stay below the ball diameter of row {row.name!r}: the two rings' shoulders would overlap"
            )
        out[row.name] = (h_i, h_o)
    if not out:
        raise InputError(
            f"geometry.{next(k for k, v in given.items() if v is not None)}: the bearing has no ball grooves"
        )
    return out
