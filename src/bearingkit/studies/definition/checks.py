"""Checks of a validated study definition: the design has what it needs, the case count and the
NSGA-III directions stay bounded, a levels × samples study samples distinct continuous factors, and
every ``[[plots]]`` entry names columns the study has.

Each failure raises :class:`bearingkit.errors.InputError` with one line naming the study file.
"""

from __future__ import annotations

import math

from bearingkit.errors import InputError
from bearingkit.studies.definition.choice import evaluator_of
from bearingkit.studies.definition.schema import (
    MAX_CASES,
    MAX_PLOTS,
    MAX_REFERENCE_DIRECTIONS,
    StudyDefinition,
)


def case_count(d: StudyDefinition) -> int:
    """Number of cases (evaluations, for an optimisation) the study asks for, without building them."""
    from bearingkit.studies.designs.generators import orthogonal_array

    if d.design == "optimize":
        return d.optimizer.pop_size * d.optimizer.generations
    if d.design == "monte_carlo":
        n = d.samples or 0
    elif d.design == "orthogonal":
        n = orthogonal_array(d.array).shape[0]
    elif d.design == "factorial":
        n = math.prod(len(f.levels or ()) for f in d.factors)
    else:
        n = sum(len(f.levels or ()) for f in d.factors)
    return n * (d.monte_carlo.per_point if d.monte_carlo is not None else 1)


def check_plots(d: StudyDefinition, ev) -> None:
    """Every ``[[plots]]`` entry names columns the study has (checked fully where the outputs are known)."""
    if len(d.plots) > MAX_PLOTS:
        raise InputError(f"{d.source}: plots ({len(d.plots)} of them) must be at most {MAX_PLOTS}")
    if d.design == "optimize" and d.plots:
        raise InputError(
            f"{d.source}: plots: an optimisation writes pareto.png; [[plots]] are for case tables"
        )
    factors = {f.name for f in d.factors} | set(d.fixed)
    if d.monte_carlo is not None:
        factors |= {f.name for f in d.monte_carlo.factors}
    known = set(ev.outputs) if not ev.fill_defaults else None  # the generic evaluator lists every output
    for i, p in enumerate(d.plots):
        where = f"{d.source}: plots[{i}]"
        need = {"lines": ("x",), "map": ("x", "series"), "scatter": ("x",), "histogram": ()}[p.kind]
        for key in need:
            if getattr(p, key) is None:
                raise InputError(f"{where}.{key}: missing; a {p.kind} plot needs {' and '.join(need)}")
        if p.kind == "histogram" and (p.x is not None or p.series is not None):
            raise InputError(f"{where}: a histogram shows the distribution of y; it takes no x or series")
        if not p.y:
            raise InputError(f"{where}.y ([]) must name at least one output")
        for key, names in (("x", [p.x]), ("series", [p.series]), ("y", list(p.y))):
            for name in names:
                if name is None or name in factors:
                    continue
                if known is not None and name not in known:
                    from bearingkit.studies.generic.paths import nearest

                    near = ", ".join(nearest(name, sorted(known | factors)))
                    raise InputError(
                        f"{where}.{key} ({name!r}) is neither a factor of the study nor one of its outputs; "
                        f"nearest: {near}"
                    )


def check_definition(d: StudyDefinition) -> None:
    _check_design(d)
    n = case_count(d)
    if n > MAX_CASES:
        what = "evaluations (pop_size x generations)" if d.design == "optimize" else "cases"
        raise InputError(
            f"{d.source}: the study asks for {n:,} {what}; at most {MAX_CASES:,} in one study "
            "(its case table is built in memory): split it into several studies"
        )
    if d.design == "optimize" and d.optimizer.algorithm == "nsga3":
        dirs = math.comb(d.optimizer.n_partitions + len(d.objectives) - 1, len(d.objectives) - 1)
        if dirs > MAX_REFERENCE_DIRECTIONS:
            raise InputError(
                f"{d.source}: optimizer.n_partitions ({d.optimizer.n_partitions}) gives {dirs:,} "
                f"NSGA-III reference directions for {len(d.objectives)} objectives; "
                f"at most {MAX_REFERENCE_DIRECTIONS:,}"
            )


def _check_design(d: StudyDefinition) -> None:
    src = d.source
    if d.monte_carlo is not None and d.design not in ("sweep", "factorial", "orthogonal"):
        raise InputError(
            f"{src}: [monte_carlo] draws samples at the points of a design; study.design ({d.design!r}) "
            "must be sweep, factorial or orthogonal (a plain monte_carlo study samples its [[factors]])"
        )
    if d.design == "optimize":
        if not d.variables or not d.objectives:
            raise InputError(f"{src}: an optimize study needs [[variables]] and [[objectives]]")
        for v in d.variables:
            if not v.high > v.low:
                raise InputError(f"{src}: variables ({v.name}) high ({v.high}) must exceed low ({v.low})")
        return
    if not d.factors:
        raise InputError(f"{src}: a {d.design} study needs [[factors]]")
    if d.design == "monte_carlo":
        if d.samples is None:
            raise InputError(f"{src}: study.samples must be given for a monte_carlo study")
        for f in d.factors:
            if f.distribution is None:
                raise InputError(f"{src}: factors ({f.name}) needs a distribution in a monte_carlo study")
        return
    for f in d.factors:
        if not f.levels:
            raise InputError(f"{src}: factors ({f.name}) needs levels in a {d.design} study")
        if f.deviation:
            raise InputError(
                f"{src}: factors ({f.name}).deviation (true) belongs in [[monte_carlo.factors]], "
                "next to the tolerance's distribution"
            )
    if d.design == "orthogonal":
        from bearingkit.studies.designs.generators import ARRAYS

        if d.array not in ARRAYS:
            raise InputError(
                f"{src}: study.array ({d.array!r}) must name an orthogonal array: {', '.join(ARRAYS)}"
            )
    if d.monte_carlo is not None:
        _check_monte_carlo(d)


def _check_monte_carlo(d: StudyDefinition) -> None:
    """A levels × samples study: sampled factors distinct, distributions given, tolerances on levels."""
    from bearingkit.studies import evaluators

    src, mc = d.source, d.monte_carlo
    if not mc.factors:
        raise InputError(f"{src}: monte_carlo.factors (none) must list at least one sampled factor")
    design = {f.name for f in d.factors}
    seen = set()
    for f in mc.factors:
        where = f"{src}: monte_carlo.factors ({f.name})"
        if f.name in seen:
            raise InputError(f"{where} is sampled twice; expected each factor once")
        seen.add(f.name)
        if f.distribution is None:
            raise InputError(
                f"{where}.distribution (None) must be one of normal, uniform, lognormal, truncnormal"
            )
        if f.levels is not None:
            raise InputError(f"{where}.levels ({list(f.levels)}) are not used; put levels in [[factors]]")
        if f.name in d.fixed:
            raise InputError(f"{where} is also in [fixed]; expected a factor to be either fixed or sampled")
        if f.deviation and f.name not in design:
            raise InputError(
                f"{where}.deviation (true) needs {f.name!r} among the design [[factors]] "
                f"({sorted(design)}): the draw is added to its level"
            )
        if f.name in design and not f.deviation:
            raise InputError(
                f"{where} is also a design factor; expected deviation = true (level + draw) or another factor"
            )
        if evaluator_of(d).factors[f.name].dimension in evaluators.NON_PHYSICAL:
            raise InputError(f"{where} is a count or a name; expected a continuous factor to sample")
    for q in mc.quantiles:
        if not 0.0 < q < 1.0:
            raise InputError(f"{src}: monte_carlo.quantiles ({q}) must lie strictly between 0 and 1")
