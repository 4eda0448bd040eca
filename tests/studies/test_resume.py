"""A study killed with SIGKILL mid-run resumes: nothing finished is recomputed, nothing is lost."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import pytest

from bearingkit.studies import evaluators
from bearingkit.studies.definition import load as sd
from bearingkit.studies.run.runner import run_study

HERE = Path(__file__).resolve().parent
N_CHUNKS = 10
STUDY = f"""
[study]
name = "resume_probe"
design = "factorial"
evaluator = "slow_counter"
chunk_size = 4

[[factors]]
name = "x"
levels = [{", ".join(str(0.5 * i) for i in range(4 * N_CHUNKS))}]
"""


def _calls(log: Path) -> list[float]:
    return [float(s) for s in log.read_text().split()] if log.exists() else []


def test_kill_and_resume(tmp_path, monkeypatch):
    study = tmp_path / "study.toml"
    study.write_text(STUDY)
    out = tmp_path / "out"
    log1, log2 = tmp_path / "calls1.log", tmp_path / "calls2.log"
    env = {
        **os.environ,
        "PYTHONPATH": os.pathsep.join([str(HERE), os.environ.get("PYTHONPATH", "")]),
        "BK_CALL_LOG": str(log1),
        "BK_SLEEP": "0.3",
    }
    proc = subprocess.Popen(
        [
            *(sys.executable, "-m", "bearingkit.studies", str(study), "--out", str(out), "--no-progress"),
            *("--allow-plugin", "bk_study_helpers:SLOW"),
        ],
        env=env,
    )
    chunk_dir = out / "chunks"
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        if chunk_dir.exists() and len(list(chunk_dir.glob("chunk-*.parquet"))) >= 3:
            break
        time.sleep(0.02)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait(timeout=10)
    assert proc.returncode == -signal.SIGKILL
    finished = {int(p.stem.split("-")[1]) for p in chunk_dir.glob("chunk-*.parquet")}
    assert 3 <= len(finished) < N_CHUNKS, "the kill must land mid-run"

    monkeypatch.syspath_prepend(str(HERE))
    monkeypatch.setattr(evaluators, "ALLOWED_PLUGINS", {})
    evaluators.allow_plugin("bk_study_helpers:SLOW")
    monkeypatch.setenv("BK_CALL_LOG", str(log2))
    monkeypatch.setenv("BK_SLEEP", "0")
    with pytest.warns(UserWarning, match="recovered the stale lock of study 'resume_probe'"):
        resumed = run_study(sd.load_study(study), store=out, resume=True, progress=False)
    # nothing finished is recomputed: the resumed run called the evaluator once per missing chunk
    recomputed = {int(x / 0.5) // 4 for x in _calls(log2)}
    assert recomputed == set(range(N_CHUNKS)) - finished
    assert len(_calls(log2)) == N_CHUNKS - len(finished)
    assert resumed.stats["computed"] == N_CHUNKS - len(finished) and resumed.stats["reused"] == len(finished)
    # nothing is lost: the results equal an uninterrupted run's
    monkeypatch.delenv("BK_CALL_LOG")
    fresh = run_study(sd.load_study(study), progress=False)
    pd.testing.assert_frame_equal(resumed.results, fresh.results)
    assert len(resumed.results) == 4 * N_CHUNKS


GENERIC_STUDY = """
[study]
name = "resume_generic"
design = "monte_carlo"
bearing = "{bearing}"
load_case = "radial_4kN"
samples = {samples}
seed = 11
chunk_size = 1
outputs = ["u_x_m", "balls_max_load_N", "L10r_rev", "converged"]

[[factors]]                      # every draw its own clearance: one build and solve per chunk
name = "geometry.clearance_radial"
distribution = "uniform"
low = "0 um"
high = "40 um"

[[factors]]
name = "load_cases.radial_4kN.F_x"
distribution = "normal"
mean = "4 kN"
std = "0.5 kN"
"""


@pytest.mark.slow  # ~11 s; test_kill_and_resume above stays in make test
def test_kill_and_resume_the_generic_evaluator(tmp_path, monkeypatch):
    """kill -9 of `bearingkit study` on a bearing file, then --resume: only the missing chunks run."""
    from bearingkit.studies.generic.evaluator import GenericModel

    n_chunks = 100
    study = tmp_path / "study.toml"
    bearing = HERE.parents[1] / "examples" / "dgbb_6209.toml"
    (tmp_path / bearing.name).write_text(bearing.read_text())  # beside the study: a study reads no farther
    study.write_text(GENERIC_STUDY.format(bearing=bearing.name, samples=n_chunks))
    out = tmp_path / "out"
    proc = subprocess.Popen(
        [sys.executable, "-m", "bearingkit.studies", str(study), "--out", str(out), "--no-progress"],
    )
    chunk_dir = out / "chunks"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        if chunk_dir.exists() and len(list(chunk_dir.glob("chunk-*.parquet"))) >= 3:
            break
        time.sleep(0.01)
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait(timeout=10)
    assert proc.returncode == -signal.SIGKILL
    finished = {int(p.stem.split("-")[1]) for p in chunk_dir.glob("chunk-*.parquet")}
    assert 3 <= len(finished) < n_chunks, "the kill must land mid-run"
    stamps = {p.name: p.stat().st_mtime_ns for p in chunk_dir.glob("chunk-*.parquet")}

    calls = []
    real = GenericModel.columns  # what a study's workers call (issue 34: numpy columns, no DataFrame)

    def counting(self, cases):
        calls.append(len(cases))
        return real(self, cases)

    monkeypatch.setattr(GenericModel, "columns", counting)
    with pytest.warns(UserWarning, match="recovered the stale lock of study 'resume_generic'"):
        resumed = run_study(sd.load_study(study), store=out, resume=True, progress=False)
    assert len(calls) == n_chunks - len(finished)  # nothing finished is recomputed
    assert resumed.stats["computed"] == n_chunks - len(finished) and resumed.stats["reused"] == len(finished)
    for name, stamp in stamps.items():  # the finished chunk files are the killed run's, untouched
        assert (chunk_dir / name).stat().st_mtime_ns == stamp
    fresh = run_study(sd.load_study(study), progress=False)
    pd.testing.assert_frame_equal(resumed.results, fresh.results)
    assert resumed.results["converged"].all()
