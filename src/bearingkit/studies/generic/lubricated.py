"""Study outputs that need a lubricant (κ, film, friction; NaN without one), apart from the other outputs."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

__all__ = ["lubricated_quantities"]


def _friction_of(c, attr: str) -> np.ndarray:
    outcome = c.analysis.friction
    if outcome is None:
        return np.full(c.n, np.nan)
    return np.asarray(getattr(outcome, attr), dtype=float)[: c.n]


def _friction(quantity) -> list:
    return [
        quantity(
            "friction_torque_Nm",
            "N·m",
            "friction torque (the analysis's friction model)",
            "friction",
            lambda c: _friction_of(c, "total"),
        ),
        quantity(
            "power_loss_W",
            "W",
            "friction power loss M |ω|",
            "friction",
            lambda c: _friction_of(c, "power_loss"),
        ),
    ]


def _lubrication_of(c):
    outcome = c.analysis.lubrication
    return None if outcome is None else outcome.result


def _kappa(c, rows: Sequence[str]) -> np.ndarray:
    res = _lubrication_of(c)
    if res is None:
        return np.full(c.n, np.nan)
    values = [np.asarray(res.kappa[r], float)[: c.n] for r in rows if r in res.kappa]
    return np.min(values, axis=0) if values else np.full(c.n, np.nan)


def _film(c, row: str) -> np.ndarray:
    res = _lubrication_of(c)
    if res is None:
        return np.full(c.n, np.nan)
    for f in res.films:
        if f.row == row:
            hi = np.where(f.loaded_inner, f.film_minimum_inner, np.inf).min(-1)
            ho = np.where(f.loaded_outer, f.film_minimum_outer, np.inf).min(-1)
            h = np.minimum(hi, ho)[: c.n]
            return np.where(np.isfinite(h), h, np.nan)
    return np.full(c.n, np.nan)


def _lubrication(quantity, rows: Sequence[str]) -> list:
    out = [
        quantity(
            "kappa",
            "-",
            "viscosity ratio κ = ν/ν1 (ISO 281 9.3.3; the smallest over the rows; NaN at rest)",
            "lubrication",
            lambda c: _kappa(c, rows),
        )
    ]
    for name in rows:
        if len(rows) > 1:
            out.append(
                quantity(
                    f"{name}_kappa",
                    "-",
                    f"viscosity ratio κ of row {name!r}",
                    "lubrication",
                    lambda c, r=name: _kappa(c, (r,)),
                )
            )
        out.append(
            quantity(
                f"{name}_film_min_m",
                "m",
                f"smallest minimum film thickness over the loaded contacts of row {name!r} (EHL)",
                "lubrication",
                lambda c, r=name: _film(c, r),
            )
        )
    return out


def lubricated_quantities(quantity, rows: Sequence[str]) -> list:
    """The lubrication and friction outputs of the generic evaluator for the rows ``rows``, each built by
    ``quantity(name, unit, description, part, get)`` (the evaluator's Quantity: passed in, so that this
    module does not import the one that imports it)."""
    return _lubrication(quantity, rows) + _friction(quantity)
