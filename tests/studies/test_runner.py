"""run_study: identical results on the three executors, Parquet streaming, study files, the CLI entry."""

import numpy as np
import pandas as pd
import pytest

from bearingkit.errors import InputError
from bearingkit.studies.definition import load as sd
from bearingkit.studies.run.executors import (
    DaskExecutor,
    InProcessExecutor,
    ProcessPoolExecutor,
)
from bearingkit.studies.run.runner import build_cases, run_study

EXAMPLES = __import__("pathlib").Path(__file__).resolve().parents[2] / "examples" / "studies"

STATICS = {
    "study": {
        "name": "statics_grid",
        "design": "factorial",
        "evaluator": "seed000_statics",
        "chunk_size": 4,
        "response": "ball_axial_share",
    },
    "fixed": {"axial_load": "3 kN", "radial_load": "1 kN"},
    "factors": [
        {"name": "clearance_axial_ball", "levels": ["-3 um", "-5 um", "-7 um"]},
        {"name": "eccentricity", "levels": ["0 m", "0.2 m", "0.4 m"]},
        {"name": "crowning", "levels": ["a", "e"]},
    ],
}


@pytest.fixture(scope="module")
def reference():
    return run_study(sd.from_dict(STATICS), progress=False)


def test_factorial_runs_and_balances_axial_load(reference):
    r = reference.results
    assert len(r) == 18 and r["converged"].all()
    carried = (
        r["roller_upper_axial_N"]
        + r["ball_upper_axial_N"]
        - r["roller_lower_axial_N"]
        - r["ball_lower_axial_N"]
    )
    np.testing.assert_allclose(carried, 3000.0, rtol=1e-8)
    assert reference.stats == {**reference.stats, "chunks": 5, "computed": 5, "reused": 0}
    assert set(reference.analysis) == {"main_effects", "range"}


def test_process_pool_gives_identical_results(reference):
    with ProcessPoolExecutor(workers=2) as ex:
        res = run_study(sd.from_dict(STATICS), executor=ex, progress=False)
    pd.testing.assert_frame_equal(res.results, reference.results)


def test_dask_local_cluster_gives_identical_results(reference, thread_cluster):
    from distributed import Client

    with thread_cluster(2) as cluster:
        with Client(cluster) as client:
            ex = DaskExecutor(client=client)
            res = run_study(sd.from_dict(STATICS), executor=ex, progress=False)
    pd.testing.assert_frame_equal(res.results, reference.results)


def test_parquet_store_holds_every_chunk(tmp_path, reference):
    res = run_study(sd.from_dict(STATICS), store=tmp_path / "s", progress=False)
    assert len(list((tmp_path / "s" / "chunks").glob("chunk-*.parquet"))) == 5
    pd.testing.assert_frame_equal(res.results, reference.results)
    again = run_study(sd.from_dict(STATICS), store=tmp_path / "s", resume=True, progress=False)
    assert again.stats["computed"] == 0 and again.stats["reused"] == 5
    pd.testing.assert_frame_equal(again.results, reference.results)
    other = sd.from_dict({**STATICS, "fixed": {"axial_load": "4 kN"}})
    with pytest.raises(InputError, match="another study"):
        run_study(other, store=tmp_path / "s", resume=True, progress=False)


def test_statics_evaluator_matches_direct_solve(reference):
    from bearingkit.analysis.solver.quasistatic import solve
    from bearingkit.bearings.common import eccentric_axial_load
    from bearingkit.bearings.turntable import composite_turntable

    row = reference.results.iloc[7]
    model = composite_turntable(clearance_axial_ball=row["clearance_axial_ball"], crowning=row["crowning"])
    res = solve(model, eccentric_axial_load(3000.0, row["eccentricity"], 1000.0)[None])
    np.testing.assert_allclose(res.row("ball_upper").max_load[0], row["ball_upper_max_load_N"], rtol=1e-9)


def test_seed000_l9_example_file_has_table3_runs():
    d = sd.load_study(EXAMPLES / "seed000_l9.toml")
    cases = build_cases(d)
    got = cases[
        ["clearance_axial_roller", "clearance_axial_ball", "groove_curvature", "eccentricity"]
    ].to_numpy()
    table3 = np.array(
        [
            (0, -4, 0.51, 0.2), (0, -5, 0.52, 0.3), (0, -6, 0.53, 0.4),
            (-1, -4, 0.52, 0.4), (-1, -5, 0.53, 0.2), (-1, -6, 0.51, 0.3),
            (-2, -4, 0.53, 0.3), (-2, -5, 0.51, 0.4), (-2, -6, 0.52, 0.2),
        ]
    )  # fmt: skip
    np.testing.assert_allclose(got, table3 * [1e-6, 1e-6, 1, 1], rtol=1e-12, atol=1e-18)
    assert (cases["axial_load"] == 3000.0).all() and (cases["radial_load"] == 3000.0).all()
    assert (cases["pitch_diameter_axial_ball"] == 0.1778).all()  # from the bearing file (Table 1)


def test_example_operating_point_equals_the_validation_module():
    from bearingkit.papers.tian2025 import validation as v

    d = sd.load_study(EXAMPLES / "seed000_l9.toml")
    assert d.fixed["viscosity_factor"] == v.VISCOSITY_FACTOR
    assert d.fixed["cage_mass"] == pytest.approx(v.CAGE_MASS)
    assert d.fixed["speed"] == pytest.approx(v.RPM * 2 * np.pi / 60)


@pytest.mark.parametrize("name", sorted(p.name for p in EXAMPLES.glob("*.toml")))
def test_every_example_study_loads(name):
    d = sd.load_study(EXAMPLES / name)
    assert d.name


def test_bad_study_files_give_one_line_errors():
    bad_unit = {**STATICS, "fixed": {"axial_load": 3000}}
    with pytest.raises(InputError, match="has no unit"):
        sd.from_dict(bad_unit)
    with pytest.raises(InputError, match="not a factor"):
        sd.from_dict({**STATICS, "fixed": {"speeed": "1 rpm"}})
    with pytest.raises(InputError, match="evaluator"):
        sd.from_dict({**STATICS, "study": {**STATICS["study"], "evaluator": "nope"}})
    with pytest.raises(InputError, match="array"):
        sd.from_dict({**STATICS, "study": {**STATICS["study"], "design": "orthogonal"}})


def test_cli_entry_writes_the_outputs(tmp_path):
    from bearingkit.studies.__main__ import run_cli

    lines = []
    res = run_cli(EXAMPLES / "seed000_l9_statics.toml", out=tmp_path, progress=False, echo=lines.append)
    assert len(res.results) == 9
    for f in ("results.parquet", "results.csv", "range.csv", "main_effects.png", "range.png", "summary.json"):
        assert (tmp_path / f).exists()
    assert any("sensitivity ranking" in s for s in lines)
    assert isinstance(InProcessExecutor().map_unordered(len, []), object)
