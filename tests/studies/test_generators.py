"""Case generators: orthogonal arrays (strength 2), seed 000 Table 3 L9, factorials, sweeps, Monte Carlo."""

import itertools

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.studies.designs import generators as g

#: (runs, columns, levels of each column) of Taguchi's standard arrays (Phadke 1989, App. C).
SHAPES = {
    "L4": (4, [2] * 3),
    "L8": (8, [2] * 7),
    "L16": (16, [2] * 15),
    "L9": (9, [3] * 4),
    "L27": (27, [3] * 13),
    "L18": (18, [2] + [3] * 7),
}


@pytest.mark.parametrize("name", list(g.ARRAYS))
def test_every_pair_of_columns_is_balanced(name):
    a = g.orthogonal_array(name)
    runs, levels = SHAPES[name]
    assert a.shape == (runs, len(levels))
    assert [np.unique(a[:, j]).size for j in range(a.shape[1])] == levels
    for i, j in itertools.combinations(range(a.shape[1]), 2):
        pairs, counts = np.unique(a[:, [i, j]], axis=0, return_counts=True)
        assert len(pairs) == levels[i] * levels[j]
        assert np.all(counts == runs // (levels[i] * levels[j]))
    assert g.is_orthogonal(a)


def test_is_orthogonal_rejects_an_unbalanced_array():
    a = g.orthogonal_array("L9").copy()
    a[0, 1] = 1
    assert not g.is_orthogonal(a)


def test_l8_and_l27_are_taguchis_printed_tables():
    """Spot rows of the printed tables (Phadke 1989, App. C)."""
    l8 = g.orthogonal_array("L8") + 1
    assert l8[1].tolist() == [1, 1, 1, 2, 2, 2, 2]
    assert l8[7].tolist() == [2, 2, 1, 2, 1, 1, 2]
    l27 = g.orthogonal_array("L27") + 1
    assert l27[3].tolist() == [1, 2, 2, 2, 1, 1, 1, 2, 2, 2, 3, 3, 3]
    assert l27[9].tolist() == [2, 1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3]


#: Seed 000 Table 3 (Tian et al. 2025): A [µm], B [µm, Table 2 sign], C, D [m] of runs 1–9.
TABLE3 = [
    (0, -4, 0.51, 0.2),
    (0, -5, 0.52, 0.3),
    (0, -6, 0.53, 0.4),
    (-1, -4, 0.52, 0.4),
    (-1, -5, 0.53, 0.2),
    (-1, -6, 0.51, 0.3),
    (-2, -4, 0.53, 0.3),
    (-2, -5, 0.51, 0.4),
    (-2, -6, 0.52, 0.2),
]


def test_l9_of_seed000_is_table3():
    levels = {
        "A": [0, -1, -2],
        "B": [-4, -5, -6],
        "C": [0.51, 0.52, 0.53],
        "D": [0.2, 0.3, 0.4],
    }
    design = g.orthogonal_design(levels, "L9")
    assert [tuple(r) for r in design[["A", "B", "C", "D"]].itertuples(index=False)] == TABLE3


def test_orthogonal_design_rejects_wrong_level_count():
    with pytest.raises(InputError):
        g.orthogonal_design({"A": [1, 2]}, "L9", columns=[1])
    with pytest.raises(InputError):
        g.orthogonal_array("L12")


def test_full_factorial_and_sweep():
    ff = g.full_factorial({"a": [1, 2, 3], "b": [10, 20]})
    assert len(ff) == 6 and len(ff.drop_duplicates()) == 6
    sw = g.sweep({"a": [1, 2, 3], "b": [10, 20]}, {"a": 2, "b": 20})
    assert len(sw) == 5
    assert (sw[sw["swept"] == "a"]["b"] == 20).all() and (sw[sw["swept"] == "b"]["a"] == 2).all()


@pytest.mark.parametrize("sampler", g.SAMPLERS)
def test_monte_carlo_is_reproducible_and_has_the_moments(sampler):
    dists = {
        "n": g.Distribution("normal", mean=1e-6, std=0.5e-6),
        "u": g.Distribution("uniform", low=2.0, high=4.0),
    }
    a = g.monte_carlo(dists, 4096, seed=7, sampler=sampler)
    b = g.monte_carlo(dists, 4096, seed=7, sampler=sampler)
    assert a.equals(b)
    assert not a.equals(g.monte_carlo(dists, 4096, seed=8, sampler=sampler))
    assert abs(a["n"].mean() - 1e-6) < 0.05e-6 and abs(a["n"].std() - 0.5e-6) < 0.05e-6
    assert a["u"].between(2.0, 4.0).all() and abs(a["u"].mean() - 3.0) < 0.05


def test_truncnormal_and_lognormal_respect_their_support():
    t = g.monte_carlo({"t": g.Distribution("truncnormal", mean=0.0, std=1.0, low=-0.5, high=1.0)}, 2000, 1)
    assert t["t"].between(-0.5, 1.0).all()
    ln = g.monte_carlo({"l": g.Distribution("lognormal", mean=2.0, std=0.2)}, 20000, 1)
    assert (ln["l"] > 0).all() and abs(ln["l"].mean() - 2.0) < 0.02 and abs(ln["l"].std() - 0.2) < 0.02
    with pytest.raises(InputError):
        g.Distribution("normal", mean=1.0)
