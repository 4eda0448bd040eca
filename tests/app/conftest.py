"""Fixtures of the web app's browser tests: the server on a free loopback port, headless Chromium driven by
selenium (Debian's ``chromium`` + ``chromium-driver``, installed by ``scripts/ensure_chromium.sh``; nothing is
downloaded at run time), and the helpers every browser test uses (``page``).

Without the browser the tests fail on purpose, with the install instruction. Screenshots are kept under the
pytest temporary folder and in ``out/`` (git-ignored): ``out/app_<page>.png``.
"""

from __future__ import annotations

import json
import shutil
import socket
import threading
import time
from pathlib import Path
from types import SimpleNamespace

import pytest

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
#: Flags as tests/report/test_report_browser.py (no network, no first-run dialogs, no sandbox in CI).
FLAGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--window-size=1400,2400",
)
#: Seconds to wait for the page (cold start of the engine and of Chromium on a loaded 2-core machine).
WAIT = 120


def _need(path: str, what: str) -> str:
    found = path if Path(path).exists() else shutil.which(Path(path).name)
    if found is None:
        pytest.fail(
            f"{path} not found: the web app's browser test needs Debian's {what}; install it with "
            "`sudo scripts/ensure_chromium.sh` (apt-get install -y chromium chromium-driver)",
            pytrace=False,
        )
    return found


@pytest.fixture(scope="module")
def server():
    import uvicorn

    from bearingkit.app import create_app

    with socket.socket() as s:  # a free loopback port
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    srv = uvicorn.Server(
        uvicorn.Config(create_app(warm=True), host="127.0.0.1", port=port, log_level="warning")
    )
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + WAIT
    while not srv.started:
        assert thread.is_alive() and time.monotonic() < deadline, "the server did not start"
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}/"
    srv.should_exit = True
    thread.join(10)


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = _need(CHROMIUM, "chromium")
    for flag in FLAGS:
        options.add_argument(flag)
    options.add_argument(f"--user-data-dir={tmp_path_factory.mktemp('profile')}")
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(_need(CHROMEDRIVER, "chromium-driver")), options=options)
    driver.set_page_load_timeout(WAIT)
    yield driver
    driver.quit()


def cli_json(*args) -> dict:
    """``bearingkit … --json``: the command line's own numbers (its typer app, in this process)."""
    from typer.testing import CliRunner

    from bearingkit.cli import app

    result = CliRunner().invoke(app, [*args, "--json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def wait_for_analysis(driver, after: int) -> None:
    """Until the bearing page has shown the answer to a request newer than ``after``."""
    from selenium.webdriver.support.ui import WebDriverWait

    def done(d):
        # settled: an answer newer than ``after`` is shown, no analysis is waiting for its debounce
        # and none is in flight (on a loaded machine a change event from clear() can fire its own
        # analysis before the typed value's; the page must be on the last request, not that one)
        status = d.find_element("id", "status")
        shown_seq = int(status.get_attribute("data-seq"))
        return (
            shown_seq > after
            and status.get_attribute("data-pending") is None
            and status.get_attribute("data-requested") == str(shown_seq)
            and d.find_element("tag name", "body").get_attribute("data-state") in ("ready", "error")
        )

    WebDriverWait(driver, WAIT).until(done)


def seq(driver) -> int:
    return int(driver.find_element("id", "status").get_attribute("data-seq"))


def shown(driver, element_id: str) -> tuple[float, str]:
    """(the exact value behind a displayed number, the text shown)."""
    e = driver.find_element("id", element_id)
    return float(e.get_attribute("data-value")), e.text


def keep(driver, tmp_path: Path, name: str):
    """Save a screenshot under ``tmp_path`` and ``out/`` (an artefact of the run); the image as an array."""
    import matplotlib.image as mpimg

    path = tmp_path / name
    assert driver.save_screenshot(str(path))
    out = ROOT / "out"
    out.mkdir(exist_ok=True)
    shutil.copy(path, out / name)
    return mpimg.imread(path)


def console_errors(driver) -> list[str]:
    """The page's script errors since the last call (a script error must fail a test); the browser's
    note of a refused request (HTTP 400, the errors the tests provoke) is not one."""
    return [
        e["message"]
        for e in driver.get_log("browser")
        if e["level"] == "SEVERE" and e.get("source") != "network"
    ]


@pytest.fixture(scope="module")
def page():
    """The helpers above, for the browser tests (a test module cannot import another's)."""
    return SimpleNamespace(
        ROOT=ROOT,
        WAIT=WAIT,
        cli_json=cli_json,
        wait_for_analysis=wait_for_analysis,
        seq=seq,
        shown=shown,
        keep=keep,
        console_errors=console_errors,
    )
