"""Notebook display: the compact HTML tables behind ``_repr_html_`` of an Analysis, a shaft, a study.

Jupyter shows an object by its ``_repr_html_``; :class:`~bearingkit.pipeline.Analysis`,
:class:`~bearingkit.systems.shaft.shaft_analysis.ShaftAnalysis` and
:class:`~bearingkit.studies.run.cases.StudyResult` build theirs from :func:`html_table`: a title, one
table whose column headers carry the units, the warnings (always shown, as every face shows them) and
the notes (folded). Values come in SI and are shown in the units engineers read (kN, MPa, h, r/min);
:func:`number` rounds them to four significant digits. Plain HTML with inline styles only: no script,
no external resource, every text escaped.
"""

from __future__ import annotations

import math
from html import escape

#: Rows shown of a long table (a study's results); the rest is counted.
MAX_ROWS = 12


def number(x, scale: float = 1.0, digits: int = 4) -> str:
    """``x * scale`` with ``digits`` significant digits; ``—`` for None, NaN or a masked value."""
    if x is None or x is ... or getattr(x, "mask", False) is True:
        return "—"
    try:
        value = float(x) * scale
    except (TypeError, ValueError):
        return escape(str(x))
    if not math.isfinite(value):
        return "—"
    return f"{value + 0.0:.{digits}g}"


def html_table(
    title: str,
    columns: list[str],
    rows: list[list[str]],
    *,
    warnings: list[str] = (),
    notes: list[str] = (),
    footer: str = "",
) -> str:
    """One titled table with warnings and folded notes.

    Parameters
    ----------
    title : str
        Plain text (escaped here).
    columns : list of str
        Headers, units included (``"L10h [h]"``); escaped here.
    rows : list of list of str
        Cells already formatted (:func:`number`) or plain text; every cell is escaped unless it is
        the output of :func:`number` (digits, signs, ``—``) — all are escaped alike, which leaves those
        unchanged.
    warnings : list of str
        Shown under the table, each on its own line (``case: text``).
    notes : list of str
        Shown folded (``<details>``).
    footer : str
        A line under the table (plain text).
    """
    th = "".join(f'<th style="text-align:right;padding:2px 8px">{escape(c)}</th>' for c in columns)
    body = "".join(
        "<tr>"
        + "".join(
            f'<td style="text-align:{"left" if j == 0 else "right"};padding:2px 8px">{escape(str(cell))}</td>'
            for j, cell in enumerate(row)
        )
        + "</tr>"
        for row in rows
    )
    parts = [
        '<div class="bearingkit">',
        f"<strong>{escape(title)}</strong>",
        f'<table style="border-collapse:collapse"><thead><tr>{th}</tr></thead><tbody>{body}</tbody></table>',
    ]
    if footer:
        parts.append(f"<div>{escape(footer)}</div>")
    if warnings:
        items = "".join(f"<li>{escape(w)}</li>" for w in warnings)
        parts.append(f'<div style="color:#a15c00"><b>warnings ({len(warnings)})</b><ul>{items}</ul></div>')
    else:
        parts.append("<div>no warnings</div>")
    if notes:
        items = "".join(f"<li>{escape(n)}</li>" for n in notes)
        parts.append(f"<details><summary>notes ({len(notes)})</summary><ul>{items}</ul></details>")
    parts.append("</div>")
    return "".join(parts)
