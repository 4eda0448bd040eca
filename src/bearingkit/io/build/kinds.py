"""Input-file types of the bearing kinds: four-point contact ball (QJ), slewing rings, spherical roller,
spherical roller thrust, self-aligning ball and needle roller bearings.

SI inside: the geometry models use the annotated unit types of :mod:`bearingkit.io.schema`, so every
``"25 mm"`` arrives in metres. :func:`register` adds the models to ``schema.GEOMETRY_MODELS`` and the
builders to the loader's registry (called once by :mod:`bearingkit.io.build.builders`); each builder maps the
validated ``[geometry]`` dict onto the keyword arguments of :mod:`bearingkit.bearings.slewing` /
:mod:`bearingkit.bearings.self_aligning`. Defaults of omitted fields are the builders' defaults.
"""

from __future__ import annotations

import dataclasses
from typing import Literal

from pydantic import Field

from bearingkit.io import schema

_ENVELOPE_ONLY = ("bore", "outer_diameter", *schema.SHOULDER_FIELDS)  # not builder arguments


class FourPointContactBallGeometry(schema.BallBase, schema.Shoulders):
    """Single-row four-point contact ball bearing (QJ) — bearings.slewing.four_point_contact_ball."""

    contact_angle: schema.Angle | None = Field(
        None, description="Design contact angle of the gothic arches. Default 35 deg."
    )
    conformity_inner: schema.Dimensionless | None = Field(None, description="Arc radius / D_w. Default 0.52.")
    conformity_outer: schema.Dimensionless | None = Field(None, description="Arc radius / D_w. Default 0.53.")
    clearance_radial: schema.Length | None = Field(
        None,
        description="Radial internal clearance P_d (negative: preload); axial play ≈ P_d/tan α. Default 0.",
    )


class SlewingFourPointGeometry(FourPointContactBallGeometry):
    """Single-row four-point contact ball slewing ring — bearings.slewing.slewing_ring_four_point.

    Defaults: contact_angle 45 deg, conformities 0.53 (assumed typical of slewing rings).
    """


class SlewingEightPointGeometry(SlewingFourPointGeometry):
    """Double-row (eight-point) ball slewing ring — bearings.slewing.slewing_ring_eight_point."""

    row_spacing: schema.PositiveLength = Field(description="Axial distance of the two ball rows.")


class SlewingCrossedRollerGeometry(schema.RollerBase):
    """Crossed roller slewing ring — bearings.slewing.slewing_ring_crossed_roller."""

    contact_angle: schema.Angle | None = Field(None, description="Contact normals ±α. Default 45 deg.")
    clearance_radial: schema.Length | None = Field(
        None, description="Radial internal clearance (negative: preload). Default 0."
    )


class SphericalRollerGeometry(schema.Envelope):
    """Double-row spherical roller bearing — bearings.self_aligning.spherical_roller."""

    n_elements: schema.Count = Field(description="Rollers per row.")
    element_diameter: schema.PositiveLength = Field(description="Roller diameter at the middle D_w.")
    effective_length: schema.PositiveLength
    pitch_diameter: schema.PositiveLength
    contact_angle: schema.Angle = Field(description="Contact angle α of the rows (0 < α < 45 deg).")
    osculation_outer: schema.Dimensionless | None = Field(
        None, description="Roller profile radius / outer sphere radius (0.8 … 1). Default 0.98."
    )
    osculation_inner: schema.Dimensionless | None = Field(
        None, description="Roller profile radius / inner raceway profile radius (0.8 … 1). Default 0.98."
    )
    clearance_radial: schema.Length | None = Field(
        None, description="Radial internal clearance (negative: preload). Default 0."
    )
    n_slices: schema.SliceCount | None = Field(None, description="Slices per contact. Default 15.")
    line_law: Literal["kunert", "iso16281"] | None = None
    stagger: bool | None = Field(None, description="Row B shifted by half a pitch. Default false.")


class SphericalRollerThrustGeometry(schema.Envelope):
    """Spherical roller thrust bearing — bearings.self_aligning.spherical_roller_thrust."""

    n_elements: schema.Count = Field(description="Rollers Z.")
    element_diameter: schema.PositiveLength = Field(description="Roller diameter at the middle D_w.")
    effective_length: schema.PositiveLength
    pitch_diameter: schema.PositiveLength
    contact_angle: schema.Angle = Field(description="Contact angle α (45 < α < 80 deg; catalogue about 50).")
    osculation_outer: schema.Dimensionless | None = Field(
        None, description="Roller profile radius / housing washer sphere radius (0.8 … 1). Default 0.98."
    )
    osculation_inner: schema.Dimensionless | None = Field(
        None,
        description="Roller profile radius / shaft washer raceway profile radius (0.8 … 1). Default 0.98.",
    )
    n_slices: schema.SliceCount | None = Field(None, description="Slices per contact. Default 15.")
    line_law: Literal["kunert", "iso16281"] | None = None


class SelfAligningBallGeometry(schema.BallBase):
    """Double-row self-aligning ball bearing — bearings.self_aligning.self_aligning_ball."""

    contact_angle: schema.Angle = Field(description="Contact angle α of the rows (0 < α < 45 deg).")
    conformity_inner: schema.Dimensionless | None = Field(
        None, description="Inner groove radius / D_w. Default 0.53."
    )
    clearance_radial: schema.Length | None = Field(
        None, description="Radial internal clearance (negative: preload). Default 0."
    )
    stagger: bool | None = Field(None, description="Row B shifted by half a pitch. Default false.")
    shoulder_height_inner: schema.ShoulderHeight | None = Field(
        None, description="Inner groove shoulder height: a length or a fraction of D_w. Default 0.20 D_w."
    )


class NeedleRollerGeometry(schema.RollerBase):
    """Needle roller bearing — bearings.self_aligning.needle_roller."""

    clearance_radial: schema.Length | None = Field(
        None, description="Radial internal clearance (negative: preload). Default 0."
    )
    inner_ring: bool | None = Field(
        None, description="False: the needles run on the shaft (a raceway-grade surface). Default true."
    )
    construction: Literal["machined", "drawn_cup"] | None = Field(
        None, description="Machined rings (NA, RNA) or drawn cup (HK, BK): the ISO 281 b_m. Default machined."
    )


def _profile(geometry: dict):
    from bearingkit.physics.contact.profiles import make_profile

    spec = geometry.get("profile")
    if spec is None:
        return None
    params = {k: v for k, v in spec.items() if k != "name" and v is not None}
    return make_profile(spec["name"], geometry["effective_length"], geometry["element_diameter"], **params)


def _builder(module: str, function: str):
    """A loader builder: ``[geometry]`` (SI) → keyword arguments of ``bearings.<module>.<function>``."""

    def build(geometry: dict, material, name: str):
        from importlib import import_module

        fn = getattr(import_module(f"bearingkit.bearings.{module}"), function)
        kwargs = {k: v for k, v in geometry.items() if v is not None and k not in _ENVELOPE_ONLY}
        if "profile" in kwargs:
            kwargs["profile"] = _profile(geometry)
        model = fn(material=material, **kwargs)
        return dataclasses.replace(model, name=name) if name else model

    return build


#: Bearing type → (geometry model, builder).
KINDS = {
    "four_point_contact_ball": (FourPointContactBallGeometry, _builder("slewing", "four_point_contact_ball")),
    "slewing_ring_four_point": (SlewingFourPointGeometry, _builder("slewing", "slewing_ring_four_point")),
    "slewing_ring_eight_point": (SlewingEightPointGeometry, _builder("slewing", "slewing_ring_eight_point")),
    "slewing_ring_crossed_roller": (
        SlewingCrossedRollerGeometry,
        _builder("slewing", "slewing_ring_crossed_roller"),
    ),
    "spherical_roller": (SphericalRollerGeometry, _builder("self_aligning", "spherical_roller")),
    "spherical_roller_thrust": (
        SphericalRollerThrustGeometry,
        _builder("self_aligning", "spherical_roller_thrust"),
    ),
    "self_aligning_ball": (SelfAligningBallGeometry, _builder("self_aligning", "self_aligning_ball")),
    "needle_roller": (NeedleRollerGeometry, _builder("self_aligning", "needle_roller")),
}


def register(builders: dict, geometry_models: dict) -> None:
    """Add the kinds to the loader's ``BUILDERS`` and to ``schema.GEOMETRY_MODELS`` (idempotent)."""
    for name, (model, build) in KINDS.items():
        geometry_models.setdefault(name, model)
        builders.setdefault(name, build)
