"""Heat: thermal reference speed (ISO 15312 method) and a heat balance giving the operating temperature.

SI units (W, W/K, rad/s; temperatures in °C).

- :func:`thermal_reference_speed`: the speed at which the bearing's friction power under the ISO 15312
  reference conditions (70 °C, 20 °C ambient, an oil of 12 mm²/s at 70 °C for radial bearings, a load of
  5 % of C0) equals the reference heat flow q_r A_r (:mod:`bearingkit.physics.friction.iso15312`). The
  friction comes from one of bearingkit's models (default SKF), not from the standard's f0r/f1r tables,
  which bearingkit does not carry: the result is that model's thermal reference speed.
- :func:`heat_balance`: the temperature T at which the friction power at T equals the heat carried away,
  P(T) = H (T − T_amb), H the bearing's heat dissipation [W/K] (``[operating] heat_dissipation``; default
  the ISO 15312 reference housing, H = q_r A_r / 50 K). The friction power falls with T (the oil thins),
  so the balance is found by bisection; none below 250 °C means thermal runaway (a warning).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from bearingkit.errors import InputError
from bearingkit.physics.friction import iso15312

__all__ = ["HeatBalance", "heat_balance", "reference_surface_of", "thermal_reference_speed"]

#: Highest temperature searched by the heat balance [°C] (the lubricants' law ends at 250 °C).
MAX_TEMPERATURE = 250.0
#: Temperature tolerance of the heat balance [K].
TEMPERATURE_TOL = 0.01


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
            "or [operating] heat_dissipation directly)"
        )
    return iso15312.reference_surface(d, big_d, width, "radial")


def _sibling(analysis, *, temperature=None, speed=None, load=None, lubricant=None):
    """An Analysis of the same bearing at other operating values, sharing the solved statics when the
    loads are the same (friction depends on the temperature only through the lubricant)."""
    op = analysis.operating
    n = op.n_cases
    changes = {}
    if temperature is not None:
        changes.update(temperature=np.broadcast_to(np.asarray(temperature, float), (n,)).copy())
        changes.update(temperature_given=np.ones(n, bool))
    if speed is not None:
        changes.update(speed=np.broadcast_to(np.asarray(speed, float), (n,)).copy())
    if lubricant is not None:
        changes.update(lubricant=lubricant)
    bearing = analysis.input if load is None else analysis.input.with_cases(load)
    sib = type(analysis)(
        bearing,
        dataclasses.replace(op, **changes),
        friction_model=analysis.friction_model,
        friction_options=analysis.friction_options,
    )
    if load is None and speed is None:
        sib.__dict__["setup"] = analysis.setup
        sib.__dict__["statics"] = analysis.statics
    return sib


def _reference_case(analysis):
    """The ISO 15312 reference load: a radial load of 5 % of the bearing's ISO 76 C0."""
    from bearingkit.analysis.solver.quasistatic import load_vector
    from bearingkit.io.loader import LoadCase

    rating = analysis.rating
    if rating is None:
        raise InputError(
            "heat: the thermal reference speed needs the bearing's C0 (the ratings did not apply)"
        )
    c0 = sum(float(np.ma.getdata(r.static_rating)[0]) for r in rating.rows)
    share = iso15312.REFERENCE_LOAD_SHARE["radial"]
    return LoadCase("iso15312_reference", load_vector(F_x=share * c0))


def thermal_reference_speed(analysis, model: str = "skf") -> float:
    """The thermal reference speed [rad/s] of the analysed bearing by friction model ``model``.

    Reference conditions of ISO 15312: radial load 0.05 C0 (the rows' ISO 76 ratings), an oil of
    ν = 12 mm²/s at the bearing temperature (ISO VG 32 at the temperature where its ν is 12 mm²/s).
    """
    from bearingkit.lubricants import get_lubricant

    heat = float(iso15312.reference_heat_flow(reference_surface_of(analysis)))
    case = _reference_case(analysis)
    # The reference oil: ν = 12 mm²/s. ISO VG 32 has it near 70 °C; the friction models see the oil only
    # through ν(T), so it is evaluated at the temperature where its ν is exactly the reference one.
    lube = get_lubricant("ISO_VG32")
    temps = np.linspace(40.0, 100.0, 601)
    nu = lube.kinematic_viscosity(temps)
    t_ref = float(np.interp(-iso15312.REFERENCE_VISCOSITY["radial"], -nu, temps))
    base = _sibling(analysis, temperature=t_ref, load=[case], lubricant=lube)

    def power(omega):
        sib = _sibling(base, speed=omega)
        return float(sib.friction_by(model).power_loss[0])

    return iso15312.thermal_reference_speed(power, heat)


@dataclass
class HeatBalance:
    """Operating temperature from the heat balance, per case.

    Attributes
    ----------
    temperature : ndarray (C,) [°C]
        NaN where the friction power exceeds the heat flow up to 250 °C (runaway).
    power_loss : ndarray (C,) [W]
        Friction power at that temperature.
    dissipation : float [W/K]
    ambient : float [°C]
    model : str
    notes : list of str
    """

    temperature: np.ndarray
    power_loss: np.ndarray
    dissipation: float
    ambient: float
    model: str
    notes: list = field(default_factory=list)

    def to_dict(self, case: int) -> dict:
        t = float(self.temperature[case])
        return {
            "temperature_C": None if np.isnan(t) else t,
            "power_loss_W": float(self.power_loss[case]),
            "heat_dissipation_W_K": self.dissipation,
            "ambient_C": self.ambient,
            "friction_model": self.model,
            "notes": list(self.notes),
        }


def heat_balance(analysis, model: str | None = None, dissipation=None, ambient=None) -> HeatBalance:
    """Operating temperature at which the friction power equals the heat flow (module docstring)."""
    from bearingkit.pipeline.conditions import _sections

    model = model or analysis.friction_model
    spec = _sections(analysis.input).operating
    notes = []
    if ambient is None:
        ambient = (
            iso15312.REFERENCE_AMBIENT_TEMPERATURE
            if spec is None or spec.temperature_ambient is None
            else (spec.temperature_ambient)
        )
    if dissipation is None and spec is not None and spec.heat_dissipation is not None:
        dissipation = spec.heat_dissipation
    if dissipation is None:
        area = reference_surface_of(analysis)
        dissipation = float(iso15312.reference_heat_flow(area)) / (
            iso15312.REFERENCE_BEARING_TEMPERATURE - iso15312.REFERENCE_AMBIENT_TEMPERATURE
        )
        notes.append(
            f"heat dissipation {dissipation:.3g} W/K of the ISO 15312 reference housing (q_r A_r / 50 K); "
            "give "
            "[operating] heat_dissipation for the real housing"
        )
    n = analysis.n_cases

    used = {}

    def excess(temps):
        outcome = _sibling(analysis, temperature=temps).friction_by(model)
        used["model"] = outcome.model  # the default ("auto") resolves to the bearing's model
        p = outcome.power_loss
        return p - dissipation * (temps - ambient), p

    lo = np.full(n, float(ambient) + TEMPERATURE_TOL)
    hi = np.full(n, MAX_TEMPERATURE)
    f_hi, _ = excess(hi)
    runaway = f_hi > 0
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        f_mid, _ = excess(mid)
        lo = np.where(f_mid > 0, mid, lo)
        hi = np.where(f_mid > 0, hi, mid)
        if np.all(hi - lo < TEMPERATURE_TOL):
            break
    temps = 0.5 * (lo + hi)
    _, power = excess(temps)
    temps = np.where(runaway, np.nan, temps)
    if runaway.any():
        notes.append(
            f"no heat balance below {MAX_TEMPERATURE:g} °C in {int(runaway.sum())} case(s): the friction "
            "power "
            "exceeds what the housing carries away (thermal runaway)"
        )
    return HeatBalance(temps, power, float(dissipation), float(ambient), used.get("model", model), notes)
