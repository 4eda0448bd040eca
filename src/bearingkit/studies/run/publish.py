"""The final outputs of a study, published as one set: the old complete set or the new, never a mix.

No units here (files only; the tables carry units in their column names).

A killed run used to leave a truncated ``results.csv`` beside the previous ``summary.json`` (issue 24).
:func:`publish` writes the whole set into ``OUT/.outputs/<run>.partial/`` (each file flushed to disk),
renames that folder to ``OUT/.outputs/<run>/`` when it is complete, and then switches one symbolic
link, ``OUT/current``, to it (``os.replace`` of a link: atomic on POSIX). ``OUT/results.csv`` and the
other names are relative links ``current/results.csv``, so whoever reads them, at any instant, reads
either the previous complete set or the new complete set. The previous set is deleted after the
switch; a kill before that leaves an extra folder in ``.outputs`` that the next publish removes.

Where symbolic links cannot be made (Windows without the privilege), each file is written to a
temporary name, flushed and renamed onto its final name, ``summary.json`` last: every file is then
complete, but a kill between two renames leaves files of two runs side by side (``summary.json`` lists
the files of its run with their sizes, so a reader can tell).
"""

from __future__ import annotations

import os
import shutil
import time
from collections.abc import Callable, Mapping
from pathlib import Path

#: Hidden folder holding the output sets (one per run; only the current one survives a publish).
OUTPUTS_DIR = ".outputs"

#: The link naming the current output set.
CURRENT = "current"

#: Every final output a study may write (the names a study folder may hold besides its store).
OUTPUT_FILES = (
    "results.parquet",
    "results.csv",
    "main_effects.csv",
    "range.csv",
    "main_effects.png",
    "range.png",
    "point_statistics.csv",
    "point_statistics.png",
    "range_std.csv",
    "pareto.csv",
    "selections.csv",
    "pareto.png",
    "statistics.csv",
    *(f"plot_{i}.png" for i in range(1, 10)),
    "summary.json",
)


def fsync_dir(path: Path) -> None:
    """Flush a directory entry (a rename is durable only once its directory is)."""
    try:
        fd = os.open(path, os.O_RDONLY)
    except OSError:  # pragma: no cover - platforms without directory fds
        return
    try:
        os.fsync(fd)
    except OSError:  # pragma: no cover - some filesystems refuse fsync on directories
        pass
    finally:
        os.close(fd)


def _fsync_file(path: Path) -> None:
    with open(path, "rb+") as fh:
        os.fsync(fh.fileno())


def _tmp(path: Path) -> Path:
    return path.with_name(f".{path.name}.{os.getpid()}.tmp")


def _link(path: Path, target: str) -> None:
    """Make ``path`` a symbolic link to ``target`` in one atomic step (replacing what was there)."""
    tmp = _tmp(path)
    if tmp.is_symlink() or tmp.exists():
        tmp.unlink()
    os.symlink(target, tmp)
    os.replace(tmp, path)


def symlinks_work(directory: Path) -> bool:
    """True when symbolic links can be made in ``directory``."""
    probe = _tmp(Path(directory) / "symlink-probe")
    try:
        if probe.is_symlink():
            probe.unlink()
        os.symlink("probe", probe)
    except (OSError, NotImplementedError):
        return False
    probe.unlink()
    return True


def run_id() -> str:
    """A name for one run's output set: UTC time and the process id (sortable, unique per process)."""
    return time.strftime("%Y%m%dT%H%M%SZ", time.gmtime()) + f"-{os.getpid()}-{time.monotonic_ns()}"


def publish(directory, writers: Mapping[str, Callable[[Path], None]], run: str | None = None) -> Path:
    """Write the outputs of one run and make them current as one set.

    Parameters
    ----------
    directory : path
        The study's output directory (locked by the caller).
    writers : mapping
        Output name (one of :data:`OUTPUT_FILES`) → function writing that file at the path it is given.
    run : str or None
        Name of the output set (default :func:`run_id`).

    Returns
    -------
    Path
        The folder now holding the current set.
    """
    d = Path(directory)
    unknown = [n for n in writers if n not in OUTPUT_FILES]
    if unknown:
        raise ValueError(f"not study outputs: {unknown}")
    if not symlinks_work(d):
        return _publish_per_file(d, writers)
    run = run or run_id()
    root = d / OUTPUTS_DIR
    root.mkdir(exist_ok=True)
    staging = root / f"{run}.partial"
    staging.mkdir()
    for name, write in writers.items():
        write(staging / name)
        _fsync_file(staging / name)
    fsync_dir(staging)
    final = root / run
    os.replace(staging, final)
    fsync_dir(root)
    # Links for the new names first: a name the old set lacks dangles (reads as absent) until the switch.
    for name in writers:
        _link(d / name, f"{CURRENT}/{name}")
    _link(d / CURRENT, f"{OUTPUTS_DIR}/{run}")  # the switch
    fsync_dir(d)
    for name in OUTPUT_FILES:  # names of the old set that the new one lacks
        if name not in writers and ((d / name).is_symlink() or (d / name).is_file()):
            (d / name).unlink()
    for old in root.iterdir():
        if old.name != run and old.is_dir() and not old.is_symlink():
            shutil.rmtree(old)
    return final


def _publish_per_file(d: Path, writers: Mapping[str, Callable[[Path], None]]) -> Path:
    """Fallback without symbolic links: every file atomic on its own, ``summary.json`` last."""
    names = sorted(writers, key=lambda n: n == "summary.json")
    for name in names:
        tmp = _tmp(d / name)
        writers[name](tmp)
        _fsync_file(tmp)
        os.replace(tmp, d / name)
    fsync_dir(d)
    for name in OUTPUT_FILES:
        if name not in writers and (d / name).is_file():
            (d / name).unlink()
    return d
