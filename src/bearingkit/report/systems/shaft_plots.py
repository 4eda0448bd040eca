"""Figures of a shaft on its bearings: outline, deflection line and bending-moment line.

SI inside (m, N·m); only the axis labels convert (mm, µm, N·m). :func:`shaft_figure` reads a
:class:`~bearingkit.systems.shaft.result.ShaftResult` and never recomputes mechanics.

- top: the shaft's half outline (sections), bearings (triangles, filled when locating) and gears;
- middle: radial deflection u_x, u_y and |u| along the shaft [µm];
- bottom: bending moment M_x, M_y and |M| along the shaft [N·m] (``ShaftResult.moment_line``).
"""

from __future__ import annotations

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

#: Resolution of written PNGs [dots per inch].
DPI = 100
#: Figure size [in].
FIGURE_SIZE = (10.0, 7.5)
_COLORS = {"x": "#2e86c1", "y": "#c0392b", "abs": "#2c3e50"}


def _outline(ax, result) -> None:
    shaft = result.system.shaft
    for s in shaft.sections:
        z = np.array([s.start, s.end]) * 1e3
        ax.fill_between(z, s.inner_diameter / 2 * 1e3, s.outer_diameter / 2 * 1e3, color="#bdc3c7", lw=0)
        ax.fill_between(z, -s.outer_diameter / 2 * 1e3, -s.inner_diameter / 2 * 1e3, color="#bdc3c7", lw=0)
    r_max = max(s.outer_diameter for s in shaft.sections) / 2 * 1e3
    for b in result.system.bearings:
        face = "#2c3e50" if b.axial == "locating" else "white"
        ax.plot([b.position * 1e3], [-r_max * 1.25], marker="^", ms=11, mfc=face, mec="#2c3e50")
        ax.annotate(
            b.name,
            (b.position * 1e3, -r_max * 1.25),
            xytext=(0, -14),
            textcoords="offset points",
            ha="center",
            va="top",
            fontsize=8,
        )
    for g in result.system.gears:
        half = min(g.pitch_diameter / 2 * 1e3, 1.6 * r_max)
        ax.plot([g.position * 1e3] * 2, [-half, half], color="#8e44ad", lw=3, alpha=0.6)
        ax.annotate(
            g.name,
            (g.position * 1e3, half),
            xytext=(0, 3),
            textcoords="offset points",
            ha="center",
            va="bottom",
            fontsize=8,
        )
    ax.set_ylabel("radius [mm]")
    ax.set_ylim(-2.0 * r_max, 2.0 * r_max)
    ax.set_title(f"{result.system.name}: outline, bearings (▲ locating, △ floating) and gears", fontsize=10)


def shaft_figure(result, case: int = 0) -> Figure:
    """Outline, deflection and bending moment of load case ``case`` (module docstring)."""
    fig = Figure(figsize=FIGURE_SIZE, dpi=DPI)
    FigureCanvasAgg(fig)
    axes = fig.subplots(3, 1, sharex=True, gridspec_kw={"height_ratios": [1.0, 1.4, 1.4]})
    fig.subplots_adjust(left=0.1, right=0.97, top=0.94, bottom=0.08, hspace=0.25)
    _outline(axes[0], result)
    z_mm = result.z * 1e3
    u = result.displacement[case]
    ax = axes[1]
    ax.plot(z_mm, u[:, 0] * 1e6, color=_COLORS["x"], label="u_x")
    ax.plot(z_mm, u[:, 1] * 1e6, color=_COLORS["y"], label="u_y")
    ax.plot(z_mm, np.hypot(u[:, 0], u[:, 1]) * 1e6, color=_COLORS["abs"], ls="--", label="|u| radial")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_ylabel("deflection [µm]")
    ax.legend(loc="best", fontsize=8, ncols=3)
    ax.set_title(f"load case {result.loads.names[case]!r}: deflection of the shaft axis", fontsize=10)
    z_m, moment = result.moment_line()
    m = moment[case]
    ax = axes[2]
    ax.plot(z_m * 1e3, m[:, 0], color=_COLORS["x"], label="M_x")
    ax.plot(z_m * 1e3, m[:, 1], color=_COLORS["y"], label="M_y")
    ax.plot(z_m * 1e3, np.hypot(m[:, 0], m[:, 1]), color=_COLORS["abs"], ls="--", label="|M|")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_ylabel("bending moment [N·m]")
    ax.set_xlabel("axial position z [mm]")
    ax.legend(loc="best", fontsize=8, ncols=3)
    for a in axes[1:]:
        for b in result.system.bearings:
            a.axvline(b.position * 1e3, color="0.75", lw=0.8, ls=":")
    return fig


def write_shaft_figure(result, path, case: int = 0):
    """Write :func:`shaft_figure` as a PNG to ``path``; returns the path."""
    from pathlib import Path

    from bearingkit.io.export import write_atomic

    fig = shaft_figure(result, case)
    return write_atomic(
        Path(path), lambda tmp: fig.savefig(tmp, dpi=DPI, format="png", metadata={"Software": None}), "figure"
    )
