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
