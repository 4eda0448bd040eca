"""Levels × samples studies: Monte Carlo draws at every point of a design, in one study file.

Generation (shape, point-major order, reproducibility, common random numbers, tolerances around a
level), per-point statistics against numpy, range analysis of the mean and of the scatter against a
model with known effects, resume after a crash, the example files, and the CLI outputs.
"""

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bearingkit.errors import InputError
from bearingkit.studies import evaluators
from bearingkit.studies.definition import load as sd
from bearingkit.studies.designs import generators
from bearingkit.studies.evaluators import Evaluator, Factor
from bearingkit.studies.results import analysis
from bearingkit.studies.run.executors import InProcessExecutor
from bearingkit.studies.run.runner import build_cases, run_study

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "studies"

#: Known level effects of the toy model (added to y), per level index of factor "a".
EFFECT_A = (0.0, 4.0, 1.0)
CALLS: list[int] = []
#: Call counts at which the toy raises (a simulated crash: the same evaluator, so the same study).
CRASH_AT: list[int] = []


def _toy(cases):
    """y = 10 + EFFECT_A[a] + b·(1 + e) + t/1 mm; ok = e > 0. Logs the first case of each call."""
    if len(CALLS) in CRASH_AT:
        raise RuntimeError("killed")
    CALLS.append(len(cases))
    a = cases["a"].to_numpy(int)
    b = cases["b"].to_numpy(float)
    e = cases["e"].to_numpy(float)
    t = cases["t"].to_numpy(float)
    y = 10.0 + np.asarray(EFFECT_A)[a] + b * (1.0 + e) + t / 1e-3
    return pd.DataFrame({"y": y, "z": 2.0 * e, "ok": e > 0.0})


TOY = Evaluator(
    "levels_toy",
    _toy,
    {
        "a": Factor("a", "count", 0),
        "b": Factor("b", "dimensionless", 0.0),
        "e": Factor("e", "dimensionless", 0.0),
        "t": Factor("t", "length", 0.0),
    },
    outputs=("y",),
)


@pytest.fixture(autouse=True)
def toy_evaluator(monkeypatch):
    monkeypatch.setitem(evaluators.REGISTRY, TOY.name, TOY)
    CALLS.clear()
    CRASH_AT.clear()
    yield
    CRASH_AT.clear()


def study(per_point=40, common=True, design="factorial", chunk_size=25, **mc):
    data = {
        "study": {
            "name": "levels_samples",
            "design": design,
            "evaluator": "levels_toy",
            "chunk_size": chunk_size,
            "response": "y",
            "seed": 7,
        },
        "factors": [
            {"name": "a", "label": "A", "levels": [0, 1, 2]},
            {"name": "b", "label": "B", "levels": [1.0, 3.0]},
        ],
        "monte_carlo": {
            "per_point": per_point,
            "common": common,
            "sampler": "lhs",
            "factors": [{"name": "e", "distribution": "normal", "mean": 0, "std": 0.1}],
            **mc,
        },
    }
    if design == "orthogonal":
        data["study"]["array"] = "L9"
        data["factors"][1]["levels"] = [1.0, 2.0, 3.0]
    return sd.from_dict(data)


# ------------------------------------------------------------------------------------- generation
def test_cases_are_points_times_draws_point_major():
    cases = build_cases(study(per_point=40))
    assert len(cases) == 6 * 40
    assert list(cases.columns[:3]) == ["case", "point", "draw"]
    np.testing.assert_array_equal(cases["case"], np.arange(240))
    np.testing.assert_array_equal(cases["point"], np.repeat(np.arange(6), 40))
    np.testing.assert_array_equal(cases["draw"], np.tile(np.arange(40), 6))
    # the design (last factor fastest) at every point, constant over its draws
    pts = cases.groupby("point")[["a", "b"]].agg(["min", "max"])
    np.testing.assert_array_equal(pts[("a", "min")], [0, 0, 1, 1, 2, 2])
    np.testing.assert_array_equal(pts[("b", "min")], [1.0, 3.0] * 3)
    assert (pts[("a", "min")] == pts[("a", "max")]).all() and (pts[("b", "min")] == pts[("b", "max")]).all()


def test_common_random_numbers_repeat_the_draws_at_every_point():
    e = build_cases(study(per_point=40, common=True))["e"].to_numpy().reshape(6, 40)
    assert np.all(e == e[0])
    assert np.unique(e[0]).size == 40
    # Latin hypercube: one draw in each of the 40 equal-probability strata of N(0, 0.1)
    from scipy import stats

    strata = np.floor(stats.norm.cdf(e[0], 0.0, 0.1) * 40).astype(int)
    assert sorted(strata) == list(range(40))


def test_independent_draws_differ_between_points_and_are_reproducible():
    e = build_cases(study(per_point=40, common=False))["e"].to_numpy().reshape(6, 40)
    assert all(not np.allclose(e[0], e[p]) for p in range(1, 6))
    again = build_cases(study(per_point=40, common=False))
    pd.testing.assert_frame_equal(build_cases(study(per_point=40, common=False)), again)
    other_seed = build_cases(study(per_point=40, common=False, seed=8))["e"].to_numpy()
    assert not np.allclose(other_seed, e.ravel())


def test_generator_tolerance_is_added_to_the_level():
    design = generators.full_factorial({"t": [1e-3, 2e-3], "b": [0.0, 1.0]})
    dists = {"t": generators.Distribution("uniform", low=-1e-5, high=1e-5)}
    out = generators.levels_by_samples(design, dists, 50, seed=3, deviations=["t"])
    assert len(out) == 200
    np.testing.assert_array_equal(out["nominal_t"], np.repeat(design["t"].to_numpy(), 50))
    dev = out["t"] - out["nominal_t"]
    assert dev.abs().max() <= 1e-5 and dev.std() > 1e-6
    np.testing.assert_allclose(dev.to_numpy().reshape(4, 50), np.tile(dev[:50], (4, 1)), atol=1e-18)
    with pytest.raises(InputError, match="deviations"):
        generators.levels_by_samples(design, {"q": dists["t"]}, 5, seed=3, deviations=["q"])


def test_bad_monte_carlo_sections_give_one_line_errors():
    base = {
        "study": {"name": "x", "design": "factorial", "evaluator": "levels_toy"},
        "factors": [{"name": "b", "levels": [0.0, 1.0]}],
    }
    normal = {"name": "e", "distribution": "normal", "mean": 0, "std": 1}
    tol = {"name": "t", "distribution": "normal", "mean": "0 m", "std": "1 um", "deviation": True}
    count = {"name": "a", "distribution": "uniform", "low": 0, "high": 1}

    def mc(*factors, per_point=5, **kw):
        return {"per_point": per_point, "factors": list(factors), **kw}

    cases = [
        (mc(normal), {"design": "monte_carlo", "samples": 5}, "must be sweep"),
        (mc({"name": "e", "mean": 0}), {}, "distribution"),
        (mc({**normal, "name": "z", "deviation": True}), {}, "not a factor"),
        (mc(tol), {}, "deviation"),  # t is not a design factor
        (mc(count), {}, "count"),
        (mc(normal, normal), {}, "sampled twice"),
        (mc(normal, per_point=0), {}, "per_point"),
        (mc(normal, quantiles=[1.5]), {}, "quantiles"),
        (mc(), {}, "at least one"),
    ]
    for section, head, message in cases:
        data = {**base, "study": {**base["study"], **head}, "monte_carlo": section}
        if head.get("design") == "monte_carlo":
            data["factors"] = [normal]
        with pytest.raises(InputError, match=message):
            sd.from_dict(data)
    clash = {**base, "factors": [{"name": "t", "levels": ["1 mm"]}]}
    with pytest.raises(InputError, match="deviation = true"):
        sd.from_dict({**clash, "monte_carlo": mc({**tol, "deviation": False})})
    with pytest.raises(InputError, match="has no unit"):
        sd.from_dict({**clash, "monte_carlo": mc({**tol, "mean": 0, "std": 1e-6})})
    assert sd.from_dict({**clash, "monte_carlo": mc(tol)}).monte_carlo.factors[0].deviation


# ------------------------------------------------------------------------------------- statistics
def test_point_statistics_equal_numpy_per_point():
    d = study(per_point=40, common=False)
    res = run_study(d, progress=False)
    table = res.analysis["point_statistics"]
    assert list(table["point"]) == list(range(6)) and (table["n_draws"] == 40).all()
    np.testing.assert_array_equal(table["a"], [0, 0, 1, 1, 2, 2])
    for out in ("y", "z"):
        x = res.results[out].to_numpy().reshape(6, 40)  # point-major
        np.testing.assert_allclose(table[f"{out}_mean"], x.mean(axis=1), rtol=1e-13)
        np.testing.assert_allclose(table[f"{out}_std"], x.std(axis=1, ddof=1), rtol=1e-12)
        np.testing.assert_array_equal(table[f"{out}_min"], x.min(axis=1))
        np.testing.assert_array_equal(table[f"{out}_max"], x.max(axis=1))
        for q, label in ((0.05, "q5"), (0.5, "q50"), (0.95, "q95")):
            np.testing.assert_allclose(table[f"{out}_{label}"], np.quantile(x, q, axis=1), rtol=1e-13)
    ok = res.results["ok"].to_numpy().reshape(6, 40)
    np.testing.assert_allclose(table["ok_fraction"], ok.mean(axis=1))
    assert "ok_mean" not in table.columns


def test_point_statistics_quantile_labels_and_single_draw():
    assert [analysis.quantile_label(q) for q in (0.05, 0.5, 0.025, 0.999)] == ["q5", "q50", "q2.5", "q99.9"]
    frame = pd.DataFrame({"point": [0, 1, 1], "y": [1.0, 2.0, 4.0], "f": [True, False, True]})
    t = analysis.point_statistics(frame, ["y", "f"], quantiles=(0.25,))
    assert np.isnan(t.loc[0, "y_std"]) and t.loc[1, "y_std"] == pytest.approx(np.sqrt(2.0))
    assert t.loc[1, "y_q25"] == pytest.approx(2.5) and list(t["f_fraction"]) == [1.0, 0.5]


def test_range_of_the_mean_and_of_the_scatter_recover_known_effects():
    """y = 10 + A-effect + b(1 + e): with common draws the level means differ exactly by the effects;
    the scatter std(y) = b·std(e) depends on B only (range of the std of A: 0)."""
    res = run_study(study(per_point=30, design="orthogonal"), progress=False)
    e = res.cases.loc[res.cases["point"] == 0, "e"].to_numpy()  # the draws every point shares
    rng = res.analysis["range"].set_index("factor")
    assert rng.loc["a", "range"] == pytest.approx(max(EFFECT_A) - min(EFFECT_A), rel=1e-12)
    assert rng.loc["b", "range"] == pytest.approx(2.0 * (1.0 + e.mean()), rel=1e-12)  # b(1 + ē), b 1..3
    std = res.analysis["range_std"].set_index("factor")
    assert std.loc["b", "range"] == pytest.approx(2.0 * e.std(ddof=1), rel=1e-9)
    assert std.loc["a", "range"] < 1e-12
    assert list(res.analysis["range"]["label"]) == ["A", "B"]
    assert len(res.analysis["point_statistics"]) == 9


# ------------------------------------------------------------------------------------- store, resume
def test_chunks_carry_point_and_draw_and_a_crash_resumes(tmp_path, monkeypatch):
    d = study(per_point=20, chunk_size=25)  # 120 cases → 5 chunks, crossing point boundaries
    fresh = run_study(d, progress=False)
    store = tmp_path / "store"

    CALLS.clear()
    CRASH_AT.append(3)  # the fourth call raises (one chunk after the other: the calls are counted)
    sequential = InProcessExecutor(threads=1)
    with pytest.raises(RuntimeError, match="killed"):
        run_study(d, executor=sequential, store=store, progress=False)
    chunk_files = sorted((store / "chunks").glob("chunk-*.parquet"))
    assert [p.name for p in chunk_files] == [f"chunk-00000{i}.parquet" for i in range(3)]
    on_disk = pd.read_parquet(chunk_files[1])
    assert list(on_disk.columns[:3]) == ["case", "point", "draw"]
    np.testing.assert_array_equal(on_disk["point"], fresh.cases["point"].iloc[25:50])
    np.testing.assert_array_equal(on_disk["draw"], fresh.cases["draw"].iloc[25:50])

    CRASH_AT.clear()
    CALLS.clear()
    resumed = run_study(d, executor=sequential, store=store, resume=True, progress=False)
    assert CALLS == [25, 20], "only the two missing chunks (cases 75-99, 100-119) are computed"
    assert resumed.stats["computed"] == 2 and resumed.stats["reused"] == 3
    pd.testing.assert_frame_equal(resumed.results, fresh.results)
    pd.testing.assert_frame_equal(resumed.analysis["point_statistics"], fresh.analysis["point_statistics"])
    # another draw count is another study: no resume into this store
    with pytest.raises(InputError, match="another study"):
        run_study(study(per_point=21, chunk_size=25), store=store, resume=True, progress=False)


def test_dask_gives_the_in_process_results(thread_cluster):
    from distributed import Client

    from bearingkit.studies.run.executors import DaskExecutor

    d = study(per_point=10, chunk_size=16)
    ref = run_study(d, progress=False)
    with thread_cluster(2) as cluster:
        with Client(cluster) as client:
            res = run_study(d, executor=DaskExecutor(client=client), progress=False)
    pd.testing.assert_frame_equal(res.results, ref.results)


# ------------------------------------------------------------------------------------- examples, CLI
def test_seed001_example_is_three_levels_of_2000_common_draws():
    d = sd.load_study(EXAMPLES / "seed001_levels_mc.toml")
    assert d.design == "factorial" and d.monte_carlo.per_point == 2000 and d.monte_carlo.common
    cases = build_cases(d)
    assert len(cases) == 3 * 2000
    np.testing.assert_allclose(cases.groupby("point")["magnitude"].first(), [0.5e-6, 1.0e-6, 1.5e-6])
    z = cases[[f"z{j}" for j in range(1, 24)]].to_numpy().reshape(3, 2000, 23)
    assert np.all(z == z[0])
    assert abs(z[0].mean()) < 0.01 and abs(z[0].std() - 1.0) < 0.01


def test_seed001_levels_equal_separate_monte_carlo_runs():
    """One levels × samples study with common draws = one plain Monte Carlo study per S_d."""
    base = sd.load_study(EXAMPLES / "seed001_levels_mc.toml")
    n = 12
    d = base.model_copy(update={"monte_carlo": base.monte_carlo.model_copy(update={"per_point": n})})
    res = run_study(d, progress=False)
    plain = sd.load_study(EXAMPLES / "seed001_monte_carlo.toml")
    assert plain.seed == base.monte_carlo.seed and plain.sampler == base.monte_carlo.sampler
    for p, s_d in enumerate((0.5e-6, 1.0e-6, 1.5e-6)):
        one = plain.model_copy(update={"samples": n, "fixed": {**plain.fixed, "magnitude": s_d}})
        sep = run_study(one, progress=False).results
        got = res.results[res.results["point"] == p].reset_index(drop=True)
        np.testing.assert_array_equal(got[["z1", "z23"]], sep[["z1", "z23"]])
        for out in ("max_contact_force_N", "sliding_increment_N"):
            np.testing.assert_allclose(got[out], sep[out], rtol=1e-9)
    stats = res.analysis["point_statistics"]
    assert stats["max_contact_force_N_mean"].is_monotonic_increasing  # larger scatter, larger peak


def test_seed000_tolerance_example_builds_toleranced_l9_runs():
    d = sd.load_study(EXAMPLES / "seed000_l9_tolerance.toml")
    cases = build_cases(d)
    assert len(cases) == 9 * 100
    runs = cases.groupby("point").first()
    np.testing.assert_allclose(runs["nominal_clearance_axial_ball"] / 1e-6, [-4, -5, -6] * 3, rtol=1e-12)
    dev = cases["clearance_axial_ball"] - cases["nominal_clearance_axial_ball"]
    assert dev.abs().max() <= 1e-6 + 1e-18 and 0.3e-6 < dev.std() < 0.5e-6  # truncated N(0, 0.5 um)


def test_cli_writes_point_statistics(tmp_path):
    from bearingkit.studies.__main__ import run_cli

    f = tmp_path / "levels.toml"
    f.write_text(
        """
[study]
name = "levels_cli"
design = "factorial"
evaluator = "levels_toy"
response = "y"
chunk_size = 10

[fixed]
b = 2.0

[[factors]]
name = "a"
levels = [0, 1, 2]

[[factors]]
name = "t"
levels = ["1 mm", "2 mm"]

[monte_carlo]
per_point = 8
seed = 1
quantiles = [0.1, 0.9]

[[monte_carlo.factors]]
name = "t"
deviation = true
distribution = "uniform"
low = "-10 um"
high = "10 um"

[[monte_carlo.factors]]
name = "e"
distribution = "normal"
mean = 0
std = 0.1
"""
    )
    lines = []
    res = run_cli(f, out=tmp_path / "out", progress=False, echo=lines.append)
    table = pd.read_csv(tmp_path / "out" / "point_statistics.csv")
    assert len(table) == 6 and {"y_q10", "y_q90", "t"} <= set(table.columns)
    np.testing.assert_allclose(table["t"], [1e-3, 2e-3] * 3)  # the level, not a draw
    for name in ("range.csv", "range_std.csv", "point_statistics.png", "results.parquet"):
        assert (tmp_path / "out" / name).exists()
    saved = pd.read_parquet(tmp_path / "out" / "results.parquet")
    assert {"point", "draw", "nominal_t"} <= set(saved.columns) and len(saved) == len(res.results) == 48
    assert any("6 design points x 8 draws" in s for s in lines)
