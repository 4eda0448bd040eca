"""Bearing selection (issue 33): candidates that meet a life by ISO 281 and ISO/TS 16281 and a static
safety, lightest first; the command line and JSON."""

from __future__ import annotations

import json

import numpy as np
import pytest
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.errors import InputError
from bearingkit.pipeline.selection import select

runner = CliRunner()


def test_select_example_gives_three_candidates_with_both_lives():
    """`bearingkit select --load Fr=5kN --load Fa=1kN --speed 3000rpm --life 20000h --count 3 --json`."""
    args = ["select", "--load", "Fr=5kN", "--load", "Fa=1kN", "--speed", "3000rpm", "--life", "20000h"]
    result = runner.invoke(app, [*args, "--count", "3", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    cands = data["candidates"]
    assert len(cands) >= 3
    for c in cands:
        assert c["L10h_iso281_h"] >= 20000 and c["L10h_iso16281_h"] >= 20000 and c["static_safety"] >= 1
        # the ISO 281 life is the catalogue law of the C and P printed with it (ball 3, roller 10/3)
        p = 3.0 if c["family"].endswith("ball") else 10.0 / 3.0
        hours = (c["C_iso281_N"] / c["P_iso281_N"]) ** p * 1e6 / (3000 * 60)
        assert c["L10h_iso281_h"] == pytest.approx(hours, rel=1e-9)
        # C0 shown beside C, and ISO 76's s0 = C0/P0 equals the catalogue method's screen
        assert c["C0_iso76_N"] > 0 and c["C0_source"] in ("catalogue", "computed")
        assert c["s0_iso76"] == pytest.approx(c["s0_catalogue_method"], rel=1e-9)
    masses = [c["mass_estimate_kg"] for c in cands]
    assert masses == sorted(masses)
    assert any("ESTIMATED" in n for n in data["notes"])


def test_select_by_kind_through_the_api():
    """Deep groove, F_r = 5 kN, F_a = 1 kN, 3000 r/min, 20000 h: a ball bearing needs
    C >= P (20000 h · 180000 rev/h / 10^6)^(1/3) = 15.3 P; every candidate has it (P >= F_r here)."""
    res = select({"F_x": "5 kN", "F_z": "1 kN"}, "3000 rpm", "20000 h", kind="deep_groove", count=3)
    assert len(res.candidates) == 3
    need = 5000.0 * (20000 * 180000 / 1e6) ** (1 / 3)
    for c in res.candidates:
        assert c["family"] == "deep_groove_ball" and c["C_iso281_N"] >= need * (1 - 1e-9)
    assert res.passed_screen >= len(res.candidates) and res.screened > res.passed_screen
    assert np.isfinite(res.seconds)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (dict(load=["Fr=5kN"], speed="3000rpm", life="-1 h"), "must be positive"),
        (dict(load=["Fr=5kN", "My=10N*m"], speed="3000rpm", life="1000 h"), "forces only"),
        (dict(load=["Fr=5kN"], speed="3000rpm", life="1000 h", kind="sleeve"), "kind"),
    ],
)
def test_bad_input_one_line(kwargs, message):
    with pytest.raises(InputError, match=message):
        select(**kwargs)


def test_select_nothing_found_exits_1_with_one_line():
    args = [
        "select",
        "--load",
        "Fr=500kN",
        "--speed",
        "3000rpm",
        "--life",
        "100000h",
        "--kind",
        "deep_groove",
    ]
    result = runner.invoke(app, args)
    assert result.exit_code == 1 and "no catalogue bearing meets" in result.stderr


@pytest.mark.parametrize("count", [0, 101, 10**20])
def test_count_outside_1_to_100_is_one_line(count):
    """The fuzz (seed 20261202 #2504): --count 10^20 with a life few rows reach analysed every row that
    passed the screen, one after another, for 32 s."""
    with pytest.raises(InputError, match=r"count \(\d+\) must be 1 to 100"):
        select({"F_x": "5 kN"}, "3000 rpm", "20000 h", count=count)


def test_the_work_limit_stops_the_full_analyses_with_a_note(monkeypatch):
    """Past BEARINGKIT_MAX_WORK_S of wall time no further full analysis starts; the note says why and
    what to do; the screen's counts are those of an unlimited run."""
    args = ({"F_x": "5 kN", "F_z": "1 kN"}, "3000 rpm", "20000 h")
    full = select(*args, kind="deep_groove", count=3)
    monkeypatch.setenv("BEARINGKIT_MAX_WORK_S", "1e-9")
    cut = select(*args, kind="deep_groove", count=3)
    assert full.candidates and not cut.candidates and not cut.rejected
    assert (cut.screened, cut.passed_screen) == (full.screened, full.passed_screen)
    assert "stopped after 0 full analyses: the work limit" in cut.notes[-1]
    assert "--count" in cut.notes[-1] and "BEARINGKIT_MAX_WORK_S" in cut.notes[-1]
    assert not any("stopped after" in n for n in full.notes)
