"""A single tapered or angular contact bearing as mounted (issue #40 item 4): u_z held instead of a refusal,
the reaction reported, the induced axial force said; --hold / --free with a designation."""

from __future__ import annotations

import json

import numpy as np
import pytest
from typer.testing import CliRunner

import bearingkit as bk
from bearingkit.cli import app
from bearingkit.errors import InputError

runner = CliRunner()


def test_rating_30205_under_radial_load_alone_is_answered():
    """The Must-show line: exit 0 with C, C0, the ISO 281 L10 and a note on the held axial DOF."""
    r = runner.invoke(app, ["rating", "30205", "--load", "Fr=1kN"], terminal_width=200)
    assert r.exit_code == 0, r.stderr
    out = r.stdout
    assert "C kN" in out and "C0 kN" in out
    assert "ISO 281: P = 1 kN, C = 32 kN (catalogue), L10 =" in out
    assert "u_z held" in out and "axial reaction F_z =" in out
    data = json.loads(runner.invoke(app, ["rating", "30205", "--load", "Fr=1kN", "--json"]).stdout)
    case = data["cases"][0]
    assert case["system"]["L10_iso281_rev"] == pytest.approx((32e3 / 1e3) ** (10 / 3) * 1e6, rel=1e-9)
    assert any(n.startswith("u_z held") for n in data["notes"])


@pytest.mark.parametrize("designation", ["30205", "30210", "32008 X"])
def test_held_reaction_is_the_induced_axial_force_of_iso281(designation):
    """With u_z held at zero clearance half the rollers carry load (ε = 0.5), so the axial reaction is the
    force the radial load induces. For a line contact (load ∝ δ^(10/9)) that is ISO 281's 0.5 F_r / Y,
    Y = 0.4 cot α (α the cup angle), i.e. 1.25 F_r tan α; the crowned rollers of a catalogue row (TS
    profile) stiffen like a point contact at light load, whose ε = 0.5 force is F_r tan α / 0.8225 =
    1.216 F_r tan α (Harris & Kotzalas 2007, Table 7.4). The reaction lies between the two (±0.5 % for
    17-23 discrete rollers)."""
    a = bk.analyze(designation, load={"F_x": "5 kN"})
    assert not a.setup.free[2]
    tan = np.tan(float(a.input.model.rows[0].contact_angle_outer))
    line, point = 0.5 * 5e3 / (0.4 / tan), 5e3 * tan / 0.8225
    assert 0.995 * point <= a.statics.load[0, 2] <= 1.005 * line


@pytest.mark.parametrize("designation", ["7208 B", "7206 C", "7308 AC"])
def test_held_reaction_of_an_angular_contact_row_is_harris_half_zone_force(designation):
    """Ball row, light load (the contact angle stays near α₀), axial held: half the row loaded (ε = 0.5),
    Q(ψ) = Q_max cos^1.5 ψ, so F_a = F_r tan α Σ cos^1.5 ψ_i / Σ cos^2.5 ψ_i over the loaded balls
    (Harris & Kotzalas 2007, §7.4: Table 7.4's J_r/J_a = 0.8225 at ε = 0.5 is this ratio's limit for
    many balls; the sum at the row's own ball count, 10–12 balls here, differs from it by up to 0.8 %),
    within 1 %."""
    a = bk.analyze(designation, load={"F_x": "100 N"})
    alpha = float(a.input.model.rows[0].contact_angle)
    psi = np.asarray(a.statics_dict()["cases"][0]["rows"][0]["azimuth_rad"])
    c = np.clip(np.cos(psi), 0.0, None)
    half_zone = 100.0 * np.tan(alpha) * np.sum(c**1.5) / np.sum(c**2.5)
    assert a.statics.load[0, 2] == pytest.approx(half_zone, rel=0.01)


def test_hold_and_free_with_a_designation():
    auto = bk.analyze("30206", load={"F_x": "8 kN"})
    held = bk.analyze("30206", load={"F_x": "8 kN"}, hold=["u_z"])
    np.testing.assert_allclose(held.statics.load, auto.statics.load, rtol=1e-12)
    assert any("held at 0" in n for n in held.notes)
    with pytest.raises(InputError, match=r"must be positive.*--hold u_z"):
        bk.analyze("30206", load={"F_x": "8 kN"}, free=["u_z"])
    with pytest.raises(InputError, match="must name a DOF"):
        bk.analyze("30206", load={"F_x": "8 kN"}, hold=["u_q"])
    with pytest.raises(InputError, match="acts on u_z, which is held"):
        bk.analyze("30206", load={"F_x": "8 kN", "F_z": "1 kN"}, hold=["u_z"])
    # freeing a tilt is not undone by the single-row default that fixes it
    tilted = bk.analyze("6208", load={"F_x": "5 kN"}, free=["theta_x", "theta_y"])
    assert tilted.setup.free[3] and tilted.setup.free[4]


def test_cli_hold_and_free_options():
    r = runner.invoke(app, ["analyze", "30206", "--load", "Fr=8kN", "--hold", "u_z", "--json"])
    assert r.exit_code == 0
    assert json.loads(r.stdout)["free_dofs"] == ["u_x", "u_y"]
    r = runner.invoke(app, ["analyze", "30206", "--load", "Fr=8kN", "--free", "u_z"])
    assert r.exit_code == 2 and len(r.stderr.strip().splitlines()) == 1


def test_axial_load_below_the_induced_force_is_explained():
    """u_z free, 0 < F_a < 0.5 F_r/Y: the row alone balances F_a with a narrow load zone — said, with the
    count of the rollers that carry it; above the induced force nothing is said."""
    low = bk.analyze("30206", load={"F_x": "8 kN", "F_z": "2 kN"})
    text = " ".join(low.warnings[0])
    assert "is below the axial force" in text and "0.5 F_r/Y" in text
    assert "3 of 17 rollers carry it" in text
    high = bk.analyze("30206", load={"F_x": "8 kN", "F_z": "4 kN"})
    assert not any("below the axial force" in w for w in high.warnings[0])


def test_file_cases_replaced_by_radial_load_are_mounted_again():
    """A file whose cases give F_a keeps u_z free; --load with F_r alone holds it for the new case; a file
    that lists u_z in [solver] free is refused instead (the user's DOFs are not overridden)."""
    spec = {
        "bearing": {"designation": "30206"},
        "load_cases": [{"name": "combined", "F_x": "8 kN", "F_z": "3 kN"}],
    }
    assert bk.analyze(spec).setup.free[2]
    a = bk.analyze(spec, load={"F_x": "3 kN"})
    assert not a.setup.free[2] and a.statics.converged.all()
    with pytest.raises(InputError, match="must be positive"):
        bk.analyze({**spec, "solver": {"free": ["u_x", "u_y", "u_z"]}}, load={"F_x": "3 kN"})
