"""Studies under faults (issue 41, Deliver 4): a pool worker killed with SIGKILL, the command killed
with its pool, a full disk during a chunk write. Each time the store stays readable (every chunk file
on disk is whole and this study's), the run stops with one line saying what is kept and how to
continue, no process is left behind, and ``--resume`` computes exactly the missing chunks: the
results equal an uninterrupted run's bit for bit. (The command killed without a pool:
``test_resume.py``; a killed Dask worker: ``test_dask_external.py``.)
"""

from __future__ import annotations

import errno
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import psutil
import pyarrow.parquet as pq
import pytest

from bearingkit.errors import RUN_INTERRUPTED_EXIT, RunInterrupted
from bearingkit.studies import evaluators
from bearingkit.studies.__main__ import run_cli
from bearingkit.studies.definition import load as sd
from bearingkit.studies.run.runner import run_study
from bearingkit.studies.run.store import STAMP_KEY

HERE = Path(__file__).resolve().parent
N_CHUNKS = 16
STUDY = f"""
[study]
name = "fault_probe"
design = "factorial"
evaluator = "slow_counter"
chunk_size = 1

[[factors]]
name = "x"
levels = [{", ".join(str(0.25 * i) for i in range(N_CHUNKS))}]
"""
PLUGIN = "bk_study_helpers:SLOW"


def _env(**extra) -> dict:
    return {
        **os.environ,
        "PYTHONPATH": os.pathsep.join([str(HERE), os.environ.get("PYTHONPATH", "")]),
        **extra,
    }


def _chunk_files(out: Path) -> list[Path]:
    return sorted((out / "chunks").glob("chunk-*.parquet")) if (out / "chunks").is_dir() else []


def _assert_store_readable(out: Path, killed: bool = False) -> set[int]:
    """Every file in chunks/ is a whole chunk of this study (read back, stamped with its own number).

    ``killed``: the writing process was SIGKILLed, which no code outlives: a chunk it was writing stays
    as its hidden temporary file (``.chunk-….<pid>.tmp``, never read as a chunk; the store removes it
    when the study is opened again, which the resume then checks)."""
    names = {p.name for p in (out / "chunks").iterdir()}
    if killed:
        names = {n for n in names if not (n.startswith(".chunk-") and n.endswith(".tmp"))}
    files = _chunk_files(out)
    assert names == {p.name for p in files}, f"stray files in the store: {names - {p.name for p in files}}"
    manifest = json.loads((out / "manifest.json").read_text())
    ids = set()
    for path in files:
        table = pq.read_table(path)
        stamp = json.loads(table.schema.metadata[STAMP_KEY])
        assert stamp["fingerprint"] == manifest["fingerprint"]
        assert path.name == f"chunk-{stamp['chunk']:06d}.parquet" and table.num_rows == stamp["rows"] == 1
        ids.add(stamp["chunk"])
    return ids


def _workers_of(pid: int) -> list[psutil.Process]:
    """The pool's worker processes (spawned by multiprocessing; not its resource tracker)."""
    kids = psutil.Process(pid).children(recursive=True)
    return [p for p in kids if "spawn_main" in " ".join(p.cmdline())]


def _wait_for_chunks(out: Path, n: int, proc: subprocess.Popen, timeout: float = 90.0) -> None:
    deadline = time.monotonic() + timeout
    while len(_chunk_files(out)) < n:
        assert proc.poll() is None, f"the study ended (rc {proc.returncode}) before {n} chunks were done"
        assert time.monotonic() < deadline, f"fewer than {n} chunks after {timeout} s"
        time.sleep(0.02)


def _resume_and_compare(study: Path, out: Path, finished: set[int], monkeypatch) -> list[str]:
    """``--resume`` computes exactly the chunks not on disk and leaves the finished files untouched;
    the results equal a clean run's exactly. Returns the lines the run printed."""
    monkeypatch.setattr(evaluators, "ALLOWED_PLUGINS", {})
    monkeypatch.setenv("BK_SLEEP", "0")
    stamps = {p.name: p.stat().st_mtime_ns for p in _chunk_files(out)}
    said = []
    resumed = run_cli(study, resume=True, out=out, progress=False, echo=said.append, allow_plugins=[PLUGIN])
    assert resumed.stats["computed"] == N_CHUNKS - len(finished) and resumed.stats["reused"] == len(finished)
    for name, stamp in stamps.items():  # the finished chunk files are the stopped run's, untouched
        assert (out / "chunks" / name).stat().st_mtime_ns == stamp
    assert _assert_store_readable(out) == set(range(N_CHUNKS))
    fresh = run_study(sd.load_study(study), progress=False)
    pd.testing.assert_frame_equal(resumed.results, fresh.results, check_exact=True)
    assert resumed.results["case"].is_unique and len(resumed.results) == N_CHUNKS
    published = pd.read_csv(out / "results.csv")
    assert published["y"].tolist() == fresh.results["y"].tolist()
    return [str(s) for s in said]


def _no_process_left(procs: list[psutil.Process]) -> None:
    _gone, alive = psutil.wait_procs(procs, timeout=15)
    assert not alive, f"{len(alive)} process(es) outlived the study"


@pytest.mark.slow  # a pool worker killed mid-study: ~7 s (make test keeps another fault: the full disk below)
def test_a_killed_pool_worker_stops_the_study_in_one_line_and_resume_finishes_it(tmp_path, monkeypatch):
    study = tmp_path / "study.toml"
    study.write_text(STUDY)
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "bearingkit.studies", str(study), "--out", str(out), "--workers", "2"]
    cmd += ["--no-progress", "--allow-plugin", PLUGIN]
    proc = subprocess.Popen(cmd, env=_env(BK_SLEEP="0.4"), stderr=subprocess.PIPE, text=True)
    procs = []
    try:
        _wait_for_chunks(out, 3, proc)
        procs = _workers_of(proc.pid)
        assert len(procs) == 2, procs
        procs[0].send_signal(signal.SIGKILL)
        _, err = proc.communicate(timeout=60)
        lines = err.strip().splitlines()
        assert proc.returncode == RUN_INTERRUPTED_EXIT, err
        assert len(lines) == 1 and "Traceback" not in err, err
        assert "a worker process ended before its chunk was done" in lines[0]
        assert "--resume" in lines[0] and str(out) in lines[0]
        _no_process_left(procs)
    finally:
        for p in [*procs, proc]:
            with_kill(p)
    finished = _assert_store_readable(out)
    assert 3 <= len(finished) < N_CHUNKS, "the kill must land mid-run"
    assert f"{len(finished)} finished chunks are kept" in lines[0]
    _resume_and_compare(study, out, finished, monkeypatch)


@pytest.mark.slow  # SIGKILL of a study and its pool, then resume: ~8 s
def test_kill_9_of_the_command_with_its_pool_then_resume_is_bit_for_bit(tmp_path, monkeypatch):
    study = tmp_path / "study.toml"
    study.write_text(STUDY)
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "bearingkit.studies", str(study), "--out", str(out), "--workers", "2"]
    cmd += ["--no-progress", "--allow-plugin", PLUGIN]
    proc = subprocess.Popen(cmd, env=_env(BK_SLEEP="0.4"))
    procs = []
    try:
        _wait_for_chunks(out, 3, proc)
        procs = psutil.Process(proc.pid).children(recursive=True)
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(timeout=10)
        assert proc.returncode == -signal.SIGKILL
        _no_process_left(procs)  # the workers and the resource tracker end with their parent
    finally:
        for p in [*procs, proc]:
            with_kill(p)
    finished = _assert_store_readable(out, killed=True)
    assert 3 <= len(finished) < N_CHUNKS, "the kill must land mid-run"
    said = _resume_and_compare(study, out, finished, monkeypatch)
    assert any("recovered the stale lock of study 'fault_probe'" in s for s in said), said


def test_a_full_disk_during_a_chunk_write_keeps_the_store_and_the_study_resumes(tmp_path, monkeypatch):
    """ENOSPC at the fsync of the 5th chunk file: the partial file goes, the 4 whole ones stay, the
    command says so in one line (exit 75), and the resumed run equals a clean one."""
    from typer.testing import CliRunner

    from bearingkit.cli import app

    study = tmp_path / "study.toml"
    study.write_text(STUDY)
    out = tmp_path / "out"
    real_fsync, written = os.fsync, []

    def full_disk(fd):
        target = os.readlink(f"/proc/self/fd/{fd}")
        if Path(target).name.startswith(".chunk-"):
            written.append(target)
            if len(written) == 5:
                raise OSError(errno.ENOSPC, "No space left on device", target)
        return real_fsync(fd)

    monkeypatch.setattr(evaluators, "ALLOWED_PLUGINS", {})
    monkeypatch.setenv("BK_SLEEP", "0")
    monkeypatch.setattr(os, "fsync", full_disk)
    result = CliRunner().invoke(app, ["study", str(study), "--out", str(out), "--allow-plugin", PLUGIN])
    monkeypatch.setattr(os, "fsync", real_fsync)
    assert result.exit_code == RUN_INTERRUPTED_EXIT, result.output
    line = result.stderr.strip()
    assert "\n" not in line and "Traceback" not in line and "[Errno" not in line, line
    assert "the disk is full" in line and "4 finished chunks are kept" in line and "--resume" in line, line
    assert _assert_store_readable(out) == {0, 1, 2, 3}  # no partial file left beside them
    assert not (out / "results.csv").exists()
    _resume_and_compare(study, out, {0, 1, 2, 3}, monkeypatch)


def test_run_interrupted_is_one_bounded_line():
    exc = RunInterrupted("the study stopped:\n" + "x" * 5000)
    assert "\n" not in str(exc) and len(str(exc)) <= 300


def with_kill(p) -> None:
    """Kill ``p`` (a Popen or a psutil.Process) if it still runs: a failed test leaves nothing behind."""
    try:
        p.kill()
    except (psutil.NoSuchProcess, ProcessLookupError):
        pass
