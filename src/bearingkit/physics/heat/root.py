"""A batched, safeguarded secant (Newton) iteration for a heat balance F(T) = 0 decreasing in T.

Units: those of the caller (bearingkit calls it with temperatures in °C and heat flows in W, SI
otherwise). The safeguarded secant is the textbook combination of the secant step with bisection
inside a bracket (Brent R.P. (1973) Algorithms for Minimization without Derivatives, ch. 4; Dekker's
method of 1969), batched here over cases.

The heat balance of a bearing, F(T) = P(T) − Φ(T) (friction heat minus heat carried away), is
positive at the lowest temperature the heat can flow to (the bearing cannot be cooler than its sink)
and decreases with T: the friction power falls as the oil thins while the dissipated heat grows. Each
case keeps a bracket [lo, hi] with F(lo) > 0 ≥ F(hi); the step is the secant (Newton with the slope of
the last two evaluations), the first one the fixed-point step of a constant friction power, and a step
that leaves the bracket is replaced by bisection. One evaluation of F per iteration for all cases at
once (an evaluation is a friction computation: the expensive part). A case converges when
|F| ≤ rtol · scale (the balance closes to rtol of the friction heat).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class RootResult:
    """Outcome per case (arrays (C,)).

    Attributes
    ----------
    x : ndarray
        Last iterate (the root where ``converged``).
    value, scale : ndarray
        F and its scale at ``x`` (the last evaluation).
    converged : ndarray of bool
    no_root : ndarray of bool
        F(upper) > 0: no root below the upper limit.
    iterations : ndarray of int
        Evaluations until each case stopped.
    """

    x: np.ndarray
    value: np.ndarray
    scale: np.ndarray
    converged: np.ndarray
    no_root: np.ndarray
    iterations: np.ndarray


def solve_decreasing(function, lower, upper, slope0, rtol=1e-6, max_iterations=60) -> RootResult:
    """Root of a decreasing F per case, batched (module docstring).

    Parameters
    ----------
    function : callable
        ``function(x) -> (F, scale)`` for an array x (C,) [same unit as x for F/slope]; F decreasing.
    lower, upper : array_like (C,)
        Search interval; F(lower) > 0 is expected (checked: a case with F(lower) ≤ 0 returns lower).
    slope0 : array_like (C,)
        −dF/dx estimate for the first step (the dissipation per kelvin), > 0.
    rtol : float
        Convergence: |F| ≤ rtol · scale.
    max_iterations : int
        Evaluations at most.

    Returns
    -------
    RootResult
    """
    lo = np.asarray(lower, dtype=float).copy()
    hi = np.asarray(upper, dtype=float).copy()
    x = lo.copy()
    f, scale = (np.asarray(v, dtype=float) for v in function(x))
    f_lo = f.copy()
    f_hi = np.full_like(f, -np.inf)
    done = np.abs(f) <= rtol * np.abs(scale)
    at_floor = f < 0  # the sink is already warmer than the balance: no heating at all
    no_root = np.zeros_like(done)
    iterations = np.ones(x.shape, dtype=int)
    x_prev, f_prev = x.copy(), f.copy()
    step = f / np.asarray(slope0, dtype=float)  # fixed point: constant friction power
    for k in range(1, max_iterations):
        active = ~(done | at_floor | no_root)
        if not active.any():
            break
        if k > 1:
            slope = (f_prev - f) / np.where(x != x_prev, x - x_prev, np.nan)
            ok = np.isfinite(slope) & (slope > 0)
            step = np.where(ok, f / np.where(ok, slope, 1.0), np.nan)
        trial = x + step
        outside = ~np.isfinite(trial) | (trial <= lo) | (trial >= hi)
        trial = np.where(outside, 0.5 * (lo + hi), trial)
        # a case whose bracket still lacks a negative end tries the upper limit itself
        trial = np.where(outside & ~np.isfinite(f_hi), hi, trial)
        x_new = np.where(active, trial, x)
        f_new, s_new = (np.asarray(v, dtype=float) for v in function(x_new))
        iterations = np.where(active, iterations + 1, iterations)
        x_prev, f_prev = np.where(active, x, x_prev), np.where(active, f, f_prev)
        x, f, scale = np.where(active, x_new, x), np.where(active, f_new, f), np.where(active, s_new, scale)
        positive = active & (f > 0)
        lo, f_lo = np.where(positive, x, lo), np.where(positive, f, f_lo)
        negative = active & (f <= 0)
        hi, f_hi = np.where(negative, x, hi), np.where(negative, f, f_hi)
        no_root |= active & positive & (x >= np.asarray(upper, dtype=float))
        done |= active & (np.abs(f) <= rtol * np.abs(scale))
    converged = done | at_floor
    return RootResult(x, f, scale, converged, no_root, iterations)
