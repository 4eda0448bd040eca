"""Resumable result store of a study: one Parquet file per finished chunk, written atomically.

SI units: the store keeps whatever the evaluator returned (units in the column names).

Layout of a store directory::

    .bearingkit.lock         the writer's lock (see bearingkit.studies.run.lock)
    manifest.json            study name, fingerprint, number of chunks, chunk size
    chunks/chunk-000017.parquet   results of chunk 17 (case ids + outputs), stamped with the study

A chunk is written to ``chunks/.chunk-000017.parquet.<pid>.tmp``, flushed to disk (fsync) and renamed
onto its final name (``os.replace``: atomic on POSIX). A process killed at any instant therefore
leaves every chunk either complete or absent (stray ``*.tmp`` files are removed on open), and
``resume=True`` recomputes exactly the chunks whose file is absent.

Integrity (issue 24):

- one writer: :meth:`ParquetStore.lock` takes the directory's lock before anything is written, and a
  second run on the same directory is refused with one line naming the holder;
- every chunk file carries, in its Parquet metadata, the study's fingerprint (definition, evaluator,
  code version, cases: :func:`bearingkit.studies.run.cases.fingerprint`) and its chunk number; on resume a
  chunk file of another study, of another chunk or unreadable is discarded and recomputed, never
  reused; resuming into a store whose manifest names another study is an error;
- the directory holds only the study's own files: a folder with other files is refused before
  anything is written (a study writes and deletes only its own files inside its output folder).
"""

from __future__ import annotations

import json
import os
import re
import warnings
from pathlib import Path

from bearingkit.errors import InputError
from bearingkit.extras import require
from bearingkit.studies.run.lock import LOCK_FILE, StoreLock, describe
from bearingkit.studies.run.publish import CURRENT, OUTPUT_FILES, OUTPUTS_DIR, fsync_dir

MANIFEST = "manifest.json"
CHUNK_DIR = "chunks"
_CHUNK_RE = re.compile(r"^chunk-(\d{6})\.parquet$")
#: Key of the study stamp in a chunk file's Parquet metadata.
STAMP_KEY = b"bearingkit.study"
#: Temporary names of this module and of :mod:`bearingkit.studies.run.publish` (``.<name>.<pid>.tmp``).
_TMP_RE = re.compile(r"^\..+\.\d+\.tmp$")
#: Entries a study's output directory may hold.
OWN_ENTRIES = frozenset({LOCK_FILE, MANIFEST, CHUNK_DIR, OUTPUTS_DIR, CURRENT, *OUTPUT_FILES})


def _fsync_dir(path: Path) -> None:
    fsync_dir(path)


def write_atomic(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary file and a rename (never a partial file)."""
    path = Path(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        with open(tmp, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:  # a full disk, an interrupt: the part written goes (its space freed at once)
        tmp.unlink(missing_ok=True)
        raise
    _fsync_dir(path.parent)


def _read_manifest(path: Path) -> dict:
    """The manifest of a store, {} when absent or unreadable."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def foreign_entries(directory: Path) -> list[str]:
    """Names in ``directory`` that a study does not write (empty for a new or a study folder)."""
    if not directory.is_dir():
        return []
    return sorted(
        p.name for p in directory.iterdir() if p.name not in OWN_ENTRIES and not _TMP_RE.match(p.name)
    )


class ParquetStore:
    """Chunked Parquet results of one study in ``directory``.

    Parameters
    ----------
    directory : path
        Created if missing (by :meth:`lock`); an existing one must be empty or a study's folder.
    """

    def __init__(self, directory):
        require("pyarrow", "studies", "a study's Parquet store")  # one line naming the extra, not a traceback
        self.directory = Path(directory)
        self.chunk_dir = self.directory / CHUNK_DIR
        self.created = False
        self.discarded = 0
        self._lock: StoreLock | None = None
        self._fingerprint: str | None = None
        self._notify = warnings.warn

    # -- lifecycle -----------------------------------------------------------------------------
    @property
    def locked(self) -> bool:
        return self._lock is not None and self._lock.held

    def lock(self, study: str, notify=None) -> None:
        """Check the directory, create it if missing, and take its lock for ``study``.

        ``notify(message)`` is told when a stale lock (of a run that was killed) is recovered;
        default :func:`warnings.warn`.
        """
        if self.locked:
            return
        self._notify = notify or warnings.warn
        d = self.directory
        if d.exists() and not d.is_dir():
            raise InputError(f"{d} is a file; expected a folder for the study's outputs (--out)")
        foreign = foreign_entries(d)
        if foreign:
            shown = ", ".join(foreign[:4]) + (", ..." if len(foreign) > 4 else "")
            raise InputError(
                f"{d} holds files that are not a study's ({shown}); choose an empty or new folder for "
                "--out (a study writes and deletes only its own files)"
            )
        for sub in (CHUNK_DIR, OUTPUTS_DIR):
            if (d / sub).is_symlink():
                raise InputError(f"{d / sub} is a symbolic link; a study writes only inside its own folder")
        if not d.exists():
            d.mkdir(parents=True)
            self.created = True
        self._lock = StoreLock(d, study)
        stale = self._lock.acquire()
        if stale is not None:
            self._notify(
                f"{d}: recovered the stale lock of {describe(stale)}: that run ended without releasing it"
            )

    def close(self) -> None:
        """Release the lock (the store can be locked again)."""
        if self._lock is not None:
            self._lock.release()
            self._lock = None

    def discard_if_unused(self) -> None:
        """Remove the directory again when this store created it and no chunk was written.

        What a run that failed before computing anything calls: it leaves no output folder behind.
        Removes only the store's own entries; a folder someone else wrote into is kept.
        """
        self.close()
        d = self.directory
        if not self.created or not d.is_dir() or self.finished_files():
            return
        for name in (LOCK_FILE, MANIFEST):
            (d / name).unlink(missing_ok=True)
        for sub in (CHUNK_DIR, OUTPUTS_DIR):
            if (d / sub).is_dir() and not any((d / sub).iterdir()):
                (d / sub).rmdir()
        if not any(d.iterdir()):
            d.rmdir()
        self.created = False

    def open(
        self, fingerprint: str, n_chunks: int, chunk_size: int, resume: bool, study: str = "?"
    ) -> set[int]:
        """Prepare the store for a run; returns the ids of the chunks already finished.

        ``resume=False`` starts afresh (previous chunks of this directory are deleted);
        ``resume=True`` keeps those of the same study (same fingerprint, checked per chunk file).
        Takes the lock for ``study`` if the caller did not.
        """
        self.lock(study)
        self.chunk_dir.mkdir(exist_ok=True)
        for tmp in self.chunk_dir.glob(".*.tmp"):
            tmp.unlink(missing_ok=True)
        self._fingerprint = fingerprint
        self.discarded = 0
        manifest = {
            "study": study,
            "fingerprint": fingerprint,
            "n_chunks": int(n_chunks),
            "chunk_size": int(chunk_size),
        }
        mpath = self.directory / MANIFEST
        if resume and mpath.exists():
            old = _read_manifest(mpath)
            if old.get("fingerprint") != fingerprint:
                other = old.get("study", "?")
                raise InputError(
                    f"{self.directory}: resume (True) but the store holds another study ({other!r}; "
                    "definition, evaluator or cases changed); use another --out or run without --resume"
                )
            return self._valid_chunks(n_chunks)
        old = _read_manifest(mpath)
        if old.get("fingerprint") not in (None, fingerprint) and self.finished_files():
            self._notify(f"{self.directory}: replacing the chunks of study {old.get('study', '?')!r}")
        for f in self.finished_files():
            f.unlink()
        write_atomic(mpath, json.dumps(manifest, indent=1).encode())
        return set()

    # -- chunk files ---------------------------------------------------------------------------
    def finished_files(self) -> list[Path]:
        if not self.chunk_dir.is_dir():
            return []
        return [p for p in self.chunk_dir.iterdir() if _CHUNK_RE.match(p.name)]

    def finished(self) -> set[int]:
        """Ids of the chunks whose results are on disk."""
        return {int(_CHUNK_RE.match(p.name).group(1)) for p in self.finished_files()}

    def _stamp(self, path: Path) -> dict | None:
        import pyarrow.parquet as pq

        try:
            meta = pq.read_schema(path).metadata or {}
            stamp = json.loads(meta[STAMP_KEY].decode())
        except Exception:  # unreadable, truncated or unstamped: not a chunk this study can trust
            return None
        return stamp if isinstance(stamp, dict) else None

    def _valid_chunks(self, n_chunks: int) -> set[int]:
        """Chunks of this study on disk; files of another study, chunk or damaged are deleted."""
        ok = set()
        for path in self.finished_files():
            chunk = int(_CHUNK_RE.match(path.name).group(1))
            stamp = self._stamp(path)
            if (
                stamp is not None
                and stamp.get("fingerprint") == self._fingerprint
                and stamp.get("chunk") == chunk
                and chunk < n_chunks
            ):
                ok.add(chunk)
            else:
                path.unlink()
                self.discarded += 1
        return ok

    def _path(self, chunk: int) -> Path:
        return self.chunk_dir / f"chunk-{int(chunk):06d}.parquet"

    def recorded_chunk_size(self, fingerprint: str) -> int | None:
        """The chunk size the manifest records for this study (a resumed run keeps it), else None."""
        old = _read_manifest(self.directory / MANIFEST)
        size = old.get("chunk_size") if old.get("fingerprint") == fingerprint else None
        return int(size) if isinstance(size, int) and size >= 1 else None

    # -- data ----------------------------------------------------------------------------------
    def write(self, chunk: int, frame) -> None:
        """Store the results of one finished chunk (atomic), stamped with the study's fingerprint.

        ``frame``: a DataFrame or columns (a dict of equally long arrays, as the executors return
        them: written without a pandas round trip).
        """
        import io

        import pyarrow as pa
        import pyarrow.parquet as pq

        if not self.locked or self._fingerprint is None:
            raise RuntimeError("ParquetStore.write before open(): the store is not locked")
        if isinstance(frame, dict):
            table = pa.table({k: _arrow(v) for k, v in frame.items()})
            rows = table.num_rows
        else:
            table = pa.Table.from_pandas(frame, preserve_index=False)
            rows = len(frame)
        stamp = json.dumps({"fingerprint": self._fingerprint, "chunk": int(chunk), "rows": rows})
        table = table.replace_schema_metadata({**(table.schema.metadata or {}), STAMP_KEY: stamp.encode()})
        buf = io.BytesIO()
        pq.write_table(table, buf)
        write_atomic(self._path(chunk), buf.getvalue())

    def read_chunk(self, chunk: int):
        import pyarrow.parquet as pq

        path = self._path(chunk)
        table = pq.read_table(path)
        stamp = json.loads((table.schema.metadata or {}).get(STAMP_KEY, b"{}").decode())
        if stamp.get("fingerprint") != self._fingerprint or stamp.get("chunk") != int(chunk):
            raise InputError(f"{path} is not chunk {chunk} of this study (the store changed during the run)")
        return table.to_pandas()

    def read(self):
        """All finished chunks as one DataFrame, in chunk order."""
        import pandas as pd

        ids = sorted(self.finished())
        if not ids:
            return pd.DataFrame()
        return pd.concat([self.read_chunk(i) for i in ids], ignore_index=True)


def _arrow(values):
    """A column for pyarrow: numpy arrays as they are; object arrays (text) with None/NaN as nulls,
    as ``pa.Table.from_pandas`` reads a DataFrame's text column."""
    import numpy as np
    import pyarrow as pa

    values = np.asarray(values)
    if values.dtype == object:
        return pa.array(values, from_pandas=True)
    return values


def frame_of(chunks: list):
    """One DataFrame of chunk results in the given order (DataFrames or columns, not mixed)."""
    import numpy as np
    import pandas as pd

    if not chunks:
        return pd.DataFrame()
    if all(isinstance(c, dict) for c in chunks):  # columns: one concatenation per column
        return pd.DataFrame({k: np.concatenate([np.asarray(c[k]) for c in chunks]) for k in chunks[0]})
    return pd.concat([c if not isinstance(c, dict) else pd.DataFrame(c) for c in chunks], ignore_index=True)


class MemoryStore:
    """The in-memory stand-in for :class:`ParquetStore` (no persistence, no resume).

    Chunks are kept as they come (columns or DataFrames) and joined once, by :meth:`read`.
    """

    def __init__(self):
        self._chunks: dict[int, object] = {}

    def open(
        self, fingerprint: str, n_chunks: int, chunk_size: int, resume: bool, study: str = "?"
    ) -> set[int]:
        self._chunks.clear()
        return set()

    def close(self) -> None:
        pass

    def finished(self) -> set[int]:
        return set(self._chunks)

    def recorded_chunk_size(self, fingerprint: str) -> int | None:
        return None

    def write(self, chunk: int, frame) -> None:
        self._chunks[int(chunk)] = frame

    def read_chunk(self, chunk: int):
        return frame_of([self._chunks[int(chunk)]])

    def read(self):
        return frame_of([self._chunks[i] for i in sorted(self._chunks)])


def progress_bar(total: int, description: str, enabled: bool | None = None):
    """A rich progress bar (cases done / total, rate in cases/s, elapsed, ETA), or a no-op.

    ``enabled=None`` shows the bar only when stderr is a terminal.
    """
    import sys

    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TaskProgressColumn,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    if enabled is None:
        enabled = sys.stderr.isatty()
    prog = Progress(
        TextColumn("[bold]{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TaskProgressColumn(),
        TextColumn("{task.fields[rate]}"),
        TimeElapsedColumn(),
        TextColumn("ETA"),
        TimeRemainingColumn(),
        disable=not enabled,
        transient=False,
    )
    task = prog.add_task(description, total=total, rate="")
    return prog, task


def advance(prog, task, n: int) -> None:
    """Advance the bar by ``n`` cases and refresh the rate field."""
    prog.advance(task, n)
    t = prog.tasks[task]
    speed = t.speed
    prog.update(task, rate=f"{speed:,.0f} cases/s" if speed else "")
