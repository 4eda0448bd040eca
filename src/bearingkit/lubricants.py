"""Lubricants: viscosity–temperature (ASTM D341 / Walther), density, pressure–viscosity, presets.

All values are SI inside: kinematic viscosity in m²/s, dynamic viscosity in Pa·s, pressure–viscosity
coefficient in 1/Pa, density in kg/m³, thermal conductivity in W/(m·K), temperature coefficients in
1/K. Temperatures are in °C (``temperature_C``, the unit the standards and the seeds use); they are
converted to kelvin only inside the Walther law. Only the Walther law works in centistokes
(1 cSt = 1 mm²/s = 1e-6 m²/s), because its offset 0.7 is defined in cSt.

A :class:`Lubricant` is either

* **Walther-type** — kinematic viscosities at 40 °C and 100 °C are given (ISO 3448 grades,
  data-sheet values); ν(T) follows ASTM D341, ρ(T) a linear thermal expansion, η = ν·ρ; or
* **constant-viscosity** — only a dynamic viscosity η₀ at the operating temperature is known (seed
  004 gives η₀ = 0.04 Pa·s for L-AN oil and nothing else). Then :meth:`Lubricant.viscosity` returns
  η₀ at every temperature (documented: no temperature model is invented), and
  :meth:`Lubricant.kinematic_viscosity` returns η₀/ρ(T), so that η = ν·ρ holds for both kinds.

The pressure–viscosity coefficient α (Barus) is a constant of each lubricant: no source the seeds
use gives its temperature dependence, so none is modelled.

Presets (:data:`LUBRICANTS`, :func:`get_lubricant`)
----------------------------------------------------
``ISO_VG32`` … ``ISO_VG220``
    Paraffinic mineral oils. ν40 = ISO 3448 grade mid-point. ν100 = typical data-sheet value of a
    VI ≈ 95–100 oil of that grade (**a documented choice**: bearingkit does not carry the ASTM D2270
    L/H table, so ν100 is not computed from a VI). α = 2.0e-8 1/Pa, ρ15 = 870 kg/m³,
    k = 0.13 W/(m·K), volumetric expansion 6.5e-4 1/K (see the constants below).
``L-AN``
    Seed 004 (Zheng et al. 2022): "lubricating oils for total loss systems L-AN" (GB 443-89),
    α = 0.0246 mm²/N = 2.46e-8 1/Pa and η₀ = 0.04 Pa·s (printed "0.04 MPa•s", an evident unit slip:
    0.04 Pa·s is what an L-AN46 oil has near 40 °C). Constant-viscosity lubricant.
``L-AN46``
    The grade bearingkit takes the seed-004 oil to be (**a choice**: the paper names only the
    family). ISO VG 46 mineral oil (ν40 = 46 cSt, ν100 as ``ISO_VG46``) with the paper's α; its η at
    40 °C is 0.0394 Pa·s, within 2 % of the paper's η₀. Use it to vary temperature.
``seed000_grease_assumed``
    Seed 000 (Tian et al. 2025) gives no lubricant data. **Assumed**: a lithium-complex grease whose
    mineral base oil is ISO VG 100; the base-oil properties (those of ``ISO_VG100``) are what the
    EHL and viscous-friction models use. Not from the paper.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError

# ---------------------------------------------------------------------------------------------
# Constants of the viscosity–temperature law and unit conversions.
# ---------------------------------------------------------------------------------------------
CST_TO_M2_PER_S = 1.0e-6  # [m²/s per cSt] 1 cSt = 1 mm²/s (exact)
KELVIN_OFFSET = 273.15  # [K] T[K] = T[°C] + 273.15 (exact)
WALTHER_OFFSET_CST = 0.7  # [cSt] ASTM D341, Z = ν + 0.7; the simple form holds for ν ≥ 2 cSt
#   (below 2 cSt ASTM D341-09 adds exp(−1.47 − 1.84ν − 0.51ν²) to Z: not modelled).
WALTHER_TEMPERATURE_MIN_C = -50.0  # [°C] lower limit of use of the Walther law in bearingkit
WALTHER_TEMPERATURE_MAX_C = 250.0  # [°C] upper limit (mineral oils decompose/evaporate above this)
REFERENCE_TEMPERATURE_40_C = 40.0  # [°C] ISO 3448 / ASTM D2270 reference temperature
REFERENCE_TEMPERATURE_100_C = 100.0  # [°C] ASTM D2270 reference temperature
DENSITY_REFERENCE_TEMPERATURE_C = 15.0  # [°C] ISO 91 / ASTM D1250 standard reference temperature
N_PER_MM2_INVERSE_TO_PER_PA = 1.0e-6  # [1/Pa per mm²/N] α in mm²/N × 1e-6 = α in 1/Pa

# Typical mineral-oil properties (used by the ISO VG presets).
MINERAL_OIL_PRESSURE_VISCOSITY = 2.0e-8  # [1/Pa] Barus α of paraffinic mineral oils near 40 °C;
#   Stachowiak & Batchelor, Engineering Tribology, Table 2.3: 1.3e-8 … 4.2e-8 1/Pa (30–100 °C).
MINERAL_OIL_DENSITY_15C = 870.0  # [kg/m³] typical paraffinic lubricating oil at 15 °C (860–890)
MINERAL_OIL_THERMAL_EXPANSION = 6.5e-4  # [1/K] volumetric expansion of lube oils, ASTM D1250 / ISO 91
#   tables give 6.3e-4 … 7.0e-4 1/K for ρ15 = 850–900 kg/m³; valid roughly −20 … 150 °C.
MINERAL_OIL_THERMAL_CONDUCTIVITY = 0.13  # [W/(m·K)] mineral oils 0.12–0.15 near 40 °C
THERMAL_EXPANSION_MAX = 5.0e-3  # [1/K] sanity bound (liquids stay below ~1.5e-3)

#: ISO 3448 mid-point kinematic viscosity at 40 °C [cSt] → typical ν at 100 °C [cSt] of a VI ≈ 95–100
#: paraffinic mineral oil (data-sheet values; the grade tolerance at 40 °C is ±10 %).
ISO_VG_NU100_CST: dict[int, float] = {
    32: 5.4,
    46: 6.8,
    68: 8.7,
    100: 11.4,
    150: 14.7,
    220: 19.0,
}

# Seed 004 (Zheng et al. 2022, Machines 10:1051, section 3, ref. [34] = GB 443-89).
SEED004_PRESSURE_VISCOSITY_MM2_PER_N = 0.0246  # [mm²/N]
SEED004_VISCOSITY = 0.04  # [Pa·s] dynamic viscosity at atmospheric pressure (operating temperature)

#: Citation keys (bearingkit.references) of the sources this module uses.
REFERENCE_KEYS = ("astm_d341", "walther1931", "iso3448", "gb443", "zheng2022", "stachowiak_batchelor")

#: Allowed values of :attr:`Lubricant.base`.
LUBRICANT_BASES = ("mineral", "synthetic", "grease")


# ---------------------------------------------------------------------------------------------
# The Walther / ASTM D341 law as pure vectorised functions.
# ---------------------------------------------------------------------------------------------
def _check_temperature(temperature_C, field: str = "temperature_C"):
    return checks.in_range(field, temperature_C, WALTHER_TEMPERATURE_MIN_C, WALTHER_TEMPERATURE_MAX_C, "degC")


def _loglog(kinematic_viscosity):
    nu_cst = np.asarray(kinematic_viscosity, dtype=float) / CST_TO_M2_PER_S
    return np.log10(np.log10(nu_cst + WALTHER_OFFSET_CST))


def walther_coefficients(temperature_1_C, kinematic_viscosity_1, temperature_2_C, kinematic_viscosity_2):
    """Constants A, B of the ASTM D341 (Walther) line through two measured points.

    .. math::

        \\log_{10}\\log_{10}(\\nu + 0.7) = A - B\\,\\log_{10} T

    with ν in cSt (mm²/s) and T in kelvin; hence

    .. math::

        B = \\frac{W_1 - W_2}{\\log_{10}T_2 - \\log_{10}T_1}, \\quad A = W_1 + B\\log_{10}T_1,
        \\quad W_i = \\log_{10}\\log_{10}(\\nu_i + 0.7).

    Parameters
    ----------
    temperature_1_C, temperature_2_C : float or array_like
        Temperatures of the two points [°C], distinct, in [−50, 250].
    kinematic_viscosity_1, kinematic_viscosity_2 : float or array_like
        Kinematic viscosities at those temperatures [m²/s], > 0.

    Returns
    -------
    (A, B) : tuple of float or ndarray
        Walther constants [-] (B > 0 when viscosity falls with temperature).

    References
    ----------
    ASTM D341-09 (2015) Standard practice for viscosity–temperature charts for liquid petroleum
    products (the Walther form with Z = ν + 0.7); Walther C. (1931) Erdöl und Teer 7:382–384.
    """
    _check_temperature(temperature_1_C, "temperature_1_C")
    _check_temperature(temperature_2_C, "temperature_2_C")
    checks.positive("kinematic_viscosity_1", kinematic_viscosity_1, "m^2/s")
    checks.positive("kinematic_viscosity_2", kinematic_viscosity_2, "m^2/s")
    log_t1 = np.log10(np.asarray(temperature_1_C, dtype=float) + KELVIN_OFFSET)
    log_t2 = np.log10(np.asarray(temperature_2_C, dtype=float) + KELVIN_OFFSET)
    if np.any(log_t1 == log_t2):
        raise InputError(
            f"temperature_2_C ({float(np.max(temperature_2_C)):.6g} degC) must differ from temperature_1_C"
        )
    w1 = _loglog(kinematic_viscosity_1)
    w2 = _loglog(kinematic_viscosity_2)
    b = (w1 - w2) / (log_t2 - log_t1)
    a = w1 + b * log_t1
    return a, b


def walther_kinematic_viscosity(temperature_C, a, b):
    """Kinematic viscosity from the ASTM D341 (Walther) constants.

    .. math::

        \\nu = 10^{10^{A - B\\log_{10} T}} - 0.7 \\quad [\\mathrm{cSt}], \\qquad T = T_C + 273.15

    Parameters
    ----------
    temperature_C : float or array_like
        Temperature [°C], in [−50, 250].
    a, b : float or array_like
        Walther constants A, B [-] from :func:`walther_coefficients`.

    Returns
    -------
    ndarray
        Kinematic viscosity ν [m²/s].

    References
    ----------
    ASTM D341-09 (2015), the Walther form with Z = ν + 0.7.
    """
    _check_temperature(temperature_C)
    log_t = np.log10(np.asarray(temperature_C, dtype=float) + KELVIN_OFFSET)
    nu_cst = 10.0 ** (10.0 ** (np.asarray(a) - np.asarray(b) * log_t)) - WALTHER_OFFSET_CST
    return nu_cst * CST_TO_M2_PER_S


# ---------------------------------------------------------------------------------------------
# The data container.
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Lubricant:
    """A lubricating oil (or a grease, described by its base oil).

    Give either both ``kinematic_viscosity_40`` and ``kinematic_viscosity_100`` (Walther-type) or
    ``constant_viscosity`` (constant-viscosity type), never both.

    Parameters
    ----------
    name : str
        Label.
    base : str
        ``"mineral"``, ``"synthetic"`` or ``"grease"`` (a grease's fields are its base oil's).
    pressure_viscosity : float
        Barus pressure–viscosity coefficient α [1/Pa], > 0.
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
    """

    name: str
    base: str
    pressure_viscosity: float
    density_15C: float
    thermal_expansion: float
    thermal_conductivity: float
    kinematic_viscosity_40: float | None = None
    kinematic_viscosity_100: float | None = None
    constant_viscosity: float | None = None
    temperature_viscosity_coefficient: float | None = None
    source: str = ""

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name:
            raise InputError(f"name ({self.name!r}) must be a non-empty string")
        checks.one_of("base", self.base, LUBRICANT_BASES)
        checks.positive("pressure_viscosity", self.pressure_viscosity, "1/Pa")
        checks.positive("density_15C", self.density_15C, "kg/m^3")
        checks.finite("thermal_expansion", self.thermal_expansion, "1/K")
        if not (0.0 <= float(self.thermal_expansion) < THERMAL_EXPANSION_MAX):
            raise InputError(
                f"thermal_expansion ({float(self.thermal_expansion):.6g} 1/K) must lie in "
                f"[0, {THERMAL_EXPANSION_MAX:g})"
            )
        checks.positive("thermal_conductivity", self.thermal_conductivity, "W/(m*K)")
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
        if self.temperature_viscosity_coefficient is not None:
            checks.positive(
                "temperature_viscosity_coefficient", self.temperature_viscosity_coefficient, "1/K"
            )

    # --- kind -------------------------------------------------------------------------------
    @property
    def is_constant_viscosity(self) -> bool:
        """True when only a constant dynamic viscosity is known."""
        return self.constant_viscosity is not None

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
        _check_temperature(temperature_C)
        dt = np.asarray(temperature_C, dtype=float) - DENSITY_REFERENCE_TEMPERATURE_C
        return self.density_15C * (1.0 - self.thermal_expansion * dt)

    def kinematic_viscosity(self, temperature_C):
        """Kinematic viscosity ν(T) [m²/s].

        Walther-type: ASTM D341 through the 40/100 °C points (:func:`walther_kinematic_viscosity`).
        Constant-viscosity: η₀/ρ(T).

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
            _check_temperature(temperature_C)
            return np.full(np.shape(temperature_C), float(self.constant_viscosity))
        return self.kinematic_viscosity(temperature_C) * self.density(temperature_C)

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
            _check_temperature(temperature_C)
            return np.full(np.shape(temperature_C), float(self.temperature_viscosity_coefficient))
        a, b = self.walther_constants()
        nu_cst = walther_kinematic_viscosity(temperature_C, a, b) / CST_TO_M2_PER_S
        t_k = np.asarray(temperature_C, dtype=float) + KELVIN_OFFSET
        w = np.log10(nu_cst + WALTHER_OFFSET_CST)
        beta_nu = (nu_cst + WALTHER_OFFSET_CST) / nu_cst * np.log(10.0) * b * w / t_k
        dt = np.asarray(temperature_C, dtype=float) - DENSITY_REFERENCE_TEMPERATURE_C
        beta_rho = self.thermal_expansion / (1.0 - self.thermal_expansion * dt)
        return beta_nu + beta_rho


# ---------------------------------------------------------------------------------------------
# Presets.
# ---------------------------------------------------------------------------------------------
def _iso_vg(grade: int) -> Lubricant:
    return Lubricant(
        name=f"ISO_VG{grade}",
        base="mineral",
        pressure_viscosity=MINERAL_OIL_PRESSURE_VISCOSITY,
        density_15C=MINERAL_OIL_DENSITY_15C,
        thermal_expansion=MINERAL_OIL_THERMAL_EXPANSION,
        thermal_conductivity=MINERAL_OIL_THERMAL_CONDUCTIVITY,
        kinematic_viscosity_40=grade * CST_TO_M2_PER_S,
        kinematic_viscosity_100=ISO_VG_NU100_CST[grade] * CST_TO_M2_PER_S,
        source=f"ISO 3448 VG {grade} mid-point at 40 degC; "
        "nu100 typical of a VI 95-100 mineral oil (assumed)",
    )


LUBRICANTS: dict[str, Lubricant] = {f"ISO_VG{g}": _iso_vg(g) for g in ISO_VG_NU100_CST}

_SEED004_ALPHA = SEED004_PRESSURE_VISCOSITY_MM2_PER_N * N_PER_MM2_INVERSE_TO_PER_PA
LUBRICANTS["L-AN46"] = Lubricant(
    name="L-AN46",
    base="mineral",
    pressure_viscosity=_SEED004_ALPHA,
    density_15C=MINERAL_OIL_DENSITY_15C,
    thermal_expansion=MINERAL_OIL_THERMAL_EXPANSION,
    thermal_conductivity=MINERAL_OIL_THERMAL_CONDUCTIVITY,
    kinematic_viscosity_40=46.0 * CST_TO_M2_PER_S,
    kinematic_viscosity_100=ISO_VG_NU100_CST[46] * CST_TO_M2_PER_S,
    source="GB 443-89 L-AN46 (grade assumed for zheng2022); alpha from zheng2022; nu100 as ISO_VG46",
)
#: Seed 004's oil: constant η₀ = 0.04 Pa·s; β is that of ``L-AN46`` at 40 °C (assumed).
LUBRICANTS["L-AN"] = Lubricant(
    name="L-AN",
    base="mineral",
    pressure_viscosity=_SEED004_ALPHA,
    density_15C=MINERAL_OIL_DENSITY_15C,
    thermal_expansion=MINERAL_OIL_THERMAL_EXPANSION,
    thermal_conductivity=MINERAL_OIL_THERMAL_CONDUCTIVITY,
    constant_viscosity=SEED004_VISCOSITY,
    temperature_viscosity_coefficient=float(
        LUBRICANTS["L-AN46"].temperature_coefficient(REFERENCE_TEMPERATURE_40_C)
    ),
    source="zheng2022 section 3: L-AN (GB 443-89), alpha 0.0246 mm^2/N, eta0 0.04 Pa*s",
)
LUBRICANTS["seed000_grease_assumed"] = Lubricant(
    name="seed000_grease_assumed",
    base="grease",
    pressure_viscosity=MINERAL_OIL_PRESSURE_VISCOSITY,
    density_15C=MINERAL_OIL_DENSITY_15C,
    thermal_expansion=MINERAL_OIL_THERMAL_EXPANSION,
    thermal_conductivity=MINERAL_OIL_THERMAL_CONDUCTIVITY,
    kinematic_viscosity_40=100.0 * CST_TO_M2_PER_S,
    kinematic_viscosity_100=ISO_VG_NU100_CST[100] * CST_TO_M2_PER_S,
    source="ASSUMED for tian2025 (no lubricant data in the paper): lithium-complex grease, "
    "ISO VG 100 mineral base oil",
)

#: Seed → preset used for it (seed 001 and 002 give no lubricant either; the lead decides those).
SEED_LUBRICANTS: dict[str, str] = {"000": "seed000_grease_assumed", "004": "L-AN"}


def get_lubricant(name: str) -> Lubricant:
    """The preset :class:`Lubricant` called ``name`` (InputError listing the valid names otherwise)."""
    checks.one_of("lubricant", name, LUBRICANTS)
    return LUBRICANTS[name]


def as_lubricant(value) -> Lubricant:
    """Return ``value`` if it is a :class:`Lubricant`, else look it up by name."""
    if isinstance(value, Lubricant):
        return value
    if isinstance(value, str):
        return get_lubricant(value)
    raise InputError(f"lubricant ({value!r}) must be a Lubricant or one of {', '.join(sorted(LUBRICANTS))}")


__all__ = [
    "LUBRICANTS",
    "REFERENCE_KEYS",
    "SEED_LUBRICANTS",
    "Lubricant",
    "as_lubricant",
    "get_lubricant",
    "walther_coefficients",
    "walther_kinematic_viscosity",
]
