"""The ``[shaft]`` input file: a shaft, its bearings (bearing files), gears and load cases, in TOML.

Units at the edge (``"45 mm"``, ``"200 N*m"``, ``"1500 rpm"``, ``"2e8 N/m"``), SI after validation, as
for bearing files (:mod:`bearingkit.io.schema`). Layout (docs/systems.md)::

    [shaft]              name, material, gravity ("-y" …), shear_deformation, max_element_length
    [[shaft.sections]]   start (default: previous end), end or length, outer_diameter, inner_diameter
    [[shaft.bearings]]   name, file (a bearing input file, relative to this file), designation
                         (a standard bearing, e.g. "6209") or stiffness,
                         position, orientation ("+z"|"-z"), axial ("locating"|"floating"),
                         axial_offset, housing = {radial, axial, tilt}
    [[shaft.gears]]      name, position, pitch_diameter, pressure_angle, helix_angle, mesh_angle, mass
    [[shaft.masses]]     name, position, mass
    [[load_cases]]       name, speed, temperature, gears = {NAME = torque}, forces = [...],
                         line_loads = [...]
    [lubricant]          name (friction of bearings whose file has none)
    [lubrication]        contamination, roughness_element, roughness_raceway (bearings whose file has none)
    [thermal]            ambient, heat_dissipation, housing_area, heat_transfer_coefficient, oil_flow,
                         oil_inlet_temperature: every bearing's temperature found by its own heat balance
                         (a bearing file's own [thermal] replaces it for that bearing)
    [solver]             rtol, max_iterations

Every malformed input is one :class:`~bearingkit.errors.InputError` line ``FILE: field (value) …``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

import numpy as np
from pydantic import Field, ValidationError, field_validator

from bearingkit.errors import InputError
from bearingkit.io import schema
from bearingkit.io.loader import load_file
from bearingkit.io.messages import one_line
from bearingkit.io.optional_sections.operating import LubricationSpec, ThermalSpec
from bearingkit.io.reading import confined_path, load_toml
from bearingkit.systems.shaft.loads import (
    AXES,
    STANDARD_GRAVITY,
    Gear,
    LineLoad,
    PointLoad,
    PointMass,
    ShaftLoads,
)
from bearingkit.systems.shaft.shaft import SHAFT_STEEL, Section, Shaft
from bearingkit.systems.shaft.solver import ShaftSystem, SystemOptions
from bearingkit.systems.shaft.supports import AXIAL_DIRECTIONS, BearingSeat, LinearBearing

Stiffness = schema.quantity("stiffness", "non_negative")
RotationalStiffness = schema.quantity("rotational_stiffness", "non_negative")
LineLoadValue = schema.quantity("line_load")
Mass = schema.quantity("mass", "non_negative")
PositiveForce = schema.quantity("force", "positive")
PositiveMass = schema.quantity("mass", "positive")


class SectionSpec(schema.Strict):
    """``[[shaft.sections]]``: one step of the shaft."""

    start: schema.Length | None = Field(
        None, description="Default: where the previous section ends (0 first)."
    )
    end: schema.Length | None = None
    length: schema.PositiveLength | None = Field(None, description="Instead of end.")
    outer_diameter: schema.PositiveLength
    inner_diameter: schema.NonNegativeLength = 0.0


class HousingSpec(schema.Strict):
    """``housing``: stiffness of the housing per outer-ring DOF; a value left out is rigid."""

    radial: Stiffness | None = None
    axial: Stiffness | None = None
    tilt: RotationalStiffness | None = None


class LinearStiffnessSpec(schema.Strict):
    """``stiffness``: a bearing given as constant stiffness (a hand model) instead of a file."""

    radial: Stiffness
    axial: Stiffness = 0.0
    tilt: RotationalStiffness = 0.0
    axial_direction: Literal["both", "+z", "-z"] = Field(
        "both",
        description="Which way the axial stiffness holds the shaft: 'both', or one way only (a shoulder on "
        "one side): '+z' pushes the shaft along +z and never pulls, '-z' the opposite.",
    )


class RatingsSpec(schema.Strict):
    """``ratings``: a maker's basic load ratings the bearing's lives use (``[bearing] rating_C``)."""

    C: PositiveForce
    C0: PositiveForce | None = None


class BearingSpec(schema.Strict):
    """``[[shaft.bearings]]``: a bearing and where it sits."""

    name: str
    file: str | None = Field(None, description="Bearing input file (TOML), relative to the shaft file.")
    designation: str | None = Field(None, description="A standard bearing (docs/catalogue.md), e.g. '6209'.")
    bearing: dict | None = Field(
        None,
        description="A bearing file's tables inline ({bearing = {...}, geometry = {...}}, "
        "docs/input-format.md).",
    )
    stiffness: LinearStiffnessSpec | None = None
    ratings: RatingsSpec | None = Field(
        None,
        description="A maker's C (and C0) for the lives, with designation or bearing (docs/catalogue.md: "
        "how a catalogue's ratings enter ISO 281 and ISO/TS 16281).",
    )
    position: schema.Length
    orientation: Literal["+z", "-z"] = "+z"
    axial: Literal["locating", "floating"] = "locating"
    axial_offset: schema.Length = 0.0
    housing: HousingSpec | None = None


class GearSpec(schema.Strict):
    """``[[shaft.gears]]``: a gear (or a pulley with pressure_angle 0 deg)."""

    name: str
    position: schema.Length
    pitch_diameter: schema.PositiveLength
    pressure_angle: schema.Angle = float(np.deg2rad(20.0))
    helix_angle: schema.Angle = 0.0
    mesh_angle: schema.Angle = 0.0
    mass: Mass = 0.0


class MassSpec(schema.Strict):
    """``[[shaft.masses]]``: a lumped mass (coupling, disc) that gravity loads."""

    name: str = "mass"
    position: schema.Length
    mass: PositiveMass


class ShaftSpec(schema.Strict):
    """``[shaft]``."""

    name: str = "shaft"
    material: schema.MaterialSpec | None = None
    gravity: Literal["+x", "-x", "+y", "-y", "+z", "-z"] | None = Field(
        None, description="Direction of gravity in shaft axes (standard gravity); none: weightless."
    )
    shear_deformation: bool = True
    max_element_length: schema.PositiveLength | None = None
    sections: list[SectionSpec]
    bearings: list[BearingSpec]
    gears: list[GearSpec] = Field(default_factory=list)
    masses: list[MassSpec] = Field(default_factory=list)

    @field_validator("bearings", mode="before")
    @classmethod
    def _few_bearings(cls, value):
        """Counted before the bearings are validated (each may name a file to read)."""
        if isinstance(value, list) and len(value) > MAX_SHAFT_BEARINGS:
            raise InputError(
                f"shaft.bearings ({len(value)} bearings) must be at most {MAX_SHAFT_BEARINGS} per shaft; "
                "a shaft rests on two to four"
            )
        return value


class ForceSpec(schema.Strict):
    """``forces = [{...}]`` of a load case: force and moment at a position."""

    name: str = "force"
    position: schema.Length
    F_x: schema.Force = 0.0
    F_y: schema.Force = 0.0
    F_z: schema.Force = 0.0
    M_x: schema.Moment = 0.0
    M_y: schema.Moment = 0.0


class LineLoadSpec(schema.Strict):
    """``line_loads = [{...}]`` of a load case: uniform load per length between start and end."""

    name: str = "line load"
    start: schema.Length
    end: schema.Length
    q_x: LineLoadValue = 0.0
    q_y: LineLoadValue = 0.0
    q_z: LineLoadValue = 0.0


class ShaftCaseSpec(schema.Strict):
    """``[[load_cases]]`` of a shaft file."""

    name: str
    speed: schema.AngularVelocity | None = None
    temperature: schema.Temperature | None = None
    gears: dict[str, schema.Moment] = Field(
        default_factory=dict, description="Torque each gear mesh applies to the shaft about +z."
    )
    forces: list[ForceSpec] = Field(default_factory=list)
    line_loads: list[LineLoadSpec] = Field(default_factory=list)


class ShaftSolverSpec(schema.Strict):
    """``[solver]`` of a shaft file."""

    rtol: schema.Dimensionless | None = None
    max_iterations: schema.IterationCount | None = None


#: Most load cases of one shaft file. Measured on the 2-core reference machine (countershaft example):
#: 100 cases take 24 s through ``bearingkit shaft``, 1,000 take 76 s and 300 MB.
MAX_SHAFT_CASES = 100
#: Most bearings on one shaft: shafts rest on two to four; 100 took 32 s per case batch and over
#: 90 s with ``--report`` (issue 41).
MAX_SHAFT_BEARINGS = 16
#: Estimated work of one bearing in one load case [s, 2-core reference machine, countershaft and
#: six-bearing variants measured]: the coupled solve with every bearing's pipeline (~0.035 s of
#: processor time), and its part of the HTML report (~0.7 s: a load-distribution figure and tables).
SHAFT_SOLVE_S = 0.05
SHAFT_REPORT_S = 0.8


class ShaftFile(schema.Strict):
    """A shaft input file."""

    shaft: ShaftSpec
    load_cases: list[ShaftCaseSpec]
    lubricant: schema.LubricantSpec | None = None
    lubrication: LubricationSpec | None = None
    thermal: ThermalSpec | None = None
    solver: ShaftSolverSpec | None = None

    @field_validator("load_cases", mode="before")
    @classmethod
    def _at_most(cls, value):
        """Counted before the cases are validated."""
        if isinstance(value, list) and len(value) > MAX_SHAFT_CASES:
            raise InputError(
                f"load_cases ({len(value)} cases) must be at most {MAX_SHAFT_CASES} per shaft file; "
                "split the file"
            )
        return value


_MODELS = {
    "": ShaftFile,
    "shaft": ShaftSpec,
    "shaft.sections": SectionSpec,
    "shaft.bearings": BearingSpec,
    "shaft.bearings.housing": HousingSpec,
    "shaft.bearings.stiffness": LinearStiffnessSpec,
    "shaft.gears": GearSpec,
    "shaft.masses": MassSpec,
    "shaft.material": schema.MaterialSpec,
    "load_cases": ShaftCaseSpec,
    "load_cases.forces": ForceSpec,
    "load_cases.line_loads": LineLoadSpec,
    "lubricant": schema.LubricantSpec,
    "lubrication": LubricationSpec,
    "thermal": ThermalSpec,
    "solver": ShaftSolverSpec,
}


@dataclass(frozen=True)
class ShaftInput:
    """A loaded shaft file (SI): the system, its load cases, solver options and notes.

    ``lubricant`` and ``lubrication`` (the ``[lubrication]`` section: contamination, roughness) apply to
    the bearings whose own file gives none.
    """

    source: str
    system: ShaftSystem
    loads: ShaftLoads
    options: SystemOptions
    lubricant: object | None = None
    warnings: tuple = field(default_factory=tuple)
    lubrication: LubricationSpec | None = None
    thermal: ThermalSpec | None = None

    def check_work(self, report: bool = False) -> None:
        """Refuse (:func:`bearingkit.budget.check_work`) a solve, or a solve and report, estimated
        past the work limit: bearings × load cases × :data:`SHAFT_SOLVE_S` (+ :data:`SHAFT_REPORT_S`)."""
        from bearingkit.budget import check_work

        n_b, n_c = len(self.system.bearings), len(self.loads.names)
        per = SHAFT_SOLVE_S + (SHAFT_REPORT_S if report else 0.0)
        what = f"{n_c} load cases x {n_b} bearings of the shaft{' with its report' if report else ''}"
        check_work(n_b * n_c * per, what, "give fewer load cases (or leave out the report)")

    def solve(self):
        """Solve every load case in one batch (a :class:`~bearingkit.systems.shaft.result.ShaftResult`)."""
        from bearingkit.systems.shaft.solver import solve

        self.check_work()
        return solve(self.system, self.loads, self.options)


def load_shaft_file(path) -> ShaftInput:
    """Read and validate a shaft file; InputError (one line naming the file and field) if malformed."""
    path = Path(path)
    data = load_toml(path)  # a regular file of at most 1 MiB, nesting bounded (bearingkit.io.reading)
    return shaft_from_dict(data, str(path), base=path.parent)


def shaft_from_dict(data: dict, source: str = "<dict>", base=None) -> ShaftInput:
    """Validate a parsed shaft file; bearing files are read relative to ``base`` (default cwd).

    With ``base`` (the shaft file's folder) every bearing ``file`` is confined by
    :func:`bearingkit.io.reading.confined_path` before it is opened (no ``~``, no NUL, nothing outside
    that folder and its project's folder above it); without it (a dict built by a program) names are
    taken relative to the working directory as given."""
    confine = base is not None
    base = Path(base) if base is not None else Path.cwd()
    try:
        spec = ShaftFile.model_validate(data)
    except ValidationError as exc:
        raise one_line(source, exc, (), _MODELS) from None
    try:
        return _build(spec, source, base, confine)
    except InputError as exc:
        text = str(exc)
        raise InputError(text if text.startswith(f"{source}:") else f"{source}: {text}") from None


def _material(spec: schema.MaterialSpec | None):
    from bearingkit.materials import MATERIALS, Material

    if spec is None or spec.name == SHAFT_STEEL.name:
        return SHAFT_STEEL
    if spec.name is not None:
        if spec.name not in MATERIALS:
            names = ", ".join([SHAFT_STEEL.name, *MATERIALS])
            raise InputError(f"shaft.material.name ({spec.name!r}) must be one of {names}")
        return MATERIALS[spec.name]
    return Material("shaft material", spec.youngs_modulus, spec.poisson_ratio, spec.density, source="input")


def _sections(specs: list[SectionSpec]) -> tuple:
    out, previous_end = [], 0.0
    for i, s in enumerate(specs):
        start = previous_end if s.start is None else s.start
        if (s.end is None) == (s.length is None):
            raise InputError(f"shaft.sections[{i}]: give exactly one of end and length")
        end = start + s.length if s.end is None else s.end
        if not end > start:
            raise InputError(
                f"shaft.sections[{i}].end ({end * 1e3:.6g} mm) must lie after its start "
                f"({start * 1e3:.6g} mm)"
            )
        try:
            out.append(Section(start, end, s.outer_diameter, s.inner_diameter))
        except InputError as exc:
            raise InputError(f"shaft.sections[{i}].{exc}") from None
        previous_end = end
    return tuple(out)


def _seat(i: int, b: BearingSpec, base: Path, confine: bool = False) -> BearingSeat:
    where = f"shaft.bearings[{i}] ({b.name})"
    if sum(v is not None for v in (b.file, b.designation, b.bearing, b.stiffness)) != 1:
        raise InputError(
            f"{where}: give exactly one of file (a bearing input file), designation (e.g. '6209'), "
            "bearing (a bearing file's tables inline) and stiffness"
        )
    rated = {}
    if b.ratings is not None:
        if b.designation is None and b.bearing is None:
            raise InputError(
                f"{where}.ratings: give them with designation or bearing (a bearing file's [bearing] takes "
                "rating_C and rating_C0 itself; a stiffness has no lives)"
            )
        rated = {"rating_C": f"{b.ratings.C} N"}
        if b.ratings.C0 is not None:
            rated["rating_C0"] = f"{b.ratings.C0} N"
    if b.bearing is not None:
        from bearingkit.io.loader import from_dict

        tables = dict(b.bearing)
        if rated:
            header = tables.get("bearing") if isinstance(tables.get("bearing"), dict) else {}
            if {"rating_C", "rating_C0", "C"} & set(header):
                raise InputError(
                    f"{where}.ratings: its bearing table gives its own ratings ([bearing] rating_C or C); "
                    "give them in one place"
                )
            tables["bearing"] = {**header, **rated}
        source = from_dict(tables, source=f"{where}.bearing")  # its errors name the source
        bearing = source.model
    elif b.designation is not None:
        from bearingkit.io.loader import from_dict

        try:
            source = from_dict({"bearing": {"designation": b.designation, **rated}}, source=b.designation)
        except InputError as exc:
            raise InputError(f"{where}.designation: {exc}") from None
        bearing = source.model
    elif b.file is not None:
        try:
            if confine:  # a name from a file: checked and resolved before anything opens it
                path = confined_path(b.file, base, "file")
            else:
                path = Path(b.file)
                path = path if path.is_absolute() else base / path
            source = load_file(path)
        except InputError as exc:
            raise InputError(f"{where}.file: {exc}") from None
        bearing = source.model
    else:
        k = b.stiffness
        source = None
        bearing = LinearBearing(
            np.diag([k.radial, k.radial, k.axial, k.tilt, k.tilt]),
            name=b.name,
            axial_direction=AXIAL_DIRECTIONS[k.axial_direction],
        )
    housing = None
    if b.housing is not None:
        h = b.housing
        vals = [h.radial, h.radial, h.axial, h.tilt, h.tilt]
        housing = np.array([np.inf if v is None else v for v in vals])
    return BearingSeat(
        name=b.name,
        bearing=bearing,
        position=b.position,
        orientation=b.orientation,
        axial=b.axial,
        axial_offset=b.axial_offset,
        housing_stiffness=housing,
        source=source,
    )


def _loads(cases: list[ShaftCaseSpec], gravity) -> ShaftLoads:
    n = len(cases)
    if n == 0:
        raise InputError("load_cases (none): give at least one [[load_cases]]")
    forces, lines, torques = [], [], {}
    for c, case in enumerate(cases):
        for f in case.forces:
            load = np.zeros((n, 5))
            load[c] = [f.F_x, f.F_y, f.F_z, f.M_x, f.M_y]
            forces.append(PointLoad(f.position, load, f.name))
        for q in case.line_loads:
            load = np.zeros((n, 3))
            load[c] = [q.q_x, q.q_y, q.q_z]
            if not q.end > q.start:
                raise InputError(f"load_cases[{c}].line_loads ({q.name}): end must lie after start")
            lines.append(LineLoad(q.start, q.end, load, q.name))
        for gear, torque in case.gears.items():
            torques.setdefault(gear, np.zeros(n))[c] = torque
    per_case = {}
    for attr in ("speed", "temperature"):
        values = [getattr(c, attr) for c in cases]
        given = [v is not None for v in values]
        if any(given) and not all(given):
            missing = cases[given.index(False)].name
            raise InputError(
                f"load_cases: case {missing!r} has no {attr} while others do; give it in every case"
            )
        per_case[attr] = np.array(values, dtype=float) if all(given) else None
    return ShaftLoads(
        names=tuple(c.name for c in cases),
        forces=tuple(forces),
        line_loads=tuple(lines),
        gear_torques=torques,
        gravity=None if gravity is None else STANDARD_GRAVITY * np.asarray(AXES[gravity]),
        speed=per_case["speed"],
        temperature=per_case["temperature"],
    )


@dataclass(frozen=True)
class _HasModel:
    """A bearing model seen as an input (what :func:`bearingkit.pipeline.operating.check_speeds` reads)."""

    model: object


def _build(spec: ShaftFile, source: str, base: Path, confine: bool = False) -> ShaftInput:
    s = spec.shaft
    shaft = Shaft(_sections(s.sections), _material(s.material), s.shear_deformation, s.name)
    seats = tuple(_seat(i, b, base, confine) for i, b in enumerate(s.bearings))
    gears = tuple(
        Gear(g.name, g.position, g.pitch_diameter, g.pressure_angle, g.helix_angle, g.mesh_angle, g.mass)
        for g in s.gears
    )
    masses = tuple(PointMass(m.position, m.mass, m.name) for m in s.masses)
    loads = _loads(spec.load_cases, s.gravity)
    if loads.speed is not None:  # n·d_m of every bearing within what rolling bearings run at
        from bearingkit.pipeline.operating import check_speeds

        for seat in seats:
            if hasattr(seat.bearing, "rows"):
                check_speeds(_HasModel(seat.bearing), loads.speed, list(loads.names))
    try:
        system = ShaftSystem(shaft, seats, gears, masses, s.max_element_length, s.name)
        system.check_loads(loads)
    except InputError as exc:  # the system names its own fields: place them in the file
        text = str(exc)
        if text.startswith(("bearings", "gears", "masses")):
            text = "shaft." + text
        elif text.startswith(("forces", "line_loads")):
            text = "load_cases: " + text
        raise InputError(text) from None
    notes = []
    for c, name in enumerate(loads.names):
        torques = [np.broadcast_to(t, (loads.n_cases,))[c] for t in loads.gear_torques.values()]
        total, size = float(np.sum(torques)) if torques else 0.0, max((abs(t) for t in torques), default=0.0)
        if abs(total) > 1e-6 * max(size, 1e-300):
            notes.append(
                f"load case {name!r}: the gear torques do not balance (sum {total:.6g} N·m); the shaft's "
                "torsion is not modelled, so the remainder is taken as passing to a coupling"
            )
    opts = {}
    if spec.solver is not None:
        opts = {
            k: v for k, v in (("rtol", spec.solver.rtol), ("max_iterations", spec.solver.max_iterations)) if v
        }
    from bearingkit.io.loader import lubricant_of

    lubricant = lubricant_of(source, spec.lubricant)  # the one lubricant builder (a name or the data)
    _check_contamination(spec.lubrication)
    return ShaftInput(
        source, system, loads, SystemOptions(**opts), lubricant, tuple(notes), spec.lubrication, spec.thermal
    )


def _check_contamination(lubrication) -> None:
    """``[lubrication] contamination``: a number 0 … 1 or an ISO 281 level name (one line otherwise)."""
    from bearingkit.physics.life.iso281_contamination import contamination_levels

    value = None if lubrication is None else lubrication.contamination
    if value is None:
        return
    if isinstance(value, str) and value.strip() not in contamination_levels():
        from bearingkit.units import parse

        try:
            value = parse(value, "dimensionless", "lubrication.contamination")
        except InputError:
            raise InputError(
                f"lubrication.contamination ({value!r}) must be a number 0 … 1 or one of "
                f"{', '.join(contamination_levels())}"
            ) from None
    if not isinstance(value, str) and not 0.0 <= float(value) <= 1.0:
        raise InputError(f"lubrication.contamination ({value!r}) must lie in 0 … 1 (ISO 281 e_C)")


def shaft_dict(inp: ShaftInput, result=None, **options) -> dict:
    """Everything a face shows about a solved shaft file, JSON-ready (SI, units in keys).

    :meth:`bearingkit.systems.shaft.shaft_analysis.ShaftAnalysis.to_dict`: the inputs; per case the shaft
    lines, every bearing's reactions, seat state, summary and full pipeline Analysis (pressures, lives,
    friction), the system life and every warning; the notes. ``options`` go to the ShaftAnalysis
    (``friction_model``, ``contamination``, ``reliability``).
    """
    from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis

    return ShaftAnalysis(inp, result, **options).to_dict()
