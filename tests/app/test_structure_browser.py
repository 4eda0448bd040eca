"""A bearing in its structure on the web app's bearing page, in a real headless Chromium (the fixtures of
tests/app/conftest.py): the card "In its structure" shows the numbers of ``bearingkit analyze --json`` for
the same file — per row the loaded count, Q_max and p_max on rigid and on flexible rings and the change,
s0 and the life each way, each ring's largest deflections, moments and fibre stress — draws the loads and
the rings against azimuth, carries the structure's warnings, and goes away with a bearing without one.
Screenshot: ``out/app_structure.png`` (git-ignored).
"""

from __future__ import annotations

from pathlib import Path

import pytest

# the structure card in Chromium: ~16 s; the same numbers through the API: test_structure_api.py
pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
#: Page against CLI: round-off of one case solved alone against a batch of the file's cases (seen ≤ 1e-13).
REL = 1e-10


def _wait(browser, page, condition):
    """WebDriverWait that polls through a re-render (an element replaced under it is not an error)."""
    from selenium.common.exceptions import StaleElementReferenceException
    from selenium.webdriver.support.ui import WebDriverWait

    return WebDriverWait(
        browser, page.WAIT, poll_frequency=0.1, ignored_exceptions=(StaleElementReferenceException,)
    ).until(condition)


def _value(browser, element_id: str) -> float:
    return float(browser.find_element("id", element_id).get_attribute("data-value"))


def _open_example(browser, page, name: str) -> None:
    from selenium.webdriver.support.ui import Select

    browser.find_element("css selector", '#tabs a[data-page="bearing"]').click()
    before = page.seq(browser)
    Select(browser.find_element("id", "example")).select_by_value(name)
    page.wait_for_analysis(browser, before)
    assert browser.find_element("tag name", "body").get_attribute("data-state") == "ready"


def _assert_structure_equals_cli(browser, case: dict) -> None:
    """Every number of the card against the CLI's ``flexible`` dict of the same case: the same pipeline,
    equal to round-off (the app solves the one case it shows, the CLI the file's cases in one batch: the
    last bits of the rings' harmonic sums differ); the page keeps the SI value behind each rounded number
    in data-value."""
    f = case["flexible"]
    assert browser.find_element("id", "structure-card").is_displayed()
    for name, r in f["rigid_vs_flexible"].items():
        assert _value(browser, f"st-qmax-rigid-{name}") == pytest.approx(r["max_load_rigid_N"], rel=REL)
        assert _value(browser, f"st-qmax-flex-{name}") == pytest.approx(r["max_load_flexible_N"], rel=REL)
        p_flex = r["max_pressure_flexible_Pa"]
        assert _value(browser, f"st-pmax-flex-{name}") == pytest.approx(p_flex, rel=REL)
        assert _value(browser, f"st-change-{name}") == pytest.approx(r["max_load_change"], rel=REL)
        loaded = browser.find_element("id", f"st-loaded-{name}").text
        assert loaded == f"{r['loaded_count_rigid']} → {r['loaded_count_flexible']}"
        # the rigid column is the rigid solve the page's own summary shows
        assert r["max_load_rigid_N"] == pytest.approx(
            next(row["max_load_N"] for row in case["rows"] if row["name"] == name), rel=REL
        )
    ch = f["change"]
    for key, element in (
        ("max_load_rigid_N", "st-q-rigid"),
        ("max_load_flexible_N", "st-q-flex"),
        ("static_safety_rigid", "st-s0-rigid"),
        ("static_safety_flexible", "st-s0-flex"),
        ("life_rev_rigid", "st-life-rigid"),
        ("life_rev_flexible", "st-life-flex"),
    ):
        assert ch[key] is not None
        assert _value(browser, element) == pytest.approx(ch[key], rel=REL)
    rings = [r for r in f["structure"]["rings"] if "radial_deflection_m" in r]
    assert rings
    for ring in rings:
        side = ring["side"]
        for key, element in (
            ("radial_deflection_m", "w"),
            ("tangential_deflection_m", "v"),
            ("axial_deflection_m", "u"),
            ("twist_rad", "twist"),
            ("bending_moment_Nm", "m-in"),
            ("out_of_plane_moment_Nm", "m-out"),
        ):
            expected = max(abs(v) for v in ring[key])
            assert _value(browser, f"st-{element}-{side}") == pytest.approx(expected, rel=REL, abs=1e-300)
        assert _value(browser, f"st-sigma-{side}") == pytest.approx(ring["max_fibre_stress_Pa"], rel=REL)
    # one load chart per row, three per ring (deflection, twist, moments)
    charts = browser.find_elements("css selector", "#structure-plots svg")
    assert len(charts) == len(f["rows"]) + 3 * len(rings)
    status = browser.find_element("id", "structure-status").text
    assert f"{f['coupling']['iterations']} iterations" in status
    assert ("NOT converged" in status) == (not f["converged"])


def test_structure_card_shows_the_cli_numbers(server, browser, page, tmp_path):
    from selenium.webdriver.support.ui import Select

    browser.get(server)
    _wait(browser, page, lambda d: len(Select(d.find_element("id", "example")).options) > 1)

    # a four-point slewing ring on bolted flanges: both rings flexible, s0 and L10 each way
    _open_example(browser, page, "slewing_four_point_flange.toml")
    flange = page.cli_json("analyze", str(EXAMPLES / "slewing_four_point_flange.toml"))["cases"][0]
    _assert_structure_equals_cli(browser, flange)
    assert {"outer", "inner"} <= {r["side"] for r in flange["flexible"]["structure"]["rings"]}
    page.keep(browser, tmp_path, "app_structure.png")

    # the 6209 in a thin housing: the outer ring only; the loaded zone widens
    _open_example(browser, page, "dgbb_6209_thin_housing.toml")
    housing = page.cli_json("analyze", str(EXAMPLES / "dgbb_6209_thin_housing.toml"))["cases"][0]
    _assert_structure_equals_cli(browser, housing)

    # a ring that nothing holds: the structure's warning is on the page as in the CLI's JSON
    text = (EXAMPLES / "dgbb_6209_thin_housing.toml").read_text()
    free = "\n".join(
        line
        for line in text.splitlines()
        if not line.startswith(("seat_wall_thickness", "axial_support", "tangential_support"))
    )
    path = tmp_path / "free_ring.toml"
    path.write_text(free + "\n", encoding="utf-8")
    cli = page.cli_json("analyze", str(path))["cases"][0]
    ring_warnings = [w for w in cli["warnings"] if "nothing given holds" in w]
    assert ring_warnings  # the case this checks: a structure warning exists
    before = page.seq(browser)
    browser.find_element("id", "upload").send_keys(str(path))
    page.wait_for_analysis(browser, before)
    _wait(browser, page, lambda d: d.find_element("id", "structure-card").is_displayed())
    shown = [li.text for li in browser.find_elements("css selector", "#warnings li")]
    for w in ring_warnings:
        assert " ".join(w.split()) in shown
    _assert_structure_equals_cli(browser, cli)

    # a bearing without a [structure]: no card, nothing of the last one left
    _open_example(browser, page, "dgbb_6209.toml")
    assert not browser.find_element("id", "structure-card").is_displayed()
    assert browser.find_elements("css selector", "#structure-plots *") == []
    assert page.console_errors(browser) == []


def test_the_seed_002_flexible_ring_shows_as_the_cli_prints_it(server, browser, page):
    """The ball–column bearing's own flexible outer ring ([geometry.ring], no [structure]): the card shows
    the case's rigid rows beside the flexible solve of ``analyze --json`` and the ring's bending."""
    from selenium.webdriver.support.ui import Select

    browser.get(server)
    _wait(browser, page, lambda d: len(Select(d.find_element("id", "example")).options) > 1)
    _open_example(browser, page, "ball_column_condition1.toml")
    case = page.cli_json("analyze", str(EXAMPLES / "ball_column_condition1.toml"))["cases"][0]
    f = case["flexible"]
    assert "rigid_vs_flexible" not in f  # not a [structure]: the seed's own ring
    assert browser.find_element("id", "structure-card").is_displayed()
    rigid = {r["name"]: r for r in case["rows"]}
    for row in f["rows"]:
        name = row["name"]
        assert _value(browser, f"st-qmax-flex-{name}") == pytest.approx(row["max_load_N"], rel=REL)
        assert _value(browser, f"st-qmax-rigid-{name}") == pytest.approx(rigid[name]["max_load_N"], rel=REL)
        assert _value(browser, f"st-pmax-flex-{name}") == pytest.approx(row["max_pressure_Pa"], rel=REL)
        loaded = browser.find_element("id", f"st-loaded-{name}").text
        assert loaded == f"{rigid[name]['loaded_count']} → {row['loaded_count']}"
    ring = f["ring"]
    w = max(abs(v) for v in ring["bending_deflection_m"])
    assert _value(browser, "st-w-outer") == pytest.approx(w, rel=REL)
    assert _value(browser, "st-sigma-outer") == pytest.approx(ring["max_fibre_stress_Pa"], rel=REL)
    assert len(browser.find_elements("css selector", "#structure-plots svg")) == len(f["rows"]) + 2
    status = browser.find_element("id", "structure-status").text
    assert f"{f['coupling']['iterations']} iterations" in status and "[geometry.ring]" in status
    assert page.console_errors(browser) == []
