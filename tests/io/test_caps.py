"""How many load cases a file and each command accept (issue 23): documented caps, one-line refusals
above them, before any solve and before anything is written."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from bearingkit.errors import MAX_MESSAGE_CHARS, InputError
from bearingkit.io import loader, schema
from bearingkit.io.loader import from_dict, load_file, parse_load_options

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _data(name: str, n_cases: int) -> dict:
    data = tomllib.loads((EXAMPLES / name).read_text(encoding="utf-8"))
    data["load_cases"] = [{"name": f"c{i}", "F_x": f"{1 + i % 7} kN"} for i in range(n_cases)]
    return data


def _refused(data: dict, source: str = "caps.toml") -> str:
    with pytest.raises(InputError) as err:
        from_dict(data, source)
    msg = str(err.value)
    assert msg.startswith(f"{source}: load_cases (") and len(msg) <= MAX_MESSAGE_CHARS, msg
    return msg


def test_load_cases_per_file(monkeypatch):
    """1,000 cases load; 1,001 are refused before the cases are validated (100,000 cases must not
    be parsed first: the count is checked on the raw list)."""
    assert len(from_dict(_data("dgbb_6209.toml", schema.MAX_LOAD_CASES), "caps.toml").cases) == 1000
    assert "(1001 cases) must be at most 1000 per file" in _refused(_data("dgbb_6209.toml", 1001))
    data = _data("dgbb_6209.toml", 2)
    data["load_cases"] = [{"name": "x", "F_x": "nonsense"}] * 100_000
    assert "(100000 cases) must be at most 1000" in _refused(data)


def test_flexible_ring_cases():
    """A flexible ring keeps a Newton Jacobian per case: at most MAX_FLEXIBLE_LOAD_CASES (100)."""
    name = "ball_column_condition1.toml"
    assert len(from_dict(_data(name, loader.MAX_FLEXIBLE_LOAD_CASES), "caps.toml").cases) == 100
    msg = _refused(_data(name, loader.MAX_FLEXIBLE_LOAD_CASES + 1))
    assert "(101 cases) must be at most 100 with a flexible ring" in msg
    rigid = _data(name, 101)
    rigid["geometry"]["ring"]["flexible"] = False
    assert len(from_dict(rigid, "caps.toml").cases) == 101
    default = _data(name, 101)  # no [geometry.ring]: the ball-column bearing is flexible by default
    del default["geometry"]["ring"]
    assert "with a flexible ring" in _refused(default)


def test_contact_points_per_run(monkeypatch):
    """cases × Σ elements × slices is bounded: the solver's per-slice arrays stay bounded."""
    data = _data("crb_nu209.toml", 3)
    bearing = from_dict(data, "caps.toml")
    points = sum(r.n_elements * r.n_slices for r in bearing.model.rows)
    monkeypatch.setattr(loader, "MAX_CASE_POINTS", 3 * points - 1)
    assert f"(3 cases × {points} contact points) must stay within" in _refused(data)
    monkeypatch.setattr(loader, "MAX_CASE_POINTS", 3 * points)
    assert len(from_dict(data, "caps.toml").cases) == 3


def test_with_cases_is_checked_too():
    bearing = load_file(EXAMPLES / "ball_column_condition1.toml")
    case = parse_load_options(["Fr=1kN"])
    with pytest.raises(InputError, match="must be at most 100 with a flexible ring"):
        bearing.with_cases([case] * 101)


def test_report_refuses_many_cases_before_writing(tmp_path):
    from bearingkit.report import report_file

    source = tmp_path / "many.toml"
    text = (EXAMPLES / "dgbb_6209.toml").read_text(encoding="utf-8").split("[[load_cases]]")[0]
    cases = "".join(f'[[load_cases]]\nname = "c{i}"\nF_x = "1 kN"\n\n' for i in range(21))
    source.write_text(text + cases, encoding="utf-8")
    out = tmp_path / "report.html"
    with pytest.raises(InputError) as err:
        report_file(source, out)
    assert str(err.value) == (
        f"{source}: load_cases (21 cases) must be at most 20 for a report; select some with --case or "
        "split the file"
    )
    assert not out.exists()


def test_shaft_file_cases():
    """The shaft solver takes ~0.1-0.2 s per case: at most MAX_SHAFT_CASES per file, counted first."""
    from bearingkit.systems.shaft.input import MAX_SHAFT_CASES, shaft_from_dict

    data = tomllib.loads((EXAMPLES / "shaft_countershaft.toml").read_text(encoding="utf-8"))
    data["load_cases"] = [{**data["load_cases"][0], "name": f"c{i}"} for i in range(MAX_SHAFT_CASES + 1)]
    with pytest.raises(InputError) as err:
        shaft_from_dict(data, "shaft.toml", base=EXAMPLES)
    assert (
        str(err.value)
        == "shaft.toml: load_cases (101 cases) must be at most 100 per shaft file; split the file"
    )
