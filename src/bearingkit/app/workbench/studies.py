"""The studies page: a design study on the current bearing, shaft or drivetrain, written as a study file.

SI inside. The page names factors (paths into the bearing's input, or the factors of the ``shaft`` and
``drivetrain`` evaluators), their levels as texts with units (first, last and a count, or a list), the
outputs, and a design (factorial, Monte Carlo, NSGA-II optimisation). This module turns that into the
files ``bearingkit study`` reads — ``study.toml`` beside the subject (``bearing.toml``: the bearing
page's input document, its one load case renamed ``page``; or ``shaft.toml`` / ``drivetrain.toml`` with
the example bearing files they name) — and checks the study whole with the study machinery itself
(:func:`bearingkit.studies.definition.load.load_study`, :func:`~bearingkit.studies.run.cases.plan_study`)
before anything runs. The job (:mod:`bearingkit.app.workbench.jobs`) then runs exactly those files
with ``python -m bearingkit.studies``: the downloaded folder gives the same numbers from the command
line.

Plots are the study's own ``[[plots]]`` (:mod:`bearingkit.studies.results.figures`), chosen by the app:
outputs against the first factor (a line per level of the second) and the map over the first two
factors, the main effects and ranges of the response (factorial), histograms and a scatter (Monte
Carlo), the Pareto front (optimisation).
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path
from typing import Annotated, Literal

import numpy as np
import tomli_w
from pydantic import Field

from bearingkit.app.form import EXAMPLES_DIR, AnalyzeRequest, FormText, StrictModel, build_document
from bearingkit.app.workbench.systems import SystemRequest, bearing_files_of, read_system
from bearingkit.errors import InputError

__all__ = [
    "MAX_STUDY_CASES",
    "PathsRequest",
    "StudyFactor",
    "StudyFiles",
    "StudyRequest",
    "study_files",
    "subject_paths",
]

#: Cases of one study the app runs at most (its work budget; the command line takes up to 10⁷). A
#: 6209 load case costs ~1-5 ms in a batch, a shaft or drivetrain case ~0.3-3 s (one whole solve).
MAX_STUDY_CASES = 2000
#: Of a shaft or drivetrain (one whole system solve per case).
MAX_SYSTEM_STUDY_CASES = 200
#: Factors, levels per factor and outputs of one study at most (the page's table).
MAX_FACTORS = 4
MAX_LEVELS = 50
MAX_OUTPUTS = 12
#: The progress bar moves in about this many steps (the study's chunks: the unit of progress and resume).
PROGRESS_STEPS = 20
#: Name of the page's one load case in the study's bearing file (its paths: ``load_cases.page.F_x``).
STUDY_CASE = "page"
#: Outputs drawn at most per plot (one panel each).
PLOTTED = 4
Name = Annotated[str, Field(min_length=1, max_length=160)]


class StudyFactor(StrictModel):
    """A factor: a path and its levels (first, last, count; or a list), its distribution, or its bounds."""

    path: Name
    start: FormText = ""
    stop: FormText = ""
    n: int = Field(3, ge=1, le=MAX_LEVELS)
    levels: list[FormText] = Field(default_factory=list, max_length=MAX_LEVELS)
    distribution: Literal["uniform", "normal"] = "uniform"


class Objective(StrictModel):
    output: Name
    sense: Literal["min", "max"] = "min"


class PathsRequest(StrictModel):
    """What a study can vary and compute on a subject."""

    subject: Literal["bearing", "shaft", "drivetrain"]
    bearing: AnalyzeRequest | None = None
    system: SystemRequest | None = None


class StudyRequest(PathsRequest):
    """A study of the subject (module docstring)."""

    design: Literal["factorial", "monte_carlo", "optimize"] = "factorial"
    factors: list[StudyFactor] = Field(min_length=1, max_length=MAX_FACTORS)
    outputs: list[Name] = Field(default_factory=list, max_length=MAX_OUTPUTS)
    response: str = Field("", max_length=160)
    objectives: list[Objective] = Field(default_factory=list, max_length=3)
    samples: int = Field(64, ge=2, le=MAX_STUDY_CASES)
    seed: int = Field(0, ge=0, le=2**31 - 1)
    population: int = Field(20, ge=4, le=200)
    generations: int = Field(10, ge=1, le=100)


class StudyFiles:
    """The files of a study (name → text), its case count and what the page shows about it."""

    def __init__(self, files: dict, n_cases: int, design: str, outputs: list, factors: list, subject: str):
        self.files = files
        self.n_cases = n_cases
        self.design = design
        self.outputs = outputs
        self.factors = factors
        self.subject = subject


# ------------------------------------------------------------------------------------------ subjects
def _bearing_subject(request: PathsRequest):
    """(files, study head, factor paths, outputs, [fixed]) of the bearing page's bearing."""
    from bearingkit.io import loader
    from bearingkit.studies.generic import quantities
    from bearingkit.studies.generic.paths import input_paths

    if request.bearing is None:
        raise InputError("study: no bearing open: open one on the bearing page first")
    document, source = build_document(request.bearing)
    document["load_cases"][0]["name"] = STUDY_CASE
    bearing = loader.from_dict(_copy(document), source=source)
    paths = [
        {"path": p.path, "unit": p.unit, "dimension": p.dimension, "kind": p.kind, "choices": list(p.choices)}
        for p in input_paths(bearing).values()
        if p.dimension != "flag"
    ]
    outputs = [{"name": q.name, "unit": q.unit, "description": q.description}
               for q in quantities.catalogue(bearing).values()]  # fmt: skip
    fixed = {}
    contamination = request.bearing.contamination.strip()
    if contamination:
        try:
            fixed["operating.contamination"] = float(contamination)
        except ValueError:
            fixed["operating.contamination"] = contamination  # a level name (the study turns it into e_C)
    if request.bearing.friction_model != "auto":
        fixed["operating.friction_model"] = request.bearing.friction_model
    head = {"bearing": "bearing.toml", "load_case": STUDY_CASE}
    return {"bearing.toml": tomli_w.dumps(document)}, head, paths, outputs, fixed


def _system_subject(request: PathsRequest):
    """(files, study head, factors of the evaluator, its outputs, [fixed]) of a shaft or drivetrain."""
    from bearingkit.studies.evaluators import get as get_evaluator

    if request.system is None or request.system.system != request.subject:
        raise InputError(f"study: no {request.subject} open: open one on the {request.subject} page first")
    document, name, text = read_system(request.system)
    files = {f"{request.subject}.toml": text}
    for _, value in bearing_files_of(document):  # example bearings, by name (read_system's rule)
        if not isinstance(value, str) or "/" in value or value not in _example_names():
            raise InputError(f"{name}: bearing file ({str(value)[:80]!r}) is not an example bearing")
        files[value] = (EXAMPLES_DIR / value).read_text(encoding="utf-8")
    ev = get_evaluator(request.subject)
    choices = _text_choices(document, request.subject)
    paths = [
        {"path": f.name, "unit": _unit(f.dimension), "dimension": f.dimension, "kind": "file",
         "choices": choices.get(f.name, [])}
        for f in ev.factors.values()
        if f.name != "file"
    ]  # fmt: skip
    outputs = [{"name": o, "unit": _output_unit(o), "description": ""} for o in ev.outputs]
    head = {"evaluator": request.subject}
    return files, head, paths, outputs, {"file": f"{request.subject}.toml"}


def _example_names() -> list[str]:
    from bearingkit.app.form import examples

    return examples()


def _text_choices(document: dict, subject: str) -> dict:
    """Names a text factor of the shaft / drivetrain evaluator takes in this file."""
    if subject == "shaft":
        bearings = [
            b.get("name") for b in (document.get("shaft") or {}).get("bearings", []) if isinstance(b, dict)
        ]
        return {"bearing": [b for b in bearings if isinstance(b, str)]}
    bearings, gears = [], []
    for s in document.get("shafts") or []:
        if isinstance(s, dict):
            bearings += [b.get("name") for b in s.get("bearings", []) if isinstance(b, dict)]
            gears += [g.get("name") for g in s.get("gears", []) if isinstance(g, dict)]
    return {
        "bearing": [b for b in bearings if isinstance(b, str)],
        "ratio_gear": [g for g in gears if isinstance(g, str)],
    }


def _unit(dimension: str) -> str:
    from bearingkit.units import SI_UNITS

    if dimension in ("count", "text", "flag"):
        return dimension
    return SI_UNITS.get(dimension) or "-"


def _output_unit(name: str) -> str:
    """The unit an output's name ends in (``_h``, ``_Pa``, ``_N`` …), ``-`` for ratios and flags."""
    for suffix, unit in (("_h", "h"), ("_Pa", "Pa"), ("_N", "N"), ("_Nm", "N·m"), ("_W", "W"), ("_m", "m"),
                         ("_rad", "rad")):  # fmt: skip
        if name.endswith(suffix):
            return unit
    return "bool" if name == "converged" else "-"


def _subject(request: PathsRequest):
    return _bearing_subject(request) if request.subject == "bearing" else _system_subject(request)


def _copy(document: dict) -> dict:
    import copy

    return copy.deepcopy(document)


def subject_paths(request: PathsRequest) -> dict:
    """``{"paths", "outputs"}``: what a study can vary (with units) and compute on the subject."""
    _, _, paths, outputs, _ = _subject(request)
    return {"paths": paths, "outputs": outputs}


# ------------------------------------------------------------------------------------------ levels
def _levels(f: StudyFactor, dimension: str, where: str) -> list:
    """The factor's levels as the study file writes them (texts with units, numbers, names)."""
    from bearingkit.studies.generic.paths import value_text
    from bearingkit.units import parse

    if f.levels:
        out = [v.strip() for v in f.levels if v.strip()]
        if dimension in ("count", "dimensionless"):
            try:
                out = [int(v) if dimension == "count" else float(v) for v in out]
            except ValueError:
                raise InputError(f"{where}.levels ({f.levels!r}) must be numbers") from None
        if not out:
            raise InputError(f"{where}.levels: give at least one level")
        return out
    if dimension in ("text", "flag"):
        raise InputError(
            f"{where}: a {dimension} factor takes a list of levels (names), e.g. ISO_VG68, ISO_VG100"
        )
    if not f.start.strip() or (f.n > 1 and not f.stop.strip()):
        raise InputError(f"{where}: give the first and the last level (texts with units, e.g. 1 kN … 10 kN)")
    lo = parse(f.start.strip(), "dimensionless" if dimension == "count" else dimension, f"{where}.from")
    hi = (
        lo
        if f.n == 1
        else parse(f.stop.strip(), "dimensionless" if dimension == "count" else dimension, f"{where}.to")
    )
    values = np.linspace(lo, hi, f.n).tolist()
    if dimension == "count":
        return sorted({round(v) for v in values})
    return [value_text(v, dimension) for v in values]


def _factor_entry(f: StudyFactor, dimension: str, design: str, where: str) -> tuple[dict, int]:
    """(``[[factors]]`` or ``[[variables]]`` entry, its level count) of one factor."""
    if design == "factorial":
        levels = _levels(f, dimension, where)
        return {"name": f.path, "levels": levels}, len(levels)
    if dimension in ("text", "flag", "count") and design == "monte_carlo":
        raise InputError(f"{where}: a Monte Carlo samples numbers; {f.path!r} is a {dimension} factor")
    if not f.start.strip() or not f.stop.strip():
        what = (
            "the low and the high bound"
            if design == "optimize" or f.distribution == "uniform"
            else "mean and std"
        )
        raise InputError(f"{where}: give {what} (texts with units)")
    if design == "optimize":
        if dimension in ("text", "flag"):
            raise InputError(f"{where}: an optimisation varies numbers; {f.path!r} is a {dimension} factor")
        entry = {"name": f.path, "low": _number(f.start, dimension), "high": _number(f.stop, dimension)}
        if dimension == "count":
            entry["integer"] = True
        return entry, 1
    if f.distribution == "uniform":
        return {"name": f.path, "distribution": "uniform", "low": _number(f.start, dimension),
                "high": _number(f.stop, dimension)}, 1  # fmt: skip
    return {"name": f.path, "distribution": "normal", "mean": _number(f.start, dimension),
            "std": _number(f.stop, dimension)}, 1  # fmt: skip


def _number(text: str, dimension: str):
    """A bound as the study file writes it: a bare number for counts and ratios, else the text."""
    text = text.strip()
    if dimension in ("count", "dimensionless"):
        try:
            return float(text) if dimension == "dimensionless" else int(float(text))
        except ValueError:
            raise InputError(f"study: {text!r} must be a number") from None
    return text


# ------------------------------------------------------------------------------------------ the file
def _plots(request: StudyRequest, numeric: list[str], units: dict, axes: list[str]) -> list[dict]:
    """The study's ``[[plots]]`` (module docstring); ``axes`` are the numeric factors (a name on an axis
    cannot be drawn); an optimisation draws its Pareto front itself (``pareto.png``) and takes none."""
    if not numeric or not axes or request.design == "optimize":
        return []
    shown = numeric[:PLOTTED]
    log = [o for o in shown if units.get(o) in ("h", "rev")]
    first = axes[0]
    if request.design == "monte_carlo":
        return [
            {"kind": "histogram", "y": shown, "title": "distribution over the draws"},
            {"kind": "scatter", "x": first, "y": shown[:2], "title": f"against {first}"},
        ]
    lines = {"kind": "lines", "x": first, "y": shown, "title": f"outputs against {first}"}
    if len(axes) > 1:
        lines["series"] = axes[1]
    if log:
        lines["log_y"] = log
    plots = [lines]
    if len(axes) > 1:
        plots.append({"kind": "map", "x": first, "series": axes[1], "y": shown[:2],
                      "title": f"{', '.join(shown[:2])} over {first} × {axes[1]}"})  # fmt: skip
    return plots


#: Factors of the shaft and drivetrain evaluators that change the bearing named by the factor ``bearing``
#: (and the drivetrain's ``ratio_teeth``, the gear named by ``ratio_gear``).
_NEEDS = {
    "designation": "bearing",
    "position_change": "bearing",
    "axial_offset_change": "bearing",
    "axial_offset": "bearing",
    "ratio_teeth": "ratio_gear",
}


def study_files(request: StudyRequest) -> StudyFiles:
    """The study's files, checked by the study machinery (module docstring); InputError in one line."""
    files, head, paths, catalogue, fixed = _subject(request)
    known = {p["path"]: p for p in paths}
    units = {o["name"]: o["unit"] for o in catalogue}
    for i, f in enumerate(request.factors):
        if f.path not in known:
            raise InputError(
                f"study.factors[{i}].path ({f.path!r}) is not a factor of this {request.subject}"
            )
    names = [f.path for f in request.factors]
    if len(set(names)) < len(names):
        raise InputError("study.factors: a factor is listed twice")
    if request.subject != "bearing":
        for i, name in enumerate(names):
            needed = _NEEDS.get(name)
            if needed and needed not in names:
                choices = ", ".join(known.get(needed, {}).get("choices", [])) or "see the file"
                raise InputError(
                    f"study.factors[{i}].path ({name!r}) changes the {needed} named by the factor "
                    f"{needed!r}: add it, with one level to fix it ({choices})"
                )
    outputs = list(dict.fromkeys(request.outputs))
    for o in outputs:
        if o not in units:
            raise InputError(f"study.outputs ({o!r}) is not an output of this {request.subject}")
    goals = [o.output for o in request.objectives]
    if request.design == "optimize":
        if len(goals) < 2:
            raise InputError(
                "study.objectives: an optimisation needs two or three objectives (outputs to min/max)"
            )
        for g in goals:
            if g not in units:
                raise InputError(f"study.objectives ({g!r}) is not an output of this {request.subject}")
        outputs = list(dict.fromkeys([*outputs, *goals]))
    if not outputs:
        raise InputError("study.outputs: choose at least one output")
    if "converged" in units and "converged" not in outputs:
        outputs.append("converged")
    numeric = [o for o in outputs if units.get(o) not in ("bool", "count") and o != "converged"]
    study: dict = {"name": f"app_{request.subject}_{request.design}", "design": request.design, **head}
    study["outputs"] = outputs
    doc: dict = {"study": study}
    entries, n_cases = [], 1
    for i, f in enumerate(request.factors):
        entry, count = _factor_entry(f, known[f.path]["dimension"], request.design, f"study.factors[{i}]")
        entries.append(entry)
        n_cases *= count
    if request.design == "factorial":
        doc["factors"] = entries
        response = request.response.strip() or (numeric[0] if numeric else "")
        if response:
            if response not in outputs:
                raise InputError(f"study.response ({response!r}) must be one of the outputs")
            study["response"] = response
    elif request.design == "monte_carlo":
        doc["factors"] = entries
        study.update(samples=request.samples, sampler="lhs", seed=request.seed)
        n_cases = request.samples
    else:
        doc["variables"] = entries
        doc["objectives"] = [{"output": o.output, "sense": o.sense} for o in request.objectives]
        doc["optimizer"] = {"algorithm": "nsga2", "pop_size": request.population,
                            "generations": request.generations, "seed": request.seed}  # fmt: skip
        n_cases = request.population * request.generations
    cap = MAX_STUDY_CASES if request.subject == "bearing" else MAX_SYSTEM_STUDY_CASES
    if n_cases > cap:
        raise InputError(
            f"study: {n_cases} cases is above the app's budget of {cap} for a {request.subject}; use fewer "
            "levels or samples, or run the downloaded study with bearingkit study on the command line"
        )
    study["chunk_size"] = max(1, math.ceil(n_cases / PROGRESS_STEPS))
    if fixed:
        doc["fixed"] = fixed
    axes = [f.path for f in request.factors if known[f.path]["dimension"] not in ("text", "flag")]
    plots = _plots(request, numeric, units, axes)
    if plots:
        doc["plots"] = plots
    files = {**files, "study.toml": _header(request) + tomli_w.dumps(doc)}
    _check(files)
    return StudyFiles(files, n_cases, request.design, outputs, names, request.subject)


def _header(request: StudyRequest) -> str:
    return (
        f"# A study made by `bearingkit serve` on the {request.subject} of its page. Run it again here with\n"
        "#     bearingkit study study.toml --out my_run\n\n"
    )


def _check(files: dict) -> None:
    """Load and plan the study from its files, as ``bearingkit study`` will (every check, nothing run).

    The subject's paths are relative to the study file (a bearing) or to the folder the job runs in (the
    ``file`` factor of a shaft or drivetrain, which planning does not open)."""
    from bearingkit.studies.definition.load import load_study
    from bearingkit.studies.run.cases import plan_study

    with tempfile.TemporaryDirectory(prefix="bearingkit-study-check-") as tmp:
        for name, text in files.items():
            (Path(tmp) / name).write_text(text, encoding="utf-8")
        plan_study(load_study(Path(tmp) / "study.toml"))
