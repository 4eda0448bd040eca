"""Threaded rows: the planetary thread roller bearing (PTRB) as equivalent-ball contact pairs.

SI units (m, N, Pa, rad). Geometry after Zheng et al. (2022), Table 1 and §2: Z threaded rollers on
the pitch diameter D_pw, each with n annular (zero-lead) teeth of pitch P. Every tooth touches the
inner ring (ITP) and the outer ring (OTP); with its contact normals through the roller axis a tooth
flank pair acts as an *equivalent ball* of diameter D_w = d_R / cos α (Zheng et al. 2021). A tooth
has two such balls, one per flank direction (contact angles +α and −α): an axial load loads one of
them on every tooth (n balls per roller), a radial load both (2n balls per roller).

This module holds

* :class:`PTRBGeometry` — the Table 1 data, validated;
* :func:`contact_pairs` — ITP and OTP curvatures, Hertz ellipse, approach, pressure and stiffness;
* :class:`ThreadedRow` — a row kernel for :mod:`bearingkit.analysis.quasistatic`: rigid rollers and
  rings, every equivalent ball a Hertz contact Q = K δ^1.5 along its fixed normal (affine approach
  δ = G q − c, like the cylindrical row); it gives the radial distribution over the rollers and the
  response to any combined load, with equal tooth shares (f_a,i = 1);
* :func:`axial_tooth_distribution` — the axial share of the teeth of one roller from Hertz contact,
  tooth bending/shear and axial compression of roller and rings (a thread-connection model in the
  spirit of Zheng et al. 2020 / Yamamoto), giving f_a,i and f_amax;
* :func:`radial_roller_distribution` — the closed form of the radial share for rigid rings without
  clearance (what the row kernel gives for a pure radial load), giving f_r,i and f_rmax.

References: ``zheng2022``, ``zheng2021``, ``zheng2020``, ``harris2007`` (ch. 6-7), ``stribeck1901``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, NamedTuple

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics.contact import hertz
from bearingkit.physics.life.ptrb_rating import thread_contact_curvature
from bearingkit.rows.base import (
    KernelBase,
    RacewayOffset,
    RowResponse,
    RowState,
    axial_row,
    azimuths,
    radial_row,
    relative_displacement,
)

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
#: Timoshenko shear coefficient of a rectangular tooth section [1] (5/6 → factor 6/5 on shear).
SHEAR_COEFFICIENT = 5.0 / 6.0
#: How the rings are held axially in :func:`axial_tooth_distribution`: the inner ring is pushed at the
#: tooth-0 end; the outer ring is supported at the far end ("opposite", the usual shaft/housing shoulder
#: arrangement: both rings in compression) or at the same end ("same": outer ring in tension).
RING_SUPPORTS = ("opposite", "same")


@dataclass(frozen=True)
class PTRBGeometry:
    """Structural parameters of a planetary thread roller bearing (Zheng et al. 2022, Table 1).

    Parameters
    ----------
    pitch_diameter : float [m]
        D_pw, pitch diameter of the roller set.
    roller_pitch_diameter : float [m]
        d_R, pitch (contact) diameter of a threaded roller.
    roller_contact_radius : float [m]
        R_rr, flank arc radius of the roller thread.
    n_elements : int
        Z, number of threaded rollers.
    n_teeth : int
        n, thread teeth per roller engaged with each ring.
    contact_angle : float [rad]
        α, flank contact angle, in (0, π/2).
    thread_pitch : float [m]
        P, distance between adjacent teeth.
    dedendum, ridge_thickness : float [m]
        h (lever arm of the root check) and s (tooth thickness on the pitch line), s < P.
    bottom_thickness_roller, bottom_thickness_inner, bottom_thickness_outer : float [m]
        B_R, B_I, B_O, root thicknesses of the teeth.
    bore_diameter, outside_diameter, width : float [m]
        d_0, D_0, H_0 of the envelope (the rollers' thread length n·P must fit in H_0).
    contact_radius_inner, contact_radius_outer : float [m]
        r_I, r_O, flank arc radii of the ring threads (concave, > R_rr); ``inf`` = flat flank. Table 1
        leaves them blank; flat flanks reproduce the paper's C_r exactly (validation cases of
        bearingkit.papers.zheng2022).
    inner_pitch_diameter, outer_pitch_diameter : float [m] or None
        d_I, d_O; None = D_pw ∓ d_R.
    youngs_modulus : float [Pa], poisson_ratio : float
        E, ν of rollers and rings (all GCr15 in the paper).
    """

    pitch_diameter: float
    roller_pitch_diameter: float
    roller_contact_radius: float
    n_elements: int
    n_teeth: int
    contact_angle: float
    thread_pitch: float
    dedendum: float
    ridge_thickness: float
    bottom_thickness_roller: float
    bottom_thickness_inner: float
    bottom_thickness_outer: float
    bore_diameter: float
    outside_diameter: float
    width: float
    contact_radius_inner: float = float("inf")
    contact_radius_outer: float = float("inf")
    inner_pitch_diameter: float | None = None
    outer_pitch_diameter: float | None = None
    youngs_modulus: float = 212.0e9
    poisson_ratio: float = 0.29

    def __post_init__(self):
        for f in (
            "pitch_diameter",
            "roller_pitch_diameter",
            "roller_contact_radius",
            "thread_pitch",
            "dedendum",
            "ridge_thickness",
            "bottom_thickness_roller",
            "bottom_thickness_inner",
            "bottom_thickness_outer",
            "bore_diameter",
            "outside_diameter",
            "width",
            "youngs_modulus",
        ):
            checks.positive(f, getattr(self, f), "Pa" if f == "youngs_modulus" else "m")
        checks.integer("n_elements", self.n_elements, low=3)
        checks.integer("n_teeth", self.n_teeth, low=1)
        checks.in_range("contact_angle", self.contact_angle, 0.0, np.pi / 2, "rad", closed=False)
        checks.in_range("poisson_ratio", self.poisson_ratio, 0.0, 0.5, closed=False)
        for f in ("contact_radius_inner", "contact_radius_outer"):
            val = float(getattr(self, f))
            if not (val > float(self.roller_contact_radius)):  # also rejects NaN
                raise InputError(
                    f"{f} ({val:.6g} m) must exceed roller_contact_radius "
                    f"({self.roller_contact_radius:.6g} m): "
                    "the ring flank must conform less than the roller flank (inf = flat flank)"
                )
        if self.ridge_thickness >= self.thread_pitch:
            raise InputError(
                f"ridge_thickness ({self.ridge_thickness:.6g} m) must be less than thread_pitch "
                f"({self.thread_pitch:.6g} m)"
            )
        length = self.n_teeth * self.thread_pitch
        if length > self.width * (1 + 1e-12):
            raise InputError(
                f"n_teeth ({self.n_teeth}) do not fit the roller: n_teeth·thread_pitch ({length:.6g} m) must "
                f"not exceed the width ({self.width:.6g} m)"
            )
        d_i, d_o = self.d_inner, self.d_outer
        checks.greater(
            "pitch_diameter", self.pitch_diameter, "roller_pitch_diameter", self.roller_pitch_diameter, "m"
        )
        checks.greater("inner_pitch_diameter", d_i, "bore_diameter", self.bore_diameter, "m")
        checks.greater("outside_diameter", self.outside_diameter, "outer_pitch_diameter", d_o, "m")
        if not d_i < self.pitch_diameter < d_o:
            raise InputError(
                f"pitch_diameter ({self.pitch_diameter:.6g} m) must lie between inner_pitch_diameter "
                f"({d_i:.6g} m) and outer_pitch_diameter ({d_o:.6g} m)"
            )
        if np.pi * self.pitch_diameter / self.n_elements < self.roller_pitch_diameter:
            raise InputError(
                f"n_elements ({self.n_elements}) rollers of roller_pitch_diameter "
                f"{self.roller_pitch_diameter:.6g} m do not fit on the pitch circle "
                f"(π·D_pw/Z = {np.pi * self.pitch_diameter / self.n_elements:.6g} m)"
            )

    # -- derived quantities (cheap, no physics) ---------------------------------------------------
    @property
    def d_inner(self) -> float:
        """d_I [m] (given, or D_pw − d_R)."""
        if self.inner_pitch_diameter is not None:
            return float(self.inner_pitch_diameter)
        return float(self.pitch_diameter - self.roller_pitch_diameter)

    @property
    def d_outer(self) -> float:
        """d_O [m] (given, or D_pw + d_R)."""
        if self.outer_pitch_diameter is not None:
            return float(self.outer_pitch_diameter)
        return float(self.pitch_diameter + self.roller_pitch_diameter)

    @property
    def element_diameter(self) -> float:
        """Equivalent ball diameter D_w = d_R / cos α [m]."""
        return float(self.roller_pitch_diameter / np.cos(self.contact_angle))

    @property
    def gamma(self) -> float:
        """γ = d_R / D_pw [1]."""
        return float(self.roller_pitch_diameter / self.pitch_diameter)

    @property
    def e_reduced(self) -> float:
        """E′ = E/(1 − ν²) of the steel–steel contacts [Pa]."""
        return float(self.youngs_modulus / (1.0 - self.poisson_ratio**2))

    def replace(self, **changes) -> PTRBGeometry:
        """A copy with fields changed (validated again)."""
        from dataclasses import replace

        return replace(self, **changes)


class ContactPair(NamedTuple):
    """Hertz data of the ITP or OTP contact of one equivalent ball (arrays over the load's shape)."""

    side: str
    curvature_sum: np.ndarray  #: Σρ [1/m]
    curvature_difference: np.ndarray  #: F(ρ) [1]
    stiffness_point: np.ndarray  #: K [N/m^1.5]
    semi_major: np.ndarray  #: a [m]
    semi_minor: np.ndarray  #: b [m]
    deflection: np.ndarray  #: δ [m]
    max_pressure: np.ndarray  #: p_max [Pa]
    ellipticity: np.ndarray  #: κ [1]


def contact_pairs(geometry: PTRBGeometry, load=0.0) -> dict[str, ContactPair]:
    """ITP and OTP contacts of one equivalent ball under a normal load.

    Parameters
    ----------
    geometry : PTRBGeometry
    load : array_like
        Normal contact load Q [N] (the same on ITP and OTP of one tooth).

    Returns
    -------
    dict
        ``{"inner": ContactPair, "outer": ContactPair}``.

    Notes
    -----
    Curvatures from :func:`bearingkit.physics.life.ptrb_rating.thread_contact_curvature`; Hertz solution and
    stiffness K from :mod:`bearingkit.physics.contact.hertz` (exact elliptic integrals).
    """
    g = geometry
    out = {}
    for side, d_x, r_x in (
        ("inner", g.d_inner, g.contact_radius_inner),
        ("outer", g.d_outer, g.contact_radius_outer),
    ):
        s, f, _, _ = thread_contact_curvature(
            g.roller_pitch_diameter, d_x, g.roller_contact_radius, r_x, g.contact_angle, side
        )
        c = hertz.point_contact(load, s, f, g.e_reduced)
        k = hertz.point_stiffness(s, f, g.e_reduced)
        out[side] = ContactPair(
            side, s, f, k, c.semi_major, c.semi_minor, c.deflection, c.max_pressure, c.ellipticity
        )
    return out


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
        self.k = _pair_stiffness(g)
        self.start_matrix = self.k * np.einsum("mi,mj->ij", self.G[0], self.G[0])
        self.start_exponent = POINT_EXPONENT
        self.char_length = float(g.pitch_diameter / 2 + n * g.thread_pitch / 2)
        self.deflection_scale = float(g.element_diameter)

    def _delta(self, q, offset: RacewayOffset | None = None):
        q = relative_displacement(q, offset)
        return q @ self.G[0].T + self.delta0

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


# ---------------------------------------------------------------------------------------------
# Radial distribution over the rollers (rigid rings, no clearance)
# ---------------------------------------------------------------------------------------------
def radial_roller_distribution(n_elements, azimuth_phase=0.0):
    """Share of a radial load carried by each roller, rigid rings and zero clearance.

    Parameters
    ----------
    n_elements : int
        Z.
    azimuth_phase : array_like
        Azimuth of roller 0 from the load direction [rad], shape (C,) or scalar.

    Returns
    -------
    f_r : ndarray (C, Z)
        F_r,j / F_r, the radial force of roller j over the bearing's radial load [1].
    f_rmax : ndarray (C,)
        Largest share [1].

    Notes
    -----
    Every equivalent ball of roller j approaches by δ cos α cos ψ_j; Q ∝ δ^1.5, so (Stribeck 1901)

    .. math:: f_{r,j} = \\frac{\\cos^{1.5}\\psi_j}{\\sum_{\\cos\\psi_k > 0}\\cos^{2.5}\\psi_k}

    (f_rmax → 4.37/Z for many rollers with ψ_0 = 0).
    """
    psi = azimuths(checks.integer("n_elements", n_elements, low=1), azimuth_phase)
    c = np.clip(np.cos(psi), 0.0, None)
    share = c**1.5 / (c**2.5).sum(axis=-1, keepdims=True)
    return share, share.max(axis=-1)


# ---------------------------------------------------------------------------------------------
# Axial distribution over the teeth of one roller
# ---------------------------------------------------------------------------------------------
class ToothDistribution(NamedTuple):
    """Axial tooth loads of one roller (leading axis: load cases)."""

    load_inner: np.ndarray  #: (C, n) axial force of the ITP contacts [N]
    load_outer: np.ndarray  #: (C, n) axial force of the OTP contacts [N]
    fa_inner: np.ndarray  #: (C, n) f_Ia,i = ITP axial force / mean [1]
    fa_outer: np.ndarray  #: (C, n) f_Oa,i [1]
    fa_max: np.ndarray  #: (C,) max of f_Ia,i and f_Oa,i [1]
    converged: np.ndarray  #: (C,) bool
    iterations: int


def tooth_compliance(geometry: PTRBGeometry, part: str):
    """Axial compliance of one thread tooth under one contact load [m/N] (cantilever, bending + shear).

    Parameters
    ----------
    geometry : PTRBGeometry
    part : {"roller", "inner", "outer"}

    Notes
    -----
    A tooth is a cantilever of length h (dedendum), root thickness B_X and width w loaded axially at
    its tip (Timoshenko beam):

    .. math:: c = \\frac{4h^3}{E w B_X^3} + \\frac{h}{\\kappa G w B_X},\\qquad G = \\frac{E}{2(1+\\nu)}

    w = π d_X / Z for a ring tooth (Z contacts share it), π d_R / 2 for a roller tooth (one ITP and one
    OTP contact). An assumption of bearingkit (Zheng et al. 2020 use a thread-tooth model after
    Yamamoto, not printed); the teeth are short (h ≪ B), so this term is small beside Hertz.
    """
    g = geometry
    e, nu, h = g.youngs_modulus, g.poisson_ratio, g.dedendum
    width = {
        "roller": np.pi * g.roller_pitch_diameter / 2.0,
        "inner": np.pi * g.d_inner / g.n_elements,
        "outer": np.pi * g.d_outer / g.n_elements,
    }
    thick = {
        "roller": g.bottom_thickness_roller,
        "inner": g.bottom_thickness_inner,
        "outer": g.bottom_thickness_outer,
    }
    checks.one_of("part", part, width)
    w, b = width[part], thick[part]
    shear_mod = e / (2.0 * (1.0 + nu))
    return 4.0 * h**3 / (e * w * b**3) + h / (SHEAR_COEFFICIENT * shear_mod * w * b)


def _body_compliances(g: PTRBGeometry):
    """Axial compliance of one pitch of roller, inner and outer ring, per roller [m/N]."""
    e, h, p = g.youngs_modulus, g.dedendum, g.thread_pitch
    area_r = np.pi / 4.0 * (g.roller_pitch_diameter - 2 * h) ** 2
    area_i = np.pi / 4.0 * ((g.d_inner - 2 * h) ** 2 - g.bore_diameter**2)
    area_o = np.pi / 4.0 * (g.outside_diameter**2 - (g.d_outer + 2 * h) ** 2)
    if area_i <= 0 or area_o <= 0:
        raise InputError(
            "the ring sections (bore to thread root, thread root to outside) must have positive area"
        )
    # a ring section carries the teeth loads of all Z rollers
    return p / (e * area_r), g.n_elements * p / (e * area_i), g.n_elements * p / (e * area_o)


def axial_tooth_distribution(
    geometry: PTRBGeometry, load_axial, ring_support: str = "opposite", max_iter: int = 60, tol: float = 1e-10
) -> ToothDistribution:
    """Axial load shares of the n teeth of a roller under a centric axial load.

    Parameters
    ----------
    geometry : PTRBGeometry
    load_axial : array_like
        Bearing axial load F_a [N], > 0, shape (C,) or scalar; each roller carries F_a / Z.
    ring_support : {"opposite", "same"}
        Where the outer ring is held (:data:`RING_SUPPORTS`); the inner ring is loaded at the tooth-0 end.
    max_iter : int
        Newton iterations.
    tol : float
        Convergence on the relative Newton step of y = F^(1/3) [1].

    Returns
    -------
    ToothDistribution

    Notes
    -----
    Unknowns: ITP and OTP axial forces F_I,i, F_O,i, the roller displacement w_0 and the inner-ring
    displacement U. Compatibility at tooth i (axial approaches):

    .. math::
        g_I(F_{I,i}) = u_{I,i} - w_i,\\qquad g_O(F_{O,i}) = w_i - u_{O,i},\\qquad
        \\sum_i F_{I,i} = \\sum_i F_{O,i} = F_a/Z

    with g(F) = (F/(K\\sin\\alpha))^{2/3}/\\sin\\alpha + (c_{tooth,R} + c_{tooth,X}) F (Hertz approach
    projected on the axis, tooth bending/shear), u_I,i = U − λ_I Σ_j min(i, j) F_I,j,
    u_O,i = λ_O Σ_j min(e_i, e_j) F_O,j (e_i pitches from the outer-ring support) and
    w_i = w_0 − λ_R Σ_j max(i − j, 0)(F_I,j − F_O,j) (axial compression of ring and roller cores, λ = P/(EA)).
    Solved by Newton's method in y = F^{1/3} (smooth at small loads), batched over the load cases.
    Follows the thread-connection approach of Zheng et al. (2020) (doi:10.1155/2020/9593051).
    """
    g = geometry
    checks.one_of("ring_support", ring_support, RING_SUPPORTS)
    fa = np.atleast_1d(np.asarray(checks.positive("load_axial", load_axial, "N"), dtype=float))
    n, sa = g.n_teeth, np.sin(g.contact_angle)
    pairs = contact_pairs(g)
    coef = {}
    for side in ("inner", "outer"):
        a_h = (1.0 / (pairs[side].stiffness_point * sa)) ** (2.0 / 3.0) / sa
        coef[side] = (float(a_h), float(tooth_compliance(g, "roller") + tooth_compliance(g, side)))
    lam_r, lam_i, lam_o = _body_compliances(g)
    idx = np.arange(n)
    dist_i = idx
    dist_o = (n - 1 - idx) if ring_support == "opposite" else idx
    a_i = lam_i * np.minimum.outer(dist_i, dist_i)
    a_o = lam_o * np.minimum.outer(dist_o, dist_o)
    t = lam_r * np.maximum(idx[:, None] - idx[None, :], 0)
    f_roller = fa / g.n_elements  # (C,)
    c = fa.size
    y = np.repeat((f_roller / n)[:, None] ** (1.0 / 3.0), 2 * n, axis=1)  # (C, 2n)
    (ai, ci), (ao, co) = coef["inner"], coef["outer"]
    w0 = ao * y[:, 0] ** 2 + co * y[:, 0] ** 3
    u = w0 + ai * y[:, 0] ** 2 + ci * y[:, 0] ** 3
    converged = np.zeros(c, dtype=bool)
    iterations = 0
    for it in range(1, max_iter + 1):
        iterations = it
        yi, yo = y[:, :n], y[:, n:]
        fi, fo = yi**3, yo**3
        w = w0[:, None] - (fi - fo) @ t.T
        r = np.concatenate(
            [
                ai * yi**2 + ci * fi - (u[:, None] - fi @ a_i.T - w),
                ao * yo**2 + co * fo - (w - fo @ a_o.T),
                (fi.sum(axis=1) - f_roller)[:, None] * (ai / f_roller[:, None] ** (1 / 3)),
                (fo.sum(axis=1) - f_roller)[:, None] * (ai / f_roller[:, None] ** (1 / 3)),
            ],
            axis=1,
        )
        di, do = 3 * yi**2, 3 * yo**2
        jac = np.zeros((c, 2 * n + 2, 2 * n + 2))
        jac[:, :n, :n] = (a_i - t)[None] * di[:, None, :] + np.einsum(
            "ci,ij->cij", 2 * ai * yi + ci * di, np.eye(n)
        )
        jac[:, :n, n : 2 * n] = t[None] * do[:, None, :]
        jac[:, :n, 2 * n] = 1.0
        jac[:, :n, 2 * n + 1] = -1.0
        jac[:, n : 2 * n, :n] = t[None] * di[:, None, :]
        jac[:, n : 2 * n, n : 2 * n] = (a_o - t)[None] * do[:, None, :] + np.einsum(
            "ci,ij->cij", 2 * ao * yo + co * do, np.eye(n)
        )
        jac[:, n : 2 * n, 2 * n] = -1.0
        scale = ai / f_roller ** (1 / 3)
        jac[:, 2 * n, :n] = di * scale[:, None]
        jac[:, 2 * n + 1, n : 2 * n] = do * scale[:, None]
        step = np.linalg.solve(jac, -r[..., None])[..., 0]
        dy = step[:, : 2 * n]
        y = np.maximum(y + dy, 0.2 * y)  # damped: loads stay positive
        w0 = w0 + step[:, 2 * n]
        u = u + step[:, 2 * n + 1]
        converged = np.max(np.abs(dy) / y, axis=1) < tol
        if converged.all():
            break
    fi, fo = y[:, :n] ** 3, y[:, n:] ** 3
    mean = (f_roller / n)[:, None]
    fai, fao = fi / mean, fo / mean
    return ToothDistribution(
        fi, fo, fai, fao, np.maximum(fai.max(axis=1), fao.max(axis=1)), converged, iterations
    )
