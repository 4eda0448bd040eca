"""Thermal equilibrium: the operating temperature found by a heat balance and fed to everything else.

SI units (W, W/K, m³/s; temperatures in °C). With a ``[thermal]`` section (or ``--heat``, or
``analyze(thermal=…)``) the operating temperature of every load case is not an input: it is the
temperature T at which the friction heat equals the heat carried away,

.. math::

    P(T) = H\\,(T - T_{amb}) + \\rho\\,c_p\\,\\dot V\\,(T - T_{in})

(:mod:`bearingkit.physics.heat.dissipation`: the form of DIN 732, the heat balance of a single rolling
bearing whose reference state is ISO 15312's; ISO/TR 14179-1/-2 balance whole gear units — housing
surface, gears, churning — and enter only through the housing term H = k·A). P(T) is the friction
power of the Analysis's friction model (the pipeline's registry, :data:`~bearingkit.pipeline.friction.models.
FRICTION_MODELS`) at T: the oil's viscosity (and its pressure–viscosity coefficient) at T, and the
statics at T where the operating clearance depends on it (fits and thermal growth,
:mod:`bearingkit.pipeline.conditions`). The root is found for all cases at once by a safeguarded secant
(Newton) iteration (:func:`bearingkit.physics.heat.root.solve_decreasing`) until the balance closes
to :data:`BALANCE_RTOL` of the friction heat. The Analysis returned is the one at the found
temperature: its viscosity, κ, a_ISO, friction and operating clearance are those at T, and it carries
the balance (:attr:`Analysis.thermal`) that every face shows.

No temperature below :data:`MAX_TEMPERATURE` (the end of the lubricants' viscosity law) balances the
heat: one line with the last temperature and the remedy (:class:`ThermalRunaway`).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from bearingkit.errors import InputError
from bearingkit.physics.friction import iso15312
from bearingkit.physics.heat import dissipation, root

__all__ = [
    "BALANCE_RTOL",
    "MAX_TEMPERATURE",
    "ThermalEquilibrium",
    "ThermalRunaway",
    "ThermalSettings",
    "at_heat_balance",
    "heat_balance_wanted",
    "reference_surface_of",
    "thermal_settings",
    "with_thermal_equilibria",
    "with_thermal_equilibrium",
]

#: Highest temperature searched [°C] (the lubricants' viscosity–temperature law ends at 250 °C).
MAX_TEMPERATURE = 250.0
#: The balance is closed when |P − Φ| ≤ this share of the friction heat P.
BALANCE_RTOL = 1.0e-6
#: Evaluations of the friction at most (the secant converges in 4–8 on smooth friction laws).
MAX_ITERATIONS = 60
#: What the faces call the method.
METHOD = "heat balance of the bearing (DIN 732 form: seats/housing + circulating oil)"


class ThermalRunaway(InputError):
    """No operating temperature balances the heat: the friction heat exceeds what can be carried away."""


@dataclass(frozen=True)
class ThermalSettings:
    """The heat sinks of the balance (SI, °C).

    Attributes
    ----------
    ambient : float [°C]
    conductance : float [W/K]
        H: heat flow through the seats and housing per kelvin above ambient.
    conductance_from : str
        How H was obtained (given, housing surface, ISO 15312 reference housing).
    oil_flow : float [m³/s]
        Circulating oil (0: none).
    oil_inlet : float [°C]
    """

    ambient: float
    conductance: float
    conductance_from: str
    oil_flow: float = 0.0
    oil_inlet: float = 20.0

    def to_dict(self) -> dict:
        return {
            "ambient_C": self.ambient,
            "heat_dissipation_W_K": self.conductance,
            "heat_dissipation_from": self.conductance_from,
            "oil_flow_m3_s": self.oil_flow,
            "oil_inlet_C": self.oil_inlet,
        }


def _width(analysis) -> float | None:
    """B of the file's geometry, else of its catalogue row (its designation's, or the row with the same
    d and D: :func:`bearingkit.pipeline.bearing_facts.bearing_facts`)."""
    from bearingkit.pipeline.bearing_facts import bearing_facts

    return bearing_facts(analysis.input).width


def reference_surface_of(analysis) -> float:
    """ISO 15312 reference surface A_r [m²] of the analysed bearing (needs d, D and, radial, B)."""
    geometry = analysis.input.geometry.model_dump()
    d, big_d = geometry.get("bore"), geometry.get("outer_diameter")
    if d is None or big_d is None:
        raise InputError("heat: the bearing's bore and outer_diameter are needed (give them in [geometry])")
    thrust = all(
        (r.kind == "ball" and abs(float(np.max(r.contact_angle))) > np.radians(60))
        or (r.kind == "cylindrical" and r.direction != 0)
        for r in analysis.input.model.rows
    )
    if thrust:
        return iso15312.reference_surface(d, big_d, kind="thrust")
    width = _width(analysis)
    if width is None:
        raise InputError(
            "heat: the bearing width B is needed for the ISO 15312 reference surface (give a designation, "
            "[geometry] width, or [thermal] heat_dissipation directly)"
        )
    return iso15312.reference_surface(d, big_d, width, "radial")


def thermal_settings(analysis, given=None) -> ThermalSettings:
    """The heat sinks from ``given`` (fields of ``[thermal]``, text with units or SI), else the file's
    ``[thermal]``, else the legacy ``[operating] temperature_ambient / heat_dissipation``, else the ISO
    15312 reference (20 °C ambient, H = q_r A_r / 50 K)."""
    from bearingkit.io.optional_sections.operating import ThermalSpec
    from bearingkit.pipeline.conditions import _sections

    sections = _sections(analysis.input)
    spec = sections.thermal
    if isinstance(given, dict) and given:
        values = {} if spec is None else spec.model_dump(exclude_none=True)
        values.update({k: v for k, v in given.items() if v is not None})
        try:
            spec = ThermalSpec.model_validate(
                {
                    k: (f"{v!r} {_SI[k]}" if isinstance(v, float) and k in _SI else v)
                    for k, v in values.items()
                }
            )
        except Exception as exc:  # pydantic's error: one line naming the field
            raise InputError(f"thermal: {_first_error(exc)}") from None
    op = sections.operating
    ambient = None if spec is None else spec.ambient
    if ambient is None and op is not None:
        ambient = op.temperature_ambient
    ambient = iso15312.REFERENCE_AMBIENT_TEMPERATURE if ambient is None else float(ambient)
    h, how = None, ""
    if spec is not None:
        area, k = spec.housing_area, spec.heat_transfer_coefficient
        if spec.heat_dissipation is not None and (area is not None or k is not None):
            raise InputError(
                "thermal: give heat_dissipation or housing_area with heat_transfer_coefficient, not both"
            )
        if (area is None) != (k is None):
            missing = "heat_transfer_coefficient" if k is None else "housing_area"
            raise InputError(
                f"thermal.{missing}: missing; housing_area and heat_transfer_coefficient go together"
            )
        if spec.heat_dissipation is not None:
            h, how = float(spec.heat_dissipation), "given"
        elif area is not None:
            h = float(dissipation.conductance_of_surface(area, k))
            how = f"housing surface {area:.4g} m² × {k:.4g} W/(m²·K)"
    if h is None and op is not None and op.heat_dissipation is not None:
        h, how = float(op.heat_dissipation), "given ([operating] heat_dissipation)"
    if h is None:
        area = reference_surface_of(analysis)
        h = float(iso15312.reference_heat_flow(area)) / (
            iso15312.REFERENCE_BEARING_TEMPERATURE - iso15312.REFERENCE_AMBIENT_TEMPERATURE
        )
        how = "ISO 15312 reference housing (q_r A_r / 50 K); give [thermal] heat_dissipation for the real one"
    flow = 0.0 if spec is None or spec.oil_flow is None else float(spec.oil_flow)
    inlet = (
        ambient if spec is None or spec.oil_inlet_temperature is None else float(spec.oil_inlet_temperature)
    )
    lube = analysis.operating.lubricant
    if flow > 0 and lube is not None and lube.is_grease:
        raise InputError(f"thermal.oil_flow ({flow:.4g} m^3/s): the lubricant {lube.name!r} is a grease")
    return ThermalSettings(ambient, h, how, flow, inlet)


#: SI unit of each [thermal] field (a float given in code is taken as SI).
_SI = {
    "ambient": "degC",
    "heat_dissipation": "W/K",
    "housing_area": "m^2",
    "heat_transfer_coefficient": "W/(m^2*K)",
    "oil_flow": "m^3/s",
    "oil_inlet_temperature": "degC",
}


def _first_error(exc) -> str:
    errors = getattr(exc, "errors", None)
    if callable(errors):
        err = errors()[0]
        where = ".".join(str(p) for p in err.get("loc", ()))
        ctx = err.get("ctx", {}).get("error")
        return f"{where}: {ctx or err.get('msg')}"
    return str(exc)


@dataclass
class ThermalEquilibrium:
    """The heat balance at the found temperature, per case (arrays (C,)).

    Attributes
    ----------
    temperature : ndarray [°C]
        Found operating temperature.
    friction_heat : ndarray [W]
        P(T), the friction power of ``model``.
    conducted, oil : ndarray [W]
        Heat through the seats and housing, and carried away by the oil.
    iterations : ndarray of int
        Friction evaluations of the secant iteration.
    settings : ThermalSettings
    model : str
        Friction model that gave P(T).
    notes : list of str
    """

    temperature: np.ndarray
    friction_heat: np.ndarray
    conducted: np.ndarray
    oil: np.ndarray
    iterations: np.ndarray
    settings: ThermalSettings
    model: str
    notes: list = field(default_factory=list)

    @property
    def residual(self) -> np.ndarray:
        """P − Φ [W] at the found temperature (≤ BALANCE_RTOL · P)."""
        return self.friction_heat - self.conducted - self.oil

    def to_dict(self, case: int) -> dict:
        """JSON-ready balance of one case (SI, units in keys)."""
        p = float(self.friction_heat[case])
        return {
            "found": True,
            "method": METHOD,
            "temperature_C": float(self.temperature[case]),
            "friction_heat_W": p,
            "conducted_heat_W": float(self.conducted[case]),
            "oil_heat_W": float(self.oil[case]),
            "balance_residual_W": float(self.residual[case]),
            "balance_relative": float(abs(self.residual[case]) / p) if p > 0 else 0.0,
            "iterations": int(self.iterations[case]),
            "friction_model": self.model,
            **self.settings.to_dict(),
            "notes": list(self.notes),
        }

    def summary(self, case: int) -> str:
        """One line for the text faces."""
        d = self.to_dict(case)
        oil = (
            f" + oil {d['oil_heat_W']:.4g} W ({d['oil_flow_m3_s'] * 6e4:.3g} l/min from "
            f"{d['oil_inlet_C']:g} °C)"
            if d["oil_flow_m3_s"] > 0
            else ""
        )
        return (
            f"operating temperature FOUND by the heat balance: {d['temperature_C']:.4g} °C — friction heat "
            f"{d['friction_heat_W']:.4g} W = seats/housing {d['conducted_heat_W']:.4g} W "
            f"({d['heat_dissipation_W_K']:.3g} W/K to {d['ambient_C']:g} °C){oil}; residual "
            f"{d['balance_residual_W']:.2g} W, {d['iterations']} iterations ({d['friction_model']} friction)"
        )


def _at_temperature(analysis, temperature):
    """An Analysis of the same input at per-case temperatures ``temperature`` (°C), sharing the solved
    statics when they do not depend on the temperature (no clearance chain of fits and ring
    temperatures)."""
    n = analysis.n_cases
    op = dataclasses.replace(
        analysis.operating,
        temperature=np.broadcast_to(np.asarray(temperature, float), (n,)).copy(),
        temperature_given=np.ones(n, bool),
    )
    sib = type(analysis)(
        analysis.input,
        op,
        friction_model=analysis.friction_model,
        load_ratings=analysis.load_ratings,
        friction_options=analysis.friction_options,
    )
    sib.contamination_level = analysis.contamination_level
    if analysis.setup.clearance is None:
        sib.__dict__["setup"] = analysis.setup
        sib.__dict__["statics"] = analysis.statics
    return sib


def with_thermal_equilibrium(analysis, given=None):
    """The Analysis of ``analysis``'s input at the temperature its heat balance finds (module docstring).

    Parameters
    ----------
    analysis : Analysis
        Any start (its temperatures are replaced).
    given : dict, optional
        ``[thermal]`` fields overriding the file's (``ambient``, ``heat_dissipation`` …).

    Returns
    -------
    Analysis
        At the found temperatures, with :attr:`~bearingkit.pipeline.Analysis.thermal` set.
    """
    return with_thermal_equilibria([analysis], [given])[0]


def _checked(analysis, given, label):
    """(settings, lubricant) of one analysis of the balance; one line where the balance cannot start."""
    try:
        settings = thermal_settings(analysis, given)
    except InputError as exc:
        raise InputError(f"{label}{exc}") from None
    lube = analysis.operating.lubricant
    if lube is None:
        raise InputError(
            f'{label}heat balance: no lubricant; the friction heat needs one ([lubricant] name = "ISO_VG68" '
            "or its data)"
        )
    if not np.all(analysis.operating.abs_speed > 0):
        i = int(np.flatnonzero(analysis.operating.abs_speed == 0)[0])
        remedy = "give each load case a speed" if label else "give --speed 3000rpm or each case's speed"
        raise InputError(
            f"{label}heat balance: load case {analysis.case_names[i]!r} has no speed; a bearing at rest "
            f"makes no friction heat ({remedy})"
        )
    return settings, lube


def with_thermal_equilibria(analyses, given=None, names=None):
    """Each Analysis of ``analyses`` at the temperature of its own heat balance, all solved at once.

    The bearings of a shaft (or a single bearing: :func:`with_thermal_equilibrium`) each balance their
    own friction heat against their own seats/housing and oil, P_b(T_b) = Φ_b(T_b) per bearing b and
    case (module docstring). The root is found by one batched secant over every (bearing, case) pair
    (:func:`bearingkit.physics.heat.root.solve_decreasing`): every iteration evaluates each bearing's
    friction once, vectorised over its cases at their temperatures. Each pair's iterates depend on that
    pair alone, so a bearing's found temperature is the one its single-bearing balance finds.

    Parameters
    ----------
    analyses : sequence of Analysis
        Bearings at any start temperature (replaced).
    given : sequence of (dict or None), optional
        ``[thermal]`` fields per analysis overriding its file's (None: the file's).
    names : sequence of str, optional
        Bearing names for the messages (a refusal names its bearing).

    Returns
    -------
    list of Analysis
        At the found temperatures, each with its :attr:`~bearingkit.pipeline.Analysis.thermal`.
    """
    analyses = list(analyses)
    given = [None] * len(analyses) if given is None else list(given)
    labels = [""] * len(analyses) if names is None else [f"bearing {n!r}: " for n in names]
    prepared = [_checked(a, g, label) for a, g, label in zip(analyses, given, labels, strict=True)]
    sizes = [a.n_cases for a in analyses]
    cuts = np.cumsum([0, *sizes])
    parts = [slice(int(cuts[b]), int(cuts[b + 1])) for b in range(len(analyses))]
    last = [{} for _ in analyses]

    def balance(temperature):
        gap, heat = np.empty(cuts[-1]), np.empty(cuts[-1])
        for b, (a, (settings, lube)) in enumerate(zip(analyses, prepared, strict=True)):
            t = temperature[parts[b]]
            sib = _at_temperature(a, t)
            try:
                outcome = sib.friction_by(a.friction_model)
            except InputError as exc:
                raise InputError(
                    f"{labels[b]}heat balance: friction ({a.friction_model}) not computed: {exc}"
                ) from None
            p = np.asarray(outcome.power_loss, dtype=float)
            out = dissipation.conducted_heat(settings.conductance, t, settings.ambient)
            oil = dissipation.oil_heat(
                settings.oil_flow, lube.density(t), lube.specific_heat, t, settings.oil_inlet
            )
            # "auto" resolves to the model of the bearing's kind
            last[b].update(analysis=sib, power=p, conducted=out, oil=oil, model=outcome.model)
            gap[parts[b]], heat[parts[b]] = p - out - oil, p
        return gap, heat

    lower, slope = [], []
    for (settings, lube), n in zip(prepared, sizes, strict=True):
        sink = min(settings.ambient, settings.oil_inlet) if settings.oil_flow > 0 else settings.ambient
        lower.append(np.full(n, sink))
        dphi = settings.conductance + settings.oil_flow * float(lube.density(sink)) * lube.specific_heat
        slope.append(np.full(n, dphi))
    res = root.solve_decreasing(
        balance,
        np.concatenate(lower),
        np.full(int(cuts[-1]), MAX_TEMPERATURE),
        np.concatenate(slope),
        rtol=BALANCE_RTOL,
        max_iterations=MAX_ITERATIONS,
    )
    if not res.converged.all():
        k = int(np.flatnonzero(~res.converged)[0])
        b = int(np.searchsorted(cuts, k, side="right") - 1)
        i = k - int(cuts[b])
        if res.no_root[k]:
            carried = res.scale[k] - res.value[k]
            why = (
                f"no thermal equilibrium below {MAX_TEMPERATURE:g} °C (last temperature {res.x[k]:.4g} °C: "
                f"friction heat {res.scale[k]:.3g} W > {carried:.3g} W carried away)"
            )
        else:
            why = (
                f"the heat balance did not close in {MAX_ITERATIONS} iterations (last temperature "
                f"{res.x[k]:.4g} °C, residual {res.value[k]:.3g} W)"
            )
        raise ThermalRunaway(
            f"{labels[b]}case {analyses[b].case_names[i]!r}: {why}; remedy: more [thermal] heat_dissipation "
            "or oil_flow, a thinner oil, less speed or load"
        )
    found = []
    for b, (a, (settings, _)) in enumerate(zip(analyses, prepared, strict=True)):
        final, n = last[b]["analysis"], sizes[b]
        notes = [
            f"ambient {settings.ambient:g} °C; heat dissipation {settings.conductance:.4g} W/K "
            f"({settings.conductance_from})"
        ]
        if a.setup.clearance is not None:
            notes.append(
                "the operating clearance (fits and thermal growth) was re-solved at every temperature"
            )
        final.thermal = ThermalEquilibrium(
            temperature=np.asarray(res.x[parts[b]], float),
            friction_heat=last[b]["power"],
            conducted=np.asarray(last[b]["conducted"], float),
            oil=np.broadcast_to(np.asarray(last[b]["oil"], float), (n,)).copy(),
            iterations=res.iterations[parts[b]],
            settings=settings,
            model=last[b]["model"],
            notes=notes,
        )
        found.append(final)
    return found


def heat_balance_wanted(thermal, system_input) -> bool:
    """Whether the bearings of a system (a shaft, a drivetrain) find their temperatures: ``thermal``
    (True, False or a dict of ``[thermal]`` fields), else (None) whether the system file has a
    ``[thermal]`` section."""
    if thermal is None:
        return getattr(system_input, "thermal", None) is not None
    return bool(thermal) or isinstance(thermal, dict)


def at_heat_balance(analyses: dict, source: str, thermal=None) -> dict:
    """Every bearing's Analysis (name → Analysis) at the temperature of its own heat balance, all solved in
    one batch (:func:`bearingkit.pipeline.thermal.balance.with_thermal_equilibria`); ``thermal`` a dict of
    ``[thermal]`` fields for every bearing, or not. A refusal is one line naming the file and bearing."""
    given = thermal if isinstance(thermal, dict) else None
    names = list(analyses)
    try:
        found = with_thermal_equilibria(analyses.values(), [given] * len(names), names)
    except InputError as exc:
        raise type(exc)(f"{source}: {exc}") from None
    return dict(zip(names, found, strict=True))
