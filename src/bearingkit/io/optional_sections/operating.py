"""Input sections of the operating conditions: ``[operating]``, ``[fits]``, ``[lubrication]``, ``[thermal]``;
and ``[structure]`` (its model in :mod:`bearingkit.io.optional_sections.structure`), validated the same way.

SI after validation (m, N, rad, rad/s, W/K; temperatures in °C), as the rest of the schema
(:mod:`bearingkit.io.schema`, whose unit-carrying types these models use). The sections are kept as
tables in :class:`~bearingkit.io.schema.BearingFile` and validated here, the way the geometry is
validated by its own model; :func:`validate_sections` gives the parsed sections (docs/operating.md).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from pydantic import Field, ValidationError

from bearingkit.io.optional_sections.structure import StructureSpec
from bearingkit.io.schema import (
    Angle,
    AngularVelocity,
    Dimensionless,
    Length,
    NonNegativeLength,
    PositiveLength,
    Strict,
    Temperature,
    quantity,
)


class OperatingSpec(Strict):
    """``[operating]``: speed effects, imposed misalignment, preload and temperatures (docs/operating.md)."""

    speed_effects: bool | None = Field(
        None, description="Element inertia at speed in the statics (centrifugal force, gyroscopic moment)."
    )
    raceway_control: Literal["outer", "inner"] | None = Field(
        None, description="Ball spin-axis hypothesis at speed (default outer)."
    )
    tilt_x: Angle | None = Field(None, description="Imposed tilt θ_x of the inner ring against the outer.")
    tilt_y: Angle | None = Field(None, description="Imposed tilt θ_y of the inner ring against the outer.")
    preload_force: quantity("force", "positive") | None = Field(
        None, description="Axial preload force (the solver finds the displacement)."
    )
    preload_displacement: quantity("length", "positive") | None = Field(
        None, description="Axial preload as a displacement (interference of the rows)."
    )
    temperature_inner_ring: Temperature | None = None
    temperature_outer_ring: Temperature | None = None
    temperature_shaft: Temperature | None = None
    temperature_housing: Temperature | None = None
    temperature_elements: Temperature | None = None
    temperature_ambient: Temperature | None = Field(
        None, description="Ambient (heat balance), default 20 °C."
    )
    heat_dissipation: quantity("thermal_conductance", "positive") | None = Field(
        None, description="Heat flow out of the bearing per kelvin above ambient (heat balance)."
    )


class FitsSpec(Strict):
    """``[fits]``: shaft and housing seats → operating clearance (docs/operating.md)."""

    shaft: str | None = Field(None, description="ISO 286 field of the shaft seat, e.g. k5.")
    housing: str | None = Field(None, description="ISO 286 field of the housing seat, e.g. H7.")
    statistic: Literal["mean", "min", "max"] | Dimensionless = Field(
        "mean", description="mean, min, max or a percentile in (0, 100)."
    )
    shaft_interference: Length | None = None
    housing_interference: Length | None = None
    shaft_bore: NonNegativeLength | None = Field(None, description="Bore of a hollow shaft.")
    housing_outer_diameter: PositiveLength | None = Field(None, description="Default: a large housing.")
    shaft_material: str | None = Field(None, description="Material preset (default structural_steel).")
    housing_material: str | None = Field(None, description="Material preset (default structural_steel).")


class LubricationSpec(Strict):
    """``[lubrication]``: cleanliness, roughness and grease data (docs/operating.md)."""

    contamination: str | Dimensionless | None = Field(
        None, description="ISO 281 e_C or a level name (normal_cleanliness, slight_contamination, …)."
    )
    roughness_element: NonNegativeLength | None = None
    roughness_raceway: NonNegativeLength | None = None
    grease: Literal["general_purpose", "wide_range"] | None = None
    grease_limiting_speed: AngularVelocity | None = Field(
        None, description="Catalogue limiting speed with grease (grease life)."
    )
    method: Literal["grease", "oil_bath", "oil_jet", "oil_air"] | None = Field(
        None,
        description="Lubrication method (SKF friction K_rs and drag, limiting speed); default grease for a "
        "grease or a sealed bearing, else oil_bath.",
    )
    oil_level: NonNegativeLength | None = Field(
        None,
        description="Oil bath level H above the lowest point of the outer ring raceway (SKF drag losses).",
    )
    drag_loss_factor: Dimensionless | None = Field(
        None, description="SKF drag loss factor V_M read from SKF's diagram; default approximated."
    )


class ThermalSpec(Strict):
    """``[thermal]``: find the operating temperature by a heat balance (docs/operating.md, "Thermal
    equilibrium"). Its presence switches the balance on: friction heat = heat through the seats and
    housing + heat carried away by a circulating oil."""

    ambient: Temperature | None = Field(None, description="Ambient (heat sink) temperature, default 20 °C.")
    heat_dissipation: quantity("thermal_conductance", "positive") | None = Field(
        None, description="Heat flow through seats and housing per kelvin above ambient (H)."
    )
    housing_area: quantity("area", "positive") | None = Field(
        None, description="Heat-transferring outer surface of the housing (H = area × coefficient)."
    )
    heat_transfer_coefficient: quantity("heat_transfer_coefficient", "positive") | None = Field(
        None, description="Convection plus radiation from the housing surface, e.g. '15 W/(m^2*K)'."
    )
    oil_flow: quantity("volume_flow", "non_negative") | None = Field(
        None, description="Circulating oil through the bearing, e.g. '0.5 l/min'."
    )
    oil_inlet_temperature: Temperature | None = Field(
        None, description="Temperature of the circulating oil at the inlet (default: the ambient)."
    )


@dataclass(frozen=True)
class OperatingSections:
    """The parsed ``[operating]``, ``[fits]``, ``[lubrication]`` and ``[thermal]`` sections (None where
    absent)."""

    operating: OperatingSpec | None = None
    fits: FitsSpec | None = None
    lubrication: LubricationSpec | None = None
    thermal: ThermalSpec | None = None
    structure: StructureSpec | None = None


#: Section name → model.
SECTION_MODELS = {
    "operating": OperatingSpec,
    "fits": FitsSpec,
    "lubrication": LubricationSpec,
    "thermal": ThermalSpec,
    "structure": StructureSpec,
}


def validate_sections(spec, source: str, one_line) -> OperatingSections:
    """Validate the operating sections of a parsed file.

    ``one_line(source, exc, prefix, models)`` turns a validation error into the one-line InputError.
    """
    out = {}
    for name, model in SECTION_MODELS.items():
        raw = getattr(spec, name, None)
        if raw is None:
            continue
        try:
            out[name] = model.model_validate(raw)
        except ValidationError as exc:
            raise one_line(source, exc, (name,), {name: model}) from None
    return OperatingSections(**out)
