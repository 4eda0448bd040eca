"""Heat: thermal reference speed (ISO 15312 method) and a heat balance giving the operating temperature.

SI units (W, W/K, rad/s; temperatures in °C).

- :func:`thermal_reference_speed`: the speed at which the bearing's friction power under the ISO 15312
  reference conditions (70 °C, 20 °C ambient, an oil of 12 mm²/s at 70 °C for radial bearings, a load of
  5 % of C0) equals the reference heat flow q_r A_r (:mod:`bearingkit.physics.friction.iso15312`). The
  friction comes from one of bearingkit's models (default SKF), not from the standard's f0r/f1r tables,
  which bearingkit does not carry: the result is that model's thermal reference speed.
- :func:`heat_balance`: the temperature T at which the friction power at T equals the heat carried away
  — the balance of :mod:`bearingkit.pipeline.thermal.balance` (seats/housing and circulating oil,
  safeguarded secant over all cases, closed to 1e-6 of the heat), returned in the compact form of
  ``friction --heat``; none below 250 °C means thermal runaway (NaN and a note).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from bearingkit.errors import InputError
from bearingkit.physics.friction import iso15312
from bearingkit.pipeline.thermal.balance import reference_surface_of

__all__ = ["HeatBalance", "heat_balance", "reference_surface_of", "thermal_reference_speed"]

#: Highest temperature searched by the heat balance [°C] (the lubricants' law ends at 250 °C).
MAX_TEMPERATURE = 250.0


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
    thermal: object = None

    @classmethod
    def of(cls, equilibrium) -> HeatBalance:
        """The compact form of a :class:`~bearingkit.pipeline.thermal.balance.ThermalEquilibrium`."""
        s = equilibrium.settings
        return cls(
            np.asarray(equilibrium.temperature, float),
            np.asarray(equilibrium.friction_heat, float),
            s.conductance,
            s.ambient,
            equilibrium.model,
            [],  # the Analysis's notes carry the balance's
            equilibrium,
        )

    def to_dict(self, case: int) -> dict:
        t = float(self.temperature[case])
        out = {
            "temperature_C": None if np.isnan(t) else t,
            "power_loss_W": float(self.power_loss[case]),
            "heat_dissipation_W_K": self.dissipation,
            "ambient_C": self.ambient,
            "friction_model": self.model,
            "notes": list(self.notes),
        }
        if self.thermal is not None:
            out["balance"] = self.thermal.to_dict(case)
        return out


def heat_balance(analysis, model: str | None = None, dissipation=None, ambient=None) -> HeatBalance:
    """Operating temperature at which the friction power equals the heat flow (module docstring).

    Parameters
    ----------
    analysis : Analysis
    model : str, optional
        Friction model (default the analysis's).
    dissipation : float [W/K], optional
        Heat flow through seats and housing per kelvin (default: ``[thermal]``/``[operating]`` of the
        file, else the ISO 15312 reference housing).
    ambient : float [°C], optional

    Returns
    -------
    HeatBalance
        NaN temperatures and a "runaway" note when some case has no balance below 250 °C.
    """
    from bearingkit.pipeline.thermal.balance import (
        ThermalRunaway,
        thermal_settings,
        with_thermal_equilibrium,
    )

    model = model or analysis.friction_model
    start = _sibling(analysis)
    start.friction_model = model
    given = {
        k: float(v) for k, v in (("heat_dissipation", dissipation), ("ambient", ambient)) if v is not None
    }
    try:
        return HeatBalance.of(with_thermal_equilibrium(start, given).thermal)
    except ThermalRunaway as exc:
        s = thermal_settings(start, given)
        n = analysis.n_cases
        return HeatBalance(
            np.full(n, np.nan),
            np.full(n, np.nan),
            s.conductance,
            s.ambient,
            model,
            [f"no heat balance below {MAX_TEMPERATURE:g} °C (thermal runaway): {exc}"],
        )
