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
