"""Threaded rows: the planetary thread roller bearing (PTRB) as equivalent-ball contact pairs.

SI units (m, N, Pa, rad). Geometry after Zheng et al. (2022), Table 1 and §2: Z threaded rollers on
the pitch diameter D_pw, each with n annular (zero-lead) teeth of pitch P. Every tooth touches the
inner ring (ITP) and the outer ring (OTP); with its contact normals through the roller axis a tooth
flank pair acts as an *equivalent ball* of diameter D_w = d_R / cos α (Zheng et al. 2021). A tooth
has two such balls, one per flank direction (contact angles +α and −α): an axial load loads one of
them on every tooth (n balls per roller), a radial load both (2n balls per roller).

This module holds

* :class:`ThreadedRow` — a row kernel for :mod:`bearingkit.analysis.solver.quasistatic`: rigid rollers and
  rings, every equivalent ball a Hertz contact Q = K δ^1.5 along its fixed normal (affine approach
  δ = G q − c, like the cylindrical row); it gives the radial distribution over the rollers and the
  response to any combined load, with equal tooth shares (f_a,i = 1);

and re-exports, as the public home of the PTRB row's names, from
:mod:`bearingkit.rows.threaded.geometry`

* :class:`PTRBGeometry` — the Table 1 data, validated;
* :func:`contact_pairs` — ITP and OTP curvatures, Hertz ellipse, approach, pressure and stiffness;

and from :mod:`bearingkit.rows.threaded.distribution`

* :func:`axial_tooth_distribution` — the axial share of the teeth of one roller from Hertz contact,
  tooth bending/shear and axial compression of roller and rings (a thread-connection model in the
  spirit of Zheng et al. 2020 / Yamamoto), giving f_a,i and f_amax;
* :func:`radial_roller_distribution` — the closed form of the radial share for rigid rings without
  clearance (what the row kernel gives for a pure radial load), giving f_r,i and f_rmax.

References: ``zheng2022``, ``zheng2021``, ``zheng2020``, ``harris2007`` (ch. 6-7), ``stribeck1901``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics.contact import hertz
from bearingkit.rows.base import (
    KernelBase,
    RacewayOffset,
    RowResponse,
    RowState,
    axial_row,
    azimuths,
    element_offsets,
    radial_row,
    relative_displacement,
)
from bearingkit.rows.threaded.distribution import (
    RING_SUPPORTS,
    ToothDistribution,
    axial_tooth_distribution,
    radial_roller_distribution,
    tooth_compliance,
)
from bearingkit.rows.threaded.geometry import ContactPair, PTRBGeometry, contact_pairs

__all__ = [
    "RING_SUPPORTS",
    "ContactPair",
    "PTRBGeometry",
    "ThreadedRow",
    "ToothDistribution",
    "axial_tooth_distribution",
    "contact_pairs",
    "radial_roller_distribution",
    "tooth_compliance",
]

POINT_EXPONENT = 1.5


def _pair_stiffness(geometry: PTRBGeometry) -> float:
    """K of one equivalent ball: ITP and OTP in series [N/m^1.5]."""
    pairs = contact_pairs(geometry)
    return float(hertz.series_stiffness(pairs["inner"].stiffness_point, pairs["outer"].stiffness_point))


# ---------------------------------------------------------------------------------------------
# Row kernel for the quasi-static engine
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ThreadedRow:
    """A PTRB as one row of the engine: Z rollers × n teeth × 2 flanks of equivalent balls.

    Parameters
    ----------
    geometry : PTRBGeometry
    clearance : float [m]
        Play counted twice along each contact normal (each equivalent ball sees clearance/2);
        negative = preload.
    axial_position : float [m]
        Axial position of the middle of the rollers' teeth.
    azimuth_phase : float [rad]
        Azimuth of roller 0.
    name : str
    """

    kind: ClassVar[str] = "threaded"

    geometry: PTRBGeometry
    clearance: float = 0.0
    axial_position: float = 0.0
    azimuth_phase: float = 0.0
    name: str = "threaded"

    def __post_init__(self):
        if not isinstance(self.geometry, PTRBGeometry):
            raise InputError(f"geometry ({type(self.geometry).__name__}) must be a PTRBGeometry")
        checks.finite("clearance", self.clearance, "m")
        checks.finite("axial_position", self.axial_position, "m")
        checks.finite("azimuth_phase", self.azimuth_phase, "rad")

    @property
    def n_elements(self) -> int:
        return int(self.geometry.n_elements)

    def kernel(self) -> ThreadedKernel:
        """Precompute the arrays the solver needs."""
        return ThreadedKernel(self)


class ThreadedKernel(KernelBase):
    """δ_m = G_m·q − c for every equivalent ball m = (roller j, tooth i, flank σ = ±1).

    The normal of flank σ in the element's (radial, axial) frame is (cos α, σ sin α); it passes
    through the roller axis at (D_pw/2, z_i), z_i = z_0 + (i − (n−1)/2) P.
    """

    def __init__(self, row: ThreadedRow):
        g = row.geometry
        self.row = row
        z_el, n = g.n_elements, g.n_teeth
        self.shape = (z_el, n, 2)
        psi = azimuths(z_el, row.azimuth_phase)[0]  # (Z,)
        self.psi = psi
        z_t = row.axial_position + (np.arange(n) - (n - 1) / 2.0) * g.thread_pitch  # (n,)
        sigma = np.array([1.0, -1.0])
        ca, sa = np.cos(g.contact_angle), np.sin(g.contact_angle)
        pp, zz = np.meshgrid(psi, z_t, indexing="ij")  # (Z, n)
        b_r = radial_row(pp, zz)  # (Z, n, 5)
        b_a = axial_row(pp, np.full_like(pp, g.pitch_diameter / 2.0))
        gm = ca * b_r[:, :, None, :] + sa * sigma[None, None, :, None] * b_a[:, :, None, :]  # (Z, n, 2, 5)
        self.G = gm.reshape(1, -1, 5)
        self.GG = (self.G[..., :, None] * self.G[..., None, :]).reshape(1, -1, 25)
        self.delta0 = -row.clearance / 2.0
        # ∂(opening of each equivalent ball)/∂(radial, axial, tilt) of its roller's raceway offset
        # (RacewayOffset: the contact point sits on the roller axis at (D_pw/2, z_i), the element's
        # reference point at (D_pw/2, z_0); a tilt moves it radially by −(z_i − z_0)·tilt).
        arm = np.broadcast_to((z_t - row.axial_position)[:, None], (n, 2))
        self.opening = np.stack(
            [np.full((n, 2), ca), np.broadcast_to(sa * sigma, (n, 2)), -ca * arm]
        ).reshape(3, 2 * n)  # (3, n·2) in the order (tooth, flank) of one roller
        self.k = _pair_stiffness(g)
        self.start_matrix = self.k * np.einsum("mi,mj->ij", self.G[0], self.G[0])
        self.start_exponent = POINT_EXPONENT
        self.char_length = float(g.pitch_diameter / 2 + n * g.thread_pitch / 2)
        self.deflection_scale = float(g.element_diameter)

    def _delta(self, q, offset: RacewayOffset | None = None):
        q = relative_displacement(q, offset)
        delta = q @ self.G[0].T + self.delta0
        parts = element_offsets(offset, (q.shape[0], self.shape[0]))
        if parts is not None:  # the nut's raceway moved at each roller: every flank contact opens
            opening = np.einsum("acz,am->czm", np.stack(parts), self.opening)  # (C, Z, 2n)
            delta = delta - opening.reshape(delta.shape)
        return delta

    def raceway_loads(self, q: np.ndarray, offset: RacewayOffset | None = None) -> np.ndarray:
        """Loads (F_r, F_z, M_t) (C, Z, 3) each roller puts on the nut (outer raceway), −∂U/∂(radial, axial,
        tilt) = Σ over its teeth and flanks of Q ∂(opening)/∂(…)."""
        z_el, n, _ = self.shape
        delta = np.maximum(self._delta(q, offset), 0.0)
        load = (self.k * delta**POINT_EXPONENT).reshape(-1, z_el, 2 * n)
        return np.einsum("czm,am->cza", load, self.opening)

    def response(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowResponse:
        """Generalised force, Jacobian and energy for displacements q (C, 5)."""
        delta = np.maximum(self._delta(q, offset), 0.0)
        root = np.sqrt(delta)
        load = self.k * delta * root
        stiff = 1.5 * self.k * root
        force = -(load @ self.G[0])
        jac = -(stiff @ self.GG[0]).reshape(-1, 5, 5)
        energy = (load * delta).sum(axis=-1) / (1.0 + POINT_EXPONENT)
        return RowResponse(force, jac, energy)

    def state(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowState:
        """Per-roller results: ``load`` = Σ contact loads of a roller, ``slice_load`` (C, Z, 2n) per ball."""
        g = self.row.geometry
        z_el, n, _ = self.shape
        delta = np.maximum(self._delta(q, offset), 0.0)
        contact_load = self.k * delta**POINT_EXPONENT  # (C, M)
        pairs = contact_pairs(g, contact_load)
        extras = {}
        for side, pair in pairs.items():
            extras[f"semi_major_{side}"] = pair.semi_major.reshape(-1, z_el, n, 2)
            extras[f"semi_minor_{side}"] = pair.semi_minor.reshape(-1, z_el, n, 2)
            extras[f"max_pressure_{side}"] = pair.max_pressure.reshape(-1, z_el, n, 2)
        p_max = np.maximum(extras["max_pressure_inner"], extras["max_pressure_outer"]).max(axis=(-1, -2))
        loads = contact_load.reshape(-1, z_el, n, 2)
        extras["tooth_load"] = loads  # (C, Z, n, 2) flank σ = +1, −1
        psi = np.broadcast_to(self.psi, (loads.shape[0], z_el))
        alpha = np.full((loads.shape[0], z_el), g.contact_angle)
        return RowState(
            "threaded",
            self.row.name,
            psi,
            loads.sum(axis=(-1, -2)),
            delta.reshape(-1, z_el, 2 * n).max(axis=-1),
            alpha,
            p_max,
            loads.reshape(-1, z_el, 2 * n),
            extras,
        )
