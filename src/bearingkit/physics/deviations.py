"""Roller diameter deviations ΔD: Gaussian generators, arrangements, and seed 001's Table 2.

SI units (m). Seed 001 (Liu et al. 2022, §2.3, eq. 14) models the geometric homogeneity of rollers by
a diameter deviation per roller drawn from a standard Gaussian in the scaled variable ΔD/S_d,

.. math:: f(\\Delta D / S_d) = \\frac{1}{\\sqrt{2\\pi}}\\exp\\big[-(\\Delta D/S_d)^2/2\\big],

so ΔD ~ N(0, S_d²): the deviation magnitude S_d is the standard deviation σ. (Table 2 agrees: series
3 and 5 are series 1 scaled by 2 and 3, i.e. one standard-normal draw times S_d = 0.5, 1, 1.5 µm.)
Arrangements (registry :data:`ARRANGEMENTS`): ``"random"`` keeps the draw order around the cage,
``"descending"`` puts the rollers in descending order of ΔD from roller 1 (ψ = phase) onwards.

References: Liu Y., Fan X., Wang J., Liu X. (2022) Lubricants 10(7):154, eq. (14), Table 2,
doi:10.3390/lubricants10070154 (key ``liu2022``).
"""

from __future__ import annotations

import csv
from importlib import resources

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError

#: Micrometre in metres.
MICROMETRE = 1e-6


def _random(values):
    return values


def _descending(values):
    return -np.sort(-values, axis=-1)


#: Arrangements of a draw of deviations around the cage (documented names).
ARRANGEMENTS = {"random": _random, "descending": _descending}


def gaussian_deviations(n_elements, magnitude, n_cases=1, arrangement="random", seed=None):
    """Per-roller diameter deviations ΔD ~ N(0, S_d²), batched over realisations.

    Parameters
    ----------
    n_elements : int
        Rollers Z.
    magnitude : float [m]
        Deviation magnitude S_d (the standard deviation), ≥ 0.
    n_cases : int
        Realisations C (leading axis).
    arrangement : str
        ``"random"`` or ``"descending"`` (:data:`ARRANGEMENTS`).
    seed : int, numpy Generator or None
        Random seed (reproducible draws: the same seed gives the same array).

    Returns
    -------
    ndarray (C, Z) [m]

    Notes
    -----
    .. math:: \\Delta D_j = S_d\\,z_j,\\quad z_j \\sim \\mathcal N(0, 1)

    Liu et al. (2022) eq. (14), doi:10.3390/lubricants10070154.
    """
    z = checks.integer("n_elements", n_elements, low=1)
    c = checks.integer("n_cases", n_cases, low=1)
    checks.non_negative("magnitude", magnitude, "m")
    checks.one_of("arrangement", arrangement, ARRANGEMENTS)
    rng = np.random.default_rng(seed)
    draw = float(magnitude) * rng.standard_normal((c, z))
    return ARRANGEMENTS[arrangement](draw)


def arrange(deviations, arrangement: str):
    """Rearrange given deviations (…, Z) [m] around the cage (``"random"`` keeps them as given).

    Parameters
    ----------
    deviations : array_like (…, Z) [m]
        Roller diameter deviations ΔD, roller 1 first.
    arrangement : str
        A key of :data:`ARRANGEMENTS` (``"random"`` or ``"descending"``, Liu et al. 2022 §3.1).
    """
    checks.one_of("arrangement", arrangement, ARRANGEMENTS)
    dev = np.asarray(deviations, dtype=float)
    checks.finite("diameter_deviation", dev, "m")
    return ARRANGEMENTS[arrangement](dev)


def _read_table2() -> dict:
    text = resources.files("bearingkit").joinpath("data", "seed001_table2.csv").read_text(encoding="utf-8")
    rows = [r for r in csv.reader(line for line in text.splitlines() if not line.startswith("#"))]
    header, body = rows[0], rows[1:]
    out = {}
    for r in body:
        rec = dict(zip(header, r, strict=True))
        out[int(rec["series"])] = {
            "magnitude": float(rec["S_d_um"]) * MICROMETRE,
            "arrangement": rec["arrangement"],
            "deviation": np.array([float(rec[f"r{j}"]) for j in range(1, 24)]) * MICROMETRE,
        }
    return out


_TABLE2: dict | None = None


def seed001_series(series: int) -> np.ndarray:
    """Seed 001 Table 2 deviation series ``series`` (1–6) as ΔD (23,) [m], roller 1 first.

    Parameters
    ----------
    series : int
        Series number 1–6 of Liu et al. (2022) Table 2.
    """
    global _TABLE2
    if _TABLE2 is None:
        _TABLE2 = _read_table2()
    if series not in _TABLE2:
        raise InputError(f"series ({series!r}) must be one of 1, 2, 3, 4, 5, 6 (seed 001 Table 2)")
    return _TABLE2[series]["deviation"].copy()


def seed001_series_info(series: int) -> dict:
    """S_d [m] and arrangement of Table 2 series ``series`` (1–6), Liu et al. (2022).

    Parameters
    ----------
    series : int
        Series number 1–6 of Table 2.
    """
    seed001_series(series)
    rec = _TABLE2[series]
    return {"magnitude": rec["magnitude"], "arrangement": rec["arrangement"]}


__all__ = ["ARRANGEMENTS", "arrange", "gaussian_deviations", "seed001_series", "seed001_series_info"]
