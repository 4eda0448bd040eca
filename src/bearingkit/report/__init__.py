"""Reports: one self-contained HTML file per analysis (inputs, load distribution, friction, ratings).

SI inside (m, N, Pa, rad, rad/s, N·m; temperatures in °C as in :mod:`bearingkit.lubricants`). Faces
never recompute physics: the report reads one :class:`bearingkit.pipeline.Analysis` (statics,
friction, rating, warnings, notes), which orchestrates everything.

- :func:`render_analysis` — the HTML report of an Analysis; registered as the pipeline's ``"html"``
  renderer, so ``analysis.report(path)`` calls it;
- :func:`report_file` — ``bearingkit report FILE -o out/report.html``: analyse a file, write its report;
- :func:`build_report` (:mod:`bearingkit.report.html`) — the HTML text from result objects, and
  :func:`write_report` — atomic write (temporary file + rename, nothing left behind on error).

>>> from bearingkit.report import report_file
>>> report_file("examples/seed000_composite.toml", "out/report.html")   # doctest: +SKIP
"""

from __future__ import annotations

import dataclasses
import math
import os
from pathlib import Path

import numpy as np

from bearingkit.errors import InputError
from bearingkit.pipeline import RENDERERS, analyze
from bearingkit.report.html import build_report

__all__ = [
    "build_report",
    "describe_operating_point",
    "render_analysis",
    "report_file",
    "write_report",
]

_RPM = 30.0 / math.pi
#: File mode of a written report (rw-r--r--; the temporary file is created private, then opened up).
REPORT_MODE = 0o644


def describe_operating_point(analysis) -> str:
    """One line on the operating point of an :class:`~bearingkit.pipeline.Analysis` for the run notes."""

    def listed(values, factor=1.0):
        vals = np.atleast_1d(np.asarray(values, dtype=float)) * factor
        uniq = np.unique(vals)
        return f"{uniq[0]:.4g}" if len(uniq) == 1 else ", ".join(f"{v:.4g}" for v in vals)

    op = analysis.operating
    lube = "none given" if op.lubricant is None else op.lubricant.name
    if getattr(analysis, "thermal", None) is not None:
        return (
            f"Operating point: {op.rotating} ring at {listed(op.speed, _RPM)} r/min (sign = direction of "
            f"rotation); temperature FOUND by the heat balance: {listed(op.temperature)} °C (see each case's "
            f"thermal equilibrium); lubricant {lube}."
        )
    extra = "".join(f"; {k} {v:g}" for k, v in analysis.friction_options.items() if isinstance(v, float))
    return (
        f"Operating point: {op.rotating} ring at {listed(op.speed, _RPM)} r/min (sign = direction of "
        f"rotation); temperature {listed(op.temperature)} °C; lubricant {lube}{extra}."
    )


#: Row kinds the component friction model covers (tapered rows: the seed-001 model behind the same name).
_COMPONENT_KINDS = {"ball", "cylindrical", "tapered"}


@dataclasses.dataclass(frozen=True)
class WholeBearingFriction:
    """The friction the report draws (torques in N·m, power in W, arrays (C,)): a catalogue model's is
    one "row", the whole bearing, with no split between the rings; the component model's has its rows
    and the torque on each ring."""

    total: np.ndarray
    components: dict
    by_row: dict
    references: tuple
    model: str = ""
    torque_inner: np.ndarray | None = None
    torque_outer: np.ndarray | None = None
    power_loss: np.ndarray | None = None
    why: str = ""


def _shown(outcome) -> WholeBearingFriction:
    native = outcome.native
    if hasattr(native, "by_row"):
        by_row, inner, outer = dict(native.by_row), native.torque_inner, native.torque_outer
    else:
        by_row, inner, outer = {"whole bearing": outcome.total}, None, None
    return WholeBearingFriction(
        outcome.total,
        dict(outcome.components),
        by_row,
        tuple(outcome.references),
        outcome.model,
        inner,
        outer,
        outcome.power_loss,
        outcome.why,
    )


def _report_friction(analysis):
    """The friction the report shows, and a run note: the analysis's model (by default the model of the
    bearing's kind, :func:`bearingkit.pipeline.friction.choice.choose`); when the component model was asked
    for and does not cover the bearing (a spherical roller, self-aligning ball or needle row), the first
    catalogue model that applies, for the whole bearing."""
    friction = analysis.friction
    if friction is not None:
        return _shown(friction), []
    kinds = {r.kind for r in analysis.input.model.rows}
    if analysis.friction_model != "components" or kinds <= _COMPONENT_KINDS:
        return None, []  # the model's note says why it was not computed
    from bearingkit.pipeline import FRICTION_MODELS

    models = ["skf", "palmgren"]
    if analysis.input.bearing_type.startswith("slewing_ring"):
        models = ["slewing"]  # the makers' formula is meant for slewing rings only
    for model in (m for m in models if m in FRICTION_MODELS):
        try:
            out = analysis.friction_by(model)
        except InputError:
            continue
        note = (
            f"friction: the component model does not apply here (its note says why); the report shows the "
            f"{model} catalogue model of the whole bearing"
        )
        return _shown(out), [note]
    return None, []


def render_analysis(analysis, path, *, title=None, notes=()) -> Path:
    """Write the HTML report of ``analysis`` to ``path`` (atomic); returns the path.

    Parameters
    ----------
    analysis : bearingkit.pipeline.Analysis
    path : str or Path
        Report file; parent folders are created.
    title : str, optional
    notes : sequence of str
        Extra run notes shown before the analysis's own.
    """
    from bearingkit.io.loader import MAX_REPORT_CASES

    analysis.input.check_cases(MAX_REPORT_CASES, "a report")  # before anything is computed
    native, friction_notes = _report_friction(analysis)
    op = analysis.operating
    shown = analysis.input.with_cases(  # the inputs table shows the speed and temperature analysed
        [
            dataclasses.replace(
                c,
                speed=float(op.speed[i]),
                temperature=float(op.temperature[i]) if op.temperature_given[i] else c.temperature,
            )
            for i, c in enumerate(analysis.input.cases)
        ]
    )
    if op.lubricant is not None:  # the lubricant analysed (a --lubricant replaces the file's)
        shown = dataclasses.replace(shown, lubricant=op.lubricant)
    from bearingkit.report.html_operating import operating_html
    from bearingkit.report.subsurface import subsurface_section_html

    sub = analysis.statics_dict(subsurface=analysis.subsurface)
    statics = sub["cases"]
    lub = analysis.lubrication
    from bearingkit.report.ring_plots import structure_html

    extras = [
        [
            lambda number, c=c, i=i: operating_html(c, None if lub is None else lub.to_dict(i), number),
            *([lambda number, c=c: structure_html(c, number)] if analysis.flexible is not None else []),
        ]
        for i, c in enumerate(statics)
    ]
    html = build_report(
        shown,
        analysis.statics,
        friction=native,
        rating=analysis.rating,
        title=title,
        notes=[*notes, describe_operating_point(analysis), *friction_notes, *analysis.notes],
        warnings=analysis.warnings,
        load_diagram=analysis.load_diagram,
        case_extras=extras,
        duty_cycle=None if analysis.duty_cycle is None else analysis.duty_cycle.to_dict(),
        after_cases=[
            (
                "Below the surface",
                "subsurface",
                lambda number: subsurface_section_html(statics, sub["subsurface"], number),
            )
        ],
    )
    return write_report(path, html)


RENDERERS["html"] = render_analysis


def report_file(path_to_toml, out_path, *, speed=None, temperature=None, **options) -> Path:
    """Analyse an input file (friction and ratings where supported) and write its HTML report.

    Parameters
    ----------
    path_to_toml : str or Path
        Input file (docs/input-format.md).
    out_path : str or Path
        Report file; written atomically, parent folders created.
    speed : float [rad/s] or str, optional
        Speed of the rotating ring replacing the load cases' speeds.
    temperature : float [°C] or str, optional
        Operating temperature replacing the load cases' temperatures.
    **options
        Further keywords of :func:`bearingkit.pipeline.analyze` (``lubricant``, ``contamination`` …).

    Returns
    -------
    Path
        The written report. Bad input raises :class:`~bearingkit.errors.InputError` (one line) before
        anything is written.
    """
    return analyze(path_to_toml, speed=speed, temperature=temperature, **options).report(out_path)


def write_report(path, html: str) -> Path:
    """Write ``html`` to ``path`` atomically (temporary file in the same folder, then rename).

    Missing parent folders are created. On any error nothing is left behind (no partial file, no
    temporary file, no folder this call created) and :class:`~bearingkit.errors.InputError` names the
    path and the cause in one line. Returns the written path.
    """
    from bearingkit.io.export import write_atomic

    def write(tmp: Path) -> None:
        with open(tmp, "w", encoding="utf-8", errors="xmlcharrefreplace") as fh:
            fh.write(html)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, REPORT_MODE)

    return write_atomic(path, write, "report")
