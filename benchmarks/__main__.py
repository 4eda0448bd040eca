"""Run every benchmark and print one table: ``python -m benchmarks [--quick] [--json FILE]``.

SI units inside; times are printed in ms or s, throughputs in cases/s. All ratios come from one run.
Besides :mod:`benchmarks.bench_quasistatic`, every other ``benchmarks/bench_*.py`` module with a
``run(quick) -> list[dict]`` (keys ``name``, ``value``, ``unit``, ``target``) is run and appended.
"""

from __future__ import annotations

import argparse
import importlib
import json
import pkgutil
import traceback
from dataclasses import asdict
from pathlib import Path

from benchmarks.bench_quasistatic import Record, format_table, run

#: Units whose value should be at most the target (times); any other unit: at least the target.
LOWER_IS_BETTER = ("s", "ms")


def _as_record(entry: dict) -> Record:
    value, target = float(entry["value"]), entry.get("target")
    if target is None or target == "":
        return Record(entry["name"], value, entry.get("unit", ""), note=entry.get("note", ""))
    text = str(target).strip()
    target = float(text.lstrip("<>= "))
    lower = text.startswith("<") or (not text.startswith(">") and entry.get("unit") in LOWER_IS_BETTER)
    ratio = (target / value if value > 0 else float("inf")) if lower else (value / target if target else None)
    sense = "<=" if lower else ">="
    return Record(
        entry["name"], value, entry.get("unit", ""), f"{sense} {target:g}", ratio, entry.get("note", "")
    )


def other_benchmarks(quick: bool) -> list[Record]:
    """Records of the other ``bench_*`` modules (a failing module gives one line saying so)."""
    records = []
    for mod in sorted(pkgutil.iter_modules([str(Path(__file__).parent)]), key=lambda m: m.name):
        if not mod.name.startswith("bench_") or mod.name == "bench_quasistatic":
            continue
        try:
            module = importlib.import_module(f"benchmarks.{mod.name}")
            records += [_as_record(e) for e in module.run(quick=quick)]
        except Exception as exc:  # report, do not lose the other numbers
            traceback.print_exc()
            records.append(
                Record(f"{mod.name} FAILED", float("nan"), "", note=f"{type(exc).__name__}: {exc}")
            )
    return records


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats and cases (about 30 s)")
    parser.add_argument("--json", metavar="FILE", help="also write the records and machine info as JSON")
    args = parser.parse_args(argv)
    records, info = run(quick=args.quick)
    records += other_benchmarks(args.quick)
    print(format_table(records, info))
    if args.json:
        with open(args.json, "w", encoding="utf-8") as fh:
            json.dump({"machine": info, "records": [asdict(r) for r in records]}, fh, indent=2)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
