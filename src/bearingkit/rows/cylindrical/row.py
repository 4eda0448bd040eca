"""Cylindrical roller rows, radial or thrust, sliced along the roller (the slice method).

SI units. A roller of effective length l is cut into n_s slices of width w = l/n_s whose centres
lie at x_k from the roller middle. Each slice is a line contact with both raceways in series;
its approach is the ring approach at the slice, minus the gap, minus twice the crown drop
(the drop is on the roller radius and relieves both contacts; Tian et al. 2025 eqs. 3–4, 9):

    radial row  δ_jk = u_r,j − x_k θ_t,j − c − 2C(x_k)          (roller axis along z)
    thrust row  δ_jk = σ (u_a,j + x_k θ_t,j) − c − 2C(x_k)       (roller axis along the radius,
                                                                  σ = ±1 the row's direction)

with c = clearance/2, and slice load q_jk = c_s ⟨δ_jk⟩^(10/9), c_s = c_l·w/l (Kunert/Palmgren or
ISO/TS 16281 line law, :mod:`bearingkit.physics.contact.hertz`). The slice approach is affine in q, so the
whole row is two matrix products per Newton iteration: δ = q Gᵀ + δ₀, f = −q_s G, J = −Gᵀ diag(q_s′) G.

The roller is rigid and held between two rigid raceways, as in the seed papers; roller tilting
inside the gap does not change the slice approach of two equal contacts.
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
    case_column,
    element_offsets,
    radial_row,
    relative_displacement,
    steel_e_reduced,
    tilt_row,
    validate_common,
)

#: Exponent of the line-contact law q ∝ δ^(10/9) (Kunert 1961; ISO/TS 16281:2008 eq. 38).
LINE_EXPONENT = 10.0 / 9.0
#: Allowed row orientations: radial, thrust pushing up (+z), thrust pushing down (−z).
ORIENTATIONS = {"radial": 0, "thrust_up": 1, "thrust_down": -1}
#: How the two raceway contacts of a slice share the total approach δ between the raceways.
#: "series": two line contacts in series, δ = δ_inner + δ_outer (physical; ISO/TS 16281 c_L is this).
#: "total_approach": the one-contact law applied to the total approach — Tian et al. 2025 eqs. (3)–(5)
#: read literally (q = w A^-1.11 l^-0.11 δ^1.11 with δ the raceway-to-raceway approach); stiffer by
#: 2^(10/9) ≈ 2.16 in load at equal approach. Offered so the seed-000 model can be reproduced as written.
PAIRINGS = ("series", "total_approach")
#: Batches up to this many cases use the dense slice products (fewer, larger numpy calls).
SMALL_BATCH = 8


@dataclass(frozen=True)
class CylindricalRow:
    """A row of Z cylindrical rollers, radial or thrust.

    Parameters
    ----------
    n_elements : int
        Number of rollers Z.
    element_diameter : float [m]
        Roller diameter D_w.
    effective_length : float [m]
        Effective contact length l.
    pitch_diameter : float [m]
        Pitch diameter d_m (roller centres; for a thrust row the diameter of the roller middles).
    orientation : str
        ``"radial"``, ``"thrust_up"`` (the row resists +u_z of the inner ring) or ``"thrust_down"``.
    clearance : float [m]
        Row clearance counted twice (diametral radial clearance u_r0 for a radial row, total axial
        play u_a0 for a thrust row, as in seed 000); each roller sees c = clearance/2. Negative = preload.
    n_slices : int
        Slices per roller (≥ 1).
    profile : Profile or None
        Crowning profile (:mod:`bearingkit.physics.contact.profiles`); None = straight roller.
    line_law : str
        ``"kunert"`` or ``"iso16281"``.
    pairing : str
        ``"series"`` (default) or ``"total_approach"``, see :data:`PAIRINGS`.
    axial_position : float [m]
        Axial position of the roller middles (radial row) or of the contact plane (thrust row).
    azimuth_phase : float [rad]
    e_reduced : float [Pa] or None
        Reduced modulus E′ (steel–steel by default).
    name : str
    """

    kind: ClassVar[str] = "cylindrical"

    n_elements: int
    element_diameter: float
    effective_length: float
    pitch_diameter: float
    orientation: str = "radial"
    clearance: float = 0.0
    n_slices: int = 20
    profile: object | None = None
    line_law: str = "kunert"
    pairing: str = "series"
    axial_position: float = 0.0
    azimuth_phase: float = 0.0
    e_reduced: float | None = None
    name: str = "roller"

    def __post_init__(self):
        validate_common(self)
        checks.positive("effective_length", self.effective_length, "m")
        checks.one_of("orientation", self.orientation, ORIENTATIONS)
        checks.integer("n_slices", self.n_slices, low=1)
        if self.e_reduced is not None:
            checks.positive("e_reduced", self.e_reduced, "Pa")
        from bearingkit.physics.contact.line import LINE_LAWS

        checks.one_of("line_law", self.line_law, LINE_LAWS)
        checks.one_of("pairing", self.pairing, PAIRINGS)
        if self.orientation != "radial":
            inner = np.asarray(self.pitch_diameter) / 2 - np.asarray(self.effective_length) / 2
            if np.any(inner <= 0):
                raise checks.InputError(
                    f"effective_length ({np.max(self.effective_length):.6g} m) of a thrust row "
                    "must be shorter "
                    f"than the pitch_diameter ({np.min(self.pitch_diameter):.6g} m)"
                )

    @property
    def direction(self) -> int:
        """σ = +1/−1 for thrust rows, 0 for a radial row."""
        return ORIENTATIONS[self.orientation]

    def envelope(self) -> tuple[float, float, float, float]:
        """Space the rollers sweep: (r_min, r_max, z_min, z_max) [m]; a thrust roller lies along the radius
        with its contact plane at ``axial_position`` and its centre half a diameter inside the gap."""
        r, d = np.max(self.pitch_diameter) / 2, np.max(self.element_diameter)
        half_l, z = np.max(self.effective_length) / 2, np.max(self.axial_position)
        if self.direction == 0:
            return (r - d / 2, r + d / 2, z - half_l, z + half_l)
        return (r - half_l, r + half_l, z - d / 2, z + d / 2)

    def kernel(self) -> CylindricalKernel:
        """Precompute the arrays the solver needs (done once per solve)."""
        return CylindricalKernel(self)


class CylindricalKernel(KernelBase):
    """Precomputed slice geometry of a :class:`CylindricalRow`.

    The approach of slice k of roller j is affine in q and in the slice position x_k:
    δ_jk = a_j + b_j x_k + δ₀_k with a_j = G_a,j·q (approach at the roller middle) and b_j = G_b,j·q
    (tilt across the roller). Force and Jacobian therefore need only the per-roller slice sums
    Σq, Σq x (force) and Σq′, Σq′x, Σq′x² (stiffness): slices are reduced first, and the products with
    the 5-DOF directions are per roller, not per slice.
    """

    #: Per-case arrays (leading axis C or 1) that :meth:`take` restricts; ``geometry`` holds the
    #: columns (C|1, 3) D_w, d_m, effective length that :meth:`state` reads.
    _case_arrays = (
        "Ga", "Gb", "GaGa", "GaGb", "GbGb", "delta0", "delta0_flat", "c_s", "x", "X2", "X3", "psi",
        "geometry",
    )  # fmt: skip

    def __init__(self, row: CylindricalRow):
        from bearingkit.physics.contact import hertz, line

        self.row = row
        z_el, n_s = row.n_elements, row.n_slices
        length = case_column(row.effective_length)[:, 0]  # (C|1,): constant fields shared
        length = length[0] if length.shape[0] == 1 else length
        x, width = line.slice_grid(length, n_s)  # (C|…, n_s)
        x = np.asarray(x, dtype=float).reshape(-1, n_s)  # (C|1, n_s)
        self.x = x
        self.e_reduced = float(row.e_reduced) if row.e_reduced is not None else steel_e_reduced()
        columns = (case_column(v) for v in (row.element_diameter, row.pitch_diameter, row.effective_length))
        self.geometry = np.concatenate(np.broadcast_arrays(*columns), axis=1)  # (C|1, 3)
        psi = azimuths(z_el, case_column(row.azimuth_phase)[:, 0])  # (C|1, Z)
        self.psi = psi
        r = case_column(row.pitch_diameter) / 2
        z = case_column(row.axial_position)
        sigma = row.direction
        if sigma == 0:  # radial: u_r at axial position z + x_k = B_r(z) − x_k B_θ
            self.Ga = radial_row(psi, z)
            self.Gb = -np.broadcast_to(tilt_row(psi), self.Ga.shape)
        else:  # thrust: σ·u_a at radius r + x_k = σ (B_a(r) + x_k B_θ)
            self.Ga = sigma * axial_row(psi, r)
            self.Gb = sigma * np.broadcast_to(tilt_row(psi), self.Ga.shape)
        outer = lambda a, b: (a[..., :, None] * b[..., None, :]).reshape(*a.shape[:-1], 25)  # noqa: E731
        self.GaGa = outer(self.Ga, self.Ga)
        self.GaGb = outer(self.Ga, self.Gb) + outer(self.Gb, self.Ga)
        self.GbGb = outer(self.Gb, self.Gb)
        self.X2 = np.stack([np.ones_like(x), x], axis=-1)  # (C|1, n_s, 2): Σq, Σq x
        self.X3 = np.stack([np.ones_like(x), x, x * x], axis=-1)  # Σq′, Σq′x, Σq′x²
        # Per-slice directions (C|1, M, 5), M = Z·n_s: used for the contact cone and the starting point.
        g = self.Ga[..., None, :] + x[:, None, :, None] * self.Gb[..., None, :]
        self.G = g.reshape(g.shape[0], z_el * n_s, 5)
        # Dense form for small batches of a shared geometry: two matrix products beat the per-roller
        # gather/scatter when there are few cases (a single solve is dominated by call overhead).
        self.GG = (self.G[0][:, :, None] * self.G[0][:, None, :]).reshape(-1, 25) if g.shape[0] == 1 else None
        self.tilt_B = tilt_row(psi)
        drop = np.zeros_like(x) if row.profile is None else np.asarray(row.profile.crown_drop(x), dtype=float)
        gap = case_column(row.clearance) / 2
        self.delta0 = -gap - 2.0 * drop  # (C|1, n_s), the same for every roller
        # (C|1, M) in the slice order of G; per case, so the small-batch path of a subset of cases keeps
        # each case's clearance.
        self.delta0_flat = np.tile(self.delta0, (1, z_el))
        # Both contacts of a slice in series; stiffness scales with the slice width (c_s = c_l w/l).
        k_contact = line.line_stiffness(length, self.e_reduced, law=row.line_law)
        if row.pairing == "series":
            k_pair = hertz.series_stiffness(k_contact, k_contact, exponent=LINE_EXPONENT)
        else:
            k_pair = k_contact
        self.c_s = np.asarray(k_pair * np.asarray(width) / length, dtype=float).reshape(-1, 1)  # (C|1, 1)
        # For the solver's starting point: Σ c_s g gᵀ over all slices, as if every slice were in contact.
        g0 = self.G[0]
        self.start_matrix = float(self.c_s.ravel()[0]) * (g0.T @ g0)
        self.start_exponent = LINE_EXPONENT
        self.char_length = float(np.max(r) + np.max(length) / 2)
        self.deflection_scale = float(np.min(row.element_diameter))
        self.shape = (z_el, n_s)

    def _delta3(self, q, offset: RacewayOffset | None = None):
        """Slice approaches (C, Z, n_s) [m]."""
        q = relative_displacement(q, offset)
        if self.Ga.shape[0] == 1:
            a, b = q @ self.Ga[0].T, q @ self.Gb[0].T
        else:
            a, b = np.einsum("czd,cd->cz", self.Ga, q), np.einsum("czd,cd->cz", self.Gb, q)
        a, b = self._offset_ab(a, b, offset)
        delta = b[:, :, None] * self.x[:, None, :]
        delta += a[:, :, None]
        delta += self.delta0[:, None, :]
        return delta

    def _delta(self, q, offset: RacewayOffset | None = None):
        """Slice approaches flattened to (C, Z·n_s) [m]."""
        d = self._delta3(q, offset)
        return d.reshape(d.shape[0], -1)

    def _response_dense(self, q: np.ndarray) -> RowResponse:
        """Small-batch path: δ = q Gᵀ + δ₀ per slice, f = −q_s G, J = −Gᵀ diag(q_s′) G."""
        delta = q @ self.G[0].T + self.delta0_flat
        np.maximum(delta, 0.0, out=delta)
        t = np.cbrt(delta)
        np.cbrt(t, out=t)
        load = delta * t
        load *= self.c_s[0]
        t *= (10.0 / 9.0) * self.c_s[0]
        energy = np.einsum("cm,cm->c", load, delta) / (1.0 + LINE_EXPONENT)
        return RowResponse(-(load @ self.G[0]), -(t @ self.GG).reshape(-1, 5, 5), energy)

    def _ab(self, q, offset: RacewayOffset | None = None):
        """Per-roller approach at the middle a and tilt b (C, Z): δ_jk = a_j + b_j x_k + δ₀_k."""
        q = relative_displacement(q, offset)
        if self.Ga.shape[0] == 1:
            a, b = q @ self.Ga[0].T, q @ self.Gb[0].T
        else:
            a, b = np.einsum("czd,cd->cz", self.Ga, q), np.einsum("czd,cd->cz", self.Gb, q)
        return self._offset_ab(a, b, offset)

    def _offset_ab(self, a, b, offset):
        """(a, b) with the raceway offset: a radial row opens by ``radial`` and tilts by ``tilt``
        (slice k at x_k sees radial − x_k tilt); a thrust row (σ) by σ·``axial`` and σ·``tilt``."""
        parts = element_offsets(offset, a.shape)
        if parts is None:
            return a, b
        radial, axial, tilt = parts
        sigma = self.row.direction
        if sigma == 0:  # an outward raceway deflection opens every slice of that roller
            return a - radial, b + tilt
        return a - sigma * axial, b - sigma * tilt

    def raceway_loads(self, q: np.ndarray, offset: RacewayOffset | None = None) -> np.ndarray:
        """Loads (F_r, F_z, M_t) (C, Z, 3) each roller puts on the outer raceway, −∂U/∂(radial, axial, tilt):
        radial rows (Σq, 0, −Σq x), thrust rows (0, σΣq, σΣq x), x the slice positions."""
        delta = np.maximum(self._delta3(q, offset), 0.0)
        q_slice = self.c_s[..., None] * delta**LINE_EXPONENT
        total, moment = q_slice.sum(-1), (q_slice * self.x[:, None, :]).sum(-1)
        zero = np.zeros_like(total)
        sigma = self.row.direction
        if sigma == 0:
            return np.stack([total, zero, -moment], axis=-1)
        return np.stack([zero, sigma * total, sigma * moment], axis=-1)

    def response(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowResponse:
        """Generalised force, Jacobian and energy for displacements q (C, 5) (raceway offset optional)."""
        if q.shape[0] <= SMALL_BATCH and self.GG is not None and self.delta0.shape[0] == 1 and offset is None:
            return self._response_dense(q)
        a, b = self._ab(q, offset)
        c, z_el = a.shape
        # Only rollers that can touch at all are sliced: a bound on the largest slice approach.
        reach = np.abs(b) * np.abs(self.x).max(axis=-1, keepdims=True) + self.delta0.max(
            axis=-1, keepdims=True
        )
        ci, zi = np.nonzero(a + reach > 0.0)
        delta = b[ci, zi, None] * (self.x[ci] if self.x.shape[0] > 1 else self.x[0])
        delta += a[ci, zi, None]
        delta += self.delta0[ci] if self.delta0.shape[0] > 1 else self.delta0[0]
        np.maximum(delta, 0.0, out=delta)
        # δ^(1/9) as two cube roots: ~3x faster than a float power and exact at δ = 0.
        t = np.cbrt(delta)
        np.cbrt(t, out=t)
        c_s = self.c_s[ci] if self.c_s.shape[0] > 1 else self.c_s[0]
        load = delta * t
        load *= c_s  # q = c_s δ^(10/9)
        t *= (10.0 / 9.0) * c_s  # q′ = dq/dδ
        if self.X2.shape[0] == 1:
            f_live, k_live = load @ self.X2[0], t @ self.X3[0]  # Σq, Σq x | Σq′, Σq′x, Σq′x²
        else:
            f_live = np.einsum("nk,nkj->nj", load, self.X2[ci])
            k_live = np.einsum("nk,nkj->nj", t, self.X3[ci])
        f_sums = np.zeros((c, z_el, 2))
        k_sums = np.zeros((c, z_el, 3))
        f_sums[ci, zi] = f_live
        k_sums[ci, zi] = k_live
        if self.Ga.shape[0] == 1:
            force = -(f_sums[..., 0] @ self.Ga[0] + f_sums[..., 1] @ self.Gb[0])
            jac = -(
                k_sums[..., 0] @ self.GaGa[0] + k_sums[..., 1] @ self.GaGb[0] + k_sums[..., 2] @ self.GbGb[0]
            )
        else:
            force = -(
                np.einsum("cz,czd->cd", f_sums[..., 0], self.Ga)
                + np.einsum("cz,czd->cd", f_sums[..., 1], self.Gb)
            )
            jac = -(
                np.einsum("cz,czk->ck", k_sums[..., 0], self.GaGa)
                + np.einsum("cz,czk->ck", k_sums[..., 1], self.GaGb)
                + np.einsum("cz,czk->ck", k_sums[..., 2], self.GbGb)
            )
        energy = np.bincount(ci, weights=np.einsum("nk,nk->n", load, delta), minlength=c) / (
            1.0 + LINE_EXPONENT
        )
        return RowResponse(force, jac.reshape(c, 5, 5), energy)

    def state(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowState:
        """Per-roller and per-slice results at displacements q (C, 5)."""
        from bearingkit.physics.contact import line

        row = self.row
        n_s = self.shape[1]
        delta = np.maximum(self._delta3(q, offset), 0.0)
        c_s = self.c_s[..., None]
        q_slice = c_s * delta**LINE_EXPONENT
        load = q_slice.sum(axis=-1)
        d, dm, length = (self.geometry[:, k, None, None] for k in range(3))
        width = length / n_s
        if row.direction == 0:  # radial: the inner contact (convex–convex) has the smaller R_x
            radius_x = {"inner": d / 2 * (1 - d / dm), "outer": d / 2 * (1 + d / dm)}
        else:  # thrust: roller on flat washers
            radius_x = {"inner": d / 2 + 0 * dm, "outer": d / 2 + 0 * dm}
        extras, p_max = {}, np.zeros_like(q_slice)
        # Hertz line contact per slice, p_max = c √q: √q once, scaled per raceway (this runs on every
        # slice of every case of a study, and the loads are valid by construction).
        root = np.sqrt(q_slice)
        for side, rx in radius_x.items():
            pressure = root * line.line_pressure_factor(width, rx, self.e_reduced)
            extras[f"slice_pressure_{side}"] = pressure
            p_max = np.maximum(p_max, pressure)
        extras["slice_position"] = np.broadcast_to(self.x[:, None, :], q_slice.shape)
        alpha = np.full(load.shape, 0.0 if row.direction == 0 else row.direction * np.pi / 2)
        psi = np.broadcast_to(self.psi, load.shape)
        return RowState(
            "cylindrical", row.name, psi, load, delta.max(axis=-1), alpha, p_max.max(axis=-1), q_slice, extras
        )
