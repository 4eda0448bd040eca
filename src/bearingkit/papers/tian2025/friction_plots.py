"""Figures of the seed-000 friction studies (Tian et al. 2025, Figs. 12-18): torque breakdowns, maps.

SI values in, engineering units on the axes (N·m, kN, µm). Written by
:func:`bearingkit.papers.tian2025.friction.run_all`.
"""

from __future__ import annotations

import numpy as np

from bearingkit.analysis.friction.components import COMPONENT_NAMES

# --- plots -------------------------------------------------------------------------------------------------
_LABELS = {
    "hysteresis_roller": "roller hysteresis (E11)",
    "hysteresis_ball": "ball hysteresis (M12)",
    "differential_sliding": "differential sliding (E2)",
    "viscous_roller": "roller EHL viscous (E31)",
    "viscous_ball": "ball EHL viscous (M32)",
    "spin_ball": "ball spin (M4)",
    "cage": "cage (M5)",
    "roller_sliding": "roller sliding (identified)",
}


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _stack(ax, x, table, categorical=False):
    """Stacked components of the torque (N·m) on ``ax``."""
    bottom = np.zeros(len(table))
    pos = np.arange(len(table)) if categorical else np.asarray(x, float)
    for name in COMPONENT_NAMES:
        val = table[f"{name}_Nm"].to_numpy()
        if categorical:
            ax.bar(pos, val, bottom=bottom, label=_LABELS[name])
        else:
            ax.fill_between(pos, bottom, bottom + val, label=_LABELS[name], alpha=0.8)
        bottom = bottom + val
    if categorical:
        ax.set_xticks(pos, list(x))
    ax.set_ylabel("friction torque by component [N·m]")
    ax.legend(fontsize=7, loc="upper left")
    ax.grid(True, alpha=0.3)


def plot_study(table, x, xlabel, title, path, stress=False, categorical=False, group=None):
    """Two panels: total torque (and max contact stress) vs ``x``; stacked components (PNG)."""
    plt = _pyplot()
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
    groups = table.groupby(group, sort=False) if group else [(None, table)]
    for key, grp in groups:
        xs = np.arange(len(grp)) if categorical else grp[x]
        lab = "total" if key is None else f"{group} = {key}"
        ax.plot(xs, grp["total_Nm"], marker="o", label=lab)
    if categorical:
        ax.set_xticks(np.arange(len(table)), list(table[x]))
    ax.set(xlabel=xlabel, ylabel="friction torque [N·m]", title=title)
    ax.grid(True, alpha=0.3)
    if stress:
        sx = ax.twinx()
        xs = np.arange(len(table)) if categorical else table[x]
        sx.plot(xs, table["max_pressure_ball_Pa"] / 1e9, "s--", color="tab:red", label="max stress, balls")
        sx.plot(
            xs, table["max_pressure_roller_Pa"] / 1e9, "^--", color="tab:purple", label="max stress, rollers"
        )
        sx.set_ylabel("max contact stress [GPa]")
        sx.legend(fontsize=7, loc="lower right")
    ax.legend(fontsize=7, loc="upper left")
    first = table if group is None else next(iter(table.groupby(group, sort=False)))[1]
    _stack(bx, first[x], first, categorical)
    bx.set_xlabel(xlabel + ("" if group is None else f"  ({group} = {table[group].iloc[0]})"))
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_clearance_map(table, path):
    """Total torque vs ball clearance per roller clearance, and the breakdown at roller clearance 0 (PNG)."""
    t = table.assign(
        ball_clearance_um=table["ball_clearance_m"] * 1e6,
        roller_clearance_um=table["roller_clearance_m"] * 1e6,
    )
    plot_study(
        t,
        "ball_clearance_um",
        "axial ball clearance [µm]",
        "Fig. 14: F_a = 5 kN, 5 r/min",
        path,
        group="roller_clearance_um",
    )


def plot_composite_vs_yrt(table, path):
    """Composite vs YRT total torque and the two breakdowns by row (PNG)."""
    plt = _pyplot()
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.2))
    for name, grp in table.groupby("bearing", sort=False):
        ax.plot(grp["axial_load_N"] / 1e3, grp["total_Nm"], marker="o", label=name)
    ax.set(
        xlabel="axial load F_a [kN]",
        ylabel="friction torque [N·m]",
        title="Fig. 10: composite vs YRT, 5 r/min",
    )
    ax.grid(True, alpha=0.3)
    ax.legend()
    rows = [c for c in table.columns if c.startswith("row_") and c.endswith("_Nm")]
    for (name, grp), style in zip(table.groupby("bearing", sort=False), ("-", "--"), strict=False):
        for c in rows:
            if grp[c].abs().sum() > 0:
                bx.plot(grp["axial_load_N"] / 1e3, grp[c], style, marker=".", label=f"{name}: {c[4:-3]}")
    bx.set(xlabel="axial load F_a [kN]", ylabel="friction torque by row [N·m]")
    bx.grid(True, alpha=0.3)
    bx.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
