"""Study definitions: a TOML file → a validated, SI-valued :class:`StudyDefinition` (pydantic).

SI inside: every quantity of the file is a string with a unit (``"-2 um"``, ``"3 kN"``) parsed with
:func:`bearingkit.units.parse` against the dimension the evaluator declares for that factor;
dimensionless factors and counts may be bare numbers.

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
    chunk_size = 1000           # cases per chunk (the unit of parallel work and of resume)

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

import hashlib
import json
import math
import re
from pathlib import Path
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from bearingkit import units
from bearingkit.errors import InputError

DESIGNS = ("sweep", "factorial", "orthogonal", "monte_carlo", "optimize")

#: Sections a study file may have.
SECTIONS = (
    "study",
    "fixed",
    "factors",
    "variables",
    "objectives",
    "constraints",
    "optimizer",
    "monte_carlo",
    "targets",
    "plots",
)

#: Most ``[[plots]]`` a study may ask for (they are written as plot_1.png … plot_9.png).
MAX_PLOTS = 9

#: A study name: it becomes the default output folder (``study-<name>``) and is written into the
#: store, so it is a plain file name — no separators, no ``..``, nothing absolute, no hidden name.
NAME_PATTERN = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]{0,63}$")
NAME_RULE = "a plain name of letters, digits, '.', '_' and '-' starting with a letter or digit (at most 64)"

#: Most cases one study may have: the case table is built in memory before anything runs (10 million
#: cases x 30 factors of float64 is 2.4 GB). Larger studies are split into several.
MAX_CASES = 10_000_000

#: Largest chunk: one chunk is one batched solve in one process, memory O(chunk x elements).
MAX_CHUNK_SIZE = 1_000_000

#: Most NSGA-III reference directions (Das-Dennis count C(p + m - 1, m - 1) for p partitions and m
#: objectives); the directions are built in memory.
MAX_REFERENCE_DIRECTIONS = 100_000


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class FactorDef(_Strict):
    """A varied factor (SI): ``levels`` or a Monte Carlo ``distribution``."""

    name: str
    label: str | None = None
    levels: tuple | None = None
    column: int | None = None
    base: float | int | str | None = None
    distribution: Literal["normal", "uniform", "lognormal", "truncnormal"] | None = None
    mean: float | None = None
    std: float | None = None
    low: float | None = None
    high: float | None = None
    deviation: bool = False
    clearance_class: str | None = None


class MonteCarloDef(_Strict):
    """Random draws at every design point of a levels × samples study (``[monte_carlo]``)."""

    per_point: int = Field(ge=1)
    sampler: Literal["random", "lhs", "sobol"] = "random"
    seed: int | None = Field(None, ge=0)
    common: bool = True
    quantiles: tuple[float, ...] = (0.05, 0.5, 0.95)
    factors: tuple[FactorDef, ...] = ()


class PlotDef(_Strict):
    """A plot of the results (``[[plots]]``, :mod:`bearingkit.studies.figures`)."""

    kind: Literal["lines", "map", "scatter", "histogram"] = "lines"
    x: str | None = None
    y: tuple[str, ...]
    series: str | None = None
    title: str | None = None
    log_y: bool | tuple[str, ...] = False

    def logarithmic(self, y: str) -> bool:
        """True when the panel of output ``y`` has a logarithmic axis (``log_y`` true, or naming ``y``)."""
        return self.log_y is True or (isinstance(self.log_y, tuple) and y in self.log_y)

    @field_validator("y", mode="before")
    @classmethod
    def _one_or_more(cls, value):
        return (value,) if isinstance(value, str) else value


class VariableDef(_Strict):
    """A design variable of an optimisation (SI bounds)."""

    name: str
    low: float
    high: float
    integer: bool = False


class ObjectiveDef(_Strict):
    output: str
    sense: Literal["min", "max"] = "min"


class ConstraintDef(_Strict):
    """output ≤ upper and/or output ≥ lower (SI)."""

    output: str
    upper: float | None = None
    lower: float | None = None


class OptimizerDef(_Strict):
    algorithm: Literal["nsga2", "nsga3"] = "nsga2"
    pop_size: int = Field(100, ge=4)
    generations: int = Field(100, ge=1)
    seed: int = Field(1, ge=0)
    n_partitions: int = Field(12, ge=1)


class StudyDefinition(_Strict):
    """A validated study (every value SI). Build with :func:`load_study` / :func:`from_dict`."""

    name: str
    design: Literal["sweep", "factorial", "orthogonal", "monte_carlo", "optimize"]
    evaluator: str
    array: str | None = None
    bearing: str | None = None
    load_case: str | None = None
    tolerances: bool = False
    quantiles: tuple[float, ...] = (0.05, 0.5, 0.95)
    response: str | None = None
    samples: int | None = Field(None, ge=1)
    sampler: Literal["random", "lhs", "sobol"] = "random"
    seed: int = Field(0, ge=0)
    chunk_size: int = Field(1000, ge=1, le=MAX_CHUNK_SIZE)
    outputs: tuple[str, ...] | None = None
    fixed: dict = Field(default_factory=dict)
    factors: tuple[FactorDef, ...] = ()
    variables: tuple[VariableDef, ...] = ()
    objectives: tuple[ObjectiveDef, ...] = ()
    constraints: tuple[ConstraintDef, ...] = ()
    optimizer: OptimizerDef = OptimizerDef()
    monte_carlo: MonteCarloDef | None = None
    targets: dict = Field(default_factory=dict)
    plots: tuple[PlotDef, ...] = ()
    source: str = "<dict>"

    @field_validator("name")
    @classmethod
    def _plain_name(cls, value: str) -> str:
        if not NAME_PATTERN.match(value):
            raise ValueError(f"must be {NAME_RULE}; it names the output folder")
        return value

    def fingerprint(self) -> str:
        """SHA-256 of the definition (without its file name): identifies the study in a store."""
        data = self.model_dump(exclude={"source"})
        return hashlib.sha256(json.dumps(data, sort_keys=True, default=str).encode()).hexdigest()


def load_study(path) -> StudyDefinition:
    """Read and validate a study TOML file (relative ``bearing`` paths are resolved from its folder)."""
    from bearingkit.io.reading import load_toml

    path = Path(path)
    data = load_toml(path)  # a regular file of at most 1 MiB, nesting bounded (bearingkit.io.reading)
    return from_dict(data, source=str(path), base_dir=path.parent)


def _si(value, factor, where: str):
    dim = factor.dimension
    if dim == "text":
        if not isinstance(value, str):
            raise InputError(f"{where} ({value!r}) must be a name (string)")
        return value
    if dim == "flag":
        if not isinstance(value, bool):
            raise InputError(f"{where} ({value!r}) must be true or false")
        return value
    if dim == "count":
        x = units.parse(value, "dimensionless", where)
        if not float(x).is_integer():
            raise InputError(f"{where} ({value!r}) must be an integer")
        return int(x)
    return units.parse(value, dim, where)


def _short(value, limit: int = 60) -> str:
    """``repr(value)``, cut to ``limit`` characters (a message stays one readable line)."""
    text = repr(value).replace("\n", " ")
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _table(value, where: str) -> dict:
    if not isinstance(value, dict):
        raise InputError(f"{where} ({_short(value)}) must be a table")
    return value


def _tables(value, where: str) -> list[dict]:
    if not isinstance(value, list):
        raise InputError(f"{where} ({_short(value)}) must be an array of tables ([[...]])")
    for i, item in enumerate(value):
        if not isinstance(item, dict):
            raise InputError(f"{where}[{i}] ({_short(item)}) must be a table")
    return value


def _number(value, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise InputError(f"{where} ({_short(value)}) must be a finite number")
    return float(value)


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
    return f"{source}: {loc} ({_short(err.get('input'))}) {msg}"


def from_dict(data: dict, source: str = "<dict>", base_dir=None) -> StudyDefinition:
    """Validate a parsed study file (see the module docstring); InputError with one line if malformed.

    Every malformed value gives one line naming the file, the field, the value and what was expected;
    nothing else escapes (a study file may come from someone else).
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
            f"{source}: study.name ({_short(name)}) must be {NAME_RULE}; it names the output folder"
        )
    bearing = head.get("bearing")
    if bearing is not None and not isinstance(bearing, str):
        raise InputError(
            f"{source}: study.bearing ({_short(bearing)}) must be a bearing file or a designation"
        )
    if isinstance(bearing, str) and base_dir is not None and not Path(bearing).is_absolute():
        from bearingkit.studies.generic import is_designation

        if not is_designation(bearing, base_dir):
            bearing = str((Path(base_dir) / bearing).resolve())
    head["bearing"] = bearing
    ev_name = head.get("evaluator")
    if ev_name is None and bearing is not None:
        from bearingkit.studies.generic import GENERIC

        ev_name = head["evaluator"] = GENERIC  # a study that names a bearing runs on its input
    if not isinstance(ev_name, str):
        raise InputError(
            f"{source}: study.evaluator ({_short(ev_name)}) must name an evaluator (or give study.bearing, "
            "a bearing file or designation, for the generic evaluator)"
        )
    try:
        ev = _evaluator(ev_name, bearing, head, data, source)
    except InputError as exc:
        text = str(exc)
        raise InputError(text if text.startswith(source) else f"{source}: study.{text}") from None

    def factor(fname, where):
        if not isinstance(fname, str) or fname not in ev.factors:
            near = ""
            if isinstance(fname, str):
                from bearingkit.studies.paths import nearest

                near = f"; nearest: {', '.join(nearest(fname, ev.factors))}"
            raise InputError(f"{source}: {where} ({_short(fname)}) is not {ev.noun}{near}")
        return ev.factors[fname]

    fixed = {
        k: _si(v, factor(k, f"fixed.{k}"), f"{source}: fixed.{k}")
        for k, v in _flatten(_table(data.get("fixed", {}), f"{source}: fixed"))
    }

    def factor_list(items, where):
        out = []
        for i, f in enumerate(_tables(items, f"{source}: {where}")):
            f = dict(f)
            spec = factor(f.get("name"), f"{where}[{i}].name")
            w = f"{source}: {where}[{i}] ({spec.name})"
            if "levels" in f:
                if not isinstance(f["levels"], list):
                    raise InputError(f"{w}.levels ({_short(f['levels'])}) must be an array of values")
                if not f["levels"]:
                    raise InputError(f"{w}.levels ([]) must list at least one value")
                f["levels"] = tuple(_si(v, spec, f"{w}.levels") for v in f["levels"])
            if f.get("clearance_class") is not None:
                from bearingkit.studies.generic import clearance_class_range

                low, high = clearance_class_range(ev, spec.name, f["clearance_class"], w)
                f.update(distribution="uniform", low=low, high=high)
            for key in ("base", "mean", "std", "low", "high"):
                if key in f:
                    f[key] = _si(f[key], spec, f"{w}.{key}")
            out.append(f)
        return out

    factors = factor_list(data.get("factors", []), "factors")
    monte_carlo = data.get("monte_carlo")
    if monte_carlo is not None:
        monte_carlo = _table(monte_carlo, f"{source}: monte_carlo")
        monte_carlo = {
            **monte_carlo,
            "factors": factor_list(monte_carlo.get("factors", []), "monte_carlo.factors"),
        }
    if head.get("tolerances"):  # the bearing file's [[tolerances]] join the sampled factors
        from bearingkit.studies.generic import tolerance_factors

        design = {f["name"] for f in factors}
        extra = factor_list(tolerance_factors(ev, design, source), "tolerances")
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
    for i, v in enumerate(_tables(data.get("variables", []), f"{source}: variables")):
        v = dict(v)
        spec = factor(v.get("name"), f"variables[{i}].name")
        for key in ("low", "high"):
            if key in v:
                v[key] = _si(v[key], spec, f"{source}: variables[{i}] ({spec.name}).{key}")
        variables.append(v)
    targets = {}
    for tname, t in _table(data.get("targets", {}), f"{source}: targets").items():
        t = _table(t, f"{source}: targets.{tname}")
        targets[tname] = {
            k: (
                _si(v, ev.factors[k], f"{source}: targets.{tname}.{k}")
                if k in ev.factors
                else _number(v, f"{source}: targets.{tname}.{k}")
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
        "plots": _tables(data.get("plots", []), f"{source}: plots"),
        "source": source,
    }
    try:
        definition = StudyDefinition.model_validate(raw)
    except ValidationError as exc:
        raise InputError(_pydantic_message(exc, source, head)) from None
    _check(definition)
    _check_plots(definition, ev)
    if not ev.fill_defaults:  # the generic evaluator: every level built into the input once
        from bearingkit.studies.generic import check_values

        check_values(ev, definition)
    return definition


def _flatten(table: dict, prefix: str = ""):
    """``(key, value)`` of a table, nested tables as dotted keys (TOML ``geometry.bore = …`` in [fixed])."""
    for k, v in table.items():
        if isinstance(v, dict):
            yield from _flatten(v, f"{prefix}{k}.")
        else:
            yield f"{prefix}{k}", v


def _names(data: dict) -> list:
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
        out += [k for k, _ in _flatten(fixed)]
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


def _evaluator(name: str, bearing, head: dict, data: dict, source: str):
    """The evaluator a study file names (the generic one is built from its bearing and checked)."""
    from bearingkit.studies import evaluators
    from bearingkit.studies.generic import GENERIC, study_evaluator

    if name != GENERIC:
        return evaluators.get(name)
    if bearing is None:
        raise InputError(
            f"{source}: study.bearing: missing; the generic evaluator needs a bearing file or a designation"
        )
    ev = study_evaluator(bearing, head, _names(data), source)
    head["load_case"] = ev.function.load_case  # the choice is part of the definition (and its fingerprint)
    return ev


def evaluator_of(d: StudyDefinition):
    """The evaluator of a checked study definition (the generic one rebuilt from its bearing, cached)."""
    from bearingkit.studies import evaluators
    from bearingkit.studies.generic import GENERIC, study_evaluator

    if d.evaluator != GENERIC:
        return evaluators.get(d.evaluator)
    head = {"load_case": d.load_case, "outputs": None if d.outputs is None else list(d.outputs)}
    return study_evaluator(d.bearing, head, (), d.source)


def case_count(d: StudyDefinition) -> int:
    """Number of cases (evaluations, for an optimisation) the study asks for, without building them."""
    from bearingkit.studies.generators import orthogonal_array

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


def _check_plots(d: StudyDefinition, ev) -> None:
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
                    from bearingkit.studies.paths import nearest

                    near = ", ".join(nearest(name, sorted(known | factors)))
                    raise InputError(
                        f"{where}.{key} ({name!r}) is neither a factor of the study nor one of its outputs; "
                        f"nearest: {near}"
                    )


def _check(d: StudyDefinition) -> None:
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
        from bearingkit.studies.generators import ARRAYS

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
