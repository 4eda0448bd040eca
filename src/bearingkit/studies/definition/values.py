"""A study file's values in SI: factors and their levels, checked against the evaluator's factors.

A factor's value is a string with a unit (``"-2 um"``, ``"3 kN"``) parsed with
:func:`bearingkit.units.parse` against the dimension the evaluator declares for it; names, flags and
counts are checked as such. Every bad value raises :class:`bearingkit.errors.InputError` with one line
naming the file, the field, the value and what was expected.
"""

from __future__ import annotations

import math

from bearingkit import units
from bearingkit.errors import InputError, did_you_mean


def si_value(value, factor, where: str):
    """``value`` in SI for ``factor`` (its ``dimension``: a unit dimension, or text, flag, count)."""
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
    named = dict(getattr(factor, "named", ()) or ())
    if named and isinstance(value, str) and not units.is_number(value.strip()):
        key = value.strip()
        if key not in named:
            raise InputError(
                f"{where} ({value!r}) must be a number or one of {', '.join(named)}{did_you_mean(key, named)}"
            )
        return float(named[key])
    return units.parse(value, dim, where)


def short(value, limit: int = 60) -> str:
    """``repr(value)``, cut to ``limit`` characters (a message stays one readable line)."""
    text = repr(value).replace("\n", " ")
    return text if len(text) <= limit else text[: limit - 3] + "..."


def as_table(value, where: str) -> dict:
    """``value`` when it is a table (dict), else InputError naming ``where``."""
    if not isinstance(value, dict):
        raise InputError(f"{where} ({short(value)}) must be a table")
    return value


def as_tables(value, where: str) -> list[dict]:
    """``value`` when it is an array of tables (``[[...]]``), else InputError naming ``where``."""
    if not isinstance(value, list):
        raise InputError(f"{where} ({short(value)}) must be an array of tables ([[...]])")
    for i, item in enumerate(value):
        if not isinstance(item, dict):
            raise InputError(f"{where}[{i}] ({short(item)}) must be a table")
    return value


def as_number(value, where: str) -> float:
    """``value`` as a float when it is a finite number (not a bool), else InputError naming ``where``."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise InputError(f"{where} ({short(value)}) must be a finite number")
    return float(value)


def flatten(table: dict, prefix: str = ""):
    """``(key, value)`` of a table, nested tables as dotted keys (TOML ``geometry.bore = …`` in [fixed])."""
    for k, v in table.items():
        if isinstance(v, dict):
            yield from flatten(v, f"{prefix}{k}.")
        else:
            yield f"{prefix}{k}", v


def factor_of(ev, fname, where: str, source: str):
    """The factor ``fname`` of evaluator ``ev``; InputError naming ``where`` (and the nearest names)."""
    if not isinstance(fname, str) or fname not in ev.factors:
        near = ""
        if isinstance(fname, str):
            from bearingkit.studies.generic.paths import nearest

            near = f"; nearest: {', '.join(nearest(fname, ev.factors))}"
        raise InputError(f"{source}: {where} ({short(fname)}) is not {ev.noun}{near}")
    return ev.factors[fname]


def factor_list(ev, items, where: str, source: str) -> list[dict]:
    """The tables of ``[[factors]]`` (or ``[[monte_carlo.factors]]``) with levels and bounds in SI; a
    ``clearance_class`` becomes the uniform distribution over that class's range."""
    out = []
    for i, f in enumerate(as_tables(items, f"{source}: {where}")):
        f = dict(f)
        spec = factor_of(ev, f.get("name"), f"{where}[{i}].name", source)
        w = f"{source}: {where}[{i}] ({spec.name})"
        if "levels" in f:
            if not isinstance(f["levels"], list):
                raise InputError(f"{w}.levels ({short(f['levels'])}) must be an array of values")
            if not f["levels"]:
                raise InputError(f"{w}.levels ([]) must list at least one value")
            f["levels"] = tuple(si_value(v, spec, f"{w}.levels") for v in f["levels"])
        if f.get("clearance_class") is not None:
            from bearingkit.studies.generic.evaluator import clearance_class_range

            low, high = clearance_class_range(ev, spec.name, f["clearance_class"], w)
            f.update(distribution="uniform", low=low, high=high)
        for key in ("base", "mean", "std", "low", "high"):
            if key in f:
                f[key] = si_value(f[key], spec, f"{w}.{key}")
        out.append(f)
    return out
