"""Where numba keeps the compiled core: a cache directory per version of the compiled sources.

numba's on-disk cache (``cache=True``) checks only the time stamp of the file that defines a
function. The compiled Newton loop (``analysis/solver/compiled_newton.py``) calls the row responses of
``rows/*/compiled.py``; after an edit of a row module alone
(a ``git checkout``, a merge) the loop's cached machine code still holds the old responses and runs
them silently. Keying the cache directory by a hash of every compiled source (and the numba
version) makes any change recompile everything. numba also files its cache by the sources' path, so
the directory is keyed by the package's folder too (one cache per installed copy).

:func:`configure` must run before numba reads its configuration; each compiled module calls it
before importing numba. A ``NUMBA_CACHE_DIR`` the user set is kept as the base directory.

It also sets OpenMP's wait policy to passive (:data:`THREAD_ENV`) unless the user set one: numba's
OpenMP threading layer otherwise keeps its threads spinning after every parallel call, and a program
that makes many small parallel calls (a study's chunks, a shaft's Newton steps, the web app) paid
that spinning in every call — measured on the 2-core machine (issue 34): an empty parallel loop
15 ms per call with the default policy on a loaded machine, 20 µs with the passive one; batches of
2-100 cases of a 6209 were 20-60x slower per case than batches of 10⁴. The variable is read when
the OpenMP runtime loads (numba's first parallel call), so setting it here, before numba is even
imported, is in time unless another library loaded OpenMP first.
"""

from __future__ import annotations

import hashlib
import os
import time
from contextlib import contextmanager
from pathlib import Path

#: The modules holding ``@njit(cache=True)`` functions, relative to the package root. A new compiled
#: module must be listed here (tests/rows/test_numba_cache.py checks that every one is).
COMPILED_SOURCES = (
    "rows/ball/compiled.py",
    "rows/cylindrical/compiled.py",
    "rows/threaded/compiled.py",
    "rows/threaded/compiled_sharing.py",
    "rows/tapered/compiled.py",
    "analysis/solver/compiled_linalg.py",
    "analysis/solver/compiled_newton.py",
)

#: Threading settings given to the OpenMP runtime when the user set none (see the module docstring).
THREAD_ENV = {"OMP_WAIT_POLICY": "PASSIVE"}
#: File written into the cache directory once every compiled kind has been compiled and cached.
BUILT_MARKER = "built"
#: File held (created exclusively) by the one process building the core, holding "<pid> <host>"; it is
#: taken to be left by a process that died when that process no longer runs on this host, or when it
#: is older than :data:`BUILD_LOCK_STALE_S` (a holder on another host sharing the cache).
BUILD_LOCK = "building"
#: Age [s] after which a build lock is stale (a build takes 1–3 min, 10 on a very loaded machine).
BUILD_LOCK_STALE_S = 1800.0
#: Environment variable: ``0`` stops :func:`start_background_build` (tests, CI and benchmarks build the
#: core with ``bearingkit compile`` in the foreground, or measure without it).
BACKGROUND_ENV = "BEARINGKIT_BACKGROUND_COMPILE"

_PACKAGE = Path(__file__).resolve().parent.parent
_DONE: dict[str, str] = {}


def sources_hash() -> str:
    """SHA-256 (first 16 hex digits) of the compiled sources, their folder and the numba version.

    The folder counts because numba files its cache by the source file's path (a subfolder named
    after a hash of it): a second copy of the same sources (another venv, a clone, a worktree) found
    the first copy's "built" marker, skipped ``bearingkit compile`` and compiled in the foreground on
    its first large job (a minute, unannounced: the fuzz saw it as 30 s hangs).
    """
    from importlib.metadata import PackageNotFoundError, version

    digest = hashlib.sha256()
    try:
        digest.update(version("numba").encode())
    except PackageNotFoundError:  # the caller's numba import fails next and says so
        pass
    digest.update(os.fsencode(_PACKAGE))
    for rel in COMPILED_SOURCES:
        digest.update(rel.encode())
        digest.update((_PACKAGE / rel).read_bytes())
    return digest.hexdigest()[:16]


def cache_dir() -> Path:
    """The directory :func:`configure` points numba at (computed, nothing created or set)."""
    base = os.environ.get("BEARINGKIT_NUMBA_BASE") or os.environ.get("NUMBA_CACHE_DIR")
    if not base:
        xdg = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
        base = str(Path(xdg) / "bearingkit" / "numba")
    if "hash" not in _DONE:
        _DONE["hash"] = sources_hash()
    return Path(base) / _DONE["hash"]


def numba_installed() -> bool:
    """Whether numba can be found (not imported: that takes a third of a second)."""
    from importlib.util import find_spec

    try:
        return find_spec("numba") is not None
    except (ImportError, ValueError):  # sys.modules["numba"] = None (a test hiding it) or a broken entry
        return False


def is_built() -> bool:
    """Whether ``bearingkit compile`` finished for these sources and this numba (no numba import)."""
    try:
        return (cache_dir() / BUILT_MARKER).is_file()
    except OSError:
        return False


def mark_built() -> None:
    """Record that every compiled kind is in the cache (called by the build once it succeeded)."""
    (cache_dir() / BUILT_MARKER).write_text("compiled by bearingkit compile\n", encoding="utf-8")


def _holder_dead(lock: Path) -> bool:
    """Whether the lock file names a process of this host that no longer runs.

    A build killed with SIGKILL (or by the OOM killer, or a fuzz run's timeout) cannot remove its lock;
    by age alone every later ``bearingkit compile`` answered "busy" for :data:`BUILD_LOCK_STALE_S` and
    no background build started. A lock of another host (a shared home), or one without a readable pid
    (written by an older version: the pid alone), is judged by its age only when its host is not ours.
    """
    import socket

    try:
        fields = lock.read_text(encoding="utf-8").split()
        pid = int(fields[0])
    except (OSError, ValueError, IndexError):
        return False
    if len(fields) > 1 and fields[1] != socket.gethostname():
        return False
    if pid <= 0 or pid == os.getpid():
        return False
    try:
        os.kill(pid, 0)  # signal 0: only asks whether the process exists
    except ProcessLookupError:
        return True
    except (PermissionError, OSError):  # exists (another user's) or cannot tell: alive
        return False
    return False


def _stale(lock: Path) -> bool:
    """Whether a build lock is left by a dead build (its process gone, or older than the stale age)."""
    try:
        return time.time() - lock.stat().st_mtime > BUILD_LOCK_STALE_S or _holder_dead(lock)
    except OSError:
        return False


@contextmanager
def build_lock(wait: float = 0.0):
    """Hold the build lock of the cache directory; yields False when another live build holds it.

    ``wait`` [s]: how long to wait for another build to finish (checked every second); a lock whose
    process is gone, or older than :data:`BUILD_LOCK_STALE_S`, is broken.
    """
    folder = cache_dir()
    folder.mkdir(parents=True, exist_ok=True)
    lock = folder / BUILD_LOCK
    deadline = time.monotonic() + wait
    while True:
        try:
            fd = os.open(lock, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644)
            break
        except FileExistsError:
            if not lock.exists() or _stale(lock):  # gone meanwhile, or left by a dead build
                lock.unlink(missing_ok=True)
                continue
            if time.monotonic() >= deadline or is_built():
                yield False
                return
            time.sleep(1.0)
    try:
        import socket

        os.write(fd, f"{os.getpid()} {socket.gethostname()}\n".encode())
        os.close(fd)
        yield True
    finally:
        lock.unlink(missing_ok=True)


def background_allowed() -> bool:
    """Whether :data:`BACKGROUND_ENV` allows a background build (anything but ``0``)."""
    return os.environ.get(BACKGROUND_ENV, "1").strip() != "0"


def start_background_build() -> bool:
    """Start ``python -m bearingkit compile --quiet --wait 0`` detached, once per process; True if started.

    Nothing is started when :data:`BACKGROUND_ENV` is ``0``, when the core is built, or when a build
    is already running (its lock file exists and its process runs). The child's output goes to the null
    device; it outlives this process (its own session), so a one-line command that answered on the
    numpy core leaves the compiled core built for the next one.
    """
    if _DONE.get("spawned") or not background_allowed() or is_built():
        return False
    _DONE["spawned"] = "1"
    lock = cache_dir() / BUILD_LOCK
    if lock.exists() and not _stale(lock):
        return False
    import subprocess
    import sys

    try:
        subprocess.Popen(
            [sys.executable, "-m", "bearingkit", "compile", "--quiet", "--wait", "0"],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            start_new_session=True,
            env={**os.environ, BACKGROUND_ENV: "0"},
        )
    except OSError:  # no interpreter to start (embedded Python): the next big job compiles instead
        return False
    return True


def configure() -> str | None:
    """Point numba's cache at ``<base>/<sources_hash>``; the directory used, or None if left alone.

    ``<base>`` is ``$NUMBA_CACHE_DIR`` if the user set it, else ``$XDG_CACHE_HOME/bearingkit/numba``
    (``~/.cache/bearingkit/numba``). If that directory cannot be created, numba's default (the
    ``__pycache__`` beside the sources) stays in use.
    """
    if "dir" in _DONE:
        return _DONE["dir"] or None
    for name, value in THREAD_ENV.items():
        os.environ.setdefault(name, value)
    target = cache_dir()
    base = str(target.parent)
    try:
        target.mkdir(parents=True, exist_ok=True)
    except OSError:  # read-only home: numba's default location still works
        _DONE["dir"] = ""
        return None
    os.environ["BEARINGKIT_NUMBA_BASE"] = base  # so a second configure() keeps the same base
    os.environ["NUMBA_CACHE_DIR"] = str(target)
    import sys

    if "numba.core.config" in sys.modules:  # numba already imported elsewhere: re-read the setting
        sys.modules["numba.core.config"].reload_config()
    _DONE["dir"] = str(target)
    return str(target)
