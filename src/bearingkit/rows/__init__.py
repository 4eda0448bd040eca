"""Row kinds of the quasi-static engine: ball, cylindrical, tapered, threaded rows. SI units.

Importing the package registers the tapered row's solver kernel (:mod:`bearingkit.rows.tapered_kernel`
needs :mod:`bearingkit.rows.tapered`, so the row cannot import its kernel itself).
"""

from bearingkit.rows import tapered_kernel  # noqa: F401 - registers TaperedRow.kernel's constructor
