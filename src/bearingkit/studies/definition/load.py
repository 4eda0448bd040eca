"""Study definitions: a TOML file → a validated, SI-valued :class:`StudyDefinition` (pydantic).

SI inside: every quantity of the file is a string with a unit (``"-2 um"``, ``"3 kN"``) parsed with
:func:`bearingkit.units.parse` against the dimension the evaluator declares for that factor;
dimensionless factors and counts may be bare numbers.

This module reads and validates a file (:func:`load_study`, :func:`from_dict`); the models and limits
are in :mod:`~bearingkit.studies.definition.schema`, the values in SI in
:mod:`~bearingkit.studies.definition.values`,
the evaluator a study names in :mod:`~bearingkit.studies.definition.choice` and the checks of a whole
definition in :mod:`~bearingkit.studies.definition.checks`. Their public names are importable from here.

File layout (all sections but ``[study]`` optional)::

    [study]
    name = "clearance_l9"
    design = "orthogonal"       # sweep | factorial | orthogonal | monte_carlo | optimize
    evaluator = "my_evaluator"
    array = "L9"                # orthogonal designs
    bearing = "../my_bearing.toml"          # geometry defaults from a bearing file (relative path)
    response = "ball_axial_share"           # output analysed (main effects, range analysis)
    samples = 1000              # monte_carlo
    sampler = "random"          # monte_carlo: random | lhs | sobol
    seed = 0
    chunk_size = "auto"         # cases per chunk (the unit of parallel work and of resume): "auto"
                                # (default) sizes it from the study's measured costs, or a number

    [fixed]                     # factor values common to all cases
    axial_load = "3 kN"

    [[factors]]                 # varied factors: levels, or a distribution (monte_carlo)
    name = "clearance_axial_roller"
    label = "A"
    levels = ["0 um", "-1 um", "-2 um"]
    # column = 1                (orthogonal: 1-based array column; default the next free one)
    # distribution = "normal", mean = "...", std = "..."   (or low/high)

    [monte_carlo]               # levels x samples: per_point random draws at every design point
    per_point = 2000            # (sweep, factorial and orthogonal designs)
    sampler = "lhs"             # random | lhs | sobol (default random)
    seed = 2022                 # default study.seed
    common = true               # same draws at every point (common random numbers; default true)
    quantiles = [0.05, 0.5, 0.95]   # reported per point with mean, std, min, max
    [[monte_carlo.factors]]     # sampled factors: a distribution as in [[factors]]
    name = "z1"
    distribution = "normal"; mean = 0; std = 1
    # deviation = true          (a design factor's tolerance: value = its level + the draw)

    [[variables]]               # optimize: design variables
    name = "x1"; low = 0; high = 1; integer = false
    [[objectives]]
    output = "f1"; sense = "min"
    [[constraints]]
    output = "g"; upper = 2.0   # and/or lower; values in the output's SI unit
    [optimizer]
    algorithm = "nsga2"; pop_size = 100; generations = 100; seed = 1
    [targets.xa1]               # named points for nearest-to-target selection (variables/outputs)
    x1 = 0.25
"""

from __future__ import annotations

from pathlib import Path

from pydantic import ValidationError

from bearingkit.errors import InputError, shown
from bearingkit.studies.definition.checks import case_count, check_definition, check_plots
from bearingkit.studies.definition.choice import evaluator_named, evaluator_of
from bearingkit.studies.definition.schema import (
    DESIGNS,
    MAX_CASES,
    MAX_CHUNK_SIZE,
    MAX_PLOTS,
    MAX_REFERENCE_DIRECTIONS,
    NAME_PATTERN,
    NAME_RULE,
    SECTIONS,
    ConstraintDef,
    FactorDef,
    MonteCarloDef,
    ObjectiveDef,
    OptimizerDef,
    PlotDef,
    StudyDefinition,
    VariableDef,
)
from bearingkit.studies.definition.values import (
    as_number,
    as_table,
    as_tables,
    factor_list,
    factor_of,
    flatten,
    short,
    si_value,
)

__all__ = [
    "DESIGNS",
    "MAX_CASES",
    "MAX_CHUNK_SIZE",
    "MAX_PLOTS",
    "MAX_REFERENCE_DIRECTIONS",
    "NAME_PATTERN",
    "NAME_RULE",
    "SECTIONS",
    "ConstraintDef",
    "FactorDef",
    "MonteCarloDef",
    "ObjectiveDef",
    "OptimizerDef",
    "PlotDef",
    "StudyDefinition",
    "VariableDef",
    "case_count",
    "evaluator_of",
    "from_dict",
    "load_study",
]


def load_study(path, allowed_paths=()) -> StudyDefinition:
    """Read and validate a study TOML file (relative ``bearing`` paths are resolved from its folder).

    ``allowed_paths``: folders beyond the file's own (and its project's) that its ``bearing`` may name
    (``--allow-path``; :func:`bearingkit.io.reading.confined_path`)."""
    from bearingkit.io.reading import load_toml

    path = Path(path)
    data = load_toml(path)  # a regular file of at most 1 MiB, nesting bounded (bearingkit.io.reading)
    return from_dict(data, source=str(path), base_dir=path.parent, allowed_paths=allowed_paths)


def _pydantic_message(exc: ValidationError, source: str, head: dict) -> str:
    """One line naming the field of the first error, its value and what was expected."""
    err = exc.errors()[0]
    parts = [str(p) for p in err["loc"]]
    if parts and (parts[0] in head or parts[0] in StudyDefinition.model_fields) and parts[0] not in SECTIONS:
        parts.insert(0, "study")
    loc = ""
    for p in parts:
        loc += f"[{p}]" if p.isdigit() else (f".{p}" if loc else p)
    msg = err["msg"].removeprefix("Value error, ")
    return f"{source}: {loc} ({short(err.get('input'))}) {msg}"


def from_dict(data: dict, source: str = "<dict>", base_dir=None, allowed_paths=()) -> StudyDefinition:
    """Validate a parsed study file (see the module docstring); InputError with one line if malformed.

    Every malformed value gives one line naming the file, the field, the value and what was expected;
    nothing else escapes (a study file may come from someone else). With ``base_dir`` (the file's
    folder) the ``bearing`` path is confined by :func:`bearingkit.io.reading.confined_path` before
    anything opens it: no ``~``, no NUL, nothing outside that folder (and its project's folder above
    it) or ``allowed_paths``.
    """

    if not isinstance(data, dict) or not isinstance(data.get("study"), dict):
        raise InputError(f"{source}: a study file needs a [study] table")
    unknown = set(data) - set(SECTIONS)
    if unknown:
        raise InputError(
            f"{source}: unknown section(s) {sorted(map(str, unknown))}; expected {list(SECTIONS)}"
        )
    head = dict(data["study"])
    keys = set(StudyDefinition.model_fields) - set(SECTIONS) - {"source"}
    stray = sorted(map(str, set(head) - keys))
    if stray:
        raise InputError(
            f"{source}: study.{stray[0]} is not a key of [study]; expected some of {sorted(keys)} "
            "(sections such as [[factors]] go after [study], not inside it)"
        )
    name = head.get("name")
    if not isinstance(name, str) or not NAME_PATTERN.match(name):
        raise InputError(
            f"{source}: study.name ({short(name)}) must be {NAME_RULE}; it names the output folder"
        )
    bearing = head.get("bearing")
    if bearing is not None and not isinstance(bearing, str):
        raise InputError(
            f"{source}: study.bearing ({short(bearing)}) must be a bearing file or a designation"
        )
    if isinstance(bearing, str) and base_dir is not None:
        from bearingkit.io.reading import confined_path
        from bearingkit.studies.generic.evaluator import is_designation

        if not is_designation(bearing, base_dir):
            try:
                bearing = str(confined_path(bearing, base_dir, "study.bearing", allowed_paths))
            except InputError as exc:
                raise InputError(f"{source}: {exc}") from None
    head["bearing"] = bearing
    ev_name = head.get("evaluator")
    if ev_name is None and bearing is not None:
        from bearingkit.studies.generic.evaluator import GENERIC

        ev_name = head["evaluator"] = GENERIC  # a study that names a bearing runs on its input
    if not isinstance(ev_name, str):
        raise InputError(
            f"{source}: study.evaluator ({short(ev_name)}) must name an evaluator (or give study.bearing, "
            "a bearing file or designation, for the generic evaluator)"
        )
    try:
        ev = evaluator_named(ev_name, bearing, head, data, source)
    except InputError as exc:
        text = str(exc)
        if text.startswith(source):
            raise
        for name in (str(bearing), shown(bearing)) if isinstance(bearing, str) else ():
            if text.startswith(f"{name}: "):  # the bearing file's own refusal (cannot read it, bad TOML …)
                raise InputError(f"{source}: study.bearing: {text}") from None
        raise InputError(f"{source}: study.{text}") from None
    fixed = {
        k: si_value(v, factor_of(ev, k, f"fixed.{k}", source), f"{source}: fixed.{k}")
        for k, v in flatten(as_table(data.get("fixed", {}), f"{source}: fixed"))
    }
    factors = factor_list(ev, data.get("factors", []), "factors", source)
    monte_carlo = data.get("monte_carlo")
    if monte_carlo is not None:
        monte_carlo = as_table(monte_carlo, f"{source}: monte_carlo")
        monte_carlo = {
            **monte_carlo,
            "factors": factor_list(ev, monte_carlo.get("factors", []), "monte_carlo.factors", source),
        }
    if head.get("tolerances"):  # the bearing file's [[tolerances]] join the sampled factors
        from bearingkit.studies.generic.evaluator import tolerance_factors

        design = {f["name"] for f in factors}
        extra = factor_list(ev, tolerance_factors(ev, design, source), "tolerances", source)
        if monte_carlo is not None:
            monte_carlo["factors"] = [*monte_carlo["factors"], *extra]
        elif head.get("design") == "monte_carlo":
            factors = [*factors, *extra]
        else:
            raise InputError(
                f"{source}: study.tolerances (true) samples the bearing's [[tolerances]]: use design = "
                "'monte_carlo' or add a [monte_carlo] section (levels x samples)"
            )
    variables = []
    for i, v in enumerate(as_tables(data.get("variables", []), f"{source}: variables")):
        v = dict(v)
        spec = factor_of(ev, v.get("name"), f"variables[{i}].name", source)
        for key in ("low", "high"):
            if key in v:
                v[key] = si_value(v[key], spec, f"{source}: variables[{i}] ({spec.name}).{key}")
        variables.append(v)
    targets = {}
    for tname, t in as_table(data.get("targets", {}), f"{source}: targets").items():
        t = as_table(t, f"{source}: targets.{tname}")
        targets[tname] = {
            k: (
                si_value(v, ev.factors[k], f"{source}: targets.{tname}.{k}")
                if k in ev.factors
                else as_number(v, f"{source}: targets.{tname}.{k}")
            )
            for k, v in t.items()
        }
    raw = {
        **head,
        "bearing": bearing,
        "fixed": fixed,
        "factors": factors,
        "variables": variables,
        "objectives": data.get("objectives", []),
        "constraints": data.get("constraints", []),
        "optimizer": data.get("optimizer", {}),
        "monte_carlo": monte_carlo,
        "targets": targets,
        "plots": as_tables(data.get("plots", []), f"{source}: plots"),
        "source": source,
    }
    try:
        definition = StudyDefinition.model_validate(raw)
    except ValidationError as exc:
        raise InputError(_pydantic_message(exc, source, head)) from None
    check_definition(definition)
    check_plots(definition, ev)
    if not ev.fill_defaults:  # the generic evaluator: every level built into the input once
        from bearingkit.studies.generic.evaluator import check_values

        check_values(ev, definition)
    return definition
