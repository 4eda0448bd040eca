"""Report section of slewing rings: the static load diagram (allowable axial force vs tilting moment).

SI inside (N, N·m, Pa); axis labels in kN and kN·m. The figure reads the analysis's
:class:`~bearingkit.analysis.slewing.SlewingLoadDiagram`
(:attr:`bearingkit.pipeline.Analysis.load_diagram`) and the load cases.

- :func:`load_diagram_figure` — the engine's static limiting load curve, the makers' straight line, and
  each load case as its Rothe Erde reference loads (combinations I and II with f_stat);
- :func:`slewing_section_html` — the section with the figure and a table of utilisations.
"""

from __future__ import annotations

from matplotlib.figure import Figure

from bearingkit.report import plots
from bearingkit.report.html_format import _figure_html, _table, fmt

#: Application factor f_stat used for the plotted load points [-]. Rothe Erde tabulates 1.0 … 1.45 and
#: more by application; 1.25 is a mid value (e.g. slewing cranes) — the report says which it used.
DEFAULT_F_STAT = 1.25
_MARKERS = {"I": "o", "II": "s"}


def load_diagram_figure(diagram, loads, case_names, f_stat: float = DEFAULT_F_STAT) -> Figure:
    """Static limiting load curve and the load cases' reference loads.

    Parameters
    ----------
    diagram : SlewingLoadDiagram
        Curve [N, N·m] and closed-form capacities.
    loads : ndarray (C, 5) [N, N, N, N·m, N·m]
        The load cases.
    case_names : sequence of str
    f_stat : float
        Application factor applied to the plotted points.
    """
    from bearingkit.analysis.slewing import LOAD_COMBINATIONS, reference_loads

    fig = plots._figure(plots.FIGURE_WIDTH * 0.62, 4.6, top=0.45, bottom=0.65, left=0.12, right=0.97)
    ax = fig.add_subplot(1, 1, 1)
    ax.plot(
        diagram.axial_force / 1e3,
        diagram.moment / 1e3,
        color=plots._OK,
        lw=2.0,
        label=f"static limiting curve (engine, p_max = {diagram.p_limit / 1e6:.0f} MPa)",
    )
    ax.plot(
        [diagram.axial_capacity / 1e3, 0.0],
        [0.0, diagram.moment_capacity / 1e3],
        color=plots._NEUTRAL,
        ls="--",
        lw=1.2,
        label="makers' straight line (C0a, C0a·d_m/4.37)",
    )
    for combo in LOAD_COMBINATIONS:
        fa, mk = reference_loads(loads, f_stat, combo)
        ax.scatter(
            fa / 1e3,
            mk / 1e3,
            marker=_MARKERS[combo],
            s=36,
            zorder=3,
            facecolors="none" if combo == "II" else plots._WARN,
            edgecolors=plots._WARN,
            label=f"load cases × f_stat {f_stat:g}, combination {combo}",
        )
        if combo == "I":
            for x, y, name in zip(fa / 1e3, mk / 1e3, case_names, strict=True):
                ax.annotate(name, (x, y), textcoords="offset points", xytext=(5, 4), fontsize=7)
    ax.set_xlabel("axial force F_a' [kN]")
    ax.set_ylabel("tilting moment M_k' [kN·m]")
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper right")
    return fig


def slewing_section_html(bearing_input, diagram, f_stat: float = DEFAULT_F_STAT) -> str:
    """The "Static load diagram" section of a slewing ring's report ("" when ``diagram`` is None).

    ``diagram`` is the analysis's own (:attr:`bearingkit.pipeline.Analysis.load_diagram`): the report
    draws it and never recomputes it.
    """
    from bearingkit.analysis.slewing import reference_loads

    if diagram is None or not bearing_input.cases:
        return ""
    loads = bearing_input.load_matrix()
    names = [c.name for c in bearing_input.cases]
    rows = []
    for i, name in enumerate(names):
        cells = [name]
        for combo in ("I", "II"):
            fa, mk = reference_loads(loads[i : i + 1], f_stat, combo)
            cells += [fmt(fa[0] / 1e3, 4), fmt(mk[0] / 1e3, 4), fmt(float(diagram.utilisation(fa, mk)[0]), 3)]
        rows.append(cells)
    headers = ["case"] + [
        f"{h} ({c})" for c in ("I", "II") for h in ("F_a' [kN]", "M_k' [kN·m]", "utilisation")
    ]
    caption = (
        "Allowable axial force against tilting moment: the engine's static limiting curve (loads that bring "
        "the most loaded contact to the ISO 76 limit stress, with the operating contact angles and load "
        "zone), the makers' straight line, and each load case as Rothe Erde reference loads "
        f"(I: F_a' = (F_a + 5.046 F_r) f_stat, M_k' = M_k f_stat; II: 1.225 F_a + 2.676 F_r, 1.225 M_k; "
        f"f_stat = {f_stat:g}). A case is statically suitable if one combination lies below the curve "
        "(utilisation < 1)."
    )
    status = "" if diagram.converged.all() else "<p>Some rays did not converge; the curve is incomplete.</p>"
    return (
        '<section id="load-diagram" data-section="load-diagram"><h3>Static load diagram (slewing ring)</h3>'
        + status
        + _figure_html(
            load_diagram_figure(diagram, loads, names, f_stat), "slewing ring load diagram", caption
        )
        + _table(headers, rows)
        + f'<p class="sub">C0a = {diagram.axial_capacity / 1e3:.4g} kN, moment capacity '
        f"{diagram.moment_capacity / 1e3:.4g} kN·m (straight line); engine curve ends "
        f"{diagram.axial_force[0] / 1e3:.4g} kN and {diagram.moment[-1] / 1e3:.4g} kN·m.</p></section>"
    )
