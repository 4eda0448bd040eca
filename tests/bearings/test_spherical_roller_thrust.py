"""Spherical roller thrust bearing (292/293/294): one SphericalRollerRow at α ≈ 50°.

Closed forms: under a centric axial load every roller carries Q = F_a/(Z sin α_op) with α_op the
operating angle of its load line (the nominal α differs from it by the approach over the line length,
~1e-4); with a radial load the load zone shifts toward the load and the rollers' forces balance it.
"""

import numpy as np
import pytest

from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings import self_aligning as sa
from bearingkit.errors import InputError
from bearingkit.rows.self_aligning import SelfAligningBallRow, SphericalRollerRow

ALPHA = np.arctan(1.2)  # NSK E1102 B225: X = 1.2 = tan α (ISO 281 8.2)
Z = 15
FREE = [True, True, True, False, False]


def _model(**kw):
    geo = dict(n_elements=Z, element_diameter=0.016, effective_length=0.016, pitch_diameter=0.097)
    return sa.spherical_roller_thrust(**(geo | {"contact_angle": ALPHA} | kw))


def _residual(model, res):
    total = sum(k.response(res.displacement).force for k in model.kernels)
    scale = np.abs(res.load).max(axis=1)
    return (np.abs(res.load + total)[:, res.free] / scale[:, None]).max(axis=1)


def test_pure_axial_load_every_roller_carries_fa_over_z_sin_alpha():
    fa = np.array([10e3, 100e3, 400e3])
    model = _model()
    res = solve(model, load_vector(F_z=fa), free=FREE)
    assert res.converged.all()
    st = res.rows[0]
    np.testing.assert_allclose(
        st.load * Z * np.sin(st.contact_angle), fa[:, None] * np.ones((1, Z)), rtol=1e-9
    )
    np.testing.assert_allclose(st.load, st.load[:, :1] * np.ones((1, Z)), rtol=1e-12)
    # the nominal angle: within the change of the line's direction under the approach (< 1e-3)
    np.testing.assert_allclose(st.load, (fa / (Z * np.sin(ALPHA)))[:, None] * np.ones((1, Z)), rtol=1e-3)
    row = res.row_load("rollers")
    assert np.abs(row[:, :2]).max() <= 1e-9 * fa.max()  # no radial force
    assert np.abs(res.displacement[:, :2]).max() < 1e-15
    assert (_residual(model, res) <= 1e-9).all()


def test_radial_load_shifts_the_load_zone_and_is_balanced():
    model = _model()
    fa = 100e3
    fr = np.array([10e3, 20e3, 30e3])  # below F_r = 0.55 F_a, the makers' limit, where rollers unload
    res = solve(model, load_vector(F_z=fa, F_x=fr), free=FREE)
    assert res.converged.all()
    assert (_residual(model, res) <= 1e-9).all()
    np.testing.assert_allclose(res.row_load("rollers")[:, :3], res.load[:, :3], rtol=1e-9, atol=1e-9 * fa)
    q = res.rows[0].load
    psi = res.rows[0].azimuth
    assert (np.argmax(q, axis=1) == np.argmin(np.abs(np.angle(np.exp(1j * psi))))).all()  # peak at ψ = 0 (+x)
    spread = q.max(axis=1) / q.min(axis=1)
    assert (np.diff(spread) > 0).all()  # the larger F_r, the more uneven the zone
    assert (res.displacement[:, 0] > 0).all()  # the shaft washer moves toward the load


def test_moment_on_a_free_tilt_is_refused_and_a_tilt_changes_nothing():
    model = _model()
    with pytest.raises(Exception, match="theta_y"):
        solve(model, load_vector(F_z=50e3, M_y=10.0))
    straight = solve(model, load_vector(F_z=50e3, F_x=10e3), free=FREE)
    tilted = solve(model, load_vector(F_z=50e3, F_x=10e3), free=FREE, displacement=[0, 0, 0, 0.02, -0.01])
    np.testing.assert_allclose(tilted.rows[0].load, straight.rows[0].load, rtol=1e-9)


def test_contact_angle_bounds():
    with pytest.raises(InputError, match=r"^contact_angle"):
        _model(contact_angle=np.radians(40.0))  # a radial angle: the double-row builder's
    with pytest.raises(InputError, match=r"^contact_angle"):
        _model(contact_angle=np.radians(80.0))
    with pytest.raises(InputError, match=r"^contact_angle"):
        sa.spherical_roller(
            n_elements=17,
            element_diameter=0.02,
            effective_length=0.02,
            pitch_diameter=0.14,
            contact_angle=ALPHA,
        )
    with pytest.raises(InputError, match=r"^contact_angle"):
        SelfAligningBallRow(n_elements=15, element_diameter=0.0127, pitch_diameter=0.072, contact_angle=ALPHA)
    with pytest.raises(InputError, match=r"^contact_angle"):
        SphericalRollerRow(
            n_elements=Z,
            element_diameter=0.016,
            effective_length=0.016,
            pitch_diameter=0.097,
            contact_angle=np.radians(81.0),
        )


def test_approach_and_angle_equal_the_sphere_geometry_by_hand():
    """The kernel's δ_j and operating angle against the geometry written out: sphere centre O on the
    axis, R_o = d_m/(2 cos α) + D_w/2, inner profile centre P_j at L₀ = R_o + R_i − D_w along
    m_j = (cos α cos ψ_j, cos α sin ψ_j, sin α), moved by the washer's translation u: δ_j = |P_j − O| − L₀
    and the load line's angle atan2(z, r) of P_j − O, for a shaft washer moved along and across the axis.
    As every row of the engine, the element stays in its azimuth plane: the washer's tangential motion
    u_t = −u_x sin ψ + u_y cos ψ is left out (it changes |P_j − O| by u_t²/(2 L₀), 2e-5 of δ here)."""
    row = _model().rows[0]
    d_m, d_w, a = row.pitch_diameter, row.element_diameter, row.contact_angle
    r_o = d_m / (2 * np.cos(a)) + d_w / 2
    r_i = 0.98 * r_o / 0.98  # R_r = 0.98 R_o (osculation_outer), R_i = R_r / 0.98 (osculation_inner)
    l0 = r_o + r_i - d_w
    u = np.array([[0.0, 0.0, 30e-6, 0.0, 0.0], [12e-6, -5e-6, 40e-6, 0.01, 0.0]])
    st = row.kernel().state(u)
    psi = 2 * np.pi * np.arange(Z) / Z
    m = np.stack([np.cos(a) * np.cos(psi), np.cos(a) * np.sin(psi), np.full(Z, np.sin(a))], axis=-1)
    p = l0 * m[None] + u[:, None, :3]  # a tilt about O moves no P_j off its sphere: it does not enter
    r = p[..., 0] * np.cos(psi) + p[..., 1] * np.sin(psi)  # in the azimuth plane (u_t dropped)
    np.testing.assert_allclose(st.deflection, np.hypot(r, p[..., 2]) - l0, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(st.contact_angle, np.arctan2(p[..., 2], r), rtol=1e-12)
    full = np.linalg.norm(p, axis=-1) - l0  # with u_t: second order, within 3e-5 of δ
    np.testing.assert_allclose(st.deflection, full, rtol=3e-5)
    assert r_o == pytest.approx(row.outer_radius, rel=1e-15) and l0 == pytest.approx(row.touch_distance)
