"""PTRB friction torque assembly (Zheng et al. 2022 §3.3).

SI units: N, m, rad/s, N·m. ``ptrb_friction`` sums the per-contact torques of
:mod:`bearingkit.physics.friction.ptrb` over the loaded ITP and OTP contacts and adds the carrier term:

* axial load F_a: every roller carries F_a/Z on one flank of each of its n teeth,
  Q_i = f_a,i F_a/(Z n sin α); M_PTRBa = Z Σ_i (M_I,i + M_O,i) + M_h (eq. 14);
* radial load F_r: roller j carries f_r,j F_r (Stribeck share of
  :func:`bearingkit.rows.threaded.distribution.radial_roller_distribution`) on both flanks of its n teeth,
  Q_j = f_r,j F_r/(2n cos α); M_PTRBr = 2n Σ_j (M_I,j + M_O,j) + M_h (eq. 15).

The prototype of the paper, its design rules, the calibration of the contact traction and the §6
objectives are in :mod:`bearingkit.papers.zheng2022.design`.

References: ``zheng2022``, ``zheng2021``, plus those of :mod:`bearingkit.physics.friction.ptrb`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.lubricants import as_lubricant
from bearingkit.physics.friction import ptrb as pf
from bearingkit.physics.friction import ptrb_laws as pl
from bearingkit.rows.threaded.distribution import axial_tooth_distribution, radial_roller_distribution
from bearingkit.rows.threaded.geometry import PTRBGeometry

__all__ = [
    "CASES",
    "TOOTH_DISTRIBUTIONS",
    "PTRBFrictionParameters",
    "PTRBFrictionResult",
    "ptrb_friction",
]

REFERENCE_KEYS = (*pf.REFERENCE_KEYS, "iso76", "iso281")
RPM = 2.0 * np.pi / 60.0
#: Load cases of the paper: pure axial or pure radial load.
CASES = ("axial", "radial")
#: Tooth shares under axial load: equal (f_a,i = 1, the default; the paper's f_amax ≈ 1.07 changes M by
#: < 0.5 %) or from the thread-connection model
#: :func:`~bearingkit.rows.threaded.distribution.axial_tooth_distribution`.
TOOTH_DISTRIBUTIONS = ("uniform", "model")
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

    traction: float = pl.CONTACT_TRACTION_CALIBRATED
    hysteresis: float = pl.HYSTERESIS_PTRB
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
    return float(lub.viscosity(temperature_C)), float(lub.pressure_viscosity_at(temperature_C))


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
