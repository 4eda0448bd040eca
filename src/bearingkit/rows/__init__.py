"""Row kinds of the quasi-static engine: ball, cylindrical, tapered, threaded rows. SI units.

The tapered row imports its solver kernel directly: the meridian geometry and constants both need
live in :mod:`bearingkit.rows.tapered_geometry`, so there is no import circle.
"""
