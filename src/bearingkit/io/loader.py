"""Load a bearing input file (TOML with units) into a :class:`BearingInput` (model, load cases, settings).

SI inside: the schema (:mod:`bearingkit.io.schema`) turns every ``"6 mm"`` into metres; this
module validates the file, resolves a designation (:mod:`bearingkit.io.build.designation`), maps
``bearing.type`` to a builder of :data:`~bearingkit.io.build.builders.BUILDERS`, checks that the rows fit
the envelope (:mod:`bearingkit.io.build.envelope`), forms the load cases (:mod:`bearingkit.io.load_cases`)
and bounds their number (the caps below). Every malformed input raises
:class:`bearingkit.errors.InputError` with one line: ``FILE: field (value) what was expected``.

The names of those modules are importable from here as before (``loader.BUILDERS``,
``loader.LoadCase``, ``loader.register_bearing_type`` …).

>>> from bearingkit.io.loader import load_file
>>> bearing = load_file("examples/seed000_composite.toml")      # doctest: +SKIP
>>> result = bearing.solve()                                     # doctest: +SKIP
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np
from pydantic import BaseModel, ValidationError

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError, did_you_mean, quote
from bearingkit.io import schema
from bearingkit.io.build.builders import BUILDERS, register_bearing_type
from bearingkit.io.build.designation import from_designation
from bearingkit.io.build.envelope import check_envelope, check_shoulders
from bearingkit.io.load_cases import (
    DOF_NAMES,
    LOAD_ALIASES,
    LOAD_NAMES,
    LOAD_UNITS,
    LoadCase,
    check_fixed_loads,
    check_single_tapered,
    load_case_of,
    mounted_free,
    override_free,
    parse_load_options,
)
from bearingkit.io.messages import one_line, prefix_field, section_models
from bearingkit.io.optional_sections import cycle as schema_cycle
from bearingkit.io.reading import parse_toml, read_text

__all__ = [
    "BUILDERS",
    "DOF_NAMES",
    "LOAD_ALIASES",
    "LOAD_NAMES",
    "LOAD_UNITS",
    "MAX_CASE_POINTS",
    "MAX_FLEXIBLE_LOAD_CASES",
    "MAX_REPORT_CASES",
    "BearingInput",
    "LoadCase",
    "from_dict",
    "load_file",
    "loads",
    "max_cases",
    "parse_load_options",
    "register_bearing_type",
]

# The caps stay in this module: max_cases and _check_case_count read them here, where callers and
# tests look them up (``loader.MAX_CASE_POINTS``).
#: Most load cases of a bearing with a flexible ring ([geometry.ring] flexible, the default of a
#: ball–column bearing): the coupled Newton solve keeps a (cases, n, n) Jacobian of the ~240 raceway
#: offsets. Measured on the 2-core reference machine: 100 cases take 27 s and 270 MB through analyze.
MAX_FLEXIBLE_LOAD_CASES = 100
#: Metadata key of a model whose input has a ``[structure]`` (flexible rings for any bearing).
STRUCTURE_KEY = "structure"
#: Most load cases in one HTML report: two figures per case (~1 s each) and a page a person reads.
#: Measured: 20 cases of a deep groove ball bearing take about a minute. More: analyze --json.
MAX_REPORT_CASES = 20
#: Most contact points (load cases × Σ rows elements × slices) one run may ask for. Measured on a
#: cylindrical roller bearing of 250 rollers × 200 slices: 2·10⁶ points peak at 260 MB through
#: friction (212 MB analyze), 10⁷ at 900 MB. A seed-000 turntable (≈ 3,200 points) takes ≈ 600 cases.
MAX_CASE_POINTS = 2_000_000


# ---------------------------------------------------------------------------------------------
# Results of loading.
# ---------------------------------------------------------------------------------------------
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
    options : bearingkit.analysis.solver.options.SolverOptions
    sections : bearingkit.io.optional_sections.operating.OperatingSections
        The parsed ``[operating]``, ``[fits]`` and ``[lubrication]`` sections.
    duty_cycle : bearingkit.io.optional_sections.cycle.DutyCycle or None
        The ``[[duty_cycle]]`` bins (load spectrum), when the file has them.
    hardness : bearingkit.hardness.HardnessProfile
        The raceways' hardness against depth (``[hardness]``, else the material's).
    tolerances : tuple of bearingkit.io.optional_sections.cycle.ToleranceSpec
        The ``[[tolerances]]`` a tolerance study samples (values keep their units).
    structure : bearingkit.analysis.structure.Structure or None
        Flexible rings or an imported FE matrix from ``[structure]`` (docs/structure.md).
    file_free : ndarray (5,) of bool or None
        The free DOFs of the file ([solver] free, else all) before an automatic hold or a caller's
        override changed ``free`` (None: ``free`` is the file's).
    dof_overrides : tuple of (str, bool)
        DOFs the caller held (False) or freed (True) over the file's (:meth:`with_dofs`).
    free_notes : tuple of str
        Why ``free`` differs from the file's (an automatic hold of a single one-way row, an override).
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
    file_free: np.ndarray | None = None
    dof_overrides: tuple = ()
    free_notes: tuple = ()
    hardness: object = None
    structure: object = None

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

    def with_cases(self, cases: Sequence[LoadCase], loads: np.ndarray | None = None) -> BearingInput:
        """A copy with ``cases`` instead of the file's load cases (checked against fixed DOFs; a single
        one-way row is mounted again for them, :func:`~bearingkit.io.load_cases.mounted_free`).

        ``loads``: the cases' loads (C, 5) when the caller has them as one array already (a study's
        group of thousands of cases): kept as the copy's :meth:`load_matrix` instead of being
        stacked again from the cases, one at a time (issue 34).
        """
        if loads is not None:
            loads = np.asarray(loads, dtype=float)
            if loads.shape != (len(cases), 5):
                raise ValueError(f"loads (shape {loads.shape}) must be ({len(cases)}, 5), one row per case")
        _check_case_count(self.source, self.model, len(cases))
        out = self._with_free(tuple(cases), self.dof_overrides, loads)
        if loads is not None:
            frozen = loads.copy()
            frozen.flags.writeable = False
            object.__setattr__(out, "_loads", frozen)  # a cache beside the fields (frozen dataclass)
        return out

    def with_dofs(self, hold: Sequence[str] = (), release: Sequence[str] = ()) -> BearingInput:
        """A copy with the DOFs named in ``hold`` fixed (at 0: their loads become reactions) and those in
        ``release`` freed, over the file's [solver] free (the CLI's ``--hold`` / ``--free``)."""
        override_free(self.source, self.free, hold, release)  # names checked before anything else
        given = dict(self.dof_overrides)
        given.update({n: False for n in hold})
        given.update({n: True for n in release})
        return self._with_free(self.cases, tuple(given.items()))

    def _with_free(self, cases: tuple, overrides: tuple, loads: np.ndarray | None = None) -> BearingInput:
        base = self.free if self.file_free is None else self.file_free
        hold = [n for n, v in overrides if not v]
        release = [n for n, v in overrides if v]
        free = override_free(self.source, base, hold, release)
        user_set = self.spec.solver.free is not None or bool(overrides)
        notes: tuple = ()
        if overrides:
            said = [f"{n} {'freed' if v else 'held at 0'}" for n, v in overrides]
            notes = (f"DOFs set by the caller over the file's: {', '.join(said)}",)
        check_fixed_loads(self.source, cases, free, loads)
        free, mounted = mounted_free(self.source, self.model, cases, free, user_set=user_set, loads=loads)
        return dataclasses.replace(
            self,
            cases=cases,
            free=free,
            file_free=base,
            dof_overrides=overrides,
            free_notes=notes + mounted,
        )

    def load_matrix(self) -> np.ndarray:
        """External loads (C, 5) [N, N, N, N·m, N·m] of the load cases (a new array each call)."""
        if not self.cases:
            raise InputError(f"{self.source}: load_cases (none): give at least one [[load_cases]] or --load")
        cached = self.__dict__.get("_loads")
        if cached is not None:
            return cached.copy()
        return np.stack([c.load for c in self.cases])

    def solve(self):
        """Solve every load case in one batch; returns a QuasiStaticResult (``converged`` per case)."""
        from bearingkit.analysis.solver.quasistatic import solve

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
    from bearingkit.analysis.solver.options import SolverOptions

    if not isinstance(data, dict):
        raise InputError(f"{source}: the file must be a table of sections, got {type(data).__name__}")
    if "shaft" in data and "bearing" not in data:  # a shaft file given to a bearing command
        raise InputError(
            f"{source}: this is a shaft file ([shaft] table), not a bearing file: run "
            f"'bearingkit shaft {source}' (or 'bearingkit report {source}' for its report)"
        )
    cycle = {k: data[k] for k in schema_cycle.SECTIONS if k in data}  # validated by schema_cycle
    try:
        spec = schema.BearingFile.model_validate({k: v for k, v in data.items() if k not in cycle})
    except ValidationError as exc:
        raise one_line(source, exc, (), section_models(None)) from None
    if spec.bearing.designation is not None:
        spec = from_designation(source, spec)
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
    check_envelope(source, model, gdict)
    check_shoulders(source, model, gdict)
    from bearingkit.io.build.hardness import hardness_of

    hardness = hardness_of(source, spec.hardness, material, model, gdict)
    free = np.ones(5, bool)
    if spec.solver.free is not None:
        free = np.array([d in spec.solver.free for d in DOF_NAMES])
    opts = {
        k: v for k, v in (("rtol", spec.solver.rtol), ("max_iterations", spec.solver.max_iterations)) if v
    }
    from bearingkit.io.optional_sections.operating import validate_sections

    sections = validate_sections(spec, source, one_line)
    from bearingkit.io.build.structure import structure_of

    try:
        structure = structure_of(source, sections.structure, model, gdict, material)
    except InputError as exc:
        raise InputError(f"{source}: {exc}") from None
    if structure is not None:
        model = dataclasses.replace(model, metadata={**model.metadata, STRUCTURE_KEY: True})
    cases = tuple(load_case_of(c) for c in spec.load_cases)
    _check_case_count(source, model, len(cases))
    check_fixed_loads(source, cases, free)
    file_free = free
    free, free_notes = mounted_free(source, model, cases, free, user_set=spec.solver.free is not None)
    duty = schema_cycle.duty_cycle_of(source, cycle.get("duty_cycle"), load_case_of)
    if duty is not None:
        _check_case_count(source, model, len(duty.bins), "duty_cycle")
        check_fixed_loads(source, duty.bins, free)
        check_single_tapered(source, model, duty.bins, free)
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
        file_free=file_free,
        free_notes=free_notes,
        hardness=hardness,
        structure=structure,
    )


def _coupled(model) -> bool:
    """Whether ``model`` is solved with a flexible ring: a ball–column ring, or a ``[structure]``."""
    return getattr(model.metadata.get("ring"), "flexible", False) is True or bool(
        model.metadata.get(STRUCTURE_KEY)
    )


def max_cases(model) -> int:
    """Most load cases one run of ``model`` may take under the caps above (a study of more cases
    solves them in runs of at most this many: :mod:`bearingkit.studies.generic.evaluator`)."""
    flexible = _coupled(model)
    points = sum(int(r.n_elements) * int(getattr(r, "n_slices", 1) or 1) for r in model.rows)
    most = MAX_FLEXIBLE_LOAD_CASES if flexible else schema.MAX_LOAD_CASES
    return max(1, min(most, MAX_CASE_POINTS // max(points, 1)))


def _check_case_count(source: str, model, n_cases: int, section: str = "load_cases") -> None:
    """Refuse more load cases (or duty-cycle bins: one batch as well) than the solver can take in
    bounded time and memory (caps above)."""
    if n_cases > schema.MAX_LOAD_CASES:
        raise InputError(f"{source}: {section} ({n_cases} cases) must be at most {schema.MAX_LOAD_CASES}")
    # a ball–column model carries its RingOptions (flexible by default, [geometry.ring] or not); a
    # [structure] marks the model with STRUCTURE_KEY
    if _coupled(model) and n_cases > MAX_FLEXIBLE_LOAD_CASES:
        how = (
            "a [structure] (flexible rings); split the file"
            if model.metadata.get(STRUCTURE_KEY)
            else "flexible ring ([geometry.ring] flexible = true); split the file or set flexible = false"
        )
        raise InputError(
            f"{source}: {section} ({n_cases} cases) must be at most {MAX_FLEXIBLE_LOAD_CASES} with a {how}"
        )
    points = sum(int(r.n_elements) * int(getattr(r, "n_slices", 1) or 1) for r in model.rows)
    if n_cases * points > MAX_CASE_POINTS:
        raise InputError(
            f"{source}: {section} ({n_cases} cases × {points} contact points) must stay within "
            f"{MAX_CASE_POINTS:.0e} contact points per run; use fewer cases, elements or n_slices"
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
    """The file's ``[lubricant]`` through the one lubricant builder (a name, or the oil's data)."""
    return lubricant_of(source, spec)


def lubricant_of(source: str, spec) -> object:
    """The Lubricant of a parsed ``[lubricant]`` table (None when absent); one line naming the file.

    Every input that has a ``[lubricant]`` (bearing files, shaft files) reads it here, with
    :func:`bearingkit.lubricants.lubricant_from_fields` (the builder the CLI, the app and studies use).
    """
    from bearingkit.lubricants import lubricant_from_fields

    if spec is None:
        return None
    fields = spec.model_dump(exclude_none=True) if hasattr(spec, "model_dump") else dict(spec)
    return lubricant_from_fields(fields, where=f"{source}: lubricant")


def load_lubricant_file(path) -> object:
    """The Lubricant of a lubricant file: a TOML file with a ``[lubricant]`` table, or its fields at the
    top (``--lubricant-file``); validated by the same model as a bearing file's ``[lubricant]``."""
    from bearingkit.io.reading import load_toml

    source = str(path)
    data = load_toml(path)
    table = data.get("lubricant", data) if isinstance(data, dict) else data
    prefix = ("lubricant",) if isinstance(data, dict) and "lubricant" in data else ()
    if not isinstance(table, dict):
        raise InputError(f"{source}: lubricant must be a table of fields (name, nu_40, nu_100, base_oil …)")
    try:
        spec = schema.LubricantSpec.model_validate(table)
    except ValidationError as exc:
        models = {".".join(prefix): schema.LubricantSpec}
        raise one_line(source, exc, prefix, models) from None
    return lubricant_of(source, spec)


def _profile_as_table(geometry: dict) -> dict:
    """Accept ``profile = "iso16281"`` as shorthand for ``profile = {name = "iso16281"}``."""
    if isinstance(geometry.get("profile"), str):
        return {**geometry, "profile": {"name": geometry["profile"]}}
    return geometry
