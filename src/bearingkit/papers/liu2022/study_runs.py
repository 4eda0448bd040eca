"""The roller-diameter scatter Monte Carlo of Liu et al. (2022), one run per S_d (common random numbers).

SI units (N, m). ``examples/studies/seed001_monte_carlo.toml``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from bearingkit.papers.examples import example, resized
from bearingkit.studies.definition.load import load_study
from bearingkit.studies.run.runner import run_study


def seed001_monte_carlo(magnitudes=None, *, samples=None, store_dir=None, executor=None, progress=False):
    """Run ``seed001_monte_carlo.toml`` once per S_d with the same unit draws (common random numbers).

    Parameters
    ----------
    magnitudes : sequence of float [m] or None
        S_d values (default seed 001's 0.5, 1, 1.5 µm).
    samples : int or None
        Realisations per S_d (default the file's).
    store_dir : path or None
        Parquet stores ``<store_dir>/sd_<S_d in nm>`` (resumable); None keeps results in memory.

    Returns
    -------
    DataFrame
        Every realisation of every S_d: the study's results plus ``magnitude_m``.
    """
    import pandas as pd

    from bearingkit.analysis.friction.tapered import SEED001_MAGNITUDES

    mags = SEED001_MAGNITUDES if magnitudes is None else tuple(float(m) for m in magnitudes)
    base = load_study(example("seed001_monte_carlo"))
    frames = []
    for m in mags:
        d = resized(base, samples=samples, fixed={"magnitude": m})
        d = d.model_copy(update={"name": f"{base.name}_sd{m * 1e9:.0f}nm"})
        store = None if store_dir is None else Path(store_dir) / f"sd_{m * 1e9:.0f}nm"
        res = run_study(d, executor=executor, store=store, progress=progress)
        frames.append(res.results.assign(magnitude_m=m))
    return pd.concat(frames, ignore_index=True)


def seed001_summary(realisations):
    """Distribution of the max contact force and of the sliding-friction increment per S_d.

    Returns one row per ``magnitude_m``: count, converged fraction, mean/std/5th/50th/95th percentile/max
    of ``max_contact_force_N`` and ``sliding_increment_N``, mean of ``sliding_increment_ratio``.
    """
    import pandas as pd

    rows = []
    for m, g in realisations.groupby("magnitude_m", sort=True):
        row = {"magnitude_m": m, "n_realisations": len(g), "converged_fraction": g["converged"].mean()}
        for col in ("max_contact_force_N", "sliding_increment_N"):
            v = g[col].to_numpy(float)
            stem = col.removesuffix("_N")
            row.update(
                {
                    f"{stem}_mean_N": v.mean(),
                    f"{stem}_std_N": v.std(ddof=1) if v.size > 1 else 0.0,
                    f"{stem}_p05_N": np.percentile(v, 5),
                    f"{stem}_p50_N": np.percentile(v, 50),
                    f"{stem}_p95_N": np.percentile(v, 95),
                    f"{stem}_max_N": v.max(),
                }
            )
        row["ideal_max_contact_force_N"] = g["ideal_max_contact_force_N"].iloc[0]
        row["ideal_max_sliding_inner_N"] = g["ideal_max_sliding_inner_N"].iloc[0]
        row["sliding_increment_ratio_mean"] = g["sliding_increment_ratio"].mean()
        rows.append(row)
    return pd.DataFrame(rows)


def plot_seed001(realisations, path):
    """Histograms of the max contact force and of the sliding increment, one colour per S_d (PNG)."""
    from bearingkit.studies.results.analysis import _plt

    plt = _plt()
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for m, g in realisations.groupby("magnitude_m", sort=True):
        lab = f"S_d = {m * 1e6:g} µm"
        axes[0].hist(g["max_contact_force_N"], bins=40, alpha=0.5, label=lab)
        axes[1].hist(g["sliding_increment_N"], bins=40, alpha=0.5, label=lab)
    axes[0].set(xlabel="max roller–cup contact force [N]", ylabel="realisations")
    axes[1].set(xlabel="increment of max cone sliding friction [N]", ylabel="realisations")
    for ax in axes:
        ax.legend()
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
