"""Seed-000 statics: how the axial load splits between balls and rollers (Tian et al. 2025, §6.1.1, §6.1.3).

SI units. Two studies of the ball–roller composite turntable bearing, each returning a tidy
:class:`pandas.DataFrame` (one line per case, SI columns with units in their names):

- :func:`clearance_map` — axial roller clearance × axial ball clearance at F_a = 5 kN;
- :func:`eccentricity_sweep` — F_a = F_r = 3 kN applied at eccentricity 0–0.6 m (M_y = −e·F_a).

``python -m bearingkit.papers.tian2025.statics OUT_DIR`` writes both tables (CSV) and their plots (PNG).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings.common import eccentric_axial_load
from bearingkit.bearings.turntable import composite_turntable

#: Seed 000 §6.1.1 ball clearance range 0 … −6 µm [m] and §6.1.3 eccentricities 0 … 0.6 m [m].
BALL_CLEARANCES = tuple(np.linspace(0.0, -6e-6, 7))
ECCENTRICITIES = tuple(np.linspace(0.0, 0.6, 7))
ROWS = ("roller_upper", "ball_upper", "roller_lower", "ball_lower", "roller_radial")


def _row_table(result, extra: dict) -> dict:
    out = dict(extra)
    for name in ROWS:
        out[f"{name}_axial_N"] = np.abs(result.row_load(name)[:, 2])
        out[f"{name}_max_load_N"] = result.row(name).max_load
        out[f"{name}_loaded_count"] = result.row(name).loaded_count
        out[f"{name}_max_pressure_Pa"] = result.row(name).max_pressure.max(axis=-1)
    balls = out["ball_upper_axial_N"] + out["ball_lower_axial_N"]
    rollers = out["roller_upper_axial_N"] + out["roller_lower_axial_N"]
    out["ball_axial_share"] = balls / (balls + rollers)
    out["u_z_m"] = result.displacement[:, 2]
    out["theta_y_rad"] = result.displacement[:, 4]
    out["converged"] = result.converged
    return out


def clearance_map(
    roller_clearances=(0.0, -1e-6, -2e-6),
    ball_clearances=BALL_CLEARANCES,
    axial_load: float = 5000.0,
    **geometry,
):
    """Axial load share of balls and rollers over a grid of axial clearances (seed 000 §6.1.1).

    Each combination is a different geometry; the grid is solved as one batch (geometry arrays with a
    leading case axis).

    Parameters
    ----------
    roller_clearances, ball_clearances : sequence of float [m]
        Axial clearances of the roller rows and ball rows (negative = preload).
    axial_load : float [N]
    geometry : dict
        Further overrides of :class:`~bearingkit.bearings.turntable.CompositeTurntableGeometry`.
    """
    import pandas as pd

    rc, bc = np.meshgrid(
        np.asarray(roller_clearances, float), np.asarray(ball_clearances, float), indexing="ij"
    )
    rc, bc = rc.ravel(), bc.ravel()
    model = composite_turntable(clearance_axial_roller=rc, clearance_axial_ball=bc, **geometry)
    res = solve(model, np.repeat(load_vector(F_z=axial_load)[None], rc.size, axis=0))
    return pd.DataFrame(_row_table(res, {"roller_clearance_m": rc, "ball_clearance_m": bc}))


def eccentricity_sweep(
    eccentricities=ECCENTRICITIES,
    axial_load: float = 3000.0,
    radial_load: float = 3000.0,
    clearance_axial_roller: float = -1e-6,
    clearance_axial_ball: float = -5e-6,
    **geometry,
):
    """Row loads vs load eccentricity (seed 000 §6.1.3: F_a = F_r = 3 kN, e = 0–0.6 m).

    Parameters
    ----------
    eccentricities : sequence of float [m]
    axial_load, radial_load : float [N]
    clearance_axial_roller, clearance_axial_ball : float [m]
    """
    import pandas as pd

    e = np.asarray(eccentricities, float)
    model = composite_turntable(
        clearance_axial_roller=clearance_axial_roller, clearance_axial_ball=clearance_axial_ball, **geometry
    )
    res = solve(model, eccentric_axial_load(axial_load, e, radial_load))
    return pd.DataFrame(_row_table(res, {"eccentricity_m": e, "moment_Nm": e * axial_load}))


def plot_clearance_map(table, path):
    """Ball share of the axial load vs ball clearance, one line per roller clearance (PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for rc, grp in table.groupby("roller_clearance_m"):
        label = f"roller clearance {rc * 1e6:+.0f} µm"
        axes[0].plot(grp["ball_clearance_m"] * 1e6, grp["ball_axial_share"], marker="o", label=label)
        axes[1].plot(grp["ball_clearance_m"] * 1e6, grp["roller_lower_axial_N"], marker="o", label=label)
    axes[0].set(xlabel="axial ball clearance [µm]", ylabel="share of F_a carried by balls [–]")
    axes[1].set(xlabel="axial ball clearance [µm]", ylabel="lower roller row axial load [N]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.suptitle("Seed 000 composite bearing, F_a = 5 kN")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_eccentricity(table, path):
    """Max element load of each row vs eccentricity (PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 4))
    for name in ROWS:
        ax.plot(table["eccentricity_m"], table[f"{name}_max_load_N"], marker="o", label=name)
    ax.set(
        xlabel="eccentricity of F_a [m]",
        ylabel="max element load [N]",
        title="Seed 000, F_a = F_r = 3 kN, M = e·F_a",
    )
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None) -> int:
    out = Path((argv or sys.argv[1:] or ["out/seed000"])[0])
    out.mkdir(parents=True, exist_ok=True)
    cmap = clearance_map()
    ecc = eccentricity_sweep()
    cmap.to_csv(out / "clearance_map.csv", index=False)
    ecc.to_csv(out / "eccentricity_sweep.csv", index=False)
    plot_clearance_map(cmap, out / "clearance_map.png")
    plot_eccentricity(ecc, out / "eccentricity_sweep.png")
    print(f"wrote {out}/clearance_map.(csv|png), {out}/eccentricity_sweep.(csv|png)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
