"""Friction assembly: breakdowns add up, zero-speed limit, load monotonicity, units in keys."""

import dataclasses

import numpy as np
import pytest

from bearingkit.analysis.friction.components import COMPONENT_NAMES, OperatingPoint, friction_torque
from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings.common import eccentric_axial_load
from bearingkit.bearings.turntable import composite_turntable, yrt_turntable
from bearingkit.errors import InputError

LOADS = eccentric_axial_load(np.array([0.0, 1000.0, 3000.0, 6000.0]), 0.2, radial_load=2000.0)


@pytest.fixture(scope="module", params=["series", "total_approach"])
def solved(request):
    return solve(
        composite_turntable(clearance_axial_roller=0.0, clearance_axial_ball=-2e-6, pairing=request.param),
        LOADS,
    )


def test_breakdowns_add_up(solved):
    fr = friction_torque(solved, OperatingPoint.from_rpm(20, cage_mass=0.3))
    assert set(fr.components) == set(COMPONENT_NAMES)
    np.testing.assert_allclose(sum(fr.components.values()), fr.total, rtol=1e-12)
    np.testing.assert_allclose(sum(fr.by_row.values()), fr.total, rtol=1e-12)
    for name, elem in fr.per_element.items():
        np.testing.assert_allclose(elem.sum(axis=-1), fr.by_row[name], rtol=1e-12)
    np.testing.assert_allclose(fr.torque_inner, -fr.torque_outer)
    assert np.all(fr.torque_inner < 0)  # resists the inner ring turning +z
    assert np.all(fr.total > 0)


def test_zero_speed_is_load_dependent_part(solved):
    op0 = OperatingPoint(cage_mass=0.3)
    fr0 = friction_torque(solved, op0)
    assert np.all(np.isfinite(fr0.total))
    assert np.all(fr0.components["viscous_roller"] == 0) and np.all(fr0.components["viscous_ball"] == 0)
    # The limit ω → 0+: tiny speed gives the same torque (viscous → 0, boundary friction Λ → 0).
    tiny = friction_torque(solved, OperatingPoint(speed_inner=1e-9, cage_mass=0.3))
    np.testing.assert_allclose(tiny.total, fr0.total, rtol=1e-3)
    # Hysteresis (a Coulomb-type loss) does not depend on speed.
    fast = friction_torque(solved, OperatingPoint.from_rpm(60, cage_mass=0.3))
    np.testing.assert_allclose(fast.components["hysteresis_roller"], fr0.components["hysteresis_roller"])


def test_either_ring_rotating(solved):
    a = friction_torque(solved, OperatingPoint.from_rpm(10, 0))
    b = friction_torque(solved, OperatingPoint.from_rpm(0, -10))
    np.testing.assert_allclose(a.total, b.total, rtol=1e-10)
    np.testing.assert_allclose(a.torque_outer, b.torque_outer, rtol=1e-10)


@pytest.mark.parametrize("builder", [composite_turntable, yrt_turntable])
def test_doubling_load_never_lowers_torque(builder):
    fa = np.array([500.0, 1000.0, 2000.0, 4000.0, 8000.0])
    res = solve(builder(), eccentric_axial_load(fa, 0.1, radial_load=fa / 2))
    for rpm in (0, 5, 90):
        t = friction_torque(res, OperatingPoint.from_rpm(rpm)).total
        assert np.all(np.diff(t) >= 0)


def test_to_dict_units_and_batch_speeds(solved):
    fr = friction_torque(solved, OperatingPoint.from_rpm(np.array([5.0, 10.0, 20.0, 40.0])))
    d = fr.to_dict(0)
    assert {"total_Nm", "components_Nm", "rows_Nm", "torque_inner_Nm", "torque_outer_Nm"} <= set(d)
    assert d["total_Nm"] == pytest.approx(fr.total_Nm[0])
    assert "tian2025" in d["references"]
    assert len(fr.to_dict()) == solved.n_cases


def test_operating_point_validation():
    with pytest.raises(InputError):
        OperatingPoint(temperature=400.0)
    with pytest.raises(InputError):
        OperatingPoint(viscous_line_model="nope")
    with pytest.raises(InputError):
        OperatingPoint(roughness_element=0.0, roughness_raceway=0.0)
    with pytest.raises(InputError):
        OperatingPoint(lubricant="no-such-oil")


def test_model_variants_run():
    res = solve(composite_turntable(), load_vector(F_z=2000.0))
    a = friction_torque(
        res, OperatingPoint.from_rpm(30, viscous_line_model="aihara", viscous_point_model="houpert")
    )
    assert np.isfinite(a.total).all() and a.total[0] > 0


def test_seed000_validation_cases():
    import bearingkit.papers.tian2025.validation as s
    from bearingkit.validation.registry import all_cases, run_cases

    cases = all_cases(["seed000/table3/", "seed000/conclusion/"])
    assert len([c for c in cases if c.id.startswith("seed000/table3/")]) == 9
    results = {r.case.id: r for r in run_cases(cases)}
    # Calibration point is met (μ_rs was identified once on run 1) and is marked as a calibration.
    assert abs(results["seed000/table3/run1/friction-torque"].rel_error) < 2e-3
    assert results["seed000/table3/run1/friction-torque"].case.role == "calibration"
    assert {r.case.role for k, r in results.items() if k != "seed000/table3/run1/friction-torque"} == {
        "prediction"
    }
    for r in results.values():
        assert r.error is None, r.error
        if r.case.known_deviation is None:
            assert r.passed, (r.case.id, r.computed, r.case.published)
    from bearingkit.papers.tian2025 import friction as sf

    identified = sf.calibrated_sliding(dataclasses.replace(sf.VARIANTS["seed000"], roller_sliding=None))
    assert s.ROLLER_SLIDING == pytest.approx(identified, rel=2e-3)
    assert s.VISCOSITY_FACTOR == 1.0  # base oil: no longer calibrated
