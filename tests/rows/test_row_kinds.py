"""The row kinds of issue 17: derivatives, equilibrium, symmetry and closed-form load distributions.

Four-point contact ball rows (floating ball, four contacts), crossed roller rows, spherical roller and
self-aligning ball rows (lines through the sphere centre) and needle rows.
"""

import numpy as np
import pytest

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings import self_aligning as sa
from bearingkit.bearings import slewing
from bearingkit.physics.contact.profiles import make_profile
from bearingkit.rows.ball.four_point import FourPointRow
from bearingkit.rows.ball.row import BallRow
from bearingkit.rows.cylindrical.crossed import CrossedRollerRow
from bearingkit.rows.cylindrical.needle import NeedleRow
from bearingkit.rows.cylindrical.row import CylindricalRow
from bearingkit.rows.self_aligning import SelfAligningBallRow, SphericalRollerRow

E_RED = 2.28e11  # [Pa] any positive value: the identities tested do not depend on it
DEG = np.pi / 180


def _four_point(clearance):
    return FourPointRow(
        n_elements=20,
        element_diameter=0.02,
        pitch_diameter=0.5,
        contact_angle=45 * DEG,
        clearance=clearance,
        axial_position=0.004,
        azimuth_phase=0.1,
        e_reduced=E_RED,
    )


def _srb(alpha=10 * DEG, clearance=-5e-6, **kw):
    return SphericalRollerRow(
        n_elements=17,
        element_diameter=0.020,
        effective_length=0.020,
        pitch_diameter=0.14,
        contact_angle=alpha,
        clearance=clearance,
        e_reduced=E_RED,
        **kw,
    )


def _sabb(alpha=12 * DEG, clearance=-3e-6):
    return SelfAligningBallRow(
        n_elements=15,
        element_diameter=0.0127,
        pitch_diameter=0.072,
        contact_angle=alpha,
        clearance=clearance,
        e_reduced=E_RED,
    )


def _rows():
    yield "four_point-preload", _four_point(-4e-6), 1.0
    yield "four_point-zero", _four_point(0.0), 1.0
    yield "four_point-clearance", _four_point(20e-6), 10.0
    yield (
        "crossed",
        CrossedRollerRow(
            n_elements=60,
            element_diameter=0.012,
            effective_length=0.010,
            pitch_diameter=0.4,
            clearance=-2e-6,
            n_slices=7,
            e_reduced=E_RED,
            profile=make_profile("full_crown", effective_length=0.010, element_diameter=0.012),
        ),
        1.0,
    )
    yield "spherical_roller", _srb(), 1.0
    yield "spherical_roller_thrust", _srb(alpha=np.arctan(1.2), clearance=0.0), 1.0
    yield "self_aligning_ball", _sabb(), 1.0
    yield (
        "needle",
        NeedleRow(
            n_elements=30,
            element_diameter=0.003,
            effective_length=0.016,
            pitch_diameter=0.053,
            n_slices=8,
            clearance=-2e-6,
            e_reduced=E_RED,
        ),
        0.3,
    )


ROWS = list(_rows())
IDS = [r[0] for r in ROWS]
STEPS = np.array([1e-10, 1e-10, 1e-10, 1e-9, 1e-9])


def _q(seed, n, scale):
    return np.random.default_rng(seed).normal(size=(n, 5)) * np.array([3e-6, 3e-6, 3e-6, 1e-5, 1e-5]) * scale


@pytest.mark.parametrize("name,row,scale", ROWS, ids=IDS)
def test_jacobian_matches_finite_differences(name, row, scale):
    kernel = row.kernel()
    q = _q(1, 4, scale)
    jac = kernel.response(q).jacobian
    fd = np.empty_like(jac)
    for i in range(5):
        dq = np.zeros(5)
        dq[i] = STEPS[i]
        fd[:, :, i] = (kernel.response(q + dq).force - kernel.response(q - dq).force) / (2 * STEPS[i])
    assert np.abs(fd).max() > 0
    # Central differences of δ^1.5 / δ^(10/9) laws with 1e-10 m steps: truncation ~1e-6 of the largest
    # entry (slice or contact kinks inside the step); the tolerance is the one of the existing row kinds.
    np.testing.assert_allclose(jac, fd, atol=1e-5 * np.abs(fd).max(), rtol=1e-4)


@pytest.mark.parametrize("name,row,scale", ROWS, ids=IDS)
def test_force_is_minus_energy_gradient(name, row, scale):
    kernel = row.kernel()
    q = _q(2, 3, scale)
    force = kernel.response(q).force
    for i in range(5):
        dq = np.zeros(5)
        dq[i] = STEPS[i]
        grad = (kernel.response(q + dq).energy - kernel.response(q - dq).energy) / (2 * STEPS[i])
        np.testing.assert_allclose(-grad, force[:, i], rtol=1e-4, atol=1e-6 * np.abs(force).max())


@pytest.mark.parametrize("name,row,scale", ROWS, ids=IDS)
def test_jacobian_symmetric_negative_semidefinite(name, row, scale):
    jac = row.kernel().response(_q(3, 5, scale)).jacobian
    np.testing.assert_allclose(jac, np.swapaxes(jac, 1, 2), atol=1e-9 * np.abs(jac).max())
    assert np.linalg.eigvalsh(jac).max() <= 1e-9 * np.abs(jac).max()


def _residual(model, res):
    """|F + Σ row forces| / load scale, recomputed from the rows (not the solver's own number)."""
    total = sum(k.response(res.displacement).force for k in model.kernels)
    scale = np.maximum(np.abs(res.load).max(axis=1), 1.0)
    free = res.free
    return (np.abs(res.load + total)[:, free] / scale[:, None]).max(axis=1)


MODELS = {
    "qj": slewing.four_point_contact_ball(n_elements=16, element_diameter=0.0127, pitch_diameter=0.065),
    "slewing_4pt": slewing.slewing_ring_four_point(n_elements=80, element_diameter=0.025, pitch_diameter=1.0),
    "slewing_8pt": slewing.slewing_ring_eight_point(
        n_elements=70, element_diameter=0.025, pitch_diameter=1.0, row_spacing=0.05
    ),
    "slewing_crossed": slewing.slewing_ring_crossed_roller(
        n_elements=120, element_diameter=0.016, effective_length=0.014, pitch_diameter=0.8
    ),
    "srb": sa.spherical_roller(
        n_elements=17,
        element_diameter=0.020,
        effective_length=0.020,
        pitch_diameter=0.14,
        contact_angle=10 * DEG,
    ),
    "sabb": sa.self_aligning_ball(
        n_elements=15, element_diameter=0.0127, pitch_diameter=0.072, contact_angle=12 * DEG
    ),
    "needle": sa.needle_roller(
        n_elements=30, element_diameter=0.003, effective_length=0.016, pitch_diameter=0.053
    ),
}
#: Load cases per model (F_x, F_z, M_y), scaled to each bearing's size; moments only where carried.
CASES = {
    "qj": load_vector(F_x=[3e3, 0, 2e3], F_z=[0, 4e3, 3e3]),
    "slewing_4pt": load_vector(F_x=[20e3, 0, 10e3], F_z=[0, 200e3, 100e3], M_y=[0, 0, 150e3]),
    "slewing_8pt": load_vector(F_x=[20e3, 0, 10e3], F_z=[0, 200e3, 100e3], M_y=[0, 0, 150e3]),
    "slewing_crossed": load_vector(F_x=[20e3, 0, 10e3], F_z=[0, 100e3, 50e3], M_y=[0, 0, 30e3]),
    "srb": load_vector(F_x=[50e3, 0, 40e3], F_z=[0, 20e3, 10e3]),
    "sabb": load_vector(F_x=[4e3, 0, 3e3], F_z=[0, 1e3, 0.8e3]),
    "needle": load_vector(F_x=[5e3, 8e3]),
}


@pytest.mark.parametrize("key", list(MODELS))
def test_equilibrium_residual_below_1e9_of_load(key):
    model, load = MODELS[key], CASES[key]
    free = None
    if key in ("qj", "srb", "sabb", "needle"):
        free = [True, True, True, False, False]  # single bearings: the tilt is held by the shaft
    res = solve(model, load, free=free)
    assert res.converged.all(), res.reason
    assert (_residual(model, res) <= 1e-9).all()
    for st in res.rows:
        assert np.isfinite(st.load).all() and np.isfinite(st.max_pressure).all()


# --- four-point contact ---------------------------------------------------------------------------------
def _slewing(clearance=0.0, z=80):
    return slewing.slewing_ring_four_point(
        n_elements=z, element_diameter=0.025, pitch_diameter=1.0, clearance_radial=clearance
    )


def test_four_point_radial_load_loads_both_diagonals_equally():
    """Pure radial load: every loaded ball carries both diagonals (X-shaped load lines) equally, its
    outer-upper and outer-lower contacts alike; the unloaded half carries nothing (Amasorrain 2003)."""
    res = solve(_slewing(), load_vector(F_x=50e3), free=[True, True, True, False, False])
    cl = res.rows[0].extras["contact_load"][0]  # (Z, 4)
    loaded = cl.max(axis=1) > 0
    assert loaded[0] and not loaded[40]
    np.testing.assert_allclose(cl[loaded, 0], cl[loaded, 1], rtol=1e-9)  # o+ = o−
    np.testing.assert_allclose(cl[loaded, 2], cl[loaded, 3], rtol=1e-9)  # i− = i+
    assert (cl[loaded] > 0).all()


def test_four_point_axial_load_loads_one_diagonal_closed_form():
    """Pure axial load: each ball carries one diagonal (outer-upper and inner-lower contacts), the other
    two contacts open; Q = F_a / (Z sin α) with the operating angle (Harris & Kotzalas 2007 §7.1)."""
    fa, z = 200e3, 80
    res = solve(_slewing(z=z), load_vector(F_z=fa))
    st = res.rows[0]
    cl = st.extras["contact_load"][0]
    assert (cl[:, [1, 3]] == 0).all() and (cl[:, [0, 2]] > 0).all()
    alpha = st.extras["contact_angle_all"][0, :, 0]
    np.testing.assert_allclose(cl[:, 0], fa / (z * np.sin(alpha)), rtol=1e-9)
    # the inverted load uses the other diagonal, mirror image
    res2 = solve(_slewing(z=z), load_vector(F_z=-fa))
    np.testing.assert_allclose(res2.rows[0].extras["contact_load"][0][:, [1, 3]], cl[:, [0, 2]], rtol=1e-9)


def test_four_point_one_diagonal_equals_groove_centre_ball_row():
    """With one diagonal loaded the floating-ball model is exactly the groove-centre ball row."""
    z, d, dm, a = 40, 0.02, 0.6, 45 * DEG
    fp = BearingModel(
        (FourPointRow(n_elements=z, element_diameter=d, pitch_diameter=dm, contact_angle=a, e_reduced=E_RED),)
    )
    ball = BearingModel(
        (
            BallRow(
                n_elements=z,
                element_diameter=d,
                pitch_diameter=dm,
                contact_angle=a,
                conformity_inner=0.52,
                conformity_outer=0.53,
                e_reduced=E_RED,
            ),
        )
    )
    load = load_vector(F_z=[80e3, 80e3], M_y=[0.0, 2e3])  # every ball stays on diagonal A
    free = [False, False, True, True, True]  # radial DOFs held: a free tilt also shifts the ring radially
    r_fp, r_ball = solve(fp, load, free=free), solve(ball, load, free=free)
    assert (r_fp.rows[0].extras["contact_load"][..., [1, 3]] == 0).all()
    np.testing.assert_allclose(r_fp.rows[0].load, r_ball.rows[0].load, rtol=1e-8)
    np.testing.assert_allclose(r_fp.displacement, r_ball.displacement, rtol=1e-8, atol=1e-15)


def test_four_point_moment_matches_stribeck_integral():
    """Pure tilting moment, zero clearance: Q_max = M / (J Z d_m sin α / 2) with the point-contact
    Sjövall integral J = 2 J_r(ε=0.5) = 2 × 0.2288 (Harris & Kotzalas 2007 Table 7.4), i.e.
    Q_max = 4.37 M / (Z d_m sin α) — the 4370·M/D of the slewing-ring makers' selection formula.
    Tolerance 2 %: the operating angle grows with load and Z = 80 is finite."""
    z, dm, m = 80, 1.0, 150e3
    res = solve(_slewing(z=z), load_vector(M_y=m), free=[True, True, True, True, True])
    st = res.rows[0]
    top = np.argmax(st.load[0])
    factor = st.load[0, top] * z * dm * np.abs(np.sin(st.contact_angle[0, top])) / m
    assert factor == pytest.approx(1 / 0.2288, rel=0.02)


def test_four_point_axial_play_follows_the_arch_geometry():
    """The play under a vanishing axial load equals the exact arch closed form, which is
    P_d / tan α₀ to first order (here P_d/2 is 2.7 % of A₀ = (f_i + f_o − 1) D_w: 3 % tolerance)."""
    pd = 40e-6
    model = _slewing(clearance=pd)
    row = model.rows[0]
    assert row.axial_play == pytest.approx(pd / np.tan(45 * DEG), rel=0.03)
    # ±1 N: the Hertz approach of 80 balls under 1 N (~3e-8 m) is the 1e-3 that remains.
    up, down = solve(model, load_vector(F_z=[1.0, -1.0])).displacement[:, 2]
    assert up - down == pytest.approx(row.axial_play, rel=2e-3)


def test_eight_point_rows_share_axial_load_and_mirror_symmetry():
    """Pure axial load: the two equal rows share it equally. Mirror z → −z: the upper row under
    (F_x, F_z) carries what the lower row carries under (F_x, −F_z), ball by ball and contact by contact
    (diagonals A ↔ B)."""
    model = MODELS["slewing_8pt"]
    axial = solve(model, load_vector(F_z=200e3))
    np.testing.assert_allclose(axial.row_load("balls_upper")[0, 2], 100e3, rtol=1e-9)
    np.testing.assert_allclose(axial.row_load("balls_lower")[0, 2], 100e3, rtol=1e-9)
    res = solve(model, load_vector(F_z=[200e3, -200e3], F_x=[10e3, 10e3]))
    up, low = res.row("balls_upper"), res.row("balls_lower")
    np.testing.assert_allclose(up.load[0], low.load[1], rtol=1e-7, atol=1e-6)
    np.testing.assert_allclose(
        up.extras["contact_load"][0], low.extras["contact_load"][1][:, [1, 0, 3, 2]], rtol=1e-7, atol=1e-6
    )
    np.testing.assert_allclose(res.displacement[0, [0, 1, 3]], res.displacement[1, [0, 1, 3]], atol=1e-15)
    np.testing.assert_allclose(res.displacement[0, [2, 4]], -res.displacement[1, [2, 4]], rtol=1e-7)


# --- crossed rollers ---------------------------------------------------------------------------------------
def test_crossed_roller_closed_forms():
    """Axial: the Z/2 rollers of one direction share F_a, q = F_a/(Z/2 sin α). Radial and moment, zero
    clearance: line-contact Stribeck integrals J_r = 0.2453 (Harris & Kotzalas 2007 Table 7.4 line
    contact; Q_max = 4.08 F_r/(Z cos α)) and, for the moment, both directions each over half the circle:
    Q_max = 2/J_r · M/(Z d_m sin α) = 8.15 M/(Z d_m sin α). Tolerance 1 % (finite Z = 120)."""
    model = MODELS["slewing_crossed"]
    z, dm, a = 120, 0.8, 45 * DEG
    res = solve(model, load_vector(F_x=[20e3, 0, 0], F_z=[0, 100e3, 0], M_y=[0, 0, 30e3]))
    load = res.rows[0].load
    np.testing.assert_allclose(load[1, ::2], 100e3 / (z / 2 * np.sin(a)), rtol=1e-9)
    assert (load[1, 1::2] == 0).all()
    assert load[0].max() * z * np.cos(a) / 20e3 == pytest.approx(1 / 0.2453, rel=0.01)
    assert load[2].max() * z * dm * np.sin(a) / 30e3 == pytest.approx(2 / 0.2453, rel=0.01)


# --- self-aligning rows ----------------------------------------------------------------------------------
@pytest.mark.parametrize("key", ["srb", "sabb"])
def test_self_aligning_bearing_carries_no_moment_at_any_tilt(key):
    model = MODELS[key]
    rng = np.random.default_rng(7)
    q = rng.normal(size=(6, 5)) * np.array([5e-6, 5e-6, 5e-6, 0.05, 0.05])  # tilts up to ~8°
    flat = q.copy()
    flat[:, 3:] = 0.0
    for k in model.kernels:
        tilted, level = k.response(q), k.response(flat)
        assert (tilted.force[:, 3:] == 0).all()
        assert (tilted.jacobian[:, 3:, :] == 0).all() and (tilted.jacobian[:, :, 3:] == 0).all()
        np.testing.assert_array_equal(tilted.force, level.force)
    # Solved with a misalignment imposed: reactions without moment, loads as without misalignment.
    load = CASES[key][2]
    free = [True, True, True, False, False]
    straight = solve(model, load, free=free)
    for tilt in (0.5 * DEG, 2.0 * DEG, 4.0 * DEG):
        res = solve(model, load, free=free, displacement=[0, 0, 0, tilt, -0.5 * tilt])
        assert (res.load[0, 3:] == 0).all()
        for a, b in zip(res.rows, straight.rows, strict=True):  # equal to the solver tolerance
            np.testing.assert_allclose(a.load, b.load, rtol=1e-9, atol=1e-9 * b.load.max())


@pytest.mark.parametrize("key", ["srb", "sabb"])
def test_self_aligning_refuses_a_moment_on_a_free_tilt(key):
    with pytest.raises(Exception, match="theta_y"):
        solve(MODELS[key], load_vector(F_x=1e3, M_y=10.0))


@pytest.mark.parametrize("key", ["srb", "sabb"])
def test_self_aligning_axial_load_sharing(key):
    """Pure axial load: only the row facing it carries, Q = F_a/(Z sin α_op); pure radial load with
    zero clearance: both rows carry the same; combined: the row forces add up to the load."""
    model = MODELS[key]
    z = model.rows[0].n_elements
    fa = CASES[key][1, 2]
    res = solve(model, CASES[key], free=[True, True, True, False, False])
    a, b = res.rows
    np.testing.assert_allclose(a.load[1], fa / (z * np.sin(a.contact_angle[1])), rtol=1e-9)
    assert (b.load[1] == 0).all()
    np.testing.assert_allclose(a.load[0], b.load[0], rtol=1e-9)
    total = res.row_load("row_A") + res.row_load("row_B")
    np.testing.assert_allclose(total[:, :3], res.load[:, :3], rtol=1e-9, atol=1e-6)
    assert res.row_load("row_A")[2, 2] > res.row_load("row_B")[2, 2]


def test_self_aligning_ball_row_equals_groove_centre_row_with_sphere_conformity():
    """The outer sphere is a groove of radius R_o centred at the bearing centre: under translations a
    ball row with conformity_outer = R_o/D_w at the same angle and axial position answers identically."""
    row = _sabb(clearance=0.0)
    ball = BallRow(
        n_elements=row.n_elements,
        element_diameter=row.element_diameter,
        pitch_diameter=row.pitch_diameter,
        contact_angle=row.contact_angle,
        conformity_inner=row.conformity_inner,
        conformity_outer=row.conformity_outer,
        axial_position=row.axial_position,
        e_reduced=E_RED,
    )
    q = _q(5, 4, 1.0)
    q[:, 3:] = 0.0
    q[:, 2] = np.abs(q[:, 2])
    a, b = row.kernel().response(q), ball.kernel().response(q)
    np.testing.assert_allclose(a.force[:, :3], b.force[:, :3], rtol=1e-12, atol=1e-12 * np.abs(b.force).max())
    np.testing.assert_allclose(a.energy, b.energy, rtol=1e-12)
    # The groove-centre row's moments are second order (its lever arms are the unloaded ones: u × F);
    # the self-aligning row's are exactly zero.
    assert np.abs(b.force[:, 3:]).max() < 1e-4 * np.abs(b.force[:, :3]).max() * row.outer_radius


def test_spherical_roller_slices_split_between_raceways():
    """Each roller's outer and inner slice loads carry the same total (series contacts) but differ in
    shape when the osculations differ; the per-roller split is solved to round-off."""
    model = BearingModel(
        (_srb(clearance=0.0, osculation_outer=0.99, osculation_inner=0.96), _srb(-10 * DEG, 0.0, name="b")),
    )
    res = solve(model, load_vector(F_x=60e3), free=[True, True, True, False, False])
    st = res.rows[0]
    outer, inner = st.slice_load[0], st.extras["slice_load_inner"][0]
    np.testing.assert_allclose(outer.sum(-1), inner.sum(-1), rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(outer.sum(-1), st.load[0], rtol=1e-12)
    top = np.argmax(st.load[0])
    # the closer-conforming outer contact spreads wider: a flatter slice distribution
    assert outer[top].max() / outer[top].sum() < inner[top].max() / inner[top].sum()


def test_needle_row_mechanics_equal_cylindrical_row():
    kw = dict(
        n_elements=30,
        element_diameter=0.003,
        effective_length=0.016,
        pitch_diameter=0.053,
        n_slices=8,
        clearance=-2e-6,
        e_reduced=E_RED,
    )
    q = _q(9, 3, 0.3)
    a, b = NeedleRow(**kw).kernel().response(q), CylindricalRow(**kw).kernel().response(q)
    np.testing.assert_array_equal(a.force, b.force)


# --- bad input ---------------------------------------------------------------------------------------------
BAD = [
    (
        lambda: _four_point(0.0).__class__(
            n_elements=20, element_diameter=0.02, pitch_diameter=0.5, conformity_inner=0.5
        ),
        "conformity_inner",
    ),
    (
        lambda: FourPointRow(n_elements=20, element_diameter=0.02, pitch_diameter=0.5, contact_angle=0.0),
        "contact_angle",
    ),
    (
        lambda: FourPointRow(n_elements=20, element_diameter=0.02, pitch_diameter=0.5, contact_angle=-0.3),
        "contact_angle",
    ),
    (
        lambda: FourPointRow(n_elements=20, element_diameter=0.02, pitch_diameter=0.5, clearance=-2e-3),
        "clearance",
    ),
    (lambda: FourPointRow(n_elements=90, element_diameter=0.02, pitch_diameter=0.5), "n_elements"),
    (
        lambda: _sabb().__class__(
            n_elements=15,
            element_diameter=0.0127,
            pitch_diameter=0.072,
            contact_angle=0.2,
            conformity_inner=0.49,
        ),
        "conformity_inner",
    ),
    (lambda: _srb(osculation_outer=1.0), "osculation_outer"),
    (lambda: _srb(osculation_inner=1.2), "osculation_inner"),
    (
        lambda: SphericalRollerRow(
            n_elements=17,
            element_diameter=0.02,
            effective_length=0.06,
            pitch_diameter=0.14,
            contact_angle=0.17,
        ),
        "effective_length",
    ),
    (
        lambda: SphericalRollerRow(
            n_elements=17,
            element_diameter=0.02,
            effective_length=0.03,
            pitch_diameter=0.14,
            contact_angle=0.05,
        ),
        "effective_length",
    ),
    (
        lambda: SphericalRollerRow(
            n_elements=30,
            element_diameter=0.02,
            effective_length=0.02,
            pitch_diameter=0.14,
            contact_angle=0.17,
        ),
        "n_elements",
    ),
    (
        lambda: CrossedRollerRow(
            n_elements=61, element_diameter=0.012, effective_length=0.01, pitch_diameter=0.4
        ),
        "n_elements",
    ),
    (
        lambda: CrossedRollerRow(
            n_elements=60, element_diameter=0.012, effective_length=0.02, pitch_diameter=0.4
        ),
        "effective_length",
    ),
    (
        lambda: NeedleRow(
            n_elements=20, element_diameter=0.005, effective_length=0.008, pitch_diameter=0.053
        ),
        "effective_length",
    ),
    (
        lambda: sa.spherical_roller(
            n_elements=17,
            element_diameter=0.02,
            effective_length=0.02,
            pitch_diameter=0.14,
            contact_angle=0.0,
        ),
        "contact_angle",
    ),
]


@pytest.mark.parametrize("make,field", BAD, ids=[f"{i}-{b[1]}" for i, b in enumerate(BAD)])
def test_bad_geometry_is_refused_in_one_line_naming_the_field(make, field):
    from bearingkit.errors import InputError

    with pytest.raises(InputError) as err:
        make()
    message = str(err.value)
    assert message.startswith(field) and "\n" not in message


def test_overload_never_returns_nan():
    res = solve(_slewing(), load_vector(F_z=[1e12, 200e3], M_y=[1e12, 0.0]))
    assert not res.converged[0] and res.converged[1]
    assert np.isfinite(res.displacement).all()
    assert all(np.isfinite(st.load).all() for st in res.rows)
