"""Case generators of design studies: sweeps, full factorials, orthogonal arrays, Monte Carlo samples,
and levels × samples (Monte Carlo draws at every point of a design).

SI units: factor values are passed through unchanged (the study definition has already parsed them
to SI). Every generator returns a :class:`pandas.DataFrame` with one row per case and one column per
factor, in a deterministic order (Monte Carlo samples are reproducible from their seed).

Orthogonal arrays (Taguchi's standard arrays, in Taguchi's standard column order):

- L4(2^3), L8(2^7), L16(2^15), L9(3^4), L27(3^13) are the Rao–Hamming (Bose) arrays over GF(2) and
  GF(3): with run r = (a, b, c, …) in base s (a the most significant digit), each column is the linear
  form Σ g_k x_k mod s of a generator vector g whose last non-zero coefficient is 1. Columns come in
  groups: the basic column of a new digit, then that digit added to every earlier combination, the
  earlier coefficients counted with the first digit fastest. This gives exactly the tables printed by
  Taguchi (1987) and Phadke (1989, App. C), e.g. L9 = (a, b, a+b, 2a+b).
- L18(2^1 × 3^7) is not a linear array; it is Taguchi's table (Phadke 1989, App. C), stored as data.

Every array is checked for strength 2 (each pair of columns holds each level pair equally often) by
:func:`is_orthogonal` in the tests. No maintained PyPI library was clearly better for these six
arrays: pyDOE3 ships Taguchi tables but would add a dependency for ~40 lines of algebra.
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from bearingkit import references
from bearingkit.errors import InputError

references.add(
    "taguchi1987",
    "Taguchi, G. (1987). System of Experimental Design, vols. 1–2. UNIPUB/Kraus, New York.",
)
references.add(
    "phadke1989",
    "Phadke, M. S. (1989). Quality Engineering Using Robust Design. Prentice Hall, Appendix C "
    "(standard orthogonal arrays).",
)
references.add(
    "hedayat1999",
    "Hedayat, A. S., Sloane, N. J. A., Stufken, J. (1999). Orthogonal Arrays: Theory and Applications. "
    "Springer, ch. 3 (Rao–Hamming construction). doi:10.1007/978-1-4612-1478-6",
)

#: Taguchi's L18(2^1 × 3^7), levels 1-based as printed (Phadke 1989, Appendix C).
_L18 = (
    "11111111 11222222 11333333 12112233 12223311 12331122 13121323 13232131 13313212 "
    "21133221 21211332 21322113 22123132 22231213 22312321 23132312 23213123 23321231"
)


def _linear_array(s: int, digits: int) -> np.ndarray:
    """Rao–Hamming array over GF(s), s prime: s**digits runs, (s**digits − 1)/(s − 1) columns."""
    runs = np.array(list(itertools.product(range(s), repeat=digits)))  # first digit most significant
    gens = []
    for k in range(digits):
        for earlier in itertools.product(range(s), repeat=k):
            # earlier coefficients counted with the first digit fastest (Taguchi's column order)
            g = [*reversed(earlier), 1] + [0] * (digits - k - 1)
            gens.append(g)
    return (runs @ np.array(gens).T) % s


def _l18() -> np.ndarray:
    return np.array([[int(ch) - 1 for ch in row] for row in _L18.split()])


#: Orthogonal array name → function returning the (runs, columns) array of 0-based levels.
ARRAYS = {
    "L4": lambda: _linear_array(2, 2),
    "L8": lambda: _linear_array(2, 3),
    "L16": lambda: _linear_array(2, 4),
    "L9": lambda: _linear_array(3, 2),
    "L27": lambda: _linear_array(3, 3),
    "L18": _l18,
}


def orthogonal_array(name: str) -> np.ndarray:
    """The orthogonal array ``name`` (one of :data:`ARRAYS`) as 0-based integer levels (runs, columns).

    Parameters
    ----------
    name : str
        ``"L4"``, ``"L8"``, ``"L9"``, ``"L16"``, ``"L18"`` or ``"L27"``.

    Notes
    -----
    Linear arrays: level of run r in column g is

    .. math:: x_{rg} = \\sum_k g_k\\, r_k \\bmod s

    with r_k the base-s digits of r (Hedayat et al. 1999, §3.4; Taguchi 1987; Phadke 1989, App. C).
    """
    if name not in ARRAYS:
        raise InputError(f"array ({name!r}) must be one of {', '.join(ARRAYS)}")
    return ARRAYS[name]()


def is_orthogonal(array: np.ndarray) -> bool:
    """True if every pair of columns holds every level pair equally often (strength 2)."""
    a = np.asarray(array)
    n, k = a.shape
    for i, j in itertools.combinations(range(k), 2):
        si, sj = np.unique(a[:, i]).size, np.unique(a[:, j]).size
        counts = np.zeros((si, sj), int)
        np.add.at(counts, (a[:, i], a[:, j]), 1)
        if not np.all(counts == n // (si * sj)) or n % (si * sj):
            return False
    return True


def _frame(columns: Mapping[str, Sequence]):
    import pandas as pd

    return pd.DataFrame({k: list(v) for k, v in columns.items()})


def orthogonal_design(factors: Mapping[str, Sequence], array: str, columns: Sequence[int] | None = None):
    """Cases of an orthogonal-array design.

    Parameters
    ----------
    factors : mapping name → levels
        Factor levels (SI), in the order of the array's levels 1, 2, 3 …
    array : str
        Array name (:data:`ARRAYS`).
    columns : sequence of int or None
        1-based array column of each factor (Taguchi's numbering); default the first columns with
        the right number of levels, in order.

    Returns
    -------
    DataFrame
        One row per run; factor values plus ``level_<name>`` (1-based level numbers).
    """
    oa = orthogonal_array(array)
    nlev = [np.unique(oa[:, j]).size for j in range(oa.shape[1])]
    names = list(factors)
    if columns is None:
        free = list(range(oa.shape[1]))
        columns = []
        for name in names:
            pick = next((j for j in free if nlev[j] == len(factors[name])), None)
            if pick is None:
                raise InputError(
                    f"factor {name!r} has {len(factors[name])} levels; no free {array} column has that many"
                )
            free.remove(pick)
            columns.append(pick + 1)
    if len(columns) != len(names) or len(set(columns)) != len(columns):
        raise InputError(f"columns ({list(columns)}) must give one distinct {array} column per factor")
    out, levels = {}, {}
    for name, col in zip(names, columns, strict=True):
        if not 1 <= col <= oa.shape[1]:
            raise InputError(f"column of factor {name!r} ({col}) must be in 1..{oa.shape[1]} for {array}")
        lv = list(factors[name])
        if len(lv) != nlev[col - 1]:
            raise InputError(
                f"factor {name!r} has {len(lv)} levels but column {col} of {array} has {nlev[col - 1]}"
            )
        idx = oa[:, col - 1]
        out[name] = [lv[i] for i in idx]
        levels[f"level_{name}"] = idx + 1
    return _frame({**out, **levels})


def full_factorial(factors: Mapping[str, Sequence]):
    """Every combination of the factor levels; the last factor varies fastest."""
    names = list(factors)
    combos = list(itertools.product(*(list(factors[n]) for n in names)))
    return _frame({n: [c[i] for c in combos] for i, n in enumerate(names)})


def sweep(factors: Mapping[str, Sequence], base: Mapping[str, object]):
    """Single-factor sweeps: each factor through its levels, every other factor at its ``base`` value.

    Returns a DataFrame with the factors and a ``swept`` column naming the factor varied in each case.
    """
    rows = []
    for name, levels in factors.items():
        for v in levels:
            rows.append({**{k: base[k] for k in factors}, name: v, "swept": name})
    import pandas as pd

    return pd.DataFrame(rows)


# ------------------------------------------------------------------------------------- Monte Carlo
@dataclass(frozen=True)
class Distribution:
    """A scalar distribution of a Monte Carlo factor (SI).

    ``kind``: ``"normal"`` (mean, std), ``"uniform"`` (low, high), ``"lognormal"`` (mean, std of the
    variable itself), ``"truncnormal"`` (mean, std, low, high).
    """

    kind: str
    mean: float | None = None
    std: float | None = None
    low: float | None = None
    high: float | None = None

    def __post_init__(self):
        need = {
            "normal": ("mean", "std"),
            "uniform": ("low", "high"),
            "lognormal": ("mean", "std"),
            "truncnormal": ("mean", "std", "low", "high"),
        }
        if self.kind not in need:
            raise InputError(f"distribution ({self.kind!r}) must be one of {', '.join(need)}")
        for f in need[self.kind]:
            if getattr(self, f) is None:
                raise InputError(f"{self.kind} distribution needs {f}")
        if self.std is not None and not self.std >= 0:
            raise InputError(f"std ({self.std}) must be non-negative")
        if self.low is not None and self.high is not None and not self.high > self.low:
            raise InputError(f"high ({self.high}) must exceed low ({self.low})")

    def ppf(self, u: np.ndarray) -> np.ndarray:
        """Inverse CDF at probabilities u ∈ (0, 1)."""
        from scipy import stats

        if self.kind == "normal":
            return stats.norm.ppf(u, self.mean, self.std)
        if self.kind == "uniform":
            return self.low + (self.high - self.low) * u
        if self.kind == "lognormal":
            s2 = np.log1p((self.std / self.mean) ** 2)
            return stats.lognorm.ppf(u, np.sqrt(s2), scale=self.mean * np.exp(-s2 / 2))
        a, b = (self.low - self.mean) / self.std, (self.high - self.mean) / self.std
        return stats.truncnorm.ppf(u, a, b, loc=self.mean, scale=self.std)


#: Monte Carlo samplers of the unit hypercube: plain pseudo-random, Latin hypercube, scrambled Sobol'.
SAMPLERS = ("random", "lhs", "sobol")


def monte_carlo(distributions: Mapping[str, Distribution], n: int, seed: int, sampler: str = "random"):
    """``n`` samples of independent factors, reproducible from ``seed``.

    Uniform numbers u ∈ (0, 1)^d from ``sampler`` (numpy PCG64, or scipy.stats.qmc Latin hypercube /
    scrambled Sobol'), mapped through each factor's inverse CDF.
    """
    if sampler not in SAMPLERS:
        raise InputError(f"sampler ({sampler!r}) must be one of {', '.join(SAMPLERS)}")
    if int(n) < 1:
        raise InputError(f"samples ({n}) must be >= 1")
    d = len(distributions)
    if sampler == "random":
        u = np.random.default_rng(seed).random((n, d))
    else:
        from scipy.stats import qmc

        eng = qmc.LatinHypercube(d, seed=seed) if sampler == "lhs" else qmc.Sobol(d, seed=seed)
        u = eng.random(n)
    u = np.clip(u, 1e-12, 1 - 1e-12)
    return _frame({k: dist.ppf(u[:, i]) for i, (k, dist) in enumerate(distributions.items())})


def _point_seeds(seed: int, n_points: int) -> list[int]:
    """Independent, reproducible seeds of the design points (numpy SeedSequence children)."""
    children = np.random.SeedSequence(int(seed)).spawn(int(n_points))
    return [int(c.generate_state(1, np.uint64)[0]) for c in children]


def levels_by_samples(
    design,
    distributions: Mapping[str, Distribution],
    per_point: int,
    seed: int,
    sampler: str = "random",
    common: bool = True,
    deviations: Sequence[str] = (),
):
    """Every design point repeated with ``per_point`` Monte Carlo draws (a levels × samples design).

    Parameters
    ----------
    design : DataFrame
        The design points, one row each (from :func:`orthogonal_design`, :func:`full_factorial` or
        :func:`sweep`), factor values in SI.
    distributions : mapping name → Distribution
        Sampled factors (SI).
    per_point : int
        Draws per design point, N.
    seed : int
        Seed of the draws (reproducible).
    sampler : str
        ``"random"``, ``"lhs"`` or ``"sobol"`` (:func:`monte_carlo`).
    common : bool
        True: the same N draws at every point (common random numbers: differences between points
        are not blurred by different draws); False: independent draws per point, from seeds spawned
        by :class:`numpy.random.SeedSequence` (``seed``) in point order.
    deviations : sequence of str
        Sampled factors that are tolerances of design factors: their value is the point's level plus
        the draw, and the level is kept in ``nominal_<name>``.

    Returns
    -------
    DataFrame
        P·N rows, point-major (row p·N + k is draw k of point p): ``point``, ``draw``, the design's
        columns, ``nominal_<name>`` for each deviation, and the sampled factors.
    """
    import pandas as pd

    n_points, n = len(design), int(per_point)
    if n < 1:
        raise InputError(f"per_point ({per_point}) must be >= 1")
    if n_points < 1:
        raise InputError("levels x samples needs at least one design point")
    missing = [k for k in deviations if k not in design.columns]
    if missing:
        raise InputError(f"deviations {missing} must be design factors ({list(design.columns)})")
    if common:
        draws = monte_carlo(distributions, n, seed, sampler)
        values = {k: np.tile(draws[k].to_numpy(float), n_points) for k in distributions}
    else:
        frames = [monte_carlo(distributions, n, s, sampler) for s in _point_seeds(seed, n_points)]
        values = {k: np.concatenate([f[k].to_numpy(float) for f in frames]) for k in distributions}
    point = np.repeat(np.arange(n_points), n)
    out = design.iloc[point].reset_index(drop=True)
    out.insert(0, "draw", np.tile(np.arange(n), n_points))
    out.insert(0, "point", point)
    for k in deviations:
        out[f"nominal_{k}"] = out[k].to_numpy(float)
    for k, v in values.items():
        out[k] = out[k].to_numpy(float) + v if k in deviations else v
    return pd.DataFrame(out)
