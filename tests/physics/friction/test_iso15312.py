"""ISO 15312 method: reference surface, reference heat flow, thermal reference speed (closed forms)."""

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.physics.friction import iso15312


def test_reference_surface_and_heat_flow():
    # 6205: B = 15, D = 52, d = 25 mm → A_r = π·15·77 mm² < 50 000 mm²: q_r = 16 kW/m².
    area = iso15312.reference_surface(0.025, 0.052, 0.015)
    assert area == pytest.approx(np.pi * 15 * 77 * 1e-6, rel=1e-14)
    assert iso15312.reference_heat_flow(area) == pytest.approx(16e3 * area, rel=1e-14)
    # Above 50 000 mm² the density falls as (A/50 000)^-0.34.
    assert iso15312.reference_heat_flow(0.1) == pytest.approx(16e3 * 2**-0.34 * 0.1, rel=1e-14)
    assert iso15312.reference_surface(0.045, 0.085, kind="thrust") == pytest.approx(
        np.pi / 2 * (0.085**2 - 0.045**2)
    )
    with pytest.raises(InputError, match="width"):
        iso15312.reference_surface(0.045, 0.085)


def test_thermal_reference_speed_solves_the_power_balance():
    k = 3e-4  # P = k ω² [W]
    omega = iso15312.thermal_reference_speed(lambda w: k * w**2, 58.0)
    assert omega == pytest.approx(np.sqrt(58.0 / k), rel=1e-9)
    assert np.isnan(iso15312.thermal_reference_speed(lambda w: 1e-9 * w, 58.0))
