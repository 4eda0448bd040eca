"""Crossed roller rows: cylindrical rollers in a V-groove, their axes alternately at ±(90° − α).

SI units. Roller j carries load along its contact normal n_j = (cos α_j, sin α_j) in its radial–axial
plane, α_j = +α for even j and −α for odd j (α = 45° in crossed roller slewing rings): it touches one
flank of the inner V and the opposite flank of the outer V along a line. The line lies along
t_j = (−sin α_j, cos α_j); slice k sits at x_k along t_j from the roller middle (R, z₀). Its approach,
both contacts in series, is the inner-ring displacement at the slice projected on n_j, minus the gap
and twice the crown drop (as :mod:`bearingkit.rows.cylindrical.row`):

    δ_jk = n_j · (u_r, u_a)(R − x_k sin α_j, z₀ + x_k cos α_j) − c − 2C(x_k)
         = G_a,j · q + x_k G_b,j · q − c − 2C(x_k),
    G_a,j = cos α_j B_r(ψ_j, z₀) + sin α_j B_a(ψ_j, R),    G_b,j = −B_θ(ψ_j)

(the tilt term does not depend on α_j: a rotation θ_t of the raceway changes the approach along any
line in the plane by −x θ_t). The slice approach is affine in q, so the row is two matrix products
per iteration; slice loads q_jk = c_s ⟨δ_jk⟩^(10/9) (Kunert or ISO/TS 16281 line law).

Each roller sees the gap c = (P_d/2) cos α, P_d being the row's diametral radial clearance (the inner
ring moving radially by P_d/2 closes the roller at ψ = 0). The end faces of a roller slide on the
other flanks; they carry no load here (as in the usual slewing-ring analyses).

References: Harris & Kotzalas (2007) ch. 7-8 (roller load distribution); Kunert (1961) line law;
ISO/TS 16281:2008 (slicing).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from bearingkit import checks
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
    steel_e_reduced,
    tilt_row,
    validate_common,
)

#: Exponent of the line-contact law q ∝ δ^(10/9) (Kunert 1961; ISO/TS 16281:2008 eq. 38).
LINE_EXPONENT = 10.0 / 9.0


@dataclass(frozen=True)
class CrossedRollerRow:
    """A row of Z cylindrical rollers crossed alternately at ±α.

    Parameters
    ----------
    n_elements : int
        Number of rollers Z (even: half carry along +α, half along −α).
    element_diameter : float [m]
        Roller diameter D_w.
    effective_length : float [m]
        Effective contact length l (≤ D_w: the roller must fit the V-groove crosswise).
    pitch_diameter : float [m]
        Pitch diameter d_m of the roller centres.
    contact_angle : float [rad]
        α of the contact normals (0 < α < 90°), 45° for crossed roller bearings.
    clearance : float [m]
        Diametral radial clearance P_d (negative = preload); each roller sees (P_d/2) cos α.
    n_slices : int
        Slices per roller.
    profile : Profile or None
        Crowning profile (:mod:`bearingkit.physics.contact.profiles`); None = straight rollers.
    line_law : str
        ``"kunert"`` or ``"iso16281"``.
    axial_position : float [m]
    azimuth_phase : float [rad]
    e_reduced : float [Pa] or None
    name : str
    """

    kind: ClassVar[str] = "crossed_roller"

    n_elements: int
    element_diameter: float
    effective_length: float
    pitch_diameter: float
    contact_angle: float = np.pi / 4
    clearance: float = 0.0
    n_slices: int = 10
    profile: object | None = None
    line_law: str = "kunert"
    axial_position: float = 0.0
    azimuth_phase: float = 0.0
    e_reduced: float | None = None
    name: str = "rollers"

    def __post_init__(self):
        validate_common(self)
        checks.integer("n_elements", self.n_elements, low=2)
        if self.n_elements % 2:
            raise checks.InputError(
                f"n_elements ({self.n_elements}) must be even: crossed rollers alternate between the two "
                "directions, half of them each way"
            )
        checks.positive("effective_length", self.effective_length, "m")
        checks.in_range("contact_angle", self.contact_angle, 0.0, np.pi / 2, "rad", closed=False)
        checks.integer("n_slices", self.n_slices, low=1)
        if self.e_reduced is not None:
            checks.positive("e_reduced", self.e_reduced, "Pa")
        from bearingkit.physics.contact.line import LINE_LAWS

        checks.one_of("line_law", self.line_law, LINE_LAWS)
        length, d = np.asarray(self.effective_length), np.asarray(self.element_diameter)
        if np.any(length > d):
            raise checks.InputError(
                f"effective_length ({np.max(length):.6g} m) must not exceed element_diameter "
                f"({np.min(d):.6g} m): a crossed roller lies crosswise in the V-groove of its neighbours"
            )
        gap = -np.asarray(self.clearance, dtype=float) / 2 * np.cos(self.contact_angle)
        if np.any(gap >= 0.05 * d):
            raise checks.InputError(
                f"clearance ({np.min(self.clearance):.6g} m) is a preload of more than 5 % of the roller "
                "diameter along the contact line; expected a few micrometres"
            )

    def envelope(self) -> tuple[float, float, float, float]:
        """Space the rollers sweep: (r_min, r_max, z_min, z_max) [m] (a roller fits a D_w square)."""
        r, d, z = np.max(self.pitch_diameter) / 2, np.max(self.element_diameter), np.max(self.axial_position)
        half = d / np.sqrt(2.0)
        return (r - half, r + half, z - half, z + half)

    @property
    def directions(self) -> np.ndarray:
        """Contact angle of each roller α_j [rad], (Z,): +α, −α, +α, …"""
        sign = np.where(np.arange(self.n_elements) % 2 == 0, 1.0, -1.0)
        return sign * float(self.contact_angle)

    def kernel(self) -> CrossedRollerKernel:
        """Precompute the arrays the solver needs (done once per solve)."""
        return CrossedRollerKernel(self)


class CrossedRollerKernel(KernelBase):
    """Affine slice approaches of a :class:`CrossedRollerRow`: δ = q Gᵀ + δ₀ over all slices."""

    _case_arrays = ("delta0",)

    def __init__(self, row: CrossedRollerRow):
        from bearingkit.physics.contact import hertz, line

        self.row = row
        z_el, n_s = row.n_elements, row.n_slices
        length = float(row.effective_length)
        x, width = line.slice_grid(length, n_s)
        self.x = np.asarray(x, dtype=float).reshape(n_s)
        self.e_reduced = float(row.e_reduced) if row.e_reduced is not None else steel_e_reduced()
        self.psi = azimuths(z_el, row.azimuth_phase)[0]  # (Z,)
        self.alpha = row.directions  # (Z,)
        r, z = float(row.pitch_diameter) / 2, float(row.axial_position)
        ca, sa = np.cos(self.alpha)[:, None], np.sin(self.alpha)[:, None]
        self.Ga = ca * radial_row(self.psi, z) + sa * axial_row(self.psi, r)  # (Z, 5)
        self.Gb = -tilt_row(self.psi)
        g = self.Ga[:, None, :] + self.x[None, :, None] * self.Gb[:, None, :]
        self.G = g.reshape(z_el * n_s, 5)
        self.GG = (self.G[:, :, None] * self.G[:, None, :]).reshape(-1, 25)
        self.reach = self.G  # every slice pushes along its own column of G (solver cone checks)
        drop = np.zeros(n_s) if row.profile is None else np.asarray(row.profile.crown_drop(self.x), float)
        gap = np.asarray(row.clearance, dtype=float).reshape(-1, 1) / 2 * np.cos(float(row.contact_angle))
        self.delta0 = np.tile(-gap - 2.0 * drop, (1, z_el))  # (C|1, Z·n_s)
        k_contact = line.line_stiffness(length, self.e_reduced, law=row.line_law)
        k_pair = hertz.series_stiffness(k_contact, k_contact, exponent=LINE_EXPONENT)
        self.c_s = float(k_pair * float(width) / length)
        self.start_matrix = self.c_s * (self.G.T @ self.G)
        self.start_exponent = LINE_EXPONENT
        self.char_length = r + row.element_diameter
        self.deflection_scale = float(row.element_diameter)
        self.shape = (z_el, n_s)

    def _delta(self, q, offset: RacewayOffset | None = None):
        q = relative_displacement(q, offset)
        delta = q @ self.G.T + self.delta0
        parts = element_offsets(offset, (q.shape[0], self.shape[0]))
        if parts is not None:  # the raceway moved: each roller's normal (cos α, sin α), slices along it
            radial, axial, tilt = parts
            opening = radial * np.cos(self.alpha) + axial * np.sin(self.alpha)  # (C, Z)
            delta = delta - np.repeat(opening, self.shape[1], axis=-1)
            delta = delta + (tilt[..., None] * self.x).reshape(delta.shape[0], -1)
        return delta

    def raceway_loads(self, q: np.ndarray, offset: RacewayOffset | None = None) -> np.ndarray:
        """Loads (F_r, F_z, M_t) (C, Z, 3) each roller puts on the outer raceway, −∂U/∂(radial, axial, tilt):
        Σq along the roller's normal (cos α_j, sin α_j) and −Σq x about its middle."""
        z_el, n_s = self.shape
        delta = np.maximum(self._delta(q, offset), 0.0).reshape(-1, z_el, n_s)
        q_slice = self.c_s * delta**LINE_EXPONENT
        total, moment = q_slice.sum(-1), (q_slice * self.x).sum(-1)
        return np.stack([total * np.cos(self.alpha), total * np.sin(self.alpha), -moment], axis=-1)

    def response(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowResponse:
        """Generalised force, Jacobian and energy for displacements q (C, 5)."""
        delta = np.maximum(self._delta(q, offset), 0.0)
        t = np.cbrt(delta)
        np.cbrt(t, out=t)  # δ^(1/9)
        load = self.c_s * delta * t
        stiff = (10.0 / 9.0) * self.c_s * t
        energy = np.einsum("cm,cm->c", load, delta) / (1.0 + LINE_EXPONENT)
        return RowResponse(-(load @ self.G), -(stiff @ self.GG).reshape(-1, 5, 5), energy)

    def state(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowState:
        """Per-roller and per-slice results at displacements q (C, 5).

        ``extras``: ``slice_pressure_inner``/``_outer`` (C, Z, n_s) [Pa], ``slice_position`` [m] and
        ``roller_direction`` (Z,) [rad], the contact angle α_j of each roller.
        """
        from bearingkit.physics.contact import line

        row = self.row
        z_el, n_s = self.shape
        delta = np.maximum(self._delta(q, offset), 0.0).reshape(-1, z_el, n_s)
        q_slice = self.c_s * delta**LINE_EXPONENT
        load = q_slice.sum(axis=-1)
        d, dm = float(row.element_diameter), float(row.pitch_diameter)
        gamma = d * np.cos(float(row.contact_angle)) / dm
        width = float(row.effective_length) / n_s
        extras, p_max = {}, np.zeros_like(q_slice)
        root = np.sqrt(q_slice)
        for side, rx in (("inner", d / 2 * (1 - gamma)), ("outer", d / 2 * (1 + gamma))):
            pressure = root * line.line_pressure_factor(width, rx, self.e_reduced)
            extras[f"slice_pressure_{side}"] = pressure
            p_max = np.maximum(p_max, pressure)
        extras["slice_position"] = np.broadcast_to(self.x, q_slice.shape)
        extras["roller_direction"] = self.alpha
        alpha = np.broadcast_to(self.alpha, load.shape).copy()
        psi = np.broadcast_to(self.psi, load.shape)
        return RowState(
            "crossed_roller",
            row.name,
            psi,
            load,
            delta.max(axis=-1),
            alpha,
            p_max.max(axis=-1),
            q_slice,
            extras,
        )
