"""Figures of the HTML report, drawn for every bearing and load case: SVG (report/svg.py); the PNG
helpers serve the matplotlib figures of the other report modules (Agg backend, no pyplot global state).

SI inside: every function reads SI result arrays (N, Pa, m, rad, N·m) and converts only for the axis
labels (kN, MPa, mm, degrees, N·mm). Faces never recompute physics: these functions only read
:class:`~bearingkit.analysis.solver.quasistatic.QuasiStaticResult`,
:class:`~bearingkit.analysis.friction.components.FrictionResult` and
:class:`~bearingkit.analysis.rating.assembly.RatingResult`
objects. Each ``*_figure`` returns a :class:`~bearingkit.report.svg.SvgFigure` or a
:class:`matplotlib.figure.Figure` (or None when there is nothing to draw); :func:`data_uri` turns either
into an inline ``data:`` URI for an ``<img>``.

Figures:

- :func:`polar_load_figure` — element loads at their azimuth, one polar panel per row (SVG);
- :func:`slice_pressure_figure` — roller rows: contact pressure per element (azimuth) × slice (SVG);
- :func:`friction_figure` — friction torque by component and by row (SVG);
- :func:`rating_figure` — static safety s0 and ISO/TS 16281 life L10r per row (SVG).
"""

from __future__ import annotations

import base64
import io
import math

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from bearingkit.report import svg
from bearingkit.report.svg import SvgFigure

#: Resolution of the inline PNGs [dots per inch], the SVG figures' pixels per inch too; with the figure
#: widths below (≤ 11 in) the images stay ≤ 1100 px wide, the width of the report's text column.
DPI = svg.DPI
#: Width of a full-width figure [in].
FIGURE_WIDTH = 11.0
#: Polar panels per figure line.
POLAR_COLUMNS = 3
#: Colour map of loads and pressures (perceptually uniform, readable in grey scale).
COLORMAP = "viridis"
#: Static safety below which a row is drawn in the warning colour (ISO 76: s0 ≥ 1 required).
S0_REQUIRED = 1.0
_WARN, _OK, _NEUTRAL = "#c0392b", "#2e86c1", "#7f8c8d"


def _figure(width: float, height: float, top: float = 0.45, bottom: float = 0.55, **adjust) -> Figure:
    """A figure with fixed margins (``top``/``bottom`` in inches; constrained layout is ~2x slower)."""
    fig = Figure(figsize=(width, height), dpi=DPI)
    FigureCanvasAgg(fig)
    fig.subplots_adjust(top=1 - top / height, bottom=bottom / height, **adjust)
    return fig


def png_bytes(fig: Figure) -> bytes:
    """The figure as PNG bytes (no timestamp metadata, so equal figures give equal bytes)."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=DPI, metadata={"Software": None})
    return buf.getvalue()


def png_data_uri(fig: Figure) -> str:
    """``data:image/png;base64,…`` of the figure, for an inline ``<img src=…>``."""
    return "data:image/png;base64," + base64.b64encode(png_bytes(fig)).decode("ascii")


def data_uri(fig) -> str:
    """The inline ``data:`` URI of an SVG figure or a matplotlib one (PNG)."""
    return fig.data_uri() if isinstance(fig, SvgFigure) else png_data_uri(fig)


def _finite(a) -> np.ndarray:
    return np.nan_to_num(np.asarray(a, dtype=float), nan=0.0, posinf=0.0, neginf=0.0)


def polar_load_figure(result, case: int) -> SvgFigure:
    """Element loads Q [kN] at their azimuth, one polar panel per row (an SVG figure, report/svg.py).

    Parameters
    ----------
    result : QuasiStaticResult
        Solved cases; ``result.rows`` gives ``azimuth`` (C|1, Z) [rad] and ``load`` (C, Z) [N].
    case : int
        Case index.

    Notes
    -----
    ψ is measured from +x towards +y (design.md §3): 0° points right, angles grow counter-clockwise.
    Bar colour and length are the element load; unloaded elements show as a grey dot on the rim.
    """
    states = list(result.rows)
    n = len(states)
    cols = min(POLAR_COLUMNS, n)
    lines = math.ceil(n / cols)
    cell_w, cell_h, top = FIGURE_WIDTH * DPI / POLAR_COLUMNS, 3.6 * DPI, 0.4 * DPI
    fig = SvgFigure(cell_w * cols, top + cell_h * lines)
    for i, s in enumerate(states):
        psi = np.mod(np.broadcast_to(s.azimuth, s.load.shape)[case], 2 * np.pi)
        q = _finite(s.load[case]) / 1e3
        q_max = float(q.max()) if q.size else 0.0
        scale = q_max if q_max > 0 else 1.0
        loaded = int(np.count_nonzero(q > 0))
        centre = (cell_w * (i % cols + 0.5), top + cell_h * (i // cols) + 0.55 * cell_h)
        svg.polar_panel(
            fig,
            centre,
            min(0.5 * cell_w - 40, 0.5 * cell_h - 60),
            psi,
            q,
            scale=scale * 1.1,
            colors=svg.colour(COLORMAP, q / scale),
            title=[f"{s.name} ({s.kind})", f"{loaded}/{len(q)} loaded, Q_max = {q_max:.3g} kN"],
            unloaded_colour=_NEUTRAL,
        )
        if q_max <= 0:
            fig.text(*centre, "no loaded element", size=9, anchor="middle", color=_WARN)
    return fig


def _slice_pressure(state, case: int):
    """(pressure or load array (Z, n_s), label, scale) of a roller row; pressure when the row gives it."""
    ex = state.extras
    if "slice_pressure_inner" in ex or "slice_pressure_outer" in ex:
        parts = [_finite(ex[k][case]) for k in ("slice_pressure_inner", "slice_pressure_outer") if k in ex]
        return np.maximum.reduce(parts), "max. slice pressure (inner/outer) [MPa]", 1e-6
    return _finite(state.slice_load[case]), "slice load q [N]", 1.0


def roller_rows(result) -> list:
    """Row states with at least two slices per roller (``slice_load`` (C, Z, n_s ≥ 2))."""
    return [s for s in result.rows if s.slice_load is not None and s.slice_load.shape[-1] >= 2]


def _edges(centres: np.ndarray) -> np.ndarray:
    """Cell edges around increasing centres (n ≥ 2): the slice map's row boundaries."""
    mid = 0.5 * (centres[1:] + centres[:-1])
    return np.concatenate([[2 * centres[0] - mid[0]], mid, [2 * centres[-1] - mid[-1]]])


def slice_pressure_figure(result, case: int) -> SvgFigure | None:
    """Slice pressure map of every sliced roller row (n_s ≥ 2): element (azimuth) × slice; else None.

    Parameters
    ----------
    result : QuasiStaticResult
        Row states with ``slice_load`` (C, Z, n_s) [N] and, when the row provides them, ``extras``
        ``slice_pressure_inner/outer`` (C, Z, n_s) [Pa] and ``slice_position`` (…, n_s) [m].
    case : int
        Case index.

    Notes
    -----
    Elements are sorted by azimuth ψ ∈ [0°, 360°); the colour is the larger of the inner and outer
    raceway slice pressures (the slice load when the row gives no pressures). A bright band at the top
    or bottom edge of a row's map is edge loading.
    """
    states = roller_rows(result)
    if not states:
        return None
    row_h, top = 2.5 * DPI, 0.3 * DPI
    fig = SvgFigure(FIGURE_WIDTH * DPI, row_h * len(states) + top)
    for i, s in enumerate(states):
        values, label, scale = _slice_pressure(s, case)
        psi = np.degrees(np.mod(np.broadcast_to(s.azimuth, s.load.shape)[case], 2 * np.pi))
        order = np.argsort(psi)
        n_s = values.shape[-1]
        pos = s.extras.get("slice_position")
        if pos is not None:
            y = np.broadcast_to(pos, s.slice_load.shape)[case][order[0]] * 1e3
            ylabel = "slice position [mm]"
        else:
            y = np.arange(n_s, dtype=float)
            ylabel = "slice"
        ticks = np.linspace(0, len(psi) - 1, min(len(psi), 9)).round().astype(int)
        svg.heatmap_panel(
            fig,
            (77.0, top + i * row_h + 22, FIGURE_WIDTH * DPI - 77 - 75, row_h - 22 - 48),
            (values[order] * scale).T,
            _edges(np.asarray(y, dtype=float)),
            cmap=COLORMAP,
            x_labels=[(int(t), f"{psi[order][t]:.0f}°") for t in ticks],
            title=f"{s.name}: {label}",
            xlabel="element, sorted by azimuth ψ",
            ylabel=ylabel,
            empty="no loaded roller",
            empty_colour=_WARN,
        )
    return fig


def _hbar_panels(fig: SvgFigure, panels: list[dict], top: float, bottom: float) -> None:
    """Side-by-side horizontal bar panels (svg.hbar_panel), each with room for its longest label."""
    width = fig.width / len(panels)
    for i, p in enumerate(panels):
        margin = max((svg.text_width(label, 8) for label in p["labels"]), default=0.0) + 12
        x0 = i * width + min(margin, 0.45 * width)
        svg.hbar_panel(fig, (x0, top, (i + 1) * width - x0 - 60, fig.height - top - bottom), **p)


def friction_figure(friction, case: int) -> SvgFigure:
    """Friction torque [N·mm] of one case by component and by row (horizontal bars, SVG).

    Parameters
    ----------
    friction : FrictionResult
        ``components`` and ``by_row``: dict name → (C,) [N·m]; each sums to ``total``.
    case : int
    """
    height = (1.3 + 0.26 * max(len(friction.components), len(friction.by_row), 3)) * DPI
    fig = SvgFigure(FIGURE_WIDTH * DPI, height)
    fig.text(
        fig.width / 2,
        16,
        f"Friction torque M = {float(friction.total[case]) * 1e3:.5g} N·mm",
        size=10,
        anchor="middle",
    )
    panels = []
    for title, parts in (("by component", friction.components), ("by row", friction.by_row)):
        v = _finite([x[case] * 1e3 for x in parts.values()])
        top = float(v.max()) if v.size and v.max() > 0 else 1.0
        panels.append(
            dict(
                labels=list(parts),
                values=v,
                colors=[_OK] * len(v),
                xlim=(0.0, top * 1.25),
                title=title,
                xlabel="friction torque [N·mm]",
            )
        )
    _hbar_panels(fig, panels, top=52, bottom=40)
    return fig


def rating_figure(rating, case: int) -> SvgFigure:
    """Static safety s0 and basic reference rating life L10r [rev] per row (log scales, SVG).

    Parameters
    ----------
    rating : RatingResult
        ``rows[].static_safety`` and ``rows[].life`` are masked arrays (C,); masked values are marked
        "n/a" instead of a bar.
    case : int

    Notes
    -----
    The dashed line is s0 = 1 (ISO 76: the limit contact pressure is reached); rows below it are red.
    """
    names = [r.name for r in rating.rows]
    fig = SvgFigure(FIGURE_WIDTH * DPI, (1.2 + 0.3 * max(len(names), 3)) * DPI)
    panels = []
    for attr, xlabel, title in (
        ("static_safety", "static safety s0 [-]", "static safety (ISO 76, from p_max)"),
        ("life", "L10r [revolutions]", "basic reference rating life (ISO/TS 16281)"),
    ):
        vals = [getattr(r, attr)[case] for r in rating.rows]
        ok = np.array([v is not np.ma.masked and np.isfinite(float(v)) and float(v) > 0 for v in vals])
        data = np.array([float(v) if o else 0.0 for v, o in zip(vals, ok, strict=True)])
        lo = float(data[ok].min()) if ok.any() else 1.0
        hi = float(data[ok].max()) if ok.any() else 10.0
        if attr == "static_safety":
            lo, hi = min(lo, S0_REQUIRED), max(hi, S0_REQUIRED)
        panels.append(
            dict(
                labels=names,
                values=np.where(ok, data, np.nan),
                colors=[
                    _WARN if attr == "static_safety" and o and d < S0_REQUIRED else _OK
                    for d, o in zip(data, ok, strict=True)
                ],
                xlim=(lo / 10**0.5, hi * 10**0.8),
                log=True,
                shown=[f"{d:.3g}" if o else "n/a" for d, o in zip(data, ok, strict=True)],
                title=title,
                xlabel=xlabel,
                vline=(S0_REQUIRED, _WARN) if attr == "static_safety" else None,
            )
        )
    _hbar_panels(fig, panels, top=30, bottom=40)
    return fig
