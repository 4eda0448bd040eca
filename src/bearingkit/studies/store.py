"""Resumable result store of a study: one Parquet file per finished chunk, written atomically.

SI units: the store keeps whatever the evaluator returned (units in the column names).

Layout of a store directory::

    manifest.json            study fingerprint, number of chunks, chunk size
    chunks/chunk-000017.parquet   results of chunk 17 (case ids + outputs)

A chunk is written to ``chunks/.chunk-000017.parquet.<pid>.tmp``, flushed to disk (fsync) and renamed
onto its final name (``os.replace``: atomic on POSIX). A process killed at any instant therefore
leaves every chunk either complete or absent (stray ``*.tmp`` files are removed on open), and
``resume=True`` recomputes exactly the chunks whose file is absent. The manifest carries a
fingerprint of the study (definition + cases): resuming into a store of another study is an error.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

from bearingkit.errors import InputError

MANIFEST = "manifest.json"
CHUNK_DIR = "chunks"
_CHUNK_RE = re.compile(r"^chunk-(\d{6})\.parquet$")


def _fsync_dir(path: Path) -> None:
    try:
        fd = os.open(path, os.O_RDONLY)
    except OSError:  # pragma: no cover - platforms without directory fds
        return
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def write_atomic(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary file and a rename (never a partial file)."""
    path = Path(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    with open(tmp, "wb") as fh:
        fh.write(data)
        fh.flush()
        os.fsync(fh.fileno())
    os.replace(tmp, path)
    _fsync_dir(path.parent)


class ParquetStore:
    """Chunked Parquet results of one study in ``directory``.

    Parameters
    ----------
    directory : path
        Created if missing.
    """

    def __init__(self, directory):
        self.directory = Path(directory)
        self.chunk_dir = self.directory / CHUNK_DIR

    # -- lifecycle -----------------------------------------------------------------------------
    def open(self, fingerprint: str, n_chunks: int, chunk_size: int, resume: bool) -> set[int]:
        """Prepare the store for a run; returns the ids of the chunks already finished.

        ``resume=False`` starts afresh (previous chunks of this directory are deleted);
        ``resume=True`` keeps them, after checking that they belong to the same study.
        """
        self.chunk_dir.mkdir(parents=True, exist_ok=True)
        for tmp in self.chunk_dir.glob(".*.tmp"):
            tmp.unlink(missing_ok=True)
        manifest = {"fingerprint": fingerprint, "n_chunks": int(n_chunks), "chunk_size": int(chunk_size)}
        mpath = self.directory / MANIFEST
        if resume and mpath.exists():
            old = json.loads(mpath.read_text(encoding="utf-8"))
            if old.get("fingerprint") != fingerprint:
                raise InputError(
                    f"{self.directory}: resume (True) but the store holds another study "
                    "(definition or cases changed); use another --out or run without --resume"
                )
        else:
            for f in self.chunk_dir.glob("chunk-*.parquet"):
                f.unlink()
            write_atomic(mpath, json.dumps(manifest, indent=1).encode())
        return self.finished()

    def finished(self) -> set[int]:
        """Ids of the chunks whose results are on disk."""
        if not self.chunk_dir.exists():
            return set()
        return {int(m.group(1)) for p in self.chunk_dir.iterdir() if (m := _CHUNK_RE.match(p.name))}

    def _path(self, chunk: int) -> Path:
        return self.chunk_dir / f"chunk-{int(chunk):06d}.parquet"

    # -- data ----------------------------------------------------------------------------------
    def write(self, chunk: int, frame) -> None:
        """Store the results of one finished chunk (atomic)."""
        import io

        buf = io.BytesIO()
        frame.to_parquet(buf, index=False)
        write_atomic(self._path(chunk), buf.getvalue())

    def read_chunk(self, chunk: int):
        import pandas as pd

        return pd.read_parquet(self._path(chunk))

    def read(self):
        """All finished chunks as one DataFrame, in chunk order."""
        import pandas as pd

        ids = sorted(self.finished())
        if not ids:
            return pd.DataFrame()
        return pd.concat([self.read_chunk(i) for i in ids], ignore_index=True)


class MemoryStore:
    """The in-memory stand-in for :class:`ParquetStore` (no persistence, no resume)."""

    def __init__(self):
        self._chunks: dict[int, object] = {}

    def open(self, fingerprint: str, n_chunks: int, chunk_size: int, resume: bool) -> set[int]:
        self._chunks.clear()
        return set()

    def finished(self) -> set[int]:
        return set(self._chunks)

    def write(self, chunk: int, frame) -> None:
        self._chunks[int(chunk)] = frame

    def read_chunk(self, chunk: int):
        return self._chunks[int(chunk)]

    def read(self):
        import pandas as pd

        if not self._chunks:
            return pd.DataFrame()
        return pd.concat([self._chunks[i] for i in sorted(self._chunks)], ignore_index=True)


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
