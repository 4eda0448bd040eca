"""A process pool reuses its workers and never outlives the command (issue 34).

``--workers 2`` had left processes running after the command ended. The pool now starts its workers
once, reuses them for every chunk (and every generation of an optimisation), ends them at close, and
kills them at once when chunks are still pending: after an error or Ctrl-C no worker goes on with
chunks nobody will read. (A parent killed with SIGKILL: ``test_orphans.py``.)
"""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import psutil
import pytest

from bearingkit.studies.run.executors import ProcessPoolExecutor

HERE = Path(__file__).resolve().parent

STUDY = """
[study]
name = "pool_probe"
design = "factorial"
evaluator = "slow_counter"
chunk_size = 1

[[factors]]
name = "x"
levels = [0, 1, 2, 3, 4, 5, 6, 7]
"""


def test_the_pool_reuses_its_workers_and_ends_them():
    from bk_study_helpers import pid_of

    ex = ProcessPoolExecutor(workers=2)
    try:
        first = {pid for _, pid in ex.map_unordered(pid_of, list(range(8)))}
        second = {pid for _, pid in ex.map_unordered(pid_of, list(range(8)))}
        workers = ex.worker_pids()
        assert len(workers) == 2 and first <= set(workers) and second <= set(workers)
        procs = [psutil.Process(p) for p in workers]
    finally:
        ex.close()
    _gone, alive = psutil.wait_procs(procs, timeout=10)
    assert not alive, "close() ends the workers"
    assert ex.worker_pids() == []


def _run_until_busy(tmp_path, extra_env):
    """Start `study --workers 2` and return (process, its children) once both workers are in a chunk."""
    study = tmp_path / "study.toml"
    study.write_text(STUDY)
    log = tmp_path / "calls.log"
    env = {
        **os.environ,
        "PYTHONPATH": os.pathsep.join([str(HERE), os.environ.get("PYTHONPATH", "")]),
        "BK_CALL_LOG": str(log),
        "BK_WORKERS_ONLY": "1",  # the probe's chunks in the parent are neither logged nor slow
        "BK_DONE_LOG": str(tmp_path / "done.log"),
        **extra_env,
    }
    cmd = [sys.executable, "-m", "bearingkit.studies", str(study), "--out", str(tmp_path / "out")]
    cmd += ["--workers", "2", "--no-progress", "--allow-plugin", "bk_study_helpers:SLOW"]
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 90
    while time.monotonic() < deadline:
        if log.exists() and len(log.read_text().split()) >= 2:
            return proc, psutil.Process(proc.pid).children(recursive=True)
        if proc.poll() is not None:
            break
        time.sleep(0.05)
    proc.kill()
    raise AssertionError(f"the workers never started a chunk: {proc.communicate()}")


@pytest.mark.slow  # a study command and its two workers, three times: ~5 s each quiet, 13-18 s loaded
@pytest.mark.parametrize("how", ["normal", "error", "interrupt"])
def test_no_worker_outlives_the_command(tmp_path, how):
    env = {"BK_SLEEP": "0.3" if how == "normal" else "5"}
    if how == "error":
        env["BK_FAIL_AT"] = "1.0"  # the second chunk raises after 0.5 s; the first takes 5 s
    proc, children = _run_until_busy(tmp_path, env)
    done = tmp_path / "done.log"
    try:
        assert len(children) >= 2
        if how == "interrupt":
            os.kill(proc.pid, signal.SIGINT)  # Ctrl-C, while both workers are inside a 5 s chunk
        t0 = time.monotonic()
        _out, err = proc.communicate(timeout=60)
        ended = time.monotonic() - t0
        _gone, alive = psutil.wait_procs(children, timeout=5)
        assert not alive, f"{len(alive)} process(es) outlived `study --workers 2` ({how})"
        if how == "normal":
            assert proc.returncode == 0, err
            assert len(done.read_text().split()) == 8
        else:  # the chunks in flight (5 s each) were abandoned, not waited for
            assert proc.returncode != 0
            assert not done.exists(), f"a worker finished a chunk after the command gave up ({how})"
            assert ended < 4.5, f"the command waited {ended:.1f} s for chunks nobody reads ({how})"
    finally:
        for p in [*children, proc]:
            try:
                p.kill()
            except (psutil.NoSuchProcess, ProcessLookupError):
                pass
