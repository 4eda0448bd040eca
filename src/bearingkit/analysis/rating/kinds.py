"""Raters of the bearing kinds: four-point contact ball, crossed roller, spherical roller, self-aligning
ball and needle rows (ISO 76 C0, ISO 281 C, ISO/TS 16281 life from the solved distribution, s0).

SI units: loads in N, pressures in Pa, lives in revolutions. Each rater follows
:mod:`bearingkit.analysis.rating.rows` (``rater(row, state, ctx) -> RowRating``) and registers itself with
:func:`bearingkit.analysis.rating.assembly.register_row_rater` when this module is imported (the package
``bearingkit.analysis`` imports it).

- **four-point** (``four_point``): rated per diagonal as a single-row angular contact ball bearing
  (i = 1: under axial load one diagonal carries, as for a single-row bearing), ISO 281 Table 2 f_c and
  ISO 76 Table 1 f0 for α₀ ≤ 45°, the thrust tables above (slewing rings at 50°-60°). The ISO/TS 16281
  life sums the four raceways (two arcs per ring), each with its own equivalent load from its contact
  loads: L10r = [Σ_r (Q_cr/Q_er)^(−10/3)]^(−0.9) (Weibull slope 10/9 per raceway). Truncation: each
  contact's ellipse must stay on its own arc, between the arch seam θ_b and the shoulder θ_s
  (:mod:`bearingkit.physics.contact.truncation`).
- **crossed roller** (``crossed_roller``): each direction (Z/2 rollers at +α, Z/2 at −α) is a single-row
  radial roller bearing at α = 45° (ISO 281 eq. (9), ISO 76 eq. (3), b_m of cylindrical rollers); its two
  raceway pairs' lives combine with slope 9/8.
- **spherical roller** (``spherical_roller``): each row a single-row radial roller row of b_m 1.15
  (ISO 281 Table 1, "spherical roller"); L10r from the outer and inner slice loads separately. A row at
  α > 45° is the row of a spherical roller thrust bearing: the thrust roller formulas (ISO 281 eq. (11),
  b_m 1.15 of "spherical roller thrust", f_c of :func:`~bearingkit.physics.life.iso281.fc_thrust_roller`;
  ISO 76 eq. (7), C0a = 220 (1 − D_we cos α/D_pw) Z L_we D_we sin α) and the thrust raceway ratings of
  ISO/TS 16281 (λ = 0.73).
- **self-aligning ball** (``self_aligning_ball``): f_c and f0 from :mod:`bearingkit.physics.life.kinds`
  (not shipped ISO columns, derived), C0 stress limit 4600 MPa; truncation checked at the inner grooves'
  shoulders (the outer raceway is a sphere).
- **needle** (``needle``): the cylindrical rater with b_m of machined (1.1) or drawn-cup (1.0) needle
  bearings (ISO 281 Table 1) and a warning when the needles run on the shaft.

References: ISO 76:2006, ISO 281:2007, ISO/TS 16281:2008, ISO/TR 1281-1; Harris & Kotzalas (2007) ch. 8.
"""

from __future__ import annotations

import numpy as np

from bearingkit.analysis.rating.assembly import register_row_rater
from bearingkit.analysis.rating.options import shoulder_heights
from bearingkit.analysis.rating.rows import (
    RowContext,
    RowRating,
    _assemble,
    _attempt,
    _edge_checks,
    _given_rating,
    _rate_roller_row,
    _truncation_text,
    check_shoulders,
    groove_truncation,
    truncation_texts,
)
from bearingkit.physics.life import iso76, iso281, iso16281
from bearingkit.physics.life import kinds as life_kinds

RADIAL_MAX_ANGLE = np.pi / 4
_BALL_EXP = iso16281.BALL_LOAD_EXP
_ROLLER_EXP = iso16281.ROLLER_COMBINE_EXP


def _means(rotating: str):
    """Equivalent-load exponents (inner, outer raceway) for the rotating ring (ISO/TS 16281)."""
    rot, stat = iso16281.BALL_ROTATING_MEAN, iso16281.BALL_STATIONARY_MEAN
    return (rot, stat) if rotating == "inner" else (stat, rot)


def _power_mean(q, p, axis=-1):
    return np.mean(q**p, axis=axis) ** (1.0 / p)


def raceway_life(loads, ratings, means, exponent, life_exponent):
    """L10r [rev] of raceways failing independently from their loads and ratings (ISO/TS 16281).

    .. math:: L_{10r} = 10^6 \\Bigl[\\sum_r (Q_{cr}/Q_{er})^{-p}\\Bigr]^{e},\\quad
              Q_{er} = \\bigl(\\overline{Q_{jr}^{m_r}}\\bigr)^{1/m_r}

    Parameters
    ----------
    loads : list of ndarray (C, Z[, n_s])
        Element (or slice) loads of each raceway [N]; all-zero raceways contribute nothing.
    ratings : list of float or ndarray
        Q_c of each raceway [N] (per slice for slices).
    means : list of float
        Equivalent-load exponent m_r of each raceway (3 / 10/3 balls, 4 / 4.5 rollers).
    exponent : float
        p (10/3 balls, 9/2 rollers).
    life_exponent : float
        e (−0.9 balls, −8/9 rollers).
    """
    total = 0.0
    for q, qc, m in zip(loads, ratings, means, strict=True):
        qe = _power_mean(np.asarray(q, float), m, axis=1)  # over the elements: (C,) or (C, n_s)
        qc = np.asarray(qc, float).reshape((-1,) + (1,) * (qe.ndim - 1))
        term = np.where(qe > 0, (qc / np.maximum(qe, 1e-300)) ** (-exponent), 0.0)
        total = total + term.reshape(term.shape[0], -1).sum(axis=-1)
    return iso16281.MILLION * np.where(total > 0, total, np.inf) ** life_exponent


# --- four-point contact ball ------------------------------------------------------------------------
def rate_four_point_row(row, state, ctx: RowContext) -> RowRating:
    """Rate a :class:`~bearingkit.rows.ball.four_point.FourPointRow` (module docstring)."""
    notes: list[str] = []
    d, dm, z = row.element_diameter, row.pitch_diameter, row.n_elements
    alpha = float(np.max(row.contact_angle))
    thrust = alpha > RADIAL_MAX_ANGLE
    kind = "thrust" if thrust else "radial"
    btype = "thrust_ball" if thrust else "angular_contact_ball"
    fi, fo = float(np.max(row.conformity_inner)), float(np.max(row.conformity_outer))
    c0 = _attempt("C0 (ISO 76)", lambda: iso76.static_rating_ball(d, dm, alpha, z, kind=kind), notes)
    c = _given_rating(ctx, row, notes)
    if c is None:
        c = _attempt(
            "C (ISO 281)", lambda: iso281.dynamic_rating_ball(d, dm, alpha, z, bearing_type=btype), notes
        )
    m_in, m_out = _means(ctx.options.rotating)
    flags = _four_point_truncation(row, state, ctx)

    def life_fn(c_arr, loaded):
        qci, qce = iso16281.ball_raceway_ratings(c_arr, d, dm, alpha, fi * d, fo * d, z, kind=kind)
        cl = np.where(loaded[:, None, None], state.extras["contact_load"], 0.0)
        loads = [cl[..., k] for k in range(4)]  # outer upper, outer lower, inner lower, inner upper
        return raceway_life(
            loads, [qce, qce, qci, qci], [m_out, m_out, m_in, m_in], _BALL_EXP, iso16281.BALL_LIFE_EXP
        )

    return _assemble(
        row,
        state,
        ctx,
        bearing_type=btype,
        element="ball",
        c=c,
        c0=c0,
        life_fn=life_fn,
        flags=flags,
        notes=notes,
        aiso_kind="thrust_ball" if thrust else "radial_ball",
        truncation_text=_truncation_text(ctx.options, row.name, "four_point").replace(
            "groove shoulder", "arch (shoulder or seam)"
        ),
        extra_references=("amasorrain2003",),
    )


def _four_point_truncation(row, state, ctx: RowContext) -> dict:
    """``truncated_ellipse`` of a four-point row: a loaded contact's ellipse leaves its arc (module doc)."""
    from bearingkit.physics.contact import truncation

    d = float(np.max(row.element_diameter))
    alpha0 = float(np.max(row.contact_angle))
    fi, fo = float(np.max(row.conformity_inner)), float(np.max(row.conformity_outer))
    h_i, h_o = shoulder_heights(ctx.options, row.name, "four_point")
    seams = (truncation.seam_angle(fi, alpha0), truncation.seam_angle(fo, alpha0))
    check_shoulders(row.name, (h_i, h_o), (fi, fo), seams)
    f = np.array([fo, fo, fi, fi])
    h = np.array([h_o, h_o, h_i, h_i]) * d
    seam = np.array([seams[1], seams[1], seams[0], seams[0]])
    hit = truncation.truncated(
        state.extras["contact_angle_all"], state.extras["semi_major"], f * d, h, seam=seam
    )
    hit &= state.extras["contact_load"] > 0
    return {"truncated_ellipse": ctx.converged & hit.any(axis=(-2, -1))}


# --- crossed rollers -------------------------------------------------------------------------------
def rate_crossed_roller_row(row, state, ctx: RowContext) -> RowRating:
    """Rate a :class:`~bearingkit.rows.cylindrical.crossed.CrossedRollerRow` (module docstring)."""
    notes: list[str] = []
    d, length, dm, z, n_s = (
        row.element_diameter,
        row.effective_length,
        row.pitch_diameter,
        row.n_elements,
        row.n_slices,
    )
    alpha, half = float(row.contact_angle), z // 2
    kind = "thrust" if alpha > RADIAL_MAX_ANGLE else "radial"
    btype = "thrust_cylindrical_roller" if kind == "thrust" else "cylindrical_roller"
    c0 = _attempt(
        "C0 (ISO 76)", lambda: iso76.static_rating_roller(d, length, dm, alpha, half, kind=kind), notes
    )
    c = _given_rating(ctx, row, notes)
    if c is None:
        c = _attempt(
            "C (ISO 281)",
            lambda: iso281.dynamic_rating_roller(d, length, dm, alpha, half, bearing_type=btype),
            notes,
        )
    notes.append(
        "crossed rollers rated per direction (Z/2 rollers) as a single-row roller bearing at the contact "
        "angle; no ISO entry exists for crossed roller bearings"
    )
    fk, flags = _edge_checks(row, state, ctx, notes)
    rot, stat = iso16281.ROLLER_ROTATING_MEAN, iso16281.ROLLER_STATIONARY_MEAN
    m_in, m_out = (rot, stat) if ctx.options.rotating == "inner" else (stat, rot)

    def life_fn(c_arr, loaded):
        qci, qce = iso16281.roller_raceway_ratings(c_arr, d, dm, alpha, half, n_s, kind=kind)
        q = np.where(loaded[:, None, None], state.slice_load, 0.0)
        if fk is not None:
            q = q * fk
        loads = [q[:, 0::2], q[:, 0::2], q[:, 1::2], q[:, 1::2]]
        return raceway_life(
            loads, [qci, qce, qci, qce], [m_in, m_out, m_in, m_out], _ROLLER_EXP, iso16281.ROLLER_LIFE_EXP
        )

    return _assemble(
        row,
        state,
        ctx,
        bearing_type=btype,
        element="roller",
        c=c,
        c0=c0,
        life_fn=life_fn,
        flags=flags,
        notes=notes,
        aiso_kind="thrust_roller" if kind == "thrust" else "radial_roller",
    )


# --- self-aligning rows ----------------------------------------------------------------------------
def _edge_flag(state, ctx: RowContext, n_slices: int) -> dict:
    """Edge loading of a sliced profiled contact: an end slice at ``edge_pressure_ratio`` of the peak."""
    if n_slices < 2:
        return {"edge_loading": np.zeros(ctx.n_cases, bool)}
    p = np.maximum(state.extras["slice_pressure_inner"], state.extras["slice_pressure_outer"])
    p_row = p.max(axis=(-2, -1))
    p_end = np.maximum(p[..., 0], p[..., -1])
    edge = (p_row > 0) & np.any(p_end >= ctx.options.edge_pressure_ratio * p_row[:, None], axis=-1)
    return {"edge_loading": ctx.converged & edge}


def rate_spherical_roller_row(row, state, ctx: RowContext) -> RowRating:
    """Rate one row of a spherical roller bearing (module docstring)."""
    notes: list[str] = []
    d, length, dm, z, n_s = (
        row.element_diameter,
        row.effective_length,
        row.pitch_diameter,
        row.n_elements,
        row.n_slices,
    )
    alpha = abs(float(row.contact_angle))
    kind = "thrust" if alpha > RADIAL_MAX_ANGLE else "radial"
    btype = "thrust_spherical_roller" if kind == "thrust" else "spherical_roller"
    c0 = _attempt(
        "C0 (ISO 76)", lambda: iso76.static_rating_roller(d, length, dm, alpha, z, kind=kind), notes
    )
    c = _given_rating(ctx, row, notes)
    if c is None:
        c = _attempt(
            "C (ISO 281)",
            lambda: iso281.dynamic_rating_roller(d, length, dm, alpha, z, bearing_type=btype),
            notes,
        )
    rot, stat = iso16281.ROLLER_ROTATING_MEAN, iso16281.ROLLER_STATIONARY_MEAN
    m_in, m_out = (rot, stat) if ctx.options.rotating == "inner" else (stat, rot)

    def life_fn(c_arr, loaded):
        qci, qce = iso16281.roller_raceway_ratings(c_arr, d, dm, alpha, z, n_s, kind=kind)
        mask = loaded[:, None, None]
        inner = np.where(mask, state.extras["slice_load_inner"], 0.0)
        outer = np.where(mask, state.slice_load, 0.0)
        return raceway_life([inner, outer], [qci, qce], [m_in, m_out], _ROLLER_EXP, iso16281.ROLLER_LIFE_EXP)

    return _assemble(
        row,
        state,
        ctx,
        bearing_type=btype,
        element="roller",
        c=c,
        c0=c0,
        life_fn=life_fn,
        flags=_edge_flag(state, ctx, n_s),
        notes=notes,
        aiso_kind="thrust_roller" if kind == "thrust" else "radial_roller",
    )


def rate_self_aligning_ball_row(row, state, ctx: RowContext) -> RowRating:
    """Rate one row of a self-aligning ball bearing (module docstring)."""
    notes: list[str] = []
    d, dm, z = row.element_diameter, row.pitch_diameter, row.n_elements
    alpha = abs(float(row.contact_angle))
    gamma = d * np.cos(alpha) / dm
    fi, fo = row.conformity_inner, row.conformity_outer
    f0 = life_kinds.f0_self_aligning_ball(gamma, fi)
    c0 = _attempt("C0 (ISO 76)", lambda: iso76.static_rating_ball(d, dm, alpha, z, f0=f0), notes)
    c = _given_rating(ctx, row, notes)
    if c is None:
        fc = life_kinds.fc_self_aligning_ball(gamma, fi)
        c = _attempt(
            "C (ISO 281)",
            lambda: iso281.dynamic_rating_ball(d, dm, alpha, z, bearing_type="self_aligning_ball", fc=fc),
            notes,
        )
    notes.append(
        "self-aligning f_c and f0 derived (ISO/TR 1281-1 ratio; ISO 76 stress definition at 4600 MPa)"
    )
    m_in, m_out = _means(ctx.options.rotating)

    def life_fn(c_arr, loaded):
        qci, qce = iso16281.ball_raceway_ratings(c_arr, d, dm, alpha, fi * d, fo * d, z)
        q = np.where(loaded[:, None], state.load, 0.0)
        return raceway_life([q, q], [qci, qce], [m_in, m_out], _BALL_EXP, iso16281.BALL_LIFE_EXP)

    heights = shoulder_heights(ctx.options, row.name, "self_aligning_ball")
    check_shoulders(row.name, heights, (fi, None))
    need = {}
    truncated = groove_truncation(state, d, (fi, None), heights, need=need)
    rating = _assemble(
        row,
        state,
        ctx,
        bearing_type="self_aligning_ball",
        element="ball",
        c=c,
        c0=c0,
        life_fn=life_fn,
        flags={"truncated_ellipse": ctx.converged & truncated},
        notes=notes,
        aiso_kind="radial_ball",
        truncation_text=truncation_texts(ctx.options, row.name, "self_aligning_ball", need),
    )
    # ISO 76 sets the self-aligning limit at 4600 MPa (not 4200): s0 = (4600/p_max)^3.
    p = rating.max_pressure
    loaded = ~np.ma.getmaskarray(rating.static_safety)
    s0 = iso76.static_safety_from_pressure(
        np.where(loaded, np.maximum(p, 1.0), 1.0), "self_aligning_ball", ctx.options.static_limit_factor
    )
    rating.static_safety = np.ma.masked_array(np.where(loaded, s0, 0.0), ~loaded)
    return rating


def rate_needle_row(row, state, ctx: RowContext) -> RowRating:
    """Rate a :class:`~bearingkit.rows.cylindrical.needle.NeedleRow`: cylindrical rater, needle b_m, shaft
    warning."""
    rating = _rate_roller_row(row, state, ctx, alpha=0.0, thrust=False, bearing_type=row.bearing_type)
    if not row.inner_ring:
        note = (
            "needles on the shaft: ISO 76/281 ratings hold only if the shaft raceway is equivalent to a "
            "bearing ring (hardened 58-64 HRC, ground); otherwise reduce C and C0"
        )
        for w, ok in zip(rating.warnings, rating.valid, strict=True):
            if ok:
                w.append(note)
    return rating


RATERS = {
    "four_point": rate_four_point_row,
    "crossed_roller": rate_crossed_roller_row,
    "spherical_roller": rate_spherical_roller_row,
    "self_aligning_ball": rate_self_aligning_ball_row,
    "needle": rate_needle_row,
}
for _kind, _rater in RATERS.items():
    register_row_rater(_kind, _rater)
