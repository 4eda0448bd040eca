"""Charts written as SVG text: the report's figures that repeat for every bearing and load case.

Why not matplotlib for these: a shaft or drivetrain report draws the element loads, the friction
breakdown, the ratings and the slice pressure map of every bearing in every load case (63 of the 67
figures of the two-stage gearbox example). Matplotlib's Agg backend took 100–150 ms for each (axis
ticks and glyph rendering, most of the report's 20 s); written as SVG they take well under a
millisecond, stay sharp at any zoom, their text can be searched, and equal data give equal bytes. Tick
positions still come from matplotlib's locators (no drawing); colours from its colour maps.

Coordinates are pixels of the figure (``DPI`` per inch), y downwards as in SVG. Every text is XML-escaped
and its control characters replaced (row names come from the user's file); no user text reaches an
attribute. The report embeds the figures as ``<img>`` data URIs (an SVG image cannot run scripts or
fetch anything); the app serves the slice map as a document under its content security policy.
"""

from __future__ import annotations

import base64
import itertools
import math
import re
from html import escape

import numpy as np
from matplotlib.ticker import LogLocator, MaxNLocator

#: Pixels per inch of the figure sizes (the report's PNG figures use the same, plots.DPI).
DPI = 100
#: Pixels per point: font sizes are given in points, as matplotlib's (7 pt = 9.7 px at 100 px per inch).
PT = DPI / 72.0
#: Fonts the browser picks from (the first one present).
FONT = "DejaVu Sans, Helvetica, Arial, sans-serif"
#: Mean advance of a glyph of the sans-serif fonts above per unit font size [-]: sizes the label margins
#: (DejaVu Sans: about 0.55–0.63 for lower case and digits [from memory]; a margin estimate only).
CHAR_WIDTH = 0.6
#: Cells of a colour map at most (elements × slices beyond are shown in blocks, each its largest value):
#: the plot is ~950 × 180 px, so 400 columns are ≥ 2 px wide, 50 rows ≥ 3.6 px tall.
HEATMAP_MAX_COLUMNS, HEATMAP_MAX_ROWS = 400, 50
REPLACEMENT = "\ufffd"  # what a control character in a name is shown as
_CONTROL = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f]")  # not allowed in XML 1.0
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")
_AXIS, _GRID, _TEXT = "#333333", "#d5d8dc", "#222222"


def _n(v: float) -> str:
    """A coordinate with 0.1 px resolution (short, deterministic text)."""
    return f"{v:.1f}".rstrip("0").rstrip(".") if abs(v) < 1e7 else f"{v:.0f}"


def text_width(text: str, size: float) -> float:
    """Estimated width [px] of ``text`` at font ``size`` [pt] (:data:`CHAR_WIDTH`)."""
    return CHAR_WIDTH * size * PT * len(text)


class SvgFigure:
    """An SVG drawing of ``width`` × ``height`` pixels; the report embeds it as an inline image.

    ``get_size_inches`` matches matplotlib's Figure, so the report sizes both kinds alike.
    """

    def __init__(self, width: float, height: float):
        self.width, self.height = float(width), float(height)
        self.parts: list[str] = []

    def get_size_inches(self) -> tuple[float, float]:
        return self.width / DPI, self.height / DPI

    def line(self, x1, y1, x2, y2, color=_AXIS, width=1.0, dash: str | None = None) -> None:
        d = f' stroke-dasharray="{dash}"' if dash else ""
        self.parts.append(
            f'<line x1="{_n(x1)}" y1="{_n(y1)}" x2="{_n(x2)}" y2="{_n(y2)}" stroke="{color}" '
            f'stroke-width="{_n(width)}"{d}/>'
        )

    def rect(self, x, y, w, h, fill, stroke: str | None = None, data: str = "") -> None:
        s = f' stroke="{stroke}"' if stroke else ""
        self.parts.append(
            f'<rect x="{_n(x)}" y="{_n(y)}" width="{_n(max(w, 0.0))}" height="{_n(max(h, 0.0))}" '
            f'fill="{fill}"{s}{data}/>'
        )

    def circle(self, cx, cy, r, fill="none", stroke: str | None = None, data: str = "") -> None:
        s = f' stroke="{stroke}"' if stroke else ""
        self.parts.append(f'<circle cx="{_n(cx)}" cy="{_n(cy)}" r="{_n(r)}" fill="{fill}"{s}{data}/>')

    def path(self, d: str, fill: str, data: str = "") -> None:
        self.parts.append(f'<path d="{d}" fill="{fill}"{data}/>')

    def text(
        self, x, y, text: str, size=8.0, anchor="start", color=_TEXT, bold=False, baseline="middle", rotate=0
    ):
        """``text`` at (x, y) [px], ``size`` in points (:data:`PT`), ``rotate`` in degrees about (x, y)."""
        w = ' font-weight="bold"' if bold else ""
        r = f' transform="rotate({_n(rotate)} {_n(x)} {_n(y)})"' if rotate else ""
        shown = escape(_CONTROL.sub(REPLACEMENT, text), quote=False)
        self.parts.append(
            f'<text x="{_n(x)}" y="{_n(y)}" font-size="{_n(size * PT)}" text-anchor="{anchor}" '
            f'dominant-baseline="{baseline}" fill="{color}"{w}{r}>{shown}</text>'
        )

    def to_svg(self) -> str:
        return (
            f'<svg xmlns="http://www.w3.org/2000/svg" width="{_n(self.width)}" height="{_n(self.height)}" '
            f'viewBox="0 0 {_n(self.width)} {_n(self.height)}" font-family="{FONT}">'
            f'<rect width="100%" height="100%" fill="white"/>{"".join(self.parts)}</svg>'
        )

    def data_uri(self) -> str:
        """``data:image/svg+xml;base64,…`` for an inline ``<img src=…>``."""
        return "data:image/svg+xml;base64," + base64.b64encode(self.to_svg().encode("utf-8")).decode("ascii")


def colour(cmap_name: str, values) -> list[str]:
    """Hex colours of ``values`` ∈ [0, 1] on a matplotlib colour map."""
    from matplotlib import colormaps

    rgba = colormaps[cmap_name](np.clip(np.asarray(values, dtype=float), 0.0, 1.0))
    return ["#{:02x}{:02x}{:02x}".format(*(round(c * 255) for c in px[:3])) for px in np.atleast_2d(rgba)]


def _decade(k: int) -> str:
    return "1" if k == 0 else ("10" if k == 1 else "10" + str(k).translate(_SUPERSCRIPT))


def _linear_ticks(lo: float, hi: float, n: int) -> list[float]:
    lo, hi = min(lo, hi), max(lo, hi)
    tol = 1e-9 * (hi - lo)
    return [float(t) for t in MaxNLocator(n).tick_values(lo, hi) if lo - tol <= t <= hi + tol]


def hbar_panel(
    fig: SvgFigure,
    box: tuple[float, float, float, float],
    labels: list[str],
    values,
    *,
    colors: list[str],
    xlim: tuple[float, float],
    log: bool = False,
    shown: list[str] | None = None,
    title: str = "",
    xlabel: str = "",
    vline: tuple[float, str] | None = None,
) -> None:
    """Horizontal bars, first label on top, in the plot area ``box`` = (x, y, width, height) [px].

    Parameters
    ----------
    values : array_like (n,)
        Bar lengths in data units; a bar whose ``shown`` text is "n/a" is not drawn.
    xlim : (float, float)
        Axis range; on a log axis both > 0.
    shown : list of str, optional
        The text beside each bar (default ``f"{v:.4g}"``).
    vline : (float, str), optional
        A dashed reference line at that value, in that colour.
    """
    x0, y0, w, h = box
    lo, hi = (float(x) for x in xlim)
    if log:  # a log axis needs 0 < lo < hi, both finite
        lo = min(max(lo, 1e-300), 1e299)
        hi = min(hi, 1e300) if hi > lo else lo * 10
    elif not hi > lo:
        hi = lo + 1.0
    v = np.asarray(values, dtype=float)
    if log:
        a, b = math.log10(lo), math.log10(hi)

        def px(x):
            return x0 + (math.log10(max(x, lo)) - a) / (b - a) * w
    else:

        def px(x):
            return x0 + (min(max(x, lo), hi) - lo) / (hi - lo) * w

    # ticks and grid
    if log:
        for k in range(math.floor(a), math.ceil(b) + 1):
            for m in range(1, 10):
                t = m * 10.0**k
                if lo <= t <= hi:
                    x = px(t)
                    fig.line(x, y0 + h, x, y0 + h + (4 if m == 1 else 2), width=0.8)
        majors = [float(t) for t in LogLocator(base=10.0, numticks=6).tick_values(lo, hi) if lo <= t <= hi]
        tick_text = [_decade(round(math.log10(t))) for t in majors]
    else:
        majors = _linear_ticks(lo, hi, 6)
        tick_text = [f"{t:g}" for t in majors]
    for t, s in zip(majors, tick_text, strict=True):
        x = px(t)
        fig.line(x, y0, x, y0 + h, color=_GRID, width=0.6)
        fig.line(x, y0 + h, x, y0 + h + 4, width=0.8)
        fig.text(x, y0 + h + 12, s, size=7, anchor="middle")
    # bars, their values and their labels
    n = max(len(labels), 1)
    band = h / n
    shown = shown if shown is not None else [f"{x:.4g}" for x in v]
    for i, (label, value, colour_, note) in enumerate(zip(labels, v, colors, shown, strict=True)):
        yc = y0 + (i + 0.5) * band
        fig.text(x0 - 5, yc, label, size=8, anchor="end")
        if note == "n/a" or not np.isfinite(value):
            fig.text(px(lo) + 4, yc, "n/a", size=7)
            continue
        right = px(value)
        fig.rect(x0, yc - 0.4 * band, right - x0, 0.8 * band, colour_, data=f' data-value="{value:.6g}"')
        fig.text(right + 3, yc, note, size=7)
    if vline is not None:
        x = px(vline[0])
        fig.line(x, y0, x, y0 + h, color=vline[1], width=1.0, dash="4 3")
    # frame, axis label, title
    fig.line(x0, y0, x0, y0 + h)
    fig.line(x0, y0 + h, x0 + w, y0 + h)
    fig.line(x0, y0, x0 + w, y0, color=_GRID)
    fig.line(x0 + w, y0, x0 + w, y0 + h, color=_GRID)
    if xlabel:
        fig.text(x0 + w / 2, y0 + h + 26, xlabel, size=8, anchor="middle")
    if title:
        fig.text(x0 + w / 2, y0 - 9, title, size=9, anchor="middle")


def polar_panel(
    fig: SvgFigure,
    centre: tuple[float, float],
    radius: float,
    psi,
    q,
    *,
    scale: float,
    colors: list[str],
    title: list[str],
    unloaded_colour: str,
    rticks: int = 3,
) -> None:
    """Bars of length ``q/scale·radius`` at the azimuths ``psi`` [rad] (ψ from +x towards +y, drawn
    counter-clockwise), radial grid circles at ``rticks`` nice values, spokes every 45°; elements with
    q ≤ 0 are dots on the rim. ``scale`` is the radial axis end (data units)."""
    cx, cy = centre
    psi = np.asarray(psi, dtype=float)
    q = np.asarray(q, dtype=float)
    fig.circle(cx, cy, radius, fill="#fbfcfc", stroke=_AXIS)
    ticks = [t for t in _linear_ticks(0.0, scale, rticks) if 0 < t < scale * 0.999]
    for t in ticks:
        fig.circle(cx, cy, t / scale * radius, stroke=_GRID)
    for deg in range(0, 360, 45):
        a = math.radians(deg)
        fig.line(cx, cy, cx + radius * math.cos(a), cy - radius * math.sin(a), color=_GRID, width=0.6)
        fig.text(
            cx + (radius + 12) * math.cos(a),
            cy - (radius + 12) * math.sin(a),
            f"{deg}°",
            size=7,
            anchor="middle",
        )
    half = np.pi / max(len(psi), 1) * 0.8
    for p, v, c in zip(psi, q, colors, strict=True):
        if v <= 0:
            fig.circle(cx + radius * math.cos(p), cy - radius * math.sin(p), 2.0, fill=unloaded_colour)
            continue
        r = min(v / scale, 1.0) * radius
        a1, a2 = p - half, p + half
        d = (
            f"M{_n(cx)} {_n(cy)}L{_n(cx + r * math.cos(a1))} {_n(cy - r * math.sin(a1))}"
            f"A{_n(r)} {_n(r)} 0 {int(2 * half > math.pi)} 0 {_n(cx + r * math.cos(a2))} "
            f"{_n(cy - r * math.sin(a2))}Z"
        )
        fig.path(d, c, data=f' data-psi="{p:.6g}" data-value="{v:.6g}"')
    label_angle = math.radians(112.5)  # the radial scale, drawn over the wedges so that none hides it
    for t in ticks:
        r = t / scale * radius
        fig.text(
            cx + r * math.cos(label_angle), cy - r * math.sin(label_angle), f"{t:g}", size=7, anchor="middle"
        )
    for i, line in enumerate(title):
        fig.text(cx, cy - radius - 34 + 14 * i - 14 * (len(title) - 1), line, size=9, anchor="middle")


def heatmap_panel(
    fig: SvgFigure,
    box: tuple[float, float, float, float],
    values,
    y_edges,
    *,
    cmap: str,
    x_labels: list[tuple[int, str]],
    title: str,
    xlabel: str,
    ylabel: str,
    empty: str,
    empty_colour: str,
) -> None:
    """A colour map of ``values`` (n_y, n_x): column j spans x ∈ [j, j+1] of the ``box``, row i spans
    ``y_edges[i]…y_edges[i+1]`` (increasing, drawn upwards); a colour bar from 0 to the largest value
    on the right; ``x_labels`` (column index, text) under the columns."""
    x0, y0, w, h = box
    v = np.nan_to_num(np.asarray(values, dtype=float), nan=0.0, posinf=0.0, neginf=0.0)
    edges = np.asarray(y_edges, dtype=float)
    n_y, n_x = v.shape
    top = float(v.max()) if v.size else 0.0
    vmax = top if top > 0 else 1.0
    span = edges[-1] - edges[0] if edges[-1] != edges[0] else 1.0
    dx = w / max(n_x, 1)  # one element's width; labels and blocks are placed by element index

    def py(e):
        return y0 + h - (e - edges[0]) / span * h

    # A map finer than the plot's pixels (a slewing ring of 2,000 elements × 200 slices) is shown in
    # blocks of bx elements × by slices, each the largest value in it (the peak stays visible).
    bx, by = -(-n_x // HEATMAP_MAX_COLUMNS), -(-n_y // HEATMAP_MAX_ROWS)
    if bx > 1:
        v = np.maximum.reduceat(v, np.arange(0, n_x, bx), axis=1)
    if by > 1:
        v = np.maximum.reduceat(v, np.arange(0, n_y, by), axis=0)
        edges = np.append(edges[:-1][::by], edges[-1])
    colours = np.asarray(colour(cmap, (v / vmax).ravel())).reshape(v.shape)
    fig.parts.append('<g shape-rendering="crispEdges">')  # no anti-aliased seams between the cells
    for i in range(v.shape[0]):
        ya, yb = py(edges[i + 1]), py(edges[i])
        row = colours[i]
        # neighbours of one colour are one rectangle (a whole unloaded stretch is one)
        cuts = [0, *(np.flatnonzero(row[1:] != row[:-1]) + 1).tolist(), len(row)]
        for a, b in itertools.pairwise(cuts):
            xa, xb = x0 + a * bx * dx, x0 + min(b * bx, n_x) * dx
            # a little wider and taller than the pitch: no hairline gaps between neighbours when scaled
            fig.rect(xa, ya, xb - xa + 0.3, yb - ya + 0.3, row[a])
    fig.parts.append("</g>")
    if bx > 1 or by > 1:
        title = f"{title} (each cell the largest of {bx} elements × {by} slices)"
    fig.line(x0, y0, x0, y0 + h)
    fig.line(x0, y0 + h, x0 + w, y0 + h)
    fig.line(x0, y0, x0 + w, y0, color=_GRID)
    fig.line(x0 + w, y0, x0 + w, y0 + h, color=_GRID)
    for j, label in x_labels:
        x = x0 + (j + 0.5) * dx
        fig.line(x, y0 + h, x, y0 + h + 4, width=0.8)
        fig.text(x, y0 + h + 12, label, size=7, anchor="middle")
    for t in _linear_ticks(float(edges[0]), float(edges[-1]), 5):
        y = py(t)
        fig.line(x0 - 4, y, x0, y, width=0.8)
        fig.text(x0 - 6, y, f"{t:g}", size=7, anchor="end")
    fig.text(x0 + w / 2, y0 + h + 26, xlabel, size=8, anchor="middle")
    fig.text(x0 - 44, y0 + h / 2, ylabel, size=8, anchor="middle", rotate=-90)
    fig.text(x0 + w / 2, y0 - 9, title, size=9, anchor="middle")
    if top <= 0:
        fig.text(x0 + w / 2, y0 + h / 2, empty, size=9, anchor="middle", color=empty_colour)
    # colour bar
    bx, bw, steps = x0 + w + 12, 14, 64
    ramp = colour(cmap, (np.arange(steps) + 0.5) / steps)
    fig.parts.append('<g shape-rendering="crispEdges">')
    for k, c in enumerate(ramp):
        fig.rect(bx, y0 + h - (k + 1) * h / steps, bw, h / steps + 0.3, c)
    fig.parts.append("</g>")
    fig.rect(bx, y0, bw, h, "none", stroke=_AXIS)
    for t in _linear_ticks(0.0, vmax, 5):
        y = y0 + h - t / vmax * h
        fig.line(bx + bw, y, bx + bw + 4, y, width=0.8)
        fig.text(bx + bw + 6, y, f"{t:g}", size=7)
