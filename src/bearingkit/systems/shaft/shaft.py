"""A stepped shaft: sections, material, the finite-element mesh and its linear stiffness and loads.

SI units (m, N, Pa, kg). The shaft runs along z from its first section's ``start`` to its last
section's ``end``; sections are contiguous (no gap, no overlap). :meth:`Shaft.mesh` places a node at
every section step, bearing seat and load position and subdivides the spans to a largest element
length; the elements are the Timoshenko elements of :mod:`bearingkit.systems.shaft.beam`. Nodal loads
(point loads, gear meshes, line loads by their consistent nodal values, weight) are assembled by
:func:`nodal_loads` over the batch of load cases.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.lazy import cached_property
from bearingkit.materials import Material
from bearingkit.systems.shaft import beam
from bearingkit.systems.shaft.beam import NODE_DOF
from bearingkit.systems.shaft.loads import ShaftLoads

#: Default shaft material: structural / heat-treatable steel, E = 210 000 N/mm² and ν = 0.3
#: (EN 1993-1-1:2005 §3.2.6 design values for steel), ρ = 7850 kg/m³ (EN 1991-1-1:2002 Table A.4,
#: steel 77.0–78.5 kN/m³) [from memory: the clause numbers could not be confirmed with the search tool].
SHAFT_STEEL = Material(
    name="shaft_steel",
    youngs_modulus=210e9,
    poisson_ratio=0.3,
    density=7850.0,
    source="EN 1993-1-1 §3.2.6 (E, nu); EN 1991-1-1 Table A.4 (density)",
)
#: Positions closer than this are one node [m] (0.1 µm: far below any drawing tolerance).
POSITION_TOL = 1e-7
#: Default number of elements a shaft's length is divided into at least (nodal values are exact; the
#: subdivision only draws the deflection and moment lines).
DEFAULT_DIVISIONS = 60
#: Most beam elements a shaft may be divided into: nodal values are exact already with a few per span,
#: and a tiny max_element_length must not allocate the machine away (the fuzz gave 1.25e12 elements).
MAX_ELEMENTS = 5000


@dataclass(frozen=True)
class Section:
    """A cylindrical (or tubular) step of the shaft.

    Parameters
    ----------
    start, end : float [m]
        Axial extent.
    outer_diameter : float [m]
    inner_diameter : float [m]
        Bore of a hollow shaft (0: solid).
    """

    start: float
    end: float
    outer_diameter: float
    inner_diameter: float = 0.0

    def __post_init__(self):
        checks.finite("start", self.start, "m")
        checks.greater("end", self.end, "start", self.start, "m")
        checks.positive("outer_diameter", self.outer_diameter, "m")
        checks.non_negative("inner_diameter", self.inner_diameter, "m")
        if not self.inner_diameter < self.outer_diameter:
            raise InputError(
                f"inner_diameter ({self.inner_diameter:.6g} m) must be smaller than outer_diameter "
                f"({self.outer_diameter:.6g} m)"
            )

    @property
    def length(self) -> float:
        return self.end - self.start


@dataclass(frozen=True)
class Shaft:
    """A stepped shaft of one material.

    Parameters
    ----------
    sections : tuple of Section
        In axial order, each starting where the previous one ends.
    material : Material
        Young's modulus, Poisson's ratio (shear modulus G = E / 2(1 + ν)) and density (weight).
    shear_deformation : bool
        Timoshenko elements (True) or Euler–Bernoulli (False).
    name : str
    """

    sections: tuple
    material: Material = SHAFT_STEEL
    shear_deformation: bool = True
    name: str = "shaft"

    def __post_init__(self):
        object.__setattr__(self, "sections", tuple(self.sections))
        if not self.sections:
            raise InputError("shaft.sections (none): give at least one section")
        for i, s in enumerate(self.sections):
            if not isinstance(s, Section):
                raise InputError(f"shaft.sections[{i}] ({s!r}) is not a Section")
        for i in range(1, len(self.sections)):
            prev, cur = self.sections[i - 1], self.sections[i]
            if cur.start < prev.end - POSITION_TOL:
                raise InputError(
                    f"shaft.sections[{i}].start ({cur.start * 1e3:.6g} mm) overlaps sections[{i - 1}], which "
                    f"ends at {prev.end * 1e3:.6g} mm; expected sections in axial order, each starting where "
                    "the previous one ends"
                )
            if cur.start > prev.end + POSITION_TOL:
                raise InputError(
                    f"shaft.sections[{i}].start ({cur.start * 1e3:.6g} mm) leaves a gap after "
                    f"sections[{i - 1}], which ends at {prev.end * 1e3:.6g} mm; expected contiguous sections"
                )

    @property
    def start(self) -> float:
        return self.sections[0].start

    @property
    def end(self) -> float:
        return self.sections[-1].end

    @property
    def length(self) -> float:
        return self.end - self.start

    @property
    def shear_modulus(self) -> float:
        """G = E / (2 (1 + ν)) [Pa] (isotropic)."""
        return self.material.youngs_modulus / (2.0 * (1.0 + self.material.poisson_ratio))

    def check_position(self, field: str, z: float, what: str = "") -> None:
        """InputError naming ``field`` (and ``what`` it places) when ``z`` [m] is not on the shaft."""
        if not (self.start - POSITION_TOL <= z <= self.end + POSITION_TOL):
            raise InputError(
                f"{field} ({z * 1e3:.6g} mm) is outside the shaft, which spans {self.start * 1e3:.6g}–"
                f"{self.end * 1e3:.6g} mm{'; ' + what if what else ''}"
            )

    def section_at(self, z) -> np.ndarray:
        """Index of the section holding each position z [m] (the later one at a step)."""
        starts = np.array([s.start for s in self.sections])
        return np.clip(np.searchsorted(starts, np.asarray(z, dtype=float), side="right") - 1, 0, None)

    def check_element_length(self, h: float) -> None:
        """Refuse an element length that is not positive or would need over :data:`MAX_ELEMENTS` [m]."""
        checks.positive("max_element_length", h, "m")
        if self.length / h > MAX_ELEMENTS:
            raise InputError(
                f"shaft.max_element_length ({h * 1e3:.6g} mm) would divide the "
                f"{self.length * 1e3:.6g} mm shaft into more than {MAX_ELEMENTS} elements; give at least "
                f"{self.length / MAX_ELEMENTS * 1e3:.3g} mm"
            )

    def mesh(self, points=(), max_element_length: float | None = None) -> Mesh:
        """The finite-element mesh with a node at every section step and at ``points`` [m].

        Parameters
        ----------
        points : iterable of float [m]
            Positions that must be nodes (bearing seats, loads, line-load ends).
        max_element_length : float or None [m]
            Largest element; default the length / :data:`DEFAULT_DIVISIONS`.
        """
        h = max_element_length if max_element_length is not None else self.length / DEFAULT_DIVISIONS
        self.check_element_length(h)
        fixed = np.array(
            [self.start, self.end, *(s.end for s in self.sections), *np.asarray(list(points), dtype=float)]
        )
        fixed = np.clip(fixed, self.start, self.end)
        fixed = np.sort(fixed)
        keep = np.concatenate([[True], np.diff(fixed) > POSITION_TOL])
        fixed = fixed[keep]
        z = [fixed[:1]]
        for a, b in itertools.pairwise(fixed):
            n = max(1, int(np.ceil((b - a) / h - 1e-9)))
            z.append(np.linspace(a, b, n + 1)[1:])
        return Mesh(self, np.concatenate(z))


@dataclass(frozen=True, eq=False)
class Mesh:
    """Nodes z (N,) [m] of a shaft and its N−1 elements between consecutive nodes."""

    shaft: Shaft
    z: np.ndarray

    @property
    def n_nodes(self) -> int:
        return len(self.z)

    @property
    def n_dof(self) -> int:
        return NODE_DOF * self.n_nodes

    @cached_property
    def length(self) -> np.ndarray:
        """Element lengths (E,) [m]."""
        return np.diff(self.z)

    @cached_property
    def section(self) -> np.ndarray:
        """Section index of each element (E,) (from its mid-point)."""
        return self.shaft.section_at(0.5 * (self.z[:-1] + self.z[1:]))

    def _per_element(self, attr: str) -> np.ndarray:
        return np.array([getattr(self.shaft.sections[i], attr) for i in self.section])

    @cached_property
    def outer_diameter(self) -> np.ndarray:
        return self._per_element("outer_diameter")

    @cached_property
    def inner_diameter(self) -> np.ndarray:
        return self._per_element("inner_diameter")

    @cached_property
    def properties(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Area A (E,) [m²], second moment I (E,) [m⁴], shear coefficient κ (E,) [-]."""
        area, inertia = beam.section_properties(self.outer_diameter, self.inner_diameter)
        kappa = beam.shear_coefficient(
            self.shaft.material.poisson_ratio, self.inner_diameter / self.outer_diameter
        )
        return area, inertia, kappa

    @cached_property
    def element_stiffness(self) -> np.ndarray:
        """Element stiffness matrices (E, 10, 10) [N/m, N, N·m]."""
        area, inertia, kappa = self.properties
        m = self.shaft.material
        return beam.element_stiffness(
            m.youngs_modulus,
            self.shaft.shear_modulus,
            area,
            inertia,
            kappa,
            self.length,
            shear=self.shaft.shear_deformation,
        )

    @cached_property
    def stiffness(self) -> np.ndarray:
        """Assembled global stiffness (5N, 5N) of the free shaft (singular: 5 rigid-body modes)."""
        k = np.zeros((self.n_dof, self.n_dof))
        for e, ke in enumerate(self.element_stiffness):  # E small matrices, assembled once
            sl = slice(NODE_DOF * e, NODE_DOF * (e + 2))
            k[sl, sl] += ke
        return k

    def element_dofs(self) -> np.ndarray:
        """Global DOF indices (E, 10) of each element."""
        e = np.arange(len(self.length))[:, None]
        return NODE_DOF * e + np.arange(2 * NODE_DOF)[None, :]

    def node(self, z: float) -> int:
        """Index of the node at position z [m] (it must have been requested when meshing)."""
        i = int(np.argmin(np.abs(self.z - z)))
        if abs(self.z[i] - z) > POSITION_TOL:
            raise InputError(f"position ({z * 1e3:.6g} mm) is not a node of the mesh")
        return i

    @cached_property
    def mass(self) -> float:
        """Mass of the shaft [kg]."""
        area, _, _ = self.properties
        return float(self.shaft.material.density * np.sum(area * self.length))


def element_line_loads(mesh: Mesh, loads: ShaftLoads) -> np.ndarray:
    """Line load on every element (C, E, 3) [N/m]: the shaft's weight and the loads' line loads."""
    n_el = len(mesh.length)
    q = np.zeros((loads.n_cases, n_el, 3))
    mid = 0.5 * (mesh.z[:-1] + mesh.z[1:])
    for item in loads.line_loads:
        inside = (mid > item.start) & (mid < item.end)
        q[:, inside, :] += item.load[:, None, :]
    if loads.gravity is not None:
        area, _, _ = mesh.properties
        q += (mesh.shaft.material.density * area)[None, :, None] * np.asarray(loads.gravity)[None, None, :]
    return q


def nodal_loads(mesh: Mesh, loads: ShaftLoads, gears=(), masses=()) -> np.ndarray:
    """Nodal load vector (C, 5N) [N, N·m] of every load case.

    Point loads and gear meshes at their nodes, line loads (and the shaft's weight) by their
    consistent nodal loads (:func:`bearingkit.systems.shaft.beam.uniform_load_vector`), the weight of the
    gears and point masses at their nodes.
    """
    n_cases = loads.n_cases
    f = np.zeros((n_cases, mesh.n_nodes, NODE_DOF))
    for p in loads.forces:
        f[:, mesh.node(p.position)] += p.load
    by_name = {g.name: g for g in gears}
    for name, torque in loads.gear_torques.items():
        g = by_name[name]
        f[:, mesh.node(g.position)] += np.broadcast_to(g.load(torque), (n_cases, NODE_DOF))
    if loads.gravity is not None:
        g_vec = np.asarray(loads.gravity)
        for item in (*gears, *masses):
            if item.mass > 0:
                f[:, mesh.node(item.position), :3] += item.mass * g_vec
    flat = f.reshape(n_cases, -1)
    q = element_line_loads(mesh, loads)
    if np.any(q):
        fe = beam.uniform_load_vector(q, mesh.length)  # (C, E, 10)
        np.add.at(flat, (slice(None), mesh.element_dofs()), fe)
    return flat
