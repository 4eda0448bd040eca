"""The heat balance of each bearing of a shaft (issue 35): every bearing at the temperature where its own
friction heat equals the heat it dissipates, batched over bearings and cases; the same temperature the
single-bearing balance finds at the reaction the shaft gives it; every face shows it; the refusal."""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.cli import app
from bearingkit.errors import InputError
from bearingkit.pipeline.thermal.balance import with_thermal_equilibrium
from bearingkit.systems.shaft.input import load_shaft_file
from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis

runner = CliRunner()
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
H = 1.5  # [W/K] the [thermal] heat_dissipation of the test file (each bearing)
AMBIENT = 20.0  # [°C] the default ambient (ISO 15312 reference)


def _shaft_file(folder: Path, thermal: str = f'heat_dissipation = "{H} W/K"', name="shaft.toml") -> Path:
    """The countershaft example (6209 + NU 209 at 1000 r/min, ISO VG 100) with a [thermal] section."""
    for f in ("dgbb_6209.toml", "crb_nu209.toml"):
        shutil.copy(EXAMPLES / f, folder / f)
    text = (EXAMPLES / "shaft_countershaft.toml").read_text(encoding="utf-8")
    path = folder / name
    path.write_text(text + f"\n[thermal]\n{thermal}\n", encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def shaft_path(tmp_path_factory) -> Path:
    return _shaft_file(tmp_path_factory.mktemp("heat"))


@pytest.fixture(scope="module")
def cli_data(shaft_path) -> dict:
    res = runner.invoke(app, ["shaft", str(shaft_path), "--json"])
    assert res.exit_code == 0, res.output
    return json.loads(res.output)


@pytest.fixture(scope="module")
def analysis(shaft_path) -> ShaftAnalysis:
    return ShaftAnalysis(load_shaft_file(shaft_path))


def test_each_bearing_balances_its_own_heat(cli_data):
    assert cli_data["heat_balance"] is True
    temperatures = set()
    for case in cli_data["cases"]:
        for b in case["bearings"]:
            t, s = b["analysis"]["thermal"], b["summary"]
            p = t["friction_heat_W"]
            assert p > 0
            # the balance closes to 1e-6 of the heat with the terms it shows
            assert abs(p - t["conducted_heat_W"] - t["oil_heat_W"]) <= 1e-6 * p
            assert t["conducted_heat_W"] == pytest.approx(H * (t["temperature_C"] - AMBIENT), rel=1e-12)
            assert t["oil_heat_W"] == 0.0 and t["heat_dissipation_W_K"] == H
            # the bearing's results are those at its found temperature
            assert s["temperature_found"] is True
            assert s["temperature_C"] == t["temperature_C"]
            assert s["power_loss_W"] == pytest.approx(p, rel=1e-12)
            assert b["analysis"]["operating"]["temperature_C"] == pytest.approx(t["temperature_C"], rel=1e-12)
            temperatures.add(round(t["temperature_C"], 6))
    # every bearing and case its own temperature, none the load cases' 60/70 °C
    assert len(temperatures) == 2 * len(cli_data["cases"])
    assert not temperatures & {60.0, 70.0}


def test_a_bearing_finds_the_single_bearing_temperature_at_its_reaction(analysis):
    # Hand check: the 6209 alone (its own file) at the load the shaft puts on it, with the same sinks,
    # the same oil and speed. Its temperature by an independent bisection on P(T) = H (T - 20 °C), each
    # P(T) from the plain pipeline at a GIVEN temperature; then the single-bearing --heat path.
    a = analysis.bearings["A"]
    c = 0
    load = analysis.result.bearing_load("A")[c]
    given = {k: f"{float(v)!r} N" for k, v in zip(("F_x", "F_y", "F_z"), load[:3], strict=True)}
    file = str(EXAMPLES / "dgbb_6209.toml")
    kw = {"load": given, "speed": "1000 rpm", "lubricant": "ISO_VG100", "friction_model": a.friction_model}

    def power(temperature: float) -> float:
        return float(bk.analyze(file, temperature=temperature, **kw).friction.power_loss[0])

    lo, hi = AMBIENT, 120.0
    for _ in range(22):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if power(mid) > H * (mid - AMBIENT) else (lo, mid)
    t_hand = 0.5 * (lo + hi)
    t_shaft = float(a.thermal.temperature[c])
    assert t_shaft == pytest.approx(t_hand, abs=1e-4)
    single = bk.analyze(file, thermal={"heat_dissipation": H}, **kw)
    assert single.thermal.model == a.thermal.model
    assert t_shaft == pytest.approx(float(single.thermal.temperature[0]), rel=1e-9)
    assert float(a.friction.power_loss[c]) == pytest.approx(float(single.friction.power_loss[0]), rel=1e-5)
    # κ at the found temperature, as for the single bearing
    k_shaft = a.lubrication.to_dict(c)["rows"][0]["kappa"]
    k_single = single.lubrication.to_dict(0)["rows"][0]["kappa"]
    assert k_shaft == pytest.approx(k_single, rel=1e-5)


def test_the_roller_bearing_too_finds_its_single_bearing_temperature(analysis):
    # the NU 209 alone (its own file) at the shaft's load on it, every case, the same sinks
    b = analysis.bearings["B"]
    for c in range(analysis.n_cases):
        load = analysis.result.bearing_load("B")[c]
        given = {k: f"{float(v)!r} N" for k, v in zip(("F_x", "F_y", "F_z"), load[:3], strict=True)}
        single = bk.analyze(
            str(EXAMPLES / "crb_nu209.toml"),
            load=given,
            speed="1000 rpm",
            lubricant="ISO_VG100",
            friction_model=b.friction_model,
            thermal={"heat_dissipation": H},
        )
        assert single.thermal.model == b.thermal.model
        found = float(single.thermal.temperature[0])
        assert float(b.thermal.temperature[c]) == pytest.approx(found, rel=1e-9)


def test_the_batched_balance_is_each_bearing_alone(analysis, shaft_path):
    # all bearings and cases in one iteration give each bearing the temperature of its own balance
    plain = ShaftAnalysis(load_shaft_file(shaft_path), thermal=False)
    for name, a in analysis.bearings.items():
        alone = with_thermal_equilibrium(plain.bearings[name])
        assert plain.bearings[name].thermal is None
        np.testing.assert_allclose(a.thermal.temperature, alone.thermal.temperature, rtol=1e-12)
        np.testing.assert_array_equal(a.thermal.iterations, alone.thermal.iterations)


def test_a_bearing_file_s_own_thermal_replaces_the_shaft_s(tmp_path):
    path = _shaft_file(tmp_path)
    own = (tmp_path / "dgbb_6209.toml").read_text(encoding="utf-8")
    (tmp_path / "dgbb_6209.toml").write_text(own + '\n[thermal]\nheat_dissipation = "4 W/K"\n')
    got = ShaftAnalysis(load_shaft_file(path)).to_dict()["cases"][0]["bearings"]
    assert [b["analysis"]["thermal"]["heat_dissipation_W_K"] for b in got] == [4.0, H]


def test_heat_switches_the_balance_on_and_a_runaway_names_bearing_and_remedy(tmp_path):
    path = _shaft_file(tmp_path, thermal='heat_dissipation = "0.002 W/K"')
    res = runner.invoke(app, ["shaft", str(path)])
    assert res.exit_code != 0
    line = res.output.strip()
    assert "\n" not in line
    assert re.search(
        r"bearing '[AB]': case 'rated': no thermal equilibrium below 250 °C \(last temperature", line
    )
    assert "remedy: more [thermal] heat_dissipation" in line
    with pytest.raises(InputError, match=r"bearing .A.*last temperature"):
        ShaftAnalysis(load_shaft_file(path)).bearings  # noqa: B018
    # without [thermal], --heat switches it on: the NU 209 file has no width for the ISO 15312 housing
    plain = tmp_path / "plain.toml"
    plain.write_text((EXAMPLES / "shaft_countershaft.toml").read_text(encoding="utf-8"))
    res = runner.invoke(app, ["shaft", str(plain), "--heat"])
    assert res.exit_code != 0
    assert "bearing 'B': heat: the bearing width B is needed" in res.output
    assert "[thermal] heat_dissipation" in res.output
    # no speed: nothing to balance, one line naming the bearing and the case
    still = (tmp_path / "shaft.toml").read_text(encoding="utf-8").replace('speed = "1000 rpm"\n', "")
    (tmp_path / "still.toml").write_text(still, encoding="utf-8")
    res = runner.invoke(app, ["shaft", str(tmp_path / "still.toml")])
    assert res.exit_code != 0
    assert "bearing 'A': heat balance: load case 'rated' has no speed" in res.output
    assert "give each load case a speed" in res.output


def test_every_face_shows_the_found_temperatures(shaft_path, cli_data, tmp_path):
    found = [(b["name"], b["analysis"]["thermal"]["temperature_C"]) for b in cli_data["cases"][0]["bearings"]]
    text = runner.invoke(app, ["shaft", str(shaft_path)], env={"COLUMNS": "220"}).output
    assert "operating temperature FOUND by each bearing's heat balance" in text
    for name, t in found:
        assert re.search(rf"│ {name}\s+│\s+{t:.4g} │", text), (name, t)
    report = tmp_path / "r.html"
    res = runner.invoke(app, ["report", str(shaft_path), "-o", str(report)])
    assert res.exit_code == 0, res.output
    html = report.read_text(encoding="utf-8")
    assert "Operating temperatures FOUND by each bearing" in html
    for _, t in found:
        assert f"<td>{t:.4g}</td>" in html or f">{t:.4g}<" in html


def _app_post(body: dict) -> dict:
    import tempfile

    from fastapi.testclient import TestClient

    from bearingkit.app import create_app
    from bearingkit.app.store import Store

    with tempfile.TemporaryDirectory() as folder:
        store = Store(Path(folder))
        with TestClient(create_app(store, allowed_hosts=("testserver",))) as client:
            r = client.post("/api/system/analyze", json=body)
        store.close()
    assert r.status_code == 200, r.text
    return r.json()["analysis"]


def _same_temperatures(cases: list, ref_cases: list) -> None:
    for case, ref in zip(cases, ref_cases, strict=True):
        for b, rb in zip(case["bearings"], ref["bearings"], strict=True):
            assert b["analysis"]["thermal"]["temperature_C"] == rb["analysis"]["thermal"]["temperature_C"]
            assert b["summary"]["temperature_C"] == rb["summary"]["temperature_C"]
            assert b["summary"]["temperature_found"] is True


def test_the_app_shows_the_cli_temperatures(cli_data):
    text = (EXAMPLES / "shaft_countershaft.toml").read_text(encoding="utf-8")
    text += f'\n[thermal]\nheat_dissipation = "{H} W/K"\n'
    got = _app_post({"system": "shaft", "source": {"kind": "upload", "name": "shaft.toml", "text": text}})
    _same_temperatures(got["cases"], cli_data["cases"])


def test_a_drivetrain_balances_every_bearing_on_every_face(tmp_path):
    # the two-stage gearbox (bearings by designation: each its ISO 15312 reference housing), --heat
    res = runner.invoke(app, ["system", str(EXAMPLES / "gearbox_two_stage.toml"), "--heat", "--json"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.output)
    assert data["heat_balance"] is True
    for case in data["cases"]:
        for b in case["bearings"]:
            t = b["analysis"]["thermal"]
            p = t["friction_heat_W"]
            assert abs(p - t["conducted_heat_W"] - t["oil_heat_W"]) <= 1e-6 * p
            assert t["heat_dissipation_from"].startswith("ISO 15312 reference housing")
            assert b["summary"]["power_loss_W"] == pytest.approx(p, rel=1e-12)
    example = {"kind": "example", "name": "gearbox_two_stage.toml"}
    got = _app_post({"system": "drivetrain", "source": example, "friction_model": "components", "heat": True})
    _same_temperatures(got["cases"], data["cases"])
