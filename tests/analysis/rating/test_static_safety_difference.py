"""Two static safeties, one line: ISO 76's s0 = C0/P0 and the rows' s0 from p_max, why they differ and which
governs, on every face (JSON, the rating caption, the report)."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.analysis.rating.compare import S0_SAME, static_safety_difference
from bearingkit.cli.commands import app


def test_the_line_names_both_values_and_the_smaller_governs():
    assert static_safety_difference(6.075, 3.999).endswith("the smaller, the rows' s0 from p_max, governs")
    assert static_safety_difference(2.0, 3.0).endswith("the smaller, ISO 76's s0 = C0/P0, governs")
    assert "= 6.075" in static_safety_difference(6.075, 3.999) and "= 3.999" in static_safety_difference(
        6.075, 3.999
    )
    # within S0_SAME they are the same number for the reader; a missing one gives no line
    assert static_safety_difference(4.0, 4.0 * (1 + 0.9 * S0_SAME)) is None
    assert static_safety_difference(None, 4.0) is None and static_safety_difference(4.0, None) is None


def test_a_cylindrical_roller_bearing_shows_both_and_why_on_every_face(tmp_path):
    """NU 2216 E at F_r = 40 kN: the catalogue C0/P0 = 243/40 = 6.08, the rows' s0 = (4000/p_max)^2 ≈ 4."""
    a = bk.analyze("NU 2216 E", load=["Fr=40kN"], speed="1500rpm")
    s = a.rating_dict()["cases"][0]["system"]
    assert s["s0_iso76"] == pytest.approx(243e3 / 40e3, rel=1e-3)
    assert s["static_safety"] < s["s0_iso76"]
    assert s["static_safety_difference"] == static_safety_difference(s["s0_iso76"], s["static_safety"])
    out = CliRunner().invoke(app, ["rating", "NU 2216 E", "--load", "Fr=40kN", "--speed", "1500rpm"])
    assert out.exit_code == 0, out.output
    assert "static safety: ISO 76 s0 = C0/P0" in " ".join(out.output.split())
    js = CliRunner().invoke(app, ["rating", "NU 2216 E", "--load", "Fr=40kN", "--speed", "1500rpm", "--json"])
    assert (
        json.loads(js.output)["cases"][0]["system"]["static_safety_difference"]
        == s["static_safety_difference"]
    )
    html = a.report(tmp_path / "r.html").read_text(encoding="utf-8")
    assert "Static safety: ISO 76 s0 = C0/P0" in html and "governs" in html
