"""Study outputs of the speed and load limits (:mod:`bearingkit.pipeline.limits`): values and flags.

SI units in the names. A flag is 1.0 where the case exceeds the limit, 0.0 where it does not, NaN where
the limit does not apply (a bearing no catalogue rule covers, a minimum load without a lubricant).
"""

from __future__ import annotations

import numpy as np

__all__ = ["limit_quantities"]

#: Flag name → meaning (the keys of OperatingLimits.flags).
FLAGS = {
    "above_limiting_speed": "1 where the speed exceeds the limiting speed (kind, cage, lubrication)",
    "above_reference_speed": "1 where the speed exceeds the ISO 15312 thermal reference speed (SKF model)",
    "seal_lip_speed_exceeded": "1 where a rubbing seal's lip speed exceeds its limit",
    "below_minimum_load": "1 where the load is below the requisite minimum load (skidding, smearing)",
}


def _flag(c, name: str) -> np.ndarray:
    lim = c.analysis.limits
    if lim is None:
        return np.full(c.n, np.nan)
    return np.array([float(lim.flags(i)[name]) for i in range(c.n)])


def _value(c, get) -> np.ndarray:
    lim = c.analysis.limits
    value = None if lim is None else get(lim)
    if value is None:
        return np.full(c.n, np.nan)
    return np.broadcast_to(np.asarray(value, dtype=float), (c.analysis.n_cases,))[: c.n].copy()


def limit_quantities(quantity) -> list:
    """The limit outputs of the generic evaluator (part ``rating``: the limits read the ratings), each
    built by ``quantity(name, unit, description, part, get)`` (the evaluator's Quantity: passed in, so
    that this module does not import the one that imports it)."""
    out = [
        quantity(
            "limiting_speed_rad_s",
            "rad/s",
            "limiting speed by bearing type, cage and lubrication (NaN: no catalogue rule)",
            "rating",
            lambda c: _value(c, lambda lim: lim.limiting_speed),
        ),
        quantity(
            "n_dm_mm_rpm",
            "mm·r/min",
            "speed factor n·d_m (as catalogues print it)",
            "rating",
            lambda c: _value(c, lambda lim: lim.n_dm),
        ),
        quantity(
            "minimum_load_N",
            "N",
            "requisite minimum load (SKF rule of the type and series)",
            "rating",
            lambda c: _value(c, lambda lim: lim.minimum_load),
        ),
    ]
    out += [
        quantity(name, "-", meaning, "rating", lambda c, name=name: _flag(c, name))
        for name, meaning in FLAGS.items()
    ]
    return out
