"""Rigid-body kinematics of rolling elements: cage speed, element rotation, spin, slip, entrainment.

SI units: rad/s, m, m/s. Pure, vectorised numpy functions that broadcast over a leading case axis.

Frame (design.md §3): bearing axis z. The inner ring turns at ``speed_inner`` ω_i and the outer
ring at ``speed_outer`` ω_o about +z (either may be zero). Everything is derived in the cage frame,
which turns at the cage speed ω_c: there the rings turn at Ω_i = ω_i − ω_c and Ω_o = ω_o − ω_c and
the element centre is fixed at radius R = d_m/2.

Element of diameter D with contact normal n = (cos α, 0, sin α) in the (radial, tangential, axial)
frame of the element; inner contact at C − (D/2) n, outer at C + (D/2) n; γ = D cos α / d_m.
No slip in the rolling direction at both contact centres (pure rolling at the pitch line, Tian et
al. 2025 §3.5; Harris & Kotzalas 2007, ch. 8) gives

.. math::
    \\omega_c = \\tfrac12\\,[\\omega_i (1 - \\gamma) + \\omega_o (1 + \\gamma)],\\qquad
    \\omega_\\perp = \\frac{d_m}{2D}\\,(1 - \\gamma^2)\\,(\\omega_o - \\omega_i)

where ω_⊥ is the component of the element's angular velocity perpendicular to n in the
radial–axial plane (the rolling component). Its component along n, ω_n, is fixed by the raceway
control hypothesis (registry :data:`RACEWAY_CONTROLS`): ``"tangent"`` (rolling axis in the contact
tangent plane, ω_n = 0), ``"outer"`` (no spin at the outer contact) or ``"inner"``. The spin of the
element relative to each raceway about n is then ω_s = ω_n − Ω sin α, and the mean entrainment
speed of both contacts is u_m = (d_m/4)(1 − γ²)|ω_i − ω_o|.

Thrust rollers (α = 90°, roller axis radial) roll without slip only at the pitch radius R; a slice
at radius y slides on the raceway with v = Ω (y − R) (Tian et al. 2025 §3.5, velocities
v_ij,in and v_ij,o).

References: Harris T.A., Kotzalas M.N. (2007) Rolling Bearing Analysis, 5th ed., ch. 8 (ball and
roller speeds); Jones A.B. (1960) J. Basic Eng. 82:309 (raceway control); Tian et al. (2025)
Machines 13:588 §3.5, doi:10.3390/machines13070588.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from bearingkit import checks, references

references.add(
    "jones1960",
    "Jones A.B. (1960) A general theory for elastically constrained ball and radial roller bearings "
    "under arbitrary load and speed conditions. J. Basic Eng. 82(2):309-320. doi:10.1115/1.3662587",
)

#: Raceway-control hypotheses for the element's spin axis (see module docstring).
RACEWAY_CONTROLS = ("tangent", "outer", "inner")
REFERENCE_KEYS = ("harris2007", "jones1960", "tian2025")


class ElementKinematics(NamedTuple):
    """Speeds of the elements of one row (arrays broadcast over the inputs, SI).

    Attributes
    ----------
    cage_speed : ndarray [rad/s]
        Orbital speed ω_c of the element set.
    rolling_speed : ndarray [rad/s]
        Rolling component ω_⊥ of the element's angular velocity (signed; > 0 for ω_o > ω_i).
    spin_speed : ndarray [rad/s]
        Magnitude of the element's total angular velocity relative to the cage, √(ω_⊥² + ω_n²).
    spin_inner, spin_outer : ndarray [rad/s]
        Spin of the element relative to each raceway about the contact normal (signed).
    entrainment_inner, entrainment_outer : ndarray [m/s]
        Mean entrainment speed u_m = (u_ring + u_element)/2 of each contact (≥ 0).
    """

    cage_speed: np.ndarray
    rolling_speed: np.ndarray
    spin_speed: np.ndarray
    spin_inner: np.ndarray
    spin_outer: np.ndarray
    entrainment_inner: np.ndarray
    entrainment_outer: np.ndarray


def _speeds(speed_inner, speed_outer):
    checks.finite("speed_inner", speed_inner, "rad/s")
    checks.finite("speed_outer", speed_outer, "rad/s")
    return np.asarray(speed_inner, dtype=float), np.asarray(speed_outer, dtype=float)


def element_kinematics(
    pitch_diameter, element_diameter, contact_angle, speed_inner, speed_outer, raceway_control="tangent"
) -> ElementKinematics:
    """Cage speed, element rotation, spin and entrainment of a ball or radial-roller row.

    Parameters
    ----------
    pitch_diameter : array_like [m]
        d_m, > element_diameter·|cos α|.
    element_diameter : array_like [m]
        D, > 0.
    contact_angle : array_like [rad]
        α in [−π/2, π/2] (0 radial ball or roller, ±π/2 thrust ball).
    speed_inner, speed_outer : array_like [rad/s]
        Ring speeds ω_i, ω_o about +z.
    raceway_control : {"tangent", "outer", "inner"}
        Spin-axis hypothesis, :data:`RACEWAY_CONTROLS`.

    Returns
    -------
    ElementKinematics

    Notes
    -----
    .. math::
        \\gamma = \\frac{D\\cos\\alpha}{d_m},\\quad
        \\omega_c = \\frac{\\omega_i(1-\\gamma) + \\omega_o(1+\\gamma)}{2},\\quad
        \\omega_\\perp = \\frac{d_m}{2D}(1-\\gamma^2)(\\omega_o-\\omega_i),\\quad
        u_m = \\frac{d_m}{4}(1-\\gamma^2)\\,|\\omega_i-\\omega_o|

    Spin about the contact normal: ω_s,i = ω_n − (ω_i − ω_c) sin α, ω_s,o = ω_n − (ω_o − ω_c) sin α
    with ω_n = 0 ("tangent"), (ω_o − ω_c) sin α ("outer") or (ω_i − ω_c) sin α ("inner").
    Harris & Kotzalas (2007) ch. 8; Tian et al. (2025) §3.5 (α = 90°: ω_c = ω_i/2, u = d_m ω_i/4).
    """
    checks.one_of("raceway_control", raceway_control, RACEWAY_CONTROLS)
    checks.positive("element_diameter", element_diameter, "m")
    checks.in_range("contact_angle", contact_angle, -np.pi / 2, np.pi / 2, "rad")
    w_i, w_o = _speeds(speed_inner, speed_outer)
    d = np.asarray(element_diameter, dtype=float)
    dm = np.asarray(pitch_diameter, dtype=float)
    alpha = np.asarray(contact_angle, dtype=float)
    checks.greater(
        "pitch_diameter", dm, "element_diameter*|cos(contact_angle)|", d * np.abs(np.cos(alpha)), "m"
    )
    gamma = d * np.cos(alpha) / dm
    w_c = 0.5 * (w_i * (1.0 - gamma) + w_o * (1.0 + gamma))
    big_i, big_o = w_i - w_c, w_o - w_c
    w_perp = dm / (2.0 * d) * (1.0 - gamma**2) * (w_o - w_i)
    sin_a = np.sin(alpha)
    w_n = {"tangent": 0.0 * w_c, "outer": big_o * sin_a, "inner": big_i * sin_a}[raceway_control]
    u_m = dm / 4.0 * (1.0 - gamma**2) * np.abs(w_i - w_o)
    out = np.broadcast_arrays(
        w_c, w_perp, np.hypot(w_perp, w_n), w_n - big_i * sin_a, w_n - big_o * sin_a, u_m, u_m
    )
    return ElementKinematics(*(np.array(a, dtype=float) for a in out))


class ThrustRollerKinematics(NamedTuple):
    """Speeds of a thrust cylindrical-roller row (SI; slice arrays end with the slice axis).

    Attributes
    ----------
    cage_speed : ndarray [rad/s]
    roller_speed : ndarray [rad/s]
        Roller rotation about its own (radial) axis, ω_r = (d_m/2D)(ω_i − ω_o) (signed).
    slide_inner, slide_outer : ndarray (..., n_s) [m/s]
        Sliding velocity of each slice on the inner and outer raceway, v = Ω (y − R) (signed).
    entrainment_inner, entrainment_outer : ndarray (..., n_s) [m/s]
        Mean entrainment speed of each slice, |Ω| (y + R)/2.
    entrainment_pitch : ndarray [m/s]
        Entrainment speed at the pitch line, |Ω| R (both contacts).
    """

    cage_speed: np.ndarray
    roller_speed: np.ndarray
    slide_inner: np.ndarray
    slide_outer: np.ndarray
    entrainment_inner: np.ndarray
    entrainment_outer: np.ndarray
    entrainment_pitch: np.ndarray


def thrust_roller_kinematics(
    pitch_diameter, element_diameter, slice_radius, speed_inner, speed_outer
) -> ThrustRollerKinematics:
    """Kinematics of a thrust cylindrical-roller row with pure rolling at the pitch line.

    Parameters
    ----------
    pitch_diameter : array_like [m]
        Diameter d_m = 2R of the roller middles; broadcast against ``slice_radius[..., 0]``.
    element_diameter : array_like [m]
        Roller diameter D.
    slice_radius : array_like (..., n_s) [m]
        Radius y of each slice centre from the bearing axis.
    speed_inner, speed_outer : array_like [rad/s]
        Ring speeds (shape broadcastable to the leading axes of ``slice_radius``).

    Returns
    -------
    ThrustRollerKinematics

    Notes
    -----
    .. math::
        \\omega_c = \\frac{\\omega_i + \\omega_o}{2},\\quad
        \\omega_r = \\frac{d_m}{2D}(\\omega_i - \\omega_o),\\quad
        v_{in} = (\\omega_i - \\omega_c)(y - R),\\quad v_o = (\\omega_o - \\omega_c)(y - R)

    Tian et al. (2025) §3.5, eqs. for ω_c, ω_r, v_ij,in, v_ij,o (rolling at y = R).
    """
    checks.positive("element_diameter", element_diameter, "m")
    checks.positive("pitch_diameter", pitch_diameter, "m")
    checks.positive("slice_radius", slice_radius, "m")
    w_i, w_o = _speeds(speed_inner, speed_outer)
    radius = np.asarray(pitch_diameter, dtype=float) / 2.0
    d = np.asarray(element_diameter, dtype=float)
    y = np.asarray(slice_radius, dtype=float)
    w_c = 0.5 * (w_i + w_o)
    big_i, big_o = w_i - w_c, w_o - w_c
    w_r = radius / d * (w_i - w_o)
    r_ = radius[..., None] if np.ndim(radius) else radius
    bi = big_i[..., None] if np.ndim(big_i) else big_i
    bo = big_o[..., None] if np.ndim(big_o) else big_o
    v_i = bi * (y - r_)
    v_o = bo * (y - r_)
    u_i = np.abs(bi) * (y + r_) / 2.0
    u_o = np.abs(bo) * (y + r_) / 2.0
    return ThrustRollerKinematics(
        np.asarray(w_c, dtype=float),
        np.asarray(w_r, dtype=float),
        v_i,
        v_o,
        u_i,
        u_o,
        np.asarray(np.abs(big_i) * radius, dtype=float),
    )


def row_kinematics(row, speed_inner, speed_outer, raceway_control="tangent"):
    """Kinematics of a bearingkit row (BallRow or CylindricalRow) at ring speeds [rad/s].

    Returns :class:`ElementKinematics` for ball and radial roller rows (free contact angle) and
    :class:`ThrustRollerKinematics` (slices at the row's slice grid) for thrust roller rows.
    """
    w_i = np.asarray(speed_inner, dtype=float).reshape(-1, 1)
    w_o = np.asarray(speed_outer, dtype=float).reshape(-1, 1)
    dm = np.asarray(row.pitch_diameter, dtype=float).reshape(-1, 1)
    d = np.asarray(row.element_diameter, dtype=float).reshape(-1, 1)
    if row.kind == "ball":
        alpha = np.asarray(row.contact_angle, dtype=float).reshape(-1, 1)
        return element_kinematics(dm, d, alpha, w_i, w_o, raceway_control)
    if row.kind == "cylindrical":
        if row.direction == 0:
            return element_kinematics(dm, d, 0.0, w_i, w_o, raceway_control)
        from bearingkit.physics.contact.line import slice_grid

        x, _ = slice_grid(np.asarray(row.effective_length, dtype=float), row.n_slices)
        y = dm / 2 + np.asarray(x, dtype=float).reshape(-1, row.n_slices)  # (C|1, n_s)
        return thrust_roller_kinematics(dm[:, 0], d[:, 0], y, w_i[:, 0], w_o[:, 0])
    raise checks.InputError(f"row kind ({row.kind!r}) has no kinematics; expected 'ball' or 'cylindrical'")
