"""Building blocks of the HTML report: number formatting, tables, figures, badges, warning categories.

SI values come in; every helper formats for display (the unit is in the column header). Shared by
:mod:`bearingkit.report.html_inputs` and :mod:`bearingkit.report.html`. Report layout: bearingkit
(2025), no external source.
"""

from __future__ import annotations

import html as _html
import math
import re

import numpy as np

from bearingkit.report import plots

#: Warning categories shown as badges: (label, lower-case phrases that select it), first match wins.
WARNING_KINDS = (
    ("non-convergence", ("did not converge", "not converged")),
    ("edge loading", ("edge loading",)),
    ("truncated contact ellipse", ("ellipse truncated", "truncated")),
    ("stress over limit", ("exceeds the iso 76 limit", "stress above", "over the limit")),
    ("unloaded row", ("no loaded element",)),
    ("not available", ("unavailable", "no life", "no fatigue", "not defined")),
)
#: Badge colour class of each warning category (default ``warn``).
WARNING_CLASSES = {
    "non-convergence": "bad",
    "stress over limit": "bad",
    "unloaded row": "note",
    "not available": "note",
    "note": "note",
}
#: Forces [N] and moments [N·m] at or below this size are solver round-off and print as 0.
FORCE_NOISE = 1e-9
#: Display unit of each load component: (name, SI unit, display unit, factor SI → display).
LOAD_DISPLAY = (
    ("F_x", "N", "kN", 1e-3),
    ("F_y", "N", "kN", 1e-3),
    ("F_z", "N", "kN", 1e-3),
    ("M_x", "N·m", "N·m", 1.0),
    ("M_y", "N·m", "N·m", 1.0),
)
#: Display unit of each displacement component.
DISPLACEMENT_DISPLAY = (
    ("u_x", "µm", 1e6),
    ("u_y", "µm", 1e6),
    ("u_z", "µm", 1e6),
    ("θ_x", "mrad", 1e3),
    ("θ_y", "mrad", 1e3),
)


# ---------------------------------------------------------------------------------------------
# Formatting helpers.
# ---------------------------------------------------------------------------------------------
def _e(text) -> str:
    return _html.escape(str(text), quote=True)


def fmt(value, digits: int = 4, factor: float = 1.0, tiny: float = 0.0) -> str:
    """A number for display (``factor`` converts from SI); masked, None, NaN or ±inf → ``—``.

    ``|value| <= tiny`` (SI, e.g. :data:`FORCE_NOISE`) and display values below 1e-12 print as 0.
    """
    if value is None or value is np.ma.masked:
        return "—"
    try:
        v = float(value)
    except (TypeError, ValueError):
        return _e(value)
    if not math.isfinite(v):
        return "—"
    x = 0.0 if abs(v) <= tiny else v * factor
    return f"{(x if abs(x) > 1e-12 else 0.0) + 0.0:.{digits}g}"


_NUMBER = re.compile(r"^(—|[-+]?[\d.]+(e[-+]?\d+)?(…[-+]?[\d.]+(e[-+]?\d+)?)?|\d+/\d+)$")


def _td(i: int, cell, left: int) -> str:
    aligned = i < left or not _NUMBER.match(str(cell))
    return f"<td{' class=l' if aligned else ''}>{cell}</td>"


def _table(headers, rows, left: int = 1, cls: str = "") -> str:
    """HTML table; the first ``left`` columns and every non-numeric cell left-aligned.

    Cells are already-escaped HTML strings.
    """
    head = "".join(f"<th{' class=l' if i < left else ''}>{h}</th>" for i, h in enumerate(headers))
    body = "".join("<tr>" + "".join(_td(i, c, left) for i, c in enumerate(r)) + "</tr>" for r in rows)
    attr = f' class="{cls}"' if cls else ""
    return f"<table{attr}><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _figure_html(fig, alt: str, caption: str) -> str:
    if fig is None:
        return ""
    width, height = (int(v * plots.DPI + 0.5) for v in fig.get_size_inches())
    return (
        f'<figure><img alt="{_e(alt)}" width="{width}" height="{height}" src="{plots.data_uri(fig)}">'
        f"<figcaption>{_e(caption)}</figcaption></figure>"
    )


def _badge(ok: bool, yes: str = "converged", no: str = "NOT converged") -> str:
    return f'<span class="badge {"ok" if ok else "bad"}">{_e(yes if ok else no)}</span>'


def warning_kind(message: str) -> str:
    """Category label of a warning message (:data:`WARNING_KINDS`; ``"note"`` when none matches)."""
    low = message.lower()
    for label, phrases in WARNING_KINDS:
        if any(p in low for p in phrases):
            return label
    return "note"


def case_warnings(result, rating, case: int) -> list[str]:
    """Warnings of one case: non-convergence (from ``result``) and the rating's warnings."""
    out = []
    converged = bool(result.converged[case])
    if not converged:
        out.append(
            f"did not converge: {result.reason[case] or 'no reason given'} — loads shown are not an "
            "equilibrium"
        )
    if rating is not None:
        for w in rating.warnings[case]:
            if converged or "did not converge" not in w:
                out.append(w)
    return out


def _warning_list(messages) -> str:
    if not messages:
        return '<p><span class="badge ok">no warnings</span></p>'
    items = []
    for m in messages:
        kind = warning_kind(m)
        cls = WARNING_CLASSES.get(kind, "warn")
        items.append(f'<li><span class="badge {cls}">{_e(kind)}</span> {_e(m)}</li>')
    return f'<ul class="warnings">{"".join(items)}</ul>'
