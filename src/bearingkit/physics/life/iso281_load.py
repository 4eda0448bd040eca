"""ISO 281:2007 equivalent dynamic load P = X F_r + Y F_a of radial, angular and thrust bearings.

SI units: loads in N, angles in rad. ISO 281:2007 clauses 5.2 (ball) and 6.2 (roller), Tables 3 and 4
(X, Y, e); the tables ship as CSV files in ``bearingkit/data`` (:mod:`bearingkit.physics.tables`).
The basic ratings are in :mod:`bearingkit.physics.life.iso281`.
"""

from __future__ import annotations

import functools

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics import tables
from bearingkit.physics.life.iso281 import RADIAL_MAX_ANGLE, _is_90

_XY_RADIAL = "iso281_xy_radial_ball.csv"
_XY_ANGULAR = "iso281_xy_angular_ball.csv"
#: ISO 281:2007 Table 3, angular contact α = 5°, 10°, 15°: e, X, Y over the relative axial load i f0 Fa/C0r.
_XY_ANGULAR_LOW = "iso281_xy_angular_ball_low.csv"
#: Contact angle [deg] from which Table 3's angular contact rows no longer depend on i f0 Fa/C0r (20° … 45°).
ANGULAR_CONSTANT_FROM_DEG = 20.0
#: Smallest contact angle [deg] of Table 3's angular contact rows.
ANGULAR_MIN_DEG = 5.0
#: ISO 281:2007 Table 3: X of radial contact groove ball bearings for Fa/Fr > e (single, double row).
X_DEEP_GROOVE_SINGLE = 0.56
X_DEEP_GROOVE_DOUBLE = 0.78
#: Thrust ball bearings, single direction, ISO 281:2007 Table 6 [M]: α [deg], e, X (Fa/Fr > e), Y = 1.
_THRUST_BALL_XE = np.array([[45.0, 1.25, 0.66], [60.0, 2.17, 0.92], [75.0, 4.67, 1.66]])
#: ISO 281:2007 7.2 / 8.2: e = 1.5 tan α for radial and thrust roller bearings (and self-aligning ball).
E_TAN_FACTOR = 1.5


def _ratio(fr, fa):
    # Fa/Fr with Fr = 0 treated as an infinite ratio
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(fr > 0, fa / np.where(fr > 0, fr, 1.0), np.inf)


def radial_first_row() -> tuple[float, float]:
    """(x₀, e₀): f0 F_a/C0r and e of ISO 281:2007 Table 3's first row, radial contact groove ball bearings."""
    return float(tables.column(_XY_RADIAL, "f0_fa_c0r")[0]), float(tables.column(_XY_RADIAL, "e")[0])


def below_table_radial(load_radial, load_axial, static_rating, f0, n_rows=1):
    """Cases of a deep groove ball bearing below ISO 281 Table 3's first row that still have P = F_r.

    Table 3 starts at f0 F_a/C0r = x₀ = 0.172 (e₀ = 0.19); a small axial load beside a radial one (the
    two locating bearings of a planet, a locating bearing of spur gearing) lies below it. Along the whole
    table e grows slower than x (e/x falls from row to row: e ∝ x^0.23 from first to last row); with e/x
    still falling below x₀ (the one assumption), e lies above its chord to the origin there,
    e(x) >= e₀ x/x₀. So F_a/F_r <= e₀ x/x₀ implies F_a/F_r <= e, where
    the standard gives X = 1, Y = 0 (single row): P = F_r. With x = f0 F_a/C0r the condition no longer
    depends on F_a:

    .. math:: F_r \\ge \\frac{x_0}{e_0} \\frac{C_{0r}}{f_0} = F_{r,\\min}

    Below x₀ with a smaller F_r (Y unknown) or a double-row bearing (Y of F_a/F_r <= e unknown) ISO 281
    gives no P. ISO 281:2007 5.2.2, Table 3 (the bound: bearingkit, docs/ratings.md).

    Parameters
    ----------
    load_radial, load_axial : array_like
        F_r, F_a [N].
    static_rating : array_like
        C0r [N].
    f0 : array_like
        ISO 76 factor f0 [MPa].
    n_rows : int
        1 (the bound) or 2 (never: False everywhere).

    Returns
    -------
    numpy.ndarray of bool
        True where 0 < f0 F_a/C0r < x₀ and P = F_r follows from the bound.
    """
    fr, fa = np.broadcast_arrays(np.asarray(load_radial, float), np.asarray(load_axial, float))
    x = tables.column(_XY_RADIAL, "f0_fa_c0r")
    x0, e0 = radial_first_row()
    c0, f0 = np.asarray(static_rating, float), np.asarray(f0, float)
    rel = f0 * fa / c0
    below = (fa > 0) & (rel < x0) & tables.outside(rel, x)
    return below & (n_rows == 1) & (fr >= x0 / e0 * c0 / f0)


def _p_deep_groove(fr, fa, alpha, n_rows, static_rating, f0):
    if static_rating is None or f0 is None:
        raise InputError(
            "static_rating and f0 must be given for bearing_type 'deep_groove_ball' (ISO 281 Table 3)"
        )
    checks.positive("static_rating", static_rating, "N")
    checks.positive("f0", f0, "MPa")
    t = _XY_RADIAL
    rel = np.asarray(f0, float) * fa / np.asarray(static_rating, float)
    x = tables.column(t, "f0_fa_c0r")
    bound = below_table_radial(fr, fa, static_rating, f0, n_rows)  # P = F_r below Table 3
    has_axial = (fa > 0) & ~bound
    rel_in = np.where(has_axial, rel, x[0])

    def col(name):
        return tables.interp_strict("relative_axial_load_f0_Fa_C0r", rel_in, x, tables.column(t, name))

    small = _ratio(fr, fa) <= col("e")
    if n_rows == 1:
        p = np.where(small, fr, X_DEEP_GROOVE_SINGLE * fr + col("y_single_gt") * fa)
    else:
        p = np.where(small, fr + col("y_double_le") * fa, X_DEEP_GROOVE_DOUBLE * fr + col("y_double_gt") * fa)
    return np.where(has_axial, p, fr)


@functools.cache
def _low_blocks():
    """Table 3's α = 5°, 10°, 15° blocks and the 20° row as a block: [(α [deg], {column: (grid, values)})].

    The 20° row does not depend on the relative axial load; it enters as a constant block so that
    α between 15° and 20° interpolates linearly in α, as Table 3's footnote asks for intermediate angles."""
    t, a = _XY_ANGULAR_LOW, tables.column(_XY_ANGULAR_LOW, "alpha_deg")
    rel = tables.column(t, "i_f0_fa_c0r")
    blocks = []
    for deg in np.unique(a):
        rows = a == deg
        cols = {name: (rel[rows], tables.column(t, name)[rows]) for name in _LOW_COLUMNS}
        blocks.append((float(deg), cols))
    at20 = tables.column(_XY_ANGULAR, "alpha_deg") == ANGULAR_CONSTANT_FROM_DEG
    whole = np.array([0.0, 1e300])  # any relative axial load
    row20 = {name: tables.column(_XY_ANGULAR, src)[at20] for name, src in _AT20.items()}
    const = {name: (whole, np.repeat(value, 2)) for name, value in row20.items()}
    blocks.append((ANGULAR_CONSTANT_FROM_DEG, const))
    return blocks


#: Columns of the low-angle table; the 20° row's columns that stand for them (single and double row share e).
_LOW_COLUMNS = (
    "e_single", "x_single_gt", "y_single_gt", "e_double", "y_double_le", "x_double_gt", "y_double_gt"
)  # fmt: skip
_AT20 = {
    "e_single": "e",
    "x_single_gt": "x_single_gt",
    "y_single_gt": "y_single_gt",
    "e_double": "e",
    "y_double_le": "y_double_le",
    "x_double_gt": "x_double_gt",
    "y_double_gt": "y_double_gt",
}


#: Weight below which a block does not count (radians → degrees round-off at a tabulated angle).
_SNAP = 1e-9


def _low_weights(deg):
    """Hat-function weights (blocks, cases) of the blocks of :func:`_low_blocks` at α [deg] (5° ≤ α ≤ 20°)."""
    nodes = np.array([b[0] for b in _low_blocks()])
    eye = np.eye(nodes.size)
    w = np.array([np.interp(deg, nodes, eye[k]) for k in range(nodes.size)])
    # an angle given in rad lands 1e-15 beside a tabulated one: that is the tabulated angle, one block
    w = np.where(w < _SNAP, 0.0, w)
    return w / np.sum(w, axis=0)


def _low_outside(rel, deg):
    """Cases whose relative axial load i f0 Fa/C0r lies outside the grid of a block α interpolates from."""
    out = np.zeros(np.broadcast(rel, deg).shape, bool)
    for w, (_, cols) in zip(_low_weights(deg), _low_blocks(), strict=True):
        grid = cols["e_single"][0]
        out |= (w > 0) & tables.outside(rel, grid)
    return out


def _low_column(name, rel, deg):
    """Table 3 column ``name`` at (i f0 Fa/C0r, α): linear in each block's own grid, then linear in α."""
    value = np.zeros(np.broadcast(rel, deg).shape)
    for w, (_, cols) in zip(_low_weights(deg), _low_blocks(), strict=True):
        grid, values = cols[name]
        value = value + w * np.interp(rel, grid, values)
    return value


def relative_axial_load(load_axial, static_rating, f0, n_rows=1):
    """ISO 281:2007 Table 3 relative axial load i f0 Fa/C0r [-] (f0 in MPa as ISO 76 tabulates it).

    Parameters
    ----------
    load_axial : array_like
        Fa [N].
    static_rating : float
        C0r [N] of the bearing (of the unit for a paired set).
    f0 : float
        ISO 76 factor f0 [MPa].
    n_rows : int
        i, the rows whose X, Y apply (2 for a double-row bearing or a DB/DF pair).
    """
    return n_rows * np.asarray(f0, float) * np.asarray(load_axial, float) / np.asarray(static_rating, float)


def _p_angular(fr, fa, alpha, n_rows, static_rating, f0):
    deg = np.round(np.degrees(alpha), 9)  # an angle given in rad: 5° is 4.999999999999999° (round-off)
    checks.in_range("contact_angle", deg, ANGULAR_MIN_DEG, 45.0, "deg")
    low = deg < ANGULAR_CONSTANT_FROM_DEG
    p = _p_angular_constant(fr, fa, np.where(low, ANGULAR_CONSTANT_FROM_DEG, deg), n_rows)
    if np.any(low):
        p_low = _p_angular_low(fr, fa, np.where(low, deg, ANGULAR_MIN_DEG), n_rows, static_rating, f0, low)
        p = np.where(low, p_low, p)
    return p


def _p_angular_constant(fr, fa, deg, n_rows):
    # ISO 281:2007 Table 3, α = 20° … 45°: e, X, Y independent of the relative axial load
    t = _XY_ANGULAR
    a = tables.column(t, "alpha_deg")

    def col(name):
        return tables.interp_strict("contact_angle", deg, a, tables.column(t, name), "deg")

    small = _ratio(fr, fa) <= col("e")
    if n_rows == 1:
        return np.where(small, fr, col("x_single_gt") * fr + col("y_single_gt") * fa)
    return np.where(small, fr + col("y_double_le") * fa, col("x_double_gt") * fr + col("y_double_gt") * fa)


def _p_angular_low(fr, fa, deg, n_rows, static_rating, f0, low):
    # ISO 281:2007 Table 3, α < 20°: e, X, Y depend on i f0 Fa/C0r (5°, 10°, 15° blocks, 20° constant)
    has_axial = fa > 0
    if not np.any(low & has_axial):
        return fr  # no axial load: P = Fr (X = 1, Y = 0 at any relative axial load)
    if static_rating is None or f0 is None:
        raise InputError(
            "static_rating and f0 must be given for bearing_type 'angular_contact_ball' with a contact angle "
            "below 20 deg (ISO 281 Table 3: e, X, Y depend on i f0 Fa/C0r)"
        )
    checks.positive("static_rating", static_rating, "N")
    checks.positive("f0", f0, "MPa")
    rel = relative_axial_load(fa, static_rating, f0, n_rows)
    bad = low & has_axial & _low_outside(rel, deg)
    if np.any(bad):
        k = np.flatnonzero(np.ravel(bad))[0]
        r, d = np.ravel(np.broadcast_to(rel, bad.shape))[k], np.ravel(np.broadcast_to(deg, bad.shape))[k]
        lo, hi = _low_range(d)
        raise InputError(
            f"relative axial load i*f0*Fa/C0r ({r:.4g}) must lie in the table range [{lo:g}, {hi:g}] of "
            f"ISO 281 Table 3 at contact angle {d:.4g} deg (an angular contact bearing below 20 deg)"
        )
    # no axial load: P = Fr whatever the column; evaluate at a grid point
    rel = np.where(has_axial, rel, 1.0)

    def col(name):
        return _low_column(name, rel, deg)

    if n_rows == 1:
        small = _ratio(fr, fa) <= col("e_single")
        p = np.where(small, fr, col("x_single_gt") * fr + col("y_single_gt") * fa)
    else:
        small = _ratio(fr, fa) <= col("e_double")
        p = np.where(small, fr + col("y_double_le") * fa, col("x_double_gt") * fr + col("y_double_gt") * fa)
    return np.where(has_axial, p, fr)


def _low_range(deg: float) -> tuple[float, float]:
    """The i f0 Fa/C0r range Table 3 covers at α [deg] < 20° (the common part of the blocks it uses)."""
    lo, hi = 0.0, np.inf
    for w, (_, cols) in zip(_low_weights(deg), _low_blocks(), strict=True):
        if w > 0:
            grid = cols["e_single"][0]
            lo, hi = max(lo, grid[0]), min(hi, grid[-1])
    return float(lo), float(hi)


def _p_self_aligning(fr, fa, alpha, n_rows, static_rating, f0):
    # ISO 281:2007 Table 3, self-aligning ball bearings (double row): e = 1.5 tan α [M]
    checks.positive("contact_angle", alpha, "rad")
    cot = 1.0 / np.tan(alpha)
    small = _ratio(fr, fa) <= E_TAN_FACTOR * np.tan(alpha)
    return np.where(small, fr + 0.42 * cot * fa, 0.65 * fr + 0.65 * cot * fa)


def _p_radial_roller(fr, fa, alpha, n_rows, static_rating, f0):
    zero = alpha == 0.0
    if np.any(zero & (fa > 0)):
        raise InputError(
            "load_axial must be 0 for a radial roller bearing with contact_angle 0 (ISO 281 7.2.2)"
        )
    a = np.where(zero, np.pi / 4, alpha)
    cot = 1.0 / np.tan(a)
    small = _ratio(fr, fa) <= E_TAN_FACTOR * np.tan(a)
    if n_rows == 1:
        p = np.where(small, fr, 0.4 * fr + 0.4 * cot * fa)
    else:
        p = np.where(small, fr + 0.45 * cot * fa, 0.67 * fr + 0.67 * cot * fa)
    return np.where(zero, fr, p)


def _thrust_e(alpha, ball: bool):
    # e of a single-direction thrust bearing: ball, ISO 281:2007 Table 6; roller, 1.5 tan α (8.2)
    if ball:
        return np.interp(np.degrees(alpha), _THRUST_BALL_XE[:, 0], _THRUST_BALL_XE[:, 1])
    return E_TAN_FACTOR * np.tan(alpha)


def _p_thrust(fr, fa, alpha, ball: bool):
    if np.any(alpha <= RADIAL_MAX_ANGLE):
        raise InputError(f"contact_angle ({checks._fmt(alpha)} rad) must exceed pi/4 for a thrust bearing")
    is_90 = _is_90(alpha)
    if np.any(is_90 & (fr > 0)):
        raise InputError(
            "load_radial must be 0 for a thrust bearing with contact_angle pi/2 (ISO 281 6.2, 8.2)"
        )
    a = np.where(is_90, np.pi / 3, alpha)
    e = _thrust_e(a, ball)
    if ball:
        deg = np.where(is_90, 60.0, np.degrees(a))
        checks.in_range("contact_angle", deg, 45.0, 75.0, "deg")
        x = np.interp(deg, _THRUST_BALL_XE[:, 0], _THRUST_BALL_XE[:, 2])
    else:
        x = np.tan(a)
    if np.any(~is_90 & (_ratio(fr, fa) <= e)):
        raise InputError(
            "load_axial/load_radial must exceed e for a single-direction thrust bearing with "
            "contact_angle < pi/2 (ISO 281 6.2, 8.2)"
        )
    return np.where(is_90, fa, x * fr + fa)


#: Equivalent dynamic load laws by bearing type (ISO 281:2007 5.2, 6.2, 7.2, 8.2).
P_MODELS = {
    "deep_groove_ball": _p_deep_groove,
    "angular_contact_ball": _p_angular,
    "self_aligning_ball": _p_self_aligning,
    "radial_roller": _p_radial_roller,
    "thrust_ball": lambda fr, fa, a, n, c0, f0: _p_thrust(fr, fa, a, True),
    "thrust_roller": lambda fr, fa, a, n, c0, f0: _p_thrust(fr, fa, a, False),
}


def refused_cases(
    load_radial, load_axial, bearing_type, contact_angle=0.0, static_rating=None, f0=None, n_rows=1
):
    """Cases whose loads :func:`equivalent_dynamic_load` refuses one by one (True: no P), in one pass.

    The refusals that depend on a case's loads, not on the bearing (ISO 281:2007 5.2, 6.2, 7.2, 8.2):

    - ``deep_groove_ball``: f0 Fa/C0r with Fa > 0 outside Table 3 (0.172 … 6.89), except below it
      where :func:`below_table_radial` gives P = F_r;
    - ``angular_contact_ball`` below 20°: i f0 Fa/C0r with Fa > 0 outside Table 3's grid of the angle
      (5°: 0.173 … 6.92, 10°: 0.175 … 7.00, 15°: 0.178 … 7.14; between two angles the common part);
    - ``radial_roller`` with α = 0: Fa > 0;
    - ``thrust_ball``/``thrust_roller``: Fr > 0 at α = 90°, and Fa/Fr <= e below 90° (single direction).

    A screen for batches: the cases it clears are computed together. Refusals of the bearing itself
    (a missing C0r, a contact angle outside a table) are not screened; the law still raises on them.

    Parameters
    ----------
    load_radial, load_axial : array_like
        Fr, Fa [N], >= 0.
    bearing_type : str
        One of :data:`P_MODELS`.
    contact_angle : float
        α [rad].
    static_rating : float, optional
        C0r [N] (deep groove ball bearings; angular contact below 20°).
    f0 : float, optional
        f0 [MPa] of ISO 76 (deep groove ball bearings; angular contact below 20°).
    n_rows : int
        i of the X, Y (angular contact below 20°: i f0 Fa/C0r).

    Returns
    -------
    numpy.ndarray of bool
        The shape of the broadcast loads.
    """
    fr, fa = np.broadcast_arrays(np.asarray(load_radial, float), np.asarray(load_axial, float))
    alpha = float(contact_angle)
    rated = static_rating is not None and f0 is not None and float(static_rating) > 0 and float(f0) > 0
    if bearing_type == "deep_groove_ball":
        if not rated:
            return np.zeros(fr.shape, bool)  # the law refuses the bearing itself: nothing to screen
        rel = float(f0) * fa / float(static_rating)
        outside = (fa > 0) & tables.outside(rel, tables.column(_XY_RADIAL, "f0_fa_c0r"))
        return outside & ~below_table_radial(fr, fa, static_rating, f0, n_rows)
    if bearing_type == "angular_contact_ball":
        deg = np.degrees(alpha)
        if not rated or not ANGULAR_MIN_DEG <= deg < ANGULAR_CONSTANT_FROM_DEG:
            return np.zeros(fr.shape, bool)
        rel = relative_axial_load(fa, float(static_rating), float(f0), n_rows)
        return (fa > 0) & _low_outside(rel, np.full(fr.shape, deg))
    if bearing_type == "radial_roller" and alpha == 0.0:
        return fa > 0
    if bearing_type.startswith("thrust") and alpha > RADIAL_MAX_ANGLE:
        if _is_90(alpha):
            return fr > 0
        return _ratio(fr, fa) <= _thrust_e(alpha, bearing_type == "thrust_ball")
    return np.zeros(fr.shape, bool)


def equivalent_dynamic_load(
    load_radial, load_axial, bearing_type, contact_angle=0.0, n_rows=1, static_rating=None, f0=None
):
    """Dynamic equivalent load P [N], ISO 281:2007 clauses 5.2, 6.2, 7.2 and 8.2.

    .. math:: P = X F_r + Y F_a

    - ``deep_groove_ball``: e, Y from Table 3 as functions of f0 Fa/C0r (0.172 … 6.89; outside → error,
      except below 0.172 with F_r >= (0.172/0.19) C0r/f0, single row: P = F_r, :func:`below_table_radial`);
      Fa/Fr <= e: X = 1, Y = 0 (single row) or Y from the double-row column; Fa/Fr > e: X = 0.56 single
      row, 0.78 double row.
    - ``angular_contact_ball``: Table 3, α = 5° … 45°. From 20° the rows do not depend on the load (linear
      interpolation in α). Below 20° (the spindle bearings' 15°) e, X, Y are functions of the relative
      axial load i f0 Fa/C0r (:func:`relative_axial_load`; i = ``n_rows``, C0r the bearing's): linear
      interpolation in the grid of the 5°, 10°, 15° blocks, then in α (between 15° and 20° towards the
      20° row); outside the grid (5°: 0.173 … 6.92, 10°: 0.175 … 7.00, 15°: 0.178 … 7.14) an error — the
      standard gives no value there. Single row at 5°: the radial contact rows (ISO's note).
    - ``self_aligning_ball``: e = 1.5 tan α; X = 1, Y = 0.42 cot α or X = 0.65, Y = 0.65 cot α.
    - ``radial_roller``: α = 0 → P = Fr (Fa must be 0); else e = 1.5 tan α, single row X = 0.4,
      Y = 0.4 cot α above e; double row X = 1, Y = 0.45 cot α / X = 0.67, Y = 0.67 cot α.
    - ``thrust_ball``/``thrust_roller``: α = 90° → P = Fa (Fr must be 0); else single direction with
      Fa/Fr > e: P = X Fr + Fa (ball X, e from Table 6 at 45°, 60°, 75°; roller X = tan α, e = 1.5 tan α).

    Parameters
    ----------
    load_radial, load_axial : array_like
        Fr, Fa [N], >= 0.
    bearing_type : str
        One of :data:`P_MODELS`.
    contact_angle : array_like
        α [rad].
    n_rows : int
        1 or 2.
    static_rating : array_like, optional
        C0r [N] (deep groove ball bearings; angular contact below 20°).
    f0 : array_like, optional
        f0 [MPa] of ISO 76 (deep groove ball bearings; angular contact below 20°).

    Returns
    -------
    numpy.ndarray
        P [N].
    """
    checks.one_of("bearing_type", bearing_type, P_MODELS)
    checks.non_negative("load_radial", load_radial, "N")
    checks.non_negative("load_axial", load_axial, "N")
    limit = np.pi / 2 if bearing_type.startswith("thrust") else RADIAL_MAX_ANGLE
    checks.in_range("contact_angle", contact_angle, 0.0, limit, "rad")
    n_rows = checks.integer("n_rows", n_rows)
    if n_rows > 2:
        raise InputError(f"n_rows ({n_rows}) must be 1 or 2 for ISO 281 equivalent dynamic load")
    fr, fa, alpha = np.broadcast_arrays(
        np.asarray(load_radial, float), np.asarray(load_axial, float), np.asarray(contact_angle, float)
    )
    return np.asarray(P_MODELS[bearing_type](fr, fa, alpha, n_rows, static_rating, f0), dtype=float)
