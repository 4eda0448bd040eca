"""The evaluator plumbing of a chunk: grouping by non-batched factors, ids, index handling."""

import numpy as np
import pandas as pd

from bearingkit.studies.evaluators import Evaluator, Factor, group_cases
from bearingkit.studies.run.executors import evaluate_chunk

FACTORS = {
    "x": Factor("x", "dimensionless", 0.0),
    "kind": Factor("kind", "text", "a", batched=False),
    "z": Factor("z", "count", 3, batched=False),
}


def _groups(cases):
    return [(idx.tolist(), dict(key)) for idx, key in group_cases(cases, FACTORS)]


def _reference(cases):
    """What pandas' groupby gives (the general path)."""
    keys = ["kind", "z"]
    return [
        (list(map(int, idx)), dict(zip(keys, key, strict=True)))
        for key, idx in cases.groupby(keys, sort=False, dropna=False).indices.items()
    ]


def test_one_group_when_the_non_batched_factors_are_fixed():
    cases = pd.DataFrame({"x": [0.1, 0.2, 0.3], "kind": "b", "z": 5})
    assert _groups(cases) == [([0, 1, 2], {"kind": "b", "z": 5})] == _reference(cases)


def test_several_groups_as_groupby_gives_them():
    kinds = ["a", "b", "a", "b", "a", "a"]
    cases = pd.DataFrame({"x": np.arange(6.0), "kind": kinds, "z": [3, 3, 3, 3, 4, 3]})
    assert _groups(cases) == _reference(cases)
    assert len(_groups(cases)) == 3


def test_missing_values_form_their_own_group():
    cases = pd.DataFrame({"x": [1.0, 2.0, 3.0], "kind": "a", "z": [np.nan, np.nan, 4.0]})
    got = _groups(cases)
    assert [g[0] for g in got] == [[0, 1], [2]]
    assert np.isnan(got[0][1]["z"]) and got[1][1]["z"] == 4.0


def _double(cases):
    cases["scratch"] = 1.0  # an evaluator may add columns to its input
    return pd.DataFrame({"y": 2.0 * cases["x"].to_numpy(float), "z_seen": cases["z"].to_numpy()})


EV = Evaluator("double", _double, FACTORS)


def test_evaluate_chunk_ids_index_and_defaults():
    cases = pd.DataFrame({"case": [7, 8, 9], "x": [1.0, 2.0, 3.0]}, index=[10, 11, 12])
    out = evaluate_chunk(EV, cases)
    assert out["case"].to_list() == [7, 8, 9] and out["y"].to_list() == [2.0, 4.0, 6.0]
    assert out["z_seen"].to_list() == [3, 3, 3]  # the default filled in
    assert list(cases.columns) == ["case", "x"]  # the caller's frame is untouched
    bare = evaluate_chunk(EV, cases.iloc[1:], with_ids=False)
    assert list(bare.columns) == ["y", "z_seen"] and bare["y"].to_list() == [4.0, 6.0]
    assert isinstance(bare.index, pd.RangeIndex) and bare.index[0] == 0
    full = cases.assign(kind="a", z=3)
    evaluate_chunk(EV, full)
    assert "scratch" not in full.columns  # no defaults to fill: still not the caller's frame
