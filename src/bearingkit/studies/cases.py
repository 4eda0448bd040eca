"""What a study evaluates: its cases (design × base values), their fingerprint, and the result object.

SI units (factor values as the evaluator defines them). :func:`build_cases` turns a study definition
into its case table; :func:`base_values` gives every factor the design does not vary; the fingerprint
identifies a study's definition and cases in a store. Used by :mod:`bearingkit.studies.runner` and
:mod:`bearingkit.studies.optimize`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit.errors import InputError
from bearingkit.studies import evaluators, generators
from bearingkit.studies.definition import StudyDefinition


@dataclass
class StudyResult:
    """Outcome of :func:`run_study`.

    Attributes
    ----------
    definition : StudyDefinition
    cases : DataFrame
        The generated cases (``case`` id, design columns such as ``level_<factor>`` or ``swept``, and
        every factor value in SI); levels × samples designs add ``point``, ``draw`` and
        ``nominal_<factor>`` for toleranced design factors.
    results : DataFrame
        ``cases`` joined with the evaluator's outputs (one row per case, ordered by ``case``); for an
        optimisation, every evaluated point with its ``generation``.
    stats : dict
        ``chunks`` (total), ``computed`` (this run), ``reused`` (found in the store), ``seconds``.
    analysis : dict of DataFrame
        ``main_effects`` and ``range`` (designs with levels and a ``response``); levels × samples:
        ``point_statistics`` (one row per design point) and, with a response, the main effects and
        ranges of its per-point mean and of its per-point standard deviation (``range_std``).
    pareto : DataFrame or None
        Non-dominated feasible points of an optimisation.
    selections : DataFrame or None
        The knee point and the points nearest each named target, one row each (``selection`` column).
    """

    definition: StudyDefinition
    cases: object
    results: object
    stats: dict = field(default_factory=dict)
    analysis: dict = field(default_factory=dict)
    pareto: object = None
    selections: object = None


def base_values(definition: StudyDefinition) -> dict:
    """Value of every factor not varied by the design: evaluator default < bearing file < [fixed]."""
    ev = evaluators.get(definition.evaluator)
    base = {k: f.default for k, f in ev.factors.items()}
    if definition.bearing:
        from bearingkit.io.loader import load_file

        bearing = load_file(definition.bearing)
        if ev.bearing_type and bearing.bearing_type != ev.bearing_type:
            raise InputError(
                f"{definition.source}: study.bearing ({definition.bearing}) is a {bearing.bearing_type!r} "
                f"bearing; evaluator {ev.name!r} needs a {ev.bearing_type!r}"
            )
        for k, v in bearing.geometry.model_dump().items():
            if k in ev.factors and v is not None:
                base[k] = v
    base.update(definition.fixed)
    return base


def build_cases(definition: StudyDefinition):
    """The cases of a non-optimisation study (DataFrame with a ``case`` id column first)."""
    d = definition
    base = base_values(d)
    levels = {f.name: list(f.levels or ()) for f in d.factors}
    if d.design == "orthogonal":
        cols = [f.column for f in d.factors]
        design = generators.orthogonal_design(levels, d.array, None if None in cols else cols)
    elif d.design == "factorial":
        design = generators.full_factorial(levels)
    elif d.design == "sweep":
        sweep_base = {f.name: (f.base if f.base is not None else base[f.name]) for f in d.factors}
        design = generators.sweep(levels, sweep_base)
    elif d.design == "monte_carlo":
        dists = {
            f.name: generators.Distribution(f.distribution, f.mean, f.std, f.low, f.high) for f in d.factors
        }
        design = generators.monte_carlo(dists, d.samples, d.seed, d.sampler)
    else:
        raise InputError(f"{d.source}: design ({d.design!r}) has no case table (use run_study)")
    if d.monte_carlo is not None:
        mc = d.monte_carlo
        dists = {
            f.name: generators.Distribution(f.distribution, f.mean, f.std, f.low, f.high) for f in mc.factors
        }
        design = generators.levels_by_samples(
            design,
            dists,
            mc.per_point,
            d.seed if mc.seed is None else mc.seed,
            mc.sampler,
            mc.common,
            deviations=[f.name for f in mc.factors if f.deviation],
        )
    for k, v in base.items():
        if k not in design.columns:
            design[k] = v
    design.insert(0, "case", np.arange(len(design)))
    return design


def _fingerprint(definition: StudyDefinition, cases=None) -> str:
    import hashlib

    import pandas as pd

    h = hashlib.sha256(definition.fingerprint().encode())
    if cases is not None:
        h.update(pd.util.hash_pandas_object(cases, index=False).to_numpy().tobytes())
    return h.hexdigest()
