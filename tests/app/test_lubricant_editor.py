"""The app's lubricant editor and heat balance (issue 35): the page's fields go through the same model as a
file's [lubricant] and [thermal]; the answer shows the found temperature; errors sit next to their field."""

from __future__ import annotations

from pathlib import Path

import pytest
from fastapi.testclient import TestClient

import bearingkit as bk
from bearingkit.app import create_app
from bearingkit.app.store import Store

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
EXAMPLE = {"kind": "example", "name": "dgbb_6209.toml"}
STATIC = Path(__file__).resolve().parents[2] / "src" / "bearingkit" / "app" / "static"


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    store = Store(tmp_path_factory.mktemp("serve"))
    with TestClient(create_app(store, allowed_hosts=("testserver",))) as c:
        yield c
    store.close()


def _analyze(client, **fields):
    return client.post(
        "/api/analyze", json={"source": EXAMPLE, "loads": {"F_x": "6 kN"}, "speed": "3000 rpm", **fields}
    )


def test_the_editor_defines_an_oil_as_a_file_would(client):
    data = {"nu_40": "68 mm^2/s", "nu_100": "8.7 mm^2/s", "base_oil": "ester"}
    r = _analyze(client, temperature="70 degC", lubricant_data=data)
    assert r.status_code == 200, r.text
    case = r.json()["analysis"]["cases"][0]
    a = bk.analyze(
        str(EXAMPLES / "dgbb_6209.toml"),
        load={"F_x": "6 kN"},
        speed="3000 rpm",
        temperature="70 degC",
        lubricant=data,
    )
    ref = a.to_dict()["cases"][0]
    assert case["friction"]["total_Nm"] == ref["friction"]["total_Nm"]
    assert (
        case["lubrication"]["rows"][0]["film_minimum_inner_m"]
        == ref["lubrication"]["rows"][0]["film_minimum_inner_m"]
    )
    # the editor's fields replace the chosen preset's: VG 68 with a VI 150 is another oil than ISO_VG68
    r2 = _analyze(client, temperature="70 degC", lubricant="ISO_VG68", lubricant_data={"vi": "150"})
    assert r2.status_code == 200, r2.text
    assert (
        r2.json()["analysis"]["cases"][0]["lubrication"]["viscosity_m2_s"]
        > case["lubrication"]["viscosity_m2_s"]
    )


def test_the_heat_balance_switch_finds_the_temperature(client):
    r = _analyze(
        client, lubricant="ISO_VG68", heat=True, thermal={"heat_dissipation": "2 W/K", "ambient": "25 degC"}
    )
    assert r.status_code == 200, r.text
    case = r.json()["analysis"]["cases"][0]
    th = case["thermal"]
    assert th["found"] and th["ambient_C"] == 25.0 and th["heat_dissipation_W_K"] == 2.0
    assert (
        case["operating"]["temperature_C"] == th["temperature_C"] and case["operating"]["temperature_found"]
    )
    assert abs(th["balance_residual_W"]) <= 1e-6 * th["friction_heat_W"]


@pytest.mark.parametrize(
    ("fields", "field", "shown"),
    [
        (
            {"lubricant_data": {"nu_40": "68 mm^2/s", "nu_100": "80 mm^2/s"}},
            "lubricant",
            "must be below nu_40",
        ),
        (
            {"lubricant_data": {"base_oil": "vegetable"}, "lubricant": "ISO_VG68"},
            "lubricant",
            "base_oil ('vegetable')",
        ),
        (
            {"lubricant": "ISO_VG68", "heat": True, "temperature": "60 degC"},
            "temperature",
            "the heat balance finds",
        ),
        (
            {"lubricant": "ISO_VG68", "heat": True, "thermal": {"heat_dissipation": "-2 W/K"}},
            "thermal",
            "positive",
        ),
    ],
)
def test_bad_editor_values_are_one_line_next_to_their_field(client, fields, field, shown):
    r = _analyze(client, **fields)
    assert r.status_code == 400, r.text  # the app's answer to bad input (as every other form field)
    data = r.json()
    assert data["field"] == field and shown in data["error"] and "\n" not in data["error"]


def test_the_page_has_the_editor_and_the_heat_switch():
    html = (STATIC / "index.html").read_text(encoding="utf-8")
    js = (STATIC / "app.js").read_text(encoding="utf-8")
    for name in ("nu_40", "nu_100", "vi", "base_oil", "thickener", "nlgi"):
        assert f'data-lube="{name}"' in html
    assert 'id="heat"' in html and 'data-for="thermal"' in html
    assert "lubricant_data" in js and "renderThermal" in js
