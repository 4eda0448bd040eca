"""Input sections of a bearing's operation over time and of its tolerances: ``[[duty_cycle]]``,
``[[tolerances]]``.

SI after validation, as the rest of the schema (the unit-carrying types of :mod:`bearingkit.io.fields`,
messages of :mod:`bearingkit.io.messages`). The loader takes these two sections out of the file before
:class:`~bearingkit.io.schema.BearingFile` validates the rest and validates them here;
:func:`json_schema` is the file's JSON Schema with them (what ``bearingkit schema`` prints).

``[[duty_cycle]]`` — the bins of a load spectrum: each a load case (F_x … M_y, eccentricity, speed,
temperature) with the share of the operation it takes, ``time_fraction`` or ``revolution_fraction``
(every bin the same kind; the shares sum to 1). The rating gives each bin's life and the combined
life by the Palmgren–Miner rule (:mod:`bearingkit.physics.life.duty_cycle`).

``[[tolerances]]`` — the scatter of input values a tolerance study samples (docs/studies.md): a
``path`` into the input (``geometry.clearance_radial``, ``load_cases.radial.F_x`` …), a distribution
(``uniform`` low/high, ``normal`` mean/std, ``truncnormal`` mean/std/low/high) of the DEVIATION from
the file's value, or ``clearance_class = "C3"`` (uniform over the ISO 5753-1 class range). Values keep
their units here; the study checks them against the dimension of the path.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from pydantic import Field, ValidationError, ValidationInfo, field_validator, model_validator

from bearingkit.errors import InputError, quote
from bearingkit.io.fields import Dimensionless, Strict
from bearingkit.io.messages import one_line
from bearingkit.io.sections import MAX_LOAD_CASES, LoadCaseSpec
from bearingkit.physics.life.duty_cycle import FRACTION_SUM_TOLERANCE

__all__ = [
    "MAX_DUTY_BINS",
    "MAX_TOLERANCES",
    "SECTIONS",
    "DutyBinSpec",
    "DutyCycle",
    "ToleranceSpec",
    "duty_cycle_of",
    "json_schema",
    "tolerances_of",
]

#: The sections validated here (arrays of tables).
SECTIONS = ("duty_cycle", "tolerances")
#: Most duty-cycle bins: the bins are solved as one batch, like the load cases, under the same cap
#: (:data:`bearingkit.io.sections.MAX_LOAD_CASES`; the contact-point cap of the loader applies too).
#: Published load spectra have a handful to a few dozen bins.
MAX_DUTY_BINS = MAX_LOAD_CASES
#: Most tolerance entries: one per input value, and a bearing file has well under a hundred scalar
#: values a tolerance study could scatter; the cap bounds the validation work on untrusted input.
MAX_TOLERANCES = 100


def _tables(source: str, value, name: str, most: int) -> list:
    if value is None:
        return []
    if not isinstance(value, list):
        raise InputError(f"{source}: {name} ({quote(value)}) must be an array of tables ([[{name}]] …)")
    if len(value) > most:  # counted before anything is validated
        raise InputError(f"{source}: {name} ({len(value)} entries) must have at most {most} entries")
    for i, v in enumerate(value):
        if not isinstance(v, dict):
            raise InputError(f"{source}: {name}[{i}] ({quote(v)}) must be a table (a [[{name}]] entry)")
    return value


class DutyBinSpec(LoadCaseSpec):
    """``[[duty_cycle]]``: one bin of the load spectrum (a load case and its share of the operation)."""

    name: str = Field("", description="Name of the bin (default bin_1, bin_2 …).")
    time_fraction: Dimensionless | None = Field(
        None, description="Share of the operating time in this bin (0 … 1; all bins sum to 1)."
    )
    revolution_fraction: Dimensionless | None = Field(
        None, description="Share of the revolutions in this bin (0 … 1; all bins sum to 1)."
    )

    @field_validator("time_fraction", "revolution_fraction")
    @classmethod
    def _share(cls, value, info: ValidationInfo):
        if value is not None and not 0.0 <= value <= 1.0:
            raise InputError(f"{info.field_name} ({value!r}) must lie in [0, 1]")
        return value

    @model_validator(mode="after")
    def _one_fraction(self):
        given = [f for f in (self.time_fraction, self.revolution_fraction) if f is not None]
        if len(given) != 1:
            raise InputError(
                "time_fraction / revolution_fraction: give exactly one of them (the bin's share of the "
                "operating time, or of the revolutions)"
            )
        return self


@dataclass(frozen=True)
class DutyCycle:
    """A loaded duty cycle (SI).

    Attributes
    ----------
    bins : tuple of LoadCase
        One load case per bin (load, speed [rad/s], temperature [°C]).
    fractions : ndarray (B,) [-]
        Time or revolution fractions (sum 1).
    kind : {"time", "revolutions"}
    """

    bins: tuple
    fractions: np.ndarray
    kind: str

    @property
    def names(self) -> list[str]:
        return [b.name for b in self.bins]


def duty_cycle_of(source: str, tables: list, make_case) -> DutyCycle | None:
    """Validate the ``[[duty_cycle]]`` tables of a file → :class:`DutyCycle` (None when there are none).

    ``make_case(spec) -> LoadCase`` turns a validated load-case spec into the loader's load case.
    """
    tables = _tables(source, tables, "duty_cycle", MAX_DUTY_BINS)
    if not tables:
        return None
    specs = []
    for i, raw in enumerate(tables):
        try:
            spec = DutyBinSpec.model_validate(raw)
        except ValidationError as exc:
            raise one_line(source, exc, ("duty_cycle", i), {"duty_cycle": DutyBinSpec}) from None
        specs.append(spec if spec.name else spec.model_copy(update={"name": f"bin_{i + 1}"}))
    dup = _repeated(s.name for s in specs)
    if dup:
        raise InputError(f"{source}: duty_cycle.name ({dup!r}) must be unique")
    kinds = {"time" if s.time_fraction is not None else "revolutions" for s in specs}
    if len(kinds) > 1:
        raise InputError(
            f"{source}: duty_cycle: mixes time_fraction and revolution_fraction; give every bin the same kind"
        )
    kind = kinds.pop()
    fractions = np.array([s.time_fraction if kind == "time" else s.revolution_fraction for s in specs])
    key = "time_fraction" if kind == "time" else "revolution_fraction"
    if abs(fractions.sum() - 1.0) > FRACTION_SUM_TOLERANCE:
        raise InputError(
            f"{source}: duty_cycle.{key} (sum of the bins {fractions.sum():.9g}) must sum to 1 (the "
            "bins' shares of the whole operation)"
        )
    if kind == "time":
        for i, s in enumerate(specs):
            if s.speed is None:
                raise InputError(
                    f"{source}: duty_cycle[{i}] ({s.name}).speed: missing; time fractions need every bin's "
                    "speed (give speed = '0 rpm' for a bin at rest, or use revolution_fraction)"
                )
    # the specs hold SI floats already: construct, do not re-validate (that would ask for units again)
    bins = tuple(
        make_case(
            LoadCaseSpec.model_construct(**s.model_dump(exclude={"time_fraction", "revolution_fraction"}))
        )
        for s in specs
    )
    return DutyCycle(bins, fractions, kind)


class ToleranceSpec(Strict):
    """``[[tolerances]]``: the scatter of one input value (values keep their units until a study reads
    them)."""

    path: str = Field(description="Input path, e.g. geometry.clearance_radial (docs/studies.md).")
    distribution: Literal["uniform", "normal", "truncnormal"] | None = Field(
        None, description="Of the deviation from the file's value (omit with clearance_class)."
    )
    mean: Any = Field(None, description="Mean deviation (normal, truncnormal), with the path's unit.")
    std: Any = Field(None, description="Standard deviation (normal, truncnormal).")
    low: Any = Field(None, description="Lowest deviation (uniform, truncnormal).")
    high: Any = Field(None, description="Highest deviation (uniform, truncnormal).")
    clearance_class: Literal["C2", "CN", "C3", "C4", "C5"] | None = Field(
        None,
        description="Radial clearance uniform over this ISO 5753-1 class (path geometry.clearance_radial).",
    )

    @model_validator(mode="after")
    def _one_kind(self):
        if (self.distribution is None) == (self.clearance_class is None):
            raise InputError("distribution / clearance_class: give exactly one of them")
        if self.clearance_class is not None and any(
            v is not None for v in (self.mean, self.std, self.low, self.high)
        ):
            raise InputError("clearance_class sets the whole range; mean/std/low/high do not go with it")
        return self


def tolerances_of(source: str, tables: list) -> tuple:
    """Validate the ``[[tolerances]]`` tables of a file → tuple of :class:`ToleranceSpec`."""
    out = []
    for i, raw in enumerate(_tables(source, tables, "tolerances", MAX_TOLERANCES)):
        try:
            out.append(ToleranceSpec.model_validate(raw))
        except ValidationError as exc:
            raise one_line(source, exc, ("tolerances", i), {"tolerances": ToleranceSpec}) from None
    dup = _repeated(t.path for t in out)
    if dup:
        raise InputError(f"{source}: tolerances.path ({dup!r}) must be unique: one distribution per value")
    return tuple(out)


def _repeated(names) -> list:
    """The names that occur more than once, sorted (linear: a file may hold up to the caps above)."""
    seen, twice = set(), set()
    for n in names:
        (twice if n in seen else seen).add(n)
    return sorted(twice)


def json_schema() -> dict:
    """The JSON Schema of an input file (:func:`bearingkit.io.schema.json_schema`) with the
    ``duty_cycle`` and ``tolerances`` arrays."""
    from bearingkit.io.schema import json_schema as file_schema

    out = file_schema()
    defs = out.setdefault("$defs", {})
    for key, model in (("duty_cycle", DutyBinSpec), ("tolerances", ToleranceSpec)):
        sub = model.model_json_schema(ref_template="#/$defs/{model}")
        defs.update(sub.pop("$defs", {}))
        defs[model.__name__] = sub
        out["properties"][key] = {"type": "array", "items": {"$ref": f"#/$defs/{model.__name__}"}}
    return out
