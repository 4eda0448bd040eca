"""The compiled core's disk cache follows its sources (numba alone checks only the defining file)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

from bearingkit.rows import numba_cache

PACKAGE = Path(numba_cache.__file__).resolve().parent.parent


def test_every_cached_njit_module_is_hashed():
    """A module with ``cache=True`` kernels that is not hashed would bring the stale-cache bug back."""
    cached = {
        p.relative_to(PACKAGE).as_posix()
        for p in PACKAGE.rglob("*.py")
        if re.search(r"^@njit\([^)]*cache=True", p.read_text(encoding="utf-8"), re.MULTILINE)
    }
    assert cached and cached == set(numba_cache.COMPILED_SOURCES)


def test_cache_directory_changes_with_any_compiled_source(tmp_path, monkeypatch):
    """Editing one row module (not the Newton loop that calls it) moves the cache directory."""
    copy = tmp_path / "bearingkit"
    for rel in numba_cache.COMPILED_SOURCES:
        (copy / rel).parent.mkdir(parents=True, exist_ok=True)
        (copy / rel).write_bytes((PACKAGE / rel).read_bytes())
    monkeypatch.setattr(numba_cache, "_PACKAGE", copy)
    before = numba_cache.sources_hash()
    assert numba_cache.sources_hash() == before  # deterministic
    row = copy / "rows/cylindrical/compiled.py"
    row.write_text(row.read_text(encoding="utf-8") + "\n# an edit\n", encoding="utf-8")
    assert numba_cache.sources_hash() != before


def test_a_fresh_process_uses_the_hashed_directory_under_the_users_base(tmp_path):
    """A NUMBA_CACHE_DIR the user set stays the base; numba writes its index files below the hash."""
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    env.pop("BEARINGKIT_NUMBA_BASE", None)
    code = "import numba.core.config as c\nimport bearingkit.rows.cylindrical.compiled\nprint(c.CACHE_DIR)"
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    used = Path(out.stdout.strip().splitlines()[-1])
    assert used == tmp_path / numba_cache.sources_hash()
    assert used.is_dir()


def test_a_second_copy_of_the_same_sources_gets_its_own_cache(tmp_path, monkeypatch):
    """numba files its cache by the source path: a copy elsewhere (a venv, a clone) must not find the
    first copy's "built" marker and then compile for a minute on its first large job."""
    hashes = []
    for name in ("a", "b"):
        copy = tmp_path / name / "bearingkit"
        for rel in numba_cache.COMPILED_SOURCES:
            (copy / rel).parent.mkdir(parents=True, exist_ok=True)
            (copy / rel).write_bytes((PACKAGE / rel).read_bytes())
        monkeypatch.setattr(numba_cache, "_PACKAGE", copy)
        hashes.append(numba_cache.sources_hash())
    assert hashes[0] != hashes[1]
