"""The final outputs of a study are replaced as one set (issue 24, item 7).

The audit killed runs during their final write: 10 of 12 kills left a truncated ``results.csv``
(2,012-37,377 of 40,000 rows) beside the previous ``summary.json``. Now every reader of
``OUT/results.csv``, ``OUT/summary.json`` … sees the previous complete set or the new one.
"""

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import pytest

from bearingkit.studies.__main__ import run_cli
from bearingkit.studies.run import publish as outputs
from bearingkit.studies.run.publish import OUTPUTS_DIR, publish

#: ZDT1 Monte Carlo studies: 33 columns, so results.csv takes a noticeable time to write.
ROWS = {"run_a": 40_000, "run_b": 30_000}


def _toml(name: str) -> str:
    factors = "".join(
        f'[[factors]]\nname = "x{i}"\ndistribution = "uniform"\nlow = 0\nhigh = 1\n' for i in range(1, 31)
    )
    return (
        f'[study]\nname = "{name}"\ndesign = "monte_carlo"\nevaluator = "zdt1"\nsamples = {ROWS[name]}\n'
        f"seed = {len(name) + ROWS[name]}\nchunk_size = 10000\n{factors}"
    )


def _consistent(out: Path) -> str:
    """The study whose complete set ``out`` shows (asserts that every file belongs to it)."""
    summary = json.loads((out / "summary.json").read_text())
    study = summary["study"]
    assert summary.get("cases", ROWS[study]) == ROWS[study]
    assert len(pd.read_csv(out / "results.csv")) == ROWS[study], "results.csv is not the summary's"
    assert len(pd.read_parquet(out / "results.parquet")) == ROWS[study]
    return study


def test_publish_keeps_the_old_set_when_a_write_fails(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    publish(
        out, {"results.csv": lambda p: p.write_text("a\n1\n"), "summary.json": lambda p: p.write_text("{}")}
    )

    def broken(path):
        path.write_text("a\n2\n")
        raise OSError("disk full")

    with pytest.raises(OSError, match="disk full"):
        publish(out, {"results.csv": lambda p: p.write_text("a\n2\n3\n"), "summary.json": broken})
    assert (out / "results.csv").read_text() == "a\n1\n" and (out / "summary.json").read_text() == "{}"
    publish(out, {"results.csv": lambda p: p.write_text("a\n4\n"), "pareto.csv": lambda p: p.write_text("p")})
    assert (out / "results.csv").read_text() == "a\n4\n" and (out / "pareto.csv").read_text() == "p"
    assert not (out / "summary.json").exists(), "a name the new set lacks is gone with the old set"
    assert len(list((out / OUTPUTS_DIR).iterdir())) == 1, "older and unfinished sets are removed"


def test_without_symbolic_links_every_file_is_replaced_whole(tmp_path, monkeypatch):
    """The fallback (Windows without the link privilege): files atomic one by one, summary last."""
    monkeypatch.setattr(outputs, "symlinks_work", lambda d: False)
    out = tmp_path / "out"
    out.mkdir()
    order = []

    def writer(text):
        def write(path):
            order.append(path.name)
            path.write_text(text)

        return write

    publish(out, {"summary.json": writer("{}"), "results.csv": writer("a\n1\n"), "pareto.csv": writer("p")})
    assert order[-1].startswith(".summary.json.") and not (out / OUTPUTS_DIR).exists()
    publish(out, {"results.csv": writer("a\n2\n"), "summary.json": writer('{"n": 2}')})
    assert sorted(p.name for p in out.iterdir()) == ["results.csv", "summary.json"]
    assert not any(p.is_symlink() for p in out.iterdir()) and (out / "results.csv").read_text() == "a\n2\n"


def test_an_interrupted_final_write_leaves_the_previous_set(tmp_path, monkeypatch):
    """In-process stand-in for a kill: the CSV writer dies half-way through the second run."""
    for name in ROWS:
        (tmp_path / f"{name}.toml").write_text(_toml(name).replace("samples = 40000", "samples = 400"))
    (tmp_path / "run_b.toml").write_text(_toml("run_b").replace("samples = 30000", "samples = 300"))
    out = tmp_path / "out"
    run_cli(tmp_path / "run_a.toml", out=out, progress=False, echo=lambda s: None)
    before = {n: (out / n).read_bytes() for n in ("results.csv", "summary.json", "results.parquet")}
    real = pd.DataFrame.to_csv

    def dies_half_way(self, path, *args, **kwargs):
        real(self.iloc[: len(self) // 2], path, *args, **kwargs)
        raise KeyboardInterrupt  # what SIGINT raises; SIGKILL is the subprocess test below

    monkeypatch.setattr(pd.DataFrame, "to_csv", dies_half_way)
    with pytest.raises(KeyboardInterrupt):
        run_cli(tmp_path / "run_b.toml", out=out, progress=False, echo=lambda s: None)
    assert {n: (out / n).read_bytes() for n in before} == before


@pytest.mark.slow  # four study processes killed with SIGKILL: ~30-60 s on the shared machine
def test_kill_9_during_the_final_write_leaves_a_complete_set(tmp_path):
    for name in ROWS:
        (tmp_path / f"{name}.toml").write_text(_toml(name))
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "bearingkit.studies", "--out", str(out), "--no-progress"]
    subprocess.run([*cmd, str(tmp_path / "run_a.toml")], check=True, timeout=300, capture_output=True)
    assert _consistent(out) == "run_a"
    for delay in (0.0, 0.05, 0.2, 0.5):
        csv = (out / "results.csv").resolve()
        mark = csv.stat().st_mtime_ns, csv.stat().st_size
        proc = subprocess.Popen([*cmd, str(tmp_path / "run_b.toml")], stderr=subprocess.DEVNULL)
        deadline = time.monotonic() + 300
        while proc.poll() is None and time.monotonic() < deadline:
            # the final write has begun: a staging folder appeared, or (a writer in place) the csv changed
            staging = (out / OUTPUTS_DIR).is_dir() and any((out / OUTPUTS_DIR).glob("*.partial"))
            try:
                now = (out / "results.csv").resolve().stat()
                changed = (now.st_mtime_ns, now.st_size) != mark
            except FileNotFoundError:
                changed = True
            if staging or changed:
                break
            time.sleep(0.002)
        time.sleep(delay)
        if proc.poll() is None:
            os.kill(proc.pid, signal.SIGKILL)
        proc.wait(timeout=30)
        assert _consistent(out) in ROWS
