"""The report's SVG figures (report/svg.py) draw what the results say: one wedge per loaded element at its
azimuth with a length proportional to its load, one bar per friction component and row with its value,
s0 below 1 in the warning colour, "n/a" for a missing life; row names escaped; equal data, equal bytes."""

from __future__ import annotations

import dataclasses
import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import bearingkit as bk
from bearingkit.report import plots, svg

SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def composite():
    """Seed 000's five-row turntable (rollers and balls, friction by component and by row)."""
    return bk.analyze("examples/seed000_composite.toml")


def _root(fig) -> ET.Element:
    return ET.fromstring(fig.to_svg())


def test_polar_wedges_are_the_loaded_elements_at_their_azimuth(composite):
    st = composite.statics
    fig = plots.polar_load_figure(st, 0)
    root = _root(fig)
    wedges = [e for e in root.iter(SVG + "path") if e.get("data-value")]
    rows = list(st.rows)
    loads = [np.asarray(r.load[0]) / 1e3 for r in rows]
    assert len(wedges) == sum(int(np.count_nonzero(q > 0)) for q in loads)
    # panel by panel (in row order): the wedge values are the loaded elements' Q [kN], in azimuth order
    k = 0
    for row, q in zip(rows, loads, strict=True):
        psi = np.mod(np.broadcast_to(row.azimuth, row.load.shape)[0], 2 * np.pi)
        loaded = q > 0
        got = wedges[k : k + int(loaded.sum())]
        k += int(loaded.sum())
        np.testing.assert_allclose([float(w.get("data-value")) for w in got], q[loaded], rtol=1e-5)
        np.testing.assert_allclose([float(w.get("data-psi")) for w in got], psi[loaded], rtol=1e-5, atol=1e-6)
        # wedge length ∝ Q: the arc's radius over the largest one is Q/Q_max
        radii = np.array([float(re.search(r"A([0-9.]+) ", w.get("d")).group(1)) for w in got])
        np.testing.assert_allclose(radii / radii.max(), q[loaded] / q.max(), atol=2e-3)
        # the longest wedge points at its ψ (counter-clockwise from +x, SVG y downwards)
        longest = int(np.argmax(radii))
        m = re.match(
            r"M([-0-9.]+) ([-0-9.]+)L([-0-9.]+) ([-0-9.]+)A[^ ]+ [^ ]+ 0 [01] 0 ([-0-9.]+) ([-0-9.]+)Z",
            got[longest].get("d"),
        )
        cx, cy, x1, y1, x2, y2 = (float(v) for v in m.groups())
        mid = math.atan2(-((y1 + y2) / 2 - cy), (x1 + x2) / 2 - cx)
        assert abs(math.remainder(mid - psi[loaded][longest], 2 * math.pi)) < 0.01
    # titles carry the loaded count and Q_max of each row
    texts = [t.text for t in root.iter(SVG + "text")]
    for q in loads:
        assert f"{int(np.count_nonzero(q > 0))}/{len(q)} loaded, Q_max = {q.max():.3g} kN" in texts


def test_friction_bars_are_the_components_and_rows(composite):
    from bearingkit.report import _shown

    fr = _shown(composite.friction)  # what the report draws: components and rows
    root = _root(plots.friction_figure(fr, 0))
    bars = [float(e.get("data-value")) for e in root.iter(SVG + "rect") if e.get("data-value")]
    expected = [v[0] * 1e3 for v in fr.components.values()] + [v[0] * 1e3 for v in fr.by_row.values()]
    np.testing.assert_allclose(bars, expected, rtol=1e-5)
    texts = [t.text for t in root.iter(SVG + "text")]
    assert f"Friction torque M = {float(fr.total[0]) * 1e3:.5g} N·mm" in texts
    assert set(fr.components) <= set(texts) and set(fr.by_row) <= set(texts)


def test_rating_bars_warn_below_s0_1_and_say_na(composite):
    rating = composite.rating
    rows = [dataclasses.replace(r) for r in rating.rows]
    rows[0].static_safety = np.ma.array([0.5])  # below ISO 76's s0 = 1
    rows[1].life = np.ma.masked_all(1)  # no life
    fig = plots.rating_figure(dataclasses.replace(rating, rows=rows), 0)
    root = _root(fig)
    bars = [e for e in root.iter(SVG + "rect") if e.get("data-value")]
    s0 = bars[: len(rows)]
    assert s0[0].get("fill") == plots._WARN and all(b.get("fill") == plots._OK for b in s0[1:])
    assert float(s0[0].get("data-value")) == 0.5
    assert len(bars) == 2 * len(rows) - 1  # the masked life is not drawn
    assert [t.text for t in root.iter(SVG + "text")].count("n/a") == 1
    dashed = [e for e in root.iter(SVG + "line") if e.get("stroke-dasharray")]
    assert len(dashed) == 1  # s0 = 1


def _two_bars() -> str:
    fig = svg.SvgFigure(400, 200)
    bars = (["<row&1>", "b"], [2.0, 5.0])
    svg.hbar_panel(fig, (150, 30, 200, 120), *bars, colors=["#2e86c1"] * 2, xlim=(0.0, 6.0), title="t")
    return fig.to_svg()


def test_names_are_escaped_and_equal_data_give_equal_bytes():
    text = _two_bars()
    assert "<row&1>" not in text and "&lt;row&amp;1&gt;" in text
    root = ET.fromstring(text)
    assert "<row&1>" in [t.text for t in root.iter(SVG + "text")]
    assert _two_bars() == text
    # bar lengths are the values on the axis: 2 and 5 of 0…6 over 200 px
    widths = [float(e.get("width")) for e in root.iter(SVG + "rect") if e.get("data-value")]
    np.testing.assert_allclose(widths, [200 * 2 / 6, 200 * 5 / 6], atol=0.06)


def test_log_axis_labels_every_decade_in_range():
    fig = svg.SvgFigure(600, 150)
    svg.hbar_panel(fig, (100, 20, 400, 80), ["a"], [3e5], colors=["#000"], xlim=(1e3, 1e7), log=True)
    texts = [t.text for t in ET.fromstring(fig.to_svg()).iter(SVG + "text")]
    assert {"10³", "10⁵", "10⁷"} <= set(texts)


def _map_grid(group: ET.Element) -> tuple[list[list[tuple]], float, float]:
    """A map's cells read back from its rectangles (a run of equal neighbours is one rectangle): per row,
    top to bottom, its (start, end, fill) runs; and the map's x range."""
    rects = [(float(e.get("x")), float(e.get("y")), float(e.get("width")), e.get("fill")) for e in group]
    x0 = min(r[0] for r in rects)
    x1 = max(r[0] + r[2] - 0.3 for r in rects)
    rows: dict[float, list] = {}
    for x, y, w, fill in rects:
        rows.setdefault(y, []).append((x, x + w - 0.3, fill))
    return [[(a, b, f) for a, b, f in sorted(runs)] for _, runs in sorted(rows.items())], x0, x1


def test_slice_map_shows_each_element_and_slice_in_its_pressure_colour():
    a = bk.analyze("examples/crb_nu209.toml")
    st = a.statics
    (row,) = plots.roller_rows(st)
    values, _, scale = plots._slice_pressure(row, 0)
    psi = np.mod(np.broadcast_to(row.azimuth, row.load.shape)[0], 2 * np.pi)
    shown = (values[np.argsort(psi)] * scale).T  # (slices, elements), elements by azimuth
    root = _root(plots.slice_pressure_figure(st, 0))
    group = next(g for g in root.iter(SVG + "g"))  # the map's cells (the colour bar is the second group)
    rows, x0, x1 = _map_grid(group)
    n_s, z = shown.shape
    assert len(rows) == n_s
    expected = np.asarray(svg.colour(plots.COLORMAP, (shown / shown.max()).ravel())).reshape(shown.shape)
    dx = (x1 - x0) / z
    for i, runs in enumerate(rows):  # top row first = the last slice
        got = []
        for a_, b_, fill in runs:
            got += [fill] * round((b_ - a_) / dx)
        assert got == list(expected[n_s - 1 - i]), i
    texts = [t.text for t in root.iter(SVG + "text")]
    assert f"{row.name}: max. slice pressure (inner/outer) [MPa]" in texts and "slice position [mm]" in texts
    assert scale == 1e-6


def test_a_map_finer_than_the_plot_is_shown_in_blocks_of_their_peak():
    """2,000 elements × 200 slices (a large slewing ring): blocks of 5 × 4, each its largest value; the
    figure stays bounded (one rectangle per run of equal blocks)."""
    v = np.zeros((200, 2000))
    v[123, 1234] = 7.0  # one peak: its block shows the top colour
    fig = svg.SvgFigure(1100, 300)
    svg.heatmap_panel(
        fig,
        (77, 22, 948, 180),
        v,
        np.linspace(0.0, 10.0, 201),
        cmap="viridis",
        x_labels=[(0, "0°")],
        title="t",
        xlabel="x",
        ylabel="y",
        empty="none",
        empty_colour="#f00",
    )
    root = _root(fig)
    rows, x0, x1 = _map_grid(next(g for g in root.iter(SVG + "g")))
    assert len(rows) == 50
    top = svg.colour("viridis", [1.0])[0]
    hot = [(i, a_, b_) for i, runs in enumerate(rows) for a_, b_, f in runs if f == top]
    assert len(hot) == 1
    i, a_, b_ = hot[0]
    dx = (x1 - x0) / 2000
    assert round((a_ - x0) / dx) == 1230 and round((b_ - x0) / dx) == 1235  # elements 1230-1234
    assert 49 - i == 123 // 4  # slices 120-123, counted from the bottom
    assert "t (each cell the largest of 5 elements × 4 slices)" in [t.text for t in root.iter(SVG + "text")]
    assert len(fig.to_svg()) < 20_000


def test_a_single_element_wedge_takes_the_long_way_round():
    """One element: its wedge spans 0.8 × 360° (the large-arc flag set), two elements: 0.8 × 180° each."""
    for n, flag in ((1, "1"), (2, "0")):
        fig = svg.SvgFigure(300, 300)
        psi = np.arange(n) * 2 * np.pi / n
        svg.polar_panel(
            fig,
            (150, 150),
            100,
            psi,
            np.ones(n),
            scale=1.0,
            colors=["#000"] * n,
            title=["t"],
            unloaded_colour="#999",
        )
        wedges = [e.get("d") for e in _root(fig).iter(SVG + "path")]
        assert len(wedges) == n and all(re.search(rf"A100 100 0 {flag} 0 ", d) for d in wedges)
