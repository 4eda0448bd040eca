"""The pydantic models of a study file (``[study]``, ``[[factors]]``, ``[monte_carlo]``, ``[[plots]]``,
the optimisation's sections) and the limits a study is held to.

Values arrive here in SI: :mod:`bearingkit.studies.definition.load` parses the file's strings with units
first (:mod:`bearingkit.studies.definition.values`). Every model forbids unknown keys and is frozen.
"""

from __future__ import annotations

import hashlib
import json
import re
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator

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


#: Most panels (outputs) one ``[[plots]]`` entry draws: a figure of more is unreadable, and a
#: histogram asking for ``y`` 1,000 times took 225 s.
MAX_PLOT_PANELS = 12
#: Most quantiles a study reports per output.
MAX_QUANTILES = 20


def _quantiles(value):
    """Each quantile a finite number strictly between 0 and 1, at most :data:`MAX_QUANTILES` of them."""
    if len(value) > MAX_QUANTILES:
        raise ValueError(f"must list at most {MAX_QUANTILES} quantiles")
    for q in value:
        if not 0.0 < q < 1.0:  # NaN fails too
            raise ValueError(f"must lie strictly between 0 and 1 (got {q})")
    return value


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

    _check_quantiles = field_validator("quantiles")(_quantiles)


class PlotDef(_Strict):
    """A plot of the results (``[[plots]]``, :mod:`bearingkit.studies.results.figures`)."""

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

    @field_validator("y")
    @classmethod
    def _few_distinct(cls, value):
        if len(value) > MAX_PLOT_PANELS:
            raise ValueError(f"must name at most {MAX_PLOT_PANELS} outputs (one panel each)")
        if len(set(value)) != len(value):
            raise ValueError("must name each output once")
        return value


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
    chunk_size: int | str = "auto"
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

    @field_validator("chunk_size", mode="before")
    @classmethod
    def _chunk_size(cls, value):
        # "auto" (bearingkit.studies.run.chunking) or a whole number of cases in range
        if value == "auto":
            return value
        if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= MAX_CHUNK_SIZE:
            raise ValueError(f'must be "auto" or a whole number of cases from 1 to {MAX_CHUNK_SIZE:,}')
        return value

    _check_quantiles = field_validator("quantiles")(_quantiles)

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
