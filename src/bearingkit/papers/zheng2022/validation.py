"""Seed 004 (Zheng et al. 2022, PTRB) validation cases: prototype ratings and Table 4 sweep endpoints.

SI values (N). Geometry: :func:`bearingkit.bearings.ptrb.ptrb_prototype` (Table 1, flat ring flanks).

* ``seed004/prototype/{C0a,Ca,C0r,Cr}`` — §4 (and Table 3, Table 6's prototype column, §8: the same
  numbers), tolerance 2 %. C0a and C0r are CALIBRATIONS (role ``calibration``): the core-compliance
  factor of the tooth load-sharing model (f_amax) is identified on C0a, the Stribeck constant k_r of
  f_rmax on C0r (:mod:`bearingkit.physics.life.ptrb_rating`); Ca and Cr follow as predictions.
* ``seed004/table4/<parameter>/<value>/<rating>`` — each structural parameter's sweep endpoints of
  Table 4, with the other parameters at the prototype values, D_pw fixed (d_I = D_pw − d_R,
  d_O = D_pw + d_R) and n·P fixed (12 mm); f_amax of each design from the load-sharing model at the §5
  load of 20 kN (issue 32; Table 4 implies f_amax varies with the design). Tolerance 2 % (4 printed
  digits; issue 32 allows 10 %). The Z = 11 endpoint is the prototype itself: diagnostics (Table 4
  prints its C_a as 33.07 kN, every other place 33.20 kN).
"""

from __future__ import annotations

import numpy as np

from bearingkit.bearings.ptrb import ptrb_prototype, ptrb_ratings
from bearingkit.validation.registry import Case, register

SOURCE = "Zheng et al. (2022) Machines 10:1051, doi:10.3390/machines10111051"
KN = 1.0e3
TOL_PROTOTYPE = 0.02
TOL_TABLE4 = 0.02
_THREAD_LENGTH = 12.0e-3  # n·P of the prototype [m], held in the n sweep

_ATTR = {"C0a": "static_axial", "C0r": "static_radial", "Ca": "dynamic_axial", "Cr": "dynamic_radial"}
PROTOTYPE = {"C0a": 38.36, "Ca": 33.20, "C0r": 19.93, "Cr": 30.26}
_CALIBRATED = {
    "C0a": "the core-compliance factor of the f_amax model, ptrb_rating.BODY_COMPLIANCE_FACTOR",
    "C0r": "the Stribeck constant k_r of f_rmax = k_r/Z, ptrb_rating.K_RMAX_CALIBRATED",
}

#: Table 4: parameter → ((low, high) in display units, unit, {rating: (low, high) kN}).
TABLE4 = {
    "contact_angle": (
        (30, 60),
        "deg",
        {"C0a": (22.49, 66.27), "C0r": (19.60, 20.19), "Ca": (18.63, 66.79), "Cr": (26.31, 38.44)},
    ),
    "n_teeth": (
        (8, 16),
        "1",
        {"C0a": (30.98, 59.65), "C0r": (15.87, 32.14), "Ca": (28.53, 44.75), "Cr": (25.89, 42.05)},
    ),
    "roller_contact_radius": (
        (4.5, 7.5),
        "mm",
        {"C0a": (34.24, 54.05), "C0r": (17.72, 28.40), "Ca": (31.52, 38.48), "Cr": (28.79, 35.42)},
    ),
    "roller_pitch_diameter": (
        (4.8, 7.2),
        "mm",
        {"C0a": (31.77, 44.12), "C0r": (16.16, 23.41), "Ca": (23.88, 42.50), "Cr": (21.45, 39.62)},
    ),
    "n_elements": (
        (7, 11),
        "1",
        {"C0a": (24.85, 38.36), "C0r": (12.67, 19.93), "Ca": (24.87, 33.07), "Cr": (22.39, 30.26)},
    ),
}


def sweep_geometry(parameter: str, value: float):
    """The prototype with one Table 4 parameter changed (value in SI: rad, m or count)."""
    base = ptrb_prototype()
    changes = {parameter: value}
    if parameter == "roller_pitch_diameter":
        changes.update(
            inner_pitch_diameter=base.pitch_diameter - value, outer_pitch_diameter=base.pitch_diameter + value
        )
    if parameter == "n_teeth":
        changes["thread_pitch"] = _THREAD_LENGTH / value
    if parameter in ("n_teeth", "n_elements"):
        changes[parameter] = int(value)
    return ptrb_prototype(**changes)


def to_si(value: float, unit: str) -> float:
    return {"deg": np.radians(value), "mm": value * 1e-3, "1": value}[unit]


def _compute(parameter, value, rating):
    def compute() -> float:
        geometry = ptrb_prototype() if parameter is None else sweep_geometry(parameter, value)
        return float(getattr(ptrb_ratings(geometry), _ATTR[rating]))

    return compute


for _name, _value in PROTOTYPE.items():
    _cal = _name in _CALIBRATED
    register(
        Case(
            id=f"seed004/prototype/{_name}",
            source=f"{SOURCE}, section 4 and Table 3",
            quantity=f"PTRB prototype basic load rating {_name}",
            unit="N",
            published=_value * KN,
            compute=_compute(None, None, _name),
            tolerance=1e-3 if _cal else TOL_PROTOTYPE,
            role="calibration" if _cal else "prediction",
            note=f"{_CALIBRATED[_name]} is identified on this number" if _cal else None,
        )
    )

for _param, ((_lo, _hi), _unit, _ratings) in TABLE4.items():
    for _k, _v in enumerate((_lo, _hi)):
        for _rating, _pub in _ratings.items():
            register(
                Case(
                    id=f"seed004/table4/{_param}/{_v}{'' if _unit == '1' else _unit}/{_rating}",
                    source=f"{SOURCE}, Table 4",
                    quantity=f"{_rating} of the prototype with {_param} = {_v} {_unit}",
                    unit="N",
                    published=_pub[_k] * KN,
                    compute=_compute(_param, to_si(_v, _unit), _rating),
                    tolerance=TOL_TABLE4,
                    role="diagnostic" if _param == "n_elements" and _v == 11 else "prediction",
                    note=(
                        f"the prototype itself (Z = 11): the counted case is seed004/prototype/{_rating}"
                        + (
                            " (Table 4 prints 33.07 kN, sections 4 and 8 and Tables 3 and 6 33.20 kN)"
                            if _rating == "Ca"
                            else ""
                        )
                        if _param == "n_elements" and _v == 11
                        else None
                    ),
                )
            )
