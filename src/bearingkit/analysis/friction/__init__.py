"""Friction assemblies on a solved bearing (SI units: N·m, W, rad/s).

- ``components`` — the physical component model (hysteresis, differential sliding, viscous rolling,
  ball spin, cage; :func:`friction_torque`) on the element kinematics of ``kinematics``;
- ``engineering`` — the SKF four-component and Palmgren catalogue models of standard bearings;
- ``tapered`` — seed 001's tapered-roller model (EHL rolling, sliding, flange, cage slip);
- ``threaded`` — seed 004's planetary thread-roller model.

The physics of each (pure functions) is in :mod:`bearingkit.physics.friction`. The public names of the
component model are importable from here: ``from bearingkit.analysis.friction import friction_torque``.
"""

from bearingkit.lazy import exports

_EXPORTS = {
    "friction_torque": "components",
    "OperatingPoint": "components",
    "FrictionResult": "components",
    "engineering_friction_moment": "engineering",
    "EngineeringFrictionResult": "engineering",
}
__all__ = sorted(_EXPORTS)

__getattr__ = exports(__name__, _EXPORTS)  # loaded on first use: importing the package stays cheap
