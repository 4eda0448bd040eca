"""Drivetrains (docs/drivetrains.md): the two-stage helical gearbox against a hand force/moment balance,
every bearing's two lives and the system life, the power balance, the mesh geometry.

The hand balance is written here from the gear geometry alone (tooth counts, module, angles, the
shafts' centres): the normal tooth force of a mesh is perpendicular to both tooth lines and transmits
the input torque; each shaft on a locating and a floating bearing is then statically determinate.
"""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pytest

from bearingkit.io.reading import load_toml
from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
from bearingkit.systems.drivetrain.gearing import GearGeometry, GearPair
from bearingkit.systems.drivetrain.input import drivetrain_from_dict, load_drivetrain_file

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
GEARBOX = EXAMPLES / "gearbox_two_stage.toml"


def _rigid(data: dict) -> dict:
    """The gearbox with every bearing a rigid radial (and, locating, axial) support, no tilt stiffness."""
    out = copy.deepcopy(data)
    for s in out["shafts"]:
        for b in s["bearings"]:
            b.pop("designation", None)
            axial = "1e13 N/m" if b["axial"] == "locating" else "0 N/m"
            b["stiffness"] = {"radial": "1e13 N/m", "axial": axial, "tilt": "0 N*m/rad"}
    out.pop("lubricant", None)
    out.pop("lubrication", None)
    for c in out["load_cases"]:
        c.pop("speed", None)
        c.pop("temperature", None)
    return out


@pytest.fixture(scope="module")
def gearbox():
    return DrivetrainAnalysis(load_drivetrain_file(GEARBOX))


def _mesh_force_on_pinion(z1, mn_mm, beta1_deg, torque, centre1, centre2):
    """Force (3,) on the pinion and its pitch point arm (3,): hand calculation (module docstring).

    Standard gears (no profile shift): r_w = z m_n / (2 cos β), tan α_t = tan 20° / cos β. The tangential
    force F_t = −T / r_w (the mesh holds the driving torque), the radial force |F_t| tan α_t pushes the
    pinion away from the wheel, and the axial force makes the normal force perpendicular to the pinion's
    tooth line h = sin β t + cos β z (β > 0 right hand): F_t sin β + F_a cos β = 0.
    """
    beta = np.deg2rad(beta1_deg)
    r_w = z1 * mn_mm * 1e-3 / (2 * np.cos(beta))
    alpha_t = np.arctan(np.tan(np.deg2rad(20.0)) / np.cos(beta))
    e = np.array([centre2[0] - centre1[0], centre2[1] - centre1[1], 0.0])
    e /= np.linalg.norm(e)
    t = np.cross([0, 0, 1.0], e)
    f_t = -torque / r_w
    f = f_t * t - abs(f_t) * np.tan(alpha_t) * e + (-f_t * np.tan(beta)) * np.array([0, 0, 1.0])
    return f, r_w * e


def _two_bearing_reactions(loads, z_a, z_b):
    """Reactions (R_A (3,), R_B (2,)) of a shaft on a locating bearing at z_a and a floating one at z_b
    under forces F_k at points (x_k, y_k, z_k): Σ F = 0 and Σ M about A (x, y) = 0."""
    # unknowns: RAx, RAy, RAz, RBx, RBy
    a = np.zeros((5, 5))
    rhs = np.zeros(5)
    a[0, [0, 3]] = 1.0
    a[1, [1, 4]] = 1.0
    a[2, 2] = 1.0
    # moments about the axis point of A: r × F with r = (0, 0, z_b − z_a) for R_B
    dz = z_b - z_a
    a[3, 4] = -dz  # M_x = y F_z − z F_y
    a[4, 3] = dz  # M_y = z F_x − x F_z
    for f, p in loads:
        rhs[:3] -= f
        r = np.array([p[0], p[1], p[2] - z_a])
        m = np.cross(r, f)
        rhs[3] -= m[0]
        rhs[4] -= m[1]
    x = np.linalg.solve(a, rhs)
    return x[:3], x[3:]


def test_gearbox_reactions_equal_a_hand_force_and_moment_balance():
    inp = drivetrain_from_dict(_rigid(load_toml(GEARBOX)), "rigid", base=EXAMPLES)
    res = DrivetrainAnalysis(inp).result
    assert res.converged.all()
    c_in, c_mid, c_out = (0.0, 0.0), (0.100, 0.0737148), (0.270, 0.0375802)
    t_in = np.array([120.0, 200.0, 60.0])
    for case, torque in enumerate(t_in):
        f1, p1 = _mesh_force_on_pinion(19, 3.0, 15.0, torque, c_in, c_mid)
        t_mid = -torque * 61 / 19  # what mesh 1 puts on the intermediate shaft (it drives pinion_2)
        f2, p2 = _mesh_force_on_pinion(21, 4.0, -12.0, t_mid, c_mid, c_out)
        expected = {
            "input": _two_bearing_reactions([(f1, (p1[0], p1[1], 0.050))], 0.010, 0.150),
            "intermediate": _two_bearing_reactions(
                [(-f1, (-p1[0] * 61 / 19, -p1[1] * 61 / 19, 0.050)), (f2, (p2[0], p2[1], 0.110))],
                0.010,
                0.150,
            ),
            "output": _two_bearing_reactions(
                [(-f2, (-p2[0] * 64 / 21, -p2[1] * 64 / 21, 0.110))], 0.010, 0.150
            ),
        }
        scale = np.abs(f2).max()
        for shaft, (ra, rb) in expected.items():
            got_a = res.reaction(f"{shaft}_A")[case]
            got_b = res.reaction(f"{shaft}_B")[case]
            np.testing.assert_allclose(got_a[:3], ra, rtol=0, atol=1e-9 * scale)
            np.testing.assert_allclose(got_b[:2], rb, rtol=0, atol=1e-9 * scale)
            assert abs(got_b[2]) <= 1e-9 * scale  # floating
    assert res.equilibrium_residual().max() < 1e-9


def test_gearbox_every_bearing_has_both_lives_and_the_system_life_combines_them(gearbox):
    lives = gearbox.system_lives
    for case in range(gearbox.n_cases):
        ts, iso, slopes = [], [], []
        for name in gearbox.bearings:
            bl = gearbox.bearing_lives(name)
            assert np.isfinite(bl["L10h_h"][case]) and bl["L10h_h"][case] > 0
            assert np.isfinite(bl["L10h_iso281_h"][case]) and bl["L10h_iso281_h"][case] > 0
            ts.append(bl["L10h_h"][case])
            iso.append(bl["L10h_iso281_h"][case])
            slopes.append(10 / 9 if name.endswith("_A") else 9 / 8)  # A: deep groove ball, B: NU roller
        for key, per in (("L10h_h", ts), ("L10h_iso281_h", iso)):
            total = lives[key][case]
            # Weibull combination of independent members: Σ (L_sys / L_i)^e_i = 1 (ISO 281 slopes)
            assert sum((total / li) ** e for li, e in zip(per, slopes, strict=True)) == pytest.approx(
                1.0, abs=1e-9
            )
            assert total < min(per)


def test_gearbox_duty_cycle_is_palmgren_miner(gearbox):
    duty = gearbox.duty_cycle()
    f = np.array([0.6, 0.1, 0.3])
    for name in gearbox.bearings:
        lives = gearbox.bearing_lives(name)["L10h_h"]
        assert duty["bearings"][name]["L10h_h"] == pytest.approx(1.0 / np.sum(f / lives), rel=1e-12)
    sys = gearbox.system_lives["L10h_h"]
    assert duty["system"]["L10h_h"] == pytest.approx(1.0 / np.sum(f / sys), rel=1e-12)


def test_gearbox_power_in_equals_power_out_plus_losses(gearbox):
    p = gearbox.power
    w_in = 1500 * np.pi / 30
    t_in = np.array([120.0, 200.0, 60.0])
    np.testing.assert_allclose(p["input_W"], t_in * w_in, rtol=1e-12)
    # lossless statics against the kinematics: the held output's reaction returns the input power
    np.testing.assert_allclose(p["output_lossless_W"], p["input_W"], rtol=1e-9)
    w = {"input": w_in, "intermediate": -w_in * 19 / 61, "output": w_in * 19 / 61 * 21 / 64}
    for shaft, value in w.items():
        np.testing.assert_allclose(p["speeds_rad_s"][shaft], value, rtol=1e-12)
    # bearing losses: friction torque × the ring's speed; mesh losses: μ_mz H_V F_t v (Ohlendorf)
    bearing = sum(
        np.abs(gearbox.bearings[n].friction.total) * abs(w[n.rsplit("_", 1)[0]]) for n in gearbox.bearings
    )
    mesh = 0.0
    for z1, z2, mn, beta, shaft, name in (
        (19, 61, 3.0, 15.0, "input", "stage_1"),
        (21, 64, 4.0, 12.0, "intermediate", "stage_2"),
    ):
        b = np.deg2rad(beta)
        mt = mn / np.cos(b)
        at = np.arctan(np.tan(np.deg2rad(20)) / np.cos(b))
        d1, d2 = z1 * mt, z2 * mt
        db1, db2 = d1 * np.cos(at), d2 * np.cos(at)
        da1, da2 = d1 + 2 * mn, d2 + 2 * mn
        pbt = np.pi * mt * np.cos(at)
        e1 = (0.5 * np.sqrt(da1**2 - db1**2) - 0.5 * db1 * np.tan(at)) / pbt
        e2 = (0.5 * np.sqrt(da2**2 - db2**2) - 0.5 * db2 * np.tan(at)) / pbt
        bb = np.arctan(np.tan(b) * np.cos(at))
        u = z2 / z1
        h_v = np.pi * (u + 1) / (z1 * u) * (1 - (e1 + e2) + e1**2 + e2**2) / np.cos(bb)
        torque = t_in if shaft == "input" else t_in * 61 / 19
        mesh = mesh + 0.05 * h_v * torque * abs(w[shaft])  # F_t r_w ω = T ω
        np.testing.assert_allclose(p["mesh"][name]["loss_W"], 0.05 * h_v * torque * abs(w[shaft]), rtol=1e-9)
    np.testing.assert_allclose(p["loss_W"], bearing + mesh, rtol=1e-12)
    np.testing.assert_allclose(p["input_W"], p["output_W"] + bearing + mesh, rtol=1e-12)
    assert np.all((p["efficiency"] > 0.9) & (p["efficiency"] < 1.0))


def test_every_bearing_is_a_pipeline_analysis_at_the_solved_state(gearbox):
    res = gearbox.result
    for name, a in gearbox.bearings.items():
        np.testing.assert_allclose(
            a.statics.load, res.bearing_load(name), rtol=0, atol=1e-9 * np.abs(res.bearing_load(name)).max()
        )


def test_the_mesh_force_is_perpendicular_to_both_tooth_lines():
    beta = np.deg2rad(14.0)
    pair = GearPair(
        GearGeometry(17, 2e-3, np.deg2rad(20), beta, 0.03),
        GearGeometry(43, 2e-3, np.deg2rad(20), -beta, 0.03),
    )
    e = np.array([np.cos(0.3), np.sin(0.3), 0.0])
    t = np.cross([0, 0, 1.0], e)
    for flank in (1.0, -1.0):
        n = pair.direction(e, flank)
        # tooth lines at the pitch point: h = sin β t_g + cos β z with each gear's own tangent t_g
        h_a = np.sin(beta) * t + np.cos(beta) * np.array([0, 0, 1.0])
        h_b = np.sin(-beta) * (-t) + np.cos(beta) * np.array([0, 0, 1.0])
        assert abs(n @ h_a) < 1e-15 and abs(n @ h_b) < 1e-15
        assert n @ e > 0  # separating
    # working centre distance of standard gears: (z1 + z2) m_t / 2
    assert pair.centre_distance == pytest.approx(60 * 2e-3 / np.cos(beta) / 2, rel=1e-12)


def test_iso6336_mesh_stiffness_of_a_standard_spur_pair():
    """c' = C_M / q' (x = 0, spur) and c_γα = c' (0.75 ε_α + 0.25) per face width (ISO 6336-1 method B)."""
    z1, z2 = 20, 40
    pair = GearPair(
        GearGeometry(z1, 3e-3, np.deg2rad(20), 0.0, 0.03), GearGeometry(z2, 3e-3, np.deg2rad(20), 0.0, 0.03)
    )
    q = 0.04723 + 0.15551 / z1 + 0.25791 / z2
    c_prime = 0.8 / q  # N/(mm µm)
    eps = pair.contact_ratio
    # contact ratio of standard spur gears, hand formula
    d1, d2 = z1 * 3.0, z2 * 3.0
    db1, db2 = d1 * np.cos(np.deg2rad(20)), d2 * np.cos(np.deg2rad(20))
    g = 0.5 * (np.sqrt((d1 + 6) ** 2 - db1**2) + np.sqrt((d2 + 6) ** 2 - db2**2)) - 90.0 * np.sin(
        np.deg2rad(20)
    )
    assert eps == pytest.approx(g / (np.pi * 3.0 * np.cos(np.deg2rad(20))), rel=1e-12)
    assert pair.mesh_stiffness() == pytest.approx(c_prime * (0.75 * eps + 0.25) * 30.0 * 1e6, rel=1e-12)
    assert 12 < c_prime * (0.75 * eps + 0.25) < 25  # ISO 6336-1: c_γ about 20 N/(mm µm) for steel spur gears


BAD = [
    (lambda d: d["shafts"][1].update(axis=[1.0, 0.0, 0.0]), "not parallel"),
    (lambda d: d["shafts"][1]["gears"][0].update(normal_module="3.5 mm"), "mismatched normal modules"),
    (lambda d: d["shafts"][1]["gears"][0].update(teeth=62), "stage_1"),
    (lambda d: d["shafts"][2].update(bearings=[]), "shafts.output: no bearing supports it"),
    (lambda d: d["shafts"][1]["gears"][0].update(hand="right"), "opposite hands"),
    (lambda d: d.update(budget={"max_bearings": 4}), "raise it with [budget] max_bearings = 6"),
    (lambda d: d["load_cases"][0].update(torques={"output": "5 N*m"}), "held shaft takes the reaction"),
]


@pytest.mark.parametrize(("edit", "needle"), BAD)
def test_bad_input_is_one_line_naming_the_part(edit, needle):
    from bearingkit.errors import InputError

    data = copy.deepcopy(load_toml(GEARBOX))
    edit(data)
    with pytest.raises(InputError) as err:
        inp = drivetrain_from_dict(data, "gearbox.toml", base=EXAMPLES)
        _ = DrivetrainAnalysis(inp).result
    text = str(err.value)
    assert "\n" not in text and needle in text and text.startswith("gearbox.toml: ")


def test_load_case_budget_is_one_line():
    from bearingkit.errors import InputError

    data = copy.deepcopy(load_toml(GEARBOX))
    data["load_cases"] = [dict(data["load_cases"][0], name=f"c{i}", time_fraction=1 / 60) for i in range(60)]
    with pytest.raises(InputError, match=r"raise it with \[budget\] max_load_cases = 60"):
        drivetrain_from_dict(data, "gearbox.toml", base=EXAMPLES)


def test_a_reversed_torque_loads_the_other_flanks():
    """Driving backwards: every tangential and axial tooth force changes sign, the radial ones do not
    (the other flanks carry); the rigid-bearing reactions still equal the hand balance."""
    data = _rigid(load_toml(GEARBOX))
    data["load_cases"] = [
        {"name": "forward", "torques": {"input": "120 N*m"}},
        {"name": "reverse", "torques": {"input": "-120 N*m"}},
    ]
    res = DrivetrainAnalysis(drivetrain_from_dict(data, "rigid", base=EXAMPLES)).result
    assert res.converged.all() and np.all([res.mesh_force(m) > 0 for m in ("stage_1", "stage_2")])
    for m in ("stage_1", "stage_2"):
        c = res.mesh_components(m, "a")
        assert c["tangential_N"][1] == pytest.approx(-c["tangential_N"][0], rel=1e-12)
        assert c["axial_N"][1] == pytest.approx(-c["axial_N"][0], rel=1e-12)
        assert c["radial_N"][1] == pytest.approx(c["radial_N"][0], rel=1e-12)
    f1, p1 = _mesh_force_on_pinion(19, 3.0, 15.0, -120.0, (0.0, 0.0), (0.100, 0.0737148))
    ra, rb = _two_bearing_reactions([(f1, (p1[0], p1[1], 0.050))], 0.010, 0.150)
    np.testing.assert_allclose(res.reaction("input_A")[1, :3], ra, rtol=0, atol=1e-9 * np.abs(f1).max())
    np.testing.assert_allclose(res.reaction("input_B")[1, :2], rb, rtol=0, atol=1e-9 * np.abs(f1).max())
