"""bearingkit: open rolling-bearing mechanics.

Quasi-static load distribution of multi-row bearings, friction torque, load ratings and life,
manufacturing deviations, flexible rings and design studies. SI units everywhere inside
(m, N, Pa, rad, s, Pa·s, 1/Pa); units are parsed only at the edges (:mod:`bearingkit.units`).
"""

from bearingkit.errors import ConvergenceError, InputError

__version__ = "0.1.0"
__all__ = ["ConvergenceError", "InputError", "__version__"]
