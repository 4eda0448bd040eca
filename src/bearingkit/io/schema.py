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

    type: str = Field(description="Builder name, one of GEOMETRY_MODELS (see docs/input-format.md).")
    name: str = Field("", description="Designation shown in results and reports.")
    source: str = Field(
        "", description="Where the geometry comes from (paper, table, catalogue, assumption)."
    )

    @field_validator("type")
    @classmethod
    def _known_type(cls, value: str) -> str:
        if value not in GEOMETRY_MODELS:
            raise InputError(f"type ({value!r}) must be one of {', '.join(GEOMETRY_MODELS)}")
        return value


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
    geometry: dict[str, Any] = Field(description="Keyword arguments of the builder (see GEOMETRY_MODELS).")
    material: MaterialSpec | None = Field(None, description="Default: GCr15 (the builders' default).")
    lubricant: LubricantSpec | None = None
    load_cases: list[LoadCaseSpec] = Field(default_factory=list)
    solver: SolverSpec = Field(default_factory=SolverSpec)

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
    """Crowning profile: a registry name of :mod:`bearingkit.physics.profiles` and its parameters."""

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
}


def _describe_defaults() -> None:
    """Put each builder default (SI) into the description of the matching optional field."""
    from bearingkit.bearings import standard, turntable

    sources = {
        "composite_turntable": {
            f.name: f.default for f in dataclasses.fields(turntable.CompositeTurntableGeometry)
        },
        "yrt_turntable": {f.name: f.default for f in dataclasses.fields(turntable.YRTGeometry)},
    }
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
