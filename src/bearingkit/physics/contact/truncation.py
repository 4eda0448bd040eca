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

Truncation as numbers
---------------------
**Track-truncation safety** (:func:`truncation_safety`): the available shoulder height over the height the
ellipse needs, h / h* (< 1: truncated); on a gothic arch's seam side the available over the needed arc
angle, (α − θ_b) / θ_a.

**Truncated pressure** (:func:`truncated_pressure`), bearingkit's "cut and re-equilibrated ellipse"
(a simple method of this project, not a published one; it ignores the stress concentration at the edge,
so the real edge pressure is higher): the part of the Hertz ellipse beyond the edge carries no load, so
the contact closes further until the part left on the groove carries the whole load Q. The pressure
keeps the Hertz shape of a larger contact of load Q′ = s³ Q (semi-axes s a, s b, peak s p_max): along the
major axis a semi-ellipsoidal pressure carries the fraction F(τ) = (2 + 3τ − τ³)/4 of its load on the
side t ≤ τ of a cut at t = x/a = τ, so with the edge at the distance τ₀ a from the contact centre

.. math:: s^3\\,F(\\tau_0 / s) = 1,\\qquad p_{tr} = s\\,p_{max}

(two cuts, shoulder and seam: F = F(τ₁) + F(τ₂) − 1). For τ₀ ≥ 1 nothing is cut (s = 1); τ₀ = 0 (the
edge through the centre) gives s = 2^{1/3}, p_tr = 1.26 p_max; τ₀ = −1 (the contact centre one semi-axis
beyond the edge) 2s³ − 3s² − 3 = 0, s = 1.91. τ₀ = r sin(θ_s − α) / a follows the arc
convention of :func:`ellipse_half_angle`. The re-equilibrated load Q′ = s³ Q is the load of the
untruncated contact with the same peak pressure, which bearingkit uses in s0 and in the life of a
truncated contact (docs/subsurface.md).
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "ellipse_half_angle",
    "load_fraction",
    "remaining_fraction",
    "required_shoulder_height",
    "seam_angle",
    "shoulder_angle",
    "truncated",
    "truncated_pressure",
    "truncation_safety",
]

#: Bisection steps of :func:`truncated_pressure` (bracket [1, 3] shrunk by 2⁻⁶⁰).
_BISECTION_STEPS = 60


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


def remaining_fraction(contact_angle, semi_major, groove_radius, edge_angle):
    """τ₀ = r sin(θ_e − |α|) / a [-]: the part of the semi-major axis on the groove towards an edge.

    ≥ 1: the ellipse stays on the groove on that side; < 1 it is cut (0: the edge through the centre,
    < 0: the contact centre itself beyond the edge). Clipped below at −1 (a contact riding on the edge);
    a = 0 gives +inf (nothing to cut).

    Parameters
    ----------
    contact_angle : array_like
        α from the groove bottom [rad] (magnitude used).
    semi_major : array_like
        a [m].
    groove_radius : array_like
        r [m].
    edge_angle : array_like
        θ_e of the edge seen from the arc's centre [rad]: the shoulder's :func:`shoulder_angle`.
    """
    a = np.asarray(semi_major, float)
    room = np.asarray(groove_radius, float) * np.sin(np.asarray(edge_angle, float) - np.abs(contact_angle))
    with np.errstate(divide="ignore", invalid="ignore"):
        tau = np.where(a > 0.0, room / np.where(a > 0.0, a, 1.0), np.inf)
    return np.maximum(tau, -1.0)


def load_fraction(tau):
    """F(τ) = (2 + 3τ − τ³)/4: the load of a semi-ellipsoidal pressure on the side x/a ≤ τ of a cut [-].

    (∫ over the chord at x of √(1 − x² − y²) is π(1 − x²)/2; integrated from −1 to τ and divided by 2π/3.)

    Parameters
    ----------
    tau : array_like
        Position of the cut along the semi-major axis, x/a [-] (clipped to [−1, 1]).
    """
    t = np.clip(np.asarray(tau, float), -1.0, 1.0)
    return (2.0 + 3.0 * t - t**3) / 4.0


def truncated_pressure(max_pressure, remaining, remaining_other=np.inf):
    """Peak pressure of a truncated contact, cut and re-equilibrated (module docstring) [Pa].

    Solves s³ [F(τ₁/s) + F(τ₂/s) − 1] = 1 for s ≥ 1 by bisection (the left side grows with s) and returns
    s p_max; s = 1 where nothing is cut.

    Parameters
    ----------
    max_pressure : array_like
        Hertz p_max of the untruncated contact [Pa].
    remaining : array_like
        τ₁ of the shoulder side (:func:`remaining_fraction`), in [−1, 1].
    remaining_other : array_like
        τ₂ of the other end (a gothic arch's seam); +inf when there is no edge there. Edges beyond the
        untruncated ellipse (τ > 1) may still cut the grown one.

    Returns
    -------
    numpy.ndarray
        p_tr ≥ p_max [Pa].
    """
    t1, t2 = np.broadcast_arrays(np.asarray(remaining, float), np.asarray(remaining_other, float))
    lo, hi = np.ones(t1.shape), np.full(t1.shape, 3.0)
    for _ in range(_BISECTION_STEPS):
        mid = 0.5 * (lo + hi)
        carried = mid**3 * (load_fraction(t1 / mid) + load_fraction(t2 / mid) - 1.0)
        lo, hi = np.where(carried < 1.0, mid, lo), np.where(carried < 1.0, hi, mid)
    cut = (t1 < 1.0) | (t2 < 1.0)
    return np.asarray(max_pressure, float) * np.where(cut, 0.5 * (lo + hi), 1.0)


def truncation_safety(contact_angle, semi_major, groove_radius, shoulder_height, seam=None):
    """Track-truncation safety [-]: available over needed shoulder height, h / h* (and on a gothic arch's
    seam side (|α| − θ_b) / θ_a); the smaller of the two. < 1: the ellipse is truncated; +inf for a = 0.

    Parameters
    ----------
    contact_angle, semi_major, groove_radius, shoulder_height
        As in :func:`truncated` [rad, m, m, m].
    seam : array_like or None
        θ_b of a gothic arch [rad]; None for a single-arc groove.
    """
    bottom = 0.0 if seam is None else seam
    need = required_shoulder_height(contact_angle, semi_major, groove_radius, bottom)
    a = np.asarray(semi_major, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.where((a > 0) & (need > 0), np.asarray(shoulder_height, float) / need, np.inf)
        if seam is not None:
            theta_a = ellipse_half_angle(a, groove_radius)
            room = np.abs(np.asarray(contact_angle, float)) - np.asarray(seam, float)
            out = np.minimum(out, np.where(a > 0, room / np.where(a > 0, theta_a, 1.0), np.inf))
    return out
