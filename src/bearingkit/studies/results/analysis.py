"""Analysis of designed experiments: main effects, range analysis (sensitivity ranking), interactions.

SI units: the response keeps the unit of its column; level values are the factors' SI values.

Range analysis (Taguchi; the method of seed 000 §6.2): for factor j at level i, the level mean

.. math:: \\bar k_{ij} = \\frac{1}{n_{ij}} \\sum_{r:\\,x_{rj} = i} y_r

and the range R_j = max_i k̄_ij − min_i k̄_ij; factors are ranked by decreasing R_j. In a balanced
(orthogonal) design the level means of one factor average out every other factor's main effect, so
for an additive model y = μ + Σ_j a_j(x_j) the range equals the spread of a_j exactly
(Taguchi 1987; Phadke 1989 ch. 3).

Levels × samples designs (:func:`point_statistics`): at every design point p the N draws of an output
y give the sample mean ȳ_p, the sample standard deviation s_p (ddof = 1), the extremes and the
requested quantiles (linear interpolation between order statistics, numpy/pandas' default). The
range analysis of ȳ_p ranks the factors' effect on the mean; that of s_p their effect on the scatter
(Taguchi's dispersion effects, Phadke 1989 ch. 5).
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


def quantile_label(q: float) -> str:
    """Column suffix of a quantile: 0.05 → ``q5``, 0.5 → ``q50``, 0.025 → ``q2.5``."""
    return f"q{100.0 * float(q):.6g}"


def point_statistics(results, outputs: Sequence[str], quantiles: Sequence[float] = (0.05, 0.5, 0.95)):
    """Statistics of each output over the draws of every design point (levels × samples studies).

    Parameters
    ----------
    results : DataFrame
        One row per case with a ``point`` column and the output columns.
    outputs : sequence of str
        Output columns. Numeric ones get ``<out>_mean``, ``_std`` (sample, ddof = 1; NaN for one
        draw), ``_min``, ``_max`` and ``_q<percent>`` per quantile; boolean ones (flags such as
        ``converged``) get ``<out>_fraction`` (share of True). NaN draws are left out.
    quantiles : sequence of float
        Probabilities in (0, 1).

    Returns
    -------
    DataFrame
        One row per ``point`` (ascending): ``point``, ``n_draws``, then the statistics.
    """
    import pandas as pd

    g = results.groupby("point", sort=True)
    flags = [o for o in outputs if pd.api.types.is_bool_dtype(results[o])]
    numeric = [o for o in outputs if o not in flags and pd.api.types.is_numeric_dtype(results[o])]
    count = g.size()
    cols = {"point": count.index.to_numpy(), "n_draws": count.to_numpy()}
    if numeric:
        x = results[["point", *numeric]].astype({o: float for o in numeric}).groupby("point", sort=True)
        stats = {"mean": x.mean(), "std": x.std(ddof=1), "min": x.min(), "max": x.max()}
        for q in quantiles:
            stats[quantile_label(q)] = x.quantile(float(q))
        for o in numeric:  # columns grouped by output: mean, std, min, max, quantiles
            for name, frame in stats.items():
                cols[f"{o}_{name}"] = frame[o].to_numpy()
    if flags:
        share = g[flags].mean()
        for o in flags:
            cols[f"{o}_fraction"] = share[o].to_numpy()
    return pd.DataFrame(cols)


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


def _tick(v) -> str:
    return f"{v:.4g}" if isinstance(v, (float, np.floating)) else str(v)


def plot_main_effects(
    effects, path, response: str = "response", labels: dict | None = None, dimensions: dict | None = None
):
    """Main-effect plot: one panel per factor, level mean vs level value (PNG).

    Panels are titled by the factor NAME (its short label, if any, in parentheses); level values and
    the response are shown in display units (:mod:`bearingkit.studies.results.display`): ``dimensions`` maps a
    factor to its physical dimension; the response's unit comes from its name (``…_N``, ``…_m``).
    Returns (title, x label, tick labels) of every panel.
    """
    from bearingkit.studies.results import display

    plt = _plt()
    factors = list(dict.fromkeys(effects["factor"]))
    means, ylabel = display.display(response, effects["mean"].to_numpy(float))
    fig, axes = plt.subplots(1, len(factors), figsize=(3.4 * len(factors), 3.4), sharey=True, squeeze=False)
    for ax, f in zip(axes[0], factors, strict=True):
        mask = (effects["factor"] == f).to_numpy()
        sub = effects[mask].sort_values("level")
        order = np.argsort(effects[mask]["level"].to_numpy(), kind="stable")
        values = sub["value"].to_numpy()
        dim = (dimensions or {}).get(f)
        numeric = dim not in (None, "text", "count", "flag") and np.issubdtype(
            np.asarray(values).dtype, np.number
        )
        unit = ""
        if numeric:
            label, factor = display.scale_for(display.column_unit(f, dim), values)
            values, unit = values.astype(float) * factor, label
        ax.plot(range(1, len(sub) + 1), means[mask][order], marker="o")
        ax.set_xticks(range(1, len(sub) + 1), [_tick(v) for v in values])
        short = (labels or {}).get(f)
        title = f if not short or short == f else f"{f} ({short})"
        ax.set_title(title, fontsize=8)
        ax.set_xlabel(f"level [{unit}]" if unit else "level", fontsize=8)
        ax.grid(True, alpha=0.3)
    axes[0][0].set_ylabel(f"mean {ylabel}")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    shown = [
        (ax.get_title(), ax.get_xlabel(), [t.get_text() for t in ax.get_xticklabels()]) for ax in axes[0]
    ]
    plt.close(fig)
    return shown


def plot_range(ranges, path, response: str = "response"):
    """Bar chart of the ranges R_j, factors (by name) in rank order, in the response's display unit (PNG)."""
    from bearingkit.studies.results import display

    plt = _plt()
    values, ylabel = display.display(response, ranges["range"].to_numpy(float))
    fig, ax = plt.subplots(figsize=(max(5.0, 1.3 * len(ranges) + 1.5), 3.6))
    ax.bar(range(len(ranges)), values)
    ax.set_xticks(range(len(ranges)), ranges["factor"].astype(str), rotation=20, ha="right", fontsize=8)
    ax.set(ylabel=f"range of mean {ylabel}", title="sensitivity (range analysis)")
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


def plot_point_statistics(table, response: str, path, quantiles: Sequence[float] = (0.05, 0.95)):
    """Mean of ``response`` per design point with a band between two quantiles, display units (PNG)."""
    from bearingkit.studies.results import display

    plt = _plt()
    fig, ax = plt.subplots(figsize=(max(4.0, 0.45 * len(table) + 2.0), 3.4))
    x = table["point"].to_numpy()
    q_lo, q_hi = quantile_label(min(quantiles)), quantile_label(max(quantiles))
    lo, hi = f"{response}_{q_lo}", f"{response}_{q_hi}"
    mean = table[f"{response}_mean"].to_numpy(float)
    label, factor = display.scale_for(display.column_unit(response), mean)
    if lo in table.columns and hi in table.columns:
        ax.fill_between(
            x, table[lo] * factor, table[hi] * factor, alpha=0.25, step="mid", label=f"{q_lo}–{q_hi}"
        )
    ax.plot(x, mean * factor, marker="o", label="mean")
    ylabel = display.axis_label(response, label)
    ax.set(xlabel="design point", ylabel=ylabel, title="statistics per design point")
    ax.set_xticks(x)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
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
