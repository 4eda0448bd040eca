"""End to end in a real headless Chromium (Debian's ``chromium`` + ``chromium-driver``, driven by selenium):
the page shows the CLI's numbers for the same input, and a broken upload's one-line error.

The browser and its driver are installed by ``scripts/ensure_chromium.sh`` (the Makefile runs it);
nothing is downloaded at run time (selenium is pointed at /usr/bin/chromedriver). Without them this
test fails on purpose, with that instruction. The screenshots are kept as artefacts under the pytest
temporary folder and in ``out/`` (``out/app_analysis.png``, ``out/app_broken_upload.png``).
"""

from __future__ import annotations

import json
import shutil
import socket
import threading
import time
from pathlib import Path

import matplotlib.image as mpimg
import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.io import loader

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "dgbb_6209.toml"
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
#: The radial load the test types (the file's cases are 8.9 kN and 4 kN).
RADIAL = "6 kN"


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
    """Until the page has shown the answer to a request newer than ``after``."""
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


def keep(driver, tmp_path: Path, name: str) -> np.ndarray:
    path = tmp_path / name
    assert driver.save_screenshot(str(path))
    out = ROOT / "out"
    out.mkdir(exist_ok=True)
    shutil.copy(path, out / name)
    return mpimg.imread(path)


def test_page_shows_the_cli_numbers_and_the_loaders_error(server, browser, tmp_path):
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import Select, WebDriverWait

    browser.get(server)
    WebDriverWait(browser, WAIT).until(lambda d: len(Select(d.find_element("id", "example")).options) > 1)
    before = seq(browser)
    Select(browser.find_element("id", "example")).select_by_value("dgbb_6209.toml")
    wait_for_analysis(browser, before)
    assert browser.find_element("tag name", "body").get_attribute("data-state") == "ready"
    assert browser.find_element("id", "F_x").get_attribute("value") == "8.9 kN"  # the file's first case

    field = browser.find_element("id", "F_x")
    field.clear()
    before = seq(browser)
    field.send_keys(RADIAL, Keys.ENTER)
    wait_for_analysis(browser, before)
    assert browser.find_element("tag name", "body").get_attribute("data-state") == "ready"

    statics = cli_json("analyze", str(EXAMPLE), "--load", f"Fr={RADIAL.replace(' ', '')}")
    rating = cli_json("rating", str(EXAMPLE), "--load", f"Fr={RADIAL.replace(' ', '')}")
    q_cli = statics["cases"][0]["rows"][0]["max_load_N"]
    l10_cli = rating["cases"][0]["system"]["L10r_rev"]

    q_page, q_text = shown(browser, "max-load")
    l10_page, l10_text = shown(browser, "l10")
    # the same input through the same pipeline: equal values, and the text is that value rounded to
    # the 4 significant digits shown (relative rounding error ≤ 5e-4)
    assert q_page == pytest.approx(q_cli, rel=1e-12)
    assert l10_page == pytest.approx(l10_cli, rel=1e-12)
    assert float(q_text) == pytest.approx(q_cli / 1e3, rel=5e-4)  # kN
    assert float(l10_text) == pytest.approx(l10_cli / 1e6, rel=5e-4)  # 10⁶ rev
    # the polar plot drew one wedge per loaded ball
    loaded = sum(q > 0 for q in statics["cases"][0]["rows"][0]["loads_N"])
    assert len(browser.find_elements("css selector", "#polar path")) == loaded

    # a one-factor sweep of the radial load: one batched analysis, one point per value on the plot
    Select(browser.find_element("id", "sweep-factor")).select_by_value("F_x")
    browser.find_element("id", "sweep-run").click()
    WebDriverWait(browser, WAIT).until(lambda d: "analysis" in d.find_element("id", "sweep-status").text)
    assert browser.find_element("id", "sweep-status").text.startswith("12 values in 1 analysis")
    assert len(browser.find_elements("css selector", "#sweep-plot circle")) == 12

    img = keep(browser, tmp_path, "app_analysis.png")
    rgb = (img[..., :3] * 255).round().astype(np.uint32).reshape(-1, 3)
    colours = len(np.unique((rgb[:, 0] << 16) | (rgb[:, 1] << 8) | rgb[:, 2]))
    assert colours > 300, f"screenshot looks blank: {colours} distinct colours"
    r, g, b = rgb.T
    assert np.count_nonzero((r > 200) & (g > 200) & (b < 80)) > 200  # the viridis-yellow peak wedge

    broken = tmp_path / "broken.toml"
    text = '[bearing\ntype = "deep_groove_ball"\n'
    broken.write_text(text)
    with pytest.raises(InputError) as expected:
        loader.loads(text, "broken.toml")
    browser.find_element("id", "upload").send_keys(str(broken))
    WebDriverWait(browser, WAIT).until(lambda d: d.find_element("id", "source-error").text.strip())
    message = browser.find_element("id", "source-error").text
    assert message == " ".join(str(expected.value).split())
    assert message.startswith("broken.toml: not valid TOML") and "\n" not in message
    assert browser.find_element("tag name", "body").get_attribute("data-state") == "error"
    keep(browser, tmp_path, "app_broken_upload.png")
