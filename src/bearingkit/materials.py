"""Elastic materials of rings and rolling elements, and the two-body elastic constants.

All values are SI: Young's modulus and yield strength in Pa, density in kg/m³, compliance in 1/Pa.
Hardness is a Vickers number HV (kgf/mm², as bearing standards quote it) and is informative only.

This module stores material constants and forms the two combinations every contact law needs,
Kunert/Palmgren's compliance η = (1−ν₁²)/E₁ + (1−ν₂²)/E₂ and Hamrock's reduced modulus E′ = 2/η.
Everything else of Hertz theory lives in :mod:`bearingkit.physics.contact.hertz`.

Presets (:data:`MATERIALS`, looked up with :func:`get_material`)
-----------------------------------------------------------------
``AISI52100``
    Through-hardened bearing steel. E = 29.5×10⁶ psi (203.4 GPa) and ρ = 0.283 lb/in³ (7833 kg/m³)
    as published on the AISI 52100 chrome-steel specification sheet; ν = 0.3 (handbook value; sources
    quote 0.27–0.30).
``GCr15``
    The Chinese (GB/T 18254) counterpart of AISI 52100 / 100Cr6 / SUJ2. E = 208 GPa, ν = 0.3,
    ρ = 7810 kg/m³ — the values of Chinese design handbooks. **Seed 000 (Tian et al. 2025) gives no
    material data; bearingkit uses this preset for it** (a documented choice, not from the paper).
``Si3N4``
    Hot-isostatically-pressed bearing-grade silicon nitride (hybrid-bearing balls): E = 310 GPa,
    ν = 0.26, ρ = 3200 kg/m³ — typical values of bearing-grade material (ASTM F2094 class); Callister
    (2007) Table B.2 lists 304 GPa for sintered/hot-pressed grades.
``seed001_steel``
    Liu et al. (2022), Table 1: E = 2.1×10⁵ N/mm², ν = 0.278 (density not given: 52100's is used).
``seed004_steel``
    Zheng et al. (2022), Table 1: GCr15, E = 212 000 MPa, ν = 0.29 (density not given: GCr15's is used).
``seed002_steel``
    Li et al. (2025) give no E or ν (only "E represents the elastic modulus of the bearing material");
    this alias of ``GCr15`` documents that choice.
``42CrMo4``, ``50CrMo4``
    Quenched-and-tempered slewing-ring steels with induction-hardened raceways: E = 210 GPa, ν = 0.3,
    ρ = 7850 kg/m³ (structural steel handbook values [from memory]) and the hardness profiles
    ``42CrMo4_induction`` / ``50CrMo4_induction`` of :mod:`bearingkit.hardness`.

Every material may carry a :class:`~bearingkit.hardness.HardnessProfile` (``hardness_profile``): the
raceways' hardness against depth, used by the subsurface check (docs/subsurface.md). Without one a ring is
through-hardened at ``hardness_hv`` (700 HV when that is not given either).
"""

from __future__ import annotations

from dataclasses import dataclass

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.hardness import HARDNESS_PRESETS, HardnessProfile

# ---------------------------------------------------------------------------------------------
# Unit conversions used to turn published imperial / engineering values into SI (exact factors).
# ---------------------------------------------------------------------------------------------
PSI_TO_PA = 6894.757293168361  # [Pa/psi] 1 lbf/in² (exact by definition of lbf and inch)
LB_PER_IN3_TO_KG_PER_M3 = 0.45359237 / 0.0254**3  # [kg/m³ per lb/in³] exact (avoirdupois pound, inch)
N_PER_MM2_TO_PA = 1.0e6  # [Pa per N/mm² = MPa]

#: Citation keys (bearingkit.references) of the sources this module uses.
REFERENCE_KEYS = ("liu2022", "zheng2022", "callister2007", "hamrock1983", "kunert1961", "harris2007")

#: Upper bound (exclusive) of Poisson's ratio for a stable isotropic solid.
POISSON_RATIO_MAX = 0.5  # [-] thermodynamic limit (incompressible), never reached by metals/ceramics


@dataclass(frozen=True)
class Material:
    """An isotropic linear-elastic material.

    Parameters
    ----------
    name : str
        Label used in reports.
    youngs_modulus : float
        Young's modulus E [Pa], > 0.
    poisson_ratio : float
        Poisson's ratio ν [-], 0 ≤ ν < 0.5.
    density : float
        Mass density ρ [kg/m³], > 0.
    yield_strength : float or None
        Tensile yield strength [Pa], > 0, optional (informative, used by stress checks).
    hardness_hv : float or None
        Vickers hardness [HV], > 0, optional (informative, ISO 76/281 hardness factors).
    thermal_expansion : float or None
        Linear thermal expansion coefficient α [1/K], ≥ 0, optional (fits and temperatures: operating
        clearance, :mod:`bearingkit.physics.structure.fits`).
    hardness_profile : HardnessProfile, dict of its fields, or None
        The raceways' hardness against depth (case-hardened rings); None: through-hardened.
    source : str
        Where the values come from (citation text or a reference key).
    """

    name: str
    youngs_modulus: float
    poisson_ratio: float
    density: float
    yield_strength: float | None = None
    hardness_hv: float | None = None
    source: str = ""
    thermal_expansion: float | None = None
    hardness_profile: HardnessProfile | None = None

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name:
            raise InputError(f"name ({self.name!r}) must be a non-empty string")
        checks.positive("youngs_modulus", self.youngs_modulus, "Pa")
        checks.finite("poisson_ratio", self.poisson_ratio)
        if not (0.0 <= float(self.poisson_ratio) < POISSON_RATIO_MAX):
            raise InputError(f"poisson_ratio ({float(self.poisson_ratio):.6g}) must lie in [0, 0.5)")
        checks.positive("density", self.density, "kg/m^3")
        if self.yield_strength is not None:
            checks.positive("yield_strength", self.yield_strength, "Pa")
        if self.hardness_hv is not None:
            checks.positive("hardness_hv", self.hardness_hv, "HV")
        if self.thermal_expansion is not None:
            checks.non_negative("thermal_expansion", self.thermal_expansion, "1/K")
        if isinstance(self.hardness_profile, dict):  # dataclasses.asdict of a Material nests it as a dict
            object.__setattr__(self, "hardness_profile", HardnessProfile(**self.hardness_profile))
        if self.hardness_profile is not None and not isinstance(self.hardness_profile, HardnessProfile):
            raise InputError(f"hardness_profile ({self.hardness_profile!r}) must be a HardnessProfile")

    @property
    def raceway_hardness(self) -> HardnessProfile:
        """The raceways' hardness profile: ``hardness_profile``, else through-hardened at ``hardness_hv``."""
        if self.hardness_profile is not None:
            return self.hardness_profile
        base = HARDNESS_PRESETS["through_hardened"]
        if self.hardness_hv is None:
            return base
        name = f"{self.name} (through-hardened)"
        return HardnessProfile(surface_hardness=float(self.hardness_hv), name=name, source=self.source)

    @property
    def plane_strain_compliance(self) -> float:
        """(1 − ν²)/E [1/Pa], this body's share of :func:`elastic_compliance`."""
        return (1.0 - self.poisson_ratio**2) / self.youngs_modulus


def elastic_compliance(m1: Material, m2: Material) -> float:
    """Two-body elastic compliance (Kunert/Palmgren η).

    .. math::

        \\eta = \\frac{1-\\nu_1^2}{E_1} + \\frac{1-\\nu_2^2}{E_2}

    Parameters
    ----------
    m1, m2 : Material
        The two contacting bodies (E [Pa], ν [-]).

    Returns
    -------
    float
        η [1/Pa].

    References
    ----------
    Harris T.A., Kotzalas M.N. (2007) Rolling Bearing Analysis, 5th ed., ch. 6 (Hertz contact);
    Kunert K.H. (1961) Forsch. Ing.-Wes. 27:165-174.
    """
    return m1.plane_strain_compliance + m2.plane_strain_compliance


def e_reduced(m1: Material, m2: Material) -> float:
    """Hamrock's effective (reduced) modulus E′.

    .. math::

        E' = \\frac{2}{(1-\\nu_1^2)/E_1 + (1-\\nu_2^2)/E_2} = \\frac{2}{\\eta}

    For two bodies of the same material this is E/(1−ν²).

    Parameters
    ----------
    m1, m2 : Material
        The two contacting bodies (E [Pa], ν [-]).

    Returns
    -------
    float
        E′ [Pa].

    References
    ----------
    Hamrock B.J., Brewe D. (1983) J. Lubr. Technol. 105(2):171-177, doi:10.1115/1.3254558.
    """
    return 2.0 / elastic_compliance(m1, m2)


# ---------------------------------------------------------------------------------------------
# Preset values (SI). Each constant names its source.
# ---------------------------------------------------------------------------------------------
# AISI 52100 chrome-steel specification sheet: E = 29,500,000 psi, density 0.283 lb/in³, yield
# 295,000 psi, through hardness HRC 60-67. ν = 0.3 is the handbook value (sheets quote 0.27-0.30).
AISI52100_E_PSI = 29.5e6  # [psi]
AISI52100_DENSITY_LB_IN3 = 0.283  # [lb/in³]
AISI52100_YIELD_PSI = 295_000.0  # [psi]
AISI52100_POISSON = 0.3  # [-]
# GCr15 per Chinese mechanical design handbooks (GB/T 18254 steel), quenched and low-tempered.
GCR15_E = 208.0e9  # [Pa]
GCR15_POISSON = 0.3  # [-]
GCR15_DENSITY = 7810.0  # [kg/m³]
GCR15_HARDNESS_HV = 700.0  # [HV] ≈ HRC 60, the lower bound of through-hardened bearing rings (ISO 76/281)
# Bearing-grade silicon nitride (HIP), typical catalogue values for hybrid-bearing balls.
SI3N4_E = 310.0e9  # [Pa] (Callister 2007 Table B.2: 304 GPa for hot-pressed / sintered grades)
SI3N4_POISSON = 0.26  # [-]
SI3N4_DENSITY = 3200.0  # [kg/m³]
SI3N4_HARDNESS_HV = 1550.0  # [HV] typical bearing grade (1400-1700)
# Thermal expansion [1/K]: Carter Bearings, "Coefficient of thermal expansion" table (52100 chrome steel
# 11.9e-6, silicon nitride 2.8e-6 per K). Used for GCr15 (the same grade: 100Cr6 / SUJ2 / 52100).
BEARING_STEEL_THERMAL_EXPANSION = 11.9e-6  # [1/K]
SI3N4_THERMAL_EXPANSION = 2.8e-6  # [1/K]
# Housing and shaft materials (typical handbook values, [from memory]: not confirmed with the search tool).
GREY_CAST_IRON_E, GREY_CAST_IRON_POISSON = 110.0e9, 0.26  # [Pa], [-] EN-GJL-250 range 103-118 GPa
GREY_CAST_IRON_DENSITY, GREY_CAST_IRON_ALPHA = 7200.0, 10.5e-6  # [kg/m³], [1/K]
ALUMINIUM_E, ALUMINIUM_POISSON = 70.0e9, 0.33  # [Pa], [-] wrought/cast Al alloys 68-72 GPa
ALUMINIUM_DENSITY, ALUMINIUM_ALPHA = 2700.0, 23.0e-6  # [kg/m³], [1/K]
STRUCTURAL_STEEL_E, STRUCTURAL_STEEL_POISSON = 210.0e9, 0.3  # [Pa], [-]
STRUCTURAL_STEEL_DENSITY, STRUCTURAL_STEEL_ALPHA = 7850.0, 12.0e-6  # [kg/m³], [1/K]
# Quenched-and-tempered slewing-ring steels (42CrMo4, 50CrMo4): handbook elastic constants [from memory].
QT_STEEL_E, QT_STEEL_POISSON, QT_STEEL_DENSITY = 210.0e9, 0.3, 7850.0  # [Pa], [-], [kg/m³]
# Seed papers.
SEED001_E_N_MM2 = 2.1e5  # [N/mm²] Liu et al. (2022) Lubricants 10:154, Table 1
SEED001_POISSON = 0.278  # [-] same table
SEED004_E_MPA = 212_000.0  # [MPa] Zheng et al. (2022) Machines 10:1051, Table 1 (GCr15)
SEED004_POISSON = 0.29  # [-] same table

_AISI52100 = Material(
    name="AISI52100",
    youngs_modulus=AISI52100_E_PSI * PSI_TO_PA,
    poisson_ratio=AISI52100_POISSON,
    density=AISI52100_DENSITY_LB_IN3 * LB_PER_IN3_TO_KG_PER_M3,
    yield_strength=AISI52100_YIELD_PSI * PSI_TO_PA,
    hardness_hv=GCR15_HARDNESS_HV,
    source="AISI 52100 chrome steel specification sheet (E 29.5e6 psi, 0.283 lb/in^3); nu handbook 0.3",
    thermal_expansion=BEARING_STEEL_THERMAL_EXPANSION,
)
_GCR15 = Material(
    name="GCr15",
    youngs_modulus=GCR15_E,
    poisson_ratio=GCR15_POISSON,
    density=GCR15_DENSITY,
    hardness_hv=GCR15_HARDNESS_HV,
    source="GCr15 (GB/T 18254), Chinese design-handbook values; bearingkit default for seed 000/002",
    thermal_expansion=BEARING_STEEL_THERMAL_EXPANSION,
)

MATERIALS: dict[str, Material] = {
    "AISI52100": _AISI52100,
    "GCr15": _GCR15,
    "Si3N4": Material(
        name="Si3N4",
        youngs_modulus=SI3N4_E,
        poisson_ratio=SI3N4_POISSON,
        density=SI3N4_DENSITY,
        hardness_hv=SI3N4_HARDNESS_HV,
        source="bearing-grade HIP silicon nitride, typical catalogue values (ASTM F2094 class)",
        thermal_expansion=SI3N4_THERMAL_EXPANSION,
    ),
    "grey_cast_iron": Material(
        name="grey_cast_iron",
        youngs_modulus=GREY_CAST_IRON_E,
        poisson_ratio=GREY_CAST_IRON_POISSON,
        density=GREY_CAST_IRON_DENSITY,
        source="EN-GJL-250 grey cast iron, typical handbook values (housings) [from memory]",
        thermal_expansion=GREY_CAST_IRON_ALPHA,
    ),
    "aluminium_alloy": Material(
        name="aluminium_alloy",
        youngs_modulus=ALUMINIUM_E,
        poisson_ratio=ALUMINIUM_POISSON,
        density=ALUMINIUM_DENSITY,
        source="aluminium alloy, typical handbook values (light housings) [from memory]",
        thermal_expansion=ALUMINIUM_ALPHA,
    ),
    "structural_steel": Material(
        name="structural_steel",
        youngs_modulus=STRUCTURAL_STEEL_E,
        poisson_ratio=STRUCTURAL_STEEL_POISSON,
        density=STRUCTURAL_STEEL_DENSITY,
        source="unalloyed structural / shaft steel, typical handbook values [from memory]",
        thermal_expansion=STRUCTURAL_STEEL_ALPHA,
    ),
    "42CrMo4": Material(
        name="42CrMo4",
        youngs_modulus=QT_STEEL_E,
        poisson_ratio=QT_STEEL_POISSON,
        density=QT_STEEL_DENSITY,
        hardness_hv=HARDNESS_PRESETS["42CrMo4_induction"].surface_hardness,
        source="42CrMo4+QT slewing-ring steel, handbook E/nu/rho [from memory]; induction-hardened raceways",
        thermal_expansion=STRUCTURAL_STEEL_ALPHA,
        hardness_profile=HARDNESS_PRESETS["42CrMo4_induction"],
    ),
    "50CrMo4": Material(
        name="50CrMo4",
        youngs_modulus=QT_STEEL_E,
        poisson_ratio=QT_STEEL_POISSON,
        density=QT_STEEL_DENSITY,
        hardness_hv=HARDNESS_PRESETS["50CrMo4_induction"].surface_hardness,
        source="50CrMo4+QT slewing-ring steel, handbook E/nu/rho [from memory]; induction-hardened raceways",
        thermal_expansion=STRUCTURAL_STEEL_ALPHA,
        hardness_profile=HARDNESS_PRESETS["50CrMo4_induction"],
    ),
    "seed001_steel": Material(
        name="seed001_steel",
        youngs_modulus=SEED001_E_N_MM2 * N_PER_MM2_TO_PA,
        poisson_ratio=SEED001_POISSON,
        density=_AISI52100.density,
        source="liu2022 Table 1 (E, nu); density of AISI52100 (not given)",
    ),
    "seed002_steel": _GCR15,
    "seed004_steel": Material(
        name="seed004_steel",
        youngs_modulus=SEED004_E_MPA * N_PER_MM2_TO_PA,
        poisson_ratio=SEED004_POISSON,
        density=GCR15_DENSITY,
        hardness_hv=GCR15_HARDNESS_HV,
        source="zheng2022 Table 1 (GCr15: E, nu); density of GCr15 (not given)",
    ),
}
#: Seed 000 (Tian et al. 2025) gives no material constants; this preset is used for it.
SEED000_MATERIAL = "GCr15"


def get_material(name: str) -> Material:
    """The preset :class:`Material` called ``name`` (InputError listing the valid names otherwise)."""
    checks.one_of("material", name, MATERIALS)
    return MATERIALS[name]


def as_material(value) -> Material:
    """Return ``value`` if it is a :class:`Material`, else look it up by name."""
    if isinstance(value, Material):
        return value
    if isinstance(value, str):
        return get_material(value)
    raise InputError(f"material ({value!r}) must be a Material or one of {', '.join(sorted(MATERIALS))}")


__all__ = [
    "MATERIALS",
    "REFERENCE_KEYS",
    "SEED000_MATERIAL",
    "Material",
    "as_material",
    "e_reduced",
    "elastic_compliance",
    "get_material",
]
