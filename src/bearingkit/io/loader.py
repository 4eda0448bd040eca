"""Load a bearing input file (TOML with units) into a model, load cases and solver settings.

SI inside: the schema (:mod:`bearingkit.io.schema`) turns every ``"6 mm"`` into metres; this
module maps ``bearing.type`` to a builder of :mod:`bearingkit.bearings` through :data:`BUILDERS`,
builds the :class:`~bearingkit.analysis.model.BearingModel`, checks that the rows fit the envelope,
and forms the (C, 5) load matrix. Every malformed input raises
:class:`bearingkit.errors.InputError` with one line: ``FILE: field (value) what was expected``.

>>> from bearingkit.io.loader import load_file
>>> bearing = load_file("examples/seed000_composite.toml")      # doctest: +SKIP
>>> result = bearing.solve()                                     # doctest: +SKIP
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

import numpy as np
from pydantic import BaseModel, ValidationError

from bearingkit.analysis.model import BearingModel
from bearingkit.errors import InputError, did_you_mean, quote
from bearingkit.io import kinds, schema, schema_cycle
from bearingkit.io.messages import one_line, prefix_field, section_models
from bearingkit.io.reading import parse_toml, read_text

#: Inner-ring DOF names, in the solver's order.
DOF_NAMES = schema.DOF_CHOICES
#: Load component names, in the solver's order.
LOAD_NAMES = ("F_x", "F_y", "F_z", "M_x", "M_y")
#: SI units of the load components.
LOAD_UNITS = ("N", "N", "N", "N*m", "N*m")
#: Most load cases of a bearing with a flexible ring ([geometry.ring] flexible, the default of a
#: ball–column bearing): the coupled Newton solve keeps a (cases, n, n) Jacobian of the ~240 raceway
#: offsets. Measured on the 2-core reference machine: 100 cases take 27 s and 270 MB through analyze.
MAX_FLEXIBLE_LOAD_CASES = 100
#: Most load cases in one HTML report: two figures per case (~1 s each) and a page a person reads.
#: Measured: 20 cases of a deep groove ball bearing take about a minute. More: analyze --json.
MAX_REPORT_CASES = 20
#: Most contact points (load cases × Σ rows elements × slices) one run may ask for. Measured on a
#: cylindrical roller bearing of 250 rollers × 200 slices: 2·10⁶ points peak at 260 MB through
#: friction (212 MB analyze), 10⁷ at 900 MB. A seed-000 turntable (≈ 3,200 points) takes ≈ 600 cases.
MAX_CASE_POINTS = 2_000_000
#: Names accepted for ``--load KEY=VALUE`` on the command line → load-case field.
LOAD_ALIASES: dict[str, str] = {
    **{k: k for k in (*LOAD_NAMES, "eccentricity", "speed", "temperature")},
    "Fx": "F_x",
    "Fr": "F_x",
    "Fy": "F_y",
    "Fz": "F_z",
    "Fa": "F_z",
    "Mx": "M_x",
    "My": "M_y",
    "e": "eccentricity",
    "n": "speed",
    "T": "temperature",
}


# ---------------------------------------------------------------------------------------------
# Builder registry: bearing type → function(geometry dict (SI), material, name) → BearingModel.
# ---------------------------------------------------------------------------------------------
def _profile(geometry: dict, diameter: float | None = None):
    from bearingkit.physics.contact.profiles import make_profile

    spec = geometry.get("profile")
    if spec is None:
        return None
    params = {k: v for k, v in spec.items() if k != "name" and v is not None}
    d = geometry["element_diameter"] if diameter is None else diameter
    return make_profile(spec["name"], geometry["effective_length"], d, **params)


def _standard(builder_name: str, renames: dict | None = None):
    def build(geometry: dict, material, name: str) -> BearingModel:
        from bearingkit.bearings import standard

        skip = ("bore", "outer_diameter", *schema.SHOULDER_FIELDS)  # not builder arguments
        kwargs = {k: v for k, v in geometry.items() if v is not None and k not in skip}
        for old, new in (renames or {}).items():
            if old in kwargs:
                kwargs[new] = kwargs.pop(old)
        if "profile" in kwargs:
            kwargs["profile"] = _profile(geometry)
        if name:
            kwargs["name"] = name
        return getattr(standard, builder_name)(material=material, **kwargs)

    return build


def _turntable(builder_name: str):
    def build(geometry: dict, material, name: str) -> BearingModel:
        from bearingkit.bearings import turntable
        from bearingkit.physics.contact.profiles import PROFILES, SEED000_CROWNING

        crowning = geometry.get("crowning")
        if crowning is not None and crowning not in SEED000_CROWNING and crowning not in PROFILES:
            raise InputError(
                f"crowning ({crowning!r}) must be a seed-000 letter ({', '.join(SEED000_CROWNING)}) or a "
                f"profile name ({', '.join(PROFILES)})"
            )
        overrides = {k: v for k, v in geometry.items() if v is not None}
        if builder_name == "yrt_turntable":
            overrides = {k: v for k, v in overrides.items() if k not in ("bore", "outer_diameter")}
        model = getattr(turntable, builder_name)(material=material, **overrides)
        return dataclasses.replace(model, name=name) if name else model

    return build


def _diameter_deviation(geometry: dict):
    """ΔD per roller (Z,) [m] from a list (SI already) or a generator spec; None when not given."""
    from bearingkit.physics.deviations import gaussian_deviations, seed001_series

    spec = geometry.get("diameter_deviation")
    if spec is None:
        return None
    if isinstance(spec, (list, tuple)):
        return np.asarray(spec, dtype=float)
    if spec.get("series") is not None:
        dev = seed001_series(spec["series"])
        if dev.shape[0] != geometry["n_elements"]:
            raise InputError(
                f"diameter_deviation (series {spec['series']}, {dev.shape[0]} rollers) must match "
                f"n_elements ({geometry['n_elements']})"
            )
        return dev
    return gaussian_deviations(
        geometry["n_elements"], spec["magnitude"], 1, spec["arrangement"], spec["seed"]
    )[0]


def _tapered(geometry: dict, material, name: str) -> BearingModel:
    """Tapered roller bearing: :class:`~bearingkit.rows.tapered.TaperedRow`, single or a DB/DF pair."""
    from bearingkit.bearings.common import e_reduced_of
    from bearingkit.bearings.tapered import tapered_pair
    from bearingkit.rows.tapered import TaperedRow

    skip = ("bore", "outer_diameter", "arrangement", "row_spacing", "diameter_deviation", "profile")
    kwargs = {k: v for k, v in geometry.items() if v is not None and k not in skip}
    kwargs.update(
        e_reduced=e_reduced_of(material),
        density=material.density,
        diameter_deviation=_diameter_deviation(geometry),
    )
    if geometry.get("profile") is not None:
        mean_diameter = 0.5 * (geometry["small_diameter"] + geometry["large_diameter"])
        kwargs["profile"] = _profile(geometry, diameter=mean_diameter)
    if geometry["arrangement"] == "single":
        row = TaperedRow(**kwargs, name="tapered")
        refs = ("liu2022", "kunert1961")
        return BearingModel((row,), name=name or "tapered roller bearing", references=refs)
    return tapered_pair(
        spacing=geometry["row_spacing"],
        arrangement=geometry["arrangement"],
        name=name or f"tapered roller pair {geometry['arrangement']}",
        **kwargs,
    )


def _ptrb(geometry: dict, material, name: str) -> BearingModel:
    """Planetary thread roller bearing (seed 004): one :class:`~bearingkit.rows.threaded.ThreadedRow`."""
    from bearingkit.bearings.ptrb import ptrb_model
    from bearingkit.rows.threaded import PTRBGeometry

    renames = {"bore": "bore_diameter", "outer_diameter": "outside_diameter"}
    kwargs = {renames.get(k, k): v for k, v in geometry.items() if v is not None and k != "clearance"}
    g = PTRBGeometry(**kwargs, youngs_modulus=material.youngs_modulus, poisson_ratio=material.poisson_ratio)
    return ptrb_model(g, clearance=geometry.get("clearance") or 0.0, name=name or "PTRB")


def _ball_column(geometry: dict, material, name: str) -> BearingModel:
    """Seed-002 ball–column composite bearing (:func:`bearingkit.bearings.ball_column.ball_column`)."""
    from bearingkit.bearings.ball_column import BallColumnGeometry, RingOptions, ball_column

    fields = {k: v for k, v in geometry.items() if v is not None and k != "ring"}
    if "support_positions" in fields:
        fields["support_positions"] = tuple(fields["support_positions"])
    ring = RingOptions(**{k: v for k, v in (geometry.get("ring") or {}).items() if v is not None})
    model = ball_column(BallColumnGeometry(**fields), material=material, ring=ring)
    return dataclasses.replace(model, name=name) if name else model


#: Bearing type → builder. Keys equal :data:`bearingkit.io.schema.GEOMETRY_MODELS`'s.
BUILDERS: dict[str, Callable[[dict, object, str], BearingModel]] = {
    "composite_turntable": _turntable("composite_turntable"),
    "yrt_turntable": _turntable("yrt_turntable"),
    "deep_groove_ball": _standard("deep_groove_ball"),
    "angular_contact_ball": _standard("angular_contact_ball"),
    "angular_contact_pair": _standard("angular_contact_pair", {"clearance_axial": "axial_clearance"}),
    "thrust_ball": _standard("thrust_ball"),
    "cylindrical_roller": _standard("cylindrical_roller"),
    "cylindrical_roller_thrust": _standard("cylindrical_roller_thrust"),
    "tapered_roller": _tapered,
    "ptrb": _ptrb,
    "ball_column": _ball_column,
}
kinds.register(BUILDERS, schema.GEOMETRY_MODELS)  # four-point, slewing, spherical, self-aligning, needle
assert set(BUILDERS) == set(schema.GEOMETRY_MODELS)


def register_bearing_type(name: str, geometry_model: type[BaseModel], builder: Callable) -> None:
    """Add a bearing type to the input format.

    Parameters
    ----------
    name : str
        The ``bearing.type`` value.
    geometry_model : pydantic model
        Validates ``[geometry]`` (use the annotated types of :mod:`bearingkit.io.schema`, e.g.
        ``schema.PositiveLength``, so values arrive in SI); unknown fields must be forbidden.
    builder : callable
        ``builder(geometry: dict (SI), material, name: str) -> BearingModel``.
    """
    if name in BUILDERS:
        raise InputError(f"bearing type ({name!r}) is already registered")
    schema.GEOMETRY_MODELS[name] = geometry_model
    BUILDERS[name] = builder


# ---------------------------------------------------------------------------------------------
# Results of loading.
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LoadCase:
    """One load case in SI.

    Attributes
    ----------
    name : str
    load : ndarray (5,) [N, N, N, N·m, N·m]
        (F_x, F_y, F_z, M_x, M_y) on the inner ring, eccentricity already turned into M_y.
    speed : float or None [rad/s]
    temperature : float or None [°C]
    """

    name: str
    load: np.ndarray
    speed: float | None = None
    temperature: float | None = None

    def to_dict(self) -> dict:
        """JSON-ready dict, units in keys."""
        return {
            "case": self.name,
            "speed_rad_s": self.speed,
            "temperature_C": self.temperature,
        }


@dataclass(frozen=True)
class BearingInput:
    """A loaded input file: the model, its load cases and the solver settings (all SI).

    Attributes
    ----------
    source : str
        File name (or ``"<string>"``) used in messages.
    spec : schema.BearingFile
        The validated file (geometry as a dict).
    geometry : pydantic model
        The validated geometry (SI floats), of ``schema.GEOMETRY_MODELS[spec.bearing.type]``.
    model : BearingModel
    material : bearingkit.materials.Material
    lubricant : bearingkit.lubricants.Lubricant or None
    cases : tuple of LoadCase
    free : ndarray (5,) of bool
    options : bearingkit.analysis.quasistatic.SolverOptions
    sections : bearingkit.io.schema_operating.OperatingSections
        The parsed ``[operating]``, ``[fits]`` and ``[lubrication]`` sections.
    duty_cycle : bearingkit.io.schema_cycle.DutyCycle or None
        The ``[[duty_cycle]]`` bins (load spectrum), when the file has them.
    tolerances : tuple of bearingkit.io.schema_cycle.ToleranceSpec
        The ``[[tolerances]]`` a tolerance study samples (values keep their units).
    """

    source: str
    spec: schema.BearingFile
    geometry: BaseModel
    model: BearingModel
    material: object
    lubricant: object | None
    cases: tuple
    free: np.ndarray
    options: object
    sections: object = None
    duty_cycle: object = None
    tolerances: tuple = ()

    @property
    def bearing_type(self) -> str:
        return self.spec.bearing.type

    def select(self, names: Iterable[str] | None) -> BearingInput:
        """A copy holding only the load cases called ``names`` (all when None or empty)."""
        names = list(names or ())
        if not names:
            return self
        known = {c.name: c for c in self.cases}
        for n in names:
            if n not in known:
                listed = f"cases are {quote(list(known))}" if known else "the file has no load cases"
                raise InputError(
                    f"{self.source}: case ({quote(n)}) not in the file; {listed}{did_you_mean(n, known)}"
                )
        return dataclasses.replace(self, cases=tuple(known[n] for n in names))

    def check_cases(self, limit: int, purpose: str) -> BearingInput:
        """``self`` when it holds at most ``limit`` load cases, else InputError naming ``purpose``."""
        if len(self.cases) > limit:
            raise InputError(
                f"{self.source}: load_cases ({len(self.cases)} cases) must be at most {limit} for "
                f"{purpose}; select some with --case or split the file"
            )
        return self

    def with_cases(self, cases: Sequence[LoadCase]) -> BearingInput:
        """A copy with ``cases`` instead of the file's load cases (checked against fixed DOFs)."""
        _check_case_count(self.source, self.model, len(cases))
        _check_fixed_loads(self.source, cases, self.free)
        _check_single_tapered(self.source, self.model, cases, self.free)
        return dataclasses.replace(self, cases=tuple(cases))

    def load_matrix(self) -> np.ndarray:
        """External loads (C, 5) [N, N, N, N·m, N·m] of the load cases."""
        if not self.cases:
            raise InputError(f"{self.source}: load_cases (none): give at least one [[load_cases]] or --load")
        return np.stack([c.load for c in self.cases])

    def solve(self):
        """Solve every load case in one batch; returns a QuasiStaticResult (``converged`` per case)."""
        from bearingkit.analysis.quasistatic import solve

        try:
            return solve(self.model, self.load_matrix(), free=self.free, options=self.options)
        except InputError as exc:
            if str(exc).startswith(self.source):
                raise
            raise InputError(f"{self.source}: {exc}") from None


# ---------------------------------------------------------------------------------------------
# Entry points.
# ---------------------------------------------------------------------------------------------
def load_file(path) -> BearingInput:
    """Read and validate a TOML input file; InputError (one line naming the file) if malformed.

    Only a regular file of at most :data:`bearingkit.io.reading.MAX_INPUT_BYTES` is read
    (:func:`bearingkit.io.reading.read_text`).
    """
    return loads(read_text(path), source=str(path))


def loads(text: str, source: str = "<string>") -> BearingInput:
    """Validate TOML text (see :func:`load_file`)."""
    return from_dict(parse_toml(text, source), source)


def from_dict(data: dict, source: str = "<dict>") -> BearingInput:
    """Validate an already-parsed file (a dict as ``tomllib`` returns it)."""
    from bearingkit.analysis.quasistatic import SolverOptions

    if not isinstance(data, dict):
        raise InputError(f"{source}: the file must be a table of sections, got {type(data).__name__}")
    cycle = {k: data[k] for k in schema_cycle.SECTIONS if k in data}  # validated by schema_cycle
    try:
        spec = schema.BearingFile.model_validate({k: v for k, v in data.items() if k not in cycle})
    except ValidationError as exc:
        raise one_line(source, exc, (), section_models(None)) from None
    if spec.bearing.designation is not None:
        spec = _from_designation(source, spec)
    elif "geometry" not in data:
        raise InputError(f"{source}: geometry: missing required field (or give bearing.designation)")
    gmodel = schema.GEOMETRY_MODELS[spec.bearing.type]
    try:
        geometry = gmodel.model_validate(_profile_as_table(spec.geometry))
    except ValidationError as exc:
        raise one_line(source, exc, ("geometry",), section_models(gmodel)) from None
    material = _material(source, spec.material)
    lubricant = _lubricant(source, spec.lubricant)
    gdict = geometry.model_dump()
    try:
        model = BUILDERS[spec.bearing.type](gdict, material, spec.bearing.name)
    except InputError as exc:
        raise InputError(f"{source}: {prefix_field(str(exc), 'geometry', gdict)}") from None
    _check_envelope(source, model, gdict)
    _check_shoulders(source, model, gdict)
    free = np.ones(5, bool)
    if spec.solver.free is not None:
        free = np.array([d in spec.solver.free for d in DOF_NAMES])
    opts = {
        k: v for k, v in (("rtol", spec.solver.rtol), ("max_iterations", spec.solver.max_iterations)) if v
    }
    from bearingkit.io.schema_operating import validate_sections

    sections = validate_sections(spec, source, one_line)
    cases = tuple(_load_case(c) for c in spec.load_cases)
    _check_case_count(source, model, len(cases))
    _check_fixed_loads(source, cases, free)
    _check_single_tapered(source, model, cases, free)
    duty = schema_cycle.duty_cycle_of(source, cycle.get("duty_cycle"), _load_case)
    if duty is not None:
        _check_case_count(source, model, len(duty.bins), "duty_cycle")
        _check_fixed_loads(source, duty.bins, free)
        _check_single_tapered(source, model, duty.bins, free)
    return BearingInput(
        source=source,
        spec=spec,
        geometry=geometry,
        model=model,
        material=material,
        lubricant=lubricant,
        cases=cases,
        free=free,
        options=SolverOptions(**opts),
        sections=sections,
        duty_cycle=duty,
        tolerances=schema_cycle.tolerances_of(source, cycle.get("tolerances")),
    )


def _check_shoulders(source: str, model, gdict: dict) -> None:
    """Refuse shoulder heights above the groove depth (one line; :mod:`bearingkit.io.shoulders`)."""
    from bearingkit.io.shoulders import shoulder_fractions

    try:
        shoulder_fractions(gdict, model)
    except InputError as exc:
        raise InputError(f"{source}: {exc}") from None


#: Geometry fields of the catalogue estimate that are angles (radians); other floats are lengths (m)
#: except the dimensionless conformities.
_CATALOGUE_ANGLES = ("contact_angle", "contact_angle_outer", "contact_angle_inner", "roller_angle")


def _catalogue_value(key: str, value):
    """A catalogue geometry value (SI) written as the input format expects it (string with unit)."""
    if isinstance(value, (dict, str, int, bool)):
        return value
    if key.startswith(("conformity", "osculation")):
        return float(value)
    return f"{float(value)!r} {'rad' if key in _CATALOGUE_ANGLES else 'm'}"


def _from_designation(source: str, spec: schema.BearingFile) -> schema.BearingFile:
    """Type, geometry (estimate, overridden by the file's [geometry]), name and source from a designation."""
    from bearingkit.catalogue import resolve

    header = spec.bearing
    try:
        found = resolve(header.designation, C=header.C, clearance_position=header.class_position())
    except InputError as exc:
        field = "bearing." if str(exc).startswith("designation") else ""
        raise InputError(f"{source}: {field}{exc}") from None
    if header.type and header.type != found.bearing_type:
        raise InputError(
            f"{source}: bearing.type ({header.type!r}) does not match designation {header.designation!r} "
            f"({found.bearing_type!r}); omit type"
        )
    geometry = {k: _catalogue_value(k, v) for k, v in found.geometry.items() if v is not None}
    geometry.update(spec.geometry)
    overridden = sorted(set(spec.geometry) & set(found.geometry))
    given = f"; given in the file, not estimated: {', '.join(overridden)}" if overridden else ""
    note = found.source + given
    bearing = header.model_copy(
        update={
            "type": found.bearing_type,
            "name": header.name or header.designation,
            "source": header.source or note,
        }
    )
    return spec.model_copy(update={"bearing": bearing, "geometry": geometry})


def parse_load_options(items: Sequence[str], name: str = "command line") -> LoadCase:
    """One load case from ``["Fa=5kN", "My=600N*m", …]`` (names in :data:`LOAD_ALIASES`)."""
    fields: dict[str, str] = {}
    for item in items:
        key, sep, value = item.partition("=")
        key = key.strip()
        if not sep or not value.strip():
            raise InputError(f"--load ({item!r}) must look like NAME=VALUE with a unit, e.g. Fa=5kN")
        if key not in LOAD_ALIASES:
            raise InputError(
                f"--load ({item!r}): unknown name {key!r}; expected one of {', '.join(LOAD_ALIASES)}"
            )
        canonical = LOAD_ALIASES[key]
        if canonical in fields:
            raise InputError(f"--load ({item!r}): {canonical} given twice")
        fields[canonical] = value.strip()
    try:
        spec = schema.LoadCaseSpec.model_validate({"name": name, **fields})
    except ValidationError as exc:
        raise one_line("--load", exc, (), {"": schema.LoadCaseSpec}) from None
    return _load_case(spec)


# ---------------------------------------------------------------------------------------------
# Helpers.
# ---------------------------------------------------------------------------------------------
def _load_case(spec: schema.LoadCaseSpec) -> LoadCase:
    from bearingkit.analysis.quasistatic import load_vector

    m_y = spec.M_y - (spec.eccentricity or 0.0) * spec.F_z
    load = load_vector(F_x=spec.F_x, F_y=spec.F_y, F_z=spec.F_z, M_x=spec.M_x, M_y=m_y)
    return LoadCase(spec.name, load, spec.speed, spec.temperature)


def _check_single_tapered(source: str, model, cases, free) -> None:
    """A lone tapered row carries axial load one way only: F_z·direction must be positive if u_z is free.

    With u_z free and no axial load towards the row's cone the inner ring lifts off (no equilibrium).
    """
    rows = model.rows
    if len(rows) != 1 or rows[0].kind != "tapered" or not free[2]:
        return
    sign = rows[0].direction
    word = "positive" if sign > 0 else "negative"
    for c in cases:
        if not c.load[2] * sign > 0.0:
            raise InputError(
                f"{source}: load case {c.name!r}: F_z ({c.load[2]:.6g} N) must be {word}: a single tapered "
                "row carries axial load one way only and lifts off otherwise; use "
                "arrangement DB or DF for reversing loads, or fix u_z in [solver] free"
            )


def max_cases(model) -> int:
    """Most load cases one run of ``model`` may take under the caps above (a study of more cases
    solves them in runs of at most this many: :mod:`bearingkit.studies.generic`)."""
    flexible = getattr(model.metadata.get("ring"), "flexible", False) is True
    points = sum(int(r.n_elements) * int(getattr(r, "n_slices", 1) or 1) for r in model.rows)
    most = MAX_FLEXIBLE_LOAD_CASES if flexible else schema.MAX_LOAD_CASES
    return max(1, min(most, MAX_CASE_POINTS // max(points, 1)))


def _check_case_count(source: str, model, n_cases: int, section: str = "load_cases") -> None:
    """Refuse more load cases (or duty-cycle bins: one batch as well) than the solver can take in
    bounded time and memory (caps above)."""
    if n_cases > schema.MAX_LOAD_CASES:
        raise InputError(f"{source}: {section} ({n_cases} cases) must be at most {schema.MAX_LOAD_CASES}")
    # a ball–column model carries its RingOptions (flexible by default, [geometry.ring] or not)
    flexible = getattr(model.metadata.get("ring"), "flexible", False) is True
    if flexible and n_cases > MAX_FLEXIBLE_LOAD_CASES:
        raise InputError(
            f"{source}: {section} ({n_cases} cases) must be at most {MAX_FLEXIBLE_LOAD_CASES} with a "
            "flexible ring ([geometry.ring] flexible = true); split the file or set flexible = false"
        )
    points = sum(int(r.n_elements) * int(getattr(r, "n_slices", 1) or 1) for r in model.rows)
    if n_cases * points > MAX_CASE_POINTS:
        raise InputError(
            f"{source}: {section} ({n_cases} cases × {points} contact points) must stay within "
            f"{MAX_CASE_POINTS:.0e} contact points per run; use fewer cases, elements or n_slices"
        )


def _check_fixed_loads(source: str, cases, free) -> None:
    fixed = np.flatnonzero(~np.asarray(free))
    if not len(cases) or not fixed.size:
        return
    loads = np.stack([c.load for c in cases])[:, fixed]  # one check for every case (studies: thousands)
    bad = np.argwhere(loads != 0.0)
    if bad.size:
        k, j = bad[0]  # the first case, its first fixed DOF: as a loop over cases and DOFs would find
        c, i = cases[k], fixed[j]
        raise InputError(
            f"{source}: load case {c.name!r}: {LOAD_NAMES[i]} ({c.load[i]:.6g} {LOAD_UNITS[i]}) "
            f"acts on {DOF_NAMES[i]}, which [solver] free keeps fixed; free it or remove the load"
        )


def _material(source: str, spec: schema.MaterialSpec | None):
    from bearingkit.materials import MATERIALS, Material, get_material

    if spec is None:
        return get_material("GCr15")
    if spec.name is not None:
        if spec.name not in MATERIALS:
            raise InputError(
                f"{source}: material.name ({quote(spec.name)}) must be one of {', '.join(MATERIALS)}"
                f"{did_you_mean(spec.name, MATERIALS)}"
            )
        return MATERIALS[spec.name]
    try:
        return Material(
            name="custom",
            youngs_modulus=spec.youngs_modulus,
            poisson_ratio=spec.poisson_ratio,
            density=spec.density,
            source=f"{source} [material]",
        )
    except InputError as exc:
        raise InputError(f"{source}: material.{exc}") from None


def _lubricant(source: str, spec: schema.LubricantSpec | None):
    from bearingkit.lubricants import LUBRICANTS

    if spec is None:
        return None
    if spec.name not in LUBRICANTS:
        raise InputError(
            f"{source}: lubricant.name ({quote(spec.name)}) must be one of {', '.join(LUBRICANTS)}"
            f"{did_you_mean(spec.name, LUBRICANTS)}"
        )
    return LUBRICANTS[spec.name]


def _profile_as_table(geometry: dict) -> dict:
    """Accept ``profile = "iso16281"`` as shorthand for ``profile = {name = "iso16281"}``."""
    if isinstance(geometry.get("profile"), str):
        return {**geometry, "profile": {"name": geometry["profile"]}}
    return geometry


def _radial_extent(row) -> tuple[float, float]:
    """Smallest and largest radius [m] a row's elements occupy."""
    if row.kind == "threaded":  # PTRB: rollers of pitch diameter d_R on the pitch circle D_pw
        g = row.geometry
        return (g.pitch_diameter - g.roller_pitch_diameter) / 2, (
            g.pitch_diameter + g.roller_pitch_diameter
        ) / 2
    radius = float(np.max(row.pitch_diameter)) / 2
    if row.kind == "tapered":
        half = float(row.large_diameter) / 2
    elif getattr(row, "orientation", "radial") != "radial":
        half = float(np.max(row.effective_length)) / 2  # thrust roller: its axis is radial
    else:
        half = float(np.max(row.element_diameter)) / 2
    return radius - half, radius + half


def _check_envelope(source: str, model: BearingModel, geometry: dict) -> None:
    """Rows must lie strictly between the bore and the outside diameter, when they are known."""
    env = model.metadata.get("geometry", {})
    env = dataclasses.asdict(env) if dataclasses.is_dataclass(env) else dict(env)
    env.update({k: geometry[k] for k in ("bore", "outer_diameter") if geometry.get(k) is not None})
    bore, outer = env.get("bore"), env.get("outer_diameter")
    if bore is not None and outer is not None and not bore < outer:
        raise InputError(f"{source}: geometry.outer_diameter ({outer:.6g} m) must exceed bore ({bore:.6g} m)")
    for row in model.rows:
        r_in, r_out = _radial_extent(row)
        if (bore is not None and r_in <= bore / 2) or (outer is not None and r_out >= outer / 2):
            raise InputError(
                f"{source}: geometry: row {row.name!r} spans diameters {2 * r_in * 1e3:.6g}–"
                f"{2 * r_out * 1e3:.6g} mm, which must lie strictly between bore ({_mm(bore)}) "
                f"and outer_diameter ({_mm(outer)})"
            )


def _mm(x) -> str:
    return "not given" if x is None else f"{x * 1e3:.6g} mm"
