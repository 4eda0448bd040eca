"""The drivetrain input file (TOML, docs/drivetrains.md): shafts, bearings, gears, meshes, planetary stages.

Units at the edge (``"45 mm"``, ``"200 N*m"``, ``"1500 rpm"``), SI after validation. Layout::

    [drivetrain]          name, held (the output shaft: its rotation is held), gravity
    [[shafts]]            name, centre = [x, y], axial_offset, material, shear_deformation,
                          max_element_length, axis
    [[shafts.sections]]   as in a shaft file (docs/systems.md)
    [[shafts.bearings]]   as in a shaft file, plus outer (a shaft: shaft-in-shaft; default the
                          housing) and outer_position (where on that shaft)
    [[shafts.gears]]      name, position, teeth, normal_module, pressure_angle, helix_angle,
                          hand ("right" | "left"), face_width, profile_shift, internal, mass
    [[shafts.masses]]     name, position, mass
    [[meshes]]            name, gears = [A, B], stiffness (default ISO 6336-1), friction (μ_mz)
    [[planetary]]         sun, ring or ring_teeth (a ring fixed in the housing), carrier,
                          carrier_position, planets, planet = {...}, planet_bearings, pin_errors …
    [[load_cases]]        name, torques = {shaft = torque}, speed = {shaft = speed}, temperature,
                          time_fraction, forces = [{shaft, position, F_x …}], line_loads = [...]
    [lubricant] [lubrication] [thermal] [solver] [budget]

The REXS reader (:mod:`bearingkit.io.rexs.reader`) writes the same dictionary, so both paths build one model.
Every malformed input is one :class:`~bearingkit.errors.InputError` line ``FILE: field (value) …``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

import numpy as np
from pydantic import Field, ValidationError

from bearingkit.errors import InputError
from bearingkit.io import schema
from bearingkit.io.messages import one_line
from bearingkit.io.optional_sections.operating import LubricationSpec, ThermalSpec
from bearingkit.io.reading import load_toml
from bearingkit.systems.drivetrain import model as dtm
from bearingkit.systems.drivetrain.gearing import GearGeometry, GearPair
from bearingkit.systems.drivetrain.model import (
    HOUSING,
    Attachment,
    DriveBearing,
    DriveGear,
    DriveShaft,
    Drivetrain,
    Mesh,
)
from bearingkit.systems.shaft.input import (
    BearingSpec,
    ForceSpec,
    LineLoadSpec,
    MassSpec,
    SectionSpec,
    ShaftSolverSpec,
    _check_contamination,
    _material,
    _seat,
    _sections,
)
from bearingkit.systems.shaft.loads import (
    AXES,
    STANDARD_GRAVITY,
    LineLoad,
    PointLoad,
    PointMass,
    ShaftLoads,
)
from bearingkit.systems.shaft.shaft import Shaft
from bearingkit.systems.shaft.solver import SystemOptions

Stiffness = schema.quantity("stiffness", "positive")


class DriveGearSpec(schema.Strict):
    """``[[shafts.gears]]``: an involute cylindrical gear."""

    name: str
    position: schema.Length
    teeth: int = Field(ge=5, le=1000)
    normal_module: schema.PositiveLength
    pressure_angle: schema.Angle = float(np.deg2rad(20.0))
    helix_angle: schema.Angle = 0.0
    hand: Literal["right", "left"] = "right"
    face_width: schema.PositiveLength
    profile_shift: schema.Dimensionless = 0.0
    internal: bool = False
    mass: schema.quantity("mass", "non_negative") = 0.0


class DriveBearingSpec(BearingSpec):
    """``[[shafts.bearings]]``: a shaft file's bearing, and the part its outer ring sits in."""

    outer: str = Field(HOUSING, description="'housing' or the shaft the outer ring sits in (shaft-in-shaft).")
    outer_position: schema.Length | None = None


class DriveShaftSpec(schema.Strict):
    """``[[shafts]]``."""

    name: str
    centre: list[schema.Length] = Field(default_factory=lambda: [0.0, 0.0])
    axial_offset: schema.Length = 0.0
    axis: list[float] = Field(default_factory=lambda: [0.0, 0.0, 1.0])
    material: schema.MaterialSpec | None = None
    shear_deformation: bool = True
    max_element_length: schema.PositiveLength | None = None
    sections: list[SectionSpec]
    bearings: list[DriveBearingSpec] = Field(default_factory=list)
    gears: list[DriveGearSpec] = Field(default_factory=list)
    masses: list[MassSpec] = Field(default_factory=list)


class MeshSpec(schema.Strict):
    """``[[meshes]]``: two gears (by name) in mesh."""

    name: str
    gears: list[str]
    stiffness: Stiffness | None = None
    friction: schema.Dimensionless | None = None


class DriveForceSpec(ForceSpec):
    """``forces = [{...}]``: a force on a shaft."""

    shaft: str


class DriveLineLoadSpec(LineLoadSpec):
    shaft: str


class DriveCaseSpec(schema.Strict):
    """``[[load_cases]]`` of a drivetrain file."""

    name: str
    torques: dict[str, schema.Moment] = Field(default_factory=dict)
    speed: dict[str, schema.AngularVelocity] = Field(default_factory=dict)
    temperature: schema.Temperature | None = None
    time_fraction: schema.Dimensionless | None = None
    forces: list[DriveForceSpec] = Field(default_factory=list)
    line_loads: list[DriveLineLoadSpec] = Field(default_factory=list)


class DrivetrainSpec(schema.Strict):
    """``[drivetrain]``."""

    name: str = "drivetrain"
    held: str | None = None
    gravity: Literal["+x", "-x", "+y", "-y", "+z", "-z"] | None = None


class BudgetSpec(schema.Strict):
    """``[budget]``: raise the work budget (module :mod:`bearingkit.systems.drivetrain.model`)."""

    max_shafts: int | None = Field(None, ge=1, le=1000)
    max_bearings: int | None = Field(None, ge=1, le=5000)
    max_load_cases: int | None = Field(None, ge=1, le=5000)


class DrivetrainFile(schema.Strict):
    drivetrain: DrivetrainSpec = Field(default_factory=DrivetrainSpec)
    shafts: list[DriveShaftSpec]
    meshes: list[MeshSpec] = Field(default_factory=list)
    planetary: list[dict] = Field(default_factory=list)
    load_cases: list[DriveCaseSpec]
    lubricant: schema.LubricantSpec | None = None
    lubrication: LubricationSpec | None = None
    thermal: ThermalSpec | None = None
    solver: ShaftSolverSpec | None = None
    budget: BudgetSpec | None = None


_MODELS = {
    "": DrivetrainFile,
    "drivetrain": DrivetrainSpec,
    "shafts": DriveShaftSpec,
    "shafts.sections": SectionSpec,
    "shafts.bearings": DriveBearingSpec,
    "shafts.gears": DriveGearSpec,
    "shafts.masses": MassSpec,
    "shafts.material": schema.MaterialSpec,
    "meshes": MeshSpec,
    "load_cases": DriveCaseSpec,
    "load_cases.forces": DriveForceSpec,
    "load_cases.line_loads": DriveLineLoadSpec,
    "lubricant": schema.LubricantSpec,
    "lubrication": LubricationSpec,
    "thermal": ThermalSpec,
    "solver": ShaftSolverSpec,
    "budget": BudgetSpec,
}


@dataclass(frozen=True)
class DrivetrainInput:
    """A loaded drivetrain file (SI): the model, its load cases, speeds, solver options and notes."""

    source: str
    drivetrain: Drivetrain
    loads: dict
    options: SystemOptions
    lubricant: object | None = None
    lubrication: LubricationSpec | None = None
    warnings: tuple = field(default_factory=tuple)
    data: dict | None = None  # the validated dictionary (REXS export, studies)
    thermal: ThermalSpec | None = None  # [thermal]: every bearing's temperature by its heat balance

    @property
    def case_names(self) -> tuple:
        return tuple(self.loads["names"])


def is_drivetrain_file(path) -> bool:
    """Whether a TOML file is a drivetrain file (a ``[[shafts]]`` array) — without raising."""
    try:
        data = load_toml(Path(path))
    except Exception:
        return False
    return isinstance(data.get("shafts"), list)


def load_drivetrain_file(path, cases=None) -> DrivetrainInput:
    """Read a drivetrain file (TOML, or REXS .rexs/.rexsj/.rexs.json/.rexs.xml); one InputError line
    naming the file and field if malformed. ``cases``: names of the load cases to keep (all when None);
    a subset drops the cases' ``time_fraction`` (it no longer adds up to 1: no duty cycle)."""
    path = Path(path)
    name = path.name.lower()
    if name.endswith((".rexs", ".rexsj", ".rexs.json", ".rexs.xml")):
        from bearingkit.io.rexs.reader import REXS_NOTES, read_rexs

        data = read_rexs(path)
        imported = tuple(data.pop(REXS_NOTES, ()))
    else:
        data, imported = load_toml(path), ()
    if cases:
        data = _keep_cases(data, list(cases), str(path))
    return drivetrain_from_dict(data, str(path), base=path.parent, notes=imported)


def _keep_cases(data, names: list, source: str):
    """The file's data with only the named load cases (in the file's order), without time fractions."""
    found = data.get("load_cases") if isinstance(data, dict) else None
    if not isinstance(found, list) or not all(isinstance(c, dict) for c in found):
        return data  # validation says what is wrong (with the file's own index of a bad case)
    have = [c.get("name") for c in found]
    unknown = [n for n in names if n not in have]
    if unknown:
        raise InputError(f"{source}: no load case {unknown[0]!r}; the file has {have}")
    kept = [{k: v for k, v in c.items() if k != "time_fraction"} for c in found if c.get("name") in names]
    return {**data, "load_cases": kept}


def drivetrain_from_dict(data: dict, source: str = "<dict>", base=None, notes=()) -> DrivetrainInput:
    """Validate a parsed drivetrain file; bearing files are read relative to ``base`` (default cwd).
    ``notes``: lines the reader of the file adds (a REXS import's), shown with the result's notes."""
    base = Path(base) if base is not None else Path.cwd()
    cases = data.get("load_cases") if isinstance(data, dict) else None
    budget = (data.get("budget") or {}) if isinstance(data, dict) else {}
    cap = budget.get("max_load_cases", dtm.MAX_LOAD_CASES) if isinstance(budget, dict) else dtm.MAX_LOAD_CASES
    if isinstance(cases, list) and isinstance(cap, int) and len(cases) > cap:
        raise InputError(
            f"{source}: load_cases ({len(cases)}) exceeds the work budget of {cap} per drivetrain; raise it "
            f"with [budget] max_load_cases = {len(cases)} in the file (each case is a Newton and every "
            "bearing's analysis)"
        )
    try:
        spec = DrivetrainFile.model_validate(data)
    except ValidationError as exc:
        raise one_line(source, exc, (), _MODELS) from None
    try:
        return _build(spec, source, base, data, tuple(notes))
    except InputError as exc:
        text = str(exc)
        raise InputError(text if text.startswith(f"{source}:") else f"{source}: {text}") from None


def gear_geometry(g: DriveGearSpec) -> GearGeometry:
    beta = abs(g.helix_angle) * (1.0 if g.hand == "right" else -1.0)
    return GearGeometry(
        teeth=g.teeth,
        normal_module=g.normal_module,
        pressure_angle=g.pressure_angle,
        helix_angle=beta,
        face_width=g.face_width,
        profile_shift=g.profile_shift,
        internal=g.internal,
    )


def _shaft(i: int, s: DriveShaftSpec) -> DriveShaft:
    where = f"shafts[{i}] ({s.name})"
    if len(s.centre) != 2:
        raise InputError(f"{where}.centre ({len(s.centre)} values) must be two lengths [x, y]")
    try:
        shaft = Shaft(_sections(s.sections), _material(s.material), s.shear_deformation, s.name)
        gears = []
        for j, g in enumerate(s.gears):
            try:
                gears.append(DriveGear(g.name, g.position, gear_geometry(g), g.mass))
            except InputError as exc:
                raise InputError(f"gears[{j}] ({g.name}).{exc}") from None
        masses = tuple(PointMass(m.position, m.mass, m.name) for m in s.masses)
        return DriveShaft(
            shaft, tuple(s.centre), s.axial_offset, tuple(gears), masses, tuple(s.axis), s.max_element_length
        )
    except InputError as exc:
        text = str(exc)
        raise InputError(text if text.startswith("shafts") else f"{where}.{text}") from None


def _bearings(specs: list[DriveShaftSpec], shafts: dict, base: Path) -> list[DriveBearing]:
    out = []
    for i, s in enumerate(specs):
        for j, b in enumerate(s.bearings):
            try:
                seat = _seat(j, b, base)
            except InputError as exc:
                raise InputError(f"shafts[{i}] ({s.name}).{str(exc).removeprefix('shaft.')}") from None
            where = f"shafts[{i}] ({s.name}).bearings[{j}] ({b.name})"
            if b.outer != HOUSING:
                if b.outer not in shafts:
                    raise InputError(
                        f"{where}.outer ({b.outer!r}) must be 'housing' or a shaft: {list(shafts)}"
                    )
                if b.outer_position is None:
                    raise InputError(
                        f"{where}.outer_position: give where on shaft {b.outer!r} its outer ring sits"
                    )
                outer = Attachment(b.outer, b.outer_position)
            else:
                outer = Attachment(HOUSING, 0.0)
            out.append(DriveBearing(seat, Attachment(s.name, b.position), outer))
    return out


def _meshes(specs: list[MeshSpec], shafts: list[DriveShaft]) -> list[Mesh]:
    where_is = {}
    for s in shafts:
        for g in s.gears:
            if g.name in where_is:
                raise InputError(
                    f"shafts.{s.name}.gears.{g.name}: gear names must be unique in the drivetrain"
                )
            where_is[g.name] = (s.name, g)
    out = []
    for i, m in enumerate(specs):
        where = f"meshes[{i}] ({m.name})"
        if len(m.gears) != 2:
            raise InputError(f"{where}.gears ({m.gears}) must name two gears")
        for g in m.gears:
            if g not in where_is:
                raise InputError(f"{where}.gears: {g!r} is no gear of the shafts; gears are {list(where_is)}")
        (sa, ga), (sb, gb) = (where_is[g] for g in m.gears)
        if sa == sb:
            raise InputError(f"{where}: gears {m.gears} are on the same shaft {sa!r}")
        if ga.geometry.internal:
            (sa, ga), (sb, gb) = (sb, gb), (sa, ga)
        try:
            pair = GearPair(ga.geometry, gb.geometry, f"meshes.{m.name}")
        except InputError as exc:
            raise InputError(str(exc)) from None
        out.append(Mesh(m.name, (sa, ga.name), (sb, gb.name), pair, m.stiffness, m.friction))
    return out


def _loads(spec: DrivetrainFile, shafts: list[DriveShaft]) -> dict:
    cases = spec.load_cases
    n = len(cases)
    if n == 0:
        raise InputError("load_cases (none): give at least one [[load_cases]]")
    names = [s.name for s in shafts]
    gravity = spec.drivetrain.gravity
    g_vec = None if gravity is None else STANDARD_GRAVITY * np.asarray(AXES[gravity])
    per = {s: {"forces": [], "lines": []} for s in names}
    torques, speeds = {}, {}
    for c, case in enumerate(cases):
        for f in case.forces:
            if f.shaft not in per:
                raise InputError(
                    f"load_cases[{c}].forces ({f.name}).shaft ({f.shaft!r}) must be one of {names}"
                )
            load = np.zeros((n, 5))
            load[c] = [f.F_x, f.F_y, f.F_z, f.M_x, f.M_y]
            per[f.shaft]["forces"].append(PointLoad(f.position, load, f.name))
        for q in case.line_loads:
            if q.shaft not in per:
                raise InputError(
                    f"load_cases[{c}].line_loads ({q.name}).shaft ({q.shaft!r}) must be one of {names}"
                )
            load = np.zeros((n, 3))
            load[c] = [q.q_x, q.q_y, q.q_z]
            per[q.shaft]["lines"].append(LineLoad(q.start, q.end, load, q.name))
        for key, target, what in ((case.torques, torques, "torques"), (case.speed, speeds, "speed")):
            for shaft, value in key.items():
                if shaft not in per:
                    raise InputError(
                        f"load_cases[{c}].{what}.{shaft}: no shaft of that name; shafts are {names}"
                    )
                target.setdefault(shaft, np.zeros(n))[c] = value
        if spec.drivetrain.held in case.torques:
            raise InputError(
                f"load_cases[{c}].torques.{spec.drivetrain.held}: the held shaft takes the reaction torque; "
                "give torques on the other shafts"
            )
    temps = [c.temperature for c in cases]
    if any(t is not None for t in temps) and not all(t is not None for t in temps):
        raise InputError("load_cases: give a temperature in every case or in none")
    speed_keys = {tuple(sorted(c.speed)) for c in cases}
    if len(speed_keys) > 1:
        raise InputError("load_cases.speed: give the speed of the same shaft(s) in every case")
    fractions = [c.time_fraction for c in cases]
    if any(f is not None for f in fractions):
        if not all(f is not None for f in fractions):
            raise InputError("load_cases.time_fraction: give it in every case (a duty cycle) or in none")
        if not all(f >= 0 for f in fractions) or not np.isclose(sum(fractions), 1.0, rtol=1e-6):
            raise InputError(f"load_cases.time_fraction ({fractions}) must be non-negative and add up to 1")
    shaft_loads = {
        s: ShaftLoads(
            names=tuple(c.name for c in cases),
            forces=tuple(v["forces"]),
            line_loads=tuple(v["lines"]),
            gravity=g_vec,
        )
        for s, v in per.items()
    }
    return {
        "names": tuple(c.name for c in cases),
        "n_cases": n,
        "shafts": shaft_loads,
        "torques": torques,
        "given_speeds": speeds,
        "temperature": np.array(temps, float) if all(t is not None for t in temps) else None,
        "time_fraction": np.array(fractions, float) if all(f is not None for f in fractions) else None,
    }


def _build(spec: DrivetrainFile, source: str, base: Path, data: dict, notes=()) -> DrivetrainInput:
    from bearingkit.systems.drivetrain.planetary import expand_stages

    shafts = [_shaft(i, s) for i, s in enumerate(spec.shafts)]
    names = {s.name: s for s in shafts}
    bearings = _bearings(spec.shafts, names, base)
    meshes = _meshes(spec.meshes, shafts)
    stages = expand_stages(spec.planetary, shafts, base)
    budget = {}
    if spec.budget is not None:
        budget = {k.removeprefix("max_"): v for k, v in spec.budget.model_dump().items() if v is not None}
    dt = Drivetrain(
        tuple(shafts) + stages["shafts"],
        tuple(bearings) + stages["bearings"],
        tuple(meshes) + stages["meshes"],
        spec.drivetrain.held,
        stages["housing_gears"],
        spec.drivetrain.name,
        stages["stages"],
        budget,
    )
    loads = _loads(spec, list(dt.shafts))
    for shaft, sl in loads["shafts"].items():
        body = dt.body(shaft)
        for f in sl.forces:
            body.shaft.check_position(
                f"load_cases.forces ({f.name}).position", f.position, f"on shaft {shaft!r}"
            )
    if dt.held is None:
        raise InputError(
            "drivetrain.held: name the output shaft whose rotation is held (it takes the reaction torque)"
        )
    opts = {}
    if spec.solver is not None:
        opts = {
            k: v for k, v in (("rtol", spec.solver.rtol), ("max_iterations", spec.solver.max_iterations)) if v
        }
    lubricant = None
    if spec.lubricant is not None:
        from bearingkit.lubricants import LUBRICANTS

        if spec.lubricant.name not in LUBRICANTS:
            raise InputError(
                f"lubricant.name ({spec.lubricant.name!r}) must be one of {', '.join(LUBRICANTS)}"
            )
        lubricant = LUBRICANTS[spec.lubricant.name]
    _check_contamination(spec.lubrication)
    notes = [
        "shafts are rigid in torsion (one rotation per shaft); mesh forces follow the lossless torque "
        "balance, losses are taken from the output power",
        *notes,
    ]
    options = SystemOptions(**opts)
    return DrivetrainInput(
        source, dt, loads, options, lubricant, spec.lubrication, tuple(notes), data, spec.thermal
    )
