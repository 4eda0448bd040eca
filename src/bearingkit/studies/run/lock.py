"""One writer per study output directory: an advisory lock held for the whole run.

No units here (files and processes only).

Two ``bearingkit study … --out X`` runs on one directory used to interleave their chunk files and
both exit 0 (issue 24). A run now holds ``X/.bearingkit.lock`` from before its first write until its
outputs are published:

- the lock is an operating-system file lock (``flock`` on POSIX, ``msvcrt.locking`` on Windows) on
  that file, so the system releases it when the holder ends in any way, SIGKILL included — a lock
  can never outlive its process, and nothing has to guess whether a pid is still alive;
- the file names the holder (pid, host, start time, study), so a second writer is refused with one
  line naming it;
- a holder that ends normally empties the file; a holder killed mid-run leaves its record behind,
  and the next run that takes the lock says it recovered a stale lock of that study.

On NFS the lock is as good as the server's lock support (NFSv4 locks work across clients).
"""

from __future__ import annotations

import json
import os
import socket
import time
from pathlib import Path

from bearingkit.errors import InputError

#: The lock file inside a study's output directory.
LOCK_FILE = ".bearingkit.lock"

#: Most bytes of a holder record read back (a record is ~150 bytes; the file may be damaged).
_RECORD_BYTES = 4096

try:  # POSIX
    import fcntl

    def _try_lock(fd: int) -> bool:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            return False
        return True

    def _unlock(fd: int) -> None:
        fcntl.flock(fd, fcntl.LOCK_UN)

except ImportError:  # pragma: no cover - Windows
    import msvcrt

    # Windows locks byte ranges and a locked range cannot be read by others: lock one byte far past
    # the record, so a refused run can still read who holds the folder.
    _LOCK_OFFSET = 1 << 20

    def _try_lock(fd: int) -> bool:
        os.lseek(fd, _LOCK_OFFSET, os.SEEK_SET)
        try:
            msvcrt.locking(fd, msvcrt.LK_NBLCK, 1)
        except PermissionError:
            return False
        return True

    def _unlock(fd: int) -> None:
        os.lseek(fd, _LOCK_OFFSET, os.SEEK_SET)
        msvcrt.locking(fd, msvcrt.LK_UNLCK, 1)


def describe(holder: dict) -> str:
    """``study 'x' (pid 123 on host h, started 2026-01-01T12:00:00Z)`` from a holder record."""
    return (
        f"study {holder.get('study', '?')!r} (pid {holder.get('pid', '?')} on host "
        f"{holder.get('host', '?')}, started {holder.get('started', '?')})"
    )


def _read_record(fd: int) -> dict | None:
    """The holder record in the lock file, {} when unreadable, None when the file is empty."""
    os.lseek(fd, 0, os.SEEK_SET)
    raw = os.read(fd, _RECORD_BYTES)
    if not raw.strip():
        return None
    try:
        record = json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, ValueError):
        return {}
    return record if isinstance(record, dict) else {}


class StoreLock:
    """The lock of one output directory for one study run.

    Parameters
    ----------
    directory : path
        The output directory (must exist).
    study : str
        The study's name, written into the lock for whoever is refused.
    """

    def __init__(self, directory, study: str):
        self.directory = Path(directory)
        self.path = self.directory / LOCK_FILE
        self.study = study
        self._fd: int | None = None

    @property
    def held(self) -> bool:
        return self._fd is not None

    def acquire(self) -> dict | None:
        """Take the lock; returns the record of a stale holder it replaced (None if there was none).

        Raises
        ------
        InputError
            One line naming the live holder when another run holds the directory.
        """
        if self._fd is not None:
            return None
        flags = os.O_RDWR | os.O_CREAT | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_BINARY", 0)
        try:
            fd = os.open(self.path, flags, 0o644)
        except OSError as exc:
            raise InputError(f"{self.directory}: cannot create the lock file {LOCK_FILE} ({exc})") from None
        try:
            locked = _try_lock(fd)
        except OSError as exc:  # a file system without locks (some network or FUSE mounts)
            os.close(fd)
            raise InputError(
                f"{self.directory}: cannot lock {LOCK_FILE} ({exc.strerror or exc}); choose an --out on a "
                "local disk"
            ) from None
        if not locked:
            holder = _read_record(fd) or {}
            os.close(fd)
            raise InputError(
                f"{self.directory} is in use by {describe(holder)}: wait for it to finish, "
                "or choose another --out"
            )
        stale = _read_record(fd)
        record = {
            "pid": os.getpid(),
            "host": socket.gethostname(),
            "started": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
            "study": self.study,
        }
        data = json.dumps(record).encode()
        os.ftruncate(fd, 0)
        os.lseek(fd, 0, os.SEEK_SET)
        os.write(fd, data)
        os.fsync(fd)
        self._fd = fd
        return stale

    def release(self) -> None:
        """Empty the record and let go (a clean end leaves no stale lock behind)."""
        fd, self._fd = self._fd, None
        if fd is None:
            return
        try:
            os.ftruncate(fd, 0)
            os.fsync(fd)
            _unlock(fd)
        finally:
            os.close(fd)

    def __enter__(self):
        self.acquire()
        return self

    def __exit__(self, *exc):
        self.release()
