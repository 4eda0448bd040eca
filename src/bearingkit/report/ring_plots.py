"""Figures of a flexible outer ring: raceway deflection and element loads against azimuth (seed 002).

SI inside (m, N, rad); only the axis labels convert (µm, N, degrees). The functions read
:class:`~bearingkit.analysis.flexible.FlexibleResult` and
:class:`~bearingkit.analysis.solver.quasistatic.QuasiStaticResult` objects and never recompute mechanics.

- :func:`ring_shape_figure` — unrolled against azimuth: top, the outward radial offset of the
  outer raceway at each element of the chosen rows (thin-ring bending + beam opening) for every
  flexible solution (the rigid ring is the zero line); bottom, the element loads of the same rows,
  rigid against flexible.
- :func:`ring_moment_figure` — the ring's bending moment (outer fibre in tension > 0) and, when the
  section knows its radii, the hoop stress at the inner and outer fibre against azimuth.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

#: Resolution of the written PNG [dots per inch].
DPI = 110
#: Line styles per row (cycled), so rows stay apart in grey-scale prints.
_STYLES = ("-", "--", ":", "-.")


def _unrolled(azimuth) -> tuple[np.ndarray, np.ndarray]:
    """Azimuth in degrees on (−180°, 180°] and the order that sorts it (the load zone in the middle)."""
    deg = np.rad2deg(np.mod(np.asarray(azimuth, dtype=float) + np.pi, 2 * np.pi) - np.pi)
    order = np.argsort(deg)
    return deg[order], order


def ring_shape_figure(
    rigid,
    flexible: dict,
    rows=("roller_2", "ball_3"),
    case: int = 0,
    title: str = "",
) -> Figure:
    """Raceway offset and element loads against azimuth, rigid vs flexible ring(s).

    Parameters
    ----------
    rigid : QuasiStaticResult
        The rigid-ring solution (loads drawn as the reference).
    flexible : dict of str to FlexibleResult
        Label → flexible solution (e.g. ``{"beam": …, "beam + ovalisation": …}``).
    rows : sequence of str
        Rows to draw.
    case : int
        Load case of every result to draw.
    title : str

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = Figure(figsize=(8.0, 6.4), dpi=DPI)
    FigureCanvasAgg(fig)
    ax_w, ax_q = fig.subplots(2, 1, sharex=True)
    colours = {label: f"C{i + 1}" for i, label in enumerate(flexible)}
    ax_w.axhline(0.0, color="C0", lw=1.2, label="rigid ring")
    for k, name in enumerate(rows):
        style = _STYLES[k % len(_STYLES)]
        st = rigid.row(name)
        deg, order = _unrolled(np.broadcast_to(st.azimuth, st.load.shape)[case])
        ax_q.plot(deg, st.load[case][order], style, color="C0", marker=".", ms=3, label=f"{name}, rigid")
        for label, flex in flexible.items():
            fst = flex.row(name)
            deg, order = _unrolled(np.broadcast_to(fst.azimuth, fst.load.shape)[case])
            off = flex.offsets.get(name)
            if off is not None and off.radial is not None:
                w = np.broadcast_to(off.radial, fst.load.shape)[case][order]
                ax_w.plot(deg, w * 1e6, style, color=colours[label], label=f"{name}, {label}")
            ax_q.plot(
                deg,
                fst.load[case][order],
                style,
                color=colours[label],
                marker=".",
                ms=3,
                label=f"{name}, {label}",
            )
    ax_w.set_ylabel("outer-raceway radial offset [µm]\n(outward +)")
    ax_q.set_ylabel("element load Q [N]")
    ax_q.set_xlabel("azimuth ψ [deg] (radial load along ψ = 0)")
    ax_q.set_xlim(-180, 180)
    ax_q.set_xticks(np.arange(-180, 181, 45))
    for ax in (ax_w, ax_q):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return fig


def write_ring_shape(path, rigid, flexible: dict, **kwargs) -> Path:
    """Draw :func:`ring_shape_figure` and write it as PNG (parent folders created); returns the path."""
    from bearingkit.io.export import write_atomic

    fig = ring_shape_figure(rigid, flexible, **kwargs)
    return write_atomic(
        Path(path), lambda tmp: fig.savefig(tmp, dpi=DPI, format="png", metadata={"Software": None}), "figure"
    )


#: Azimuths of the moment figure [–] (one point per degree).
MOMENT_POINTS = 360


def ring_moment_figure(flexible: dict, case: int = 0, title: str = "") -> Figure:
    """Ring bending moment and fibre stresses against azimuth for one or more flexible solutions.

    Parameters
    ----------
    flexible : dict of str to FlexibleResult
        Label → flexible solution.
    case : int
        Load case to draw.
    title : str

    Returns
    -------
    matplotlib.figure.Figure
        Top: M [N·m] (outer fibre in tension > 0); bottom: hoop stress at the inner (dashed) and outer
        (solid) fibre [MPa], for the solutions whose ring section knows its radii.
    """
    fig = Figure(figsize=(8.0, 6.4), dpi=DPI)
    FigureCanvasAgg(fig)
    ax_m, ax_s = fig.subplots(2, 1, sharex=True)
    theta = np.linspace(-np.pi, np.pi, MOMENT_POINTS, endpoint=False)
    deg = np.rad2deg(theta)
    for i, (label, flex) in enumerate(flexible.items()):
        colour = f"C{i + 1}"
        forces = flex.ring_forces(theta)
        ax_m.plot(deg, forces.moment[case], color=colour, label=label)
        stress = flex.ring.fibre_stress(forces)
        if stress is not None:
            ax_s.plot(deg, stress[1][case] / 1e6, color=colour, label=f"{label}, outer fibre")
            ax_s.plot(deg, stress[0][case] / 1e6, "--", color=colour, label=f"{label}, inner fibre")
    ax_m.axhline(0.0, color="0.5", lw=0.8)
    ax_m.set_ylabel("ring bending moment M [N·m]\n(outer fibre in tension +)")
    ax_s.set_ylabel("hoop stress [MPa]")
    ax_s.set_xlabel("azimuth ψ [deg] (radial load along ψ = 0)")
    ax_s.set_xlim(-180, 180)
    ax_s.set_xticks(np.arange(-180, 181, 45))
    for ax in (ax_m, ax_s):
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, ncol=2)
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return fig


def write_ring_moment(path, flexible: dict, **kwargs) -> Path:
    """Draw :func:`ring_moment_figure` and write it as PNG (parent folders created); returns the path."""
    from bearingkit.io.export import write_atomic

    fig = ring_moment_figure(flexible, **kwargs)
    return write_atomic(
        Path(path), lambda tmp: fig.savefig(tmp, dpi=DPI, format="png", metadata={"Software": None}), "figure"
    )
