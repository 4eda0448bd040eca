"""The workbench in a real headless Chromium (the fixtures of tests/app/conftest.py): every page, driven as a
user would, shows the command line's numbers, its errors as one line next to their field, and nothing of
a bearing it no longer shows. Screenshots of each page: ``out/app_<page>.png`` (git-ignored).

- bearing page: switching between a designation, an example and an upload leaves no stale input, plot or
  download; fixed DOFs as solved; speed limits; the slewing ring's friction and its hardened layer;
- catalogue: filter, pick a designation (it opens on the bearing page), compare two bearings;
- shaft: the example's bearing reactions equal ``bearingkit shaft --json``; an edited file; an error;
- drivetrain: the example's efficiency equals ``bearingkit system --json``;
- studies: a 50-case study with its progress bar to the end, a value equal to ``bearingkit study``'s on
  the downloaded folder; an error under its factor;
- duty cycle: the file's bins, the Miner life of ``bearingkit rating --json``, a bad cell.
"""

from __future__ import annotations

import io
import subprocess
import sys
import urllib.request
import zipfile
from pathlib import Path

import numpy as np
import pytest

# every workbench page in Chromium: ~60 s; the same numbers through the API: test_workbench_api.py
pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


def _select(browser, element_id: str, value: str) -> None:
    from selenium.webdriver.support.ui import Select

    Select(browser.find_element("id", element_id)).select_by_value(value)


def _wait(browser, page, condition, seconds=None):
    """Poll until ``condition``; a table re-rendered under the poll (its cells replaced) is not an error."""
    from selenium.common.exceptions import StaleElementReferenceException
    from selenium.webdriver.support.ui import WebDriverWait

    ignored = (StaleElementReferenceException,)
    return WebDriverWait(browser, seconds or page.WAIT, poll_frequency=0.1, ignored_exceptions=ignored).until(
        condition
    )


def _tab(browser, name: str) -> None:
    browser.find_element("css selector", f'#tabs a[data-page="{name}"]').click()
    assert not browser.find_element("id", f"page-{name}").get_attribute("hidden")


def _value(browser, element_id: str) -> float:
    return float(browser.find_element("id", element_id).get_attribute("data-value"))


def _text(browser, element_id: str) -> str:
    return browser.find_element("id", element_id).text


@pytest.fixture(scope="module")
def opened(server, browser, page):
    """The page, loaded and ready (its script errors fail the tests that follow)."""
    browser.get(server)
    _wait(browser, page, lambda d: len(d.find_elements("css selector", "#example option")) > 1)
    assert page.console_errors(browser) == []
    return browser


def _open_example(browser, page, name: str) -> None:
    _tab(browser, "bearing")
    before = page.seq(browser)
    _select(browser, "example", name)
    page.wait_for_analysis(browser, before)


# ------------------------------------------------------------------------------------------ bearing page
def test_switching_sources_leaves_no_stale_input_plot_or_download(opened, page, tmp_path):
    from selenium.webdriver.common.keys import Keys

    browser = opened
    _tab(browser, "bearing")
    box = browser.find_element("id", "designation")
    box.clear()
    before = page.seq(browser)
    box.send_keys("6308-2RS C3", Keys.ENTER)
    page.wait_for_analysis(browser, before)
    assert "6308" in _text(browser, "bearing-title")
    # the tilt the pipeline fixes for a single row is what the page says is fixed (and the note says why)
    assert _text(browser, "fixed-dofs") == "theta_x, theta_y"
    assert any("tilt fixed" in li.text for li in browser.find_elements("css selector", "#notes li"))
    _select(browser, "sweep-factor", "F_x")
    browser.find_element("id", "sweep-run").click()
    _wait(browser, page, lambda d: "analysis" in _text(d, "sweep-status"))
    assert len(browser.find_elements("css selector", "#sweep-plot circle")) == 12

    _open_example(browser, page, "slewing_four_point.toml")
    assert browser.find_element("id", "designation").get_attribute("value") == ""
    assert (
        browser.find_elements("css selector", "#sweep-plot *") == [] and _text(browser, "sweep-status") == ""
    )
    assert "slewing" in _text(browser, "bearing-title")
    case = page.cli_json("analyze", str(EXAMPLES / "slewing_four_point.toml"))["cases"][0]
    assert browser.find_element("id", "F_z").get_attribute("value") == "200 kN"  # the file's first case
    assert _value(browser, "max-load") == pytest.approx(max(r["max_load_N"] for r in case["rows"]), rel=1e-12)
    assert _text(browser, "fixed-dofs") == "none"  # [solver] free lists all five
    # the slewing ring's friction is the makers' model (not "not computed"), its raceways case-hardened
    assert "model: slewing" in _text(browser, "friction")
    assert browser.find_element("id", "subsurface-card").is_displayed()
    rows = browser.find_elements("css selector", "#subsurface-table tr")
    assert len(rows) == 2 and "core" in rows[1].text
    page.keep(browser, tmp_path, "app_bearing_slewing.png")

    _open_example(browser, page, "dgbb_6209.toml")
    assert _text(browser, "fixed-dofs") == "theta_x, theta_y"
    before = page.seq(browser)
    browser.find_element("id", "speed").send_keys("3000 rpm", Keys.ENTER)
    page.wait_for_analysis(browser, before)
    limits = page.cli_json("rating", str(EXAMPLES / "dgbb_6209.toml"), "--speed", "3000rpm")["cases"][0][
        "limits"
    ]
    _wait(browser, page, lambda d: d.find_element("id", "limit-speed").get_attribute("data-value"))
    assert _value(browser, "limit-speed") == pytest.approx(
        limits["limiting_speed_rad_s"] * 30 / np.pi, rel=1e-12
    )
    page.keep(browser, tmp_path, "app_bearing.png")

    broken = tmp_path / "broken.toml"
    broken.write_text("[bearing\n", encoding="utf-8")
    browser.find_element("id", "upload").send_keys(str(broken))
    _wait(browser, page, lambda d: _text(d, "source-error"))
    assert _text(browser, "source-error").startswith("broken.toml: not valid TOML")
    # nothing of the 6209 stays: no example chosen, no title, no results, no downloads
    assert browser.find_element("id", "example").get_attribute("value") == ""
    assert _text(browser, "bearing-title") == "No bearing open"
    assert browser.find_elements("css selector", "#summary *") == []
    assert browser.find_elements("css selector", "#polar *") == []
    assert "disabled" in browser.find_element("id", "dl-json").get_attribute("class")
    assert page.console_errors(browser) == []


# ------------------------------------------------------------------------------------------ catalogue
def test_catalogue_pick_a_designation_and_compare_two(opened, page, tmp_path):
    from selenium.webdriver.common.keys import Keys

    from bearingkit.catalogue.search import search

    browser = opened
    _tab(browser, "catalogue")
    _wait(browser, page, lambda d: d.find_elements("css selector", "#cat-table tbody tr"))
    bad = browser.find_element("id", "cat-d")
    bad.send_keys("45 kN", Keys.ENTER)
    _wait(browser, page, lambda d: _text(d, "catalogue-error"))
    assert _text(browser, "catalogue-error").startswith("catalogue.d: ")
    assert "invalid" in bad.get_attribute("class")
    bad.clear()
    bad.send_keys("45 mm")
    _select(browser, "cat-kind", "deep_groove")
    _wait(browser, page, lambda d: not _text(d, "catalogue-error") and "match" in _text(d, "cat-count"))
    expected = [r.entry.designation for r in search(kind="deep_groove", d=0.045)]
    _wait(
        browser,
        page,
        lambda d: [e.text for e in d.find_elements("css selector", "#cat-table td.designation")] == expected,
    )

    for designation in ("6209", "6309"):
        browser.find_element(
            "css selector", f'#cat-table input.compare[data-designation="{designation}"]'
        ).click()
    assert [
        c.get_attribute("data-designation") for c in browser.find_elements("css selector", "#cmp-list .chip")
    ] == ["6209", "6309"]
    browser.find_element("id", "cmp-run").click()
    _wait(browser, page, lambda d: d.find_elements("id", "cmp-1-L10h_iso281_h") or _text(d, "compare-error"))
    assert _text(browser, "compare-error") == ""
    for i, designation in enumerate(("6209", "6309")):
        ref = page.cli_json(
            "rating", designation, "--load", "Fr=5kN", "--speed", "3000rpm", "--temperature", "70degC",
            "--lubricant", "ISO_VG68", "--contamination", "0.5",
        )["cases"][0]["system"]  # fmt: skip
        assert _value(browser, f"cmp-{i}-L10h_iso281_h") == pytest.approx(ref["L10h_iso281_h"], rel=1e-12)
        assert _value(browser, f"cmp-{i}-L10h_iso16281_h") == pytest.approx(ref["L10h_h"], rel=1e-12)
        assert _value(browser, f"cmp-{i}-static_safety") == pytest.approx(ref["static_safety"], rel=1e-12)
    assert "best" in browser.find_element("id", "cmp-1-L10h_iso281_h").get_attribute("class")
    page.keep(browser, tmp_path, "app_catalogue.png")

    # pick one: it opens on the bearing page, its designation in the box
    before = page.seq(browser)
    browser.find_element("css selector", '#cat-table button.open[data-designation="6209"]').click()
    page.wait_for_analysis(browser, before)
    assert not browser.find_element("id", "page-bearing").get_attribute("hidden")
    assert browser.find_element("id", "designation").get_attribute("value") == "6209"
    statics = page.cli_json("analyze", "6209", "--load", "Fr=1kN")["cases"][0]  # the page's start: 1 kN
    assert _value(browser, "max-load") == pytest.approx(statics["rows"][0]["max_load_N"], rel=1e-12)
    assert page.console_errors(browser) == []


# ------------------------------------------------------------------------------------------ systems
def test_shaft_example_reactions_equal_the_cli_and_edits_are_solved(opened, page, tmp_path):
    browser = opened
    _tab(browser, "shaft")
    _select(browser, "shaft-example", "shaft_countershaft.toml")
    _wait(
        browser, page, lambda d: d.find_element("id", "shaft-status").get_attribute("data-state") == "ready"
    )
    ref = page.cli_json("shaft", str(EXAMPLES / "shaft_countershaft.toml"))["cases"][0]["bearings"]
    for j, b in enumerate(ref):
        assert _value(browser, f"shaft-reaction-{j}-Fx") == b["reaction_on_shaft"]["F_x_N"]
        assert _value(browser, f"shaft-reaction-{j}-Fy") == b["reaction_on_shaft"]["F_y_N"]
    shown = browser.find_element("id", "shaft-reaction-0-Fx").text
    assert float(shown) == pytest.approx(ref[0]["reaction_on_shaft"]["F_x_N"], rel=5e-5)  # 5 digits shown
    # the system lives: ISO 281 first (the CLI's numbers), ISO/TS 16281 beside it, the line on why
    system = page.cli_json("shaft", str(EXAMPLES / "shaft_countershaft.toml"))["cases"][0]["rating"]["system"]
    assert _value(browser, "shaft-system-l10-iso") == system["L10h_iso281_h"]
    assert _value(browser, "shaft-system-l10") == system["L10h_h"]
    ids = [m.get_attribute("id") for m in browser.find_elements("css selector", "#shaft-summary [id]")]
    assert ids.index("shaft-system-l10-iso") < ids.index("shaft-system-l10")
    assert "why they differ" in _text(browser, "shaft-life-difference")
    assert len(browser.find_elements("css selector", "#shaft-layout-svg .bearing-mark")) == 2
    assert len(browser.find_elements("css selector", "#shaft-lines svg")) == 2
    page.keep(browser, tmp_path, "app_shaft.png")

    # edit the file on the page: the output pinion moved 20 mm; the CLI on the same text agrees
    text = browser.find_element("id", "shaft-text")
    edited = text.get_attribute("value").replace('position = "185 mm"', 'position = "205 mm"')
    browser.execute_script("arguments[0].value = arguments[1]", text, edited)
    old = _value(browser, "shaft-reaction-1-Fx")
    browser.find_element("id", "shaft-analyze").click()
    _wait(browser, page, lambda d: _value(d, "shaft-reaction-1-Fx") != old)
    folder = tmp_path / "edited"
    folder.mkdir()
    for name in ("dgbb_6209.toml", "crb_nu209.toml"):
        (folder / name).write_text((EXAMPLES / name).read_text(encoding="utf-8"), encoding="utf-8")
    (folder / "shaft.toml").write_text(edited, encoding="utf-8")
    ref = page.cli_json("shaft", str(folder / "shaft.toml"))["cases"][0]["bearings"]
    assert _value(browser, "shaft-reaction-1-Fx") == ref[1]["reaction_on_shaft"]["F_x_N"]

    # a file naming a bearing file outside the examples: one line, nothing solved
    browser.execute_script(
        "arguments[0].value = arguments[1]", text, edited.replace('"crb_nu209.toml"', '"/etc/hosts"')
    )
    browser.find_element("id", "shaft-analyze").click()
    _wait(browser, page, lambda d: _text(d, "shaft-error"))
    assert "shaft.bearings[1].file ('/etc/hosts') must name an example bearing file" in _text(
        browser, "shaft-error"
    )
    assert browser.find_elements("css selector", "#shaft-bearings tr") == []
    assert page.console_errors(browser) == []


def test_shaft_heat_balance_shows_the_cli_temperatures(opened, page, tmp_path):
    # the countershaft with [thermal]: every bearing's found temperature on the page = bearingkit shaft's
    browser = opened
    _tab(browser, "shaft")
    text = browser.find_element("id", "shaft-text")
    edited = (EXAMPLES / "shaft_countershaft.toml").read_text(encoding="utf-8")
    edited += '\n[thermal]\nheat_dissipation = "1.5 W/K"\n'
    browser.execute_script("arguments[0].value = arguments[1]", text, edited)
    browser.find_element("id", "shaft-analyze").click()
    _wait(browser, page, lambda d: d.find_element("id", "shaft-heat-card").get_attribute("hidden") is None)
    folder = tmp_path / "heat"
    folder.mkdir()
    for name in ("dgbb_6209.toml", "crb_nu209.toml"):
        (folder / name).write_text((EXAMPLES / name).read_text(encoding="utf-8"), encoding="utf-8")
    (folder / "shaft.toml").write_text(edited, encoding="utf-8")
    ref = page.cli_json("shaft", str(folder / "shaft.toml"))["cases"][0]["bearings"]
    for j, b in enumerate(ref):
        found = b["analysis"]["thermal"]["temperature_C"]
        assert _value(browser, f"shaft-heat-{j}-T") == found
        assert _value(browser, f"shaft-temperature-{j}") == found
    assert "FOUND by each bearing's heat balance" in _text(browser, "shaft-heat-note")
    assert page.console_errors(browser) == []


def test_drivetrain_example_efficiency_equals_the_cli(opened, page, tmp_path):
    browser = opened
    _tab(browser, "drivetrain")
    _select(browser, "drivetrain-example", "planetary_stage.toml")
    _wait(
        browser,
        page,
        lambda d: d.find_element("id", "drivetrain-status").get_attribute("data-state") == "ready",
    )
    ref = page.cli_json("system", str(EXAMPLES / "planetary_stage.toml"))["cases"][0]
    assert _value(browser, "dt-efficiency-text") == ref["power"]["efficiency"]
    assert _value(browser, "dt-bearing-0-Fr") == ref["bearings"][0]["summary"]["radial_load_N"]
    ids = [m.get_attribute("id") for m in browser.find_elements("css selector", "#drivetrain-summary [id]")]
    assert ids.index("dt-system-l10-iso") < ids.index("dt-system-l10")  # ISO 281 first
    assert _text(browser, "dt-life-difference") == f"why they differ: {ref['system']['life_difference']}"
    _wait(
        browser,
        page,
        lambda d: d.execute_script(
            "const i = document.getElementById('drivetrain-layout-img');"
            "return i && i.complete && i.naturalWidth > 0;"
        ),
    )
    page.keep(browser, tmp_path, "app_drivetrain.png")
    assert page.console_errors(browser) == []


# ------------------------------------------------------------------------------------------ studies
def test_a_50_case_study_runs_to_the_end_and_equals_the_cli_study(opened, page, server, tmp_path):
    browser = opened
    _open_example(browser, page, "dgbb_6209.toml")
    _tab(browser, "study")
    _wait(browser, page, lambda d: len(d.find_elements("css selector", "#study-factors .factor")) == 2)
    assert browser.find_element("id", "study-count").get_attribute("data-cases") == "50"
    # an error first: a level of the wrong dimension, shown under its factor, nothing started
    first = browser.find_element("css selector", "#study-factors .factor .f-start")
    first.clear()
    first.send_keys("0 kN")
    browser.find_element("id", "study-run").click()
    _wait(browser, page, lambda d: d.find_element("css selector", "#study-factors .factor-error").text)
    assert browser.find_element("css selector", "#study-factors .factor-error").text.startswith(
        "study.factors[0].from"
    )
    assert browser.find_element("id", "study-status").get_attribute("data-state") == "idle"
    first.clear()
    first.send_keys("0 um")

    browser.find_element("id", "study-run").click()
    seen = set()

    def finished(d):
        seen.add(round(float(d.find_element("id", "study-progress").get_attribute("value")), 3))
        return d.find_element("id", "study-status").get_attribute("data-state") in (
            "done",
            "failed",
            "stopped",
        )

    _wait(browser, page, finished, seconds=300)
    status = _text(browser, "study-status")
    assert status.startswith("done: 50 of 50 cases"), status
    assert float(browser.find_element("id", "study-progress").get_attribute("value")) == 1.0
    assert len(seen) >= 2  # the bar moved while the study ran, not only at its end
    _wait(browser, page, lambda d: d.find_elements("css selector", "#study-table tbody tr"))
    assert len(browser.find_elements("css selector", "#study-table tbody tr")) == 50
    _wait(
        browser,
        page,
        lambda d: d.execute_script(
            "const im = [...document.querySelectorAll('#study-figures img')];"
            "return im.length >= 3 && im.every((i) => i.complete && i.naturalWidth > 0);"
        ),
    )
    page.keep(browser, tmp_path, "app_study.png")

    link = browser.find_element("id", "study-download").get_attribute("href")
    with urllib.request.urlopen(link, timeout=60) as r:
        zipfile.ZipFile(io.BytesIO(r.read())).extractall(tmp_path)
    study = next(tmp_path.glob("study-*/study.toml"))
    # the command line in a fresh process, in the unpacked folder, as a user runs it (in this process the
    # study's work estimate could catch the solver switching cores after the page's many small solves)
    cli = subprocess.run(
        [sys.executable, "-m", "bearingkit", "study", "study.toml", "--out", str(tmp_path / "cli")],
        cwd=study.parent,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert cli.returncode == 0, cli.stderr
    import pandas as pd

    theirs = pd.read_csv(tmp_path / "cli" / "results.csv")
    k = 37  # any case: clearance level 4 (30 µm) × load level 8 (8 kN)
    assert theirs.loc[k, "geometry.clearance_radial"] == pytest.approx(30e-6, rel=1e-12)
    assert theirs.loc[k, "load_cases.page.F_x"] == pytest.approx(8000.0, rel=1e-12)
    columns = list(theirs.columns)
    assert columns.index("L10_iso281_rev") < columns.index("L10r_rev")  # ISO 281 first
    for col in ("L10_iso281_rev", "L10r_rev", "max_load_N", "s0"):
        assert _value(browser, f"study-cell-{k}-{col}") == theirs.loc[k, col], col
    assert page.console_errors(browser) == []


# ------------------------------------------------------------------------------------------ duty cycle
def test_duty_cycle_bins_rated_as_the_cli_rates_them(opened, page, tmp_path):
    browser = opened
    _open_example(browser, page, "dgbb_6209_duty_cycle.toml")
    assert browser.find_element("id", "duty-hint").is_displayed()
    _tab(browser, "duty")
    _wait(browser, page, lambda d: len(d.find_elements("css selector", "#duty-bins tr.bin")) == 4)
    browser.find_element("id", "duty-run").click()
    _wait(browser, page, lambda d: d.find_elements("id", "duty-l10"))
    ref = page.cli_json("rating", str(EXAMPLES / "dgbb_6209_duty_cycle.toml"))["duty_cycle"]
    assert _value(browser, "duty-l10") == ref["L10r_h"]
    assert _value(browser, "duty-l10-iso") == ref["L10h_iso281_h"]
    # ISO 281 is the first life of the summary, ISO/TS 16281 beside it
    ids = [m.get_attribute("id") for m in browser.find_elements("css selector", "#duty-summary [id]")]
    assert ids.index("duty-l10-iso") < ids.index("duty-l10")
    iso_shares = [
        float(td.get_attribute("data-value"))
        for td in browser.find_elements("css selector", "#duty-bins td.r-share-iso")
    ]
    assert iso_shares == [b["damage_share_iso281"] for b in ref["bins"]]
    shares = [
        float(td.get_attribute("data-value"))
        for td in browser.find_elements("css selector", "#duty-bins td.r-share")
    ]
    assert shares == [b["damage_share"] for b in ref["bins"]] and sum(shares) == pytest.approx(1.0, rel=1e-12)
    page.keep(browser, tmp_path, "app_duty.png")

    cell = browser.find_elements("css selector", '#duty-bins tr.bin input[data-key="F_x"]')[2]
    cell.clear()
    cell.send_keys("9 kg")
    browser.find_element("id", "duty-run").click()
    _wait(browser, page, lambda d: _text(d, "duty-error"))
    assert "duty_cycle[2].F_x ('9 kg') has dimension [mass]" in _text(browser, "duty-error")
    assert "invalid" in cell.get_attribute("class")
    assert page.console_errors(browser) == []
