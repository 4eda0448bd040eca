"""Timoshenko beam elements of a shaft: section properties, element stiffness, equivalent loads.

SI units (m, N, Pa, N·m, rad). The shaft axis is z, the bearing axis of design.md §3; x and y are
radial. Each node carries the five DOFs the bearings act on, in the bearings' order
(u_x, u_y, u_z, θ_x, θ_y); torsion θ_z is not modelled (no bearing reacts to it).

Sign of the rotations. A rigid rotation θ_y about +y moves a point at axial position z by u_x = θ_y z
and a rotation θ_x about +x by u_y = −θ_x z (right-hand rule; the same kinematics as
``rows/base.py``). In the x–z plane the Euler–Bernoulli slope is therefore θ_y = +du_x/dz and in the
y–z plane θ_x = −du_y/dz: the y–z plane uses the textbook planar element with the sign of its
rotation DOFs flipped.

Planar element (Przemieniecki 1968, *Theory of Matrix Structural Analysis*, ch. 5, the beam element
with shear deformation; Davis, Henshell & Warburton 1972, J. Sound Vib. 22(4) 475–487): with DOFs
(v₁, θ₁, v₂, θ₂), θ = dv/dz for the bending part, and the shear parameter Φ = 12 E I / (κ G A L²),

    K = E I / ((1 + Φ) L³) · [[ 12,       6L,   −12,       6L     ],
                               [ 6L, (4+Φ)L²,   −6L, (2−Φ)L²     ],
                               [−12,      −6L,    12,      −6L     ],
                               [ 6L, (2−Φ)L²,   −6L, (4+Φ)L²     ]].

It is exact for a prismatic Timoshenko beam loaded at its ends (it follows from the homogeneous
equations), so a shaft meshed with a node at every load, seat and step has exact nodal displacements.
The same holds for a uniform distributed load with the consistent nodal loads qL/2 and ±qL²/12: the
fixed-end moments of a Timoshenko beam under a uniform load are those of Euler–Bernoulli, because
both end slopes vanish by symmetry and the shear strain is antisymmetric.

Shear coefficient of a hollow circular section with m = d_i/d_o (Cowper 1966, J. Appl. Mech. 33(2)
335–340, Table 1):

    κ = 6 (1 + ν) (1 + m²)² / ((7 + 6ν)(1 + m²)² + (20 + 12ν) m²),   κ(m=0) = 6(1+ν)/(7+6ν).
"""

from __future__ import annotations

import numpy as np

#: DOFs per node and their names (the bearings' DOF order, design.md §3).
NODE_DOF = 5
#: Index of u_x, u_y, u_z, θ_x, θ_y in a node's DOFs.
UX, UY, UZ, TX, TY = range(NODE_DOF)


def section_properties(outer_diameter, inner_diameter=0.0) -> tuple[np.ndarray, np.ndarray]:
    """Area A [m²] and second moment of area I [m⁴] of a (hollow) circular section.

    A = π (d_o² − d_i²)/4,  I = π (d_o⁴ − d_i⁴)/64.

    Parameters
    ----------
    outer_diameter, inner_diameter : array_like [m]
    """
    do = np.asarray(outer_diameter, dtype=float)
    di = np.asarray(inner_diameter, dtype=float)
    return np.pi * (do**2 - di**2) / 4.0, np.pi * (do**4 - di**4) / 64.0


def shear_coefficient(poisson_ratio, diameter_ratio=0.0) -> np.ndarray:
    """Timoshenko shear coefficient κ [-] of a hollow circular section (Cowper 1966, Table 1).

    κ = 6 (1 + ν) (1 + m²)² / ((7 + 6ν)(1 + m²)² + (20 + 12ν) m²), m = d_i/d_o; 0.886 for a solid
    steel section (ν = 0.3).

    Parameters
    ----------
    poisson_ratio : array_like [-]
    diameter_ratio : array_like [-]
        m = d_i / d_o, 0 for a solid section.
    """
    nu = np.asarray(poisson_ratio, dtype=float)
    m2 = np.asarray(diameter_ratio, dtype=float) ** 2
    a = (1.0 + m2) ** 2
    return 6.0 * (1.0 + nu) * a / ((7.0 + 6.0 * nu) * a + (20.0 + 12.0 * nu) * m2)


def shear_parameter(youngs_modulus, shear_modulus, area, second_moment, kappa, length) -> np.ndarray:
    """Φ = 12 E I / (κ G A L²) [-], the ratio of shear to bending flexibility of an element."""
    return 12.0 * youngs_modulus * second_moment / (kappa * shear_modulus * area * np.asarray(length) ** 2)


def planar_bending_stiffness(ei, length, phi) -> np.ndarray:
    """Planar Timoshenko bending stiffness (E, 4, 4) on (v₁, θ₁, v₂, θ₂), θ = dv/dz (module docstring).

    Parameters
    ----------
    ei : array_like (E,) [N·m²]
        Bending stiffness E I.
    length : array_like (E,) [m]
    phi : array_like (E,) [-]
        Shear parameter Φ (0: Euler–Bernoulli).
    """
    ei, L, phi = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (ei, length, phi)))
    c = ei / ((1.0 + phi) * L**3)
    L2 = L * L
    k = np.empty((*L.shape, 4, 4))
    k[..., 0, :] = np.stack([12 + 0 * L, 6 * L, -12 + 0 * L, 6 * L], -1)
    k[..., 1, :] = np.stack([6 * L, (4 + phi) * L2, -6 * L, (2 - phi) * L2], -1)
    k[..., 2, :] = np.stack([-12 + 0 * L, -6 * L, 12 + 0 * L, -6 * L], -1)
    k[..., 3, :] = np.stack([6 * L, (2 - phi) * L2, -6 * L, (4 + phi) * L2], -1)
    return c[..., None, None] * k


#: Element DOF indices (node-local index 0..9) of the x–z and y–z bending planes and the bar.
_XZ = np.array([UX, TY, NODE_DOF + UX, NODE_DOF + TY])
_YZ = np.array([UY, TX, NODE_DOF + UY, NODE_DOF + TX])
_BAR = np.array([UZ, NODE_DOF + UZ])
#: θ_x = −du_y/dz: the y–z plane's rotation DOFs enter the planar element with a minus sign.
_YZ_SIGN = np.array([1.0, -1.0, 1.0, -1.0])


def element_stiffness(youngs_modulus, shear_modulus, area, second_moment, kappa, length, shear=True):
    """Stiffness (E, 10, 10) of shaft elements on (node 1, node 2) × (u_x, u_y, u_z, θ_x, θ_y).

    Bending in x–z and y–z by :func:`planar_bending_stiffness` (the y–z plane with its rotations
    sign-flipped, see the module docstring), the axial bar E A / L [[1, −1], [−1, 1]].

    Parameters
    ----------
    youngs_modulus, shear_modulus : float [Pa]
    area : array_like (E,) [m²]
    second_moment : array_like (E,) [m⁴]
    kappa : array_like (E,) [-]
        Shear coefficient (:func:`shear_coefficient`).
    length : array_like (E,) [m]
    shear : bool
        Include shear deformation (Timoshenko); False gives the Euler–Bernoulli element (Φ = 0).
    """
    area, second_moment, kappa, length = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (area, second_moment, kappa, length))
    )
    phi = (
        shear_parameter(youngs_modulus, shear_modulus, area, second_moment, kappa, length)
        if shear
        else np.zeros_like(length)
    )
    kb = planar_bending_stiffness(youngs_modulus * second_moment, length, phi)
    k = np.zeros((*length.shape, 2 * NODE_DOF, 2 * NODE_DOF))
    k[..., _XZ[:, None], _XZ[None, :]] = kb
    k[..., _YZ[:, None], _YZ[None, :]] = kb * _YZ_SIGN[:, None] * _YZ_SIGN[None, :]
    ka = youngs_modulus * area / length
    k[..., _BAR[:, None], _BAR[None, :]] = ka[..., None, None] * np.array([[1.0, -1.0], [-1.0, 1.0]])
    return k


def uniform_load_vector(line_load, length) -> np.ndarray:
    """Consistent nodal loads (C, E, 10) of a uniform line load on elements.

    Per plane: (qL/2, ±qL²/12, qL/2, ∓qL²/12) on (v₁, θ₁, v₂, θ₂); exact for Timoshenko elements
    (module docstring). The y–z plane's moments change sign with its rotation DOFs.

    Parameters
    ----------
    line_load : array_like (C, E, 3) [N/m]
        (q_x, q_y, q_z) on each element.
    length : array_like (E,) [m]
    """
    q = np.asarray(line_load, dtype=float)
    L = np.asarray(length, dtype=float)
    half = q * (L / 2.0)[None, :, None]
    moment = (L * L / 12.0)[None, :]
    f = np.zeros((*q.shape[:2], 2 * NODE_DOF))
    f[..., [UX, UY, UZ]] = half
    f[..., [NODE_DOF + UX, NODE_DOF + UY, NODE_DOF + UZ]] = half
    f[..., TY] = q[..., 0] * moment
    f[..., NODE_DOF + TY] = -q[..., 0] * moment
    f[..., TX] = -q[..., 1] * moment
    f[..., NODE_DOF + TX] = q[..., 1] * moment
    return f
