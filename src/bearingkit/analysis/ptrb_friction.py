"""PTRB friction torque assembly (Zheng et al. 2022 §3.3) and the vectorised §6 objectives.

SI units: N, m, rad/s, N·m. ``ptrb_friction`` sums the per-contact torques of
:mod:`bearingkit.physics.friction.ptrb` over the loaded ITP and OTP contacts and adds the carrier term:

* axial load F_a: every roller carries F_a/Z on one flank of each of its n teeth,
  Q_i = f_a,i F_a/(Z n sin α); M_PTRBa = Z Σ_i (M_I,i + M_O,i) + M_h (eq. 14);
* radial load F_r: roller j carries f_r,j F_r (Stribeck share of
  :func:`bearingkit.rows.threaded.radial_roller_distribution`) on both flanks of its n teeth,
  Q_j = f_r,j F_r/(2n cos α); M_PTRBr = 2n Σ_j (M_I,j + M_O,j) + M_h (eq. 15).

``ptrb_objectives`` is the same model as a pure function of design-variable arrays (the population
axis of an optimiser), with the ratings of :mod:`bearingkit.physics.life.ptrb_rating`.

References: ``zheng2022``, ``zheng2021``, plus those of :mod:`bearingkit.physics.friction.ptrb`.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.lubricants import as_lubricant
from bearingkit.physics.friction import ptrb as pf
from bearingkit.physics.life import ptrb_rating as pr
from bearingkit.rows.threaded import PTRBGeometry, axial_tooth_distribution, radial_roller_distribution

__all__ = [
    "CALIBRATION_POINT",
    "CASES",
    "PROTOTYPE_PITCH_DIAMETER",
    "PROTOTYPE_THREAD_LENGTH",
    "TOOTH_DISTRIBUTIONS",
    "PTRBFrictionParameters",
    "PTRBFrictionResult",
    "calibrate_contact_traction",
    "design_geometry",
    "ptrb_friction",
    "ptrb_objectives",
]

REFERENCE_KEYS = (*pf.REFERENCE_KEYS, "iso76", "iso281")
RPM = 2.0 * np.pi / 60.0
#: Load cases of the paper: pure axial or pure radial load.
CASES = ("axial", "radial")
#: Tooth shares under axial load: equal (f_a,i = 1, the default; the paper's f_amax ≈ 1.07 changes M by
#: < 0.5 %) or from the thread-connection model :func:`~bearingkit.rows.threaded.axial_tooth_distribution`.
TOOTH_DISTRIBUTIONS = ("uniform", "model")
#: The ONE published number the contact traction is calibrated against: Zheng et al. (2022) Table 7,
#: axial simulation, 20 kN, 600 rpm → 0.476 N·m.
CALIBRATION_POINT = {"case": "axial", "load_N": 20.0e3, "speed_rpm": 600.0, "torque_Nm": 0.476}
#: D_pw of the prototype, held in the §5 sweeps and §6 optimisation ("the dimension was unchanged") [m].
PROTOTYPE_PITCH_DIAMETER = 42.5e-3
#: n·P of the prototype, held when n changes (§5 (2): n = 8–16 ↔ P = 1.6–0.8 mm) [m].
PROTOTYPE_THREAD_LENGTH = 12.0e-3
#: Temperature of the paper's friction tests (§7.2.2) [°C].
TEST_TEMPERATURE_C = 40.0


@dataclass(frozen=True)
class PTRBFrictionParameters:
    """Friction parameters the paper does not give (defaults: see :mod:`bearingkit.physics.friction.ptrb`).

    Parameters
    ----------
    traction : float [1]
        μ_c of spin and differential sliding (calibrated default).
    hysteresis : float [1]
        β.
    carrier_friction : float [1]
        μ_h of the roller journals in the carrier.
    journal_ratio : float [1]
        Journal diameter / d_R.
    viscous_model : str
        EHL rolling-resistance model, one of :data:`~bearingkit.physics.friction.ptrb.VISCOUS_MODELS`
        (``harris``, the default; ``houpert`` or ``fujiwara``).
    convention : str
        ``paper`` (default: eq. (13)–(15) summed as printed) or ``power`` (power balance)
        (:data:`~bearingkit.physics.friction.ptrb.CONVENTIONS`).
    viscous_projection : str or None
        ``axis`` or ``contact`` (paper convention), ``eq13`` or ``power`` (power convention); None: the
        convention's default (``axis``, ``eq13``)
        (:data:`~bearingkit.physics.friction.ptrb.VISCOUS_PROJECTIONS`).
    viscous_radius_y : str
        R_y of Harris's F_v: ``ball`` (default, D_w/2), ``flank`` or ``rolling``
        (:data:`~bearingkit.physics.friction.ptrb.VISCOUS_RADII_Y`).

    Notes
    -----
    The calibrated ``traction`` belongs to the default reading; :meth:`power_balance` gives the
    power-balance reading with its own calibration (same published value).
    """

    traction: float = pf.CONTACT_TRACTION_CALIBRATED
    hysteresis: float = pf.HYSTERESIS_PTRB
    carrier_friction: float = pf.CARRIER_FRICTION
    journal_ratio: float = pf.JOURNAL_DIAMETER_RATIO
    viscous_model: str = "harris"
    convention: str = "paper"
    viscous_projection: str | None = None
    viscous_radius_y: str = "ball"

    @classmethod
    def power_balance(cls, **changes) -> PTRBFrictionParameters:
        """The power-balance reading (the former default), :data:`~bearingkit.physics.friction.ptrb.
        POWER_BALANCE_OPTIONS` with its calibrated traction; ``changes`` override fields."""
        return cls(**{**pf.POWER_BALANCE_OPTIONS, **changes})

    def __post_init__(self):
        pf.resolve_viscous_projection(self.convention, self.viscous_projection)
        checks.one_of("viscous_radius_y", self.viscous_radius_y, pf.VISCOUS_RADII_Y)
        checks.non_negative("traction", self.traction)
        checks.non_negative("hysteresis", self.hysteresis)
        checks.non_negative("carrier_friction", self.carrier_friction)
        checks.in_range("journal_ratio", self.journal_ratio, 0.0, 1.0, closed=False)
        checks.one_of("viscous_model", self.viscous_model, pf.VISCOUS_MODELS)


@dataclass(frozen=True)
class PTRBFrictionResult:
    """Friction torque of a PTRB (arrays over the broadcast load/speed cases, SI)."""

    case: str
    load: np.ndarray  #: F_a or F_r [N]
    speed: np.ndarray  #: ω [rad/s]
    components: dict  #: {"inner": {component: N·m}, "outer": {...}}, summed over contacts
    carrier: np.ndarray  #: M_h [N·m]
    bore_diameter: float
    references: tuple = field(default=REFERENCE_KEYS)

    @property
    def inner(self) -> np.ndarray:
        """Σ over ITP contacts [N·m]."""
        return sum(self.components["inner"].values())

    @property
    def outer(self) -> np.ndarray:
        """Σ over OTP contacts [N·m]."""
        return sum(self.components["outer"].values())

    @property
    def torque(self) -> np.ndarray:
        """M_PTRBa or M_PTRBr [N·m]."""
        return self.inner + self.outer + self.carrier

    @property
    def friction_coefficient(self) -> np.ndarray:
        """μ_PTRBa or μ_PTRBr = 2M/(d_0 F) [1]."""
        return pf.friction_coefficient(self.torque, self.load, self.bore_diameter)

    def efficiency(self, input_torque) -> np.ndarray:
        """η = 1 − M/(M + M_D) [1] for the input torque M_D [N·m]."""
        return pf.efficiency(self.torque, input_torque)

    def by_component(self) -> dict:
        """{component: ITP + OTP torque [N·m]} plus ``carrier``."""
        out = {k: self.components["inner"][k] + self.components["outer"][k] for k in pf.COMPONENTS}
        out["carrier"] = self.carrier
        return out

    def to_dict(self) -> dict:
        """JSON-ready (lists), units in the keys."""

        def lst(x):
            return np.asarray(x, dtype=float).tolist()

        out = {
            "case": self.case,
            "load_N": lst(self.load),
            "speed_rad_s": lst(self.speed),
            "torque_Nm": lst(self.torque),
            "friction_coefficient": lst(self.friction_coefficient),
            "references": list(self.references),
        }
        out.update({f"{k}_torque_Nm": lst(v) for k, v in self.by_component().items()})
        return out

    def to_pandas(self):
        """One row per case, one column per component."""
        import pandas as pd

        data = {"load_N": self.load, "speed_rpm": self.speed / RPM}
        data.update({f"{k}_Nm": v for k, v in self.by_component().items()})
        data["torque_Nm"] = self.torque
        data["friction_coefficient"] = self.friction_coefficient
        return pd.DataFrame({k: np.ravel(np.broadcast_to(v, np.shape(self.torque))) for k, v in data.items()})


def _lubricant_props(lubricant, temperature_C):
    lub = as_lubricant(lubricant)
    return float(lub.viscosity(temperature_C)), float(lub.pressure_viscosity)


def _sum_contacts(geom: dict, loads_in, loads_out, weights, speed, params, viscosity, alpha_p):
    """Σ weights·torque over contacts; loads (..., K), weights broadcast to (..., K)."""
    comps = {}
    for side, loads in (("inner", loads_in), ("outer", loads_out)):
        r_x = geom["r_I"] if side == "inner" else geom["r_O"]
        t = pf.contact_torques(
            loads,
            side,
            geom["d_R"],
            geom["d_I"],
            geom["d_O"],
            geom["R_rr"],
            r_x,
            geom["alpha"],
            geom["E"],
            viscosity,
            alpha_p,
            speed,
            traction=params.traction,
            hysteresis=params.hysteresis,
            viscous_model=params.viscous_model,
            convention=params.convention,
            viscous_projection=params.viscous_projection,
            viscous_radius_y=params.viscous_radius_y,
        )
        comps[side] = {k: (v * weights).sum(axis=-1) for k, v in t.items()}
    return comps


def _geom_dict(g: PTRBGeometry) -> dict:
    return {
        "d_R": g.roller_pitch_diameter,
        "d_I": g.d_inner,
        "d_O": g.d_outer,
        "R_rr": g.roller_contact_radius,
        "r_I": g.contact_radius_inner,
        "r_O": g.contact_radius_outer,
        "alpha": g.contact_angle,
        "E": g.e_reduced,
    }


def ptrb_friction(
    geometry: PTRBGeometry,
    load,
    speed,
    case: str = "axial",
    lubricant="L-AN",
    temperature_C: float = TEST_TEMPERATURE_C,
    parameters: PTRBFrictionParameters | None = None,
    tooth_distribution: str = "uniform",
    azimuth_phase: float = 0.0,
) -> PTRBFrictionResult:
    """Friction torque M_PTRBa or M_PTRBr of a PTRB, batched over load and speed.

    Parameters
    ----------
    geometry : PTRBGeometry
    load : array_like
        F_a (``case="axial"``) or F_r (``"radial"``) [N], > 0; broadcast with ``speed``.
    speed : array_like
        Inner-ring speed ω [rad/s], ≥ 0 (outer ring fixed).
    case : {"axial", "radial"}
    lubricant : str or Lubricant
        Default ``"L-AN"`` (η₀ = 0.04 Pa·s, α = 2.46e-8 1/Pa: Zheng et al. 2022 §4).
    temperature_C : float
        Oil temperature [°C] (the paper's tests: 40 °C; L-AN is a constant-viscosity preset).
    parameters : PTRBFrictionParameters or None
        Parameters the paper does not give.
    tooth_distribution : {"uniform", "model"}
        Axial tooth shares (:data:`TOOTH_DISTRIBUTIONS`); ignored for radial load.
    azimuth_phase : float
        Azimuth of roller 0 from the radial load [rad] (radial case).

    Returns
    -------
    PTRBFrictionResult

    Notes
    -----
    .. math::
        M_{PTRBa} = Z\\sum_{i=1}^{n}(M_{I,i} + M_{O,i}) + M_h,\\qquad
        M_{PTRBr} = 2n\\sum_{j=1}^{Z_e}(M_{I,j} + M_{O,j}) + M_h

    Zheng et al. (2022) eq. (14)-(15); per-contact torques from
    :func:`bearingkit.physics.friction.ptrb.contact_torques`.
    """
    if not isinstance(geometry, PTRBGeometry):
        raise InputError(f"geometry ({type(geometry).__name__}) must be a PTRBGeometry")
    checks.one_of("case", case, CASES)
    checks.one_of("tooth_distribution", tooth_distribution, TOOTH_DISTRIBUTIONS)
    params = parameters or PTRBFrictionParameters()
    g = geometry
    f, w = np.broadcast_arrays(
        np.asarray(checks.positive("load", load, "N"), dtype=float),
        np.asarray(checks.non_negative("speed", speed, "rad/s"), dtype=float),
    )
    shape = f.shape
    f, w = f.reshape(-1), w.reshape(-1)
    eta, alpha_p = _lubricant_props(lubricant, temperature_C)
    geom = _geom_dict(g)
    sa, ca = np.sin(g.contact_angle), np.cos(g.contact_angle)
    if case == "axial":
        if tooth_distribution == "uniform":
            q = (f / (g.n_elements * g.n_teeth * sa))[:, None]
            q_in, q_out = q, q
            weights = np.array([float(g.n_elements * g.n_teeth)])
        else:
            dist = axial_tooth_distribution(g, f)
            q_in, q_out = dist.load_inner / sa, dist.load_outer / sa
            weights = np.full(g.n_teeth, float(g.n_elements))
    else:
        share = radial_roller_distribution(g.n_elements, azimuth_phase)[0].reshape(-1)  # (Z,)
        q_in = f[:, None] * share[None, :] / (2.0 * g.n_teeth * ca)
        q_out = q_in
        weights = np.full(g.n_elements, 2.0 * g.n_teeth)
    comps = _sum_contacts(geom, q_in, q_out, weights, w[:, None], params, eta, alpha_p)
    m_h = pf.carrier_torque(
        g.n_elements,
        g.roller_pitch_diameter,
        g.d_inner,
        g.d_outer,
        g.n_teeth * g.thread_pitch,
        params.carrier_friction,
        params.journal_ratio,
    )
    comps = {s: {k: v.reshape(shape) for k, v in d.items()} for s, d in comps.items()}
    return PTRBFrictionResult(
        case, f.reshape(shape), w.reshape(shape), comps, np.full(shape, float(m_h)), float(g.bore_diameter)
    )


def calibrate_contact_traction(
    geometry: PTRBGeometry | None = None,
    convention: str | None = None,
    parameters: PTRBFrictionParameters | None = None,
) -> float:
    """Recompute :data:`~bearingkit.physics.friction.ptrb.CONTACT_TRACTION_CALIBRATED` [1].

    The torque is affine in μ_c (spin and differential sliding ∝ μ_c, the rest independent of it), so
    two evaluations at :data:`CALIBRATION_POINT` give the μ_c that reproduces 0.476 N·m exactly.
    ``parameters`` (its ``traction`` ignored) sets the other model choices (default: the default
    reading; ``PTRBFrictionParameters.power_balance()`` recomputes
    :data:`~bearingkit.physics.friction.ptrb.CONTACT_TRACTION_POWER_BALANCE`); ``convention``, if
    given, overrides its convention (with that convention's default viscous projection).
    """
    from bearingkit.bearings.ptrb import ptrb_prototype

    g = geometry or ptrb_prototype()
    base = parameters or PTRBFrictionParameters()
    if convention is not None:
        base = replace(base, convention=convention, viscous_projection=None)
    p = CALIBRATION_POINT
    args = (g, p["load_N"], p["speed_rpm"] * RPM, p["case"])
    m0 = float(ptrb_friction(*args, parameters=replace(base, traction=0.0)).torque)
    m1 = float(ptrb_friction(*args, parameters=replace(base, traction=1.0)).torque)
    return (p["torque_Nm"] - m0) / (m1 - m0)


def design_geometry(
    contact_angle=None, n_teeth=None, roller_contact_radius=None, roller_pitch_diameter=None, **kw
):
    """The prototype with §5/§6 design variables changed under the paper's rules [SI].

    D_pw is held (d_I = D_pw − d_R, d_O = D_pw + d_R) and n·P is held at 12 mm (P = 12 mm / n).
    Other :class:`PTRBGeometry` fields may be given by keyword (e.g. ``n_elements``).
    """
    from bearingkit.bearings.ptrb import ptrb_prototype

    changes = dict(kw)
    if contact_angle is not None:
        changes["contact_angle"] = float(contact_angle)
    if roller_contact_radius is not None:
        changes["roller_contact_radius"] = float(roller_contact_radius)
    if roller_pitch_diameter is not None:
        d_r = float(roller_pitch_diameter)
        changes.update(
            roller_pitch_diameter=d_r,
            inner_pitch_diameter=PROTOTYPE_PITCH_DIAMETER - d_r,
            outer_pitch_diameter=PROTOTYPE_PITCH_DIAMETER + d_r,
        )
    if n_teeth is not None:
        n = checks.integer("n_teeth", n_teeth)
        changes.update(n_teeth=n, thread_pitch=PROTOTYPE_THREAD_LENGTH / n)
    return ptrb_prototype(**changes)


def ptrb_objectives(
    alpha,
    n,
    R_rr,
    d_R,
    case: str = "axial",
    load=20.0e3,
    speed=4000.0 * RPM,
    n_elements: int = 11,
    lubricant="L-AN",
    temperature_C: float = TEST_TEMPERATURE_C,
    parameters: PTRBFrictionParameters | None = None,
) -> dict:
    """Objectives of the §6 optimisation for a population of designs (pure, vectorised).

    Parameters
    ----------
    alpha : array_like
        Contact angle α [rad], in (0, π/2), shape (P,).
    n : array_like
        Teeth per roller [1] (rounded to integers), shape (P,).
    R_rr : array_like
        Roller flank radius [m].
    d_R : array_like
        Roller pitch diameter [m].
    case : {"axial", "radial"}
    load : float
        Load of the friction objective [N] (§6: 20 kN).
    speed : float
        ω [rad/s] (§6: 4000 rpm).
    n_elements : int
        Z (§6: the maximum, 11).

    Returns
    -------
    dict of ndarray (P,)
        ``C0`` [N] (C0a or C0r), ``C`` [N] (Ca or Cr), ``M`` [N·m], ``mu`` [1], all four ratings
        ``C0a, Ca, C0r, Cr``, and ``feasible`` (bool: d_R ≤ 2 R_rr cos α, §5 (3)-(4), and the roller
        fits between the pitch circles).

    Notes
    -----
    Same rules as :func:`design_geometry` (D_pw = 42.5 mm, n·P = 12 mm, flat ring flanks, E = 212 GPa,
    ν = 0.29); ratings as :func:`bearingkit.bearings.ptrb.ptrb_ratings` (calibrated f_amax, f_rmax),
    friction as :func:`ptrb_friction` (uniform tooth shares). Infeasible designs are evaluated anyway
    (flagged, not NaN) as long as the inputs are physical.
    """
    from bearingkit.bearings.ptrb import ptrb_prototype

    checks.one_of("case", case, CASES)
    params = parameters or PTRBFrictionParameters()
    base = ptrb_prototype()
    alpha, n_f, r_rr, d_r = np.broadcast_arrays(
        *(np.atleast_1d(np.asarray(x, float)) for x in (alpha, n, R_rr, d_R))
    )
    checks.in_range("alpha", alpha, 0.0, np.pi / 2, "rad", closed=False)
    checks.positive("R_rr", r_rr, "m")
    checks.in_range("d_R", d_r, 0.0, PROTOTYPE_PITCH_DIAMETER, "m", closed=False)
    n_t = np.rint(checks.positive("n", n_f))
    z = checks.integer("n_elements", n_elements, low=3)
    e_red = base.e_reduced
    d_i, d_o = PROTOTYPE_PITCH_DIAMETER - d_r, PROTOTYPE_PITCH_DIAMETER + d_r
    inf = np.full_like(d_r, np.inf)
    q0 = np.minimum(
        *(
            pr.static_contact_load(*pr.thread_contact_curvature(d_r, dx, r_rr, inf, alpha, side)[:2], e_red)
            for side, dx in (("inner", d_i), ("outer", d_o))
        )
    )
    f_amax, f_rmax = pr.calibrated_distribution_coefficients(z)
    gamma = d_r / PROTOTYPE_PITCH_DIAMETER
    dw = d_r / np.cos(alpha)
    fca = pr.fc_axial(gamma, alpha, r_rr, inf, d_r)
    fcr = pr.fc_radial(gamma, alpha, r_rr, inf, d_r)
    out = {
        "C0a": pr.static_rating_axial(q0, z, n_t, alpha, f_amax),
        "C0r": pr.static_rating_radial(q0, n_t, alpha, f_rmax),
        "Ca": pr.basic_dynamic_axial(pr.dynamic_rating_thread(fca, dw, z, alpha, axial=True), n_t, f_amax),
        "Cr": pr.basic_dynamic_radial(pr.dynamic_rating_thread(fcr, dw, z, alpha, axial=False), n_t),
    }
    eta, alpha_p = _lubricant_props(lubricant, temperature_C)
    geom = {
        "d_R": d_r,
        "d_I": d_i,
        "d_O": d_o,
        "R_rr": r_rr,
        "r_I": inf,
        "r_O": inf,
        "alpha": alpha,
        "E": e_red,
    }
    geom = {k: np.asarray(v)[:, None] if np.ndim(v) else v for k, v in geom.items()}
    f = float(checks.positive("load", load, "N"))
    if case == "axial":
        q = (f / (z * n_t * np.sin(alpha)))[:, None]
        weights = (z * n_t)[:, None]
    else:
        share = radial_roller_distribution(z)[0].reshape(1, -1)
        q = f * share / (2.0 * n_t * np.cos(alpha))[:, None]
        weights = np.broadcast_to((2.0 * n_t)[:, None], q.shape)
    comps = _sum_contacts(geom, q, q, weights, float(speed), params, eta, alpha_p)
    m_h = pf.carrier_torque(
        z, d_r, d_i, d_o, PROTOTYPE_THREAD_LENGTH, params.carrier_friction, params.journal_ratio
    )
    torque = sum(sum(d.values()) for d in comps.values()) + m_h
    out["M"] = torque
    out["mu"] = pf.friction_coefficient(torque, f, base.bore_diameter)
    out["C0"] = out["C0a"] if case == "axial" else out["C0r"]
    out["C"] = out["Ca"] if case == "axial" else out["Cr"]
    fits = np.pi * PROTOTYPE_PITCH_DIAMETER / z >= d_r
    out["feasible"] = (d_r <= 2.0 * r_rr * np.cos(alpha) * (1 + 1e-12)) & fits
    return out
