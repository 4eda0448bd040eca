"""Lubricant presets: the ISO VG mineral oils and the seeds' lubricants (unchanged, fixed α).

``ISO_VG32`` … ``ISO_VG220``
    Paraffinic mineral oils. ν40 = ISO 3448 grade mid-point. ν100 = typical data-sheet value of a
    VI ≈ 95–100 oil of that grade (ASTM D2270 gives them VI 97–102). α = 2.0e-8 1/Pa at every
    temperature (a documented constant; an oil given by its data gets α(T) from its base oil instead),
    ρ15 = 870 kg/m³, k = 0.13 W/(m·K), volumetric expansion 6.5e-4 1/K (see the constants below).
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

from bearingkit import checks
from bearingkit.lubricants.model import Grease, Lubricant
from bearingkit.lubricants.walther import CST_TO_M2_PER_S, REFERENCE_TEMPERATURE_40_C

N_PER_MM2_INVERSE_TO_PER_PA = 1.0e-6  # [1/Pa per mm²/N] α in mm²/N × 1e-6 = α in 1/Pa

# Typical mineral-oil properties (used by the ISO VG presets).
MINERAL_OIL_PRESSURE_VISCOSITY = 2.0e-8  # [1/Pa] Barus α of paraffinic mineral oils near 40 °C;
#   Stachowiak & Batchelor, Engineering Tribology, Table 2.3: 1.3e-8 … 4.2e-8 1/Pa (30–100 °C).
MINERAL_OIL_DENSITY_15C = 870.0  # [kg/m³] typical paraffinic lubricating oil at 15 °C (860–890)
MINERAL_OIL_THERMAL_EXPANSION = 6.5e-4  # [1/K] volumetric expansion of lube oils, ASTM D1250 / ISO 91
#   tables give 6.3e-4 … 7.0e-4 1/K for ρ15 = 850–900 kg/m³; valid roughly −20 … 150 °C.
MINERAL_OIL_THERMAL_CONDUCTIVITY = 0.13  # [W/(m·K)] mineral oils 0.12–0.15 near 40 °C

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

#: Citation keys (bearingkit.references) of the sources this package uses.
REFERENCE_KEYS = ("astm_d341", "walther1931", "iso3448", "gb443", "zheng2022", "stachowiak_batchelor")


def _iso_vg(grade: int) -> Lubricant:
    return Lubricant(
        name=f"ISO_VG{grade}",
        base_oil="mineral",
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
    base_oil="mineral",
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
    base_oil="mineral",
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
    base_oil="mineral",
    pressure_viscosity=MINERAL_OIL_PRESSURE_VISCOSITY,
    density_15C=MINERAL_OIL_DENSITY_15C,
    thermal_expansion=MINERAL_OIL_THERMAL_EXPANSION,
    thermal_conductivity=MINERAL_OIL_THERMAL_CONDUCTIVITY,
    kinematic_viscosity_40=100.0 * CST_TO_M2_PER_S,
    kinematic_viscosity_100=ISO_VG_NU100_CST[100] * CST_TO_M2_PER_S,
    grease=Grease(thickener="lithium_complex", nlgi="2", life_class="general_purpose"),
    source="ASSUMED for tian2025 (no lubricant data in the paper): lithium-complex grease, "
    "ISO VG 100 mineral base oil",
)

#: Seed → preset used for it (seed 001 and 002 give no lubricant either; the lead decides those).
SEED_LUBRICANTS: dict[str, str] = {"000": "seed000_grease_assumed", "004": "L-AN"}


def get_lubricant(name: str) -> Lubricant:
    """The preset :class:`Lubricant` called ``name`` (InputError listing the valid names otherwise)."""
    checks.one_of("lubricant", name, LUBRICANTS)
    return LUBRICANTS[name]
