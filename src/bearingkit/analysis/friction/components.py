"""Friction torque of a solved bearing: the seed-000 component model for ball and roller rows.

SI units inside (N, m, Pa, Pa·s, rad/s, W, N·m); the operating temperature is in °C (as the
lubricant API). Keys of :meth:`FrictionResult.to_dict` carry their unit (``total_Nm`` …).

Method (Tian et al. 2025 §4, energy method): every contact dissipates a power P = F·v (hysteresis
and EHL rolling resistance × entrainment speed, sliding traction × slip speed, spin moment × spin
speed); the bearing's friction torque is the total power over the relative ring speed,
M = ΣP / |ω_i − ω_o|, plus the cage–guide torque M5. Steady state (no external torque on the cage
or elements) gives the torque on the inner ring −sign(ω_i − ω_o)·M and on the outer ring +sign·M.

Zero speed: Coulomb-type losses (hysteresis, sliding, spin) scale with |ω_i − ω_o|, so their
torque is speed independent; they are evaluated with the kinematics at unit relative speed (inner
ring turning) and the film parameter at the actual speed (Λ = 0 at rest: boundary friction). The
EHL viscous torque is F(u)·u/|Δω| = F(u)·(u per unit Δω), which vanishes at rest. Hence zero speed
returns the load-dependent part only, with no division by zero.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks
from bearingkit.analysis.friction.kinematics import (
    RACEWAY_CONTROLS,
    element_kinematics,
    thrust_roller_kinematics,
)
from bearingkit.lubricants import Lubricant, as_lubricant
from bearingkit.physics.contact import hertz, line
from bearingkit.physics.friction import components as fc
from bearingkit.physics.lubrication import ehl
from bearingkit.physics.lubrication.traction import MU_BOUNDARY, MU_EHL_SKF_CYLINDRICAL, traction_mixed

#: Composite-free RMS roughness of a rolling element [m]: superfinished balls/rollers R_q ≈ 0.05 µm
#: (Harris & Kotzalas 2007, ch. 4 (lubricant films), typical values 0.025–0.1 µm).
ROUGHNESS_ELEMENT = 0.05e-6
#: RMS roughness of a ground and honed raceway [m], typical 0.05–0.2 µm (same source).
ROUGHNESS_RACEWAY = 0.10e-6
#: Cage–guide friction coefficient (steel or brass on steel, grease lubricated), 0.05–0.15 (assumed
#: mid value; Harris & Kotzalas 2007 ch. 9 use boundary-lubricated sliding for cage lands).
CAGE_FRICTION = 0.1
COMPONENT_NAMES = (
    "hysteresis_roller",
    "hysteresis_ball",
    "differential_sliding",
    "viscous_roller",
    "viscous_ball",
    "spin_ball",
    "cage",
    "roller_sliding",
)
FILM_LINE_MODEL = "pan_hamrock"


@dataclass(frozen=True)
class OperatingPoint:
    """Speeds, lubricant and friction data of a friction calculation.

    Parameters
    ----------
    speed_inner, speed_outer : float or (C,) array [rad/s]
        Ring speeds about the bearing axis.
    lubricant : Lubricant or str
        Lubricant (a grease is described by its base oil), see :mod:`bearingkit.lubricants`.
    temperature : float [°C]
        Operating (inlet) temperature.
    roughness_element, roughness_raceway : float [m]
        RMS roughness R_q of elements and raceways (film parameter Λ).
    mu_boundary : float [-]
        Boundary friction coefficient (Λ → 0).
    mu_ehl : float [-]
        Full-film traction coefficient (Λ → ∞).
    hysteresis_roller, hysteresis_ball : float [-]
        Hysteresis loss fractions ξ, β.
    cage_mass : float [kg]
        Total mass of the cages that slide on guides under their weight (0: no cage term).
    cage_friction : float [-]
        Cage–guide friction coefficient f_c.
    cage_guide_diameter : float or None [m]
        Diameter of the cage guide; None = mean pitch diameter of the rows.
    viscosity_factor : float [-]
        Multiplier of the base-oil viscosity (effective grease viscosity / base-oil viscosity); 1 =
        base oil. The single calibration knob of the seed-000 reproduction.
    viscous_line_model, viscous_point_model : str
        Keys of :data:`~bearingkit.physics.friction.components.VISCOUS_LINE_MODELS` /
        :data:`~bearingkit.physics.friction.components.VISCOUS_POINT_MODELS`.
    raceway_control : str
        Spin-axis hypothesis of the balls (:data:`~bearingkit.analysis.friction.kinematics.RACEWAY_CONTROLS`).
    roller_sliding : float [-]
        Coefficient μ_rs of the load-proportional sliding of thrust roller rows at their pitch radius
        (:func:`~bearingkit.physics.friction.components.roller_sliding_torque`); 0 = off (default:
        no source gives it for a bearing without catalogue data; seed 000 identifies it).
    """

    speed_inner: float = 0.0
    speed_outer: float = 0.0
    lubricant: Lubricant | str = "seed000_grease_assumed"
    temperature: float = 25.0
    roughness_element: float = ROUGHNESS_ELEMENT
    roughness_raceway: float = ROUGHNESS_RACEWAY
    mu_boundary: float = MU_BOUNDARY
    mu_ehl: float = MU_EHL_SKF_CYLINDRICAL
    hysteresis_roller: float = fc.HYSTERESIS_ROLLER
    hysteresis_ball: float = fc.HYSTERESIS_BALL
    cage_mass: float = 0.0
    cage_friction: float = CAGE_FRICTION
    cage_guide_diameter: float | None = None
    viscosity_factor: float = 1.0
    viscous_line_model: str = "matsuyama"
    viscous_point_model: str = "fujiwara"
    raceway_control: str = "tangent"
    roller_sliding: float = 0.0

    def __post_init__(self):
        checks.finite("speed_inner", self.speed_inner, "rad/s")
        checks.finite("speed_outer", self.speed_outer, "rad/s")
        object.__setattr__(self, "lubricant", as_lubricant(self.lubricant))
        checks.in_range("temperature", self.temperature, -50.0, 250.0, "degC")
        checks.non_negative("roughness_element", self.roughness_element, "m")
        checks.non_negative("roughness_raceway", self.roughness_raceway, "m")
        checks.positive(
            "roughness_element + roughness_raceway", self.roughness_element + self.roughness_raceway, "m"
        )
        checks.in_range("mu_boundary", self.mu_boundary, 0.0, 1.0)
        checks.in_range("mu_ehl", self.mu_ehl, 0.0, 1.0)
        checks.in_range("hysteresis_roller", self.hysteresis_roller, 0.0, 1.0)
        checks.in_range("hysteresis_ball", self.hysteresis_ball, 0.0, 1.0)
        checks.non_negative("cage_mass", self.cage_mass, "kg")
        checks.in_range("cage_friction", self.cage_friction, 0.0, 1.0)
        if self.cage_guide_diameter is not None:
            checks.positive("cage_guide_diameter", self.cage_guide_diameter, "m")
        checks.positive("viscosity_factor", self.viscosity_factor)
        checks.one_of("viscous_line_model", self.viscous_line_model, fc.VISCOUS_LINE_MODELS)
        checks.one_of("viscous_point_model", self.viscous_point_model, fc.VISCOUS_POINT_MODELS)
        checks.one_of("raceway_control", self.raceway_control, RACEWAY_CONTROLS)
        checks.in_range("roller_sliding", self.roller_sliding, 0.0, 1.0)

    @classmethod
    def from_rpm(cls, rpm_inner=0.0, rpm_outer=0.0, **kwargs) -> OperatingPoint:
        """Build from ring speeds in r/min (converted to rad/s)."""
        to = 2.0 * np.pi / 60.0
        return cls(
            speed_inner=np.asarray(rpm_inner, dtype=float) * to,
            speed_outer=np.asarray(rpm_outer, dtype=float) * to,
            **kwargs,
        )


@dataclass
class FrictionResult:
    """Friction torque of a batch of solved cases (leading axis C).

    Attributes
    ----------
    total : ndarray (C,) [N·m]
        Friction torque M = ΣP/|Δω| + M5 (magnitude).
    components : dict name → (C,) [N·m]
        Breakdown by component (:data:`COMPONENT_NAMES`); sums to ``total``.
    by_row : dict row name → (C,) [N·m]
        Breakdown by row plus ``"cage"``; sums to ``total``.
    per_element : dict row name → (C, Z) [N·m]
        Torque of each element (all its contacts); sums over elements to ``by_row``.
    torque_inner, torque_outer : ndarray (C,) [N·m]
        Friction torque acting on the inner and on the outer ring about +z (equal and opposite).
    references : tuple of str
    """

    total: np.ndarray
    components: dict
    by_row: dict
    per_element: dict
    torque_inner: np.ndarray
    torque_outer: np.ndarray
    references: tuple = field(default_factory=tuple)

    @property
    def total_Nm(self) -> np.ndarray:
        """Total friction torque (C,) [N·m] (alias of ``total``, unit in the name)."""
        return self.total

    def to_dict(self, case: int | None = None):
        """JSON-ready dict with units in the keys; a list over cases when ``case`` is None."""
        if case is None:
            return [self.to_dict(c) for c in range(self.total.shape[0])]
        return {
            "total_Nm": float(self.total[case]),
            "components_Nm": {k: float(v[case]) for k, v in self.components.items()},
            "rows_Nm": {k: float(v[case]) for k, v in self.by_row.items()},
            "elements_Nm": {k: v[case].tolist() for k, v in self.per_element.items()},
            "torque_inner_Nm": float(self.torque_inner[case]),
            "torque_outer_Nm": float(self.torque_outer[case]),
            "references": list(self.references),
        }


def _safe(load):
    live = load > 0
    return live, np.where(live, load, 1.0)


def _ball_row(row, kernel, state, op, ctx):
    """Per-element torques (dict component → (C, Z)) of a ball row."""
    load = state.load
    live, qs = _safe(load)
    d = np.asarray(row.element_diameter, dtype=float).reshape(-1, 1)
    dm = np.asarray(row.pitch_diameter, dtype=float).reshape(-1, 1)
    alpha0 = np.asarray(row.contact_angle, dtype=float).reshape(-1, 1)
    kin_n = element_kinematics(dm, d, alpha0, ctx["wi_n"], ctx["wo_n"], op.raceway_control)
    kin = element_kinematics(dm, d, alpha0, ctx["wi"], ctx["wo"], op.raceway_control)
    out = {k: np.zeros_like(load) for k in ("hysteresis_ball", "viscous_ball", "spin_ball")}
    e_red = kernel.e_reduced
    for side, f in (("inner", row.conformity_inner), ("outer", row.conformity_outer)):
        f = np.asarray(f, dtype=float).reshape(-1, 1)
        srho, frho = hertz.ball_raceway_curvature(d, dm, np.abs(alpha0), f * d, side)
        rx, ry = hertz.effective_radii(srho, frho)
        a = np.where(live, state.extras[f"semi_major_{side}"], 0.0)
        b = np.where(live, state.extras[f"semi_minor_{side}"], 0.0)
        kappa = np.where(live, a / np.where(b > 0, b, 1.0), 1.0)
        u_act = getattr(kin, f"entrainment_{side}")
        u_n = getattr(kin_n, f"entrainment_{side}")
        film = ehl.film_point_hamrock_dowson(
            ctx["eta"], u_act, ctx["alpha_p"], e_red, rx, ry, qs, ellipticity=np.maximum(kappa, 1.0)
        )
        lam = ehl.film_parameter(film.minimum, op.roughness_element, op.roughness_raceway)
        mu = traction_mixed(lam, op.mu_ehl, op.mu_boundary)
        f_h = fc.hysteresis_force_point(load, b, rx, op.hysteresis_ball)
        out["hysteresis_ball"] += f_h * u_n
        f_v = fc.VISCOUS_POINT_MODELS[op.viscous_point_model](
            load, ctx["eta"], u_act, ctx["alpha_p"], e_red, rx, a, b
        )
        out["viscous_ball"] += np.where(live, f_v, 0.0) * u_n
        m_s = fc.spin_moment(load, a, np.maximum(kappa, 1.0), mu)
        out["spin_ball"] += np.where(live, m_s, 0.0) * np.abs(getattr(kin_n, f"spin_{side}"))
    return out


def _roller_row(row, kernel, state, op, ctx):
    """Per-element torques (dict component → (C, Z)) of a cylindrical roller row."""
    load = state.load
    q_s = state.slice_load  # (C, Z, n_s)
    live, qs = _safe(load)
    d = np.asarray(row.element_diameter, dtype=float).reshape(-1, 1)
    dm = np.asarray(row.pitch_diameter, dtype=float).reshape(-1, 1)
    length = np.asarray(row.effective_length, dtype=float).reshape(-1, 1)
    width = length[..., None] / row.n_slices
    e_red = kernel.e_reduced
    keys = ("hysteresis_roller", "viscous_roller", "differential_sliding", "roller_sliding")
    out = {k: np.zeros_like(load) for k in keys}
    if row.direction == 0:
        kin_n = element_kinematics(dm, d, 0.0, ctx["wi_n"], ctx["wo_n"], "tangent")
        kin = element_kinematics(dm, d, 0.0, ctx["wi"], ctx["wo"], "tangent")
        radius_x = {"inner": d / 2 * (1 - d / dm), "outer": d / 2 * (1 + d / dm)}
        speeds = {
            s: (getattr(kin, f"entrainment_{s}"), getattr(kin_n, f"entrainment_{s}"), None, None)
            for s in radius_x
        }
    else:
        y = dm / 2 + kernel.x  # (C|1, n_s)
        kin_n = thrust_roller_kinematics(dm[:, 0], d[:, 0], y, ctx["wi_n"][:, 0], ctx["wo_n"][:, 0])
        kin = thrust_roller_kinematics(dm[:, 0], d[:, 0], y, ctx["wi"][:, 0], ctx["wo"][:, 0])
        radius_x = {"inner": d / 2 + 0 * dm, "outer": d / 2 + 0 * dm}
        out["roller_sliding"] = fc.roller_sliding_torque(load, op.roller_sliding, dm)
        u_pitch = kin.entrainment_pitch.reshape(-1, 1)
        u_pitch_n = kin_n.entrainment_pitch.reshape(-1, 1)
        speeds = {
            s: (
                u_pitch,
                u_pitch_n,
                getattr(kin_n, f"entrainment_{s}")[:, None, :],
                getattr(kin_n, f"slide_{s}"),
            )
            for s in radius_x
        }
    for side, rx in radius_x.items():
        u_act, u_n, u_slice_n, slide_n = speeds[side]
        film = ehl.film_line_pan_hamrock(ctx["eta"], u_act, ctx["alpha_p"], e_red, rx, qs, length)
        lam = ehl.film_parameter(film.minimum, op.roughness_element, op.roughness_raceway)
        b = line.line_contact(q_s, width, rx[..., None], e_red).half_width
        f_h = fc.hysteresis_force_line(q_s, b, rx[..., None], op.hysteresis_roller)
        u_roll = u_n[..., None] if u_slice_n is None else u_slice_n
        out["hysteresis_roller"] += (f_h * u_roll).sum(axis=-1)
        f_v = fc.VISCOUS_LINE_MODELS[op.viscous_line_model](
            load, ctx["eta"], u_act, ctx["alpha_p"], e_red, rx, length
        )
        out["viscous_roller"] += np.where(live, f_v, 0.0) * u_n
        if slide_n is not None:
            mu = traction_mixed(lam, op.mu_ehl, op.mu_boundary)
            out["differential_sliding"] += fc.sliding_power(q_s, slide_n[:, None, :], mu[..., None]).sum(
                axis=-1
            )
    return out


def friction_torque(result, operating_point: OperatingPoint) -> FrictionResult:
    """Friction torque of every case of a solved bearing (:class:`QuasiStaticResult`).

    Parameters
    ----------
    result : QuasiStaticResult
        Solved load distribution (C cases).
    operating_point : OperatingPoint
        Speeds [rad/s] (scalar or (C,)), lubricant, temperature [°C], roughness, friction data.

    Returns
    -------
    FrictionResult
        Torque [N·m] in total, by component, by row, per element, and on each ring.

    Notes
    -----
    .. math:: M = \\frac{1}{|\\omega_i - \\omega_o|}\\sum_{\\text{contacts}} P + W_g f_c \\frac{d_g}{2}

    Tian et al. (2025) §4.1–4.6, doi:10.3390/machines13070588.
    """
    op = operating_point
    if not isinstance(op, OperatingPoint):
        raise checks.InputError(f"operating_point ({op!r}) must be an OperatingPoint")
    c = result.n_cases
    wi = np.broadcast_to(np.asarray(op.speed_inner, dtype=float), (c,)).reshape(-1, 1)
    wo = np.broadcast_to(np.asarray(op.speed_outer, dtype=float), (c,)).reshape(-1, 1)
    dw = wi - wo
    moving = np.abs(dw) > 0
    scale = np.where(moving, np.abs(dw), 1.0)
    ctx = {
        "wi": wi,
        "wo": wo,
        "wi_n": np.where(moving, wi / scale, 1.0),
        "wo_n": np.where(moving, wo / scale, 0.0),
        "eta": float(op.lubricant.viscosity(op.temperature)) * op.viscosity_factor,
        "alpha_p": float(op.lubricant.pressure_viscosity_at(op.temperature)),  # α at T (base-oil law)
    }
    components = {k: np.zeros(c) for k in COMPONENT_NAMES}
    by_row, per_element = {}, {}
    for row, kernel, state in zip(result.model.rows, result.model.kernels, result.rows, strict=True):
        if row.kind == "ball":
            parts = _ball_row(row, kernel, state, op, ctx)
        elif row.kind == "cylindrical":
            parts = _roller_row(row, kernel, state, op, ctx)
        else:
            raise checks.InputError(  # say where to go: the catalogue models cover several such kinds
                f"row {row.name!r} of kind {row.kind!r} has no component friction model yet; the "
                "catalogue models may cover the bearing (friction model 'skf', 'palmgren', 'trb' or "
                "'slewing'; `bearingkit friction FILE --compare` shows which apply)"
            )
        elem = sum(parts.values())
        per_element[row.name] = elem
        by_row[row.name] = elem.sum(axis=-1)
        for k, v in parts.items():
            components[k] += v.sum(axis=-1)
    guide = op.cage_guide_diameter
    if guide is None:
        guide = float(np.mean([np.mean(r.pitch_diameter) for r in result.model.rows]))
    cage = fc.cage_torque(op.cage_mass * fc.STANDARD_GRAVITY, op.cage_friction, guide)
    components["cage"] = np.full(c, float(cage))
    by_row["cage"] = components["cage"].copy()
    total = sum(components.values())
    sign = np.where(dw[:, 0] >= 0, 1.0, -1.0)
    refs = tuple(dict.fromkeys(("tian2025", *fc.REFERENCE_KEYS, "hamrock1977", "pan1989", "skf_friction")))
    return FrictionResult(total, components, by_row, per_element, -sign * total, sign * total, refs)
