"""The server's memory: recent analyses by id, and the one temporary folder downloads are written to.

SI inside (nothing here computes). An analysis is kept under the id the page was given so that its
downloads (TOML, JSON, HTML report) are "what is on screen" without recomputing; the newest
:data:`MAX_KEPT` are kept. Files are written only inside the store's temporary folder, under names the
server makes (``<id>.<ext>``), and removed with the analysis they belong to and when the server stops.
"""

from __future__ import annotations

import hashlib
import json
import re
import shutil
import tempfile
import threading
from collections import OrderedDict
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path

import tomli_w

from bearingkit.errors import InputError
from bearingkit.io.export import to_json

__all__ = ["DOWNLOADS", "MAX_KEPT", "Kept", "Store", "request_id"]

#: Analyses kept for their downloads (each holds its solved cases: ~kB for a standard bearing).
MAX_KEPT = 64
#: Download kinds: extension → media type.
DOWNLOADS = {"toml": "application/toml", "json": "application/json", "html": "text/html"}
#: A download name: an id the server made and a known extension (anything else is refused).
DOWNLOAD_NAME = re.compile(r"^([0-9a-f]{16})\.(toml|json|html)$")


def request_id(payload: dict) -> str:
    """16 hex digits identifying a page state (equal states share an id, and their analysis)."""
    text = json.dumps(payload, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


@dataclass
class Kept:
    """An analysis and the input document it was made from."""

    analysis: object
    document: dict
    source: str
    contamination: str = ""
    friction_model: str = "auto"

    @property
    def stem(self) -> str:
        """A safe base name for downloads (``dgbb_6209``, ``6205-2RS_C3``)."""
        stem = Path(self.source).stem if self.source.endswith(".toml") else self.source
        return re.sub(r"[^A-Za-z0-9._-]+", "_", stem).strip("._") or "bearing"


class Store:
    """Recent analyses (LRU, thread-safe) and the server's temporary folder.

    Parameters
    ----------
    root : Path, optional
        Folder for the downloads; default a new temporary folder, made when the first download is
        written and removed by :meth:`close`.
    max_kept : int
    """

    def __init__(self, root: Path | None = None, max_kept: int = MAX_KEPT):
        self._own = root is None
        self._root = None if root is None else Path(root)
        self.max_kept = max_kept
        self._kept: OrderedDict[str, Kept] = OrderedDict()
        self._lock = threading.Lock()

    @property
    def root(self) -> Path:
        """The folder downloads are written to (a new temporary folder, made on first use)."""
        with self._lock:
            if self._root is None:
                self._root = Path(tempfile.mkdtemp(prefix="bearingkit-serve-"))
            self._root.mkdir(parents=True, exist_ok=True)
            return self._root

    def put(self, key: str, kept: Kept) -> None:
        with self._lock:
            self._kept[key] = kept
            self._kept.move_to_end(key)
            while len(self._kept) > self.max_kept:
                old, _ = self._kept.popitem(last=False)
                for ext in DOWNLOADS:
                    if self._root is not None:
                        (self._root / f"{old}.{ext}").unlink(missing_ok=True)

    def get(self, key: str) -> Kept | None:
        with self._lock:
            kept = self._kept.get(key)
            if kept is not None:
                self._kept.move_to_end(key)
            return kept

    def download(self, name: str) -> tuple[Path, str, str]:
        """(path, media type, name for the user) of download ``name`` = ``<id>.<ext>``; written on first use.

        Raises
        ------
        LookupError
            ``name`` is not a download of a kept analysis (unknown id or extension, or any path).
        """
        m = DOWNLOAD_NAME.fullmatch(name)
        if m is None:
            raise LookupError(name)
        key, ext = m.groups()
        kept = self.get(key)
        if kept is None:
            raise LookupError(name)
        path = self.root / f"{key}.{ext}"
        # cannot happen with the pattern above; a second guard against a path outside the folder
        if path.resolve().parent != self.root.resolve():
            raise LookupError(name)
        if not path.is_file():
            self._write(kept, path, ext)
        return path, DOWNLOADS[ext], f"{kept.stem}.{ext}"

    def _write(self, kept: Kept, path: Path, ext: str) -> None:
        tmp = path.with_name(f".{path.name}.tmp")
        if ext == "html":
            kept.analysis.report(path)
            return
        if ext == "json":
            try:
                text = to_json(kept.analysis.to_dict())
            except ValueError as exc:
                raise InputError(f"{kept.source}: {exc}") from None
        else:
            text = toml_text(kept)
        tmp.write_text(text, encoding="utf-8")
        tmp.replace(path)

    def close(self) -> None:
        """Forget every analysis and remove the temporary folder (when the store made it)."""
        with self._lock:
            self._kept.clear()
            if self._own and self._root is not None:
                shutil.rmtree(self._root, ignore_errors=True)
                self._root = None


def toml_text(kept: Kept) -> str:
    """The input file of what the page shows: the document as TOML, under a header saying where it is from."""
    stamp = datetime.now(UTC).strftime("%Y-%m-%d %H:%M UTC")
    lines = [
        f"# Written by `bearingkit serve` on {stamp} from {kept.source}: the bearing and the load case",
        "# on screen (comments of the original file are not kept). Analyse it again with",
        f"#     bearingkit analyze {kept.stem}.toml",
    ]
    if kept.contamination.strip():
        lines.append(
            f"# The page also used contamination e_C = {kept.contamination.strip()} (no file field; give "
            f"--contamination {kept.contamination.strip()} to bearingkit rating)."
        )
    if kept.friction_model != "auto":
        lines.append(f"# Friction model on the page: {kept.friction_model} (bearingkit friction --model).")
    return "\n".join(lines) + "\n\n" + tomli_w.dumps(kept.document)
