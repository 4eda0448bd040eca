"""Per-row ratings of a solved bearing: one rater per row kind (ball, cylindrical, tapered).

SI units throughout: loads in N, pressures in Pa, lengths in m, lives in revolutions.

A rater ``rater(row, state, ctx) -> RowRating`` rates one row of a
:class:`~bearingkit.analysis.solver.quasistatic.QuasiStaticResult` as a single-row bearing of its own
geometry:
ISO 76 C0, ISO 281 C, the ISO/TS 16281 basic reference rating life from the solved element or slice loads,
the static safety from the largest contact pressure and the row's warnings.
:data:`bearingkit.analysis.rating.assembly.ROW_RATERS` maps ``row.kind`` to its rater (threaded rows:
:mod:`bearingkit.analysis.rating.threaded`); :func:`bearingkit.analysis.rating.assembly.rate` combines the
rows.
Values that cannot be computed are masked (``numpy.ma``), never NaN.

References: ISO 76:2006, ISO 281:2007, ISO/TS 16281:2008, ISO/TR 1281-1; Lundberg & Palmgren (1947, 1952);
Zheng et al. (2022) doi:10.3390/machines10111051 (PTRB ratings).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from bearingkit import references
from bearingkit.analysis.rating.options import RatingOptions, shoulder_heights
from bearingkit.errors import InputError
from bearingkit.physics.life import iso76, iso281, iso281_life, iso16281

__all__ = [
    "ISO281_CONFORMITY_LIMITS",
    "WEIBULL_SLOPES",
    "RowContext",
    "RowRating",
    "rate_ball_row",
    "rate_cylindrical_row",
    "rate_tapered_row",
]

references.add(
    "lundberg1952",
    "Lundberg G., Palmgren A. (1952) Dynamic capacity of roller bearings. Acta Polytech. Mech. Eng. Ser. "
    "2(4).",
)
references.add(
    "zaretsky2013",
    "Zaretsky E.V. (2013) Rolling bearing life prediction, theory, and application. NASA/TP-2013-215305.",
)

_REFERENCES = (
    "iso76",
    "iso281",
    "iso16281",
    "iso_tr1281_1",
    "lundberg1947",
    "lundberg1952",
    "harris2007",
    "zaretsky2013",
)


def _masked(values, mask) -> np.ma.MaskedArray:
    return np.ma.masked_array(np.asarray(values, dtype=float), mask=np.asarray(mask, dtype=bool))


#: Weibull slope e of the life scatter [-]: 10/9 point contact, 9/8 line contact (Lundberg & Palmgren
#: 1947, 1952; Harris & Kotzalas 2007 vol. 2 ch. 8); the slopes behind the ISO/TS 16281 raceway exponents.
WEIBULL_SLOPES = {"ball": 10.0 / 9.0, "roller": 9.0 / 8.0}
#: ISO 281:2007 5.1.1 / 6.1.1: the f_c tables hold for groove radii r_i <= 0.52 D_w and r_e <= 0.53 D_w
#: (radial ball), r <= 0.54 D_w (thrust ball); larger radii lower the real rating.
ISO281_CONFORMITY_LIMITS = {"radial": (0.52, 0.53), "thrust": (0.54, 0.54)}


@dataclass
class RowContext:
    """What a row rater needs besides its row and state."""

    options: RatingOptions
    converged: np.ndarray
    n_cases: int


@dataclass
class RowRating:
    """Ratings of one row over the cases (arrays (C,), masked where a value is not available).

    Attributes
    ----------
    name, kind : str
        Row name and ``row.kind``.
    bearing_type : str
        The ISO 281 bearing type the row is rated as (``deep_groove_ball``, ``angular_contact_ball``,
        ``thrust_ball``, ``cylindrical_roller``, ``thrust_cylindrical_roller``).
    element : {"ball", "roller"}
    weibull_slope : float
        e [-] (:data:`WEIBULL_SLOPES`).
    load_rating, static_rating : MaskedArray [N]
        ISO 281 C and ISO 76 C0 of the row as a single-row bearing.
    life : MaskedArray [rev]
        ISO/TS 16281 basic reference rating life L10r.
    reference_load : MaskedArray [N]
        P_ref = C (L10r/10⁶)^(−1/p).
    life_modification : MaskedArray [-]
        a_ISO (masked unless lubrication inputs were given).
    modified_life_90, modified_life : MaskedArray [rev]
        a_ISO L10r and a1 a_ISO L10r.
    static_safety : MaskedArray [-]
        s0 from the largest contact pressure.
    max_pressure : ndarray [Pa]
    loaded_count : ndarray of int
    valid : ndarray of bool
        The case converged.
    flags : dict of str to ndarray of bool
        ``unloaded``, ``static_overload``, ``truncated_ellipse`` (balls), ``edge_loading`` (rollers).
    warnings : list of list of str
        Per case.
    references : tuple of str
    """

    name: str
    kind: str
    bearing_type: str
    element: str
    weibull_slope: float
    load_rating: np.ma.MaskedArray
    static_rating: np.ma.MaskedArray
    life: np.ma.MaskedArray
    reference_load: np.ma.MaskedArray
    life_modification: np.ma.MaskedArray
    modified_life_90: np.ma.MaskedArray
    modified_life: np.ma.MaskedArray
    static_safety: np.ma.MaskedArray
    max_pressure: np.ndarray
    loaded_count: np.ndarray
    valid: np.ndarray
    flags: dict
    warnings: list
    references: tuple = ()


def _attempt(what: str, fn, notes: list):
    """``fn()``; an InputError (a table range, a missing factor) becomes a note and None."""
    try:
        return fn()
    except InputError as exc:
        notes.append(f"{what} unavailable: {exc}")
        return None


def _assemble(
    row,
    state,
    ctx: RowContext,
    *,
    bearing_type,
    element,
    c,
    c0,
    life_fn,
    flags,
    notes,
    aiso_kind,
    pitch_diameter=None,
    truncation_text=None,
    extra_references=(),
):
    """Everything that is common to the row kinds: masks, s0, a_ISO, warnings.

    ``pitch_diameter`` [m] defaults to ``row.pitch_diameter`` (κ and C_u); ``truncation_text`` (a string, or
    a function of the case index) replaces the ball-groove wording of the truncation warning;
    ``extra_references`` are added to the row's references.
    """
    n, opts = ctx.n_cases, ctx.options
    valid = ctx.converged
    loaded = (state.loaded_count > 0) & valid
    ones = np.ones(n)
    c_arr = None if c is None else np.broadcast_to(np.asarray(c, float), (n,))
    c0_arr = None if c0 is None else np.broadcast_to(np.asarray(c0, float), (n,))
    p_max = state.max_pressure.max(axis=-1)
    limit_kind = "ball" if element == "ball" else "roller"
    s0 = iso76.static_safety_from_pressure(np.where(loaded, p_max, 1.0), limit_kind, opts.static_limit_factor)
    s0 = _masked(np.where(loaded, s0, 0.0), ~loaded)
    overload = loaded & (np.ma.getdata(s0) < 1.0)

    life_mask = ~loaded if c_arr is not None else np.ones(n, bool)
    life = np.zeros(n) if c_arr is None or not loaded.any() else life_fn(c_arr, loaded)
    life = _masked(np.where(life_mask, 0.0, life), life_mask)
    p_ref = _masked(ones, np.ones(n, bool))
    if c_arr is not None:
        safe_life = np.where(life_mask, 1.0e6, np.ma.getdata(life))
        p_ref = _masked(
            np.where(life_mask, 0.0, iso16281.reference_equivalent_load(safe_life, c_arr, element)), life_mask
        )

    a_iso = _masked(ones, True)
    kappa_low = np.zeros(n, bool)
    if opts.modified and c_arr is not None and c0_arr is not None:
        from bearingkit.lubricants import as_lubricant

        nu = as_lubricant(opts.lubricant).kinematic_viscosity(opts.temperature_C)
        dm = np.asarray(row.pitch_diameter if pitch_diameter is None else pitch_diameter, float)
        kappa = iso281.viscosity_ratio(nu, opts.speed, dm) * ones
        kappa_low = kappa < iso281_life.KAPPA_MIN
        cu = iso281.fatigue_load_limit_estimate(c0_arr, dm, element)
        p_safe = np.where(life_mask, c_arr, np.ma.getdata(p_ref))
        a = iso281.life_modification_factor(
            np.maximum(kappa, iso281_life.KAPPA_MIN), opts.contamination_factor, cu, p_safe, aiso_kind
        )
        a_iso = _masked(a, life_mask | kappa_low)
    a1 = float(iso281.reliability_factor(opts.reliability))
    mod90 = a_iso * life
    flags = {"unloaded": valid & ~loaded, "static_overload": overload, **flags}

    warnings = []
    for k in range(n):
        w = [] if not valid[k] else list(notes)
        if valid[k] and not loaded[k]:
            w.append("no loaded element: no fatigue life or static safety; excluded from the system life")
        if overload[k]:
            p_lim = iso76.CONTACT_LIMITS[limit_kind][0] * opts.static_limit_factor
            which = "ISO 76" if opts.static_limit_factor == 1.0 else "raceway material's (ISO 76 × hardness)"
            w.append(
                f"static safety s0 = {float(s0[k]):.3g} < 1: max contact pressure {p_max[k] / 1e6:.0f} MPa "
                f"exceeds the {which} limit {p_lim / 1e6:.0f} MPa"
            )
        if flags.get("truncated_ellipse", np.zeros(n, bool))[k]:
            if callable(truncation_text):  # per case: names the height the ellipses need
                w.append(truncation_text(k))
            else:
                w.append(truncation_text or _truncation_text(opts, row.name, bearing_type))
        if flags.get("edge_loading", np.zeros(n, bool))[k]:
            w.append(
                f"edge loading: a roller end slice reaches {opts.edge_pressure_ratio:.0%} of the row's "
                "largest slice pressure; the slice model does not resolve the edge stress peak"
            )
        if kappa_low[k] and loaded[k]:
            kmin = iso281_life.KAPPA_MIN
            w.append(f"viscosity ratio kappa below {kmin:g}: a_ISO not defined (ISO 281 9.3.3)")
        warnings.append(w)
    return RowRating(
        name=row.name,
        kind=row.kind,
        bearing_type=bearing_type,
        element=element,
        weibull_slope=WEIBULL_SLOPES[element],
        load_rating=_masked(c_arr if c_arr is not None else ones, np.full(n, c_arr is None)),
        static_rating=_masked(c0_arr if c0_arr is not None else ones, np.full(n, c0_arr is None)),
        life=life,
        reference_load=p_ref,
        life_modification=a_iso,
        modified_life_90=mod90,
        modified_life=mod90 * a1,
        static_safety=s0,
        max_pressure=np.where(valid, p_max, 0.0),
        loaded_count=np.where(valid, state.loaded_count, 0),
        valid=valid,
        flags=flags,
        warnings=warnings,
        references=tuple(dict.fromkeys(_REFERENCES + tuple(extra_references))),
    )


def _truncation_text(opts: RatingOptions, name: str, bearing_type: str, need=None) -> str:
    """The truncation warning; ``need`` = (h*_i, h*_o) / D_w of one case adds the heights that hold it."""
    h_i, h_o = shoulder_heights(opts, name, bearing_type)
    given = opts.shoulder_height is not None and (
        not isinstance(opts.shoulder_height, Mapping) or name in opts.shoulder_height
    )
    heights = f"inner {h_i:.3g} D_w" + ("" if h_o is None else f", outer {h_o:.3g} D_w")
    needed = ""
    if need is not None:
        parts = [
            f"{side} {x:.3g} D_w"
            for side, x, h in zip(("inner", "outer"), need, (h_i, h_o), strict=True)
            if x is not None and h is not None and x > h
        ]
        needed = f"; the loaded ellipses need {', '.join(parts)}" if parts else ""
    return (
        f"contact ellipse truncated by the groove shoulder (shoulder heights {heights}, "
        f"{'given' if given else 'default of the kind, not from the input'}{needed}): Hertz pressure and "
        "life are optimistic"
    )


def truncation_texts(opts: RatingOptions, name: str, bearing_type: str, need: dict):
    """Per-case truncation warning (a function of the case index) from :func:`groove_truncation`'s need."""

    def text(k: int) -> str:
        pick = tuple(None if need.get(side) is None else float(need[side][k]) for side in ("inner", "outer"))
        return _truncation_text(opts, name, bearing_type, pick)

    return text


def groove_truncation(
    state, dw, conformities, heights, *, bottom=0.0, angle=None, semi_major=None, need=None
):
    """Per case: is any loaded contact ellipse truncated by its groove shoulder (single-arc grooves)?

    Parameters
    ----------
    state : RowState
        ``contact_angle`` (C, Z) (or, at speed, ``extras['contact_angle_inner'/'_outer']``) [rad] and
        ``extras['semi_major_inner'/'semi_major_outer']`` [m].
    dw : array_like
        Ball diameter(s) D_w [m], (G,) or scalar.
    conformities : (array_like, array_like or None)
        f_i, f_o [-] (None: no outer groove, e.g. a spherical outer raceway).
    heights : (float, float or None)
        Shoulder heights h_i, h_o / D_w [-].
    bottom : array_like
        Angle of the groove bottom from the radial plane [rad] (±π/2 for thrust rows).
    angle, semi_major : optional
        Override ``state.contact_angle`` and the semi-axes (dict side → array).
    need : dict, optional
        Filled with side → (C,) the shoulder height / D_w that would hold every loaded ellipse of that
        ring (:func:`bearingkit.physics.contact.truncation.required_shoulder_height`; 0 when none loaded).
    """
    from bearingkit.physics.contact import truncation

    dw = np.asarray(dw, float).reshape(-1, 1)
    out = np.zeros(state.load.shape, bool)
    for side, f, h in zip(("inner", "outer"), conformities, heights, strict=True):
        if f is None or h is None:
            continue
        # at speed the inner and outer contact angles part (speed kernels report both)
        own = state.extras.get(f"contact_angle_{side}", state.contact_angle) if angle is None else angle
        off = np.abs(own - bottom)
        a = state.extras[f"semi_major_{side}"] if semi_major is None else semi_major[side]
        r = np.asarray(f, float).reshape(-1, 1) * dw
        loaded = (state.load > 0) & (a > 0)
        out |= loaded & truncation.truncated(off, a, r, h * dw)
        if need is not None:
            h_star = truncation.required_shoulder_height(off, a, r) / dw
            need[side] = np.where(loaded, h_star, 0.0).max(axis=-1, initial=0.0)
    return out.any(axis=-1)


def check_shoulders(row_name: str, heights, conformities, seams=(0.0, 0.0)):
    """Refuse shoulder heights / D_w at or above the groove depth f cos θ_b (one line, naming the row)."""
    for side, h, f, seam in zip(("inner", "outer"), heights, conformities, seams, strict=True):
        if h is None or f is None:
            continue
        depth = float(np.min(np.asarray(f, float) * np.cos(seam)))
        if not h < depth:
            raise InputError(
                f"shoulder_height_{side} ({h:.6g} D_w) of row {row_name!r} must be below the groove depth "
                f"{depth:.6g} D_w (the arc radius f·D_w above the groove bottom)"
            )


def _given_rating(ctx: RowContext, row, notes):
    """C [N] of the row given by the user (noted) or derived from the bearing's catalogue C (the rating's
    notes say so once), else None (computed by ISO 281 from the geometry)."""
    c = ctx.options.load_ratings.get(row.name)
    if c is not None:
        notes.append(f"C = {float(c):.6g} N given by the user (load_ratings), not computed by ISO 281")
        return c
    return ctx.options.catalogue_ratings.get(row.name)


def _one_class(name, values):
    arr = np.atleast_1d(values)
    if not (np.all(arr) or not np.any(arr)):
        raise InputError(f"{name} must not mix radial and thrust rows within one batched row geometry")
    return bool(arr.flat[0])


def rate_ball_row(row, state, ctx: RowContext) -> RowRating:
    """Rate a :class:`~bearingkit.rows.ball.row.BallRow`.

    Mapping by the free contact angle |α₀|: 0 → ``deep_groove_ball``; (0, 45°] → ``angular_contact_ball``
    (ISO 281 Table 2 / ISO 76 Table 1 with γ = D_w cos α/D_pw); (45°, 90°] → ``thrust_ball`` (Tables 4 and 3;
    ISO 281 f_c is shipped for 45°–75° and 90° only, other angles report C unavailable). L10r uses the
    nominal |α₀| in the raceway ratings (the operating angle enters through the element loads only) and the
    ball normal loads, equal at both raceways (no centrifugal force in the quasi-static engine).

    Truncation (:mod:`bearingkit.physics.contact.truncation`): the groove of radius r = f D_w ends at a
    shoulder h = ``shoulder_height`` · D_w above its bottom (bottom at 0 for radial/angular rows, at ±90° for
    thrust rows), i.e. at the angle θ_s = arccos(1 − h/r) from the bottom seen from the groove centre; the
    ellipse of semi-major axis a spans θ_a = arcsin(a/r) about the contact point, so it is truncated when
    |α − α_bottom| + θ_a > θ_s. Inner and outer shoulders may differ (``shoulder_height`` pairs); the
    defaults depend on the kind (deep groove / angular contact high shoulder / thrust,
    :data:`~bearingkit.analysis.rating.options.DEFAULT_SHOULDER_HEIGHTS`).
    """
    notes: list[str] = []
    alpha0 = np.asarray(row.contact_angle, float)
    a_abs = np.abs(alpha0)
    thrust = _one_class("contact_angle", a_abs > iso281.RADIAL_MAX_ANGLE)
    radial_zero = _one_class("contact_angle", a_abs == 0.0)
    kind = "thrust" if thrust else "radial"
    btype = "thrust_ball" if thrust else ("deep_groove_ball" if radial_zero else "angular_contact_ball")
    d, dm, z = row.element_diameter, row.pitch_diameter, row.n_elements
    fi, fo = np.asarray(row.conformity_inner, float), np.asarray(row.conformity_outer, float)
    c0 = _attempt("C0 (ISO 76)", lambda: iso76.static_rating_ball(d, dm, a_abs, z, kind=kind), notes)
    c = _given_rating(ctx, row, notes)
    if c is None:
        c = _attempt(
            "C (ISO 281)", lambda: iso281.dynamic_rating_ball(d, dm, a_abs, z, bearing_type=btype), notes
        )
        lim_i, lim_o = ISO281_CONFORMITY_LIMITS[kind]
        if c is not None and (np.any(fi > lim_i) or np.any(fo > lim_o)):
            notes.append(
                f"groove conformities ({np.max(fi):g}, {np.max(fo):g}) exceed the ISO 281 assumption "
                f"({lim_i:g}, {lim_o:g}): C overestimates the rating"
            )

    def life_fn(c_arr, loaded):
        qci, qce = iso16281.ball_raceway_ratings(c_arr, d, dm, a_abs, fi * d, fo * d, z, kind=kind)
        loads = np.where(loaded[:, None], state.load, 1.0)
        return iso16281.ball_reference_life(loads, qci, qce, rotating=ctx.options.rotating)

    heights = shoulder_heights(ctx.options, row.name, btype)
    check_shoulders(row.name, heights, (fi, fo))
    bottom = np.where(thrust, np.sign(alpha0) * np.pi / 2, 0.0).reshape(-1, 1)
    need = {}
    truncated = groove_truncation(state, d, (fi, fo), heights, bottom=bottom, need=need)
    flags = {"truncated_ellipse": ctx.converged & truncated}
    aiso_kind = "thrust_ball" if thrust else "radial_ball"
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
        aiso_kind=aiso_kind,
        truncation_text=truncation_texts(ctx.options, row.name, btype, need),
    )


#: Profiles ISO/TS 16281 states its edge-stress factor eq. (60) for: its logarithmic profiles eq. (42)-(44)
#: (registry names of :mod:`bearingkit.physics.contact.profiles`).
TS_PROFILES = ("iso16281", "iso16281_tapered")
#: Row kinds whose raters apply eq. (60) through :func:`_edge_checks`.
EDGE_FACTOR_KINDS = ("cylindrical", "tapered", "needle", "crossed_roller")
#: Total misalignment of the rings up to which ISO/TS 16281 states eq. (60): 4′ [rad] (the TS's note, as a
#: public implementation quotes it); beyond it the rating warns that the end-slice factor is approximate.
EDGE_FACTOR_MAX_MISALIGNMENT = np.radians(4.0 / 60.0)


def _edge_checks(row, state, ctx: RowContext, notes: list):
    """Edge-stress factor f_k to apply (or None) and the ``edge_loading`` flag of a sliced roller row.

    f_k (ISO/TS 16281:2008 eq. (60)) multiplies the slice loads per ``edge_stress_factor`` ("auto" and
    "always": every row with n_s >= 2). The TS gives eq. (60) as the approximation of its pressure-based
    factors eq. (58)-(59) for rollers with its own profile (eq. (42)-(44)); on a straight roller or another
    crowning it stands in for eq. (58)-(59), which bearingkit does not implement, and a note says so.
    Edge loading: an end slice whose Hertz pressure (inner or outer raceway, ``extras['slice_pressure_*']``)
    reaches ``edge_pressure_ratio`` of the row's largest slice pressure; not assessed for n_s = 1.
    """
    opts, n_s = ctx.options, row.n_slices
    use_fk = opts.edge_stress_factor in ("auto", "always")
    if use_fk and n_s < 2:
        notes.append("edge-stress factor not applied: n_slices = 1")
        use_fk = False
    profile = getattr(getattr(row, "profile", None), "name", None)
    if use_fk and profile not in TS_PROFILES:
        notes.append(
            f"edge-stress factor f_k of ISO/TS 16281 eq. (60) applied to a {profile or 'straight'} roller: "
            "the TS states it for its logarithmic profile (eq. (42)-(44)) and asks for pressure-based "
            "factors otherwise"
        )
    edge = np.zeros(ctx.n_cases, bool)
    if n_s < 2:
        notes.append("edge loading not assessed: n_slices = 1")
    else:
        p = np.maximum(state.extras["slice_pressure_inner"], state.extras["slice_pressure_outer"])
        p_row = p.max(axis=(-2, -1))
        p_end = np.maximum(p[..., 0], p[..., -1])
        edge = (p_row > 0) & np.any(p_end >= opts.edge_pressure_ratio * p_row[:, None], axis=-1)
    fk = iso16281.edge_stress_factor(n_s) if use_fk else None
    return fk, {"edge_loading": ctx.converged & edge}


def rate_cylindrical_row(row, state, ctx: RowContext) -> RowRating:
    """Rate a :class:`~bearingkit.rows.cylindrical.row.CylindricalRow`.

    Radial rows → ``cylindrical_roller`` (α = 0; ISO 281 f_c from the ISO/TR 1281-1 closed form, ISO 76
    eq. (3)); thrust rows → ``thrust_cylindrical_roller`` (α = 90°; ISO 76 eq. (8); ISO 281 f_c from the
    ISO/TR 1281-1 thrust closed form, :func:`~bearingkit.physics.life.iso281.fc_thrust_roller`). L10r from the
    slice loads (ISO/TS 16281 eq. (58)-(65)), with the edge-stress factor f_k of eq. (60) per
    ``edge_stress_factor``. Edge loading: an end slice whose pressure reaches ``edge_pressure_ratio`` of the
    row's largest slice pressure (not assessed for n_s = 1).
    """
    thrust = row.orientation != "radial"
    return _rate_roller_row(
        row,
        state,
        ctx,
        alpha=np.pi / 2 if thrust else 0.0,
        thrust=thrust,
        bearing_type="thrust_cylindrical_roller" if thrust else "cylindrical_roller",
    )


def _rate_roller_row(row, state, ctx: RowContext, *, alpha, thrust, bearing_type, inner_slice_load=None):
    """Ratings and ISO/TS 16281 life of a sliced roller row (cylindrical or tapered).

    ``inner_slice_load`` (C, Z, n_s) [N] is the inner-raceway slice load when it differs from the outer
    one (tapered rows: the rib takes part of the roller load); None = both raceways carry
    ``state.slice_load``.
    """
    notes: list[str] = []
    opts = ctx.options
    kind = "thrust" if thrust else "radial"
    d, length, dm, z, n_s = (
        row.element_diameter,
        row.effective_length,
        row.pitch_diameter,
        row.n_elements,
        row.n_slices,
    )
    c0 = _attempt(
        "C0 (ISO 76)", lambda: iso76.static_rating_roller(d, length, dm, alpha, z, kind=kind), notes
    )
    c = _given_rating(ctx, row, notes)
    if c is None:
        c = _attempt(
            "C (ISO 281)",
            lambda: iso281.dynamic_rating_roller(d, length, dm, alpha, z, bearing_type=bearing_type),
            notes,
        )
    fk, flags = _edge_checks(row, state, ctx, notes)

    def life_fn(c_arr, loaded):
        qci, qce = iso16281.roller_raceway_ratings(c_arr, d, dm, alpha, z, n_s, kind=kind)
        m = loaded[:, None, None]
        outer = np.where(m, state.slice_load, 1.0)
        if inner_slice_load is None:
            return iso16281.roller_reference_life(outer, qci, qce, rotating=opts.rotating, slice_factor=fk)
        inner = np.where(m, inner_slice_load, 1.0)
        return iso16281.roller_reference_life(
            inner, qci, qce, rotating=opts.rotating, slice_loads_outer=outer, slice_factor=fk
        )

    return _assemble(
        row,
        state,
        ctx,
        bearing_type=bearing_type,
        element="roller",
        c=c,
        c0=c0,
        life_fn=life_fn,
        flags=flags,
        notes=notes,
        aiso_kind="thrust_roller" if thrust else "radial_roller",
    )


def rate_tapered_row(row, state, ctx: RowContext) -> RowRating:
    """Rate a :class:`~bearingkit.rows.tapered.row.TaperedRow`.

    ISO nominal contact angle α = the cup angle α_e (ISO 281 / ISO 76: half the outer-raceway cone angle),
    D_we = mean roller diameter, L_we = ``effective_length``, D_pw = ``pitch_diameter``. α_e <= 45° →
    ``tapered_roller`` (ISO 281 eq. (9) with the radial roller f_c, γ = D_we cos α/D_pw; ISO 76 eq. (3));
    α_e > 45° → ``thrust_tapered_roller`` (thrust f_c, ISO 76 eq. (8)). L10r (ISO/TS 16281 eq. (47)-(65),
    radial roller constants λν = 0.83, 0.378/0.364 with cos α): the cone (inner) raceway takes the cone
    slice loads ``extras['slice_load_inner']``, the cup (outer) raceway the cup slice loads
    ``RowState.slice_load`` — they differ because the rib carries part of the roller load; the rib contact
    is a sliding contact and is not rated. Edge-stress factor and edge loading as for cylindrical rows.
    """
    alpha = float(row.contact_angle_outer)
    thrust = alpha > iso281.RADIAL_MAX_ANGLE
    return _rate_roller_row(
        row,
        state,
        ctx,
        alpha=alpha,
        thrust=thrust,
        bearing_type="thrust_tapered_roller" if thrust else "tapered_roller",
        inner_slice_load=state.extras["slice_load_inner"],
    )
