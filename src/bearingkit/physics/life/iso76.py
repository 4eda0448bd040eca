"""ISO 76:2006 static load ratings, equivalent static load and static safety.

All inputs and outputs are SI (m, N, Pa, rad). ISO 76 writes its formulas in N and mm with the factors
f0, 44 and 220 in N/mm² (= MPa); here every length is converted to mm at the function boundary — or,
equivalently, the factors are taken in Pa and lengths in m, which is what the code does
(f0 [MPa] · 1e6 = f0 [Pa]; C0 [N] = f0 [Pa] · Dw² [m²]). Table look-ups interpolate linearly inside the
tabulated range and raise :class:`~bearingkit.errors.InputError` outside it.

Radial bearings are those with nominal contact angle 0 <= α <= 45°, thrust bearings those with
45° < α <= 90° (ISO 76:2006 clause 3 / ISO 5593).

References: ISO 76:2006 (``cite("iso76")``); Harris & Kotzalas 2007 ch. 2 of vol. 2 (``cite("harris2007")``).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics import tables

__all__ = [
    "CONTACT_LIMITS",
    "P0_MODELS",
    "equivalent_static_load",
    "f0_radial_ball",
    "f0_thrust_ball",
    "static_rating_ball",
    "static_rating_roller",
    "static_safety",
    "static_safety_from_pressure",
]

#: Pa per MPa: ISO 76 factors f0, 44 and 220 are in N/mm² = MPa.
MPA = 1.0e6
#: Largest contact angle of a radial bearing [rad] (ISO 76:2006 clause 3: radial α <= 45°).
RADIAL_MAX_ANGLE = np.pi / 4
#: ISO 76:2006 eq. (3)-(4): roller C0r factor 44 MPa (contact stress 4000 MPa at the centre of the most
#: heavily loaded contact); valid 0 <= α <= 45°.
ROLLER_RADIAL_FACTOR = 44.0 * MPA
#: ISO 76:2006 eq. (7)-(8): thrust roller C0a factor 220 MPa; valid 45° < α <= 90°.
ROLLER_THRUST_FACTOR = 220.0 * MPA
#: ISO 76:2006 6.2: radial factor X0 and axial factor Y0, radial contact groove ball bearings (single and
#: double row).
X0_DEEP_GROOVE = 0.6
Y0_DEEP_GROOVE = 0.5
#: ISO 76:2006 6.2: X0 of single-row angular contact / self-aligning ball / radial roller bearings.
X0_SINGLE = 0.5
#: ISO 76:2006 6.2: X0 of double-row angular contact / self-aligning ball / radial roller bearings.
X0_DOUBLE = 1.0
#: ISO 76:2006 6.2 / 7.2: Y0 = 0.22 cot α (single row) and 0.44 cot α (double row) for self-aligning ball
#: and radial roller bearings with α != 0.
Y0_COT_SINGLE = 0.22
Y0_COT_DOUBLE = 0.44
#: ISO 76:2006 8.2 / 9.2: thrust bearings with α != 90°: P0a = 2.3 Fr tan α + Fa.
THRUST_RADIAL_FACTOR = 2.3

_F0_RADIAL = "iso76_f0_radial_ball.csv"
_F0_THRUST = "iso76_f0_thrust_ball.csv"
_X0Y0_ANGULAR = "iso76_x0y0_angular_ball.csv"

#: Contact-stress criterion behind C0 (ISO 76:2006 clause 4): computed maximum contact pressure at the
#: centre of the most heavily loaded contact [Pa], and the exponent n of the load–pressure law
#: (Hertz: load ∝ p³ for point contact, ∝ p² for line contact), so that C0/P0 = (p_limit / p_max)^n.
CONTACT_LIMITS: dict[str, tuple[float, int]] = {
    "ball": (4200.0 * MPA, 3),  # radial/angular/thrust ball bearings, ISO 76:2006 4
    "self_aligning_ball": (4600.0 * MPA, 3),  # self-aligning ball bearings, ISO 76:2006 4
    "roller": (4000.0 * MPA, 2),  # all roller bearings (line contact), ISO 76:2006 4
}


def _geometry(element_diameter, pitch_diameter, contact_angle, thrust: bool):
    checks.positive("element_diameter", element_diameter, "m")
    checks.positive("pitch_diameter", pitch_diameter, "m")
    checks.greater("pitch_diameter", pitch_diameter, "element_diameter", element_diameter, "m")
    if thrust:
        checks.in_range("contact_angle", contact_angle, RADIAL_MAX_ANGLE, np.pi / 2, "rad")
        if np.any(np.asarray(contact_angle, dtype=float) <= RADIAL_MAX_ANGLE):
            raise InputError(
                f"contact_angle ({checks._fmt(contact_angle)} rad) must exceed pi/4 for a thrust bearing"
            )
    else:
        checks.in_range("contact_angle", contact_angle, 0.0, RADIAL_MAX_ANGLE, "rad")
    as_float = (np.asarray(v, dtype=float) for v in (element_diameter, pitch_diameter, contact_angle))
    return tuple(as_float)


def f0_radial_ball(gamma):
    """Factor f0 [MPa] for radial and angular contact groove ball bearings, ISO 76:2006 Table 1.

    Parameters
    ----------
    gamma : array_like
        γ = Dw cos α / Dpw [-], tabulated 0 … 0.40.

    Returns
    -------
    numpy.ndarray
        f0 [MPa] (N/mm²), linear interpolation in the table.
    """
    return tables.interp_strict(
        "gamma", gamma, tables.column(_F0_RADIAL, "gamma"), tables.column(_F0_RADIAL, "f0")
    )


def f0_thrust_ball(gamma):
    """Factor f0 [MPa] for thrust ball bearings, ISO 76:2006 Table 3.

    Parameters
    ----------
    gamma : array_like
        γ = Dw cos α / Dpw [-], tabulated 0 … 0.35; γ = 0 for α = 90° (f0 = 61.6).

    Notes
    -----
    The table is f0 = Q/Dw² at 4200 MPa (Hertz, groove radius 0.54 Dw) with the washer raceway's
    circumferential curvature (2/Dw) γ/(1 − γ) (tests/physics/life/test_iso76.py reproduces every checked
    row). That curvature is n_r/r, the radial share of the contact normal over the contact radius; at
    α = 90° the normal is axial and the curvature vanishes, so γ = Dw cos 90°/Dpw = 0 — unlike ISO 281
    Table 4, whose α = 90° column takes Dw/Dpw for the rolling kinematics (the (1 ∓ γ) speed terms),
    which a static stress criterion does not contain.
    """
    return tables.interp_strict(
        "gamma", gamma, tables.column(_F0_THRUST, "gamma"), tables.column(_F0_THRUST, "f0")
    )


def static_rating_ball(
    element_diameter, pitch_diameter, contact_angle, n_elements, n_rows=1, kind="radial", f0=None
):
    """Basic static load rating C0 [N] of a ball bearing, ISO 76:2006 eq. (1) and (5)-(6).

    .. math::

        C_{0r} = f_0\\, i\\, Z\\, D_w^2 \\cos\\alpha \\quad\\text{(radial)},\\qquad
        C_{0a} = f_0\\, Z\\, D_w^2 \\sin\\alpha \\quad\\text{(thrust; } \\sin 90° = 1)

    with f0 from ISO 76:2006 Table 1 (radial) or Table 3 (thrust), both at γ = Dw cos α/Dpw (thrust
    α = 90°: γ = 0, see :func:`f0_thrust_ball`).

    Parameters
    ----------
    element_diameter : array_like
        Ball diameter Dw [m].
    pitch_diameter : array_like
        Pitch diameter Dpw [m]; must exceed ``element_diameter``.
    contact_angle : array_like
        Nominal contact angle α [rad]; 0 … π/4 for ``kind="radial"``, (π/4, π/2] for ``"thrust"``.
    n_elements : array_like
        Balls per row Z [-] (thrust: balls carrying load in one direction).
    n_rows : array_like
        Rows i [-] (radial only; ignored for thrust, where Z counts all balls of one direction).
    kind : {"radial", "thrust"}
        Which table and formula.
    f0 : array_like, optional
        Factor f0 [MPa] given explicitly (e.g. self-aligning ball bearings, whose ISO 76 column is not
        shipped); replaces the table look-up.

    Returns
    -------
    numpy.ndarray
        C0r or C0a [N].

    References
    ----------
    ISO 76:2006 clauses 6.1 and 8.1, Tables 1 and 3.
    """
    if kind not in ("radial", "thrust"):
        checks.one_of("kind", kind, ("radial", "thrust"))
    thrust = kind == "thrust"
    dw, dpw, alpha = _geometry(element_diameter, pitch_diameter, contact_angle, thrust)
    checks.positive("n_elements", n_elements)
    checks.positive("n_rows", n_rows)
    is_90 = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
    # Dw cos α/Dpw, exactly 0 at α = 90° (cos(π/2) is 6e-17 in floating point)
    gamma = np.where(is_90, 0.0, dw * np.cos(alpha) / dpw)
    if f0 is None:
        f0 = f0_thrust_ball(gamma) if thrust else f0_radial_ball(gamma)
    else:
        checks.positive("f0", f0, "MPa")
    f0_pa = np.asarray(f0, dtype=float) * MPA
    if thrust:
        return f0_pa * n_elements * dw**2 * np.where(is_90, 1.0, np.sin(alpha))
    return f0_pa * n_rows * n_elements * dw**2 * np.cos(alpha)


def static_rating_roller(
    element_diameter, effective_length, pitch_diameter, contact_angle, n_elements, n_rows=1, kind="radial"
):
    """Basic static load rating C0 [N] of a roller bearing, ISO 76:2006 eq. (3) and (7)-(8).

    .. math::

        C_{0r} = 44\\,\\mathrm{MPa}\\,\\Bigl(1 - \\frac{D_{we}\\cos\\alpha}{D_{pw}}\\Bigr)
                 i Z L_{we} D_{we}\\cos\\alpha,\\qquad
        C_{0a} = 220\\,\\mathrm{MPa}\\,\\Bigl(1 - \\frac{D_{we}\\cos\\alpha}{D_{pw}}\\Bigr)
                 Z L_{we} D_{we}\\sin\\alpha

    (for α = 90° the thrust formula reduces to 220 Z Lwe Dwe, as in ISO 76 eq. (8)).

    Parameters
    ----------
    element_diameter : array_like
        Roller diameter Dwe [m] (mean diameter for tapered rollers).
    effective_length : array_like
        Effective roller length Lwe [m].
    pitch_diameter : array_like
        Pitch diameter Dpw [m]; must exceed ``element_diameter``.
    contact_angle : array_like
        Nominal contact angle α [rad]; 0 … π/4 radial, (π/4, π/2] thrust.
    n_elements : array_like
        Rollers per row Z [-] (thrust: rollers carrying load in one direction).
    n_rows : array_like
        Rows i [-] (radial only).
    kind : {"radial", "thrust"}

    Returns
    -------
    numpy.ndarray
        C0r or C0a [N].

    References
    ----------
    ISO 76:2006 clauses 7.1 and 9.1.
    """
    if kind not in ("radial", "thrust"):
        checks.one_of("kind", kind, ("radial", "thrust"))
    thrust = kind == "thrust"
    dwe, dpw, alpha = _geometry(element_diameter, pitch_diameter, contact_angle, thrust)
    checks.positive("effective_length", effective_length, "m")
    checks.positive("n_elements", n_elements)
    checks.positive("n_rows", n_rows)
    lwe = np.asarray(effective_length, dtype=float)
    cos_a = np.where(np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12), 0.0, np.cos(alpha))
    base = (1.0 - dwe * cos_a / dpw) * n_elements * lwe * dwe
    if thrust:
        return ROLLER_THRUST_FACTOR * base * np.sin(alpha)
    return ROLLER_RADIAL_FACTOR * base * n_rows * cos_a


# --- equivalent static load ------------------------------------------------------------------------------


def _single_row(x0, y0, fr, fa):
    # ISO 76:2006 6.2.1 / 7.2.1: P0r = X0 Fr + Y0 Fa, but not less than Fr
    return np.maximum(x0 * fr + y0 * fa, fr)


def _deep_groove(fr, fa, alpha, n_rows):
    return _single_row(X0_DEEP_GROOVE, Y0_DEEP_GROOVE, fr, fa)


def _angular_contact(fr, fa, alpha, n_rows):
    alpha_deg = np.degrees(alpha)
    a = tables.column(_X0Y0_ANGULAR, "alpha_deg")
    y_single, y_double = (
        tables.interp_strict("contact_angle", alpha_deg, a, tables.column(_X0Y0_ANGULAR, name), "deg")
        for name in ("y0_single", "y0_double")
    )
    return np.where(n_rows == 1, _single_row(X0_SINGLE, y_single, fr, fa), X0_DOUBLE * fr + y_double * fa)


def _cot_law(fr, fa, alpha, n_rows):
    cot = 1.0 / np.tan(alpha)
    single = _single_row(X0_SINGLE, Y0_COT_SINGLE * cot, fr, fa)
    return np.where(n_rows == 1, single, X0_DOUBLE * fr + Y0_COT_DOUBLE * cot * fa)


def _self_aligning(fr, fa, alpha, n_rows):
    checks.positive("contact_angle", alpha, "rad")
    return _cot_law(fr, fa, alpha, n_rows)


def _radial_roller(fr, fa, alpha, n_rows):
    zero = alpha == 0.0
    if np.any(zero & (fa > 0)):
        raise InputError(
            "load_axial must be 0 for a radial roller bearing with contact_angle 0 "
            "(ISO 76:2006 7.2.2: P0r = Fr)"
        )
    safe = np.where(zero, np.pi / 4, alpha)
    return np.where(zero, fr, _cot_law(fr, fa, safe, n_rows))


def _thrust(fr, fa, alpha, n_rows):
    if np.any(alpha <= RADIAL_MAX_ANGLE):
        raise InputError(f"contact_angle ({checks._fmt(alpha)} rad) must exceed pi/4 for a thrust bearing")
    is_90 = np.isclose(alpha, np.pi / 2, rtol=0.0, atol=1e-12)
    if np.any(is_90 & (fr > 0)):
        raise InputError(
            "load_radial must be 0 for a thrust bearing with contact_angle pi/2 (ISO 76:2006 8.2.2)"
        )
    return np.where(is_90, fa, THRUST_RADIAL_FACTOR * fr * np.tan(np.where(is_90, 0.0, alpha)) + fa)


#: Equivalent static load laws by bearing type (ISO 76:2006 6.2, 7.2, 8.2, 9.2).
P0_MODELS = {
    "deep_groove_ball": _deep_groove,
    "angular_contact_ball": _angular_contact,
    "self_aligning_ball": _self_aligning,
    "radial_roller": _radial_roller,
    "thrust_ball": _thrust,
    "thrust_roller": _thrust,
}


def equivalent_static_load(load_radial, load_axial, bearing_type, contact_angle=0.0, n_rows=1):
    """Static equivalent load P0 [N], ISO 76:2006 clauses 6.2, 7.2, 8.2, 9.2.

    .. math::

        P_{0r} = \\max(X_0 F_r + Y_0 F_a,\\; F_r) \\;\\text{(single row)},\\qquad
        P_{0r} = X_0 F_r + Y_0 F_a \\;\\text{(double row)},\\qquad
        P_{0a} = 2.3 F_r \\tan\\alpha + F_a \\;\\text{(thrust, } \\alpha \\ne 90°)

    X0, Y0: deep groove 0.6/0.5; angular contact 0.5 (single) or 1 (double) with Y0 from ISO 76 Table 2
    (α = 15° … 45°, linear interpolation); self-aligning ball and radial roller (α != 0) 0.5/0.22 cot α
    (single), 1/0.44 cot α (double); radial roller with α = 0: P0r = Fr; thrust α = 90°: P0a = Fa.

    Parameters
    ----------
    load_radial : array_like
        Radial load Fr [N], >= 0.
    load_axial : array_like
        Axial load Fa [N], >= 0.
    bearing_type : str
        One of :data:`P0_MODELS`.
    contact_angle : array_like
        Nominal contact angle α [rad].
    n_rows : int
        1 (single row / single direction) or 2 (double row).

    Returns
    -------
    numpy.ndarray
        P0r (radial types) or P0a (thrust types) [N].

    Notes
    -----
    The validity limit ISO 76 places on Fr/Fa for single-direction thrust bearings is not checked.
    """
    checks.one_of("bearing_type", bearing_type, P0_MODELS)
    checks.non_negative("load_radial", load_radial, "N")
    checks.non_negative("load_axial", load_axial, "N")
    if bearing_type.startswith("thrust"):
        checks.in_range("contact_angle", contact_angle, 0.0, np.pi / 2, "rad")
    else:
        checks.in_range("contact_angle", contact_angle, 0.0, RADIAL_MAX_ANGLE, "rad")
    n_rows = checks.integer("n_rows", n_rows)
    if n_rows > 2:
        raise InputError(f"n_rows ({n_rows}) must be 1 or 2 for ISO 76 equivalent static load")
    fr, fa, alpha = np.broadcast_arrays(
        np.asarray(load_radial, float), np.asarray(load_axial, float), np.asarray(contact_angle, float)
    )
    return np.asarray(P0_MODELS[bearing_type](fr, fa, alpha, n_rows), dtype=float)


def static_safety(static_rating, equivalent_static_load_):
    """Static safety factor s0 = C0 / P0 [-], ISO 76:2006 clause 10.

    .. math:: s_0 = C_0 / P_0

    Parameters
    ----------
    static_rating : array_like
        C0 [N], > 0.
    equivalent_static_load_ : array_like
        P0 [N], > 0 (an unloaded bearing has no finite safety factor).
    """
    checks.positive("static_rating", static_rating, "N")
    checks.positive("equivalent_static_load", equivalent_static_load_, "N")
    return np.asarray(static_rating, float) / np.asarray(equivalent_static_load_, float)


def static_safety_from_pressure(max_pressure, kind, limit_factor=1.0):
    """Static safety from the largest computed contact pressure [-].

    C0 is the load producing the limit pressure of ISO 76:2006 clause 4 (4200 MPa ball, 4600 MPa
    self-aligning ball, 4000 MPa roller) at the centre of the most heavily loaded contact. By Hertz theory
    the contact load grows as p³ in point contact (Q ∝ a b p, a, b ∝ Q^(1/3)) and as p² in line contact
    (q ∝ b p, b ∝ q^(1/2)), so the load ratio equivalent to a pressure ratio is

    .. math:: s_0 = (f\\, p_\\mathrm{limit} / p_\\max)^n,\\quad n = 3\\ (\\text{point}),\\ 2\\ (\\text{line})

    with f = ``limit_factor`` the raceway material's share of the ISO 76 limit (1 for rings of at least
    58 HRC; :meth:`bearingkit.hardness.HardnessProfile.limit_factor`).

    Parameters
    ----------
    max_pressure : array_like
        Largest maximum Hertz pressure in the bearing p_max [Pa], > 0.
    kind : str
        One of :data:`CONTACT_LIMITS` (``"ball"``, ``"self_aligning_ball"``, ``"roller"``).
    limit_factor : float
        f > 0 [-], multiplies the ISO 76 limit pressure (material dependent; default 1).

    Returns
    -------
    numpy.ndarray
        s0 [-]; 1 at the (material's) limit pressure.
    """
    checks.one_of("kind", kind, CONTACT_LIMITS)
    checks.positive("max_pressure", max_pressure, "Pa")
    checks.positive("limit_factor", limit_factor)
    p_limit, exponent = CONTACT_LIMITS[kind]
    return (limit_factor * p_limit / np.asarray(max_pressure, dtype=float)) ** exponent
