"""One writer per study folder, and no chunk of another study ever reused (issue 24, item 1).

The audit: two ``study … --out X`` runs of different studies both exited 0 and X ended with the second
study only; after a crash, ``--resume`` of the second reported "0 chunks computed, 160 reused" with
32,500 of 40,000 rows holding the other study's outputs. Now the folder is locked for a run, every
chunk file carries its study's fingerprint, and a folder holding other files is refused.
"""

import json
import os
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pandas as pd
import pyarrow.parquet as pq
import pytest

from bearingkit.errors import InputError
from bearingkit.studies import evaluators
from bearingkit.studies.__main__ import main, run_cli
from bearingkit.studies.definition import load as sd
from bearingkit.studies.run.lock import LOCK_FILE
from bearingkit.studies.run.runner import run_study
from bearingkit.studies.run.store import STAMP_KEY

HERE = Path(__file__).resolve().parent


def _study(name: str, levels, chunk_size: int = 2) -> dict:
    return {
        "study": {"name": name, "design": "factorial", "evaluator": "slow_counter", "chunk_size": chunk_size},
        "factors": [{"name": "x", "levels": list(levels)}],
    }


def _toml(name: str, levels, chunk_size: int = 2) -> str:
    return (
        f'[study]\nname = "{name}"\ndesign = "factorial"\nevaluator = "slow_counter"\n'
        f'chunk_size = {chunk_size}\n[[factors]]\nname = "x"\nlevels = {list(levels)}\n'
    )


@pytest.fixture
def slow(monkeypatch):
    """The slow_counter test evaluator, allowed as a plugin, without sleeping."""
    monkeypatch.setattr(evaluators, "ALLOWED_PLUGINS", {})
    monkeypatch.syspath_prepend(str(HERE))
    monkeypatch.setenv("BK_SLEEP", "0")
    evaluators.allow_plugin("bk_study_helpers:SLOW")


def _stamps(out: Path) -> list[dict]:
    files = sorted((out / "chunks").glob("chunk-*"))
    return [json.loads(pq.read_schema(p).metadata[STAMP_KEY]) for p in files]


def _fingerprint(out: Path) -> str:
    return json.loads((out / "manifest.json").read_text())["fingerprint"]


@pytest.mark.slow  # a study in a second process: ~10 s on the shared 2-core machine
def test_a_second_writer_is_refused_naming_the_holder(tmp_path, slow, capsys):
    out = tmp_path / "X"
    (tmp_path / "a.toml").write_text(_toml("study_a", range(24)))
    (tmp_path / "b.toml").write_text(_toml("study_b", range(100, 124)))
    env = {
        **os.environ,
        "PYTHONPATH": os.pathsep.join([str(HERE), os.environ.get("PYTHONPATH", "")]),
        "BK_SLEEP": "0.5",
    }
    cmd = [sys.executable, "-m", "bearingkit.studies", str(tmp_path / "a.toml"), "--out", str(out)]
    proc = subprocess.Popen([*cmd, "--no-progress", "--allow-plugin", "bk_study_helpers:SLOW"], env=env)
    try:
        deadline = time.monotonic() + 90
        while not list((out / "chunks").glob("chunk-*.parquet")) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert proc.poll() is None, "study A must still be running"
        code = main([str(tmp_path / "b.toml"), "--out", str(out), "--no-progress"])
        err = capsys.readouterr().err
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=10)
    assert code == 2 and err.count("\n") == 1, err
    assert f"is in use by study 'study_a' (pid {proc.pid} on host " in err and ", started 20" in err
    manifest = json.loads((out / "manifest.json").read_text())
    assert manifest["study"] == "study_a"
    assert {s["fingerprint"] for s in _stamps(out)} == {manifest["fingerprint"]}


def test_a_second_writer_in_the_same_process_is_refused_and_the_first_finishes(tmp_path, slow, monkeypatch):
    """Two runs side by side (threads of one process, as a web app would start them)."""
    out = tmp_path / "X"
    # 12 chunks of 0.3 s: a is still running when b has read, planned and probed its first cases
    # (issue 41: three evaluator calls in b's own process before it asks for the lock)
    (tmp_path / "a.toml").write_text(_toml("study_a", range(24)))
    (tmp_path / "b.toml").write_text(_toml("study_b", range(100, 108)))
    monkeypatch.setenv("BK_SLEEP", "0.3")
    done = {}

    def run_a():
        done["a"] = run_cli(tmp_path / "a.toml", out=out, progress=False, echo=lambda s: None)

    thread = threading.Thread(target=run_a)
    thread.start()
    deadline = time.monotonic() + 30
    while not list((out / "chunks").glob("chunk-*.parquet")) and time.monotonic() < deadline:
        time.sleep(0.02)
    with pytest.raises(InputError, match=rf"is in use by study 'study_a' \(pid {os.getpid()} on host "):
        run_cli(tmp_path / "b.toml", out=out, progress=False, echo=lambda s: None)
    thread.join(60)
    assert list(pd.read_csv(out / "results.csv")["y"]) == [x * x + 1.0 for x in range(24)]
    assert json.loads((out / "summary.json").read_text())["study"] == "study_a"
    assert {s["fingerprint"] for s in _stamps(out)} == {_fingerprint(out)}


def test_stale_lock_of_a_killed_run_is_recovered_with_a_message(tmp_path, slow):
    out = tmp_path / "X"
    out.mkdir()
    record = {"pid": 999999, "host": "gone-host", "started": "2026-01-01T00:00:00Z", "study": "ghost"}
    (out / LOCK_FILE).write_text(json.dumps(record))  # what a killed holder leaves (no OS lock held)
    (tmp_path / "a.toml").write_text(_toml("study_a", range(4)))
    lines = []
    res = run_cli(tmp_path / "a.toml", out=out, progress=False, echo=lines.append)
    assert len(res.results) == 4
    said = (
        "recovered the stale lock of study 'ghost' "
        "(pid 999999 on host gone-host, started 2026-01-01T00:00:00Z)"
    )
    assert any(said in line for line in lines), lines
    assert (out / LOCK_FILE).read_text() == "", "a clean end leaves no record behind"


def test_a_chunk_of_another_study_is_never_reused(tmp_path, slow):
    """Chunk files of another study (as a second writer left them) are discarded and recomputed."""
    a, b = sd.from_dict(_study("study_a", range(8))), sd.from_dict(_study("study_b", range(100, 108)))
    run_study(a, store=tmp_path / "A", progress=False)
    fresh_b = run_study(b, store=tmp_path / "B", progress=False)
    # chunks 1 and 3 of B replaced by A's chunks of the same numbers; chunk 2 renamed from B's chunk 0
    for k in (1, 3):
        shutil.copy(tmp_path / "A" / "chunks" / f"chunk-00000{k}.parquet", tmp_path / "B" / "chunks")
    shutil.copy(
        tmp_path / "B" / "chunks" / "chunk-000000.parquet", tmp_path / "B" / "chunks" / "chunk-000002.parquet"
    )
    resumed = run_study(b, store=tmp_path / "B", resume=True, progress=False)
    assert resumed.stats["reused"] == 1 and resumed.stats["computed"] == 3 and resumed.stats["discarded"] == 3
    pd.testing.assert_frame_equal(resumed.results, fresh_b.results)
    assert list(resumed.results["y"]) == [x * x + 1.0 for x in range(100, 108)]


def test_a_damaged_chunk_file_is_recomputed(tmp_path, slow):
    d = sd.from_dict(_study("study_a", range(6)))
    fresh = run_study(d, store=tmp_path / "A", progress=False)
    chunk = tmp_path / "A" / "chunks" / "chunk-000001.parquet"
    chunk.write_bytes(chunk.read_bytes()[:100])  # truncated (a copy interrupted outside bearingkit)
    resumed = run_study(d, store=tmp_path / "A", resume=True, progress=False)
    assert resumed.stats["computed"] == 1 and resumed.stats["discarded"] == 1
    pd.testing.assert_frame_equal(resumed.results, fresh.results)


def test_a_folder_with_other_files_is_refused_and_left_alone(tmp_path, slow):
    out = tmp_path / "docs"
    out.mkdir()
    (out / "thesis.tex").write_text("mine")
    (out / "results.csv").write_text("mine too")
    (tmp_path / "a.toml").write_text(_toml("study_a", range(4)))
    with pytest.raises(InputError, match=r"holds files that are not a study's \(thesis\.tex\)"):
        run_cli(tmp_path / "a.toml", out=out, progress=False, echo=lambda s: None)
    assert sorted(p.name for p in out.iterdir()) == ["results.csv", "thesis.tex"]
    assert (out / "results.csv").read_text() == "mine too"


def test_runs_one_after_the_other_share_a_folder(tmp_path, slow):
    """Locking is per run: a finished run frees the folder; a new study replaces the old store."""
    out = tmp_path / "X"
    (tmp_path / "a.toml").write_text(_toml("study_a", range(4)))
    (tmp_path / "b.toml").write_text(_toml("study_b", range(10, 16)))
    run_cli(tmp_path / "a.toml", out=out, progress=False, echo=lambda s: None)
    lines = []
    res = run_cli(tmp_path / "b.toml", out=out, progress=False, echo=lines.append)
    assert f"{out}: replacing the chunks of study 'study_a'" in lines
    assert list(pd.read_csv(out / "results.csv")["y"]) == [x * x + 1.0 for x in range(10, 16)]
    assert json.loads((out / "summary.json").read_text())["study"] == "study_b"
    assert {s["fingerprint"] for s in _stamps(out)} == {
        json.loads((out / "manifest.json").read_text())["fingerprint"]
    }
    assert res.stats["reused"] == 0
