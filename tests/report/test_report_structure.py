"""The report of a bearing in its structure: a numbered section per case after the operating conditions
(its own number, the warnings after it), with the rigid → flexible table and the figure; none without
a [structure]."""

import re

from bearingkit.report import report_file


def _headings(html: str) -> list[str]:
    return re.findall(r"<h[1-4][^>]*>([^<]*)", html)


def test_structure_section_has_its_own_number(tmp_path):
    out = tmp_path / "r.html"
    report_file("examples/dgbb_6209_thin_housing.toml", out)
    html = out.read_text()
    heads = _headings(html)
    assert "2.4. Operating conditions" in heads
    assert "2.5. In its structure: rigid → flexible rings" in heads
    assert "2.6. Warnings" in heads
    numbers = [h.split(" ", 1)[0] for h in heads if re.match(r"\d+\.\d+\.", h)]
    assert len(numbers) == len(set(numbers))  # no number twice
    sections = [part.split("</section>", 1)[0] for part in html.split('data-section="structure"')[1:]]
    assert len(sections) == 2  # one per load case
    # 4 kN: the housing lets 5 balls carry (3 on rigid rings)
    assert "5 → 5" in sections[0] and "3 → 5" in sections[1]
    assert all("<img" in section for section in sections)


def test_no_structure_section_without_a_structure(tmp_path):
    out = tmp_path / "r.html"
    report_file("examples/dgbb_6209.toml", out)
    heads = _headings(out.read_text())
    assert "2.5. Warnings" in heads
    assert not any("In its structure" in h for h in heads)
