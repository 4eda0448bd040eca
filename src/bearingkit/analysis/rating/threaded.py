"""Ratings of threaded rows (planetary thread roller bearings, PTRB) as rows of equivalent balls.

SI units throughout: loads in N, lengths in m, lives in revolutions. C_r and C0r from Zheng et al. (2022)
eq. (5)-(12) (doi:10.3390/machines10111051) with the calibrated distribution coefficients; the
ISO/TS 16281:2008 reference life from the per-flank equivalent-ball loads. The rater plugs into
:data:`bearingkit.analysis.rating.assembly.ROW_RATERS`.
"""

from __future__ import annotations

import numpy as np

from bearingkit.analysis.rating.rows import RowContext, RowRating, _assemble, _attempt, _given_rating
from bearingkit.physics.life import iso16281

__all__ = ["rate_threaded_row", "threaded_groove_radii", "threaded_ratings"]


def threaded_ratings(geometry):
    """C_r and C0r [N] of a PTRB, Zheng et al. (2022) eq. (5)-(12), (physics.ptrb_rating).

    The same numbers as :func:`bearingkit.bearings.ptrb.ptrb_ratings` with the calibrated distribution
    coefficients (``analysis`` may not import ``bearings``): C_r = (2n)^0.7 C_Dr does not depend on the load
    distribution; C0r = 2n Q_0 cos α / f_rmax with the calibrated f_rmax.

    Parameters
    ----------
    geometry : PTRBGeometry

    Returns
    -------
    tuple of float
        (C_r, C0r) [N].
    """
    from bearingkit.physics.life import ptrb_rating as pr
    from bearingkit.rows.threaded.geometry import contact_pairs

    g = geometry
    pairs = contact_pairs(g)
    q0 = min(
        float(pr.static_contact_load(p.curvature_sum, p.curvature_difference, g.e_reduced))
        for p in pairs.values()
    )
    _, f_rmax = pr.calibrated_distribution_coefficients(g.n_elements)
    c0r = float(pr.static_rating_radial(q0, g.n_teeth, g.contact_angle, f_rmax))
    args = (
        g.gamma,
        g.contact_angle,
        g.roller_contact_radius,
        g.contact_radius_inner,
        g.roller_pitch_diameter,
    )
    cdr = pr.dynamic_rating_thread(
        pr.fc_radial(*args), g.element_diameter, g.n_elements, g.contact_angle, False
    )
    return float(pr.basic_dynamic_radial(cdr, g.n_teeth)), c0r


def threaded_groove_radii(geometry):
    """Groove radii (r_i, r_e) [m] of a ball with the PTRB flanks' ISO/TS 16281 conformity ratio.

    The TS ring-rating ratio holds [(r_i/r_e)(2r_e − D_w)/(2r_i − D_w)]^0.41 = (ρ_e/ρ_i)^0.41 with
    ρ = 2/D_w − 1/r the meridional curvature sum of ball and groove. For a thread flank pair it is
    ρ_X = 1/R_rr − 1/r_X (roller flank arc against ring flank, r_X = inf: flat). The radii with
    D_w/r_X' = 2 − ρ_X / max(ρ_i, ρ_e) reproduce the ratio exactly and stay finite (flat flanks: r' = D_w).

    Parameters
    ----------
    geometry : PTRBGeometry

    Returns
    -------
    tuple of float
        (r_i', r_e') [m].
    """
    g = geometry
    rho_i = 1.0 / g.roller_contact_radius - 1.0 / g.contact_radius_inner
    rho_e = 1.0 / g.roller_contact_radius - 1.0 / g.contact_radius_outer
    top = max(rho_i, rho_e)
    dw = g.element_diameter
    return dw / (2.0 - rho_i / top), dw / (2.0 - rho_e / top)


def rate_threaded_row(row, state, ctx: RowContext) -> RowRating:
    """Rate a :class:`~bearingkit.rows.threaded.row.ThreadedRow` (planetary thread roller bearing, PTRB).

    C = C_r and C0 = C0r of Zheng et al. (2022) (:func:`threaded_ratings`); the flank angle α <= 45° makes
    the PTRB a radial bearing in the ISO sense. L10r (ISO/TS 16281 eq. (19)-(29)) per equivalent ball:
    every (tooth, flank) is a row k of Z equivalent balls of diameter D_w = d_R/cos α (``RowState.
    slice_load``, the same load at ITP and OTP), with the raceway ratings Q_ci, Q_ce from C_r for i = 2n
    rows (the i^0.7 law of C_r) and the flanks' conformity ratio (:func:`threaded_groove_radii`); the rows'
    raceway terms add,

    .. math:: L_{10r} = \\Bigl[\\sum_k \\Bigl(\\frac{Q_{ci}}{Q_{ei,k}}\\Bigr)^{-10/3}
              + \\Bigl(\\frac{Q_{ce}}{Q_{ee,k}}\\Bigr)^{-10/3}\\Bigr]^{-0.9},

    which gives back ISO 281's (2n)^0.7 law when all rows carry the same loads. Flanks without load (the
    unloaded side of every tooth under axial load) drop out. Truncation: the flank-direction half-axis of
    a loaded contact (a when the meridional curvature sum ρ_A is the smaller, else b) exceeds the flank
    half-height h/sin α (dedendum h; a symmetric tooth is assumed).
    """
    from bearingkit.physics.life.ptrb_rating import thread_contact_curvature

    notes: list[str] = []
    g = row.geometry
    z, n, alpha, dw, dm = g.n_elements, g.n_teeth, g.contact_angle, g.element_diameter, g.pitch_diameter
    c = _given_rating(ctx, row, notes)
    ratings = _attempt("C, C0 (PTRB, Zheng et al. 2022)", lambda: threaded_ratings(g), notes)
    c0 = None if ratings is None else ratings[1]
    if c is None and ratings is not None:
        c = ratings[0]
    r_i, r_e = threaded_groove_radii(g)

    def life_fn(c_arr, loaded):
        qci, qce = iso16281.ball_raceway_ratings(c_arr, dw, dm, alpha, r_i, r_e, z, n_rows=2 * n)
        loads = np.moveaxis(state.slice_load, -1, -2)  # (C, 2n rows, Z balls)
        row_on = (loads.max(axis=-1) > 0) & loaded[:, None]
        safe = np.where(row_on[..., None], loads, 1.0)
        life_k = iso16281.ball_reference_life(safe, qci[:, None], qce[:, None], rotating=ctx.options.rotating)
        s = np.where(row_on, (life_k / iso16281.MILLION) ** (1.0 / iso16281.BALL_LIFE_EXP), 0.0).sum(-1)
        return iso16281.MILLION * np.where(loaded, s, 1.0) ** iso16281.BALL_LIFE_EXP

    half_height = g.dedendum / np.sin(alpha)
    truncated = np.zeros(state.slice_load.shape[0], bool)
    for side, d_x, r_x in (
        ("inner", g.d_inner, g.contact_radius_inner),
        ("outer", g.d_outer, g.contact_radius_outer),
    ):
        _, _, rho_a, rho_b = thread_contact_curvature(
            g.roller_pitch_diameter, d_x, g.roller_contact_radius, r_x, alpha, side
        )
        width = state.extras[f"{'semi_major' if rho_a <= rho_b else 'semi_minor'}_{side}"]
        truncated |= np.any((state.extras["tooth_load"] > 0) & (width > half_height), axis=(-3, -2, -1))
    text = (
        f"contact ellipse truncated by the thread flank (flank half-height h/sin α = {half_height * 1e3:.3g} "
        "mm assumed): Hertz pressure and life are optimistic"
    )
    return _assemble(
        row,
        state,
        ctx,
        bearing_type="planetary_thread_roller",
        element="ball",
        c=c,
        c0=c0,
        life_fn=life_fn,
        flags={"truncated_ellipse": ctx.converged & truncated},
        notes=notes,
        aiso_kind="radial_ball",
        pitch_diameter=dm,
        truncation_text=text,
        extra_references=("zheng2022", "zheng2021", "zheng2020"),
    )
