"""ISO 281:2007 equivalent dynamic load P = X F_r + Y F_a of radial, angular and thrust bearings.

SI units: loads in N, angles in rad. ISO 281:2007 clauses 5.2 (ball) and 6.2 (roller), Tables 3 and 4
(X, Y, e); the tables ship as CSV files in ``bearingkit/data`` (:mod:`bearingkit.physics.tables`).
The basic ratings are in :mod:`bearingkit.physics.life.iso281`.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics import tables
from bearingkit.physics.life.iso281 import RADIAL_MAX_ANGLE, _is_90

_XY_RADIAL = "iso281_xy_radial_ball.csv"
_XY_ANGULAR = "iso281_xy_angular_ball.csv"
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


def _p_deep_groove(fr, fa, alpha, n_rows, static_rating, f0):
    if static_rating is None or f0 is None:
        raise InputError(
            "static_rating and f0 must be given for bearing_type 'deep_groove_ball' (ISO 281 Table 3)"
        )
    checks.positive("static_rating", static_rating, "N")
    checks.positive("f0", f0, "MPa")
    t = _XY_RADIAL
    rel = np.asarray(f0, float) * fa / np.asarray(static_rating, float)
    has_axial = fa > 0
    x = tables.column(t, "f0_fa_c0r")
    rel_in = np.where(has_axial, rel, x[0])

    def col(name):
        return tables.interp_strict("relative_axial_load_f0_Fa_C0r", rel_in, x, tables.column(t, name))

    small = _ratio(fr, fa) <= col("e")
    if n_rows == 1:
        p = np.where(small, fr, X_DEEP_GROOVE_SINGLE * fr + col("y_single_gt") * fa)
    else:
        p = np.where(small, fr + col("y_double_le") * fa, X_DEEP_GROOVE_DOUBLE * fr + col("y_double_gt") * fa)
    return np.where(has_axial, p, fr)


def _p_angular(fr, fa, alpha, n_rows, static_rating, f0):
    t = _XY_ANGULAR
    deg = np.degrees(alpha)
    a = tables.column(t, "alpha_deg")

    def col(name):
        return tables.interp_strict("contact_angle", deg, a, tables.column(t, name), "deg")

    small = _ratio(fr, fa) <= col("e")
    if n_rows == 1:
        return np.where(small, fr, col("x_single_gt") * fr + col("y_single_gt") * fa)
    return np.where(small, fr + col("y_double_le") * fa, col("x_double_gt") * fr + col("y_double_gt") * fa)


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


def refused_cases(load_radial, load_axial, bearing_type, contact_angle=0.0, static_rating=None, f0=None):
    """Cases whose loads :func:`equivalent_dynamic_load` refuses one by one (True: no P), in one pass.

    The refusals that depend on a case's loads, not on the bearing (ISO 281:2007 5.2, 6.2, 7.2, 8.2):

    - ``deep_groove_ball``: f0 Fa/C0r with Fa > 0 outside Table 3 (0.172 … 6.89);
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
        C0r [N] (deep groove ball bearings).
    f0 : float, optional
        f0 [MPa] of ISO 76 (deep groove ball bearings).

    Returns
    -------
    numpy.ndarray of bool
        The shape of the broadcast loads.
    """
    fr, fa = np.broadcast_arrays(np.asarray(load_radial, float), np.asarray(load_axial, float))
    alpha = float(contact_angle)
    if bearing_type == "deep_groove_ball":
        if static_rating is None or f0 is None or not (float(static_rating) > 0 and float(f0) > 0):
            return np.zeros(fr.shape, bool)  # the law refuses the bearing itself: nothing to screen
        rel = float(f0) * fa / float(static_rating)
        return (fa > 0) & tables.outside(rel, tables.column(_XY_RADIAL, "f0_fa_c0r"))
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

    - ``deep_groove_ball``: e, Y from Table 3 as functions of f0 Fa/C0r (0.172 … 6.89; outside → error);
      Fa/Fr <= e: X = 1, Y = 0 (single row) or Y from the double-row column; Fa/Fr > e: X = 0.56 single
      row, 0.78 double row.
    - ``angular_contact_ball``: Table 3 rows α = 20° … 45°, linear interpolation in α.
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
        C0r [N] (deep groove ball bearings).
    f0 : array_like, optional
        f0 [MPa] of ISO 76 (deep groove ball bearings).

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
