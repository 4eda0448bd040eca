"""``python -m bearingkit.studies FILE [--scheduler ADDRESS] [--workers N] [--resume] [--out DIR]
[--allow-plugin MODULE:ATTR]``.

SI units in every written table (units in the column names). :func:`run_cli` is what the
``bearingkit study`` command calls; it runs the study (:func:`bearingkit.studies.run.runner.run_study`),
streams chunks to ``DIR/chunks`` and writes, in ``DIR``:

- ``results.parquet`` and ``results.csv`` — every case with its outputs;
- designs with levels and a response: ``main_effects.csv``, ``range.csv``, ``main_effects.png``,
  ``range.png``;
- levels × samples designs (``[monte_carlo]``): ``point_statistics.csv`` (mean, std, min, max and
  quantiles of every output per design point) and, with a response, ``point_statistics.png`` and
  ``range_std.csv`` (range analysis of the per-point standard deviation);
- optimisations: ``pareto.csv``, ``selections.csv``, ``pareto.png``;
- ``summary.json`` — the run statistics, the study's fingerprint and the files of the set.

The outputs are published as one set (``.outputs/<run>/`` behind the link ``current``; the names
above are links into it): a kill leaves the previous complete set or the new one, never a mix.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from pathlib import Path

from bearingkit.errors import (
    RUN_INTERRUPTED_EXIT,
    SHORT_SOURCE_CHARS,
    InputError,
    RunInterrupted,
    error_line,
    os_reason,
    quote,
    shown,
)


def run_cli(
    file,
    scheduler: str | None = None,
    workers: int | None = None,
    resume: bool = False,
    out=None,
    progress: bool | None = None,
    echo=print,
    allow_plugins=(),
    allowed_paths=(),
):
    """Run the study in ``file`` and write its outputs; returns the StudyResult.

    Parameters
    ----------
    file : path
        Study TOML file.
    scheduler : str or None
        Dask scheduler address (``tcp://host:8786``) → Dask executor.
    workers : int or None
        Local workers: > 1 → a process pool of that many processes (with ``scheduler`` ignored).
    resume : bool
        Continue a killed run in ``out`` (chunks already there are not recomputed).
    out : path or None
        Output directory (default ``study-<name>`` in the current directory). It must be new, empty
        or a study's folder; the run locks it, and writes and deletes only its own files in it.
    allow_plugins : sequence of str
        Evaluator plugins ``"package.module:attribute"`` the study file may name (the explicit opt-in
        of ``--allow-plugin``; a file alone can name only built-in and installed evaluators).
    allowed_paths : sequence of path
        Folders the study's ``bearing`` may lie in beyond the study's own folder and its project's
        folder above it (``--allow-path``; :func:`bearingkit.io.reading.confined_path`).

    Notes
    -----
    Everything that can refuse the study (the file, the evaluator, the bearing file, the cases) is
    checked before ``out`` is created: a refused study leaves no folder. The final files are published
    as one set (:func:`bearingkit.studies.run.publish.publish`).
    """
    from concurrent.futures.process import BrokenProcessPool

    from bearingkit.studies import evaluators
    from bearingkit.studies.definition.load import load_study
    from bearingkit.studies.run.cases import plan_study
    from bearingkit.studies.run.executors import make_executor
    from bearingkit.studies.run.probe import probe_study
    from bearingkit.studies.run.publish import publish
    from bearingkit.studies.run.runner import run_study
    from bearingkit.studies.run.store import ParquetStore

    for spec in allow_plugins:
        evaluators.allow_plugin(spec)
    check_workers(workers)
    check_scheduler(scheduler)
    d = load_study(file, allowed_paths)
    plan = plan_study(d)
    probe_study(plan, workers or 1)  # output names checked and the work estimated, before any write
    out = Path(out or f"study-{d.name}")
    store = ParquetStore(out)
    store.lock(d.name, notify=echo)
    try:
        executor = make_executor(workers=workers, scheduler=scheduler)
        try:
            res = run_study(d, executor=executor, store=store, resume=resume, progress=progress, plan=plan)
            publish(out, _writers(res, plan.fingerprint, echo))
        except (BrokenProcessPool, OSError) as exc:
            raise _interrupted(exc, store, out) from exc
        finally:
            executor.close()
    except BaseException:
        store.discard_if_unused()
        raise
    finally:
        store.close()
    s = res.stats
    echo(
        f"{d.name}: {len(res.results)} cases, {s['computed']} chunks computed, {s['reused']} reused, "
        f"{s['seconds']:.1f} s on {s['executor']} → {out}"
    )
    if s.get("discarded"):
        echo(f"{s['discarded']} chunk file(s) in {out} were not this study's (or damaged): recomputed")
    return res


def _interrupted(exc: BaseException, store, out: Path) -> RunInterrupted:
    """A run stopped by a killed worker process or an operating-system error (a full disk) → one line
    saying what happened, what is kept and how to continue (the finished chunks stay valid: each was
    written whole, stamped with the study's fingerprint). The system's reason is given without the
    path of the temporary file it names: the line must keep room for the folder and the remedy."""
    if not isinstance(exc, OSError):  # a process pool broken by a worker's death
        what = "a worker process ended before its chunk was done (killed, or out of memory)"
    else:
        what = os_reason(exc)
    kept = len(store.finished_files())
    return RunInterrupted(
        f"the study stopped: {what}; {kept} finished chunk{'s' if kept != 1 else ''} "
        f"{'are' if kept != 1 else 'is'} kept in {shown(out, SHORT_SOURCE_CHARS)}: run the same command "
        "again with --resume"
    )


def check_workers(workers) -> None:
    """``--workers N``: at least 1 and at most the machine's cores (each worker is a process of a few
    hundred MB solving with one thread: more workers than cores only add memory; 12 on 2 cores
    took 2.5 GB)."""
    if workers is None:
        return
    import os

    cores = os.cpu_count() or 1
    if not 1 <= workers <= cores:
        raise InputError(
            f"--workers ({workers}) must lie in 1 … {cores}, the cores of this machine (each worker is "
            "one process solving on one core)"
        )
    import multiprocessing

    if workers > 1 and multiprocessing.current_process().daemon:
        # a daemonic process (a multiprocessing pool's worker, the fuzz's workers) may not start
        # processes: the pool failed after the probe with Python's AssertionError
        raise InputError(
            f"--workers ({workers}) starts worker processes, which this process cannot: it is itself a "
            "daemonic worker process; give --workers 1, or --scheduler ADDRESS for a Dask cluster"
        )


#: A Dask scheduler address: scheme, host and port (Dask's own schemes over a network).
SCHEDULER_ADDRESS = re.compile(r"^(tcp|tls|ws|wss)://(\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9.-]{1,253}):[0-9]{1,5}$")


def check_scheduler(address) -> None:
    """``--scheduler ADDRESS``: ``tcp://host:port`` (or tls, ws, wss), checked before Dask sees it."""
    if address is None:
        return
    match = SCHEDULER_ADDRESS.match(address)
    if match is None or not 0 < int(address.rsplit(":", 1)[1]) < 65536:
        raise InputError(
            f"--scheduler ({quote(address)}) must be a Dask scheduler address such as tcp://host:8786 "
            "(tcp, tls, ws or wss; a port in 1 … 65535)"
        )


def _bearing_of(file, allowed_paths=()) -> str:
    """The bearing a ``--list-*`` request is about: FILE itself, or the ``bearing`` of a study FILE.

    FILE is read by the bounded reader (:func:`bearingkit.io.reading.load_toml`: a regular file of at
    most 1 MiB, UTF-8, nesting bounded) and the bearing it names is confined like a study's
    (:func:`bearingkit.io.reading.confined_path`)."""
    from bearingkit.io.reading import confined_path, load_toml
    from bearingkit.studies.generic.evaluator import is_designation

    text = str(file)
    if is_designation(text):
        return text
    path = Path(text)
    data = load_toml(path)
    study = data.get("study")
    if not isinstance(study, dict):
        return str(path.resolve())
    bearing = study.get("bearing")
    if not isinstance(bearing, str):
        raise InputError(
            f"{path}: study.bearing: missing; --list-outputs needs a bearing file or a designation"
        )
    if is_designation(bearing, path.parent):
        return bearing
    try:
        return str(confined_path(bearing, path.parent, "study.bearing", allowed_paths))
    except InputError as exc:
        raise InputError(f"{path}: {exc}") from None


def list_outputs(file, allowed_paths=()) -> list[tuple[str, str, str]]:
    """(name, SI unit, description) of every output the generic evaluator offers for FILE.

    FILE is a bearing file, a designation, or a study file (its ``bearing`` is used).
    """
    from bearingkit.io.loader import from_dict
    from bearingkit.studies.generic import quantities
    from bearingkit.studies.generic.evaluator import load_bearing

    source = _bearing_of(file, allowed_paths)
    bearing = from_dict(load_bearing(source)[0], source)
    return [(q.name, q.unit, q.description) for q in quantities.catalogue(bearing).values()]


#: Column heads of :func:`list_factors`.
FACTOR_COLUMNS = ("path", "unit", "kind", "value in the file (SI)", "text levels")


def list_factors(file, allowed_paths=()) -> list[tuple[str, str, str, str, str]]:
    """(path, SI unit, kind, nominal value, the names a text path takes) of every factor path of FILE
    (as :func:`list_outputs`)."""
    from bearingkit.io.loader import from_dict
    from bearingkit.studies.generic.evaluator import _paths as paths_of
    from bearingkit.studies.generic.evaluator import load_bearing

    source = _bearing_of(file, allowed_paths)
    bearing = from_dict(load_bearing(source)[0], source)
    out = []
    for p in paths_of(bearing).values():
        if p.nominal is None:
            nominal = ""
        elif isinstance(p.nominal, float):
            nominal = f"{p.nominal:.6g}"  # 1.5e-05, not 1.4999999999999999e-05
        else:
            nominal = repr(p.nominal)
        out.append((p.path, p.unit, p.kind, nominal, "|".join(p.choices or ())))
    return out


def print_table(rows, head, echo=print) -> None:
    """Rows of text as aligned columns."""
    widths = [max(len(str(r[i])) for r in [head, *rows]) for i in range(len(head))]
    for r in [head, *rows]:
        echo("  ".join(str(c).ljust(w) for c, w in zip(r, widths, strict=True)).rstrip())


def _named(row) -> str:
    """A factor of a range table by name, its short label in parentheses when it has one."""
    return row.factor if row.label == row.factor else f"{row.factor} ({row.label})"


def _dimensions(d) -> dict:
    """Factor name → physical dimension (for the plots' display units)."""
    from bearingkit.studies.definition.load import evaluator_of

    return {name: f.dimension for name, f in evaluator_of(d).factors.items()}


def _writers(res, fingerprint: str, echo) -> dict:
    """Output name → function writing it (summary.json last: it lists the others with their sizes)."""
    from bearingkit.studies.results import analysis

    d = res.definition
    w = {
        "results.parquet": lambda p: res.results.to_parquet(p, index=False),
        "results.csv": lambda p: res.results.to_csv(p, index=False),
    }
    if "range" in res.analysis:
        labels = {f.name: f.label or f.name for f in d.factors}
        w["main_effects.csv"] = lambda p: res.analysis["main_effects"].to_csv(p, index=False)
        w["range.csv"] = lambda p: res.analysis["range"].to_csv(p, index=False)
        dims = _dimensions(d)
        w["main_effects.png"] = lambda p: analysis.plot_main_effects(
            res.analysis["main_effects"], p, d.response, labels, dims
        )
        w["range.png"] = lambda p: analysis.plot_range(res.analysis["range"], p, d.response)
        ranking = " > ".join(_named(r) for r in res.analysis["range"].itertuples())
        echo(f"sensitivity ranking of {d.response}: {ranking}")
    if "point_statistics" in res.analysis:
        table = res.analysis["point_statistics"]
        w["point_statistics.csv"] = lambda p: table.to_csv(p, index=False)
        if d.response:
            w["point_statistics.png"] = lambda p: analysis.plot_point_statistics(
                table, d.response, p, d.monte_carlo.quantiles
            )
        if "range_std" in res.analysis:
            w["range_std.csv"] = lambda p: res.analysis["range_std"].to_csv(p, index=False)
            ranking = " > ".join(_named(r) for r in res.analysis["range_std"].itertuples())
            echo(f"sensitivity ranking of the scatter (std) of {d.response}: {ranking}")
        echo(f"{len(table)} design points x {d.monte_carlo.per_point} draws → point_statistics.csv")
    if "statistics" in res.analysis:
        w["statistics.csv"] = lambda p: res.analysis["statistics"].to_csv(p, index=False)
        echo(f"{len(res.results)} draws → statistics.csv (mean, std, min, max, quantiles of every output)")
    if d.plots:
        from bearingkit.studies.results import figures

        dims = _dimensions(d)
        quantiles = d.monte_carlo.quantiles if d.monte_carlo is not None else d.quantiles
        for i, spec in enumerate(d.plots, 1):
            missing = [n for n in (spec.x, spec.series, *spec.y) if n is not None and n not in res.results]
            if missing:
                raise InputError(
                    f"{d.source}: plots[{i - 1}] names {missing}, which the results do not have; they have "
                    f"{list(res.results.columns)}"
                )
            w[f"plot_{i}.png"] = lambda p, spec=spec: figures.plot(spec, res.results, p, dims, quantiles)
    if res.pareto is not None:
        w["pareto.csv"] = lambda p: res.pareto.to_csv(p, index=False)
        w["selections.csv"] = lambda p: res.selections.to_csv(p, index=False)
        if len(d.objectives) >= 2:
            w["pareto.png"] = lambda p: analysis.plot_pareto(
                res.pareto, [o.output for o in d.objectives], p, res.selections
            )
        echo(f"Pareto front: {len(res.pareto)} points; selections: {list(res.selections['selection'])}")

    def summary(path):
        files = {n: (path.parent / n).stat().st_size for n in w if n != "summary.json"}
        data = {"study": d.name, "cases": len(res.results), **res.stats, "fingerprint": fingerprint}
        data["files"] = files
        path.write_text(json.dumps(data, indent=1, default=str), encoding="utf-8")

    w["summary.json"] = summary
    return w


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m bearingkit.studies", description="Run a design study.")
    p.add_argument("file")
    p.add_argument("--list-outputs", action="store_true", help="list the outputs of FILE's bearing")
    p.add_argument("--list-factors", action="store_true", help="list the factor paths of FILE's bearing")
    p.add_argument("--scheduler", default=None, help="Dask scheduler address, e.g. tcp://host:8786")
    p.add_argument("--workers", type=int, default=None, help="local worker processes")
    p.add_argument("--resume", action="store_true", help="continue a killed run in --out")
    p.add_argument("--out", default=None, help="output directory")
    p.add_argument("--no-progress", action="store_true")
    p.add_argument(
        "--allow-plugin",
        action="append",
        default=[],
        metavar="MODULE:ATTR",
        help="let the study use this evaluator plugin (a study file alone cannot import code)",
    )
    p.add_argument(
        "--allow-path",
        action="append",
        default=[],
        metavar="DIR",
        help="a folder the study's bearing file may lie in (beyond the study's folder and the one above)",
    )
    a = p.parse_args(argv)
    try:
        if a.list_outputs or a.list_factors:
            if a.list_outputs:
                print_table(list_outputs(a.file, a.allow_path), ("output", "unit", "meaning"))
            if a.list_factors:
                print_table(list_factors(a.file, a.allow_path), FACTOR_COLUMNS)
            return 0
        run_cli(
            a.file,
            a.scheduler,
            a.workers,
            a.resume,
            a.out,
            progress=False if a.no_progress else None,
            allow_plugins=a.allow_plugin,
            allowed_paths=a.allow_path,
        )
    except InputError as exc:
        print(error_line(exc, a.file), file=sys.stderr)
        return 2
    except RunInterrupted as exc:
        print(error_line(exc, a.file), file=sys.stderr)
        return RUN_INTERRUPTED_EXIT
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
