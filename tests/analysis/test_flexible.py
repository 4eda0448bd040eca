"""Coupled flexible-ring solve: rigid limit, Newton with ovalisation, Jacobian, outputs, bad input."""

import numpy as np
import pytest

from bearingkit.analysis import flexible as flex_mod
from bearingkit.analysis.flexible import solve_flexible
from bearingkit.analysis.solver.quasistatic import SolverOptions, load_vector, solve
from bearingkit.bearings.ball_column import BallColumnGeometry, ball_column, outer_ring
from bearingkit.errors import InputError
from bearingkit.rings.flexible import FlexibleOuterRing
from bearingkit.rings.section import RingSection

G = BallColumnGeometry(n_slices=6)
MODEL = ball_column(G)
LOADS = load_vector(F_x=[5000.0, 20000.0], F_z=[0.0, 3000.0])


@pytest.mark.parametrize("bending,method", [(True, "newton"), (False, "newton"), (False, "aitken")])
def test_rigid_limit_equals_engine(bending, method):
    rigid = solve(MODEL, LOADS)
    stiff = FlexibleOuterRing(
        RingSection(1e3, 1.0, 0.075, 0.198, 1e3), support_positions=(-0.025, 0.025), bending=bending
    )
    flex = solve_flexible(MODEL, LOADS, stiff, method=method)
    assert flex.converged.all()
    assert np.allclose(flex.result.displacement, rigid.displacement, rtol=1e-9, atol=1e-9 * 1e-5)
    for name in ("ball_1", "roller_2", "ball_3"):
        assert np.allclose(flex.row(name).load, rigid.row(name).load, rtol=1e-9, atol=1e-9 * 1e3)
    zero = solve_flexible(MODEL, LOADS, outer_ring(G, compliance_scale=0.0))
    assert np.array_equal(zero.result.displacement, rigid.displacement)


def test_flexible_ring_unloads_roller_row_and_converges():
    ring = outer_ring(G, bending=False)
    flex = solve_flexible(MODEL, LOADS, ring)
    rigid = solve(MODEL, LOADS)
    assert flex.converged.all() and (flex.iterations < 15).all()
    assert (flex.offset_change <= 1e-11 + 1e-8 * 1e-4).all()
    share_f = flex.row_load("roller_2")[:, 0] / LOADS[:, 0]
    share_r = rigid.row_load("roller_2")[:, 0] / LOADS[:, 0]
    assert np.all(share_f < share_r)
    # equilibrium: the rows carry the external load
    total = sum(flex.row_load(n) for n in ("ball_1", "roller_2", "ball_3"))
    assert np.allclose(total[:, :3], LOADS[:, :3], rtol=1e-8, atol=1e-6)
    # the beam opening equals FL³/(48 EI) of the roller row force
    span = 0.05
    expected = flex.row_load("roller_2")[:, 0] * span**3 / (48 * ring.beam_rigidity)
    assert np.allclose(flex.offsets["roller_2"].radial[:, 0], expected, rtol=1e-6)


def test_aitken_beats_constant_relaxation():
    ring = outer_ring(G, bending=False, compliance_scale=3.0)
    ait = solve_flexible(MODEL, LOADS[1:], ring, method="aitken")
    rel = solve_flexible(MODEL, LOADS[1:], ring, method="relaxed", relaxation=0.5, max_iterations=40)
    assert ait.converged.all()
    assert not rel.converged.all() or rel.iterations[0] > ait.iterations[0]


def test_bad_input():
    sec = RingSection.rectangular(0.075, 0.008, 0.195)
    with pytest.raises(InputError, match="support span"):
        FlexibleOuterRing(sec, support_positions=(-0.05, 0.05))
    with pytest.raises(InputError, match="method"):
        solve_flexible(MODEL, LOADS, outer_ring(G), method="secant")
    with pytest.raises(InputError, match="relaxation"):
        solve_flexible(MODEL, LOADS, outer_ring(G), relaxation=1.5)
    with pytest.raises(InputError, match="youngs_modulus"):
        FlexibleOuterRing(sec, youngs_modulus=-1.0)


CONDITIONS = load_vector(F_x=[20e3, 30e3, 13.5e3], F_z=[0.0, 20e3, 0.0])  # seed 002 Table 2


def test_newton_converges_with_ovalisation_where_fixed_points_diverge():
    """Beam + thin-ring ovalisation of the seed-002 ring, conditions 1–3: Newton converges (measured
    6–8 iterations), the relaxed fixed points blow up (the free ring is ~2,500x softer than the contacts)."""
    ring = outer_ring(G, bending=True, housing_stiffness=0.0)
    flex = solve_flexible(MODEL, CONDITIONS, ring)
    assert flex.converged.all() and (flex.iterations <= 12).all()
    # The solution is a fixed point: the offsets are what the ring does under the final element loads.
    again = ring.offsets(MODEL, flex.result)
    for name, off in flex.offsets.items():
        assert np.allclose(
            off.radial, again[name].radial, rtol=0, atol=1e-11 + 1e-8 * np.abs(off.radial).max()
        )
    total = sum(flex.row_load(n) for n in ("ball_1", "roller_2", "ball_3"))
    assert np.allclose(total[:, :3], CONDITIONS[:, :3], rtol=1e-8, atol=1e-6)
    # Ovalisation under a radial load along +x: the ring bulges out at ψ = 0 and moves in at ±90°.
    w = flex.deflection_shape(np.array([0.0, np.pi / 2, -np.pi / 2]))
    assert (w[:, 0] > 0).all() and (w[:, 1] < 0).all() and np.allclose(w[:, 1], w[:, 2], rtol=1e-6)
    for method in ("aitken", "relaxed"):
        other = solve_flexible(MODEL, CONDITIONS, ring, method=method, max_iterations=20)
        assert not other.converged.any()


def test_fixed_point_jacobian_matches_engine_differences():
    """∂T/∂x assembled from fixed-q differences + the contact symmetry ∂f/∂w_j = ∂P_j/∂q equals central
    differences of T through full engine solves (small bearing, so the check stays fast)."""
    g = BallColumnGeometry(n_balls=24, n_rollers=24, n_slices=4)
    model = ball_column(g)
    load = load_vector(F_x=20e3, F_z=3e3)
    ring = outer_ring(g, bending=True, housing_stiffness=0.0)
    opts = SolverOptions(rtol=1e-14, max_iterations=100)
    flex = solve_flexible(model, load, ring, max_iterations=2, options=opts)
    layout = flex_mod._layout(ring, model)
    _, names, sizes = layout
    length = ring.section.centroid_radius
    x = flex_mod._pack(ring, names, flex.offsets, length, 1)
    res = flex.result
    cmat = ring.bending_matrix(ring.ring_loads(model, res).azimuth)
    jac = flex_mod._fixed_point_jacobian(model, ring, res, x, layout, length, None, cmat)

    def t_of(xx):
        offsets = flex_mod._unpack(ring, names, sizes, xx, length)
        r = solve(model, load, displacement=res.displacement, options=opts, raceway_offsets=offsets)
        return flex_mod._pack(ring, names, ring.offsets(model, r), length, 1)

    h = 1e-8
    for j in (0, 24, 30, 48):  # loaded elements of ball_1, roller_2 (two) and ball_3
        e = np.zeros_like(x)
        e[0, j] = h
        col = (t_of(x + e) - t_of(x - e))[0] / (2 * h)
        assert np.abs(col).max() > 1.0
        assert np.allclose(jac[0, :, j], col, rtol=0, atol=1e-5 * np.abs(col).max())


def test_to_dict_is_json_with_shares_and_ring_shape():
    from bearingkit.io.export import non_finite_paths, to_json

    ring = outer_ring(G, bending=True)
    flex = solve_flexible(MODEL, CONDITIONS[:2], ring)
    data = flex.to_dict()
    assert len(data) == 2 and non_finite_paths(data) == []
    to_json(data)  # strict JSON
    for c, d in enumerate(data):
        assert d["converged"] and d["coupling"]["method"] == "newton"
        rows = {r["name"]: r for r in d["rows"]}
        assert sum(r["radial_share"] for r in rows.values()) == pytest.approx(1.0)
        radial = {n: np.hypot(*flex.row_load(n)[c, :2]) for n in rows}
        assert rows["roller_2"]["radial_share"] == pytest.approx(radial["roller_2"] / sum(radial.values()))
        assert rows["ball_1"]["loaded_count"] == int(flex.row("ball_1").loaded_count[c])
        assert len(rows["roller_2"]["raceway_radial_offset_m"]) == G.n_rollers
        shape = np.array(d["ring"]["bending_deflection_m"])
        assert shape.shape == (flex_mod.SHAPE_POINTS,)
        # The housing takes the n = 0, 1 harmonics: the bending shape has no mean and no cos/sin ψ part.
        theta = np.array(d["ring"]["shape_azimuth_rad"])
        for basis in (np.ones_like(theta), np.cos(theta), np.sin(theta)):
            assert abs(np.mean(shape * basis)) < 1e-3 * np.abs(shape).max()  # 72-point quadrature
    # Condition 2 (F_a = 20 kN toward +z): row 3 carries most of the axial load.
    assert {r["name"]: r["axial_share"] for r in data[1]["rows"]}["ball_3"] > 0.5
    rigid = solve_flexible(MODEL, CONDITIONS[:1], outer_ring(G, compliance_scale=0.0)).to_dict(0)
    assert rigid["ring"]["flexural_rigidity_Nm2"] is None  # ∞ is not JSON


def test_ring_moment_is_the_curvature_change_of_the_coupled_deflection():
    """The reported ring bending moment is −EI (w″ + w)/R² of the bending deflection the coupled solve
    used (finite differences between elements), and the fibre stresses are N/A ∓ M c/I."""
    ring = outer_ring(G, bending=True)
    flex = solve_flexible(MODEL, CONDITIONS[:1], ring)
    theta, h = np.array([0.9, 2.0, 3.3, 4.6]) + 0.013, 1e-4  # off the element azimuths
    w = [flex.deflection_shape(theta + d)[0] for d in (-h, 0.0, h)]
    ei, r = ring.flexural_rigidity, ring.section.centroid_radius
    m_fd = -ei * ((w[0] - 2 * w[1] + w[2]) / h**2 + w[1]) / r**2
    forces = flex.ring_forces(theta)
    assert forces.moment[0] == pytest.approx(m_fd, rel=1e-4, abs=1e-6 * np.abs(m_fd).max())
    d = flex.to_dict(0)["ring"]
    assert len(d["bending_moment_Nm"]) == flex_mod.SHAPE_POINTS
    m, n = np.array(d["bending_moment_Nm"]), np.array(d["hoop_force_N"])
    sec = ring.section
    outer = np.array(d["fibre_stress_outer_Pa"])
    assert outer == pytest.approx(
        n / sec.area + m * (sec.outer_radius - sec.centroid_radius) / sec.area_moment
    )
    assert d["max_fibre_stress_Pa"] >= np.abs(outer).max()


def test_ring_moment_figure_draws_moment_and_stresses(tmp_path):
    from bearingkit.report.ring_plots import ring_moment_figure, write_ring_moment

    flex = solve_flexible(MODEL, CONDITIONS[:1], outer_ring(G, bending=True))
    fig = ring_moment_figure({"beam + ovalisation": flex})
    ax_m, ax_s = fig.axes
    m = ax_m.lines[0].get_ydata()
    assert np.max(np.abs(m)) == pytest.approx(
        np.max(np.abs(flex.ring_forces(ax_m.lines[0].get_xdata() * np.pi / 180).moment[0]))
    )
    assert len(ax_s.lines) == 2  # outer and inner fibre
    path = write_ring_moment(tmp_path / "m.png", {"beam + ovalisation": flex})
    assert path.stat().st_size > 10000


def test_rigid_housing_equals_beam_only_through_the_coupled_solve():
    """k_h → ∞ removes the ovalisation: beam + ovalisation in a rigid housing is the beam model (1e-9)."""
    beam = solve_flexible(MODEL, CONDITIONS, outer_ring(G, bending=False))
    housed = solve_flexible(MODEL, CONDITIONS, outer_ring(G, bending=True, housing_stiffness=np.inf))
    assert beam.converged.all() and housed.converged.all()
    assert np.allclose(housed.result.displacement, beam.result.displacement, rtol=1e-9, atol=1e-9 * 1e-5)
    for name in ("ball_1", "roller_2", "ball_3"):
        assert np.allclose(housed.row(name).load, beam.row(name).load, rtol=1e-9, atol=1e-9 * 1e3)
        assert np.allclose(housed.offsets[name].radial, beam.offsets[name].radial, rtol=1e-9, atol=1e-15)
    assert np.array_equal(housed.deflection_shape(np.linspace(0, 6, 7)), np.zeros((3, 7)))
    assert housed.to_dict(0)["ring"]["housing_stiffness_N_per_m2"] is None  # ∞ is not JSON


def test_housing_stiffens_the_ovalisation_monotonically():
    """Free ring → stiffer housing: the spread of the bending offsets of the roller row shrinks and the
    inward motion near ±90° (free ring: ≈ −9 µm) disappears."""
    spread, lowest = [], []
    for k_h in (0.0, 1e8, 1e9, 1e10, 1e11):
        flex = solve_flexible(
            MODEL, CONDITIONS[:1], outer_ring(G, compliance_scale=0.5, housing_stiffness=k_h)
        )
        assert flex.converged.all()
        w = flex.offsets["roller_2"].radial[0]
        spread.append(w.max() - w.min())
        lowest.append(w.min())
    assert np.all(np.diff(spread) < 0)
    assert lowest[0] < -5e-6 and lowest[-1] > 0
    # The free ring of the dataclass default equals an explicit k_h = 0 bit for bit.
    sec = outer_ring(G).section
    a = FlexibleOuterRing(sec, support_positions=(-0.025, 0.025))
    b = FlexibleOuterRing(sec, support_positions=(-0.025, 0.025), housing_stiffness=0.0)
    psi = np.linspace(0, 2 * np.pi, 9)
    assert np.array_equal(a.bending_matrix(psi), b.bending_matrix(psi))


def test_housing_stiffness_bad_input():
    sec = RingSection.rectangular(0.075, 0.008, 0.195)
    with pytest.raises(InputError, match=r"housing_stiffness \(-1 N/m²\) must be non-negative"):
        FlexibleOuterRing(sec, housing_stiffness=-1.0)
    with pytest.raises(InputError, match="housing_stiffness"):
        FlexibleOuterRing(sec, housing_stiffness=float("nan"))


def test_the_last_step_is_judged_too():
    """A solve that converges in k steps converges with max_iterations = k (the final state is checked)."""
    ring = outer_ring(G, bending=False)
    full = solve_flexible(MODEL, LOADS, ring)
    k = int(full.iterations.max())
    capped = solve_flexible(MODEL, LOADS, ring, max_iterations=k)
    assert capped.converged.all()
    np.testing.assert_array_equal(capped.result.displacement, full.result.displacement)
    short = solve_flexible(MODEL, LOADS, ring, max_iterations=1)
    assert not short.converged.all() and np.isfinite(short.offset_change).all()
