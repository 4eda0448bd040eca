"""Input section ``[structure]``: flexible rings, housings and imported FE matrices for any bearing.

SI after validation (m, m², m⁴, N/m, N/m², Pa, rad), as the rest of the schema. The section is kept as a
table in :class:`~bearingkit.io.schema.BearingFile` and validated here, the way ``[operating]`` is
(:data:`bearingkit.io.optional_sections.operating.SECTION_MODELS` lists it, so its numbers are study factors:
``structure.outer.seat_stiffness``, ``structure.outer.flange.bolt_stiffness``,
``structure.outer.stiffness_scale`` …). :mod:`bearingkit.io.build.structure` turns it into a
:class:`~bearingkit.analysis.structure.Structure` (docs/structure.md)::

    [structure.outer]          the outer ring as a curved beam (section, material, seat, stiffness scale)
    [structure.outer.flange]   bolted at n points to a flange of given stiffness
    [structure.outer.split]    a split housing: the seat missing beside the joints
    [structure.inner]          the inner ring, the same fields (its seat is the shaft)
    [structure.imported]       a condensed stiffness or compliance from an FE code (Matrix Market / CSV)
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, field_validator, model_validator

from bearingkit.errors import InputError, quote
from bearingkit.io.schema import (
    Angle,
    Count,
    Dimensionless,
    Length,
    NonNegativeLength,
    NonNegativeStiffnessPerLength,
    PositiveLength,
    PositivePressure,
    Strict,
    quantity,
)

#: Section shapes of a ring (:mod:`bearingkit.rings.sections`).
SECTION_SHAPES = ("rectangular", "grooved", "stepped", "given")
#: Most Fourier harmonics of a ring (the series cost grows with them; 512 is the default).
MAX_HARMONICS = 4096


class FlangeSpec(Strict):
    """``[structure.<ring>.flange]``: the ring bolted at n points to a flange (rings.supports)."""

    n_bolts: Count
    bolt_circle_diameter: PositiveLength
    bolt_stiffness: quantity("stiffness", "positive") = Field(
        description="Axial stiffness of one bolt with its clamped parts, in series (VDI 2230)."
    )
    lateral_stiffness: quantity("stiffness", "non_negative") | None = Field(
        None, description="Radial and tangential stiffness of each joint (friction or spigot); default 0."
    )
    face: Literal["lower", "upper"] | None = Field(
        None, description="Which face of the ring is bolted: at its smallest z (lower, default) or largest."
    )
    face_stiffness: NonNegativeStiffnessPerLength | None = Field(
        None,
        description="Axial Winkler stiffness of the flange face under the ring, per unit length (N/m^2).",
    )
    face_width: NonNegativeLength | None = Field(None, description="Radial width of that face (default 0).")
    phase: Angle | None = Field(None, description="Azimuth of the first bolt (default 0).")


class SplitSpec(Strict):
    """``[structure.<ring>.split]``: a split housing (rings.supports.SplitHousing)."""

    azimuth: Angle | None = Field(None, description="Azimuth of the split plane (default 90 deg).")
    gap: Angle | None = Field(None, description="Half-width of the unsupported arc at each joint (10 deg).")
    remaining: Dimensionless | None = Field(None, description="Share of the seat left there (default 0).")

    @field_validator("remaining")
    @classmethod
    def _share(cls, value):
        if value is not None and not 0 <= value <= 1:
            raise InputError(f"remaining ({value!r}) must lie in [0, 1]")
        return value


class RingSpec(Strict):
    """``[structure.outer]`` / ``[structure.inner]``: a ring as a curved beam on its supports."""

    section: Literal["rectangular", "grooved", "stepped", "given"] | None = Field(
        None, description="Section shape (default rectangular; grooved needs groove_depth)."
    )
    inner_diameter: PositiveLength | None = Field(
        None, description="Bore of the ring (outer ring: default pitch + element diameter; inner: the bore)."
    )
    outer_diameter: PositiveLength | None = Field(
        None, description="Outside of the ring (outer: default [geometry] outer_diameter; inner: pitch − D)."
    )
    width: PositiveLength | None = Field(
        None, description="Axial width of the ring (required but for 'given')."
    )
    axial_position: Length | None = Field(
        None, description="Axial position of the ring's middle (default 0)."
    )
    groove_depth: PositiveLength | None = Field(None, description="Depth of the raceway groove (grooved).")
    groove_radius: PositiveLength | None = Field(
        None, description="Radius of the raceway groove (default the row's conformity × element diameter)."
    )
    steps: list[list[str]] | None = Field(
        None,
        description="Stepped section: rectangles [inner diameter, outer diameter, z_min, z_max] with units.",
    )
    area: quantity("area", "positive") | None = Field(None, description="Given section: area.")
    inertia_in: quantity("second_moment", "positive") | None = Field(
        None, description="Given section: ∫(r − r_c)² dA (bending in the ring's plane)."
    )
    inertia_out: quantity("second_moment", "positive") | None = Field(
        None, description="Given section: ∫(z − z_c)² dA (bending out of the plane)."
    )
    torsion_constant: quantity("second_moment", "positive") | None = Field(
        None, description="Given section: Saint-Venant torsion constant J."
    )
    centroid_diameter: PositiveLength | None = Field(None, description="Given section: 2 r_c.")
    bolt_holes: Count | None = Field(None, description="Axial bolt holes through the ring (smeared).")
    bolt_hole_diameter: PositiveLength | None = None
    bolt_hole_circle: PositiveLength | None = Field(None, description="Diameter of the holes' circle.")
    youngs_modulus: PositivePressure | None = Field(None, description="Default: [material].")
    poisson_ratio: Dimensionless | None = Field(None, description="Default: [material].")
    seat_stiffness: NonNegativeStiffnessPerLength | None = Field(
        None, description="Radial Winkler stiffness of the housing bore / shaft seat per unit length (N/m^2)."
    )
    seat_wall_thickness: PositiveLength | None = Field(
        None, description="Housing wall (or hollow shaft wall) t: seat stiffness E t b / R^2 (thin wall)."
    )
    seat_youngs_modulus: PositivePressure | None = Field(None, description="Of the housing wall (208 GPa).")
    axial_support: NonNegativeStiffnessPerLength | None = Field(
        None, description="Axial Winkler stiffness of a shoulder holding the ring (N/m^2); default 0."
    )
    tangential_support: NonNegativeStiffnessPerLength | None = Field(
        None, description="Tangential Winkler stiffness of the seat (friction); default 0."
    )
    stiffness_scale: Dimensionless | None = Field(
        None, description="Multiplies the ring's and its supports' stiffness (> 0; large: near rigid)."
    )
    harmonics: Count | None = Field(
        None, description=f"Fourier harmonics of the ring (default 512, ≤ {MAX_HARMONICS})."
    )
    rows: list[str] | None = Field(None, description="Rows whose raceway this ring carries (default all).")
    flange: FlangeSpec | None = None
    split: SplitSpec | None = None

    @field_validator("stiffness_scale")
    @classmethod
    def _scale(cls, value):
        if value is not None and not value > 0:
            raise InputError(f"stiffness_scale ({value!r}) must be positive")
        return value

    @field_validator("harmonics")
    @classmethod
    def _harmonics(cls, value):
        if value is not None and not 8 <= value <= MAX_HARMONICS:
            raise InputError(f"harmonics ({value!r}) must lie in [8, {MAX_HARMONICS}]")
        return value

    @model_validator(mode="after")
    def _consistent(self):
        shape = self.section or "rectangular"
        given = ("area", "inertia_in", "inertia_out", "torsion_constant", "centroid_diameter")
        if shape == "given":
            missing = [f for f in given if getattr(self, f) is None]
            if missing:
                raise InputError(f"section ('given') needs {', '.join(missing)}")
        elif self.width is None and shape != "stepped":
            raise InputError(f"width (missing): a {shape} ring section needs its axial width")
        if shape == "grooved" and self.groove_depth is None:
            raise InputError(
                "groove_depth (missing): a grooved section needs the depth of its raceway groove"
            )
        if shape == "stepped" and not self.steps:
            raise InputError("steps (missing): a stepped section needs its rectangles")
        holes = (self.bolt_holes, self.bolt_hole_diameter, self.bolt_hole_circle)
        if any(v is not None for v in holes) and any(v is None for v in holes):
            raise InputError(
                "bolt_holes, bolt_hole_diameter and bolt_hole_circle go together (smeared holes)"
            )
        if self.seat_stiffness is not None and self.seat_wall_thickness is not None:
            raise InputError(
                "seat_stiffness and seat_wall_thickness: give one (the wall gives the stiffness)"
            )
        if self.steps is not None:
            for i, step in enumerate(self.steps):
                if len(step) != 4:
                    raise InputError(
                        f"steps[{i}] ({quote(step)}) must be [inner diameter, outer diameter, z_min, z_max]"
                    )
        return self


class ImportSpec(Strict):
    """``[structure.imported]``: a condensed matrix of an FE model at raceway nodes (rings.imported)."""

    matrix: str = Field(
        description="File of the matrix: Matrix Market (.mtx) or CSV (dense rows), node-major."
    )
    nodes: str = Field(description="CSV of node coordinates x, y, z (one node per line, one per element).")
    kind: Literal["stiffness", "compliance"] | None = Field(None, description="Default stiffness.")
    dofs: list[Literal["ux", "uy", "uz", "rx", "ry", "rz"]] | None = Field(
        None, description="DOFs per node in the matrix's order (default ux, uy, uz)."
    )
    ring: Literal["outer", "inner"] | None = Field(
        None, description="The raceway it carries (default outer)."
    )
    rows: list[str] | None = Field(None, description="Rows whose elements the nodes carry (default all).")
    free: bool | None = Field(
        None, description="Accept a free structure (6 rigid-body modes); default false."
    )
    matrix_unit: str | None = Field(
        None, description="Unit of a translational matrix, e.g. 'N/mm' (stiffness) or 'mm/N'; default SI."
    )
    length_unit: str | None = Field(None, description="Unit of the node coordinates, e.g. 'mm'; default m.")
    stiffness_scale: Dimensionless | None = Field(None, description="Multiplies the stiffness (> 0).")


class StructureSpec(Strict):
    """``[structure]``: what carries the raceways (docs/structure.md)."""

    outer: RingSpec | None = None
    inner: RingSpec | None = None
    imported: ImportSpec | None = None
    max_iterations: Count | None = Field(None, description="Newton iterations of the coupling (default 50).")

    @model_validator(mode="after")
    def _parts(self):
        if self.outer is None and self.inner is None and self.imported is None:
            raise InputError(
                "structure (empty): give [structure.outer], [structure.inner] or [structure.imported]"
            )
        if self.imported is not None:
            side = self.imported.ring or "outer"
            if getattr(self, side) is not None:
                raise InputError(
                    f"structure.imported carries the {side} ring and so does [structure.{side}]: "
                    "give one of them"
                )
        return self
