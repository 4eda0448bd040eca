"""The shaft and drivetrain pages: a system file (an example, an upload or the page's edited text) solved
and shown with every bearing's results.

SI inside; the file is TOML text parsed as data (the bounded parser of :mod:`bearingkit.io.reading`) and
validated by the same readers as ``bearingkit shaft`` / ``bearingkit system``
(:func:`~bearingkit.systems.shaft.input.shaft_from_dict`,
:func:`~bearingkit.systems.drivetrain.input.drivetrain_from_dict`); the results are
:meth:`ShaftAnalysis.to_dict() <bearingkit.systems.shaft.shaft_analysis.ShaftAnalysis.to_dict>` and
:meth:`DrivetrainAnalysis.to_dict() <bearingkit.systems.drivetrain.analysis.DrivetrainAnalysis.to_dict>`,
the same dicts as the commands' ``--json``.

Bearing files a system names (``file = "dgbb_6209.toml"``) are looked up among the example bearings by
name, never as paths: a file sent to the server cannot make it read another file. Bearings by
designation or by stiffness need no file. The app caps the load cases per system
(:data:`MAX_SYSTEM_CASES`), below the files' own caps, so one request stays a few seconds.
"""

from __future__ import annotations

import copy
import hashlib
import threading
import tomllib
from collections import OrderedDict
from pathlib import Path
from typing import Literal

from pydantic import Field

from bearingkit.app.common import TooLarge
from bearingkit.app.form import (
    EXAMPLES_DIR,
    FRICTION_CHOICES,
    MAX_TOML_BYTES,
    FormText,
    StrictModel,
    examples,
)
from bearingkit.errors import InputError

__all__ = [
    "MAX_SYSTEM_CASES",
    "SYSTEMS",
    "KeptSystems",
    "SystemRequest",
    "SystemSource",
    "analyse_system",
    "bearing_files_of",
    "system_examples",
]

#: The two kinds of system file and the top-level table that tells them apart.
SYSTEMS = {"shaft": "shaft", "drivetrain": "shafts"}
#: Most load cases of a system the app solves in one request (each is a Newton of the whole system and
#: every bearing's analysis; the countershaft example's 3 cases take ~1 s, the two-stage gearbox's 4
#: ~3 s on the 2-core reference machine). ``bearingkit shaft``/``system`` take up to the files' caps.
MAX_SYSTEM_CASES = 24
#: Solved systems kept for their figures (a ShaftResult holds every case's lines: ~100 kB).
MAX_KEPT_SYSTEMS = 8


class SystemSource(StrictModel):
    """A system file: an example by name, or text the page sends (an upload, or the editor's text)."""

    kind: Literal["example", "upload"]
    name: str = Field(min_length=1, max_length=256)
    text: str | None = None


class SystemRequest(StrictModel):
    """Solve a shaft or a drivetrain file."""

    system: Literal["shaft", "drivetrain"]
    source: SystemSource
    friction_model: Literal[FRICTION_CHOICES] = "auto"
    contamination: FormText = ""
    heat: bool = Field(False, description="Each bearing's temperature by its heat balance (else the file's).")


def _kind_of(path: Path) -> str | None:
    try:
        if path.stat().st_size > MAX_TOML_BYTES:
            return None
        data = tomllib.loads(path.read_text("utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError):
        return None
    if isinstance(data.get("shaft"), dict):
        return "shaft"
    if isinstance(data.get("shafts"), list):
        return "drivetrain"
    return None


def system_examples() -> dict[str, list[str]]:
    """File names of the example shafts and drivetrains (TOML), sorted."""
    out: dict[str, list[str]] = {"shaft": [], "drivetrain": []}
    if EXAMPLES_DIR.is_dir():
        for p in sorted(EXAMPLES_DIR.glob("*.toml")):
            kind = _kind_of(p) if p.is_file() else None
            if kind is not None:
                out[kind].append(p.name)
    return out


def read_system(request: SystemRequest) -> tuple[dict, str, str]:
    """(parsed document, name for messages, the file's text) of the request's source."""
    from bearingkit.io.reading import parse_toml

    src = request.source
    if src.kind == "example":
        if src.name not in system_examples()[request.system]:  # a name from the list, never a path
            names = ", ".join(system_examples()[request.system]) or "none"
            raise InputError(f"example ({src.name!r}) is not one of the {request.system} examples: {names}")
        text = (EXAMPLES_DIR / src.name).read_text(encoding="utf-8")
        name = src.name
    else:
        name = Path(src.name).name or f"{request.system}.toml"
        if src.text is None:
            raise InputError(f"{name}: no file content received")
        text = src.text
    size = len(text.encode("utf-8"))
    if size > MAX_TOML_BYTES:
        raise TooLarge(f"{name}: file too large ({size} bytes); at most {MAX_TOML_BYTES} bytes")
    document = parse_toml(text, name)
    table = SYSTEMS[request.system]
    other = next(k for k in SYSTEMS if k != request.system)
    if table not in document:
        hint = (
            f"; it looks like a {other} file: open it on the {other} page"
            if SYSTEMS[other] in document
            else ""
        )
        raise InputError(f"{name}: {table}: missing; a {request.system} file has [{table}]{hint}")
    cases = document.get("load_cases")
    if isinstance(cases, list) and len(cases) > MAX_SYSTEM_CASES:
        raise InputError(
            f"{name}: load_cases ({len(cases)}) must be at most {MAX_SYSTEM_CASES} in the app; split the "
            f"file or run bearingkit {'shaft' if request.system == 'shaft' else 'system'} on it"
        )
    return document, name, text


def bearing_files_of(document, where: str = "") -> list[tuple[str, object]]:
    """(path in the document, value) of every ``file`` key in ``document`` (bearing files of a system)."""
    out = []
    if isinstance(document, dict):
        for key, value in document.items():
            path = f"{where}.{key}" if where else str(key)
            if key == "file":
                out.append((path, value))
            else:
                out.extend(bearing_files_of(value, path))
    elif isinstance(document, list):
        for i, value in enumerate(document):
            out.extend(bearing_files_of(value, f"{where}[{i}]"))
    return out


def _check_bearing_files(document: dict, name: str) -> None:
    """Every bearing file a system names must be an example bearing, by name (module docstring)."""
    known = examples()
    for path, value in bearing_files_of(document):
        if not isinstance(value, str) or value not in known:
            raise InputError(
                f"{name}: {path} ({str(value)[:60]!r}) must name an example bearing file, such as "
                f"{known[0] if known else 'dgbb_6209.toml'} (the app reads no other file); or give the "
                'bearing by designation = "6209"'
            )


def analyse_system(request: SystemRequest):
    """(analysis, text of the file, name): a ShaftAnalysis or DrivetrainAnalysis of the request, solved."""
    document, name, text = read_system(request)
    _check_bearing_files(document, name)
    contamination = request.contamination.strip() or None
    if request.system == "shaft":
        from bearingkit.systems.shaft.input import shaft_from_dict
        from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis

        inp = shaft_from_dict(copy.deepcopy(document), name, base=EXAMPLES_DIR)
        analysis = ShaftAnalysis(
            inp,
            friction_model=request.friction_model,
            contamination=contamination,
            thermal=True if request.heat else None,  # off: the file's [thermal] decides
        )
    else:
        from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
        from bearingkit.systems.drivetrain.input import drivetrain_from_dict

        inp = drivetrain_from_dict(copy.deepcopy(document), name, base=EXAMPLES_DIR)
        model = "components" if request.friction_model == "auto" else request.friction_model
        analysis = DrivetrainAnalysis(
            inp, friction_model=model, contamination=contamination, thermal=True if request.heat else None
        )
    analysis.result  # noqa: B018 - solve now, under the caller's lock
    return analysis, text, name


def system_id(request: SystemRequest, text: str) -> str:
    """16 hex digits naming a solved system (same kind, text and settings: same id)."""
    key = "\0".join((request.system, text, request.friction_model, request.contamination, str(request.heat)))
    return hashlib.sha256(key.encode("utf-8")).hexdigest()[:16]


class KeptSystems:
    """The newest solved systems by id (thread-safe LRU), for their figures."""

    def __init__(self, most: int = MAX_KEPT_SYSTEMS):
        self.most = most
        self._kept: OrderedDict[str, object] = OrderedDict()
        self._lock = threading.Lock()

    def put(self, key: str, analysis) -> None:
        with self._lock:
            self._kept[key] = analysis
            self._kept.move_to_end(key)
            while len(self._kept) > self.most:
                self._kept.popitem(last=False)

    def get(self, key: str):
        with self._lock:
            return self._kept.get(key)

    def clear(self) -> None:
        with self._lock:
            self._kept.clear()
