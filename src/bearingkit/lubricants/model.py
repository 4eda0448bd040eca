"""The lubricant as data: an oil (or a grease by its base oil) and its properties at temperature.

All values are SI inside: kinematic viscosity in m²/s, dynamic viscosity in Pa·s, pressure–viscosity
coefficient in 1/Pa, density in kg/m³, thermal conductivity in W/(m·K), specific heat in J/(kg·K),
temperature coefficients in 1/K. Temperatures are in °C (``temperature_C``).

A :class:`Lubricant` is either

* **Walther-type** — kinematic viscosities at 40 °C and 100 °C are given (ISO 3448 grades, data-sheet
  values, or ν40 and a viscosity index, :mod:`bearingkit.lubricants.viscosity_index`); ν(T) follows ASTM
  D341 (:mod:`bearingkit.lubricants.walther`), ρ(T) a linear thermal expansion, η = ν·ρ; or
* **constant-viscosity** — only a dynamic viscosity η₀ at the operating temperature is known (seed
  004 gives η₀ = 0.04 Pa·s for L-AN oil and nothing else). Then :meth:`Lubricant.viscosity` returns
  η₀ at every temperature (documented: no temperature model is invented), and
  :meth:`Lubricant.kinematic_viscosity` returns η₀/ρ(T), so that η = ν·ρ holds for both kinds.

Pressure–viscosity coefficient: ``pressure_viscosity`` is α at 40 °C; with
``pressure_viscosity_exponent`` t > 0 it follows the viscosity, α(T) = α(40 °C) (η(T)/η(40 °C))^t —
the base-oil law of :mod:`bearingkit.lubricants.base_oils` (an oil built from its data gets its base
oil's t). t = 0 keeps α constant: the presets do (their α is a documented constant the seed
validations rest on).

A grease is its base oil plus a :class:`Grease` (thickener, NLGI consistency class, the grease-life
class and the temperature limits of its data sheet): the EHL film, κ and the viscous friction use the
base oil; the friction models use the grease's lubrication method (SKF K_rs = 6e-8, Palmgren f0 of
grease), the grease-life formula its class.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.lubricants import base_oils
from bearingkit.lubricants.viscosity_index import NU100_MIN_MM2_S, viscosity_index
from bearingkit.lubricants.walther import (
    CST_TO_M2_PER_S,
    KELVIN_OFFSET,
    REFERENCE_TEMPERATURE_40_C,
    REFERENCE_TEMPERATURE_100_C,
    WALTHER_OFFSET_CST,
    check_temperature,
    walther_coefficients,
    walther_kinematic_viscosity,
)

DENSITY_REFERENCE_TEMPERATURE_C = 15.0  # [°C] ISO 91 / ASTM D1250 standard reference temperature
THERMAL_EXPANSION_MAX = 5.0e-3  # [1/K] sanity bound (liquids stay below ~1.5e-3)
#: Largest pressure–viscosity exponent t accepted (the fitted laws have 0.12–0.16).
PRESSURE_VISCOSITY_EXPONENT_MAX = 1.0
#: Thickeners of a grease (the families of grease data sheets).
THICKENERS = (
    "lithium",
    "lithium_complex",
    "calcium",
    "calcium_complex",
    "calcium_sulfonate",
    "sodium",
    "aluminium_complex",
    "barium_complex",
    "polyurea",
    "bentonite",
    "ptfe",
)
#: NLGI consistency classes (worked penetration bands of NLGI / ISO 2137).
NLGI_CLASSES = ("000", "00", "0", "1", "2", "3", "4", "5", "6")
#: Classes of the grease-life formula (:mod:`bearingkit.physics.lubrication.grease_life`).
GREASE_LIFE_CLASSES = ("general_purpose", "wide_range")


@dataclass(frozen=True)
class Grease:
    """What makes a lubricant a grease (its base oil is the :class:`Lubricant`'s oil).

    Parameters
    ----------
    thickener : str
        One of :data:`THICKENERS`.
    nlgi : str
        NLGI consistency class, one of :data:`NLGI_CLASSES` (``"2"``).
    life_class : str
        Class of the grease-life formula: ``"general_purpose"`` or ``"wide_range"``.
    temperature_min_C, temperature_max_C : float or None
        Lower and upper operating-temperature limits of the data sheet [°C]; a found or given
        temperature above the upper one is warned about.
    """

    thickener: str
    nlgi: str = "2"
    life_class: str = "general_purpose"
    temperature_min_C: float | None = None
    temperature_max_C: float | None = None

    def __post_init__(self):
        checks.one_of("thickener", self.thickener, THICKENERS)
        checks.one_of("nlgi", str(self.nlgi), NLGI_CLASSES)
        checks.one_of("life_class", self.life_class, GREASE_LIFE_CLASSES)
        for key in ("temperature_min_C", "temperature_max_C"):
            if getattr(self, key) is not None:
                checks.finite(key, getattr(self, key), "degC")
        low, high = self.temperature_min_C, self.temperature_max_C
        if low is not None and high is not None and not low < high:
            raise InputError(f"temperature_max ({high:g} degC) must be above temperature_min ({low:g} degC)")


@dataclass(frozen=True)
class Lubricant:
    """A lubricating oil, or a grease by its base oil (module docstring).

    Give either both ``kinematic_viscosity_40`` and ``kinematic_viscosity_100`` (Walther-type) or
    ``constant_viscosity`` (constant-viscosity type), never both.

    Parameters
    ----------
    name : str
        Label.
    pressure_viscosity : float
        Barus pressure–viscosity coefficient α at 40 °C [1/Pa], > 0.
    density_15C : float
        Density at 15 °C [kg/m³], > 0.
    thermal_expansion : float
        Volumetric thermal expansion coefficient a [1/K], 0 ≤ a < 5e-3: ρ(T) = ρ15 [1 − a (T − 15)].
    thermal_conductivity : float
        Thermal conductivity k [W/(m·K)], > 0.
    kinematic_viscosity_40, kinematic_viscosity_100 : float or None
        Kinematic viscosities at 40 °C and 100 °C [m²/s], > 0, ν100 < ν40.
    constant_viscosity : float or None
        Dynamic viscosity η₀ [Pa·s], > 0, used at every temperature.
    temperature_viscosity_coefficient : float or None
        β = −d ln η / dT [1/K], > 0, for thermal reduction. If None, a Walther-type lubricant
        computes it from its ν(T) and ρ(T) (:meth:`temperature_coefficient`).
    source : str
        Where the values come from.
    base_oil : str
        ``"mineral"``, ``"pao"``, ``"ester"`` or ``"pag"`` (:data:`bearingkit.lubricants.BASE_OILS`).
    pressure_viscosity_exponent : float
        t of α(T) = α(40 °C) (η(T)/η(40 °C))^t, 0 ≤ t < 1 (0: α constant).
    specific_heat : float
        Specific heat c_p [J/(kg·K)], > 0 (heat carried away by a circulating oil).
    grease : Grease or None
        The thickener and grease data when the lubricant is a grease.
    """

    name: str
    pressure_viscosity: float
    density_15C: float
    thermal_expansion: float
    thermal_conductivity: float
    kinematic_viscosity_40: float | None = None
    kinematic_viscosity_100: float | None = None
    constant_viscosity: float | None = None
    temperature_viscosity_coefficient: float | None = None
    source: str = ""
    base_oil: str = "mineral"
    pressure_viscosity_exponent: float = 0.0
    specific_heat: float = 1900.0
    grease: Grease | None = None

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name:
            raise InputError(f"name ({self.name!r}) must be a non-empty string")
        object.__setattr__(self, "base_oil", base_oils.base_oil_key(self.base_oil))
        if isinstance(self.grease, dict):  # dataclasses.asdict round trip
            object.__setattr__(self, "grease", Grease(**self.grease))
        if self.grease is not None and not isinstance(self.grease, Grease):
            raise InputError(f"grease ({self.grease!r}) must be a Grease or None")
        checks.positive("pressure_viscosity", self.pressure_viscosity, "1/Pa")
        checks.finite("pressure_viscosity_exponent", self.pressure_viscosity_exponent)
        if not 0.0 <= float(self.pressure_viscosity_exponent) < PRESSURE_VISCOSITY_EXPONENT_MAX:
            raise InputError(
                f"pressure_viscosity_exponent ({float(self.pressure_viscosity_exponent):.6g}) must lie in "
                f"[0, {PRESSURE_VISCOSITY_EXPONENT_MAX:g})"
            )
        checks.positive("density_15C", self.density_15C, "kg/m^3")
        checks.finite("thermal_expansion", self.thermal_expansion, "1/K")
        if not (0.0 <= float(self.thermal_expansion) < THERMAL_EXPANSION_MAX):
            raise InputError(
                f"thermal_expansion ({float(self.thermal_expansion):.6g} 1/K) must lie in "
                f"[0, {THERMAL_EXPANSION_MAX:g})"
            )
        checks.positive("thermal_conductivity", self.thermal_conductivity, "W/(m*K)")
        checks.positive("specific_heat", self.specific_heat, "J/(kg*K)")
        has_40 = self.kinematic_viscosity_40 is not None
        has_100 = self.kinematic_viscosity_100 is not None
        has_const = self.constant_viscosity is not None
        if has_40 != has_100:
            missing = "kinematic_viscosity_100" if has_40 else "kinematic_viscosity_40"
            raise InputError(f"{missing} (None) must be given together with the other reference viscosity")
        if has_const == has_40:
            raise InputError(
                f"constant_viscosity ({self.constant_viscosity!r} Pa*s) must be given exactly when "
                "kinematic_viscosity_40/kinematic_viscosity_100 are not"
            )
        if has_40:
            checks.positive("kinematic_viscosity_40", self.kinematic_viscosity_40, "m^2/s")
            checks.positive("kinematic_viscosity_100", self.kinematic_viscosity_100, "m^2/s")
            if not float(self.kinematic_viscosity_100) < float(self.kinematic_viscosity_40):
                raise InputError(
                    f"kinematic_viscosity_100 ({float(self.kinematic_viscosity_100):.6g} m^2/s) must be "
                    f"below kinematic_viscosity_40 ({float(self.kinematic_viscosity_40):.6g} m^2/s)"
                )
        else:
            checks.positive("constant_viscosity", self.constant_viscosity, "Pa*s")
            if self.pressure_viscosity_exponent:
                raise InputError(
                    "pressure_viscosity_exponent must be 0 for a constant-viscosity lubricant (its η, hence "
                    "its α, does not change with temperature)"
                )
        if self.temperature_viscosity_coefficient is not None:
            checks.positive(
                "temperature_viscosity_coefficient", self.temperature_viscosity_coefficient, "1/K"
            )

    # --- kind -------------------------------------------------------------------------------
    @property
    def is_constant_viscosity(self) -> bool:
        """True when only a constant dynamic viscosity is known."""
        return self.constant_viscosity is not None

    @property
    def is_grease(self) -> bool:
        """True for a grease (its fields are its base oil's)."""
        return self.grease is not None

    @property
    def base(self) -> str:
        """``"grease"``, ``"mineral"`` or ``"synthetic"``: the lubrication method and oil class the
        engineering friction models select by (SKF K_rs and μ_EHL, Palmgren f0)."""
        if self.is_grease:
            return "grease"
        return base_oils.ehl_class(self.base_oil)

    @property
    def ehl_class(self) -> str:
        """SKF's μ_EHL class of the (base) oil: ``"mineral"`` or ``"synthetic"``."""
        return base_oils.ehl_class(self.base_oil)

    @property
    def viscosity_index(self) -> float | None:
        """ASTM D2270 viscosity index, None for a constant-viscosity lubricant or ν100 < 2 mm²/s."""
        if self.is_constant_viscosity or self.kinematic_viscosity_100 < NU100_MIN_MM2_S * CST_TO_M2_PER_S:
            return None
        return float(viscosity_index(self.kinematic_viscosity_40, self.kinematic_viscosity_100))

    def walther_constants(self) -> tuple[float, float]:
        """ASTM D341 constants (A, B) through the 40 °C and 100 °C points (InputError if constant-η)."""
        if self.is_constant_viscosity:
            raise InputError(
                f"lubricant ({self.name!r}) has only constant_viscosity; it has no viscosity-temperature law"
            )
        a, b = walther_coefficients(
            REFERENCE_TEMPERATURE_40_C,
            self.kinematic_viscosity_40,
            REFERENCE_TEMPERATURE_100_C,
            self.kinematic_viscosity_100,
        )
        return float(a), float(b)

    # --- properties at temperature ----------------------------------------------------------
    def density(self, temperature_C):
        """Density at temperature [kg/m³].

        .. math:: \\rho(T) = \\rho_{15}\\,[1 - a\\,(T - 15)]

        Parameters
        ----------
        temperature_C : float or array_like
            Temperature [°C], in [−50, 250].

        References
        ----------
        Linearised ASTM D1250 / ISO 91 volume-correction tables (a ≈ 6.5e-4 1/K for lube oils).
        """
        check_temperature(temperature_C)
        dt = np.asarray(temperature_C, dtype=float) - DENSITY_REFERENCE_TEMPERATURE_C
        return self.density_15C * (1.0 - self.thermal_expansion * dt)

    def kinematic_viscosity(self, temperature_C):
        """Kinematic viscosity ν(T) [m²/s].

        Walther-type: ASTM D341 through the 40/100 °C points. Constant-viscosity: η₀/ρ(T).

        Parameters
        ----------
        temperature_C : float or array_like
            Temperature [°C], in [−50, 250].

        References
        ----------
        ASTM D341-09 (2015), the Walther form with Z = ν + 0.7.
        """
        if self.is_constant_viscosity:
            return self.constant_viscosity / self.density(temperature_C)
        a, b = self.walther_constants()
        return walther_kinematic_viscosity(temperature_C, a, b)

    def viscosity(self, temperature_C):
        """Dynamic viscosity η(T) = ν(T)·ρ(T) [Pa·s] at atmospheric pressure.

        Constant-viscosity lubricants return ``constant_viscosity`` at every temperature (broadcast
        to the shape of ``temperature_C``).

        Parameters
        ----------
        temperature_C : float or array_like
            Temperature [°C], in [−50, 250].
        """
        if self.is_constant_viscosity:
            check_temperature(temperature_C)
            return np.full(np.shape(temperature_C), float(self.constant_viscosity))
        return self.kinematic_viscosity(temperature_C) * self.density(temperature_C)

    def pressure_viscosity_at(self, temperature_C):
        """Pressure–viscosity coefficient α(T) [1/Pa].

        .. math:: \\alpha(T) = \\alpha_{40}\\,\\bigl(\\eta(T) / \\eta(40\\,°\\mathrm{C})\\bigr)^{t}

        (t = ``pressure_viscosity_exponent``; the base-oil law of
        :func:`bearingkit.lubricants.base_oils.pressure_viscosity` written about 40 °C).

        Parameters
        ----------
        temperature_C : float or array_like
            Temperature [°C], in [−50, 250].
        """
        t = float(self.pressure_viscosity_exponent)
        if t == 0.0:
            check_temperature(temperature_C)
            return np.full(np.shape(temperature_C), float(self.pressure_viscosity))
        ratio = self.viscosity(temperature_C) / self.viscosity(REFERENCE_TEMPERATURE_40_C)
        return self.pressure_viscosity * ratio**t

    def temperature_coefficient(self, temperature_C):
        """Temperature–viscosity coefficient β = −d ln η / dT [1/K] (for thermal reduction).

        Returns ``temperature_viscosity_coefficient`` when it is given. Otherwise (Walther-type only)
        it is differentiated analytically from ASTM D341 and ρ(T), with
        w = log₁₀(ν + 0.7) = 10^(A − B log₁₀ T):

        .. math::

            \\beta = \\frac{\\nu + 0.7}{\\nu}\\,\\ln 10\\; \\frac{B\\,w}{T}
                   + \\frac{a}{1 - a\\,(T_C - 15)}

        (ν in cSt, T in K).

        Parameters
        ----------
        temperature_C : float or array_like
            Temperature [°C], in [−50, 250].
        """
        if self.temperature_viscosity_coefficient is not None:
            check_temperature(temperature_C)
            return np.full(np.shape(temperature_C), float(self.temperature_viscosity_coefficient))
        a, b = self.walther_constants()
        nu_cst = walther_kinematic_viscosity(temperature_C, a, b) / CST_TO_M2_PER_S
        t_k = np.asarray(temperature_C, dtype=float) + KELVIN_OFFSET
        w = np.log10(nu_cst + WALTHER_OFFSET_CST)
        beta_nu = (nu_cst + WALTHER_OFFSET_CST) / nu_cst * np.log(10.0) * b * w / t_k
        dt = np.asarray(temperature_C, dtype=float) - DENSITY_REFERENCE_TEMPERATURE_C
        beta_rho = self.thermal_expansion / (1.0 - self.thermal_expansion * dt)
        return beta_nu + beta_rho

    # --- faces ------------------------------------------------------------------------------
    def to_dict(self) -> dict:
        """JSON-ready description (SI, units in keys) for every face."""
        vi = self.viscosity_index
        out = {
            "name": self.name,
            "kind": "grease" if self.is_grease else "oil",
            "base_oil": self.base_oil,
            "nu_40_m2_s": self.kinematic_viscosity_40,
            "nu_100_m2_s": self.kinematic_viscosity_100,
            "constant_viscosity_Pa_s": self.constant_viscosity,
            "viscosity_index": None if vi is None else round(vi, 1),
            "density_15C_kg_m3": float(self.density_15C),
            "pressure_viscosity_40_per_Pa": float(self.pressure_viscosity),
            "pressure_viscosity_exponent": float(self.pressure_viscosity_exponent),
            "source": self.source,
        }
        if self.grease is not None:
            out["grease"] = dataclasses.asdict(self.grease)
        return out
