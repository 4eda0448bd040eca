"""Meridian-plane geometry of one tapered roller, and the constants tapered rows share. SI units.

Used by the row data (:mod:`bearingkit.rows.tapered.row`) and the solver kernel
(:mod:`bearingkit.rows.tapered.kernel`); the frame and symbols are described in
:mod:`bearingkit.rows.tapered.row`. Local coordinates: radial r and axial s (σ = +1), the roller centre at
the pitch radius, s = 0.
"""

from __future__ import annotations

import numpy as np

#: Line-contact exponent (Kunert 1961; seed 001 eq. 3).
LINE_EXPONENT = 10.0 / 9.0
#: Hertz point-contact exponent for the rib (seed 001 eq. 3).
POINT_EXPONENT = 1.5
#: Deviation models: "exact" adds Δ to the approach; "taylor" is seed 001 eq. (4) (first order in Δ).
DEVIATION_MODELS = ("exact", "taylor")
#: Largest angle between the rib force n_f and the roller axis a for which the rib can hold the
#: roller [rad] (bearingkit's consistency limit: rib faces are within a few degrees of normal to
#: the roller axis in practice; beyond 30° the geometry is not a tapered roller bearing rib).
MAX_FLANGE_TILT = np.pi / 6
#: Relative tolerance on the consistency of roller angle, raceway angles and end diameters [-]
#: (Table 1 of seed 001 is given to 3–4 digits: tan ε from the diameters is 0.02617, 0.0262 given).
ANGLE_CONSISTENCY_RTOL = 0.02
#: Default rib contact height above the cone-side edge of the roller end, as a fraction of the large
#: end diameter [-]. Choice (seed 001 does not give e_r): rib contacts sit in the lower half of the
#: end face, typically 0.2–0.4 D.
DEFAULT_FLANGE_HEIGHT_RATIO = 0.25
#: Default radius of the spherical roller end as a fraction of the apex distance of the large end
#: [-]. Choice (not in seed 001): spherical ends of 0.8–0.95 of the apex length are usual; it only sets
#: the rib stiffness K_f, which barely matters (the rib load follows from equilibrium).
DEFAULT_END_RADIUS_RATIO = 0.9
#: Density of bearing steel [kg/m³] (GCr15 / 100Cr6: 7.8e3–7.85e3).
STEEL_DENSITY = 7830.0


def _rot(v):
    return np.array([-v[1], v[0]])


def _cross2(p, v):
    """Moment p × v of a meridian-plane force v at point p (r, s components)."""
    return p[0] * v[1] - p[1] * v[0]


class TapGeometry:
    """Meridian-plane geometry of one tapered roller (local r, s coordinates, σ = +1)."""

    def __init__(self, row):
        """``row``: a :class:`~bearingkit.rows.tapered.row.TaperedRow` (any object with its fields)."""
        ae, ai = float(row.contact_angle_outer), float(row.contact_angle_inner)
        self.eps = row.half_angle
        self.kappa = row.cone_axis_angle
        self.n_e = np.array([np.cos(ae), np.sin(ae)])
        self.n_i = np.array([np.cos(ai), np.sin(ai)])
        self.t_e, self.t_i = _rot(self.n_e), _rot(self.n_i)  # t = (−sin α, cos α), towards the apex
        self.a = np.array([-np.sin(self.kappa), np.cos(self.kappa)])
        self.e = np.array([np.cos(self.kappa), np.sin(self.kappa)])
        phi = float(row.flange_angle)
        self.n_f = np.sin(phi) * self.t_i - np.cos(phi) * self.n_i
        self.r_m = 0.5 * row.element_diameter
        self.length = float(row.effective_length)
        self.centre = np.array([0.5 * float(row.pitch_diameter), 0.0])
        self.d_l = float(row.large_diameter)
        e_r = (
            DEFAULT_FLANGE_HEIGHT_RATIO * self.d_l
            if row.flange_contact_height is None
            else row.flange_contact_height
        )
        self.flange_height = float(e_r)
        end_centre = self.centre - 0.5 * self.length * self.a
        self.p_f = end_centre - (0.5 * self.d_l - self.flange_height) * self.e
        # Radii of the cone and cup contact points at mid-length (seed 001 R_i, R_e).
        self.radius_inner = float((self.centre - self.r_m * self.e)[0])
        self.radius_outer = float((self.centre + self.r_m * self.e)[0])
        self.radius_flange = float(self.p_f[0])
        # Apex distance of the large end: the roller axis meets the bearing axis at t = R/sin κ.
        self.apex_distance = float(self.centre[0] / np.sin(self.kappa) + 0.5 * self.length)
        # Curvature radii in the rolling direction at mid-length (cone convex, cup concave).
        rr = self.r_m / np.cos(self.eps)
        self.radius_x_inner = 1.0 / (1.0 / rr + np.cos(ai) / self.radius_inner)
        self.radius_x_outer = 1.0 / (1.0 / rr - np.cos(ae) / self.radius_outer)
        # Frustum volume and mass-centre radius (mass centre ≈ mid-length at the pitch radius).
        rs, rl = 0.5 * float(row.small_diameter), 0.5 * float(row.large_diameter)
        self.volume = np.pi * self.length * (rs * rs + rs * rl + rl * rl) / 3.0
