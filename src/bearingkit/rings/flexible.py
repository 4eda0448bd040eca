"""A flexible outer ring shared by several rows: element loads → raceway offsets (seed 002 §2.3).

SI units (m, N, Pa, rad). Two compliances, superposed (Li et al. 2025, Machines 13:785):

1. thin-ring in-plane bending (eqs. 7–10, :mod:`bearingkit.physics.structure.thin_ring`): the outward
   radial components of all element loads of all carried rows bend one ring of centroidal radius R;
   the deflection at each element (modes n ≥ 2 only, the housing takes the net force; optionally
   held by the housing wall, ``housing_stiffness``) opens its gap
   (``RacewayOffset.radial``);
2. axial beam between the housing supports A and B (eqs. 4–6, :mod:`bearingkit.physics.structure.ring_beam`):
   the radial force of each row deflects the ring as a simply supported beam; at each row the beam
   deflection u and slope u′ move that row's outer raceway as a rigid body
   (``RacewayOffset.shift``): the raceway point at axial z moves by u(z_k) + u′(z_k)(z − z_k),
   i.e. shift = (u − u′z_k, v − v′z_k, 0, −v′, u′) for deflections (u, v) along x and y.

How the beam deflection enters the contacts (``beam_mode``, documented names in :data:`BEAM_MODES`):

- ``"clearance"`` — seed 002's reading (eqs. 11 and 19: u_s is subtracted from the groove-centre
  distance / the roller approach like the radial clearance u_br): the row's outer raceway opens
  uniformly around the circumference by u_s(z_k) (``RacewayOffset.radial``);
- ``"translation"`` — the row's outer raceway translates rigidly by u_s along the row force
  (``RacewayOffset.shift``).

``beam_tilt=True`` adds the beam slope as a rigid tilt of each row's raceway (seed 002 writes
θ = θ_b − θ_B, eq. 11). It is off by default: the slope of a locally bent strip rotates the groove
section at the loaded azimuth, it does not tilt the whole raceway about a diameter (which would move
the raceway at ψ = 0 axially by r·θ_B — hundreds of µm for the seed-002 section).

``housing_stiffness`` k_h [N/m²] holds the ring in its housing bore as a bilateral Winkler
foundation (:mod:`bearingkit.physics.structure.thin_ring`): the ovalisation modes n ≥ 2 then have the
stiffness π [EI (n²−1)² + k_h R⁴]/R³ instead of π EI (n²−1)²/R³. 0 (the dataclass default) is the
free ring, np.inf a rigid housing (no ovalisation: the beam model alone). The housing is not scaled
by ``compliance_scale`` (it is not part of the ring).

``compliance_scale`` multiplies both compliances (0: rigid ring; used for the rigid → flexible
study of seed 002 §3.2, where the paper varies the outer-ring deflection as a parameter).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit import checks
from bearingkit.physics.structure import ring_beam, thin_ring, thin_ring_forces
from bearingkit.rings.section import RingSection
from bearingkit.rows.base import RacewayOffset

REFERENCES = ("li2025", "roark2012", "cavallaro2005")
#: How the beam deflection acts on a row (see module docstring).
BEAM_MODES = ("clearance", "translation")


@dataclass(frozen=True)
class FlexibleOuterRing:
    """The outer ring's compliance.

    Parameters
    ----------
    section : RingSection
        Section properties (in-plane I, centroid radius, beam-strip I).
    youngs_modulus : float [Pa]
        E of the ring material.
    axial_center : float [m]
        Axial position of the ring's middle (bearing frame).
    support_positions : tuple of 2 float or None [m]
        Axial positions z_A < z_B of the housing supports; None disables the beam deflection.
    bending : bool
        Include the thin-ring bending (ovalisation).
    compliance_scale : float [–]
        Multiplies both compliances (≥ 0; 0 = rigid).
    rows : tuple of str or None
        Names of the rows whose outer raceway is this ring (None: every row of the bearing).
    beam_mode : str
        ``"clearance"`` or ``"translation"`` (:data:`BEAM_MODES`).
    beam_tilt : bool
        Apply the beam slope as a rigid raceway tilt (seed 002's θ_B; off by default).
    housing_stiffness : float [N/m²]
        Winkler stiffness k_h of the housing that holds the ring's ovalisation (≥ 0; 0 = free ring,
        np.inf = rigid housing). See :func:`bearingkit.physics.structure.thin_ring.housing_wall_stiffness`.
    """

    section: RingSection
    youngs_modulus: float = 2.08e11
    axial_center: float = 0.0
    support_positions: tuple | None = None
    bending: bool = True
    compliance_scale: float = 1.0
    rows: tuple | None = None
    beam_mode: str = "clearance"
    beam_tilt: bool = False
    housing_stiffness: float = 0.0

    def __post_init__(self):
        checks.one_of("beam_mode", self.beam_mode, BEAM_MODES)
        k = float(self.housing_stiffness)
        if np.isnan(k) or k < 0:
            raise checks.InputError(
                f"housing_stiffness ({k:.6g} N/m²) must be non-negative (0 = free ring, inf = rigid housing)"
            )
        if not isinstance(self.section, RingSection):
            raise checks.InputError(f"section ({self.section!r}) must be a RingSection")
        checks.positive("youngs_modulus", self.youngs_modulus, "Pa")
        checks.finite("axial_center", self.axial_center, "m")
        checks.non_negative("compliance_scale", self.compliance_scale)
        if self.support_positions is not None:
            za, zb = (float(v) for v in self.support_positions)
            checks.finite("support_positions", [za, zb], "m")
            if not zb > za:
                raise checks.InputError(
                    f"support_positions ({za:.6g}, {zb:.6g} m) must be increasing (z_A < z_B)"
                )
            half = self.section.width / 2
            lo, hi = self.axial_center - half, self.axial_center + half
            if za < lo - 1e-12 or zb > hi + 1e-12:
                raise checks.InputError(
                    f"support span ({za:.6g} … {zb:.6g} m, {zb - za:.6g} m) must lie within the ring "
                    f"({lo:.6g} … {hi:.6g} m, width {self.section.width:.6g} m)"
                )
            if self.section.beam_area_moment is None:
                raise checks.InputError(
                    "section.beam_area_moment (None) is needed when support_positions is given"
                )

    @property
    def flexural_rigidity(self) -> float:
        """In-plane EI [N·m²] (∞ when the compliance scale is 0)."""
        if self.compliance_scale == 0:
            return np.inf
        return self.youngs_modulus * self.section.area_moment / self.compliance_scale

    @property
    def beam_rigidity(self) -> float:
        """EI of the axial beam strip [N·m²] (∞ when the scale is 0)."""
        if self.compliance_scale == 0 or self.section.beam_area_moment is None:
            return np.inf
        return self.youngs_modulus * self.section.beam_area_moment / self.compliance_scale

    def carried(self, model) -> list:
        """Indices of the model's rows this ring carries."""
        names = [r.name for r in model.rows]
        if self.rows is None:
            return list(range(len(names)))
        unknown = set(self.rows) - set(names)
        if unknown:
            raise checks.InputError(f"ring rows {sorted(unknown)} are not in the bearing; rows are {names}")
        return [names.index(n) for n in self.rows]

    @property
    def has_radial(self) -> bool:
        """Whether the ring imposes per-element radial offsets (bending, or the beam as clearance)."""
        return self.bending or (self.support_positions is not None and self.beam_mode == "clearance")

    @property
    def has_shift(self) -> bool:
        """Whether the ring imposes rigid raceway shifts (beam as translation, or the beam tilt)."""
        return self.support_positions is not None and (self.beam_mode == "translation" or self.beam_tilt)

    # -- compliance -------------------------------------------------------------------------------
    def ring_loads(self, model, result) -> RingLoads:
        """What the ring carries in ``result``: element radial loads and row forces (:class:`RingLoads`)."""
        idx = self.carried(model)
        states = [result.rows[i] for i in idx]
        psi, q = self.element_loads(states)
        forces = None
        if self.support_positions is not None:
            forces = np.stack([result.row_load(model.rows[i].name)[:, :2] for i in idx], axis=1)
        sizes = tuple(int(st.load.shape[-1]) for st in states)
        return RingLoads(psi, q, forces, sizes)

    def offsets(self, model, result) -> dict:
        """Raceway offsets {row name: RacewayOffset} produced by the element loads of ``result``."""
        return self.offsets_from(model, self.ring_loads(model, result))

    def offsets_from(self, model, loads: RingLoads, matrix=None) -> dict:
        """Raceway offsets {row name: RacewayOffset} of given ring loads (the ring's own map).

        The map is linear in the element radial loads (thin-ring bending, :meth:`bending_matrix`;
        pass ``matrix`` to reuse it: the element azimuths do not change during a solve) and depends
        on the row forces through the beam (linear, except the opening |u| of the ``"clearance"`` mode).
        """
        idx = self.carried(model)
        n_cases = loads.radial.shape[0]
        cuts = np.cumsum(loads.sizes)[:-1]
        radial = [None] * len(idx)
        if self.bending:
            cmat = self.bending_matrix(loads.azimuth) if matrix is None else matrix
            w = np.einsum("cmn,cn->cm", cmat, loads.radial)
            radial = np.split(w, cuts, axis=-1)
        shifts = [None] * len(idx)
        if self.support_positions is not None:
            shifts, opening = self._beam(model, loads.row_forces, idx)
            if self.beam_mode == "clearance":
                radial = [
                    o[:, None] + np.zeros((n_cases, z)) + (0.0 if w is None else w)
                    for o, z, w in zip(opening, loads.sizes, radial, strict=True)
                ]
        return {
            model.rows[i].name: RacewayOffset(shift=s, radial=w)
            for i, w, s in zip(idx, radial, shifts, strict=True)
        }

    def bending_matrix(self, azimuth) -> np.ndarray:
        """Thin-ring influence matrix (C, N, N) [m/N] between the carried elements at ``azimuth`` (C, N).

        Zero when bending is off or the ring is rigid (compliance scale 0).
        """
        psi = np.atleast_2d(azimuth)
        if not self.bending or self.compliance_scale == 0:
            return np.zeros((psi.shape[0], psi.shape[-1], psi.shape[-1]))
        return thin_ring.radial_influence(
            psi, psi, self.section.centroid_radius, self.flexural_rigidity, self.housing_stiffness
        )

    @staticmethod
    def element_loads(states):
        """Azimuths (C, N) and outward radial element loads (C, N) [N] of the given row states."""
        psi, q = [], []
        for st in states:
            radial_part = np.cos(st.contact_angle) if st.kind == "ball" else np.ones_like(st.load)
            if st.kind == "cylindrical" and np.any(st.contact_angle != 0):
                radial_part = np.zeros_like(st.load)  # thrust rows push axially, not radially
            psi.append(np.broadcast_to(st.azimuth, st.load.shape))
            q.append(st.load * radial_part)
        return np.concatenate(psi, axis=-1), np.concatenate(q, axis=-1)

    def _beam(self, model, forces, idx):
        za, zb = (float(v) for v in self.support_positions)
        z = np.array([float(np.asarray(model.rows[i].axial_position)) for i in idx])
        if np.any(z < za - 1e-12) or np.any(z > zb + 1e-12):
            raise checks.InputError(
                f"row axial positions ({z.min():.6g} … {z.max():.6g} m) must lie between the housing "
                f"supports ({za:.6g}, {zb:.6g} m)"
            )
        x = np.clip(z - za, 0.0, zb - za)
        u, du = ring_beam.beam_deflection(x, x, forces[..., 0], zb - za, self.beam_rigidity)
        v, dv = ring_beam.beam_deflection(x, x, forces[..., 1], zb - za, self.beam_rigidity)
        zeros = np.zeros_like(u)
        tilt = 1.0 if self.beam_tilt else 0.0
        if self.beam_mode == "translation":
            shift = np.stack([u - tilt * du * z, v - tilt * dv * z, zeros, -tilt * dv, tilt * du], axis=-1)
        else:
            shift = np.stack([-tilt * du * z, -tilt * dv * z, zeros, -tilt * dv, tilt * du], axis=-1)
        opening = np.hypot(u, v)  # deflection along the row force (C, K)
        shifts = [shift[:, k] if self.has_shift else None for k in range(len(idx))]
        return shifts, [opening[:, k] for k in range(len(idx))]

    def deflection_shape(self, model, result, theta) -> np.ndarray:
        """Outward thin-ring bending deflection (C, M) [m] at angles θ (for plots)."""
        loads = self.ring_loads(model, result)
        theta = np.asarray(theta, dtype=float)
        if not self.bending or self.compliance_scale == 0:
            return np.zeros((loads.radial.shape[0], theta.shape[-1]))
        return thin_ring.radial_deflection(
            theta,
            loads.azimuth,
            loads.radial,
            self.section.centroid_radius,
            self.flexural_rigidity,
            housing_stiffness=self.housing_stiffness,
        )

    def ring_forces(self, model, result, theta) -> thin_ring_forces.RingForces:
        """Bending moment, hoop force and shear of the ring (C, M) at angles θ under the element loads.

        The housing model of the deflection (:mod:`bearingkit.physics.structure.thin_ring_forces`,
        ``support="housing"``): the n = 0, 1 harmonics of the element loads go to the housing, the
        housing wall (k_h) holds the ovalisation. The hoop force therefore excludes the uniform part
        that the housing takes. Computed whether or not the ring's bending enters the contacts
        (``bending``), since a ring carries these moments even when its deflection is neglected.
        """
        loads = self.ring_loads(model, result)
        theta = np.asarray(theta, dtype=float)
        return thin_ring_forces.ring_forces(
            theta,
            self.section.centroid_radius,
            radial=(loads.azimuth, loads.radial),
            flexural_rigidity=self.flexural_rigidity,
            housing_stiffness=self.housing_stiffness,
        )

    def fibre_stress(self, forces: thin_ring_forces.RingForces):
        """Hoop stress (inner, outer fibre) [Pa] of ``forces``; None if the section's radii are unknown."""
        sec = self.section
        if sec.inner_fibre is None or sec.outer_fibre is None:
            return None
        return thin_ring_forces.fibre_stress(
            forces.moment, forces.normal_force, sec.area, sec.area_moment, sec.inner_fibre, sec.outer_fibre
        )


@dataclass(frozen=True)
class RingLoads:
    """The loads a flexible ring carries, in the order of its carried rows (SI).

    Attributes
    ----------
    azimuth : ndarray (C, N) [rad]
        Azimuth of every carried element (rows concatenated).
    radial : ndarray (C, N) [N]
        Outward radial element loads (ball: Q cos α; radial roller: Q).
    row_forces : ndarray (C, K, 2) or None [N]
        Radial force (x, y) each carried row passes to the ring (None without housing supports).
    sizes : tuple of int
        Elements per carried row (Σ = N).
    """

    azimuth: np.ndarray
    radial: np.ndarray
    row_forces: np.ndarray | None
    sizes: tuple
