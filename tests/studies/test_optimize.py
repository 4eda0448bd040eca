"""NSGA-II/III through run_study: ZDT1 front shape, mixed integer + constraints, knee/nearest, resume."""

import numpy as np
import pandas as pd
import pytest

from bearingkit.studies import evaluators
from bearingkit.studies.definition import load as sd
from bearingkit.studies.run.optimize import knee_point, nearest
from bearingkit.studies.run.runner import run_study


def zdt1_study(pop=60, gen=80, algorithm="nsga2", n_var=30):
    return {
        "study": {"name": "zdt1", "design": "optimize", "evaluator": "zdt1", "chunk_size": 1000},
        "optimizer": {"algorithm": algorithm, "pop_size": pop, "generations": gen, "seed": 3},
        "variables": [{"name": f"x{i}", "low": 0.0, "high": 1.0} for i in range(1, n_var + 1)],
        "objectives": [{"output": "f1"}, {"output": "f2"}],
        "targets": {"mid": {"f1": 0.25}},
    }


@pytest.fixture(scope="module")
def zdt1():
    return run_study(sd.from_dict(zdt1_study(n_var=30, pop=100, gen=100)), progress=False)


def test_zdt1_front_is_recovered(zdt1):
    front = zdt1.pareto
    assert zdt1.stats["computed"] == 100 and zdt1.stats["evaluations"] == 100 * 100  # one call per generation
    assert len(front) >= 30
    # points lie close to the true front f2 = 1 − √f1 and spread over f1 ∈ [0, 1]
    err = front["f2"] - (1 - np.sqrt(front["f1"]))
    assert err.min() >= -1e-12 and np.median(err) < 0.05
    assert front["f1"].min() < 0.05 and front["f1"].max() > 0.8
    assert np.all(np.diff(front["f2"].to_numpy()) <= 0)  # sorted by f1 → f2 falls: a trade-off front


def test_selections(zdt1):
    sel = zdt1.selections.set_index("selection")
    assert set(sel.index) == {"knee", "mid"}
    assert abs(sel.loc["mid", "f1"] - 0.25) < 0.05
    # the knee of f2 = 1 − √f1 (normalised) maximises 1 − f1 − f2 at f1 = 1/4
    assert abs(sel.loc["knee", "f1"] - 0.25) < 0.1


def test_knee_and_nearest_closed_form():
    f1 = np.linspace(0, 1, 101)
    F = np.column_stack([f1, 1 - np.sqrt(f1)])
    assert F[knee_point(F), 0] == pytest.approx(0.25)
    frame = pd.DataFrame(F, columns=["a", "b"])
    assert nearest(frame, {"a": 0.62}) == 62


def test_nsga3_runs():
    res = run_study(sd.from_dict(zdt1_study(pop=40, gen=20, algorithm="nsga3", n_var=5)), progress=False)
    assert res.stats["computed"] == 20 and len(res.pareto) > 3


def test_mixed_integer_with_constraint(monkeypatch):
    monkeypatch.setattr(evaluators, "ALLOWED_PLUGINS", {})
    evaluators.allow_plugin("bk_study_helpers:MIXED")  # the explicit opt-in (a file cannot import code)
    study = {
        "study": {"name": "mixed", "design": "optimize", "evaluator": "mixed"},
        "optimizer": {"pop_size": 40, "generations": 30, "seed": 2},
        "variables": [
            {"name": "n", "low": 1, "high": 6, "integer": True},
            {"name": "x", "low": 0.0, "high": 2.0},
        ],
        "objectives": [{"output": "cost"}, {"output": "loss"}],
        "constraints": [{"output": "c", "lower": 1.0}],
    }
    res = run_study(sd.from_dict(study), progress=False)
    front = res.pareto
    assert len(front) > 3
    assert np.all(front["n"] == np.round(front["n"]))
    assert (front["c"] >= 1.0 - 1e-12).all()
    # every evaluated integer variable was integral when the evaluator saw it
    assert np.all(res.results["n"] == np.round(res.results["n"]))


def test_optimisation_resumes_by_replay(tmp_path):
    d = sd.from_dict(zdt1_study(pop=20, gen=10, n_var=5))
    full = run_study(d, store=tmp_path / "a", progress=False)
    # simulate a crash after generation 6: drop the later chunks, then resume
    for p in (tmp_path / "a" / "chunks").glob("chunk-*.parquet"):
        if int(p.stem.split("-")[1]) >= 6:
            p.unlink()
    res = run_study(d, store=tmp_path / "a", resume=True, progress=False)
    assert res.stats["reused"] == 6 and res.stats["computed"] == 4
    pd.testing.assert_frame_equal(res.results, full.results)
    pd.testing.assert_frame_equal(res.pareto, full.pareto)


def test_chunking_of_a_generation_does_not_change_the_run():
    # A population split into chunks of 7 (evaluated one by one, reassembled in order) must give the
    # run of one chunk per generation bit for bit: pymoo sees the same F and G either way.
    one = run_study(sd.from_dict(zdt1_study(pop=20, gen=6, n_var=5)), progress=False)
    split = zdt1_study(pop=20, gen=6, n_var=5)
    split["study"]["chunk_size"] = 7
    many = run_study(sd.from_dict(split), progress=False)
    pd.testing.assert_frame_equal(many.results, one.results, check_exact=True)
    pd.testing.assert_frame_equal(many.pareto, one.pareto, check_exact=True)
    assert list(one.results.columns[:2]) == ["generation", "x1"]
    assert one.results["generation"].to_list() == [g for g in range(6) for _ in range(20)]
