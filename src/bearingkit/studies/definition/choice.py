"""The evaluator a study runs on: a registered one by name, or the generic evaluator built from the
study's bearing file or designation (:mod:`bearingkit.studies.generic.evaluator`) for the names the file uses.
"""

from __future__ import annotations

from bearingkit.errors import InputError
from bearingkit.studies.definition.schema import StudyDefinition
from bearingkit.studies.definition.values import flatten


def names_used(data: dict) -> list:
    """Every factor and output name a parsed study file uses (before it is checked), for the generic
    evaluator: the load case its paths name, the outputs it needs."""
    out = []
    for key in ("factors", "variables"):
        items = data.get(key, [])
        out += [f.get("name") for f in items if isinstance(f, dict)] if isinstance(items, list) else []
    mc = data.get("monte_carlo")
    if isinstance(mc, dict) and isinstance(mc.get("factors"), list):
        out += [f.get("name") for f in mc["factors"] if isinstance(f, dict)]
    fixed = data.get("fixed")
    if isinstance(fixed, dict):
        out += [k for k, _ in flatten(fixed)]
    head = data.get("study", {})
    out.append(head.get("response"))
    for key, fields in (
        ("plots", ("x", "y", "series")),
        ("objectives", ("output",)),
        ("constraints", ("output",)),
    ):
        items = data.get(key, [])
        for item in items if isinstance(items, list) else []:
            for f in fields if isinstance(item, dict) else ():
                value = item.get(f)
                out += value if isinstance(value, list) else [value]
    return out


def evaluator_named(name: str, bearing, head: dict, data: dict, source: str):
    """The evaluator a study file names (the generic one is built from its bearing and checked)."""
    from bearingkit.studies import evaluators
    from bearingkit.studies.generic.evaluator import GENERIC, study_evaluator

    if name != GENERIC:
        return evaluators.get(name)
    if bearing is None:
        raise InputError(
            f"{source}: study.bearing: missing; the generic evaluator needs a bearing file or a designation"
        )
    ev = study_evaluator(bearing, head, names_used(data), source)
    head["load_case"] = ev.function.load_case  # the choice is part of the definition (and its fingerprint)
    return ev


def evaluator_of(d: StudyDefinition):
    """The evaluator of a checked study definition (the generic one rebuilt from its bearing, cached)."""
    from bearingkit.studies import evaluators
    from bearingkit.studies.generic.evaluator import GENERIC, study_evaluator

    if d.evaluator != GENERIC:
        return evaluators.get(d.evaluator)
    head = {"load_case": d.load_case, "outputs": None if d.outputs is None else list(d.outputs)}
    return study_evaluator(d.bearing, head, (), d.source)
