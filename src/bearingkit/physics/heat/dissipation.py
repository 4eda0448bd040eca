"""Heat carried away from a rolling bearing: through its seats and housing, and by a circulating oil.

SI units: W, W/K, m², W/(m²·K), m³/s, kg/m³, J/(kg·K); temperatures in °C (only differences enter).
The bearing's friction heat P leaves it two ways (the structure of DIN 732:2010, the thermally safe
operating speed of a rolling bearing, whose reference state is that of ISO 15312; the clause numbers
and its tabulated seat heat-transfer coefficients are not reproduced here [from memory: the standard
was not found with the search tool]):

.. math::

    \\Phi = \\underbrace{H\\,(T - T_{amb})}_{\\text{seats, housing}}
          + \\underbrace{\\rho\\,c_p\\,\\dot V\\,(T - T_{in})}_{\\text{circulating oil}}

- **Through the seats and the housing**: a conductance H [W/K] — given (a measured or computed
  housing), or the housing's outer surface A times a heat-transfer coefficient k (convection and
  radiation lumped, the housing term of ISO/TR 14179-2 for gear units [M]), or the ISO 15312 reference
  housing H = q_r A_r / (70 °C − 20 °C).
- **By a circulating oil** of volume flow V̇ entering at T_in and leaving at the bearing temperature
  (the oil leaves as warm as the bearing: the usual assumption of DIN 732 and of catalogue heat
  balances).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks


def conductance_of_surface(area, heat_transfer_coefficient):
    """Housing conductance H = k·A [W/K] from its outer surface and heat-transfer coefficient.

    Parameters
    ----------
    area : array_like
        Heat-transferring outer surface A [m²], > 0.
    heat_transfer_coefficient : array_like
        k [W/(m²·K)] (convection plus radiation), > 0.
    """
    checks.positive("housing_area", area, "m^2")
    checks.positive("heat_transfer_coefficient", heat_transfer_coefficient, "W/(m^2*K)")
    return np.asarray(area, dtype=float) * np.asarray(heat_transfer_coefficient, dtype=float)


def conducted_heat(conductance, temperature, ambient):
    """Heat flow through the seats and housing Φ_H = H (T − T_amb) [W].

    Parameters
    ----------
    conductance : array_like
        H [W/K], ≥ 0.
    temperature, ambient : array_like
        Bearing and ambient temperatures [°C].
    """
    checks.non_negative("heat_dissipation", conductance, "W/K")
    return np.asarray(conductance, dtype=float) * (
        np.asarray(temperature, float) - np.asarray(ambient, float)
    )


def oil_heat(volume_flow, density, specific_heat, temperature, inlet):
    """Heat carried away by a circulating oil Φ_oil = ρ c_p V̇ (T − T_in) [W].

    Parameters
    ----------
    volume_flow : array_like
        V̇ [m³/s], ≥ 0.
    density : array_like
        Oil density ρ [kg/m³] (at the mean of inlet and outlet, or at the bearing temperature), > 0.
    specific_heat : array_like
        c_p [J/(kg·K)], > 0.
    temperature, inlet : array_like
        Bearing (= oil outlet) and oil inlet temperatures [°C].
    """
    checks.non_negative("oil_flow", volume_flow, "m^3/s")
    checks.positive("density", density, "kg/m^3")
    checks.positive("specific_heat", specific_heat, "J/(kg*K)")
    flow = np.asarray(volume_flow, float) * np.asarray(density, float) * np.asarray(specific_heat, float)
    return flow * (np.asarray(temperature, float) - np.asarray(inlet, float))
