"""MkDocs hook: the example gallery, executed at build time (``hooks:`` in mkdocs.yml).

Every ``examples/gallery/NN_name.py`` runs in its own interpreter from the repository root (as a user
would run it), with ``BEARINGKIT_GALLERY_OUT`` pointing at a folder for its figures. Its page
``gallery/NN_name.md`` holds the script's docstring, its code, what it printed and its figures; the
index ``gallery/index.md`` links them. A script that fails (exit code ≠ 0, or no output) fails the
build with its output, so the gallery cannot go stale silently. Scripts run two at a time.

``BEARINGKIT_DOCS_GALLERY=0`` builds the index alone, saying the examples were not run (the test of
the API pages builds the site that way, in seconds).
"""

from __future__ import annotations

import ast
import os
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from mkdocs.exceptions import PluginError
from mkdocs.structure.files import File

ROOT = Path(__file__).resolve().parents[1]
GALLERY = ROOT / "examples" / "gallery"
#: Longest an example may run [s] before the build fails.
TIMEOUT_S = 300


def _run(script: Path, out: Path) -> tuple[str, float]:
    env = {**os.environ, "BEARINGKIT_GALLERY_OUT": str(out), "BEARINGKIT_BACKGROUND_COMPILE": "0"}
    env["MPLBACKEND"] = "Agg"
    t0 = time.perf_counter()
    proc = subprocess.run(
        [sys.executable, str(script)], cwd=ROOT, env=env, capture_output=True, text=True, timeout=TIMEOUT_S
    )
    if proc.returncode != 0 or not proc.stdout.strip():
        raise PluginError(
            f"gallery example {script.name} failed (exit {proc.returncode}):\n{proc.stderr[-3000:]}"
        )
    return proc.stdout, time.perf_counter() - t0


def _page(script: Path, output: str, figures: list[str], seconds: float) -> str:
    source = script.read_text(encoding="utf-8")
    doc = ast.get_docstring(ast.parse(source)) or script.stem
    title, _, rest = doc.partition("\n")
    body = source.split('"""', 2)[2].lstrip("\n") if source.lstrip().startswith('"""') else source
    parts = [f"# {title.strip()}", rest.strip(), f"`python examples/gallery/{script.name}` ({seconds:.1f} s "
             "when this site was built):", f"```python\n{body.rstrip()}\n```", "Output:",
             f"```text\n{output.rstrip()}\n```"]  # fmt: skip
    parts += [f"![{name}]({script.stem}/{name})" for name in figures]
    return "\n\n".join(p for p in parts if p) + "\n"


def on_files(files, config):
    scripts = sorted(p for p in GALLERY.glob("[0-9]*.py"))
    index = [
        "# Examples (gallery)",
        "Each example is a script in `examples/gallery/`, run when this site was built; its page shows the "
        "code, what it printed and its figures. Run one yourself from the repository root: "
        "`python examples/gallery/01_designation_to_life.py` (figures in `out/gallery/`).",
    ]
    if os.environ.get("BEARINGKIT_DOCS_GALLERY", "1") == "0":
        index.append("*The examples were not run for this build (BEARINGKIT_DOCS_GALLERY=0).*")
        index += [f"- `{s.name}`" for s in scripts]
        files.append(File.generated(config, "gallery/index.md", content="\n\n".join(index) + "\n"))
        return files
    work = Path(tempfile.mkdtemp(prefix="bearingkit-gallery-"))
    with ThreadPoolExecutor(max_workers=2) as pool:
        runs = dict(zip(scripts, pool.map(lambda s: _run(s, work / s.stem), scripts), strict=True))
    lines = []
    for script, (output, seconds) in runs.items():
        figures = sorted(p.name for p in (work / script.stem).glob("*.png"))
        for name in figures:
            content = (work / script.stem / name).read_bytes()
            files.append(File.generated(config, f"gallery/{script.stem}/{name}", content=content))
        files.append(
            File.generated(
                config, f"gallery/{script.stem}.md", content=_page(script, output, figures, seconds)
            )
        )
        title = (ast.get_docstring(ast.parse(script.read_text(encoding="utf-8"))) or script.stem).split("\n")[
            0
        ]
        thumb = f"\n\n    ![{title}]({script.stem}/{figures[0]}){{ width=320 }}" if figures else ""
        lines.append(f"- [{title}]({script.stem}.md){thumb}")
    index.append("\n".join(lines))
    files.append(File.generated(config, "gallery/index.md", content="\n\n".join(index) + "\n"))
    return files
