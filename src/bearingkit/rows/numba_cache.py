"""Where numba keeps the compiled core: a cache directory per version of the compiled sources.

numba's on-disk cache (``cache=True``) checks only the time stamp of the file that defines a
function. The compiled Newton loop (``analysis/solver/compiled_newton.py``) calls the row responses of
``rows/*/compiled.py``; after an edit of a row module alone
(a ``git checkout``, a merge) the loop's cached machine code still holds the old responses and runs
them silently. Keying the cache directory by a hash of every compiled source (and the numba
version) makes any change recompile everything, and lets identical sources share one cache.

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
from pathlib import Path

#: The modules holding ``@njit(cache=True)`` functions, relative to the package root. A new compiled
#: module must be listed here (tests/rows/test_numba_cache.py checks that every one is).
COMPILED_SOURCES = (
    "rows/ball/compiled.py",
    "rows/cylindrical/compiled.py",
    "rows/threaded/compiled.py",
    "rows/tapered/compiled.py",
    "analysis/solver/compiled_linalg.py",
    "analysis/solver/compiled_newton.py",
)

#: Threading settings given to the OpenMP runtime when the user set none (see the module docstring).
THREAD_ENV = {"OMP_WAIT_POLICY": "PASSIVE"}

_PACKAGE = Path(__file__).resolve().parent.parent
_DONE: dict[str, str] = {}


def sources_hash() -> str:
    """SHA-256 (first 16 hex digits) of the compiled sources and the installed numba version."""
    from importlib.metadata import PackageNotFoundError, version

    digest = hashlib.sha256()
    try:
        digest.update(version("numba").encode())
    except PackageNotFoundError:  # the caller's numba import fails next and says so
        pass
    for rel in COMPILED_SOURCES:
        digest.update(rel.encode())
        digest.update((_PACKAGE / rel).read_bytes())
    return digest.hexdigest()[:16]


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
    base = os.environ.get("BEARINGKIT_NUMBA_BASE") or os.environ.get("NUMBA_CACHE_DIR")
    if not base:
        xdg = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
        base = str(Path(xdg) / "bearingkit" / "numba")
    target = Path(base) / sources_hash()
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
