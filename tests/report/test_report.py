"""The HTML report: every section and row present, figures decode, no network, atomic writes."""

from __future__ import annotations

import base64
import dataclasses
import io
import os
import re
import xml.etree.ElementTree as ET
from html.parser import HTMLParser
from pathlib import Path

import matplotlib.image as mpimg
import numpy as np
import pytest

from bearingkit.analysis.rating.assembly import rate
from bearingkit.analysis.solver.quasistatic import SolverOptions
from bearingkit.cli.flagship import FlagshipContext
from bearingkit.errors import InputError
from bearingkit.io.loader import load_file, loads
from bearingkit.pipeline import analyze
from bearingkit.references import REFERENCES
from bearingkit.report import build_report, report_file, write_report
from bearingkit.report.html_format import fmt, warning_kind

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SEED000 = EXAMPLES / "seed000_composite.toml"
DGBB = EXAMPLES / "dgbb_6209.toml"


class Page(HTMLParser):
    """Collects images, sections and table cells of a report."""

    def __init__(self, text: str):
        super().__init__()
        self.images: list[dict] = []
        self.sections: list[dict] = []
        self.tables: list[dict] = []  # {"cls", "section", "rows": [[cell text]]}
        self.tags: set[str] = set()
        self._section: dict | None = None
        self._cell: list[str] | None = None
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.tags.add(tag)
        if tag == "img":
            self.images.append(a)
        elif tag == "section":
            self._section = a
            self.sections.append(a)
        elif tag == "table":
            self.tables.append({"cls": a.get("class", ""), "section": self._section, "rows": []})
        elif tag == "tr":
            self.tables[-1]["rows"].append([])
        elif tag in ("td", "th"):
            self._cell = []

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self.tables[-1]["rows"][-1].append("".join(self._cell).strip())
            self._cell = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


def decode(src: str) -> np.ndarray:
    head, _, data = src.partition(",")
    assert head == "data:image/png;base64"
    return mpimg.imread(io.BytesIO(base64.b64decode(data, validate=True)), format="png")


def decode_svg(src: str) -> ET.Element:
    """The root element of an inline SVG image (it must parse as XML)."""
    head, _, data = src.partition(",")
    assert head == "data:image/svg+xml;base64"
    text = base64.b64decode(data, validate=True).decode("utf-8")
    assert "<script" not in text and "href" not in text  # nothing to run, nothing fetched
    return ET.fromstring(text)


def distinct_colours(img: np.ndarray) -> int:
    rgb = (np.asarray(img)[..., :3] * 255).round().astype(np.uint32).reshape(-1, 3)
    return len(np.unique((rgb[:, 0] << 16) | (rgb[:, 1] << 8) | rgb[:, 2]))


@pytest.fixture(scope="module")
def flagship(tmp_path_factory):
    """Seed-000 flagship case through the flagship's Analysis (as `make run` does)."""
    ctx = FlagshipContext()
    path = ctx.analysis.report(tmp_path_factory.mktemp("flag") / "out" / "report.html")
    return ctx, path, path.read_text(encoding="utf-8")


@pytest.fixture(scope="module")
def dgbb():
    a = analyze(DGBB, lubricant="ISO_VG68", temperature=40.0, speed=100.0)
    native = a.friction_by("components").native
    html = build_report(
        a.input, a.statics, friction=native, rating=a.rating, notes=a.notes, warnings=a.warnings
    )
    return a.input, a.statics, native, a.rating, html


# ------------------------------------------------------------------------------------------------
# Content.
# ------------------------------------------------------------------------------------------------
def test_flagship_has_every_section_and_row(flagship):
    ctx, _, html = flagship
    page = Page(html)
    ids = [s.get("id") for s in page.sections]
    # "subsurface": the stresses below the contacts against the raceways' strength (issue 36)
    assert ids == ["inputs", "case-0", "subsurface", "warnings", "references"]
    rows = [t for t in page.tables if t["cls"] == "rows"]
    assert len(rows) == 1
    names = [r[0] for r in rows[0]["rows"][1:]]
    assert names == [r.name for r in ctx.bearing.model.rows]
    for h in (
        "Geometry",
        "Rows as modelled",
        "Material",
        "Lubricant",
        "Load cases",
        "Friction torque",
        "Ratings and static safety",
        "Slice pressure map",
        "Warnings",
        "References",
    ):
        assert h in html, h


def test_row_table_reads_the_result(flagship):
    """Q_max, p_max and loaded counts in the table are the result's (no recomputation)."""
    ctx, _, html = flagship
    table = next(t for t in Page(html).tables if t["cls"] == "rows")
    header, *body = table["rows"]
    for cells, state in zip(body, ctx.result.rows, strict=True):
        assert cells[header.index("Q_max [N]")] == fmt(state.max_load[0], 5)
        assert cells[header.index("p_max [MPa]")] == fmt(state.max_pressure[0].max(), 5, 1e-6)
        assert cells[header.index("loaded")] == f"{state.loaded_count[0]}/{state.load.shape[1]}"


def test_geometry_table_lists_every_given_field_with_units(flagship):
    ctx, _, html = flagship
    geo = next(t for t in Page(html).tables if t["rows"][0][:2] == ["field", "as given"])
    fields = {r[0]: r for r in geo["rows"][1:]}
    assert set(fields) == set(ctx.bearing.spec.geometry)
    assert fields["ball_diameter"][1:] == ["6 mm", "0.006", "m"]
    assert fields["n_axial_balls"][3] == "–"


def test_images_decode_and_are_not_blank(flagship):
    _, _, html = flagship
    page = Page(html)
    # polar, slice pressure map (roller rows), friction, rating, stress against depth (subsurface)
    assert len(page.images) == 5
    kinds = []
    for img in page.images:
        if img["src"].startswith("data:image/svg+xml"):  # polar, slice map, friction, rating: SVG
            root = decode_svg(img["src"])
            assert float(root.get("height")) > 100 and float(root.get("width")) > 300
            # something drawn from the results: bars and wedges carry their value; a map's cells (its
            # first group) more than one colour
            drawn = [e for e in root.iter() if e.get("data-value")]
            groups = [g for g in root.iter() if g.tag.endswith("g")]
            cells = {e.get("fill") for e in groups[0]} if groups else set()
            assert drawn or len(cells) > 1, img["alt"]
            kinds.append("svg")
        else:  # the stresses below the surface: a matplotlib PNG
            pix = decode(img["src"])
            assert pix.ndim == 3 and pix.shape[0] > 100 and pix.shape[1] > 500
            assert distinct_colours(pix) > 20, img["alt"]
            kinds.append("png")
    assert kinds.count("svg") == 4


def test_no_network_resources(flagship, dgbb):
    for html in (flagship[2], dgbb[4]):
        page = Page(html)
        assert not page.tags & {"script", "link", "iframe", "object", "embed"}
        before_refs = html.split('<section id="references"')[0]
        text = re.sub(r"data:image/(png|svg\+xml);base64,[A-Za-z0-9+/=]+", "", before_refs)
        assert "data:" not in text and "http" not in text.lower() and "//" not in text
        assert "url(" not in html
        for i in page.images:
            if i["src"].startswith("data:image/svg+xml;base64,"):
                decode_svg(i["src"])  # parses, no script, no link
            else:
                assert i["src"].startswith("data:image/png;base64,")


def test_references_are_full_citations(flagship):
    ctx, _, html = flagship
    refs = next(t for t in Page(html).sections if t.get("id") == "references")
    assert refs is not None
    for key in ctx.result.references:
        assert f'id="ref-{key}"' in html
    # friction and rating sources are listed with their full text (HTML-escaped)
    for key in ("iso76", "iso16281", "tian2025"):
        assert REFERENCES[key].split(" (")[0].replace("&", "&amp;") in html


def test_every_case_and_row_of_a_multi_case_file(dgbb):
    bearing, _, friction, _, html = dgbb
    page = Page(html)
    cases = [s for s in page.sections if s.get("data-section") == "case"]
    assert [s["data-case"] for s in cases] == [c.name for c in bearing.cases]
    row_tables = [t for t in page.tables if t["cls"] == "rows"]
    assert len(row_tables) == len(bearing.cases)
    for t in row_tables:
        assert [r[0] for r in t["rows"][1:]] == [r.name for r in bearing.model.rows]
    # no roller rows: polar + friction + rating per case, no slice map
    assert len(page.images) == 3 * len(bearing.cases)
    assert "Slice pressure map" not in html
    # friction total per case in the summary, in N·m (the unit of the CLI and the JSON)
    summary = next(t for t in page.tables if t["cls"] == "summary")
    col = summary["rows"][0].index("friction [N·m]")
    for c, r in enumerate(summary["rows"][1:]):
        assert r[col] == fmt(friction.total[c], 5)


def test_displacement_is_shown_in_display_units(dgbb):
    bearing, result, *_, html = dgbb
    disp = [t for t in Page(html).tables if t["cls"] == "displacement"]
    assert len(disp) == len(bearing.cases)
    for c, t in enumerate(disp):
        assert t["rows"][0][0] == "u_x [µm]"
        assert t["rows"][1][0] == fmt(result.displacement[c, 0], 5, 1e6)


def test_friction_skipped_without_lubricant_is_explained(tmp_path):
    a = analyze(DGBB, cases=["radial_4kN"])
    assert a.friction is None
    assert any("friction (components) not computed" in n and "lubricant: none given" in n for n in a.notes)
    html = a.report(tmp_path / "r.html").read_text(encoding="utf-8")
    assert "friction (components) not computed" in html
    assert "Not computed in this run: friction torque" in html
    assert len(Page(html).images) == 3  # the polar plot, the ratings, the stress against depth


# ------------------------------------------------------------------------------------------------
# Warnings.
# ------------------------------------------------------------------------------------------------
def test_non_convergence_is_reported():
    bearing = load_file(DGBB).select(["radial_4kN"])
    bearing = dataclasses.replace(bearing, options=SolverOptions(max_iterations=1, continuation_steps=0))
    result = bearing.solve()
    assert not result.converged[0]
    html = build_report(bearing, result, rating=rate(result))
    assert "NOT converged" in html
    assert html.count("non-convergence</span>") == 2  # in the case and in the warnings section
    assert result.reason[0] in html.replace("&#x27;", "'")


def test_edge_loading_of_uncrowned_rollers_is_reported():
    """Rollers without crowning load their ends: RatingResult flags it and the report shows the badge."""
    text = (EXAMPLES / "crb_nu209.toml").read_text()
    bearing = loads("\n".join(x for x in text.splitlines() if not x.startswith("profile"))).select(
        ["radial_10kN"]
    )
    result = bearing.solve()
    rating = rate(result)
    assert rating.rows[0].flags["edge_loading"][0]
    html = build_report(bearing, result, rating=rating)
    assert html.count("edge loading</span>") == 2  # in the case and in the warnings section
    assert "edge_loading" in html  # the flag column of the rating table


def test_truncated_ellipse_is_reported():
    bearing = load_file(DGBB).select(["radial_8.9kN"])
    result = bearing.solve()
    rating = rate(result, shoulder_height=0.001)
    assert any(warning_kind(w) == "truncated contact ellipse" for w in rating.warnings[0])
    html = build_report(bearing, result, rating=rating)
    assert "truncated contact ellipse</span>" in html


def test_static_overload_is_a_stress_warning():
    bearing = load_file(DGBB)
    heavy = dataclasses.replace(bearing.cases[0], name="overload", load=bearing.cases[0].load * 40.0)
    bearing = bearing.with_cases([heavy])
    result = bearing.solve()
    rating = rate(result)
    assert float(rating.static_safety[0]) < 1.0
    html = build_report(bearing, result, rating=rating)
    assert "stress over limit</span>" in html
    assert 'style="color:#c0392b"' in html  # s0 < 1 highlighted in the table


def test_warning_kinds():
    assert warning_kind("case 0 did not converge (x)") == "non-convergence"
    assert warning_kind("r: static safety s0 = 0.5 < 1: ... exceeds the ISO 76 limit 4200 MPa") == (
        "stress over limit"
    )
    assert warning_kind("r: no loaded element: no fatigue life or static safety") == "unloaded row"
    assert warning_kind("something else") == "note"


def test_mismatched_results_are_rejected(dgbb):
    bearing, result, *_ = dgbb
    with pytest.raises(InputError, match="load cases"):
        build_report(bearing.select(["radial_4kN"]), result)


# ------------------------------------------------------------------------------------------------
# Writing.
# ------------------------------------------------------------------------------------------------
def _leftovers(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


def test_write_report_is_atomic_and_creates_folders(tmp_path):
    out = tmp_path / "a" / "b" / "report.html"
    assert write_report(out, "<p>é ✓</p>") == out
    assert out.read_text(encoding="utf-8") == "<p>é ✓</p>"
    assert _leftovers(out.parent) == ["report.html"]


def test_unwritable_path_raises_and_leaves_nothing(tmp_path):
    blocker = tmp_path / "not_a_folder"
    blocker.write_text("x")
    for target in (blocker / "report.html", blocker / "sub" / "dir" / "report.html"):
        with pytest.raises(InputError, match=r"cannot write the report") as err:
            write_report(target, "<p>x</p>")
        assert str(target) in str(err.value) and "\n" not in str(err.value)
    assert _leftovers(tmp_path) == ["not_a_folder"]
    assert blocker.read_text() == "x"
    with pytest.raises(InputError, match="is a directory"):
        write_report(tmp_path, "<p>x</p>")


def test_failed_write_keeps_old_report_and_removes_temporaries(tmp_path, monkeypatch):
    old = tmp_path / "report.html"
    old.write_text("old")

    def boom(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", boom)
    with pytest.raises(InputError, match="the disk is full \\(no space left on device\\); free some space"):
        write_report(old, "<p>new</p>")
    with pytest.raises(InputError):
        write_report(tmp_path / "new" / "deeper" / "report.html", "<p>new</p>")
    assert old.read_text() == "old"
    assert _leftovers(tmp_path) == ["report.html"]


def test_report_file_end_to_end(tmp_path):
    out = tmp_path / "out" / "report.html"
    assert report_file(DGBB, out, speed=150.0, temperature=60.0) == out
    html = out.read_text(encoding="utf-8")
    page = Page(html)
    assert [s["data-case"] for s in page.sections if s.get("data-section") == "case"] == [
        "radial_8.9kN",
        "radial_4kN",
    ]
    loads = next(t for t in page.tables if t["rows"][0][0] == "case" and "speed [r/min]" in t["rows"][0])
    col = loads["rows"][0].index("speed [r/min]")
    assert {r[col] for r in loads["rows"][1:]} == {fmt(150.0 * 30 / np.pi, 5)}
    assert "friction (components) not computed" in html  # the 6209 file has no lubricant
    assert "Ratings and static safety" in html


def test_report_file_bad_input_writes_nothing(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(DGBB.read_text().replace('element_diameter = "12.7 mm"', 'element_diameter = "-12.7 mm"'))
    out = tmp_path / "out" / "report.html"
    with pytest.raises(InputError, match=r"bad\.toml.*element_diameter"):
        report_file(bad, out)
    assert not (tmp_path / "out").exists()


def test_report_shows_the_analysis_it_is_given(tmp_path):
    """The report shows the Analysis's own friction, rating and operating point (not recomputed)."""
    a = analyze(
        DGBB,
        cases=["radial_4kN"],
        speed=10.0,
        lubricant="ISO_VG46",
        temperature=55.0,
        reliability=0.99,
        friction_options={"cage_mass": 0.25},
    )
    path = a.report(tmp_path / "out" / "report.html", title="bearingkit flagship — test")
    html = path.read_text(encoding="utf-8")
    assert "bearingkit flagship" in html
    assert "L1r [rev]" in html  # the analysis's 99 % reliability rating
    assert "temperature 55 °C; lubricant ISO_VG46" in html and "cage_mass 0.25" in html
    assert fmt(a.friction.total[0], 5) in html


def test_flagship_fallback_uses_seed000_friction_data(flagship):
    from bearingkit.papers.tian2025 import validation as seed000_friction

    _, path, html = flagship
    assert f"viscosity_factor {seed000_friction.VISCOSITY_FACTOR:g}" in html
    assert f"cage_mass {seed000_friction.CAGE_MASS:g}" in html
    assert path.parent.name == "out"  # parent folder created


@pytest.mark.parametrize(("name", "model"), [("srb_22220.toml", "skf"), ("needle_na4910.toml", "palmgren")])
def test_kinds_without_a_component_model_show_a_catalogue_model(tmp_path, name, model):
    """Spherical roller and needle rows have no component friction model: by default they get a catalogue
    model (SKF, Palmgren for needles), the report names it with its reason and its torque and power; asked
    for, the component model falls back in the report to the first catalogue model that applies."""
    a = analyze(EXAMPLES / name, speed="1000 rpm")
    assert a.friction.model == model and a.friction.why
    html = a.report(tmp_path / "r.html").read_text(encoding="utf-8")
    assert "Not computed in this run: friction torque" not in html
    assert f"Friction model: {model} — " in html
    for case in range(a.n_cases):
        total = fmt(float(a.friction_by(model).total[case]), 5)
        power = fmt(float(a.friction_by(model).power_loss[case]), 4)
        assert (
            f"Total M = <b>{total} N·m</b>, power loss P = <b>{power} W</b> ({model} catalogue model" in html
        )
    b = analyze(EXAMPLES / name, speed="1000 rpm", friction_model="components")
    assert b.friction is None
    html = b.report(tmp_path / "c.html").read_text(encoding="utf-8")
    assert "the report shows the skf catalogue model" in html or "the report shows the palmgren" in html
