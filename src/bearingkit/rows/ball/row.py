"""Ball rows: radial, angular-contact and thrust (α = 90°) rows of balls in grooves.

SI units. Each ball sits between an inner and an outer groove. The loaded contact angle follows
from the positions of the two groove curvature centres (Jones; Harris & Kotzalas 2007, §7 and
§8.1): their unloaded distance is A₀ − c with A₀ = (f_i + f_o − 1) D_w and c the gap per element,
along the free contact angle α₀. The inner-ring displacement moves the inner groove centre, the
distance becomes A = |s|, the contact approach is δ = A − A₀, and the ball load (both contacts in
series, Hertz) is Q = K_n δ^1.5 along s, so the contact angle α = atan2(s_a, s_r) changes with load.

Centrifugal force and gyroscopic moments are neglected (quasi-static, low speed: the seeds'
turntable and composite bearings run at ≤ 90 rpm). K_n is evaluated at the free contact angle α₀;
its change with the operating angle is of second order (ISO/TS 16281 does the same) and keeping it
constant keeps the Jacobian exact.
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
    point_offset,
    radial_row,
    relative_displacement,
    steel_e_reduced,
    validate_common,
)

#: Largest accepted conformity r/D_w [1]: real grooves have 0.505–0.6; above ~1 the "groove" is nearly
#: flat and Hertz point contact with a shoulder no longer describes it (bound chosen to catch typos).
MAX_CONFORMITY = 10.0
#: Hertz point-contact load exponent (Q = K δ^n), Hertz 1881 / Harris & Kotzalas 2007 eq. 6.43.
POINT_EXPONENT = 1.5


def _arm_groove_centre(pitch_radius, axial_position, offset):
    """Inner groove curvature centre: R_i = d_m/2 + (f_i − ½) D_w cos α₀ (Harris & Kotzalas 2007, §8.1)."""
    return pitch_radius + offset[..., 0], axial_position + offset[..., 1]


def _arm_pitch_radius(pitch_radius, axial_position, offset):
    """Ball centre on the pitch circle: the tilt acts at d_m/2 (ISO/TS 16281:2008 moment equation)."""
    return pitch_radius + 0.0 * offset[..., 0], axial_position + 0.0 * offset[..., 1]


#: Tilt lever arm of ball rows: the inner-ring point whose displacement moves the inner groove
#: centre under a ring tilt θ, as (radius, axial position) from (d_m/2, z, groove-centre offset).
#: ``"groove_centre"`` (default): the inner groove curvature centre, at (f_i − ½) D_w from the ball
#: centre along the contact line — the rigid-ring kinematics of Jones and Harris (Harris & Kotzalas
#: 2007, Rolling Bearing Analysis, §8.1, eq. 8.8 with R_i). ``"pitch_radius"``: the ball centre on
#: the pitch circle, as ISO/TS 16281:2008 writes the axial approach under a tilt
#: (δ_a + θ d_m/2 cos ψ) and commercial tools apply it. Both give the same contacts when the ring
#: does not tilt; under a tilt the groove-centre arm moves each inner groove centre by θ R_i axially
#: and θ (f_i − ½) D_w sin α₀ radially, the pitch arm by θ d_m/2 axially only, so ball loads and the
#: tilt stiffness differ under a moment (see docs/engine.md).
TILT_ARMS = {"groove_centre": _arm_groove_centre, "pitch_radius": _arm_pitch_radius}


@dataclass(frozen=True)
class BallRow:
    """A row of Z balls.

    Parameters
    ----------
    n_elements : int
        Number of balls Z.
    element_diameter : float [m]
        Ball diameter D_w.
    pitch_diameter : float [m]
        Pitch diameter d_m (ball centres).
    contact_angle : float [rad]
        Free contact angle α₀ of the line from the outer to the inner groove centre, measured from
        the radial plane; its sign is the row's axial direction (α₀ > 0: the row resists +u_z of the
        inner ring). 0 for a radial row, ±π/2 for a thrust row.
    conformity_inner, conformity_outer : float
        Groove radius over ball diameter f = r/D_w (> 0.5).
    clearance : float [m]
        The row's clearance measured along the contact line, counted twice (diametral for a radial
        row, total axial play for a thrust row: seed 000 writes δ = δ_a − 0.5 u_a0). Negative = preload.
        Each ball sees a gap c = clearance/2.
    axial_position : float [m]
        Axial position z of the ball centres.
    azimuth_phase : float [rad]
        Azimuth of ball 0.
    e_reduced : float [Pa]
        Reduced modulus E′ of the ball/raceway pair (steel–steel by default, from the materials).
    hertz_method : str
        ``"exact"`` or ``"hamrock_brewe"`` (see :mod:`bearingkit.physics.contact.hertz`).
    one_sided : bool or None
        The grooves have a shoulder on the loaded side only (angular contact and thrust rows): a
        contact whose operating angle changes sign would run over the relieved shoulder, so it does
        not exist. Default: True when α₀ ≠ 0, False for a radial (deep groove) row.
    tilt_arm : str
        Lever arm of a ring tilt, :data:`TILT_ARMS`: ``"groove_centre"`` (Harris, default) or
        ``"pitch_radius"`` (ISO/TS 16281).
    name : str
        The row's name in its bearing.

    Geometry fields may be arrays of shape (C,) to batch many designs of the same topology.
    """

    kind: ClassVar[str] = "ball"

    n_elements: int
    element_diameter: float
    pitch_diameter: float
    contact_angle: float = 0.0
    conformity_inner: float = 0.52
    conformity_outer: float = 0.53
    clearance: float = 0.0
    axial_position: float = 0.0
    azimuth_phase: float = 0.0
    e_reduced: float | None = None
    hertz_method: str = "exact"
    one_sided: bool | None = None
    tilt_arm: str = "groove_centre"
    name: str = "ball"

    def __post_init__(self):
        validate_common(self)
        checks.in_range("contact_angle", self.contact_angle, -np.pi / 2, np.pi / 2, "rad")
        for f in ("conformity_inner", "conformity_outer"):
            val = np.asarray(getattr(self, f), dtype=float)
            checks.finite(f, val)
            if np.any(val > MAX_CONFORMITY):
                raise checks.InputError(
                    f"{f} ({np.max(val):.6g}) must be at most {MAX_CONFORMITY:g} (a groove, not a flat)"
                )
            if np.any(val <= 0.5):
                raise checks.InputError(
                    f"{f} ({np.min(val):.6g}) must exceed 0.5: the groove radius must exceed half the ball "
                    "diameter"
                )
        if self.e_reduced is not None:
            checks.positive("e_reduced", self.e_reduced, "Pa")
        from bearingkit.physics.contact.hertz import POINT_METHODS

        checks.one_of("hertz_method", self.hertz_method, POINT_METHODS)
        checks.one_of("tilt_arm", self.tilt_arm, TILT_ARMS)
        spare = (np.asarray(self.conformity_inner) + np.asarray(self.conformity_outer) - 1.0) * np.asarray(
            self.element_diameter
        ) - np.asarray(self.clearance) / 2
        if np.any(spare <= 0):
            raise checks.InputError(
                f"clearance ({np.max(self.clearance):.6g} m) is larger than twice the groove-centre distance "
                f"(f_i + f_o − 1)·D_w; expected a clearance below "
                f"{2 * np.min(spare + self.clearance / 2):.6g} m"
            )

    def envelope(self) -> tuple[float, float, float, float]:
        """Space the balls sweep: (r_min, r_max, z_min, z_max) [m] around the pitch circle."""
        r, d, z = np.max(self.pitch_diameter) / 2, np.max(self.element_diameter), np.max(self.axial_position)
        return (r - d / 2, r + d / 2, z - d / 2, z + d / 2)

    # -- derived, used by the solver -------------------------------------------------------------
    def kernel(self) -> BallKernel:
        """Precompute the arrays the solver needs (done once per solve)."""
        return BallKernel(self)


def one_sided_row(row: BallRow, alpha0) -> bool:
    """Whether the row's grooves have a loaded shoulder only (see ``BallRow.one_sided``)."""
    return row.one_sided if row.one_sided is not None else bool(np.any(np.asarray(alpha0) != 0.0))


class BallKernel(KernelBase):
    """Precomputed geometry and stiffness of a :class:`BallRow` for fast repeated evaluation."""

    #: Per-case arrays (leading axis C or 1) that :meth:`take` restricts; ``geometry`` holds the
    #: columns (C|1, 4) D_w, d_m, f_i, f_o that :meth:`state` reads (a study may vary them per case).
    _case_arrays = ("B", "Bf", "BB", "s0", "a0", "k_n", "side", "psi", "geometry")

    def __init__(self, row: BallRow):
        from bearingkit.physics.contact import hertz

        self.row = row

        col = case_column  # (C,)|() -> (C|1, 1), broadcast over the elements; constant fields shared

        d, dm = col(row.element_diameter), col(row.pitch_diameter)
        alpha0 = col(row.contact_angle)
        fi, fo = col(row.conformity_inner), col(row.conformity_outer)
        self.geometry = np.concatenate(np.broadcast_arrays(d, dm, fi, fo), axis=1)  # (C|1, 4)
        self.e_reduced = float(row.e_reduced) if row.e_reduced is not None else steel_e_reduced()
        self.psi = azimuths(row.n_elements, case_column(row.azimuth_phase)[:, 0])  # (C|1, Z)
        self.a0 = (fi + fo - 1.0) * d  # groove-centre distance at first touch
        gap = col(row.clearance) / 2.0
        unit0 = np.stack([np.cos(alpha0), np.sin(alpha0)], axis=-1)  # (C|1, 1, 2) from outer to inner centre
        self.s0 = (self.a0 - gap)[..., None] * unit0  # unloaded centre separation (C|1, 1, 2)
        # The inner groove centre sits (f_i − ½)D_w from the ball centre along the contact line; the
        # tilt acts at the point TILT_ARMS names (that centre, or the ball centre on the pitch circle).
        offset = ((fi - 0.5) * d)[..., None] * unit0
        # The outer groove centre from the ball centre (the element's reference point of a raceway
        # offset): a raceway tilt moves it by tilt·(−Δz, Δr) (RacewayOffset).
        self.outer_arm = -((fo - 0.5) * d)[..., None] * unit0  # (C|1, 1, 2)
        r_c, z_c = TILT_ARMS[row.tilt_arm](dm / 2, col(row.axial_position), offset)
        self.B = np.stack([radial_row(self.psi, z_c), axial_row(self.psi, r_c)], axis=-2)  # (C|1, Z, 2, 5)
        # Series stiffness of the two contacts, at the free contact angle.
        k = []
        for side, f in (("inner", fi), ("outer", fo)):
            sr, fr = hertz.ball_raceway_curvature(d, dm, np.abs(alpha0), f * d, side)
            k.append(hertz.point_stiffness(sr, fr, self.e_reduced, method=row.hertz_method))
        self.k_n = hertz.series_stiffness(k[0], k[1], exponent=POINT_EXPONENT)  # (C|1, 1)
        # Flattened forms so the hot path is matrix products: u = q B̃ᵀ, f = f_local B̃, J = k_local BB.
        z_el = row.n_elements
        self.Bf = self.B.reshape(self.B.shape[0], z_el * 2, 5)
        self.BB = np.einsum("...zai,...zbj->...zabij", self.B, self.B).reshape(self.B.shape[0], z_el * 4, 25)
        n0 = self.s0 / np.linalg.norm(self.s0, axis=-1, keepdims=True)
        n0 = np.broadcast_to(n0, np.broadcast_shapes(n0.shape, self.B.shape[:-1]))
        self.directions = np.einsum("...zij,...zi->...zj", self.B, n0)  # (C|1, Z, 5) contact normals
        # What the row can push on at all: a two-sided groove (deep groove ball row) also carries
        # axial load in either direction once the contact angle has moved; count both flanks.
        if one_sided_row(row, alpha0):
            self.reach = self.directions[0]
        else:
            flanks = [np.stack([np.cos(a), np.sin(a)], axis=-1) for a in (np.pi / 4, -np.pi / 4)]
            self.reach = np.concatenate(
                [np.einsum("zij,zi->zj", self.B[0], np.broadcast_to(f, self.B.shape[1:-1])) for f in flanks]
                + [self.directions[0]]
            )
        g0 = self.directions[0]
        k0 = np.broadcast_to(self.k_n, self.directions.shape[:2])[0]
        self.start_matrix = np.einsum("z,zi,zj->ij", k0, g0, g0)
        self.start_exponent = POINT_EXPONENT
        one_sided = one_sided_row(row, alpha0)
        self.side = np.sign(alpha0) if one_sided else np.zeros_like(alpha0)  # (C|1, 1): 0 = both sides
        self.pitch_radius = dm / 2
        self.char_length = float(np.max(dm) / 2)
        self.deflection_scale = float(np.min(d))

    def _geometry(self, q, offset: RacewayOffset | None = None):
        q = relative_displacement(q, offset)
        if self.Bf.shape[0] == 1:
            u = (q @ self.Bf[0].T).reshape(q.shape[0], -1, 2)  # (C, Z, 2) local displacement
        else:
            u = np.einsum("czij,cj->czi", self.B, q)
        s = self.s0 + u
        moved = point_offset(offset, s.shape[:-1], self.outer_arm[..., 0], self.outer_arm[..., 1])
        if moved is not None:  # the outer groove centre moves with the raceway
            s = s - moved
        a = np.sqrt(s[..., 0] ** 2 + s[..., 1] ** 2)
        return u, s, a

    def raceway_loads(self, q: np.ndarray, offset: RacewayOffset | None = None) -> np.ndarray:
        """Loads (F_r, F_z, M_t) (C, Z, 3) each ball puts on the outer raceway, −∂U/∂(radial, axial, tilt).

        Q n along the line of the groove centres (n = s/|s|, outward), and its moment about the ball
        centre through the outer groove centre's arm (RacewayOffset).
        """
        _, s, a = self._geometry(q, offset)
        load = self.k_n * self._approach(s, a) ** POINT_EXPONENT
        n = s / a[..., None]
        arm_r, arm_z = self.outer_arm[..., 0], self.outer_arm[..., 1]
        moment = load * (n[..., 1] * arm_r - n[..., 0] * arm_z)
        return np.stack([load * n[..., 0], load * n[..., 1], moment], axis=-1)

    def _approach(self, s, a):
        """Contact approach δ ≥ 0; zero where a one-sided groove would be loaded on its relieved side."""
        delta = np.maximum(a - self.a0, 0.0)
        return np.where(self.side * s[..., 1] < 0.0, 0.0, delta)

    def response(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowResponse:
        """Generalised force, Jacobian and energy for displacements q (C, 5) (raceway offset optional)."""
        _, s, a = self._geometry(q, offset)
        delta = self._approach(s, a)
        root = np.sqrt(delta)
        load = self.k_n * delta * root  # K δ^1.5
        stiff = 1.5 * self.k_n * root  # dQ/dδ
        n = s / a[..., None]
        f_local = -load[..., None] * n  # on the inner ring, towards the outer groove centre
        # d f_local / d u = −[Q' n nᵀ + (Q/A)(I − n nᵀ)]
        nn = n[..., :, None] * n[..., None, :]
        eye = np.eye(2)
        k_local = -(stiff[..., None, None] * nn + (load / a)[..., None, None] * (eye - nn))
        c = q.shape[0]
        if self.Bf.shape[0] == 1:
            force = f_local.reshape(c, -1) @ self.Bf[0]
            jac = (k_local.reshape(c, -1) @ self.BB[0]).reshape(c, 5, 5)
        else:
            force = np.einsum("czi,czij->cj", f_local.reshape(c, -1, 1)[..., 0].reshape(c, -1, 2), self.B)
            jac = np.einsum("cm,cmk->ck", k_local.reshape(c, -1), self.BB).reshape(c, 5, 5)
        energy = (self.k_n * delta * delta * root / 2.5).sum(axis=-1)
        return RowResponse(force, jac, energy)

    def state(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowState:
        """Per-ball results at displacements q (C, 5): loads, operating contact angles, pressures."""
        from bearingkit.physics.contact import hertz

        row = self.row
        _, s, a = self._geometry(q, offset)
        delta = self._approach(s, a)
        load = self.k_n * delta**POINT_EXPONENT
        alpha = np.arctan2(s[..., 1], s[..., 0])
        d, dm, f_i, f_o = (self.geometry[:, k : k + 1] for k in range(4))
        extras, p_max = {}, np.zeros_like(load)
        # The curvatures depend on cos α only; a thrust contact leaning past 90° uses |cos α|.
        alpha_geo = np.arccos(np.clip(np.abs(np.cos(alpha)), 0.0, 1.0))
        for side, f in (("inner", f_i), ("outer", f_o)):
            sr, fr = hertz.ball_raceway_curvature(d, dm, alpha_geo, f * d, side)
            contact = hertz.point_contact(load, sr, fr, self.e_reduced, method=row.hertz_method)
            extras[f"semi_major_{side}"] = contact.semi_major
            extras[f"semi_minor_{side}"] = contact.semi_minor
            extras[f"max_pressure_{side}"] = contact.max_pressure
            p_max = np.maximum(p_max, contact.max_pressure)
        psi = np.broadcast_to(self.psi, load.shape)
        return RowState("ball", row.name, psi, load, delta, alpha, p_max, None, extras)
