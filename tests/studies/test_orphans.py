"""SIGKILL of a ``--workers 2`` study leaves no worker running (issue 24, item 7).

The audit found the pool's workers still running over a minute after their parent was killed with
``kill -9`` (they finished the chunks they had queued). Every pool worker now exits as soon as its
parent is gone (``executors.exit_with_parent``).
"""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import psutil
import pytest

HERE = Path(__file__).resolve().parent

STUDY = """
[study]
name = "orphan_probe"
design = "factorial"
evaluator = "slow_counter"
chunk_size = 1

[[factors]]
name = "x"
levels = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]
"""


@pytest.mark.slow  # spawns a study and its two workers: ~10-20 s on the shared 2-core machine
def test_kill_9_of_the_parent_leaves_no_worker(tmp_path):
    study = tmp_path / "study.toml"
    study.write_text(STUDY)
    log = tmp_path / "calls.log"
    env = {
        **os.environ,
        "PYTHONPATH": os.pathsep.join([str(HERE), os.environ.get("PYTHONPATH", "")]),
        "BK_CALL_LOG": str(log),
        "BK_WORKERS_ONLY": "1",  # the probe's chunks in the parent are neither logged nor slow
        "BK_SLEEP": "3",  # every chunk takes 3 s: the workers are busy when the parent dies
    }
    cmd = [sys.executable, "-m", "bearingkit.studies", str(study), "--out", str(tmp_path / "out")]
    cmd += ["--workers", "2", "--no-progress", "--allow-plugin", "bk_study_helpers:SLOW"]
    proc = subprocess.Popen(cmd, env=env)
    children = []
    try:
        deadline = time.monotonic() + 90
        while time.monotonic() < deadline:  # both workers are inside a chunk
            if log.exists() and len(log.read_text().split()) >= 2:
                break
            time.sleep(0.05)
        else:
            raise AssertionError("the workers never started a chunk")
        children = psutil.Process(proc.pid).children(recursive=True)
        assert len(children) >= 2
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(timeout=10)
        _gone, alive = psutil.wait_procs(children, timeout=5)
        assert not alive, f"{len(alive)} worker process(es) outlived their killed parent"
    finally:  # whatever happened, leave nothing of this test running
        for p in [*children, proc]:
            try:
                p.kill()
            except (psutil.NoSuchProcess, ProcessLookupError):
                pass
