"""The sections every input file shares: ``[bearing]``, ``[material]``, ``[lubricant]``,
``[[load_cases]]``, ``[solver]``, and the whole file (:class:`BearingFile`); ``[hardness]`` is
:mod:`bearingkit.io.schema_hardness`'s.

SI after validation (values arrive as strings with units, see :mod:`bearingkit.io.fields`). The
geometry table depends on ``bearing.type`` and is validated by :mod:`bearingkit.io.geometries`.
"""

from __future__ import annotations

from typing import Any, Literal

from pydantic import Field, field_validator, model_validator

from bearingkit.errors import InputError, did_you_mean, quote
from bearingkit.io.fields import (
    AngularVelocity,
    Dimensionless,
    Force,
    IterationCount,
    Length,
    Moment,
    PositiveDensity,
    PositiveForce,
    PositivePressure,
    Strict,
    Temperature,
)
from bearingkit.io.geometries import GEOMETRY_MODELS
from bearingkit.io.schema_hardness import HardnessSpec

#: Most load cases one file may hold. Measured on the 2-core reference machine: 1,000 cases of a
#: deep groove ball bearing take 6 s through analyze, rating or friction; more belongs in a study.
#: (Flexible rings and reports have lower caps: :mod:`bearingkit.io.loader`.)
MAX_LOAD_CASES = 1_000


class BearingHeader(Strict):
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
    C: PositiveForce | None = Field(
        None, description="Catalogue C the estimated element size is scaled to (with designation)."
    )
    clearance_position: Literal["min", "mean", "max"] | Dimensionless = Field(
        "mean",
        description="Where in the clearance class of the designation the clearance is taken: min, mean, "
        "max or a percentile 0 … 100 of the class range (with designation).",
    )
    name: str = Field("", description="Designation shown in results and reports.")
    source: str = Field(
        "", description="Where the geometry comes from (paper, table, catalogue, assumption)."
    )

    @field_validator("type")
    @classmethod
    def _known_type(cls, value: str) -> str:
        if value and value not in GEOMETRY_MODELS:
            raise InputError(
                f"type ({quote(value)}) must be one of {', '.join(GEOMETRY_MODELS)}"
                f"{did_you_mean(value, GEOMETRY_MODELS)}"
            )
        return value

    @field_validator("clearance_position", mode="before")
    @classmethod
    def _position(cls, value):
        named = ("min", "mean", "max")
        number = isinstance(value, (int, float)) and not isinstance(value, bool)
        if value in named or (number and 0.0 <= value <= 100.0):
            return value
        shown = quote(value) if isinstance(value, str) else repr(value)
        raise InputError(
            f"clearance_position ({shown}) must be min, mean, max or a percentile 0 … 100 "
            "of the clearance class range, e.g. clearance_position = 90"
        )

    @model_validator(mode="after")
    def _type_or_designation(self):
        if not self.type and self.designation is None:
            raise InputError("type: missing required field (or give designation = '6205-2RS C3')")
        if self.C is not None and self.designation is None:
            raise InputError("C: calibrates an estimated geometry; give it together with designation")
        if self.clearance_position != "mean" and self.designation is None:
            raise InputError(
                "clearance_position: picks a clearance in a designation's class; give designation"
            )
        return self

    def class_position(self) -> float:
        """``clearance_position`` as a fraction of the class range (0 = min, 0.5 = mean, 1 = max)."""
        named = {"min": 0.0, "mean": 0.5, "max": 1.0}
        if isinstance(self.clearance_position, str):
            return named[self.clearance_position]
        return float(self.clearance_position) / 100.0


class MaterialSpec(Strict):
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


class LubricantSpec(Strict):
    """``[lubricant]``: a preset of :data:`bearingkit.lubricants.LUBRICANTS` (used by friction)."""

    name: str = Field(description="Preset name (ISO_VG100, L-AN46, seed000_grease_assumed, …).")


class LoadCaseSpec(Strict):
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


class SolverSpec(Strict):
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
            raise InputError(f"free ({quote(value)}) must list distinct DOF names, at least one")
        return value

    @field_validator("rtol")
    @classmethod
    def _rtol(cls, value):
        if value is not None and not 0 < value < 1:
            raise InputError(f"rtol ({value!r}) must lie in (0, 1)")
        return value


class BearingFile(Strict):
    """A whole input file (geometry validated separately, by :data:`GEOMETRY_MODELS`)."""

    bearing: BearingHeader
    geometry: dict[str, Any] = Field(
        default_factory=dict,
        description="Keyword arguments of the builder (see GEOMETRY_MODELS); optional with designation.",
    )
    material: MaterialSpec | None = Field(None, description="Default: GCr15 (the builders' default).")
    hardness: HardnessSpec | None = Field(
        None, description="Raceway hardness against depth (default: the material's, through-hardened)."
    )
    lubricant: LubricantSpec | None = None
    load_cases: list[LoadCaseSpec] = Field(
        default_factory=list, description=f"At most {MAX_LOAD_CASES} load cases."
    )
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

    @field_validator("load_cases", mode="before")
    @classmethod
    def _at_most(cls, value):
        """Count the cases before validating them (refusing 100,000 cases must not parse them first)."""
        if isinstance(value, list) and len(value) > MAX_LOAD_CASES:
            raise InputError(
                f"load_cases ({len(value)} cases) must be at most {MAX_LOAD_CASES} per file; split the "
                "file or run a study (docs/studies.md)"
            )
        return value

    @field_validator("load_cases")
    @classmethod
    def _unique_names(cls, value):
        names = [c.name for c in value]
        dup = sorted({n for n in names if names.count(n) > 1})
        if dup:
            raise InputError(f"load_cases ({quote(dup)}): case names must be unique")
        return value
