"""Friction of a solved tapered roller bearing (seed 001 §2.2): per-roller forces, ring torques, Monte Carlo.

SI units inside (N, m, Pa, Pa·s, rad/s, N·m); the lubricant temperature is in °C (the lubricant API).
Result keys carry their unit (``torque_inner_Nm`` …).

Method (Liu et al. 2022, eqs. 7–13): the quasi-static solve of a :class:`~bearingkit.rows.tapered.row.
TaperedRow` gives per roller the cone, cup and rib loads (per slice for sliced rows). With outer-raceway
control (cage slip S_c, :func:`~bearingkit.physics.friction.trb.outer_control_kinematics`) every
roller carries EHL rolling resistance F_ro on both raceways, sliding traction F_rs on the cone
(v_si = ω_i R_i S_c; none on the cup) and rib sliding F_fs = Q_f μ₀ e^(−1.8Λ^1.2); the torques are
M_er = Σ F_ro,e R_e and M_ir = Σ (F_ro,i + F_rs,i) R_i + F_fs·arm. Everything is batched over the case
axis (deviation realisations) and the rollers; no Python loop over either.

F_rs is eq. (8) (Newtonian shear with Roelands viscosity over the Hertz strip) capped by the limiting
shear stress τ_L = 0.075 p by default (``sliding_model="limiting_shear"``): as printed
(``"newtonian"``) it reaches F_rs/Q = 0.075 at 10 kN and S_c = 0.01 % and 0.38 at 0.05 %, above boundary
friction. The cap does not make it small: at 10 kN the cone contacts are near the plateau
(F_rs/Q ≈ 0.04 at S_c = 0.01 %), so F_rs is ~99 % of M_ir there (docs/seed001.md).

Choices where the paper is silent (see :class:`TRBOperatingPoint`): lubricant ISO VG 46 mineral oil at
40 °C (η₀ = 0.039 Pa·s, α = 2e-8 1/Pa), roller-end and rib roughness, μ₀, the rib film by
Hamrock–Dowson for the spherical roller end on a flat rib, the rib moment arm from the row geometry,
the limiting-shear coefficient Λ_L = 0.075 (Bair & Winer 1979, mid-range of 0.05–0.1 for mineral oils).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks
from bearingkit.analysis.scatter import SEED001_FREE
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.errors import InputError
from bearingkit.lubricants import Lubricant, as_lubricant
from bearingkit.physics.deviations import gaussian_deviations
from bearingkit.physics.friction import trb as tf
from bearingkit.physics.friction import trb_rheology as rh
from bearingkit.physics.lubrication import ehl
from bearingkit.physics.lubrication.traction import MU_BOUNDARY, flange_friction_force
from bearingkit.rows.tapered.row import TaperedRow

#: Default lubricant (seed 001 gives none): ISO VG 46 mineral oil, a usual grade for small TRBs at
#: 1000 rpm; at 40 °C its ν = 46 mm²/s is the ISO 3448 reference value itself (no extrapolation).
DEFAULT_LUBRICANT = "ISO_VG46"
DEFAULT_TEMPERATURE_C = 40.0  # [°C]
#: RMS roughness of the ground roller end face [m] (assumed; ground faces 0.1–0.3 µm Rq).
ROUGHNESS_ROLLER_END = 0.10e-6
#: RMS roughness of the ground cone rib face [m] (assumed; ground faces 0.1–0.4 µm Rq).
ROUGHNESS_RIB = 0.20e-6
#: Cage slip rates of seed 001 Fig. 7 (0.01 % and 0.05 %) [-].
SEED001_CAGE_SLIPS = (1e-4, 5e-4)
#: Speed of seed 001 §3 (1000 rpm) [rad/s].
SEED001_SPEED = 1000.0 * 2.0 * np.pi / 60.0
#: Rib friction moment arm (documented names): the rib contact radius from the row geometry, or the
#: paper's R_i + e_r (eq. 12, mid-length cone radius plus rib contact height).
FLANGE_ARMS = ("geometric", "liu2022")
#: Deviation magnitudes S_d of seed 001 Table 2 [m].
SEED001_MAGNITUDES = (0.5e-6, 1.0e-6, 1.5e-6)


@dataclass(frozen=True)
class TRBOperatingPoint:
    """Speed, cage slip, lubricant and friction data of a TRB friction calculation.

    Parameters
    ----------
    speed : float [rad/s]
        Inner-ring speed ω_i (cup fixed), ≥ 0.
    cage_slip : float [-]
        Cage slip rate S_c in [0, 1) (seed 001: 1e-4 … 5e-4).
    lubricant : Lubricant or str
        Default :data:`DEFAULT_LUBRICANT`.
    temperature_C : float [°C]
        Oil temperature (viscosity at ambient pressure).
    roughness_roller_end, roughness_rib : float [m]
        RMS roughness of the two rib-contact surfaces (film parameter Λ of eq. 9).
    mu_coulomb : float [-]
        Coulomb coefficient μ₀ of eq. (9); default SKF μ_bl = 0.12.
    rolling_model : str
        Reading of eq. (7)'s constant, :data:`bearingkit.physics.friction.trb.ROLLING_COEFFICIENTS`.
    roelands_exponent : float or None [-]
        Z of eq. (10); None derives it from the lubricant's α (:func:`~bearingkit.physics.friction.trb.
        roelands_exponent`). Default: the seed's 0.601.
    flange_arm : str
        :data:`FLANGE_ARMS`.
    sliding_model : str
        Reading of eq. (8), :data:`bearingkit.physics.friction.trb.SLIDING_MODELS`: ``"limiting_shear"``
        (default; Newtonian shear capped by τ_L = Λ_L p) or ``"newtonian"`` (eq. 8 as printed).
    limiting_shear_coeff : float [-]
        Λ_L = τ_L/p of the ``"limiting_shear"`` reading (default 0.075, Bair & Winer 1979).
    """

    speed: float = SEED001_SPEED
    cage_slip: float = 1e-4
    lubricant: Lubricant | str = DEFAULT_LUBRICANT
    temperature_C: float = DEFAULT_TEMPERATURE_C
    roughness_roller_end: float = ROUGHNESS_ROLLER_END
    roughness_rib: float = ROUGHNESS_RIB
    mu_coulomb: float = MU_BOUNDARY
    rolling_model: str = "aihara1987"
    roelands_exponent: float | None = rh.ROELANDS_EXPONENT_LIU2022
    flange_arm: str = "geometric"
    sliding_model: str = "limiting_shear"
    limiting_shear_coeff: float = rh.SLIDING_LIMITING_SHEAR_COEFF

    def __post_init__(self):
        for name in (
            "speed",
            "cage_slip",
            "temperature_C",
            "roughness_roller_end",
            "roughness_rib",
            "mu_coulomb",
            "limiting_shear_coeff",
        ):
            if np.ndim(getattr(self, name)) != 0:
                raise InputError(f"{name} (shape {np.shape(getattr(self, name))}) must be a scalar")
        checks.non_negative("speed", self.speed, "rad/s")
        checks.in_range("cage_slip", self.cage_slip, 0.0, 1.0, closed=True)
        if self.cage_slip >= 1.0:
            raise InputError(f"cage_slip ({self.cage_slip:.6g}) must be below 1")
        object.__setattr__(self, "lubricant", as_lubricant(self.lubricant))
        self.lubricant.viscosity(self.temperature_C)  # validates the temperature
        checks.non_negative("roughness_roller_end", self.roughness_roller_end, "m")
        checks.non_negative("roughness_rib", self.roughness_rib, "m")
        checks.positive(
            "composite rib roughness", np.hypot(self.roughness_roller_end, self.roughness_rib), "m"
        )
        checks.non_negative("mu_coulomb", self.mu_coulomb)
        checks.one_of("rolling_model", self.rolling_model, tf.ROLLING_COEFFICIENTS)
        if self.roelands_exponent is not None:
            checks.positive("roelands_exponent", self.roelands_exponent)
        checks.one_of("flange_arm", self.flange_arm, FLANGE_ARMS)
        checks.one_of("sliding_model", self.sliding_model, tf.SLIDING_MODELS)
        checks.positive("limiting_shear_coeff", self.limiting_shear_coeff)

    @property
    def viscosity(self) -> float:
        """η₀ at ``temperature_C`` [Pa·s]."""
        return float(self.lubricant.viscosity(self.temperature_C))

    @property
    def exponent(self) -> float:
        """Roelands index Z used in the tractive integral [-]."""
        if self.roelands_exponent is not None:
            return float(self.roelands_exponent)
        return float(
            rh.roelands_exponent(self.lubricant.pressure_viscosity_at(self.temperature_C), self.viscosity)
        )


#: Share of M_ir carried by cone sliding traction above which the result warns [-] (bearingkit's
#: choice: beyond one half, M_ir describes the imposed cage slip more than the rolling losses).
SLIDING_DOMINANCE_WARN = 0.5


@dataclass(frozen=True)
class TRBFrictionResult:
    """Per-roller friction forces and ring torques of a batch of solved TRB cases (SI).

    Attributes
    ----------
    load_inner, load_outer, load_flange : ndarray (C, Z) [N]
        Cone, cup and rib contact loads.
    rolling_inner, rolling_outer : ndarray (C, Z) [N]
        F_ro on the cone and cup (eq. 7).
    sliding_inner, sliding_outer : ndarray (C, Z) [N]
        F_rs on the cone and cup (eq. 8 in the operating point's ``sliding_model`` reading; cup 0 under
        outer-raceway control).
    flange : ndarray (C, Z) [N]
        F_fs (eq. 9).
    film_parameter_flange : ndarray (C, Z) [-]
        Λ of the rib contact (0 where unloaded).
    torque_outer, torque_inner : ndarray (C,) [N·m]
        M_er, M_ir (eqs. 11–12).
    sliding_share_inner : ndarray (C,) [-]
        Share of M_ir that is cone sliding traction, Σ F_rs,i R_i / M_ir (0 where M_ir = 0).
    converged : ndarray (C,) of bool
    kinematics : TRBKinematics
    operating_point : TRBOperatingPoint
    references : tuple of str
    """

    load_inner: np.ndarray
    load_outer: np.ndarray
    load_flange: np.ndarray
    rolling_inner: np.ndarray
    rolling_outer: np.ndarray
    sliding_inner: np.ndarray
    sliding_outer: np.ndarray
    flange: np.ndarray
    film_parameter_flange: np.ndarray
    torque_outer: np.ndarray
    torque_inner: np.ndarray
    sliding_share_inner: np.ndarray
    converged: np.ndarray
    kinematics: tf.TRBKinematics
    operating_point: TRBOperatingPoint
    references: tuple = field(default=tf.REFERENCE_KEYS)

    @property
    def warnings(self) -> list[list[str]]:
        """Per case: what a reader of M_ir should know (empty when nothing to say)."""
        out = []
        for share in self.sliding_share_inner:
            w = []
            if share > SLIDING_DOMINANCE_WARN:
                w.append(
                    f"{share:.0%} of M_ir is cone sliding traction F_rs·R_i at the imposed cage slip "
                    "(seed 001 eq. 12 adds forces times radii): the power it dissipates is F_rs·v_s, "
                    "far below M_ir·ω; compare sliding models before using M_ir as a loss"
                )
            out.append(w)
        return out

    @property
    def max_sliding_inner(self) -> np.ndarray:
        """Largest cone sliding traction over the rollers, per case (C,) [N] (seed 001 Fig. 7)."""
        return self.sliding_inner.max(axis=-1)

    def to_dict(self, case: int = 0) -> dict:
        """JSON-ready summary of one case (units in keys)."""
        return {
            "converged": bool(self.converged[case]),
            "torque_outer_Nm": float(self.torque_outer[case]),
            "torque_inner_Nm": float(self.torque_inner[case]),
            "max_sliding_inner_N": float(self.max_sliding_inner[case]),
            "sliding_share_inner": float(self.sliding_share_inner[case]),
            "warnings": self.warnings[case],
            "rolling_inner_N": self.rolling_inner[case].tolist(),
            "rolling_outer_N": self.rolling_outer[case].tolist(),
            "sliding_inner_N": self.sliding_inner[case].tolist(),
            "flange_N": self.flange[case].tolist(),
            "film_parameter_flange": self.film_parameter_flange[case].tolist(),
            "references": list(self.references),
        }

    def to_pandas(self):
        """Long table: one row per (case, roller) with every per-roller force (units in columns)."""
        import pandas as pd

        c, z = self.load_inner.shape
        cols = {
            "case": np.repeat(np.arange(c), z),
            "roller": np.tile(np.arange(1, z + 1), c),
            "load_inner_N": self.load_inner.ravel(),
            "load_outer_N": self.load_outer.ravel(),
            "load_flange_N": self.load_flange.ravel(),
            "rolling_inner_N": self.rolling_inner.ravel(),
            "rolling_outer_N": self.rolling_outer.ravel(),
            "sliding_inner_N": self.sliding_inner.ravel(),
            "sliding_outer_N": self.sliding_outer.ravel(),
            "flange_N": self.flange.ravel(),
            "film_parameter_flange": self.film_parameter_flange.ravel(),
        }
        return pd.DataFrame(cols)


def friction_from_state(
    kernel, roller_state: dict, op: TRBOperatingPoint, converged=None
) -> TRBFrictionResult:
    """Friction of solved rollers: ``roller_state`` from :meth:`TaperedKernel.roller_state`.

    Parameters
    ----------
    kernel : TaperedKernel
        The row's kernel (geometry, E′, slice grid, roller end radius).
    roller_state : dict
        ``slice_load_inner`` (C, Z, n_s), ``slice_load_outer`` (C, Z, n_s), ``load_flange`` (C, Z) [N].
    op : TRBOperatingPoint
    converged : array (C,) of bool or None
    """
    if not isinstance(op, TRBOperatingPoint):
        raise InputError(f"operating_point ({type(op).__name__}) must be a TRBOperatingPoint")
    geo, row = kernel.geo, kernel.row
    q_i = np.asarray(roller_state["slice_load_inner"], dtype=float)
    q_e = np.asarray(roller_state["slice_load_outer"], dtype=float)
    q_f = np.asarray(roller_state["load_flange"], dtype=float)
    width = geo.length / row.n_slices
    eta, alpha, e_red = (
        op.viscosity,
        float(op.lubricant.pressure_viscosity_at(op.temperature_C)),
        kernel.e_reduced,
    )
    rho_f = 0.5 * geo.d_l - geo.flange_height
    kin = tf.outer_control_kinematics(
        op.speed, op.cage_slip, geo.radius_inner, geo.radius_outer, geo.r_m, geo.radius_flange, rho_f
    )
    model = op.rolling_model
    ro_i = tf.rolling_friction_force(
        q_i, eta, kin.entrainment_inner, alpha, e_red, geo.radius_x_inner, width, model
    )
    ro_e = tf.rolling_friction_force(
        q_e, eta, kin.entrainment_outer, alpha, e_red, geo.radius_x_outer, width, model
    )
    sliding = dict(model=op.sliding_model, limiting_shear_coeff=op.limiting_shear_coeff)
    rs_i = tf.sliding_friction_force(
        kin.slide_inner,
        q_i,
        eta,
        kin.entrainment_inner,
        alpha,
        e_red,
        geo.radius_x_inner,
        width,
        op.exponent,
        **sliding,
    )
    rs_e = tf.sliding_friction_force(
        kin.slide_outer,
        q_e,
        eta,
        kin.entrainment_outer,
        alpha,
        e_red,
        geo.radius_x_outer,
        width,
        op.exponent,
        **sliding,
    )
    # Rib: spherical roller end (radius kernel.end_radius) on a flat rib, Hamrock–Dowson circular contact.
    loaded = q_f > 0
    lam = np.zeros_like(q_f)
    if np.any(loaded) and float(kin.entrainment_flange) > 0:
        r_end = kernel.end_radius
        film = ehl.film_point_hamrock_dowson(
            eta, kin.entrainment_flange, alpha, e_red, r_end, r_end, np.where(loaded, q_f, 1.0)
        )
        lam = np.where(
            loaded, ehl.film_parameter(film.minimum, op.roughness_roller_end, op.roughness_rib), 0.0
        )
    f_fs = flange_friction_force(q_f, lam, op.mu_coulomb)
    arm = geo.radius_flange if op.flange_arm == "geometric" else geo.radius_inner + geo.flange_height
    ro_i, ro_e, rs_i, rs_e = (a.sum(-1) for a in (ro_i, ro_e, rs_i, rs_e))
    m_e, m_i = tf.ring_torques(ro_e, rs_e, ro_i, rs_i, f_fs, geo.radius_outer, geo.radius_inner, arm)
    c = q_f.shape[0]
    conv = np.ones(c, dtype=bool) if converged is None else np.asarray(converged, dtype=bool)
    return TRBFrictionResult(
        load_inner=q_i.sum(-1),
        load_outer=q_e.sum(-1),
        load_flange=q_f,
        rolling_inner=ro_i,
        rolling_outer=ro_e,
        sliding_inner=rs_i,
        sliding_outer=rs_e,
        flange=f_fs,
        film_parameter_flange=lam,
        torque_outer=m_e,
        torque_inner=m_i,
        sliding_share_inner=np.divide(
            rs_i.sum(-1) * geo.radius_inner, m_i, out=np.zeros_like(np.asarray(m_i, float)), where=m_i != 0
        ),
        converged=conv,
        kinematics=kin,
        operating_point=op,
    )


@dataclass(frozen=True)
class SolvedRollers:
    """A batched TRB solve kept for repeated friction evaluations (different S_c, lubricants …)."""

    kernel: object
    roller_state: dict
    converged: np.ndarray

    def friction(self, op: TRBOperatingPoint) -> TRBFrictionResult:
        """Friction at operating point ``op`` (its speed should match the solve's centrifugal speed)."""
        return friction_from_state(self.kernel, self.roller_state, op, self.converged)


def solve_rollers(
    row: TaperedRow, axial_load, deviations=None, *, speed=0.0, free=SEED001_FREE
) -> SolvedRollers:
    """Solve ``row`` under a pure axial load for every realisation of ``deviations`` in one batch.

    Parameters
    ----------
    row : TaperedRow
        Template row (its ``diameter_deviation`` and ``speed`` are replaced).
    axial_load : float or array (C,) [N]
    deviations : array (Z,) or (C, Z) [m] or None
    speed : float [rad/s]
        Inner-ring speed for the roller centrifugal force.
    free : sequence of 5 bool
    """
    if not isinstance(row, TaperedRow):
        raise InputError(f"row ({type(row).__name__}) must be a TaperedRow")
    checks.finite("axial_load", axial_load, "N")
    if deviations is None:
        dev, n = None, 1
    else:
        dev = np.atleast_2d(np.asarray(deviations, dtype=float))
        n = dev.shape[0]
    row = dataclasses.replace(row, diameter_deviation=dev, speed=float(speed))
    fz = np.broadcast_to(np.asarray(axial_load, dtype=float), (n,)) * row.direction
    model = BearingModel((row,), name="tapered row", references=("liu2022",))
    res = solve(model, load_vector(F_z=fz), free=list(free))
    kernel = model.kernels[0]
    res.seed_rollers()  # the per-roller loads start where the compiled solve left them
    return SolvedRollers(kernel, kernel.roller_state(res.displacement), np.asarray(res.converged))


def tapered_friction(row: TaperedRow, axial_load, op: TRBOperatingPoint, deviations=None, free=SEED001_FREE):
    """Solve the row (batched over ``deviations``) and return its :class:`TRBFrictionResult`."""
    if not isinstance(op, TRBOperatingPoint):
        raise InputError(f"operating_point ({type(op).__name__}) must be a TRBOperatingPoint")
    return solve_rollers(row, axial_load, deviations, speed=op.speed, free=free).friction(op)


def friction_monte_carlo(
    row: TaperedRow,
    axial_load: float,
    op: TRBOperatingPoint,
    magnitudes=SEED001_MAGNITUDES,
    n_realisations: int = 1000,
    *,
    arrangement: str = "random",
    seed=None,
    per_realisation: bool = False,
    free=SEED001_FREE,
):
    """Monte Carlo of the TRB friction over Gaussian roller-diameter deviations, all S_d in one solve.

    Every magnitude S_d uses the same standard-normal draws scaled by S_d (common random numbers, as
    seed 001 Table 2 series 1/3/5), so differences between magnitudes are not sampling noise.

    Parameters
    ----------
    row : TaperedRow
    axial_load : float [N]
    op : TRBOperatingPoint
    magnitudes : sequence of float [m]
        Deviation magnitudes S_d (default seed 001's 0.5, 1, 1.5 µm).
    n_realisations : int
    arrangement : str
        ``"random"`` or ``"descending"``.
    seed : int or None
    per_realisation : bool
        Return one row per realisation instead of the per-S_d statistics.

    Returns
    -------
    pandas.DataFrame
        Statistics per S_d (``per_realisation=False``): ``magnitude_m``, ``n_realisations``,
        ``converged_fraction``, ``ideal_max_sliding_inner_N``, ``max_sliding_inner_{mean,std,p95,max}_N``,
        ``sliding_increment_{mean,p95}_N``, ``sliding_increment_ratio_{mean,p95}``,
        ``torque_{inner,outer}_change_ratio_mean``, ``max_contact_force_mean_N``. The increment is
        max_j F_rs,i − F_rs,i(ideal), its ratio over F_rs,i(ideal); torque change ratios are ΔM/M_ideal.
        Per realisation: ``magnitude_m``, ``realisation``, ``max_sliding_inner_N``, ``sliding_increment_N``,
        ``sliding_increment_ratio``, ``torque_inner_Nm``, ``torque_outer_Nm``, ``torque_inner_change_ratio``,
        ``torque_outer_change_ratio``, ``max_contact_force_N``, ``converged``.
    """
    import pandas as pd

    n = checks.integer("n_realisations", n_realisations, low=1)
    if np.ndim(axial_load) != 0:
        raise InputError(f"axial_load (shape {np.shape(axial_load)}) must be a scalar for a Monte Carlo run")
    mags = np.atleast_1d(np.asarray(magnitudes, dtype=float))
    if mags.ndim != 1 or mags.size == 0:
        raise InputError(f"magnitudes (shape {mags.shape}) must be a non-empty 1-D sequence")
    checks.non_negative("magnitudes", mags, "m")
    unit = gaussian_deviations(row.n_elements, 1.0, n, arrangement=arrangement, seed=seed)  # (n, Z) N(0,1)
    dev = (mags[:, None, None] * unit[None]).reshape(-1, row.n_elements)
    dev = np.concatenate([np.zeros((1, row.n_elements)), dev])  # case 0: ideal rollers
    res = tapered_friction(row, axial_load, op, dev, free=free)
    ideal_rs = res.max_sliding_inner[0]
    ideal_mi, ideal_me = res.torque_inner[0], res.torque_outer[0]
    max_rs = res.max_sliding_inner[1:].reshape(mags.size, n)
    inc = max_rs - ideal_rs
    ratio = inc / ideal_rs if ideal_rs > 0 else np.full_like(inc, np.nan)
    d_mi = (res.torque_inner[1:].reshape(mags.size, n) - ideal_mi) / ideal_mi
    d_me = (res.torque_outer[1:].reshape(mags.size, n) - ideal_me) / ideal_me
    qmax = res.load_outer[1:].max(-1).reshape(mags.size, n)
    conv = res.converged[1:].reshape(mags.size, n)
    if per_realisation:
        return pd.DataFrame(
            {
                "magnitude_m": np.repeat(mags, n),
                "realisation": np.tile(np.arange(n), mags.size),
                "max_sliding_inner_N": max_rs.ravel(),
                "sliding_increment_N": inc.ravel(),
                "sliding_increment_ratio": ratio.ravel(),
                "torque_inner_Nm": res.torque_inner[1:],
                "torque_outer_Nm": res.torque_outer[1:],
                "torque_inner_change_ratio": d_mi.ravel(),
                "torque_outer_change_ratio": d_me.ravel(),
                "max_contact_force_N": qmax.ravel(),
                "converged": conv.ravel(),
            }
        )
    return pd.DataFrame(
        {
            "magnitude_m": mags,
            "n_realisations": n,
            "converged_fraction": conv.mean(1),
            "ideal_max_sliding_inner_N": ideal_rs,
            "max_sliding_inner_mean_N": max_rs.mean(1),
            "max_sliding_inner_std_N": max_rs.std(1),
            "max_sliding_inner_p95_N": np.percentile(max_rs, 95, axis=1),
            "max_sliding_inner_max_N": max_rs.max(1),
            "sliding_increment_mean_N": inc.mean(1),
            "sliding_increment_p95_N": np.percentile(inc, 95, axis=1),
            "sliding_increment_ratio_mean": ratio.mean(1),
            "sliding_increment_ratio_p95": np.percentile(ratio, 95, axis=1),
            "torque_inner_change_ratio_mean": d_mi.mean(1),
            "torque_outer_change_ratio_mean": d_me.mean(1),
            "max_contact_force_mean_N": qmax.mean(1),
        }
    )


__all__ = [
    "DEFAULT_LUBRICANT",
    "FLANGE_ARMS",
    "SEED001_CAGE_SLIPS",
    "SEED001_MAGNITUDES",
    "SEED001_SPEED",
    "SolvedRollers",
    "TRBFrictionResult",
    "TRBOperatingPoint",
    "friction_from_state",
    "friction_monte_carlo",
    "solve_rollers",
    "tapered_friction",
]
