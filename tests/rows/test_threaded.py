"""Threaded (PTRB) row: geometry validation, equivalent-ball curvatures, kernel derivatives, distributions."""

import numpy as np
import pytest

from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings.ptrb import ptrb_model, ptrb_prototype
from bearingkit.errors import InputError
from bearingkit.physics.contact import hertz
from bearingkit.physics.life.ptrb_rating import thread_contact_curvature
from bearingkit.rows.threaded.row import (
    ThreadedRow,
    axial_tooth_distribution,
    contact_pairs,
    radial_roller_distribution,
)


def test_prototype_derived_geometry():
    g = ptrb_prototype()
    assert g.element_diameter == pytest.approx(6e-3 / np.cos(np.pi / 4))  # "8.5 mm" of the paper
    assert g.d_inner == pytest.approx(g.pitch_diameter - g.roller_pitch_diameter)
    assert g.d_outer == pytest.approx(g.pitch_diameter + g.roller_pitch_diameter)


@pytest.mark.parametrize(
    "changes, word",
    [
        ({"contact_radius_inner": 5.0e-3}, "contact_radius_inner"),
        ({"contact_radius_outer": 4.0e-3}, "contact_radius_outer"),
        ({"contact_angle": 0.0}, "contact_angle"),
        ({"contact_angle": np.pi / 2}, "contact_angle"),
        ({"n_teeth": 16}, "n_teeth"),  # 16 × 1.2 mm > 18 mm
        ({"ridge_thickness": 1.3e-3}, "ridge_thickness"),
        ({"n_elements": 30}, "n_elements"),
    ],
)
def test_bad_geometry_raises(changes, word):
    with pytest.raises(InputError, match=word):
        ptrb_prototype(**changes)


def test_curvature_reduces_to_ball_in_groove():
    """R_rr = D_w/2 and the circumferential planes reproduce Harris' ball–raceway curvatures."""
    dw, dm, alpha, r = 8e-3, 40e-3, 0.5, 4.2e-3
    d_r = dw * np.cos(alpha)
    for side, d_x in (("inner", dm - d_r), ("outer", dm + d_r)):
        s, f, _, _ = thread_contact_curvature(d_r, d_x, dw / 2, r, alpha, side)
        s_ref, f_ref = hertz.ball_raceway_curvature(dw, dm, alpha, r, side)
        assert s == pytest.approx(s_ref, rel=1e-12)
        assert f == pytest.approx(f_ref, rel=1e-12)


def test_flat_flank_sensitivity_direction():
    """A conforming ring flank (finite r_I) lowers Σρ and the pressure at equal load."""
    flat = contact_pairs(ptrb_prototype(), 500.0)
    arc = contact_pairs(ptrb_prototype(contact_radius_inner=75e-3, contact_radius_outer=75e-3), 500.0)
    for side in ("inner", "outer"):
        assert arc[side].curvature_sum < flat[side].curvature_sum
        assert arc[side].max_pressure < flat[side].max_pressure
    assert flat["inner"].max_pressure > flat["outer"].max_pressure  # ITP is the critical pair


def test_kernel_derivatives():
    row = ThreadedRow(ptrb_prototype(), clearance=-2e-6, axial_position=1e-3, azimuth_phase=0.2)
    k = row.kernel()
    rng = np.random.default_rng(1)
    q = rng.normal(size=(3, 5)) * np.array([2e-6, 2e-6, 2e-6, 1e-4, 1e-4])
    r0 = k.response(q)
    for i in range(5):
        h = np.zeros(5)
        h[i] = 1e-9 if i < 3 else 1e-7
        rp, rm = k.response(q + h), k.response(q - h)
        fd = (rp.force - rm.force) / (2 * h[i])
        np.testing.assert_allclose(r0.jacobian[:, :, i], fd, rtol=1e-5, atol=1e-3 * np.abs(fd).max())
        de = (rp.energy - rm.energy) / (2 * h[i])
        np.testing.assert_allclose(r0.force[:, i], -de, rtol=1e-5, atol=1e-6 * np.abs(de).max())


def test_engine_pure_radial_matches_stribeck_sum():
    model = ptrb_model()
    fr = np.array([2e3, 10e3])
    res = solve(model, load_vector(F_x=fr))
    assert res.converged.all()
    st = res.row("threaded")
    g = ptrb_prototype()
    radial_force = st.load * np.cos(g.contact_angle)  # Σ Q cos α of each roller
    share, _ = radial_roller_distribution(g.n_elements, 0.0)
    np.testing.assert_allclose(
        radial_force / fr[:, None], np.broadcast_to(share, radial_force.shape), atol=1e-6
    )
    # both flanks of every tooth of a roller carry the same load under a radial load
    tl = st.extras["tooth_load"]
    np.testing.assert_allclose(tl[..., 0], tl[..., 1], rtol=1e-8, atol=1e-9)


def test_engine_pure_axial_equal_shares():
    g = ptrb_prototype()
    res = solve(ptrb_model(), load_vector(F_z=np.array([5e3])))
    tl = res.row("threaded").extras["tooth_load"]
    loaded = tl.max(axis=-1)
    expected = 5e3 / (g.n_elements * g.n_teeth * np.sin(g.contact_angle))
    np.testing.assert_allclose(loaded, expected, rtol=1e-6)
    assert np.all(tl.min(axis=-1) == 0.0)  # the opposite flank is unloaded


def test_stribeck_limit():
    _, f_max = radial_roller_distribution(400, 0.0)
    assert f_max[0] * 400 == pytest.approx(4.37, abs=0.01)


def test_axial_distribution_equilibrium_and_trend():
    g = ptrb_prototype()
    d = axial_tooth_distribution(g, np.array([1e3, 10e3, 38e3]))
    assert d.converged.all()
    np.testing.assert_allclose(d.fa_inner.sum(axis=1), g.n_teeth, rtol=1e-9)
    np.testing.assert_allclose(d.fa_outer.sum(axis=1), g.n_teeth, rtol=1e-9)
    assert np.all(d.fa_max >= 1.0)
    # Hertz contacts stiffen with load, so the core compliance matters more: less uniform at high load
    assert np.all(np.diff(d.fa_max) > 0)
    # the inner ring is loaded at the tooth-0 end: its first tooth is the most loaded ITP tooth
    assert np.all(np.argmax(d.fa_inner, axis=1) == 0)


def test_axial_distribution_stiff_cores_uniform():
    """The core compliance per pitch is P/(EA): a 4× shorter pitch cuts the spread roughly 4×."""
    g = ptrb_prototype()
    short = ptrb_prototype(thread_pitch=0.3e-3, ridge_thickness=0.15e-3)
    assert axial_tooth_distribution(short, 10e3).fa_max[0] < axial_tooth_distribution(g, 10e3).fa_max[0]
    assert axial_tooth_distribution(short, 10e3).fa_max[0] - 1 < 0.35 * (
        axial_tooth_distribution(g, 10e3).fa_max[0] - 1
    )


def test_axial_distribution_bad_input():
    with pytest.raises(InputError, match="load_axial"):
        axial_tooth_distribution(ptrb_prototype(), -1.0)
    with pytest.raises(InputError, match="ring_support"):
        axial_tooth_distribution(ptrb_prototype(), 1e3, ring_support="middle")


def test_threaded_rows_solve_batches_that_converge_at_different_iterations():
    from bearingkit.analysis.solver.quasistatic import load_vector, solve
    from bearingkit.bearings.ptrb import ptrb_model

    res = solve(ptrb_model(), load_vector(F_z=[1000.0, 5000.0, 20000.0], F_x=[0.0, 2000.0, 500.0]))
    assert res.converged.all() and len(set(res.iterations.tolist())) > 1
    np.testing.assert_allclose(res.row_load(res.rows[0].name)[:, 2], [1000.0, 5000.0, 20000.0], rtol=1e-8)
