"""The compiled solver core agrees with the numpy reference (design.md §7.4), and falls back without numba.

Every example file and the validation bearings are solved by both backends; the displacement,
stiffness and reactions must agree to 1e-12 relative (both follow the same algorithm step by step;
what remains is the order of floating-point sums). Tapered rows under light loads agree to their
roller sub-problem's tolerance instead (ROLLER_RTOL = 1e-12 of the roller load plus an absolute
floor of ~2e-10 N per roller, reached from different warm starts).
"""

import os
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest

from bearingkit.analysis.solver.quasistatic import SolverOptions, load_vector, solve
from bearingkit.bearings.tapered import seed001_pair, seed001_row
from bearingkit.bearings.turntable import composite_turntable
from bearingkit.io.loader import load_file
from bearingkit.physics.deviations import seed001_series

#: Every example file of one bearing (shaft-system files hold several and are solved by systems/).
EXAMPLES = [
    p
    for p in sorted((Path(__file__).resolve().parents[3] / "examples").glob("*.toml"))
    if "bearing" in tomllib.loads(p.read_text(encoding="utf-8"))
]
COMPILED = SolverOptions(backend="compiled")
NUMPY = SolverOptions(backend="numpy")


def _agree(model, load, free=None, rtol=1e-12):
    a = solve(model, load, free=free, options=COMPILED)
    b = solve(model, load, free=free, options=NUMPY)
    np.testing.assert_array_equal(a.converged, b.converged)
    np.testing.assert_array_equal(a.iterations, b.iterations)
    for x, y in ((a.displacement, b.displacement), (a.stiffness, b.stiffness), (a.load, b.load)):
        scale = np.abs(y).reshape(len(y), -1).max(axis=1)
        err = np.abs(x - y).reshape(len(y), -1).max(axis=1)
        np.testing.assert_array_less(err, rtol * scale + 1e-300)
    return a


def _compiled(model) -> bool:
    from bearingkit.analysis.solver import compiled_newton

    return compiled_newton.pack_model(model.kernels) is not None


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_every_example_agrees_with_the_numpy_reference(path):
    """Every example whose kernels the compiled core covers; the others run the numpy path (auto)."""
    inp = load_file(path)
    if not _compiled(inp.model):
        auto = solve(inp.model, inp.load_matrix(), free=inp.free, options=SolverOptions(backend="auto"))
        ref = solve(inp.model, inp.load_matrix(), free=inp.free, options=NUMPY)
        np.testing.assert_array_equal(auto.displacement, ref.displacement)  # auto fell back to numpy
        return
    res = _agree(inp.model, inp.load_matrix(), free=inp.free)
    assert res.converged.all()


def test_seed000_composite_batch_agrees():
    loads = load_vector(
        F_z=np.linspace(1000.0, 8000.0, 12), F_x=np.linspace(0.0, 3000.0, 12), M_y=-np.linspace(0, 1800.0, 12)
    )
    _agree(composite_turntable(), loads)
    _agree(composite_turntable(), loads, free=[True, False, True, False, True])


def test_seed001_deviation_batch_and_pairs_agree():
    dev = np.stack([seed001_series(k) for k in range(1, 7)])
    from bearingkit.analysis.solver.model import BearingModel

    model = BearingModel((seed001_row(diameter_deviation=dev),))
    _agree(model, load_vector(F_z=np.full(6, 10_000.0)), free=[True, True, True, False, False])
    pair = seed001_pair(arrangement="DB", spacing=0.04, clearance=-10e-6)
    _agree(pair, load_vector(F_x=[3000.0, -500.0], F_z=[5000.0, 200.0], M_y=[-60.0, 5.0]), rtol=1e-10)


def test_without_numba_the_numpy_reference_runs_with_one_warning():
    """Small jobs never ask for numba (issue 42: they run on the numpy core anyway); the first job large
    enough to want the compiled core warns once that it is unavailable, and runs on numpy (the numpy
    path counts no coarse-model evaluations)."""
    code = (
        "import sys, warnings; sys.modules['numba'] = None\n"
        "import numpy as np\n"
        "from bearingkit.analysis.solver.backend import SMALL_JOB_CASES\n"
        "from bearingkit.analysis.solver.quasistatic import solve, load_vector\n"
        "from bearingkit.bearings.turntable import composite_turntable\n"
        "m = composite_turntable()\n"
        "big = load_vector(F_z=np.linspace(1000.0, 4000.0, SMALL_JOB_CASES + 1))\n"
        "with warnings.catch_warnings(record=True) as w:\n"
        "    warnings.simplefilter('always')\n"
        "    a = solve(m, load_vector(F_z=3000.0))\n"
        "    before = len(w)\n"
        "    b = solve(m, big); c = solve(m, big)\n"
        "n = sum('compiled solver core is unavailable' in str(x.message) for x in w)\n"
        "print(before, n, a.converged[0], b.converged.all(), b.coarse_evaluations is None)\n"
    )
    env = {**os.environ, "BEARINGKIT_BACKGROUND_COMPILE": "0"}
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env)
    assert out.stdout.split() == ["0", "1", "True", "True", "True"]


def test_compiled_backend_refuses_what_it_cannot_take():
    from bearingkit.errors import InputError
    from bearingkit.rows.base import RacewayOffset

    model = composite_turntable()
    offset = {"ball_upper": RacewayOffset(shift=np.zeros((1, 5)))}
    with pytest.raises(InputError, match="raceway offsets"):
        solve(model, load_vector(F_z=3000.0), options=COMPILED, raceway_offsets=offset)
    # "auto" runs the numpy reference for it instead.
    assert solve(model, load_vector(F_z=3000.0), raceway_offsets=offset).converged.all()


def test_kernels_at_speed_run_the_numpy_path():
    """A ball row at speed is a subclass of the ball kernel with more physics: never packed as a plain one."""
    from bearingkit.analysis.solver import compiled_newton
    from bearingkit.analysis.solver.speed import model_at_speed

    inp = load_file(Path(__file__).resolve().parents[3] / "examples" / "acbb_7209.toml")
    assert compiled_newton.pack_model(inp.model.kernels) is not None
    fast = model_at_speed(inp.model, np.full(len(inp.cases), 2000.0))
    assert compiled_newton.pack_model(fast.kernels) is None
    auto = solve(inp.model, inp.load_matrix(), free=inp.free, speed=2000.0)
    ref = solve(inp.model, inp.load_matrix(), free=inp.free, speed=2000.0, options=NUMPY)
    np.testing.assert_array_equal(auto.displacement, ref.displacement)


def test_compiled_roller_loads_agree_with_roller_state():
    """The Monte Carlo's compiled per-roller loads against the numpy kernel's roller sub-problem
    (same algorithm from the same closed-form start: agreement to rounding, 1e-12 of the largest)."""
    from bearingkit.analysis.solver.model import BearingModel
    from bearingkit.rows.tapered.compiled import roller_loads

    dev = np.stack([seed001_series(k) for k in range(1, 7)])
    row = seed001_row(diameter_deviation=dev)
    model = BearingModel((row,))
    load = load_vector(F_z=np.linspace(200.0, 20_000.0, 6) * row.direction, F_x=[0, 0, 300.0, 0, 0, 900.0])
    res = solve(model, load, free=[True, True, True, False, False])
    assert res.converged.all()
    got = roller_loads(model.kernels[0], res.displacement)
    ref = model.kernels[0].roller_state(res.displacement)
    for k, key in enumerate(("load_inner", "load_outer", "load_flange")):
        np.testing.assert_allclose(got[..., k], ref[key], rtol=0, atol=1e-12 * np.abs(ref[key]).max())


@pytest.mark.parametrize("backend", ["compiled", "numpy"])
def test_light_load_tapered_roller_loads_balance_the_ring(backend, monkeypatch):
    """Seed 001's 32008 under F_z = 0.49 N: the reported roller loads must balance the ring.

    The compiled core solves the rollers inside its Newton; the outputs used to solve them again from
    the closed-form guess, which at this load needs more than ROLLER_MAX_ITER steps: the JSON then
    showed a 7.5 N roller (cup loads summing to 6.7 N radial, 1.8 N axial) for a converged 0.49 N
    case. The outputs now start from the compiled solve's roller positions.
    """
    from bearingkit.pipeline.analysis import analyze

    path = Path(__file__).resolve().parents[3] / "examples" / "trb_32008.toml"
    monkeypatch.setenv("BEARINGKIT_BACKEND", backend)
    res = analyze(path, load={"F_z": "0.49 N"}, speed="241.6 rpm").statics
    assert res.converged.all()
    row = res.to_dict(0)["rows"][0]
    assert row["axial_load_N"] == pytest.approx(0.49, rel=1e-9)
    assert row["radial_load_N"] < 1e-9 * 0.49
    assert max(row["loads_N"]) < 0.49  # no roller carries more than the whole bearing


def test_tapered_rows_at_a_speed_per_case_agree_and_equal_each_speed_alone():
    """A tapered bearing whose load cases run at different speeds (a load spectrum) is one solve: each
    roller's centrifugal force is that case's. The compiled core agrees with the numpy reference to
    1e-12, and every case equals the same load solved alone at its own speed (1e-9; both converge to
    the solver's tolerance from different iterates). The speeds are high enough that the centrifugal
    force moves the result: one speed for all cases would fail the comparison."""
    from bearingkit.analysis.solver.model import BearingModel

    pair = seed001_pair(arrangement="DB", spacing=0.04, clearance=-10e-6)
    rpm = np.array([500.0, 6000.0, 12000.0, 6000.0])
    speed = rpm * np.pi / 30.0
    load = load_vector(F_x=[3000.0, 3000.0, 1500.0, -500.0], F_z=[5000.0, 5000.0, 2000.0, 200.0])
    both = [solve(pair, load, speed=speed, options=o) for o in (COMPILED, NUMPY)]
    for res in both:
        assert res.converged.all(), res.reason
    a, b = both
    for x, y in ((a.displacement, b.displacement), (a.stiffness, b.stiffness)):
        scale = np.abs(y).reshape(len(y), -1).max(axis=1)
        np.testing.assert_array_less(np.abs(x - y).reshape(len(y), -1).max(axis=1), 1e-12 * scale)
    assert isinstance(pair, BearingModel)
    for c in range(len(rpm)):
        alone = solve(pair, load[c : c + 1], speed=speed[c], options=NUMPY)
        scale = np.abs(alone.displacement[0]).max()
        np.testing.assert_array_less(np.abs(b.displacement[c] - alone.displacement[0]), 1e-9 * scale)
    # the speed matters at this precision: cases 0 and 1 share the load, not the speed
    assert np.abs(b.displacement[1] - b.displacement[0]).max() > 1e-6 * np.abs(b.displacement[0]).max()
    # the compiled per-roller loads (Monte Carlo outputs) take each case's centrifugal force too
    from bearingkit.analysis.solver.speed import model_at_speed
    from bearingkit.rows.tapered.compiled import roller_loads

    for kernel in model_at_speed(pair, speed).kernels:
        got = roller_loads(kernel, b.displacement)
        ref = kernel.roller_state(b.displacement)
        for k, key in enumerate(("load_inner", "load_outer", "load_flange")):
            np.testing.assert_allclose(got[..., k], ref[key], rtol=0, atol=1e-12 * np.abs(ref[key]).max())


def test_speeds_that_are_not_one_per_case_are_one_line():
    from bearingkit.errors import InputError

    pair = seed001_pair(arrangement="DB", spacing=0.04, clearance=-10e-6)
    load = load_vector(F_z=[5000.0, 5000.0, 2000.0, 200.0])
    with pytest.raises(InputError, match=r"speed \(inner ring\): 3 values for 4 load cases") as err:
        solve(pair, load, speed=np.array([100.0, 200.0, 300.0]))
    assert "\n" not in str(err.value)
    with pytest.raises(InputError, match=r"speed \(shape \(2, 3\)\) must be one value"):
        seed001_row(speed=np.ones((2, 3)))
    with pytest.raises(InputError, match="must be finite"):
        solve(pair, load, speed=np.array([100.0, np.nan, 1.0, 2.0]))
