"""Seed 004 (Zheng et al. 2022, PTRB) friction validation cases: Tables 7, 8 and 5 (simulation columns).

SI values (N·m). Model: :func:`bearingkit.analysis.ptrb_friction.ptrb_friction` with its defaults
(prototype of Table 1, flat ring flanks, L-AN oil η₀ = 0.04 Pa·s, α = 2.46e-8 1/Pa, power convention,
Harris EHL rolling resistance added to eq. (13) as printed ("eq13"), uniform tooth shares, roller 0
under the radial load).

ONE number is calibrated: the contact traction μ_c, against ``seed004/table7/axial/20kN`` (0.476 N·m),
see :data:`bearingkit.physics.ptrb_friction.CONTACT_TRACTION_CALIBRATED`. Nothing in the viscous
(speed-dependent) term is fitted. All other cases follow: Table 7 within 5.3 %, Table 8 within 3.6 %.
Tolerance 0.15 (the task's; the paper's own test/simulation deviation is up to 0.1 N·m, i.e. 20–50 %).

Known deviations (stated per case) are all in Table 5 (20 kN, 4000 rpm, one design parameter changed):

* d_R and α under axial load: the trend is opposite. bearingkit turns contact moments into bearing
  torque by the power balance, whose factor ΔΩ/ω ∝ 1 + d_I/d_R falls as d_R grows; the paper's eq.
  (13)–(15) sum contact moments without it. Under axial load a larger α lowers Q = F/(Z n sin α) and
  the viscous force (R_x ∝ 1/cos α enters F_v as R_x^-1.6).
* R_rr (and α under radial load) act too strongly: Harris's rolling resistance carries R_y² = R_rr²
  (flat ring flanks), so F_v triples from R_rr = 4.5 to 7.5 mm where the paper's torque rises 13 %.
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

_T5_DR = (
    "trend opposite (paper: torque rises with d_R): bearingkit's power balance weights every contact "
    "moment by the relative angular speed of roller and ring, dOmega/omega ~ 1 + d_I/d_R, which falls "
    "as d_R grows; the paper's eq. (13)-(15) sum contact moments without it"
)
_T5_ALPHA_AX = (
    "trend opposite under axial load (paper: +4.5 % from 30 to 60 deg): the contact load "
    "F/(Z n sin alpha) and Harris's viscous force (R_x ~ 1/cos alpha, F_v ~ R_x^-1.6) both fall with alpha"
)
_T5_ALPHA_RA = (
    "alpha acts too strongly under radial load (paper +67 %, bearingkit +120 % from 30 to 60 deg): the "
    "radial contact load F_r share/(2n cos alpha) grows with alpha and Harris's F_v with it"
)
_T5_RRR = (
    "R_rr acts too strongly (paper +11-13 %, bearingkit +67-82 % from 4.5 to 7.5 mm): Harris's rolling "
    "resistance carries R_y^2 = R_rr^2 with flat ring flanks, the paper's torque hardly feels R_rr"
)
#: Cases whose computed value misses the tolerance, with their cause.
KNOWN_DEVIATIONS = {
    "seed004/table5/contact_angle/30deg/axial": _T5_ALPHA_AX,
    "seed004/table5/contact_angle/60deg/axial": _T5_ALPHA_AX,
    "seed004/table5/contact_angle/60deg/radial": _T5_ALPHA_RA,
    "seed004/table5/roller_contact_radius/7.5mm/axial": _T5_RRR,
    "seed004/table5/roller_contact_radius/7.5mm/radial": _T5_RRR,
    "seed004/table5/roller_pitch_diameter/4.8mm/axial": _T5_DR,
    "seed004/table5/roller_pitch_diameter/7.2mm/axial": _T5_DR,
    "seed004/table5/roller_pitch_diameter/4.8mm/radial": _T5_DR,
    "seed004/table5/roller_pitch_diameter/7.2mm/radial": _T5_DR,
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
