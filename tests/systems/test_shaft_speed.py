"""The shaft's bearings at the shaft speed: the same rows at speed as a single-bearing solve.

The inner rings turn with the shaft, the outer rings stand; a bearing turned "-z" sees the speed with
the opposite sign about its own axis. The checks compare the system against the single-bearing
solver (:func:`bearingkit.analysis.solver.quasistatic.solve` with ``speed=``) at the same state, and the
physics a spindle engineer expects: a preloaded angular pair softens radially at 20,000 r/min (the
balls' centrifugal force unloads the inner contacts and turns the outer contact angle down).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from bearingkit.analysis.solver.quasistatic import solve as solve_bearing
from bearingkit.analysis.solver.speed import ModelAtSpeed
from bearingkit.io.loader import load_file
from bearingkit.systems.shaft.loads import PointLoad, ShaftLoads
from bearingkit.systems.shaft.shaft import Section, Shaft
from bearingkit.systems.shaft.solver import ShaftSystem, solve
from bearingkit.systems.shaft.stiffness import shaft_stiffness_table
from bearingkit.systems.shaft.supports import BearingSeat, LinearBearing

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
RPM = np.pi / 30.0


@pytest.fixture(scope="module")
def acbb():
    return load_file(EXAMPLES / "acbb_7209.toml")


def _pair(acbb, offset=20e-6):
    shaft = Shaft((Section(0.0, 0.02, 0.045), Section(0.02, 0.28, 0.045), Section(0.28, 0.3, 0.045)))
    return ShaftSystem(
        shaft,
        (
            BearingSeat("A", acbb.model, 0.01, orientation="+z", source=acbb),
            BearingSeat("B", acbb.model, 0.29, orientation="-z", axial_offset=offset, source=acbb),
        ),
        max_element_length=0.01,
    )


FORCES = np.array([[1e3, 0, 0, 0, 0], [2e3, -1e3, 800.0, 0, 0], [0, 3e3, -600.0, 0, 0]])


def _loads(speed_rpm):
    speed = None if speed_rpm is None else np.full(len(FORCES), speed_rpm * RPM)
    return ShaftLoads(("a", "b", "c"), forces=(PointLoad(0.15, FORCES),), speed=speed)


def test_zero_speed_is_the_zero_speed_solve(acbb):
    """Speed 0 in every case: the laws at rest themselves, so the results equal a solve without speed."""
    system = _pair(acbb)
    rest = solve(system, _loads(None))
    zero = solve(system, _loads(0.0))
    assert rest.converged.all() and zero.converged.all()
    for b in "AB":
        assert zero.model(b) is acbb.model
        scale = np.abs(rest.bearing_load(b)).max()
        assert np.abs(zero.reaction(b) - rest.reaction(b)).max() <= 1e-12 * scale
        assert np.abs(zero.stiffness(b) - rest.stiffness(b)).max() <= 1e-12 * np.abs(rest.stiffness(b)).max()
    assert np.abs(zero.displacement - rest.displacement).max() <= 1e-12 * np.abs(rest.displacement).max()


def test_preloaded_pair_at_20000_rpm_is_softer_radially_and_in_equilibrium(acbb):
    system = _pair(acbb)
    rest = solve(system, _loads(None))
    fast = solve(system, _loads(20_000.0))
    assert fast.converged.all(), fast.reason
    assert np.all(fast.residual_norm <= 1e-9)
    assert np.all(fast.equilibrium_residual() <= 1e-9)  # the full, uncondensed shaft
    for b in "AB":
        assert isinstance(fast.model(b), ModelAtSpeed)
        k_rest, k_fast = rest.stiffness(b)[:, 0, 0], fast.stiffness(b)[:, 0, 0]
        assert np.all(k_fast < 0.9 * k_rest), (k_fast, k_rest)
    # softer bearings: the shaft deflects more under the same load at its loaded end
    assert np.all(
        np.abs(fast.displacement[:, :, :2]).max(axis=(1, 2))
        > np.abs(rest.displacement[:, :, :2]).max(axis=(1, 2))
    )
    # a position-set (rigid) preload grows with speed: the balls' centrifugal force wedges them between
    # the outer raceways (spindle practice: a rigid preload rises with speed) [from memory]
    assert np.all(fast.bearing_load("A")[:, 2] > 1.5 * rest.bearing_load("A")[:, 2])
    # axial balance in the shaft frame still holds
    total = fast.reaction("A")[:, 2] + fast.reaction("B")[:, 2] + FORCES[:, 2]
    assert np.abs(total).max() <= 1e-9 * np.abs(FORCES).max()


def test_bearing_at_speed_equals_the_single_bearing_solve_at_its_seat(acbb):
    """A shaft on one 7209 at speed (locating, tilt-stiff enough with a radial support): the bearing's
    load is the single-bearing solve at speed with the seat's displacement imposed (residual ≤ 1e-9),
    and its stiffness and row states are that solve's; per-case speeds, both orientations."""
    shaft = Shaft((Section(0.0, 0.3, 0.045),))
    speeds = np.array([0.0, 8_000.0, 20_000.0, 12_000.0]) * RPM
    forces = np.array(
        [[1e3, 0, 2e3, 0, 0], [2e3, 500.0, 3e3, 0, 0], [1e3, 0, 2e3, 0, 0], [0, -1.5e3, 2.5e3, 0, 0]]
    )
    for orientation, sign in (("+z", 1.0), ("-z", -1.0)):
        system = ShaftSystem(
            shaft,
            (
                BearingSeat("A", acbb.model, 0.02, orientation=orientation, source=acbb),
                BearingSeat("S", LinearBearing(np.diag([2e8, 2e8, 0, 0, 0])), 0.28, axial="floating"),
            ),
        )
        loads = ShaftLoads(
            ("a", "b", "c", "d"), forces=(PointLoad(0.15, forces * [1, 1, sign, 1, 1]),), speed=speeds
        )
        res = solve(system, loads)
        assert res.converged.all(), res.reason
        assert np.all(res.equilibrium_residual() <= 1e-9)
        seat = system.bearing("A")
        np.testing.assert_array_equal(seat.speed_of(speeds).inner, sign * speeds)
        q = res.relative_displacement("A")
        single = solve_bearing(
            acbb.model, np.zeros((4, 5)), free=[False] * 5, displacement=q, speed=seat.speed_of(speeds)
        )
        scale = np.abs(res.bearing_load("A")).max()
        assert np.abs(single.load - res.bearing_load("A")).max() <= 1e-9 * scale
        kmax = np.abs(single.stiffness).max()
        assert np.abs(single.stiffness - res.stiffness("A", frame="bearing")).max() <= 1e-9 * kmax
        inner = res.bearing_result("A").rows[0].extras["contact_angle_inner"]
        np.testing.assert_allclose(inner, single.rows[0].extras["contact_angle_inner"], atol=1e-9)
        # the speeds matter: case c (20,000 r/min) and case a (at rest) carry the same load
        assert res.stiffness("A")[2, 0, 0] < 0.9 * res.stiffness("A")[0, 0, 0]


def test_stiffness_export_reflects_speed(acbb):
    system = _pair(acbb)
    rest = shaft_stiffness_table(solve(system, _loads(None)), "A")
    fast_result = solve(system, _loads(20_000.0))
    fast = shaft_stiffness_table(fast_result, "A")
    np.testing.assert_allclose(fast.speeds, 20_000.0 * RPM)
    assert np.all(fast.radial()[:, 0, 0] < 0.9 * rest.radial()[:, 0, 0])
    # the table is the tangent of the single bearing at speed at the seat state (shaft frame, "+z")
    single = solve_bearing(
        acbb.model,
        np.zeros((3, 5)),
        free=[False] * 5,
        displacement=fast_result.relative_displacement("A"),
        speed=system.bearing("A").speed_of(fast_result.loads.speed),
    )
    assert np.abs(fast.stiffness - single.stiffness).max() <= 1e-9 * np.abs(single.stiffness).max()


def test_speed_beyond_the_ball_model_is_not_converged_with_the_reason(acbb):
    """A lightly preloaded pair far above its speed range: the shaft result says why, per case."""
    system = _pair(acbb, offset=1e-6)
    loads = ShaftLoads(
        ("slow", "absurd"),
        forces=(PointLoad(0.15, np.array([[200.0, 0, 0, 0, 0]] * 2)),),
        speed=np.array([1_000.0, 150_000.0]) * RPM,
    )
    res = solve(system, loads)
    assert res.converged[0]
    assert not res.converged[1]
    assert "high-speed ball model" in res.reason[1] and res.reason[1].startswith("bearing '")
    assert not res.bearing_result("A").converged[1]


def test_tapered_rows_at_several_speeds_are_one_solve_equal_to_each_speed_alone():
    """A shaft on two 32008 facing each other whose load cases run at different speeds (a load
    spectrum) is solved in one run; every case equals the same case solved alone at its speed
    (reactions, stiffness, displacements to 1e-9); the speeds matter at that precision."""
    trb = load_file(EXAMPLES / "trb_32008.toml")
    shaft = Shaft((Section(0.0, 0.3, 0.04),))
    system = ShaftSystem(
        shaft,
        (
            BearingSeat("front", trb.model, 0.02, orientation="+z", source=trb),
            BearingSeat("rear", trb.model, 0.28, orientation="-z", axial_offset=1e-5, source=trb),
        ),
    )
    force = np.array([[2e3, 0, 0, 0, 0], [2e3, 0, 0, 0, 0], [1e3, 500.0, 800.0, 0, 0]])
    rpm = np.array([100.0, 8000.0, 3000.0])
    loads = ShaftLoads(("a", "b", "c"), forces=(PointLoad(0.15, force),), speed=rpm * RPM)
    res = solve(system, loads)
    assert res.converged.all(), res.reason
    assert isinstance(res.model("front"), ModelAtSpeed)
    assert np.all(res.equilibrium_residual() <= 1e-9)
    for c in range(3):
        one = ShaftLoads(("x",), forces=(PointLoad(0.15, force[c : c + 1]),), speed=rpm[c : c + 1] * RPM)
        alone = solve(system, one)
        assert alone.converged.all(), alone.reason
        for b in ("front", "rear"):
            scale = np.abs(alone.reaction(b)).max()
            assert np.abs(res.reaction(b)[c] - alone.reaction(b)[0]).max() <= 1e-9 * scale
            k = alone.stiffness(b)
            assert np.abs(res.stiffness(b)[c] - k[0]).max() <= 1e-9 * np.abs(k).max()
        u = alone.displacement
        assert np.abs(res.displacement[c] - u[0]).max() <= 1e-9 * np.abs(u).max()
    # cases a and b carry the same load at 100 and 8000 r/min: the rollers' centrifugal force shows
    ka, kb = res.stiffness("front")[0], res.stiffness("front")[1]
    assert np.abs(kb - ka).max() > 1e-6 * np.abs(ka).max()
