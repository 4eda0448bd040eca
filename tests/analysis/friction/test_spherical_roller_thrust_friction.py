"""SKF friction of spherical roller thrust bearings (292, 293, 294): the model by hand, the CLI, --compare.

Forms and constants: SKF General Catalogue 6000 (Russian edition 2006, pp. 92-95, Table 2b and Table 3g,
stored as text in the search index), the same 45 constants in a public Python SKF friction calculator's
registry. 294 E row: R1 1.25e-6, R2 1.67, R3 2.15e-6, R4 2.86, S1 6.42e-3, S2 0.21, S3 0.04, S4 0.2,
S5 0.54; K_Z 5.6 (Table 5).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.lubricants import as_lubricant
from bearingkit.physics.friction import skf

runner = CliRunner()
RPM = 2.0 * np.pi / 60.0


def _by_hand(n, nu, fa, fr=0.0):
    """M [N·m] of a 29412 E (d 60, D 130, d_m 95 mm) in SKF units, oil bath (K_rs 3e-8), mineral oil
    (μ_EHL 0.05), μ_bl 0.15, written out from SKF Table 2b with the 294 E constants of Table 3g."""
    d, big_d, dm = 60.0, 130.0, 95.0
    g_rr = min(1.25e-6 * dm**1.96 * (fr + 1.67 * fa) ** 0.54, 2.15e-6 * dm**2.39 * (fr + 2.86 * fa) ** 0.31)
    g_sr = min(6.42e-3 * dm**-0.35 * (fr ** (5 / 3) + 0.21 * fa ** (5 / 3)), 0.04 * dm**0.89 * (fr + fa))
    g_f = 0.2 * dm**0.76 * (fr + 0.54 * fa)
    x = 1e-6 * (n * nu) ** 1.4 * dm
    g_sl = g_sr + (g_f * math.exp(-x) if x < 700 else 0.0)
    phi_ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = math.exp(-3e-8 * nu * n * (d + big_d) * math.sqrt(5.6 / (2 * (big_d - d))))
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = phi_bl * 0.15 + (1 - phi_bl) * 0.05
    return (phi_ish * phi_rs * g_rr * (nu * n) ** 0.6 + g_sl * mu_sl) * 1e-3


@pytest.mark.parametrize(
    ("n", "fa", "fr", "total"),
    [
        (1000.0, 50e3, 0.0, 4.4532),  # full film: the flange term exp(-950) is gone
        (10.0, 50e3, 0.0, 8.5628),  # 10 r/min: the flange term G_f e^-1.51 dominates the sliding part
        (10.0, 50e3, 20e3, 15.532),  # F_r enters every law (F_r <= 0.55 F_a)
    ],
)
def test_skf_moment_of_a_29412_equals_the_hand_calculation(n, fa, fr, total):
    got = skf.skf_friction_moment(
        "spherical_roller_thrust",
        series="294E",
        bore_diameter=0.060,
        outside_diameter=0.130,
        speed=n * RPM,
        kinematic_viscosity=100e-6,
        load_axial=fa,
        load_radial=fr,
    )
    assert float(got["total_Nm"]) == pytest.approx(_by_hand(n, 100.0, fa, fr), rel=1e-9)
    assert float(got["total_Nm"]) == pytest.approx(total, rel=1e-4)


def _cli(*args):
    res = runner.invoke(
        app, ["friction", *args, "--load", "Fa=50kN", "--speed", "1000rpm", "--lubricant", "ISO_VG100"]
    )
    return res


def test_friction_of_29412_is_the_skf_model_with_the_294E_constants():
    res = _cli("29412", "--json")
    assert res.exit_code == 0, res.stderr
    data = json.loads(res.stdout)
    nu = float(as_lubricant("ISO_VG100").kinematic_viscosity(25.0))
    expected = skf.skf_friction_moment(
        "spherical_roller_thrust",
        series="294E",
        bore_diameter=0.060,
        outside_diameter=0.130,
        speed=1000 * RPM,
        kinematic_viscosity=nu,
        load_axial=50e3,
    )["total_Nm"]
    friction = data["cases"][0]["friction"]
    assert friction["model"] == "skf"
    assert friction["total_Nm"] == pytest.approx(float(expected), rel=1e-9)
    assert "standard spherical roller thrust bearing" in friction["model_why"]
    assert any("SKF constants of series 294E" in note for note in data["notes"])


@pytest.mark.parametrize(
    ("designation", "key", "note"),
    [("29240", "292", None), ("29320", "293E", None), ("29440", "294E", "constants for 294 E only")],
)
def test_series_key_from_the_designation_and_design(designation, key, note):
    res = _cli(designation, "--json")
    assert res.exit_code == 0, res.stderr
    notes = json.loads(res.stdout)["notes"]
    assert any(f"SKF constants of series {key} (designation {designation})" in n for n in notes)
    assert (note is None) or any(note in n for n in notes)


def test_compare_lists_skf_and_says_why_palmgren_and_components_do_not_apply():
    res = _cli("29412", "--compare", "--json")
    assert res.exit_code == 0, res.stderr
    models = json.loads(res.stdout)["models"]
    assert models["skf"]["total_Nm"][0] > 0
    assert "refused" in models["palmgren"]["not_applicable"]
    assert "spherical roller thrust" in models["palmgren"]["not_applicable"]
    assert "no component friction model" in models["components"]["not_applicable"]


def test_components_model_still_refuses_in_one_line():
    res = _cli("29412", "--model", "components")
    assert res.exit_code == 2 and res.stdout == ""
    line = res.stderr.strip()
    assert "\n" not in line and "no component friction model yet" in line and "'skf'" in line
