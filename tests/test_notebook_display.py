"""Notebook display (issue 42): what a Jupyter cell shows for an Analysis, a shaft and a study result.

Jupyter calls ``_repr_html_`` and renders the HTML; the tests read that HTML back with the standard
library's parser, cell by cell, as a reader of the notebook would, and check it against values worked
out here (ISO 281 by hand from the catalogue C) and against the warnings the analysis carries.
"""

from __future__ import annotations

import math
from html.parser import HTMLParser
from pathlib import Path

import pytest

import bearingkit as bk

ROOT = Path(__file__).resolve().parents[1]


class _Cells(HTMLParser):
    """Headers, body rows (list of cell texts) and list items of a rendered table."""

    def __init__(self):
        super().__init__()
        self.headers, self.rows, self.items, self.scripts = [], [], [], 0
        self._tag, self._text = None, ""

    def handle_starttag(self, tag, attrs):
        if tag == "tr" and self._tag != "th":
            self.rows.append([])
        if tag in ("th", "td", "li"):
            self._tag, self._text = tag, ""
        if tag == "script":
            self.scripts += 1

    def handle_endtag(self, tag):
        if tag == self._tag:
            {"th": self.headers, "li": self.items}.get(tag, self.rows[-1] if self.rows else []).append(
                self._text
            )
            self._tag = None

    def handle_data(self, data):
        if self._tag:
            self._text += data


def _read(html: str) -> _Cells:
    cells = _Cells()
    cells.feed(html)
    cells.rows = [r for r in cells.rows if r]
    return cells


def _notebook_html(obj) -> str:
    """What Jupyter's HTML formatter takes: ``_repr_html_`` (IPython calls exactly this method)."""
    html = obj._repr_html_()
    assert isinstance(html, str) and html.startswith("<div")
    return html


def test_an_analysis_shows_L10h_and_its_warnings():
    """Two cases of a 6205 at 3000 r/min: 2 kN (no warning) and 10 kN (s0 < 1: a warning). The ISO 281
    column is the hand calculation L10h = (C/P)³ 10⁶ / (60 n) with the catalogue C = 14.0 kN."""
    a = bk.analyze("6205", load=[{"F_x": "2 kN"}, {"F_x": "10 kN"}], speed="3000 rpm")
    cells = _read(_notebook_html(a))
    head = cells.headers
    assert head[:3] == ["case", "converged", "n [r/min]"]
    assert "L10h ISO 281 [h]" in head and "L10h ISO/TS 16281 [h]" in head and "s0" in head
    rows = {r[0]: dict(zip(head, r, strict=True)) for r in cells.rows}
    assert len(rows) == 2
    for row, P in zip(rows.values(), (2000.0, 10000.0), strict=True):
        by_hand = (14000.0 / P) ** 3 * 1e6 / (60.0 * 3000.0)
        assert float(row["L10h ISO 281 [h]"]) == pytest.approx(by_hand, rel=5e-4)  # 4 digits shown
        assert float(row["F_r [kN]"]) == pytest.approx(P / 1e3)
        ts = a.rating.to_dict(list(rows).index(row["case"]))["system"]["L10h_h"]
        assert float(row["L10h ISO/TS 16281 [h]"]) == pytest.approx(ts, rel=5e-4)
    assert all(r["converged"] == "yes" for r in rows.values())
    # every warning of the analysis is shown, named by its case; the 10 kN case's s0 < 1 among them
    expected = [f"{name}: {w}" for name, ws in zip(a.case_names, a.warnings, strict=True) for w in ws]
    assert a.warnings[0] == [] and any("static safety" in w for w in a.warnings[1])
    assert [i for i in cells.items if i in expected] == expected
    light, heavy = rows.values()
    assert float(heavy["s0"]) < 1.0 < float(light["s0"])
    assert cells.scripts == 0


def test_a_failing_repr_still_shows_the_error():
    a = bk.analyze("6205", load={"F_x": "2 kN"})
    a.__class__ = type("Broken", (type(a),), {"statics": property(lambda self: 1 / 0)})
    assert "error: division by zero" in _notebook_html(a)


def test_the_package_lists_its_public_names():
    assert "analyze" in dir(bk) and "Analysis" in dir(bk)
    assert set(bk.__all__) <= set(dir(bk))
    for name in bk.__all__:
        assert getattr(bk, name) is not None


def test_text_is_escaped():
    from bearingkit.display import html_table, number

    html = html_table("<b>x</b>", ["a [<]"], [["<script>", number(math.nan)]], warnings=["w & <i>"])
    assert "<script>" not in html and "&lt;script&gt;" in html and "—" in html
    assert "w &amp; &lt;i&gt;" in html


def test_a_shaft_shows_every_bearings_life_and_the_system_life():
    from bearingkit.systems.shaft.input import load_shaft_file
    from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis

    shaft = ShaftAnalysis(load_shaft_file(ROOT / "examples" / "shaft_countershaft.toml"))
    cells = _read(_notebook_html(shaft))
    head = cells.headers
    assert head[:2] == ["case", "bearing"]
    assert head.index("L10h ISO 281 [h]") < head.index("L10rh ISO/TS 16281 [h]")  # ISO 281 first
    data = shaft.to_dict()
    expected_rows = sum(len(c["bearings"]) + 1 for c in data["cases"])  # + the system line
    assert len(cells.rows) == expected_rows
    first = data["cases"][0]
    line = dict(zip(head, cells.rows[0], strict=True))
    summary = first["bearings"][0]["summary"]
    assert line["bearing"] == summary["name"]
    assert float(line["L10rh ISO/TS 16281 [h]"]) == pytest.approx(summary["L10h_h"], rel=5e-4)
    assert float(line["L10h ISO 281 [h]"]) == pytest.approx(summary["L10h_iso281_h"], rel=5e-4)
    system = dict(zip(head, cells.rows[len(first["bearings"])], strict=True))
    assert system["bearing"] == "system"
    sysd = first["rating"]["system"]
    assert float(system["L10rh ISO/TS 16281 [h]"]) == pytest.approx(sysd["L10h_h"], rel=5e-4)
    assert float(system["L10h ISO 281 [h]"]) == pytest.approx(sysd["L10h_iso281_h"], rel=5e-4)
    warnings = [f"{c['case']}: {w}" for c in data["cases"] for w in c["warnings"]]
    assert [i for i in cells.items if i in warnings] == warnings


def test_a_study_result_shows_its_first_rows_with_units_and_its_counts():
    pytest.importorskip("pyarrow")
    from bearingkit.studies.run.runner import run_study

    result = run_study(ROOT / "examples" / "studies" / "dgbb_6209_clearance_load.toml")
    cells = _read(_notebook_html(result))
    n = len(result.results)
    assert any(h.endswith("_N") or h.endswith("_h") or "[" in h for h in cells.headers)  # units in names
    from bearingkit.display import MAX_ROWS

    assert len(cells.rows) == min(n, MAX_ROWS)
    first = dict(zip(cells.headers, cells.rows[0], strict=True))
    assert first["case"] == str(result.results["case"].iloc[0])
