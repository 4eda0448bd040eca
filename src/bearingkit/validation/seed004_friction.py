"""Seed 004 (Zheng et al. 2022, PTRB) friction validation cases: Tables 7, 8 and 5 (simulation columns).

SI values (N·m). Model: :func:`bearingkit.analysis.ptrb_friction.ptrb_friction` with its defaults
(prototype of Table 1, flat ring flanks, L-AN oil η₀ = 0.04 Pa·s, α = 2.46e-8 1/Pa, power convention,
Houpert EHL rolling resistance, uniform tooth shares, roller 0 under the radial load).

ONE number is calibrated: the contact traction μ_c, against ``seed004/table7/axial/20kN`` (0.476 N·m),
see :data:`bearingkit.physics.ptrb_friction.CONTACT_TRACTION_CALIBRATED`. All other cases follow.
Tolerance 0.15 (the task's; the paper's own test/simulation deviation is up to 0.1 N·m, i.e. 20–50 %).

Known deviations (stated per case):

* low load (1–2 kN) and high speed: the speed-dependent (viscous) part is under-predicted. Houpert's
  EHL rolling resistance gives about 60 % of the paper's speed slope (Table 8: +0.035 N·m from 600 to
  2000 rpm at 2 kN, bearingkit +0.02 N·m); the paper's M_v formula (Zheng et al. 2021) is not printed.
* Table 5 (4000 rpm): the same speed effect, plus trends bearingkit does not reproduce (α and n under
  axial load, d_R under both loads: the power balance makes the torque fall with d_R because the
  roller's relative angular speed ΔΩ/ω ∝ (1 + d_I/d_R) falls).
"""

from __future__ import annotations

import numpy as np

from bearingkit.analysis.ptrb_friction import RPM, design_geometry, ptrb_friction
from bearingkit.bearings.ptrb import ptrb_prototype
from bearingkit.validation.registry import Case, register

SOURCE = "Zheng et al. (2022) Machines 10:1051, doi:10.3390/machines10111051"
KN = 1.0e3
TOLERANCE = 0.15

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

_LOW_LOAD = (
    "under-predicted at low load: the speed-dependent viscous part (Houpert EHL rolling resistance) is "
    "~60 % of the paper's (its M_v formula, Zheng 2021, is not printed) and the load-independent part "
    "the paper has at 1 kN is missing"
)
_SPEED = (
    "under-predicted at high speed / low load: Houpert's EHL rolling resistance gives ~60 % of the "
    "paper's speed slope (the paper's M_v formula, Zheng 2021, is not printed)"
)
_T5_SPEED = "4000 rpm: the speed-dependent viscous part is under-predicted (see Table 8 cases)"
_T5_TREND = (
    "trend not reproduced: bearingkit's power balance weights spin by ΔΩ/ω ∝ 1 + d_I/d_R and Q^(4/3) "
    "sums fall with more contacts, while the paper's torque rises with α, n (axial) and d_R"
)
#: Cases whose computed value misses the tolerance, with their cause.
KNOWN_DEVIATIONS = {
    "seed004/table7/axial/1kN": _LOW_LOAD,
    "seed004/table7/radial/1kN": _LOW_LOAD,
    **{f"seed004/table8/axial/2kN/{s}rpm": _SPEED for s in TABLE8_SPEEDS},
    **{f"seed004/table8/radial/2kN/{s}rpm": _SPEED for s in TABLE8_SPEEDS},
    **{f"seed004/table8/axial/5kN/{s}rpm": _SPEED for s in TABLE8_SPEEDS[2:]},
    **{f"seed004/table8/radial/5kN/{s}rpm": _SPEED for s in TABLE8_SPEEDS[3:]},
    **{f"seed004/table8/axial/8kN/{s}rpm": _SPEED for s in TABLE8_SPEEDS[5:]},
    **{f"seed004/table8/radial/8kN/{s}rpm": _SPEED for s in TABLE8_SPEEDS[7:]},
    "seed004/table5/contact_angle/60deg/axial": _T5_TREND,
    "seed004/table5/contact_angle/30deg/radial": _T5_SPEED + "; the α effect under radial load is too strong",
    "seed004/table5/contact_angle/60deg/radial": _T5_SPEED + "; the α effect under radial load is too strong",
    "seed004/table5/n_teeth/16/axial": _T5_TREND,
    "seed004/table5/n_teeth/16/radial": _T5_SPEED,
    "seed004/table5/roller_contact_radius/4.5mm/axial": _T5_SPEED,
    "seed004/table5/roller_contact_radius/7.5mm/axial": _T5_SPEED,
    "seed004/table5/roller_pitch_diameter/7.2mm/axial": _T5_TREND,
    "seed004/table5/roller_pitch_diameter/7.2mm/radial": _T5_TREND,
    "seed004/table5/n_elements/11/axial": _T5_SPEED,
}


def _si(value, unit):
    return {"deg": np.radians(value), "mm": value * 1e-3, "1": int(value)}[unit]


def _friction(case, load_kn, speed_rpm, parameter=None, value=None):
    def compute() -> float:
        g = ptrb_prototype() if parameter is None else design_geometry(**{parameter: value})
        return float(ptrb_friction(g, load_kn * KN, speed_rpm * RPM, case).torque)

    return compute


def _register(case_id, source, quantity, published, compute):
    register(
        Case(
            id=case_id,
            source=source,
            quantity=quantity,
            unit="N*m",
            published=published,
            compute=compute,
            tolerance=TOLERANCE,
            known_deviation=KNOWN_DEVIATIONS.get(case_id),
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
