"""The work a command may start without being asked: refused in one line, before it starts, when an
estimate passes the limit.

Seconds here are estimates on the 2-core reference machine (docs/security.md, "How much work a file
can ask for"). A study, a shaft with its report or a long duty cycle can ask for minutes: that is
fine when the user means it, and a slip or a hostile file when not, so above :func:`max_work` the
command stops before any work with one line that says what would take how long, how to ask for
less, and how to raise the limit (``BEARINGKIT_MAX_WORK_S``). The per-run caps of the input files
(load cases, contact points) stay: they bound memory, this bounds time.
"""

from __future__ import annotations

import math
import os

from bearingkit.errors import InputError

#: Environment variable that raises (or lowers) the limit [s].
MAX_WORK_ENV = "BEARINGKIT_MAX_WORK_S"
#: Default limit [s of estimated work]: two minutes. Every example of the project stays below a
#: minute; what passes two minutes on the reference machine is a study or a sweep the user should
#: have asked for on purpose.
DEFAULT_MAX_WORK_S = 120.0


def max_work() -> float:
    """The limit [s]: ``$BEARINGKIT_MAX_WORK_S``, else :data:`DEFAULT_MAX_WORK_S`."""
    value = os.environ.get(MAX_WORK_ENV, "").strip()
    if not value:
        return DEFAULT_MAX_WORK_S
    try:
        limit = float(value)
    except ValueError:
        limit = -1.0
    if not (limit > 0.0 and math.isfinite(limit)):
        raise InputError(f"{MAX_WORK_ENV}={value!r}: expected a positive number of seconds")
    return limit


def duration(seconds: float) -> str:
    """``"about 3 min"``: a duration as a person reads it."""
    if seconds < 10:
        return f"about {seconds:.2g} s"
    if seconds < 90:
        return f"about {seconds:.0f} s"
    if seconds < 5400:
        return f"about {seconds / 60:.0f} min"
    if seconds < 48 * 3600:
        return f"about {seconds / 3600:.0f} h"
    return f"about {seconds / 86400:.3g} days"


def check_work(seconds: float, what: str, fewer: str) -> None:
    """Refuse when ``seconds`` (an estimate) pass :func:`max_work`.

    Parameters
    ----------
    seconds : float [s]
        Estimated work on the reference machine.
    what : str
        What would take that long (``"100 load cases x 12 bearings of the shaft"``).
    fewer : str
        How to ask for less (``"give fewer load cases"``).
    """
    limit = max_work()
    if not seconds <= limit:
        ask = 10 ** math.ceil(math.log10(max(seconds, 1.0))) if math.isfinite(seconds) else "a larger number"
        raise InputError(
            f"{what} would take {duration(seconds) if math.isfinite(seconds) else 'unbounded time'} "
            f"(at most {limit:g} s is started without asking): {fewer}, or raise the limit with "
            f"{MAX_WORK_ENV}={ask}"
        )
