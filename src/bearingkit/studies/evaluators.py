"""Registry of study evaluators: pure functions of a batch of cases → a table of outputs.

SI units: every factor column holds SI values (m, N, Pa, rad/s, °C for temperatures as the lubricant
API); every output column names its unit (``max_load_N``, ``friction_torque_Nm``).

An :class:`Evaluator` declares the factors it accepts (name, physical dimension used to parse the
study file, default) and computes a DataFrame of outputs, one row per case, from a DataFrame of cases.
It must be a pure function of the case values (no state, no randomness) so that any executor and any
chunking give the same numbers.

A study file names its evaluator; the name is looked up, in this order, among the registered ones
(:data:`REGISTRY`: the built-in ``zdt1`` and any registered by Python code), the plugins this process
allowed with :func:`allow_plugin` (the CLI's ``--allow-plugin module:attribute``), and the entry points
of the group :data:`ENTRY_POINT_GROUP` (installed packages, e.g. the paper reproductions of
:mod:`bearingkit.papers`, declare theirs in their metadata; loaded only when a file names one). A file
never imports code: a value ``"module:attribute"`` is refused unless that exact plugin was allowed by
the person running the study (input files are data; they may come from someone else).

Built-in evaluator: ``zdt1``, Zitzler–Deb–Thiele problem 1 (30 variables ``x1…x30`` → ``f1``, ``f2``),
the cheap vectorised objective of tests and benchmarks.
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np

from bearingkit import references
from bearingkit.errors import InputError

references.add(
    "zitzler2000",
    "Zitzler, E., Deb, K., Thiele, L. (2000). Comparison of Multiobjective Evolutionary Algorithms: "
    "Empirical Results. Evolutionary Computation 8(2):173–195. doi:10.1162/106365600568202",
)

#: Dimensions a factor may have besides the physical ones of :data:`bearingkit.units.SI_UNITS`.
NON_PHYSICAL = ("count", "text", "flag")


@dataclass(frozen=True)
class Factor:
    """A factor an evaluator accepts.

    Parameters
    ----------
    name : str
    dimension : str
        A key of :data:`bearingkit.units.SI_UNITS` (values in the study file need a unit unless
        ``"dimensionless"``), ``"count"`` (integer), ``"text"`` (a name, e.g. a crowning type) or
        ``"flag"`` (true / false).
    default : object
        Value (SI) used when the study neither varies nor fixes the factor.
    batched : bool
        True when cases differing in this factor can share one vectorised solve; False groups the
        cases by its value (one solve per group).
    named : tuple of (str, float)
        Values a study may give by name, with their SI value (ISO 281 contamination levels →
        e_C of the study's bearing); a name is turned into its value where the study file is read.
    """

    name: str
    dimension: str
    default: object
    batched: bool = True
    named: tuple = ()


@dataclass(frozen=True)
class Evaluator:
    """A named pure function ``function(cases: DataFrame) -> DataFrame`` with its declared factors.

    ``fill_defaults`` False: the cases carry only the factors a study sets (the evaluator takes the
    others from its input, as the generic evaluator of :mod:`bearingkit.studies.generic.evaluator` does);
    ``factor_noun`` says in messages what a factor is (default "a factor of evaluator NAME").
    """

    name: str
    function: Callable
    factors: Mapping[str, Factor]
    outputs: tuple = ()
    bearing_type: str | None = None
    description: str = ""
    references: tuple = field(default_factory=tuple)
    fill_defaults: bool = True
    factor_noun: str = ""

    @property
    def noun(self) -> str:
        """What a factor of this evaluator is, for messages."""
        return self.factor_noun or f"a factor of evaluator {self.name!r}"

    def complete(self, cases):
        """``cases`` with a column for every declared factor (defaults filled in)."""
        out = cases.copy()
        if not self.fill_defaults:
            return out
        for name, f in self.factors.items():
            if name not in out.columns:
                out[name] = f.default
        return out

    def _prepared(self, cases):
        """``cases`` checked (no unknown factor), completed with defaults, on a default index."""
        columns = list(cases.columns)  # a list: `in` on a pandas 3 str Index costs µs per name
        unknown = [c for c in columns if c not in self.factors and c != "case"]
        if unknown:
            raise InputError(
                f"evaluator {self.name!r}: unknown factors {unknown}; known: {list(self.factors)}"
            )
        if self.fill_defaults and not set(self.factors) <= set(columns):
            cases = self.complete(cases)
        else:  # a shallow copy (copy-on-write): the function may add columns without touching ours
            cases = cases.copy(deep=False)
        if not is_default_index(cases.index, len(cases)):
            cases = cases.reset_index(drop=True)
        return cases

    def __call__(self, cases):
        cases = self._prepared(cases)
        out = self.function(cases)
        if len(out) != len(cases):
            raise RuntimeError(f"evaluator {self.name!r} returned {len(out)} rows for {len(cases)} cases")
        return out

    def columns(self, cases) -> dict:
        """The outputs as numpy columns (name → (C,) array), what a study's workers send back.

        A function with a ``columns(cases)`` method of its own (the generic evaluator) gives them
        without building a DataFrame; any other is called and its table taken apart.
        """
        cases = self._prepared(cases)
        direct = getattr(self.function, "columns", None)
        if callable(direct):
            out = {k: np.asarray(v) for k, v in direct(cases).items()}
            rows = {len(v) for v in out.values()} or {len(cases)}
        else:
            table = self.function(cases)
            out = {k: table[k].to_numpy() for k in table.columns}
            rows = {len(table)}
        if rows != {len(cases)}:
            raise RuntimeError(f"evaluator {self.name!r} returned {sorted(rows)} rows for {len(cases)} cases")
        return out


#: Evaluator name → Evaluator (the built-in ones, and any registered by Python code).
REGISTRY: dict[str, Evaluator] = {}

#: Entry-point group through which installed packages (and :mod:`bearingkit.papers`) offer evaluators:
#: ``[project.entry-points."bearingkit.evaluators"]`` ``my_model = "my_package.models:MY_EVALUATOR"``
#: in the package's pyproject.toml; a study file then says ``evaluator = "my_model"``. Installing the
#: package is the opt-in.
ENTRY_POINT_GROUP = "bearingkit.evaluators"

#: Plugins allowed in this process by :func:`allow_plugin`: ``"module:attribute"`` → Evaluator.
ALLOWED_PLUGINS: dict[str, Evaluator] = {}

_SPEC = re.compile(r"^[A-Za-z_][\w]*(\.[A-Za-z_][\w]*)*:[A-Za-z_][\w]*$")


def register(evaluator: Evaluator) -> Evaluator:
    """Add (or replace) an evaluator under its name (Python code only; files cannot register)."""
    REGISTRY[evaluator.name] = evaluator
    return evaluator


def allow_plugin(spec: str) -> Evaluator:
    """Import the evaluator ``"package.module:attribute"`` and let study files name it.

    The explicit opt-in for code outside bearingkit (what ``--allow-plugin`` calls). A study file may
    then name it by its evaluator name or by ``spec`` itself. It may not take the name of a built-in.
    """
    if not isinstance(spec, str) or not _SPEC.match(spec):
        raise InputError(f"--allow-plugin ({spec!r}) must be 'package.module:attribute'")
    if spec in ALLOWED_PLUGINS:
        return ALLOWED_PLUGINS[spec]
    mod, _, attr = spec.partition(":")
    try:
        obj = getattr(importlib.import_module(mod), attr)
    except (ImportError, AttributeError) as exc:
        raise InputError(f"--allow-plugin ({spec!r}) cannot be imported: {exc}".replace("\n", " ")) from None
    if not isinstance(obj, Evaluator):
        raise InputError(f"--allow-plugin ({spec!r}) is a {type(obj).__name__}, not an Evaluator")
    from importlib.metadata import entry_points

    taken = set(REGISTRY) | {ep.name for ep in entry_points(group=ENTRY_POINT_GROUP)}
    if obj.name in taken and REGISTRY.get(obj.name) is not obj:
        raise InputError(
            f"--allow-plugin ({spec!r}): its name {obj.name!r} is that of a built-in or installed evaluator"
        )
    ALLOWED_PLUGINS[spec] = obj
    return obj


def _from_entry_point(name: str) -> Evaluator | None:
    """The evaluator an installed package declares under ``name`` (registered on first use), else None."""
    from importlib.metadata import entry_points

    for ep in entry_points(group=ENTRY_POINT_GROUP, name=name):
        try:
            obj = ep.load()
        except Exception as exc:  # a broken plugin is the plugin's error, said in one line
            msg = f"evaluator ({name!r}): the installed plugin {ep.value!r} does not load: {exc}"
            raise InputError(msg.replace("\n", " ")) from None
        if not isinstance(obj, Evaluator):
            raise InputError(f"evaluator ({name!r}): entry point {ep.value} is a {type(obj).__name__}")
        return register(obj)
    return None


def available() -> list[str]:
    """Names of every evaluator: registered ones, allowed plugins and those installed packages declare."""
    from importlib.metadata import entry_points

    names = set(REGISTRY) | {ev.name for ev in ALLOWED_PLUGINS.values()}
    return sorted(names | {ep.name for ep in entry_points(group=ENTRY_POINT_GROUP)})


def get(name: str) -> Evaluator:
    """The evaluator called ``name``: registered, allowed plugin, or entry point (in that order).

    A ``"module:attribute"`` name resolves only when that plugin was allowed (:func:`allow_plugin`).
    """
    if not isinstance(name, str):
        raise InputError(f"evaluator ({name!r}) must be the name of an evaluator")
    if name in REGISTRY:
        return REGISTRY[name]
    if name in ALLOWED_PLUGINS:
        return ALLOWED_PLUGINS[name]
    for ev in ALLOWED_PLUGINS.values():
        if ev.name == name:
            return ev
    if ":" in name:
        raise InputError(
            f"evaluator ({name!r}) names Python code; a study file cannot import code. Use one of "
            f"{', '.join(available())} (built in or installed: entry point group {ENTRY_POINT_GROUP!r}), "
            f"or allow this one explicitly: --allow-plugin {name}"
        )
    found = _from_entry_point(name)
    if found is not None:
        return found
    raise InputError(
        f"evaluator ({name!r}) must be one of {', '.join(available())} (built in or installed: entry point "
        f"group {ENTRY_POINT_GROUP!r}) or a plugin allowed with --allow-plugin"
    )


def is_default_index(index, n: int) -> bool:
    """True for the RangeIndex 0…n−1 (what reset_index(drop=True) would make)."""
    import pandas as pd

    return isinstance(index, pd.RangeIndex) and index.start == 0 and index.step == 1 and len(index) == n


# ------------------------------------------------------------------------------ helpers for evaluators
def group_cases(cases, factors: Mapping[str, Factor]):
    """Split cases by the values of their non-batched factors → (index array, key dict)."""
    keys = [n for n, f in factors.items() if not f.batched and n in cases.columns]
    if not keys:
        yield np.arange(len(cases)), {}
        return
    # The usual chunk holds one group (the non-batched factors fixed by the study): found with one
    # comparison per column instead of a pandas groupby (~1 ms per chunk).
    same = {}
    for k in keys:
        col = cases[k].to_numpy()
        if not len(col) or not np.all(col == col[0]):  # NaN ≠ NaN: left to groupby (dropna=False)
            break
        same[k] = col[0]
    else:
        yield np.arange(len(cases)), same
        return
    for key, idx in cases.groupby(keys, sort=False, dropna=False).indices.items():
        key = key if isinstance(key, tuple) else (key,)
        yield np.asarray(idx), dict(zip(keys, key, strict=True))


def python_value(value, factor: Factor):
    """A factor value as the Python type its dimension implies (int count, str text, float)."""
    if factor.dimension == "count":
        return int(value)
    if factor.dimension == "text":
        return str(value)
    if factor.dimension == "flag":
        return bool(value)
    return float(value)


def assemble_arrays(n: int, parts) -> dict[str, np.ndarray]:
    """Columns of ``n`` rows (name → (n,) array) from ``(index array, {column: values})`` parts."""
    cols: dict[str, np.ndarray] = {}
    for idx, table in parts:
        for k, v in table.items():
            v = np.asarray(v)
            if k not in cols:
                cols[k] = np.zeros(n, dtype=v.dtype)
            cols[k][idx] = v
    return cols


def assemble_columns(n: int, parts):
    """One DataFrame of ``n`` rows from ``(index array, {column: values})`` parts."""
    import pandas as pd

    return pd.DataFrame(assemble_arrays(n, parts))


# ------------------------------------------------------------------------------ analytic problems
#: Number of decision variables of ZDT1 (Zitzler et al. 2000).
ZDT1_VARIABLES = 30


def zdt1(cases):
    """ZDT1 (Zitzler et al. 2000, eq. T1): f1 = x1, g = 1 + 9 Σ_{i≥2} x_i/(n−1), f2 = g (1 − √(f1/g)).

    Pareto front: g = 1 (x2…xn = 0), f2 = 1 − √f1, f1 ∈ [0, 1].
    """
    import pandas as pd

    x = cases[[f"x{i}" for i in range(1, ZDT1_VARIABLES + 1)]].to_numpy(float)
    f1 = x[:, 0]
    g = 1.0 + 9.0 * x[:, 1:].sum(axis=1) / (ZDT1_VARIABLES - 1)
    return pd.DataFrame({"f1": f1, "f2": g * (1.0 - np.sqrt(np.clip(f1 / g, 0.0, None))), "g": g})


register(
    Evaluator(
        "zdt1",
        zdt1,
        {f"x{i}": Factor(f"x{i}", "dimensionless", 0.0) for i in range(1, ZDT1_VARIABLES + 1)},
        outputs=("f1", "f2"),
        description="ZDT1 test problem (Zitzler, Deb, Thiele 2000)",
        references=("zitzler2000",),
    )
)
