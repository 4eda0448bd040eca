"""The web app's answer for a bearing in its structure (FastAPI TestClient): the case's ``flexible`` dict —
rigid against flexible element loads, the rings' deflection, moments and fibre stress around the
circumference, the change in Q_max, s0 and life — is the one of ``bearingkit analyze --json`` for the same
file, with the same warnings; and the page has the card and the script that show it (the browser test,
tests/app/test_structure_browser.py, checks what is drawn)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from fastapi.testclient import TestClient
from typer.testing import CliRunner

from bearingkit.app import create_app
from bearingkit.app.store import Store
from bearingkit.cli import app as cli

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    store = Store(tmp_path_factory.mktemp("serve"))
    with TestClient(create_app(store, allowed_hosts=("testserver",))) as c:
        yield c
    store.close()


def _cli_case(path: Path) -> dict:
    result = CliRunner().invoke(cli, ["analyze", str(path), "--json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)["cases"][0]


def _close(a, b) -> None:
    """Equal to round-off: the app solves the one case it shows, the CLI every case of the file in one
    batch, so sums of the ring's harmonics differ in their last bits (seen: ≤ 1e-13 of a curve's largest
    value). A list is compared against its own largest magnitude (a ring held in its plane has an axial
    deflection of round-off size, 1e-20 m, equal to 1e-15 of itself); text, counts and flags exactly."""
    if isinstance(b, dict):
        assert a.keys() == b.keys()
        for key in b:
            _close(a[key], b[key])
    elif isinstance(b, list) and b and all(isinstance(v, float) for v in b):
        x, y = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        assert x.shape == y.shape and np.abs(x - y).max() <= 1e-10 * np.abs(y).max()
    elif isinstance(b, list):
        assert len(a) == len(b)
        for u, v in zip(a, b, strict=True):
            _close(u, v)
    elif isinstance(b, float):
        assert a == pytest.approx(b, rel=1e-10)
    else:
        assert a == b


@pytest.mark.parametrize("name", ["slewing_four_point_flange.toml", "dgbb_6209_thin_housing.toml"])
def test_structure_results_equal_the_cli_json(client, name):
    r = client.post("/api/analyze", json={"source": {"kind": "example", "name": name}})
    assert r.status_code == 200, r.text
    page = r.json()["analysis"]["cases"][0]
    cli_case = _cli_case(EXAMPLES / name)
    flex = page["flexible"]
    # what the card reads, key by key
    _close(flex["rigid_vs_flexible"], cli_case["flexible"]["rigid_vs_flexible"])
    _close(flex["change"], cli_case["flexible"]["change"])
    _close(flex["structure"], cli_case["flexible"]["structure"])
    _close([row["loads_N"] for row in flex["rows"]], [row["loads_N"] for row in cli_case["flexible"]["rows"]])
    assert flex["coupling"]["iterations"] == cli_case["flexible"]["coupling"]["iterations"]
    assert flex["converged"] is cli_case["flexible"]["converged"] is True
    assert page["warnings"] == cli_case["warnings"]
    # the flexibility changes the answer (else the card would show nothing worth a card)
    for row in flex["rigid_vs_flexible"].values():
        assert row["max_load_flexible_N"] != pytest.approx(row["max_load_rigid_N"], rel=1e-3)
    # the rigid column is the rigid solve the page's summary shows
    rigid = {row["name"]: row["max_load_N"] for row in page["rows"]}
    assert {n: r["max_load_rigid_N"] for n, r in flex["rigid_vs_flexible"].items()} == rigid


def test_a_ring_nothing_holds_warns_on_the_page_as_in_the_cli(client, tmp_path):
    text = (EXAMPLES / "dgbb_6209_thin_housing.toml").read_text()
    free = "\n".join(
        line
        for line in text.splitlines()
        if not line.startswith(("seat_wall_thickness", "axial_support", "tangential_support"))
    )
    path = tmp_path / "free_ring.toml"
    path.write_text(free + "\n", encoding="utf-8")
    source = {"kind": "upload", "name": "free_ring.toml", "text": free + "\n"}
    r = client.post("/api/analyze", json={"source": source})
    assert r.status_code == 200, r.text
    page = r.json()["analysis"]["cases"][0]
    cli_case = _cli_case(path)
    held = [w for w in cli_case["warnings"] if "nothing given holds its rigid-body motion" in w]
    assert held and all(w in page["warnings"] for w in held)


def test_the_page_has_the_structure_card_and_its_script(client):
    html = client.get("/").text
    assert '<script src="/static/structure.js" defer></script>' in html
    for element in ("card", "rows", "change", "rings", "plots"):
        assert f'id="structure-{element}"' in html
    script = client.get("/static/structure.js")
    assert script.status_code == 200 and "function renderStructure" in script.text
    assert "renderStructure(c)" in client.get("/static/app.js").text


@pytest.mark.parametrize("matrix", ["/etc/passwd", "/no/such/file.mtx", "k.mtx"])
def test_an_upload_naming_an_fe_export_is_refused_before_any_path_is_looked_at(client, matrix):
    """A file sent to the server cannot make it read another: [structure.imported] in an upload is one
    line under the file's field, the same line whether the path exists, is readable or not (no oracle of
    the server's files); opening it is refused the same way."""
    text = (EXAMPLES / "dgbb_6209.toml").read_text()
    text += f'\n[structure.imported]\nmatrix = "{matrix}"\nnodes = "nodes.csv"\n'
    source = {"kind": "upload", "name": "fe.toml", "text": text}
    for route in ("/api/analyze", "/api/open"):
        r = client.post(route, json={"source": source})
        assert r.status_code == 400, r.text
        body = r.json()
        assert body["field"] == "source" and "\n" not in body["error"]
        assert body["error"] == (
            "fe.toml: structure.imported names files (its matrix and nodes), which the web app does not "
            "open: a file sent to the server cannot make it read another; analyse it with "
            "`bearingkit analyze FILE` (the files beside it)"
        )
