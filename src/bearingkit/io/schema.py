"""Input-file schema: pydantic v2 models of one bearing's TOML file, with JSON Schema export.

Units live only here, at the edge: every dimensional value in a file is a string with its unit
(``"6 mm"``, ``"-5 um"``, ``"600 N*m"``, ``"5 rpm"``, ``"40 deg"``), parsed by
:func:`bearingkit.units.parse` into SI (m, N, N·m, Pa, rad, rad/s; temperature in °C). A bare number is
accepted only for dimensionless fields (counts, conformities, slice counts, Poisson's ratio, rtol).
After validation every model holds SI floats.

File layout (see docs/input-format.md)::

    [bearing]      type, name, source
    [geometry]     the builder's keyword arguments (one geometry model per bearing type)
    [material]     name = "GCr15"  or  youngs_modulus / poisson_ratio / density
    [lubricant]    name = "ISO_VG100"                     (optional)
    [[load_cases]] name, F_x, F_y, F_z, M_x, M_y, eccentricity, speed, temperature
    [solver]       free, rtol, max_iterations             (optional)
    [operating]    speed effects, tilt, preload, temperatures (optional)
    [fits]         shaft / housing tolerance fields      (optional)
    [lubrication]  contamination, roughness, grease      (optional)

The geometry table depends on ``bearing.type``; :data:`GEOMETRY_MODELS` maps each type to its
model, and :func:`json_schema` writes the dependency as JSON Schema ``if``/``then`` clauses.
Defaults of omitted geometry fields are the builders' defaults (they are not repeated here).
"""

from __future__ import annotations

import dataclasses
import inspect
from typing import Annotated, Any, Literal

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationInfo,
    WithJsonSchema,
    field_validator,
    model_validator,
)

from bearingkit import units
from bearingkit.errors import InputError

#: Examples shown in messages and in the JSON Schema, per dimension.
UNIT_EXAMPLES = {
    "length": "6 mm",
    "force": "5 kN",
    "moment": "600 N*m",
    "pressure": "208 GPa",
    "angle": "40 deg",
    "angular_velocity": "5 rpm",
    "temperature": "40 degC",
    "density": "7810 kg/m^3",
}


def _quantity_parser(dimension: str, sign: str | None):
    def parse(value, info: ValidationInfo) -> float:
        x = units.parse(value, dimension, info.field_name)
        if sign == "positive" and not x > 0:
            raise InputError(f"{info.field_name} ({value!r}) must be positive")
        if sign == "non_negative" and not x >= 0:
            raise InputError(f"{info.field_name} ({value!r}) must be non-negative")
        return x

    return parse


def quantity(dimension: str, sign: str | None = None):
    """Annotated float type of a dimensional field: a string with a unit in, SI float out."""
    words = {"positive": "a positive ", "non_negative": "a non-negative "}.get(sign or "", "a ")
    return Annotated[
        float,
        BeforeValidator(_quantity_parser(dimension, sign)),
        WithJsonSchema(
            {
                "type": "string",
                "description": f"{words}{dimension.replace('_', ' ')} with its unit, e.g. "
                f"'{UNIT_EXAMPLES.get(dimension, '1 ' + units.SI_UNITS[dimension])}'",
                "x-dimension": dimension,
                "x-si-unit": units.SI_UNITS[dimension],
            }
        ),
    ]


def _dimensionless(value, info: ValidationInfo) -> float:
    return units.parse(value, "dimensionless", info.field_name)


#: Largest accepted counts: elements per row, slices per roller, solver iterations (a guard against
#: typing errors that would exhaust memory or time, far above any real bearing).
MAX_ELEMENTS = 100_000
MAX_SLICES = 500
MAX_ITERATIONS = 10_000


def _counter(high: int):
    def count(value, info: ValidationInfo) -> int:
        x = units.parse(value, "dimensionless", info.field_name)
        if not float(x).is_integer() or not 1 <= x <= high:
            raise InputError(f"{info.field_name} ({value!r}) must be an integer in [1, {high}]")
        return int(x)

    return count


def _count_type(high: int):
    return Annotated[
        int,
        BeforeValidator(_counter(high)),
        WithJsonSchema({"type": "integer", "minimum": 1, "maximum": high, "x-dimension": "count"}),
    ]


Length = quantity("length")
PositiveLength = quantity("length", "positive")
NonNegativeLength = quantity("length", "non_negative")
Force = quantity("force")
Moment = quantity("moment")
PositivePressure = quantity("pressure", "positive")
#: Force per length per displacement [N/m²] (a Winkler foundation on a ring): the dimension of a pressure.
NonNegativeStiffnessPerLength = quantity("pressure", "non_negative")
Angle = quantity("angle")
AngularVelocity = quantity("angular_velocity")
Temperature = quantity("temperature")
PositiveDensity = quantity("density", "positive")
Dimensionless = Annotated[
    float,
    BeforeValidator(_dimensionless),
    WithJsonSchema({"type": "number", "x-dimension": "dimensionless"}),
]
Count = _count_type(MAX_ELEMENTS)
SliceCount = _count_type(MAX_SLICES)
IterationCount = _count_type(MAX_ITERATIONS)


class _Strict(BaseModel):
    """Base: unknown fields are errors, models are immutable."""

    model_config = ConfigDict(extra="forbid", frozen=True)


# ---------------------------------------------------------------------------------------------
# Sections shared by every bearing type.
# ---------------------------------------------------------------------------------------------
class BearingHeader(_Strict):
    """``[bearing]``: which builder, a designation and where the geometry comes from."""

    type: str = Field(
        "",
        description="Builder name, one of GEOMETRY_MODELS (docs/input-format.md); optional with designation.",
    )
    designation: str | None = Field(
        None,
        description="Standard bearing such as '6205-2RS C3' (docs/catalogue.md): type and geometry are "
        "estimated from the catalogue; [geometry] fields given override the estimate.",
    )
    C: quantity("force", "positive") | None = Field(
        None,
        description="Catalogue C the estimated element size is scaled to (with designation)."
    )
    name: str = Field("", description="Designation shown in results and reports.")
    source: str = Field(
        "", description="Where the geometry comes from (paper, table, catalogue, assumption)."
    )

    @field_validator("type")
    @classmethod
    def _known_type(cls, value: str) -> str:
        if value and value not in GEOMETRY_MODELS:
            raise InputError(f"type ({value!r}) must be one of {', '.join(GEOMETRY_MODELS)}")
        return value

    @model_validator(mode="after")
    def _type_or_designation(self):
        if not self.type and self.designation is None:
            raise InputError("type: missing required field (or give designation = '6205-2RS C3')")
        if self.C is not None and self.designation is None:
            raise InputError("C: calibrates an estimated geometry; give it together with designation")
        return self


class MaterialSpec(_Strict):
    """``[material]``: a preset name (:data:`bearingkit.materials.MATERIALS`) or elastic constants."""

    name: str | None = Field(None, description="Preset name (GCr15, AISI52100, Si3N4, …).")
    youngs_modulus: PositivePressure | None = None
    poisson_ratio: Dimensionless | None = None
    density: PositiveDensity | None = None

    @model_validator(mode="after")
    def _name_or_constants(self):
        constants = (self.youngs_modulus, self.poisson_ratio, self.density)
        given = [c is not None for c in constants]
        if self.name is not None and any(given):
            raise InputError("material: give either name or youngs_modulus/poisson_ratio/density, not both")
        if self.name is None and not all(given):
            raise InputError(
                "material: give name (a preset) or all of youngs_modulus, poisson_ratio and density"
            )
        return self


class LubricantSpec(_Strict):
    """``[lubricant]``: a preset of :data:`bearingkit.lubricants.LUBRICANTS` (used by friction)."""

    name: str = Field(description="Preset name (ISO_VG100, L-AN46, seed000_grease_assumed, …).")


class LoadCaseSpec(_Strict):
    """``[[load_cases]]``: the external load on the inner ring and the operating point."""

    name: str = Field(description="Unique name of the load case.")
    F_x: Force = 0.0
    F_y: Force = 0.0
    F_z: Force = 0.0
    M_x: Moment = 0.0
    M_y: Moment = 0.0
    eccentricity: Length | None = Field(
        None, description="Radial offset e of F_z along +x; adds M_y = -e·F_z (Tian et al. 2025 §6.1.3)."
    )
    speed: AngularVelocity | None = Field(None, description="Inner-ring speed (friction, later).")
    temperature: Temperature | None = Field(None, description="Operating temperature (lubricant).")


#: Names of the inner-ring degrees of freedom a ``[solver] free`` list may contain.
DOF_CHOICES = ("u_x", "u_y", "u_z", "theta_x", "theta_y")


class SolverSpec(_Strict):
    """``[solver]``: which DOFs are free (the others stay 0) and the tolerance."""

    free: list[Literal["u_x", "u_y", "u_z", "theta_x", "theta_y"]] | None = Field(
        None, description="Free inner-ring DOFs (default all five); fixed DOFs stay at 0."
    )
    rtol: Dimensionless | None = None
    max_iterations: IterationCount | None = None

    @field_validator("free")
    @classmethod
    def _unique(cls, value):
        if value is not None and (len(set(value)) != len(value) or not value):
            raise InputError(f"free ({value!r}) must list distinct DOF names, at least one")
        return value

    @field_validator("rtol")
    @classmethod
    def _rtol(cls, value):
        if value is not None and not 0 < value < 1:
            raise InputError(f"rtol ({value!r}) must lie in (0, 1)")
        return value


class BearingFile(_Strict):
    """A whole input file (geometry validated separately, by :data:`GEOMETRY_MODELS`)."""

    bearing: BearingHeader
    geometry: dict[str, Any] = Field(
        default_factory=dict,
        description="Keyword arguments of the builder (see GEOMETRY_MODELS); optional with designation.",
    )
    material: MaterialSpec | None = Field(None, description="Default: GCr15 (the builders' default).")
    lubricant: LubricantSpec | None = None
    load_cases: list[LoadCaseSpec] = Field(default_factory=list)
    solver: SolverSpec = Field(default_factory=SolverSpec)
    operating: dict[str, Any] | None = Field(
        None, description="Speed effects, tilt, preload, temperatures (io.schema_operating.OperatingSpec)."
    )
    fits: dict[str, Any] | None = Field(
        None, description="Shaft/housing fits (io.schema_operating.FitsSpec)."
    )
    lubrication: dict[str, Any] | None = Field(
        None, description="Contamination, roughness, grease (io.schema_operating.LubricationSpec)."
    )

    @field_validator("load_cases")
    @classmethod
    def _unique_names(cls, value):
        names = [c.name for c in value]
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise InputError(f"load_cases ({dup!r}): case names must be unique")
        return value


# ---------------------------------------------------------------------------------------------
# Geometry models, one per bearing type. Field names are the builders' keyword names (nomenclature).
# ---------------------------------------------------------------------------------------------
class ProfileSpec(_Strict):
    """Crowning profile: a registry name of :mod:`bearingkit.physics.contact.profiles` and its parameters."""

    name: str
    crown_radius: PositiveLength | None = None
    end_drop: NonNegativeLength | None = None
    flat_length: NonNegativeLength | None = None
    semi_minor: PositiveLength | None = None
    design_load: quantity("force", "positive") | None = None
    e_reduced: PositivePressure | None = None
    clip: Dimensionless | None = None


class _Envelope(_Strict):
    bore: PositiveLength | None = Field(None, description="Bore d; rows must fit between d and D.")
    outer_diameter: PositiveLength | None = Field(None, description="Outside diameter D.")


class _BallBase(_Envelope):
    n_elements: Count
    element_diameter: PositiveLength
    pitch_diameter: PositiveLength
    tilt_arm: Literal["groove_centre", "pitch_radius"] | None = Field(
        None,
        description="Lever arm of a ring tilt: inner groove curvature centre (Harris, default) or pitch "
        "radius (ISO/TS 16281); see docs/engine.md.",
    )


class DeepGrooveBallGeometry(_BallBase):
    conformity_inner: Dimensionless | None = None
    conformity_outer: Dimensionless | None = None
    clearance_radial: Length | None = Field(None, description="Diametral clearance P_d (negative: preload).")


class AngularContactBallGeometry(_BallBase):
    contact_angle: Angle
    conformity_inner: Dimensionless | None = None
    conformity_outer: Dimensionless | None = None
    clearance: Length | None = Field(None, description="Clearance along the contact line, counted twice.")


class AngularContactPairGeometry(_BallBase):
    arrangement: Literal["DB", "DF", "DT"]
    contact_angle: Angle
    row_spacing: PositiveLength
    clearance_axial: Length | None = Field(None, description="Axial play of the pair (negative: preload).")
    conformity_inner: Dimensionless | None = None
    conformity_outer: Dimensionless | None = None


class ThrustBallGeometry(_BallBase):
    conformity: Dimensionless | None = None


class _RollerBase(_Envelope):
    n_elements: Count
    element_diameter: PositiveLength
    effective_length: PositiveLength
    pitch_diameter: PositiveLength
    n_slices: SliceCount | None = None
    profile: ProfileSpec | None = Field(
        None, description="Crowning: a profile name (string shorthand for {name = ...}) or a table."
    )
    line_law: Literal["kunert", "iso16281"] | None = None


class CylindricalRollerGeometry(_RollerBase):
    clearance_radial: Length | None = Field(None, description="Diametral clearance (negative: preload).")


class CylindricalRollerThrustGeometry(_RollerBase):
    pass


class CompositeTurntableGeometry(_Strict):
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


class YRTGeometry(_Envelope):
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


class DeviationGenerator(_Strict):
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
        return tuple(units.parse(v, "length", f"{info.field_name}[{i}]") for i, v in enumerate(value))
    raise InputError(
        f"{info.field_name} ({value!r}) must be a list of lengths such as ['1 um', '-0.5 um', …] or a "
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


class TaperedRollerGeometry(_Envelope):
    """Tapered roller bearing: one row (rows.tapered.TaperedRow fields) or a DB/DF pair."""

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
                f"row_spacing ({self.row_spacing!r}) must be given for arrangement DB/DF and only then "
                f"(arrangement is {self.arrangement!r})"
            )
        dev = self.diameter_deviation
        if isinstance(dev, tuple) and len(dev) != self.n_elements:
            raise InputError(
                f"diameter_deviation ({len(dev)} values) must have one value per roller (n_elements = "
                f"{self.n_elements})"
            )
        return self


class PTRBGeometrySpec(_Strict):
    """Planetary thread roller bearing (rows.threaded.PTRBGeometry; E, ν from [material])."""

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


class BallColumnRingSpec(_Strict):
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
            f"{info.field_name} ({value!r}) must be two axial positions such as ['-25 mm', '25 mm']"
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


class BallColumnGeometrySpec(_Strict):
    """Seed-002 ball–column composite bearing (bearings.ball_column.BallColumnGeometry fields)."""

    n_balls: Count | None = None
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
    from bearingkit.rows.tapered import TaperedRow
    from bearingkit.rows.threaded import PTRBGeometry

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
        model.model_rebuild(force=True)


_describe_defaults()


def json_schema() -> dict:
    """The JSON Schema (draft 2020-12) of an input file, geometry chosen by ``bearing.type``."""
    schema = BearingFile.model_json_schema(ref_template="#/$defs/{model}")
    defs = schema.setdefault("$defs", {})
    branches = []
    for name, model in GEOMETRY_MODELS.items():
        sub = model.model_json_schema(ref_template="#/$defs/{model}")
        defs.update(sub.pop("$defs", {}))
        key = f"geometry_{name}"
        defs[key] = sub
        branches.append(
            {
                "if": {"properties": {"bearing": {"properties": {"type": {"const": name}}}}},
                "then": {"properties": {"geometry": {"$ref": f"#/$defs/{key}"}}},
            }
        )
    defs["BearingHeader"]["properties"]["type"]["enum"] = list(GEOMETRY_MODELS)
    schema["allOf"] = branches
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = "bearingkit input file"
    return schema
