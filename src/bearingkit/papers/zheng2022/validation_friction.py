"""Seed 004 (Zheng et al. 2022, PTRB) friction validation cases: Tables 5, 7, 8 and §4 (simulation data).

SI values (N·m, 1). Model: :func:`bearingkit.analysis.friction.threaded.ptrb_friction` with its defaults
(prototype of Table 1, flat ring flanks, L-AN oil η₀ = 0.04 Pa·s, α = 2.46e-8 1/Pa, eq. (13)–(15)
summed as printed with M_v = F_v d_X/2, Harris's EHL rolling resistance with the equivalent ball's
R_y = D_w/2, uniform tooth shares, roller 0 under the radial load).

ONE number is calibrated: the contact traction μ_c, against ``seed004/table7/axial/20kN`` (0.476 N·m),
see :data:`bearingkit.physics.friction.ptrb_laws.CONTACT_TRACTION_CALIBRATED`. Nothing in the
viscous (speed-dependent) term is fitted. All other cases follow: Table 7 within 6.4 %, Table 8 within 5.9 %,
§4 within 6.3 %, Table 5 within 7.1 % except the contact-angle row.
Tolerance 0.10 (issue 32: values within 10 % where the paper states no accuracy for its simulation).

Roles (issue 32): ``seed004/table7/axial/20kN`` is the calibration point; Table 7's 5 kN simulation
values are diagnostics (Table 8 prints the same state, 5 kN / 600 rpm, with the same numbers); the
Table 5 arrows are diagnostics (derived from the two printed values of each row). The Table 7 deviation
row is registered beside the test values (:mod:`bearingkit.papers.zheng2022.validation_tests`).

New predictions (issue 32): ``seed004/section4/life/<40|100>pct`` (§4: a constant load of 40–100 % of
the dynamic rating gives 15.6 to 1.0 million revolutions: L10 = (C/P)³, ISO 281 for ball bearings, as
the PTRB is rated), ``seed004/section8/mu_a/max`` (§8 prints the axial μ range as 0.0011–0.0023, §4 as
0.0011–0.0024: the same computed maximum is compared with both), and
``seed004/section5/other-parameters-below-0.1Nm`` (§5 (2): apart from the contact angle "the effect of
other structural parameters on friction torque was less than 0.1 Nm": 1 if the largest change of M over
the Table 5 range of n, R_rr, d_R and Z, both load cases, is below 0.1 N·m).

Cases:

* ``seed004/table7/<case>/<load>kN``, ``seed004/table8/<case>/<load>kN/<speed>rpm`` — Tables 7, 8.
* ``seed004/section4/<case>/30kN/<100|4000>rpm`` — §4: M_PTRBa 0.715 → 1.045 N·m and M_PTRBr
  1.042 → 1.389 N·m at 30 kN from 100 to 4000 rpm.
* ``seed004/table5/<parameter>/<value>/<case>`` — Table 5 values (20 kN, 4000 rpm).
* ``seed004/table5/<parameter>/direction/<case>`` — the printed arrow (+1 ↑, −1 ↓) against the sign
  of M(high) − M(low) over the §5 range; tolerance 0 (a wrong direction is a relative error of 2).
* ``seed004/mu_range/<case>/<min|max>`` — the extremes of μ over 10–30 kN × 100–4000 rpm (§4, Fig. 4)
  against the printed bounds; tolerance 0.15 as the torques (μ = 2M/(d_0 F) is a torque at a corner
  of that domain divided by a constant).
* ``seed004/mu_range/<case>/inside`` — 1 if the computed μ range lies inside the printed one
  (the issue's criterion), else 0; tolerance 0, no rounding allowance (the computed ranges are inside
  the printed bounds themselves, see :data:`MU_RANGE`).

Known deviations (stated per case) are all in the contact-angle row of Table 5 (:data:`_T5_ALPHA`):
the row is inconsistent with the paper's own load exponent under the printed load relations, so no
per-contact model with the torque ∝ (contact load)^p, p ≈ 1, can follow both of its columns.

The previous default (power balance, :meth:`~bearingkit.analysis.friction.threaded.PTRBFrictionParameters.
power_balance`) reversed the d_R trends (both loads) as well; see ``docs/ptrb_friction.md``.
"""

from __future__ import annotations

import numpy as np

from bearingkit.analysis.friction.threaded import RPM, ptrb_friction
from bearingkit.bearings.ptrb import ptrb_prototype
from bearingkit.papers.zheng2022.design import design_geometry
from bearingkit.validation.registry import Case, register

SOURCE = "Zheng et al. (2022) Machines 10:1051, doi:10.3390/machines10111051"
KN = 1.0e3
TOLERANCE = 0.10
#: The calibration point of the contact traction μ_c (ptrb_laws.CONTACT_TRACTION_CALIBRATED).
CALIBRATION_CASE = "seed004/table7/axial/20kN"
#: Simulation numbers printed twice for one state: diagnostic id → the counted case.
DUPLICATES = {
    "seed004/table7/axial/5kN": "seed004/table8/axial/5kN/600rpm (the same 0.103 N*m)",
    "seed004/table7/radial/5kN": "seed004/table8/radial/5kN/600rpm (the same 0.132 N*m)",
}
#: Table 7, deviation row (test − simulation) [N·m], printed: case → load [kN] → deviation.
TABLE7_DEVIATION = {
    "axial": {1: 0.030, 5: 0.040, 10: 0.045, 15: 0.070, 20: 0.097, 25: 0.097, 30: 0.099},
    "radial": {1: 0.029, 5: 0.031, 10: 0.053, 15: 0.071, 20: 0.071, 25: 0.092, 30: 0.075},
}
#: §4: "a constant load of 40–100 % of the basic dynamic load rating" → "15.6 million to 1.0 million"
#: revolutions: P/C → L10 [10⁶ rev].
SECTION4_LIVES = {40: (0.4, 15.6), 100: (1.0, 1.0)}
#: §8's axial μ range upper end (§4 prints 0.0024 for the same range).
SECTION8_MU_A_MAX = 0.0023
#: §5 (2): bound on the torque change over the range of every parameter but α [N·m].
SECTION5_OTHER_BOUND = 0.1

#: Table 7, simulation data, 600 rpm: load [kN] → M [N·m].
TABLE7 = {
    "axial": {1: 0.028, 5: 0.103, 10: 0.212, 15: 0.338, 20: 0.476, 25: 0.626, 30: 0.786},
    "radial": {1: 0.032, 5: 0.132, 10: 0.286, 15: 0.465, 20: 0.667, 25: 0.885, 30: 1.121},
}
TABLE8_SPEEDS = (600, 800, 1000, 1200, 1400, 1600, 1800, 2000)
#: Table 8, simulation data: case → load [kN] → M [N·m] at TABLE8_SPEEDS.
TABLE8 = {
    "axial": {
        2: (0.046, 0.052, 0.057, 0.063, 0.067, 0.072, 0.077, 0.081),
        5: (0.103, 0.112, 0.121, 0.129, 0.136, 0.143, 0.150, 0.157),
        8: (0.167, 0.178, 0.189, 0.199, 0.208, 0.217, 0.226, 0.234),
    },
    "radial": {
        2: (0.055, 0.061, 0.067, 0.072, 0.077, 0.082, 0.087, 0.091),
        5: (0.132, 0.142, 0.151, 0.159, 0.167, 0.174, 0.181, 0.188),
        8: (0.221, 0.233, 0.244, 0.255, 0.264, 0.274, 0.283, 0.291),
    },
}
#: Table 5 (20 kN, 4000 rpm): parameter → ((low, high) display values, unit, axial (lo, hi), radial (lo, hi)).
TABLE5 = {
    "contact_angle": ((30, 60), "deg", (0.688, 0.719), (0.701, 1.170)),
    "n_teeth": ((8, 16), "1", (0.690, 0.711), (0.906, 0.886)),
    "roller_contact_radius": ((4.5, 7.5), "mm", (0.672, 0.760), (0.874, 0.974)),
    "roller_pitch_diameter": ((4.8, 7.2), "mm", (0.681, 0.703), (0.878, 0.912)),
    "n_elements": ((7, 11), "1", (0.699, 0.689), (0.932, 0.890)),
}

#: §4, 30 kN: case → {speed [rpm]: M [N·m]} (the 600 rpm values are Table 7's).
SECTION4 = {"axial": {100: 0.715, 4000: 1.045}, "radial": {100: 1.042, 4000: 1.389}}
#: §4 (text and the Table 3 discussion): μ over 10–30 kN and 100–4000 rpm, case → (min, max). Printed to
#: two significant digits, so 0.0024 stands for 0.00235–0.00245. The conclusions (§8) print the axial
#: range as 0.0011–0.0023 (and "0 kN–30 kN"); §4 is used here, where Fig. 4 is discussed.
MU_RANGE = {"axial": (0.0011, 0.0024), "radial": (0.0016, 0.0031)}
#: The §4 domain of the μ range: loads [kN] and speeds [rpm] (the extremes lie on its corners).
MU_RANGE_LOADS_KN = (10.0, 15.0, 20.0, 25.0, 30.0)
MU_RANGE_SPEEDS_RPM = (100.0, 600.0, 1000.0, 2000.0, 3000.0, 4000.0)

_T5_ALPHA = (
    "Table 5's contact-angle row is inconsistent with the paper's own load exponent. Under the printed "
    "load relations (axial Q = F/(Z n sin alpha), radial Q ~ F/(2n cos alpha)) any per-contact torque "
    "~ Q^p g(alpha) gives [M_a(60)/M_a(30)] / [M_r(60)/M_r(30)] = (tan 60 / tan 30)^-p = 3^-p. The "
    "paper's row gives 1.045/1.669 = 0.626, i.e. p = 0.43; its own load sweep at 4000 rpm (20 -> 30 kN: "
    "Table 5 at Z = 11 and section 4) gives p = 1.03 (axial) and 1.10 (radial), and every component "
    "of the model has p >= 0.47 (F_v ~ Q^0.47). bearingkit follows its own p = 1.05 (ratio 0.32): "
    "with the radial trend right (+174 % vs +67 %), the axial one comes out falling (-13 % vs +4.5 %)"
)
#: Cases whose computed value misses the tolerance, with their cause.
KNOWN_DEVIATIONS = {
    "seed004/table5/contact_angle/direction/axial": _T5_ALPHA,
    "seed004/table5/contact_angle/30deg/radial": _T5_ALPHA,
    "seed004/table5/contact_angle/60deg/radial": _T5_ALPHA,
}


def _si(value, unit):
    return {"deg": np.radians(value), "mm": value * 1e-3, "1": int(value)}[unit]


def _friction(case, load_kn, speed_rpm, parameter=None, value=None):
    def compute() -> float:
        g = ptrb_prototype() if parameter is None else design_geometry(**{parameter: value})
        return float(ptrb_friction(g, load_kn * KN, speed_rpm * RPM, case).torque)

    return compute


def _direction(case, parameter, low, high):
    def compute() -> float:
        m_lo, m_hi = (_friction(case, 20.0, 4000.0, parameter, x)() for x in (low, high))
        return float(np.sign(m_hi - m_lo))

    return compute


def mu_range(case: str, parameters=None) -> tuple[float, float]:
    """(min, max) of μ_PTRBa or μ_PTRBr [1] of the prototype over the §4 domain (10–30 kN, 100–4000 rpm).

    Parameters
    ----------
    case : {"axial", "radial"}
    parameters : PTRBFrictionParameters or None
        Friction model (None: the defaults).
    """
    loads, speeds = np.meshgrid(np.array(MU_RANGE_LOADS_KN) * KN, np.array(MU_RANGE_SPEEDS_RPM) * RPM)
    mu = ptrb_friction(ptrb_prototype(), loads, speeds, case, parameters=parameters).friction_coefficient
    return float(mu.min()), float(mu.max())


def _mu_inside(case):
    def compute() -> float:
        lo, hi = mu_range(case)
        return float(MU_RANGE[case][0] <= lo and hi <= MU_RANGE[case][1])

    return compute


def _register(case_id, source, quantity, published, compute, unit="N*m", tolerance=TOLERANCE, note=None):
    role = "prediction"
    if case_id == CALIBRATION_CASE:
        role, tolerance = "calibration", 1e-3
        note = (
            "the contact traction mu_c (ptrb_laws.CONTACT_TRACTION_CALIBRATED) is identified on this number"
        )
    elif case_id in DUPLICATES:
        role, note = "diagnostic", f"printed twice for one state: the counted case is {DUPLICATES[case_id]}"
    elif note:
        role = "diagnostic"
    register(
        Case(
            id=case_id,
            source=source,
            quantity=quantity,
            unit=unit,
            published=published,
            compute=compute,
            tolerance=tolerance,
            known_deviation=KNOWN_DEVIATIONS.get(case_id),
            role=role,
            note=note,
        )
    )


for _case, _rows in TABLE7.items():
    for _load, _m in _rows.items():
        _cal = " (CALIBRATION POINT of the contact traction)" if (_case, _load) == ("axial", 20) else ""
        _register(
            f"seed004/table7/{_case}/{_load}kN",
            f"{SOURCE}, Table 7 (simulation data)",
            f"PTRB prototype friction torque, {_case} load {_load} kN, 600 rpm{_cal}",
            _m,
            _friction(_case, _load, 600.0),
        )

for _case, _rows in TABLE8.items():
    for _load, _vals in _rows.items():
        for _speed, _m in zip(TABLE8_SPEEDS, _vals, strict=True):
            _register(
                f"seed004/table8/{_case}/{_load}kN/{_speed}rpm",
                f"{SOURCE}, Table 8 (simulation data)",
                f"PTRB prototype friction torque, {_case} load {_load} kN, {_speed} rpm",
                _m,
                _friction(_case, _load, float(_speed)),
            )

for _param, ((_lo, _hi), _unit, _ax, _ra) in TABLE5.items():
    for _k, _v in enumerate((_lo, _hi)):
        for _case, _pub in (("axial", _ax), ("radial", _ra)):
            _register(
                f"seed004/table5/{_param}/{_v}{'' if _unit == '1' else _unit}/{_case}",
                f"{SOURCE}, Table 5",
                f"friction torque, {_case} 20 kN, 4000 rpm, {_param} = {_v} {_unit}",
                _pub[_k],
                _friction(_case, 20.0, 4000.0, _param, _si(_v, _unit)),
            )

for _param, ((_lo, _hi), _unit, _ax, _ra) in TABLE5.items():
    for _case, _pub in (("axial", _ax), ("radial", _ra)):
        _arrow = float(np.sign(_pub[1] - _pub[0]))
        _register(
            f"seed004/table5/{_param}/direction/{_case}",
            f"{SOURCE}, Table 5 (arrow)",
            f"direction of the friction torque ({_case} 20 kN, 4000 rpm) as {_param} goes {_lo} -> {_hi} "
            f"{_unit}: sign of M(high) - M(low), +1 rising, -1 falling",
            _arrow,
            _direction(_case, _param, _si(_lo, _unit), _si(_hi, _unit)),
            unit="1",
            tolerance=0.0,
            note="derived: the arrow is the sign of the two printed values of the row (each counted); it "
            "shows the trend of the computed pair",
        )

for _case, _rows in SECTION4.items():
    for _speed, _m in _rows.items():
        _register(
            f"seed004/section4/{_case}/30kN/{_speed}rpm",
            f"{SOURCE}, section 4 (Fig. 3)",
            f"PTRB prototype friction torque, {_case} load 30 kN, {_speed} rpm",
            _m,
            _friction(_case, 30.0, float(_speed)),
        )


def _mu_end(case, k):
    return lambda: mu_range(case)[k]


for _case, (_mu_lo, _mu_hi) in MU_RANGE.items():
    for _k, (_end, _pub) in enumerate((("min", _mu_lo), ("max", _mu_hi))):
        _register(
            f"seed004/mu_range/{_case}/{_end}",
            f"{SOURCE}, section 4 (Fig. 4; printed to 2 digits)",
            f"{_end} of the prototype's {_case} friction coefficient over 10-30 kN and 100-4000 rpm",
            _pub,
            _mu_end(_case, _k),
            unit="1",
        )
    _register(
        f"seed004/mu_range/{_case}/inside",
        f"{SOURCE}, section 4: mu_PTRB{_case[0]} ranged from {_mu_lo} to {_mu_hi}",
        f"1 if the prototype's {_case} friction coefficient over 10-30 kN and 100-4000 rpm lies inside "
        f"[{_mu_lo}, {_mu_hi}] (printed bounds, no rounding allowance), else 0",
        1.0,
        _mu_inside(_case),
        unit="1",
        tolerance=0.0,
    )


def _life(load_ratio: float) -> float:
    """L10 [10⁶ rev] at P/C = ``load_ratio`` (ISO 281 basic rating life, ball exponent 3)."""
    from bearingkit.physics.life.iso281_life import MILLION, basic_rating_life

    return float(basic_rating_life(1.0, load_ratio, "ball")) / MILLION


for _pct, (_ratio, _pub) in SECTION4_LIVES.items():
    _register(
        f"seed004/section4/life/{_pct}pct",
        f"{SOURCE}, section 4 ('a constant load of 40-100% of the basic dynamic load rating ... from 15.6 "
        "million to 1.0 million' revolutions)",
        f"basic rating life L10 [10^6 rev] at P = {_pct} % of the dynamic rating (ISO 281, ball: exponent 3)",
        _pub,
        lambda r=_ratio: _life(r),
        unit="1",
        tolerance=0.005,  # printed to 3 digits
    )

_register(
    "seed004/section8/mu_a/max",
    f"{SOURCE}, section 8 ('mu_PTRBa and mu_PTRBr ranged from 0.0011 to 0.0023 and 0.0016 to 0.0031')",
    "max of the prototype's axial friction coefficient over 10-30 kN and 100-4000 rpm (section 8 prints "
    "0.0023 where section 4 prints 0.0024 for the same range)",
    SECTION8_MU_A_MAX,
    _mu_end("axial", 1),
    unit="1",
)


def other_parameters_max_change() -> float:
    """Largest |M(high) − M(low)| [N·m] over Table 5's ranges of n, R_rr, d_R and Z (20 kN, 4000 rpm)."""
    out = 0.0
    for param, ((lo, hi), unit, _, _) in TABLE5.items():
        if param == "contact_angle":
            continue
        for case in ("axial", "radial"):
            m_lo, m_hi = (_friction(case, 20.0, 4000.0, param, _si(x, unit))() for x in (lo, hi))
            out = max(out, abs(m_hi - m_lo))
    return out


_register(
    "seed004/section5/other-parameters-below-0.1Nm",
    f"{SOURCE}, section 5 (2) ('the effect of other structural parameters on friction torque was less "
    "than 0.1 Nm')",
    "indicator: 1 if the largest change of the friction torque over the Table 5 range of n, R_rr, d_R and Z "
    "(axial and radial, 20 kN, 4000 rpm) is below 0.1 N*m",
    1.0,
    lambda: float(other_parameters_max_change() < SECTION5_OTHER_BOUND),
    unit="1",
    tolerance=0.0,
)
