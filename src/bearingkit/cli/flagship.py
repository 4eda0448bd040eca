"""The flagship demonstration (``bearingkit run-flagship``, ``make run``): a list of sections.

SI inside; every section returns a rich renderable for the terminal and a JSON-ready dict (units in
keys). Sections share one :class:`FlagshipContext`: the seed-000 composite turntable bearing
(Tian et al. 2025, doi:10.3390/machines13070588) loaded once from ``examples/seed000_composite.toml``
and its flagship load case (F_a = F_r = 3 kN, M = 600 N·m, 5 r/min) solved once; friction and
ratings come from ONE :class:`~bearingkit.pipeline.Analysis` held by the context.

Adding a section is one function decorated with :func:`flagship_section`. The HTML report of that
analysis is written last; the context then holds every section's dict in ``ctx.data`` (title → dict).
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from rich.console import Group
from rich.markup import escape
from rich.table import Table
from rich.text import Text

from bearingkit.paths import examples_dir

#: The example files (the repository's, or the copy a wheel installs: bearingkit.paths).
EXAMPLES_DIR = examples_dir()
#: The flagship input file and load case (seed 000, sections 6.1.4–6.1.5: F_a = F_r = 3 kN, M = 600 N·m).
FLAGSHIP_FILE = EXAMPLES_DIR / "seed000_composite.toml"
FLAGSHIP_CASE = "flagship"
#: Ball load of the flagship Hertz summary [N] (one axial ball of seed 000 at 1 kN).
FLAGSHIP_HERTZ_LOAD = 1000.0
#: Lubricant of the flagship friction (seed 000 gives none; ``bearingkit.lubricants`` documents it).
FLAGSHIP_LUBRICANT = "seed000_grease_assumed"
#: Reliability of the flagship ratings [-] (L10: ISO 281 a1 = 1).
FLAGSHIP_RELIABILITY = 0.9
#: Temperature of the flagship friction [°C]: that of the seed-000 Table 3 calibration (room-temperature
#: rig, :mod:`bearingkit.papers.tian2025.validation`), not the 40 °C the example file assumes for its cases.
FLAGSHIP_TEMPERATURE = 25.0
#: Where run-flagship writes the HTML report (relative to the working directory).
FLAGSHIP_REPORT = Path("out") / "report.html"


@dataclass
class FlagshipContext:
    """What flagship sections share: ONE :class:`~bearingkit.pipeline.Analysis` of the flagship case.

    Attributes
    ----------
    file : Path
    case : str
    data : dict
        Title → JSON-ready dict of every section already run (filled by :func:`run_sections`).
    shown : set of str
        Warnings a section printed (:meth:`unseen`): the load distribution and the rating share them.
    """

    file: Path = FLAGSHIP_FILE
    case: str = FLAGSHIP_CASE
    _analysis: object = None
    data: dict = field(default_factory=dict)
    shown: set = field(default_factory=set)

    def unseen(self, warnings) -> list[str]:
        """The ``warnings`` no earlier section printed; marks them printed."""
        out = [w for w in dict.fromkeys(warnings) if w not in self.shown]
        self.shown.update(out)
        return out

    @property
    def analysis(self):
        """The flagship Analysis: the seed-000 friction data of the validation (Table 3 calibration).

        :mod:`bearingkit.papers.tian2025.calibration` supplies the cage mass, the viscosity factor (1,
        base oil) and the roller sliding coefficient identified once on Table 3 run 1; lubricant
        :data:`FLAGSHIP_LUBRICANT` at :data:`FLAGSHIP_TEMPERATURE`, the temperature of that calibration;
        L10 (reliability 0.9).
        """
        if self._analysis is None:
            from bearingkit.papers.tian2025 import calibration as seed000
            from bearingkit.pipeline import analyze

            self._analysis = analyze(
                self.file,
                cases=[self.case],
                lubricant=FLAGSHIP_LUBRICANT,
                temperature=FLAGSHIP_TEMPERATURE,
                reliability=FLAGSHIP_RELIABILITY,
                friction_options={
                    "cage_mass": seed000.CAGE_MASS,
                    "viscosity_factor": seed000.VISCOSITY_FACTOR,
                    "roller_sliding": seed000.ROLLER_SLIDING,
                },
            )
        return self._analysis

    @property
    def bearing(self):
        """The flagship :class:`~bearingkit.io.loader.BearingInput`, only the flagship case."""
        return self.analysis.input

    @property
    def result(self):
        """The solved flagship case (QuasiStaticResult, one case)."""
        return self.analysis.statics


@dataclass(frozen=True)
class Section:
    """A flagship section: a title and ``run(ctx) -> (rich renderable, JSON-ready dict)``."""

    title: str
    run: Callable


#: Sections printed by ``bearingkit run-flagship``, in order (see :func:`flagship_section`).
FLAGSHIP_SECTIONS: list[Section] = []


def flagship_section(title: str):
    """Register ``fn(ctx: FlagshipContext) -> (renderable, dict)`` as a run-flagship section."""

    def register(fn):
        FLAGSHIP_SECTIONS.append(Section(title, fn))
        return fn

    return register


@flagship_section("Hertz contact of one seed-000 axial ball")
def _hertz_section(ctx: FlagshipContext):
    from bearingkit.io.export import hertz_ball_summary
    from bearingkit.materials import e_reduced

    g = ctx.bearing.geometry
    f = g.groove_curvature
    data = hertz_ball_summary(
        FLAGSHIP_HERTZ_LOAD,
        g.ball_diameter,
        g.pitch_diameter_axial_ball,
        math.pi / 2,
        f,
        f,
        e_reduced(ctx.bearing.material, ctx.bearing.material),
    )
    data.update(
        element_diameter_m=g.ball_diameter,
        pitch_diameter_m=g.pitch_diameter_axial_ball,
        contact_angle_rad=math.pi / 2,
        conformity=f,
        material=ctx.bearing.material.name,
    )
    table = Table(
        title=escape(
            f"ball Ø {g.ball_diameter * 1e3:g} mm, α = 90°, f = {f:g}, "
            f"d_m = {g.pitch_diameter_axial_ball * 1e3:g} mm, {ctx.bearing.material.name}, "
            f"Q = {FLAGSHIP_HERTZ_LOAD / 1e3:g} kN"
        )
    )
    for col in ("contact", "a mm", "b mm", "δ µm", "p_max MPa", "κ = a/b"):
        table.add_column(col, justify="left" if col == "contact" else "right", no_wrap=True)
    for side in ("inner", "outer"):
        s = data[side]
        table.add_row(
            side,
            f"{s['semi_major_m'] * 1e3:.4f}",
            f"{s['semi_minor_m'] * 1e3:.4f}",
            f"{s['deflection_m'] * 1e6:.3f}",
            f"{s['max_pressure_Pa'] / 1e6:.0f}",
            f"{s['ellipticity']:.3f}",
        )
    return table, data


@flagship_section("Load distribution of the seed-000 composite bearing (flagship case)")
def _load_distribution_section(ctx: FlagshipContext):
    from bearingkit.cli.tables import case_table, warnings_text

    data = ctx.analysis.statics_dict()["cases"][0]
    return Group(case_table(data), warnings_text(ctx.unseen(data["warnings"]))), data


@flagship_section("Friction torque of the flagship case (seed-000 component model)")
def _friction_section(ctx: FlagshipContext):
    from bearingkit.cli.tables import friction_table
    from bearingkit.papers.tian2025 import calibration as seed000

    data = ctx.analysis.friction_dict("components")["cases"][0]
    data["calibration"] = (
        f"roller_sliding = {seed000.ROLLER_SLIDING} identified once on Tian et al. (2025) Table 3 run 1 "
        f"(bearingkit.papers.tian2025.calibration); viscosity_factor = {seed000.VISCOSITY_FACTOR:g} "
        "(base oil), cage mass and lubricant assumed there"
    )
    return Group(friction_table(data), Text(data["calibration"], style="dim")), data


@flagship_section("Load ratings and life of the flagship case (ISO 76, ISO 281, ISO/TS 16281)")
def _rating_section(ctx: FlagshipContext):
    from bearingkit.cli.tables import rating_table

    data = ctx.analysis.rating_dict()["cases"][0]
    notes = [Text(f"  warning: {w}", style="yellow") for w in ctx.unseen(data["warnings"])]
    return Group(rating_table(data), *notes), data


def run_sections(console, as_json: bool = False, report_path: Path | None = FLAGSHIP_REPORT) -> dict:
    """Run every section in order, print tables (or JSON on stdout), then write the HTML report.

    The report is the flagship Analysis's own (:meth:`bearingkit.pipeline.Analysis.report`); its path
    is announced on stderr (JSON mode) or on the console.
    """
    from bearingkit.io.export import to_json

    ctx = FlagshipContext()
    for i, section in enumerate(FLAGSHIP_SECTIONS, 1):
        renderable, data = section.run(ctx)
        ctx.data[section.title] = data
        if not as_json:
            console.rule(f"{i}. {section.title}")
            console.print(renderable)
    if as_json:
        sys.stdout.write(to_json(ctx.data) + "\n")
    if report_path is not None:
        a = ctx.analysis
        written = a.report(
            Path(report_path),
            title=f"bearingkit flagship — {a.input.model.name}",
            notes=[f"Flagship case of {a.input.source}: seed 000 (Tian et al. 2025), sections 6.1.4-6.1.5."],
        )
        message = f"report written to {written}"
        if as_json:
            sys.stderr.write(message + "\n")
        else:
            console.print(message, markup=False, highlight=False)
    return ctx.data
