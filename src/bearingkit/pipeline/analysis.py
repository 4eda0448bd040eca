"""The one orchestration: bearing input → statics (+ flexible ring) → friction → rating → :class:`Analysis`.

SI units inside (m, N, Pa, rad, rad/s, N·m, W; temperatures in °C). Every face — the CLI commands, the
HTML report, ``make run``'s flagship, the study evaluators and the web app — builds an
:class:`Analysis` and reads its parts; none of them orchestrates by itself. Each part is computed only
when asked for, and only once:

- :attr:`Analysis.statics` — the batched quasi-static solve of every load case (rigid rings);
- :attr:`Analysis.flexible` — the coupled flexible-ring solve, where the input configures one;
- :meth:`Analysis.friction_by` / :attr:`Analysis.friction` — friction by a model of
  :data:`~bearingkit.pipeline.friction.models.FRICTION_MODELS`;
- :attr:`Analysis.rating` — ISO 76 / ISO 281 / ISO/TS 16281 ratings, lives and static safety;
- :attr:`Analysis.limits` — limiting and thermal reference speed, seal lip speed and minimum load of a
  standard bearing (:mod:`bearingkit.pipeline.limits`);
- :attr:`Analysis.rating` — ISO 76 / ISO 281 / ISO/TS 16281 ratings, lives and static safety (the ISO 76
  limit pressures scaled by the raceways' hardness, :attr:`Analysis.hardness`);
- :attr:`Analysis.subsurface` / :meth:`Analysis.subsurface_by` — stresses below the most loaded contacts
  and the hardened-layer check (:mod:`bearingkit.pipeline.rating.subsurface`); :attr:`Analysis.truncation`
  — truncated contact ellipses as pressures and safeties, with s0 and L10r rated with them;
- :attr:`Analysis.warnings` — per case, everything doubtful any computed part found (non-convergence,
  pressure above the static limit, s0 < 1, truncated ellipse, edge loading, free tilt of a single-row
  bearing, a speed or load limit exceeded …); every face shows them.

>>> import bearingkit as bk
>>> a = bk.analyze("examples/dgbb_6209.toml", load={"F_x": "5 kN"}, speed="3000 rpm")  # doctest: +SKIP
>>> a.rating.life                                                                     # doctest: +SKIP
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from bearingkit.errors import InputError
from bearingkit.lazy import cached_property
from bearingkit.pipeline import analysis_messages
from bearingkit.pipeline.analysis_messages import FREE_TILT_LIMIT  # re-exported: its home before the split
from bearingkit.pipeline.analysis_output import AnalysisOutput
from bearingkit.pipeline.friction.models import FRICTION_MODELS, FrictionOutcome
from bearingkit.pipeline.inputs import ModelInput, load_input
from bearingkit.pipeline.operating import Operating

__all__ = ["FREE_TILT_LIMIT", "RENDERERS", "Analysis", "analyze"]

#: Renderers of an Analysis by format (``"html"``), registered by the report layer
#: (:mod:`bearingkit.report` adds itself on import; :meth:`Analysis.report` loads it by name).
RENDERERS: dict[str, Callable] = {}
#: Where the renderer of each format lives (imported on first use, the way plugins are).
_RENDERER_MODULES = {"html": "bearingkit.report"}


class Analysis(AnalysisOutput):
    """A bearing under its load cases and operating conditions; parts computed lazily, once.

    The JSON-ready output (``statics_dict``, ``rating_dict``, ``friction_dict``, ``to_dict``,
    ``to_pandas`` …) is inherited from :class:`~bearingkit.pipeline.analysis_output.AnalysisOutput`.

    Parameters
    ----------
    bearing : BearingInput
        The input (:func:`bearingkit.pipeline.load_input`).
    operating : Operating
        Per-case operating conditions.
    friction_model : str
        Default model of :attr:`friction` (a key of :data:`FRICTION_MODELS`); ``"auto"`` picks the model
        of the bearing's kind (:func:`bearingkit.pipeline.friction.choice.choose`).
    load_ratings : dict, optional
        Row name → C [N] replacing ISO 281 ratings (catalogue values).
    friction_options : dict, optional
        Further fields of :class:`bearingkit.analysis.friction.components.OperatingPoint` for the component
        model
        (``viscosity_factor``, ``cage_mass``, roughness, traction …).
    """

    def __init__(
        self,
        bearing,
        operating: Operating,
        *,
        friction_model: str = "auto",
        load_ratings=None,
        friction_options=None,
    ):
        if friction_model not in FRICTION_MODELS:
            raise InputError(
                f"friction model ({friction_model!r}) must be one of {', '.join(FRICTION_MODELS)}"
            )
        self.input = bearing
        self.operating = operating
        self.friction_model = friction_model
        self.load_ratings = dict(load_ratings or {})
        self.friction_options = dict(friction_options or {})
        self._friction: dict[str, FrictionOutcome] = {}
        self._friction_errors: dict[str, str] = {}
        self._subsurface: dict[tuple, object] = {}
        #: ISO 281 level name the contamination factor came from (None: a number or not given).
        self.contamination_level: str | None = None
        #: The heat balance that found the operating temperature (None: the temperature was an input),
        #: :class:`~bearingkit.pipeline.thermal.balance.ThermalEquilibrium`.
        self.thermal = None

    # ------------------------------------------------------------------------------- parts
    @property
    def n_cases(self) -> int:
        return len(self.input.cases)

    @property
    def case_names(self) -> list[str]:
        return [c.name for c in self.input.cases]

    @cached_property
    def setup(self):
        """What the statics are solved with: speed, fits and temperatures, tilt, preload
        (:func:`bearingkit.pipeline.conditions.statics_setup`)."""
        from bearingkit.pipeline.conditions import statics_setup

        return self._in_file(statics_setup, self)

    @cached_property
    def statics(self):
        """QuasiStaticResult of every load case (one batched solve, with the rows at speed, the
        operating clearance, the imposed tilt and the preload of :attr:`setup`)."""
        setup = self.setup
        same = np.array_equal(setup.free, self.input.free) and np.array_equal(
            setup.load, self.input.load_matrix()
        )
        if setup.plain and same:
            return self.input.solve()
        from bearingkit.analysis.solver.quasistatic import solve

        b = self.input
        return self._in_file(
            solve,
            b.model,
            setup.load,
            free=setup.free,
            displacement=setup.displacement,
            options=b.options,
            raceway_offsets=setup.offsets,
            speed=setup.speed,
        )

    def _in_file(self, fn, *args, **kwargs):
        """Call ``fn``; an InputError is prefixed with the input's name (one line)."""
        try:
            return fn(*args, **kwargs)
        except InputError as exc:
            if str(exc).startswith(f"{self.input.source}:"):
                raise
            raise InputError(f"{self.input.source}: {exc}") from None

    @property
    def clearance(self):
        """ClearanceChain of the radial rows (fits and temperatures), or None when none were given."""
        return self.setup.clearance

    @cached_property
    def preload(self):
        """Axial force [N] each row carries at rest without external load, or None when not preloaded.

        Solved once, for the bearing as mounted (fits at the reference temperature are included when
        given; speed is not: a preload is set at rest).
        """
        from bearingkit.pipeline.operating_output import preload_state

        return preload_state(self)

    @cached_property
    def lubrication(self):
        """LubricationResult: film thickness and Λ per contact, ν, ν1, κ, e_C, a_ISO, L_nm, grease life
        (:mod:`bearingkit.analysis.lubrication`); None without a lubricant or a speed."""
        from bearingkit.pipeline.operating_output import lubrication

        return lubrication(self)

    @cached_property
    def flexible(self):
        """The coupled flexible-ring solve, or None when the input has no flexible ring: a
        :class:`~bearingkit.analysis.structure.StructureResult` for a ``[structure]`` (any bearing,
        :mod:`bearingkit.pipeline.structure`), a :class:`~bearingkit.analysis.flexible.FlexibleResult`
        for the seed-002 ball–column ring."""
        if getattr(self.input, "structure", None) is not None:
            from bearingkit.pipeline.structure import solve_input

            return solve_input(self)
        if self.input.bearing_type != "ball_column":
            return None
        from bearingkit.bearings.ball_column import solve_flexible_input

        return solve_flexible_input(self.input)

    @cached_property
    def flexible_rating(self):
        """RatingResult of the ``[structure]``'s coupled solution (None without one), beside
        :attr:`rating` of the rigid rings (:func:`bearingkit.pipeline.structure.change`)."""
        from bearingkit.pipeline.structure import flexible_rating

        return flexible_rating(self)

    def friction_by(self, model: str | None = None) -> FrictionOutcome:
        """Friction by ``model`` (default :attr:`friction_model`); InputError when it does not apply."""
        model = model or self.friction_model
        if model not in FRICTION_MODELS:
            raise InputError(f"friction model ({model!r}) must be one of {', '.join(FRICTION_MODELS)}")
        if model in self._friction_errors:
            raise InputError(self._friction_errors[model])
        if model not in self._friction:
            try:
                self._friction[model] = FRICTION_MODELS[model](self)
            except InputError as exc:
                self._friction_errors[model] = str(exc)
                raise
        return self._friction[model]

    @property
    def friction(self) -> FrictionOutcome | None:
        """Friction by the default model, or None when it cannot be computed (:attr:`notes` say why)."""
        try:
            return self.friction_by()
        except InputError:
            return None

    def _rate(self, statics):
        """The rating of ``statics`` with this analysis's operating point, shoulders and raceway hardness."""
        from bearingkit.analysis.rating.assembly import rate

        op = self.operating
        speed = op.abs_speed if np.all(op.abs_speed > 0) else None
        life = {}
        if op.contamination is not None and op.lubricant is not None and speed is not None:
            life = {
                "lubricant": op.lubricant,
                "temperature_C": op.temperature,
                "contamination_factor": op.contamination,
            }
        return rate(
            statics,
            speed=speed,
            rotating=op.rotating,
            reliability=op.reliability,
            load_ratings=self.load_ratings,
            shoulder_height=self._shoulder_heights(),
            catalogue_rating=self._catalogue_rating(),
            static_limit_factor=self.hardness.limit_factor(),
            **life,
        )

    @cached_property
    def _rating(self):
        from bearingkit.pipeline.rating.statics import ts_statics

        try:
            statics, arm_note = ts_statics(self)  # the TS's pitch-radius arm where a ring tilts
            rated = self._rate(statics)
            if arm_note:
                rated.notes.append(arm_note)
            return rated, None
        except InputError as exc:
            return None, f"ratings not computed: {exc}"

    @property
    def hardness(self):
        """The raceways' HardnessProfile (the file's ``[hardness]``, else the material's)."""
        from bearingkit.pipeline.rating.subsurface import raceway_profile

        return raceway_profile(self)

    def subsurface_by(
        self, *, traction: float = 0.0, target_safety: float = 1.0, every_contact: bool = False
    ):
        """SubsurfaceResult (:mod:`bearingkit.analysis.subsurface`) with these settings, once each."""
        from bearingkit.pipeline.rating.subsurface import subsurface_of

        key = (float(traction), float(target_safety), bool(every_contact))
        if key not in self._subsurface:
            self._subsurface[key] = subsurface_of(
                self, traction=traction, target_safety=target_safety, every_contact=every_contact
            )
        return self._subsurface[key]

    @property
    def subsurface(self):
        """Stresses below the most loaded contact of every row and case and the hardened-layer check
        (frictionless, target case safety 1; :meth:`subsurface_by` for other settings)."""
        return self.subsurface_by()

    @cached_property
    def truncation(self):
        """TruncationOutcome: truncated ball contacts as pressures and safeties, and the rating with them
        (:mod:`bearingkit.pipeline.rating.subsurface`)."""
        from bearingkit.pipeline.rating.subsurface import truncation_of

        return truncation_of(self)

    def _catalogue_rating(self):
        """(C, C0) [N] the catalogue publishes for the input's designation (or the file's bearing.C), or
        (C, C0, (C's source, C0's source)) for a maker's ``rating_C`` (``rating_C0`` or the catalogue's C0)
        given with a designation or a geometry;
        None for a bearing given by its geometry alone or a catalogue row without ratings."""
        spec = getattr(self.input, "spec", None)
        header = getattr(spec, "bearing", None)
        designation = getattr(header, "designation", None)
        maker = getattr(header, "rating_C", None)
        maker_c0 = getattr(header, "rating_C0", None)
        if maker is not None and not designation:  # a geometry with a maker's ratings
            return float(maker), None if maker_c0 is None else float(maker_c0), ("rating_C", "rating_C0")
        if not designation:
            return None
        from bearingkit.catalogue import parse, tables

        des = parse(designation)
        entry = tables.entries(des.family).get(des.base)
        given = getattr(header, "C", None)
        if maker is not None:  # a maker's ratings in place of the catalogue's (one bearing, radial basis)
            given, c0 = maker, maker_c0
            if c0 is None and entry is not None and entry.C0 is not None:  # the catalogue's, radial basis
                from bearingkit.catalogue.iso_ratings import radial_basis

                c0 = radial_basis(des.family, entry.C, entry.C0)[1]
            c, c0 = float(maker), None if c0 is None else float(c0)
        elif given is not None:
            c, c0 = float(given), None if entry is None else entry.C0
        elif entry is None or entry.C is None:
            return None
        else:
            c, c0 = entry.C, entry.C0
        if given is None:  # QJ rows print axial ratings: the radial C_r, C_0r ISO 281's X, Y go with
            from bearingkit.catalogue.iso_ratings import radial_basis

            c, c0 = radial_basis(des.family, c, c0)
        if des.is_pair:  # the catalogue rates one bearing: ISO 281's paired unit (C 2^0.7, 2^(7/9); C0 2)
            from bearingkit.physics.life.iso281 import paired_unit_ratings

            element = tables.FAMILIES[des.family][2]
            c, c0 = (None if x is None else float(x) for x in paired_unit_ratings(c, c0, element, 2))
        if maker is None:
            return c, c0
        # what the notes name: the maker's C, and its C0 or the catalogue's
        return (
            c,
            c0,
            ("rating_C", "catalogue" if maker_c0 is None else "rating_C0"),
        )

    def _shoulder_heights(self):
        """The file's groove shoulder heights per row (io.shoulders), or None (a model built in code)."""
        if isinstance(self.input, ModelInput):
            return None
        from bearingkit.io.build.shoulders import shoulder_fractions

        return shoulder_fractions(self.input.geometry.model_dump(), self.input.model)

    @cached_property
    def limits(self):
        """Speed and load limits per case (limiting and thermal reference speed, seal lip speed, minimum
        load: :class:`~bearingkit.pipeline.limits.OperatingLimits`); None for a bearing no catalogue rule
        covers (seed composites, slewing rings, models built in code)."""
        from bearingkit.pipeline.limits import operating_limits

        return self._in_file(operating_limits, self)

    @cached_property
    def load_diagram(self):
        """Static load diagram of a slewing ring (allowable axial force vs tilting moment,
        :class:`~bearingkit.analysis.slewing.SlewingLoadDiagram`), None for other bearings."""
        from bearingkit.analysis.slewing import LIMIT_STRESS, closed_form_capacities, static_load_diagram
        from bearingkit.bearings.slewing import SLEWING_KEY

        model = self.input.model
        if not getattr(model, "metadata", {}).get(SLEWING_KEY):
            return None
        factor = self.hardness.limit_factor()  # the raceways' static limit (ISO 76 × hardness)
        p_limit = None if factor == 1.0 else LIMIT_STRESS[closed_form_capacities(model)[2]] * factor
        return static_load_diagram(model, p_limit=p_limit)

    @property
    def rating(self):
        """RatingResult, or None when the bearing cannot be rated (:attr:`notes` say why)."""
        return self._rating[0]

    @cached_property
    def duty_cycle(self):
        """DutyCycleResult: every ``[[duty_cycle]]`` bin rated (one batch) and the combined life
        (Palmgren–Miner, :mod:`bearingkit.pipeline.duty_cycle`); None when the input has no duty cycle."""
        if getattr(self.input, "duty_cycle", None) is None:
            return None
        from bearingkit.pipeline.duty_cycle import at_rest, bins_input, summarise

        def sub(bearing, operating):
            return Analysis(
                bearing,
                operating,
                friction_model=self.friction_model,
                load_ratings=self.load_ratings,
                friction_options=self.friction_options,
            )

        cycle = self.input.duty_cycle
        bins = sub(*bins_input(self))
        rest = at_rest(cycle)
        turning = None
        if rest.any() and not rest.all():  # lives of the turning bins alone: a_ISO and hours need speed
            turning = sub(*bins_input(self, np.flatnonzero(~rest)))
        return summarise(cycle, bins, turning)

    # ------------------------------------------------------------------------------- messages
    @property
    def notes(self) -> list[str]:
        """What was assumed or skipped, for every face (not per case)."""
        return analysis_messages.notes(self)

    @cached_property
    def warnings(self) -> list[list[str]]:
        """Per case: every doubtful finding of the parts computed for it (statics and ratings always)."""
        return analysis_messages.warnings(self)

    @property
    def references(self) -> list[str]:
        """Citation keys of every part computed so far."""
        keys = list(self.statics.references)
        if self.rating is not None:
            keys += list(self.rating.references)
        for outcome in self._friction.values():
            keys += list(outcome.references)
        if self._subsurface:
            from bearingkit import hardness
            from bearingkit.physics.contact import subsurface, subsurface_line

            keys += [*subsurface.REFERENCE_KEYS, *subsurface_line.REFERENCE_KEYS, *hardness.REFERENCE_KEYS]
        return list(dict.fromkeys(keys))

    # ------------------------------------------------------------------------------- output
    def report(self, path, **options):
        """Write the HTML report of this analysis to ``path`` (atomic); returns the path."""
        import importlib

        if "html" not in RENDERERS:
            importlib.import_module(_RENDERER_MODULES["html"])  # the report layer registers itself
        return RENDERERS["html"](self, path, **options)


def _check_lubricant_range(bearing, operating) -> None:
    """One line for a temperature outside the lubricant's viscosity–temperature range."""
    from bearingkit.lubricants import WALTHER_TEMPERATURE_MAX_C, WALTHER_TEMPERATURE_MIN_C

    if operating.lubricant is None:
        return
    for i, t in enumerate(operating.temperature):
        if not WALTHER_TEMPERATURE_MIN_C <= t <= WALTHER_TEMPERATURE_MAX_C:
            side = "below" if t < WALTHER_TEMPERATURE_MIN_C else "above"
            raise InputError(
                f"{bearing.source}: load case {bearing.cases[i].name!r}: temperature ({t:g} °C) is {side} "
                f"the range of lubricant {operating.lubricant.name!r} ({WALTHER_TEMPERATURE_MIN_C:g} … "
                f"{WALTHER_TEMPERATURE_MAX_C:g} °C, its viscosity–temperature law); expected one in it"
            )


def analyze(
    source,
    *,
    load=None,
    cases=None,
    speed=None,
    temperature=None,
    rotating: str = "inner",
    lubricant=None,
    contamination=None,
    reliability=0.9,
    friction_model: str = "auto",
    load_ratings=None,
    friction_options=None,
    thermal=None,
    hold=(),
    free=(),
) -> Analysis:
    """Analyse a bearing: the entry point of the library, the CLI, the report, studies and the app.

    Parameters
    ----------
    source : str, Path, dict, BearingInput or ModelInput
        Input file (docs/input-format.md), a designation, a parsed file, a loaded input, or a model and
        its loads built in code (:class:`~bearingkit.pipeline.inputs.ModelInput`).
    load : Mapping or list, optional
        Load case(s) replacing the file's, values with units: ``{"F_x": "5 kN", "F_z": "1 kN"}``.
    cases : list of str, optional
        Only these load cases of the file.
    speed : float [rad/s] or str, optional
        Speed of the rotating ring for every case, e.g. ``"3000 rpm"`` (sign rule:
        :mod:`bearingkit.pipeline.operating`); default each case's speed, else 0.
    temperature : float [°C] or str, optional
        E.g. ``"60 degC"``; default each case's, else 25 °C.
    rotating : {"inner", "outer"}
    lubricant : str, optional
        Preset name; default the file's ``[lubricant]``.
    contamination : float or str, optional
        ISO 281 e_C (0 … 1): with a lubricant, a temperature and a speed, gives a_ISO and L_nm.
    reliability : float or str
        Reliability of L_nr, 0.9 … 0.9995.
    friction_model : str
        ``"auto"`` (default: the model of the bearing's kind, see
        :func:`bearingkit.pipeline.friction.choice.choose`), ``"components"``, ``"skf"``, ``"palmgren"``
        … (:data:`FRICTION_MODELS`).
    load_ratings : dict, optional
        Row name → C [N] replacing the ISO 281 rating.
    friction_options : dict, optional
        Further :class:`~bearingkit.analysis.friction.components.OperatingPoint` fields of the component
        model.
    thermal : bool or dict, optional
        Find the operating temperature by the heat balance
        (:mod:`bearingkit.pipeline.thermal.balance`): True, or a dict of ``[thermal]`` fields
        (``ambient``, ``heat_dissipation``, ``housing_area``, ``heat_transfer_coefficient``,
        ``oil_flow``, ``oil_inlet_temperature``; text with units or SI); False: never. Default: when
        the file has a ``[thermal]`` section.
    hold, free : sequence of str, optional
        Inner-ring DOFs (``u_x`` … ``theta_y``) to hold at 0 (their loads become reactions) or to free,
        over the file's [solver] free and the defaults (``bearingkit analyze --hold u_z``).

    Returns
    -------
    Analysis
        Nothing is computed until a part is asked for (with ``thermal``: the balance is solved here and
        the Analysis returned is the one at the found temperature).
    """
    from bearingkit.pipeline.operating_output import resolve_contamination

    bearing = source if isinstance(source, ModelInput) else load_input(source, load=load, cases=cases)
    if hold or free:
        if isinstance(bearing, ModelInput):
            raise InputError("hold/free: a model built in code takes its free DOFs from ModelInput.free")
        bearing = bearing.with_dofs(hold, free)
    e_c, level = resolve_contamination(bearing, contamination)
    operating = Operating.of(
        bearing,
        speed=speed,
        temperature=temperature,
        rotating=rotating,
        lubricant=lubricant,
        contamination=e_c,
        reliability=reliability,
    )
    _check_lubricant_range(bearing, operating)
    from bearingkit.pipeline.friction.choice import check_inputs

    check_inputs(bearing)
    out = Analysis(
        bearing,
        operating,
        friction_model=friction_model,
        load_ratings=load_ratings,
        friction_options=friction_options,
    )
    out.contamination_level = level
    if thermal is None:
        from bearingkit.pipeline.conditions import _sections

        thermal = _sections(bearing).thermal is not None
    if thermal is False or out.n_cases == 0:  # no load case (a duty cycle alone): nothing to balance
        return out
    if temperature is not None:
        raise InputError(
            f"{bearing.source}: temperature ({temperature!r}) and the heat balance both set the operating "
            "temperature; give one (drop --temperature, or --heat / [thermal])"
        )
    from bearingkit.pipeline.thermal.balance import with_thermal_equilibrium

    return out._in_file(with_thermal_equilibrium, out, thermal if isinstance(thermal, dict) else None)
