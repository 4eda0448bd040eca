"""Seed-000 statements not covered by :mod:`.validation`: §5.3.2 errors, §6.1.1, §6.1.4, conclusion (1).

SI units (N·m, Pa, m); indicators are 1 when the statement holds, 0 when not (tolerance 0). Everything is
computed with the validated reading ``"seed000"`` of :mod:`bearingkit.papers.tian2025.friction`
(one coefficient, the roller sliding μ_rs, identified on Table 3 run 1; nothing else fitted).
Tian et al. (2025) Machines 13:588, doi:10.3390/machines13070588.

Cases and thresholds:

* ``seed000/section5.3.2/<speed|axial-load|moment>/mean-test-theory-error`` — the printed mean errors
  15.97 %, 17.84 %, 12.70 % between the rig and the paper's theory (Figs. 11–13). Not computable: both
  curves are printed only as figures; registered as not-computable numbers (with the recommended
  clearances and groove range of §6.1.1–6.1.2, design choices without a stated criterion).
* ``seed000/section6.1.1/torque-rises-with-roller-preload`` — F_a = 5 kN, roller clearance 0, −1, −2 µm
  × ball clearance 0 … −6 µm (1 µm steps, Fig. 14): 1 if the torque averaged over the ball clearances
  rises strictly from 0 to −1 to −2 µm AND at no single ball clearance does the more negative roller
  clearance lower the torque by more than 0.5 % (ties within 0.5 % are "equal", not a fall).
* ``seed000/section6.1.1/roller-1um/torque-falls-with-ball-preload`` — roller −1 µm: 1 if the torque
  falls at every step of the ball clearance 0 → −6 µm ("decreases gradually … a continuous decrease").
* ``seed000/section6.1.1/roller-2um/torque-unchanged-with-ball-preload`` — roller −2 µm: 1 if
  (max − min)/mean of the torque over ball clearance 0 … −6 µm is at most 5 % ("remains relatively
  constant … essentially unchanged").
* ``seed000/section6.1.4/stresses-low-and-comparable-at-1to1`` — F_a = F_r = 3 kN, M = 600 N·m, roller
  −1 / ball −5 µm, f = 0.52; 1 if at 31/31 both the ball and the roller maximum contact pressure are the
  lowest of the three ratios 31/31, 42/21, 48/16 ("relatively low") AND they differ by at most 20 % of
  the larger ("comparable").
* ``seed000/conclusion/torque-mainly-from-rollers`` — conclusion (1): the three roller rows' share of
  the total torque (the total includes the balls and the cage) at the same point; 1 if above one half.
"""

from __future__ import annotations

import functools

import numpy as np

from bearingkit.validation.registry import Case, NotComputable, register, register_not_computable

SOURCE = "Tian et al. (2025) Machines 13:588, doi:10.3390/machines13070588"
#: §5.3.2: mean test–theory error of Figs. 11 (speed), 12 (axial load), 13 (moment) [1].
MEAN_ERRORS = {"speed": (0.1597, "11"), "axial-load": (0.1784, "12"), "moment": (0.1270, "13")}
#: A more negative roller clearance may lower the torque by at most this before it counts as a fall [1].
TIE_BAND = 0.005
#: "Essentially unchanged": (max − min)/mean at most this [1].
FLAT_BAND = 0.05
#: "Comparable" stresses: |p_ball − p_roller| / max(p_ball, p_roller) at most this [1].
COMPARABLE_BAND = 0.20

NOT_COMPUTABLE = (
    "not computable from the printed text: the test and the theoretical values of Fig. {fig} are given "
    "only as a figure (the text prints the mean error alone), so neither bearingkit's error against the "
    "rig nor its distance to the paper's theory can be formed; the trend of the same figure is case "
    "seed000/conclusion/{trend}"
)
TREND_OF_FIGURE = {"speed": "speed-rises", "axial-load": "axial-load-rises", "moment": "moment-rises"}


@functools.cache
def _clearance_table():
    from bearingkit.papers.tian2025.friction import clearance_map

    cm = clearance_map()
    return cm.pivot(index="ball_clearance_m", columns="roller_clearance_m", values="total_Nm").sort_index(
        ascending=False
    )  # rows: ball clearance 0 → −6 µm; columns: roller clearance −2, −1, 0 µm


def _torque(roller_um: int) -> np.ndarray:
    t = _clearance_table()
    col = min(t.columns, key=lambda c: abs(c - roller_um * 1e-6))
    return t[col].to_numpy()


def rises_with_roller_preload() -> float:
    """Indicator of §6.1.1 "increases as |roller clearance| rises" (thresholds: module docstring)."""
    t0, t1, t2 = _torque(0), _torque(-1), _torque(-2)
    means = [t.mean() for t in (t0, t1, t2)]
    mean_rises = bool(np.all(np.diff(means) > 0))
    no_fall = bool(np.all(t1 >= t0 * (1 - TIE_BAND)) and np.all(t2 >= t1 * (1 - TIE_BAND)))
    return float(mean_rises and no_fall)


def falls_with_ball_preload() -> float:
    """Indicator of §6.1.1 "at roller −1 µm the torque decreases … continuously"."""
    return float(np.all(np.diff(_torque(-1)) < 0))


def unchanged_with_ball_preload() -> float:
    """Indicator of §6.1.1 "at roller −2 µm the torque remains essentially unchanged"."""
    t = _torque(-2)
    return float((t.max() - t.min()) / t.mean() <= FLAT_BAND)


@functools.cache
def _ratio_table():
    from bearingkit.papers.tian2025.friction import ratio_study

    return ratio_study().set_index("ratio")


def stresses_low_and_comparable() -> float:
    """Indicator of §6.1.4 "at 1:1 the max contact stresses are relatively low and comparable"."""
    t = _ratio_table()
    ball, roller = t["max_pressure_ball_Pa"], t["max_pressure_roller_Pa"]
    lowest = ball.idxmin() == "31/31" and roller.idxmin() == "31/31"
    pb, pr = ball["31/31"], roller["31/31"]
    return float(lowest and abs(pb - pr) / max(pb, pr) <= COMPARABLE_BAND)


def roller_share() -> float:
    """Share of the three roller rows in the total torque at the 31/31 point of §6.1.4 [1]."""
    row = _ratio_table().loc["31/31"]
    rollers = sum(row[f"row_{name}_Nm"] for name in ("roller_upper", "roller_lower", "roller_radial"))
    return float(rollers / row["total_Nm"])


#: Published numbers of seed 000 that cannot be computed, with the reason (registered, shown in the docs).
NOT_COMPUTABLE_ITEMS = (
    *(
        (
            f"seed000/section5.3.2/{name}/mean-test-theory-error",
            f"{err * 100:.2f} %",
            NOT_COMPUTABLE.format(fig=fig, trend=TREND_OF_FIGURE[name]),
        )
        for name, (err, fig) in MEAN_ERRORS.items()
    ),
    (
        "seed000/section6.1.1/recommended-roller-clearance",
        "-1 um",
        "a design choice 'to optimize the loading of rolling elements while minimizing the friction "
        "torque' with no stated criterion: the paper's own Fig. 14 has the lowest torque at roller 0 um, "
        "so -1 um is not a torque minimum; the torque trends it rests on are the section6.1.1 cases",
    ),
    (
        "seed000/section6.1.1/recommended-ball-clearance",
        "-5 um",
        "a design choice with no stated criterion (at the recommended roller -1 um the torque 'decreases "
        "continuously' down to -6 um by the paper's own words); the minimum at -5 um for roller 0 um is "
        "case seed000/conclusion/clearance-minimum",
    ),
    (
        "seed000/section6.1.2/recommended-groove-range-low",
        "0.515",
        "set by 'the manufacturing challenges associated with the groove and the overall structural "
        "constraints', not by a computed quantity; the computable part, the steep rise up to 0.51, is case "
        "seed000/conclusion/groove-steep-rise",
    ),
    (
        "seed000/section6.1.2/recommended-groove-range-high",
        "0.53",
        "as the low end: a manufacturing and structural choice, no model output bounds it",
    ),
)


def _register() -> None:
    for item_id, published, why in NOT_COMPUTABLE_ITEMS:
        register_not_computable(NotComputable(item_id, published, why))
    indicators = (
        (
            "section6.1.1/torque-rises-with-roller-preload",
            "§6.1.1 ('the total friction torque ... increases as the absolute value of the negative axial "
            "clearance of the cylindrical rollers rises'), Fig. 14",
            "indicator, F_a = 5 kN: mean torque over ball clearance 0...-6 um rises strictly from roller 0 "
            "to -1 to -2 um, and no single ball clearance shows a fall of more than 0.5 %",
            rises_with_roller_preload,
            None,
        ),
        (
            "section6.1.1/roller-1um/torque-falls-with-ball-preload",
            "§6.1.1 ('When the axial clearance of the cylindrical rollers is -1 um, the total friction "
            "torque ... decreases gradually'), Fig. 14",
            "indicator, F_a = 5 kN, roller -1 um: torque falls at every 1 um step of the ball clearance "
            "0 -> -6 um",
            falls_with_ball_preload,
            None,
        ),
        (
            "section6.1.1/roller-2um/torque-unchanged-with-ball-preload",
            "§6.1.1 ('when the axial clearance of the cylindrical rollers is -2 um, the total friction "
            "torque ... remains relatively constant ... essentially unchanged'), Fig. 14",
            "indicator, F_a = 5 kN, roller -2 um: (max - min)/mean of the torque over ball clearance "
            "0...-6 um <= 5 %",
            unchanged_with_ball_preload,
            None,
        ),
        (
            "section6.1.4/stresses-low-and-comparable-at-1to1",
            "§6.1.4 ('When the ratio of axial steel balls to rollers equals 1, the maximum contact stresses "
            "for both components are relatively low and comparable'), Fig. 17",
            "indicator, F_a = F_r = 3 kN, M = 600 N*m: at 31/31 ball and roller p_max are each the lowest of "
            "31/31, 42/21, 48/16 and differ by <= 20 % of the larger",
            stresses_low_and_comparable,
            None,
        ),
        (
            "conclusion/torque-mainly-from-rollers",
            "§7 conclusion (1) ('The friction torque ... is primarily generated by the rollers')",
            "indicator: share of the three roller rows in the total torque > 1/2 (F_a = F_r = 3 kN, "
            "M = 600 N*m, roller -1 / ball -5 um, 31/31)",
            lambda: float(roller_share() > 0.5),
            None,
        ),
    )
    for suffix, where, quantity, fn, dev in indicators:
        register(
            Case(
                id=f"seed000/{suffix}",
                source=f"{SOURCE}, {where}",
                quantity=quantity,
                unit="1",
                published=1.0,
                compute=fn,
                tolerance=0.0,
                known_deviation=dev,
            )
        )


_register()
