"""Ball kinematics at unequal inner and outer contact angles under a raceway-control hypothesis.

SI units: rad, rad/s, m. Pure, vectorised functions; they also accept complex angles so that the
high-speed ball kernel can differentiate them by the complex step.

Frame: the ball's radial–axial plane with unit vectors r̂ (outward) and ẑ (bearing axis); the
contact normals n_k = (cos α_k, sin α_k) point from the outer groove centre towards the inner one
(the outer contact lies at C + (D/2) n_o, the inner one at C − (D/2) n_i). In the cage frame, which
turns at the orbital speed ω_m, the rings turn at Ω_k = ω_k − ω_m and the ball spins at ω_R about
the axis (−sin β, cos β): β is the attitude angle of Harris & Kotzalas (positive for positive
contact angles, 0 for a radial ball row). No slip in the rolling direction at both contact centres
(γ′ = D/d_m):

.. math::
    \\Omega_o\\,(1 + \\gamma'\\cos\\alpha_o) = \\gamma'\\,\\omega_R\\cos(\\alpha_o - \\beta),\\qquad
    \\Omega_i\\,(1 - \\gamma'\\cos\\alpha_i) = -\\gamma'\\,\\omega_R\\cos(\\alpha_i - \\beta)

so, with a_o = 1 + γ′cos α_o, a_i = 1 − γ′cos α_i, k_k = cos(α_k − β),

.. math::
    \\omega_m = \\frac{\\omega_i a_i k_o + \\omega_o a_o k_i}{a_i k_o + a_o k_i},\\qquad
    \\omega_R = \\frac{(\\omega_o - \\omega_m)\\,a_o}{\\gamma' k_o}.

With ω_o = 0 these are Harris & Kotzalas' ω_m/ω and ω_R/ω. The raceway-control hypothesis (Jones
1959, 1960) fixes β: the ball does not spin on the controlling raceway,

.. math::
    \\text{outer: } \\tan\\beta = \\frac{\\sin\\alpha_o}{\\cos\\alpha_o + \\gamma'},\\qquad
    \\text{inner: } \\tan\\beta = \\frac{\\sin\\alpha_i}{\\cos\\alpha_i - \\gamma'}.

Relative to raceway k the ball turns at ω_R(−sin β, cos β) − Ω_k ẑ; its component along n_k is the
spin ω_s,k = ω_R sin(α_k − β) − Ω_k sin α_k and the one along the in-plane tangent
(−sin α_k, cos α_k) is the rolling speed ω_roll,k = ω_R cos(α_k − β) − Ω_k cos α_k.

References: Jones A.B. (1959) Ball motion and sliding friction in ball bearings, J. Basic Eng.
81:1-12; Jones A.B. (1960) J. Basic Eng. 82(2):309-320; Harris T.A., Kotzalas M.N. (2007) Advanced
Concepts of Bearing Technology, 5th ed., ch. 3 (ω_m/ω, ω_R/ω, tan β for outer- and inner-raceway
control); MESYS AG, Rolling bearing calculation manual, "Options for gyroscopic moment" (outer race
control: no spin at the outer contact, the gyroscopic moment reacted at the outer contact only).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from bearingkit import checks, references

references.add(
    "jones1959",
    "Jones A.B. (1959) Ball motion and sliding friction in ball bearings. J. Basic Eng. 81(1):1-12.",
)
references.add(
    "harris2007advanced",
    "Harris T.A., Kotzalas M.N. (2007) Advanced Concepts of Bearing Technology (Rolling Bearing "
    "Analysis, 5th ed., vol. 2), CRC Press, ch. 3: high-speed ball bearings.",
)

#: Raceway-control hypotheses: the raceway on which the ball does not spin.
RACEWAY_CONTROLS = ("outer", "inner")
#: Share λ of the gyroscopic moment reacted by friction at (inner, outer) contact, per control:
#: the controlling raceway takes it all (Harris & Kotzalas 2007 vol. 2 ch. 3: λ_o = 2, λ_i = 0 for
#: outer-raceway control; MESYS "outer race control": friction at the outer race only).
GYROSCOPIC_SHARE = {"outer": (0.0, 2.0), "inner": (2.0, 0.0)}
REFERENCE_KEYS = ("jones1959", "jones1960", "harris2007advanced")


class BallSpeeds(NamedTuple):
    """Speeds of a ball (arrays broadcast over the inputs; signed as in the module docstring).

    Attributes
    ----------
    cage_speed : ndarray [rad/s]
        Orbital speed ω_m of the ball centre.
    spin_speed : ndarray [rad/s]
        ω_R, the ball's angular speed in the cage frame (negative when the inner ring turns +).
    attitude_angle : ndarray [rad]
        β, angle of the ball's rotation axis from the bearing axis.
    spin_inner, spin_outer : ndarray [rad/s]
        Spin ω_s of the ball relative to each raceway about the contact normal.
    roll_inner, roll_outer : ndarray [rad/s]
        Rolling speed ω_roll of the ball relative to each raceway.
    """

    cage_speed: np.ndarray
    spin_speed: np.ndarray
    attitude_angle: np.ndarray
    spin_inner: np.ndarray
    spin_outer: np.ndarray
    roll_inner: np.ndarray
    roll_outer: np.ndarray


def attitude_angle(contact_angle_inner, contact_angle_outer, diameter_ratio, raceway_control="outer"):
    """Ball attitude angle β under outer- or inner-raceway control.

    .. math::
        \\text{outer: } \\beta = \\arctan\\frac{\\sin\\alpha_o}{\\cos\\alpha_o + \\gamma'},\\qquad
        \\text{inner: } \\beta = \\arctan\\frac{\\sin\\alpha_i}{\\cos\\alpha_i - \\gamma'}

    Parameters
    ----------
    contact_angle_inner, contact_angle_outer : array_like [rad]
        Operating contact angles α_i, α_o (real or complex for the complex step).
    diameter_ratio : array_like [-]
        γ′ = D/d_m, in (0, 1).
    raceway_control : {"outer", "inner"}
        :data:`RACEWAY_CONTROLS`.

    Returns
    -------
    ndarray [rad]

    References
    ----------
    Harris & Kotzalas (2007) Advanced Concepts, ch. 3; Jones (1959).
    """
    checks.one_of("raceway_control", raceway_control, RACEWAY_CONTROLS)
    if raceway_control == "outer":
        a = contact_angle_outer
        return np.arctan(np.sin(a) / (np.cos(a) + diameter_ratio))
    a = contact_angle_inner
    return np.arctan(np.sin(a) / (np.cos(a) - diameter_ratio))


def ball_speeds(
    speed_inner,
    speed_outer,
    contact_angle_inner,
    contact_angle_outer,
    element_diameter,
    pitch_diameter,
    raceway_control="outer",
) -> BallSpeeds:
    """Cage speed, ball spin, attitude angle and spin/roll at each contact (module docstring).

    Parameters
    ----------
    speed_inner, speed_outer : array_like [rad/s]
        Ring speeds ω_i, ω_o about the bearing axis.
    contact_angle_inner, contact_angle_outer : array_like [rad]
        Operating contact angles α_i, α_o (complex allowed: complex-step derivatives).
    element_diameter : array_like [m]
        Ball diameter D.
    pitch_diameter : array_like [m]
        Pitch diameter d_m (> D).
    raceway_control : {"outer", "inner"}
        Which raceway the ball does not spin on.

    Returns
    -------
    BallSpeeds

    References
    ----------
    Harris & Kotzalas (2007) Advanced Concepts, ch. 3 (ω_m/ω, ω_R/ω); Jones (1959, 1960).
    """
    w_i = np.asarray(speed_inner)
    w_o = np.asarray(speed_outer)
    a_i_ang = np.asarray(contact_angle_inner)
    a_o_ang = np.asarray(contact_angle_outer)
    g = np.asarray(element_diameter, dtype=float) / np.asarray(pitch_diameter, dtype=float)
    beta = attitude_angle(a_i_ang, a_o_ang, g, raceway_control)
    a_o = 1.0 + g * np.cos(a_o_ang)
    a_i = 1.0 - g * np.cos(a_i_ang)
    k_o = np.cos(a_o_ang - beta)
    k_i = np.cos(a_i_ang - beta)
    w_m = (w_i * a_i * k_o + w_o * a_o * k_i) / (a_i * k_o + a_o * k_i)
    w_r = (w_o - w_m) * a_o / (g * k_o)
    big_i, big_o = w_i - w_m, w_o - w_m
    spin_i = w_r * np.sin(a_i_ang - beta) - big_i * np.sin(a_i_ang)
    spin_o = w_r * np.sin(a_o_ang - beta) - big_o * np.sin(a_o_ang)
    roll_i = w_r * np.cos(a_i_ang - beta) - big_i * np.cos(a_i_ang)
    roll_o = w_r * np.cos(a_o_ang - beta) - big_o * np.cos(a_o_ang)
    return BallSpeeds(w_m, w_r, beta, spin_i, spin_o, roll_i, roll_o)
