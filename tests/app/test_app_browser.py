"""End to end in a real headless Chromium (Debian's ``chromium`` + ``chromium-driver``, driven by selenium):
the page shows the CLI's numbers for the same input, and a broken upload's one-line error.

The browser and its driver are installed by ``scripts/ensure_chromium.sh`` (the Makefile runs it);
nothing is downloaded at run time (selenium is pointed at /usr/bin/chromedriver). Without them this
test fails on purpose, with that instruction. The screenshots are kept as artefacts under the pytest
temporary folder and in ``out/`` (``out/app_analysis.png``, ``out/app_broken_upload.png``). The server,
browser and helpers are the fixtures of ``tests/app/conftest.py``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.io import loader

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "dgbb_6209.toml"
#: The radial load the test types (the file's cases are 8.9 kN and 4 kN).
RADIAL = "6 kN"


def test_page_shows_the_cli_numbers_and_the_loaders_error(server, browser, page, tmp_path):
    from selenium.webdriver.common.keys import Keys
    from selenium.webdriver.support.ui import Select, WebDriverWait

    browser.get(server)
    WebDriverWait(browser, page.WAIT).until(
        lambda d: len(Select(d.find_element("id", "example")).options) > 1
    )
    before = page.seq(browser)
    Select(browser.find_element("id", "example")).select_by_value("dgbb_6209.toml")
    page.wait_for_analysis(browser, before)
    assert browser.find_element("tag name", "body").get_attribute("data-state") == "ready"
    assert browser.find_element("id", "F_x").get_attribute("value") == "8.9 kN"  # the file's first case

    field = browser.find_element("id", "F_x")
    field.clear()
    before = page.seq(browser)
    field.send_keys(RADIAL, Keys.ENTER)
    page.wait_for_analysis(browser, before)
    assert browser.find_element("tag name", "body").get_attribute("data-state") == "ready"

    statics = page.cli_json("analyze", str(EXAMPLE), "--load", f"Fr={RADIAL.replace(' ', '')}")
    rating = page.cli_json("rating", str(EXAMPLE), "--load", f"Fr={RADIAL.replace(' ', '')}")
    q_cli = statics["cases"][0]["rows"][0]["max_load_N"]
    l10_cli = rating["cases"][0]["system"]["L10r_rev"]

    q_page, q_text = page.shown(browser, "max-load")
    l10_page, l10_text = page.shown(browser, "l10")
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
    WebDriverWait(browser, page.WAIT).until(lambda d: "analysis" in d.find_element("id", "sweep-status").text)
    assert browser.find_element("id", "sweep-status").text.startswith("12 values in 1 analysis")
    assert len(browser.find_elements("css selector", "#sweep-plot circle")) == 12

    img = page.keep(browser, tmp_path, "app_analysis.png")
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
    WebDriverWait(browser, page.WAIT).until(lambda d: d.find_element("id", "source-error").text.strip())
    message = browser.find_element("id", "source-error").text
    assert message == " ".join(str(expected.value).split())
    assert message.startswith("broken.toml: not valid TOML") and "\n" not in message
    assert browser.find_element("tag name", "body").get_attribute("data-state") == "error"
    page.keep(browser, tmp_path, "app_broken_upload.png")
