"""The default friction model by bearing kind, with seals, drag and the series' own constants (issue 40).

The SKF numbers are checked against a hand calculation of the SKF model written out here from the
catalogue's equations and tables (SKF 17000 EN "Friction": φ_ish, φ_rs, G_rr/G_sl of deep groove ball
bearings, μ_sl, the seal formula; constants typed from the tables), independent of bearingkit's code.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.catalogue import parse
from bearingkit.catalogue.seals import SEALS, seal_of_suffix
from bearingkit.catalogue.suffixes import COMMON
from bearingkit.cli import app
from bearingkit.errors import InputError
from bearingkit.lubricants import as_lubricant
from bearingkit.physics.friction import skf
from bearingkit.physics.friction.skf_drag import V_M_FULL, drag_loss_factor

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
RPM = np.pi / 30.0
runner = CliRunner()
#: The issue's case: a 6308-2RS C3 under Fr 5 kN + Fa 1 kN at 3000 r/min, ISO VG 68 at 70 °C.
ISSUE_CASE = [
    "6308-2RS C3",
    "--load",
    "Fr=5kN",
    "--load",
    "Fa=1kN",
    "--speed",
    "3000rpm",
    "--lubricant",
    "ISO_VG68",
    "--temperature",
    "70degC",
]


def _json(args):
    res = runner.invoke(app, args)
    assert res.exit_code == 0, res.stderr
    return json.loads(res.stdout)


def _skf_by_hand_6308_2rs1(nu):
    """SKF four-component model of a 6308-2RS1 written out in SKF units (N·mm, mm, r/min, mm²/s).

    Inputs: d 40, D 90 mm (ISO 15), C0 = 24 kN (the catalogue row), series 63 constants R1 = 3.7e-7,
    R2 = 1.7, S1 = 2.84e-3, S2 = 92.8 and K_Z = 3.1 (SKF tables); greased for life: K_rs = 6e-8;
    μ_bl = 0.15, μ_EHL = 0.05 (mineral base oil); two RS1 seals on D = 90 mm: β = 2.25, K_S1 = 0.018,
    K_S2 = 15, on d_s = d + 0.25 (D − d) = 52.5 mm (bearingkit's documented estimate of d1).
    """
    n, d, big_d, fr, fa, c0 = 3000.0, 40.0, 90.0, 5000.0, 1000.0, 24000.0
    dm = 0.5 * (d + big_d)
    sin_af = np.sin(np.radians(24.6 * (fa / c0) ** 0.24))
    g_rr = 3.7e-7 * dm**1.96 * (fr + 1.7 / sin_af * fa) ** 0.54
    g_sl = 2.84e-3 * dm**-0.145 * (fr**5 + 92.8 * dm**1.5 / sin_af * fa**4) ** (1 / 3)
    phi_ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = 1 / np.exp(6e-8 * nu * n * (d + big_d) * np.sqrt(3.1 / (2 * (big_d - d))))
    m_rr = phi_ish * phi_rs * g_rr * (nu * n) ** 0.6
    phi_bl = 1 / np.exp(2.6e-8 * (n * nu) ** 1.4 * dm)
    m_sl = g_sl * (phi_bl * 0.15 + (1 - phi_bl) * 0.05)
    m_seal = 0.018 * 52.5**2.25 + 15.0
    return {"rolling": m_rr * 1e-3, "sliding": m_sl * 1e-3, "seal": m_seal * 1e-3}


def test_issue_case_defaults_to_skf_with_seals_and_power():
    """Must-show: the 6308-2RS C3 case reports the SKF model by default, a seal term > 0, the power in W,
    within 10 % of --model skf; every term equals the hand calculation."""
    data = _json(["friction", *ISSUE_CASE, "--json"])
    assert data["friction_model"] == "skf" and "standard deep groove ball" in data["friction_model_why"]
    f = data["cases"][0]["friction"]
    assert f["components_Nm"]["seal"] > 0
    assert f["power_loss_W"] == pytest.approx(f["total_Nm"] * 3000 * RPM, rel=1e-12)
    asked = _json(["friction", *ISSUE_CASE, "--model", "skf", "--json"])["cases"][0]["friction"]
    assert abs(f["total_Nm"] / asked["total_Nm"] - 1) < 0.10
    hand = _skf_by_hand_6308_2rs1(as_lubricant("ISO_VG68").kinematic_viscosity(70.0) * 1e6)
    for name, value in hand.items():
        assert f["components_Nm"][name] == pytest.approx(value, rel=1e-9), name
    assert f["components_Nm"]["drag"] == 0.0  # no oil bath
    text = runner.invoke(app, ["friction", *ISSUE_CASE]).stdout
    assert "friction model: skf (standard deep groove ball bearing" in text and "P = 128 W" in text


def test_seed000_keeps_the_component_model():
    data = _json(["friction", str(EXAMPLES / "seed000_composite.toml"), "--json"])
    assert data["friction_model"] == "components" and "not a catalogue bearing" in data["friction_model_why"]
    assert data["cases"][0]["friction"]["model"] == "components"


@pytest.mark.parametrize(
    ("example", "model"),
    [
        ("slewing_four_point.toml", "slewing"),
        ("needle_na4910.toml", "palmgren"),
        ("acbb_7209_DB.toml", "skf"),
        ("srb_22220.toml", "skf"),
        ("thrust_ball_51209.toml", "skf"),
    ],
)
def test_default_model_by_kind_names_itself(example, model):
    a = bk.analyze(EXAMPLES / example, speed="500 rpm", lubricant="ISO_VG68", temperature="60 degC")
    assert a.friction.model == model and a.friction.why
    assert any(n.startswith(f"friction: the {model} model by default: ") for n in a.notes)


def test_a_6209_file_gets_the_constants_of_series_62():
    """examples/dgbb_6209.toml has no designation: its d and D find the catalogue row 6209 (series 62)."""
    a = bk.analyze(EXAMPLES / "dgbb_6209.toml", speed="3000 rpm", lubricant="ISO_VG68", temperature="60 degC")
    nu = as_lubricant("ISO_VG68").kinematic_viscosity(60.0)
    kw = dict(bore_diameter=0.045, outside_diameter=0.085, speed=3000 * RPM, kinematic_viscosity=nu)
    loads = np.hypot(*a.input.load_matrix()[:, :2].T)
    by_series = {
        s: skf.skf_friction_moment("deep_groove_ball", load_radial=loads, series=s, **kw)["total_Nm"]
        for s in ("60", "62")
    }
    np.testing.assert_allclose(a.friction.total, by_series["62"], rtol=1e-12)
    assert np.all(np.abs(by_series["60"] / by_series["62"] - 1) > 0.05)  # the series matters
    assert any("series 62 (catalogue row 6209" in n for n in a.notes)


def test_a_file_can_choose_its_series_seal_and_oil_bath(tmp_path):
    path = tmp_path / "b.toml"
    path.write_text(
        '[bearing]\ntype = "deep_groove_ball"\nseries = "63"\nseal = "2RSH"\n'
        'seal_counterface_diameter = "50 mm"\n'
        '[geometry]\nbore = "45 mm"\nouter_diameter = "85 mm"\nn_elements = 9\nelement_diameter = "12.7 mm"\n'
        'pitch_diameter = "65 mm"\nconformity_inner = 0.52\nconformity_outer = 0.52\n'
        '[lubrication]\nmethod = "oil_bath"\noil_level = "20 mm"\n'
        '[[load_cases]]\nname = "a"\nF_x = "4 kN"\n'
    )
    a = bk.analyze(path, speed="3000 rpm", lubricant="ISO_VG68", temperature="60 degC")
    nu = as_lubricant("ISO_VG68").kinematic_viscosity(60.0)
    expected = skf.skf_friction_moment(
        "deep_groove_ball",
        bore_diameter=0.045,
        outside_diameter=0.085,
        speed=3000 * RPM,
        kinematic_viscosity=nu,
        load_radial=4000.0,
        series="63",
        lubrication="oil_bath",
        seal="RSH",
        seal_counterface_diameter=0.050,
        oil_level=0.020,
        width=0.019,  # the 6209 row's B (same d and D)
    )
    assert a.friction.model == "skf"
    for name in ("rolling", "sliding", "seal", "drag"):
        assert a.friction.components[name][0] == pytest.approx(float(expected[f"{name}_Nm"]), rel=1e-12)
    assert a.friction.components["drag"][0] > 0 and a.friction.components["seal"][0] > 0


@pytest.mark.parametrize(
    ("field", "value", "names"),
    [("seal", "2RX", "2RS1, RSR"), ("series", "65", "60, 62, 63, 64, 160, 618, 619")],
)
def test_a_seal_or_series_that_does_not_exist_is_one_line_naming_the_valid_ones(
    tmp_path, field, value, names
):
    path = tmp_path / "bad.toml"
    path.write_text(
        f'[bearing]\ndesignation = "6208"\n{field} = "{value}"\n[[load_cases]]\nname = "a"\nF_x = "1 kN"\n'
    )
    res = runner.invoke(app, ["friction", str(path), "--speed", "1000rpm", "--lubricant", "ISO_VG68"])
    assert res.exit_code == 2 and res.stdout == ""
    line = res.stderr.strip()
    assert "\n" not in line and f"bearing.{field} ('{value}')" in line and names in line


def test_seal_suffixes_of_every_maker_map_to_an_skf_type():
    assert parse("6308-2RS C3").seal == "2RS"
    assert parse("6205 N").seal is None  # a snap ring closes nothing
    parsed = {code for code, c in COMMON.items() if c.field == "seal"}
    assert parsed == set(SEALS)  # every closure the grammar reads has its friction construction
    assert seal_of_suffix("LLU").skf_type == "RS1" and seal_of_suffix("2Z").skf_type is None
    assert seal_of_suffix("none") is None and seal_of_suffix("RS1").sides == 1
    assert all(s.sides == 2 for k, s in SEALS.items() if k.startswith("2") or k in ("ZZ", "LLU", "DDU", "VV"))
    with pytest.raises(InputError, match="did you mean"):
        seal_of_suffix("2RZZ")


def test_shields_add_no_seal_friction_and_say_so():
    a = bk.analyze("6208-2Z", load={"F_x": "3 kN"}, speed="3000 rpm", lubricant="ISO_VG68")
    assert a.friction.components["seal"][0] == 0.0
    assert any("2Z shields" in n and "no seal friction" in n for n in a.notes)


def test_vm_approximation_rises_from_zero_to_the_submerged_value():
    dm = 0.065
    levels = np.linspace(0.0, 1.5 * dm, 61)
    for roller in (False, True):
        vm = drag_loss_factor(levels, dm, roller)
        assert vm[0] == 0.0 and np.all(np.diff(vm) >= 0)
        full = V_M_FULL["roller" if roller else "ball"]
        assert vm[-1] == pytest.approx(full, rel=1e-12)  # capped at H = 1.2 d_m (SKF)
        # half the circle of radius 0.6 d_m under oil at H = 0.6 d_m: (π − 0)/2π = 1/2
        assert drag_loss_factor(0.6 * dm, dm, roller) == pytest.approx(0.5 * full, rel=1e-12)
