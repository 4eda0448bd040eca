"""The slewing-ring section of the HTML report: static load diagram with the load cases."""

import base64
import re
from pathlib import Path

from bearingkit.report import report_file

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _section(html: str) -> str:
    start = html.index('id="load-diagram"')
    return html[start : html.index("</section>", start)]


def test_slewing_report_draws_the_load_diagram_with_every_case(tmp_path):
    out = report_file(EXAMPLES / "slewing_crossed_roller.toml", tmp_path / "r.html")
    html = out.read_text()
    section = _section(html)
    png = re.search(r'src="data:image/png;base64,([^"]+)"', section).group(1)
    assert base64.b64decode(png).startswith(b"\x89PNG")
    for case in ("table", "overhung"):  # one table line per load case, with utilisations
        assert f"<td>{case}</td>" in section or f">{case}<" in section
    assert "5.046" in section and "f_stat" in section


def test_other_bearings_have_no_load_diagram(tmp_path):
    html = report_file(EXAMPLES / "srb_22220.toml", tmp_path / "r.html").read_text()
    assert 'id="load-diagram"' not in html


def test_the_report_draws_the_analysis_diagram_without_recomputing_it(tmp_path, monkeypatch):
    """The diagram is a part of the Analysis (computed once); the report only reads it."""
    from bearingkit.analysis import slewing
    from bearingkit.pipeline import analyze

    a = analyze(EXAMPLES / "slewing_four_point.toml")
    diagram = a.load_diagram
    assert diagram is not None and a.to_dict()["load_diagram"]["axial_capacity_N"] > 0

    def forbidden(*args, **kwargs):
        raise AssertionError("the report recomputed the load diagram")

    monkeypatch.setattr(slewing, "static_load_diagram", forbidden)
    html = a.report(tmp_path / "r.html").read_text()
    assert 'id="load-diagram"' in html
    assert analyze(EXAMPLES / "dgbb_6209.toml").load_diagram is None
