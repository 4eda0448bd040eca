"""Lamé thick cylinders, shrink-fit pressure and thermal growth: closed forms."""

import numpy as np
import pytest

from bearingkit.physics.structure import fits

E, NU = 208e9, 0.3


def test_lame_displacement_closed_forms():
    # Solid cylinder under external pressure: u = −(1 − ν) p r / E (uniform biaxial compression).
    assert fits.lame_radial_displacement(0.02, 0.0, 0.03, 0.0, 50e6, E, NU) == pytest.approx(
        -(1 - NU) * 50e6 * 0.02 / E, rel=1e-13
    )
    # Internal pressure only, outside surface: u(b) = 2 p a² b / [E (b² − a²)], independent of ν.
    a, b, p = 0.0225, 0.02615, 40e6
    for nu in (0.0, 0.3, 0.45):
        assert fits.lame_radial_displacement(b, a, b, p, 0.0, E, nu) == pytest.approx(
            2 * p * a**2 * b / (E * (b**2 - a**2)), rel=1e-13
        )


def test_fit_pressure_closes_the_interference():
    """The pressure closes the gap: 2[u_outer(d/2) − u_inner(d/2)] = Δ (hollow shaft, two materials)."""
    d, d_i, d_o, delta = 0.045, 0.02, 0.0523, 13.5e-6
    e_s, nu_s, e_r, nu_r = 200e9, 0.29, 208e9, 0.3
    p = fits.fit_pressure(delta, d, d_i, d_o, e_s, nu_s, e_r, nu_r)
    u_ring = fits.lame_radial_displacement(d / 2, d / 2, d_o / 2, p, 0.0, e_r, nu_r)
    u_shaft = fits.lame_radial_displacement(d / 2, d_i / 2, d / 2, 0.0, p, e_s, nu_s)
    assert 2 * (u_ring - u_shaft) == pytest.approx(delta, rel=1e-12)
    assert fits.fit_pressure(-5e-6, d, 0.0, d_o, E, NU, E, NU) == 0.0  # a clearance fit presses nothing


def test_same_material_solid_shaft_rule_and_infinite_housing():
    """Solid shaft, same material: the raceway grows by Δ·d/d_r; a ring in an infinite housing of its
    material shrinks by Δ·D_r/D (Harris & Kotzalas' fitting rules)."""
    d, d_r, delta = 0.045, 0.0523, 13.5e-6
    p = fits.fit_pressure(delta, d, 0.0, d_r, E, NU, E, NU)
    assert fits.ring_expansion(p, d, d_r, E) == pytest.approx(delta * d / d_r, rel=1e-13)
    big_d, d_or = 0.085, 0.0777
    p = fits.fit_pressure(delta, big_d, d_or, np.inf, E, NU, E, NU)
    assert fits.ring_contraction(p, d_or, big_d, E) == pytest.approx(delta * d_or / big_d, rel=1e-13)


def test_thermal_growth():
    assert fits.thermal_growth(0.0523, 11.9e-6, 40.0) == pytest.approx(0.0523 * 11.9e-6 * 40.0, rel=1e-15)
