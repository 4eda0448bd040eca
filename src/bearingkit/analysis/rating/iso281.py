"""ISO 281:2007 basic rating life of the whole bearing, beside the ISO/TS 16281 life of the rows.

SI units: loads in N, lives in revolutions. What a catalogue calculation gives (MESYS and KISSsoft print
it next to L10r): the equivalent dynamic load P = X F_r + Y F_a of the applied load (F_r = |(F_x, F_y)|,
F_a = |F_z|; ISO 281 5.2, 6.2, 7.2, 8.2, :func:`bearingkit.physics.life.iso281_load.equivalent_dynamic_load`),
the bearing's basic dynamic rating C, L10 = (C/P)^p 10⁶ rev (p = 3 ball, 10/3 roller) and, with the
lubrication inputs, L_nm = a1 a_ISO L10 with a_ISO from the rows' κ, e_C and C_u at P.

Which bearings have an ISO 281 P: one row (deep groove, angular contact, thrust ball; cylindrical,
tapered, thrust roller, spherical roller thrust; four-point, self-aligning, spherical, needle through
:data:`bearingkit.physics.life.kinds.KIND_LOAD_LAWS`) and two equal ball or tapered rows side by side,
rated as ISO 281's paired unit (:func:`bearingkit.physics.life.iso281.paired_unit_ratings`): C = 2^0.7
C_row (ball) or 2^(7/9) C_row (roller), C0 = 2 C0_row, with the double-row X, Y for rows of opposite
contact angle (DB, DF; or 0°) and the single-row X, Y for a tandem set (DT). Anything else (composites
of unequal rows, two thrust cylindrical rows, crossed roller and slewing rings, threaded rows) gets a note
instead of an invented X/Y.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit.analysis.rating.options import RatingOptions
from bearingkit.errors import InputError
from bearingkit.physics.life import iso76, iso281, iso281_life, iso281_load
from bearingkit.physics.life import kinds as life_kinds

#: Relative tolerance for "equal rows" (element size, pitch diameter, |α|).
_SAME = 1e-9
#: F_r or F_a below this fraction of the larger one is round-off of a fixed DOF's reaction (taken as 0).
_ROUND_OFF = 1e-9
#: Contact angle [rad] from which ISO 281 Table 3's angular contact X, Y no longer depend on i f0 F_a/C0r.
_XY_CONSTANT_FROM = np.radians(iso281_load.ANGULAR_CONSTANT_FROM_DEG)
#: ``model.metadata`` key of slewing rings (:data:`bearingkit.bearings.slewing.SLEWING_KEY`; the
#: bearings layer sits above this one).
_SLEWING_KEY = "slewing_ring"


@dataclass
class Iso281Life:
    """ISO 281 basic and modified rating life of the whole bearing over the cases (arrays (C,)).

    Attributes
    ----------
    load : MaskedArray [N]
        P = X F_r + Y F_a.
    load_rating : float or None [N]
        C of the bearing.
    rating_source : str or None
        ``"catalogue"`` (the designation's published C), ``"rating_C"`` / ``"rating_C0"`` (a maker's,
        ``[bearing] rating_C``), ``"given"`` (``load_ratings``) or ``"computed"`` (ISO 281 from the geometry).
    life, modified_life_n : MaskedArray [rev]
        L10 = (C/P)^p 10⁶ and L_nm = a1 a_ISO L10 (masked without lubrication inputs).
    life_modification : MaskedArray [-]
        a_ISO at P.
    note : str or None
        Why nothing (or only part) is given.
    static_load : MaskedArray [N] or None
        ISO 76 P0 = X0 F_r + Y0 F_a of the applied load (clauses 6.2-9.2), masked where ISO 76 has none.
    static_rating : float or None [N]
        C0 of the bearing (the catalogue's where it prints one; ``static_rating_source`` says which).
    static_safety : MaskedArray [-] or None
        ISO 76 clause 10: s0 = C0 / P0 (the catalogue method, beside the s0 from p_max of the rows).
    """

    load: np.ma.MaskedArray
    load_rating: float | None
    rating_source: str | None
    life: np.ma.MaskedArray
    life_modification: np.ma.MaskedArray
    modified_life: np.ma.MaskedArray
    note: str | None = None
    static_load: np.ma.MaskedArray | None = None
    static_rating: float | None = None
    static_rating_source: str | None = None
    static_safety: np.ma.MaskedArray | None = None


#: ISO rows per model row where one model row holds several (a four-point row: its two diagonals, each
#: rated as a single-row angular contact bearing, while ISO 281 and the catalogues rate the bearing as the
#: double-row angular contact bearing, i = 2).
ROWS_PER_MODEL_ROW = {"four_point": 2}


def catalogue_row_ratings(model, ratings, catalogue) -> dict:
    """C [N] per row derived from the catalogue C of the whole bearing, {} when there is none.

    The inverse of the combination :func:`bearing_life` uses: C_row = C / i^0.7 (ball) or C / i^(7/9)
    (roller), i the ISO rows (ISO 281:2007 eq. (2), (9)); only for the bearings that have an ISO 281 P
    (one row, or two equal rows; :func:`_law`). ISO/TS 16281 derives its raceway ratings from the
    bearing's C, so both methods then start from the same C.

    Parameters
    ----------
    model : BearingModel
    ratings : list of RowRating
        The rows rated once (their element kind and bearing type).
    catalogue : (float, float or None) or None
        The designation's published (C, C0) [N].
    """
    if catalogue is None or catalogue[0] is None or not ratings:
        return {}
    law = _law(model, ratings)
    if isinstance(law, str):
        return {}
    unit, _ = iso281.paired_unit_ratings(1.0, None, ratings[0].element, law[1])  # i^0.7 or i^(7/9)
    c_row = float(catalogue[0]) / float(unit)
    return {row.name: c_row for row in model.rows}


def catalogue_row_static_ratings(model, ratings, catalogue) -> dict:
    """C0 [N] per row from the catalogue C0 of the whole bearing, {} when there is none.

    ISO 76:2006 eq. (1), (3): C0 is linear in the number of rows i, so C0_row = C0 / i (the rows of
    :func:`catalogue_row_ratings`).
    """
    if catalogue is None or len(catalogue) < 2 or catalogue[1] is None or not ratings:
        return {}
    law = _law(model, ratings)
    if isinstance(law, str):
        return {}
    return {row.name: float(catalogue[1]) / law[1] for row in model.rows}


def _none(n: int, note: str) -> Iso281Life:
    empty = np.ma.masked_array(np.zeros(n), mask=np.ones(n, bool))
    return Iso281Life(empty, None, None, empty.copy(), empty.copy(), empty.copy(), note)


def _alpha(row) -> float:
    if row.kind == "tapered":
        return abs(float(row.contact_angle_outer))
    if row.kind == "cylindrical":
        return np.pi / 2 if row.orientation != "radial" else 0.0
    return float(np.max(np.abs(getattr(row, "contact_angle", 0.0))))


def _equal(a, b) -> bool:
    return bool(np.allclose(np.asarray(a, float), np.asarray(b, float), rtol=_SAME, atol=0.0))


def _direction(row):
    """Sign of the axial load a row carries: its contact angle (ball) or direction (tapered)."""
    if row.kind == "tapered":
        return np.sign(float(getattr(row, "direction", 1)))
    return np.sign(np.asarray(getattr(row, "contact_angle", 0.0), float))


def _law(model, ratings) -> tuple[str, int, float, int] | str:
    """(ISO 281 P law, rows i, nominal α [rad], rows of the X, Y) of the bearing, or why it has none."""
    rows = list(model.rows)
    kind = rows[0].kind
    if getattr(model, "metadata", {}).get(_SLEWING_KEY):
        return (
            "ISO 281 gives no X, Y for slewing rings (tilting moment): no ISO 281 basic rating life "
            "(see L10r)"
        )
    if kind in ("threaded", "crossed_roller") or len(rows) > 2:
        what = {"threaded": "planetary thread roller", "crossed_roller": "crossed roller"}.get(kind)
        what = what or f"{len(rows)}-row"
        return f"ISO 281 gives no X, Y for a {what} bearing: no ISO 281 basic rating life (see L10r)"
    alpha = _alpha(rows[0])
    if len(rows) == 2:
        a, b = rows
        same = a.kind == b.kind and all(
            _equal(getattr(a, k), getattr(b, k)) for k in ("element_diameter", "pitch_diameter", "n_elements")
        )
        signs = _direction(a) * _direction(b)
        # two equal radial cylindrical rows are a double-row bearing (NN): ISO 281 7.1 with i = 2, P = F_r;
        # other cylindrical pairs (thrust rows of two directions) have no ISO 281 X, Y
        radial_pair = kind == "cylindrical" and alpha == 0.0
        if not same or not _equal(_alpha(a), _alpha(b)) or (kind == "cylindrical" and not radial_pair):
            return (
                "ISO 281 gives no X, Y for this two-row composite (unequal rows, or rows ISO 281 does not "
                "rate as one bearing): no ISO 281 basic rating life (see L10r)"
            )
        if alpha > 0 and np.all(signs > 0) and kind in ("ball", "tapered"):
            arrangement = "DT"  # a tandem set: the single-row X, Y (ISO 281 paired mounting)
        elif alpha > 0 and np.any(signs > 0):
            return "ISO 281 gives no X, Y for rows of mixed directions: no ISO 281 basic rating life"
        else:
            arrangement = "DB"  # DB or DF: one double-row bearing
    n_rows = len(rows)
    xy_rows = iso281.PAIRED_UNIT_XY_ROWS[arrangement] if n_rows == 2 else n_rows
    if kind in ROWS_PER_MODEL_ROW:  # a four-point row: i = 2 rows and the double-row X, Y (ISO 281 Table 3)
        return life_kinds.KIND_LOAD_LAWS[kind][0], ROWS_PER_MODEL_ROW[kind], alpha, ROWS_PER_MODEL_ROW[kind]
    if kind == "spherical_roller" and n_rows == 1 and alpha > iso281.RADIAL_MAX_ANGLE:
        return "thrust_roller", 1, alpha, 1  # a spherical roller thrust bearing: ISO 281 8.2
    if kind in life_kinds.KIND_LOAD_LAWS:
        return life_kinds.KIND_LOAD_LAWS[kind][0], n_rows, alpha, xy_rows
    btype = ratings[0].bearing_type
    law = {
        "deep_groove_ball": "deep_groove_ball",
        "angular_contact_ball": "angular_contact_ball",
        "thrust_ball": "thrust_ball",
        "cylindrical_roller": "radial_roller",
        "tapered_roller": "radial_roller",
        "thrust_cylindrical_roller": "thrust_roller",
        "thrust_tapered_roller": "thrust_roller",
    }.get(btype)
    if law is None:
        return f"ISO 281 gives no X, Y for a {btype} bearing: no ISO 281 basic rating life (see L10r)"
    return law, n_rows, alpha, xy_rows


def _equivalent_load(fr, fa, p_law, alpha, n_rows, c0, f0, notes):
    """P (C,) [N] and the cases ISO 281 has no P for (e.g. F_r on a 90° thrust bearing), with a note."""
    law = dict(n_rows=n_rows, static_rating=c0, f0=f0)
    try:
        p = iso281_load.equivalent_dynamic_load(fr, fa, p_law, alpha, **law)
        return p, np.zeros(fr.shape, bool)
    except InputError:
        pass
    # Some cases have no P: the others in one batch (a 6209 study with 14 % of its cases below Table 3
    # took 0.9 s per 10^4 cases one by one), then each refused case alone, so that its note carries the
    # law's own message. A refusal the screen does not know sends every case through one by one.
    p, failed = np.zeros(fr.shape), np.zeros(fr.shape, bool)
    refused = iso281_load.refused_cases(fr, fa, p_law, alpha, static_rating=c0, f0=f0, n_rows=n_rows)
    ask = np.flatnonzero(refused)
    if ask.size < fr.shape[0]:
        try:
            p[~refused] = iso281_load.equivalent_dynamic_load(fr[~refused], fa[~refused], p_law, alpha, **law)
        except InputError:
            ask = np.arange(fr.shape[0])
    for c in ask:
        try:
            p[c] = iso281_load.equivalent_dynamic_load(fr[c], fa[c], p_law, alpha, **law)
        except InputError as exc:
            failed[c] = True
            notes.append(f"case {c}: no ISO 281 basic rating life: {exc}")
    return p, failed


def bearing_life(
    result, ratings, opts: RatingOptions, catalogue=None, geometry_static_rating=None
) -> Iso281Life:
    """ISO 281 P, C, L10 and L_nm of the whole bearing (module docstring).

    Parameters
    ----------
    result : QuasiStaticResult
        Its applied load (C, 5) gives F_r and F_a.
    ratings : list of RowRating
        The rows' ISO 281 C, ISO 76 C0 (rated as single-row bearings).
    opts : RatingOptions
    catalogue : (float, float or None), optional
        The designation's published (C, C0) [N]; replaces the computed ones.
    geometry_static_rating : float, optional
        C0 [N] of the first row from its geometry, when the rows' C0 were replaced by the catalogue's:
        the C0 the fatigue load limit C_u is estimated from (as without a catalogue C0).

    Returns
    -------
    Iso281Life
    """
    n = result.n_cases
    law = _law(result.model, ratings)
    if isinstance(law, str):
        return _none(n, law)
    p_law, n_rows, alpha, xy_rows = law
    row, rr = result.model.rows[0], ratings[0]
    element = rr.element
    c_row = np.ma.getdata(rr.load_rating)[0] if not np.ma.getmaskarray(rr.load_rating)[0] else None
    c0_row = np.ma.getdata(rr.static_rating)[0] if not np.ma.getmaskarray(rr.static_rating)[0] else None
    source = "given" if rr.name in opts.load_ratings else "computed"
    c = c0 = None
    if c_row is not None:  # i rows of one bearing or a paired unit: the same i^0.7 / i^(7/9) law
        c, c0 = (
            None if x is None else float(x)
            for x in iso281.paired_unit_ratings(c_row, c0_row, element, n_rows)
        )
    elif c0_row is not None:
        c0 = float(c0_row) * n_rows
    c0_cu = c0 if geometry_static_rating is None else float(geometry_static_rating) * n_rows
    c0_source = None if c0 is None else "computed"
    if catalogue is not None and catalogue[0] is not None:
        # (C's source, C0's source): "rating_C"/"rating_C0" a maker's, given; else the catalogue's
        sources = catalogue[2] if len(catalogue) > 2 else ("catalogue", "catalogue")
        c, source = float(catalogue[0]), sources[0]
        if catalogue[1] is not None:
            c0, c0_source = float(catalogue[1]), sources[1]
    if c is None:
        return _none(
            n, "ISO 281 basic rating life not computed: the bearing has no ISO 281 C (see the row notes)"
        )

    load = np.asarray(result.load, float)
    fr, fa = np.hypot(load[:, 0], load[:, 1]), np.abs(load[:, 2])
    scale = np.maximum(fr, fa)
    # a fixed DOF's reaction carries the solver's round-off (1e-16 N of F_r on a thrust bearing)
    fr = np.where(fr <= _ROUND_OFF * scale, 0.0, fr)
    fa = np.where(fa <= _ROUND_OFF * scale, 0.0, fa)
    notes = []
    tilt_free = np.asarray(getattr(result, "free", np.zeros(5, bool)), bool)[3:]
    moment = np.any(np.abs(load[:, 3:][:, tilt_free]) > 0, axis=1)  # a held tilt's reaction is no load
    if moment.any():
        cases = ", ".join(str(c) for c in np.flatnonzero(moment))
        notes.append(f"ISO 281 P takes F_r and F_a only: the tilting moment of case(s) {cases} is not in P")
    f0 = None
    if p_law == "deep_groove_ball" or (p_law == "angular_contact_ball" and alpha < _XY_CONSTANT_FROM):
        # ISO 281 Table 3 reads e, X, Y at i f0 F_a/C0r here; f0 of ISO 76 at γ = D_w cos α / d_m
        gamma = float(np.max(row.element_diameter)) * np.cos(alpha) / float(np.max(row.pitch_diameter))
        f0 = iso76.f0_radial_ball(gamma)
    p, failed = _equivalent_load(fr, fa, p_law, alpha, xy_rows, c0, f0, notes)
    if p_law == "deep_groove_ball" and c0 is not None and f0 is not None:
        bound = iso281_load.below_table_radial(fr, fa, c0, f0, xy_rows) & ~failed
        if bound.any():
            cases = ", ".join(str(c) for c in np.flatnonzero(bound))
            x0, e0 = iso281_load.radial_first_row()
            notes.append(
                f"case(s) {cases}: f0 F_a/C0r below ISO 281 Table 3's first row ({x0:g}): P = F_r, since "
                f"F_r >= ({x0:g}/{e0:g}) C0r/f0 = {x0 / e0 * c0 / f0:.4g} N puts F_a/F_r under "
                f"e >= {e0:g} x/{x0:g}, the chord bound of e (e/x falls along the table; X = 1, Y = 0; "
                "docs/ratings.md)"
            )
    if failed.all():
        return _none(n, "; ".join(notes))
    mask = ~np.asarray(result.converged, bool) | ~(p > 0) | failed
    p_safe = np.where(mask, c, p)
    life = iso281_life.basic_rating_life(c, p_safe, element)
    a_iso = np.ma.masked_array(np.ones(n), mask=np.ones(n, bool))
    if opts.modified and c0_cu is not None:
        from bearingkit.lubricants import as_lubricant

        dm = float(np.max(row.pitch_diameter))
        nu = as_lubricant(opts.lubricant).kinematic_viscosity(opts.temperature_C)
        kappa = iso281.viscosity_ratio(nu, opts.speed, dm) * np.ones(n)
        low = kappa < iso281_life.KAPPA_MIN
        cu = iso281.fatigue_load_limit_estimate(c0_cu, dm, element)
        thrust = p_law.startswith("thrust")
        aiso_kind = ("thrust_" if thrust else "radial_") + element
        a = iso281.life_modification_factor(
            np.maximum(kappa, iso281_life.KAPPA_MIN), opts.contamination_factor, cu, p_safe, aiso_kind
        )
        a_iso = np.ma.masked_array(a, mask=mask | low)
    a1 = float(iso281.reliability_factor(opts.reliability))
    life_m = np.ma.masked_array(life, mask=mask)
    p0, s0 = _static(fr, fa, p_law, alpha, xy_rows, c0, ~np.asarray(result.converged, bool), notes)
    return Iso281Life(
        load=np.ma.masked_array(np.where(mask, 0.0, p), mask=mask),
        load_rating=c,
        rating_source=source,
        life=life_m,
        life_modification=a_iso,
        modified_life=a1 * a_iso * life_m,
        note="; ".join(notes) or None,
        static_load=p0,
        static_rating=c0,
        static_rating_source=c0_source,
        static_safety=s0,
    )


def _static(fr, fa, law, alpha, rows, c0, unsolved, notes):
    """ISO 76 P0 (C,) [N] and s0 = C0/P0 (C,) [-], masked where ISO 76 gives no P0, P0 = 0 or no C0.

    P0 by :func:`bearingkit.physics.life.iso76.equivalent_static_load` with the law and rows of the ISO
    281 P (ISO 76:2006 6.2-9.2; the double-row X0, Y0 for two rows, a four-point bearing, a DB/DF pair).
    """
    n = fr.shape[0]
    p0 = np.zeros(n)
    failed = np.array(unsolved, bool)
    try:
        p0 = np.asarray(iso76.equivalent_static_load(fr, fa, law, alpha, n_rows=rows), float) * np.ones(n)
    except InputError:
        for c in range(n):
            try:
                p0[c] = float(iso76.equivalent_static_load(fr[c], fa[c], law, alpha, n_rows=rows))
            except InputError as exc:
                failed[c] = True
                notes.append(f"case {c}: no ISO 76 static safety: {exc}")
    mask = failed | ~(p0 > 0)
    p0_m = np.ma.masked_array(np.where(mask, 0.0, p0), mask=mask)
    if c0 is None:
        return p0_m, np.ma.masked_array(np.zeros(n), mask=np.ones(n, bool))
    s0 = np.ma.masked_array(c0 / np.where(mask, 1.0, p0), mask=mask)
    return p0_m, s0


def _fmt(x, scale: float = 1.0) -> str:
    return "—" if x is None else format(x * scale, ".4g")


def caption(system: dict) -> str | None:
    """One line of the ISO 281 basic rating life from a case's ``system`` dict (CLI table and HTML report
    show the same text): ``ISO 281: P = … kN, C = … kN (catalogue|computed|given), L10 = … 10⁶ rev,
    L10h = … h[, a_ISO = …, L_nm = … 10⁶ rev, L_nmh = … h]``; the note when there is none; None for a dict
    without the keys."""
    if "C_iso281_N" not in system:
        return None
    note = system.get("iso281_note")
    if system["C_iso281_N"] is None:
        return f"ISO 281: {note}" if note else "ISO 281: no basic rating life"
    text = (
        f"ISO 281: P = {_fmt(system['P_iso281_N'], 1e-3)} kN, C = {_fmt(system['C_iso281_N'], 1e-3)} kN "
        f"({system['C_source']}), L10 = {_fmt(system['L10_iso281_rev'], 1e-6)} 10⁶ rev, "
        f"L10h = {_fmt(system['L10h_iso281_h'])} h"
    )
    if system.get("Lnm_iso281_rev") is not None:
        text += (
            f", a_ISO = {_fmt(system['a_ISO_iso281'])}, L_nm = {_fmt(system['Lnm_iso281_rev'], 1e-6)} 10⁶ rev"
        )
        if system.get("Lnm_iso281_h") is not None:
            text += f", L_nmh = {_fmt(system['Lnm_iso281_h'])} h"
    text += f" ({note})" if note else ""
    if system.get("C0_iso76_N") is not None:
        text += (
            f"; ISO 76: P0 = {_fmt(system.get('P0_iso76_N'), 1e-3)} kN, C0 = "
            f"{_fmt(system['C0_iso76_N'], 1e-3)} kN ({system['C0_source']}), "
            f"s0 = {_fmt(system.get('s0_iso76'))}"
        )
    return text
