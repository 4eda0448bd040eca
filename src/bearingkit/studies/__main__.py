"""``python -m bearingkit.studies FILE [--scheduler ADDRESS] [--workers N] [--resume] [--out DIR]
[--allow-plugin MODULE:ATTR]``.

SI units in every written table (units in the column names). :func:`run_cli` is what the
``bearingkit study`` command calls; it runs the study (:func:`bearingkit.studies.runner.run_study`),
streams chunks to ``DIR/chunks`` and writes, in ``DIR``:

- ``results.parquet`` and ``results.csv`` — every case with its outputs;
- designs with levels and a response: ``main_effects.csv``, ``range.csv``, ``main_effects.png``,
  ``range.png``;
- levels × samples designs (``[monte_carlo]``): ``point_statistics.csv`` (mean, std, min, max and
  quantiles of every output per design point) and, with a response, ``point_statistics.png`` and
  ``range_std.csv`` (range analysis of the per-point standard deviation);
- optimisations: ``pareto.csv``, ``selections.csv``, ``pareto.png``;
- ``summary.json`` — the run statistics.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from bearingkit.errors import InputError


def run_cli(
    file,
    scheduler: str | None = None,
    workers: int | None = None,
    resume: bool = False,
    out=None,
    progress: bool | None = None,
    echo=print,
    allow_plugins=(),
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
        Output directory (default ``study-<name>`` in the current directory).
    allow_plugins : sequence of str
        Evaluator plugins ``"package.module:attribute"`` the study file may name (the explicit opt-in
        of ``--allow-plugin``; a file alone can name only built-in and installed evaluators).
    """
    from bearingkit.studies import analysis, evaluators
    from bearingkit.studies.definition import load_study
    from bearingkit.studies.executors import make_executor
    from bearingkit.studies.runner import run_study
    from bearingkit.studies.store import ParquetStore

    for spec in allow_plugins:
        evaluators.allow_plugin(spec)
    d = load_study(file)
    out = Path(out or f"study-{d.name}")
    out.mkdir(parents=True, exist_ok=True)
    executor = make_executor(workers=workers, scheduler=scheduler)
    try:
        res = run_study(d, executor=executor, store=ParquetStore(out), resume=resume, progress=progress)
    finally:
        executor.close()
    res.results.to_parquet(out / "results.parquet", index=False)
    res.results.to_csv(out / "results.csv", index=False)
    if "range" in res.analysis:
        res.analysis["main_effects"].to_csv(out / "main_effects.csv", index=False)
        res.analysis["range"].to_csv(out / "range.csv", index=False)
        labels = {f.name: f.label or f.name for f in d.factors}
        analysis.plot_main_effects(res.analysis["main_effects"], out / "main_effects.png", d.response, labels)
        analysis.plot_range(res.analysis["range"], out / "range.png", d.response)
        ranking = " > ".join(f"{r.label}" for r in res.analysis["range"].itertuples())
        echo(f"sensitivity ranking of {d.response}: {ranking}")
    if "point_statistics" in res.analysis:
        table = res.analysis["point_statistics"]
        table.to_csv(out / "point_statistics.csv", index=False)
        if d.response:
            analysis.plot_point_statistics(
                table, d.response, out / "point_statistics.png", d.monte_carlo.quantiles
            )
        if "range_std" in res.analysis:
            res.analysis["range_std"].to_csv(out / "range_std.csv", index=False)
            ranking = " > ".join(f"{r.label}" for r in res.analysis["range_std"].itertuples())
            echo(f"sensitivity ranking of the scatter (std) of {d.response}: {ranking}")
        echo(f"{len(table)} design points x {d.monte_carlo.per_point} draws → point_statistics.csv")
    if res.pareto is not None:
        res.pareto.to_csv(out / "pareto.csv", index=False)
        res.selections.to_csv(out / "selections.csv", index=False)
        if len(d.objectives) >= 2:
            analysis.plot_pareto(
                res.pareto, [o.output for o in d.objectives], out / "pareto.png", res.selections
            )
        echo(f"Pareto front: {len(res.pareto)} points; selections: {list(res.selections['selection'])}")
    (out / "summary.json").write_text(json.dumps({"study": d.name, **res.stats}, indent=1, default=str))
    s = res.stats
    echo(
        f"{d.name}: {len(res.results)} cases, {s['computed']} chunks computed, {s['reused']} reused, "
        f"{s['seconds']:.1f} s on {s['executor']} → {out}"
    )
    return res


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m bearingkit.studies", description="Run a design study.")
    p.add_argument("file")
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
    a = p.parse_args(argv)
    try:
        run_cli(
            a.file,
            a.scheduler,
            a.workers,
            a.resume,
            a.out,
            progress=False if a.no_progress else None,
            allow_plugins=a.allow_plugin,
        )
    except InputError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
