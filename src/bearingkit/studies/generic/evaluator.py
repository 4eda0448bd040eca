"""The generic evaluator: any bearing file or designation × factors that are paths into its input.

SI units: factor columns hold SI values (:mod:`bearingkit.studies.generic.paths`), output columns name their
unit (:mod:`bearingkit.studies.generic.quantities`).

A study that names a bearing (``bearing = "../dgbb_6209.toml"`` or ``bearing = "6205 C3"``) and no
evaluator runs on this one (or ``evaluator = "generic"``). Its factors are the paths of that input
(:func:`bearingkit.studies.generic.paths.input_paths`), its outputs the named quantities of the pipeline's
Analysis (:func:`bearingkit.studies.generic.quantities.catalogue`). It runs on top of the pipeline only:
input → :func:`bearingkit.io.loader.from_dict` → :class:`bearingkit.pipeline.Analysis`.

One study case is the bearing with the study's values set, under ONE load case of the file (``study
.load_case``, or the one the factor paths name, or the file's only one). Cases are grouped by the
values of their ``file`` and ``analysis`` paths (geometry, material, lubricant, settings); every group
is ONE batched Analysis whose load cases are the group's study cases (loads, speeds and temperatures
are per case: no Python loop over cases) and, when duty-cycle outputs are asked for, one more of every
case's bins (G·B load cases). A group larger than one run may hold (the loader's caps, at most 1,000
cases and 2·10⁶ contact points: :func:`bearingkit.io.loader.max_cases`) is solved in consecutive runs
of that size, so any chunk size streams through in bounded memory. A group whose input is refused
gives NaN outputs, ``converged = False`` and the one-line reason in the ``error`` column; the study
goes on.
"""

from __future__ import annotations

import hashlib
import itertools
from pathlib import Path

import numpy as np

from bearingkit.errors import InputError
from bearingkit.io import schema
from bearingkit.studies.evaluators import Evaluator, Factor
from bearingkit.studies.generic import paths as pathmod
from bearingkit.studies.generic import quantities as qmod

__all__ = ["GENERIC", "GenericModel", "is_designation", "load_bearing", "study_evaluator"]

#: The name a study file may give the generic evaluator (the default when it names a bearing).
GENERIC = "generic"
#: Analysis parts whose outputs a study gets when it lists no ``outputs`` (friction and the duty cycle
#: cost another model or more solves: they are computed when the study names one of their outputs).
DEFAULT_PARTS = ("statics", "rows", "rating", "lubrication")
#: Name of the load case a study adds when the input has none (a designation, or a duty cycle only).
DEFAULT_CASE = "load"


def is_designation(text: str, base_dir=None) -> bool:
    """True when ``text`` names a standard bearing (``"6205 C3"``), not a file (relative to ``base_dir``).

    Text no file system would take (a NUL byte, a control character, more than 255 bytes) is taken
    for a path, which :func:`bearingkit.io.reading.confined_path` then refuses in one line."""
    if not text.isprintable() or len(text.encode("utf-8", "surrogateescape")) > 255:
        return False
    path = Path(text)
    try:
        if base_dir is not None and not path.is_absolute() and (Path(base_dir) / path).exists():
            return False
        exists = path.exists()
    except (OSError, ValueError):  # a name the system refuses to look up is no designation either
        return False
    return not exists and path.suffix.lower() not in (".toml", ".json") and "/" not in text


def load_bearing(source: str) -> tuple[dict, str]:
    """The parsed input of ``source`` (a file or a designation) and a digest of its content."""
    if is_designation(source):
        data = {"bearing": {"designation": source}}
        return data, hashlib.sha256(f"designation:{source}".encode()).hexdigest()
    from bearingkit.io.reading import parse_toml, read_text

    # bounded like every input file: a regular file of at most 1 MiB, UTF-8, nesting checked
    text = read_text(source)
    return parse_toml(text, source), hashlib.sha256(text.encode("utf-8")).hexdigest()


class GenericModel:
    """The evaluator function of one bearing input: ``model(cases) -> DataFrame`` of outputs.

    Picklable by value (worker processes rebuild the input from the parsed data it carries).

    Parameters
    ----------
    source : str
        The bearing file (absolute path) or the designation.
    data : dict
        The parsed input.
    digest : str
        SHA-256 of the input's content (part of the study's fingerprint).
    load_case : str
        The load case every study case analyses.
    outputs : tuple of str
        The outputs to compute (names of :func:`bearingkit.studies.generic.quantities.catalogue`).
    """

    def __init__(self, source: str, data: dict, digest: str, load_case: str, outputs: tuple):
        self.source = source
        self.data = data
        self.digest = digest
        self.load_case = load_case
        self.outputs = tuple(outputs)
        self._cache = None

    def __getstate__(self):
        return {k: v for k, v in self.__dict__.items() if k != "_cache"} | {"_cache": None}

    def __repr__(self) -> str:
        return (
            f"bearingkit.studies.generic.evaluator:GenericModel({self.source!r}, sha256={self.digest[:16]}, "
            f"load_case={self.load_case!r}, outputs={list(self.outputs)})"
        )

    # ------------------------------------------------------------------------------ the input
    def _base(self):
        """(BearingInput, paths, catalogue) of the unmodified input (built once per process)."""
        if self._cache is None:
            from bearingkit.io.loader import from_dict

            bearing = from_dict(self.data, self.source)
            self._cache = (bearing, _paths(bearing), qmod.catalogue(bearing))
        return self._cache

    @property
    def paths(self) -> dict:
        return self._base()[1]

    @property
    def catalogue(self) -> dict:
        return self._base()[2]

    def build(self, values: dict):
        """The BearingInput with the ``file`` paths in ``values`` set (the base input when there are none)."""
        from bearingkit.io.loader import from_dict

        bearing, paths, _ = self._base()
        file_values = {k: v for k, v in values.items() if paths[k].kind == "file" and not _missing(v)}
        if not file_values:
            return bearing
        return from_dict(pathmod.apply(self.data, file_values, paths), self.source)

    # ------------------------------------------------------------------------------ evaluation
    def __call__(self, cases):
        import pandas as pd

        return pd.DataFrame(self.columns(cases))

    def columns(self, cases) -> dict:
        """Outputs (name → (C,) array) of the C cases of ``cases``, in their order.

        What a study's workers send back (:meth:`bearingkit.studies.evaluators.Evaluator.columns`):
        plain arrays, no DataFrame built, indexed, concatenated and sorted per chunk (issue 34).
        """
        _, paths, _ = self._base()
        n = len(cases)
        data = {c: cases[c].to_numpy() for c in cases.columns}
        keys = [c for c in data if paths[c].kind != "case"]
        parts = []
        for idx, key in _groups(cases, data, keys):
            sub = data if len(idx) == n else {c: v[idx] for c, v in data.items()}
            try:
                table = self.evaluate_group(sub, key, len(idx))
            except InputError as exc:
                table = self._failed(len(idx), str(exc))
            parts.append((idx, table))
        if len(parts) == 1:
            return parts[0][1]
        out = {}
        for idx, table in parts:
            for k, v in table.items():
                if k not in out:
                    out[k] = np.empty(n, dtype=np.asarray(v).dtype)
                out[k][idx] = v
        return out

    def _failed(self, n: int, reason: str) -> dict:
        table = {}
        for name in self.outputs:
            q = self.catalogue[name]
            if q.unit == "bool":
                table[name] = np.zeros(n, bool)
            elif q.unit == "count":
                table[name] = np.full(n, -1, dtype=np.int64)
            else:
                table[name] = np.full(n, np.nan)
        table["error"] = np.full(n, reason, dtype=object)
        return table

    def evaluate_group(self, sub: dict, key: dict, g: int | None = None) -> dict:
        """Outputs (name → (G,)) of the G cases of ``sub`` (column → array) sharing the non-batched
        values ``key``.

        The G cases are solved in runs of at most :func:`bearingkit.io.loader.max_cases` (the caps of
        one run: load cases, flexible rings, contact points; divided by the duty-cycle bins when those
        are solved too), so a chunk of any size streams through in bounded memory. Their load cases
        are formed once for the group, and each run takes its slice.
        """
        from bearingkit.io.loader import max_cases

        bearing = self.build(key)
        g = len(next(iter(sub.values()))) if g is None else g
        quantities = [self.catalogue[n] for n in self.outputs]
        duty = "duty" in qmod.parts_of(quantities)
        settings = {k.split(".", 1)[1]: v for k, v in key.items() if self.paths[k].kind == "analysis"}
        settings = {k: v for k, v in settings.items() if not _missing(v)}
        options = {
            "rotating": settings.get("rotating", "inner"),
            "contamination": settings.get("contamination"),
            "reliability": settings.get("reliability", 0.9),
            "friction_model": settings.get("friction_model", "auto"),
        }
        step = max_cases(bearing.model)
        if duty:
            step = max(1, step // len(bearing.duty_cycle.bins))
        # as few runs as the caps allow, of equal sizes: 2,048 cases are 3 runs of 682–683, not
        # 1,000 + 1,000 + 48 (a run of 48 leaves the solver's thread pool idle)
        runs = -(-g // step)
        bounds = [g * i // runs for i in range(runs + 1)]
        cases, loads = self._load_cases(bearing, sub, g)
        parts = []
        for a, b in itertools.pairwise(bounds):
            part = sub if runs == 1 else {c: v[a:b] for c, v in sub.items()}
            parts.append(self._run(bearing, part, cases[a:b], loads[a:b], quantities, options, duty))
        table = {k: np.concatenate([p[k] for p in parts]) for k in parts[0]} if len(parts) > 1 else parts[0]
        table["error"] = np.full(g, "", dtype=object)
        return table

    def _run(self, bearing, sub: dict, cases, loads, quantities, options: dict, duty: bool) -> dict:
        """Outputs of one run within the caps (``cases`` and their ``loads``): one batched Analysis."""
        from bearingkit.pipeline import analyze

        g = len(cases)
        # the pipeline's one entry: the same contamination and lubricant checks as the command line
        analysis = analyze(bearing.with_cases(cases, loads), **options)
        lives = self._duty(bearing, sub, g, options) if duty else None
        return qmod.extract(analysis, g, quantities, lives)

    def _columns(self, sub, prefix: str, spec: dict, g: int, extra: dict | None = None) -> dict:
        """Per-case arrays (G,) of the load-case fields: the column where the study sets it, else ``spec``."""
        out = {}
        for f in pathmod.CASE_FIELDS:
            base = spec.get(f)
            col = f"{prefix}.{f}"
            alias = (extra or {}).get(f)
            given = col if col in sub else alias if alias is not None and alias in sub else None
            if given is None:
                out[f] = np.full(g, np.nan if base is None else float(base))
                continue
            values = np.asarray(sub[given], dtype=float)
            out[f] = np.where(np.isnan(values), np.nan if base is None else float(base), values)
        return out

    def _load_cases(self, bearing, sub: dict, g: int) -> tuple[list, np.ndarray]:
        from bearingkit.io.loader import LoadCase

        specs = {c.name: c.model_dump() for c in bearing.spec.load_cases}
        spec = specs.get(self.load_case, {f: 0.0 for f in pathmod.CASE_FIELDS[:5]})
        cols = self._columns(
            sub,
            f"load_cases.{self.load_case}",
            spec,
            g,
            {"speed": "operating.speed", "temperature": "operating.temperature"},
        )
        return _cases(self.load_case, cols, g, LoadCase, with_loads=True)

    def _bin_cases(self, bearing, sub, g: int) -> list:
        """Every bin of the duty cycle for every case, bin-major (bin b of case k at g·b + k)."""
        from bearingkit.io.loader import LoadCase

        out = []
        for lc in bearing.duty_cycle.bins:
            spec = {
                "F_x": lc.load[0],
                "F_y": lc.load[1],
                "F_z": lc.load[2],
                "M_x": lc.load[3],
                "M_y": lc.load[4],
                "eccentricity": 0.0,
                "speed": lc.speed,
                "temperature": lc.temperature,
            }
            out += _cases(lc.name, self._columns(sub, f"duty_cycle.{lc.name}", spec, g), g, LoadCase)
        return out

    def _duty(self, bearing, sub, g: int, options: dict) -> dict:
        """Bin lives (G, B) and the combined lives (G,) of every case's duty cycle.

        The G·B bins of the group are ONE batched Analysis of their own (not mixed with the study's
        load cases: a case without speed would take the speed, hence a_ISO and hours, from the bins'
        rating). Bins at rest in a time-fraction cycle turn no revolutions and are left out.
        """
        from bearingkit.pipeline import analyze
        from bearingkit.pipeline.duty_cycle import bin_lives, combine

        cycle = bearing.duty_cycle
        b = len(cycle.bins)
        bins = self._bin_cases(bearing, sub, g)  # bin-major: bin j of case k at j·g + k
        speeds = np.array([c.speed or 0.0 for c in bins]).reshape(b, g).T
        turning = (speeds != 0.0).T.ravel() if cycle.kind == "time" else np.ones(g * b, bool)
        # a bin at rest does no damage; ISO 281 (listed first) beside the ISO/TS 16281 lives
        lives = {k: np.full(g * b, np.inf) for k in ("L10", "Lnm", "L10r", "Lnmr")}
        if turning.any():
            run = analyze(bearing.with_cases([c for c, t in zip(bins, turning, strict=True) if t]), **options)
            for key, attr, iso in (
                ("L10", "life", True),
                ("Lnm", "modified_life", True),
                ("L10r", "life", False),
                ("Lnmr", "modified_life", False),
            ):
                rated = np.nan if run.rating is None else bin_lives(run.rating, attr, iso281=iso)
                lives[key][turning] = rated
        lives = {k: v.reshape(b, g).T for k, v in lives.items()}
        out = combine(lives, cycle.fractions, cycle.kind, speeds)
        for key in ("L10", "L10r"):
            life = lives[key]
            out[f"bin_{key}"] = np.where(speeds == 0.0, np.nan, life) if cycle.kind == "time" else life
        return out


def _groups(cases, data: dict, keys: list):
    """(index array, key dict) of the groups of cases sharing the values of ``keys``.

    The usual chunk is one group (the study fixes every non-batched path): found without pandas.
    """
    same = {}
    for k in keys:
        col = data[k]
        if not len(col) or not np.all(col == col[0]):  # NaN ≠ NaN: left to groupby (dropna=False)
            break
        same[k] = col[0]
    else:
        yield np.arange(len(cases)), same
        return
    for key, idx in cases.groupby(keys, sort=False, dropna=False).indices.items():
        key = key if isinstance(key, tuple) else (key,)
        yield np.asarray(idx), dict(zip(keys, key, strict=True))


def _missing(value) -> bool:
    return value is None or (isinstance(value, float) and value != value)


def _cases(name: str, cols: dict, g: int, make, with_loads: bool = False):
    """G load cases from per-case field arrays (the loader's rule: M_y − e·F_z from an eccentricity).

    ``with_loads``: also return their loads (G, 5) as one array (the pipeline then never stacks them).
    """
    from bearingkit.analysis.solver.quasistatic import load_vector

    zero = {k: np.nan_to_num(cols[k], nan=0.0) for k in ("F_x", "F_y", "F_z", "M_x", "M_y")}
    e = np.nan_to_num(cols["eccentricity"], nan=0.0)
    load = load_vector(zero["F_x"], zero["F_y"], zero["F_z"], zero["M_x"], zero["M_y"] - e * zero["F_z"])
    # Python floats once for the whole group (a NaN is "not given"): a numpy scalar test per case
    # cost a fifth of a statics study's time once the solve itself got fast.
    speed = [None if v != v else v for v in np.asarray(cols["speed"], float).tolist()]
    temp = [None if v != v else v for v in np.asarray(cols["temperature"], float).tolist()]
    cases = [make(name, row, v, t) for row, v, t in zip(load, speed, temp, strict=True)]
    return (cases, load) if with_loads else cases


def _paths(bearing) -> dict:
    out = pathmod.input_paths(bearing)
    if not bearing.spec.load_cases:  # a designation or a duty cycle only: the study adds one load case
        probe = pathmod.model_paths("x", schema.LoadCaseSpec, None, "case")
        for f in pathmod.CASE_FIELDS:
            p = probe[f"x.{f}"]
            path = f"load_cases.{DEFAULT_CASE}.{f}"
            out[path] = pathmod.InputPath(path, p.dimension, None, "case", (), p.description)
    return out


def _factor(p: pathmod.InputPath) -> Factor:
    return Factor(p.path, p.dimension, p.nominal, batched=p.kind == "case", named=p.named)


def choose_load_case(bearing, head: dict, names, source: str) -> str:
    """The load case a study analyses: ``study.load_case``, the one its paths name, or the only one."""
    known = [c.name for c in bearing.spec.load_cases] or [DEFAULT_CASE]
    named = sorted(
        {
            n[len("load_cases.") :].rsplit(".", 1)[0]
            for n in names
            if isinstance(n, str) and n.startswith("load_cases.")
        }
    )
    wanted = head.get("load_case")
    if wanted is not None:
        if wanted not in known:
            raise InputError(
                f"{source}: study.load_case ({wanted!r}) is not a load case of the bearing; it has "
                f"{', '.join(known)}"
            )
        other = [n for n in named if n != wanted and n in known]
        if other:
            raise InputError(
                f"{source}: the factors set load case {other[0]!r} but the study analyses "
                f"study.load_case ({wanted!r}); set load_cases.{wanted}.… instead"
            )
        return wanted
    named = [n for n in named if n in known]
    if len(named) > 1:
        raise InputError(
            f"{source}: the factors set load cases {', '.join(named)}; a study analyses one load case: "
            "name it with study.load_case"
        )
    if named:
        return named[0]
    if len(known) > 1:
        raise InputError(
            f"{source}: study.load_case: missing; the bearing has load cases {', '.join(known)}: name the "
            "one the study analyses"
        )
    return known[0]


_EVALUATORS: dict = {}


def study_evaluator(bearing_source: str, head: dict, names=(), source: str = "<study>") -> Evaluator:
    """The generic evaluator of ``bearing_source`` for a study (checked: load case and outputs).

    Parameters
    ----------
    bearing_source : str
        The bearing file (a path the caller resolved) or a designation.
    head : dict
        The study's ``[study]`` table (``load_case``, ``outputs``).
    names : iterable of str
        Every factor name the study uses (to find the load case its paths name).
    source : str
        The study file, for messages.
    """
    from bearingkit.io.loader import from_dict

    data, digest = load_bearing(bearing_source)
    try:
        bearing = from_dict(data, bearing_source)
    except InputError as exc:
        raise InputError(f"{source}: study.bearing: {exc}") from None
    load_case = choose_load_case(bearing, head, names, source)
    cat = qmod.catalogue(bearing)
    outputs = head.get("outputs")
    if outputs is None:  # the cheap parts, and whatever else the study names (response, plots, objectives)
        named = {n for n in names if isinstance(n, str)}
        outputs = tuple(n for n, q in cat.items() if q.part in DEFAULT_PARTS or n in named)
    elif not isinstance(outputs, (list, tuple)) or not all(isinstance(o, str) for o in outputs):
        raise InputError(f"{source}: study.outputs ({outputs!r}) must be a list of output names")
    for o in outputs:
        if o not in cat:
            near = ", ".join(pathmod.nearest(o, cat))
            raise InputError(
                f"{source}: study.outputs ({o!r}) is not an output of {Path(bearing_source).name}; nearest: "
                f"{near} (bearingkit study --list-outputs lists them)"
            )
    key = (bearing_source, digest, load_case, tuple(outputs))
    if key not in _EVALUATORS:
        model = GenericModel(bearing_source, data, digest, load_case, tuple(outputs))
        model._cache = (bearing, _paths(bearing), cat)
        factors = {p.path: _factor(p) for p in model.paths.values()}
        _EVALUATORS[key] = Evaluator(
            GENERIC,
            model,
            factors,
            outputs=tuple(outputs),
            bearing_type=None,
            description=f"generic evaluator of {bearing_source} (load case {load_case!r})",
            fill_defaults=False,
            factor_noun=f"a path of {Path(bearing_source).name} (bearingkit study --list-factors lists them)",
        )
    return _EVALUATORS[key]


def check_values(ev: Evaluator, definition) -> None:
    """Refuse, before anything runs, a value of the study the input cannot take (one line naming it).

    Text values are checked against the choices the schema lists; every distinct level of a ``file``
    path is built into the input once (with the study's fixed values), so a level the loader refuses
    (a negative diameter, a row outside the envelope) stops the study here, not in a worker.
    """
    model = _model_of(ev, "check_values")
    src = definition.source
    groups = [("fixed", [(k, v) for k, v in definition.fixed.items()])]
    groups += [
        (f"factors[{i}] ({f.name}).levels", [(f.name, v) for v in (f.levels or ())])
        for i, f in enumerate(definition.factors)
    ]
    for where, items in groups:
        for path, value in items:
            p = model.paths[path]
            if p.choices and value not in p.choices:
                raise InputError(
                    f"{src}: {where} ({value!r}) must be one of {', '.join(p.choices)} for {path}"
                )
    fixed = {k: v for k, v in definition.fixed.items() if model.paths[k].kind == "file"}
    try:
        model.build(fixed)
    except InputError as exc:
        raise InputError(f"{src}: fixed: the bearing with these values is refused: {exc}") from None
    for where, items in groups[1:]:
        for path, value in dict.fromkeys(items):
            if model.paths[path].kind != "file":
                continue
            try:
                model.build({**fixed, path: value})
            except InputError as exc:
                raise InputError(f"{src}: {where} ({value!r}) is refused by the bearing: {exc}") from None


# ------------------------------------------------------------------------------ tolerances
#: Bearing type → clearance group of the ISO 5753-1 tables (:mod:`bearingkit.catalogue.clearances`).
CLEARANCE_GROUPS = {"deep_groove_ball": "deep_groove_ball", "cylindrical_roller": "cylindrical_roller"}


def _model_of(ev: Evaluator, what: str) -> GenericModel:
    if not isinstance(ev.function, GenericModel):
        raise InputError(f"{what} needs the generic evaluator (a study that names a bearing file)")
    return ev.function


def clearance_class_range(ev: Evaluator, path: str, cls: str, where: str) -> tuple[str, str]:
    """(low, high) of the ISO 5753-1 radial clearance class ``cls`` of the study's bearing, as input text."""
    from bearingkit.catalogue.clearances import CLASSES, clearance_range

    model = _model_of(ev, f"{where}.clearance_class")
    if path != "geometry.clearance_radial":
        raise InputError(f"{where}.clearance_class ({cls!r}) sets geometry.clearance_radial, not {path}")
    if cls not in CLASSES:
        raise InputError(f"{where}.clearance_class ({cls!r}) must be one of {', '.join(CLASSES)}")
    bearing = model._base()[0]
    group = CLEARANCE_GROUPS.get(bearing.bearing_type)
    bore = ev.factors.get("geometry.bore")
    if group is None or bore is None or bore.default is None:
        raise InputError(
            f"{where}.clearance_class ({cls!r}) needs a {' or '.join(CLEARANCE_GROUPS)} bearing with "
            f"geometry.bore; this one is a {bearing.bearing_type}"
            + ("" if bore is not None and bore.default is not None else " without a bore")
        )
    low, high = clearance_range(group, float(bore.default), cls)
    return pathmod.value_text(low, "length"), pathmod.value_text(high, "length")


def tolerance_factors(ev: Evaluator, design, source: str) -> list[dict]:
    """The bearing file's ``[[tolerances]]`` as sampled factors of a study (values as input text).

    A tolerance of a design factor stays a deviation (value = level + draw, ``deviation = true``);
    of any other path it becomes the absolute distribution around the file's value (mean, low and high
    shifted by it); a ``clearance_class`` becomes uniform over the ISO 5753-1 class range.
    """
    from bearingkit import units

    model = _model_of(ev, "study.tolerances")
    bearing = model._base()[0]
    if not bearing.tolerances:
        raise InputError(f"{source}: study.tolerances (true) but {bearing.source} has no [[tolerances]]")
    out = []
    for i, t in enumerate(bearing.tolerances):
        where = f"{bearing.source}: tolerances[{i}]"
        if t.path not in ev.factors:
            near = ", ".join(pathmod.nearest(t.path, ev.factors))
            raise InputError(f"{where}.path ({t.path!r}) is not a path of the bearing; nearest: {near}")
        f = ev.factors[t.path]
        if f.dimension in ("count", "text"):
            raise InputError(f"{where}.path ({t.path!r}) is a count or a name; a tolerance needs a quantity")
        if t.clearance_class is not None:
            if t.path in design:
                raise InputError(
                    f"{where}.clearance_class sets {t.path} over a whole class; it cannot scatter a design "
                    "factor's levels (give a distribution of the deviation instead)"
                )
            low, high = clearance_class_range(ev, t.path, t.clearance_class, where)
            out.append({"name": t.path, "distribution": "uniform", "low": low, "high": high})
            continue
        given = {k: getattr(t, k) for k in ("mean", "std", "low", "high") if getattr(t, k) is not None}
        if t.path in design:
            out.append({"name": t.path, "deviation": True, "distribution": t.distribution, **given})
            continue
        if f.default is None:
            raise InputError(
                f"{where}.path ({t.path!r}) has no value in the file to scatter around; give it in the file"
            )
        row = {"name": t.path, "distribution": t.distribution}
        for k, v in given.items():
            x = units.parse(v, f.dimension, f"{where} ({t.path}).{k}")
            row[k] = pathmod.value_text(x if k == "std" else x + float(f.default), f.dimension)
        out.append(row)
    return out
