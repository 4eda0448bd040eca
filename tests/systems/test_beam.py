"""Timoshenko shaft elements against closed forms (Cowper 1966; Timoshenko & Gere; Przemieniecki 1968).

Closed forms used (prismatic beam, E, G = E/2(1+ν), I, A, κ):
- cantilever, tip force P: tip deflection P L³/(3EI) + P L/(κ G A), tip rotation P L²/(2EI)
  (bending plus the shear angle P/(κGA) along the length; the section rotation has no shear part);
- simply supported, uniform load w: mid-span deflection 5 w L⁴/(384 EI) + w L²/(8 κ G A).
The element is exact for end loads and, with its consistent loads, for uniform loads (module
docstring of bearingkit.systems.shaft.beam), so the tolerance is round-off (1e-9 relative).
"""

from __future__ import annotations

import numpy as np
import pytest

from bearingkit.systems.shaft import beam
from bearingkit.systems.shaft.shaft import Section, Shaft
from bearingkit.systems.shaft.solver import rigid_modes

E, NU = 210e9, 0.3
G = E / (2 * (1 + NU))


def test_cowper_shear_coefficients():
    """Cowper (1966) Table 1: solid circle 6(1+ν)/(7+6ν); thin-walled tube (m → 1) 2(1+ν)/(4+3ν)."""
    assert beam.shear_coefficient(NU, 0.0) == pytest.approx(6 * 1.3 / 8.8, rel=1e-15)
    assert beam.shear_coefficient(NU, 1.0) == pytest.approx(2 * 1.3 / 4.9, rel=1e-15)
    k = beam.shear_coefficient(NU, np.linspace(0, 1, 11))
    assert np.all(np.diff(k) < 0)  # a thinner wall shears more


def test_rigid_body_modes_carry_no_force():
    """The five rigid motions of the shaft (translations, tilts about x and y) are stress-free."""
    area, inertia = beam.section_properties(0.05, 0.02)
    kappa = beam.shear_coefficient(NU, 0.4)
    k = beam.element_stiffness(E, G, area, inertia, kappa, 0.08)
    z1, z2 = 0.3, 0.38
    for mode in range(5):
        u = np.concatenate([rigid_modes(z1)[mode], rigid_modes(z2)[mode]])
        assert np.abs(k @ u).max() <= 1e-6 * np.abs(k).max() * np.abs(u).max()
    assert np.allclose(k, k.T, rtol=0, atol=1e-9 * np.abs(k).max())
    assert np.linalg.eigvalsh(k).min() > -1e-6 * np.abs(k).max()


def _cantilever(plane: str, shear: bool):
    length, d = 0.12, 0.06  # L/d = 2: shear is ~20 % of the tip deflection
    shaft = Shaft((Section(0.0, length, d),), shear_deformation=shear)
    mesh = shaft.mesh(max_element_length=length / 7)
    k = mesh.stiffness
    n = mesh.n_dof
    f = np.zeros(n)
    p = 1000.0
    f[n - 5 + (0 if plane == "x" else 1)] = p
    free = np.arange(5, n)
    u = np.zeros(n)
    u[free] = np.linalg.solve(k[np.ix_(free, free)], f[free])
    area, inertia = beam.section_properties(d)
    kappa = beam.shear_coefficient(NU)
    tip = p * length**3 / (3 * E * inertia) + (p * length / (kappa * G * area) if shear else 0.0)
    rot = p * length**2 / (2 * E * inertia)
    return u[n - 5 :], tip, rot


@pytest.mark.parametrize("shear", [True, False])
def test_cantilever_tip_in_both_planes(shear):
    ux, tip, rot = _cantilever("x", shear)
    assert ux[0] == pytest.approx(tip, rel=1e-9)
    assert ux[4] == pytest.approx(rot, rel=1e-9)  # θ_y = +du_x/dz
    uy, tip_y, rot_y = _cantilever("y", shear)
    assert uy[1] == pytest.approx(tip_y, rel=1e-9)
    assert uy[3] == pytest.approx(-rot_y, rel=1e-9)  # θ_x = −du_y/dz
    if shear:
        _, tip_eb, _ = _cantilever("x", False)
        assert tip / tip_eb - 1 > 0.1  # the check would fail without the shear term


def test_uniform_load_simply_supported_mid_span():
    length, d, w = 0.2, 0.05, 2.0e5  # [m, m, N/m]
    shaft = Shaft((Section(0.0, length, d),))
    mesh = shaft.mesh(max_element_length=length / 10)
    q = np.zeros((1, len(mesh.length), 3))
    q[..., 1] = w
    f = np.zeros(mesh.n_dof)
    np.add.at(f, mesh.element_dofs(), beam.uniform_load_vector(q, mesh.length)[0])
    # Pin both ends in x, y, z (and the tilt about z is not a DOF); the twist-free beam keeps the rest free.
    held = [0, 1, 2, mesh.n_dof - 5, mesh.n_dof - 4]
    free = np.setdiff1d(np.arange(mesh.n_dof), held)
    u = np.zeros(mesh.n_dof)
    u[free] = np.linalg.solve(mesh.stiffness[np.ix_(free, free)], f[free])
    area, inertia = beam.section_properties(d)
    kappa = beam.shear_coefficient(NU)
    mid = 5 * w * length**4 / (384 * E * inertia) + w * length**2 / (8 * kappa * G * area)
    assert u[5 * mesh.node(length / 2) + 1] == pytest.approx(mid, rel=1e-9)
