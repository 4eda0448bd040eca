"""Check the built documentation site (``make docs`` runs it after ``mkdocs build --strict``).

- the API page lists ``bearingkit.analyze`` with its signature and every parameter of its docstring;
- each gallery example has its page with its output and at least one figure (unless the build left the
  gallery out: ``BEARINGKIT_DOCS_GALLERY=0``);
- every user-guide page of ``docs/`` was built.

Prints one line per check (``site-check: …``); exit 1 on the first failure.
"""

from __future__ import annotations

import html
import inspect
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def text_of(path: Path) -> str:
    return html.unescape(re.sub(r"<[^>]+>", " ", path.read_text(encoding="utf-8")))


def main(site: Path) -> int:
    sys.path.insert(0, str(ROOT / "src"))
    from bearingkit.pipeline.analysis import analyze

    api = text_of(site / "reference" / "index.html")
    params = list(inspect.signature(analyze).parameters)
    missing = [p for p in params if not re.search(rf"\b{p}\b", api)]
    named = re.search(r"bearingkit\s*\.\s*analyze", api) and re.search(r"\banalyze\s*\(", api)
    if not named or missing:
        print(f"site-check: FAILED: reference/index.html lacks bearingkit.analyze or parameters {missing}")
        return 1
    print(f"site-check: API page lists bearingkit.analyze with its parameters ({', '.join(params)})")
    pages = sorted(p.stem for p in (ROOT / "docs").glob("*.md"))
    absent = [p for p in pages if not (site / (p if p != "index" else "") / "index.html").is_file()]
    if absent:
        print(f"site-check: FAILED: pages not built: {absent}")
        return 1
    print(f"site-check: {len(pages)} user-guide pages built")
    scripts = sorted((ROOT / "examples" / "gallery").glob("[0-9]*.py"))
    index = (site / "gallery" / "index.html").read_text(encoding="utf-8")
    if "were not run for this build" in index:
        print(f"site-check: gallery not run for this build ({len(scripts)} examples listed)")
        return 0
    for script in scripts:
        page = site / "gallery" / script.stem / "index.html"
        figures = list((site / "gallery" / script.stem).glob("*.png"))
        if not page.is_file() or not figures or "Output:" not in text_of(page):
            print(f"site-check: FAILED: {script.name}: page {page.is_file()}, {len(figures)} figures")
            return 1
    print(f"site-check: gallery: {len(scripts)} examples executed, each with its output and figures")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "out" / "site"))
