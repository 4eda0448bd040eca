"""Duty cycles: every bin rated in one batch, the combined life is the hand Miner sum of the bin lives."""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.cli import app
from bearingkit.errors import InputError
from bearingkit.io.loader import from_dict

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "dgbb_6209_duty_cycle.toml"
runner = CliRunner()


@pytest.fixture(scope="module")
def cycle():
    return bk.analyze(EXAMPLE, contamination=0.5).rating_dict()["duty_cycle"]


def test_combined_life_is_the_hand_miner_sum_of_the_bin_lives(cycle):
    bins = cycle["bins"]
    t = np.array([b["time_fraction"] for b in bins])
    n = np.array([b["speed_rad_s"] for b in bins])
    u = t * n / np.sum(t * n)  # revolution fractions, by hand
    np.testing.assert_allclose([b["revolution_fraction"] for b in bins], u, rtol=1e-14)
    for key in ("L10r_rev", "Lnmr_rev"):
        lives = np.array([b[key] for b in bins])
        assert np.all(np.isfinite(lives))
        hand = 1.0 / np.sum(u / lives)
        assert cycle[key] == pytest.approx(hand, rel=1e-13)
        # hours: the revolutions over the mean revolution rate Σ t_i n_i / 2π [rev/s]
        hours = hand / (np.sum(t * n) / (2 * math.pi)) / 3600.0
        assert cycle[key.replace("_rev", "_h")] == pytest.approx(hours, rel=1e-13)
    shares = np.array([b["damage_share"] for b in bins])
    assert shares.sum() == pytest.approx(1.0, rel=1e-14)


def test_iso281_damage_shares_and_combined_lives_are_the_hand_miner_sums(cycle):
    """ISO 281 first: per-bin L10 and L_nm, the ISO 281 damage shares n_i/L_i normalised, the Miner sum."""
    bins = cycle["bins"]
    assert cycle["headline"]["method"] == "ISO 281"
    t = np.array([b["time_fraction"] for b in bins])
    n = np.array([b["speed_rad_s"] for b in bins])
    u = t * n / np.sum(t * n)
    rate = np.sum(t * n) / (2 * math.pi)  # mean revolutions per second
    for key in ("L10_iso281", "Lnm_iso281"):
        lives = np.array([b[f"{key}_rev"] for b in bins])
        assert np.all(np.isfinite(lives)) and np.all(lives > 0)
        hand = 1.0 / np.sum(u / lives)
        assert cycle[f"{key}_rev"] == pytest.approx(hand, rel=1e-12)
        hours = cycle[key.replace("L10_", "L10h_") + "_h"]
        assert hours == pytest.approx(hand / rate / 3600.0, rel=1e-12)
    lives = np.array([b["L10_iso281_rev"] for b in bins])
    hand_shares = (u / lives) / np.sum(u / lives)
    np.testing.assert_allclose([b["damage_share_iso281"] for b in bins], hand_shares, rtol=1e-12, atol=0)
    # the ISO 281 shares are their own, not the TS's
    assert [b["damage_share_iso281"] for b in bins] != [b["damage_share"] for b in bins]
    assert cycle["life_difference"] and "ISO/TS 16281" in cycle["life_difference"]


def test_a_bearing_iso281_does_not_rate_leads_with_the_ts_life_and_says_why():
    """A slewing ring (no ISO 281 X, Y under a tilting moment): no ISO 281 duty-cycle life, the TS's leads
    in the JSON and the console, and a note names the reason."""
    root = EXAMPLE.parent
    data = tomllib.loads((root / "slewing_four_point.toml").read_text())
    cases = data.pop("load_cases")
    data["duty_cycle"] = [{**c, "time_fraction": f} for c, f in zip(cases, (0.5, 0.2, 0.3), strict=True)]
    d = bk.analyze(from_dict(data, "slew.toml")).rating_dict()["duty_cycle"]
    assert d["headline"]["method"] == "ISO/TS 16281" and d["L10_iso281_rev"] is None
    assert d["L10r_rev"] is not None and d["life_difference"] is None
    assert all(b["L10_iso281_rev"] is None and b["damage_share_iso281"] is None for b in d["bins"])
    assert any("no combined ISO 281 life (ISO 281 gives no X, Y for slewing rings" in n for n in d["notes"])
    from rich.console import Console

    from bearingkit.cli.tables import duty_cycle_table

    console = Console(width=400, record=True)
    console.print(duty_cycle_table(d))
    text = console.export_text()
    assert text.index("ISO/TS 16281: L10r =") < text.index("ISO 281: L10 =")


def test_each_bin_is_rated_as_its_own_load_case(cycle):
    """A bin's life is that of the same load, speed and temperature analysed as a plain load case."""
    for b in cycle["bins"]:
        ld = b["load"]
        a = bk.analyze(
            EXAMPLE,
            load={"F_x": f"{ld['F_x_N']!r} N", "F_z": f"{ld['F_z_N']!r} N"},
            speed=b["speed_rad_s"],
            temperature=b["temperature_C"],
            contamination=0.5,
        )
        single = a.rating_dict()["cases"][0]["system"]
        assert b["L10r_rev"] == pytest.approx(single["L10r_rev"], rel=1e-9)
        assert b["Lnmr_rev"] == pytest.approx(single["Lnmr_rev"], rel=1e-9)
        assert b["static_safety"] == pytest.approx(single["static_safety"], rel=1e-9)
        assert b["L10_iso281_rev"] == pytest.approx(single["L10_iso281_rev"], rel=1e-9)
        assert b["Lnm_iso281_rev"] == pytest.approx(single["Lnm_iso281_rev"], rel=1e-9)


def _data() -> dict:
    return tomllib.loads(EXAMPLE.read_text())


def test_bins_at_rest_do_no_damage_and_do_not_block_the_modified_life():
    data = _data()
    data["duty_cycle"][3] = {**data["duty_cycle"][3], "speed": "0 rpm", "name": "parked"}
    a = bk.analyze(from_dict(data, "rest.toml"), contamination=0.5)
    d = a.rating_dict()["duty_cycle"]
    parked = d["bins"][3]
    assert parked["revolution_fraction"] == 0.0 and parked["damage_share"] == 0.0
    assert parked["L10r_rev"] is None and parked["static_safety"] > 1.0
    assert d["Lnmr_rev"] is not None
    assert any("'parked' is at rest" in n for n in d["notes"])


def test_unloaded_bin_counts_as_no_damage():
    data = _data()
    data["duty_cycle"][3] = {**data["duty_cycle"][3], "F_x": "0 N"}
    d = bk.analyze(from_dict(data, "x.toml")).rating_dict()["duty_cycle"]
    assert d["bins"][3]["no_load"] is True and d["bins"][3]["damage_share"] == 0.0
    u = np.array([b["revolution_fraction"] for b in d["bins"][:3]])
    lives = np.array([b["L10r_rev"] for b in d["bins"][:3]])
    assert d["L10r_rev"] == pytest.approx(1.0 / np.sum(u / lives), rel=1e-13)


def test_revolution_fractions_without_speeds_give_revolutions_only():
    data = _data()
    data["duty_cycle"] = [
        {"name": "a", "F_x": "3 kN", "revolution_fraction": 0.7},
        {"name": "b", "F_x": "6 kN", "revolution_fraction": 0.3},
    ]
    d = bk.analyze(from_dict(data, "x.toml")).rating_dict()["duty_cycle"]
    lives = np.array([b["L10r_rev"] for b in d["bins"]])
    assert d["L10r_rev"] == pytest.approx(1.0 / (0.7 / lives[0] + 0.3 / lives[1]), rel=1e-13)
    assert d["L10r_h"] is None and any("no life in hours" in n for n in d["notes"])


def test_a_file_with_only_a_duty_cycle_is_rated():
    data = _data()
    del data["load_cases"]
    out = bk.analyze(from_dict(data, "x.toml")).rating_dict()
    assert out["cases"] == [] and out["duty_cycle"]["L10r_rev"] > 0


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (
            {0: {"time_fraction": 0.5}},
            r"^x.toml: duty_cycle.time_fraction \(sum of the bins 0.95\) must sum to 1",
        ),
        (
            {1: {"time_fraction": None, "revolution_fraction": 0.25}},
            r"^x.toml: duty_cycle: mixes time_fraction and revolution_fraction",
        ),
        ({2: {"time_fraction": 1.5}}, r"duty_cycle\[2\]\.time_fraction \(1.5\) must lie in \[0, 1\]"),
        ({0: {"speed": None}}, r"duty_cycle\[0\] \(cruise\)\.speed: missing; time fractions need"),
        ({0: {"F_x": "3 kg"}}, r"duty_cycle\[0\]\.F_x \('3 kg'\)"),
        ({1: {"time_fraction": None}}, r"give exactly one of them"),
        ({1: {"name": "cruise"}}, r"^x.toml: duty_cycle.name \(\['cruise'\]\) must be unique$"),
    ],
)
def test_bad_duty_cycles_are_one_line_naming_the_field(change, message):
    data = _data()
    for i, fields in change.items():
        row = dict(data["duty_cycle"][i])
        for k, v in fields.items():
            if v is None:
                row.pop(k, None)
            else:
                row[k] = v
        data["duty_cycle"][i] = row
    with pytest.raises(InputError, match=message) as err:
        from_dict(data, "x.toml")
    assert "\n" not in str(err.value)


def test_cli_rating_shows_the_duty_cycle_and_json_has_it(tmp_path):
    out = runner.invoke(app, ["rating", str(EXAMPLE), "--contamination", "0.5"])
    assert out.exit_code == 0, out.stderr
    assert "duty cycle: 4 bins, time fractions, Palmgren–Miner" in out.stdout
    text = " ".join(out.stdout[out.stdout.index("duty cycle: 4 bins") :].split())
    assert "over the cycle: ISO 281: L10 =" in text
    # ISO 281 before ISO/TS 16281: in the caption and in the bins' columns
    assert text.index("ISO 281: L10 =") < text.index("ISO/TS 16281: L10r =")
    assert text.index("L10 ISO 281") < text.index("L10r TS") and "why they differ:" in text
    data = json.loads(runner.invoke(app, ["rating", str(EXAMPLE), "--json"]).stdout)
    assert [b["bin"] for b in data["duty_cycle"]["bins"]] == ["cruise", "climb", "peak", "idle"]


def test_report_has_a_duty_cycle_section(tmp_path):
    path = bk.analyze(EXAMPLE, contamination=0.5).report(tmp_path / "r.html")
    html = path.read_text()
    assert 'id="duty-cycle"' in html and "Palmgren–Miner" in html
    assert "palmgren1924" in html and "miner1945" in html
    section = html[html.index('id="duty-cycle"') :]
    assert section.index("L10 ISO 281 [10⁶ rev]") < section.index("L10r ISO/TS 16281 [10⁶ rev]")
    assert section.index("<td class=l>ISO 281</td>") < section.index("<td class=l>ISO/TS 16281</td>")
    assert "Why they differ:" in section


@pytest.mark.parametrize(
    ("value", "message"),
    [
        (3.0, r"^x.toml: duty_cycle \(3.0\) must be an array of tables \(\[\[duty_cycle\]\] …\)$"),
        ([{"F_x": "1 kN"}, 7], r"^x.toml: duty_cycle\[1\] \(7\) must be a table"),
        ([{}] * 1001, r"^x.toml: duty_cycle \(1001 entries\) must have at most 1000 entries$"),
    ],
)  # fmt: skip
def test_duty_cycle_shape_and_count_are_checked_before_the_bins(value, message):
    """The cap of the load cases holds for the bins (one batched run, same memory); counted first."""
    data = _data()
    data["duty_cycle"] = value
    with pytest.raises(InputError, match=message):
        from_dict(data, "x.toml")


def test_duty_cycle_bins_obey_the_contact_point_cap(monkeypatch):
    from bearingkit.io import loader

    monkeypatch.setattr(loader, "MAX_CASE_POINTS", 30)  # 4 bins × the 6209's 9 balls = 36 points
    data = _data()
    del data["load_cases"]
    with pytest.raises(InputError, match=r"^x.toml: duty_cycle \(4 cases × 9 contact points\) must stay"):
        from_dict(data, "x.toml")
