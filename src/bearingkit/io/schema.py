"""Input-file schema: pydantic v2 models of one bearing's TOML file, with JSON Schema export.

Units live only at the edge: every dimensional value in a file is a string with its unit
(``"6 mm"``, ``"-5 um"``, ``"600 N*m"``, ``"5 rpm"``, ``"40 deg"``), parsed by
:func:`bearingkit.units.parse` into SI (m, N, N·m, Pa, rad, rad/s; temperature in °C). A bare number is
accepted only for dimensionless fields (counts, conformities, slice counts, Poisson's ratio, rtol),
and there only a TOML number, not a string. After validation every model holds SI floats.

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

The models live in three modules, one idea each; this module gathers their public names and writes
the JSON Schema:

- :mod:`bearingkit.io.fields`: value types (quantities with units, strict counts, the caps);
- :mod:`bearingkit.io.sections`: the shared sections and the whole file (:class:`BearingFile`);
- :mod:`bearingkit.io.geometries`: one geometry model per bearing type (:data:`GEOMETRY_MODELS`),
  whose dependency on ``bearing.type`` :func:`json_schema` writes as ``if``/``then`` clauses.
"""

from __future__ import annotations

from bearingkit.io.fields import (
    MAX_ELEMENTS,
    MAX_ITERATIONS,
    MAX_SLICES,
    UNIT_EXAMPLES,
    Angle,
    AngularVelocity,
    Count,
    Dimensionless,
    Force,
    IterationCount,
    Length,
    Moment,
    NonNegativeLength,
    NonNegativeStiffnessPerLength,
    PositiveDensity,
    PositiveForce,
    PositiveLength,
    PositivePressure,
    ShoulderHeight,
    SliceCount,
    Strict,
    Temperature,
    quantity,
)
from bearingkit.io.geometries import (
    GEOMETRY_MODELS,
    SHOULDER_FIELDS,
    AngularContactBallGeometry,
    AngularContactPairGeometry,
    BallBase,
    BallColumnGeometrySpec,
    BallColumnRingSpec,
    CompositeTurntableGeometry,
    CylindricalRollerGeometry,
    CylindricalRollerThrustGeometry,
    DeepGrooveBallGeometry,
    DeviationGenerator,
    Deviations,
    Envelope,
    ProfileSpec,
    PTRBGeometrySpec,
    RollerBase,
    Shoulders,
    SupportPositions,
    TaperedRollerGeometry,
    ThrustBallGeometry,
    YRTGeometry,
)
from bearingkit.io.sections import (
    DOF_CHOICES,
    MAX_LOAD_CASES,
    BearingFile,
    BearingHeader,
    HardnessSpec,
    LoadCaseSpec,
    LubricantSpec,
    MaterialSpec,
    SolverSpec,
)

#: The names these classes had before the split, for modules written against them (io.build.kinds,
#: io.optional_sections.operating and branches in flight); new code uses the public names.
_Strict, _Envelope, _BallBase, _RollerBase = Strict, Envelope, BallBase, RollerBase

__all__ = [
    "DOF_CHOICES",
    "GEOMETRY_MODELS",
    "MAX_ELEMENTS",
    "MAX_ITERATIONS",
    "MAX_LOAD_CASES",
    "MAX_SLICES",
    "SHOULDER_FIELDS",
    "UNIT_EXAMPLES",
    "Angle",
    "AngularContactBallGeometry",
    "AngularContactPairGeometry",
    "AngularVelocity",
    "BallBase",
    "BallColumnGeometrySpec",
    "BallColumnRingSpec",
    "BearingFile",
    "BearingHeader",
    "CompositeTurntableGeometry",
    "Count",
    "CylindricalRollerGeometry",
    "CylindricalRollerThrustGeometry",
    "DeepGrooveBallGeometry",
    "DeviationGenerator",
    "Deviations",
    "Dimensionless",
    "Envelope",
    "Force",
    "HardnessSpec",
    "IterationCount",
    "Length",
    "LoadCaseSpec",
    "LubricantSpec",
    "MaterialSpec",
    "Moment",
    "NonNegativeLength",
    "NonNegativeStiffnessPerLength",
    "PTRBGeometrySpec",
    "PositiveDensity",
    "PositiveForce",
    "PositiveLength",
    "PositivePressure",
    "ProfileSpec",
    "RollerBase",
    "ShoulderHeight",
    "Shoulders",
    "SliceCount",
    "SolverSpec",
    "Strict",
    "SupportPositions",
    "TaperedRollerGeometry",
    "Temperature",
    "ThrustBallGeometry",
    "YRTGeometry",
    "json_schema",
    "quantity",
]


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
