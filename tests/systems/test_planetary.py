"""Planetary stage (examples/planetary_stage.toml): equal load sharing without errors, the closed-form
load sharing with a pin position error, the planet bearings' lives, the stage's ratio.

Closed form (spur gears, derived for the model of docs/drivetrains.md). Planet i turns freely on its
pin, so its sun and ring meshes carry the same normal force F_i. With the sun's centre, the carrier
and the ring held, the sun turned by θ_s, and the planet's centre moved along the tangent by w_i
(its pin error e_i plus the planet bearings' deflection 2 F_i cos α / K_B, K_B their total radial
stiffness), the two mesh deflections add up to

    δ_sp + δ_rp = r_bs θ_s − 2 cos α w_i = F_i (1/k_sp + 1/k_rp) = F_i / k_eq,

so F_i = k_e (r_bs θ_s − 2 cos α e_i), k_e = k_eq / (1 + 4 k_eq cos²α / K_B); the sun's torque
T_s = r_bs Σ F_i fixes θ_s and

    F_i = T_s / (N r_bs) + 2 k_e cos α (ē − e_i),   ē = Σ e_i / N.
"""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pytest

from bearingkit.io.reading import load_toml
from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
from bearingkit.systems.drivetrain.input import drivetrain_from_dict, load_drivetrain_file

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
PLANETARY = EXAMPLES / "planetary_stage.toml"


@pytest.fixture(scope="module")
def stage():
    return DrivetrainAnalysis(load_drivetrain_file(PLANETARY))


def test_equal_sharing_without_errors_and_planet_bearing_lives(stage):
    res = stage.result
    assert res.converged.all()
    sun_forces = np.array([res.mesh_force(f"stage.sun-planet{i}") for i in (1, 2, 3)])
    ring_forces = np.array([res.mesh_force(f"stage.planet{i}-ring") for i in (1, 2, 3)])
    np.testing.assert_allclose(
        sun_forces, np.broadcast_to(sun_forces.mean(axis=0), sun_forces.shape), rtol=1e-9
    )
    np.testing.assert_allclose(ring_forces, sun_forces, rtol=1e-9)
    # the sun's torque T = N F r_b (spur, no profile shift: r_b = z m cos 20° / 2)
    r_bs = 21 * 3e-3 * np.cos(np.deg2rad(20)) / 2
    np.testing.assert_allclose(sun_forces.sum(axis=0) * r_bs, [200.0, 100.0], rtol=1e-9)
    # ratio with the ring fixed: 1 + z_r / z_s; the carrier holds T (1 + 69/21)
    np.testing.assert_allclose(stage.omega["carrier"], 3000 * np.pi / 30 / (1 + 69 / 21), rtol=1e-12)
    np.testing.assert_allclose(res.held_torque(), -np.array([200.0, 100.0]) * (1 + 69 / 21), rtol=1e-9)
    for name in stage.bearings:
        if ".planet" in name:
            lives = stage.bearing_lives(name)
            assert np.all(np.isfinite(lives["L10h_h"])) and np.all(lives["L10h_h"] > 0)
    life = stage.system_lives["L10h_h"]
    planet = min(stage.bearing_lives(n)["L10h_h"][0] for n in stage.bearings if ".planet" in n)
    assert np.isfinite(life).all() and life[0] < planet
    p = stage.power
    np.testing.assert_allclose(p["output_lossless_W"], p["input_W"], rtol=1e-9)


def _linear_stage(pin_errors_um, k_support):
    """The example with linear planet bearings (K_B known), rigid planets, the sun and carrier held at the
    gear plane by supports of stiffness k_support."""
    data = copy.deepcopy(load_toml(PLANETARY))
    data.pop("lubricant")
    data.pop("lubrication")
    for c in data["load_cases"]:
        c.pop("speed")
        c.pop("temperature")
    rigid = {"radial": f"{k_support} N/m", "axial": f"{k_support} N/m", "tilt": f"{k_support} N*m/rad"}
    sun, carrier = data["shafts"]
    sun["bearings"].append({"name": "sun_held", "stiffness": rigid, "position": "150 mm"})
    carrier["bearings"].append({"name": "carrier_held", "stiffness": rigid, "position": "20 mm"})
    st = data["planetary"][0]
    st["mesh_stiffness"] = "4e8 N/m"
    data["solver"] = {"rtol": 1e-9}  # the rigid planets leave round-off near 1e-10 of the load scale
    st["pin_errors"] = [f"{e} um" for e in pin_errors_um]
    # the closed form takes the planet body as rigid: a planet 1e5 times stiffer than steel
    st["planet"]["material"] = {"youngs_modulus": "2.1e16 Pa", "poisson_ratio": 0.3, "density": "7850 kg/m^3"}
    for b in st["planet_bearings"]:
        b.pop("designation")
        b["stiffness"] = {"radial": "3e8 N/m", "axial": "1e8 N/m", "tilt": "0 N*m/rad"}
    return DrivetrainAnalysis(drivetrain_from_dict(data, "linear_stage", base=EXAMPLES)).result


def _closed_form(torque, errors_m):
    k_eq = 4e8 * 4e8 / (4e8 + 4e8)
    k_b = 2 * 3e8
    cos_a = np.cos(np.deg2rad(20))
    k_e = k_eq / (1 + 4 * k_eq * cos_a**2 / k_b)
    r_bs = 21 * 3e-3 * cos_a / 2
    e = np.asarray(errors_m)
    return torque / (3 * r_bs) + 2 * k_e * cos_a * (e.mean() - e)


def test_a_pin_error_gives_the_closed_form_sharing():
    errors = [5.0, 0.0, 0.0]  # µm: planet 1's pin 5 µm ahead
    deviations = []
    for k_support in (1e12, 1e13):
        res = _linear_stage(errors, k_support)
        assert res.converged.all()
        for case, torque in enumerate((200.0, 100.0)):
            expected = _closed_form(torque, np.array(errors) * 1e-6)
            got = np.array([res.mesh_force(f"stage.sun-planet{i}")[case] for i in (1, 2, 3)])
            ring = np.array([res.mesh_force(f"stage.planet{i}-ring")[case] for i in (1, 2, 3)])
            np.testing.assert_allclose(ring, got, rtol=0, atol=1e-8 * got.max())  # the planets turn freely
            assert got.sum() == pytest.approx(expected.sum(), rel=1e-8)  # the sum holds
            spread = expected - expected.mean()
            deviations.append(np.abs((got - got.mean()) - spread).max() / np.abs(spread).max())
            assert expected[0] < expected[1]  # the pin ahead unloads its planet
    # the remaining difference is the supports' compliance (1e12 and 1e13 N/m): it falls ∝ 1/k
    assert deviations[2] < 1e-4 and deviations[0] / deviations[2] == pytest.approx(10.0, rel=0.05)


def test_planet_bearings_iso281_life_by_hand(stage):
    """The planets' two locating 6304 share a ~0.1 N axial load: f0 F_a/C0r lies below ISO 281 Table 3's
    first row (0.172), but F_r >= (0.172/0.19) C0r/f0 puts F_a/F_r under e (docs/ratings.md): P = F_r.
    By hand: L10 = (C/F_r)^3 10^6 rev at the speed relative to the carrier, n_p - n_c with
    n_c = n_s / (1 + z_r/z_s), n_p - n_c = -(z_s/z_p)(n_s - n_c); the stage's ISO 281 system life
    combines the six equal planet bearings (the others carry nothing) with the ball slope e = 10/9."""
    import csv

    from bearingkit.physics.life import iso76

    cat = EXAMPLES.parent / "src" / "bearingkit" / "catalogue" / "data" / "deep_groove_ball.csv"
    with cat.open() as f:
        C, c0 = next(
            (float(r["C_N"]), float(r["C0_N"])) for r in csv.DictReader(f) if r["designation"] == "6304"
        )
    n_s = 3000.0
    n_c = n_s / (1 + 69 / 21)
    n_rel = abs(-(21 / 24) * (n_s - n_c))  # rpm
    res = stage.result
    by_hand = []
    for name in (n for n in stage.bearings if ".planet" in n):
        load = res.bearing_load(name)
        fr, fa = np.hypot(load[:, 0], load[:, 1]), np.abs(load[:, 2])
        a = stage.bearings[name]
        row = a.statics.model.rows[0]
        f0 = iso76.f0_radial_ball(float(np.max(row.element_diameter)) / float(np.max(row.pitch_diameter)))
        assert np.all((fa > 0) & (f0 * fa / c0 < 0.172))  # a small axial load: below Table 3
        assert np.all(fr >= 0.172 / 0.19 * c0 / f0)  # the bound holds: P = F_r
        expected = (C / fr) ** 3 * 1e6 / (n_rel * 60.0)
        np.testing.assert_allclose(stage.bearing_lives(name)["L10h_iso281_h"], expected, rtol=1e-9)
        assert "below ISO 281 Table 3's first row" in a.rating.iso281.note
        by_hand.append(expected)
    assert len(by_hand) == 6
    e = 10 / 9
    system = np.sum(np.array(by_hand) ** -e, axis=0) ** (-1 / e)
    np.testing.assert_allclose(stage.system_lives["L10h_iso281_h"], system, rtol=1e-9)
    # every face: the JSON per bearing and system, the CLI/report notes
    d = stage.to_dict()
    text = str(d)
    assert "below ISO 281 Table 3's first row" in text
