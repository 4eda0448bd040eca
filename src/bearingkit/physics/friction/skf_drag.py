"""The drag loss factor V_M of the SKF friction model, approximated where the user gives none.

SI units at the boundary (oil level and d_m in m; V_M is dimensionless).

SKF gives V_M (the first, churning term of the drag moment in an oil bath,
:func:`bearingkit.physics.friction.skf_terms.drag_moment`) only as a diagram of V_M against the oil level
H/d_m, one curve for ball and one for roller bearings (SKF Group 2018, Rolling bearings 17000 EN,
"Drag losses in oil bath lubrication"). bearingkit does not digitise the diagram; it approximates it by
the share of the rolling-element circle under oil:

.. math::

    V_M(H) = V_{M,full}\\,\\frac{t - \\sin t}{2\\pi},\\qquad
    t = 2\\cos^{-1}\\frac{0.6 d_m - H}{0.6 d_m}\\quad (H \\le 1.2 d_m)

where (t − sin t)/2π is the wetted share of a circle of radius 0.6 d_m filled to H — the same immersion
geometry SKF's own drag formula uses in its second term (R_s ∝ t − sin t) — so V_M rises from 0 with zero
slope at H = 0 and levels off at the fully submerged value V_M,full at H = 1.2 d_m, as the diagram does.

V_M,full: ball bearings 1.2e-3 (the plateau of SKF's ball curve as read by one public code transcription
[S1]); roller bearings 5e-4 (from memory of the diagram's roller curve [M]). The shape in between is
bearingkit's approximation, not SKF's curve: read V_M from the diagram and give it
(``[lubrication] drag_loss_factor``) where the drag term matters.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks

__all__ = ["DRAG_LEVEL_CAP", "V_M_FULL", "drag_loss_factor"]

#: V_M of a fully submerged bearing (H ≥ 1.2 d_m) [-]: ball [S1], roller [M] (module docstring).
V_M_FULL = {"ball": 1.2e-3, "roller": 5.0e-4}
#: Oil level over d_m at which SKF caps the immersion (H = 1.2 d_m, SKF "Drag losses").
DRAG_LEVEL_CAP = 1.2  # [-]
#: Radius of the rolling-element circle of SKF's immersion geometry over d_m (t-law factor 0.6).
_CIRCLE = 0.6  # [-]


def drag_loss_factor(oil_level, pitch_diameter, roller: bool):
    """Approximate SKF drag loss factor V_M [-] at oil level H (module docstring).

    .. math:: V_M = V_{M,full}(t - \\sin t)/(2\\pi)

    Parameters
    ----------
    oil_level : array_like
        Oil level H above the lowest point of the outer ring raceway [m], ≥ 0.
    pitch_diameter : array_like
        Bearing mean diameter d_m [m], > 0.
    roller : bool
        Roller (True) or ball (False) bearing.

    Returns
    -------
    ndarray [-]

    References
    ----------
    SKF (2018) Rolling bearings 17000 EN, "Drag losses in oil bath lubrication" (the diagram this
    approximates; V_M,full sources in :data:`V_M_FULL`).
    """
    checks.non_negative("oil_level", oil_level, "m")
    checks.positive("pitch_diameter", pitch_diameter, "m")
    dm = np.asarray(pitch_diameter, dtype=float)
    h = np.minimum(np.asarray(oil_level, dtype=float), DRAG_LEVEL_CAP * dm)
    t = 2.0 * np.arccos(np.clip((_CIRCLE * dm - h) / (_CIRCLE * dm), -1.0, 1.0))
    return V_M_FULL["roller" if roller else "ball"] * (t - np.sin(t)) / (2.0 * np.pi)
