"""Life over a duty cycle: Palmgren–Miner linear damage summation of the lives of its bins.

SI in and out: speeds in rad/s, lives in revolutions (``*_rev``) or seconds; fractions are
dimensionless. Every function is vectorised over leading axes; the bins are the LAST axis.

A duty cycle (a load spectrum) is a set of bins i, each run at a constant load, speed and temperature
for a share of the operation. The bearing's life under the cycle follows from the lives L_i it would
have if it ran in bin i only, by the linear damage hypothesis of Palmgren (1924) and Miner (1945): a
revolution in bin i uses 1/L_i of the life, so with U_i the share of the revolutions spent in bin i

.. math:: L = \\Bigl(\\sum_i \\frac{U_i}{L_i}\\Bigr)^{-1}\\qquad [\\text{rev}],\\qquad \\sum_i U_i = 1.

This is the rule ISO 281:2007 uses for variable loads and speeds (its mean equivalent load
P_m = (Σ U_i P_i^p)^{1/p} is the same sum written for one C: L = (C/P_m)^p) and ISO/TS 16281:2008
applies to the reference lives L_10r,i and L_nmr,i of the bins [the clause numbers from memory; the
rule itself is the standard linear damage sum, confirmed in Harris & Kotzalas 2007 vol. 2 ch. 8 and
in makers' catalogues (SKF: G_h = T / (t_I/G_hI + t_II/G_hII + …) with time shares)].

When the shares are given as time fractions t_i (Σ t_i = 1) at speeds n_i, the revolution fractions are

.. math:: U_i = \\frac{t_i |n_i|}{\\sum_j t_j |n_j|},

bins at rest do no fatigue damage, and the life in time is L / Σ_j t_j |n_j| (revolutions over the mean
revolution rate) — the same as L_h = (Σ_i t_i / L_h,i)^{-1} with the bins' lives in hours.

References: Palmgren (1924) Z. VDI 68:339–341; Miner (1945) J. Appl. Mech. 12:A159–A164;
ISO 281:2007; ISO/TS 16281:2008; Harris & Kotzalas (2007) vol. 2 ch. 8.
"""

from __future__ import annotations

import numpy as np

from bearingkit import references
from bearingkit.errors import InputError

references.add(
    "palmgren1924",
    "Palmgren, A. (1924). Die Lebensdauer von Kugellagern. Zeitschrift des VDI 68(14):339–341.",
)
references.add(
    "miner1945",
    "Miner, M. A. (1945). Cumulative damage in fatigue. Journal of Applied Mechanics 12:A159–A164.",
)

#: How the shares of a duty cycle are given: of the operating time, or of the revolutions.
FRACTION_KINDS = ("time", "revolutions")
#: Largest |Σ fractions − 1| accepted as a complete cycle [-] (shares typed with 6 significant digits).
FRACTION_SUM_TOLERANCE = 1.0e-6


def revolution_fractions(fractions, speeds=None, kind: str = "time") -> np.ndarray:
    """Share U_i of the revolutions spent in each bin (..., B) [-].

    Parameters
    ----------
    fractions : array_like (..., B) [-]
        Time fractions t_i (``kind="time"``) or revolution fractions U_i (``kind="revolutions"``).
    speeds : array_like (..., B) [rad/s], optional
        Speed of each bin (its sign is ignored); needed for time fractions.
    kind : {"time", "revolutions"}

    Returns
    -------
    ndarray (..., B)
        U_i = t_i |n_i| / Σ_j t_j |n_j| (time) or the fractions themselves; NaN where no bin turns.
    """
    if kind not in FRACTION_KINDS:
        raise InputError(f"fraction kind ({kind!r}) must be one of {', '.join(FRACTION_KINDS)}")
    f = np.asarray(fractions, dtype=float)
    if kind == "revolutions":
        return f.copy()
    if speeds is None:
        raise InputError("time fractions need the speed of every bin to give revolution fractions")
    rate = f * np.abs(np.asarray(speeds, dtype=float))
    total = rate.sum(axis=-1, keepdims=True)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(total > 0.0, rate / np.where(total > 0.0, total, 1.0), np.nan)


def mean_revolution_rate(fractions, speeds, kind: str = "time") -> np.ndarray:
    """Revolutions per second of operation over the cycle, Σ t_i |n_i| / 2π (...) [rev/s].

    With revolution fractions U_i the time shares are t_i ∝ U_i / |n_i|, so the rate is
    1 / Σ_i (U_i 2π / |n_i|); a bin with U_i > 0 at rest gives no finite rate (NaN).

    Parameters
    ----------
    fractions : array_like (..., B) [-]
        Time fractions t_i or revolution fractions U_i (``kind``).
    speeds : array_like (..., B) [rad/s]
        Speed of each bin (sign ignored).
    kind : {"time", "revolutions"}
    """
    f = np.asarray(fractions, dtype=float)
    n = np.abs(np.asarray(speeds, dtype=float)) / (2.0 * np.pi)
    if kind == "time":
        return (f * n).sum(axis=-1)
    if kind not in FRACTION_KINDS:
        raise InputError(f"fraction kind ({kind!r}) must be one of {', '.join(FRACTION_KINDS)}")
    with np.errstate(divide="ignore", invalid="ignore"):
        seconds = np.where(f > 0.0, f / np.where(n > 0.0, n, np.nan), 0.0).sum(axis=-1)
        return 1.0 / seconds


def miner_life(lives, fractions) -> np.ndarray:
    """Life over the cycle by linear damage summation, L = (Σ_i U_i / L_i)^{-1} (...) [rev].

    Parameters
    ----------
    lives : array_like (..., B) [rev]
        Life L_i of each bin; +inf for a bin that does no damage (no load); NaN where unknown.
    fractions : array_like (..., B) [-]
        Revolution fractions U_i (:func:`revolution_fractions`).

    Returns
    -------
    ndarray (...)
        +inf when no bin does damage; NaN when a bin with U_i > 0 has no life (or no bin turns).
    """
    life = np.asarray(lives, dtype=float)
    u = np.asarray(fractions, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        damage = np.where(u > 0.0, u / life, 0.0)  # U/inf = 0: an unloaded bin does no damage
        total = damage.sum(axis=-1)
        return np.where(np.isnan(total), np.nan, 1.0 / total)


def damage_shares(lives, fractions) -> np.ndarray:
    """Share of the damage each bin does, (U_i / L_i) / Σ_j (U_j / L_j) (..., B) [-].

    Parameters
    ----------
    lives : array_like (..., B) [rev]
        Life of each bin (+inf: no damage).
    fractions : array_like (..., B) [-]
        Revolution fractions U_i.
    """
    life = np.asarray(lives, dtype=float)
    u = np.asarray(fractions, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        damage = np.where(u > 0.0, u / life, 0.0)
        total = damage.sum(axis=-1, keepdims=True)
        shares = damage / np.where(total > 0.0, total, 1.0)
        return np.where(total > 0.0, shares, np.where(total == 0.0, 0.0, np.nan))
