"""Analysis of designed experiments: main effects, range analysis (sensitivity ranking), interactions.

SI units: the response keeps the unit of its column; level values are the factors' SI values.

Range analysis (Taguchi; the method of seed 000 §6.2): for factor j at level i, the level mean

.. math:: \\bar k_{ij} = \\frac{1}{n_{ij}} \\sum_{r:\\,x_{rj} = i} y_r

and the range R_j = max_i k̄_ij − min_i k̄_ij; factors are ranked by decreasing R_j. In a balanced
(orthogonal) design the level means of one factor average out every other factor's main effect, so
for an additive model y = μ + Σ_j a_j(x_j) the range equals the spread of a_j exactly
(Taguchi 1987; Phadke 1989 ch. 3).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np


def main_effects(results, factors: Sequence[str], response: str):
    """Mean response at each level of each factor.

    Returns
    -------
    DataFrame
        Columns ``factor``, ``level`` (1-based, in the order of first appearance sorted by value),
        ``value`` (the factor's SI value), ``mean``, ``count``.
    """
    import pandas as pd

    rows = []
    for f in factors:
        level_col = f"level_{f}"
        if level_col in results.columns:
            g = results.groupby(level_col, sort=True)
            for lev, grp in g:
                rows.append(
                    {
                        "factor": f,
                        "level": int(lev),
                        "value": grp[f].iloc[0],
                        "mean": grp[response].mean(),
                        "count": len(grp),
                    }
                )
        else:
            for k, (val, grp) in enumerate(results.groupby(f, sort=True)):
                rows.append(
                    {
                        "factor": f,
                        "level": k + 1,
                        "value": val,
                        "mean": grp[response].mean(),
                        "count": len(grp),
                    }
                )
    return pd.DataFrame(rows)


def range_analysis(results, factors: Sequence[str], response: str, labels: dict | None = None):
    """Range analysis: level means k̄_i, range R = max − min, and the sensitivity rank (1 = largest R).

    Returns
    -------
    DataFrame
        One row per factor: ``factor``, ``label``, ``k1`` … ``kn`` (level means), ``range``, ``rank``,
        ``best_level`` (level of the smallest mean, for a smaller-is-better response), sorted by rank.
    """
    import pandas as pd

    me = main_effects(results, factors, response)
    rows = []
    for f in factors:
        sub = me[me["factor"] == f].sort_values("level")
        row = {"factor": f, "label": (labels or {}).get(f, f)}
        for lev, mean in zip(sub["level"], sub["mean"], strict=True):
            row[f"k{lev}"] = mean
        row["range"] = sub["mean"].max() - sub["mean"].min()
        row["best_level"] = int(sub["level"].iloc[int(np.argmin(sub["mean"].to_numpy()))])
        rows.append(row)
    out = pd.DataFrame(rows)
    out["rank"] = out["range"].rank(ascending=False, method="min").astype(int)
    return out.sort_values("rank", kind="stable").reset_index(drop=True)


def sensitivity_ranking(results, factors: Sequence[str], response: str) -> list[str]:
    """Factor names from the most to the least influential (by range)."""
    return list(range_analysis(results, factors, response)["factor"])


def interaction_table(results, factor_a: str, factor_b: str, response: str):
    """Mean response for each combination of two factors' levels (rows: a, columns: b).

    In an L9 the two-factor cells hold one run each: the table then shows the raw responses and the
    interaction is confounded with the other columns (Phadke 1989 §7.3); a full factorial separates it.
    """
    return results.pivot_table(index=factor_a, columns=factor_b, values=response, aggfunc="mean")


def interaction_strength(results, factor_a: str, factor_b: str, response: str) -> float:
    """Root-mean-square departure of the two-factor cell means from additivity.

    .. math:: I = \\sqrt{\\overline{(\\bar y_{ij} - \\bar y_{i\\cdot} - \\bar y_{\\cdot j} + \\bar y)^2}}

    Zero for an additive model; meaningful on designs where every cell holds runs balanced over the
    other factors (full factorials).
    """
    t = interaction_table(results, factor_a, factor_b, response).to_numpy(float)
    resid = t - t.mean(axis=1, keepdims=True) - t.mean(axis=0, keepdims=True) + t.mean()
    return float(np.sqrt(np.nanmean(resid**2)))


# ------------------------------------------------------------------------------------------ plots
def _plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def plot_main_effects(effects, path, response: str = "response", labels: dict | None = None):
    """Main-effect plot: one panel per factor, level mean vs level value (PNG)."""
    plt = _plt()
    factors = list(dict.fromkeys(effects["factor"]))
    fig, axes = plt.subplots(1, len(factors), figsize=(3.2 * len(factors), 3.2), sharey=True, squeeze=False)
    for ax, f in zip(axes[0], factors, strict=True):
        sub = effects[effects["factor"] == f].sort_values("level")
        ax.plot(range(1, len(sub) + 1), sub["mean"], marker="o")
        ax.set_xticks(
            range(1, len(sub) + 1), [f"{v:.4g}" if isinstance(v, float) else str(v) for v in sub["value"]]
        )
        ax.set_title((labels or {}).get(f, f), fontsize=9)
        ax.grid(True, alpha=0.3)
    axes[0][0].set_ylabel(f"mean {response}")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_range(ranges, path, response: str = "response"):
    """Bar chart of the ranges R_j, factors in rank order (PNG)."""
    plt = _plt()
    fig, ax = plt.subplots(figsize=(5, 3.2))
    ax.bar(ranges["label"].astype(str), ranges["range"])
    ax.set(ylabel=f"range of mean {response}", title="sensitivity (range analysis)")
    ax.grid(True, axis="y", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_interaction(results, factor_a: str, factor_b: str, response: str, path):
    """Interaction plot: mean response vs factor a, one line per level of factor b (PNG)."""
    plt = _plt()
    t = interaction_table(results, factor_a, factor_b, response)
    fig, ax = plt.subplots(figsize=(5, 3.5))
    for col in t.columns:
        ax.plot(t.index, t[col], marker="o", label=f"{factor_b} = {col:.4g}")
    ax.set(xlabel=factor_a, ylabel=f"mean {response}")
    ax.legend(fontsize=8)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_pareto(front, objectives: Sequence[str], path, highlight=None):
    """Scatter of a 2-objective Pareto front (first two objectives), optional highlighted rows (PNG)."""
    plt = _plt()
    fig, ax = plt.subplots(figsize=(5, 4))
    a, b = objectives[0], objectives[1]
    ax.scatter(front[a], front[b], s=12, label="Pareto front")
    if highlight is not None and len(highlight):
        ax.scatter(highlight[a], highlight[b], s=60, marker="*", color="C3", label="selected")
        for _, r in highlight.iterrows():
            ax.annotate(str(r.get("selection", "")), (r[a], r[b]), fontsize=8)
    ax.set(xlabel=a, ylabel=b)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
