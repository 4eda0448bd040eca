"""Settings of a quasi-static solve (SolverOptions, per-case budgets): what is asked of it, apart from how."""

from __future__ import annotations

import math
import os
from dataclasses import dataclass

from bearingkit import checks
from bearingkit.analysis.solver import backend
from bearingkit.analysis.solver.coarse import COARSE_ITERATIONS
from bearingkit.errors import InputError

__all__ = [
    "CASE_SECONDS",
    "CASE_SECONDS_ENV",
    "DEFAULT_OPTIONS",
    "EVALUATIONS_PER_ITERATION",
    "SolverOptions",
]

#: Default evaluation budget of one case per Newton iteration allowed (``max_evaluations`` =
#: this × ``max_iterations``; 50 × 60 = 3,000). A converging case uses 5–70 evaluations (3–13
#: iterations, mostly full steps, and the coarse start); the slowest converging one measured (a 6209
#: at 3,000 rpm under 75 N, its first attempt crawling with ~28 line-search halvings per iteration
#: before the load continuation converges) 1,755. The cap stops the cases that would otherwise spend
#: 5 attempts × 60 iterations × 41 line-search trials (12,300 evaluations, minutes for a row at speed).
EVALUATIONS_PER_ITERATION = 50
#: Default time budget of one case in the numpy reference [s of processor time]: a converging ball
#: row at speed takes well under 1 s per case on the 2-core reference machine; a case still running
#: after this has met a problem the evaluation cap does not see (evaluations far slower than usual).
CASE_SECONDS = 10.0
#: Environment variable overriding :data:`CASE_SECONDS` (``SolverOptions.case_seconds`` wins).
CASE_SECONDS_ENV = "BEARINGKIT_CASE_SECONDS"


@dataclass(frozen=True)
class SolverOptions:
    """Tolerances and limits of the Newton solver.

    Parameters
    ----------
    rtol : float
        Converged when max |residual| ≤ rtol × load scale (scaled units, see
        :mod:`bearingkit.analysis.solver.quasistatic`).
    max_iterations : int
        Newton iterations per attempt.
    max_step : float or None [m]
        Largest change of any scaled DOF in one step; default 2 % of the smallest element diameter.
    continuation_steps : int
        Load fractions tried for cases that fail the plain attempt (0 disables continuation).
    divergence_limit : float
        A case whose scaled displacement exceeds this fraction of the smallest element diameter is
        declared diverged (the load cannot be carried).
    backend : str or None
        ``"auto"``, ``"compiled"`` or ``"numpy"`` (:mod:`bearingkit.analysis.solver.backend`); None reads
        ``$BEARINGKIT_BACKEND`` (default ``"auto"``: the compiled core where it applies).
    max_evaluations : int
        Row evaluations one case may use in one solve (every attempt, trial step and continuation
        step together; the coarse stage is not counted; :class:`~bearingkit.analysis.solver.newton.
        Effort`): a case past it is stopped, not converged, and the rest of its batch goes on. Both
        cores count alike and stop the same cases (the compiled core in
        :func:`~bearingkit.analysis.solver.compiled_newton.solve_packed`).
    case_seconds : float or None [s]
        Processor time one case may use in one solve of the numpy reference (its share of each
        batched evaluation; the compiled core, microseconds per evaluation, has the evaluation
        budget alone); None reads ``$BEARINGKIT_CASE_SECONDS`` (default :data:`CASE_SECONDS`).
    coarse_iterations : int
        Newton iterations on the coarse model (sliced rollers at a few slices) before the full model's,
        when no start is given (:mod:`bearingkit.analysis.solver.coarse`); 0 starts the full model directly.
        The equilibrium is the same to the tolerance ``rtol`` either way.
    """

    rtol: float = 1e-10
    max_iterations: int = 60
    max_step: float | None = None
    continuation_steps: int = 4
    divergence_limit: float = 0.5
    backend: str | None = None
    coarse_iterations: int = COARSE_ITERATIONS
    max_evaluations: int = 0
    case_seconds: float | None = None

    def __post_init__(self):
        if self.max_evaluations == 0:  # the default: proportional to the iteration cap
            object.__setattr__(self, "max_evaluations", EVALUATIONS_PER_ITERATION * self.max_iterations)
        checks.positive("rtol", self.rtol)
        checks.integer("max_iterations", self.max_iterations, low=1)
        if self.max_step is not None:
            checks.positive("max_step", self.max_step, "m")
        checks.integer("continuation_steps", self.continuation_steps, low=0)
        checks.positive("divergence_limit", self.divergence_limit)
        if self.backend is not None:
            checks.one_of("backend", self.backend, backend.BACKENDS)
        checks.integer("coarse_iterations", self.coarse_iterations, low=0)
        checks.integer("max_evaluations", self.max_evaluations, low=1)
        if self.case_seconds is not None:
            checks.positive("case_seconds", self.case_seconds, "s")

    def seconds_per_case(self) -> float:
        """The wall-time budget of one case [s]: ``case_seconds``, else ``$BEARINGKIT_CASE_SECONDS``,
        else :data:`CASE_SECONDS`."""
        if self.case_seconds is not None:
            return self.case_seconds
        value = os.environ.get(CASE_SECONDS_ENV, "").strip()
        if not value:
            return CASE_SECONDS
        try:
            seconds = float(value)
        except ValueError:
            seconds = -1.0
        if not (seconds > 0 and math.isfinite(seconds)):
            raise InputError(f"{CASE_SECONDS_ENV}={value!r}: expected a positive number of seconds")
        return seconds


#: The options of a solve that gives none (one instance: building and checking them costs more than
#: a small compiled solve).
DEFAULT_OPTIONS = SolverOptions()
