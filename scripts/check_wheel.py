"""Build the sdist and wheel, install the wheel into a fresh venv and use it from outside the source tree.

``make test`` runs this first (``python scripts/check_wheel.py``), so a data file, a static asset or a
sub-package left out of the package fails CI. The wheel is installed WITHOUT extras: what a user gets
from ``pip install bearingkit`` must answer ``analyze``, ``rating``, the Python API and
``validate --quick``, and an extra's command must say which extra to install.

Each step prints one line (``wheel-check: …``) with its time; the last says the smoke test passed and
from which directory. Exit 1 on the first failure, with the command and its output. SI inside.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def say(message: str) -> None:
    print(f"wheel-check: {message}", flush=True)


def run(argv, cwd, env=None, expect=0) -> subprocess.CompletedProcess:
    out = subprocess.run([str(a) for a in argv], cwd=cwd, env=env, capture_output=True, text=True)
    if out.returncode != expect:
        say(f"FAILED (exit {out.returncode}, expected {expect}): {' '.join(map(str, argv))}")
        sys.stdout.write(out.stdout[-4000:] + "\n" + out.stderr[-4000:] + "\n")
        raise SystemExit(1)
    return out


def main() -> int:
    t_all = time.perf_counter()
    # A venv of the core is ~650 MB: in memory (/dev/shm) writing and deleting it takes seconds, on a
    # busy disk minutes.
    shm = Path("/dev/shm")
    fast = shm.is_dir() and os.access(shm, os.W_OK) and shutil.disk_usage(shm).free > 2e9
    work = Path(tempfile.mkdtemp(prefix="bearingkit-wheel-", dir=shm if fast else None))
    try:
        dist, venv, elsewhere = work / "dist", work / "venv", work / "elsewhere"
        elsewhere.mkdir()
        t0 = time.perf_counter()
        run([sys.executable, "-m", "build", "--outdir", dist, ROOT], cwd=ROOT)
        wheel = next(dist.glob("bearingkit-*.whl"))
        sdist = next(dist.glob("bearingkit-*.tar.gz"))
        say(f"built {wheel.name} ({wheel.stat().st_size / 1e6:.1f} MB) and {sdist.name} "
            f"({time.perf_counter() - t0:.0f} s)")  # fmt: skip

        t0 = time.perf_counter()
        run([sys.executable, "-m", "venv", "--without-pip", venv], cwd=work)
        py = venv / "bin" / "python"
        # This interpreter's pip installs into the new venv (no ensurepip); its cache makes it quick, and
        # no byte-compiling of every installed module (half of pip's time; imports compile what they use).
        run([sys.executable, "-m", "pip", "--python", py, "install", "-q", "--no-compile", wheel], cwd=work)
        say(f"installed {wheel.name} (no extras) in a fresh venv {venv} ({time.perf_counter() - t0:.0f} s)")

        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
        env["PATH"] = f"{venv / 'bin'}{os.pathsep}{env.get('PATH', '')}"
        env["BEARINGKIT_BACKGROUND_COMPILE"] = "0"  # no build left running behind the check
        bk = venv / "bin" / "bearingkit"
        t0 = time.perf_counter()
        where = run([py, "-c", "import bearingkit; print(bearingkit.__file__)"], elsewhere, env).stdout
        where = where.strip()
        if not where.startswith(str(venv)):
            say(f"FAILED: bearingkit imported from {where}, not from the venv")
            return 1
        out = run([bk, "--help"], elsewhere, env).stdout
        assert "analyze" in out and "compile" in out, out
        data = json.loads(run([bk, "analyze", "6205", "--load", "Fr=2kN", "--json"], elsewhere, env).stdout)
        assert data["cases"][0]["converged"] is True, data["cases"][0]
        api = (
            "import bearingkit as bk\n"
            "assert 'analyze' in dir(bk) and 'analyze' in bk.__all__\n"
            "a = bk.analyze('6205', load={'F_x': '2 kN'}, speed='3000 rpm')\n"
            "life = a.rating.to_dict(0)['system']\n"
            "assert life['L10h_h'] > 1000, life\n"
            "assert 'L10h' in a._repr_html_()\n"
            "print(round(life['L10h_h']))\n"
        )
        hours = run([py, "-c", api], elsewhere, env).stdout.strip()
        # exit 1 on an unexplained failure, as validate without --json
        cases = json.loads(run([bk, "validate", "--quick", "--json"], elsewhere, env).stdout)
        known = sum(1 for c in cases if not c["passed"] and c["known_deviation"])
        quick = f"{len(cases)} cases, {sum(c['passed'] for c in cases)} pass, {known} known deviations"
        static = (
            "from importlib.resources import files\n"
            "static = files('bearingkit') / 'app' / 'static'\n"
            "names = sorted(p.name for p in static.iterdir())\n"
            "assert {'index.html', 'app.js', 'app.css'} <= set(names), names\n"
            "from bearingkit.paths import examples_dir\n"
            "assert (examples_dir() / 'studies' / 'seed000_l9.toml').is_file(), examples_dir()\n"
            "print(len(names), examples_dir())\n"
        )
        n_static, examples = run([py, "-c", static], elsewhere, env).stdout.split()
        rows = json.loads(run([bk, "catalogue", "62*", "--json"], elsewhere, env).stdout)
        assert len(rows) > 10 and all(r["C_catalogue_N"] for r in rows[:5]), rows[:2]
        missing = run([bk, "study", Path(examples) / "studies" / "seed000_l9.toml"], elsewhere, env, expect=2)
        line = missing.stderr.strip()
        assert "\n" not in line and "pip install 'bearingkit[studies]'" in line, line
        say(
            f"smoke test passed from {elsewhere} ({time.perf_counter() - t0:.0f} s): --help; analyze 6205 "
            f"converged; API L10h = {hours} h; validate --quick: {quick}; {n_static} static files of the "
            f"app; catalogue 62*: {len(rows)} rows; examples at {examples}; study without [studies]: "
            f"'{line[:60]}…'"
        )
        say(f"done in {time.perf_counter() - t_all:.0f} s")
        return 0
    finally:
        shutil.rmtree(work, ignore_errors=True)
        shutil.rmtree(ROOT / "build", ignore_errors=True)  # setuptools' staging folder


if __name__ == "__main__":
    raise SystemExit(main())
