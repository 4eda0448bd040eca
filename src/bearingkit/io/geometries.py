"""Geometry models of the input file, one per ``bearing.type`` (the ``[geometry]`` table).

Field names are the builders' keyword names (docs/nomenclature.md); values arrive as strings with
units and leave as SI floats (:mod:`bearingkit.io.fields`). :data:`GEOMETRY_MODELS` maps each bearing
type to its model; the loader's builder registry uses the same keys. Defaults of omitted fields are
the builders' defaults: :func:`_describe_defaults` writes them into the field descriptions (and so
into the JSON Schema) without repeating them here.
"""

from __future__ import annotations

import dataclasses
import inspect
from typing import Annotated, Literal

from pydantic import BaseModel, BeforeValidator, Field, ValidationInfo, WithJsonSchema, model_validator

from bearingkit import units
from bearingkit.errors import InputError, quote
from bearingkit.io.fields import (
    Angle,
    Count,
    Dimensionless,
    Length,
    NonNegativeLength,
    NonNegativeStiffnessPerLength,
    PositiveForce,
    PositiveLength,
    PositivePressure,
    ShoulderHeight,
    SliceCount,
    Strict,
)


# ---------------------------------------------------------------------------------------------
# Geometry models, one per bearing type. Field names are the builders' keyword names (nomenclature).
# ---------------------------------------------------------------------------------------------
class ProfileSpec(Strict):
    """Crowning profile: a registry name of :mod:`bearingkit.physics.contact.profiles` and its parameters."""

    name: str
    crown_radius: PositiveLength | None = None
    end_drop: NonNegativeLength | None = None
    flat_length: NonNegativeLength | None = None
    semi_minor: PositiveLength | None = None
    design_load: PositiveForce | None = None
    e_reduced: PositivePressure | None = None
    clip: Dimensionless | None = None


class Envelope(Strict):
    bore: PositiveLength | None = Field(None, description="Bore d; rows must fit between d and D.")
    outer_diameter: PositiveLength | None = Field(None, description="Outside diameter D.")


class BallBase(Envelope):
    n_elements: Count
    element_diameter: PositiveLength
    pitch_diameter: PositiveLength
    tilt_arm: Literal["groove_centre", "pitch_radius"] | None = Field(
        None,
        description="Lever arm of a ring tilt: inner groove curvature centre (Harris, default) or pitch "
        "radius (ISO/TS 16281); see docs/engine.md.",
    )


#: Names of the shoulder-height fields of the ball-bearing geometries (not builder arguments).
SHOULDER_FIELDS = ("shoulder_height_inner", "shoulder_height_outer")
_SHOULDER_NOTE = (
    "Shoulder height above the groove bottom on the side the contact runs to (angular contact: the high "
    "shoulder): a length, or a number = fraction of D_w. Default by kind (docs/ratings.md)."
)


class Shoulders(Strict):
    """Groove shoulder heights of a ball bearing's rings (truncation of the contact ellipse, #23)."""

    shoulder_height_inner: ShoulderHeight | None = Field(None, description=_SHOULDER_NOTE)
    shoulder_height_outer: ShoulderHeight | None = Field(None, description=_SHOULDER_NOTE)


class DeepGrooveBallGeometry(BallBase, Shoulders):
    conformity_inner: Dimensionless | None = None
    conformity_outer: Dimensionless | None = None
    clearance_radial: Length | None = Field(None, description="Diametral clearance P_d (negative: preload).")


class AngularContactBallGeometry(BallBase, Shoulders):
    contact_angle: Angle
    conformity_inner: Dimensionless | None = None
    conformity_outer: Dimensionless | None = None
    clearance: Length | None = Field(None, description="Clearance along the contact line, counted twice.")


class AngularContactPairGeometry(BallBase, Shoulders):
    arrangement: Literal["DB", "DF", "DT"]
    contact_angle: Angle
    row_spacing: PositiveLength
    clearance_axial: Length | None = Field(None, description="Axial play of the pair (negative: preload).")
    conformity_inner: Dimensionless | None = None
    conformity_outer: Dimensionless | None = None


class ThrustBallGeometry(BallBase, Shoulders):
    conformity: Dimensionless | None = None


class RollerBase(Envelope):
    n_elements: Count
    element_diameter: PositiveLength
    effective_length: PositiveLength
    pitch_diameter: PositiveLength
    n_slices: SliceCount | None = None
    profile: ProfileSpec | None = Field(
        None, description="Crowning: a profile name (string shorthand for {name = ...}) or a table."
    )
    line_law: Literal["kunert", "iso16281"] | None = None


class CylindricalRollerGeometry(RollerBase):
    clearance_radial: Length | None = Field(None, description="Diametral clearance (negative: preload).")
    rows: Literal[1, 2] | None = Field(
        None, description="Roller rows: 2 for a double-row bearing (NN30) on shared rings. Default 1."
    )
    row_spacing: PositiveLength | None = Field(
        None, description="Axial distance of the two rows' centres (rows = 2 only)."
    )


class CylindricalRollerThrustGeometry(RollerBase):
    pass


class CompositeTurntableGeometry(Strict):
    """Seed-000 ball–roller composite turntable (fields of bearings.turntable.CompositeTurntableGeometry)."""

    bore: PositiveLength | None = None
    outer_diameter: PositiveLength | None = None
    pitch_diameter_axial_roller: PositiveLength | None = None
    pitch_diameter_axial_ball: PositiveLength | None = None
    pitch_diameter_radial_roller: PositiveLength | None = None
    n_axial_rollers: Count | None = None
    n_axial_balls: Count | None = None
    n_radial_rollers: Count | None = None
    axial_roller_diameter: PositiveLength | None = None
    axial_roller_length: PositiveLength | None = None
    ball_diameter: PositiveLength | None = None
    radial_roller_diameter: PositiveLength | None = None
    radial_roller_length: PositiveLength | None = None
    groove_curvature: Dimensionless | None = None
    clearance_axial_roller: Length | None = None
    clearance_axial_ball: Length | None = None
    clearance_radial: Length | None = None
    crowning: str | None = Field(None, description="Seed-000 letter a–e or a profile registry name.")
    n_slices: SliceCount | None = None


class YRTGeometry(Envelope):
    """YRT-type three-row roller turntable (fields of bearings.turntable.YRTGeometry)."""

    pitch_diameter_axial_roller: PositiveLength | None = None
    n_axial_rollers: Count | None = None
    axial_roller_diameter: PositiveLength | None = None
    axial_roller_length: PositiveLength | None = None
    pitch_diameter_radial_roller: PositiveLength | None = None
    n_radial_rollers: Count | None = None
    radial_roller_diameter: PositiveLength | None = None
    radial_roller_length: PositiveLength | None = None
    clearance_axial_roller: Length | None = None
    clearance_radial: Length | None = None
    crowning: str | None = None
    n_slices: SliceCount | None = None


class DeviationGenerator(Strict):
    """Generated roller diameter deviations ΔD ~ N(0, S_d²) (Liu et al. 2022 eq. 14) or a seed-001 series."""

    magnitude: NonNegativeLength | None = Field(None, description="S_d, the standard deviation of ΔD.")
    arrangement: Literal["random", "descending"] = Field(
        "random", description="Order around the cage (bearingkit.physics.deviations.ARRANGEMENTS)."
    )
    seed: Annotated[int, Field(ge=0)] | None = Field(
        None, description="Random seed (required with magnitude)."
    )
    series: Annotated[int, Field(ge=1, le=6)] | None = Field(
        None, description="Seed 001 Table 2 series 1-6 instead of a draw (23 rollers)."
    )

    @model_validator(mode="after")
    def _one_kind(self):
        if (self.series is None) == (self.magnitude is None):
            raise InputError("diameter_deviation: give either magnitude (with seed) or series, not both")
        if self.magnitude is not None and self.seed is None:
            raise InputError("diameter_deviation: seed is required with magnitude (reproducible draws)")
        return self


def _deviations(value, info: ValidationInfo):
    """A list of lengths with units → tuple of SI floats; a table → :class:`DeviationGenerator`."""
    if value is None or isinstance(value, DeviationGenerator):
        return value
    if isinstance(value, dict):
        return DeviationGenerator.model_validate(value)
    if isinstance(value, (list, tuple)):
        n = info.data.get("n_elements")  # validated before (field order): count before parsing
        if n is not None and len(value) != n:
            raise InputError(
                f"{info.field_name} ({quote(value)}) must have one value per roller (n_elements = {n})"
            )
        return tuple(units.parse(v, "length", f"{info.field_name}[{i}]") for i, v in enumerate(value))
    raise InputError(
        f"{info.field_name} ({quote(value)}) must be a list of lengths such as ['1 um', '-0.5 um', …] or a "
        "table {magnitude = '1 um', arrangement = 'random', seed = 1} or {series = 1}"
    )


#: Per-roller diameter deviations: a list of lengths (one per roller) or a generator table.
Deviations = Annotated[
    tuple[float, ...] | DeviationGenerator,
    BeforeValidator(_deviations),
    WithJsonSchema(
        {
            "oneOf": [
                {"type": "array", "items": {"type": "string", "x-dimension": "length", "x-si-unit": "m"}},
                DeviationGenerator.model_json_schema(),
            ],
            "description": "ΔD per roller (list of lengths) or a generator table (magnitude, arrangement, "
            "seed) or {series = 1..6} (seed 001 Table 2).",
        }
    ),
]


class TaperedRollerGeometry(Envelope):
    """Tapered roller bearing: one row (rows.tapered.row.TaperedRow fields) or a DB/DF pair."""

    arrangement: Literal["single", "DB", "DF"] = Field(
        "single", description="One row, or two rows back-to-back (DB) / face-to-face (DF)."
    )
    row_spacing: PositiveLength | None = Field(None, description="Axial distance of the rows (pairs only).")
    n_elements: Count
    small_diameter: PositiveLength
    large_diameter: PositiveLength
    effective_length: PositiveLength
    pitch_diameter: PositiveLength
    contact_angle_outer: Angle
    contact_angle_inner: Angle
    flange_angle: Angle | None = None
    roller_angle: Angle | None = Field(None, description="Half roller angle ε, checked when given.")
    clearance: Length | None = Field(None, description="Along the cup normal, counted twice (< 0: preload).")
    n_slices: SliceCount | None = None
    profile: ProfileSpec | None = Field(None, description="Crowning (name or table), as cylindrical rows.")
    line_law: Literal["kunert", "iso16281"] | None = None
    deviation_model: Literal["exact", "taylor"] | None = None
    diameter_deviation: Deviations | None = None
    flange_contact_height: PositiveLength | None = None
    end_radius: PositiveLength | None = None

    @model_validator(mode="after")
    def _pair(self):
        if (self.arrangement == "single") != (self.row_spacing is None):
            raise InputError(
                f"row_spacing ({quote(self.row_spacing)}) must be given for arrangement DB/DF and only then "
                f"(arrangement is {self.arrangement!r})"
            )
        dev = self.diameter_deviation
        if isinstance(dev, tuple) and len(dev) != self.n_elements:
            raise InputError(
                f"diameter_deviation ({len(dev)} values) must have one value per roller (n_elements = "
                f"{self.n_elements})"
            )
        return self


class PTRBGeometrySpec(Strict):
    """Planetary thread roller bearing (rows.threaded.geometry.PTRBGeometry; E, ν from [material])."""

    bore: PositiveLength = Field(description="Bore d_0 (PTRBGeometry.bore_diameter).")
    outer_diameter: PositiveLength = Field(
        description="Outside diameter D_0 (PTRBGeometry.outside_diameter)."
    )
    width: PositiveLength = Field(description="Width H_0.")
    pitch_diameter: PositiveLength
    roller_pitch_diameter: PositiveLength
    roller_contact_radius: PositiveLength
    n_elements: Count
    n_teeth: Count
    contact_angle: Angle
    thread_pitch: PositiveLength
    dedendum: PositiveLength
    ridge_thickness: PositiveLength
    bottom_thickness_roller: PositiveLength
    bottom_thickness_inner: PositiveLength
    bottom_thickness_outer: PositiveLength
    contact_radius_inner: PositiveLength | None = Field(None, description="r_I; omitted = flat flank (inf).")
    contact_radius_outer: PositiveLength | None = Field(None, description="r_O; omitted = flat flank (inf).")
    inner_pitch_diameter: PositiveLength | None = None
    outer_pitch_diameter: PositiveLength | None = None
    clearance: Length | None = Field(None, description="Play along each contact normal, counted twice.")


class BallColumnRingSpec(Strict):
    """``[geometry.ring]`` of a ball–column bearing: how the shared outer ring is modelled
    (bearings.ball_column.RingOptions fields)."""

    flexible: bool | None = Field(
        None, description="Coupled flexible-ring solve (analysis.flexible); false: rigid ring. Default true."
    )
    compliance_scale: Dimensionless | None = Field(
        None, description="Multiplies the ring compliances (>= 0; 0 = rigid). Default 1."
    )
    bending: bool | None = Field(None, description="Thin-ring ovalisation on top of the beam. Default true.")
    beam_mode: Literal["clearance", "translation"] | None = Field(
        None, description="How the beam deflection acts on a row. Default 'clearance'."
    )
    beam_tilt: bool | None = Field(None, description="Beam slope as a rigid raceway tilt. Default false.")
    housing_stiffness: NonNegativeStiffnessPerLength | None = Field(
        None,
        description="Winkler stiffness k_h of the housing on the ring's ovalisation, per unit "
        "circumferential length (N/m^2, e.g. '6.9e9 N/m^2'; 0 = free ring). "
        "Exclusive with housing_wall_thickness.",
    )
    housing_wall_thickness: PositiveLength | None = Field(
        None,
        description="Housing wall thickness t_h: k_h = E_h t_h b / R_h^2 (bilateral fit). "
        "Default (neither given): 20 mm of steel.",
    )
    housing_youngs_modulus: PositivePressure | None = Field(
        None, description="Young's modulus E_h of the housing. Default 208 GPa (steel)."
    )


def _support_positions(value, info: ValidationInfo):
    """Two axial positions with units → (z_A, z_B) in metres."""
    if value is None:
        return None
    if not isinstance(value, (list, tuple)) or len(value) != 2:
        raise InputError(
            f"{info.field_name} ({quote(value)}) must be two axial positions such as ['-25 mm', '25 mm']"
        )
    return tuple(units.parse(v, "length", f"{info.field_name}[{i}]") for i, v in enumerate(value))


#: Housing supports (z_A, z_B) of a flexible outer ring.
SupportPositions = Annotated[
    tuple[float, float],
    BeforeValidator(_support_positions),
    WithJsonSchema(
        {
            "type": "array",
            "items": {"type": "string", "x-dimension": "length", "x-si-unit": "m"},
            "minItems": 2,
            "maxItems": 2,
            "description": "Axial positions z_A < z_B of the housing supports, e.g. ['-25 mm', '25 mm'].",
        }
    ),
]


class BallColumnGeometrySpec(Strict):
    """Seed-002 ball–column composite bearing (bearings.ball_column.BallColumnGeometry fields)."""

    n_balls: Count | None = None
    ball_count: Literal["per_row", "total"] | None = Field(
        None,
        description="How n_balls counts: per ball row (default) or the total of both rows (row 1 "
        "staggered half a pitch; seed 002's reading of its Table 1).",
    )
    ball_diameter: PositiveLength | None = None
    n_rollers: Count | None = None
    roller_diameter: PositiveLength | None = None
    roller_length: PositiveLength | None = None
    outer_diameter: PositiveLength | None = None
    bore: PositiveLength | None = None
    width: PositiveLength | None = None
    inner_ring_width: PositiveLength | None = Field(None, description="Row spacing a.")
    pitch_diameter: PositiveLength | None = None
    contact_angle: Angle | None = None
    conformity_inner: Dimensionless | None = None
    conformity_outer: Dimensionless | None = None
    clearance_ball: NonNegativeLength | None = Field(
        None, description="Diametral clearance of each ball row."
    )
    clearance_roller: NonNegativeLength | None = Field(
        None, description="Diametral clearance of the roller row."
    )
    n_slices: SliceCount | None = None
    beam_width: PositiveLength | None = Field(
        None, description="Outer-ring beam strip width (flexible ring)."
    )
    support_positions: SupportPositions | None = Field(
        None, description="Housing supports of the outer ring (default: at the two ball rows)."
    )
    ring: BallColumnRingSpec | None = Field(None, description="Outer-ring model ([geometry.ring]).")


#: Bearing type → geometry model. The loader's builder registry uses the same keys.
GEOMETRY_MODELS: dict[str, type[BaseModel]] = {
    "composite_turntable": CompositeTurntableGeometry,
    "yrt_turntable": YRTGeometry,
    "deep_groove_ball": DeepGrooveBallGeometry,
    "angular_contact_ball": AngularContactBallGeometry,
    "angular_contact_pair": AngularContactPairGeometry,
    "thrust_ball": ThrustBallGeometry,
    "cylindrical_roller": CylindricalRollerGeometry,
    "cylindrical_roller_thrust": CylindricalRollerThrustGeometry,
    "tapered_roller": TaperedRollerGeometry,
    "ptrb": PTRBGeometrySpec,
    "ball_column": BallColumnGeometrySpec,
}


def _describe_defaults() -> None:
    """Put each builder default (SI) into the description of the matching optional field."""
    from bearingkit.bearings import standard, turntable
    from bearingkit.rows.tapered.row import TaperedRow
    from bearingkit.rows.threaded.geometry import PTRBGeometry

    def defaults(cls):
        return {f.name: f.default for f in dataclasses.fields(cls) if f.default is not dataclasses.MISSING}

    sources = {
        "composite_turntable": defaults(turntable.CompositeTurntableGeometry),
        "yrt_turntable": defaults(turntable.YRTGeometry),
        "tapered_roller": defaults(TaperedRow),
        "ptrb": defaults(PTRBGeometry),
    }
    try:  # the seed-002 builder is optional (bearings/ball_column.py)
        from bearingkit.bearings.ball_column import BallColumnGeometry

        sources["ball_column"] = defaults(BallColumnGeometry)
    except ImportError:  # pragma: no cover - the module ships with bearingkit
        pass
    for name in GEOMETRY_MODELS:
        fn = getattr(standard, name, None)
        if fn is not None:
            sources[name] = {
                k: p.default
                for k, p in inspect.signature(fn).parameters.items()
                if p.default is not inspect.Parameter.empty
            }
    sources["angular_contact_pair"]["clearance_axial"] = sources["angular_contact_pair"].get(
        "axial_clearance"
    )
    for name, model in GEOMETRY_MODELS.items():
        for key, info in model.model_fields.items():
            default = sources.get(name, {}).get(key, inspect.Parameter.empty)
            if info.default is None and default is not inspect.Parameter.empty and default is not None:
                note = f"Default (SI): {default!r}."
                info.description = f"{info.description} {note}" if info.description else note
        if model.__pydantic_complete__:  # built already; otherwise (defer_build) the first use reads them
            model.model_rebuild(force=True)


_describe_defaults()
