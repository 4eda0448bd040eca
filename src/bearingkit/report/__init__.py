"""Reports: one self-contained HTML file per run (inputs, load distribution, friction, ratings).

SI inside (m, N, Pa, rad, rad/s, N·m; temperatures in °C as in :mod:`bearingkit.lubricants`). Faces
never recompute physics: :func:`build_report` only reads result objects. The helpers below call the
public analysis API (solve, :func:`~bearingkit.analysis.friction.friction_torque`,
:func:`~bearingkit.analysis.rating.rate`) the way the command line does:

- :func:`report_file` — ``bearingkit report FILE -o out/report.html``: load, solve, friction and rating
  where the bearing supports them, write the report;
- :func:`write_flagship_report` — the report of ``make run`` from the CLI's ``FlagshipContext``;
- :func:`run_friction`, :func:`run_rating` — friction and rating of a loaded file with notes on what
  was assumed or skipped (shown in the report);
- :func:`build_report` (:mod:`bearingkit.report.html`) — the HTML text from result objects, and
  :func:`write_report` — atomic write (temporary file + rename, nothing left behind on error).

>>> from bearingkit.report import report_file
>>> report_file("examples/seed000_composite.toml", "out/report.html")   # doctest: +SKIP
"""

from __future__ import annotations

import dataclasses
import math
import os
import tempfile
from pathlib import Path

import numpy as np

from bearingkit.errors import InputError
from bearingkit.report.html import build_report

__all__ = [
    "DEFAULT_TEMPERATURE",
    "build_report",
    "describe_operating_point",
    "report_file",
    "run_friction",
    "run_rating",
    "write_flagship_report",
    "write_report",
]

#: Operating temperature [°C] used for friction when neither the load case nor the caller gives one:
#: the default of :class:`bearingkit.analysis.friction.OperatingPoint` (room temperature).
DEFAULT_TEMPERATURE = 25.0
_RPM = 30.0 / math.pi
#: File mode of a written report (rw-r--r--; the temporary file is created private, then opened up).
REPORT_MODE = 0o644


def _case_values(bearing, attr: str, override, default):
    """Per-case speed or temperature: ``override`` if given, else the load case's value, else ``default``."""
    if override is not None:
        return np.full(len(bearing.cases), float(override))
    return np.array([default if getattr(c, attr) is None else float(getattr(c, attr)) for c in bearing.cases])


def _merge_friction(parts, n_cases: int):
    """One FrictionResult from several, case ``c`` taken from the part whose mask holds ``c``."""
    from bearingkit.analysis.friction import FrictionResult

    first = parts[0][1]

    def pick(get):
        out = np.array(get(first), dtype=float, copy=True)
        for mask, fr in parts[1:]:
            out[mask] = np.asarray(get(fr))[mask]
        return out

    return FrictionResult(
        total=pick(lambda f: f.total),
        components={k: pick(lambda f, k=k: f.components[k]) for k in first.components},
        by_row={k: pick(lambda f, k=k: f.by_row[k]) for k in first.by_row},
        per_element={k: pick(lambda f, k=k: f.per_element[k]) for k in first.per_element},
        torque_inner=pick(lambda f: f.torque_inner),
        torque_outer=pick(lambda f: f.torque_outer),
        references=first.references,
    )


def describe_operating_point(op, temperature=None) -> str:
    """One line on a friction :class:`~bearingkit.analysis.friction.OperatingPoint` for the run notes.

    Parameters
    ----------
    op : OperatingPoint
        Speeds [rad/s] (shown in r/min), lubricant, temperature [°C], friction data.
    temperature : array_like, optional [°C]
        Per-case temperatures replacing ``op.temperature`` in the text.
    """

    def listed(values, factor=1.0):
        vals = np.atleast_1d(np.asarray(values, dtype=float)) * factor
        uniq = np.unique(vals)
        return f"{uniq[0]:.4g}" if len(uniq) == 1 else ", ".join(f"{v:.4g}" for v in vals)

    temps = op.temperature if temperature is None else temperature
    return (
        f"Friction: inner ring at {listed(op.speed_inner, _RPM)} r/min, outer ring at "
        f"{listed(op.speed_outer, _RPM)} r/min; temperature {listed(temps)} °C; lubricant "
        f"{op.lubricant.name}; viscosity factor {op.viscosity_factor:g}; cage mass {op.cage_mass:g} kg; "
        f"roughness {op.roughness_element * 1e6:g}/{op.roughness_raceway * 1e6:g} µm (element/raceway)."
    )


def run_friction(bearing, result, *, speed=None, temperature=None, **operating_point):
    """Friction torque of every load case, or None with the reason; the inner ring turns.

    Parameters
    ----------
    bearing : BearingInput
    result : QuasiStaticResult
        The solve of ``bearing.cases``.
    speed : float, optional [rad/s]
        Inner-ring speed for every case; default: each load case's ``speed`` (0 when absent: only the
        load-dependent part of the torque).
    temperature : float, optional [°C]
        Default: each load case's ``temperature``, else :data:`DEFAULT_TEMPERATURE`.
    **operating_point
        Further :class:`~bearingkit.analysis.friction.OperatingPoint` fields (``viscosity_factor``,
        ``cage_mass`` …).

    Returns
    -------
    (FrictionResult or None, list of str)
        The result and the notes for the report (assumptions, or why friction was skipped).
    """
    from bearingkit.analysis.friction import OperatingPoint, friction_torque

    if bearing.lubricant is None and "lubricant" not in operating_point:
        return None, ["Friction not computed: the input file gives no [lubricant]."]
    speeds = _case_values(bearing, "speed", speed, 0.0)
    temps = _case_values(bearing, "temperature", temperature, DEFAULT_TEMPERATURE)
    kw = {"lubricant": bearing.lubricant, **operating_point}
    parts = []
    try:
        for t in np.unique(temps):
            op = OperatingPoint(speed_inner=speeds, temperature=float(t), **kw)
            parts.append((temps == t, friction_torque(result, op)))
    except InputError as exc:
        return None, [f"Friction not computed: {exc}"]
    notes = [describe_operating_point(OperatingPoint(speed_inner=speeds, **kw), temperature=temps)]
    if np.any(speeds == 0):
        notes.append("Friction at zero speed: only the load-dependent (Coulomb-type) part of the torque.")
    return _merge_friction(parts, result.n_cases), notes


def run_rating(bearing, result, *, speed=None, **options):
    """Ratings, lives and static safety of every load case, or None with the reason.

    Parameters
    ----------
    bearing : BearingInput
    result : QuasiStaticResult
    speed : float, optional [rad/s]
        Relative speed for lives in hours; default: the load cases' speeds (lives in hours only when
        every case has a positive speed).
    **options
        Further keywords of :func:`bearingkit.analysis.rating.rate` (``rotating``, ``load_ratings`` …).

    Returns
    -------
    (RatingResult or None, list of str)
    """
    from bearingkit.analysis.rating import rate

    speeds = _case_values(bearing, "speed", speed, 0.0)
    notes = []
    if not np.all(speeds > 0):
        speeds = None
        notes.append("Ratings: no speed for every case, lives in hours are not given.")
    try:
        rating = rate(result, speed=speeds, **options)
    except InputError as exc:
        return None, [f"Ratings not computed: {exc}"]
    return rating, notes


def report_file(path_to_toml, out_path, *, speed=None, temperature=None) -> Path:
    """Load an input file, solve it, add friction and ratings where supported, write the HTML report.

    Parameters
    ----------
    path_to_toml : str or Path
        Input file (docs/input-format.md).
    out_path : str or Path
        Report file; written atomically, parent folders created.
    speed : float, optional [rad/s]
        Inner-ring speed replacing the load cases' speeds.
    temperature : float, optional [°C]
        Operating temperature replacing the load cases' temperatures.

    Returns
    -------
    Path
        The written report. Bad input raises :class:`~bearingkit.errors.InputError` (one line) before
        anything is written.
    """
    from bearingkit.io.loader import MAX_REPORT_CASES, load_file

    bearing = load_file(path_to_toml).check_cases(MAX_REPORT_CASES, "a report")
    if speed is not None or temperature is not None:
        cases = [
            dataclasses.replace(
                c,
                speed=c.speed if speed is None else float(speed),
                temperature=c.temperature if temperature is None else float(temperature),
            )
            for c in bearing.cases
        ]
        bearing = bearing.with_cases(cases)
    result = bearing.solve()
    friction, f_notes = run_friction(bearing, result)
    rating, r_notes = run_rating(bearing, result)
    html = build_report(bearing, result, friction=friction, rating=rating, notes=f_notes + r_notes)
    return write_report(out_path, html)


def _flagship_operating_point() -> dict:
    """Seed-000 friction data of the validation module (calibrated viscosity factor, cage mass)."""
    from bearingkit.validation import seed000_friction as s0f

    return {"viscosity_factor": s0f.VISCOSITY_FACTOR, "cage_mass": s0f.CAGE_MASS}


def write_flagship_report(ctx, path) -> Path:
    """Write the flagship (seed-000) report from the CLI's ``FlagshipContext``.

    Reads ``ctx.bearing`` (BearingInput of the flagship case) and ``ctx.result`` (its solve). Uses
    ``ctx.friction`` / ``ctx.rating`` when the context carries them (so the printed summary and the
    report agree); otherwise computes them here with the seed-000 friction data of
    :mod:`bearingkit.validation.seed000_friction` (calibrated viscosity factor, cage mass) at
    :data:`DEFAULT_TEMPERATURE`, the temperature of that calibration.
    """
    bearing, result = ctx.bearing, ctx.result
    notes = [f"Flagship case of {bearing.source}: seed 000 (Tian et al. 2025), sections 6.1.4-6.1.5."]
    friction = getattr(ctx, "friction", None)
    op = getattr(ctx, "operating_point", None)
    if friction is not None and op is not None:
        notes.append(describe_operating_point(op))
    if friction is None:
        friction, more = run_friction(
            bearing, result, temperature=DEFAULT_TEMPERATURE, **_flagship_operating_point()
        )
        notes += more
    rating = getattr(ctx, "rating", None)
    if rating is None:
        rating, more = run_rating(bearing, result)
        notes += more
    html = build_report(
        bearing,
        result,
        friction=friction,
        rating=rating,
        title=f"bearingkit flagship — {bearing.model.name}",
        notes=notes,
    )
    return write_report(path, html)


def write_report(path, html: str) -> Path:
    """Write ``html`` to ``path`` atomically (temporary file in the same folder, then rename).

    Missing parent folders are created. On any error nothing is left behind (no partial file, no
    temporary file, no folder this call created) and :class:`~bearingkit.errors.InputError` names the
    path and the cause in one line. Returns the written path.
    """
    path = Path(path)
    if path.exists() and path.is_dir():
        raise InputError(
            f"{path}: report path is a directory; give a file name such as {path / 'report.html'}"
        )
    created: list[Path] = []
    parent = path.parent
    tmp = None
    done = False
    try:
        missing = []
        p = parent
        while not p.exists():
            missing.append(p)
            p = p.parent
        for d in reversed(missing):
            d.mkdir()
            created.append(d)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=parent)
        with os.fdopen(fd, "w", encoding="utf-8", errors="xmlcharrefreplace") as fh:
            fh.write(html)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, REPORT_MODE)
        os.replace(tmp, path)
        done = True
    except OSError as exc:
        raise InputError(
            f"{path}: cannot write the report ({type(exc).__name__}: {exc.strerror or exc})".replace(
                "\n", " "
            )
        ) from None
    finally:
        if not done:
            if tmp is not None:
                Path(tmp).unlink(missing_ok=True)
            for d in reversed(created):
                try:
                    d.rmdir()
                except OSError:
                    pass
    return path
