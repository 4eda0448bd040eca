"""Start-up of the command line (issue 42): ``--help``, a warm one-case analysis, the cold first answer.

Each line is the best of N runs of a fresh process (wall time), with its CPU time, its ratio to a bare
``python -c pass`` of the same interpreter, and the 1-minute load average when it ran (the machine is
shared: the load says how far the wall time is from an idle machine's):

- ``python -c pass``: the interpreter alone (the floor);
- ``bearingkit --help``: target < 0.3 s;
- ``analyze 6205 --load Fr=2kN --json``, warm: the compiled core built (``bearingkit compile`` first),
  Python's byte code cached; target < 1 s;
- the same, cold first answer: an empty compiled-core cache (``NUMBA_CACHE_DIR`` an empty folder, no
  background build), as right after ``pip install``; target < 10 s.

Also alone: ``python -m benchmarks.bench_startup [--quick]``.
"""

from __future__ import annotations

import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ANALYZE = ["analyze", "6205", "--load", "Fr=2kN", "--json"]


def _bearingkit() -> list[str]:
    script = Path(sys.executable).parent / "bearingkit"
    return [str(script)] if script.is_file() else [sys.executable, "-m", "bearingkit"]


def _time(argv, env=None, repeat=3) -> tuple[float, float, float]:
    """(best wall [s], CPU of that run [s], load average after) over ``repeat`` fresh processes."""
    best = (float("inf"), 0.0)
    for _ in range(repeat):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        wall = time.perf_counter() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        best = min(best, (wall, cpu))
    return best[0], best[1], os.getloadavg()[0]


def run(quick: bool = False) -> list[dict]:
    repeat = 3 if quick else 7
    env = {**os.environ, "BEARINGKIT_BACKGROUND_COMPILE": "0"}
    # An installed package has its byte code compiled (pip does it); a shell that sets
    # PYTHONDONTWRITEBYTECODE would make every run compile bearingkit's ~140 modules again.
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    bk = _bearingkit()
    subprocess.run([*bk, "compile", "--quiet"], env=env, check=True)  # the warm lines need the core built
    subprocess.run([*bk, *ANALYZE], env=env, stdout=subprocess.DEVNULL, check=True)  # byte code cached
    floor, floor_cpu, load = _time([sys.executable, "-c", "pass"], env, repeat)
    out = [
        {
            "name": "startup: python -c pass (the floor)",
            "value": floor,
            "unit": "s",
            "note": f"CPU {floor_cpu:.3f} s; load {load:.2f}",
        }
    ]

    def line(name, argv, target, run_env, n=repeat):
        wall, cpu, load = _time(argv, run_env, n)
        out.append(
            {
                "name": name,
                "value": wall,
                "unit": "s",
                "target": f"< {target}",
                "note": f"{wall / floor:.0f}x python -c pass; CPU {cpu:.2f} s; load {load:.2f}",
            }
        )

    line("startup: bearingkit --help", [*bk, "--help"], 0.3, env)
    line("startup: analyze 6205 one case, warm", [*bk, *ANALYZE], 1.0, env)
    cold = tempfile.mkdtemp(prefix="bearingkit-cold-cache-")
    try:
        cold_env = {**env, "NUMBA_CACHE_DIR": cold}
        cold_env.pop("BEARINGKIT_NUMBA_BASE", None)
        name = "startup: analyze 6205, cold first answer (empty core cache)"
        line(name, [*bk, *ANALYZE], 10.0, cold_env, 1)
    finally:
        shutil.rmtree(cold, ignore_errors=True)
    return out


if __name__ == "__main__":
    for r in run(quick="--quick" in sys.argv):
        print(f"{r['name']:62s} {r['value']:7.3f} s  target {r.get('target', '-'):7s} {r['note']}")
