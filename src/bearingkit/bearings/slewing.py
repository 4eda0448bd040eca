"""Builders of four-point contact ball bearings (QJ) and slewing rings from their internal geometry.

SI units. Each builder returns a :class:`~bearingkit.analysis.solver.model.BearingModel`; the keyword
arguments
are the internal geometry (element count and size, pitch diameter, conformities, contact angle,
clearance), so a catalogue of designations can call them with its estimates.

- :func:`four_point_contact_ball` — single-row QJ bearing (gothic arches on both rings, α₀ = 35°);
- :func:`slewing_ring_four_point` — single-row four-point contact ball slewing ring (α₀ = 45°);
- :func:`slewing_ring_eight_point` — double-row ball slewing ring ("eight-point": two four-point rows);
- :func:`slewing_ring_crossed_roller` — crossed roller slewing ring (rollers alternately at ±45°).

Slewing rings carry axial force, radial force and tilting moment together; the static load diagram of
allowable axial force versus tilting moment is :mod:`bearingkit.analysis.slewing`.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.bearings.common import e_reduced_of
from bearingkit.rows.ball.four_point import FourPointRow
from bearingkit.rows.cylindrical.crossed import CrossedRollerRow

#: Design contact angle of QJ four-point contact ball bearings [rad] (SKF/ISO series QJ 2, QJ 3: 35°).
QJ_CONTACT_ANGLE = np.radians(35.0)
#: Nominal contact angle of ball and crossed roller slewing rings [rad] (the makers' usual 45°).
SLEWING_CONTACT_ANGLE = np.radians(45.0)
#: Arc radius over ball diameter of slewing-ring raceways [-]: an osculation D_w/(2r) ≈ 0.94, typical of
#: the four-point slewing-bearing literature (e.g. Amasorrain et al. 2003; Aguirrebeitia et al. 2012 use
#: 0.94-0.96). Assumed default; give the real value when known.
SLEWING_CONFORMITY = 0.53
#: Metadata key telling the faces that a model is a slewing ring (load diagram in the report).
SLEWING_KEY = "slewing_ring"
_REFS = ("harris2007", "amasorrain2003")


def _four_point(
    name,
    row_name,
    n_elements,
    element_diameter,
    pitch_diameter,
    contact_angle,
    fi,
    fo,
    clearance,
    material,
    axial_position=0.0,
):
    return FourPointRow(
        n_elements=n_elements,
        element_diameter=element_diameter,
        pitch_diameter=pitch_diameter,
        contact_angle=contact_angle,
        conformity_inner=fi,
        conformity_outer=fo,
        clearance=clearance,
        axial_position=axial_position,
        e_reduced=e_reduced_of(material),
        name=row_name,
    )


def four_point_contact_ball(
    *,
    n_elements: int,
    element_diameter: float,
    pitch_diameter: float,
    contact_angle: float = QJ_CONTACT_ANGLE,
    conformity_inner: float = 0.52,
    conformity_outer: float = 0.53,
    clearance_radial: float = 0.0,
    material=None,
    name: str = "four-point contact ball bearing",
) -> BearingModel:
    """Single-row four-point contact ball bearing (QJ): gothic arches on both rings.

    Parameters
    ----------
    n_elements : int
        Balls Z.
    element_diameter, pitch_diameter : float [m]
        D_w and d_m.
    contact_angle : float [rad]
        Design contact angle α₀ of the arches (QJ: 35°).
    conformity_inner, conformity_outer : float
        Arc radius over ball diameter (> 0.5).
    clearance_radial : float [m]
        Radial internal clearance P_d (negative = preload); the axial play is about P_d/tan α₀.
    material : Material or None
        Ring and ball material (GCr15 by default).
    name : str
    """
    row = _four_point(
        name,
        "balls",
        n_elements,
        element_diameter,
        pitch_diameter,
        contact_angle,
        conformity_inner,
        conformity_outer,
        clearance_radial,
        material,
    )
    return BearingModel((row,), name=name, references=_REFS)


def slewing_ring_four_point(
    *,
    n_elements: int,
    element_diameter: float,
    pitch_diameter: float,
    contact_angle: float = SLEWING_CONTACT_ANGLE,
    conformity_inner: float = SLEWING_CONFORMITY,
    conformity_outer: float = SLEWING_CONFORMITY,
    clearance_radial: float = 0.0,
    material=None,
    name: str = "four-point contact ball slewing ring",
) -> BearingModel:
    """Single-row four-point contact ball slewing ring (large d_m, many balls, α₀ = 45°).

    Parameters as :func:`four_point_contact_ball`. The model carries ``metadata["slewing_ring"]`` so
    reports draw its static load diagram.
    """
    row = _four_point(
        name,
        "balls",
        n_elements,
        element_diameter,
        pitch_diameter,
        contact_angle,
        conformity_inner,
        conformity_outer,
        clearance_radial,
        material,
    )
    return BearingModel((row,), name=name, references=_REFS, metadata={SLEWING_KEY: "four_point"})


def slewing_ring_eight_point(
    *,
    n_elements: int,
    element_diameter: float,
    pitch_diameter: float,
    row_spacing: float,
    contact_angle: float = SLEWING_CONTACT_ANGLE,
    conformity_inner: float = SLEWING_CONFORMITY,
    conformity_outer: float = SLEWING_CONFORMITY,
    clearance_radial: float = 0.0,
    material=None,
    name: str = "double-row ball slewing ring (eight-point)",
) -> BearingModel:
    """Double-row four-point contact ball slewing ring ("eight-point"): two equal rows ``row_spacing`` apart.

    Parameters
    ----------
    n_elements : int
        Balls per row.
    row_spacing : float [m]
        Axial distance of the two ball rows (> element_diameter).
    Others as :func:`slewing_ring_four_point` (both rows alike).
    """
    checks.positive("row_spacing", row_spacing, "m")
    if row_spacing <= np.max(element_diameter):
        raise checks.InputError(
            f"row_spacing ({row_spacing:.6g} m) must exceed element_diameter "
            f"({np.max(element_diameter):.6g} m): the two ball rows would overlap"
        )
    rows = tuple(
        _four_point(
            name,
            f"balls_{label}",
            n_elements,
            element_diameter,
            pitch_diameter,
            contact_angle,
            conformity_inner,
            conformity_outer,
            clearance_radial,
            material,
            axial_position=z,
        )
        for label, z in (("lower", -row_spacing / 2), ("upper", row_spacing / 2))
    )
    return BearingModel(rows, name=name, references=_REFS, metadata={SLEWING_KEY: "eight_point"})


def slewing_ring_crossed_roller(
    *,
    n_elements: int,
    element_diameter: float,
    effective_length: float,
    pitch_diameter: float,
    contact_angle: float = SLEWING_CONTACT_ANGLE,
    clearance_radial: float = 0.0,
    n_slices: int = 10,
    profile=None,
    line_law: str = "kunert",
    material=None,
    name: str = "crossed roller slewing ring",
) -> BearingModel:
    """Crossed roller slewing ring: Z rollers (even) alternately at ±``contact_angle``.

    Parameters
    ----------
    n_elements : int
        Rollers Z (half each way).
    element_diameter, effective_length, pitch_diameter : float [m]
        D_w, l (≤ D_w) and d_m.
    contact_angle : float [rad]
        α of the contact normals (45°).
    clearance_radial : float [m]
        Diametral radial clearance (negative = preload).
    n_slices, profile, line_law
        As :class:`~bearingkit.rows.cylindrical.crossed.CrossedRollerRow`.
    """
    row = CrossedRollerRow(
        n_elements=n_elements,
        element_diameter=element_diameter,
        effective_length=effective_length,
        pitch_diameter=pitch_diameter,
        contact_angle=contact_angle,
        clearance=clearance_radial,
        n_slices=n_slices,
        profile=profile,
        line_law=line_law,
        e_reduced=e_reduced_of(material),
        name="rollers",
    )
    return BearingModel(
        (row,), name=name, references=("harris2007", "kunert1961"), metadata={SLEWING_KEY: "crossed_roller"}
    )
