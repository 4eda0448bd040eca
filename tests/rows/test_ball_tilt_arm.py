"""Tilt lever arm of ball rows (issue 22 item 3): groove curvature centre (Harris) or pitch radius (ISO)."""

from pathlib import Path

import numpy as np
import pytest

from bearingkit.analysis.solver.quasistatic import SolverOptions, load_vector, solve
from bearingkit.bearings.standard import angular_contact_ball, angular_contact_pair
from bearingkit.errors import InputError
from bearingkit.io import schema
from bearingkit.io.loader import load_file
from bearingkit.rows.ball.row import TILT_ARMS, BallRow

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

PAIR = dict(
    arrangement="DB", n_elements=15, element_diameter=0.0119, pitch_diameter=0.0655,
    contact_angle=np.deg2rad(25), row_spacing=0.02, axial_clearance=-10e-6,
)  # fmt: skip


def _pair(arm):
    return angular_contact_pair(**PAIR, tilt_arm=arm)


@pytest.mark.parametrize("backend", ["numpy", "compiled"])
def test_both_arms_agree_without_a_moment(backend):
    # A DB pair under a radial or an axial force alone does not tilt (symmetry): the tilt columns of
    # the kinematics (the only place the arm enters) see θ = 0, so loads and displacements agree.
    opts = SolverOptions(backend=backend)
    load = load_vector(F_x=[2000.0, 0.0], F_z=[0.0, -3000.0])
    a = solve(_pair("groove_centre"), load, options=opts)
    b = solve(_pair("pitch_radius"), load, options=opts)
    assert a.converged.all() and b.converged.all()
    np.testing.assert_allclose(a.displacement, b.displacement, rtol=0, atol=1e-15)
    for ra, rb in zip(a.rows, b.rows, strict=True):
        np.testing.assert_allclose(ra.load, rb.load, rtol=1e-12, atol=1e-9)
    # A single row with its tilts held: identical loads. The moment reaction is taken about the arm's
    # point; both points lie on the unloaded contact line, so it differs only through the change of
    # the loaded contact angle (here 0.05 %).
    free = [True, True, True, False, False]
    geo = dict(n_elements=15, element_diameter=0.0119, pitch_diameter=0.0655, contact_angle=np.deg2rad(25))
    single = {arm: angular_contact_ball(**geo, tilt_arm=arm) for arm in TILT_ARMS}
    sa = solve(single["groove_centre"], load_vector(F_x=1500.0, F_z=3000.0), free=free, options=opts)
    sb = solve(single["pitch_radius"], load_vector(F_x=1500.0, F_z=3000.0), free=free, options=opts)
    np.testing.assert_allclose(sa.rows[0].load, sb.rows[0].load, rtol=1e-12)
    np.testing.assert_allclose(sa.load[0, 3:], sb.load[0, 3:], rtol=2e-3, atol=1e-9)


@pytest.mark.parametrize("backend", ["numpy", "compiled"])
def test_arms_differ_under_a_moment(backend):
    opts = SolverOptions(backend=backend)
    load = load_vector(F_z=1000.0, M_y=60.0)
    a = solve(_pair("groove_centre"), load, options=opts)
    b = solve(_pair("pitch_radius"), load, options=opts)
    assert a.converged.all() and b.converged.all()
    # The groove-centre radius R_i = d_m/2 + (f_i − ½) D_w cos α₀ exceeds d_m/2: the same moment
    # tilts the ring less, and the ball loads differ.
    row = _pair("groove_centre").rows[0]
    arm = (row.conformity_inner - 0.5) * row.element_diameter * np.cos(row.contact_angle)
    r_i = row.pitch_diameter / 2 + arm
    assert r_i > row.pitch_diameter / 2
    assert abs(a.displacement[0, 4]) < abs(b.displacement[0, 4])
    # Both points lie on the unloaded contact line, so to first order a tilt changes every normal
    # approach equally (θ (z cos α₀ − d_m/2 sin α₀) cos ψ for both); the loads differ through the
    # tangential part, i.e. the loaded contact angles: here by ~4e-4 of the largest ball load, far
    # above round-off (1e-15) and far below the tilt difference.
    q_a = np.concatenate([r.load[0] for r in a.rows])
    q_b = np.concatenate([r.load[0] for r in b.rows])
    assert 1e-5 * q_a.max() < np.abs(q_a - q_b).max() < 1e-2 * q_a.max()


def test_tilt_arm_is_validated_and_read_from_the_file(tmp_path):
    with pytest.raises(InputError, match="tilt_arm"):
        BallRow(n_elements=10, element_diameter=0.01, pitch_diameter=0.06, tilt_arm="pitch")
    choices = schema.AngularContactPairGeometry.model_fields["tilt_arm"].annotation.__args__[0].__args__
    assert set(choices) == set(TILT_ARMS)
    src = (EXAMPLES / "acbb_7209_DB.toml").read_text()
    path = tmp_path / "pair.toml"
    path.write_text(src.replace("[geometry]", '[geometry]\ntilt_arm = "pitch_radius"', 1))
    assert {r.tilt_arm for r in load_file(path).model.rows} == {"pitch_radius"}
