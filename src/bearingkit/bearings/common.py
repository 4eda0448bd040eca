"""Helpers shared by the bearing builders. SI units."""

from __future__ import annotations

import numpy as np

from bearingkit import checks


def e_reduced_of(material=None, element_material=None) -> float:
    """Reduced modulus E′ [Pa] of element and ring materials (GCr15 bearing steel by default)."""
    from bearingkit.materials import e_reduced, get_material

    ring = get_material("GCr15") if material is None else material
    element = ring if element_material is None else element_material
    return float(e_reduced(ring, element))


def eccentric_axial_load(axial_load, eccentricity, radial_load=0.0) -> np.ndarray:
    """Load vector (…, 5) for an axial force applied at a radial offset along +x, plus a radial force.

    The axial force F_a acts along +z at the point (e, 0); its moment about the bearing centre is
    r × F = (e, 0, 0) × (0, 0, F_a) = (0, −e F_a, 0), i.e. M_y = −e·F_a (seed 000 §6.1.3: 3 kN at
    0.1 m ↔ 300 N·m). The radial force acts along +x.

    Parameters
    ----------
    axial_load : float or array [N]
    eccentricity : float or array [m]
    radial_load : float or array [N]
    """
    from bearingkit.analysis.solver.quasistatic import load_vector

    checks.finite("eccentricity", eccentricity, "m")
    fa = np.asarray(axial_load, dtype=float)
    return load_vector(F_x=radial_load, F_z=fa, M_y=-np.asarray(eccentricity, dtype=float) * fa)
