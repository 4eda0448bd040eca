"""Seed-000 friction studies: the single-factor sweeps of Tian et al. (2025) §5.3 and §6.1, with breakdowns.

SI units inside (N, m, Pa, rad/s, N·m); speeds are given in r/min only at the edge (``rpm``
arguments) and converted by :meth:`~bearingkit.analysis.friction.components.OperatingPoint.from_rpm`.
Every study returns a :class:`pandas.DataFrame` with one line per case and units in the column
names: ``total_Nm``, one ``<component>_Nm`` column per friction component (they add up to the
total), one ``row_<row>_Nm`` column per row plus ``row_cage_Nm`` (they add up to the total too),
``max_pressure_<row>_Pa`` per row, ``max_pressure_ball_Pa`` / ``max_pressure_roller_Pa`` and
``converged``.

Studies (Tian et al. 2025, Machines 13:588, doi:10.3390/machines13070588):

=====================  ==========================================================================
:func:`speed_sweep`     5–90 r/min, F_a = 2 kN, clearances roller 0 / ball −2 µm (§5.3.2, Fig. 11)
:func:`axial_load_sweep` F_a 0–8 kN at 5 r/min (§5.3.2, Fig. 12)
:func:`moment_sweep`    M 0–400 N·m (§5.3.2, Fig. 13)
:func:`composite_vs_yrt` composite vs YRT-type bearing, F_a 0–6 kN (§5.3.1, Fig. 10)
:func:`clearance_map`   roller 0/−1/−2 µm × ball 0…−6 µm at F_a = 5 kN (§6.1.1, Fig. 14)
:func:`groove_sweep`    groove coefficient 0.505–0.54 (§6.1.2, Fig. 15)
:func:`eccentricity_sweep` e = 0–0.6 m, F_a = F_r = 3 kN (§6.1.3, Fig. 16)
:func:`ratio_study`     balls/rollers 31/31, 42/21, 48/16 at M = 600 N·m (§6.1.4, Fig. 17)
:func:`crowning_study`  crowning a–e at M = 600 N·m (§6.1.5, Fig. 18)
=====================  ==========================================================================

Model readings (:data:`VARIANTS`, keyed by documented names) fix the choices the paper leaves open
(slice-law pairing, crowning of the base bearing, the spin coefficient f_s of M4, the viscous
models, the YRT clearance); ``"seed000"`` is the validated reading of
:mod:`bearingkit.papers.tian2025.validation` with the constants of
:mod:`bearingkit.papers.tian2025.calibration`. A variant with ``roller_sliding=None`` has its roller
sliding coefficient μ_rs identified once on Table 3 run 1 (the single calibration of the seed-000
reproduction) by :func:`calibrated_sliding`; ``viscous_only`` is the reading before issue 32 (no
μ_rs, the grease viscosity factor identified on run 1 instead, :func:`calibrated_factor`).
``python -m bearingkit.papers.tian2025.friction OUT`` writes CSV + PNG.
"""

from __future__ import annotations

import dataclasses
import functools
import sys
from pathlib import Path

import numpy as np

from bearingkit import checks, references
from bearingkit.analysis.friction.components import COMPONENT_NAMES, OperatingPoint, friction_torque
from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings.common import eccentric_axial_load
from bearingkit.bearings.turntable import composite_turntable, yrt_turntable
from bearingkit.papers.tian2025 import validation as v000
from bearingkit.papers.tian2025.friction_plots import (
    _pyplot,
    plot_clearance_map,
    plot_composite_vs_yrt,
    plot_study,
)
from bearingkit.papers.tian2025.friction_variants import (  # noqa: F401 (re-exported: its home before the split)
    SLIDING_READINGS,
    SPIN_READINGS,
    VARIANTS,
    FrictionVariant,
    _variant,
)

references.add(
    "schaeffler_yrt",
    "Schaeffler Technologies (2019) Rotary table bearings YRT, YRTC, YRTS, ZKLDF, YRTM, YRTSM (catalogue "
    "TPI 120 / HG 1): YRT bearings are supplied axially and radially preloaded; catalogue frictional "
    "torque M_RL at 5 r/min.",
)

#: Speeds of the §5.3.2 speed test [r/min] (Fig. 11 spans 5–90 r/min).
SPEEDS_RPM = (5.0, 10.0, 20.0, 30.0, 45.0, 60.0, 75.0, 90.0)
#: Axial loads of Fig. 12 [N] and Fig. 10 [N].
AXIAL_LOADS = tuple(np.linspace(0.0, 8000.0, 9))
YRT_AXIAL_LOADS = tuple(np.linspace(0.0, 6000.0, 7))
#: Overturning moments of Fig. 13 [N·m].
MOMENTS = tuple(np.linspace(0.0, 400.0, 9))
#: Clearance grid of §6.1.1 [m].
ROLLER_CLEARANCES = (0.0, -1e-6, -2e-6)
BALL_CLEARANCES = tuple(-1e-6 * np.arange(7))
#: Groove curvature coefficients of §6.1.2 [-].
GROOVES = (0.505, 0.51, 0.515, 0.52, 0.525, 0.53, 0.535, 0.54)
#: Eccentricities of §6.1.3 [m].
ECCENTRICITIES = tuple(np.linspace(0.0, 0.6, 7))
#: Ball/roller counts per axial row of §6.1.4 (balls, rollers).
RATIOS = ((31, 31), (42, 21), (48, 16))
#: Base operating speed of every study but the speed test [r/min] (the §5 test speed).
RPM = v000.RPM


def operating_point(variant="seed000", rpm=RPM, viscosity_factor=None) -> OperatingPoint:
    """The seed-000 operating point of ``variant`` at ``rpm`` [r/min] (inner ring turning)."""
    v = _variant(variant)
    vf = viscosity_factor or v.viscosity_factor or calibrated_factor(v)
    mu_rs = v.roller_sliding if v.roller_sliding is not None else calibrated_sliding(v)
    return v000.operating_point(
        rpm,
        vf,
        roller_sliding=mu_rs,
        viscous_line_model=v.viscous_line_model,
        viscous_point_model=v.viscous_point_model,
        raceway_control=v.raceway_control,
    )


def _friction(res, op: OperatingPoint, spin: str, sliding: str = "mixed"):
    """Friction of a solved batch with the spin coefficient read as ``spin`` → (components, by_row).

    ``"mixed"`` is :func:`friction_torque` as is (f_s interpolated by Λ like E2). For ``"boundary"``
    / ``"ehl"`` a second evaluation with μ_bl = μ_EHL = f_s gives the spin of the ball rows (spin is
    linear in μ and the only μ-dependent ball-row term); the roller rows keep the first evaluation.
    ``sliding`` (:data:`SLIDING_READINGS`) likewise re-evaluates E2, the only μ-dependent term of the
    roller rows, with that reading's (μ_bl, μ_EHL); the ball rows keep theirs.
    """
    base = friction_torque(res, op)
    comps, rows = dict(base.components), dict(base.by_row)
    if spin != "mixed":
        mu = op.mu_boundary if spin == "boundary" else op.mu_ehl
        alt = friction_torque(res, dataclasses.replace(op, mu_boundary=mu, mu_ehl=mu))
        comps["spin_ball"] = alt.components["spin_ball"]
        for row in res.model.rows:
            if row.kind == "ball":
                rows[row.name] = alt.by_row[row.name]
    if SLIDING_READINGS[sliding] is not None:
        mu_bl, mu_ehl = SLIDING_READINGS[sliding]
        alt = friction_torque(res, dataclasses.replace(op, mu_boundary=mu_bl, mu_ehl=mu_ehl))
        comps["differential_sliding"] = alt.components["differential_sliding"]
        for row in res.model.rows:
            if row.kind == "cylindrical":
                rows[row.name] = alt.by_row[row.name]
    return comps, rows


def evaluate(model, load, variant="seed000", rpm=RPM, viscosity_factor=None, extra=None):
    """Solve ``model`` under ``load`` (C, 5) and tabulate the friction torque and its breakdowns.

    Parameters
    ----------
    model : BearingModel
    load : array (C, 5) [N, N·m]
    variant : str or FrictionVariant
    rpm : float or (C,) array [r/min]
        Inner-ring speed (outer ring fixed).
    viscosity_factor : float, optional
        Overrides the variant's factor.
    extra : dict, optional
        Columns (C,) to put first (the swept factor).

    Returns
    -------
    pandas.DataFrame
    """
    import pandas as pd

    v = _variant(variant)
    res = solve(model, np.atleast_2d(load))
    op = operating_point(v, rpm, viscosity_factor)
    comps, rows = _friction(res, op, v.spin, v.sliding)
    out = dict(extra or {})
    out["total_Nm"] = sum(comps.values())
    out.update({f"{k}_Nm": comps[k] for k in COMPONENT_NAMES})
    out.update({f"row_{k}_Nm": val for k, val in rows.items()})
    ball, roller = np.zeros(res.n_cases), np.zeros(res.n_cases)
    for row, state in zip(res.model.rows, res.rows, strict=True):
        p = state.max_pressure.max(axis=-1)
        out[f"max_pressure_{row.name}_Pa"] = p
        if row.kind == "ball":
            ball = np.maximum(ball, p)
        else:
            roller = np.maximum(roller, p)
    out["max_pressure_ball_Pa"] = ball
    out["max_pressure_roller_Pa"] = roller
    out["converged"] = res.converged
    return pd.DataFrame(out)


# --- calibration of a reading -----------------------------------------------------------------------
def _table3_loads():
    e = np.array([r[3] for r in v000.TABLE3])
    return eccentric_axial_load(3000.0, e, radial_load=3000.0)


def table3(variant="seed000", viscosity_factor=None):
    """Table 3 (L9) runs 1–9: computed vs published friction torque [N·m] (one batched solve)."""
    v = _variant(variant)
    t = np.array(v000.TABLE3)
    model = composite_turntable(
        clearance_axial_roller=t[:, 0] * 1e-6,
        clearance_axial_ball=t[:, 1] * 1e-6,
        groove_curvature=t[:, 2],
        **v.geometry,
    )
    df = evaluate(
        model,
        _table3_loads(),
        v,
        viscosity_factor=viscosity_factor,
        extra={"run": np.arange(1, 10), "eccentricity_m": t[:, 3], "published_Nm": t[:, 4] / 1e3},
    )
    df["rel_error"] = df["total_Nm"] / df["published_Nm"] - 1.0
    return df


def _run1(v: FrictionVariant):
    """Table 3 run 1 solved with ``v``'s geometry, and its published torque [N·m]."""
    t = np.array(v000.TABLE3[0])
    model = composite_turntable(
        clearance_axial_roller=t[0] * 1e-6,
        clearance_axial_ball=t[1] * 1e-6,
        groove_curvature=t[2],
        **v.geometry,
    )
    load = eccentric_axial_load(3000.0, t[3], radial_load=3000.0)
    return solve(model, np.atleast_2d(load)), t[4] / 1e3


@functools.cache
def calibrated_factor(variant: FrictionVariant) -> float:
    """η_eff/η_base that meets Table 3 run 1 (2.8717 N·m) with ``variant``'s μ_rs (0 if unset)."""
    from scipy.optimize import brentq

    v = dataclasses.replace(variant, viscosity_factor=1.0, roller_sliding=variant.roller_sliding or 0.0)
    res, target = _run1(v)

    def err(x):
        comps, _ = _friction(res, operating_point(v, RPM, x), v.spin, v.sliding)
        return float(sum(comps.values())[0]) - target

    return float(brentq(err, 0.05, 200.0, xtol=1e-4))


@functools.cache
def calibrated_sliding(variant: FrictionVariant) -> float:
    """μ_rs that meets Table 3 run 1 (2.8717 N·m) with ``variant``'s viscosity factor (the calibration)."""
    from scipy.optimize import brentq

    if variant.viscosity_factor is None:
        raise checks.InputError(f"variant {variant.name!r}: give viscosity_factor to identify roller_sliding")
    res, target = _run1(variant)

    def err(mu):
        v = dataclasses.replace(variant, roller_sliding=mu)
        comps, _ = _friction(res, operating_point(v, RPM), v.spin, v.sliding)
        return float(sum(comps.values())[0]) - target

    if err(0.0) > 0:
        raise checks.InputError(f"variant {variant.name!r} exceeds Table 3 run 1 without roller sliding")
    return float(brentq(err, 0.0, 0.1, xtol=1e-8))


# --- the studies ---------------------------------------------------------------------------------------
def _composite(v, **kw):
    return composite_turntable(**{**v.geometry, **kw})


def speed_sweep(speeds_rpm=SPEEDS_RPM, axial_load=2000.0, variant="seed000"):
    """Torque vs inner-ring speed (§5.3.2(1), Fig. 11): F_a = 2 kN, roller 0 µm, ball −2 µm."""
    v, n = _variant(variant), np.asarray(speeds_rpm, float)
    load = np.repeat(load_vector(F_z=axial_load)[None], n.size, axis=0)
    model = _composite(v, clearance_axial_roller=0.0, clearance_axial_ball=-2e-6)
    return evaluate(model, load, v, rpm=n, extra={"speed_rpm": n})


def axial_load_sweep(axial_loads=AXIAL_LOADS, variant="seed000"):
    """Torque vs axial load at 5 r/min (§5.3.2(2), Fig. 12): roller 0 µm, ball −2 µm."""
    v, f = _variant(variant), np.asarray(axial_loads, float)
    model = _composite(v, clearance_axial_roller=0.0, clearance_axial_ball=-2e-6)
    return evaluate(model, load_vector(F_z=f), v, extra={"axial_load_N": f})


def moment_sweep(moments=MOMENTS, variant="seed000"):
    """Torque vs overturning moment M_y = −M (§5.3.2(3), Fig. 13): roller 0 µm, ball −2 µm, F_a = 0."""
    v, m = _variant(variant), np.asarray(moments, float)
    model = _composite(v, clearance_axial_roller=0.0, clearance_axial_ball=-2e-6)
    return evaluate(model, load_vector(M_y=-m), v, extra={"moment_Nm": m})


def composite_vs_yrt(axial_loads=YRT_AXIAL_LOADS, variant="seed000"):
    """Composite (roller 0, ball −2 µm) vs YRT-type bearing at 5 r/min, F_a 0–6 kN (§5.3.1, Fig. 10).

    Returns one line per (bearing, load) with a ``bearing`` column (``"composite"`` / ``"yrt"``).
    """
    import pandas as pd

    v, f = _variant(variant), np.asarray(axial_loads, float)
    comp = evaluate(
        _composite(v, clearance_axial_roller=0.0, clearance_axial_ball=-2e-6),
        load_vector(F_z=f),
        v,
        extra={"bearing": np.full(f.size, "composite"), "axial_load_N": f},
    )
    yrt = evaluate(
        yrt_turntable(clearance_axial_roller=v.yrt_clearance, **v.geometry),
        load_vector(F_z=f),
        v,
        extra={"bearing": np.full(f.size, "yrt"), "axial_load_N": f},
    )
    return pd.concat([comp, yrt], ignore_index=True).fillna(0.0)


def clearance_map(
    roller_clearances=ROLLER_CLEARANCES, ball_clearances=BALL_CLEARANCES, axial_load=5000.0, variant="seed000"
):
    """Torque over axial roller × ball clearance at F_a = 5 kN (§6.1.1, Fig. 14), one batched solve."""
    v = _variant(variant)
    rc, bc = np.meshgrid(
        np.asarray(roller_clearances, float), np.asarray(ball_clearances, float), indexing="ij"
    )
    rc, bc = rc.ravel(), bc.ravel()
    model = _composite(v, clearance_axial_roller=rc, clearance_axial_ball=bc)
    load = np.repeat(load_vector(F_z=axial_load)[None], rc.size, axis=0)
    return evaluate(model, load, v, extra={"roller_clearance_m": rc, "ball_clearance_m": bc})


def groove_sweep(grooves=GROOVES, axial_load=5000.0, variant="seed000"):
    """Torque vs ball groove coefficient f = r/D_w (§6.1.2, Fig. 15): roller −1 µm, ball −5 µm."""
    v, g = _variant(variant), np.asarray(grooves, float)
    model = _composite(v, clearance_axial_roller=-1e-6, clearance_axial_ball=-5e-6, groove_curvature=g)
    load = np.repeat(load_vector(F_z=axial_load)[None], g.size, axis=0)
    return evaluate(model, load, v, extra={"groove_curvature": g})


def eccentricity_sweep(eccentricities=ECCENTRICITIES, variant="seed000"):
    """Torque vs eccentricity of F_a (§6.1.3, Fig. 16): F_a = F_r = 3 kN, roller −1 µm, ball −5 µm."""
    v, e = _variant(variant), np.asarray(eccentricities, float)
    model = _composite(v, clearance_axial_roller=-1e-6, clearance_axial_ball=-5e-6)
    load = eccentric_axial_load(3000.0, e, radial_load=3000.0)
    return evaluate(model, load, v, extra={"eccentricity_m": e, "moment_Nm": 3000.0 * e})


def _combined_case(v, **kw):
    model = _composite(v, clearance_axial_roller=-1e-6, clearance_axial_ball=-5e-6, **kw)
    return model, eccentric_axial_load(3000.0, 0.2, radial_load=3000.0)


def ratio_study(ratios=RATIOS, variant="seed000"):
    """Ball/roller counts per axial row (§6.1.4, Fig. 17): F_a = F_r = 3 kN, M = 600 N·m."""
    import pandas as pd

    v = _variant(variant)
    parts = []
    for nb, nr in ratios:
        model, load = _combined_case(v, n_axial_balls=nb, n_axial_rollers=nr)
        parts.append(
            evaluate(model, load, v, extra={"ratio": [f"{nb}/{nr}"], "n_balls": [nb], "n_rollers": [nr]})
        )
    return pd.concat(parts, ignore_index=True)


def crowning_study(letters="abcde", variant="seed000"):
    """Roller crowning a–e (§6.1.5, Fig. 18): F_a = F_r = 3 kN, M = 600 N·m (radial rollers alike)."""
    import pandas as pd

    v = _variant(variant)
    parts = []
    for letter in letters:
        model, load = _combined_case(dataclasses.replace(v, crowning=letter))
        parts.append(evaluate(model, load, v, extra={"crowning": [letter]}))
    return pd.concat(parts, ignore_index=True)


# --- conclusions ------------------------------------------------------------------------------------------
def _rising(x) -> bool:
    return bool(np.all(np.diff(np.asarray(x, float)) > 0))


def conclusions(variant="seed000") -> dict:
    """The seed-000 conclusions evaluated with ``variant`` (bools, the clearance minimum in m, ratios)."""
    v = _variant(variant)
    cy = composite_vs_yrt(variant=v)
    c = cy[cy.bearing == "composite"]["total_Nm"].to_numpy()
    y = cy[cy.bearing == "yrt"]["total_Nm"].to_numpy()
    cm = clearance_map(roller_clearances=(0.0,), variant=v)
    gr = groove_sweep(variant=v)["total_Nm"].to_numpy()
    ra = ratio_study(variant=v)
    cr = crowning_study(variant=v).set_index("crowning")
    tq, st = cr["total_Nm"], cr[["max_pressure_ball_Pa", "max_pressure_roller_Pa"]].max(axis=1)
    return {
        "speed_rises": _rising(speed_sweep(variant=v)["total_Nm"]),
        "axial_load_rises": _rising(axial_load_sweep(variant=v)["total_Nm"]),
        "moment_rises": _rising(moment_sweep(variant=v)["total_Nm"]),
        "composite_below_yrt": bool(np.all(c < y)),
        "composite_over_yrt_at_0": float(c[0] / y[0]),
        "clearance_minimum_m": float(cm["ball_clearance_m"].iloc[int(np.argmin(cm["total_Nm"]))]),
        "groove_rises": _rising(gr),
        "groove_change": float(gr[-1] / gr[0] - 1.0),
        "eccentricity_rises": _rising(eccentricity_sweep(variant=v)["total_Nm"]),
        "ratio_trend": _rising(-ra["total_Nm"])
        and _rising(ra[["max_pressure_ball_Pa", "max_pressure_roller_Pa"]].max(axis=1)),
        "crowning_extremes": tq.idxmin() == "d"
        and st.idxmax() == "d"
        and tq.idxmax() == "e"
        and st.idxmin() == "e",
    }


def run_all(out, variant="seed000") -> dict:
    """Run every study; write ``seed000_friction_<study>.csv`` and ``.png`` into ``out``; return tables."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    tables = {
        "speed": speed_sweep(variant=variant),
        "axial_load": axial_load_sweep(variant=variant),
        "moment": moment_sweep(variant=variant),
        "yrt": composite_vs_yrt(variant=variant),
        "clearance": clearance_map(variant=variant),
        "groove": groove_sweep(variant=variant),
        "eccentricity": eccentricity_sweep(variant=variant),
        "ratio": ratio_study(variant=variant),
        "crowning": crowning_study(variant=variant),
        "table3": table3(variant=variant),
    }
    for key, t in tables.items():
        t.to_csv(out / f"seed000_friction_{key}.csv", index=False)
    p = out / "seed000_friction_{}.png"
    plot_study(
        tables["speed"],
        "speed_rpm",
        "inner-ring speed [r/min]",
        "Fig. 11: F_a = 2 kN",
        str(p).format("speed"),
    )
    ax_t = tables["axial_load"].assign(axial_load_kN=tables["axial_load"]["axial_load_N"] / 1e3)
    plot_study(ax_t, "axial_load_kN", "axial load F_a [kN]", "Fig. 12: 5 r/min", str(p).format("axial_load"))
    plot_study(
        tables["moment"],
        "moment_Nm",
        "overturning moment M [N·m]",
        "Fig. 13: 5 r/min",
        str(p).format("moment"),
    )
    plot_composite_vs_yrt(tables["yrt"], str(p).format("yrt"))
    plot_clearance_map(tables["clearance"], str(p).format("clearance"))
    plot_study(
        tables["groove"],
        "groove_curvature",
        "groove curvature coefficient f = r/D_w [-]",
        "Fig. 15: F_a = 5 kN, roller −1 µm, ball −5 µm",
        str(p).format("groove"),
        stress=True,
    )
    plot_study(
        tables["eccentricity"],
        "eccentricity_m",
        "eccentricity of F_a [m]",
        "Fig. 16: F_a = F_r = 3 kN",
        str(p).format("eccentricity"),
    )
    plot_study(
        tables["ratio"],
        "ratio",
        "balls / rollers per axial row",
        "Fig. 17: F_a = F_r = 3 kN, M = 600 N·m",
        str(p).format("ratio"),
        stress=True,
        categorical=True,
    )
    plot_study(
        tables["crowning"],
        "crowning",
        "roller crowning (a log, b/c arc-slope, d full, e straight)",
        "Fig. 18: F_a = F_r = 3 kN, M = 600 N·m",
        str(p).format("crowning"),
        stress=True,
        categorical=True,
    )
    t3 = tables["table3"]
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.bar(t3["run"] - 0.2, t3["published_Nm"], 0.4, label="Tian et al. Table 3")
    ax.bar(t3["run"] + 0.2, t3["total_Nm"], 0.4, label="bearingkit")
    ax.set(xlabel="Table 3 run", ylabel="friction torque [N·m]", title="Table 3 (L9), F_a = F_r = 3 kN")
    ax.legend()
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(str(p).format("table3"), dpi=110)
    plt.close(fig)
    return tables


def main(argv=None) -> int:
    args = list(argv if argv is not None else sys.argv[1:])
    out = Path(args[0] if args else "out/seed000_friction")
    variant = args[1] if len(args) > 1 else "seed000"
    run_all(out, variant)
    print(f"wrote {out}/seed000_friction_*.csv|png (variant {variant})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
