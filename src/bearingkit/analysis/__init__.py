"""Quasi-static solver, kinematics, friction, ratings and flexible rings (SI units).

Importing the package registers the raters of the bearing kinds (:mod:`bearingkit.analysis.rating_kinds`).
"""

from bearingkit.analysis import rating_kinds  # noqa: F401 - registers the raters of the kinds' rows
