"""Friction components: closed forms, quadrature checks, zero limits, input validation."""

import numpy as np
import pytest
from scipy.integrate import quad

from bearingkit.errors import InputError
from bearingkit.physics.friction import components as fc


def test_registry_names():
    assert set(fc.COMPONENTS) == {
        "hysteresis_roller",
        "hysteresis_ball",
        "differential_sliding",
        "viscous_roller",
        "viscous_ball",
        "spin_ball",
        "cage",
        "roller_sliding",
    }
    assert set(fc.VISCOUS_LINE_MODELS) == {"matsuyama", "aihara"}
    assert set(fc.VISCOUS_POINT_MODELS) == {"fujiwara", "houpert"}


def test_line_front_moment_by_quadrature():
    # ∫0^b p x dx with p = p0 sqrt(1 - x²/b²), q = π p0 b / 2 per unit length → (2/3π) q b.
    b, p0 = 1.0, 1.0
    m, _ = quad(lambda x: p0 * np.sqrt(1 - x**2) * x, 0, b)
    assert m == pytest.approx(fc.LINE_FRONT_MOMENT * (np.pi * p0 * b / 2) * b)
    assert fc.hysteresis_force_line(10.0, 2e-5, 2e-3, 0.01) == pytest.approx(
        0.01 * m / (np.pi / 2) * 10 * 2e-5 / 2e-3
    )


def test_point_front_moment_and_spin_circle():
    # Circle a = b: spin moment (3/8) μ Q a E(0) = 3π μ Q a /16 (closed form).
    assert fc.spin_moment(100.0, 1e-4, 1.0, 0.1) == pytest.approx(3 * np.pi * 0.1 * 100 * 1e-4 / 16)
    # Front-half moment of the Hertz ellipse = 3 Q b /16 (polar quadrature over the unit disc)
    inner = quad(lambda r: np.sqrt(1 - r**2) * r**2, 0, 1)[0] * 2  # ∫_{-π/2}^{π/2} cos θ dθ = 2
    total = quad(lambda r: np.sqrt(1 - r**2) * r, 0, 1)[0] * 2 * np.pi
    assert inner / total == pytest.approx(fc.POINT_FRONT_MOMENT)


def test_spin_grows_with_ellipticity():
    assert fc.spin_moment(100.0, 1e-4, 5.0, 0.1) < fc.spin_moment(100.0, 1e-4, 1.0, 0.1)


@pytest.mark.parametrize("name", ["matsuyama", "aihara"])
def test_viscous_line_zero_speed_and_monotone(name):
    f = fc.VISCOUS_LINE_MODELS[name]
    args = dict(
        viscosity=0.2, pressure_viscosity=2e-8, e_reduced=2.3e11, radius_x=2e-3, effective_length=4.8e-3
    )
    assert f(50.0, entrainment_speed=0.0, **args) == 0.0
    lo, hi = f(50.0, entrainment_speed=0.1, **args), f(50.0, entrainment_speed=1.0, **args)
    assert 0 < lo < hi


@pytest.mark.parametrize("name", ["fujiwara", "houpert"])
def test_viscous_point_zero_speed_and_monotone(name):
    f = fc.VISCOUS_POINT_MODELS[name]
    args = dict(
        viscosity=0.2,
        pressure_viscosity=2e-8,
        e_reduced=2.3e11,
        radius_x=3e-3,
        semi_major=4e-4,
        semi_minor=8e-5,
    )
    assert f(100.0, entrainment_speed=0.0, **args) == pytest.approx(0.0)
    assert 0 < f(100.0, entrainment_speed=0.1, **args) < f(100.0, entrainment_speed=1.0, **args)


def test_sliding_and_cage():
    assert fc.sliding_power(10.0, -0.2, 0.1) == pytest.approx(0.2)
    assert fc.cage_torque(1.0, 0.1, 0.2) == pytest.approx(0.01)


def test_bad_inputs_raise():
    with pytest.raises(InputError):
        fc.hysteresis_force_line(-1.0, 1e-5, 1e-3)
    with pytest.raises(InputError):
        fc.spin_moment(1.0, 1e-4, 0.5, 0.1)
    with pytest.raises(InputError):
        fc.sliding_power(1.0, np.nan, 0.1)
