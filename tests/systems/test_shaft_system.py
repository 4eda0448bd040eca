"""A shaft on bearings against closed forms, and the equilibrium of nonlinear bearing systems.

Closed forms (Euler–Bernoulli plus the Timoshenko shear term; Timoshenko & Gere, Mechanics of
Materials; Roark's Formulas for Stress and Strain, table of beam cases):
- simply supported span L, central force P: mid-span deflection P L³/(48EI) + P L/(4κGA), support
  section rotation P L²/(16EI) (shear deforms, it does not rotate sections), reactions P/2;
- equal end moments M on a span L: mid-span deflection M L²/(8EI) (superposed for bearings with
  tilt stiffness, M read from the shaft's moment line at the support);
- two spans on three supports: Clapeyron's three-moment equation
  M_A L1 + 2 M_B (L1 + L2) + M_C L2 = −6 EI (θ1 + θ2), θ the free end rotations of the loaded spans
  at B (a point load P at a from the near support of a span L rotates the far end by
  P a (L² − a²)/(6 EI L)).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.io.loader import load_file
from bearingkit.systems.shaft import beam
from bearingkit.systems.shaft.loads import Gear, PointLoad, ShaftLoads
from bearingkit.systems.shaft.shaft import SHAFT_STEEL, Section, Shaft
from bearingkit.systems.shaft.solver import ShaftSystem, solve
from bearingkit.systems.shaft.supports import BearingSeat, LinearBearing

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
E = SHAFT_STEEL.youngs_modulus
G = E / (2 * (1 + SHAFT_STEEL.poisson_ratio))


def _props(d):
    area, inertia = beam.section_properties(d)
    return area, inertia, beam.shear_coefficient(SHAFT_STEEL.poisson_ratio)


def _linear(k_radial, k_axial=0.0, k_tilt=0.0):
    return LinearBearing(np.diag([k_radial, k_radial, k_axial, k_tilt, k_tilt]))


def test_two_stiff_bearings_short_thick_shaft_with_shear():
    """Reactions P/2; mid-span deflection with the shear term (L/d = 2.5: shear is ~ 20 % of it)."""
    length, d, p, k = 0.1, 0.04, 20e3, 1e14
    shaft = Shaft((Section(0.0, length, d),))
    system = ShaftSystem(
        shaft,
        (
            BearingSeat("A", _linear(k, k), 0.0),
            BearingSeat("B", _linear(k), length, axial="floating"),
        ),
    )
    res = solve(system, ShaftLoads(("c",), forces=(PointLoad(length / 2, [-p, 0, 0, 0, 0]),)))
    assert res.converged.all()
    for name in "AB":
        assert res.reaction(name)[0, 0] == pytest.approx(p / 2, rel=1e-12)
    area, inertia, kappa = _props(d)
    bending, shear = p * length**3 / (48 * E * inertia), p * length / (4 * kappa * G * area)
    assert shear / bending > 0.2
    mid = res.displacement[0, res.assembly.mesh.node(length / 2), 0] - res.seat_displacement("A")[0, 0]
    assert -mid == pytest.approx(bending + shear, rel=1e-9)
    # Seat tilt: the section rotation at the support, P L²/(16 EI), seen by the bearing as misalignment.
    slope = p * length**2 / (16 * E * inertia)
    assert res.seat_displacement("A")[0, 4] == pytest.approx(-slope, rel=1e-9)
    assert res.misalignment("A")[0] == pytest.approx(slope, rel=1e-9)
    _z, moment = res.moment_line()
    assert np.abs(moment[0, :, 1]).max() == pytest.approx(p * length / 4, rel=1e-12)


def test_two_deep_groove_ball_bearings_central_load():
    """Two 6209 (nonlinear, with their tilt stiffness): reactions P/2 and the closed-form deflection
    relative to the seats once the bearings' restraining moment M (read at the support) is superposed."""
    dgbb = load_file(EXAMPLES / "dgbb_6209.toml").model
    length, d, p = 0.25, 0.045, 8e3
    shaft = Shaft((Section(0.0, length, d),))
    system = ShaftSystem(
        shaft,
        (BearingSeat("A", dgbb, 0.0), BearingSeat("B", dgbb, length, axial="floating")),
        max_element_length=0.01,
    )
    res = solve(system, ShaftLoads(("c",), forces=(PointLoad(length / 2, [-p, 0, 0, 0, 0]),)))
    assert res.converged.all()
    for name in "AB":
        assert res.reaction(name)[0, 0] == pytest.approx(p / 2, rel=1e-9)
    area, inertia, kappa = _props(d)
    _z, moment = res.moment_line()
    m_support = moment[0, 0, 1]  # internal M_y just right of bearing A
    assert m_support < 0  # the ball bearing's tilt stiffness restrains the shaft a little
    closed = p * length**3 / (48 * E * inertia) + p * length / (4 * kappa * G * area)
    closed += m_support * length**2 / (8 * E * inertia)
    mid = res.displacement[0, res.assembly.mesh.node(length / 2), 0] - res.seat_displacement("A")[0, 0]
    assert -mid == pytest.approx(closed, rel=1e-9)
    # The bearing's moment on the shaft balances the support moment (equilibrium of the end node).
    assert res.reaction("A")[0, 4] == pytest.approx(-m_support, abs=1e-9 * p * length)


def test_seat_tilt_equals_the_beam_slope():
    """Euler–Bernoulli shaft on two 6209, gear loads: the tilt each bearing sees equals du/dz at its seat."""
    dgbb = load_file(EXAMPLES / "dgbb_6209.toml").model
    length = 0.3
    shaft = Shaft((Section(0.0, 0.1, 0.045), Section(0.1, length, 0.05)), shear_deformation=False)
    gear = Gear("g", 0.09, 0.15, helix_angle=np.deg2rad(12.0), mesh_angle=np.deg2rad(30.0))
    system = ShaftSystem(
        shaft,
        (BearingSeat("A", dgbb, 0.02), BearingSeat("B", dgbb, 0.28, axial="floating")),
        gears=(gear,),
        max_element_length=2e-3,
    )
    res = solve(system, ShaftLoads(("c",), gear_torques={"g": 300.0}))
    assert res.converged.all()
    u, z = res.displacement[0], res.z
    for name, pos, side in (("A", 0.02, +1), ("B", 0.28, -1)):
        i = res.assembly.mesh.node(pos)
        # One-sided four-point difference on the loaded span's side of the seat (the bearing's moment
        # makes the curvature jump at the seat): exact for the cubic deflection between point loads.
        j = i + side * np.arange(4)
        h = z[j[1]] - z[j[0]]  # signed: negative when stepping towards −z
        assert np.allclose(np.diff(z[j]), h, rtol=1e-9)
        weights = np.array([-11.0, 18.0, -9.0, 2.0]) / (6 * h)
        slope_x, slope_y = weights @ u[j, 0], weights @ u[j, 1]
        q = res.relative_displacement(name)[0]  # rigid housing: the bearing sees the seat tilt
        assert q[4] == pytest.approx(slope_x, rel=1e-8)
        assert q[3] == pytest.approx(-slope_y, rel=1e-8)
        assert np.hypot(slope_x, slope_y) > 1e-4  # a tilt worth checking (0.1 mrad)


def _three_moment_reactions(l1, l2, p1, a1, p2, b2, ei):
    theta1 = p1 * a1 * (l1**2 - a1**2) / (6 * ei * l1)  # span 1 rotation at B
    theta2 = p2 * b2 * (l2**2 - b2**2) / (6 * ei * l2)  # span 2 rotation at B
    m_b = -3 * ei * (theta1 + theta2) / (l1 + l2)  # Clapeyron, M_A = M_C = 0
    r_a = p1 * (l1 - a1) / l1 + m_b / l1
    r_c = p2 * (l2 - b2) / l2 + m_b / l2
    return r_a, p1 + p2 - r_a - r_c, r_c


def test_three_bearings_approach_the_three_moment_equation():
    l1, l2, d = 0.2, 0.3, 0.04
    p1, a1, p2, b2 = 5e3, 0.07, 8e3, 0.12
    shaft = Shaft((Section(0.0, l1 + l2, d),), shear_deformation=False)
    _, inertia, _ = _props(d)
    expected = np.array(_three_moment_reactions(l1, l2, p1, a1, p2, b2, E * inertia))
    loads = ShaftLoads(
        ("c",), forces=(PointLoad(a1, [0, -p1, 0, 0, 0]), PointLoad(l1 + l2 - b2, [0, -p2, 0, 0, 0]))
    )
    errors, reactions = [], []
    stiffnesses = (1e8, 1e10, 1e12, 1e14)
    for k in stiffnesses:
        system = ShaftSystem(
            shaft,
            (
                BearingSeat("A", _linear(k, k), 0.0),
                BearingSeat("B", _linear(k), l1, axial="floating"),
                BearingSeat("C", _linear(k), l1 + l2, axial="floating"),
            ),
        )
        res = solve(system, loads)
        assert res.converged.all()
        reactions.append(np.array([res.reaction(n)[0, 1] for n in "ABC"]))
        errors.append(np.abs(reactions[-1] / expected - 1).max())
    assert errors[0] > 0.1  # soft supports change the reactions…
    # …and the error falls as 1/k (ratio 100 per step) towards the three-moment values:
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.allclose(ratios[1:], 100.0, rtol=0.01)
    assert errors[-1] < 1e-6
    # Richardson extrapolation k → ∞ of the last two (error ∝ 1/k) lands on the closed form.
    limit = reactions[-1] + (reactions[-1] - reactions[-2]) / (stiffnesses[-1] / stiffnesses[-2] - 1)
    assert np.allclose(limit, expected, rtol=1e-9)


def _preloaded_pair(offset):
    acbb = load_file(EXAMPLES / "acbb_7209.toml").model
    shaft = Shaft((Section(0.0, 0.02, 0.045), Section(0.02, 0.28, 0.035), Section(0.28, 0.3, 0.045)))
    return ShaftSystem(
        shaft,
        (
            BearingSeat("A", acbb, 0.01, orientation="+z"),
            BearingSeat("B", acbb, 0.29, orientation="-z", axial_offset=offset),
        ),
        max_element_length=0.01,
    )


def test_preloaded_angular_pair_on_flexible_shaft_in_equilibrium():
    """Two 7209 set against each other by a 20 µm outer-ring adjustment, on a slender (35 mm) shaft."""
    system = _preloaded_pair(20e-6)
    forces = np.array([[0, 0, 0, 0, 0], [2e3, -1e3, 1.5e3, 0, 0], [4e3, 0, -2.5e3, 0, 0], [0, 6e3, 0, 0, 0]])
    loads = ShaftLoads(tuple("abcd"), forces=(PointLoad(0.15, forces),))
    res = solve(system, loads)
    assert res.converged.all(), res.reason
    assert np.all(res.residual_norm <= 1e-9)
    assert np.all(res.equilibrium_residual() <= 1e-9)  # the full, uncondensed shaft
    fa, fb = res.bearing_load("A")[:, 2], res.bearing_load("B")[:, 2]
    assert fa[0] > 100 and fb[0] == pytest.approx(fa[0], rel=1e-9)  # preload, each in its own frame
    # Axial balance in the shaft frame: A pushes +z, B pushes −z, their sum balances the axial load.
    total = res.reaction("A")[:, 2] + res.reaction("B")[:, 2] + forces[:, 2]
    assert np.abs(total).max() <= 1e-9 * np.abs(forces).max()
    assert np.all(fa > 0) and np.all(fb > 0)  # the preload keeps both rows loaded in these cases


def test_mirrored_system_gives_mirrored_reactions():
    """Turning the shaft end for end (positions z → L − z, orientations swapped) mirrors the results."""
    acbb = load_file(EXAMPLES / "acbb_7209.toml").model
    length = 0.3
    shaft = Shaft((Section(0.0, length, 0.045),))

    def system(mirror: bool):
        pos = (lambda z: length - z) if mirror else (lambda z: z)
        flip = {"+z": "-z", "-z": "+z"} if mirror else {"+z": "+z", "-z": "-z"}
        return ShaftSystem(
            shaft,
            (
                BearingSeat("A", acbb, pos(0.02), orientation=flip["+z"]),
                BearingSeat(
                    "B", acbb, pos(0.28), orientation=flip["-z"], axial_offset=(-1 if mirror else 1) * 1e-5
                ),
            ),
        )

    f = np.array([1.5e3, -2e3, 1e3, 20.0, -30.0])
    # A half turn about x maps (F_x, F_y, F_z, M_x, M_y) → (F_x, −F_y, −F_z, M_x, −M_y).
    t = np.diag([1.0, -1.0, -1.0, 1.0, -1.0])
    a = solve(system(False), ShaftLoads(("c",), forces=(PointLoad(0.1, f),)))
    b = solve(system(True), ShaftLoads(("c",), forces=(PointLoad(length - 0.1, t @ f),)))
    assert a.converged.all() and b.converged.all()
    for name in "AB":
        assert np.allclose(b.reaction(name)[0], t @ a.reaction(name)[0], rtol=1e-8, atol=1e-8 * 2e3)
        assert np.allclose(b.bearing_load(name), a.bearing_load(name), rtol=1e-8, atol=1e-6)


def test_housing_springs_in_series_and_floating_bearing_carries_no_axial_load():
    k_b, k_h, p, fz = 4e8, 1e8, 6e3, 2e3
    shaft = Shaft((Section(0.0, 0.2, 0.05),))
    housing = np.array([k_h, k_h, np.inf, np.inf, np.inf])
    system = ShaftSystem(
        shaft,
        (
            BearingSeat("A", _linear(k_b, 1e9), 0.0, housing_stiffness=housing),
            BearingSeat("B", _linear(k_b, 1e9), 0.2, axial="floating", housing_stiffness=housing),
        ),
    )
    res = solve(system, ShaftLoads(("c",), forces=(PointLoad(0.1, [0, -p, fz, 0, 0]),)))
    assert res.converged.all()
    assert res.seat_displacement("A")[0, 1] == pytest.approx(-p / 2 * (1 / k_b + 1 / k_h), rel=1e-9)
    assert res.outer_displacement("A")[0, 1] == pytest.approx(-p / 2 / k_h, rel=1e-9)
    assert abs(res.reaction("B")[0, 2]) <= 1e-10 * p  # zero to the solver's tolerance
    assert res.reaction("A")[0, 2] == pytest.approx(-fz, rel=1e-10)


def test_batch_equals_single_cases():
    """One batched Newton over the cases gives each case's own solution (no cross-talk)."""
    dgbb = load_file(EXAMPLES / "dgbb_6209.toml").model
    nu = load_file(EXAMPLES / "crb_nu209.toml").model
    shaft = Shaft((Section(0.0, 0.25, 0.05),))
    system = ShaftSystem(
        shaft,
        (BearingSeat("A", dgbb, 0.01), BearingSeat("B", nu, 0.24, axial="floating")),
        gears=(Gear("g", 0.08, 0.12, helix_angle=np.deg2rad(15.0)),),
    )
    torque = np.array([50.0, -200.0, 400.0, 0.0])
    loads = ShaftLoads(
        tuple("abcd"), gear_torques={"g": torque}, forces=(PointLoad(0.2, [[0, -500, 0, 0, 0]]),)
    )
    batch = solve(system, loads)
    assert batch.converged.all()
    for c in range(4):
        one = solve(system, loads.take([c]))
        assert np.allclose(one.unknowns[0], batch.unknowns[c], rtol=1e-9, atol=1e-12)


def test_exported_stiffness_is_the_tangent_of_the_seat_force():
    """K of a seat predicts the change of the bearing force for a small change of its displacement."""
    from bearingkit.systems.shaft.stiffness import shaft_stiffness_table

    dgbb = load_file(EXAMPLES / "dgbb_6209.toml").model
    system = ShaftSystem(
        Shaft((Section(0.0, 0.2, 0.05),)),
        (BearingSeat("A", dgbb, 0.0, orientation="-z"), BearingSeat("B", dgbb, 0.2, axial="floating")),
    )
    res = solve(system, ShaftLoads(("c",), forces=(PointLoad(0.08, [3e3, 1e3, 500.0, 0, 0]),)))
    table = shaft_stiffness_table(res, "A")
    k = table.stiffness[0]
    seat = system.bearing("A")
    q = res.relative_displacement("A")
    dq = np.array([1e-9, -2e-9, 1e-9, 1e-8, 2e-8])
    f0 = seat.law.response(q).force[0] @ seat.transform
    f1 = seat.law.response(q + seat.transform @ dq).force[0] @ seat.transform
    assert np.allclose(-(f1 - f0), k @ dq, rtol=1e-3, atol=1e-4 * np.abs(k @ dq).max())
    assert np.allclose(table.radial()[0], k[:2, :2])
    assert abs(k[0, 1]) > 1e-3 * k[0, 0]  # a load not along x gives cross terms


def test_unloaded_and_barely_loaded_bearings_with_clearance():
    """Clearance (6209: 15 µm, NU 209: 30 µm) and a floating outer ring: zero load, weight only, and
    a load a million times larger all converge in one batch (zero-stiffness start, mechanisms)."""
    dgbb = load_file(EXAMPLES / "dgbb_6209.toml").model
    nu = load_file(EXAMPLES / "crb_nu209.toml").model
    shaft = Shaft((Section(0.0, 0.25, 0.05),))
    system = ShaftSystem(
        shaft,
        (
            BearingSeat("A", dgbb, 0.01, axial="floating"),
            BearingSeat("B", dgbb, 0.12),
            BearingSeat("C", nu, 0.24, axial="floating"),
        ),
    )
    f = np.array([[0, 0, 0, 0, 0], [0, -1e-2, 0, 0, 0], [0, -1e2, 1.0, 0, 0], [3e3, -1e4, 500.0, 0, 0]])
    res = solve(system, ShaftLoads(tuple("abcd"), forces=(PointLoad(0.06, f),)))
    assert res.converged.all(), res.reason
    assert np.all(res.residual_norm <= 1e-10)
    # The full-shaft check is round-off limited by ‖K‖‖u‖ (u includes the rigid motion that closes the
    # clearance), which is ~1e-8 of a 0.01 N load: check it on the loads that are not that small.
    assert np.all(res.equilibrium_residual()[2:] <= 1e-9)
    assert np.all(res.unknowns[0] == 0.0)  # nothing loaded, nothing moves
    assert np.abs(res.reaction("A")[:, 2]).max() <= 1e-9 * np.abs(f).max()  # floating: no thrust


def test_a_load_the_bearings_cannot_carry_is_reported():
    """Thrust towards −z on a shaft held axially only by one angular contact bearing carrying +z."""
    acbb = load_file(EXAMPLES / "acbb_7209.toml").model
    nu = load_file(EXAMPLES / "crb_nu209.toml").model
    system = ShaftSystem(
        Shaft((Section(0.0, 0.2, 0.045),)),
        (BearingSeat("A", acbb, 0.01), BearingSeat("B", nu, 0.19, axial="floating")),
    )
    res = solve(
        system,
        ShaftLoads(("ok", "bad"), forces=(PointLoad(0.1, [[1e3, 0, 2e3, 0, 0], [1e3, 0, -2e3, 0, 0]]),)),
    )
    assert res.converged.tolist() == [True, False]
    assert "cannot be carried" in res.reason[1] and "F_z" in res.reason[1]


def test_a_one_way_axial_stiffness_pushes_one_way_and_is_a_convex_potential():
    """LinearBearing(axial_direction=±1): the axial force on the inner ring only of that sign, its energy
    ½ K_zz q_z² there and 0 beyond, the force −∂U/∂q (central differences); a coupled axial row refused."""
    from bearingkit.systems.shaft.supports import BearingLaw

    k = np.diag([2e8, 2e8, 5e7, 1e4, 1e4])
    q = np.array([[1e-6, -2e-6, 3e-6, 1e-5, 0.0], [1e-6, -2e-6, -3e-6, 1e-5, 0.0]])
    both = BearingLaw(LinearBearing(k)).response(q)
    for s in (1, -1):
        law = BearingLaw(LinearBearing(k, axial_direction=s))
        r = law.response(q)
        pushing = s * both.force[:, 2] > 0
        assert pushing.tolist() == ([False, True] if s == 1 else [True, False])
        np.testing.assert_array_equal(r.force[:, 2], np.where(pushing, both.force[:, 2], 0.0))
        np.testing.assert_array_equal(r.force[:, [0, 1, 3, 4]], both.force[:, [0, 1, 3, 4]])
        idle_energy = np.where(pushing, 0.0, 0.5 * k[2, 2] * q[:, 2] ** 2)
        np.testing.assert_allclose(r.energy, both.energy - idle_energy)
        h = 1e-9
        for i in range(2):
            for d in range(5):
                e = np.zeros((1, 5))
                e[0, d] = h
                up, down = law.response(q[i : i + 1] + e), law.response(q[i : i + 1] - e)
                fd = -(up.energy - down.energy) / (2 * h)
                assert fd[0] == pytest.approx(r.force[i, d], rel=1e-6, abs=1e-9)
        assert (law.reach[:, 2] * s >= 0).all() and (law.reach[:, 2] * s > 0).any()
    coupled = k.copy()
    coupled[2, 0] = coupled[0, 2] = 1e6
    with pytest.raises(InputError, match="one-way axial stiffness"):
        LinearBearing(coupled, axial_direction=1)


def test_two_one_way_stiffness_bearings_cross_locate_a_shaft():
    """A shaft file with two constant-stiffness bearings set against each other (axial_direction "+z" at A,
    "-z" at B): a thrust along +z goes wholly to B, one along −z wholly to A (the shaft's axial balance to
    1e-9), whichever way the Newton starts."""
    import copy
    import tomllib

    from bearingkit.systems.shaft.input import shaft_from_dict
    from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis

    examples = Path(__file__).resolve().parents[2] / "examples"
    data = tomllib.loads((examples / "shaft_countershaft.toml").read_text(encoding="utf-8"))
    for thrust, carrier in ((800.0, "B"), (-800.0, "A")):
        d = copy.deepcopy(data)
        d["shaft"]["bearings"] = [
            {"name": "A", "position": "12.5 mm", "stiffness": {"radial": "3e8 N/m", "axial": "2e8 N/m",
                                                                 "axial_direction": "+z"}},
            {"name": "B", "position": "237.5 mm", "stiffness": {"radial": "3e8 N/m", "axial": "2e8 N/m",
                                                                  "axial_direction": "-z"}},
        ]  # fmt: skip
        for case in d["load_cases"]:
            case["forces"] = [{"name": "thrust", "position": "120 mm", "F_z": f"{thrust} N"}]
        res = ShaftAnalysis(shaft_from_dict(d, "cross-located", base=examples)).result
        assert res.converged.all()
        idle = "A" if carrier == "B" else "B"
        np.testing.assert_array_equal(res.reaction(idle)[:, 2], 0.0)
        np.testing.assert_allclose(res.reaction(carrier)[:, 2], -thrust, rtol=1e-9)
