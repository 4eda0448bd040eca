"""Thermal equilibrium (issue 35): the operating temperature found by the heat balance and fed to the
viscosity, κ, a_ISO, friction and the operating clearance; every face says so; the one-line refusals."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.cli import app
from bearingkit.errors import InputError
from bearingkit.lubricants import LUBRICANTS

runner = CliRunner()
MUST_SHOW = ["rating", "6208", "--load", "Fr=4kN", "--speed", "6000rpm", "--lubricant", "ISO_VG32", "--heat"]

# ISO 15312 reference housing of a 6208 (d 40, D 80, B 18 mm), written out: A_r = π B (D + d),
# q_r = 16 kW/m² (A_r ≤ 50,000 mm²), H = q_r A_r / (70 °C − 20 °C).
A_R = math.pi * 18e-3 * (80e-3 + 40e-3)
H_REF = 16e3 * A_R / 50.0
AMBIENT = 20.0


def _json(result) -> dict:
    assert result.exit_code == 0, result.output
    return json.loads(result.output)


def _power(temperature: float, **kw) -> float:
    """Friction power [W] of the must-show case at a GIVEN temperature (the plain pipeline, no balance)."""
    a = bk.analyze(
        "6208", load={"F_x": "4 kN"}, speed="6000 rpm", lubricant="ISO_VG32", temperature=temperature, **kw
    )
    return float(a.friction.power_loss[0])


@pytest.fixture(scope="module")
def must_show():
    return _json(runner.invoke(app, [*MUST_SHOW, "--json"]))


def test_the_must_show_command_reports_the_found_temperature(must_show):
    case = must_show["cases"][0]
    th = case["thermal"]
    assert th["found"] is True and th["method"].startswith("heat balance")
    assert th["heat_dissipation_W_K"] == pytest.approx(H_REF, rel=1e-9)
    assert th["ambient_C"] == AMBIENT
    # the balance closes to 1e-6 of the heat, with the terms it prints
    p, t = th["friction_heat_W"], th["temperature_C"]
    assert abs(p - th["conducted_heat_W"] - th["oil_heat_W"]) <= 1e-6 * p
    assert th["conducted_heat_W"] == pytest.approx(H_REF * (t - AMBIENT), rel=1e-12)
    assert th["oil_heat_W"] == 0.0
    assert case["friction"]["power_loss_W"] == pytest.approx(p, rel=1e-12)


def test_the_found_temperature_matches_a_hand_iteration(must_show):
    # An independent bisection on the heat balance P(T) = H (T − 20 °C), each P from the plain pipeline at a
    # given temperature.
    lo, hi = 20.0, 200.0
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if _power(mid) > H_REF * (mid - AMBIENT) else (lo, mid)
    t_hand = 0.5 * (lo + hi)
    th = must_show["cases"][0]["thermal"]
    assert th["temperature_C"] == pytest.approx(t_hand, abs=1e-3)
    assert 30.0 < t_hand < 120.0


def test_kappa_and_friction_are_those_at_the_found_temperature(must_show):
    case = must_show["cases"][0]
    t = case["thermal"]["temperature_C"]
    row = case["lubrication"]["rows"][0]
    # κ = ν(T)/ν1, ν1 = 4500 n^-0.5 D_pw^-0.5 mm²/s (ISO 281 eq. 27, n ≥ 1000 r/min), D_pw of the 6208 model
    d_pw = bk.analyze("6208", load={"F_x": "4 kN"}).input.model.rows[0].pitch_diameter
    nu1 = 4500.0 * 6000.0**-0.5 * (float(d_pw) * 1e3) ** -0.5 * 1e-6
    nu = float(LUBRICANTS["ISO_VG32"].kinematic_viscosity(t))
    assert row["reference_viscosity_m2_s"] == pytest.approx(nu1, rel=1e-9)
    assert row["kappa"] == pytest.approx(nu / nu1, rel=1e-9)
    assert case["lubrication"]["viscosity_m2_s"] == pytest.approx(nu, rel=1e-12)
    assert case["friction"]["power_loss_W"] == pytest.approx(_power(t), rel=1e-9)


def test_a_iso_at_the_found_temperature():
    data = _json(runner.invoke(app, [*MUST_SHOW, "--contamination", "normal_cleanliness", "--json"]))
    case = data["cases"][0]
    t = case["thermal"]["temperature_C"]
    given = bk.analyze(
        "6208",
        load={"F_x": "4 kN"},
        speed="6000 rpm",
        lubricant="ISO_VG32",
        temperature=t,
        contamination="normal_cleanliness",
    )
    a_iso = float(np.ma.getdata(given.rating.rows[0].life_modification)[0])
    assert case["lubrication"]["rows"][0]["a_ISO"] == pytest.approx(a_iso, rel=1e-6)
    assert case["lubrication"]["contamination_level"] == "normal_cleanliness"


def test_the_text_faces_say_the_temperature_was_found():
    out = runner.invoke(app, MUST_SHOW)
    assert out.exit_code == 0, out.output
    assert "temperature FOUND" in out.output and "friction at the found temperature" in out.output
    assert "κ" in out.output


def test_every_friction_model_of_the_registry_closes_the_balance():
    for model in ("skf", "palmgren"):
        a = bk.analyze(
            "6208",
            load={"F_x": "4 kN"},
            speed="6000 rpm",
            lubricant="ISO_VG32",
            thermal=True,
            friction_model=model,
        )
        th = a.thermal
        assert th.model == model and abs(th.residual[0]) <= 1e-6 * th.friction_heat[0]
        assert a.operating.temperature[0] == th.temperature[0]
        assert float(a.friction_by(model).power_loss[0]) == pytest.approx(th.friction_heat[0], rel=1e-12)


def test_oil_flow_and_housing_terms_by_hand(tmp_path):
    f = tmp_path / "oil.toml"
    f.write_text(
        '[bearing]\ndesignation = "6208"\n[lubricant]\nname = "ISO_VG32"\n'
        '[thermal]\nhousing_area = "0.05 m^2"\nheat_transfer_coefficient = "20 W/(m^2*K)"\n'
        'oil_flow = "0.3 l/min"\noil_inlet_temperature = "35 degC"\nambient = "25 degC"\n'
    )
    a = bk.analyze(str(f), load={"F_x": "4 kN"}, speed="6000 rpm")
    d = a.thermal.to_dict(0)
    t = d["temperature_C"]
    lub = LUBRICANTS["ISO_VG32"]
    assert d["heat_dissipation_W_K"] == pytest.approx(0.05 * 20.0)
    assert d["conducted_heat_W"] == pytest.approx(1.0 * (t - 25.0), rel=1e-12)
    flow = 0.3e-3 / 60.0
    assert d["oil_heat_W"] == pytest.approx(
        float(lub.density(t)) * lub.specific_heat * flow * (t - 35.0), rel=1e-12
    )
    assert abs(d["balance_residual_W"]) <= 1e-6 * d["friction_heat_W"]


def test_the_found_temperature_sets_the_operating_clearance(tmp_path):
    f = tmp_path / "fits.toml"
    f.write_text(
        '[bearing]\ndesignation = "6208"\n[lubricant]\nname = "ISO_VG32"\n'
        '[fits]\nshaft = "k5"\nhousing = "H7"\n'
        '[operating]\ntemperature_outer_ring = "30 degC"\n[thermal]\nheat_dissipation = "1.5 W/K"\n'
    )
    a = bk.analyze(str(f), load={"F_x": "4 kN"}, speed="6000 rpm")
    t = float(a.operating.temperature[0])
    plain = bk.analyze(str(f), load={"F_x": "4 kN"}, speed="6000 rpm", thermal=False, temperature=t)
    got, ref = a.clearance.to_dict(0), plain.clearance.to_dict(0)
    assert got["rows"][0]["operating_m"] == pytest.approx(ref["rows"][0]["operating_m"], rel=1e-12)
    cold = bk.analyze(str(f), load={"F_x": "4 kN"}, speed="6000 rpm", thermal=False, temperature=30.0)
    assert got["rows"][0]["operating_m"] != pytest.approx(cold.clearance.to_dict(0)["rows"][0]["operating_m"])
    assert any("re-solved at every temperature" in n for n in a.notes)


def test_no_equilibrium_is_one_line_with_the_last_temperature_and_the_remedy(tmp_path):
    f = tmp_path / "hot.toml"
    f.write_text(
        '[bearing]\ndesignation = "6208"\n[lubricant]\nname = "ISO_VG32"\n'
        '[thermal]\nheat_dissipation = "0.001 W/K"\n'
    )
    out = runner.invoke(app, ["rating", str(f), "--load", "Fr=4kN", "--speed", "6000rpm"])
    assert out.exit_code == 2
    line = out.output.strip()
    assert "\n" not in line and "no thermal equilibrium below 250 °C" in line
    assert "last temperature 250 °C" in line and "remedy: more [thermal] heat_dissipation" in line


@pytest.mark.parametrize(
    ("args", "shown"),
    [
        (["--temperature", "60degC"], "--temperature and --heat both set the operating temperature"),
        (["--lubricant", "VG32 estr"], "unknown word 'estr'"),
    ],
)
def test_bad_heat_inputs_are_one_line(args, shown):
    argv = ["rating", "6208", "--load", "Fr=4kN", "--speed", "6000rpm", "--heat", *args]
    out = runner.invoke(app, argv)
    assert out.exit_code == 2 and shown in out.output and out.output.count("\n") == 1


def test_no_speed_or_lubricant_is_refused_in_one_line():
    with pytest.raises(InputError, match="has no speed"):
        bk.analyze("6208", load={"F_x": "4 kN"}, lubricant="ISO_VG32", thermal=True)
    with pytest.raises(InputError, match="no lubricant"):
        bk.analyze("6208", load={"F_x": "4 kN"}, speed="6000 rpm", thermal=True)
    with pytest.raises(InputError, match="heat_transfer_coefficient: missing"):
        bk.analyze(
            "6208",
            load={"F_x": "4 kN"},
            speed="6000 rpm",
            lubricant="ISO_VG32",
            thermal={"housing_area": "0.05 m^2"},
        )


def test_report_and_json_show_the_balance(tmp_path):
    a = bk.analyze("6208", load={"F_x": "4 kN"}, speed="6000 rpm", lubricant="VG68 ester", thermal=True)
    data = a.to_dict()
    assert data["cases"][0]["thermal"]["found"] and data["cases"][0]["operating"]["temperature_found"]
    assert a.to_pandas()["temperature_found"].all()
    html = a.report(tmp_path / "r.html").read_text(encoding="utf-8")
    assert "Operating temperature FOUND by the heat balance" in html and "ester" in html
