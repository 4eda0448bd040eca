"""The sections every input file shares: ``[bearing]``, ``[material]``, ``[lubricant]``,
``[[load_cases]]``, ``[solver]``, and the whole file (:class:`BearingFile`); ``[hardness]`` is
:mod:`bearingkit.io.schema_hardness`'s.

SI after validation (values arrive as strings with units, see :mod:`bearingkit.io.fields`). The
geometry table depends on ``bearing.type`` and is validated by :mod:`bearingkit.io.geometries`.
"""

from __future__ import annotations

from typing import Any, ClassVar, Literal

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
    PositiveLength,
    PositivePressure,
    Strict,
    Temperature,
    quantity,
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
    rating_C: PositiveForce | None = Field(
        None,
        description="A maker's basic dynamic load rating C the lives use, as a catalogue's (ISO 281 with it; "
        "ISO/TS 16281's raceway ratings scaled to it); the geometry is kept (with a designation or a "
        "geometry).",
    )
    rating_C0: PositiveForce | None = Field(
        None, description="A maker's basic static load rating C0 (ISO 281's X, Y and ISO 76's s0 with it)."
    )
    clearance_position: Literal["min", "mean", "max"] | Dimensionless = Field(
        "mean",
        description="Where in the clearance class of the designation the clearance is taken: min, mean, "
        "max or a percentile 0 … 100 of the class range (with designation).",
    )
    preload: str | None = Field(
        None,
        description="Preload of a DB/DF pair named by designation ('7014 C DB'): extra_light, light, "
        "medium, heavy (a rule on C, docs/catalogue.md) or a force such as '480 N'.",
    )
    name: str = Field("", description="Designation shown in results and reports.")
    source: str = Field(
        "", description="Where the geometry comes from (paper, table, catalogue, assumption)."
    )
    series: str | None = Field(
        None,
        description="Dimension series (e.g. '62'): selects the SKF friction constants and the minimum-load "
        "factor; default from the designation or the catalogue row with the file's bore and outer diameter.",
    )
    seal: str | None = Field(
        None,
        description="Seals or shields: a designation suffix such as '2RS1', '2RSH', '2Z', 'LLU', or 'none'; "
        "default the designation's suffix (docs/operating.md).",
    )
    seal_counterface_diameter: PositiveLength | None = Field(
        None,
        description="Diameter the seal lips run on (SKF d1 or d2 of the product tables); default "
        "estimated as d + 0.25 (D - d).",
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

    @field_validator("seal")
    @classmethod
    def _known_seal(cls, value):
        from bearingkit.catalogue.seals import seal_of_suffix

        seal_of_suffix(value)  # one line naming the valid suffixes
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
        if self.C is not None and self.rating_C is not None:
            raise InputError(
                "rating_C: C scales the estimated geometry to a rating, rating_C rates the geometry as it "
                "is; give one of them"
            )
        if self.rating_C0 is not None and self.rating_C is None:
            raise InputError("rating_C0: give it with rating_C (a maker's C and C0)")
        if self.preload is not None and self.designation is None:
            raise InputError(
                "preload: sets the preload of a pair named by designation ('7014 C DB'); for a bearing "
                "given by its geometry use [operating] preload_force"
            )
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
    """``[lubricant]``: a preset or library name, or the oil's (or grease's) data (docs/lubricants.md).

    The fields are those of :data:`bearingkit.lubricants.FIELDS`; the one builder
    :func:`bearingkit.lubricants.lubricant_from_fields` turns them into a lubricant (every face uses it).
    With a ``name`` of a preset or library entry, the fields given replace that entry's.
    """

    #: Other spellings of the fields (the one-line message suggests the field they mean).
    FIELD_ALIASES: ClassVar[dict[str, str]] = {
        "viscosity_40": "nu_40",
        "viscosity_100": "nu_100",
        "kinematic_viscosity_40": "nu_40",
        "kinematic_viscosity_100": "nu_100",
        "nu40": "nu_40",
        "nu100": "nu_100",
        "viscosity_index": "vi",
        "iso_vg_grade": "iso_vg",
        "grade": "iso_vg",
        "base": "base_oil",
        "alpha": "pressure_viscosity",
    }

    name: str | None = Field(
        None,
        description="Preset or library name (ISO_VG100, VG68_PAO, SKF_LGMT2 …), or a label for an oil given "
        "by its data.",
    )
    iso_vg: Dimensionless | None = Field(None, description="ISO 3448 grade (nu_40 = the grade in mm²/s).")
    nu_40: quantity("kinematic_viscosity", "positive") | None = Field(
        None, description="Kinematic viscosity at 40 °C (of the base oil for a grease)."
    )
    nu_100: quantity("kinematic_viscosity", "positive") | None = Field(
        None, description="Kinematic viscosity at 100 °C (or give vi)."
    )
    vi: Dimensionless | None = Field(None, description="Viscosity index (ASTM D2270), instead of nu_100.")
    base_oil: str | None = Field(None, description="mineral (default), pao, ester or pag.")
    density: PositiveDensity | None = Field(None, description="Density at 15 °C (default: the base oil's).")
    pressure_viscosity: quantity("pressure_viscosity", "positive") | None = Field(
        None, description="Pressure-viscosity coefficient at 40 °C (default: the base oil's law)."
    )
    thermal_conductivity: quantity("thermal_conductivity", "positive") | None = None
    specific_heat: quantity("specific_heat", "positive") | None = Field(
        None, description="Specific heat (heat carried away by a circulating oil)."
    )
    thickener: str | None = Field(None, description="A grease's thickener (lithium, polyurea, …).")
    nlgi: str | int | None = Field(None, description="A grease's NLGI consistency class (000 … 6).")
    life_class: str | None = Field(
        None, description="A grease's class in the grease-life formula: general_purpose or wide_range."
    )
    temperature_min: Temperature | None = Field(None, description="A grease's lower temperature limit.")
    temperature_max: Temperature | None = Field(None, description="A grease's upper temperature limit.")
    source: str | None = Field(None, description="Where the data come from (a data sheet).")


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
        None,
        description="Speed effects, tilt, preload, temperatures "
        "(io.optional_sections.operating.OperatingSpec).",
    )
    fits: dict[str, Any] | None = Field(
        None, description="Shaft/housing fits (io.optional_sections.operating.FitsSpec)."
    )
    lubrication: dict[str, Any] | None = Field(
        None, description="Contamination, roughness, grease (io.optional_sections.operating.LubricationSpec)."
    )
    thermal: dict[str, Any] | None = Field(
        None,
        description="Heat balance: the operating temperature found "
        "(io.optional_sections.operating.ThermalSpec).",
    )
    structure: dict[str, Any] | None = Field(
        None,
        description="Flexible rings, housings, flanges or an imported FE matrix for any bearing "
        "(io.optional_sections.structure.StructureSpec; docs/structure.md).",
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
