"""Why the seed-000 reproduction needed a load-proportional roller sliding term (issue 32): E2 alone.

SI units (N·m, Pa·s). Tian et al. (2025) Machines 13:588, doi:10.3390/machines13070588, §4.2 and Table 3.
Two diagnostics of the reading WITHOUT the roller sliding term (variant ``viscous_only``: μ_rs = 0, the
grease viscosity factor identified on Table 3 run 1 instead), behind docs/seed000-friction.md:

* :func:`multiplier_scan` — E2 multiplied by k, the viscosity factor re-identified on run 1 for every k,
  and the rms error of runs 1–9: which E2 Table 3 would need if the pitch-line differential sliding
  carried the load-proportional loss. The effective coefficient μ_eff = E2_k / Σ(q |v|)/ω is the μ a
  Coulomb reading of E2 would need (≈ 0.3, beyond lubricated steel).
* :func:`reading_table` — the documented readings of μ_ij
  (:data:`~bearingkit.papers.tian2025.friction_variants.SLIDING_READINGS`, each re-identified on run 1):
  their E2 relative to the default's and their error.

Nothing here is used by a validation case.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from bearingkit.analysis.friction.components import friction_torque
from bearingkit.analysis.solver.quasistatic import solve
from bearingkit.bearings.turntable import composite_turntable
from bearingkit.papers.tian2025 import friction as f
from bearingkit.papers.tian2025 import friction_variants as fv
from bearingkit.papers.tian2025 import validation as v000

__all__ = ["multiplier_scan", "reading_table"]


def _solved():
    t = np.array(v000.TABLE3)
    model = composite_turntable(
        clearance_axial_roller=t[:, 0] * 1e-6, clearance_axial_ball=t[:, 1] * 1e-6, groove_curvature=t[:, 2]
    )
    return solve(model, f._table3_loads()), t[:, 4] / 1e3


#: The reading these diagnostics scan: no roller sliding term (the model before issue 32).
BASE = "viscous_only"


def _components(res, viscosity_factor, **op):
    point = dataclasses.replace(f.operating_point(BASE, viscosity_factor=viscosity_factor), **op)
    return friction_torque(res, point).components


def multiplier_scan(multipliers=(1.0, 2.0, 3.0, 4.0, 4.5)):
    """Table 3 with E2 × k and the viscosity factor recalibrated on run 1, for each k.

    Returns
    -------
    pandas.DataFrame
        ``k``, ``viscosity_factor`` (NaN where run 1 cannot be met: E2 alone exceeds it), ``rms_error``
        and ``max_error`` over runs 1–9 [1], ``e2_share_run1`` [1], ``mu_effective`` (E2_k over the
        Coulomb E2 with μ = 1, run 1) [1].
    """
    import pandas as pd
    from scipy.optimize import brentq

    res, pub = _solved()
    unit = _components(res, f.calibrated_factor(fv.VARIANTS[BASE]), mu_boundary=1.0, mu_ehl=1.0)[
        "differential_sliding"
    ]

    def total(vf, k):
        c = _components(res, vf)
        return sum(c.values()) + (k - 1.0) * c["differential_sliding"], c

    rows = []
    for k in multipliers:
        try:
            vf = brentq(lambda x, k=k: total(x, k)[0][0] - pub[0], 0.01, 50.0, xtol=1e-5)
        except ValueError:
            rows.append(dict(k=k, viscosity_factor=np.nan, rms_error=np.nan, max_error=np.nan))
            continue
        tot, c = total(vf, k)
        err = tot / pub - 1.0
        e2 = k * c["differential_sliding"]
        rows.append(
            dict(
                k=k,
                viscosity_factor=vf,
                rms_error=float(np.sqrt(np.mean(err**2))),
                max_error=float(np.abs(err).max()),
                e2_share_run1=float(e2[0] / tot[0]),
                mu_effective=float(e2[0] / unit[0]),
            )
        )
    return pd.DataFrame(rows)


def reading_table(readings=None):
    """E2 and Table 3 under each documented reading of μ_ij, recalibrated on run 1.

    Parameters
    ----------
    readings : sequence of str or None
        Keys of :data:`~bearingkit.papers.tian2025.friction_variants.SLIDING_READINGS` (None: all).

    Returns
    -------
    pandas.DataFrame
        ``reading``, ``viscosity_factor``, ``e2_run1_Nm``, ``e2_factor`` (E2 over today's at run 1, both
        recalibrated), ``rms_error``, ``max_error`` [1].
    """
    import pandas as pd

    rows = []
    base_e2 = None
    for name in readings or fv.SLIDING_READINGS:
        variant = fv.FrictionVariant(f"scan_{name}", sliding=name, viscosity_factor=None, roller_sliding=0.0)
        t = f.table3(variant)
        e2 = float(t["differential_sliding_Nm"].iloc[0])
        base_e2 = e2 if base_e2 is None and name == "mixed" else base_e2
        rows.append(
            dict(
                reading=name,
                viscosity_factor=f.calibrated_factor(variant),
                e2_run1_Nm=e2,
                rms_error=float(np.sqrt(np.mean(t["rel_error"] ** 2))),
                max_error=float(np.abs(t["rel_error"]).max()),
            )
        )
    out = pd.DataFrame(rows)
    if base_e2 is not None:
        out["e2_factor"] = out["e2_run1_Nm"] / base_e2
    return out
