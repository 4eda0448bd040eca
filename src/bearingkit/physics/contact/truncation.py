"""Truncation of a ball's contact ellipse by the edge of its groove (the shoulder, or an arch seam).

SI units (m, rad). A ball groove is a circular arc of radius r = f D_w about its curvature centre. Seen from
that centre, the contact point lies at the angle α from the groove's bottom direction (the radial direction
for radial and angular contact rings, the axial one for thrust washers), and the contact ellipse's
semi-major axis a (along the groove profile) spans the arc angle θ_a = arcsin(a/r) on either side of it
(a chord of length a subtends it; the ellipse lies on the arc). The groove ends at a shoulder of height h
above its bottom: the arc point at depth r cos θ_s = r cos θ_b − h below the centre, so

    θ_s = arccos(cos θ_b − h/r)

with θ_b the angle of the groove bottom itself: 0 for a single-arc groove, and for a gothic arch (two
arcs whose centres sit ±ρ sin α₀ on either side of the ball plane, ρ = (f − ½) D_w) the seam where the two
arcs meet, sin θ_b = ρ sin α₀ / r. The ellipse is truncated when it reaches past either end of its arc:

    α + θ_a > θ_s      (over the shoulder)      or      α − θ_a < θ_b   (over the arch seam, gothic arches)

Then the contact is no longer a Hertz ellipse on a smooth surface: the pressure peaks at the edge and the
Hertz pressure and the life computed from it are optimistic. Harris & Kotzalas (2007) *Rolling Bearing
Analysis*, 5th ed., *Essential Concepts*, ch. 6 (contact ellipse) and ch. 7 (ball-groove geometry, the
shoulder-height limit of the contact angle).
"""

from __future__ import annotations

import numpy as np

__all__ = ["ellipse_half_angle", "required_shoulder_height", "seam_angle", "shoulder_angle", "truncated"]


def shoulder_angle(shoulder_height, groove_radius, seam=0.0):
    """Angle θ_s [rad] of the shoulder edge seen from the groove's curvature centre.

    .. math:: \\theta_s = \\arccos(\\cos\\theta_b - h/r)

    Parameters
    ----------
    shoulder_height : array_like
        Shoulder height h above the groove bottom [m], 0 < h ≤ r cos θ_b (clipped to that range).
    groove_radius : array_like
        Groove (arc) radius r = f D_w [m].
    seam : array_like
        Angle θ_b of the groove bottom seen from the arc's centre [rad] (0 for a single-arc groove,
        :func:`seam_angle` for a gothic arch).
    """
    h, r = np.asarray(shoulder_height, float), np.asarray(groove_radius, float)
    c = np.cos(np.asarray(seam, float)) - h / r
    return np.arccos(np.clip(c, 0.0, 1.0))


def ellipse_half_angle(semi_major, groove_radius):
    """Arc angle θ_a = arcsin(a/r) [rad] the contact ellipse spans on either side of the contact point.

    Parameters
    ----------
    semi_major : array_like
        Semi-major axis a of the contact ellipse (along the groove profile) [m].
    groove_radius : array_like
        Groove radius r [m].
    """
    return np.arcsin(np.clip(np.asarray(semi_major, float) / np.asarray(groove_radius, float), 0.0, 1.0))


def seam_angle(conformity, contact_angle):
    """Angle θ_b [rad] of a gothic arch's seam seen from one arc's centre: sin θ_b = (f − ½)/f · sin α₀.

    Parameters
    ----------
    conformity : array_like
        f = r/D_w of the arcs [-], > 0.5.
    contact_angle : array_like
        Design contact angle α₀ of the arches [rad] (the arc centres sit (f − ½) D_w sin α₀ off the
        ball plane).
    """
    f = np.asarray(conformity, float)
    return np.arcsin((f - 0.5) / f * np.sin(np.asarray(contact_angle, float)))


def truncated(contact_angle, semi_major, groove_radius, shoulder_height, seam=None):
    """Whether a contact ellipse reaches past the shoulder (or a gothic arch's seam).

    .. math:: \\alpha + \\theta_a > \\theta_s \\quad\\text{or}\\quad \\alpha - \\theta_a < \\theta_b

    Parameters
    ----------
    contact_angle : array_like
        Angle α of the contact from the groove bottom direction, seen from the arc's centre [rad]
        (its magnitude is used: the contact runs towards the shoulder on its own side).
    semi_major : array_like
        Semi-major axis a [m]; contacts with a = 0 (unloaded) are never truncated.
    groove_radius : array_like
        Groove radius r [m].
    shoulder_height : array_like
        Shoulder height h above the groove bottom [m].
    seam : array_like or None
        θ_b of a gothic arch [rad] (then the seam side is checked too); None for a single-arc groove.
    """
    alpha = np.abs(np.asarray(contact_angle, float))
    a = np.asarray(semi_major, float)
    theta_a = ellipse_half_angle(a, groove_radius)
    bottom = 0.0 if seam is None else seam
    out = alpha + theta_a > shoulder_angle(shoulder_height, groove_radius, bottom)
    if seam is not None:
        out = out | (alpha - theta_a < np.asarray(seam, float))
    return out & (a > 0)


def required_shoulder_height(contact_angle, semi_major, groove_radius, seam=0.0):
    """Smallest shoulder height h* [m] above the groove bottom that still holds the whole contact ellipse.

    The inverse of :func:`shoulder_angle` at the ellipse's far end θ_s = α + θ_a:

    .. math:: h^* = r\\,(\\cos\\theta_b - \\cos(\\alpha + \\theta_a))

    A value at or above the groove depth r cos θ_b means no shoulder of that groove can hold the ellipse.

    Parameters
    ----------
    contact_angle : array_like
        Angle α of the contact from the groove bottom direction [rad] (magnitude used).
    semi_major : array_like
        Semi-major axis a [m].
    groove_radius : array_like
        Groove radius r [m].
    seam : array_like
        θ_b of a gothic arch [rad]; 0 for a single-arc groove.
    """
    r = np.asarray(groove_radius, float)
    edge = np.abs(np.asarray(contact_angle, float)) + ellipse_half_angle(semi_major, r)
    return r * (np.cos(np.asarray(seam, float)) - np.cos(edge))
