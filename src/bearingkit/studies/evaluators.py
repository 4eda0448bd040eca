"""Registry of study evaluators: pure functions of a batch of cases → a table of outputs.

SI units: every factor column holds SI values (m, N, Pa, rad/s, °C for temperatures as the lubricant
API); every output column names its unit (``max_load_N``, ``friction_torque_Nm``).

An :class:`Evaluator` declares the factors it accepts (name, physical dimension used to parse the
study file, default) and computes a DataFrame of outputs, one row per case, from a DataFrame of cases.
It must be a pure function of the case values (no state, no randomness) so that any executor and any
chunking give the same numbers. Evaluators are looked up by name in :data:`REGISTRY`; a study may also
name one as ``"package.module:attribute"`` (an :class:`Evaluator` object importable on every worker).

Built-in evaluators:

- ``seed000_statics``: the seed-000 composite turntable bearing (Tian et al. 2025) solved by the
  batched quasi-static engine → row loads, ball share of the axial load, max loads and pressures;
- ``seed000_friction``: the same plus the friction torque (:mod:`bearingkit.analysis.friction`),
  registered only when that module imports;
- ``zdt1``: Zitzler–Deb–Thiele problem 1 (30 variables ``x1…x30`` → ``f1``, ``f2``), the cheap
  vectorised objective of tests and benchmarks.
"""

from __future__ import annotations

import dataclasses
import importlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np

from bearingkit import references
from bearingkit.errors import InputError

references.add(
    "zitzler2000",
    "Zitzler, E., Deb, K., Thiele, L. (2000). Comparison of Multiobjective Evolutionary Algorithms: "
    "Empirical Results. Evolutionary Computation 8(2):173–195. doi:10.1162/106365600568202",
)

#: Dimensions a factor may have besides the physical ones of :data:`bearingkit.units.SI_UNITS`.
NON_PHYSICAL = ("count", "text")


@dataclass(frozen=True)
class Factor:
    """A factor an evaluator accepts.

    Parameters
    ----------
    name : str
    dimension : str
        A key of :data:`bearingkit.units.SI_UNITS` (values in the study file need a unit unless
        ``"dimensionless"``), ``"count"`` (integer) or ``"text"`` (a name, e.g. a crowning type).
    default : object
        Value (SI) used when the study neither varies nor fixes the factor.
    batched : bool
        True when cases differing in this factor can share one vectorised solve; False groups the
        cases by its value (one solve per group).
    """

    name: str
    dimension: str
    default: object
    batched: bool = True


@dataclass(frozen=True)
class Evaluator:
    """A named pure function ``function(cases: DataFrame) -> DataFrame`` with its declared factors."""

    name: str
    function: Callable
    factors: Mapping[str, Factor]
    outputs: tuple = ()
    bearing_type: str | None = None
    description: str = ""
    references: tuple = field(default_factory=tuple)

    def complete(self, cases):
        """``cases`` with a column for every declared factor (defaults filled in)."""
        out = cases.copy()
        for name, f in self.factors.items():
            if name not in out.columns:
                out[name] = f.default
        return out

    def __call__(self, cases):
        unknown = [c for c in cases.columns if c not in self.factors and c != "case"]
        if unknown:
            raise InputError(
                f"evaluator {self.name!r}: unknown factors {unknown}; known: {list(self.factors)}"
            )
        cases = self.complete(cases).reset_index(drop=True)
        out = self.function(cases)
        if len(out) != len(cases):
            raise RuntimeError(f"evaluator {self.name!r} returned {len(out)} rows for {len(cases)} cases")
        return out


#: Evaluator name → Evaluator.
REGISTRY: dict[str, Evaluator] = {}


def register(evaluator: Evaluator) -> Evaluator:
    """Add (or replace) an evaluator under its name."""
    REGISTRY[evaluator.name] = evaluator
    return evaluator


def get(name: str) -> Evaluator:
    """The evaluator called ``name``, or importable as ``"module:attribute"``."""
    if name in REGISTRY:
        return REGISTRY[name]
    if ":" in name:
        mod, _, attr = name.partition(":")
        try:
            obj = getattr(importlib.import_module(mod), attr)
        except (ImportError, AttributeError) as exc:
            raise InputError(f"evaluator ({name!r}) cannot be imported: {exc}") from None
        if not isinstance(obj, Evaluator):
            raise InputError(f"evaluator ({name!r}) is a {type(obj).__name__}, not an Evaluator")
        return obj
    raise InputError(
        f"evaluator ({name!r}) must be one of {', '.join(sorted(REGISTRY))} or 'module:attribute'"
    )


def evaluate_chunk(evaluator_name: str, cases):
    """Evaluate one chunk (top-level, picklable: what executors send to workers).

    Returns the cases' ``case`` ids joined with the outputs.
    """
    ev = get(evaluator_name)
    ids = cases["case"].to_numpy() if "case" in cases.columns else np.arange(len(cases))
    out = ev(cases.drop(columns=["case"], errors="ignore"))
    out = out.reset_index(drop=True)
    out.insert(0, "case", ids)
    return out


# ------------------------------------------------------------------------------ seed 000 bearing
def _turntable_factors() -> dict[str, Factor]:
    from bearingkit.bearings.turntable import CompositeTurntableGeometry

    dims = {
        "groove_curvature": "dimensionless",
        "crowning": "text",
        "pairing": "text",
    }
    batched = {"clearance_axial_roller", "clearance_axial_ball", "clearance_radial", "groove_curvature"}
    out = {}
    for f in dataclasses.fields(CompositeTurntableGeometry):
        dim = dims.get(f.name, "count" if f.name.startswith("n_") else "length")
        out[f.name] = Factor(f.name, dim, f.default, f.name in batched)
    out["axial_load"] = Factor("axial_load", "force", 0.0)
    out["radial_load"] = Factor("radial_load", "force", 0.0)
    out["eccentricity"] = Factor("eccentricity", "length", 0.0)
    return out


#: Rows of the composite bearing (:func:`bearingkit.bearings.turntable.composite_turntable`).
TURNTABLE_ROWS = ("roller_upper", "ball_upper", "roller_lower", "ball_lower", "roller_radial")
#: Speed used when a friction study does not give one [rad/s]: 5 r/min, the test speed of seed 000 §5.
DEFAULT_SPEED = 5.0 * 2.0 * np.pi / 60.0


def _groups(cases, factors: Mapping[str, Factor]):
    """Split cases by the values of their non-batched factors → (index array, key dict)."""
    keys = [n for n, f in factors.items() if not f.batched and n in cases.columns]
    if not keys:
        yield np.arange(len(cases)), {}
        return
    for key, idx in cases.groupby(keys, sort=False, dropna=False).indices.items():
        key = key if isinstance(key, tuple) else (key,)
        yield np.asarray(idx), dict(zip(keys, key, strict=True))


def _py(value, factor: Factor):
    if factor.dimension == "count":
        return int(value)
    if factor.dimension == "text":
        return str(value)
    return float(value)


def _solve_turntable(cases, factors):
    """Yield (idx, QuasiStaticResult, group key) for every group of cases (one batched solve each)."""
    from bearingkit.analysis.quasistatic import solve
    from bearingkit.bearings.common import eccentric_axial_load
    from bearingkit.bearings.turntable import CompositeTurntableGeometry, composite_turntable

    geom = {f.name for f in dataclasses.fields(CompositeTurntableGeometry)}
    for idx, key in _groups(cases, factors):
        sub = cases.iloc[idx]
        kw = {k: _py(v, factors[k]) for k, v in key.items() if k in geom}
        for name in geom - set(key):
            kw[name] = sub[name].to_numpy(dtype=float)
        model = composite_turntable(**kw)
        load = eccentric_axial_load(
            sub["axial_load"].to_numpy(float),
            sub["eccentricity"].to_numpy(float),
            sub["radial_load"].to_numpy(float),
        )
        yield idx, solve(model, load), key


def _statics_table(res) -> dict:
    out = {}
    for name in TURNTABLE_ROWS:
        row, force = res.row(name), res.row_load(name)
        out[f"{name}_axial_N"] = np.abs(force[:, 2])
        out[f"{name}_radial_N"] = np.hypot(force[:, 0], force[:, 1])
        out[f"{name}_max_load_N"] = row.max_load
        out[f"{name}_loaded_count"] = row.loaded_count
        out[f"{name}_max_pressure_Pa"] = row.max_pressure.max(axis=-1)
    balls = out["ball_upper_axial_N"] + out["ball_lower_axial_N"]
    rollers = out["roller_upper_axial_N"] + out["roller_lower_axial_N"]
    total = balls + rollers
    out["ball_axial_share"] = np.divide(balls, total, out=np.zeros_like(total), where=total > 0)
    out["max_ball_pressure_Pa"] = np.maximum(
        out["ball_upper_max_pressure_Pa"], out["ball_lower_max_pressure_Pa"]
    )
    out["max_roller_pressure_Pa"] = np.maximum.reduce(
        [out[f"{r}_max_pressure_Pa"] for r in ("roller_upper", "roller_lower", "roller_radial")]
    )
    for k, lab in enumerate(("u_x_m", "u_y_m", "u_z_m", "theta_x_rad", "theta_y_rad")):
        out[lab] = res.displacement[:, k]
    out["converged"] = np.asarray(res.converged, bool)
    out["iterations"] = np.asarray(res.iterations, int)
    return out


def _assemble(n: int, parts):
    import pandas as pd

    cols: dict[str, np.ndarray] = {}
    for idx, table in parts:
        for k, v in table.items():
            v = np.asarray(v)
            if k not in cols:
                cols[k] = np.zeros(n, dtype=v.dtype)
            cols[k][idx] = v
    return pd.DataFrame(cols)


def seed000_statics(cases):
    """Statics of the seed-000 composite turntable bearing for a batch of cases.

    Loads: an axial force ``axial_load`` [N] at ``eccentricity`` [m] along +x (M_y = −e·F_a) and a
    radial force ``radial_load`` [N] along +x (:func:`bearingkit.bearings.common.eccentric_axial_load`).
    Geometry factors are the fields of :class:`~bearingkit.bearings.turntable.CompositeTurntableGeometry`.
    Clearances and groove curvature batch along the case axis; other geometry groups the cases.
    """
    parts = [(idx, _statics_table(res)) for idx, res, _ in _solve_turntable(cases, SEED000_FACTORS)]
    return _assemble(len(cases), parts)


SEED000_FACTORS = _turntable_factors()
register(
    Evaluator(
        "seed000_statics",
        seed000_statics,
        SEED000_FACTORS,
        outputs=("ball_axial_share", "max_ball_pressure_Pa", "max_roller_pressure_Pa"),
        bearing_type="composite_turntable",
        description="seed-000 composite turntable bearing: row loads, ball share, max loads and pressures",
        references=("tian2025",),
    )
)


# ------------------------------------------------------------------------------ seed 000 friction
def _friction_factors() -> dict[str, Factor]:
    from bearingkit.analysis.friction import OperatingPoint

    defaults = {f.name: f.default for f in dataclasses.fields(OperatingPoint)}
    out = dict(SEED000_FACTORS)
    out["speed"] = Factor("speed", "angular_velocity", DEFAULT_SPEED)
    out["temperature"] = Factor("temperature", "temperature", defaults["temperature"], batched=False)
    out["lubricant"] = Factor("lubricant", "text", defaults["lubricant"], batched=False)
    out["viscosity_factor"] = Factor("viscosity_factor", "dimensionless", 1.0, batched=False)
    out["cage_mass"] = Factor("cage_mass", "mass", defaults["cage_mass"], batched=False)
    return out


def seed000_friction(cases):
    """Statics (:func:`seed000_statics`) plus the friction torque of the seed-000 bearing [N·m].

    Operating point: inner ring at ``speed`` [rad/s], outer ring fixed, ``lubricant`` at ``temperature``
    [°C], ``viscosity_factor`` and ``cage_mass`` [kg] as :class:`bearingkit.analysis.friction.OperatingPoint`.
    """
    from bearingkit.analysis.friction import OperatingPoint, friction_torque

    parts = []
    for idx, res, key in _solve_turntable(cases, FRICTION_FACTORS):
        sub = cases.iloc[idx]
        op = OperatingPoint(
            speed_inner=sub["speed"].to_numpy(float),
            lubricant=str(key["lubricant"]),
            temperature=float(key["temperature"]),
            viscosity_factor=float(key["viscosity_factor"]),
            cage_mass=float(key["cage_mass"]),
        )
        fr = friction_torque(res, op)
        table = _statics_table(res)
        table["friction_torque_Nm"] = fr.total
        for name, v in fr.components.items():
            table[f"torque_{name}_Nm"] = v
        parts.append((idx, table))
    return _assemble(len(cases), parts)


try:  # friction lands with its own issue; register when it imports
    FRICTION_FACTORS = _friction_factors()
except ImportError:  # pragma: no cover
    FRICTION_FACTORS = None
else:
    register(
        Evaluator(
            "seed000_friction",
            seed000_friction,
            FRICTION_FACTORS,
            outputs=("friction_torque_Nm",),
            bearing_type="composite_turntable",
            description="seed-000 composite turntable bearing: statics + friction torque",
            references=("tian2025",),
        )
    )


# ------------------------------------------------------------------------------ analytic problems
#: Number of decision variables of ZDT1 (Zitzler et al. 2000).
ZDT1_VARIABLES = 30


def zdt1(cases):
    """ZDT1 (Zitzler et al. 2000, eq. T1): f1 = x1, g = 1 + 9 Σ_{i≥2} x_i/(n−1), f2 = g (1 − √(f1/g)).

    Pareto front: g = 1 (x2…xn = 0), f2 = 1 − √f1, f1 ∈ [0, 1].
    """
    import pandas as pd

    x = cases[[f"x{i}" for i in range(1, ZDT1_VARIABLES + 1)]].to_numpy(float)
    f1 = x[:, 0]
    g = 1.0 + 9.0 * x[:, 1:].sum(axis=1) / (ZDT1_VARIABLES - 1)
    return pd.DataFrame({"f1": f1, "f2": g * (1.0 - np.sqrt(np.clip(f1 / g, 0.0, None))), "g": g})


register(
    Evaluator(
        "zdt1",
        zdt1,
        {f"x{i}": Factor(f"x{i}", "dimensionless", 0.0) for i in range(1, ZDT1_VARIABLES + 1)},
        outputs=("f1", "f2"),
        description="ZDT1 test problem (Zitzler, Deb, Thiele 2000)",
        references=("zitzler2000",),
    )
)


# ------------------------------------------------------------------------------ seed studies (issue 9)
# ``seed001_scatter``: seed-001 TRB 32008J (Liu et al. 2022) with Gaussian roller-diameter scatter,
# ΔD_j = S_d z_j (eq. 14): the study samples the unit draws z1…zZ, the evaluator solves every
# realisation plus the ideal bearing in one batch → max contact force and sliding-friction increment.
# ``seed002_clearance``: seed-002 ball–column bearing (Li et al. 2025) → radial-load shares of the rows
# for ball-row / roller-row radial clearances and loads (rigid, or flexible outer ring).
# ``seed004_ptrb``: seed-004 PTRB §6 objectives (Zheng et al. 2022) C0, C, M of a design population.
def _seed001_factors() -> dict[str, Factor]:
    from bearingkit.analysis.trb_friction import (
        DEFAULT_LUBRICANT,
        DEFAULT_TEMPERATURE_C,
        SEED001_SPEED,
        TRBOperatingPoint,
    )
    from bearingkit.bearings.tapered import SEED001_GEOMETRY

    out = {
        f"z{j}": Factor(f"z{j}", "dimensionless", 0.0) for j in range(1, SEED001_GEOMETRY["n_elements"] + 1)
    }
    out["magnitude"] = Factor("magnitude", "length", 1.0e-6)
    out["arrangement"] = Factor("arrangement", "text", "random", batched=False)
    out["axial_load"] = Factor("axial_load", "force", SEED001_AXIAL_LOAD, batched=False)
    out["speed"] = Factor("speed", "angular_velocity", SEED001_SPEED, batched=False)
    out["cage_slip"] = Factor("cage_slip", "dimensionless", 1.0e-4, batched=False)
    out["lubricant"] = Factor("lubricant", "text", DEFAULT_LUBRICANT, batched=False)
    out["temperature"] = Factor("temperature", "temperature", DEFAULT_TEMPERATURE_C, batched=False)
    # Reading of seed 001 eq. (8) (bearingkit.physics.friction.trb.SLIDING_MODELS), so a study can
    # compare the capped default with the equation as printed ("newtonian").
    out["sliding_model"] = Factor("sliding_model", "text", TRBOperatingPoint().sliding_model, batched=False)
    return out


#: Axial load of seed 001 §3 (Figs. 5–7: F_a = 10 kN) [N].
SEED001_AXIAL_LOAD = 10_000.0


def _ratio(x, ref):
    return np.divide(x - ref, ref, out=np.full(np.shape(x), np.nan), where=np.asarray(ref) != 0)


def seed001_scatter(cases):
    """Seed-001 TRB with roller-diameter scatter: contact and sliding-friction response per realisation.

    Roller j of a case gets ΔD_j = S_d z_j (Liu et al. 2022, eq. 14: ΔD ~ N(0, S_d²)) with ``magnitude``
    S_d [m] and the unit draws ``z1…zZ`` [1] (sampled by the study), arranged by ``arrangement``
    (:data:`bearingkit.physics.deviations.ARRANGEMENTS`). Each group of cases is one batched solve
    (:func:`bearingkit.analysis.trb_friction.tapered_friction`) with the ideal bearing as an extra case,
    at ``axial_load`` [N], ``speed`` [rad/s], ``cage_slip`` [1], ``lubricant`` at ``temperature`` [°C],
    with eq. (8) read as ``sliding_model`` (default: the capped ``"limiting_shear"``).

    Outputs: ``max_contact_force_N`` (max_j Q_e,j), its ``contact_force_increment_ratio`` over the ideal
    bearing's, ``contact_force_variance_N2``, ``max_sliding_inner_N`` (max_j F_rs,i), the
    ``sliding_increment_N`` = max_j F_rs,i − F_rs,i(ideal) and its ratio, the ring torques [N·m] and their
    change ratios ΔM/M_ideal (as :func:`~bearingkit.analysis.trb_friction.friction_monte_carlo`).
    """
    from bearingkit import checks
    from bearingkit.analysis.trb_friction import TRBOperatingPoint, tapered_friction
    from bearingkit.bearings.tapered import seed001_row
    from bearingkit.physics.deviations import arrange

    row = seed001_row()
    zcols = [f"z{j}" for j in range(1, row.n_elements + 1)]
    parts = []
    for idx, key in _groups(cases, SEED001_FACTORS):
        sub = cases.iloc[idx]
        s_d = checks.non_negative("magnitude", sub["magnitude"].to_numpy(float), "m")
        dev = arrange(s_d[:, None] * sub[zcols].to_numpy(float), str(key["arrangement"]))
        dev = np.concatenate([np.zeros((1, row.n_elements)), dev])  # case 0: ideal rollers
        op = TRBOperatingPoint(
            speed=float(key["speed"]),
            cage_slip=float(key["cage_slip"]),
            lubricant=str(key["lubricant"]),
            temperature_C=float(key["temperature"]),
            sliding_model=str(key["sliding_model"]),
        )
        res = tapered_friction(row, float(key["axial_load"]), op, dev)
        q_max = res.load_outer.max(axis=-1)
        f_rs = res.max_sliding_inner
        parts.append(
            (
                idx,
                {
                    "max_contact_force_N": q_max[1:],
                    "ideal_max_contact_force_N": np.full(idx.size, q_max[0]),
                    "contact_force_increment_ratio": _ratio(q_max[1:], q_max[0]),
                    "contact_force_variance_N2": res.load_outer[1:].var(axis=-1),
                    "max_sliding_inner_N": f_rs[1:],
                    "ideal_max_sliding_inner_N": np.full(idx.size, f_rs[0]),
                    "sliding_increment_N": f_rs[1:] - f_rs[0],
                    "sliding_increment_ratio": _ratio(f_rs[1:], f_rs[0]),
                    "torque_inner_Nm": res.torque_inner[1:],
                    "torque_outer_Nm": res.torque_outer[1:],
                    "torque_inner_change_ratio": _ratio(res.torque_inner[1:], res.torque_inner[0]),
                    "torque_outer_change_ratio": _ratio(res.torque_outer[1:], res.torque_outer[0]),
                    "converged": np.asarray(res.converged[1:], bool) & bool(res.converged[0]),
                },
            )
        )
    return _assemble(len(cases), parts)


SEED001_FACTORS = _seed001_factors()
register(
    Evaluator(
        "seed001_scatter",
        seed001_scatter,
        SEED001_FACTORS,
        outputs=("max_contact_force_N", "sliding_increment_N", "sliding_increment_ratio"),
        description="seed-001 TRB 32008J: roller-diameter scatter → max contact force, sliding increment",
        references=("liu2022",),
    )
)


# ------------------------------------------------------------------------------ seed 002 clearance map
#: Rows of the seed-002 ball–column bearing (:data:`bearingkit.bearings.ball_column.ROWS`).
SEED002_ROWS = ("ball_1", "roller_2", "ball_3")


def _seed002_factors() -> dict[str, Factor]:
    from bearingkit.bearings.ball_column import BallColumnGeometry

    g = BallColumnGeometry()
    return {
        "clearance_ball": Factor("clearance_ball", "length", g.clearance_ball),
        "clearance_roller": Factor("clearance_roller", "length", g.clearance_roller),
        "radial_load": Factor("radial_load", "force", 20_000.0),  # condition 1 of Li et al. Table 2
        "axial_load": Factor("axial_load", "force", 0.0),
        "compliance_scale": Factor("compliance_scale", "dimensionless", 0.0, batched=False),
        "contact_angle": Factor("contact_angle", "angle", g.contact_angle, batched=False),
        "n_balls": Factor("n_balls", "count", g.n_balls, batched=False),
        "n_rollers": Factor("n_rollers", "count", g.n_rollers, batched=False),
    }


def seed002_clearance(cases):
    """Seed-002 ball–column bearing: radial-load share of each row vs clearances and load.

    ``clearance_ball`` / ``clearance_roller`` [m] are the radial (diametral) clearances of the ball rows
    and of the roller row (batched along the case axis with the loads), ``radial_load`` [N] acts along
    +x and ``axial_load`` [N] along +z. ``compliance_scale`` 0 solves with rigid rings
    (:func:`bearingkit.analysis.quasistatic.solve`); > 0 couples the flexible outer ring of
    :func:`bearingkit.bearings.ball_column.outer_ring` (:func:`bearingkit.analysis.flexible.solve_flexible`,
    via :func:`bearingkit.studies.seed002.solve_case`: beam + ovalisation in the default housing). The
    share of row r is |F_r,radial| / Σ_rows.
    """
    from bearingkit.analysis.quasistatic import load_vector
    from bearingkit.bearings.ball_column import BallColumnGeometry
    from bearingkit.studies.seed002 import solve_case

    parts = []
    for idx, key in _groups(cases, SEED002_FACTORS):
        sub = cases.iloc[idx]
        geom = BallColumnGeometry(
            clearance_ball=sub["clearance_ball"].to_numpy(float),
            clearance_roller=sub["clearance_roller"].to_numpy(float),
            contact_angle=float(key["contact_angle"]),
            n_balls=int(key["n_balls"]),
            n_rollers=int(key["n_rollers"]),
        )
        load = load_vector(F_x=sub["radial_load"].to_numpy(float), F_z=sub["axial_load"].to_numpy(float))
        res, flex = solve_case(geom, load, float(key["compliance_scale"]))
        radial = {n: np.hypot(*res.row_load(n)[:, :2].T) for n in SEED002_ROWS}
        total = sum(radial.values())
        table = {}
        for n in SEED002_ROWS:
            table[f"{n}_radial_N"] = radial[n]
            table[f"{n}_radial_share"] = np.divide(
                radial[n], total, out=np.zeros_like(total), where=total > 0
            )
            table[f"{n}_loaded_count"] = res.row(n).loaded_count
            table[f"{n}_max_load_N"] = res.row(n).max_load
            table[f"{n}_max_pressure_Pa"] = res.row(n).max_pressure.max(axis=-1)
        table["roller_radial_share"] = table["roller_2_radial_share"]
        table["converged"] = np.asarray(res.converged if flex is None else flex.converged, bool)
        parts.append((idx, table))
    return _assemble(len(cases), parts)


SEED002_FACTORS = _seed002_factors()
register(
    Evaluator(
        "seed002_clearance",
        seed002_clearance,
        SEED002_FACTORS,
        outputs=("roller_radial_share",),
        description="seed-002 ball–column bearing: radial-load shares of the rows vs clearances and load",
        references=("li2025",),
    )
)


# ------------------------------------------------------------------------------ seed 004 PTRB objectives
def _seed004_factors() -> dict[str, Factor]:
    from bearingkit.analysis.ptrb_friction import RPM, TEST_TEMPERATURE_C
    from bearingkit.bearings.ptrb import ptrb_prototype

    p = ptrb_prototype()
    return {
        "contact_angle": Factor("contact_angle", "angle", p.contact_angle),
        "n_teeth": Factor("n_teeth", "count", p.n_teeth),
        "roller_contact_radius": Factor("roller_contact_radius", "length", p.roller_contact_radius),
        "roller_pitch_diameter": Factor("roller_pitch_diameter", "length", p.roller_pitch_diameter),
        "load_case": Factor("load_case", "text", "axial", batched=False),
        "load": Factor("load", "force", 20.0e3, batched=False),  # §6: 20 kN
        "speed": Factor("speed", "angular_velocity", 4000.0 * RPM, batched=False),  # §6: 4000 rpm
        "n_elements": Factor("n_elements", "count", 11, batched=False),  # §6: the maximum Z
        "lubricant": Factor("lubricant", "text", "L-AN", batched=False),
        "temperature": Factor("temperature", "temperature", TEST_TEMPERATURE_C, batched=False),
    }


def seed004_ptrb(cases):
    """Seed-004 PTRB §6 objectives of a design population (Zheng et al. 2022).

    Design variables α = ``contact_angle`` [rad], n = ``n_teeth`` [1], R_rr = ``roller_contact_radius``
    [m], d_R = ``roller_pitch_diameter`` [m] (D_pw and n·P held, Z = ``n_elements``) →
    :func:`bearingkit.analysis.ptrb_friction.ptrb_objectives` under ``load`` [N] of ``load_case``
    (axial/radial) at ``speed`` [rad/s]. Outputs: ``C0_N``, ``C_N`` (ratings of the load case), ``M_Nm``,
    ``mu``, the four ratings, the Hertz-validity margin ``hertz_margin_m`` = 2 R_rr cos α − d_R (§5 (3)–(4),
    feasible ≥ 0) and ``feasible``.
    """
    from bearingkit.analysis.ptrb_friction import ptrb_objectives

    parts = []
    for idx, key in _groups(cases, SEED004_FACTORS):
        sub = cases.iloc[idx]
        alpha = sub["contact_angle"].to_numpy(float)
        r_rr = sub["roller_contact_radius"].to_numpy(float)
        d_r = sub["roller_pitch_diameter"].to_numpy(float)
        o = ptrb_objectives(
            alpha,
            sub["n_teeth"].to_numpy(float),
            r_rr,
            d_r,
            case=str(key["load_case"]),
            load=float(key["load"]),
            speed=float(key["speed"]),
            n_elements=int(key["n_elements"]),
            lubricant=str(key["lubricant"]),
            temperature_C=float(key["temperature"]),
        )
        table = {f"{k}_N": o[k] for k in ("C0", "C", "C0a", "Ca", "C0r", "Cr")}
        table.update(M_Nm=o["M"], mu=o["mu"], feasible=np.asarray(o["feasible"], bool))
        table["hertz_margin_m"] = 2.0 * r_rr * np.cos(alpha) - d_r
        parts.append((idx, table))
    return _assemble(len(cases), parts)


SEED004_FACTORS = _seed004_factors()
register(
    Evaluator(
        "seed004_ptrb",
        seed004_ptrb,
        SEED004_FACTORS,
        outputs=("C0_N", "C_N", "M_Nm"),
        description="seed-004 PTRB §6: load ratings C0, C and friction torque M of a design population",
        references=("zheng2022",),
    )
)
