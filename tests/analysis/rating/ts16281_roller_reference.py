"""An independent implementation of the ISO/TS 16281:2008 roller-bearing life, for the tests only.

Written from the standard's equations, not from bearingkit's code: the slice model of a radial roller
bearing (eq. (36)-(46): steel slice stiffness c_L = 35948 L_we^(8/9) N/mm^(10/9) of the whole roller,
c_s = c_L / n_s, q_jk = c_s δ_jk^(10/9), δ_jk = δ_r cos ψ_j − s/2 − 2 P(x_k), the logarithmic profile
P(x) = 0.00035 D_we ln[1/(1 − (2x/L_we)²)] of eq. (42) for L_we <= 2.5 D_we, radial equilibrium solved for
δ_r; eq. (43) for longer rollers: no drop over the middle L_we − 2.5 D_we, 0.0005 D_we ln[1/(1 − u²)],
u = (2|x| − (L_we − 2.5 D_we))/(2.5 D_we), towards the ends) and the life assembly (eq. (47)-(65)):

- Q_ci = C/(λν 0.378 Z cos α i^(7/9)) (1 + T^(9/2))^(2/9), Q_ce = C/(λν 0.364 Z cos α i^(7/9))
  (1 + T^(−9/2))^(2/9), T = 1.038 ((1−γ)/(1+γ))^(143/108), λν = 0.83 (radial), eq. (47)-(49);
- lamina ratings q_c = Q_c (1/n_s)^(7/9), eq. (56)-(57);
- edge-stress factor f_k = 1 − 0.01/ln(1.985 |(2k − n_s − 1)/(2n_s − 2)|), the same for both rings
  (f_i = f_e), eq. (60);
- lamina equivalent loads, rotating ring (1/Z Σ_j (f_k q_jk)^4)^(1/4), stationary ring
  (1/Z Σ_j (f_k q_jk)^(9/2))^(2/9), eq. (61)-(64);
- L10r = [Σ_k (q_kei/q_ci)^(9/2) + (q_kee/q_ce)^(9/2)]^(−8/9) 10⁶ rev, eq. (65).

The TS text itself was not available: the equations are as two public implementations of the TS transcribe
them (minzhun/ISO16281 ``RollerBearing.py``; the ``axisforge`` ISO/TS 16281 roller solver, which quotes the
TS's note that eq. (60) holds for the profile of eq. (42)-(44), medium load and a misalignment below 4').
Units here are the TS's: mm, N; lives in 10⁶ rev.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

LAMBDA_NU_RADIAL = 0.83
STEEL_LINE_STIFFNESS = 35948.0  # N/mm^(10/9) per mm^(8/9) of roller length, eq. (35)


def edge_factor(n_s: int) -> np.ndarray:
    """f_k of eq. (60), k = 1 … n_s."""
    k = np.arange(1, n_s + 1)
    x = 1.985 * np.abs((2 * k - n_s - 1) / (2 * n_s - 2))
    return np.where(x > 0, 1.0 - 0.01 / np.log(np.where(x > 0, x, 0.5)), 1.0)


def profile_drop(x, dwe, lwe):
    """P(x) [mm] of eq. (42) (L_we <= 2.5 D_we) and eq. (43) (longer rollers: flat middle, log ends)."""
    if lwe <= 2.5 * dwe:
        return 0.00035 * dwe * np.log(1.0 / (1.0 - (2.0 * x / lwe) ** 2))
    flat = (lwe - 2.5 * dwe) / 2.0
    u = np.clip((2.0 * np.abs(x) - (lwe - 2.5 * dwe)) / (2.5 * dwe), 0.0, None)
    return np.where(np.abs(x) <= flat, 0.0, 0.0005 * dwe * np.log(1.0 / (1.0 - u**2)))


def slice_loads(fr, *, z, dwe, lwe, dpw, n_s, clearance=0.0, profile=True):
    """q_jk [N], (Z, n_s): rollers at ψ_j = 2πj/Z (roller 0 under the load), eq. (36)-(46)."""
    x = (np.arange(n_s) - n_s / 2 + 0.5) * lwe / n_s
    drop = profile_drop(x, dwe, lwe) if profile else np.zeros(n_s)
    c_s = STEEL_LINE_STIFFNESS * lwe ** (8.0 / 9.0) / n_s
    psi = 2.0 * np.pi * np.arange(z) / z

    def q(delta_r):
        d = delta_r * np.cos(psi)[:, None] - clearance / 2.0 - 2.0 * drop[None, :]
        return c_s * np.maximum(d, 0.0) ** (10.0 / 9.0)

    delta = brentq(lambda d: float(np.sum(q(d).sum(axis=1) * np.cos(psi))) - fr, 1e-9, 1.0, xtol=1e-15)
    return q(delta)


def life(q, *, c, z, dwe, dpw, n_s, f_inner=None, f_outer=None):
    """L10r [10⁶ rev] of a radial roller row, inner ring rotating, from its slice loads (eq. (47)-(65)).

    ``f_inner`` / ``f_outer`` are the edge-stress factors of the two rings (None: 1).
    """
    g = dwe / dpw
    t = 1.038 * ((1.0 - g) / (1.0 + g)) ** (143.0 / 108.0)
    q_ci = c / (LAMBDA_NU_RADIAL * 0.378 * z) * (1.0 + t**4.5) ** (2.0 / 9.0) * n_s ** (-7.0 / 9.0)
    q_ce = c / (LAMBDA_NU_RADIAL * 0.364 * z) * (1.0 + t**-4.5) ** (2.0 / 9.0) * n_s ** (-7.0 / 9.0)
    fi = np.ones(n_s) if f_inner is None else f_inner
    fe = np.ones(n_s) if f_outer is None else f_outer
    q_kei = np.mean((fi * q) ** 4, axis=0) ** 0.25
    q_kee = np.mean((fe * q) ** 4.5, axis=0) ** (1.0 / 4.5)
    return float(np.sum((q_kei / q_ci) ** 4.5 + (q_kee / q_ce) ** 4.5) ** (-8.0 / 9.0))
