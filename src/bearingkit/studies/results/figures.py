"""The plots a study file asks for in ``[[plots]]``: lines, maps, scatter and histograms of its results.

SI in (the results table); every axis shows a factor or output NAME with its display unit
(:mod:`bearingkit.studies.results.display`: µm, kN, MPa, r/min, 10⁶ rev …), never raw SI numbers.

Kinds (``kind``):

- ``lines`` — ``y`` against ``x``, one line per value of ``series`` (e.g. max load vs radial load, a
  line per clearance): one panel per ``y``;
- ``map`` — ``y`` over the grid of ``x`` × ``series`` (a factorial of two factors), one cell per
  design point, with contour lines of continuous outputs;
- ``scatter`` — ``y`` against ``x`` point by point (e.g. life against a sampled clearance);
- ``histogram`` — the distribution of ``y`` over the cases (Monte Carlo), with its quantiles marked.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from bearingkit.studies.results import display

__all__ = ["KINDS", "plot"]

#: Plot kinds of ``[[plots]]``.
KINDS = ("lines", "map", "scatter", "histogram")


def _plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _shown(results, name: str, dimensions: Mapping[str, str]):
    values = results[name].to_numpy()
    if values.dtype == bool:
        values = values.astype(float)
    return display.display(name, values.astype(float), dimensions.get(name))


def plot(
    spec,
    results,
    path,
    dimensions: Mapping[str, str] | None = None,
    quantiles: Sequence[float] = (0.05, 0.5, 0.95),
) -> list[tuple[str, str]]:
    """Draw one ``[[plots]]`` entry of a study into a PNG file.

    Parameters
    ----------
    spec : PlotDef
        ``kind``, ``x``, ``y`` (tuple), ``series``, ``title``, ``log_y`` (true, or the outputs whose
        panels have a logarithmic axis).
    results : DataFrame
        The study's results (factors and outputs, SI).
    path : path
        PNG file.
    dimensions : mapping, optional
        Factor name → physical dimension (outputs carry their unit in their name).
    quantiles : sequence of float
        Marked on histograms.

    Returns
    -------
    list of (str, str)
        The x and y axis labels of every panel.
    """
    plt = _plt()
    dims = dict(dimensions or {})
    ys = list(spec.y)
    fig, axes = plt.subplots(1, len(ys), figsize=(4.6 * len(ys) + 0.6, 3.8), squeeze=False)
    for ax, y in zip(axes[0], ys, strict=True):
        yv, ylabel = _shown(results, y, dims)
        if spec.kind == "histogram":
            finite = yv[np.isfinite(yv)]
            ax.hist(finite, bins=max(10, min(60, int(np.sqrt(max(len(finite), 1))))), color="C0", alpha=0.75)
            for q in quantiles:
                if len(finite):
                    v = float(np.quantile(finite, q))
                    ax.axvline(v, color="C3", lw=1, ls="--")
                    ax.annotate(f"q{100 * q:g}", (v, 0.95), xycoords=("data", "axes fraction"), fontsize=7)
            ax.set(xlabel=ylabel, ylabel="cases")
        else:
            xv, xlabel = _shown(results, spec.x, dims)
            if spec.kind == "scatter":
                ax.plot(xv, yv, ".", ms=3, alpha=0.6)
            elif spec.kind == "lines":
                _lines(ax, results, xv, yv, spec.series, dims)
            else:
                _map(fig, ax, results, xv, yv, spec.series, dims, ylabel)
            if spec.kind == "map":
                ax.set(xlabel=xlabel, ylabel=_shown(results, spec.series, dims)[1])
                ax.set_title(ylabel, fontsize=9)
            else:
                ax.set(xlabel=xlabel, ylabel=ylabel)
        if spec.logarithmic(y) and spec.kind in ("lines", "scatter"):
            ax.set_yscale("log")
        ax.grid(True, alpha=0.3)
    if spec.title:
        fig.suptitle(spec.title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    labels = [(ax.get_xlabel(), ax.get_ylabel()) for ax in axes[0]]
    plt.close(fig)
    return labels


def _lines(ax, results, xv, yv, series, dims) -> None:
    if series is None:
        order = np.argsort(xv, kind="stable")
        ax.plot(xv[order], yv[order], marker="o", ms=3)
        return
    sv, slabel = _shown(results, series, dims)
    raw = results[series].to_numpy()
    for value in dict.fromkeys(raw.tolist()):
        mask = raw == value
        order = np.argsort(xv[mask], kind="stable")
        shown = sv[mask][0]
        ax.plot(xv[mask][order], yv[mask][order], marker="o", ms=3, label=f"{shown:.4g}")
    ax.legend(title=slabel, fontsize=7, title_fontsize=7)


def _map(fig, ax, results, xv, yv, series, dims, ylabel) -> None:
    sv, _ = _shown(results, series, dims)
    xs, ss = np.unique(xv), np.unique(sv)
    if xs.size < 2 or ss.size < 2:  # no area to fill: one line per value
        _lines(ax, results, xv, yv, series, dims)
        return
    grid = np.full((ss.size, xs.size), np.nan)
    grid[np.searchsorted(ss, sv), np.searchsorted(xs, xv)] = yv
    # one cell per design point (the values computed, nothing interpolated); contour lines on top of
    # continuous outputs only (counts and flags change in steps)
    cells = ax.pcolormesh(xs, ss, grid, shading="nearest", cmap="viridis")
    finite = grid[np.isfinite(grid)]
    if finite.size and not np.allclose(finite, np.round(finite)) and np.ptp(finite) > 0:
        lines = ax.contour(xs, ss, grid, levels=7, colors="k", linewidths=0.5)
        ax.clabel(lines, fontsize=6, fmt="%.3g")
    fig.colorbar(cells, ax=ax, label=ylabel)
