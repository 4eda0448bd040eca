"""Report section "Below the surface": stress against depth under the most loaded contacts, against the
raceways' strength profile (docs/subsurface.md).

SI dicts in (``rows[].subsurface`` of :meth:`bearingkit.pipeline.Analysis.statics_dict` with the
analysis's :attr:`~bearingkit.pipeline.Analysis.subsurface`); MPa and mm shown.
"""

from __future__ import annotations

import numpy as np

from bearingkit.report import plots
from bearingkit.report.html_format import _e, _figure_html, _table, fmt

#: Load cases drawn (every case gets its table; the figures stop here to keep reports small).
MAX_FIGURE_CASES = 6
#: Rows drawn side by side per figure line.
_COLUMNS = 3


def subsurface_figure(rows: list[dict], settings: dict):
    """Von Mises, Tresca and orthogonal shear against depth per row, with the yield-strength profile.

    Parameters
    ----------
    rows : list of dict
        ``rows[]`` of one case with their ``subsurface`` dicts.
    settings : dict
        The analysis's subsurface settings (``case_depth_m`` marks the hardened layer).
    """
    shown = [r for r in rows if r.get("subsurface") and r["subsurface"]["max_von_mises_Pa"]]
    if not shown:
        return None
    cols = min(_COLUMNS, len(shown))
    lines = -(-len(shown) // cols)
    fig = plots._figure(plots.FIGURE_WIDTH, 3.4 * lines + 0.4, top=0.35, bottom=0.55, left=0.07, right=0.98)
    for i, row in enumerate(shown):
        s = row["subsurface"]
        ax = fig.add_subplot(lines, cols, i + 1)
        z = np.array(s["depth_m"], float) * 1e3
        for key, label, style in (
            ("von_mises_Pa", "von Mises", "-"),
            ("tresca_Pa", "Tresca (max shear)", "--"),
            ("orthogonal_shear_Pa", "orthogonal shear τ₀", ":"),
        ):
            ax.plot(np.array(s[key], float) / 1e6, z, style, color=plots._OK, lw=1.6, label=label)
        strength = np.array(s["strength_Pa"], float) / 1e6
        ax.plot(strength, z, color=plots._WARN, lw=1.4, label="yield strength from hardness")
        depth_case = settings.get("case_depth_m")
        if depth_case:
            ax.axhline(depth_case * 1e3, color=plots._NEUTRAL, lw=0.8, ls="-.", label="effective case depth")
        ax.plot([s["max_von_mises_Pa"] / 1e6], [s["depth_max_von_mises_m"] * 1e3], "o", color=plots._OK, ms=4)
        ax.set_ylim(z[-1], 0.0)
        ax.set_xlim(left=0.0)
        ax.set_xlabel("stress [MPa]")
        ax.set_ylabel("depth [mm]")
        ax.set_title(
            f"{row['name']}: {s['raceway']} raceway, p₀ = {s['max_pressure_Pa'] / 1e6:.0f} MPa", fontsize=9
        )
        ax.grid(alpha=0.3)
        if i == 0:
            ax.legend(fontsize=7, loc="lower right")
    return fig


def _safety_cell(s: dict) -> str:
    if s["case_safety"] is None:
        return "—"
    text = f"{s['case_safety']:.2f} ({s['case_safety_zone']}, {s['depth_case_safety_m'] * 1e3:.3g} mm)"
    return f'<span class="warn">{_e(text)}</span>' if s["case_safety"] < 1 else _e(text)


def subsurface_section_html(cases: list[dict], settings: dict, number: int) -> str:
    """The "Below the surface" section: method, hardness profile, a table and a figure per load case.

    Parameters
    ----------
    cases : list of dict
        ``cases`` of :meth:`~bearingkit.pipeline.Analysis.statics_dict` with ``rows[].subsurface``.
    settings : dict
        Its ``subsurface`` settings.
    number : int
        The section number.
    """
    head = ["row", "raceway", "p₀ [MPa]", "σ_vM max [MPa]", "at [mm]", "σ_vM/p₀", "τ_max [MPa]", "τ₀ [MPa]"]
    head += ["case safety", "case needed [mm]"]
    parts = [
        f'<section id="subsurface" data-section="subsurface"><h2>{number}. Below the surface</h2>',
        "<p>Stresses below the most loaded contact of every row (the largest Hertz pressure over the "
        "elements, both raceways and every roller slice): von Mises and Tresca stress below the contact "
        "centre and the amplitude of the orthogonal shear against depth (Thomas &amp; Hoersch / Sackfield "
        "&amp; Hills for ball contacts, McEwen for roller slices; traction coefficient "
        f"{settings['traction_coefficient']:g}), against the raceway's yield strength from its hardness "
        f"({_e(settings['strength_model'])}). Raceways: {_e(settings['hardness_profile'])}. The case safety "
        "is the smallest ratio of strength to von Mises stress where the hardness has left its surface "
        "value (transition zone and core); the hardened surface itself is judged by ISO 76 (s0).</p>",
    ]
    for k, case in enumerate(cases):
        rows = [r for r in case["rows"] if r.get("subsurface")]
        table = []
        for r in rows:
            s = r["subsurface"]
            if not s["max_von_mises_Pa"]:
                table.append([_e(r["name"])] + ["—"] * (len(head) - 1))
                continue
            need = s["required_case_depth_m"]
            table.append(
                [
                    _e(r["name"]),
                    _e(s["raceway"] + (" (edge slice)" if s["edge_slice"] else "")),
                    fmt(s["max_pressure_Pa"], 4, 1e-6),
                    fmt(s["max_von_mises_Pa"], 4, 1e-6),
                    fmt(s["depth_max_von_mises_m"], 3, 1e3),
                    fmt(s["von_mises_over_pressure"], 3),
                    fmt(s["max_tresca_Pa"], 4, 1e-6),
                    fmt(s["max_orthogonal_shear_Pa"], 4, 1e-6),
                    _safety_cell(s),
                    "—"
                    if need is None
                    else ("none reaches it" if need == float("inf") else fmt(need, 3, 1e3)),
                ]
            )
        parts.append(f"<h3>{number}.{k + 1}. Load case “{_e(case['case'])}”</h3>")
        parts.append(_table(head, table, left=2))
        if k < MAX_FIGURE_CASES:
            parts.append(
                _figure_html(
                    subsurface_figure(rows, settings),
                    f"stress against depth, case {case['case']}",
                    "Stress against depth below the most loaded contact of each row; red: the yield strength "
                    "from the hardness profile; dot: the von Mises maximum.",
                )
            )
    if len(cases) > MAX_FIGURE_CASES:
        parts.append(
            f"<p>Figures of the first {MAX_FIGURE_CASES} load cases only; every case is tabulated.</p>"
        )
    parts.append("</section>")
    return "".join(parts)
