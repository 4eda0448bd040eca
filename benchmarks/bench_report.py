"""Report drawing: the charts drawn for every bearing and load case (SVG, report/svg.py) against the same
kind of chart drawn with matplotlib's Agg backend, and the whole two-stage gearbox report.

``python -m benchmarks.bench_report`` prints the lines; ``make bench`` includes them. The matplotlib
reference is a two-panel horizontal-bar figure of the same size as the friction chart (the kind the
SVG charts replaced), drawn and saved as PNG at the report's resolution: a reading of what one figure
cost, not a copy of the old code.
"""

from __future__ import annotations

import io
import statistics
import time
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _median_s(fn, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def _matplotlib_bars(labels, values) -> bytes:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(11.0, 1.3 + 0.26 * max(len(labels), 3)), dpi=100)
    FigureCanvasAgg(fig)
    for k in range(2):
        ax = fig.add_subplot(1, 2, k + 1)
        ax.barh(range(len(labels)), values)
        ax.set_yticks(range(len(labels)), labels, fontsize=8)
        for y, v in enumerate(values):
            ax.text(v, y, f"{v:.4g}", va="center", fontsize=7)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=100)
    return buf.getvalue()


def run(quick: bool = False) -> list[dict]:
    import tempfile

    import bearingkit as bk
    from bearingkit.report import _shown, plots
    from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
    from bearingkit.systems.drivetrain.input import load_drivetrain_file

    repeats = 3 if quick else 10
    a = bk.analyze(str(EXAMPLES / "seed000_composite.toml"))
    friction = _shown(a.friction)
    labels, values = list(friction.components), [float(v[0]) * 1e3 for v in friction.components.values()]
    svg_s = _median_s(lambda: plots.friction_figure(friction, 0).to_svg(), repeats * 10)
    mpl_s = _median_s(lambda: _matplotlib_bars(labels, values), repeats)
    polar_s = _median_s(lambda: plots.polar_load_figure(a.statics, 0).to_svg(), repeats * 10)
    gearbox = DrivetrainAnalysis(load_drivetrain_file(EXAMPLES / "gearbox_two_stage.toml"))
    _ = gearbox.result  # solved before the clock starts
    with tempfile.TemporaryDirectory() as tmp:
        first_s = _median_s(lambda: gearbox.report(Path(tmp) / "r.html"), 1)  # + each bearing's analyses
        report_s = _median_s(lambda: gearbox.report(Path(tmp) / "r.html"), 1 if quick else 3)
    return [
        {
            "name": "report: friction chart, SVG / matplotlib Agg PNG",
            "value": svg_s * 1e3,
            "unit": "ms",
            "target": "<= 5",
            "note": f"matplotlib bars of the same size {mpl_s * 1e3:.1f} ms: {mpl_s / svg_s:.0f}x; "
            f"polar chart of seed 000's five rows (SVG) {polar_s * 1e3:.2f} ms",
        },
        {
            "name": "report: two-stage gearbox (9 bearings x 2 cases), solved before",
            "value": report_s,
            "unit": "s",
            "target": "",
            "note": f"drawing and writing the HTML again (67 figures, 63 of them SVG charts); the first "
            f"report, with each bearing's friction and ratings, {first_s:.2f} s",
        },
    ]


if __name__ == "__main__":
    for line in run():
        print(f"{line['name']}: {line['value']:.3g} {line['unit']} ({line['note']})")
