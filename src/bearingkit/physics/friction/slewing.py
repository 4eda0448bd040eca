"""Friction torque of slewing rings by the slewing-ring makers' formula (Rothe Erde).

SI units: forces in N, moments in N·m, diameters in m. The makers write the formula in kN, kN·m and m;
it is linear in the loads, so it holds unchanged in N and N·m.

.. math::

    M_r = \\tfrac{\\mu}{2}(4.4 M_k + F_a D_L + 2.2 \\cdot 1.73 F_r D_L)\\ \\text{(ball)},\\quad
    M_r = \\tfrac{\\mu}{2}(4.1 M_k + F_a D_L + 2.05 F_r D_L)\\ \\text{(roller)}

the start-up friction torque of a loaded, installed bearing (no seals, no unloaded preload torque; the
maker quotes a scatter of ±25 %), D_L the raceway (pitch) diameter, μ a friction coefficient per bearing
series. The drive power is P = M_r ω / η.

References: Rothe Erde GmbH (2007) Slewing bearings catalogue, "Turning torque calculation" (p. 27);
the same formula and symbols in thyssenkrupp rothe erde's current technical basics, "Calculation of the
frictional torque".
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks, references

references.add(
    "rotheerde_friction",
    "thyssenkrupp rothe erde, Slewing bearings - technical basics: calculation of the frictional torque "
    "(M_r = mu/2 (4.4 M_k + F_a D_L + 2.2 F_r D_L 1.73) ball, mu/2 (4.1 M_k + F_a D_L + 2.05 F_r D_L) "
    "roller).",
)

#: Coefficients of the makers' formula per element: (moment factor, radial factor) [-].
COEFFICIENTS = {"ball": (4.4, 2.2 * 1.73), "roller": (4.1, 2.05)}
#: Friction coefficient μ used when none is given [-]: the maker tabulates μ per series; the value for
#: single-row ball slewing rings of series KD 210 is 0.008 (maker's page); 0.006 for four-point and
#: 0.003 for crossed roller rings are [from memory] of the same table (not confirmed).
DEFAULT_MU = {"ball": 0.006, "roller": 0.003}
REFERENCE_KEYS = ("rotheerde_friction",)


def slewing_friction_moment(
    axial_force, radial_force, tilting_moment, pitch_diameter, element="ball", mu=None
):
    """Start-up friction torque M_r [N·m] of a loaded slewing ring (module docstring).

    Parameters
    ----------
    axial_force, radial_force : array_like [N]
        |F_a|, |F_r|.
    tilting_moment : array_like [N·m]
        Resulting tilting moment |M_k|.
    pitch_diameter : float [m]
        Raceway diameter D_L.
    element : {"ball", "roller"}
    mu : float or None
        Friction coefficient μ [-]; default :data:`DEFAULT_MU`.

    Returns
    -------
    numpy.ndarray
        M_r [N·m].
    """
    checks.one_of("element", element, COEFFICIENTS)
    checks.positive("pitch_diameter", pitch_diameter, "m")
    mu = DEFAULT_MU[element] if mu is None else mu
    checks.in_range("mu", mu, 0.0, 0.1)
    km, kr = COEFFICIENTS[element]
    fa, fr, mk = (np.abs(np.asarray(v, float)) for v in (axial_force, radial_force, tilting_moment))
    return 0.5 * mu * (km * mk + fa * pitch_diameter + kr * fr * pitch_diameter)
