"""Bearings on a shaft: the seat, the bearing's 5-DOF law, the housing and the axial location.

SI units (m, N, N·m, rad, N/m, N·m/rad). Frames (design.md §3): each bearing has its own frame with
its axis z'; its inner ring sits on the shaft node at the seat and its outer ring in the housing. The
bearing law gives the contact force f(q) on the inner ring for the inner ring's displacement q
relative to the outer ring, in the bearing frame, with its Jacobian and energy (the row kernels'
``response``, exactly what the single-bearing solver uses).

Orientation. ``"+z"``: the bearing frame is the shaft frame. ``"-z"``: the bearing is turned end for
end, a half turn about x: (x', y', z') = (x, −y, −z), so q' = T q and f = Tᵀ f' with
T = diag(1, −1, −1, 1, −1) (rotations are axial vectors: a half turn about x maps (θ_x, θ_y) to
(θ_x, −θ_y)). An angular contact bearing that carries +F_z' carries −F_z of the shaft when turned.

Relative displacement. q' = T (x_seat − x_outer): x_seat the shaft node's five DOFs, x_outer the
outer ring's. The outer ring is held by the housing DOF by DOF: rigidly at its prescribed position
(0, 0, ``axial_offset``, 0, 0), or by a spring of the given housing stiffness to that position; a
``"floating"`` bearing's outer ring slides axially (axial spring 0), so it carries no axial load.
``axial_offset`` moves the outer ring along the shaft's +z: the adjustment that preloads a pair of
single angular contact or tapered bearings set against each other.

Speed. The inner rings turn with the shaft at the load case's shaft speed Ω, the outer rings stand.
A bearing's rows then include their rolling elements' inertia exactly as a single-bearing solve at
speed (:func:`bearingkit.analysis.solver.speed.model_at_speed`: ball rows with centrifugal force and
gyroscopic moment, cylindrical and tapered rows with the rollers' centrifugal force), per load case.
About its own axis z' a bearing turned ``"-z"`` sees the inner ring turn at −Ω (only the sign of
friction torques depends on it; the inertia terms depend on Ω²). Element density and raceway control
come from the bearing file (its material, ``[operating] raceway_control``), else GCr15 and outer-raceway
control, as ``bearingkit analyze --speed`` takes them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit import checks
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.rows.base import N_DOF, RowResponse

#: Axial location of a bearing in its housing.
AXIAL_LOCATIONS = ("locating", "floating")
#: Frame transformation q' = T q of each orientation (module docstring).
ORIENTATIONS = {
    "+z": np.eye(N_DOF),
    "-z": np.diag([1.0, -1.0, -1.0, 1.0, -1.0]),
}
#: ``axial_direction`` of a linear bearing's stiffness → the sign of the only axial force it gives the shaft
#: (0: both ways).
AXIAL_DIRECTIONS = {"both": 0, "+z": 1, "-z": -1}
#: Deflection scale [m] of a linear bearing law: the Newton step cap is 2 % of the smallest scale of
#: the bearings, and a linear law needs none (one Newton step solves it).
LINEAR_DEFLECTION_SCALE = 1.0


@dataclass(frozen=True, eq=False)
class LinearBearing:
    """A bearing with a constant stiffness matrix: a hand model, or a stiffness taken from a table.

    Parameters
    ----------
    stiffness : array_like (5, 5) [N/m, N, N·m/rad …]
        K = −∂f/∂q in the bearing frame, symmetric positive semi-definite.
    name : str
    axial_direction : {0, 1, -1}
        0: the axial stiffness acts both ways. ±1: it acts one way only, as a shoulder on one side of the
        ring: the axial force on the inner ring, f_z = −K_zz q_z, is kept where its sign is this one and
        is zero otherwise (energy ½ K_zz q_z² there, 0 elsewhere: convex and continuously differentiable,
        so the Newton's active set settles in a few steps). Needs an axial row and column of K without
        coupling to the other DOFs (a REXS ``concept_bearing`` with ``axial_force_absorption``
        ``positive``/``negative``).
    """

    stiffness: np.ndarray
    name: str = "linear bearing"
    axial_direction: int = 0

    def __post_init__(self):
        k = np.asarray(self.stiffness, dtype=float)
        if k.shape != (N_DOF, N_DOF):
            raise InputError(f"stiffness (shape {k.shape}) must be 5×5 (u_x, u_y, u_z, θ_x, θ_y)")
        checks.finite("stiffness", k)
        if not np.allclose(k, k.T, rtol=1e-12, atol=1e-12 * np.abs(k).max()):
            raise InputError("stiffness must be symmetric (a conservative elastic support)")
        if np.linalg.eigvalsh(k).min() < -1e-12 * np.abs(k).max():
            raise InputError("stiffness must be positive semi-definite (a support that resists displacement)")
        if self.axial_direction not in (0, 1, -1):
            raise InputError(f"axial_direction ({self.axial_direction!r}) must be 0 (both ways), 1 or -1")
        if self.axial_direction and np.any(np.delete(k[2], 2) != 0.0):
            raise InputError(
                "a one-way axial stiffness (axial_direction) needs an axial row of the stiffness without "
                "coupling to the radial and tilt DOFs"
            )
        object.__setattr__(self, "stiffness", k)


class BearingLaw:
    """The 5-DOF law of one bearing for the system solver (sum of its rows' kernels).

    Attributes
    ----------
    deflection_scale : float [m]
        Smallest element diameter (sizes the Newton step cap and the divergence test).
    char_length : float [m]
        Largest pitch radius (scales rotations).
    start_terms : list of (ndarray (5, 5), float)
        (M, n) with the all-contacts-closed tangent stiffness n δ^(n−1) M (starting estimate).
    reach : ndarray (M, 5)
        Unloaded directions the contacts can push the inner ring along (support checks).
    """

    def __init__(self, bearing, kernels=None):
        self.bearing = bearing
        if isinstance(bearing, LinearBearing):
            self.kernels = ()
            self.linear = bearing.stiffness
            self.deflection_scale = LINEAR_DEFLECTION_SCALE
            self.char_length = 0.0
            self.start_terms = [(bearing.stiffness, 1.0)]
            self.one_way = bearing.axial_direction
            k = bearing.stiffness
            keep = np.arange(N_DOF) != 2 if self.one_way else np.ones(N_DOF, bool)
            lam, vec = np.linalg.eigh(k[np.ix_(keep, keep)])
            live = np.zeros((int((lam > 1e-12 * max(lam.max(), 1e-300)).sum()), N_DOF))
            live[:, keep] = vec[:, lam > 1e-12 * max(lam.max(), 1e-300)].T
            reach = [live, -live]
            if self.one_way and k[2, 2] > 0.0:  # K's axial row is uncoupled: it pushes along one sign only
                reach.append(self.one_way * np.eye(N_DOF)[2:3])
            self.reach = np.concatenate(reach)
            return
        if not isinstance(bearing, BearingModel):
            raise InputError(f"bearing ({bearing!r}) must be a BearingModel or a LinearBearing")
        self.linear = None
        self.one_way = 0
        self.kernels = tuple(kernels if kernels is not None else bearing.kernels)
        self.deflection_scale = min(k.deflection_scale for k in self.kernels)
        self.char_length = max(k.char_length for k in self.kernels)
        self.start_terms = [(k.start_matrix, k.start_exponent) for k in self.kernels]
        parts = []
        for k in self.kernels:
            reach = getattr(k, "reach", None)
            parts.append(reach if reach is not None else (k.G[0] if hasattr(k, "G") else k.directions[0]))
        self.reach = np.concatenate(parts, axis=0)

    def response(self, q: np.ndarray) -> RowResponse:
        """Contact force on the inner ring (C, 5), its Jacobian (C, 5, 5) and energy (C,) at q (C, 5)."""
        if self.linear is not None:
            force = -q @ self.linear
            jac = np.broadcast_to(-self.linear, (q.shape[0], N_DOF, N_DOF)).copy()
            if self.one_way:  # a shoulder on one side: no axial force the other way (LinearBearing)
                idle = self.one_way * force[:, 2] <= 0.0
                force[idle, 2] = 0.0
                jac[idle, 2, 2] = 0.0
            return RowResponse(force, jac, 0.5 * np.einsum("ci,ci->c", q, -force))
        force = np.zeros_like(q)
        jac = np.zeros((*q.shape, N_DOF))
        energy = np.zeros(q.shape[0])
        for k in self.kernels:
            r = k.response(q)
            force += r.force
            jac += r.jacobian
            energy += r.energy
        return RowResponse(force, jac, energy)

    def take(self, cases: np.ndarray) -> BearingLaw:
        """The law restricted to some cases of the batch (per-case kernel arrays sliced)."""
        if self.linear is not None:
            return self
        return BearingLaw(self.bearing, [k.take(cases) for k in self.kernels])


@dataclass(frozen=True, eq=False)
class BearingSeat:
    """One bearing on the shaft.

    Parameters
    ----------
    name : str
        Unique in the system; used in results and messages.
    bearing : BearingModel or LinearBearing
        The bearing (e.g. ``load_file("dgbb_6209.toml").model``).
    position : float [m]
        Axial position on the shaft of the bearing frame's origin (the builders put it mid-width).
    orientation : {"+z", "-z"}
        Bearing axis along the shaft's +z or turned end for end (module docstring).
    axial : {"locating", "floating"}
        Whether the outer ring is held axially in the housing (locating) or slides (floating).
    axial_offset : float [m]
        Outer ring's prescribed axial position along the shaft's +z (preload adjustment).
    housing_stiffness : array_like (5,) or None [N/m, N/m, N/m, N·m/rad, N·m/rad]
        Stiffness of the housing per outer-ring DOF in the shaft frame (inf: that DOF held rigidly);
        None = rigid housing.
    source : object
        The loaded input file (:class:`bearingkit.io.loader.BearingInput`) when the bearing came
        from one: its lubricant and name are used for ratings and friction.
    """

    name: str
    bearing: object
    position: float
    orientation: str = "+z"
    axial: str = "locating"
    axial_offset: float = 0.0
    housing_stiffness: np.ndarray | None = None
    source: object = None

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name:
            raise InputError(f"name ({self.name!r}) must be a non-empty string")
        checks.finite(f"{self.name}.position", self.position, "m")
        checks.one_of(f"{self.name}.orientation", self.orientation, ORIENTATIONS)
        checks.one_of(f"{self.name}.axial", self.axial, AXIAL_LOCATIONS)
        checks.finite(f"{self.name}.axial_offset", self.axial_offset, "m")
        if self.housing_stiffness is not None:
            k = np.asarray(self.housing_stiffness, dtype=float)
            if k.shape != (N_DOF,):
                raise InputError(
                    f"{self.name}.housing_stiffness (shape {k.shape}) must have 5 values (radial x, "
                    "radial y, axial, tilt x, tilt y)"
                )
            if np.any(np.isnan(k)) or np.any(k < 0):
                raise InputError(
                    f"{self.name}.housing_stiffness ({k.tolist()}) must be non-negative (inf: held rigidly)"
                )
            object.__setattr__(self, "housing_stiffness", k)
        object.__setattr__(self, "law", BearingLaw(self.bearing))

    @property
    def transform(self) -> np.ndarray:
        """T (5, 5) with q' = T q (orthogonal and symmetric, so also f = T f')."""
        return ORIENTATIONS[self.orientation]

    @property
    def outer_position(self) -> np.ndarray:
        """Prescribed outer-ring position (5,) in the shaft frame [m, m, m, rad, rad]."""
        return np.array([0.0, 0.0, self.axial_offset, 0.0, 0.0])

    @property
    def global_reach(self) -> np.ndarray:
        """Contact directions (M, 5) in the shaft frame, without the DOFs a free outer ring cannot pass on."""
        reach = self.law.reach @ self.transform  # rows d' → d = T d' (T symmetric)
        return np.where(self.outer_springs() == 0.0, 0.0, reach)

    def seat_speed(self, shaft_speed) -> np.ndarray:
        """Inner-ring speed about the bearing's own axis (C,) [rad/s] for the shaft speed Ω (C,)."""
        return self.transform[2, 2] * np.asarray(shaft_speed, dtype=float)

    def speed_of(self, shaft_speed):
        """The :class:`~bearingkit.analysis.solver.speed.OperatingSpeed` of this bearing at shaft speed Ω
        (C,).

        Inner ring at :meth:`seat_speed`, outer ring at rest; element density from the bearing file's
        material (else :data:`~bearingkit.analysis.solver.speed.DEFAULT_ELEMENT_DENSITY`) and the file's
        ``[operating] raceway_control`` (else "outer"), as a single-bearing analysis at speed.
        """
        from bearingkit.analysis.solver.speed import DEFAULT_ELEMENT_DENSITY, OperatingSpeed

        src = self.source
        density = getattr(getattr(src, "material", None), "density", None) or DEFAULT_ELEMENT_DENSITY
        sections = getattr(src, "sections", None)
        operating = getattr(sections, "operating", None)
        control = getattr(operating, "raceway_control", None) or "outer"
        return OperatingSpeed(self.seat_speed(shaft_speed), 0.0, float(density), control)

    def law_at(self, shaft_speed) -> BearingLaw:
        """The bearing's law with its rows at shaft speed Ω (C,) [rad/s]; :attr:`law` itself when no
        case turns (the zero-speed law, unchanged) or for a linear bearing.

        Each case's rows run at that case's speed (a load spectrum at several speeds is one solve).
        Raises InputError naming the bearing when its rows cannot take these speeds.
        """
        if shaft_speed is None or not isinstance(self.bearing, BearingModel):
            return self.law
        from bearingkit.analysis.solver.speed import model_at_speed

        speed = self.speed_of(shaft_speed)
        if not speed.moving:
            return self.law
        model = model_at_speed(self.bearing, speed)
        try:
            return BearingLaw(model)
        except InputError as exc:
            raise InputError(f"bearings.{self.name}: {exc}") from None

    def outer_springs(self) -> np.ndarray:
        """Housing stiffness per outer-ring DOF (5,): inf = held rigidly, 0 = free (floating axially)."""
        k = np.full(N_DOF, np.inf) if self.housing_stiffness is None else self.housing_stiffness.copy()
        if self.axial == "floating":
            k[2] = 0.0
        # A DOF the bearing cannot act on at all needs no outer-ring unknown: hold it.
        acts = np.abs(self.law.reach @ self.transform).max(axis=0, initial=0.0) > 0.0
        return np.where(acts, k, np.inf)
