"""Study jobs: a study of the studies page run in the background, with progress, stop, resume, download.

No units here (files and processes). A job is a folder in the server's temporary folder
(``<store>/studies/<16 hex>/``) holding the study's files (:mod:`bearingkit.app.workbench.studies`) and
``out/``, the study's output folder. It runs ``python -m bearingkit.studies study.toml --out out`` — the
command line's own runner and Parquet store — in a child process, so:

- the page never waits for it: the server answers every other request while it runs, and reads the
  progress from the store itself (the chunk files finished against the manifest's count);
- stopping it kills the child; the chunks already written stay (each is written atomically, the
  store's lock dies with its holder), and **resume** runs the same command with ``--resume``, which
  computes only the missing chunks;
- it is bounded: one job runs at a time (a second is refused until it ends), a run is stopped after
  :data:`MAX_RUN_SECONDS` (resumable) and the study's own work estimate refuses, before any case, a
  study estimated above that (``BEARINGKIT_MAX_WORK_S``, :mod:`bearingkit.budget`), the case count
  was capped when the study was made, the child gets one solver thread (the page keeps a core), and
  at most :data:`MAX_JOBS` job folders are kept (the oldest finished one is removed); they all go
  with the server's temporary folder.

The download is the job folder as a zip: the study file, the subject, the results, tables and plots,
the chunks and the run's log; ``bearingkit study study.toml --out OUT`` in the unpacked folder gives the
same numbers. (It cannot ``--resume`` there: a study's fingerprint holds the absolute path of its
bearing file, so the moved folder is another study to the store; the app resumes in place.)
"""

from __future__ import annotations

import io
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
import zipfile
from dataclasses import dataclass, field
from pathlib import Path

from bearingkit.budget import MAX_WORK_ENV
from bearingkit.errors import InputError

__all__ = ["FIGURES", "MAX_JOBS", "MAX_RUN_SECONDS", "Busy", "Job", "Jobs"]

#: Wall time one run of a job may take [s]; it is then stopped (and can be resumed).
MAX_RUN_SECONDS = 600.0
#: Job folders kept (finished ones beyond this are removed, oldest first).
MAX_JOBS = 8
#: Results rows sent to the page at most (the download has them all).
MAX_ROWS = 2000
#: Figures a study writes that the page shows (``[[plots]]``, main effects, ranges, Pareto front …).
FIGURES = re.compile(r"^(plot_[1-9]|main_effects|range|pareto|point_statistics)\.png$")
#: A job id: 16 hex digits the server makes.
JOB_ID = re.compile(r"^[0-9a-f]{16}$")
#: Files of the output folder left out of the download (the run's lock).
_PRIVATE = (".bearingkit.lock",)
#: Tables of the output folder sent to the page besides the results (design analyses).
_TABLES = ("range.csv", "main_effects.csv", "statistics.csv", "pareto.csv", "selections.csv")


class Busy(InputError):
    """A job is running already (the server answers 409)."""


@dataclass
class Job:
    """One study job (module docstring)."""

    id: str
    folder: Path
    subject: str
    design: str
    n_cases: int
    outputs: list
    factors: list
    state: str = "queued"  # queued | running | done | failed | stopped
    message: str = ""
    started: float = 0.0
    finished: float = 0.0
    runs: int = 0
    process: subprocess.Popen | None = field(default=None, repr=False)
    stop_asked: bool = False

    @property
    def out(self) -> Path:
        return self.folder / "out"

    def progress(self) -> tuple[int, int]:
        """(chunks finished, chunks in all) read from the study's store (0, 0 before it opened)."""
        try:
            manifest = json.loads((self.out / "manifest.json").read_text(encoding="utf-8"))
            total = int(manifest["n_chunks"])
        except (OSError, ValueError, KeyError, TypeError):
            return 0, 0
        chunks = self.out / "chunks"
        done = len([p for p in chunks.glob("chunk-*.parquet")]) if chunks.is_dir() else 0
        return min(done, total), total

    def to_dict(self) -> dict:
        done, total = self.progress()
        fraction = 1.0 if self.state == "done" else (done / total if total else 0.0)
        elapsed = (self.finished or time.time()) - self.started if self.started else 0.0
        return {
            "id": self.id,
            "subject": self.subject,
            "design": self.design,
            "state": self.state,
            "message": self.message,
            "cases": self.n_cases,
            "chunks_done": done,
            "chunks": total,
            "fraction": fraction,
            "cases_done": round(fraction * self.n_cases),
            "elapsed_s": elapsed,
            "runs": self.runs,
            "outputs": self.outputs,
            "factors": self.factors,
        }


class Jobs:
    """The server's study jobs (thread-safe): start, progress, stop, resume, results, download.

    Parameters
    ----------
    root : callable
        Returns the server's temporary folder (made on first use); jobs live in ``root()/studies``.
    max_seconds : float
        :data:`MAX_RUN_SECONDS`.
    """

    def __init__(self, root, max_seconds: float = MAX_RUN_SECONDS, most: int = MAX_JOBS):
        self._root = root
        self.max_seconds = max_seconds
        self.most = most
        self._jobs: dict[str, Job] = {}
        self._lock = threading.Lock()

    # -------------------------------------------------------------------------------- control
    def start(self, files: dict, n_cases: int, design: str, subject: str, outputs, factors) -> Job:
        """Write the study's files in a new job folder and run it (:class:`Busy` if one is running)."""
        import secrets

        with self._lock:
            self._refuse_if_running()
            self._prune()
            key = secrets.token_hex(8)
            folder = Path(self._root()) / "studies" / key
            folder.mkdir(parents=True)
            for name, text in files.items():  # names the server made (study.toml, bearing.toml, examples)
                (folder / Path(name).name).write_text(text, encoding="utf-8")
            job = Job(key, folder, subject, design, n_cases, list(outputs), list(factors))
            self._jobs[key] = job
            self._launch(job, resume=False)
            return job

    def resume(self, key: str) -> Job:
        """Run a stopped or failed job again with ``--resume`` (the finished chunks are kept)."""
        with self._lock:
            job = self._get(key)
            if job.state in ("running", "queued"):
                raise Busy(f"study {key}: it is running; wait for it or stop it")
            self._refuse_if_running()
            self._launch(job, resume=True)
            return job

    def stop(self, key: str) -> Job:
        """Stop a running job (its finished chunks stay; resume continues)."""
        with self._lock:
            job = self._get(key)
            proc = job.process
            if job.state == "running" and proc is not None:
                job.stop_asked = True
                _kill(proc)
            return job

    def get(self, key: str) -> Job:
        with self._lock:
            return self._get(key)

    def close(self) -> None:
        """Stop every job (the folders go with the server's temporary folder)."""
        with self._lock:
            for job in self._jobs.values():
                if job.process is not None and job.process.poll() is None:
                    job.stop_asked = True
                    _kill(job.process)
            self._jobs.clear()

    def _get(self, key: str) -> Job:
        job = self._jobs.get(key) if JOB_ID.fullmatch(key or "") else None
        if job is None:
            raise LookupError(key)
        return job

    def _refuse_if_running(self) -> None:
        running = [j for j in self._jobs.values() if j.state in ("running", "queued")]
        if running:
            raise Busy(
                f"a study is running ({running[0].id}, {running[0].to_dict()['cases_done']} of "
                f"{running[0].n_cases} cases): one at a time; wait for it or stop it"
            )

    def _prune(self) -> None:
        ended = sorted((j for j in self._jobs.values() if j.state not in ("running", "queued")),
                       key=lambda j: j.finished)  # fmt: skip
        while len(self._jobs) >= self.most and ended:
            old = ended.pop(0)
            shutil.rmtree(old.folder, ignore_errors=True)
            del self._jobs[old.id]

    def _launch(self, job: Job, resume: bool) -> None:
        command = [sys.executable, "-m", "bearingkit.studies", "study.toml", "--out", "out", "--no-progress"]
        if resume:
            command.append("--resume")
        env = {**os.environ, "BEARINGKIT_THREADS": "1", "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}
        env["MPLBACKEND"] = "Agg"
        # the study's own work estimate (bearingkit.budget) may take what one run of the app may take: the
        # app's bounds (cases, seconds per run) govern, not the command line's default of 120 s, which a
        # page cannot raise (a limit the server was started with stays)
        env.setdefault(MAX_WORK_ENV, f"{self.max_seconds:g}")
        log = (job.folder / "run.log").open("ab")
        job.state, job.message, job.stop_asked = "running", "", False
        job.started, job.finished = time.time(), 0.0
        job.runs += 1
        try:
            job.process = subprocess.Popen(
                command,
                cwd=job.folder,
                env=env,
                stdin=subprocess.DEVNULL,
                stdout=log,
                stderr=log,
                start_new_session=True,  # its own process group: stop kills the run and nothing else
            )
        except OSError as exc:
            job.state, job.message = "failed", f"cannot start the study: {exc.strerror or exc}"
            job.finished = time.time()
            return
        finally:
            log.close()
        threading.Thread(target=self._watch, args=(job,), daemon=True, name=f"study-{job.id}").start()

    def _watch(self, job: Job) -> None:
        proc = job.process
        try:
            code = proc.wait(timeout=self.max_seconds)
            timed_out = False
        except subprocess.TimeoutExpired:
            _kill(proc)
            code, timed_out = proc.wait(), True
        with self._lock:
            job.finished = time.time()
            job.process = None
            if code == 0:
                job.state, job.message = "done", _last_line(job.folder / "run.log", "")
            elif timed_out:
                job.state = "stopped"
                job.message = (
                    f"stopped at the app's limit of {self.max_seconds:.0f} s per run: resume to continue, or "
                    "download the study and run it with bearingkit study --resume"
                )
            elif job.stop_asked:
                job.state, job.message = "stopped", "stopped: resume continues from the finished chunks"
            else:
                job.state = "failed"
                job.message = _last_line(job.folder / "run.log", f"the study ended with exit code {code}")

    # -------------------------------------------------------------------------------- results
    def results(self, key: str) -> dict:
        """The finished study's results table (≤ :data:`MAX_ROWS` rows), analysis tables and figures."""
        import pandas as pd

        job = self.get(key)
        if job.state != "done":
            raise InputError(f"study {key}: no results yet ({job.state})")
        frame = pd.read_parquet(job.out / "results.parquet")
        out = {"job": job.to_dict(), "columns": list(frame.columns), "rows": _rows(frame.head(MAX_ROWS))}
        out["total_rows"] = len(frame)
        tables = {}
        for name in _TABLES:
            path = job.out / name
            if path.is_file():
                t = pd.read_csv(path)
                tables[name.removesuffix(".csv")] = {
                    "columns": list(t.columns),
                    "rows": _rows(t.head(MAX_ROWS)),
                }
        out["tables"] = tables
        out["figures"] = sorted(p.name for p in job.out.iterdir() if FIGURES.fullmatch(p.name) and p.exists())
        summary = job.out / "summary.json"
        out["summary"] = json.loads(summary.read_text(encoding="utf-8")) if summary.is_file() else None
        return out

    def figure(self, key: str, name: str) -> Path:
        """The path of a figure of a finished job (LookupError for anything else)."""
        job = self.get(key)
        path = job.out / name
        if not FIGURES.fullmatch(name) or not path.is_file():
            raise LookupError(name)
        return path

    def archive(self, key: str) -> bytes:
        """The job folder as a zip (module docstring); links are written as the files they point to."""
        job = self.get(key)
        if job.state in ("running", "queued"):
            raise Busy(f"study {key}: it is running; download it when it has finished or been stopped")
        buf = io.BytesIO()
        top = f"study-{key}"
        with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
            for path in sorted(job.folder.rglob("*")):
                rel = path.relative_to(job.folder)
                if rel.parts[0] == "out" and len(rel.parts) > 1 and rel.parts[1].startswith("."):
                    continue  # the store's published sets (.outputs/) and its lock: the links carry them
                if path.name in _PRIVATE or not path.is_file():
                    continue
                z.write(path, f"{top}/{rel.as_posix()}")
        return buf.getvalue()


def _rows(frame) -> list[list]:
    """Rows of a table as JSON values (NaN → None, numpy scalars → Python)."""
    import numpy as np

    out = []
    for row in frame.itertuples(index=False):
        values = []
        for v in row:
            if isinstance(v, (bool, np.bool_)):
                values.append(bool(v))
            elif isinstance(v, (int, np.integer)):
                values.append(int(v))
            elif isinstance(v, (float, np.floating)):
                values.append(float(v) if np.isfinite(v) else None)
            else:
                values.append(None if v is None else str(v))
        out.append(values)
    return out


def _last_line(path: Path, default: str) -> str:
    """The last non-empty line of the run's log: the study's one-line summary or error."""
    try:
        lines = [line.strip() for line in path.read_text(encoding="utf-8", errors="replace").splitlines()]
    except OSError:
        return default
    lines = [line for line in lines if line]
    if not lines:
        return default
    return " ".join(lines[-1].removeprefix("error: ").split())[:500]


def _kill(proc: subprocess.Popen) -> None:
    """End a job's process group (the study and any worker it started)."""
    try:
        os.killpg(proc.pid, signal.SIGTERM)
    except (ProcessLookupError, PermissionError, AttributeError):
        try:
            proc.terminate()
        except ProcessLookupError:
            pass
