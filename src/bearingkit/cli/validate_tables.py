"""Rich tables of ``bearingkit validate``: the per-paper summary, the case rows, the not-computable list.

Faces only: the counts come from :func:`bearingkit.validation.registry.summarize`.
"""

from __future__ import annotations

from rich.table import Table

_STATUS_STYLE = {
    "pass": "[green]pass[/]",
    "calibrated": "[cyan]calibrated[/]",
    "known": "[yellow]known[/]",
    "FAIL": "[red]FAIL[/]",
    "diagnostic": "[dim]diagnostic[/]",
}


def summary_table(summaries, with_diagnostics: bool) -> Table:
    """One line per paper and one for the literature group."""
    t = Table(title="bearingkit validate: predictions passing / total, per paper")
    cols = ("group", "predictions passing", "calibrations", "deviations", "FAIL", "not computable")
    cols += ("diagnostics",) if with_diagnostics else ()
    for col in cols:
        t.add_column(col, justify="left" if col == "group" else "right")
    for s in summaries:
        row = [
            f"{s.group}: {s.title}",
            f"{s.passing} / {s.predictions}",
            f"{s.calibrations_met} / {s.calibrations}" if s.calibrations else "0",
            str(s.deviations),
            str(s.failures),
            str(s.not_computable) if s.group.startswith("seed") else "-",
        ]
        if with_diagnostics:
            row.append(str(s.diagnostics))
        t.add_row(*row)
    t.caption = (
        "Only predictions count as passes. A calibration is the published number a stated constant was "
        "identified on; deviations are predictions (or calibrations) that miss their tolerance for a stated "
        "cause. --all adds the diagnostics (derived values, numbers printed twice, alternative models); "
        "--table lists the cases."
    )
    return t


def case_table(results) -> Table:
    """The row table: one line per case."""
    t = Table(title=f"bearingkit validate: {len(results)} cases")
    for col in ("id", "role", "unit", "published", "computed", "rel. error", "tol.", "status"):
        t.add_column(col, justify="left" if col in ("id", "role") else "right")
    for r in results:
        status = _STATUS_STYLE[r.status] + (f" {r.error}" if r.error else "")
        t.add_row(
            r.case.id,
            r.case.role,
            r.case.unit,
            f"{r.case.published:.6g}",
            f"{r.computed:.6g}",
            f"{r.rel_error:+.3%}",
            f"{r.case.tolerance:.1%}",
            status,
        )
    return t


def not_computable_table(items) -> Table:
    """Published numbers of the papers that cannot be computed, with the reason."""
    t = Table(title="published numbers that cannot be computed")
    for col in ("id", "published", "why"):
        t.add_column(col)
    for i in items:
        t.add_row(i.id, i.published, i.why)
    return t
