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


# -- any bearing in its structure ([structure]) ----------------------------------------------------------
def structure_figure(case: dict) -> Figure:
    """The rings of a ``[structure]`` and what they change, for one case of ``statics_dict``.

    ``case`` is a case dict of :meth:`~bearingkit.pipeline.Analysis.statics_dict` whose ``flexible`` entry
    is a :class:`~bearingkit.analysis.structure.StructureResult`'s. Top left: each ring's centroid deformed
    in its plane (radial deflection magnified, the factor in the legend) over its undeformed circle; top
    right: the element loads against azimuth, rigid (thin) and flexible (thick) rings; bottom left: the
    rings' axial deflection and twist; bottom right: their in-plane and out-of-plane bending moments.
    """
    flex = case["flexible"]
    rings = [r for r in flex["structure"]["rings"] if "radial_deflection_m" in r]
    fig = Figure(figsize=(10.5, 7.5))
    FigureCanvasAgg(fig)
    ax_ring = fig.add_subplot(2, 2, 1, projection="polar")
    ax_load = fig.add_subplot(2, 2, 2)
    ax_axial = fig.add_subplot(2, 2, 3)
    ax_moment = fig.add_subplot(2, 2, 4)
    biggest = max([max(abs(v) for v in r["radial_deflection_m"]) for r in rings] + [1e-12])
    for i, ring in enumerate(rings):
        theta = np.asarray(ring["shape_azimuth_rad"] + ring["shape_azimuth_rad"][:1])
        w = np.asarray(ring["radial_deflection_m"] + ring["radial_deflection_m"][:1])
        radius = 1.0 if ring["side"] == "outer" else 0.75
        scale = 0.1 / biggest  # the largest deflection drawn as 10 % of the outer ring's radius
        colour = f"C{i}"
        ax_ring.plot(theta, np.full_like(theta, radius), ":", color=colour, lw=0.8)
        ax_ring.plot(theta, radius + scale * w, "-", color=colour, label=f"{ring['side']} ring")
        deg, order = _unrolled(theta[:-1])
        # rounded to 1e-6 µm / µrad: a ring held in its plane moves by round-off only (1e-13), drawn as 0
        ax_axial.plot(deg, np.round(np.asarray(ring["axial_deflection_m"])[order] * 1e6, 6), "-",
                      color=colour, label=f"{ring['side']}: axial u [µm]")  # fmt: skip
        ax_axial.plot(deg, np.round(np.asarray(ring["twist_rad"])[order] * 1e6, 6), "--", color=colour,
                      label=f"{ring['side']}: twist φ [µrad]")  # fmt: skip
        ax_moment.plot(deg, np.asarray(ring["bending_moment_Nm"])[order], "-", color=colour,
                       label=f"{ring['side']}: in plane")  # fmt: skip
        ax_moment.plot(deg, np.asarray(ring["out_of_plane_moment_Nm"])[order], "--", color=colour,
                       label=f"{ring['side']}: out of plane")  # fmt: skip
    ax_ring.set_yticklabels([])
    ax_ring.set_title(f"rings deformed in their plane\n(largest radial deflection {biggest * 1e6:.3g} µm "
                      "drawn as 10 % of the radius)", fontsize=9)  # fmt: skip
    ax_ring.legend(loc="lower left", fontsize=8, bbox_to_anchor=(-0.1, -0.15))
    rigid_rows = {r["name"]: r for r in case["rows"]}
    for k, row in enumerate(flex["rows"]):
        deg, order = _unrolled(row["azimuth_rad"])
        style = _STYLES[k % len(_STYLES)]
        ax_load.plot(deg, np.asarray(rigid_rows[row["name"]]["loads_N"])[order], style, color="0.55", lw=1,
                     label=f"{row['name']} rigid")  # fmt: skip
        ax_load.plot(deg, np.asarray(row["loads_N"])[order], style, color="C3", lw=1.8,
                     label=f"{row['name']} flexible")  # fmt: skip
    ax_load.set_xlabel("azimuth ψ [°]")
    ax_load.set_ylabel("element load Q [N]")
    ax_load.legend(fontsize=8)
    ax_load.grid(alpha=0.3)
    for ax, label in ((ax_axial, "µm, µrad"), (ax_moment, "bending moment [N·m]")):
        ax.set_xlabel("azimuth θ [°]")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"case {case.get('case', '')!r}: the bearing in its structure", fontsize=11)
    fig.tight_layout()
    return fig


def structure_html(case: dict, number: str) -> str:
    """The report's section of one case in its structure ("" without a ``[structure]``)."""
    from bearingkit.report.html_format import _e, _figure_html, _table, fmt

    flex = case.get("flexible")
    if flex is None or "rigid_vs_flexible" not in flex:
        return ""
    rows = []
    for name, r in flex["rigid_vs_flexible"].items():
        change = r["max_load_change"]
        rows.append(
            [
                _e(name),
                f"{r['loaded_count_rigid']} → {r['loaded_count_flexible']}",
                fmt(r["max_load_rigid_N"], 4),
                fmt(r["max_load_flexible_N"], 4),
                "—" if change is None else f"{change * 100:+.2f} %",
                fmt(r["max_pressure_rigid_Pa"], 4, 1e-6),
                fmt(r["max_pressure_flexible_Pa"], 4, 1e-6),
            ]
        )
    ch = flex.get("change", {})
    extra = []
    for key, label, factor in (("static_safety", "s0", 1.0), ("life_rev", "L10 [10⁶ rev]", 1e-6)):
        a, b = ch.get(f"{key}_rigid"), ch.get(f"{key}_flexible")
        if a is not None and b is not None:
            extra.append(f"{label}: {fmt(a, 4, factor)} rigid → {fmt(b, 4, factor)} flexible")
    stresses = [
        f"{r['side']} ring: largest hoop fibre stress {fmt(r['max_fibre_stress_Pa'], 3, 1e-6)} MPa"
        for r in flex["structure"]["rings"]
        if "max_fibre_stress_Pa" in r
    ]
    how = flex["coupling"]
    caption = (
        "Rigid rings (grey) against the rings and supports of [structure] (red): the rings' deflection, "
        "twist and bending moments come from the same coupled solution "
        f"(Newton, {how['iterations']} iterations, {'converged' if flex['converged'] else 'NOT converged'}"
        + (
            f"; the element forces balance the load to {max(how['force_balance'], 1e-16):.0e} of it)."
            if how.get("force_balance") is not None
            else ")."
        )
    )
    return (
        f'<section data-section="structure"><h4>{number}. In its structure: rigid → flexible rings</h4>'
        + _table(
            [
                "row",
                "loaded",
                "Q_max rigid [N]",
                "Q_max flexible [N]",
                "change",
                "p_max rigid [MPa]",
                "p_max flexible [MPa]",
            ],
            rows,
        )
        + (f"<p>{_e('; '.join(extra + stresses))}.</p>" if extra or stresses else "")
        + _figure_html(structure_figure(case), "the rings deformed and the load distribution", caption)
        + "</section>"
    )
