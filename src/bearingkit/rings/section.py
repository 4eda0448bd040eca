"""Cross-section properties of a bearing ring: rectangular, arc-backed (spherical outside), or given.

SI units (m, m², m⁴). The section lies in the axial–radial plane; ``area_moment`` is the second
moment about the centroidal axis parallel to the bearing axis (in-plane ring bending, thin-ring
theory), ``beam_area_moment`` that of the strip used for the axial beam model of the outer ring
between its housing supports (seed 002 eqs. 4–6), whose circumferential width the paper does not
give (see :data:`DEFAULT_BEAM_WIDTH_FRACTION`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit import checks

#: Gauss–Legendre points used to integrate the arc-backed section over its width [–].
N_QUADRATURE = 64
#: Circumferential width of the axial beam strip as a fraction of the ring circumference [–]. Assumed:
#: the loaded half-zone's central quarter, π R/2 (seed 002 gives no value; §3.2 sweeps the deflection).
DEFAULT_BEAM_WIDTH_FRACTION = 0.25


@dataclass(frozen=True)
class RingSection:
    """Section properties of a ring (given directly or from :meth:`rectangular` / :meth:`arc_backed`).

    Parameters
    ----------
    area_moment : float [m⁴]
        Second moment of area for in-plane ring bending (about the axis parallel to the bearing axis).
    area : float [m²]
        Section area.
    width : float [m]
        Axial width of the ring.
    centroid_radius : float [m]
        Radius of the section centroid (the thin ring's R).
    beam_area_moment : float or None [m⁴]
        Second moment of the axial beam strip (None: no beam deflection).
    bore_radius : float or None [m]
        Radius of the inner surface (None: unknown; fibre stresses are then not available).
    outer_radius : float or None [m]
        Largest radius of the outer surface (None: unknown).
    """

    area_moment: float
    area: float
    width: float
    centroid_radius: float
    beam_area_moment: float | None = None
    bore_radius: float | None = None
    outer_radius: float | None = None

    def __post_init__(self):
        checks.positive("area_moment", self.area_moment, "m^4")
        checks.positive("area", self.area, "m^2")
        checks.positive("width", self.width, "m")
        checks.positive("centroid_radius", self.centroid_radius, "m")
        if self.beam_area_moment is not None:
            checks.positive("beam_area_moment", self.beam_area_moment, "m^4")
        if self.bore_radius is not None and not 0 < self.bore_radius < self.centroid_radius:
            raise checks.InputError(
                f"bore_radius ({self.bore_radius:.6g} m) must lie between 0 and the centroid radius "
                f"({self.centroid_radius:.6g} m)"
            )
        if self.outer_radius is not None and not self.outer_radius > self.centroid_radius:
            raise checks.InputError(
                f"outer_radius ({self.outer_radius:.6g} m) must exceed the centroid radius "
                f"({self.centroid_radius:.6g} m)"
            )

    @property
    def inner_fibre(self) -> float | None:
        """Distance of the inner surface from the centroid, r_c − r_b [m] (None if unknown)."""
        return None if self.bore_radius is None else self.centroid_radius - self.bore_radius

    @property
    def outer_fibre(self) -> float | None:
        """Distance of the outermost fibre from the centroid, r_o − r_c [m] (None if unknown)."""
        return None if self.outer_radius is None else self.outer_radius - self.centroid_radius

    @property
    def mean_thickness(self) -> float:
        """Area / width [m]."""
        return self.area / self.width

    @classmethod
    def rectangular(cls, width, thickness, bore_radius, beam_width=None) -> RingSection:
        """Rectangular section b × h at bore radius r_b.

        Parameters
        ----------
        width : float [m]
            Axial width b.
        thickness : float [m]
            Radial wall thickness h.
        bore_radius : float [m]
            Inner radius of the section (outer-ring raceway radius).
        beam_width : float or None [m]
            Circumferential width of the axial beam strip (default π(r_b + h/2)/2).

        Notes
        -----
        .. math:: I = \\frac{b h^3}{12}, \\quad I_{beam} = \\frac{w h^3}{12}
        """
        checks.positive("width", width, "m")
        checks.positive("thickness", thickness, "m")
        checks.positive("bore_radius", bore_radius, "m")
        r_c = bore_radius + thickness / 2
        w = _beam_width(beam_width, r_c)
        return cls(
            width * thickness**3 / 12,
            width * thickness,
            width,
            r_c,
            w * thickness**3 / 12,
            bore_radius=bore_radius,
            outer_radius=bore_radius + thickness,
        )

    @classmethod
    def arc_backed(cls, width, bore_radius, sphere_radius, beam_width=None) -> RingSection:
        """Outer ring with a spherical (self-aligning) outside of radius R_s centred on the axis.

        The wall thickness is h(z) = √(R_s² − z²) − r_b for |z| ≤ b/2.

        Parameters
        ----------
        width : float [m]
        bore_radius : float [m]
            r_b, the bore (raceway) radius; the raceway grooves are not subtracted.
        sphere_radius : float [m]
            R_s, the crown radius of the arc back (half the outer diameter).
        beam_width : float or None [m]

        Notes
        -----
        Integrated in strips dz (Gauss–Legendre):

        .. math:: A = \\int h\\,dz,\\quad r_c = \\frac{1}{A}\\int h\\,(r_b + h/2)\\,dz,\\quad
                  I = \\int \\left[\\frac{h^3}{12} + h\\,(r_b + h/2 - r_c)^2\\right] dz

        The beam strip uses the mean thickness: I_beam = w h̄³/12.
        """
        checks.positive("width", width, "m")
        checks.positive("bore_radius", bore_radius, "m")
        edge = np.sqrt(max(sphere_radius**2 - (width / 2) ** 2, 0.0)) - bore_radius
        if not np.isfinite(sphere_radius) or edge <= 0:
            raise checks.InputError(
                f"sphere_radius ({sphere_radius:.6g} m) leaves no wall at the ring edges: it must exceed "
                f"√(bore_radius² + (width/2)²) = {np.hypot(bore_radius, width / 2):.6g} m"
            )
        x, wq = np.polynomial.legendre.leggauss(N_QUADRATURE)
        z = x * width / 2
        dz = wq * width / 2
        h = np.sqrt(sphere_radius**2 - z**2) - bore_radius
        area = float(np.sum(h * dz))
        mid = bore_radius + h / 2
        r_c = float(np.sum(h * mid * dz) / area)
        inertia = float(np.sum((h**3 / 12 + h * (mid - r_c) ** 2) * dz))
        w = _beam_width(beam_width, r_c)
        return cls(
            inertia,
            area,
            width,
            r_c,
            w * (area / width) ** 3 / 12,
            bore_radius=bore_radius,
            outer_radius=float(sphere_radius),  # the crown of the arc back, at mid-width
        )


def _beam_width(beam_width, r_c) -> float:
    if beam_width is None:
        return DEFAULT_BEAM_WIDTH_FRACTION * 2 * np.pi * r_c
    checks.positive("beam_width", beam_width, "m")
    return float(beam_width)
