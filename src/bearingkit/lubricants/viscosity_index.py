"""Viscosity index (ASTM D2270) from ν40 and ν100, and ν100 from ν40 and a viscosity index.

Kinematic viscosities in m²/s at the boundary (the standard works in mm²/s; converted inside). The L
and H values of ASTM D2270 Table 1 (ν100 = 2 … 70 mm²/s) are in ``bearingkit/data/astm_d2270_lh.csv``
(linear interpolation between rows, as the standard allows); above 70 mm²/s the standard's closed forms
apply:

.. math::

    L = 0.8353\\,Y^2 + 14.67\\,Y - 216, \\qquad H = 0.1684\\,Y^2 + 11.85\\,Y - 97

(Y = ν100 in mm²/s; from memory of the standard [M], checked in the tests to meet the table's last row
within 0.1 %). Procedure A (VI ≤ 100) and B (VI > 100):

.. math::

    \\mathrm{VI} = 100\\,\\frac{L - U}{L - H}; \\qquad
    N = \\frac{\\log H - \\log U}{\\log Y},\\quad \\mathrm{VI} = \\frac{10^N - 1}{0.00715} + 100

with U = ν40. The VI is not defined for ν100 < 2 mm²/s (an InputError says so).

References: ASTM D2270-10 (2016) Standard practice for calculating viscosity index from kinematic
viscosity at 40 and 100 °C, Table 1 and clauses 6–7.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.lubricants.tables import rows

_TABLE = "astm_d2270_lh.csv"
MM2_PER_S = 1.0e-6  # m²/s per mm²/s
#: Lowest ν100 for which ASTM D2270 defines a VI [mm²/s].
NU100_MIN_MM2_S = 2.0
#: Last row of Table 1 [mm²/s]; above it the closed forms apply.
NU100_TABLE_MAX_MM2_S = 70.0
#: ASTM D2270 closed forms above 70 mm²/s: L = a Y² + b Y + c, H likewise [M].
L_ABOVE_70 = (0.8353, 14.67, -216.0)
H_ABOVE_70 = (0.1684, 11.85, -97.0)
#: Procedure B constant.
PROCEDURE_B = 0.00715
#: Largest ν100 searched when a ν100 is found from a VI [mm²/s] (far above any lubricating oil).
NU100_SEARCH_MAX_MM2_S = 5000.0


def _columns():
    table = rows(_TABLE)
    y = np.array([float(r["nu100_mm2_s"]) for r in table])
    return y, np.array([float(r["L_mm2_s"]) for r in table]), np.array([float(r["H_mm2_s"]) for r in table])


def reference_viscosities(nu100_mm2_s):
    """(L, H) [mm²/s] of ASTM D2270 for ν100 = Y [mm²/s] ≥ 2 (table, then closed forms above 70)."""
    y = np.asarray(nu100_mm2_s, dtype=float)
    ty, tl, th = _columns()
    inside = y <= NU100_TABLE_MAX_MM2_S
    big_l = np.where(inside, np.interp(y, ty, tl), np.polyval(L_ABOVE_70, y))
    big_h = np.where(inside, np.interp(y, ty, th), np.polyval(H_ABOVE_70, y))
    return big_l, big_h


def viscosity_index(kinematic_viscosity_40, kinematic_viscosity_100):
    """Viscosity index VI [-] by ASTM D2270 (procedure A up to 100, B above).

    Parameters
    ----------
    kinematic_viscosity_40, kinematic_viscosity_100 : array_like
        ν40 > ν100 ≥ 2 mm²/s, in m²/s.

    Returns
    -------
    ndarray
        VI (not rounded; the standard rounds to the nearest whole number).
    """
    checks.positive("kinematic_viscosity_40", kinematic_viscosity_40, "m^2/s")
    checks.positive("kinematic_viscosity_100", kinematic_viscosity_100, "m^2/s")
    u = np.asarray(kinematic_viscosity_40, dtype=float) / MM2_PER_S
    y = np.asarray(kinematic_viscosity_100, dtype=float) / MM2_PER_S
    if np.any(y < NU100_MIN_MM2_S):
        raise InputError(
            f"kinematic_viscosity_100 ({checks._fmt(y)} mm^2/s) must be at least {NU100_MIN_MM2_S:g} mm^2/s "
            "for a viscosity index (ASTM D2270)"
        )
    big_l, big_h = reference_viscosities(y)
    vi_a = 100.0 * (big_l - u) / (big_l - big_h)
    n = (np.log10(big_h) - np.log10(u)) / np.log10(y)
    vi_b = (10.0**n - 1.0) / PROCEDURE_B + 100.0
    return np.where(vi_a > 100.0, vi_b, vi_a)


def nu100_from_vi(kinematic_viscosity_40, vi):
    """ν100 [m²/s] of an oil with ν40 and viscosity index VI (ASTM D2270 solved for ν100).

    VI rises with ν100 at fixed ν40 (L and H both grow with ν100), so the root is bracketed between
    2 mm²/s and :data:`NU100_SEARCH_MAX_MM2_S` and found by bisection, batched over the inputs, to a
    relative 1e-12.

    Parameters
    ----------
    kinematic_viscosity_40 : array_like
        ν40 [m²/s], > 0.
    vi : array_like
        Viscosity index [-], finite.

    Returns
    -------
    ndarray
        ν100 [m²/s]; InputError when no ν100 ≥ 2 mm²/s below ν40 has that VI.
    """
    checks.positive("kinematic_viscosity_40", kinematic_viscosity_40, "m^2/s")
    checks.finite("vi", vi)
    u = np.asarray(kinematic_viscosity_40, dtype=float)
    v = np.asarray(vi, dtype=float)
    u, v = np.broadcast_arrays(u, v)
    lo = np.full(u.shape, NU100_MIN_MM2_S * MM2_PER_S)
    hi = np.minimum(u, NU100_SEARCH_MAX_MM2_S * MM2_PER_S)
    if (
        np.any(hi <= lo)
        or np.any(viscosity_index(u, lo) > v)
        or np.any(viscosity_index(u, hi * (1 - 1e-12)) < v)
    ):
        raise InputError(
            f"vi ({checks._fmt(v)}) with nu_40 ({checks._fmt(u / MM2_PER_S)} mm^2/s) gives no nu_100 between "
            f"{NU100_MIN_MM2_S:g} mm^2/s and nu_40 (ASTM D2270); check both"
        )
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        low = viscosity_index(u, mid) < v
        lo, hi = np.where(low, mid, lo), np.where(low, hi, mid)
        if np.all(hi - lo <= 1e-12 * hi):
            break
    return 0.5 * (lo + hi)
