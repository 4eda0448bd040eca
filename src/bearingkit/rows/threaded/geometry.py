"""Geometry of a planetary thread roller bearing (PTRB) and the Hertz contacts of its equivalent balls.

SI units (m, N, Pa, rad). Geometry after Zheng et al. (2022), Table 1 and §2: Z threaded rollers on
the pitch diameter D_pw, each with n annular (zero-lead) teeth of pitch P. Every tooth touches the
inner ring (ITP) and the outer ring (OTP); with its contact normals through the roller axis a tooth
flank pair acts as an *equivalent ball* of diameter D_w = d_R / cos α (Zheng et al. 2021).

This module holds

* :class:`PTRBGeometry` — the Table 1 data, validated;
* :func:`contact_pairs` — ITP and OTP curvatures, Hertz ellipse, approach, pressure and stiffness.

It is apart from the row kernel (:mod:`bearingkit.rows.threaded.row`) and the load shares
(:mod:`bearingkit.rows.threaded.distribution`) because both of them, the input reader, the ratings and
the friction model need the geometry and its contacts, and none of them needs the solver's kernel.
:mod:`bearingkit.rows.threaded.row` re-exports these names.

References: ``zheng2022``, ``zheng2021``, ``harris2007`` (ch. 6-7).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics.contact import hertz
from bearingkit.physics.life.ptrb_rating import thread_contact_curvature

__all__ = ["ContactPair", "PTRBGeometry", "contact_pairs"]


@dataclass(frozen=True)
class PTRBGeometry:
    """Structural parameters of a planetary thread roller bearing (Zheng et al. 2022, Table 1).

    Parameters
    ----------
    pitch_diameter : float [m]
        D_pw, pitch diameter of the roller set.
    roller_pitch_diameter : float [m]
        d_R, pitch (contact) diameter of a threaded roller.
    roller_contact_radius : float [m]
        R_rr, flank arc radius of the roller thread.
    n_elements : int
        Z, number of threaded rollers.
    n_teeth : int
        n, thread teeth per roller engaged with each ring.
    contact_angle : float [rad]
        α, flank contact angle, in (0, π/2).
    thread_pitch : float [m]
        P, distance between adjacent teeth.
    dedendum, ridge_thickness : float [m]
        h (lever arm of the root check) and s (tooth thickness on the pitch line), s < P.
    bottom_thickness_roller, bottom_thickness_inner, bottom_thickness_outer : float [m]
        B_R, B_I, B_O, root thicknesses of the teeth.
    bore_diameter, outside_diameter, width : float [m]
        d_0, D_0, H_0 of the envelope (the rollers' thread length n·P must fit in H_0).
    contact_radius_inner, contact_radius_outer : float [m]
        r_I, r_O, flank arc radii of the ring threads (concave, > R_rr); ``inf`` = flat flank. Table 1
        leaves them blank; flat flanks reproduce the paper's C_r exactly (validation cases of
        bearingkit.papers.zheng2022).
    inner_pitch_diameter, outer_pitch_diameter : float [m] or None
        d_I, d_O; None = D_pw ∓ d_R.
    youngs_modulus : float [Pa], poisson_ratio : float
        E, ν of rollers and rings (all GCr15 in the paper).
    """

    pitch_diameter: float
    roller_pitch_diameter: float
    roller_contact_radius: float
    n_elements: int
    n_teeth: int
    contact_angle: float
    thread_pitch: float
    dedendum: float
    ridge_thickness: float
    bottom_thickness_roller: float
    bottom_thickness_inner: float
    bottom_thickness_outer: float
    bore_diameter: float
    outside_diameter: float
    width: float
    contact_radius_inner: float = float("inf")
    contact_radius_outer: float = float("inf")
    inner_pitch_diameter: float | None = None
    outer_pitch_diameter: float | None = None
    youngs_modulus: float = 212.0e9
    poisson_ratio: float = 0.29

    def __post_init__(self):
        for f in (
            "pitch_diameter",
            "roller_pitch_diameter",
            "roller_contact_radius",
            "thread_pitch",
            "dedendum",
            "ridge_thickness",
            "bottom_thickness_roller",
            "bottom_thickness_inner",
            "bottom_thickness_outer",
            "bore_diameter",
            "outside_diameter",
            "width",
            "youngs_modulus",
        ):
            checks.positive(f, getattr(self, f), "Pa" if f == "youngs_modulus" else "m")
        checks.integer("n_elements", self.n_elements, low=3)
        checks.integer("n_teeth", self.n_teeth, low=1)
        checks.in_range("contact_angle", self.contact_angle, 0.0, np.pi / 2, "rad", closed=False)
        checks.in_range("poisson_ratio", self.poisson_ratio, 0.0, 0.5, closed=False)
        for f in ("contact_radius_inner", "contact_radius_outer"):
            val = float(getattr(self, f))
            if not (val > float(self.roller_contact_radius)):  # also rejects NaN
                raise InputError(
                    f"{f} ({val:.6g} m) must exceed roller_contact_radius "
                    f"({self.roller_contact_radius:.6g} m): "
                    "the ring flank must conform less than the roller flank (inf = flat flank)"
                )
        if self.ridge_thickness >= self.thread_pitch:
            raise InputError(
                f"ridge_thickness ({self.ridge_thickness:.6g} m) must be less than thread_pitch "
                f"({self.thread_pitch:.6g} m)"
            )
        length = self.n_teeth * self.thread_pitch
        if length > self.width * (1 + 1e-12):
            raise InputError(
                f"n_teeth ({self.n_teeth}) do not fit the roller: n_teeth·thread_pitch ({length:.6g} m) must "
                f"not exceed the width ({self.width:.6g} m)"
            )
        d_i, d_o = self.d_inner, self.d_outer
        checks.greater(
            "pitch_diameter", self.pitch_diameter, "roller_pitch_diameter", self.roller_pitch_diameter, "m"
        )
        checks.greater("inner_pitch_diameter", d_i, "bore_diameter", self.bore_diameter, "m")
        checks.greater("outside_diameter", self.outside_diameter, "outer_pitch_diameter", d_o, "m")
        if not d_i < self.pitch_diameter < d_o:
            raise InputError(
                f"pitch_diameter ({self.pitch_diameter:.6g} m) must lie between inner_pitch_diameter "
                f"({d_i:.6g} m) and outer_pitch_diameter ({d_o:.6g} m)"
            )
        if np.pi * self.pitch_diameter / self.n_elements < self.roller_pitch_diameter:
            raise InputError(
                f"n_elements ({self.n_elements}) rollers of roller_pitch_diameter "
                f"{self.roller_pitch_diameter:.6g} m do not fit on the pitch circle "
                f"(π·D_pw/Z = {np.pi * self.pitch_diameter / self.n_elements:.6g} m)"
            )

    # -- derived quantities (cheap, no physics) ---------------------------------------------------
    @property
    def d_inner(self) -> float:
        """d_I [m] (given, or D_pw − d_R)."""
        if self.inner_pitch_diameter is not None:
            return float(self.inner_pitch_diameter)
        return float(self.pitch_diameter - self.roller_pitch_diameter)

    @property
    def d_outer(self) -> float:
        """d_O [m] (given, or D_pw + d_R)."""
        if self.outer_pitch_diameter is not None:
            return float(self.outer_pitch_diameter)
        return float(self.pitch_diameter + self.roller_pitch_diameter)

    @property
    def element_diameter(self) -> float:
        """Equivalent ball diameter D_w = d_R / cos α [m]."""
        return float(self.roller_pitch_diameter / np.cos(self.contact_angle))

    @property
    def gamma(self) -> float:
        """γ = d_R / D_pw [1]."""
        return float(self.roller_pitch_diameter / self.pitch_diameter)

    @property
    def e_reduced(self) -> float:
        """E′ = E/(1 − ν²) of the steel–steel contacts [Pa]."""
        return float(self.youngs_modulus / (1.0 - self.poisson_ratio**2))

    def replace(self, **changes) -> PTRBGeometry:
        """A copy with fields changed (validated again)."""
        from dataclasses import replace

        return replace(self, **changes)


class ContactPair(NamedTuple):
    """Hertz data of the ITP or OTP contact of one equivalent ball (arrays over the load's shape)."""

    side: str
    curvature_sum: np.ndarray  #: Σρ [1/m]
    curvature_difference: np.ndarray  #: F(ρ) [1]
    stiffness_point: np.ndarray  #: K [N/m^1.5]
    semi_major: np.ndarray  #: a [m]
    semi_minor: np.ndarray  #: b [m]
    deflection: np.ndarray  #: δ [m]
    max_pressure: np.ndarray  #: p_max [Pa]
    ellipticity: np.ndarray  #: κ [1]


def contact_pairs(geometry: PTRBGeometry, load=0.0) -> dict[str, ContactPair]:
    """ITP and OTP contacts of one equivalent ball under a normal load.

    Parameters
    ----------
    geometry : PTRBGeometry
    load : array_like
        Normal contact load Q [N] (the same on ITP and OTP of one tooth).

    Returns
    -------
    dict
        ``{"inner": ContactPair, "outer": ContactPair}``.

    Notes
    -----
    Curvatures from :func:`bearingkit.physics.life.ptrb_rating.thread_contact_curvature`; Hertz solution and
    stiffness K from :mod:`bearingkit.physics.contact.hertz` (exact elliptic integrals).
    """
    g = geometry
    out = {}
    for side, d_x, r_x in (
        ("inner", g.d_inner, g.contact_radius_inner),
        ("outer", g.d_outer, g.contact_radius_outer),
    ):
        s, f, _, _ = thread_contact_curvature(
            g.roller_pitch_diameter, d_x, g.roller_contact_radius, r_x, g.contact_angle, side
        )
        c = hertz.point_contact(load, s, f, g.e_reduced)
        k = hertz.point_stiffness(s, f, g.e_reduced)
        out[side] = ContactPair(
            side, s, f, k, c.semi_major, c.semi_minor, c.deflection, c.max_pressure, c.ellipticity
        )
    return out
