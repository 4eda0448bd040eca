"""Truncated contact ellipses of a solved bearing as numbers: pressure, track-truncation safety, and the
loads that carry them into s0 and the life.

SI units (m, N, Pa). For the ball rows whose contact ellipses can run over a groove shoulder (ball,
four-point — shoulder and arch seam —, self-aligning ball inner grooves), every loaded contact gets
(:mod:`bearingkit.physics.contact.truncation`)

- the track-truncation safety h / h* (available over needed shoulder height; < 1: truncated);
- the truncated pressure p_tr = s p_max of the ellipse cut at the edge and re-equilibrated, and the load
  Q′ = s³ Q of the untruncated contact with that peak pressure.

Per row and case the results are the largest p_tr and the smallest safety over the contacts.
:func:`truncated_result` gives a copy of the solution whose truncated contacts carry Q′ and p_tr, so that
the unchanged rating (:func:`bearingkit.analysis.rating.assembly.rate`) returns s0 and L10r *with* truncation
(the pipeline does that beside the plain rating). The shoulder geometry and its defaults are the rating's
(:func:`bearingkit.analysis.rating.options.shoulder_heights`), so the numbers and the warning agree.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from bearingkit.analysis.rating.options import RatingOptions, shoulder_heights
from bearingkit.physics.contact import truncation as tr
from bearingkit.physics.life.iso281 import RADIAL_MAX_ANGLE
from bearingkit.rows.base import RowState

__all__ = ["ROW_KINDS", "RowTruncation", "row_truncation", "truncated_result", "truncation"]

#: Row kinds whose contact ellipses are checked against groove shoulders.
ROW_KINDS = ("ball", "four_point", "self_aligning_ball")


@dataclass
class RowTruncation:
    """Truncation of one ball row's contacts, per load case (leading axis C).

    Attributes
    ----------
    name, kind : str
    pressure : ndarray (C,) [Pa]
        Largest contact pressure with truncation (p_tr of a cut contact, p_max of the others).
    hertz_pressure : ndarray (C,) [Pa]
        The untruncated Hertz p_max of the contact whose p_tr is the largest.
    safety : ndarray (C,) [-]
        Smallest track-truncation safety over the loaded contacts (+inf: none loaded).
    truncated : ndarray (C,) of bool
        Some loaded contact is cut (safety < 1).
    scale : ndarray [-]
        s per contact ((C, Z, sides) or (C, Z, 4) for four-point balls): p_tr / p_max, Q′/Q = s³.
    """

    name: str
    kind: str
    pressure: np.ndarray
    hertz_pressure: np.ndarray
    safety: np.ndarray
    truncated: np.ndarray
    scale: np.ndarray


def _ball_geometry(row, options):
    """(f_i, f_o), (h_i, h_o)·D_w [m], groove-bottom angle [rad] of a ball or self-aligning ball row."""
    d = np.asarray(row.element_diameter, float).reshape(-1, 1)
    fi, fo = np.asarray(row.conformity_inner, float), np.asarray(row.conformity_outer, float)
    if row.kind == "self_aligning_ball":
        hi, _ = shoulder_heights(options, row.name, "self_aligning_ball")
        return d, (fi.reshape(-1, 1), None), (hi, None), 0.0
    alpha0 = np.asarray(row.contact_angle, float)
    thrust = bool(np.all(np.abs(alpha0) > RADIAL_MAX_ANGLE))
    radial = "deep_groove_ball" if np.all(alpha0 == 0) else "angular_contact_ball"
    btype = "thrust_ball" if thrust else radial
    heights = shoulder_heights(options, row.name, btype)
    bottom = np.where(thrust, np.sign(alpha0) * np.pi / 2, 0.0).reshape(-1, 1)
    return d, (fi.reshape(-1, 1), fo.reshape(-1, 1)), heights, bottom


def _sides(row, state, options):
    """Per raceway: p_max, p_tr, safety (C, Z); scale (C, Z, sides)."""
    d, conformity, heights, bottom = _ball_geometry(row, options)
    ptr, pmax, safe = [], [], []
    for side, f, h in zip(("inner", "outer"), conformity, heights, strict=True):
        if f is None or h is None:
            continue
        own = state.extras.get(f"contact_angle_{side}", state.contact_angle)
        off = np.abs(own - bottom)
        a = state.extras[f"semi_major_{side}"]
        p = state.extras[f"max_pressure_{side}"]
        r, hd = f * d, h * d
        loaded = (state.load > 0) & (a > 0)
        tau = tr.remaining_fraction(off, a, r, tr.shoulder_angle(hd, r))
        ptr.append(np.where(loaded, tr.truncated_pressure(p, tau), 0.0))
        pmax.append(np.where(loaded, p, 0.0))
        safe.append(np.where(loaded, tr.truncation_safety(off, a, r, hd), np.inf))
    return np.stack(pmax, -1), np.stack(ptr, -1), np.stack(safe, -1)


def _four_point(row, state, options):
    """Per contact (C, Z, 4): p_max, p_tr, safety, with the shoulder and the arch seam."""
    d = float(np.max(row.element_diameter))
    alpha0 = float(np.max(row.contact_angle))
    fi, fo = float(np.max(row.conformity_inner)), float(np.max(row.conformity_outer))
    h_i, h_o = shoulder_heights(options, row.name, "four_point")
    seams = (tr.seam_angle(fi, alpha0), tr.seam_angle(fo, alpha0))
    r = np.array([fo, fo, fi, fi]) * d
    h = np.array([h_o, h_o, h_i, h_i]) * d
    seam = np.array([seams[1], seams[1], seams[0], seams[0]])
    ex = state.extras
    alpha, a, p = np.abs(ex["contact_angle_all"]), ex["semi_major"], ex["max_pressure_contact"]
    loaded = (ex["contact_load"] > 0) & (a > 0)
    shoulder = tr.remaining_fraction(alpha, a, r, tr.shoulder_angle(h, r, seam))
    # seam side: the arc between the contact point and the seam, r sin(α − θ_b), over a
    with np.errstate(divide="ignore", invalid="ignore"):
        near = np.where(a > 0, r * np.sin(alpha - seam) / np.where(a > 0, a, 1.0), np.inf)
    ptr = np.where(loaded, tr.truncated_pressure(p, shoulder, np.maximum(near, -1.0)), 0.0)
    safe = np.where(loaded, tr.truncation_safety(alpha, a, r, h, seam=seam), np.inf)
    return np.where(loaded, p, 0.0), ptr, safe


def row_truncation(row, state, options: RatingOptions, converged) -> RowTruncation | None:
    """Truncation numbers of one row (None for rows without groove shoulders)."""
    if row.kind not in ROW_KINDS:
        return None
    pmax, ptr, safe = (_four_point if row.kind == "four_point" else _sides)(row, state, options)
    c = pmax.shape[0]
    flat = lambda a: a.reshape(c, -1)  # noqa: E731
    k = np.argmax(flat(ptr), axis=1)
    ok = np.asarray(converged, bool)
    pressure = np.where(ok, flat(ptr).max(axis=1), 0.0)
    hertz = np.where(ok, np.take_along_axis(flat(pmax), k[:, None], 1)[:, 0], 0.0)
    safety = np.where(ok, flat(safe).min(axis=1), np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        scale = np.where(pmax > 0, ptr / np.where(pmax > 0, pmax, 1.0), 1.0)
    return RowTruncation(row.name, row.kind, pressure, hertz, safety, ok & (safety < 1.0), scale)


def truncation(result, options: RatingOptions) -> list:
    """:func:`row_truncation` of every row of a solved bearing (None for rows without shoulders)."""
    return [
        row_truncation(row, state, options, result.converged)
        for row, state in zip(result.model.rows, result.rows, strict=True)
    ]


def _scaled_state(state, t: RowTruncation) -> RowState:
    """A copy of a ball row's state whose contacts carry Q′ = s³ Q and p_tr = s p_max."""
    ex = dict(state.extras)
    s3 = t.scale**3
    if t.kind == "four_point":
        ex["contact_load"] = ex["contact_load"] * s3
        ex["max_pressure_contact"] = ex["max_pressure_contact"] * t.scale
        load = ex["contact_load"].max(axis=-1)
        p = ex["max_pressure_contact"].max(axis=-1)
    else:
        # one ball load for both raceways: the larger re-equilibrated load of its two contacts
        load = state.load * s3.max(axis=-1)
        sides = [s for s in ("inner", "outer") if f"max_pressure_{s}" in ex][: t.scale.shape[-1]]
        for i, side in enumerate(sides):
            ex[f"max_pressure_{side}"] = ex[f"max_pressure_{side}"] * t.scale[..., i]
        p = np.max([ex[f"max_pressure_{side}"] for side in sides], axis=0)
    return RowState(
        state.kind,
        state.name,
        state.azimuth,
        load,
        state.deflection,
        state.contact_angle,
        p,
        state.slice_load,
        ex,
    )


def truncated_result(result, truncations: list):
    """A copy of ``result`` whose truncated ball contacts carry the re-equilibrated loads and pressures
    (rows without truncation keep their states), for rating s0 and L10r with truncation."""
    rows = [
        state if t is None or not t.truncated.any() else _scaled_state(state, t)
        for state, t in zip(result.rows, truncations, strict=True)
    ]
    return dataclasses.replace(result, _rows=rows)
