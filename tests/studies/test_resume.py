"""A study killed with SIGKILL mid-run resumes: nothing finished is recomputed, nothing is lost."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import pytest

from bearingkit.studies import definition as sd
from bearingkit.studies import evaluators
from bearingkit.studies.runner import run_study

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
