"""A drivetrain: several shafts joined by gear meshes and coaxial bearings, held by a housing.

SI units (m, N, N·m, rad). Every shaft is a Timoshenko beam (:mod:`bearingkit.systems.shaft.shaft`) whose
axis is parallel to the gearbox's z axis, at ``centre`` (x, y), with its local z = 0 at the gearbox's
``axial_offset``. Displacements of every shaft are in the gearbox axes; each shaft adds one rotation
about its axis θ_z (the shaft is rigid in torsion: torsion is not modelled, the rotation carries the
torque from its gears to its loads). Bodies (:class:`DriveShaft`) are the shafts, the planets of
planetary stages and the housing (ground).

Each bearing (:class:`DriveBearing`) connects its inner ring to a point of one body and its outer ring
to a point of another body or the housing; a point sits on the body's axis at a node, or off the axis
on a rigid arm (the pins of a planet carrier). The bearing sees q = T (x_inner − x_outer) in its own
frame (:mod:`bearingkit.systems.shaft.supports`, orientation T). A gear mesh (:class:`Mesh`) is a linear
spring k along the line of action n between the two gears' material points at the pitch point:
δ = n·(v_a − v_b), energy ½ k δ² (:mod:`bearingkit.systems.drivetrain.gearing`); with the shafts' rotations
among
the unknowns, the mesh carries the transmitted torque by its own deflection, so the whole drivetrain is
one potential and one Newton (:mod:`bearingkit.systems.drivetrain.solver`).

The ``held`` shaft's rotation is held (the output: it takes the reaction torque); the load cases apply
torques to other shafts (the inputs). Speeds follow from the gear ratios
(:mod:`bearingkit.systems.drivetrain.power_flow`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.systems.drivetrain.gearing import CENTRE_DISTANCE_RTOL, GearGeometry, GearPair
from bearingkit.systems.shaft.shaft import POSITION_TOL, Shaft
from bearingkit.systems.shaft.supports import BearingSeat

#: Name of the ground body (the gearbox housing).
HOUSING = "housing"
#: Work budget of one drivetrain (each raises the solve's cost: the global Newton's matrix grows with
#: the shafts and bearings, every bearing is a pipeline analysis per load case). Raise with the file's
#: ``[budget]`` table (docs/drivetrains.md).
MAX_SHAFTS = 24
MAX_BEARINGS = 60
MAX_LOAD_CASES = 50


@dataclass(frozen=True)
class DriveGear:
    """A cylindrical gear fixed on a body at axial ``position`` [m] (local z), with its geometry."""

    name: str
    position: float
    geometry: GearGeometry
    mass: float = 0.0

    def __post_init__(self):
        checks.finite(f"{self.name}.position", self.position, "m")
        checks.non_negative(f"{self.name}.mass", self.mass, "kg")


@dataclass(frozen=True, eq=False)
class DriveShaft:
    """A body of the drivetrain: a shaft (or a planet) on the gearbox's z axis direction.

    Parameters
    ----------
    shaft : Shaft
    centre : tuple (x, y) [m]
        Where its axis crosses the gearbox's x–y plane.
    axial_offset : float [m]
        Gearbox z of the shaft's local z = 0.
    gears : tuple of DriveGear
    masses : tuple of PointMass
    axis : tuple (3,)
        Direction of the axis (must be ±z: only parallel-axis drivetrains are modelled).
    max_element_length : float or None [m]
    """

    shaft: Shaft
    centre: tuple = (0.0, 0.0)
    axial_offset: float = 0.0
    gears: tuple = ()
    masses: tuple = ()
    axis: tuple = (0.0, 0.0, 1.0)
    max_element_length: float | None = None

    @property
    def name(self) -> str:
        return self.shaft.name

    def __post_init__(self):
        object.__setattr__(self, "gears", tuple(self.gears))
        object.__setattr__(self, "masses", tuple(self.masses))
        c = np.asarray(self.centre, dtype=float).reshape(-1)
        if c.shape != (2,):
            raise InputError(f"shafts.{self.name}.centre ({self.centre!r}) must be two lengths (x, y)")
        checks.finite(f"shafts.{self.name}.centre", c, "m")
        object.__setattr__(self, "centre", (float(c[0]), float(c[1])))
        for g in self.gears:
            self.shaft.check_position(f"shafts.{self.name}.gears.{g.name}.position", g.position)
        for m in self.masses:
            self.shaft.check_position(f"shafts.{self.name}.masses.{m.name}.position", m.position)

    def gear(self, name: str) -> DriveGear:
        for g in self.gears:
            if g.name == name:
                return g
        raise InputError(
            f"gear ({name!r}) is not on shaft {self.name!r}; its gears are {[g.name for g in self.gears]}"
        )


@dataclass(frozen=True)
class Attachment:
    """Where a ring of a bearing sits: a body, the node at local z ``position`` [m] and a rigid ``arm``
    (x, y, z) [m] from that node (0 on the axis); ``error`` (x, y) [m] a fixed position error (a pin)."""

    body: str
    position: float = 0.0
    arm: tuple = (0.0, 0.0, 0.0)
    error: tuple = (0.0, 0.0)


@dataclass(frozen=True, eq=False)
class DriveBearing:
    """A bearing of the drivetrain: its seat (law, orientation, axial location, housing stiffness) and
    the bodies its rings sit on (``outer.body`` = :data:`HOUSING` for a housing bearing).

    ``rotating``: which ring turns relative to the load in the ratings ("inner" or "outer").
    ``frame_body``: the body whose rotation is the reference of the ring speeds (a planet bearing's
    carrier; None = the housing).
    """

    seat: BearingSeat
    inner: Attachment
    outer: Attachment
    frame_body: str | None = None

    @property
    def name(self) -> str:
        return self.seat.name


@dataclass(frozen=True, eq=False)
class Mesh:
    """Two gears in mesh: ``a`` and ``b`` as (body, gear name); a ring gear on the housing is
    (:data:`HOUSING`, name). ``stiffness`` [N/m] along the line of action (None: ISO 6336-1 from the
    geometry); ``friction`` μ_mz [-] for the mesh loss (None: no mesh loss)."""

    name: str
    a: tuple
    b: tuple
    pair: GearPair
    stiffness: float | None = None
    friction: float | None = None
    frame_body: str | None = None  # a planetary stage's carrier: the mesh rolls relative to it

    def __post_init__(self):
        if self.stiffness is not None:
            checks.positive(f"meshes.{self.name}.stiffness", self.stiffness, "N/m")
        if self.friction is not None:
            checks.in_range(f"meshes.{self.name}.friction", self.friction, 0.0, 0.3, "")

    @property
    def k(self) -> float:
        """Mesh stiffness along the line of action [N/m]."""
        return self.stiffness if self.stiffness is not None else self.pair.mesh_stiffness()


@dataclass(frozen=True, eq=False)
class Drivetrain:
    """Bodies, bearings, meshes, the held (output) shaft and the housing gears (fixed ring gears).

    Checks (one line naming the part): unique names, every shaft held by at least one bearing, every
    bearing's bodies known, meshing gears on parallel shafts at the centre distance their geometry
    gives, and the work budget.
    """

    shafts: tuple
    bearings: tuple
    meshes: tuple = ()
    held: str | None = None
    housing_gears: tuple = ()  # DriveGear on the housing with their centre: ((gear, (x, y), z), ...)
    name: str = "drivetrain"
    stages: tuple = ()  # planetary stage descriptions (for outputs)
    budget: dict = field(default_factory=dict)

    def __post_init__(self):
        for attr in ("shafts", "bearings", "meshes", "housing_gears", "stages"):
            object.__setattr__(self, attr, tuple(getattr(self, attr)))
        limits = {"shafts": MAX_SHAFTS, "bearings": MAX_BEARINGS, **self.budget}
        for what in ("shafts", "bearings"):
            n, cap = len(getattr(self, what)), int(limits[what])
            if n > cap:
                raise InputError(
                    f"{what} ({n}) exceeds the work budget of {cap} per drivetrain; raise it with "
                    f"[budget] max_{what} = {n} in the file (each adds to the global Newton's matrix)"
                )
        if not self.shafts:
            raise InputError("shafts (none): a drivetrain needs at least one [[shafts]]")
        names = [s.name for s in self.shafts]
        if len(set(names)) != len(names) or HOUSING in names:
            raise InputError(f"shafts names ({names}) must be unique and not {HOUSING!r}")
        bnames = [b.name for b in self.bearings]
        if len(set(bnames)) != len(bnames):
            raise InputError(f"bearings names ({bnames}) must be unique across the drivetrain")
        held_by = {n: 0 for n in names}
        for b in self.bearings:
            for side, att in (("inner", b.inner), ("outer", b.outer)):
                if att.body != HOUSING and att.body not in held_by:
                    raise InputError(
                        f"bearings.{b.name}.{side} ({att.body!r}) is not a shaft of the drivetrain; "
                        f"shafts are {names}"
                    )
                if att.body != HOUSING:
                    self.body(att.body).shaft.check_position(
                        f"bearings.{b.name}.{side} position", att.position
                    )
                    held_by[att.body] += 1
            if b.inner.body == b.outer.body:
                raise InputError(
                    f"bearings.{b.name}: inner and outer ring on the same shaft {b.inner.body!r}"
                )
        for s in self.shafts:
            if held_by[s.name] == 0:
                raise InputError(
                    f"shafts.{s.name}: no bearing supports it (no bearing has it as inner or outer part); "
                    "give it bearings (a shaft with no support is free)"
                )
            ax = np.asarray(s.axis, dtype=float)
            if not np.allclose(np.abs(ax / np.linalg.norm(ax)), [0.0, 0.0, 1.0], atol=1e-9):
                raise InputError(
                    f"shafts.{s.name}.axis ({list(s.axis)}) is not parallel to z; only parallel-axis "
                    "drivetrains are modelled"
                )
        if self.held is not None and self.held not in names:
            raise InputError(f"held ({self.held!r}) is not a shaft; shafts are {names}")
        mnames = [m.name for m in self.meshes]
        if len(set(mnames)) != len(mnames):
            raise InputError(f"meshes names ({mnames}) must be unique")
        for m in self.meshes:
            self._check_mesh(m)

    # -- lookups ------------------------------------------------------------------------------
    def body(self, name: str) -> DriveShaft:
        for s in self.shafts:
            if s.name == name:
                return s
        raise InputError(
            f"shaft ({name!r}) not in the drivetrain; shafts are {[s.name for s in self.shafts]}"
        )

    def bearing(self, name: str) -> DriveBearing:
        for b in self.bearings:
            if b.name == name:
                return b
        raise InputError(
            f"bearing ({name!r}) not in the drivetrain; bearings are {[b.name for b in self.bearings]}"
        )

    def gear_of(self, ref: tuple) -> tuple[DriveGear, tuple, float]:
        """(gear, centre (x, y), gearbox z of the gear) of a (body, gear name) reference."""
        body, name = ref
        if body == HOUSING:
            for g, centre, z in self.housing_gears:
                if g.name == name:
                    return g, centre, z
            raise InputError(f"gear ({name!r}) is not a housing gear")
        s = self.body(body)
        g = s.gear(name)
        return g, s.centre, s.axial_offset + g.position

    @property
    def char_length(self) -> float:
        """L [m]: the largest bearing pitch radius, else the largest shaft radius (rotation scale)."""
        radii = [b.seat.law.char_length for b in self.bearings]
        shafts = [max(sec.outer_diameter for sec in s.shaft.sections) / 2 for s in self.shafts]
        return max([*radii, *shafts])

    def _check_mesh(self, m: Mesh) -> None:
        ga, ca, za = self.gear_of(m.a)
        gb, cb, zb = self.gear_of(m.b)
        for ref in (m.a, m.b):
            if ref[0] != HOUSING:
                ax = np.asarray(self.body(ref[0]).axis, dtype=float)
                if not np.allclose(np.abs(ax / np.linalg.norm(ax)), [0.0, 0.0, 1.0], atol=1e-9):
                    raise InputError(
                        f"meshes.{m.name}: gear {ref[1]!r} is on shaft {ref[0]!r} whose axis is not parallel "
                        "to the other gear's; only parallel-axis (cylindrical) gear meshes are modelled"
                    )
        distance = float(np.hypot(cb[0] - ca[0], cb[1] - ca[1]))
        expected = m.pair.centre_distance
        if abs(distance - expected) > CENTRE_DISTANCE_RTOL * expected:
            raise InputError(
                f"meshes.{m.name}: the shafts' axes are {distance * 1e3:.6g} mm apart but gears "
                f"{m.a[1]!r} and "
                f"{m.b[1]!r} ({ga.geometry.teeth} and {gb.geometry.teeth} teeth, m_n "
                f"{ga.geometry.normal_module * 1e3:.6g} mm) mesh at a_w = {expected * 1e3:.6g} mm; check the "
                "tooth counts, module, profile shifts or shaft centres"
            )
        overlap = 0.5 * (ga.geometry.face_width + gb.geometry.face_width) - abs(za - zb)
        if overlap <= POSITION_TOL:
            raise InputError(
                f"meshes.{m.name}: gears {m.a[1]!r} (z = {za * 1e3:.6g} mm) and {m.b[1]!r} "
                f"(z = {zb * 1e3:.6g} mm) "
                "do not overlap axially; check the gear positions and the shafts' axial_offset"
            )

    def mesh_geometry(self, m: Mesh) -> dict:
        """Pitch point arms p_a, p_b (3,) from each gear's node, e (3,) from a's axis to the pitch point."""
        _, ca, _ = self.gear_of(m.a)
        _, cb, _ = self.gear_of(m.b)
        d = np.array([cb[0] - ca[0], cb[1] - ca[1], 0.0])
        d /= np.linalg.norm(d)
        ra = 0.5 * m.pair.working_diameter("a")
        rb = 0.5 * m.pair.working_diameter("b")
        if m.pair.b.internal:
            e = -d  # the pitch point lies on the far side of the pinion from the ring's centre
            p_b = rb * e
        else:
            e = d
            p_b = -rb * e
        return {"e": e, "p_a": ra * e, "p_b": p_b, "r_a": ra, "r_b": rb}
