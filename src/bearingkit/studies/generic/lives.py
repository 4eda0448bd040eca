"""Study outputs of the bearing's lives: the ISO 281 lives (listed first, as every face of a single bearing
shows them) and the duty cycle's Palmgren–Miner lives, apart from the other outputs.

SI units: lives in revolutions (``*_rev``) and hours (``*_h``), damage shares [-].
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

__all__ = ["duty_quantities", "iso281_quantities"]


def _iso281_of(c, attr: str, rated, masked, hours: bool = False) -> np.ndarray:
    """An ISO 281 life of the bearing (:class:`bearingkit.analysis.rating.iso281.Iso281Life`), NaN where
    ISO 281 does not rate it."""

    def get(r):
        iso = getattr(r, "iso281", None)
        if iso is None:
            return np.full(c.n, np.nan)
        value = getattr(iso, attr)
        return masked(r.hours(value) if hours else value, c.n)

    return rated(c, get)


def iso281_quantities(quantity, rated, masked) -> list:
    """The ISO 281 lives of the bearing, listed first (the life a single bearing's faces show first).

    ``quantity``: the :class:`~bearingkit.studies.generic.quantities.Quantity` class; ``rated(c, get)`` and
    ``masked(values, n)``: its module's readers of the rating (the flexible one where there is one).
    """
    return [
        quantity(
            "L10_iso281_rev",
            "rev",
            "basic rating life of the bearing (ISO 281: (C/P)^p from the equivalent load; NaN where ISO 281 "
            "does not rate the bearing)",
            "rating",
            lambda c: _iso281_of(c, "life", rated, masked),
        ),
        quantity(
            "L10h_iso281_h",
            "h",
            "ISO 281 L10 in hours at the case's speed",
            "rating",
            lambda c: _iso281_of(c, "life", rated, masked, hours=True),
        ),
        quantity(
            "Lnm_iso281_rev",
            "rev",
            "modified rating life a1 a_ISO L10 (ISO 281; needs a lubricant, e_C and a speed)",
            "rating",
            lambda c: _iso281_of(c, "modified_life", rated, masked),
        ),
        quantity(
            "Lnm_iso281_h",
            "h",
            "ISO 281 L_nm in hours at the case's speed",
            "rating",
            lambda c: _iso281_of(c, "modified_life", rated, masked, hours=True),
        ),
    ]


def duty_quantities(quantity, bins: Sequence[str]) -> list:
    """The duty cycle's lives, ISO 281 first (Palmgren–Miner on each method's own bin lives), per bin
    its lives and damage shares (``c.duty``: the block the generic evaluator computes for the bins)."""
    out = [
        quantity(
            "duty_L10_iso281_rev",
            "rev",
            "ISO 281 L10 over the duty cycle (Palmgren–Miner sum of the bins' ISO 281 lives)",
            "duty",
            lambda c: c.duty["L10_rev"],
        ),
        quantity(
            "duty_L10h_iso281_h",
            "h",
            "ISO 281 L10 over the duty cycle, in hours",
            "duty",
            lambda c: c.duty["L10_h"],
        ),
        quantity(
            "duty_Lnm_iso281_rev",
            "rev",
            "ISO 281 L_nm over the duty cycle (Palmgren–Miner)",
            "duty",
            lambda c: c.duty["Lnm_rev"],
        ),
        quantity(
            "duty_Lnm_iso281_h",
            "h",
            "ISO 281 L_nm over the duty cycle, in hours",
            "duty",
            lambda c: c.duty["Lnm_h"],
        ),
        quantity(
            "duty_L10r_rev",
            "rev",
            "L10r over the duty cycle (Palmgren–Miner sum of the bins' lives)",
            "duty",
            lambda c: c.duty["L10r_rev"],
        ),
        quantity(
            "duty_L10r_h",
            "h",
            "L10r over the duty cycle, in hours",
            "duty",
            lambda c: c.duty["L10r_h"],
        ),
        quantity(
            "duty_Lnmr_rev",
            "rev",
            "L_nmr over the duty cycle (Palmgren–Miner)",
            "duty",
            lambda c: c.duty["Lnmr_rev"],
        ),
        quantity(
            "duty_Lnmr_h",
            "h",
            "L_nmr over the duty cycle, in hours",
            "duty",
            lambda c: c.duty["Lnmr_h"],
        ),
    ]
    for b, name in enumerate(bins):
        out += [
            quantity(
                f"duty_{name}_L10_iso281_rev",
                "rev",
                f"ISO 281 L10 of duty-cycle bin {name!r}",
                "duty",
                lambda c, b=b: c.duty["bin_L10"][:, b],
            ),
            quantity(
                f"duty_{name}_damage_share_iso281",
                "-",
                f"share of the ISO 281 duty-cycle damage bin {name!r} does",
                "duty",
                lambda c, b=b: c.duty["L10_damage_share"][:, b],
            ),
            quantity(
                f"duty_{name}_L10r_rev",
                "rev",
                f"L10r of duty-cycle bin {name!r}",
                "duty",
                lambda c, b=b: c.duty["bin_L10r"][:, b],
            ),
            quantity(
                f"duty_{name}_damage_share",
                "-",
                f"share of the duty-cycle damage bin {name!r} does",
                "duty",
                lambda c, b=b: c.duty["L10r_damage_share"][:, b],
            ),
        ]
    return out
