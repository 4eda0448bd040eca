"""Builders of self-aligning bearings (spherical roller, self-aligning ball) and needle roller bearings.

SI units. Each builder returns a :class:`~bearingkit.analysis.solver.model.BearingModel` from the internal
geometry (per-row element count, element size, pitch diameter, osculations or conformity, contact
angle, clearance), the parameters a designation catalogue estimates.

The self-aligning bearings are two rows on one spherical outer raceway centred at the bearing centre
(the origin): they carry radial and axial force but no moment, at any misalignment (see
:mod:`bearingkit.rows.self_aligning`). A moment on a free tilt is refused by the solver; fix the tilts
(``free = [True, True, True, False, False]``) to impose a misalignment.

The spherical roller thrust bearing (series 292, 293, 294) is one row of the same kind at 45° < α ≤ 80°
(catalogue bearings about 50°): the housing washer's sphere is centred on the axis where the rollers'
load lines meet it; it carries an axial load with a radial load of up to about F_r ≤ 0.55 F_a (NSK
E1102 B225: ISO 281's e = 1.5 tan α at tan α = 1.2), and, like the radial kinds, no moment.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.bearings.common import e_reduced_of
from bearingkit.rows.cylindrical.needle import NeedleRow
from bearingkit.rows.self_aligning import SelfAligningBallRow, SphericalRollerRow


def _two_rows(cls, contact_angle, stagger, n_elements, **row):
    """Rows ``row_A`` (+α, at +z) and ``row_B`` (−α), row B shifted half a pitch when staggered."""
    checks.in_range("contact_angle", contact_angle, 0.0, np.pi / 4, "rad", closed=False)
    phase = np.pi / n_elements if stagger else 0.0
    return (
        cls(n_elements=n_elements, contact_angle=contact_angle, azimuth_phase=0.0, name="row_A", **row),
        cls(n_elements=n_elements, contact_angle=-contact_angle, azimuth_phase=phase, name="row_B", **row),
    )


def spherical_roller(
    *,
    n_elements: int,
    element_diameter: float,
    effective_length: float,
    pitch_diameter: float,
    contact_angle: float,
    osculation_outer: float = 0.98,
    osculation_inner: float = 0.98,
    clearance_radial: float = 0.0,
    n_slices: int = 15,
    line_law: str = "kunert",
    stagger: bool = False,
    material=None,
    name: str = "spherical roller bearing",
) -> BearingModel:
    """Double-row spherical roller bearing: symmetric barrel rollers on a spherical outer raceway.

    Parameters
    ----------
    n_elements : int
        Rollers per row.
    element_diameter : float [m]
        Roller diameter at the middle D_w.
    effective_length : float [m]
        Effective roller length l.
    pitch_diameter : float [m]
        Pitch diameter d_m of the roller centres.
    contact_angle : float [rad]
        α of the rows (0 < α < 45°; catalogue 222/223 series about 9°-15°).
    osculation_outer, osculation_inner : float
        Roller profile radius over raceway profile radius (0.8 … 1).
    clearance_radial : float [m]
        Radial internal clearance P_d (negative = preload).
    n_slices : int
        Slices per contact.
    line_law : str
        ``"kunert"`` or ``"iso16281"``.
    stagger : bool
        Shift row B by half a roller pitch (False: the rows' rollers face each other).
    material : Material or None
    name : str

    Returns
    -------
    BearingModel
        Rows ``row_A`` (α > 0, at +z, carries +F_z) and ``row_B`` (α < 0).
    """
    rows = _two_rows(
        SphericalRollerRow,
        contact_angle,
        stagger,
        n_elements,
        element_diameter=element_diameter,
        effective_length=effective_length,
        pitch_diameter=pitch_diameter,
        osculation_outer=osculation_outer,
        osculation_inner=osculation_inner,
        clearance=clearance_radial,
        n_slices=n_slices,
        line_law=line_law,
        e_reduced=e_reduced_of(material),
    )
    return BearingModel(rows, name=name, references=("harris2007", "kunert1961", "iso16281"))


def spherical_roller_thrust(
    *,
    n_elements: int,
    element_diameter: float,
    effective_length: float,
    pitch_diameter: float,
    contact_angle: float,
    osculation_outer: float = 0.98,
    osculation_inner: float = 0.98,
    n_slices: int = 15,
    line_law: str = "kunert",
    material=None,
    name: str = "spherical roller thrust bearing",
) -> BearingModel:
    """Spherical roller thrust bearing: one row of barrel rollers on the housing washer's sphere.

    Parameters
    ----------
    n_elements : int
        Rollers Z.
    element_diameter : float [m]
        Roller diameter at the middle D_w.
    effective_length : float [m]
        Effective roller length l.
    pitch_diameter : float [m]
        Pitch diameter d_m of the roller centres.
    contact_angle : float [rad]
        α of the row, 45° < α < 80° (catalogue 292/293/294 series about 50°).
    osculation_outer, osculation_inner : float
        Roller profile radius over the housing washer's sphere radius and over the shaft washer's
        raceway profile radius (0.8 … 1).
    n_slices : int
        Slices per contact.
    line_law : str
        ``"kunert"`` or ``"iso16281"``.
    material : Material or None
    name : str

    Returns
    -------
    BearingModel
        One row ``rollers`` (α > 0: carries +F_z on the shaft washer, the "inner ring"). A single-direction
        thrust bearing has no internal clearance to speak of: the row starts at first touch.
    """
    checks.in_range(
        "contact_angle", contact_angle, np.pi / 4, SphericalRollerRow.max_contact_angle, "rad", closed=False
    )
    row = SphericalRollerRow(
        n_elements=n_elements,
        element_diameter=element_diameter,
        effective_length=effective_length,
        pitch_diameter=pitch_diameter,
        contact_angle=contact_angle,
        osculation_outer=osculation_outer,
        osculation_inner=osculation_inner,
        clearance=0.0,
        n_slices=n_slices,
        line_law=line_law,
        e_reduced=e_reduced_of(material),
        name="rollers",
    )
    return BearingModel((row,), name=name, references=("harris2007", "kunert1961", "iso16281"))


def self_aligning_ball(
    *,
    n_elements: int,
    element_diameter: float,
    pitch_diameter: float,
    contact_angle: float,
    conformity_inner: float = 0.53,
    clearance_radial: float = 0.0,
    stagger: bool = False,
    material=None,
    name: str = "self-aligning ball bearing",
) -> BearingModel:
    """Double-row self-aligning ball bearing: grooved inner ring, spherical outer raceway.

    Parameters
    ----------
    n_elements : int
        Balls per row.
    element_diameter, pitch_diameter : float [m]
        D_w and d_m.
    contact_angle : float [rad]
        α of the rows (0 < α < 45°; 12/22 series about 7°-15°).
    conformity_inner : float
        Inner groove radius over ball diameter (> 0.5).
    clearance_radial : float [m]
        Radial internal clearance P_d (negative = preload).
    stagger : bool
        Shift row B by half a ball pitch.
    material : Material or None
    name : str
    """
    rows = _two_rows(
        SelfAligningBallRow,
        contact_angle,
        stagger,
        n_elements,
        element_diameter=element_diameter,
        pitch_diameter=pitch_diameter,
        conformity_inner=conformity_inner,
        clearance=clearance_radial,
        e_reduced=e_reduced_of(material),
    )
    return BearingModel(rows, name=name, references=("harris2007",))


def needle_roller(
    *,
    n_elements: int,
    element_diameter: float,
    effective_length: float,
    pitch_diameter: float,
    clearance_radial: float = 0.0,
    inner_ring: bool = True,
    construction: str = "machined",
    n_slices: int = 20,
    profile=None,
    line_law: str = "kunert",
    material=None,
    name: str = "needle roller bearing",
) -> BearingModel:
    """Needle roller bearing (NA/RNA machined, HK/BK drawn cup), with or without inner ring.

    Parameters
    ----------
    n_elements : int
        Needles Z.
    element_diameter, effective_length, pitch_diameter : float [m]
        D_w, l (≥ 2.5 D_w) and d_m.
    clearance_radial : float [m]
        Radial internal clearance (negative = preload).
    inner_ring : bool
        False: the needles run on the shaft (RNA, HK), which must be a raceway-grade surface.
    construction : str
        ``"machined"`` or ``"drawn_cup"`` (ISO 281 b_m).
    n_slices, profile, line_law
        As :class:`~bearingkit.rows.cylindrical.row.CylindricalRow`.
    """
    row = NeedleRow(
        n_elements=n_elements,
        element_diameter=element_diameter,
        effective_length=effective_length,
        pitch_diameter=pitch_diameter,
        clearance=clearance_radial,
        n_slices=n_slices,
        profile=profile,
        line_law=line_law,
        inner_ring=inner_ring,
        construction=construction,
        e_reduced=e_reduced_of(material),
    )
    return BearingModel((row,), name=name, references=("harris2007", "kunert1961"))
