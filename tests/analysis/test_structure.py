"""The coupled solve of a bearing in its structure (issue 37's Must-show).

- a 6209 in a thin housing against an independent solve written here (scipy): the thin ring on a
  Winkler housing in closed form (Hetényi's foundation, seed 002's kernel; n = 1 the ring's translation
  in the housing) and Hertz's balls; the flexible ring widens the loaded zone and lowers Q_max;
- the same housing as an imported compliance matrix (Matrix Market file, the loader) reproduces it;
- the rigid limit (stiffness → ∞) is the rigid solve; the outer raceway's loads balance the load;
- the seed-002 ring's ovalisation (analysis/flexible.py, unchanged) is the general model where their
  assumptions coincide;
- every row kind couples.
"""

import dataclasses
import tomllib

import numpy as np
import pytest
import scipy.io
import scipy.optimize

from bearingkit.analysis.structure import Structure, element_loads, solve
from bearingkit.io.loader import from_dict, load_file
from bearingkit.physics.structure import thin_ring
from bearingkit.pipeline import analyze
from bearingkit.rings.curved_beam import FlexibleRing
from bearingkit.rings.imported import ring_export
from bearingkit.rings.sections import rectangular_section
from bearingkit.rings.supports import Foundation

E = 2.08e11
#: The 6209's outer ring as a plain ring from its raceway (77.7 mm) to 85 mm, 19 mm wide; a thin steel
#: housing wall of 3 mm around it (k_h = E t b/R_h², the seed-002 estimate).
SEC_6209 = rectangular_section(0.07770 / 2, 0.085 / 2, -0.0095, 0.0095)
K_HOUSING = float(thin_ring.housing_wall_stiffness(E, 0.003, 0.085 / 2 + 0.0015, 0.019))


def _dgbb():
    b = load_file("examples/dgbb_6209.toml")
    return b.model, b.load_matrix(), b.free


def _independent_6209(model, load):
    """Ball loads (C, 9) of the 6209 on its flexible outer ring, solved with scipy from closed forms."""
    kernel = model.kernels[0]
    psi = kernel.psi[0]
    k_n = float(np.ravel(kernel.k_n)[0])
    gap = float(model.rows[0].clearance) / 2
    r = SEC_6209.centroid_radius
    ei = E * SEC_6209.inertia_in
    d = np.subtract.outer(psi, psi)
    g = thin_ring.radial_influence(psi, psi, r, ei, K_HOUSING) + np.cos(d) / (np.pi * r * K_HOUSING)
    out = []
    for f_x in load[:, 0]:

        def equations(x, f_x=f_x):
            u, w = x[0], x[1:]
            q = k_n * np.maximum(u * np.cos(psi) - gap - w, 0.0) ** 1.5
            return np.concatenate([[q @ np.cos(psi) / f_x - 1.0], (w - g @ q) * 1e6])

        x0 = np.concatenate([[2e-5], np.zeros(psi.size)])
        x = scipy.optimize.fsolve(equations, x0, xtol=1e-12, maxfev=20000)  # 1e-14: "too small" warning
        assert np.abs(equations(x)).max() < 1e-9
        out.append(k_n * np.maximum(x[0] * np.cos(psi) - gap - x[1:], 0.0) ** 1.5)
    return np.array(out)


def test_6209_in_a_thin_housing_against_an_independent_solve():
    """The source case (thin ring on a Winkler housing): every ball load to 1e-6; the flexible ring
    widens the loaded zone and lowers Q_max against the rigid solve, as the thin ring predicts."""
    model, load, free = _dgbb()
    ring = FlexibleRing(
        SEC_6209, E, foundation=Foundation(radial=K_HOUSING), inextensible=True, in_plane_only=True
    )
    res = solve(model, load, Structure(outer=ring), free=free)
    assert res.converged.all()
    ref = _independent_6209(model, load)
    got = res.result.row("balls").load
    assert got == pytest.approx(ref, rel=1e-6, abs=1e-6 * ref.max())
    rigid = res.rigid.row("balls")
    assert np.all(got.max(-1) < rigid.max_load)  # the housing lets the loaded balls give way
    assert np.all(res.result.row("balls").loaded_count >= rigid.loaded_count)
    assert res.result.row("balls").loaded_count[1] > rigid.loaded_count[1]  # 4 kN: 3 → 5 balls


def _toml(path):
    with open(path, "rb") as f:
        return tomllib.load(f)


HELD = {
    "width": "19 mm",
    "inner_diameter": "77.7 mm",
    "seat_wall_thickness": "3 mm",
    "tangential_support": "1e8 N/m^2",
}


@pytest.mark.parametrize("kind", ["compliance", "stiffness"])
def test_imported_compliance_reproduces_the_ring_model(tmp_path, kind):
    """The ring of [structure.outer] (in its plane: the raceway does not tilt) exported at the ball
    nodes as an FE code would (Cartesian u_x, u_y; Matrix Market, 17 digits), as its compliance or its
    stiffness (a supported structure: no rigid-body mode among the in-plane motions), and read back
    through [structure.imported]: every ball load to 1e-6 (2.6e-14 measured)."""
    data = _toml("examples/dgbb_6209.toml")
    data["structure"] = {"outer": dict(HELD)}
    ring_input = from_dict(data, "ring.toml")
    ring = dataclasses.replace(ring_input.structure.outer, in_plane_only=True)
    ring_input = dataclasses.replace(ring_input, structure=Structure(outer=ring))
    a = analyze(ring_input)
    psi = ring_input.model.kernels[0].psi[0]
    c, nodes = ring_export(ring, psi, 0.0325, 0.0, dofs=("ux", "uy"))
    matrix = c if kind == "compliance" else np.linalg.inv(c)
    scipy.io.mmwrite(str(tmp_path / "housing.mtx"), matrix, precision=17, symmetry="symmetric")
    np.savetxt(tmp_path / "nodes.csv", nodes * 1e3, delimiter=",", header="x, y, z [mm]", fmt="%.17g")
    data["structure"] = {
        "imported": {
            "matrix": "housing.mtx",
            "nodes": "nodes.csv",
            "kind": kind,
            "dofs": ["ux", "uy"],
            "length_unit": "mm",
        }
    }
    b = from_dict(data, str(tmp_path / "imported.toml"))
    flex = analyze(b).flexible
    ref = a.flexible.result.row("balls").load
    assert flex.converged.all() and a.flexible.converged.all()
    assert flex.result.row("balls").load == pytest.approx(ref, rel=1e-6, abs=1e-6 * ref.max())
    assert np.any(np.abs(ref - a.flexible.rigid.row("balls").load) > 1e-3 * ref.max())  # it does flex


def _slewing():
    return load_file("examples/slewing_four_point_flange.toml")


def _slewing_scaled(b, s):
    """The slewing ring's structure with both rings' stiffness × s, solved under the file's loads."""
    base = b.structure
    st = Structure(
        outer=dataclasses.replace(base.outer, stiffness_scale=s),
        inner=dataclasses.replace(base.inner, stiffness_scale=s),
    )
    res = solve(b.model, b.load_matrix(), st, free=b.free)
    assert res.converged.all()
    rigid = res.rigid.row("balls").load
    return np.abs(res.result.row("balls").load - rigid).max() / rigid.max()


def test_slewing_ring_rigid_limit_and_equilibrium():
    """Issue 37's must-show, run by make test: stiffness × 1e9 gives the rigid solve's ball loads within
    1e-9; the coupled solution's loads on the outer raceway (raceway_loads, placed at the elements)
    balance the load to 1e-9."""
    b = _slewing()
    load = b.load_matrix()
    assert _slewing_scaled(b, 1e9) <= 1e-9
    res = solve(b.model, load, b.structure, free=b.free)
    _assert_balanced(res, load)
    assert np.all(res.force_balance <= 1e-9)  # what the faces print (coupling.force_balance)


@pytest.mark.slow
def test_slewing_ring_approaches_the_rigid_solve_as_one_over_the_stiffness():
    """Stiffness × s: the ball loads approach the rigid solve as 1/s (s = 1e3 → 1e6: 1e3 times closer)."""
    b = _slewing()
    assert _slewing_scaled(b, 1e3) / _slewing_scaled(b, 1e6) == pytest.approx(1e3, rel=0.05)


def _assert_balanced(res, load, rtol=1e-9, moments=True):
    """Σ over elements of (F_r e_r + F_z e_z) at (r_e, ψ, z_e) and of the couples −M_t e_θ = the load.

    Forces to ``rtol``. Moments within Σ|element force| times the largest displacement (rings and
    raceways): the rows take the moments of their contact forces at the undeformed points (small
    displacements), the inner ring's at its groove centres, the outer raceway's here at its own. The
    tapered rows' are left out: their rollers have no moment balance of their own (two translational
    DOFs, design.md).
    """
    f = element_loads(res.result.model, res.result.displacement, res.offsets).reshape(load.shape[0], -1, 3)
    p = res.points
    c, s = np.cos(p.azimuth), np.sin(p.azimuth)
    force = np.stack([f[..., 0] * c, f[..., 0] * s, f[..., 1]], -1)
    pos = np.stack([p.radius * c, p.radius * s, p.z], -1)
    moment = np.cross(pos, force) - f[..., 2:3] * np.stack([-s, c, 0 * c], -1)
    total = np.concatenate([force.sum(1), moment.sum(1)[:, :2]], -1)
    free = np.asarray(res.result.free)
    scale = np.abs(load[:, :3]).max()
    miss = np.abs(total - res.result.load)
    assert np.all(miss[:, :3][:, free[:3]] <= rtol * scale)
    if moments:
        moved = np.abs(res.result.displacement[:, :3]).max() + np.abs(res.raceway_offsets[..., :2]).max()
        carried = np.hypot(f[..., 0], f[..., 1]).sum()
        assert np.all(miss[:, 3:][:, free[3:]] <= carried * moved + rtol * scale)
    assert res.result.load[:, free] == pytest.approx(load[:, free], rel=1e-12)


def test_6209_equilibrium_and_rigid_limit():
    model, load, free = _dgbb()
    data = _toml("examples/dgbb_6209.toml")
    data["structure"] = {"outer": dict(HELD, axial_support="1e9 N/m^2")}
    ring = from_dict(data, "ring.toml").structure.outer
    res = solve(model, load, Structure(outer=ring), free=free)
    assert res.converged.all()
    _assert_balanced(res, load)
    stiff = solve(model, load, Structure(outer=dataclasses.replace(ring, stiffness_scale=1e9)), free=free)
    rigid = stiff.rigid.row("balls").load
    assert np.abs(stiff.result.row("balls").load - rigid).max() <= 1e-9 * rigid.max()


def test_seed002_ovalisation_is_the_general_ring_where_the_models_coincide():
    """Seed 002's ring (analysis/flexible.py, unchanged) with its ovalisation alone (no beam between
    supports) against the general curved ring with the same assumptions: inextensible, in its plane,
    harmonics n ≥ 2 (the housing holds n = 0, 1 rigidly) on the same Winkler housing. Same loads."""
    from bearingkit.analysis.flexible import solve_flexible
    from bearingkit.bearings.ball_column import outer_ring
    from bearingkit.rings.sections import CurvedSection

    b = load_file("examples/ball_column_condition1.toml")
    g = b.model.metadata["geometry"]
    seed = dataclasses.replace(outer_ring(g, compliance_scale=0.5), support_positions=None)
    old = solve_flexible(b.model, b.load_matrix(), seed, free=b.free)
    s = seed.section
    section = CurvedSection(s.area, s.centroid_radius, 0.0, s.area_moment, s.area_moment, s.area_moment)
    general = FlexibleRing(
        section,
        seed.youngs_modulus / 0.5,
        foundation=Foundation(radial=seed.housing_stiffness),
        inextensible=True,
        in_plane_only=True,
        first_harmonic=2,
        harmonics=2048,
    )
    new = solve(b.model, b.load_matrix(), Structure(outer=general), free=b.free)
    assert old.converged.all() and new.converged.all()
    for row in ("ball_1", "roller_2", "ball_3"):
        ref = old.result.row(row).load
        assert new.result.row(row).load == pytest.approx(ref, rel=1e-5, abs=1e-5 * ref.max()), row
        assert np.array_equal(new.result.row(row).loaded_count, old.result.row(row).loaded_count)


KINDS = [
    "crb_nu209",
    "trb_32008_DB",
    "srb_22220",
    "sabb_1209",
    "slewing_crossed_roller",
    "thrust_ball_51209",
    "needle_na4910",
    "acbb_7209_DB",
    "qj_208",
    "crtb_81209",
    "ptrb_prototype",
]


@pytest.mark.parametrize("name", KINDS)
def test_every_row_kind_couples(name):
    """A ring on its seat under every row kind: the coupling converges and the loads balance."""
    data = _toml(f"examples/{name}.toml")
    outer = {"width": "20 mm", "seat_stiffness": "5e9 N/m^2", "axial_support": "1e9 N/m^2"}
    outer["tangential_support"] = "1e8 N/m^2"
    if name == "ptrb_prototype":  # the threaded row has no pitch diameter of its own
        outer.update(inner_diameter="140 mm", outer_diameter="160 mm")
    data["structure"] = {"outer": outer}
    b = from_dict(data, name)
    flex = analyze(b).flexible
    assert flex.converged.all()
    _assert_balanced(flex, flex.result.load, rtol=1e-8, moments=not name.startswith("trb"))
