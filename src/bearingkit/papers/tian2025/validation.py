"""Seed-000 friction torque: Table 3 (L9 array) and the single-factor conclusions of §5–6.1.

SI units (N·m, m, rad/s). Tian et al. (2025) Machines 13:588, doi:10.3390/machines13070588.

Inputs the paper does not give, and the values chosen here:

- lubricant: ``seed000_grease_assumed`` (ISO VG 100 mineral base oil) at 25 °C (room-temperature rig);
- roughness R_q 0.05 µm (elements), 0.10 µm (raceways); μ_bl 0.12, μ_EHL 0.02 (SKF catalogue values,
  :mod:`bearingkit.physics.lubrication.traction`); hysteresis ξ = 0.01 (rollers), β = 0.007 (balls)
  from the paper;
- cages: two brass cages (8500 kg/m³), annulus Ø160–185 mm × 3.5 mm minus 31 roller and 31 ball
  pockets → 1.86e-5 m³ each, 2 × 0.158 kg = :data:`CAGE_MASS`; f_c = 0.1; guide at the mean pitch
  diameter;
- Table 3 load case: F_a = F_r = 3 kN, M = −e·F_a (the load case of §6.1.3–6.1.5), speed 5 r/min
  (the speed of every other test in §5), ball clearances −4/−5/−6 µm (Table 2; Table 3 drops the sign);
- roller slice law: the bearing builder's default ``pairing`` (Tian et al. eqs. 3–5 read literally).

Calibration (one coefficient, once, in :mod:`bearingkit.papers.tian2025.calibration`): the roller
sliding coefficient μ_rs of the axial roller rows is identified on Table 3 run 1 (2871.7 N·mm; case
``seed000/table3/run1/friction-torque``, role ``calibration``). Runs 2–9, the range ranking and every
conclusion below are predictions with it untouched; the grease acts with its base oil's viscosity.
"""

from __future__ import annotations

import numpy as np

from bearingkit.papers.tian2025.calibration import CAGE_MASS, ROLLER_SLIDING, VISCOSITY_FACTOR
from bearingkit.validation.registry import Case, register

SOURCE = "Tian et al. (2025) Machines 13:588, doi:10.3390/machines13070588"
RPM = 5.0
#: Table 3 (A roller clearance µm, B ball clearance µm (negative, Table 2), C groove coeff., D e [m],
#: friction torque N·mm).
TABLE3 = (
    (0, -4, 0.51, 0.2, 2871.7),
    (0, -5, 0.52, 0.3, 4045.4),
    (0, -6, 0.53, 0.4, 5379.6),
    (-1, -4, 0.52, 0.4, 5692.0),
    (-1, -5, 0.53, 0.2, 3208.1),
    (-1, -6, 0.51, 0.3, 4092.0),
    (-2, -4, 0.53, 0.3, 4767.5),
    (-2, -5, 0.51, 0.4, 5774.0),
    (-2, -6, 0.52, 0.2, 3772.4),
)


def operating_point(rpm=RPM, viscosity_factor=None, **kw):
    """The seed-000 operating point at ``rpm`` [r/min] with the constants of :mod:`.calibration`."""
    from bearingkit.analysis.friction.components import OperatingPoint

    vf = VISCOSITY_FACTOR if viscosity_factor is None else viscosity_factor
    kw.setdefault("roller_sliding", ROLLER_SLIDING)
    return OperatingPoint.from_rpm(rpm, cage_mass=CAGE_MASS, viscosity_factor=vf, **kw)


def torque(load, rpm=RPM, viscosity_factor=None, builder=None, **geometry):
    """Friction torque [N·m] (C,) of the composite bearing (or ``builder``) under ``load`` (C, 5)."""
    from bearingkit.analysis.friction.components import friction_torque
    from bearingkit.analysis.solver.quasistatic import solve
    from bearingkit.bearings.turntable import composite_turntable

    model = (builder or composite_turntable)(**geometry)
    res = solve(model, np.atleast_2d(load))
    return friction_torque(res, operating_point(rpm, viscosity_factor)).total, res


def table3_torque(k: int, viscosity_factor=None) -> float:
    """Computed friction torque [N·m] of Table 3 run k (1..9)."""
    from bearingkit.bearings.common import eccentric_axial_load

    a, b, c, e, _ = TABLE3[k - 1]
    t, _ = torque(
        eccentric_axial_load(3000.0, e, radial_load=3000.0),
        viscosity_factor=viscosity_factor,
        clearance_axial_roller=a * 1e-6,
        clearance_axial_ball=b * 1e-6,
        groove_curvature=c,
    )
    return float(t[0])


def _rising(values) -> float:
    return float(np.all(np.diff(np.asarray(values)) > 0))


# --- the single-factor conclusions (indicator 1.0 = the paper's statement holds) -------------------
def speed_rises() -> float:
    """§5.3.2(1): torque rises with speed 5–90 r/min (F_a = 2 kN, clearances 0/−2 µm)."""
    from bearingkit.analysis.friction.components import friction_torque
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.bearings.turntable import composite_turntable

    res = solve(
        composite_turntable(clearance_axial_roller=0.0, clearance_axial_ball=-2e-6), load_vector(F_z=2000.0)
    )
    vals = [friction_torque(res, operating_point(n)).total[0] for n in (5, 20, 40, 60, 90)]
    return _rising(vals)


def axial_load_rises() -> float:
    """§5.3.2(2): torque rises with axial load 0–8 kN at 5 r/min."""
    from bearingkit.analysis.solver.quasistatic import load_vector

    t, _ = torque(
        load_vector(F_z=np.linspace(0, 8000, 9)), clearance_axial_roller=0.0, clearance_axial_ball=-2e-6
    )
    return _rising(t)


def moment_rises() -> float:
    """§5.3.2(3): torque rises with overturning moment 0–400 N·m."""
    from bearingkit.analysis.solver.quasistatic import load_vector

    t, _ = torque(
        load_vector(M_y=-np.linspace(0, 400, 9)), clearance_axial_roller=0.0, clearance_axial_ball=-2e-6
    )
    return _rising(t)


def composite_below_yrt() -> float:
    """§5.3.1: the composite bearing's torque is below the YRT bearing's at every axial load 0–6 kN."""
    from bearingkit.analysis.solver.quasistatic import load_vector
    from bearingkit.bearings.turntable import yrt_turntable

    load = load_vector(F_z=np.linspace(0, 6000, 7))
    comp, _ = torque(load, clearance_axial_roller=0.0, clearance_axial_ball=-2e-6)
    # The paper's YRT comparator has "identical dimensional specifications and test conditions" but no
    # stated clearance. Catalogue YRT turntable bearings are supplied preloaded (Schaeffler YRT
    # catalogue), and Tian et al. give 0 to -2 um as the usual roller clearance (§6.1): the comparator
    # is taken at -2 um. (At 0 um no YRT roller touches at F_a = 0 and the comparison is empty.)
    yrt, _ = torque(load, builder=yrt_turntable, clearance_axial_roller=-2e-6)
    return float(np.max(comp / yrt) < 1.0)


def clearance_minimum() -> float:
    """§6.1.1: at roller clearance 0 and F_a = 5 kN the torque is lowest near ball clearance −5 µm [m]."""
    from bearingkit.analysis.solver.quasistatic import load_vector

    grid = -np.arange(0, 7) * 1e-6
    vals = [
        torque(load_vector(F_z=5000.0), clearance_axial_roller=0.0, clearance_axial_ball=c)[0][0]
        for c in grid
    ]
    return float(grid[int(np.argmin(vals))])


def groove_steep_rise() -> float:
    """§6.1.2: torque rises with f = 0.505–0.54, steeply up to 0.51 (slope there > mean slope after)."""
    from bearingkit.analysis.solver.quasistatic import load_vector

    f = np.array([0.505, 0.51, 0.52, 0.53, 0.54])
    t = np.array(
        [
            torque(
                load_vector(F_z=5000.0),
                clearance_axial_roller=-1e-6,
                clearance_axial_ball=-5e-6,
                groove_curvature=g,
            )[0][0]
            for g in f
        ]
    )
    steep = (t[1] - t[0]) / 0.005 > (t[-1] - t[1]) / 0.03
    return float(_rising(t) and steep)


def eccentricity_rises() -> float:
    """§6.1.3: torque rises with eccentricity 0–0.6 m (F_a = F_r = 3 kN)."""
    from bearingkit.bearings.common import eccentric_axial_load

    t, _ = torque(
        eccentric_axial_load(3000.0, np.linspace(0, 0.6, 7), radial_load=3000.0),
        clearance_axial_roller=-1e-6,
        clearance_axial_ball=-5e-6,
    )
    return _rising(t)


def _combined():
    from bearingkit.bearings.common import eccentric_axial_load

    return eccentric_axial_load(3000.0, 0.2, radial_load=3000.0)


def ratio_trend() -> float:
    """§6.1.4: ball/roller 31/31 → 42/21 → 48/16: torque falls and max contact stress rises."""
    tq, st = [], []
    for nb, nr in ((31, 31), (42, 21), (48, 16)):
        t, res = torque(
            _combined(),
            clearance_axial_roller=-1e-6,
            clearance_axial_ball=-5e-6,
            n_axial_balls=nb,
            n_axial_rollers=nr,
        )
        tq.append(t[0])
        st.append(max(float(r.max_pressure.max()) for r in res.rows))
    return float(_rising(-np.asarray(tq)) and _rising(st))


def crowning_extremes() -> float:
    """§6.1.5: crowning d lowest torque + highest stress; e highest torque + lowest stress."""
    tq, st = {}, {}
    for letter in "abcde":
        t, res = torque(
            _combined(), clearance_axial_roller=-1e-6, clearance_axial_ball=-5e-6, crowning=letter
        )
        tq[letter] = t[0]
        st[letter] = max(float(r.max_pressure.max()) for r in res.rows)
    ok = (
        min(tq, key=tq.get) == "d"
        and max(st, key=st.get) == "d"
        and max(tq, key=tq.get) == "e"
        and min(st, key=st.get) == "e"
    )
    return float(ok)


#: Table 3 tolerance [1]: issue 32's default for values (the paper states no accuracy for Table 3).
TOL_TABLE3 = 0.10
#: Calibration point: met to the accuracy of the identification [1].
TOL_CALIBRATION = 1e-3


def _register():
    from bearingkit.papers.tian2025.calibration import CALIBRATION_RUNS

    for k, (a, b, c, e, m) in enumerate(TABLE3, start=1):
        calibration = k in CALIBRATION_RUNS
        register(
            Case(
                id=f"seed000/table3/run{k}/friction-torque",
                source=f"{SOURCE}, Table 3 run {k} (A={a} um, B={b} um, C={c}, D={e} m)",
                quantity="bearing friction torque at F_a = F_r = 3 kN, M = -e F_a, 5 r/min",
                unit="N*m",
                published=m / 1e3,
                compute=lambda k=k: table3_torque(k),
                tolerance=TOL_CALIBRATION if calibration else TOL_TABLE3,
                role="calibration" if calibration else "prediction",
                note=(
                    "roller sliding coefficient mu_rs = calibration.ROLLER_SLIDING is identified on this run"
                    if calibration
                    else None
                ),
            )
        )
    conclusions = (
        (
            "speed-rises",
            speed_rises,
            1.0,
            "indicator: torque rises 5-90 r/min, F_a = 2 kN (§5.3.2, Fig. 11)",
            None,
        ),
        (
            "axial-load-rises",
            axial_load_rises,
            1.0,
            "indicator: torque rises with F_a 0-8 kN (§5.3.2, Fig. 12)",
            None,
        ),
        (
            "moment-rises",
            moment_rises,
            1.0,
            "indicator: torque rises with M 0-400 N*m (§5.3.2, Fig. 13)",
            None,
        ),
        (
            "composite-below-yrt",
            composite_below_yrt,
            1.0,
            "indicator: M_composite < M_YRT at every F_a 0-6 kN (§5.3.1)",
            None,
        ),
        (
            "clearance-minimum",
            clearance_minimum,
            -5e-6,
            "ball clearance of minimum torque at roller clearance 0 (grid 0...-6 um in 1 um steps; exact)",
            None,
        ),
        (
            "groove-steep-rise",
            groove_steep_rise,
            1.0,
            "indicator: rises 0.505-0.54, steepest to 0.51 (§6.1.2)",
            None,
        ),
        (
            "eccentricity-rises",
            eccentricity_rises,
            1.0,
            "indicator: torque rises with e 0-0.6 m (§6.1.3)",
            None,
        ),
        (
            "ratio-trend",
            ratio_trend,
            1.0,
            "indicator: torque falls, max stress rises 31/31->48/16 (§6.1.4)",
            None,
        ),
        (
            "crowning-extremes",
            crowning_extremes,
            1.0,
            "indicator: d lowest torque/highest stress, e reverse",
            None,
        ),
    )
    for name, fn, pub, quantity, dev in conclusions:
        register(
            Case(
                id=f"seed000/conclusion/{name}",
                source=f"{SOURCE}, §5-6.1",
                quantity=quantity,
                unit="1" if name != "clearance-minimum" else "m",
                published=pub,
                compute=fn,
                tolerance=0.0,
                known_deviation=KNOWN_DEVIATIONS.get(name, dev),
            )
        )


#: Conclusions the documented physics does not reproduce, with the mechanism (not forced).
KNOWN_DEVIATIONS: dict[str, str] = {
    "clearance-minimum": "at roller clearance 0 the torque still falls from ball -5 to -6 um (1.318 -> 1.301 "
    "N*m, -1.2 %), so the grid minimum is the end point -6 um: the relief of the upper roller row "
    "(roller sliding and E2 fall with its load) outweighs the rise of the ball terms (Fujiwara M32 ~ "
    "Q^0.40, spin) beyond -5 um, where the paper has the balls' rise win",
}

_register()
