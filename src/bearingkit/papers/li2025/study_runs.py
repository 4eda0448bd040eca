"""The clearance map of the ball–column bearing of Li et al. (2025): roller share of the radial load.

SI units (m, N). ``examples/studies/seed002_clearance_map.toml``.
"""

from __future__ import annotations

from bearingkit.studies.run.cases import StudyResult

#: Columns of the generic evaluator's study (paths into ball_column_condition1.toml) → short names.
GENERIC_COLUMNS = {
    "geometry.clearance_ball": "clearance_ball",
    "geometry.clearance_roller": "clearance_roller",
    "load_cases.condition1.F_x": "radial_load",
    "roller_2_radial_share": "roller_radial_share",
}


def seed002_clearance_map(result: StudyResult):
    """Pivot a ``seed002_clearance_map`` result: one row per (ball, roller) clearance, one share column
    per radial load (``roller_share_<load in N>N``), plus ``gradient`` = heavy − light share.

    Reads the study of ``examples/studies/seed002_clearance_map.toml`` (the generic evaluator: paths as
    column names) or one run on the ``seed002_clearance`` evaluator (short names)."""
    results = result.results
    if "roller_radial_share" not in results:
        results = results.rename(columns=GENERIC_COLUMNS)
    table = results.pivot_table(
        index=["clearance_ball", "clearance_roller"], columns="radial_load", values="roller_radial_share"
    )
    loads = sorted(table.columns)
    table.columns = [f"roller_share_{f:.0f}N" for f in table.columns]
    table = table.reset_index()
    table["gradient"] = table[f"roller_share_{loads[-1]:.0f}N"] - table[f"roller_share_{loads[0]:.0f}N"]
    return table


def plot_clearance_map(table, path):
    """Heat maps of the roller share at each load over ball × roller clearance [µm] (PNG)."""
    from bearingkit.studies.results.analysis import _plt

    plt = _plt()
    cols = [c for c in table.columns if c.startswith("roller_share_")]
    fig, axes = plt.subplots(1, len(cols), figsize=(5 * len(cols), 4), squeeze=False)
    for ax, col in zip(axes[0], cols, strict=True):
        grid = table.pivot(index="clearance_roller", columns="clearance_ball", values=col)
        im = ax.imshow(grid.to_numpy(), origin="lower", vmin=0.0, vmax=1.0, aspect="auto", cmap="viridis")
        ax.set_xticks(range(grid.shape[1]), [f"{v * 1e6:g}" for v in grid.columns])
        ax.set_yticks(range(grid.shape[0]), [f"{v * 1e6:g}" for v in grid.index])
        ax.set(xlabel="ball-row clearance [µm]", ylabel="roller-row clearance [µm]", title=col)
        fig.colorbar(im, ax=ax, label="roller share of F_r [–]")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
