"""The spindle bearings (15°: 70xxC, 718/719 C, 72xxC) have an ISO 281 life now that Table 3's rows below
20° are shipped (issue 33): `bearingkit rating "7014 C"` and `bearingkit select` with the hand-checked P."""

from __future__ import annotations

import itertools
import json
import math

import pytest
from typer.testing import CliRunner

from bearingkit.catalogue import entries, resolve
from bearingkit.cli import app
from bearingkit.physics.life import iso76

runner = CliRunner()

#: ISO 281:2007 Table 3, α = 15°, single row, the first three rows as printed: (i f0 Fa/C0r, e, Y); X = 0.44.
ROWS_15 = [(0.178, 0.38, 1.47), (0.357, 0.40, 1.40), (0.714, 0.43, 1.30)]


def _table_15(rel: float) -> tuple[float, float]:
    """e, Y at i f0 Fa/C0r by hand between the printed rows."""
    for (r0, e0, y0), (r1, e1, y1) in itertools.pairwise(ROWS_15):
        if r0 <= rel <= r1:
            t = (rel - r0) / (r1 - r0)
            return e0 + t * (e1 - e0), y0 + t * (y1 - y0)
    raise AssertionError(rel)


def _f0_and_c0(name: str) -> tuple[float, float]:
    """f0 of the estimated geometry and the C0r the rating uses: the catalogue's where the row prints one
    (the 70xxC rows to 7022C: NSK E1102 B50-B60), else the estimate's."""
    b = resolve(name)
    g = b.estimate.element_diameter * math.cos(b.estimate.contact_angle) / b.estimate.pitch_diameter
    c0 = entries("angular_contact_ball")[b.designation.base].C0
    return float(iso76.f0_radial_ball(g)), b.C0 if c0 is None else float(c0)


def test_7014_c_has_an_iso281_life():
    """`bearingkit rating "7014 C" --load Fr=1kN --load Fa=0.5kN --speed 6000rpm`: P = X Fr + Y Fa with e, Y
    of Table 3 at i f0 Fa/C0r (C0r = 43 kN, NSK E1102 B56; f0 of the estimated geometry)."""
    args = ["rating", "7014 C", "--load", "Fr=1kN", "--load", "Fa=0.5kN", "--speed", "6000rpm", "--json"]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    system = json.loads(result.stdout)["cases"][0]["system"]
    f0, c0 = _f0_and_c0("7014 C")
    e, y = _table_15(f0 * 500.0 / c0)
    assert 0.5 > e  # Fa/Fr above e: X = 0.44
    assert system["P_iso281_N"] == pytest.approx(0.44 * 1000.0 + y * 500.0, rel=1e-6)
    assert system["iso281_note"] is None
    hours = (system["C_iso281_N"] / system["P_iso281_N"]) ** 3 * 1e6 / (6000 * 60)
    assert system["L10h_iso281_h"] == pytest.approx(hours, rel=1e-9)


def test_7014_c_below_the_table_says_so_in_one_line():
    """At Fa = 0.3 kN i f0 Fa/C0r is below Table 3's first 15° row (0.178): ISO 281 has no
    value there; the note says which value and which range, the ISO/TS 16281 life is still given."""
    args = ["rating", "7014 C", "--load", "Fr=1kN", "--load", "Fa=0.3kN", "--speed", "6000rpm", "--json"]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    system = json.loads(result.stdout)["cases"][0]["system"]
    f0, c0 = _f0_and_c0("7014 C")
    assert f0 * 300.0 / c0 < 0.178
    assert system["P_iso281_N"] is None and "[0.178, 7.14]" in system["iso281_note"]
    assert system["L10r_rev"] > 0


def test_select_returns_spindle_bearings():
    """15° rows pass the catalogue-method screen: `select --pattern "70??C"` returns 70xxC bearings, each
    with both lives and the ISO 281 P of Table 3 (checked by hand on each)."""
    args = ["select", "--load", "Fr=2kN", "--load", "Fa=1kN", "--speed", "6000rpm", "--life", "20000h"]
    result = runner.invoke(app, [*args, "--pattern", "70??C", "--count", "2", "--json"])
    assert result.exit_code == 0, result.output
    cands = json.loads(result.stdout)["candidates"]
    assert len(cands) == 2
    for cand in cands:
        assert cand["designation"].startswith("70") and cand["designation"].endswith("C")
        assert cand["L10h_iso281_h"] >= 20000 and cand["L10h_iso16281_h"] >= 20000
        f0, c0 = _f0_and_c0(cand["designation"])
        e, y = _table_15(f0 * 1000.0 / c0)
        assert 0.5 > e
        assert cand["P_iso281_N"] == pytest.approx(0.44 * 2000.0 + y * 1000.0, rel=1e-9)
