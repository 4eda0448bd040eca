"""Self-aligning rows: spherical roller and self-aligning ball rows on a spherical outer raceway.

SI units. The outer raceway is a sphere of radius R_o = d_m/(2 cos α) + D_w/2 centred at the bearing
centre O, the origin of the bearing frame. An element of a row with contact angle α sits on the line
from O through the inner-raceway profile centre P_j (a point of the inner ring): in equilibrium, with
no force on the element but its two contacts, both contact normals lie on that line (the outer one
passes through O because the raceway is a sphere, the inner one through P_j because the inner raceway
profile is a circle about P_j), so the element's load acts along n_j = (P_j − O)/|P_j − O| and the
total approach of its two contacts is

    δ_j = |P_j − O| − L₀,     P_j − O = L₀ m_j − c m_j + u     (3-D, in the inner ring's frame)

with m_j = (cos α cos ψ_j, cos α sin ψ_j, sin α), L₀ the distance |P_j − O| at first touch (roller:
R_o + R_i − D_w; ball: R_o + (f_i − 1) D_w), c = (P_d/2) cos α the gap a radial clearance P_d leaves
along the line, and u = (u_x, u_y, u_z) the translation of the inner ring.

**Self-aligning.** The tilts θ_x, θ_y rotate the inner ring about O: that moves every P_j on a sphere
about O and changes no |P_j − O|, exactly (not only to first order). The row therefore carries no
moment at any tilt: its response depends on the translation only, its force passes through O, and the
tilt columns of its stiffness are zero. Loads and displacements are in the inner ring's frame (for a
tilted shaft, the shaft's frame). A lone self-aligning bearing under a moment cannot be in equilibrium:
the solver refuses a moment on a free tilt ("no row can carry"), and a free tilt under no moment stays
where it starts (an unloaded mechanism).

**Spherical roller thrust bearings** (one row, 45° < α ≤ 80°) have the same geometry: the housing
washer's raceway is a sphere centred on the bearing axis, the rollers' load lines meet the axis at its
centre O (the self-aligning point, below the shaft washer), and the shaft washer plays the inner ring,
whose raceway profile is a circle about P_j. Nothing above depends on α ≤ 45°. What the row assumes
there: symmetric barrel rollers with both contacts on one line through O; the makers' rollers are
asymmetric and pushed by the roller/raceway contact forces against a flange of the shaft washer, a
small force (and the slightly different contact angles on the two washers) this line model leaves out.

**Element law.** Each element's two contacts are in series along n_j: δ = δ_o + δ_i with the same load
Q on both. Balls: Hertz point contacts (ball in the groove of conformity f_i; ball in the sphere),
Q = K δ^1.5 with the series K. Barrel rollers: each contact is sliced along the roller profile
(slice k at arc length s_k from the roller middle, width w = l/n_s); the roller profile (radius R_r)
and the raceway profile (R_o outer sphere, R_i inner torus) part by the osculation gap
g_k = s_k²/2 (1/R_r − 1/R_race), so Q_c(δ_c) = Σ_k c_s ⟨δ_c − g_k⟩^(10/9) (one line contact per slice,
c_s = c_l w/l, Kunert or ISO/TS 16281). The split δ_o + δ_i = δ with Q_o(δ_o) = Q_i(δ_i) is solved per
roller (safeguarded Newton); Q(δ), its derivative Q_o′Q_i′/(Q_o′ + Q_i′) and the energy
U = U_o(δ_o) + U_i(δ_i) follow. The outer and inner slice loads differ (different osculations) and
both are kept for ISO/TS 16281.

**Speed hook.** A centrifugal force F_c on each element (outward, radial) enters the element balance
as Q_o = Q_i + F_c cos α_j: :func:`split_approach` already takes that normal force
(``normal_force``); a speed model passes F_c cos α_j per element (C, Z) and adds the work of F_c to the
energy. Its component F_c sin α_j along the raceway profile moves the roller along the sphere, which
this line model does not resolve (the contact stays at the roller middle).

References: Harris & Kotzalas (2007) Rolling Bearing Analysis 5th ed., ch. 1-2 (spherical outer
raceway, osculation), ch. 6-7 (Hertz, slicing); ISO/TS 16281:2008 (slices); Kunert (1961).
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
    azimuths,
    element_offsets,
    steel_e_reduced,
    validate_common,
)

#: Hertz point-contact and line-contact load exponents (Harris & Kotzalas 2007 eq. 6.43; Kunert 1961).
POINT_EXPONENT = 1.5
LINE_EXPONENT = 10.0 / 9.0
#: Largest contact angle of a self-aligning ball row [rad]: ISO radial bearings (α ≤ 45°).
MAX_CONTACT_ANGLE = np.pi / 4
#: Largest contact angle of a spherical roller row [rad]: up to 80° for the single row of a spherical
#: roller thrust bearing (catalogue bearings about 50°: NSK's X = 1.2 = tan α). The geometry (sphere about
#: O, lines through O) holds for any α < 90°; the cap keeps R_o = d_m/(2 cos α) + D_w/2 below 3 d_m, short
#: of the flat washer (α = 90°) where the sphere degenerates to a plane.
MAX_THRUST_CONTACT_ANGLE = np.radians(80.0)
#: Osculation (roller profile radius / raceway profile radius) accepted for barrel rollers [-]: below 1
#: (the roller is more curved than its raceway) and above 0.8 (catalogue designs are 0.96-0.99; a much
#: smaller value is a typing error).
OSCULATION_RANGE = (0.8, 1.0)
#: Split iterations of a roller's two sliced contacts and the tolerance on their load difference
#: relative to the load (round-off level).
SPLIT_ITERATIONS = 80
SPLIT_RTOL = 1e-14


def _common(row):
    validate_common(row)
    alpha = np.asarray(row.contact_angle, dtype=float)
    checks.finite("contact_angle", alpha, "rad")
    limit = row.max_contact_angle
    if np.any(np.abs(alpha) > limit):
        what = "self-aligning ball row" if limit == MAX_CONTACT_ANGLE else "spherical roller row"
        raise checks.InputError(
            f"contact_angle ({np.degrees(np.max(np.abs(alpha))):.6g} deg) must lie within "
            f"±{np.degrees(limit):.6g} deg for a {what}"
        )
    if row.e_reduced is not None:
        checks.positive("e_reduced", row.e_reduced, "Pa")
    if np.ndim(row.element_diameter) or np.ndim(row.pitch_diameter) or np.ndim(row.contact_angle):
        raise checks.InputError(
            "element_diameter, pitch_diameter and contact_angle of a self-aligning row must be scalars "
            "(batch designs as separate rows or cases; clearance may be per case)"
        )


def outer_sphere_radius(element_diameter, pitch_diameter, contact_angle):
    """Radius R_o of the spherical outer raceway [m]: R_o = d_m / (2 cos α) + D_w / 2.

    Parameters
    ----------
    element_diameter : float [m]
        D_w (roller: largest diameter, at the middle).
    pitch_diameter : float [m]
        d_m, diameter of the element centres.
    contact_angle : float [rad]
        α of the row.

    Notes
    -----
    The element centre lies at distance R_o − D_w/2 from the sphere centre along the contact line at α,
    at radius d_m/2 (Harris & Kotzalas 2007 ch. 1, spherical outer raceway).
    """
    return pitch_diameter / (2.0 * np.cos(contact_angle)) + element_diameter / 2.0


@dataclass(frozen=True)
class SphericalRollerRow:
    """One row of symmetric barrel rollers of a spherical roller bearing.

    Parameters
    ----------
    n_elements : int
        Rollers in this row Z.
    element_diameter : float [m]
        Roller diameter at the middle D_w.
    effective_length : float [m]
        Effective contact length l along the roller profile.
    pitch_diameter : float [m]
        Pitch diameter d_m of the roller centres.
    contact_angle : float [rad]
        α of the row, |α| ≤ 45° for a radial (double-row) bearing, 45° < |α| ≤ 80° for the single row of
        a spherical roller thrust bearing (the shaft washer is the "inner ring", the housing washer's
        sphere the outer raceway); its sign is the row's side and axial direction (α > 0: the row lies at
        +z and resists +u_z of the inner ring).
    osculation_outer, osculation_inner : float
        Roller profile radius over raceway profile radius, R_r/R_o and R_r/R_i (0.8 … 1, typically
        0.97-0.99 [from memory]).
    clearance : float [m]
        Diametral radial internal clearance P_d (negative = preload).
    n_slices : int
        Slices per contact (odd keeps a slice at the roller middle).
    line_law : str
        ``"kunert"`` or ``"iso16281"`` (one contact per slice).
    azimuth_phase : float [rad]
    e_reduced : float [Pa] or None
    name : str
    """

    kind: ClassVar[str] = "spherical_roller"
    #: |α| allowed: the radial bearings' rows (≤ 45°, capped by their builder) and the thrust bearing's row.
    max_contact_angle: ClassVar[float] = MAX_THRUST_CONTACT_ANGLE

    n_elements: int
    element_diameter: float
    effective_length: float
    pitch_diameter: float
    contact_angle: float
    osculation_outer: float = 0.98
    osculation_inner: float = 0.98
    clearance: float = 0.0
    n_slices: int = 15
    line_law: str = "kunert"
    azimuth_phase: float = 0.0
    e_reduced: float | None = None
    name: str = "rollers"

    def __post_init__(self):
        _common(self)
        checks.positive("effective_length", self.effective_length, "m")
        checks.integer("n_slices", self.n_slices, low=1)
        from bearingkit.physics.contact.line import LINE_LAWS

        checks.one_of("line_law", self.line_law, LINE_LAWS)
        lo, hi = OSCULATION_RANGE
        for f in ("osculation_outer", "osculation_inner"):
            v = getattr(self, f)
            checks.finite(f, v)
            if not lo < v < hi:
                raise checks.InputError(
                    f"{f} ({v:.6g}) must lie in ({lo:g}, {hi:g}): the barrel roller's profile radius must be "
                    "smaller than the raceway's (osculation ≥ 1 would load the roller ends)"
                )
        r_r, half = self.profile_radius, self.effective_length / 2
        if half >= r_r or self.end_diameter <= 0:
            raise checks.InputError(
                f"effective_length ({self.effective_length:.6g} m) does not fit the roller profile: a "
                f"barrel of diameter {self.element_diameter:.6g} m and profile radius {r_r:.6g} m has no end "
                "diameter left; shorten the roller or raise the osculation"
            )
        alpha = abs(self.contact_angle)
        if alpha > 0:
            inner_end = (
                abs(self.axial_position) - half * np.cos(alpha) - self.end_diameter / 2 * np.sin(alpha)
            )
            if inner_end <= 0:
                raise checks.InputError(
                    f"effective_length ({self.effective_length:.6g} m): the rollers of this row reach past "
                    f"the bearing centre plane by {-inner_end * 1e3:.3g} mm, where the other row runs; "
                    "shorten the rollers or raise contact_angle"
                )

    @property
    def outer_radius(self) -> float:
        """Outer raceway sphere radius R_o [m]."""
        return float(outer_sphere_radius(self.element_diameter, self.pitch_diameter, self.contact_angle))

    @property
    def profile_radius(self) -> float:
        """Roller profile radius R_r = osculation_outer · R_o [m]."""
        return self.osculation_outer * self.outer_radius

    @property
    def inner_profile_radius(self) -> float:
        """Inner raceway profile radius R_i = R_r / osculation_inner [m]."""
        return self.profile_radius / self.osculation_inner

    @property
    def end_diameter(self) -> float:
        """Roller diameter at the ends of the effective length [m] (the barrel's profile)."""
        r_r, half = self.profile_radius, self.effective_length / 2
        return float(self.element_diameter - 2.0 * (r_r - np.sqrt(max(r_r**2 - half**2, 0.0))))

    @property
    def axial_position(self) -> float:
        """Axial position of the roller centres [m]: (R_o − D_w/2) sin α."""
        return float((self.outer_radius - self.element_diameter / 2) * np.sin(self.contact_angle))

    @property
    def touch_distance(self) -> float:
        """L₀ = R_o + R_i − D_w: distance from O to the inner profile centre at first touch [m]."""
        return self.outer_radius + self.inner_profile_radius - self.element_diameter

    def envelope(self) -> tuple[float, float, float, float]:
        """Space the rollers sweep: (r_min, r_max, z_min, z_max) [m]."""
        r, d, z = self.pitch_diameter / 2, self.element_diameter, self.axial_position
        half = max(d, self.effective_length) / 2
        return (r - half, r + half, z - half, z + half)

    def kernel(self) -> SelfAligningKernel:
        """Precompute the arrays the solver needs (done once per solve)."""
        return SelfAligningKernel(self)


@dataclass(frozen=True)
class SelfAligningBallRow:
    """One ball row of a self-aligning ball bearing (grooved inner ring, spherical outer raceway).

    Parameters
    ----------
    n_elements : int
        Balls in this row Z.
    element_diameter : float [m]
        Ball diameter D_w.
    pitch_diameter : float [m]
        Pitch diameter d_m.
    contact_angle : float [rad]
        α of the row, |α| ≤ 45° (self-aligning ball bearings: about 7°-15°); sign as for
        :class:`SphericalRollerRow`.
    conformity_inner : float
        Inner groove radius over ball diameter f_i (> 0.5). The outer "conformity" is R_o/D_w.
    clearance : float [m]
        Diametral radial internal clearance P_d (negative = preload).
    azimuth_phase : float [rad]
    e_reduced : float [Pa] or None
    hertz_method : str
        ``"exact"`` or ``"hamrock_brewe"``.
    name : str
    """

    kind: ClassVar[str] = "self_aligning_ball"
    max_contact_angle: ClassVar[float] = MAX_CONTACT_ANGLE

    n_elements: int
    element_diameter: float
    pitch_diameter: float
    contact_angle: float
    conformity_inner: float = 0.53
    clearance: float = 0.0
    azimuth_phase: float = 0.0
    e_reduced: float | None = None
    hertz_method: str = "exact"
    name: str = "balls"

    def __post_init__(self):
        _common(self)
        checks.finite("conformity_inner", self.conformity_inner)
        if not self.conformity_inner > 0.5:
            raise checks.InputError(
                f"conformity_inner ({self.conformity_inner:.6g}) must exceed 0.5: the groove radius must "
                "exceed half the ball diameter"
            )
        if self.conformity_inner > 10.0:
            raise checks.InputError(f"conformity_inner ({self.conformity_inner:.6g}) must be at most 10")
        from bearingkit.physics.contact.hertz import POINT_METHODS

        checks.one_of("hertz_method", self.hertz_method, POINT_METHODS)
        alpha = abs(self.contact_angle)
        if alpha > 0 and abs(self.axial_position) <= self.element_diameter / 2:
            raise checks.InputError(
                f"contact_angle ({np.degrees(alpha):.6g} deg) is too small for two ball rows: the balls "
                "reach past the bearing centre plane into the other row"
            )

    @property
    def outer_radius(self) -> float:
        """Outer raceway sphere radius R_o [m]."""
        return float(outer_sphere_radius(self.element_diameter, self.pitch_diameter, self.contact_angle))

    @property
    def conformity_outer(self) -> float:
        """R_o / D_w: the outer raceway seen as a groove [-] (large: a sphere)."""
        return self.outer_radius / self.element_diameter

    @property
    def axial_position(self) -> float:
        """Axial position of the ball centres [m]: (R_o − D_w/2) sin α."""
        return float((self.outer_radius - self.element_diameter / 2) * np.sin(self.contact_angle))

    @property
    def touch_distance(self) -> float:
        """L₀ = R_o + (f_i − 1) D_w: distance from O to the inner groove centre at first touch [m]."""
        return self.outer_radius + (self.conformity_inner - 1.0) * self.element_diameter

    def envelope(self) -> tuple[float, float, float, float]:
        """Space the balls sweep: (r_min, r_max, z_min, z_max) [m]."""
        r, d, z = self.pitch_diameter / 2, self.element_diameter, self.axial_position
        return (r - d / 2, r + d / 2, z - d / 2, z + d / 2)

    def kernel(self) -> SelfAligningKernel:
        """Precompute the arrays the solver needs (done once per solve)."""
        return SelfAligningKernel(self)


# ---------------------------------------------------------------------------------------------
# Element laws: load, stiffness and energy of an element's two contacts in series.
# ---------------------------------------------------------------------------------------------
def sliced_load(approach, gaps, slice_stiffness):
    """Load, its derivative and energy of one sliced contact: Q(δ) = Σ_k c_s ⟨δ − g_k⟩^(10/9).

    Parameters
    ----------
    approach : ndarray (...,) [m]
        Contact approach δ at the roller middle.
    gaps : ndarray (n_s,) [m]
        Profile gap g_k of each slice (osculation), ≥ 0.
    slice_stiffness : float [N/m^(10/9)]
        c_s of one slice.

    Returns
    -------
    load, stiffness, energy, slice_loads : ndarrays (...,), (...,), (...,), (..., n_s)
        Q [N], dQ/dδ [N/m], U = ∫Q dδ [J], per-slice loads [N].
    """
    d = np.maximum(approach[..., None] - gaps, 0.0)
    t = np.cbrt(np.cbrt(d))  # d^(1/9)
    q = slice_stiffness * d * t
    return q.sum(-1), (LINE_EXPONENT * slice_stiffness * t).sum(-1), (q * d).sum(-1) / (1 + LINE_EXPONENT), q


def split_approach(total, outer, inner, normal_force=None):
    """Split a total approach between two contacts in series: Q_o(δ_o) = Q_i(δ − δ_o) + F_n.

    Parameters
    ----------
    total : ndarray (...,) [m]
        δ = δ_o + δ_i, the element's total approach (≤ 0: both contacts open).
    outer, inner : callable
        ``law(approach) -> (load, stiffness, energy, slice_loads)`` of each contact.
    normal_force : ndarray (...,) [N] or None
        Force on the element along its load line towards the outer raceway (the speed hook: centrifugal
        force F_c cos α); None = 0.

    Returns
    -------
    ndarray (...,) [m]
        δ_o (safeguarded Newton in [0, δ]; the load difference is monotone in δ_o).
    """
    f_n = 0.0 if normal_force is None else normal_force
    t = np.maximum(total, 0.0)
    lo, hi = np.zeros_like(t), t.copy()
    y = 0.5 * t
    for _ in range(SPLIT_ITERATIONS):
        q_o, k_o = outer(y)[:2]
        q_i, k_i = inner(t - y)[:2]
        h = q_o - q_i - f_n  # increasing in δ_o
        done = np.abs(h) <= SPLIT_RTOL * np.maximum(np.maximum(q_o, q_i), 1e-300)
        if done.all():
            break
        lo = np.where(h < 0, y, lo)
        hi = np.where(h > 0, y, hi)
        slope = k_o + k_i
        newton = y - h / np.where(slope > 0, slope, np.inf)
        inside = (newton > lo) & (newton < hi) & (slope > 0)
        y = np.where(done, y, np.where(inside, newton, 0.5 * (lo + hi)))
    return y


def _moved(offset) -> bool:
    """Whether a structure's offsets (axial or tilt given) move the raceway, as opposed to the
    radial-only offsets of fits."""
    return offset is not None and (offset.axial is not None or offset.tilt is not None)


class SelfAligningKernel(KernelBase):
    """Element lines through the sphere centre of a :class:`SphericalRollerRow` or
    :class:`SelfAligningBallRow`: response from the inner ring's translation only."""

    _case_arrays = ("gap",)

    def __init__(self, row):
        from bearingkit.physics.contact import hertz, line

        self.row = row
        self.roller = row.kind == "spherical_roller"
        self.e_reduced = float(row.e_reduced) if row.e_reduced is not None else steel_e_reduced()
        alpha, d, dm = float(row.contact_angle), float(row.element_diameter), float(row.pitch_diameter)
        self.psi = azimuths(row.n_elements, row.azimuth_phase)[0]  # (Z,)
        self.m_rz = (np.cos(alpha), np.sin(alpha))  # the unloaded line in each element's (r, z) plane
        self.m = np.stack(
            [
                np.cos(alpha) * np.cos(self.psi),
                np.cos(alpha) * np.sin(self.psi),
                np.full_like(self.psi, np.sin(alpha)),
            ],
            axis=-1,
        )  # (Z, 3) unit lines from O through the elements
        self.touch = float(row.touch_distance)
        self.gap = np.asarray(row.clearance, dtype=float).reshape(-1, 1) / 2.0 * np.cos(alpha)  # (C|1, 1)
        if self.roller:
            length, n_s = float(row.effective_length), row.n_slices
            s, width = line.slice_grid(length, n_s)
            self.s = np.asarray(s, dtype=float).reshape(n_s)
            self.width = float(width)
            r_r = row.profile_radius
            self.gaps = {
                "outer": 0.5 * self.s**2 * (1.0 / r_r - 1.0 / row.outer_radius),
                "inner": 0.5 * self.s**2 * (1.0 / r_r - 1.0 / row.inner_profile_radius),
            }
            c_l = line.line_stiffness(length, self.e_reduced, law=row.line_law)  # one contact
            self.c_s = float(c_l * self.width / length)
            k_start = float(hertz.series_stiffness(c_l, c_l, exponent=LINE_EXPONENT))
            self.start_exponent = LINE_EXPONENT
        else:
            k = {}
            for side, radius in (("inner", row.conformity_inner * d), ("outer", row.outer_radius)):
                sr, fr = hertz.ball_raceway_curvature(d, dm, abs(alpha), radius, side)
                k[side] = float(hertz.point_stiffness(sr, fr, self.e_reduced, method=row.hertz_method))
            self.k_point = k
            self.k_series = float(hertz.series_stiffness(k["inner"], k["outer"], exponent=POINT_EXPONENT))
            k_start = self.k_series
            self.start_exponent = POINT_EXPONENT
        # What the row pushes on: along its lines, no moment (solver cone checks and starting point).
        self.directions = np.concatenate([self.m, np.zeros((len(self.psi), 2))], axis=-1)[None]  # (1, Z, 5)
        self.reach = self.directions[0]
        self.start_matrix = k_start * self.reach.T @ self.reach
        self.char_length = float(row.outer_radius)
        self.deflection_scale = d

    # -- element law -----------------------------------------------------------------------------
    def _law(self, side):
        return lambda a: sliced_load(a, self.gaps[side], self.c_s)

    def element_law(self, delta):
        """Load Q, dQ/dδ, energy U and the outer/inner approaches of each element for δ (C, Z) [m]."""
        if not self.roller:
            d = np.maximum(delta, 0.0)
            root = np.sqrt(d)
            load = self.k_series * d * root
            d_i = (load / self.k_point["inner"]) ** (1.0 / POINT_EXPONENT)
            return load, 1.5 * self.k_series * root, load * d / 2.5, d - d_i, d_i
        outer, inner = self._law("outer"), self._law("inner")
        d_o = split_approach(delta, outer, inner)
        d_i = np.maximum(delta, 0.0) - d_o
        q_o, k_o, u_o, _ = outer(d_o)
        _, k_i, u_i, _ = inner(d_i)
        total = k_o + k_i
        stiff = np.where(total > 0, k_o * k_i / np.where(total > 0, total, 1.0), 0.0)
        return q_o, stiff, u_o + u_i, d_o, d_i

    # -- solver interface ------------------------------------------------------------------------
    def _lines(self, q, offset: RacewayOffset | None):
        """Unit load lines n (C, Z, 2) in each element's (r, z) plane, approaches δ (C, Z), lengths (C, Z).

        The element stays in its azimuth plane (as every row of the engine): the inner ring's translation
        enters through its radial and axial components at the element, u_r = u_x cos ψ + u_y sin ψ and u_z;
        the tilts do not enter at all (rotation about the sphere centre).
        """
        u = q if offset is None or offset.shift is None else q - offset.shift
        u_r = u[:, :1] * np.cos(self.psi) + u[:, 1:2] * np.sin(self.psi)  # (C, Z)
        reach = (self.touch - self.gap) * np.ones_like(u_r)
        u_z = u[:, 2:3] + np.zeros_like(u_r)
        if _moved(offset):  # a structure moved the raceway: the relative motion, exactly
            radial, axial, _ = element_offsets(offset, u_r.shape)  # a sphere takes no tilt about O
            u_r, u_z = u_r - radial, u_z - axial
        elif offset is not None and offset.radial is not None:
            # radial-only offsets (fits, as before structures existed): the opening along the line
            reach = reach - offset.radial * np.cos(float(self.row.contact_angle))
        v = np.stack([reach * self.m_rz[0] + u_r, reach * self.m_rz[1] + u_z], axis=-1)
        length = np.sqrt(v[..., 0] ** 2 + v[..., 1] ** 2)
        return v / length[..., None], length - self.touch, length

    def raceway_loads(self, q: np.ndarray, offset: RacewayOffset | None = None) -> np.ndarray:
        """Loads (F_r, F_z, 0) (C, Z, 3) each element puts on the outer raceway, −∂U/∂(radial, axial, tilt):
        Q n along its line (the spherical raceway takes no tilt). With radial-only offsets (fits) the
        opening acts along the unloaded line m, and −∂U/∂radial is Q (n·m) m_r."""
        n, delta, _ = self._lines(q, offset)
        load = self.element_law(delta)[0]
        zero = np.zeros_like(load)
        if offset is not None and offset.radial is not None and not _moved(offset):
            along = load * (n[..., 0] * self.m_rz[0] + n[..., 1] * self.m_rz[1])
            return np.stack([along * self.m_rz[0], zero, zero], axis=-1)
        return np.stack([load * n[..., 0], load * n[..., 1], zero], axis=-1)

    def response(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowResponse:
        """Force (through O: no moment), Jacobian (zero tilt columns) and energy for q (C, 5)."""
        n, delta, length = self._lines(q, offset)
        load, stiff, energy, _, _ = self.element_law(delta)
        c = q.shape[0]
        cos, sin = np.cos(self.psi), np.sin(self.psi)
        force = np.zeros((c, 5))
        f_r = -load * n[..., 0]
        force[:, 0], force[:, 1] = f_r @ cos, f_r @ sin
        force[:, 2] = -(load * n[..., 1]).sum(axis=-1)
        # In-plane stiffness k = Q′ n nᵀ + (Q/L)(I − n nᵀ), mapped by u_r = (cos ψ, sin ψ, 0)·u, u_z.
        geo = load / length
        nn = n[..., :, None] * n[..., None, :]
        k2 = stiff[..., None, None] * nn + geo[..., None, None] * (np.eye(2) - nn)  # (C, Z, 2, 2)
        b = np.zeros((len(self.psi), 2, 3))
        b[:, 0, 0], b[:, 0, 1], b[:, 1, 2] = cos, sin, 1.0
        jac = np.zeros((c, 5, 5))
        jac[:, :3, :3] = -np.einsum("zai,czab,zbj->cij", b, k2, b)
        return RowResponse(force, jac, energy.sum(axis=-1))

    def state(self, q: np.ndarray, offset: RacewayOffset | None = None) -> RowState:
        """Per-element results: load, operating contact angle, pressures (and slice loads for rollers).

        ``extras`` (rollers): ``slice_load_inner`` (C, Z, n_s) [N] (``slice_load`` is the outer raceway's),
        ``slice_pressure_inner``/``_outer`` [Pa], ``slice_position`` [m] (arc length from the roller middle),
        ``approach_inner``/``_outer`` [m]. Balls: ``semi_major``/``semi_minor``/``max_pressure`` per side.
        """
        from bearingkit.physics.contact import hertz, line

        row = self.row
        n, delta, _ = self._lines(q, offset)
        load, _, _, d_o, d_i = self.element_law(delta)
        alpha = np.arctan2(n[..., 1], n[..., 0])
        d, dm = float(row.element_diameter), float(row.pitch_diameter)
        extras = {"approach_outer": d_o, "approach_inner": d_i}
        psi = np.broadcast_to(self.psi, load.shape)
        if self.roller:
            q_o = sliced_load(d_o, self.gaps["outer"], self.c_s)[3]
            q_i = sliced_load(d_i, self.gaps["inner"], self.c_s)[3]
            gamma = d * np.cos(float(row.contact_angle)) / dm
            r_r = row.profile_radius
            d_k = d - 2.0 * (r_r - np.sqrt(r_r**2 - self.s**2))  # barrel diameter at each slice
            p_max = np.zeros_like(q_o)
            for side, qs, sign in (("inner", q_i, -1.0), ("outer", q_o, 1.0)):
                rx = d_k / 2 * (1 + sign * gamma)
                pressure = np.sqrt(qs) * line.line_pressure_factor(self.width, rx, self.e_reduced)
                extras[f"slice_pressure_{side}"] = pressure
                p_max = np.maximum(p_max, pressure)
            extras["slice_load_inner"] = q_i
            extras["slice_position"] = np.broadcast_to(self.s, q_o.shape)
            return RowState(
                row.kind, row.name, psi, load, np.maximum(delta, 0.0), alpha, p_max.max(-1), q_o, extras
            )
        p_max = np.zeros_like(load)
        alpha_geo = np.clip(np.abs(alpha), 0.0, np.pi / 2)
        for side, radius in (("inner", row.conformity_inner * d), ("outer", row.outer_radius)):
            sr, fr = hertz.ball_raceway_curvature(d, dm, alpha_geo, radius, side)
            contact = hertz.point_contact(load, sr, fr, self.e_reduced, method=row.hertz_method)
            extras[f"semi_major_{side}"] = contact.semi_major
            extras[f"semi_minor_{side}"] = contact.semi_minor
            extras[f"max_pressure_{side}"] = contact.max_pressure
            p_max = np.maximum(p_max, contact.max_pressure)
        return RowState(row.kind, row.name, psi, load, np.maximum(delta, 0.0), alpha, p_max, None, extras)
