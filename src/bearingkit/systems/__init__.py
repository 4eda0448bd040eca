"""Shafts on several bearings (Timoshenko beam FE coupled with the bearings' 5-DOF laws) and the export
of bearing stiffness to rotordynamics. See docs/systems.md."""
