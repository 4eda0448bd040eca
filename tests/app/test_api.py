"""The web app's HTTP API (FastAPI TestClient): results equal the pipeline's, bad input is one line next to
its field, size limits hold, downloads cannot leave the server's temporary folder."""

from __future__ import annotations

import json
import re
import socket
import tomllib
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

import bearingkit as bk
from bearingkit.app import api as app_api
from bearingkit.app import create_app, server
from bearingkit.app.api import MAX_REQUEST_BYTES
from bearingkit.app.form import MAX_TOML_BYTES
from bearingkit.app.store import Store
from bearingkit.errors import InputError
from bearingkit.io import loader

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
STATIC = Path(__file__).resolve().parents[2] / "src" / "bearingkit" / "app" / "static"
EXAMPLE = {"kind": "example", "name": "dgbb_6209.toml"}
JSON = {"content-type": "application/json"}


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    s = Store(tmp_path_factory.mktemp("serve"))
    yield s
    s.close()


@pytest.fixture(scope="module")
def client(store):
    with TestClient(create_app(store, allowed_hosts=("testserver",))) as c:
        yield c


def analyze(client, **fields):
    body = {"source": EXAMPLE, **fields}
    return client.post("/api/analyze", json=body)


def open_(client, source):
    return client.post("/api/open", json={"source": source})


def error_of(response, status: int) -> dict:
    assert response.status_code == status, response.text
    data = response.json()
    assert set(data) == {"error", "field"}
    assert "\n" not in data["error"] and "Traceback" not in data["error"]
    return data


# ------------------------------------------------------------------------------------------ results
def test_analysis_equals_the_pipeline_for_the_same_input(client):
    r = analyze(
        client,
        loads={"F_x": "6 kN"},
        speed="3000 rpm",
        temperature="70 degC",
        lubricant="ISO_VG68",
        contamination="0.5",
    )
    assert r.status_code == 200, r.text
    case = r.json()["analysis"]["cases"][0]
    a = bk.analyze(
        str(EXAMPLES / "dgbb_6209.toml"),
        load={"F_x": "6 kN"},
        speed="3000 rpm",
        temperature="70 degC",
        lubricant="ISO_VG68",
        contamination=0.5,
    )
    ref = a.to_dict()["cases"][0]
    # the same input through the same pipeline: equal to the last bit
    assert case["rows"][0]["max_load_N"] == ref["rows"][0]["max_load_N"]
    assert case["rating"]["system"]["L10r_rev"] == ref["rating"]["system"]["L10r_rev"]
    assert case["rating"]["system"]["Lnmr_h"] == ref["rating"]["system"]["Lnmr_h"]
    assert case["friction"]["total_Nm"] == ref["friction"]["total_Nm"]
    assert case["stiffness_SI"] == ref["stiffness_SI"]
    assert case["operating"]["temperature_C"] == 70.0


def test_open_example_fills_the_form_from_the_file(client):
    r = client.post("/api/open", json={"source": EXAMPLE})
    assert r.status_code == 200, r.text
    o = r.json()
    raw = tomllib.loads((EXAMPLES / "dgbb_6209.toml").read_text())
    assert [c["name"] for c in o["cases"]] == [c["name"] for c in raw["load_cases"]]
    assert o["cases"][0]["F_x"] == raw["load_cases"][0]["F_x"]
    assert o["clearances"] == {"clearance_radial": raw["geometry"]["clearance_radial"]}
    assert o["free_dofs"] == raw["solver"]["free"]


def test_designation_opens_with_its_estimated_clearance(client):
    r = client.post("/api/open", json={"source": {"kind": "designation", "name": "6205-2RS C3"}})
    assert r.status_code == 200, r.text
    o = r.json()
    assert o["bearing_type"] == "deep_groove_ball" and o["cases"] == []
    ref = bk.load_input("6205-2RS C3")
    shown = float(o["clearances"]["clearance_radial"].removesuffix(" um"))
    assert shown == pytest.approx(ref.geometry.clearance_radial * 1e6, rel=1e-5)  # 6 significant digits
    r = client.post(
        "/api/analyze",
        json={"source": {"kind": "designation", "name": "6205-2RS C3"}, "loads": {"F_x": "2 kN"}},
    )
    assert r.status_code == 200, r.text
    ref_max = bk.analyze("6205-2RS C3", load={"F_x": "2 kN"}).statics.rows[0].max_load[0]
    assert r.json()["analysis"]["cases"][0]["rows"][0]["max_load_N"] == float(ref_max)


def test_clearance_override_changes_the_bearing(client):
    base = analyze(client, loads={"F_x": "6 kN"}).json()["analysis"]["cases"][0]
    tight = analyze(client, loads={"F_x": "6 kN"}, geometry={"clearance_radial": "0 um"}).json()
    case = tight["analysis"]["cases"][0]
    # less clearance spreads the load over more balls: a lower peak (Harris & Kotzalas 2007, ch. 7)
    assert case["rows"][0]["max_load_N"] < base["rows"][0]["max_load_N"]
    text = client.get(tight["downloads"]["toml"]).text
    assert tomllib.loads(text)["geometry"]["clearance_radial"] == "0 um"


# ------------------------------------------------------------------------------------------ errors
@pytest.mark.parametrize(
    ("fields", "field", "start"),
    [
        ({"loads": {"F_x": "6 kg"}}, "load.F_x", "dgbb_6209.toml: load_cases[0].F_x ('6 kg')"),
        ({"loads": {"M_x": "5 N*m"}}, "load.M_x", "dgbb_6209.toml: load case 'radial_8.9kN (edited)': M_x"),
        ({"speed": "fast"}, "speed", "dgbb_6209.toml: load_cases[0].speed ('fast')"),
        ({"temperature": "70 kN"}, "temperature", "dgbb_6209.toml: load_cases[0].temperature ('70 kN')"),
        (
            {"geometry": {"clearance_radial": "15 kg"}},
            "geometry.clearance_radial",
            "dgbb_6209.toml: geometry.clearance_radial ('15 kg')",
        ),
        ({"lubricant": "honey"}, "lubricant", "dgbb_6209.toml: lubricant.name ('honey')"),
        ({"contamination": "2"}, "contamination", "contamination (2"),
        ({"geometry": {"bore": "1 m"}}, "source", "dgbb_6209.toml: geometry.bore: the page edits only"),
    ],
)
def test_bad_input_is_one_line_next_to_its_field(client, fields, field, start):
    data = error_of(analyze(client, **fields), 400)
    assert data["field"] == field
    assert data["error"].startswith(start), data["error"]


def test_broken_upload_gives_the_loaders_message(client):
    text = "[bearing\ntype = 'deep_groove_ball'\n"
    data = error_of(
        client.post("/api/open", json={"source": {"kind": "upload", "name": "broken.toml", "text": text}}),
        400,
    )
    with pytest.raises(InputError) as exc:
        loader.loads(text, "broken.toml")
    assert data["error"] == " ".join(str(exc.value).split())
    assert data["error"].startswith("broken.toml: not valid TOML")


def test_upload_is_validated_by_the_schema(client):
    text = (EXAMPLES / "dgbb_6209.toml").read_text()
    text = text.replace("conformity_inner = 0.52", "conformity_innr = 0.52")
    data = error_of(
        client.post("/api/open", json={"source": {"kind": "upload", "name": "../../x.toml", "text": text}}),
        400,
    )
    # the file's base name only, and the loader's message ("unknown field; did you mean …")
    assert data["error"] == (
        "x.toml: geometry.conformity_innr (0.52): unknown field; did you mean 'conformity_inner'?"
    )


def test_unknown_example_and_bad_designation(client):
    data = error_of(open_(client, {"kind": "example", "name": "../pyproject.toml"}), 400)
    assert data["error"].startswith("example ('../pyproject.toml') is not one of acbb_7209.toml")
    data = error_of(open_(client, {"kind": "designation", "name": "XYZ123"}), 400)
    assert "XYZ123" in data["error"]


def test_malformed_request_is_422_with_one_line(client):
    data = error_of(client.post("/api/analyze", json={"source": {"kind": "file", "name": "a"}}), 422)
    assert data["error"].startswith("source.kind:")
    data = error_of(client.post("/api/analyze", content=b"{not json", headers=JSON), 422)


def test_internal_error_is_one_line_without_traceback(store, monkeypatch):
    def boom(_request):
        raise RuntimeError("secret detail\n  File x.py, line 1")

    monkeypatch.setattr(app_api, "build_document", boom)
    with TestClient(create_app(store, allowed_hosts=("testserver",)), raise_server_exceptions=False) as c:
        data = error_of(analyze(c, loads={"F_x": "1 kN"}, speed="1 rpm"), 500)
    assert data["error"] == "internal error (RuntimeError); the server's log has the details"


def test_foreign_host_header_is_refused(client):
    # DNS rebinding: a page on another site resolving its name to 127.0.0.1 must not reach the API
    assert client.get("/api/meta", headers={"host": "evil.example"}).status_code == 400


# ------------------------------------------------------------------------------------------ limits
def test_file_above_the_cap_is_413(client):
    text = "# " + "x" * MAX_TOML_BYTES + "\n"
    data = error_of(
        client.post("/api/open", json={"source": {"kind": "upload", "name": "big.toml", "text": text}}), 413
    )
    assert data["error"].startswith("big.toml: file too large")


def test_request_body_above_the_cap_is_413(client):
    body = b'{"source": {"kind": "upload", "name": "a.toml", "text": "' + b"x" * MAX_REQUEST_BYTES + b'"}}'
    data = error_of(client.post("/api/open", content=body, headers=JSON), 413)
    assert data["error"].startswith("request too large")

    def chunks():  # no Content-Length: counted while it streams
        yield b'{"source": {"kind": "upload", "name": "a.toml", "text": "'
        for _ in range(MAX_REQUEST_BYTES // 65536 + 2):
            yield b"x" * 65536
        yield b'"}}'

    data = error_of(client.post("/api/open", content=chunks(), headers=JSON), 413)
    assert data["error"].startswith("request too large")


def test_sweep_size_is_capped(client):
    body = {"base": {"source": EXAMPLE}, "factor": "F_x", "start": "1 kN", "stop": "2 kN", "n": 51}
    assert error_of(client.post("/api/sweep", json=body), 422)["error"].startswith("n:")


# ------------------------------------------------------------------------------------------ downloads
def test_downloads_are_what_is_on_screen(client, store):
    r = analyze(client, loads={"F_x": "6 kN"}, speed="3000 rpm", lubricant="ISO_VG68").json()
    shown = r["analysis"]["cases"][0]
    toml = client.get(r["downloads"]["toml"])
    assert toml.status_code == 200
    assert toml.headers["content-disposition"] == 'attachment; filename="dgbb_6209.toml"'
    again = bk.analyze(loader.loads(toml.text, "again.toml")).to_dict()["cases"][0]
    assert again["rows"][0]["max_load_N"] == shown["rows"][0]["max_load_N"]
    assert again["friction"]["total_Nm"] == shown["friction"]["total_Nm"]
    js = client.get(r["downloads"]["json"])
    assert json.loads(js.text)["cases"][0]["rows"][0]["max_load_N"] == shown["rows"][0]["max_load_N"]
    html = client.get(r["downloads"]["html"])
    assert html.status_code == 200 and "<h1>" in html.text and "6209" in html.text
    # written in the server's folder only, under names the server made
    files = {p.name for p in store.root.iterdir()}
    assert {f"{r['id']}.{e}" for e in ("toml", "json", "html")} <= files
    assert all(len(n.split(".")[0]) == 16 for n in files)


@pytest.mark.parametrize(
    "name",
    [
        "..%2F..%2Fetc%2Fpasswd",
        "%2Fetc%2Fpasswd",
        "..%2Fbearingkit-serve.toml",
        "0123456789abcdef.html",  # well formed, never made
        "0123456789abcdef.toml%00.html",
        "0123456789ABCDEF.toml",
    ],
)
def test_no_path_traversal_in_download_names(client, name):
    # a "/" in the name never reaches the route (the router's 404); anything else is refused by name
    data = error_of(client.get(f"/api/download/{name}"), 404)
    assert data["error"].startswith("no download") or data["error"] == "Not Found"


def test_kept_id_with_another_extension_is_404(client):
    key = analyze(client, loads={"F_x": "1 kN"}).json()["id"]
    for ext in ("py", "toml.py", "html/../../x"):
        assert client.get(f"/api/download/{key}.{ext}").status_code == 404


# ------------------------------------------------------------------------------------------ sweep
def test_load_sweep_is_one_batched_analysis_equal_to_single_analyses(client):
    body = {
        "base": {"source": EXAMPLE, "speed": "3000 rpm", "lubricant": "ISO_VG68"},
        "factor": "F_x",
        "start": "2 kN",
        "stop": "8 kN",
        "n": 4,
    }
    r = client.post("/api/sweep", json=body)
    assert r.status_code == 200, r.text
    out = r.json()
    assert out["analyses"] == 1 and out["values"] == [2000.0, 4000.0, 6000.0, 8000.0]
    single = analyze(client, loads={"F_x": "6 kN"}, speed="3000 rpm", lubricant="ISO_VG68").json()
    case = single["analysis"]["cases"][0]
    assert out["outputs"][2]["max_load_N"] == pytest.approx(case["rows"][0]["max_load_N"], rel=1e-12)
    assert out["outputs"][2]["friction_torque_Nm"] == pytest.approx(case["friction"]["total_Nm"], rel=1e-12)
    loads = [o["max_load_N"] for o in out["outputs"]]
    assert loads == sorted(loads)  # monotone in the radial load


def test_clearance_sweep_is_one_analysis_per_value(client):
    body = {
        "base": {"source": EXAMPLE, "loads": {"F_x": "6 kN"}},
        "factor": "geometry.clearance_radial",
        "start": "0 um",
        "stop": "30 um",
        "n": 3,
    }
    out = client.post("/api/sweep", json=body).json()
    assert out["analyses"] == 3
    base = analyze(client, loads={"F_x": "6 kN"}).json()["analysis"]["cases"][0]
    assert out["outputs"][1]["max_load_N"] == pytest.approx(base["rows"][0]["max_load_N"], rel=1e-12)


def test_sweep_factor_and_values_are_checked(client):
    body = {"base": {"source": EXAMPLE}, "factor": "geometry.bore", "start": "1 mm", "stop": "2 mm", "n": 3}
    message = error_of(client.post("/api/sweep", json=body), 400)["error"]
    assert message.startswith("sweep factor ('geometry.bore')")
    body = {"base": {"source": EXAMPLE}, "factor": "speed", "start": "1 kN", "stop": "2 kN", "n": 3}
    message = error_of(client.post("/api/sweep", json=body), 400)["error"]
    assert message.startswith("sweep speed from ('1 kN')")


# ------------------------------------------------------------------------------------------ page
def test_page_and_assets_are_local_only(client):
    r = client.get("/")
    assert r.status_code == 200 and "app.js" in r.text
    assert "default-src 'self'" in r.headers["content-security-policy"]
    for path in STATIC.iterdir():
        text = path.read_text(encoding="utf-8")
        urls = re.findall(r"(?:https?:)?//[A-Za-z0-9-]+(?:\.[A-Za-z0-9-]+)+", text)  # hosts, not // comments
        assert set(urls) <= {"http://www.w3.org"}, (path.name, urls)  # the SVG namespace only
        assert client.get(f"/static/{path.name}").status_code == 200


# ------------------------------------------------------------------------------------------ server
def test_loopback_detection():
    assert server.is_loopback("127.0.0.1") and server.is_loopback("::1") and server.is_loopback("localhost")
    assert not server.is_loopback("0.0.0.0") and not server.is_loopback("192.168.1.10")


def test_port_in_use_is_one_line():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        port = s.getsockname()[1]
        with pytest.raises(InputError, match=rf"^--port \({port}\) cannot be used on 127.0.0.1"):
            server.serve("127.0.0.1", port)


def test_exposed_host_warns(monkeypatch, capsys):
    import uvicorn

    seen = {}
    monkeypatch.setattr(uvicorn.Server, "run", lambda self: seen.setdefault("host", self.config.host))
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    server.serve("0.0.0.0", port, echo=lambda *_: None)
    assert seen["host"] == "0.0.0.0"
    warning = f"warning: serving on 0.0.0.0: anyone who can reach this machine on port {port}"
    assert capsys.readouterr().err.startswith(warning)


def test_cli_serve_on_a_busy_port_is_one_line_and_exit_2():
    from typer.testing import CliRunner

    from bearingkit.cli import app as cli_app

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        port = s.getsockname()[1]
        result = CliRunner().invoke(cli_app, ["serve", "--port", str(port)])
    assert result.exit_code == 2
    assert result.stderr.startswith(f"error: --port ({port}) cannot be used on 127.0.0.1")
    assert result.stderr.count("\n") == 1


def test_downloads_live_in_one_temporary_folder_removed_at_shutdown(tmp_path, monkeypatch):
    import tempfile

    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))  # where the server's own folder goes
    with TestClient(create_app(allowed_hosts=("testserver",))) as c:
        r = analyze(c, loads={"F_x": "3 kN"}).json()
        assert c.get(r["downloads"]["html"]).status_code == 200
        (folder,) = tmp_path.iterdir()
        assert folder.name.startswith("bearingkit-serve-")
        assert sorted(p.name for p in folder.iterdir()) == [f"{r['id']}.html"]
    assert list(tmp_path.iterdir()) == []


def test_examples_are_the_bearing_files_and_each_one_analyses(client):
    names = client.get("/api/meta").json()["examples"]
    bearing_files = sorted(
        p.name for p in EXAMPLES.glob("*.toml") if "bearing" in tomllib.loads(p.read_text("utf-8"))
    )
    assert names == bearing_files and "dgbb_6209.toml" in names
    for name in names:
        if name.startswith("ball_column"):  # the coupled flexible ring takes seconds: one is enough
            continue
        r = client.post("/api/analyze", json={"source": {"kind": "example", "name": name}})
        assert r.status_code == 200, (name, r.text)
        assert r.json()["analysis"]["cases"][0]["converged"], name


def test_form_values_are_short_text(client):
    data = error_of(analyze(client, loads={"F_x": "1" * 65 + " N"}), 422)
    assert data["error"].startswith("loads.F_x:")
    assert error_of(analyze(client, speed="1" * 65), 422)["error"].startswith("speed:")


def test_the_pressure_map_is_an_svg_of_the_roller_rows(client):
    """``pressure_map`` true for a roller bearing, its figure an SVG image (false and a 404 for balls)."""
    import xml.etree.ElementTree as ET

    r = client.post("/api/analyze", json={"source": {"kind": "example", "name": "crb_nu209.toml"}})
    assert r.status_code == 200, r.text
    data = r.json()
    assert data["pressure_map"] is True
    fig = client.get(f"/api/figure/{data['id']}/pressure.svg")
    assert fig.status_code == 200 and fig.headers["content-type"].startswith("image/svg+xml")
    root = ET.fromstring(fig.text)
    assert root.tag.endswith("svg") and "script" not in fig.text
    balls = analyze(client).json()
    assert balls["pressure_map"] is False
    assert client.get(f"/api/figure/{balls['id']}/pressure.svg").status_code == 404
