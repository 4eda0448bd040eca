"""Thermal reference speed (ISO 15312): reference conditions, reference heat flow, the speed balance.

SI units: m², W, W/m², rad/s, °C, m²/s. ISO 15312:2018 defines the thermal reference speed n_θr of a
bearing as the speed at which, under reference conditions, the frictional heat equals the heat the
bearing's reference surface carries away:

    M(n_θr) · ω_θr = q_r · A_r,
    q_r = 16 kW/m²                          for A_r ≤ 50 000 mm²,
    q_r = 16 (A_r / 50 000 mm²)^−0.34 kW/m² for A_r > 50 000 mm²,
    A_r = π B (D + d)  (radial bearings),   A_r = (π/2)(D² − d²)  (thrust bearings),

at a bearing temperature of 70 °C, 20 °C ambient, an oil of ν_r = 12 mm²/s (radial) or 24 mm²/s
(thrust) at 70 °C, and a load of 5 % of C0 (radial) or 2 % of C0a (thrust). The standard's own
friction coefficients f0r, f1r are not carried by bearingkit: the moment M comes from one of its
friction models evaluated under the reference conditions (so n_θr is that model's, not the
catalogue's). All constants here are from memory of ISO 15312 [M].

References: ISO 15312:2018 Rolling bearings — Thermal speed rating — Calculation, clauses 3–6.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks, references
from bearingkit.errors import InputError

references.add(
    "iso15312",
    "ISO 15312:2018 Rolling bearings - Thermal speed rating - Calculation.",
)

#: Reference heat flow density for small reference surfaces [W/m²] and the area where it starts to drop [m²].
REFERENCE_HEAT_FLOW_DENSITY = 16.0e3
REFERENCE_AREA_KNEE = 50_000e-6
REFERENCE_AREA_EXPONENT = -0.34
#: Reference temperatures [°C]: bearing (outer ring) and ambient.
REFERENCE_BEARING_TEMPERATURE = 70.0
REFERENCE_AMBIENT_TEMPERATURE = 20.0
#: Reference kinematic viscosity at 70 °C [m²/s]: radial and thrust bearings.
REFERENCE_VISCOSITY = {"radial": 12e-6, "thrust": 24e-6}
#: Reference load as a share of the static load rating: radial (C0r) and thrust (C0a).
REFERENCE_LOAD_SHARE = {"radial": 0.05, "thrust": 0.02}


def reference_surface(bore, outside_diameter, width=None, kind="radial"):
    """Heat-emitting reference surface A_r of ISO 15312.

    .. math::
        A_r = \\pi B (D + d)\\ \\text{(radial)},\\quad A_r = \\tfrac{\\pi}{2}(D^2 - d^2)\\ \\text{(thrust)}

    Parameters
    ----------
    bore, outside_diameter : float [m]
        d and D.
    width : float [m] or None
        B (radial bearings; total height for thrust bearings is not needed).
    kind : {"radial", "thrust"}

    Returns
    -------
    float [m²]

    References
    ----------
    ISO 15312:2018 clause 5 [M].
    """
    checks.one_of("kind", kind, REFERENCE_VISCOSITY)
    checks.positive("bore", bore, "m")
    checks.greater("outside_diameter", outside_diameter, "bore", bore, "m")
    if kind == "thrust":
        return float(np.pi / 2 * (outside_diameter**2 - bore**2))
    if width is None:
        raise InputError("width (None) is needed for the reference surface of a radial bearing: give B")
    checks.positive("width", width, "m")
    return float(np.pi * width * (outside_diameter + bore))


def reference_heat_flow(area):
    """Reference heat flow Φ_r = q_r A_r [W] through the reference surface (module docstring).

    Parameters
    ----------
    area : array_like [m²]
        A_r.

    Returns
    -------
    ndarray [W]

    References
    ----------
    ISO 15312:2018 clause 6 [M].
    """
    checks.positive("area", area, "m^2")
    a = np.asarray(area, dtype=float)
    q = REFERENCE_HEAT_FLOW_DENSITY * np.where(
        a <= REFERENCE_AREA_KNEE, 1.0, (a / REFERENCE_AREA_KNEE) ** REFERENCE_AREA_EXPONENT
    )
    return q * a


def thermal_reference_speed(friction_power, heat_flow, low=1.0, high=1.0e4):
    """Speed ω at which ``friction_power(ω)`` equals ``heat_flow`` (bisection on a log scale).

    Parameters
    ----------
    friction_power : callable
        ω [rad/s] → frictional power [W] under the reference conditions (increasing in ω).
    heat_flow : float [W]
        Reference heat flow Φ_r.
    low, high : float [rad/s]
        Search bracket.

    Returns
    -------
    float [rad/s]
        n_θr as an angular speed; NaN when the power stays below Φ_r up to ``high``.

    References
    ----------
    ISO 15312:2018 clause 6 (the heat balance defining n_θr) [M].
    """
    checks.positive("heat_flow", heat_flow, "W")
    if friction_power(high) < heat_flow:
        return float("nan")
    lo, hi = np.log(low), np.log(high)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if friction_power(np.exp(mid)) > heat_flow:
            hi = mid
        else:
            lo = mid
    return float(np.exp(0.5 * (lo + hi)))
