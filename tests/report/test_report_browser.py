"""The HTML report renders in headless Chromium (Debian's ``chromium``) with its plots.

Chromium is installed by ``scripts/ensure_chromium.sh`` (the Makefile/CI runs it); without it this test
fails on purpose, with that instruction.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import matplotlib.image as mpimg
import numpy as np
import pytest

from bearingkit.cli.flagship import FlagshipContext

CHROMIUM = "/usr/bin/chromium"
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
#: Seconds one headless Chromium run may take (cold start on a loaded CI machine).
TIMEOUT = 120
FLAGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
)


def chromium() -> str:
    path = CHROMIUM if Path(CHROMIUM).exists() else shutil.which("chromium")
    if path is None:
        pytest.fail(
            f"{CHROMIUM} not found: the report's browser test needs Debian's chromium; "
            "install it with `sudo scripts/ensure_chromium.sh` (apt-get install -y chromium)",
            pytrace=False,
        )
    return path


def run_chromium(args, tmp: Path) -> subprocess.CompletedProcess:
    cmd = [chromium(), *FLAGS, f"--user-data-dir={tmp / 'profile'}", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=TIMEOUT, check=False, cwd=tmp)


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("browser")
    path = FlagshipContext().analysis.report(tmp / "report.html")
    return tmp, path


def test_screenshot_shows_the_report(report):
    tmp, path = report
    png = tmp / "shot.png"
    proc = run_chromium([f"--screenshot={png}", "--window-size=1200,3000", path.as_uri()], tmp)
    assert png.is_file(), f"no screenshot (exit {proc.returncode}): {proc.stderr[-2000:]}"
    img = mpimg.imread(png)
    assert img.shape[:2] == (3000, 1200)
    rgb = (img[..., :3] * 255).round().astype(np.uint32).reshape(-1, 3)
    colours = len(np.unique((rgb[:, 0] << 16) | (rgb[:, 1] << 8) | rgb[:, 2]))
    # text, tables and the viridis-coloured polar plot (the first figure sits within 3000 px)
    assert colours > 500, f"screenshot looks blank: {colours} distinct colours"
    white = np.mean(np.all(rgb > 245, axis=1))
    assert white < 0.97, f"screenshot is {white:.1%} white"
    # saturated plot pixels (viridis yellow-green bars): the polar figure rendered
    r, g, b = rgb.T
    assert np.count_nonzero((g > 150) & (b < 100) & (r > 100)) > 1000


def test_dom_holds_the_inline_images(report):
    tmp, path = report
    proc = run_chromium(["--dump-dom", path.as_uri()], tmp)
    dom = proc.stdout
    assert "<h1>" in dom, f"empty DOM (exit {proc.returncode}): {proc.stderr[-2000:]}"
    srcs = re.findall(r'<img[^>]*\ssrc="([^"]*)"', dom)
    html = path.read_text(encoding="utf-8")
    assert len(srcs) == html.count("<img ") == 5  # polar, slice map, friction, rating, stress against depth
    # polar, slice map, friction and rating as SVG, the stresses as PNG
    assert sum(s.startswith("data:image/svg+xml;base64,") for s in srcs) == 4
    assert all(s.startswith(("data:image/png;base64,", "data:image/svg+xml;base64,")) for s in srcs)
    assert all(len(s) > 5_000 for s in srcs)
    for section in ('id="inputs"', 'id="case-0"', 'id="warnings"', 'id="references"'):
        assert section in dom
