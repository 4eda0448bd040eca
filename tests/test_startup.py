"""Start-up (issue 42): the command line loads what a command needs when it runs, and a one-case job
answers on the numpy core without loading (or waiting for) the compiled one.

Every check runs a fresh interpreter and reads its ``sys.modules``: a command module that imports the
pipeline, numpy or pint at module level, or a new command that does, fails here. Times are measured
in ``benchmarks/bench_startup.py`` (a shared machine makes them unfit for assertions).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from bearingkit.analysis.solver import backend
from bearingkit.rows import numba_cache

#: Libraries no ``--help`` may load (each costs 0.1–1 s; together they were 2.4 s of every call).
HEAVY = (
    "numpy", "scipy", "pint", "pydantic", "numba", "pandas", "matplotlib", "dask", "distributed",
    "pyarrow", "pymoo", "fastapi", "uvicorn", "llvmlite",
)  # fmt: skip
#: typer itself builds pydantic adapters for a command's parameters when it parses them, so a
#: command's ``--help`` may load pydantic (not the input schema: ``bearingkit.io`` stays out).
TYPER_OWN = ("pydantic",)

_RUNNER = """
import json, sys
from bearingkit.cli import main
HEAVY = {heavy!r}
seen = {{}}
for argv in {argvs!r}:
    sys.argv = ["bearingkit", *argv]
    try:
        main()
    except SystemExit:
        pass
    seen[" ".join(argv)] = sorted(m for m in HEAVY if m in sys.modules)
seen["bearingkit modules"] = sorted(m for m in sys.modules if m.startswith("bearingkit."))
sys.stderr.write("\\nSEEN " + json.dumps(seen) + "\\n")
"""


def _run(argvs, env=None, heavy=HEAVY):
    """Run ``bearingkit ARGV`` for each ARGV in one fresh interpreter; (modules seen after each, stdout,
    stderr)."""
    code = _RUNNER.format(heavy=tuple(heavy), argvs=[list(a) for a in argvs])
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env={**os.environ, **(env or {})}
    )
    marker = out.stderr.rindex("\nSEEN ")
    return json.loads(out.stderr[marker + 6 :]), out.stdout, out.stderr[:marker]


def _commands() -> list[str]:
    import typer

    from bearingkit.cli import app

    return sorted(typer.main.get_command(app).commands)


def test_help_loads_no_heavy_library():
    """``bearingkit --help`` (target < 0.3 s) loads typer and rich, none of the scientific stack."""
    seen, out, _ = _run([["--help"]])
    assert "analyze" in out and "compile" in out
    assert seen["--help"] == []
    assert not any(m.startswith(("bearingkit.io", "bearingkit.pipeline")) for m in seen["bearingkit modules"])


def test_every_commands_help_loads_no_heavy_library():
    """Each command's ``--help`` (every registered command, so a new one is checked too) loads nothing
    heavy: a command module imports the pipeline, numpy, pint … inside its command function."""
    commands = _commands()
    assert {"analyze", "rating", "friction", "study", "shaft", "validate", "compile"} <= set(commands)
    seen, _out, _ = _run([[c, "--help"] for c in commands])
    for c in commands:
        loaded = [m for m in seen[f"{c} --help"] if m not in TYPER_OWN]
        assert loaded == [], f"bearingkit {c} --help loads {loaded}"
    assert not any(m.startswith("bearingkit.io.") for m in seen["bearingkit modules"])


def test_the_check_can_fail():
    """A command that imports numpy at module level is caught (the same runner, a planted import)."""
    seen, _, _ = _run([["--help"]], env={"PYTHONSTARTUP": ""}, heavy=("json", "numpy"))
    assert seen["--help"] == ["json"]  # the runner itself imports json: it is seen


def _fresh_cache(tmp_path: Path, built: bool) -> dict:
    """Environment of a process whose compiled-core cache is empty (or marked built but empty)."""
    env = {"NUMBA_CACHE_DIR": str(tmp_path), "BEARINGKIT_BACKGROUND_COMPILE": "0"}
    env_all = {**os.environ, **env}
    env_all.pop("BEARINGKIT_NUMBA_BASE", None)
    code = "from bearingkit.rows.numba_cache import cache_dir; print(cache_dir())"
    folder = Path(
        subprocess.run(
            [sys.executable, "-c", code], env=env_all, capture_output=True, text=True
        ).stdout.strip()
    )
    assert folder.parent == tmp_path
    if built:
        folder.mkdir(parents=True)
        (folder / numba_cache.BUILT_MARKER).write_text("test\n")
    return {**env, "BEARINGKIT_NUMBA_BASE": ""}


def test_first_answer_of_a_fresh_install_runs_on_the_numpy_core_with_one_note(tmp_path):
    """Empty compiled-core cache: the answer comes from the numpy core (no numba, no pint loaded), with
    one line on stderr saying so and how to build the compiled core."""
    env = _fresh_cache(tmp_path, built=False)
    seen, out, err = _run([["analyze", "6205", "--load", "Fr=2kN", "--json"]], env=env)
    data = json.loads(out)
    assert data["cases"][0]["converged"] is True
    # no scipy: scipy.special alone cost ~0.3 s of the answer (physics/contact/elliptic.py, issue 42)
    assert seen["analyze 6205 --load Fr=2kN --json"] == ["numpy", "pydantic"]
    notes = [line for line in err.splitlines() if line.startswith("note:")]
    # BEARINGKIT_BACKGROUND_COMPILE=0 here: the note does not claim a build in the background
    assert notes == [f"note: {backend.NOT_BUILT_NO_BACKGROUND_NOTE}"]


def test_a_one_case_job_does_not_load_the_built_compiled_core(tmp_path):
    """With the core built, a one-case job still runs on the numpy core (cheaper than loading the
    compiled one, by measurement: module doc of backend), silently."""
    env = _fresh_cache(tmp_path, built=True)
    seen, out, err = _run([["rating", "6205", "--load", "Fr=2kN", "--speed", "3000rpm", "--json"]], env=env)
    assert json.loads(out)["cases"][0]["system"]["L10h_h"] > 0
    assert "numba" not in seen["rating 6205 --load Fr=2kN --speed 3000rpm --json"]
    assert "note:" not in err


@pytest.fixture
def policy(monkeypatch):
    """backend's process state reset, the cache 'built' or not as the test sets it."""
    state = {"numpy_seconds": 0.0}
    monkeypatch.setattr(backend, "_STATE", state)
    started = []
    monkeypatch.setattr(numba_cache, "start_background_build", lambda: started.append(1) or True)
    monkeypatch.setattr(numba_cache, "numba_installed", lambda: True)
    monkeypatch.delenv(numba_cache.BACKGROUND_ENV, raising=False)
    return state, started


def test_auto_runs_small_jobs_on_numpy_and_large_ones_compiled(policy, monkeypatch):
    _state, started = policy
    monkeypatch.setattr(numba_cache, "is_built", lambda: True)
    assert not backend.wants_compiled(1)
    assert not backend.wants_compiled(backend.SMALL_JOB_CASES)
    assert backend.wants_compiled(backend.SMALL_JOB_CASES + 1)
    # many small solves: after LOAD_BUDGET_S of numpy time the compiled core is worth loading
    backend.spent_numpy(backend.LOAD_BUDGET_S * 0.6)
    assert not backend.wants_compiled(1)
    backend.spent_numpy(backend.LOAD_BUDGET_S * 0.6)
    assert backend.wants_compiled(1)
    assert started == []  # built: nothing to start


def test_auto_while_not_built_notes_once_and_starts_one_background_build(policy, monkeypatch, caplog):
    _state, started = policy
    monkeypatch.setattr(numba_cache, "is_built", lambda: False)
    with caplog.at_level("INFO", logger="bearingkit.solver"):
        assert not backend.wants_compiled(1)
        assert not backend.wants_compiled(3)
        backend.spent_numpy(10 * backend.LOAD_BUDGET_S)  # no budget rule while there is nothing to load
        assert not backend.wants_compiled(1)
        assert backend.wants_compiled(backend.SMALL_JOB_CASES + 1)  # compiles in the foreground, says so
    assert started == [1]
    assert [r.getMessage() for r in caplog.records] == [
        backend.NOT_BUILT_NOTE,
        backend.COMPILING_NOTE.format(n=backend.SMALL_JOB_CASES + 1),
    ]


def test_a_loaded_core_is_used_for_every_job(policy):
    state, _ = policy
    state["module"] = object()  # loaded in this process
    assert backend.wants_compiled(1)


def test_background_build_starts_once_and_respects_the_switch(tmp_path, monkeypatch):
    calls = []

    class Popen:
        def __init__(self, argv, **kw):
            calls.append((argv, kw))

    monkeypatch.setattr(subprocess, "Popen", Popen)
    monkeypatch.setattr(numba_cache, "cache_dir", lambda: tmp_path)
    monkeypatch.setattr(numba_cache, "_DONE", {})
    monkeypatch.setenv(numba_cache.BACKGROUND_ENV, "0")
    assert numba_cache.start_background_build() is False and calls == []
    monkeypatch.setenv(numba_cache.BACKGROUND_ENV, "1")
    assert numba_cache.start_background_build() is True
    assert numba_cache.start_background_build() is False  # once per process
    (argv, kw) = calls[0]
    assert argv == [sys.executable, "-m", "bearingkit", "compile", "--quiet", "--wait", "0"]
    assert kw["start_new_session"] and kw["env"][numba_cache.BACKGROUND_ENV] == "0"
    # a build already running (fresh lock file): nothing started
    monkeypatch.setattr(numba_cache, "_DONE", {})
    (tmp_path / numba_cache.BUILD_LOCK).write_text("1\n")
    assert numba_cache.start_background_build() is False and len(calls) == 1


def test_one_build_at_a_time(tmp_path, monkeypatch):
    monkeypatch.setattr(numba_cache, "cache_dir", lambda: tmp_path)
    with numba_cache.build_lock() as first:
        with numba_cache.build_lock(wait=0.0) as second:
            assert first is True and second is False
    assert not (tmp_path / numba_cache.BUILD_LOCK).exists()
    with numba_cache.build_lock() as again:  # released
        assert again is True


def test_a_lock_left_by_a_killed_build_is_broken_at_once(tmp_path, monkeypatch):
    """A build killed with SIGKILL cannot remove its lock: by age alone, every ``bearingkit compile`` said
    "busy" for half an hour and no background build started (the fuzz found it: a killed run's lock). A
    lock naming a process of this host that no longer runs is broken; a live holder's is kept."""
    import socket

    monkeypatch.setattr(numba_cache, "cache_dir", lambda: tmp_path)
    monkeypatch.setattr(numba_cache, "_DONE", {})
    lock = tmp_path / numba_cache.BUILD_LOCK
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()  # its pid is now free (a new process taking it within the test is not expected)
    host = socket.gethostname()
    lock.write_text(f"{dead.pid} {host}\n")
    with numba_cache.build_lock(wait=0.0) as mine:
        assert mine is True
        assert lock.read_text().split() == [str(os.getpid()), host]
    assert not lock.exists()
    # a live holder (this test's parent process) keeps the lock: busy, and no background build
    lock.write_text(f"{os.getppid()} {host}\n")
    with numba_cache.build_lock(wait=0.0) as mine:
        assert mine is False
    assert lock.exists()
    # a lock of another host is judged by its age only
    lock.write_text(f"{dead.pid} not-{host}\n")
    with numba_cache.build_lock(wait=0.0) as mine:
        assert mine is False
    # the background build starts past a dead holder's lock, not past a live one's
    calls = []
    monkeypatch.setattr(subprocess, "Popen", lambda argv, **kw: calls.append(argv))
    monkeypatch.setenv(numba_cache.BACKGROUND_ENV, "1")
    lock.write_text(f"{os.getppid()} {host}\n")
    assert numba_cache.start_background_build() is False and calls == []
    monkeypatch.setattr(numba_cache, "_DONE", {})
    lock.write_text(f"{dead.pid} {host}\n")
    assert numba_cache.start_background_build() is True and len(calls) == 1


def test_compile_says_busy_in_one_error_line_and_refuses_a_negative_wait(tmp_path, monkeypatch, capsys):
    """``bearingkit compile --wait 0`` while another live process builds: exit 1 with one ``error:`` line
    saying what to do (it printed only "compiled solver core busy"); ``--wait -1``: exit 2, one line."""
    import socket

    from typer.testing import CliRunner

    from bearingkit.cli import app
    from bearingkit.cli.commands import main
    from bearingkit.errors import InputError

    monkeypatch.setattr(numba_cache, "cache_dir", lambda: tmp_path)
    (tmp_path / numba_cache.BUILD_LOCK).write_text(f"{os.getppid()} {socket.gethostname()}\n")
    for argv, code, words in (
        (["compile", "--wait", "0"], 1, "being built by another process"),
        (["compile", "--wait", "-1"], 2, "must be 0 or more seconds"),
    ):
        monkeypatch.setattr(sys, "argv", ["bearingkit", *argv])
        with pytest.raises(SystemExit) as exit_:
            main()
        assert exit_.value.code == code
        err = [line for line in capsys.readouterr().err.splitlines() if line.strip()]
        assert len(err) == 1 and err[0].startswith("error: ") and words in err[0], err
        # the same through the app in process (typer's runner: no traceback, the same line)
        res = CliRunner().invoke(app, argv)
        assert res.exit_code == code and not isinstance(res.exception, InputError), res.exception
        assert words in res.output and "Traceback" not in res.output


def test_compile_solves_every_kind_on_the_compiled_core_and_marks_it_built(tmp_path, monkeypatch):
    """``bearingkit compile`` (the warm-up build) in a process whose numba cache is the real one: every
    warm-up bearing converges on the compiled core, then the marker is written; a second run knows."""
    from typer.testing import CliRunner

    from bearingkit.bearings.warmup import warmup_bearings
    from bearingkit.cli import app

    kinds = {row.kind for model, _ in warmup_bearings().values() for row in model.rows}
    assert kinds == {"ball", "cylindrical", "tapered", "threaded"}  # compiled_newton.SUPPORTED_KINDS
    monkeypatch.setattr(numba_cache, "cache_dir", lambda: tmp_path)
    first = CliRunner().invoke(app, ["compile"])
    assert first.exit_code == 0, first.output
    assert "compiled solver core built" in first.output
    assert (tmp_path / numba_cache.BUILT_MARKER).is_file()
    second = CliRunner().invoke(app, ["compile"])
    assert "already built" in second.output


def test_the_note_says_no_background_build_where_it_is_switched_off(policy, monkeypatch, caplog):
    _state, _started = policy
    monkeypatch.setattr(numba_cache, "is_built", lambda: False)
    monkeypatch.setenv(numba_cache.BACKGROUND_ENV, "0")
    with caplog.at_level("INFO", logger="bearingkit.solver"):
        assert not backend.wants_compiled(1)
    assert [r.getMessage() for r in caplog.records] == [backend.NOT_BUILT_NO_BACKGROUND_NOTE]
    assert "building it" not in backend.NOT_BUILT_NO_BACKGROUND_NOTE
