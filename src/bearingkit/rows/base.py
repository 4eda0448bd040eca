"""What every row shares: element placement, the rigid-ring kinematics, and the row response.

SI units. Frame (design.md §3): bearing axis z, x and y radial. The inner ring is a rigid body
displaced by q = (u_x, u_y, u_z, θ_x, θ_y) relative to the fixed outer ring. A point of the inner
ring at azimuth ψ, radius r and axial position z moves (small rotations) by

    radial  u_r = (u_x + θ_y z) cos ψ + (u_y − θ_x z) sin ψ
    axial   u_a = u_z + r (θ_x sin ψ − θ_y cos ψ)

and the raceway tilts in the element's radial–axial plane by θ_t = θ_x sin ψ − θ_y cos ψ. These
are rows of a matrix B(ψ, r, z) with u = B q, so a contact law written in the element's local
(radial, axial) frame maps to the ring by virtual work: f = Bᵀ f_local, ∂f/∂q = Bᵀ (∂f_local/∂u) B.
"""

from __future__ import annotations

import copy
import threading
from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks

#: Names of the five rigid-body degrees of freedom of the inner ring, in order.
DOF_NAMES = ("u_x", "u_y", "u_z", "theta_x", "theta_y")
#: Names of the matching generalised loads.
LOAD_NAMES = ("F_x", "F_y", "F_z", "M_x", "M_y")
N_DOF = 5


def azimuths(n_elements: int, azimuth_phase=0.0) -> np.ndarray:
    """Element azimuths ψ_j = phase + 2πj/Z [rad], shape (C|1, Z) for a phase of shape (C,) or scalar."""
    j = np.arange(n_elements)
    return np.asarray(azimuth_phase, dtype=float).reshape(-1, 1) + 2.0 * np.pi * j / n_elements


def radial_row(psi, z):
    """Row of B giving the radial displacement at azimuth ψ and axial position z; shape (..., 5)."""
    c, s = np.cos(psi), np.sin(psi)
    zeros = np.zeros(np.broadcast(psi, z).shape)
    z = np.broadcast_to(z, zeros.shape)
    return np.stack([c + zeros, s + zeros, zeros, -z * s, z * c], axis=-1)


def axial_row(psi, r):
    """Row of B giving the axial displacement at azimuth ψ and radius r; shape (..., 5)."""
    c, s = np.cos(psi), np.sin(psi)
    zeros = np.zeros(np.broadcast(psi, r).shape)
    r = np.broadcast_to(r, zeros.shape)
    return np.stack([zeros, zeros, 1.0 + zeros, r * s, -r * c], axis=-1)


def tilt_row(psi):
    """Row of B giving the raceway tilt θ_t in the element's radial–axial plane; shape (..., 5)."""
    c, s = np.cos(psi), np.sin(psi)
    zeros = np.zeros(np.shape(psi))
    return np.stack([zeros, zeros, zeros, s, -c], axis=-1)


def case_column(value) -> np.ndarray:
    """A row field that may vary per case, as (C|1, 1) floats; a field equal in every case is (1, 1).

    Studies pass geometry factors as per-case arrays even when a factor is held constant; keeping
    one copy then saves the per-case copies of constant geometry (memory O(C·elements) and the
    slower per-case products) without changing any value.
    """
    a = np.asarray(value, dtype=float).reshape(-1, 1)
    if a.shape[0] > 1 and np.all(a == a[0]):
        return a[:1]
    return a


@dataclass(frozen=True)
class RacewayOffset:
    r"""Deflection of a row's outer raceway relative to its inner one, imposed on the contact geometry.

    What flexible rings and structures impose (:mod:`bearingkit.analysis.flexible`,
    :mod:`bearingkit.analysis.structure`). The per-element fields are the motion of the OUTER raceway
    relative to the INNER raceway at the element's reference point, the element centre (pitch
    radius r_e, the row's axial position z_e): a flexible inner ring enters with the opposite sign.

    Attributes
    ----------
    shift : ndarray (C, 5) or None [m, m, m, rad, rad]
        Rigid-body displacement of the outer raceway at this row (e.g. the outer ring's beam
        deflection and end rotation between housing supports); the contacts see q − shift.
    radial : ndarray (C, Z) or None [m]
        Outward radial deflection of the outer raceway at each element (thin-ring bending); it
        opens the radial gap, reducing the element's approach by its radial component.
    axial : ndarray (C, Z) or None [m]
        Axial (+z) displacement of the outer raceway at each element's reference point.
    tilt : ndarray (C, Z) or None [rad]
        Rotation of the outer raceway's section in the element's radial–axial plane, in the sense of
        the ring tilt θ_t = θ_x sin ψ − θ_y cos ψ: a raceway point at (r, z) moves by
        tilt·(−(z − z_e), r − r_e) on top of (radial, axial). The contacts see θ_t − tilt.

    Notes
    -----
    An outer raceway point at (r, z) of element j moves by

    .. math:: d_r = \text{radial}_j - (z - z_e)\,\text{tilt}_j, \qquad
              d_z = \text{axial}_j + (r - r_e)\,\text{tilt}_j

    (small rotations), and every contact of that element loses the approach n·d, n its outward
    normal on the outer raceway. Offsets equal to a rigid shift s at every element
    (radial = B_r(z_e) s, axial = B_a(r_e) s, tilt = B_θ s) give the contacts the shift does
    (tested per row kind). Every row kind's kernel accepts these fields and reports, with
    ``raceway_loads(q, offset)`` (C, Z, 3), the generalised loads (F_r, F_z, M_t) the elements put on
    the outer raceway, conjugate to (radial, axial, tilt): −∂U/∂offset.
    """

    shift: np.ndarray | None = None
    radial: np.ndarray | None = None
    axial: np.ndarray | None = None
    tilt: np.ndarray | None = None

    def take(self, cases: np.ndarray) -> RacewayOffset:
        """The offsets of some cases only (arrays with a leading case axis of 1 are shared)."""
        pick = lambda a: a if a is None or np.shape(a)[0] == 1 else np.asarray(a)[cases]  # noqa: E731
        return RacewayOffset(pick(self.shift), pick(self.radial), pick(self.axial), pick(self.tilt))

    @property
    def local(self) -> bool:
        """Whether any per-element field (radial, axial, tilt) is set."""
        return self.radial is not None or self.axial is not None or self.tilt is not None


def element_offsets(offset: RacewayOffset | None, shape) -> tuple | None:
    """(radial, axial, tilt) of ``offset`` as arrays of ``shape`` (C, Z) (zeros where None); None when
    the offset has no per-element field."""
    if offset is None or not offset.local:
        return None
    fill = lambda a: np.zeros(shape) if a is None else np.broadcast_to(np.asarray(a, float), shape)  # noqa: E731
    return fill(offset.radial), fill(offset.axial), fill(offset.tilt)


def point_offset(offset: RacewayOffset | None, shape, arm_r, arm_z) -> np.ndarray | None:
    """Displacement (C, Z, 2) [m] of an outer-raceway point at (r_e + arm_r, z_e + arm_z) of each element.

    ``arm_r``, ``arm_z`` broadcast against (C, Z). None when ``offset`` has no per-element field.
    """
    parts = element_offsets(offset, shape)
    if parts is None:
        return None
    radial, axial, tilt = parts
    return np.stack([radial - arm_z * tilt, axial + arm_r * tilt], axis=-1)


def relative_displacement(q: np.ndarray, offset: RacewayOffset | None) -> np.ndarray:
    """q − shift: the inner ring's displacement relative to the (moved) outer raceway of a row."""
    if offset is None or offset.shift is None:
        return q
    return q - offset.shift


class KernelBase:
    """Shared behaviour of row kernels: restriction to a subset of the batch's cases.

    ``_case_arrays`` names the attributes used by ``response`` whose leading axis is the case axis
    (length C, or 1 when the geometry is shared by every case).
    """

    _case_arrays: tuple[str, ...] = ()

    def take(self, cases: np.ndarray):
        """A shallow copy whose per-case arrays hold only ``cases``."""
        out = copy.copy(self)
        for name in self._case_arrays:
            a = getattr(self, name)
            if np.shape(a)[0] != 1:
                setattr(out, name, a[cases])
        return out


@dataclass
class RowResponse:
    """The response of one row to a batch of inner-ring displacements (internal, per iteration).

    Attributes
    ----------
    force : ndarray (C, 5)
        Generalised force of the contacts on the inner ring [N, N, N, N·m, N·m].
    jacobian : ndarray (C, 5, 5)
        ∂force/∂q (negative semi-definite: the contacts resist displacement).
    energy : ndarray (C,)
        Elastic energy stored in the row's contacts [J]; force = −∂energy/∂q.
    """

    force: np.ndarray
    jacobian: np.ndarray
    energy: np.ndarray


@dataclass
class RowState:
    """Per-element results of a row at the solution (all arrays carry the leading case axis C).

    Attributes
    ----------
    kind, name : str
        Row kind (``"ball"``, ``"cylindrical"`` …) and the row's name in its bearing.
    azimuth : ndarray (C|1, Z) [rad]
    load : ndarray (C, Z) [N]
        Element contact load (normal load for balls, sum of slice loads for rollers).
    deflection : ndarray (C, Z) [m]
        Total elastic approach of the element (for rollers: at the most compressed slice).
    contact_angle : ndarray (C, Z) [rad]
        Operating contact angle (constant for roller rows).
    max_pressure : ndarray (C, Z) [Pa]
        Largest Hertz pressure over the element's contacts (inner and outer; all slices).
    slice_load : ndarray (C, Z, n_s) [N] or None
    extras : dict
        Row-kind specific arrays (contact ellipse semi-axes, slice pressures, …).
    """

    kind: str
    name: str
    azimuth: np.ndarray
    load: np.ndarray
    deflection: np.ndarray
    contact_angle: np.ndarray
    max_pressure: np.ndarray
    slice_load: np.ndarray | None = None
    extras: dict = field(default_factory=dict)

    @property
    def loaded_count(self) -> np.ndarray:
        """Number of elements carrying load (C,)."""
        return np.count_nonzero(self.load > 0.0, axis=-1)

    @property
    def max_load(self) -> np.ndarray:
        """Largest element load (C,) [N]."""
        return self.load.max(axis=-1)


def validate_common(row) -> None:
    """Checks shared by every row kind (field names as in docs/nomenclature.md)."""
    checks.integer("n_elements", row.n_elements, low=1)
    checks.positive("element_diameter", row.element_diameter, "m")
    checks.positive("pitch_diameter", row.pitch_diameter, "m")
    checks.greater("pitch_diameter", row.pitch_diameter, "element_diameter", row.element_diameter, "m")
    checks.finite("axial_position", row.axial_position, "m")
    checks.finite("azimuth_phase", row.azimuth_phase, "rad")
    checks.finite("clearance", row.clearance, "m")
    # Elements must fit on the pitch circle without overlapping (ball/roller circumferential width).
    gap = np.pi * np.asarray(row.pitch_diameter) / row.n_elements - np.asarray(row.element_diameter)
    if np.any(gap < -1e-12):
        raise checks.InputError(
            f"n_elements ({row.n_elements}) do not fit on the pitch circle: π·pitch_diameter/Z "
            f"({np.min(np.pi * np.asarray(row.pitch_diameter) / row.n_elements):.6g} m) must be at least "
            f"element_diameter ({np.max(row.element_diameter):.6g} m)"
        )


def concat_cases(arrays):
    """Concatenate per-row arrays along the element axis after broadcasting their case axes (1 or C).

    What the compiled kernels' packers (``rows/*/compiled.py``) use to flatten every row of a kind.
    """
    lead = max(a.shape[0] for a in arrays)
    arrays = [np.broadcast_to(a, (lead, *a.shape[1:])) for a in arrays]
    return np.ascontiguousarray(np.concatenate(arrays, axis=1), dtype=np.float64)


def steel_e_reduced() -> float:
    """Reduced modulus E' [Pa] of two bearing-steel bodies (GCr15), every row kind's default."""
    from bearingkit.materials import e_reduced, get_material

    steel = get_material("GCr15")
    return float(e_reduced(steel, steel))


class InnerStats:
    """Effort of a kernel's roller sub-problems, shared by the kernel and its per-case copies.

    Attributes
    ----------
    calls : int
        Roller solves so far.
    iterations_max : int
        Most Newton steps one solve took.
    unconverged : int
        Rollers, summed over solves, that reached the iteration cap without meeting the tolerance.
    """

    def __init__(self):
        self.calls = 0
        self.iterations_max = 0
        self.unconverged = 0
        self._lock = threading.Lock()  # copies of one kernel run on the solver's thread pool

    def record(self, iterations: int, unconverged: int) -> None:
        """Add one solve."""
        with self._lock:
            self.calls += 1
            self.iterations_max = max(self.iterations_max, iterations)
            self.unconverged += unconverged
