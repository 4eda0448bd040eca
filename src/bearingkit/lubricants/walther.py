"""The ASTM D341 (Walther) viscosity–temperature law as pure vectorised functions, and its constants.

Kinematic viscosity in m²/s at the boundary; the law itself works in centistokes (1 cSt = 1 mm²/s =
1e-6 m²/s) because its offset 0.7 is defined in cSt, and in kelvin. Temperatures at the boundary are
in °C (``temperature_C``, the unit the standards and the seeds use).

References: ASTM D341-09 (2015) Standard practice for viscosity–temperature charts for liquid
petroleum products; Walther C. (1931) Erdöl und Teer 7:382–384.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError

CST_TO_M2_PER_S = 1.0e-6  # [m²/s per cSt] 1 cSt = 1 mm²/s (exact)
KELVIN_OFFSET = 273.15  # [K] T[K] = T[°C] + 273.15 (exact)
WALTHER_OFFSET_CST = 0.7  # [cSt] ASTM D341, Z = ν + 0.7; the simple form holds for ν ≥ 2 cSt
#   (below 2 cSt ASTM D341-09 adds exp(−1.47 − 1.84ν − 0.51ν²) to Z: not modelled).
WALTHER_TEMPERATURE_MIN_C = -50.0  # [°C] lower limit of use of the Walther law in bearingkit
WALTHER_TEMPERATURE_MAX_C = 250.0  # [°C] upper limit (mineral oils decompose/evaporate above this)
REFERENCE_TEMPERATURE_40_C = 40.0  # [°C] ISO 3448 / ASTM D2270 reference temperature
REFERENCE_TEMPERATURE_100_C = 100.0  # [°C] ASTM D2270 reference temperature


def check_temperature(temperature_C, field: str = "temperature_C"):
    """``temperature_C`` when it lies in the law's range [−50, 250] °C, else the one-line InputError."""
    return checks.in_range(field, temperature_C, WALTHER_TEMPERATURE_MIN_C, WALTHER_TEMPERATURE_MAX_C, "degC")


def _loglog(kinematic_viscosity):
    nu_cst = np.asarray(kinematic_viscosity, dtype=float) / CST_TO_M2_PER_S
    return np.log10(np.log10(nu_cst + WALTHER_OFFSET_CST))


def walther_coefficients(temperature_1_C, kinematic_viscosity_1, temperature_2_C, kinematic_viscosity_2):
    """Constants A, B of the ASTM D341 (Walther) line through two measured points.

    .. math::

        \\log_{10}\\log_{10}(\\nu + 0.7) = A - B\\,\\log_{10} T

    with ν in cSt (mm²/s) and T in kelvin; hence

    .. math::

        B = \\frac{W_1 - W_2}{\\log_{10}T_2 - \\log_{10}T_1}, \\quad A = W_1 + B\\log_{10}T_1,
        \\quad W_i = \\log_{10}\\log_{10}(\\nu_i + 0.7).

    Parameters
    ----------
    temperature_1_C, temperature_2_C : float or array_like
        Temperatures of the two points [°C], distinct, in [−50, 250].
    kinematic_viscosity_1, kinematic_viscosity_2 : float or array_like
        Kinematic viscosities at those temperatures [m²/s], > 0.

    Returns
    -------
    (A, B) : tuple of float or ndarray
        Walther constants [-] (B > 0 when viscosity falls with temperature).

    References
    ----------
    ASTM D341-09 (2015) Standard practice for viscosity–temperature charts for liquid petroleum
    products (the Walther form with Z = ν + 0.7); Walther C. (1931) Erdöl und Teer 7:382–384.
    """
    check_temperature(temperature_1_C, "temperature_1_C")
    check_temperature(temperature_2_C, "temperature_2_C")
    checks.positive("kinematic_viscosity_1", kinematic_viscosity_1, "m^2/s")
    checks.positive("kinematic_viscosity_2", kinematic_viscosity_2, "m^2/s")
    log_t1 = np.log10(np.asarray(temperature_1_C, dtype=float) + KELVIN_OFFSET)
    log_t2 = np.log10(np.asarray(temperature_2_C, dtype=float) + KELVIN_OFFSET)
    if np.any(log_t1 == log_t2):
        raise InputError(
            f"temperature_2_C ({float(np.max(temperature_2_C)):.6g} degC) must differ from temperature_1_C"
        )
    w1 = _loglog(kinematic_viscosity_1)
    w2 = _loglog(kinematic_viscosity_2)
    b = (w1 - w2) / (log_t2 - log_t1)
    a = w1 + b * log_t1
    return a, b


def walther_kinematic_viscosity(temperature_C, a, b):
    """Kinematic viscosity from the ASTM D341 (Walther) constants.

    .. math::

        \\nu = 10^{10^{A - B\\log_{10} T}} - 0.7 \\quad [\\mathrm{cSt}], \\qquad T = T_C + 273.15

    Parameters
    ----------
    temperature_C : float or array_like
        Temperature [°C], in [−50, 250].
    a, b : float or array_like
        Walther constants A, B [-] from :func:`walther_coefficients`.

    Returns
    -------
    ndarray
        Kinematic viscosity ν [m²/s].

    References
    ----------
    ASTM D341-09 (2015), the Walther form with Z = ν + 0.7.
    """
    check_temperature(temperature_C)
    log_t = np.log10(np.asarray(temperature_C, dtype=float) + KELVIN_OFFSET)
    nu_cst = 10.0 ** (10.0 ** (np.asarray(a) - np.asarray(b) * log_t)) - WALTHER_OFFSET_CST
    return nu_cst * CST_TO_M2_PER_S
