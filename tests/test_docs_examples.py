"""The Python examples of docs/ run as written (a new user copies them; placeholders such as ``...``
or names defined nowhere once made docs/ratings.md and docs/systems.md fail on the first run).

Blocks of one page share a namespace, in order, as a reader runs them; the ROSS block of
docs/systems.md needs the optional ``[ross]`` extra and is run by the ``ross`` suite instead.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BLOCK = re.compile(r"```python\n(.*?)```", re.S)
#: (page, number of its leading python blocks that run without optional extras)
PAGES = [
    ("catalogue.md", 1),
    ("engine.md", 1),
    ("ratings.md", 1),
    ("subsurface.md", 1),
    ("systems.md", 2),
    ("lubricants.md", 1),
    ("drivetrains.md", 1),
    ("index.md", 1),
    ("structure.md", 1),
]


def _run(page: str, n_blocks: int) -> str:
    blocks = BLOCK.findall((ROOT / "docs" / page).read_text(encoding="utf-8"))
    assert len(blocks) >= n_blocks, f"docs/{page} lost its examples"
    namespace = {"__name__": "docs"}
    out = io.StringIO()
    cwd = os.getcwd()
    os.chdir(ROOT)  # the examples name files relative to the repository, and write under out/
    try:
        with contextlib.redirect_stdout(out):
            for code in blocks[:n_blocks]:
                exec(compile(code, f"docs/{page}", "exec"), namespace)
    finally:
        os.chdir(cwd)
    return out.getvalue()


#: What each page's examples print (a piece of it): the run reached its last line.
PRINTS = {
    "catalogue.md": "6308 2RS1 contact_seal C3",
    "engine.md": "",
    "ratings.md": "'L10r_rev'",
    "subsurface.md": "[",
    "systems.md": "[",
    "lubricants.md": "VG68 ester: VI 140",
    "drivetrains.md": "0.98",
    "index.md": "",
    "structure.md": "3 5",
}


@pytest.mark.parametrize("page, n_blocks", PAGES, ids=[p for p, _ in PAGES])
def test_docs_python_examples_run_as_written(page, n_blocks):
    assert PRINTS[page] in _run(page, n_blocks)


def test_every_docs_page_with_python_is_covered():
    pages = {p.name for p in (ROOT / "docs").glob("*.md") if BLOCK.search(p.read_text(encoding="utf-8"))}
    assert pages == {p for p, _ in PAGES}
