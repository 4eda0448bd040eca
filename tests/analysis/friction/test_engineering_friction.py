"""Tests of the engineering friction models (SKF four-component, Palmgren) and their registry."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingkit.analysis.friction import engineering as fm
from bearingkit.bearings.standard import (
    angular_contact_ball,
    cylindrical_roller,
    cylindrical_roller_thrust,
    deep_groove_ball,
    thrust_ball,
)
from bearingkit.errors import InputError
from bearingkit.physics.friction import palmgren as pg
from bearingkit.physics.friction import skf, skf_terms

RPM = 2.0 * np.pi / 60.0
# 6208-like deep groove ball bearing (d 40, D 80 mm), SI.
DGBB = dict(bore_diameter=0.040, outside_diameter=0.080, series="62")


def _dgbb(**kw):
    args = dict(DGBB, speed=1500 * RPM, kinematic_viscosity=20e-6, load_radial=3000.0, lubrication="oil_jet")
    args.update(kw)
    return skf.skf_friction_moment("deep_groove_ball", **args)


def test_skf_matches_catalogue_formulas_in_skf_units():
    """Closed form written out in SKF units (N·mm, mm, r/min, mm²/s): the SI boundary converts right."""
    n, nu, dm, d, big_d, fr = 1500.0, 20.0, 60.0, 40.0, 80.0, 3000.0
    r1, s1 = 3.9e-7, 3.23e-3
    phi_ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = 1 / np.exp(3e-8 * nu * n * (d + big_d) * np.sqrt(3.1 / (2 * (big_d - d))))
    m_rr = phi_ish * phi_rs * r1 * dm**1.96 * fr**0.54 * (nu * n) ** 0.6
    phi_bl = 1 / np.exp(2.6e-8 * (n * nu) ** 1.4 * dm)
    m_sl = s1 * dm**-0.26 * fr ** (5 / 3) * (phi_bl * 0.15 + (1 - phi_bl) * 0.05)
    r = _dgbb()
    assert r["rolling_Nm"] == pytest.approx(m_rr * 1e-3, rel=1e-12)
    assert r["sliding_Nm"] == pytest.approx(m_sl * 1e-3, rel=1e-12)


def test_breakdown_adds_up_with_seal_and_drag():
    r = _dgbb(
        lubrication="oil_bath",
        oil_level=0.03,
        drag_loss_factor=2e-4,
        seal="RS1",
        seal_counterface_diameter=0.052,
        speed=np.array([0.0, 500.0, 3000.0]) * RPM,
    )
    parts = r["rolling_Nm"] + r["sliding_Nm"] + r["seal_Nm"] + r["drag_Nm"]
    np.testing.assert_allclose(parts, r["total_Nm"], rtol=1e-14)
    assert np.all(r["seal_Nm"] > 0) and r["drag_Nm"][2] > r["drag_Nm"][1] > 0


def test_rolling_moment_scales_with_nu_n_to_0_6_before_inlet_shear():
    speeds = np.array([300.0, 1200.0, 4800.0])
    r = _dgbb(speed=speeds * RPM)
    bare = r["rolling_Nm"] / (r["phi_ish"] * r["phi_rs"])
    np.testing.assert_allclose(bare / bare[0], (speeds / speeds[0]) ** 0.6, rtol=1e-12)
    # the same scaling with viscosity at fixed speed
    nus = np.array([5e-6, 20e-6, 80e-6])
    r = _dgbb(kinematic_viscosity=nus)
    bare = r["rolling_Nm"] / (r["phi_ish"] * r["phi_rs"])
    np.testing.assert_allclose(bare / bare[0], (nus / nus[0]) ** 0.6, rtol=1e-12)


def test_zero_speed_gives_load_dependent_part_only():
    r = _dgbb(speed=0.0, load_radial=np.array([1000.0, 4000.0]))
    assert np.all(r["rolling_Nm"] == 0) and np.all(r["drag_Nm"] == 0)
    np.testing.assert_allclose(r["mu_sl"], skf_terms.MU_BL)
    g_sl = 3.23e-3 * 60.0**-0.26 * np.array([1000.0, 4000.0]) ** (5 / 3)
    np.testing.assert_allclose(r["total_Nm"], g_sl * skf_terms.MU_BL * 1e-3, rtol=1e-12)


@settings(max_examples=40, deadline=None)
@given(
    fr=st.floats(10.0, 2e4),
    factor=st.floats(1.0, 4.0),
    fa=st.floats(0.0, 5e3),
    rpm=st.floats(0.0, 1e4),
    btype=st.sampled_from(["deep_groove_ball", "cylindrical_roller", "angular_contact_ball"]),
)
def test_torque_never_falls_with_load(fr, factor, fa, rpm, btype):
    kw = dict(
        bore_diameter=0.04,
        outside_diameter=0.08,
        speed=rpm * RPM,
        kinematic_viscosity=30e-6,
        load_radial=np.array([fr, factor * fr]),
        load_axial=np.array([fa, factor * fa]),
        static_rating=19000.0,
    )
    m = skf.skf_friction_moment(btype, **kw)["total_Nm"]
    assert m[1] >= m[0] * (1 - 1e-12)


@pytest.mark.parametrize("btype", ["thrust_ball", "cylindrical_roller_thrust"])
def test_thrust_torque_rises_with_axial_load(btype):
    m = skf.skf_friction_moment(
        btype,
        bore_diameter=0.04,
        outside_diameter=0.06,
        speed=1000 * RPM,
        kinematic_viscosity=30e-6,
        load_axial=np.array([500.0, 1000.0, 2000.0]),
    )["total_Nm"]
    assert np.all(np.diff(m) > 0)
    with pytest.raises(InputError, match="load_radial"):
        skf.skf_friction_moment(
            btype,
            bore_diameter=0.04,
            outside_diameter=0.06,
            speed=1.0,
            kinematic_viscosity=30e-6,
            load_radial=10.0,
            load_axial=100.0,
        )


def test_skf_factors_decrease_with_speed_and_stay_in_unit_interval():
    r = _dgbb(speed=np.array([10.0, 1e3, 1e4, 3e4]) * RPM, lubrication="grease")
    for key in ("phi_ish", "phi_rs", "phi_bl"):
        assert np.all((r[key] > 0) & (r[key] <= 1)) and np.all(np.diff(r[key]) < 0)
    # grease (K_rs 6e-8) starves more than oil jet (3e-8)
    oil = _dgbb(speed=1e4 * RPM, lubrication="oil_jet")
    grease = _dgbb(speed=1e4 * RPM, lubrication="grease")
    assert grease["phi_rs"] < oil["phi_rs"]


def test_one_seal_is_half_of_two():
    two = _dgbb(seal="RS1", seal_counterface_diameter=0.052)
    one = _dgbb(seal="RS1", seal_counterface_diameter=0.052, n_seals=1)
    assert one["seal_Nm"] == pytest.approx(0.5 * two["seal_Nm"]) and two["seal_Nm"] > 0


def test_drag_without_vm_uses_the_approximation_and_vanishes_at_rest():
    from bearingkit.physics.friction.skf_drag import drag_loss_factor

    approx = _dgbb(lubrication="oil_bath", oil_level=0.02)
    d_m = 0.5 * (0.040 + 0.080)  # the bearing of _dgbb
    given = _dgbb(lubrication="oil_bath", oil_level=0.02, drag_loss_factor=drag_loss_factor(0.02, d_m, False))
    assert np.all(approx["drag_Nm"] > 0)
    np.testing.assert_allclose(approx["drag_Nm"], given["drag_Nm"], rtol=1e-12)
    r = _dgbb(lubrication="oil_bath", oil_level=0.02, drag_loss_factor=1e-4, speed=0.0)
    assert r["drag_Nm"] == 0.0


def test_unknown_type_lists_the_types():
    with pytest.raises(InputError) as err:
        fm.engineering_friction_moment("skf", "spherical_plain", **DGBB)
    for name in ("deep_groove_ball", "cylindrical_roller", "thrust_ball"):
        assert name in str(err.value)
    with pytest.raises(InputError, match="palmgren"):
        fm.engineering_friction_moment("coulomb", "deep_groove_ball")
    with pytest.raises(InputError, match="62"):
        _dgbb(series="99")


def test_bad_inputs_raise():
    with pytest.raises(InputError, match="outside_diameter"):
        _dgbb(outside_diameter=0.03)
    with pytest.raises(InputError, match="kinematic_viscosity"):
        _dgbb(kinematic_viscosity=0.0)
    with pytest.raises(InputError, match="static_rating"):
        skf.skf_friction_moment(
            "deep_groove_ball",
            **DGBB,
            speed=100.0,
            kinematic_viscosity=2e-5,
            load_radial=1.0,
            load_axial=100.0,
        )
    with pytest.raises(InputError, match="lubrication"):
        _dgbb(lubrication="splash")


# --- Palmgren -------------------------------------------------------------------------------------
def test_palmgren_closed_form_and_branch_continuity():
    dm = 0.06
    r = pg.palmgren_friction_moment(
        "cylindrical_roller",
        pitch_diameter=dm,
        speed=1500 * RPM,
        kinematic_viscosity=20e-6,
        load_radial=5000.0,
        f0=3.0,
    )
    m0 = 1e-7 * 3.0 * (20 * 1500) ** (2 / 3) * 60.0**3
    assert r["viscous_Nm"] == pytest.approx(m0 * 1e-3, rel=1e-12)
    assert r["load_Nm"] == pytest.approx(0.00025 * 5000.0 * 60.0 * 1e-3, rel=1e-12)
    # the two M0 branches meet within 1 % at nu n = 2000 (2000^(2/3) = 158.7 vs 160)
    lo = pg.viscous_moment(1.0, 1999.999, 60.0)
    hi = pg.viscous_moment(1.0, 2000.0, 60.0)
    assert abs(hi / lo - 1) < 0.01


def test_palmgren_load_part_rises_and_zero_speed_is_low_speed_branch():
    r = pg.palmgren_friction_moment(
        "deep_groove_ball",
        pitch_diameter=0.06,
        speed=0.0,
        kinematic_viscosity=20e-6,
        load_radial=np.array([1000.0, 2000.0, 4000.0]),
        static_rating=19000.0,
    )
    assert np.all(np.diff(r["load_Nm"]) > 0)
    np.testing.assert_allclose(r["viscous_Nm"], 160e-7 * 2.0 * 60.0**3 * 1e-3)
    np.testing.assert_allclose(r["viscous_Nm"] + r["load_Nm"], r["total_Nm"])


def test_palmgren_needs_rating_and_angle():
    with pytest.raises(InputError, match="static_rating"):
        pg.palmgren_friction_moment(
            "deep_groove_ball", pitch_diameter=0.06, speed=1.0, kinematic_viscosity=2e-5
        )
    with pytest.raises(InputError, match="contact_angle"):
        pg.palmgren_friction_moment(
            "angular_contact_ball",
            pitch_diameter=0.06,
            speed=1.0,
            kinematic_viscosity=2e-5,
            static_rating=1e4,
        )
    with pytest.raises(InputError, match="oil_bath"):
        pg.palmgren_friction_moment(
            "deep_groove_ball",
            pitch_diameter=0.06,
            speed=1.0,
            kinematic_viscosity=2e-5,
            lubrication="oil_air",
            static_rating=1e4,
        )


# --- from a bearingkit bearing model --------------------------------------------------------------
BUILDERS = {
    "deep_groove_ball": lambda: deep_groove_ball(n_elements=9, element_diameter=12.7e-3, pitch_diameter=0.06),
    "angular_contact_ball": lambda: angular_contact_ball(
        n_elements=12, element_diameter=11e-3, pitch_diameter=0.06, contact_angle=np.radians(40)
    ),
    "thrust_ball": lambda: thrust_ball(n_elements=15, element_diameter=7.9e-3, pitch_diameter=0.05),
    "cylindrical_roller": lambda: cylindrical_roller(
        n_elements=13, element_diameter=11e-3, effective_length=11e-3, pitch_diameter=0.06
    ),
    "cylindrical_roller_thrust": lambda: cylindrical_roller_thrust(
        n_elements=18, element_diameter=5e-3, effective_length=5e-3, pitch_diameter=0.05
    ),
}


@pytest.mark.parametrize("btype", list(BUILDERS))
@pytest.mark.parametrize("model", ["skf", "palmgren"])
def test_engineering_torque_of_standard_bearings(btype, model):
    bearing = BUILDERS[btype]()
    assert fm.bearing_type_of(bearing) == btype
    thrust = btype in ("thrust_ball", "cylindrical_roller_thrust")
    loads = np.array([1000.0, 2000.0])
    kw = dict(load_axial=loads) if thrust else dict(load_radial=loads, load_axial=0.1 * loads)
    res = fm.engineering_friction_torque(
        bearing, speed=1000 * RPM, lubricant="ISO_VG68", temperature=50.0, model=model, **kw
    )
    assert res.bearing_type == btype
    np.testing.assert_allclose(sum(res.components.values()), res.total, rtol=1e-12)
    assert np.all(res.total > 0) and res.total[1] >= res.total[0]
    d = res.to_dict()
    assert "total_Nm" in d and all(f"{c}_Nm" in d for c in fm.MODEL_COMPONENTS[model])
    assert any("estimated" in n for n in res.notes)


def test_engineering_torque_uses_given_dimensions_and_matches_direct_call():
    bearing = BUILDERS["deep_groove_ball"]()
    res = fm.engineering_friction_torque(
        bearing,
        load_radial=3000.0,
        speed=1500 * RPM,
        lubricant="ISO_VG68",
        temperature=60.0,
        bore_diameter=0.04,
        outside_diameter=0.08,
        series="62",
        lubrication="oil_jet",
    )
    from bearingkit.lubricants import get_lubricant

    direct = _dgbb(kinematic_viscosity=get_lubricant("ISO_VG68").kinematic_viscosity(60.0))
    assert res.total == pytest.approx(direct["total_Nm"], rel=1e-12)
    assert not any("estimated" in n for n in res.notes)


def test_multi_row_bearing_is_refused():
    from bearingkit.bearings.standard import angular_contact_pair

    pair = angular_contact_pair(
        arrangement="DB",
        n_elements=12,
        element_diameter=11e-3,
        pitch_diameter=0.06,
        contact_angle=np.radians(40),
        row_spacing=0.03,
    )
    with pytest.raises(InputError, match="single-row"):
        fm.engineering_friction_torque(pair, speed=1.0, lubricant="ISO_VG68", temperature=40.0)


def test_validation_cases_pass():
    from bearingkit.validation.registry import all_cases, failures, run_cases

    cases = all_cases(["skf/", "palmgren/"])
    assert len(cases) >= 4
    assert not failures(run_cases(cases))
