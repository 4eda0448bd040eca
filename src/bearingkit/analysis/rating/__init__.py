"""Ratings and lives of a solved bearing (SI units): ISO 76, ISO 281, ISO/TS 16281, PTRB.

``assembly`` (:func:`rate`, the system life, the result object) over the per-row raters ``rows``,
``threaded`` and ``kinds`` (registered with :func:`register_row_rater`), the bearing-level ISO 281 life
``iso281`` and the settings ``options``. Importing the package registers the raters of every row kind,
so :func:`rate` always finds them.
"""

from bearingkit.analysis.rating import kinds as _kinds  # noqa: F401 - registers the raters of the kinds' rows
from bearingkit.analysis.rating.assembly import ROW_RATERS, RatingResult, rate, register_row_rater
from bearingkit.analysis.rating.options import RatingOptions

__all__ = ["ROW_RATERS", "RatingOptions", "RatingResult", "rate", "register_row_rater"]
