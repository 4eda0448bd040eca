"""Seed-002 ball–column bearing: examples (common input format), rigid counts, ring options, bad input."""

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from bearingkit.analysis.solver.quasistatic import load_vector, solve
from bearingkit.bearings.ball_column import (
    ROWS,
    BallColumnGeometry,
    RingOptions,
    ball_column,
    outer_ring_of,
    solve_flexible_input,
    wall_housing_stiffness,
)
from bearingkit.errors import InputError
from bearingkit.io.loader import from_dict, load_file

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize("cond,fr,fa", [(1, 20e3, 0.0), (2, 30e3, 20e3), (3, 13.5e3, 0.0)])
def test_examples_load_and_solve(cond, fr, fa):
    """The condition files are common-format inputs of type ball_column (Table 1 + Table 2)."""
    bearing = load_file(EXAMPLES / f"ball_column_condition{cond}.toml")
    assert bearing.bearing_type == "ball_column"
    (case,) = bearing.cases
    assert case.load[0] == pytest.approx(fr) and case.load[2] == pytest.approx(fa)
    g = bearing.model.metadata["geometry"]
    assert g.n_balls == 74 and g.n_rollers == 78 and g.ball_diameter == pytest.approx(0.015)
    assert g.support_positions == pytest.approx((-0.025, 0.025))
    assert bearing.model.metadata["ring"] == RingOptions(
        flexible=True, compliance_scale=1.0, bending=True, housing_wall_thickness=0.020
    )
    model = ball_column(replace(g, n_slices=6), ring=bearing.model.metadata["ring"])
    res = solve(model, bearing.load_matrix())
    assert res.converged.all()
    total = sum(res.row_load(n) for n in ROWS)
    assert np.allclose(total[0, :3], bearing.load_matrix()[0, :3], atol=1e-6 * fr)


def test_flexible_solve_of_an_input_file():
    bearing = load_file(EXAMPLES / "ball_column_condition1.toml")
    g = bearing.model.metadata["geometry"]
    bearing = replace(bearing, model=ball_column(replace(g, n_slices=6), ring=bearing.model.metadata["ring"]))
    flex = solve_flexible_input(bearing)
    assert flex.converged.all() and flex.ring.bending
    assert flex.ring.support_positions == pytest.approx((-0.025, 0.025))
    rigid = solve(bearing.model, bearing.load_matrix())
    # §3.2: the flexible ring moves radial load from the rollers to the balls.
    assert flex.row_load("roller_2")[0, 0] < rigid.row_load("roller_2")[0, 0]
    off = replace(bearing, model=ball_column(replace(g, n_slices=6), ring=RingOptions(flexible=False)))
    assert solve_flexible_input(off) is None


def _file(**geometry):
    return {
        "bearing": {"type": "ball_column"},
        "geometry": geometry,
        "load_cases": [{"name": "c1", "F_x": "20 kN"}],
    }


def test_ring_options_from_the_input_format():
    b = from_dict(
        _file(support_positions=["-30 mm", "35 mm"], ring={"compliance_scale": 0.5, "bending": False})
    )
    assert b.model.metadata["geometry"].support_positions == pytest.approx((-0.03, 0.035))
    ring = outer_ring_of(b.model)
    assert ring.compliance_scale == 0.5 and not ring.bending and ring.beam_mode == "clearance"
    assert ring.youngs_modulus == pytest.approx(b.material.youngs_modulus)
    with pytest.raises(InputError, match=r"geometry\.support_positions.*support span"):
        from_dict(_file(support_positions=["-50 mm", "50 mm"]))
    with pytest.raises(InputError, match=r"support_positions"):
        from_dict(_file(support_positions=["-20 mm"]))
    # a ball row (at ∓25 mm) outside the supports is refused when the file is read, naming the field
    with pytest.raises(InputError, match=r"geometry\.support_positions.*between the housing supports"):
        from_dict(_file(support_positions=["-20 mm", "30 mm"]))
    with pytest.raises(InputError, match=r"geometry\.ring\.stiffness.*unknown field"):
        from_dict(_file(ring={"stiffness": 1.0}))
    with pytest.raises(InputError, match=r"compliance_scale"):
        from_dict(_file(ring={"compliance_scale": -1.0}))
    with pytest.raises(InputError, match=r"beam_mode"):
        from_dict(_file(ring={"beam_mode": "bent"}))


def test_rigid_roller_zone_is_half_the_rollers():
    """Zero clearance, pure radial load: the load zone is ±90°, 39 of 78 rollers (seed 002 §3.2)."""
    res = solve(ball_column(n_slices=4), load_vector(F_x=20e3))
    assert res.row("roller_2").loaded_count[0] == 39
    assert res.row("ball_1").loaded_count[0] == res.row("ball_3").loaded_count[0]


def test_bad_input():
    with pytest.raises(InputError, match="pitch_diameter"):
        BallColumnGeometry(pitch_diameter=0.41)
    with pytest.raises(InputError, match="n_elements"):
        ball_column(roller_diameter=0.016)  # Table 1's Ø16 rollers do not fit 78 on the pitch circle
    with pytest.raises(InputError, match="support span"):
        BallColumnGeometry(support_positions=(-0.05, 0.05))  # longer than the 75 mm ring
    from bearingkit.rings.section import RingSection

    with pytest.raises(InputError, match=r"area_moment \(-1e-09"):
        RingSection(-1e-9, 5e-4, 0.075, 0.198)
    with pytest.raises(InputError, match=r"beam_area_moment \(0"):
        RingSection(1e-9, 5e-4, 0.075, 0.198, 0.0)
    with pytest.raises(InputError, match="compliance_scale"):
        RingOptions(compliance_scale=-0.1)
    with pytest.raises(InputError, match="ring"):
        ball_column(ring={"bending": False})
    with pytest.raises(InputError, match="clearance_ball"):
        BallColumnGeometry(clearance_ball=-1e-6)


def test_housing_options_from_the_input_format():
    """[geometry.ring] housing_wall_thickness → k_h = E_h t_h b/R_h² (R_h = D/2 + t_h/2); housing_stiffness
    given directly; the default is a 20 mm steel wall; negative or both → InputError naming the field."""
    g = BallColumnGeometry()
    default = outer_ring_of(from_dict(_file()).model)
    r_h = g.outer_diameter / 2 + 0.010
    assert default.housing_stiffness == pytest.approx(2.08e11 * 0.020 * g.width / r_h**2, rel=1e-12)
    wall = outer_ring_of(from_dict(_file(ring={"housing_wall_thickness": "40 mm"})).model)
    assert wall.housing_stiffness == pytest.approx(
        2.08e11 * 0.040 * g.width / (g.outer_diameter / 2 + 0.02) ** 2
    )
    iron = from_dict(_file(ring={"housing_wall_thickness": "40 mm", "housing_youngs_modulus": "104 GPa"}))
    assert outer_ring_of(iron.model).housing_stiffness == pytest.approx(wall.housing_stiffness / 2)
    free = outer_ring_of(from_dict(_file(ring={"housing_stiffness": "0 N/m^2"})).model)
    assert free.housing_stiffness == 0.0
    given = outer_ring_of(from_dict(_file(ring={"housing_stiffness": "5e9 N/m^2"})).model)
    assert given.housing_stiffness == pytest.approx(5e9)
    assert wall_housing_stiffness(g, 0.040) == pytest.approx(wall.housing_stiffness)
    with pytest.raises(InputError, match=r"geometry\.ring\.housing_stiffness.*non-negative"):
        from_dict(_file(ring={"housing_stiffness": "-1e9 N/m^2"}))
    with pytest.raises(InputError, match=r"housing_wall_thickness.*positive"):
        from_dict(_file(ring={"housing_wall_thickness": "0 mm"}))
    with pytest.raises(InputError, match=r"housing_stiffness.*housing_wall_thickness.*not both"):
        from_dict(_file(ring={"housing_stiffness": "1e9 N/m^2", "housing_wall_thickness": "20 mm"}))
    with pytest.raises(InputError, match=r"housing_stiffness \(-1 N/m²\)"):
        RingOptions(housing_stiffness=-1.0)


def test_ball_count_total_splits_and_staggers_the_rows():
    """ball_count = "total" (issue 32, seed 002's Table 1): n_balls is both rows together, row 1 half a pitch
    off row 3; an odd total is refused in one line."""
    m = ball_column(BallColumnGeometry(ball_count="total"))
    b1, _, b3 = m.rows
    assert b1.n_elements == b3.n_elements == 37
    assert b1.azimuth_phase == pytest.approx(np.pi / 37) and b3.azimuth_phase == 0.0
    with pytest.raises(InputError, match="n_balls"):
        BallColumnGeometry(n_balls=75, ball_count="total")
    with pytest.raises(InputError, match="ball_count"):
        BallColumnGeometry(ball_count="both")
