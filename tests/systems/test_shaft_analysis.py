"""Every bearing of a shaft as a pipeline Analysis: same numbers as the shaft solver, in every face.

The per-bearing Analysis must reproduce what the shaft solution already holds (its reactions, and the
ratings and friction of the direct functions of :mod:`bearingkit.systems.shaft.life`), the system lives
must solve the Weibull system equation, and a bearing's warning must reach the CLI, the JSON and the
HTML report.
"""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

from bearingkit.analysis.solver.quasistatic import solve
from bearingkit.errors import InputError
from bearingkit.systems.shaft.input import load_shaft_file, shaft_from_dict
from bearingkit.systems.shaft.life import friction_system, rate_system
from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
COUNTERSHAFT = EXAMPLES / "shaft_countershaft.toml"
SPINDLE = EXAMPLES / "shaft_spindle.toml"


@pytest.fixture(scope="module")
def countershaft():
    return ShaftAnalysis(load_shaft_file(COUNTERSHAFT))


@pytest.fixture(scope="module")
def spindle():
    return ShaftAnalysis(load_shaft_file(SPINDLE))


def _cli(*args):
    """The command run in-process by typer's CliRunner (the code path of a subprocess without Python's
    start-up, which the start-up tests cover): returncode, stdout and stderr as a subprocess gives them."""
    from types import SimpleNamespace

    from typer.testing import CliRunner

    from bearingkit.cli import app

    result = CliRunner().invoke(app, [str(a) for a in args])
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise result.exception
    return SimpleNamespace(returncode=result.exit_code, stdout=result.stdout, stderr=result.stderr)


@pytest.mark.parametrize("name", ["countershaft", "spindle"])
def test_each_bearing_analysis_equals_the_shaft_solution(name, request):
    """Statics at the seat state: load = the shaft's bearing load (round-off), q imposed exactly; ratings
    and friction equal the direct functions on the shaft result (same kernels, same state)."""
    sa = request.getfixturevalue(name)
    res = sa.result
    direct = rate_system(res)
    torque, _ = friction_system(res, lubricant=sa.input.lubricant)
    assert set(sa.bearings) == {b.name for b in sa.system.bearings}
    for b, a in sa.bearings.items():
        load = res.bearing_load(b)
        scale = np.abs(load[:, :3]).max()
        # the same kernel response at the same q, evaluated twice: equal to a few ulps of the load scale
        assert np.abs(a.statics.load - load).max() <= 1e-12 * scale
        assert np.array_equal(a.statics.displacement, res.relative_displacement(b))
        assert np.array_equal(a.statics.converged, res.converged)
        np.testing.assert_allclose(
            np.ma.getdata(a.rating.life), np.ma.getdata(direct.bearings[b].life), rtol=1e-12
        )
        np.testing.assert_allclose(a.friction_by("components").total, torque[b], rtol=1e-12)
        for c in range(res.n_cases):
            summary = sa.bearing_summary(b, c)
            assert list(summary["reaction_on_shaft"].values()) == pytest.approx(res.reaction(b)[c], abs=0)
            assert summary["L10r_rev"] == pytest.approx(float(direct.bearings[b].life[c]), rel=1e-12)
    np.testing.assert_allclose(np.ma.getdata(sa.rating.life), np.ma.getdata(direct.life), rtol=1e-12)


@pytest.mark.parametrize("name", ["countershaft", "spindle"])
def test_the_imposed_state_is_the_equilibrium_of_the_bearing_under_its_load(name, request):
    """Independent check: the bearing alone, all five DOFs free, under the load the shaft puts on it,
    settles at the seat's relative displacement q (the single-bearing Newton, rtol 1e-10), at the
    seat's speed (inner ring at the shaft speed, with the sign of the bearing's orientation)."""
    sa = request.getfixturevalue(name)
    for b in sa.bearings:
        seat = sa.system.bearing(b)
        res = solve(seat.bearing, sa.result.bearing_load(b), speed=seat.speed_of(sa.input.loads.speed))
        assert res.converged.all(), res.reason
        q = sa.result.relative_displacement(b)
        acts = np.abs(seat.law.reach).max(axis=0) > 0  # an NU has no axial contact: u_z is arbitrary
        scale = np.abs(q[:, :3]).max()
        assert acts[:2].all() and acts[2] == (seat.bearing.name.startswith("7209") or b == "A")
        tol = 1e-5 * np.array([scale] * 3 + [scale / seat.law.char_length] * 2)
        error = np.abs(res.displacement - q)[:, acts] / tol[acts]
        assert error.max() <= 1.0, error


def test_system_lives_solve_the_weibull_equation(countershaft):
    """Ball (e = 10/9) and roller (e = 9/8) bearing: Σ (L_sys / L_i)^e_i = 1 for L10 and for L_nm
    (each bearing has one row), and the system outlives none of its bearings."""
    r = countershaft.rating
    slopes = {n: a.rating.rows[0].weibull_slope for n, a in countershaft.bearings.items()}
    assert sorted(slopes.values()) == pytest.approx([10 / 9, 9 / 8])
    for attr in ("life", "modified_life"):
        system = np.ma.getdata(getattr(r, attr))
        lives = {n: np.ma.getdata(getattr(a.rating, attr)) for n, a in countershaft.bearings.items()}
        total = sum((system / lives[n]) ** e for n, e in slopes.items())
        np.testing.assert_allclose(total, 1.0, rtol=1e-9)
        assert np.all(system < np.min(list(lives.values()), axis=0))
    assert not np.ma.getmaskarray(r.modified_life).any()  # the example gives e_C: L_nm exists


def _weibull_root(lives, slopes) -> float:
    """L10 of independently failing members by brentq on the survival product: Π S_i(L) = 0.9 with
    S_i(L) = 0.9^((L/L_i)^e_i) (written from the two-parameter Weibull law, not from the library)."""
    from scipy.optimize import brentq

    def gap(log_life):
        survival = np.prod(
            [0.9 ** ((np.exp(log_life) / li) ** e) for li, e in zip(lives, slopes, strict=True)]
        )
        return survival - 0.9

    lo, hi = np.log(min(lives)) - 10.0, np.log(min(lives)) + 1e-9
    return float(np.exp(brentq(gap, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps)))


def test_iso281_system_life_is_the_weibull_root_of_the_bearings_iso281_lives(countershaft):
    """ISO 281 system L10 and L_nm (listed first) = the brentq root of the survival product over the
    bearings' own ISO 281 lives (ball 10/9, roller 9/8), to 1e-12; hours at the cases' speed."""
    r = countershaft.rating
    data = countershaft.to_dict()
    slopes = [a.rating.rows[0].weibull_slope for a in countershaft.bearings.values()]
    for c, case in enumerate(data["cases"]):
        system = case["rating"]["system"]
        assert system["headline"]["method"] == "ISO 281"
        assert list(system).index("L10_iso281_rev") < list(system).index("L10r_rev")
        for key, attr in (("L10_iso281_rev", "life"), ("Lnm_iso281_rev", "modified_life")):
            lives = [float(getattr(a.rating.iso281, attr)[c]) for a in countershaft.bearings.values()]
            hand = _weibull_root(lives, slopes)
            assert system[key] == pytest.approx(hand, rel=1e-12)
            assert system[key] < min(lives)
        # the per-bearing summaries carry the same ISO 281 lives, first among the lives
        for b in case["bearings"]:
            s = b["summary"]
            own = countershaft.bearings[b["name"]].rating.to_dict(c)["system"]
            assert s["L10h_iso281_h"] == own["L10h_iso281_h"] and s["Lnm_iso281_h"] == own["Lnm_iso281_h"]
            assert list(s).index("L10h_iso281_h") < list(s).index("L10h_h")
        speed = abs(float(countershaft.input.loads.speed[c]))
        hours = system["L10_iso281_rev"] / (speed / (2 * np.pi)) / 3600.0
        assert system["L10h_iso281_h"] == pytest.approx(hours, rel=1e-12)
    assert not np.ma.getmaskarray(r.iso281_life).any()
    # the example's 'rated' case: the ISO 281 system L10h printed first (6,577 h when this was built)
    assert data["cases"][0]["case"] == "rated"
    assert data["cases"][0]["rating"]["system"]["L10h_iso281_h"] == pytest.approx(6577.33, rel=1e-5)


def test_cli_and_report_show_the_iso281_system_life_first(tmp_path):
    out = _cli("shaft", COUNTERSHAFT, "--report", tmp_path / "s.html")
    assert out.returncode == 0, out.stderr
    text = " ".join(out.stdout.split())
    assert text.index("system ISO 281: L10h =") < text.index("system ISO/TS 16281: L10rh =")
    assert text.index("L10h ISO 281 h") < text.index("L10rh TS h")
    assert "why they differ:" in text and "e = 10/9 ball, 9/8 roller" in text
    html = (tmp_path / "s.html").read_text()
    assert html.index("L10h ISO 281 [h]") < html.index("L10rh ISO/TS 16281 [h]")
    section = html[html.index("System life</h4>") :]
    assert section.index("<td class=l>ISO 281</td>") < section.index("<td class=l>ISO/TS 16281</td>")
    assert "Why they differ:" in section


def _low_film_file(tmp_path) -> Path:
    """The countershaft's first load case with a thin oil, hot and slow: κ < 1 in every bearing."""
    data = tomllib.loads(COUNTERSHAFT.read_text())
    text = COUNTERSHAFT.read_text().split("[[load_cases]]")[0]
    for name in ("dgbb_6209.toml", "crb_nu209.toml"):  # beside the shaft file: a file reads no farther
        (tmp_path / name).write_text((EXAMPLES / name).read_text())
    text += '[[load_cases]]\nname = "hot"\nspeed = "200 rpm"\ntemperature = "100 degC"\n'
    text += f'gears = {{ input_gear = "{data["load_cases"][0]["gears"]["input_gear"]}", '
    text += f'output_pinion = "{data["load_cases"][0]["gears"]["output_pinion"]}" }}\n'
    text += '[lubricant]\nname = "ISO_VG32"\n'
    path = tmp_path / "hot_shaft.toml"
    path.write_text(text)
    return path


def test_a_bearing_warning_reaches_cli_json_and_report(tmp_path):
    from typer.testing import CliRunner

    from bearingkit.cli import app

    path = _low_film_file(tmp_path)
    sa = ShaftAnalysis(load_shaft_file(path))
    warning = next(w for w in sa.warnings[0] if w.startswith("B: ") and "κ =" in w)
    assert warning[3:] in sa.bearings["B"].warnings[0]  # it is the bearing's own Analysis warning
    runner = CliRunner()
    out = runner.invoke(app, ["shaft", str(path), "--json"])
    assert out.exit_code == 0, out.output
    data = json.loads(out.stdout)
    assert warning in data["cases"][0]["warnings"]
    assert warning[3:] in data["cases"][0]["bearings"][1]["analysis"]["warnings"]
    report = tmp_path / "hot.html"
    out = runner.invoke(app, ["shaft", str(path), "--report", str(report)])
    assert out.exit_code == 0, out.output
    assert warning in " ".join(out.stdout.split())
    import html as html_lib

    assert html_lib.escape(warning, quote=True) in report.read_text()


def _cells(html: str, cls: str) -> list[list[str]]:
    """Rows of cell texts of every table of class ``cls``."""
    out = []
    for table in re.findall(rf'<table class="{cls}">(.*?)</table>', html, flags=re.S):
        body = table.split("<tbody>")[1]
        for row in re.findall(r"<tr>(.*?)</tr>", body, flags=re.S):
            out.append(
                [re.sub(r"<[^>]+>", "", c) for c in re.findall(r"<td[^>]*>(.*?)</td>", row, flags=re.S)]
            )
    return out


def _shown(cell: str, value, factor: float = 1.0):
    if value is None:
        assert cell == "—"
        return
    # displayed with ≥ 3 significant digits (4 or 5 for most): half a unit of the 3rd digit
    assert float(cell) == pytest.approx(value * factor, rel=5e-3, abs=1e-9), (cell, value)


def test_report_shows_the_numbers_of_the_json(tmp_path):
    from bearingkit.report.systems.shaft_html import REACTION_COLUMNS, RESULT_COLUMNS, SEAT_COLUMNS

    raw = tomllib.loads(COUNTERSHAFT.read_text())
    raw["load_cases"] = raw["load_cases"][2:]  # the case with a coupling force: every reaction non-zero
    analysis = ShaftAnalysis(shaft_from_dict(raw, "one_case.toml", base=EXAMPLES))
    html = analysis.report(tmp_path / "shaft.html").read_text()
    data = json.loads(json.dumps(analysis.to_dict()))
    reactions, results, systems = _cells(html, "reactions"), _cells(html, "bearings"), _cells(html, "system")
    n_b = len(data["bearings"])
    assert len(reactions) == len(results) == n_b * len(data["cases"])
    assert len(systems) == 2 * len(data["cases"])  # per case: the ISO 281 row, then the ISO/TS 16281 row
    for c, case in enumerate(data["cases"]):
        for i, b in enumerate(case["bearings"]):
            s = b["summary"]
            row = reactions[c * n_b + i]
            assert row[0] == b["name"]
            for cell, (key, _, factor, _) in zip(row[2:7], REACTION_COLUMNS, strict=True):
                _shown(
                    cell,
                    s["reaction_on_shaft"][key] if abs(s["reaction_on_shaft"][key]) > 1e-6 else 0.0,
                    factor,
                )
            for cell, (key, _, factor, _) in zip(row[7:12], SEAT_COLUMNS, strict=True):
                _shown(cell, s["seat_displacement"][key], factor)
            _shown(row[12], s["misalignment_rad"], 1e3)
            row = results[c * n_b + i]
            assert row[0] == b["name"]
            for cell, (key, _, factor, _) in zip(row[1:], RESULT_COLUMNS, strict=False):
                _shown(cell, s[key] if key != "axial_load_N" or abs(s[key]) > 1e-6 else 0.0, factor)
        system = case["rating"]["system"]
        iso, ts = systems[2 * c], systems[2 * c + 1]
        assert iso[0] == "ISO 281" and ts[0] == "ISO/TS 16281"
        iso_keys = ("L10_iso281_rev", "L10h_iso281_h", "Lnm_iso281_rev", "Lnm_iso281_h")
        for cell, key in zip(iso[1:], iso_keys, strict=True):
            _shown(cell, system[key])
        for cell, key in zip(ts[1:], ("L10r_rev", "L10h_h", "Lnmr_rev", "Lnmr_h"), strict=True):
            _shown(cell, system[key])
        shown_loss = re.findall(r"Power loss of the bearings: ([^ ]+) W", html)
        _shown(shown_loss[c], case["power_loss_W"])
    # each bearing's own subsection, by the single-bearing renderer, once per load case
    for b in data["bearings"]:
        for c in range(len(data["cases"])):
            assert f'id="bearing-{b["name"]}-case-{c}"' in html
    assert html.count('src="data:image/') >= len(data["cases"]) * (1 + n_b)
    assert "http" not in re.sub(r'<section id="references".*?</section>', "", html, flags=re.S)


def test_bad_contamination_in_a_shaft_file_is_one_line():
    data = tomllib.loads(COUNTERSHAFT.read_text())
    for value, expected in (("dirty", "must be a number 0 … 1 or one of"), ("1.5", "must lie in 0 … 1")):
        data["lubrication"] = {"contamination": value}
        with pytest.raises(InputError) as info:
            shaft_from_dict(data, "bad.toml", base=EXAMPLES)
        message = str(info.value)
        assert "\n" not in message and message.startswith("bad.toml: lubrication.contamination")
        assert expected in message


def test_cli_bad_input_is_one_line_and_writes_no_report(tmp_path):
    report = tmp_path / "never.html"
    out = _cli("shaft", str(COUNTERSHAFT), "--contamination", "7", "--report", str(report))
    assert out.returncode == 2 and out.stdout == ""
    assert out.stderr.count("\n") == 1 and out.stderr.startswith("error: ")
    assert "(bearing A)" in out.stderr and "contamination" in out.stderr
    assert not report.exists()
    bad = tmp_path / "bad_shaft.toml"
    bad.write_text(
        COUNTERSHAFT.read_text().replace('max_element_length = "5 mm"', 'max_element_length = "-5 mm"')
    )
    from typer.testing import CliRunner

    from bearingkit.cli import app

    out = CliRunner().invoke(app, ["report", str(bad), "-o", str(report)])
    assert out.exit_code == 2 and out.stderr.count("\n") == 1 and "shaft.max_element_length" in out.stderr
    assert not report.exists()
    out = CliRunner().invoke(app, ["report", str(COUNTERSHAFT), "-o", str(report), "--speed", "100 rpm"])
    assert out.exit_code == 2 and "--speed apply to a bearing file" in out.stderr
    assert not report.exists()


def test_linear_bearing_has_reactions_but_no_analysis():
    data = tomllib.loads(COUNTERSHAFT.read_text())
    b = data["shaft"]["bearings"][1]
    del b["file"]
    b["stiffness"] = {"radial": "2e8 N/m"}
    sa = ShaftAnalysis(shaft_from_dict(data, "linear.toml", base=EXAMPLES))
    assert set(sa.bearings) == {"A"}
    d = sa.to_dict()
    s = d["cases"][0]["bearings"][1]["summary"]
    assert s["radial_load_N"] > 0 and s["L10r_rev"] is None and "analysis" not in d["cases"][0]["bearings"][1]
    assert any(n.startswith("B: a linear stiffness") for n in d["notes"])
    # the system life is then the ball bearing's alone
    np.testing.assert_allclose(
        np.ma.getdata(sa.rating.life), np.ma.getdata(sa.bearings["A"].rating.life), rtol=1e-12
    )


def test_report_refuses_more_cases_than_the_report_cap(tmp_path):
    from bearingkit.io.loader import MAX_REPORT_CASES

    raw = tomllib.loads(COUNTERSHAFT.read_text())
    one = raw["load_cases"][0]
    raw["load_cases"] = [{**one, "name": f"c{i}"} for i in range(MAX_REPORT_CASES + 1)]
    analysis = ShaftAnalysis(shaft_from_dict(raw, "many.toml", base=EXAMPLES))
    with pytest.raises(InputError) as info:
        analysis.report(tmp_path / "many.html")
    assert str(info.value).startswith(f"many.toml: load_cases ({MAX_REPORT_CASES + 1} cases) must be at most")
    assert "result" not in analysis.__dict__  # refused before anything was solved
    assert not (tmp_path / "many.html").exists()


def test_report_tells_a_shaft_file_by_the_bounded_reader(tmp_path):
    """`bearingkit report` looks for [shaft] through the bounded reader: a deeply nested bearing file
    still gets the reader's one-line message (a plain tomllib parse would recurse too deep)."""
    from typer.testing import CliRunner

    from bearingkit.cli import app

    deep = tmp_path / "deep.toml"
    deep.write_text("[geometry]\nouter_diameter = " + "[" * 5000 + "]" * 5000 + "\n")
    out = CliRunner().invoke(app, ["report", str(deep), "-o", str(tmp_path / "r.html")])
    assert out.exit_code == 2 and (out.exception is None or isinstance(out.exception, SystemExit))
    assert out.stderr.count("\n") == 1 and out.stderr.startswith(f"error: {deep}: ")
    assert "nested" in out.stderr


def test_a_bearing_without_rating_leaves_the_system_without_life():
    """A bearing whose rating failed (the Analysis says why in its notes) masks the system life: the
    system is not the longer-lived rest."""
    sa = ShaftAnalysis(load_shaft_file(COUNTERSHAFT))
    sa.bearings["B"].__dict__["_rating"] = (None, "ratings not computed: stand-in failure")
    assert np.ma.getmaskarray(sa.rating.life).all() and np.ma.getmaskarray(sa.rating.modified_life).all()
    assert np.ma.getmaskarray(sa.rating.iso281_life).all()
    assert np.ma.getmaskarray(sa.rating.iso281_modified_life).all()
    assert all(any("no system life: bearing(s) ['B']" in w for w in case) for case in sa.warnings)
    assert "B: ratings not computed: stand-in failure" in sa.notes
    d = sa.to_dict()
    assert d["cases"][0]["rating"]["system"]["L10r_rev"] is None
    assert d["cases"][0]["rating"]["system"]["L10_iso281_rev"] is None
    assert d["cases"][0]["bearings"][1]["summary"]["L10h_h"] is None
