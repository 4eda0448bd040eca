"""Tapered roller rows: per-roller equilibrium (cone, cup, rib, centrifugal force), condensed.

SI units (m, N, Pa, rad, rad/s, kg/m³).

Frame and mapping
-----------------
bearingkit's frame (design.md §3): the outer ring (cup) is fixed, the inner ring (cone, with the
large rib) is displaced by q = (u_x, u_y, u_z, θ_x, θ_y). Seed 001 (Liu et al. 2022, eqs. 1–6) fixes
the inner ring and displaces the outer ring by d = (d_x, d_y, d_z) under a load F on the outer
ring. A rigid motion of the whole assembly by −d maps one onto the other: u = −d, the load on the
inner ring is −F, the roller displacements X_seed − d = X here; contact approaches and forces are
unchanged. The seed's 3-DOF model is ``free = [True, True, True, False, False]`` here.

Geometry in the meridian plane of roller j (radial r, axial s = σ (z − z_row), σ = ``direction``)
---------------------------------------------------------------------------------------------
Cup contact normal (roller → cup) n_e = (cos α_e, sin α_e), cone normal (cone → roller)
n_i = (cos α_i, sin α_i), roller axis (towards the bearing apex, small end) a = (−sin κ, cos κ) with
κ = (α_e + α_i)/2 and half roller angle ε = (α_e − α_i)/2. The rib (flange) sits on the cone at
the roller's large end. ``flange_angle`` φ_f is the angle in the meridian plane between the cone
raceway generatrix (towards the apex, t_i) and the rib face; the rib pushes the roller along
n_f = sin φ_f t_i − cos φ_f n_i (φ_f = π/2: along the raceway). The roller centre sits at the
pitch radius, s = 0; its inner and outer contact lines are p_i(x) = c − r_m e + x t_i and
p_e(x) = c + r_m e + x t_e (e = (cos κ, sin κ), r_m the mean roller radius); the rib contact point
is on the large end face at ``flange_contact_height`` e_r above the cone-side edge.

Per roller (X = roller translation in its meridian plane, 2 DOF as seed 001 eq. 5), linear kinematics:

    cone slice k:  δ_ik = n_i·(w(p_ik) − X) − C(x_k) + Δ_j
    cup slice k:   δ_ek = n_e·X − C(x_k) − c/2 + Δ_j
    rib:           δ_f  = n_f·(w(p_f) − X)

w(p) = (u_r − p_s σθ_t … ) is the cone's displacement at p (rows of B, :mod:`bearingkit.rows.base`),
C(x) the crown drop, c the clearance (counted twice) and Δ_j = ½ ΔD_j cos ε the approach added by a
roller diameter deviation ΔD_j (a larger roller moves each generatrix by ½ΔD cos ε along the contact
normal). Slices carry q = c_s δ^(10/9) (c_s = K_a w/l, K_a from :func:`bearingkit.physics.contact.hertz.
line_stiffness`), the rib Q_f = K_f δ_f^1.5 (sphere-on-plane Hertz). With ``deviation_model =
"taylor"`` the slice law is seed 001 eq. (4): q = c_s[δ^(10/9) + (10/9) δ^(1/9) Δ] (δ without Δ),
clipped at 0.

Every approach is affine in (q, X) and each law is the derivative of a convex energy, so the roller
equilibrium is the minimum over X of Φ = Σ E_c(δ_c) − F_c·X (F_c the centrifugal force), solved by a
damped Newton iteration over all rollers and cases at once. The condensed energy U*(q) = min_X Φ
is convex; by the envelope theorem its force is −Σ Q_c ∂δ_c/∂q and its stiffness the Schur complement
K* = K_qq − K_qX K_XX⁻¹ K_Xq (implicit-function theorem). A roller with every contact open (a ring
moved away, a zero load) has Φ ≡ 0 near its position: it keeps its start and contributes exactly
zero force, energy and stiffness.

Tilting a single row
--------------------
Eliminating X leaves each roller one load path: its cone and rib loads sum to a force along −n_e on
a fixed line of its meridian plane, and these lines all meet the bearing axis at the pressure centre
z_P (:attr:`TaperedRow.pressure_centre`). A whole-roller row (``n_slices = 1``, seed 001's law)
therefore has no stiffness against a rotation about z_P: with the tilts free it carries only loads
whose line of action passes through z_P (pure axial; F_x with M_y = z_P F_x …); any other load has
no equilibrium, and the solver reports it as not carriable. Sliced rows shift their cone load
along the rollers (edge loading) and carry moderate moments with a tilt; pairs (DB/DF) carry
moments through the spread of their two pressure centres.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.rows.tapered.geometry import (
    ANGLE_CONSISTENCY_RTOL,
    DEFAULT_END_RADIUS_RATIO,
    DEFAULT_FLANGE_HEIGHT_RATIO,
    DEVIATION_MODELS,
    LINE_EXPONENT,
    MAX_FLANGE_TILT,
    POINT_EXPONENT,
    STEEL_DENSITY,
    TapGeometry,
    _cross2,
)
from bearingkit.rows.tapered.kernel import TaperedKernel


@dataclass(frozen=True)
class TaperedRow:
    """A row of Z tapered rollers between a cup (fixed) and a cone with a large rib (loaded).

    Parameters
    ----------
    n_elements : int
        Number of rollers Z.
    small_diameter, large_diameter : float [m]
        Roller end diameters D_s < D_l.
    effective_length : float [m]
        Roller (contact) length l, measured along the roller axis.
    pitch_diameter : float [m]
        Diameter of the circle through the roller centres (mid-length on the axis).
    contact_angle_outer, contact_angle_inner : float [rad]
        Cup angle α_e and cone angle α_i (contact normals from the radial plane), α_e > α_i.
    flange_angle : float [rad]
        Angle φ_f between the cone raceway generatrix and the rib face (seed 001 Table 1: 1.5621).
    roller_angle : float or None [rad]
        Half roller angle ε; checked against (α_e − α_i)/2 and the diameters when given.
    direction : int
        +1: the row carries +F_z of the inner ring; −1: −F_z (pairs: back-to-back / face-to-face).
    clearance : float [m]
        Clearance along the cup normal, counted twice (each roller sees clearance/2); < 0 preload.
    diameter_deviation : array (Z,) or (C, Z) [m] or None
        Per-roller diameter deviation ΔD_j (a case axis batches realisations).
    deviation_model : str
        ``"exact"`` or ``"taylor"`` (seed 001 eq. 4), see :data:`DEVIATION_MODELS`.
    n_slices : int
        Slices per raceway contact (1 = the seed's whole-roller law).
    profile : Profile or None
        Crown drop of the roller (e.g. ``make_profile("iso16281_tapered", …)``).
    line_law : str
        ``"kunert"`` or ``"iso16281"`` (:data:`bearingkit.physics.contact.line.LINE_LAWS`).
    raceway_stiffness : float or None [N/m^(10/9)]
        K_a of one whole raceway line contact, Q = K_a δ^(10/9), where a source gives it (or it is
        identified); None = from ``line_law`` with E′ and the roller length.
    e_reduced : float or None [Pa]
        E′ (steel–steel from the materials by default).
    flange_contact_height : float or None [m]
        e_r, height of the rib contact above the cone-side edge of the large end.
    end_radius : float or None [m]
        Spherical radius of the roller's large end (rib stiffness K_f).
    speed : float or array (C,) [rad/s]
        Inner-ring speed ω_i (centrifugal force at the pure-rolling cage speed); an array gives each
        load case its own speed (a drivetrain's load spectrum).
    density : float [kg/m³]
        Roller density.
    axial_position, azimuth_phase : float [m], [rad]
    name : str
    """

    kind: ClassVar[str] = "tapered"

    n_elements: int
    small_diameter: float
    large_diameter: float
    effective_length: float
    pitch_diameter: float
    contact_angle_outer: float
    contact_angle_inner: float
    flange_angle: float = np.pi / 2
    roller_angle: float | None = None
    direction: int = 1
    clearance: float = 0.0
    diameter_deviation: object = None
    deviation_model: str = "exact"
    n_slices: int = 1
    profile: object | None = None
    line_law: str = "kunert"
    raceway_stiffness: float | None = None
    e_reduced: float | None = None
    flange_contact_height: float | None = None
    end_radius: float | None = None
    speed: object = 0.0
    density: float = STEEL_DENSITY
    axial_position: float = 0.0
    azimuth_phase: float = 0.0
    name: str = "tapered"

    def __post_init__(self):
        checks.integer("n_elements", self.n_elements, low=3)
        for f in ("small_diameter", "large_diameter", "effective_length", "pitch_diameter"):
            _scalar(f, getattr(self, f))
            checks.positive(f, getattr(self, f), "m")
        checks.greater("large_diameter", self.large_diameter, "small_diameter", self.small_diameter, "m")
        checks.greater("pitch_diameter", self.pitch_diameter, "large_diameter", self.large_diameter, "m")
        _scalar("contact_angle_outer", self.contact_angle_outer)
        _scalar("contact_angle_inner", self.contact_angle_inner)
        checks.in_range("contact_angle_inner", self.contact_angle_inner, 0.0, np.pi / 2, "rad", closed=False)
        checks.in_range("contact_angle_outer", self.contact_angle_outer, 0.0, np.pi / 2, "rad", closed=False)
        checks.greater(
            "contact_angle_outer",
            self.contact_angle_outer,
            "contact_angle_inner",
            self.contact_angle_inner,
            "rad",
        )
        eps = self.half_angle
        tan_d = (self.large_diameter - self.small_diameter) / (2.0 * self.effective_length)
        if abs(np.arctan(tan_d) - eps) > ANGLE_CONSISTENCY_RTOL * eps:
            raise InputError(
                f"large_diameter/small_diameter/effective_length give a half roller angle "
                f"({np.arctan(tan_d):.6g} rad) inconsistent with "
                f"(contact_angle_outer − contact_angle_inner)/2 "
                f"({eps:.6g} rad); the roller must fit the cone and the cup"
            )
        if self.roller_angle is not None:
            _scalar("roller_angle", self.roller_angle)
            checks.positive("roller_angle", self.roller_angle, "rad")
            if abs(self.roller_angle - eps) > ANGLE_CONSISTENCY_RTOL * eps:
                raise InputError(
                    f"roller_angle ({self.roller_angle:.6g} rad) must equal (contact_angle_outer − "
                    f"contact_angle_inner)/2 ({eps:.6g} rad) within {ANGLE_CONSISTENCY_RTOL:.0%}"
                )
        _scalar("flange_angle", self.flange_angle)
        checks.finite("flange_angle", self.flange_angle, "rad")
        tilt = abs(np.pi / 2 + eps - self.flange_angle)  # angle between n_f and the roller axis
        if tilt >= MAX_FLANGE_TILT:
            raise InputError(
                f"flange_angle ({self.flange_angle:.6g} rad) is inconsistent with the cone: the rib force "
                f"would make {tilt:.4g} rad with the roller axis; expected a flange_angle within "
                f"{MAX_FLANGE_TILT:.4g} rad of π/2 + ε = {np.pi / 2 + eps:.6g} rad"
            )
        if self.direction not in (1, -1):
            raise InputError(f"direction ({self.direction!r}) must be +1 or -1")
        checks.finite("clearance", self.clearance, "m")
        checks.one_of("deviation_model", self.deviation_model, DEVIATION_MODELS)
        checks.integer("n_slices", self.n_slices, low=1)
        from bearingkit.physics.contact.line import LINE_LAWS

        checks.one_of("line_law", self.line_law, LINE_LAWS)
        if self.raceway_stiffness is not None:
            _scalar("raceway_stiffness", self.raceway_stiffness)
            checks.positive("raceway_stiffness", self.raceway_stiffness, "N/m^(10/9)")
        if self.e_reduced is not None:
            checks.positive("e_reduced", self.e_reduced, "Pa")
        if self.flange_contact_height is not None:
            checks.in_range(
                "flange_contact_height",
                self.flange_contact_height,
                0.0,
                self.large_diameter,
                "m",
                closed=False,
            )
        if self.end_radius is not None:
            checks.positive("end_radius", self.end_radius, "m")
        checks.finite("speed", self.speed, "rad/s")
        if np.ndim(self.speed) > 1:
            raise InputError(
                f"speed (shape {np.shape(self.speed)}) must be one value [rad/s] or one per load case "
                "(n_cases,)"
            )
        checks.positive("density", self.density, "kg/m^3")
        checks.finite("axial_position", self.axial_position, "m")
        checks.finite("azimuth_phase", self.azimuth_phase, "rad")
        gap = np.pi * self.pitch_diameter / self.n_elements - self.large_diameter * np.cos(
            self.cone_axis_angle
        )
        if gap < 0:
            raise InputError(
                f"n_elements ({self.n_elements}) do not fit on the pitch circle: π·pitch_diameter/Z "
                f"({np.pi * self.pitch_diameter / self.n_elements:.6g} m) is below the large roller diameter"
            )
        if self.diameter_deviation is not None:
            dev = np.asarray(self.diameter_deviation, dtype=float)
            if dev.ndim not in (1, 2) or dev.shape[-1] != self.n_elements:
                raise InputError(
                    f"diameter_deviation (shape {dev.shape}) must have shape (n_elements,) = "
                    f"({self.n_elements},) or (n_cases, {self.n_elements})"
                )
            checks.finite("diameter_deviation", dev, "m")
            if np.any(np.abs(dev) >= 0.05 * self.small_diameter):
                raise InputError(
                    f"diameter_deviation (max |ΔD| {np.max(np.abs(dev)):.6g} m) must stay below 5 % of the "
                    f"small_diameter ({self.small_diameter:.6g} m): a deviation, not another roller"
                )

    # -- derived geometry ------------------------------------------------------------------------
    @property
    def half_angle(self) -> float:
        """ε = (α_e − α_i)/2 [rad]."""
        return 0.5 * (float(self.contact_angle_outer) - float(self.contact_angle_inner))

    @property
    def cone_axis_angle(self) -> float:
        """κ = (α_e + α_i)/2, angle between the roller axis and the bearing axis [rad]."""
        return 0.5 * (float(self.contact_angle_outer) + float(self.contact_angle_inner))

    @property
    def element_diameter(self) -> float:
        """Mean roller diameter D_m = (D_s + D_l)/2 [m]."""
        return 0.5 * (float(self.small_diameter) + float(self.large_diameter))

    @property
    def pressure_centre(self) -> float:
        """Axial position z_P of the row's pressure centre on the bearing axis [m].

        With the cone load at mid-length, each roller's cone and rib loads add up on the inner ring
        to one force along −n_e (the roller's balance) on a fixed line of its meridian plane; by
        axisymmetry every such line meets the bearing axis at z_P (the effective load centre of
        catalogues; e.g. Harris & Kotzalas 2006, Rolling Bearing Analysis, 5th ed.). A
        whole-roller row (``n_slices = 1``) transmits no moment about z_P: with free tilts it carries
        only loads whose line of action passes through it (M_x = −z_P F_y, M_y = z_P F_x). Sliced rows
        can move the load along the rollers and carry a limited moment by tilting.
        """
        geo = TapGeometry(self)
        qi, qf = np.linalg.solve(np.stack([geo.n_i, geo.n_f], axis=1), geo.n_e)
        p_i = geo.centre - geo.r_m * geo.e
        moment = qi * _cross2(p_i, geo.n_i) + qf * _cross2(geo.p_f, geo.n_f)
        return float(self.axial_position) - float(self.direction) * moment / geo.n_e[0]

    @property
    def n_cases(self) -> int:
        """Cases carried by ``diameter_deviation`` (1 without a case axis)."""
        dev = self.diameter_deviation
        return 1 if dev is None or np.ndim(dev) < 2 else int(np.shape(dev)[0])

    def kernel(self) -> TaperedKernel:
        """Precompute the arrays the solver needs (done once per model)."""
        return TaperedKernel(self)


def _scalar(field, value):
    if np.ndim(value) != 0:
        raise InputError(f"{field} (shape {np.shape(value)}) must be a scalar for a tapered row")


__all__ = [
    "ANGLE_CONSISTENCY_RTOL",
    "DEFAULT_END_RADIUS_RATIO",
    "DEFAULT_FLANGE_HEIGHT_RATIO",
    "DEVIATION_MODELS",
    "LINE_EXPONENT",
    "MAX_FLANGE_TILT",
    "POINT_EXPONENT",
    "STEEL_DENSITY",
    "TapGeometry",
    "TaperedRow",
]
