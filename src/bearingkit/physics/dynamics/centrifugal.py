"""Inertia forces on rolling elements: masses, centrifugal forces and the ball gyroscopic moment.

SI units: m, kg, kg·m², rad/s, N, N·m. Pure, vectorised functions that broadcast over their inputs.

A rolling element whose centre orbits the bearing axis at the cage speed ω_c on the radius
r = d_m/2 is pushed outward by the centrifugal force F_c = m r ω_c² (Harris & Kotzalas 2007, ch. 8;
Jones 1960). A ball that spins at ω_R about an axis inclined by the attitude angle β to the bearing
axis, while that axis is carried round at ω_c, needs the gyroscopic moment M_g = J ω_R ω_c sin β
about the circumferential axis (rate of change of its angular momentum), with J = m D²/10 the
moment of inertia of a solid sphere.

The roller forms apply to any roller whose centre of mass orbits at the pitch radius: cylindrical
and needle rollers (mass of a cylinder of the roller diameter and length), and barrel or tapered
rollers with their own mass (pass it in).

References: Harris T.A., Kotzalas M.N. (2007) Advanced Concepts of Bearing Technology, 5th ed., CRC
Press, ch. 3 (high-speed ball bearings: F_c = ½ m d_m ω_m², M_g = J ω_R ω_m sin β); Jones A.B. (1960)
J. Basic Eng. 82(2):309-320.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks

#: Moment of inertia of a solid sphere about a diameter over m D² [-] (J = m D²/10, exact).
SPHERE_INERTIA_FACTOR = 0.1


def ball_mass(element_diameter, density):
    """Mass of a solid ball.

    .. math:: m = \\rho\\,\\frac{\\pi D^3}{6}

    Parameters
    ----------
    element_diameter : array_like [m]
        Ball diameter D, > 0.
    density : array_like [kg/m³]
        Ball material density ρ, > 0.

    Returns
    -------
    ndarray [kg]

    References
    ----------
    Harris & Kotzalas (2007), Advanced Concepts, ch. 3.
    """
    checks.positive("element_diameter", element_diameter, "m")
    checks.positive("density", density, "kg/m^3")
    d = np.asarray(element_diameter, dtype=float)
    return np.asarray(density, dtype=float) * np.pi * d**3 / 6.0


def ball_inertia(element_diameter, density):
    """Mass moment of inertia of a solid ball about a diameter.

    .. math:: J = \\frac{m D^2}{10} = \\rho\\,\\frac{\\pi D^5}{60}

    Parameters
    ----------
    element_diameter : array_like [m]
        Ball diameter D, > 0.
    density : array_like [kg/m³]
        Density ρ, > 0.

    Returns
    -------
    ndarray [kg·m²]

    References
    ----------
    Harris & Kotzalas (2007), Advanced Concepts, ch. 3 (J = ρπD⁵/60).
    """
    d = np.asarray(element_diameter, dtype=float)
    return SPHERE_INERTIA_FACTOR * ball_mass(element_diameter, density) * d**2


def roller_mass(element_diameter, length, density):
    """Mass of a solid cylindrical roller.

    .. math:: m = \\rho\\,\\frac{\\pi D^2 l}{4}

    Parameters
    ----------
    element_diameter : array_like [m]
        Roller diameter D, > 0.
    length : array_like [m]
        Roller length l, > 0 (the effective contact length when the overall length is unknown:
        the end chamfers then make the mass slightly high).
    density : array_like [kg/m³]
        Density ρ, > 0.

    Returns
    -------
    ndarray [kg]

    References
    ----------
    Harris & Kotzalas (2007), Advanced Concepts, ch. 3 (roller centrifugal force).
    """
    checks.positive("element_diameter", element_diameter, "m")
    checks.positive("length", length, "m")
    checks.positive("density", density, "kg/m^3")
    d = np.asarray(element_diameter, dtype=float)
    return np.asarray(density, dtype=float) * np.pi * d**2 * np.asarray(length, dtype=float) / 4.0


def centrifugal_force(mass, orbit_radius, cage_speed):
    """Centrifugal force on a rolling element whose centre orbits at the cage speed.

    .. math:: F_c = m\\,r\\,\\omega_c^2

    For a ball on the pitch circle r = d_m/2 this is Harris's F_c = ½ m d_m ω_m².

    Parameters
    ----------
    mass : array_like [kg]
        Element mass m, ≥ 0.
    orbit_radius : array_like [m]
        Radius r of the element centre's orbit (d_m/2 for a ball or a radial roller), > 0.
    cage_speed : array_like [rad/s]
        Orbital (cage) speed ω_c (either sign).

    Returns
    -------
    ndarray [N]
        F_c ≥ 0, radially outward.

    References
    ----------
    Harris & Kotzalas (2007), Advanced Concepts, ch. 3; Jones (1960).
    """
    checks.non_negative("mass", mass, "kg")
    checks.positive("orbit_radius", orbit_radius, "m")
    checks.finite("cage_speed", cage_speed, "rad/s")
    w = np.asarray(cage_speed)
    return np.asarray(mass, dtype=float) * np.asarray(orbit_radius, dtype=float) * w * w


def gyroscopic_moment(inertia, spin_speed, cage_speed, attitude_angle):
    """Gyroscopic moment needed to carry a spinning ball's rotation axis round the bearing axis.

    .. math:: M_g = J\\,\\omega_R\\,\\omega_c\\,\\sin\\beta

    Parameters
    ----------
    inertia : array_like [kg·m²]
        Ball moment of inertia J (:func:`ball_inertia`).
    spin_speed : array_like [rad/s]
        Ball angular speed ω_R about its own axis (signed, as :mod:`.ball_kinematics` returns it).
    cage_speed : array_like [rad/s]
        Orbital speed ω_c.
    attitude_angle : array_like [rad]
        Angle β between the ball's rotation axis and the bearing axis, in the radial–axial plane.

    Returns
    -------
    ndarray [N·m]
        M_g about the circumferential direction (signed like ω_R ω_c sin β). It may be supplied
        with complex inputs (the kinematics differentiate it by the complex step).

    References
    ----------
    Harris & Kotzalas (2007), Advanced Concepts, ch. 3 (M_g = J ω_R ω_m sin β).
    """
    return inertia * spin_speed * cage_speed * np.sin(attitude_angle)
