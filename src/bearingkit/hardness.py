"""Hardness of a raceway below its surface, and the local strength it gives.

SI units (m, Pa); hardness as a Vickers number HV (kgf/mm², as heat-treatment drawings and standards quote
it). A :class:`HardnessProfile` describes a ring: surface hardness, effective case depth, core hardness,
or through-hardened (the default of every bearing: the same hardness at every depth).

Case depth
----------
The effective case depth is the depth at which the hardness has fallen to a limit hardness
(:data:`CASE_DEPTH_DEFINITIONS`):

- ``"SHD"`` — surface hardening depth of flame- or induction-hardened parts (ISO 3754, now ISO 18203):
  limit hardness 0.8 × the (minimum) surface hardness [from memory: the factor 0.8 was not confirmed
  against a stored copy of the standard]; the usual definition for slewing-ring raceways;
- ``"CHD"`` — case hardening depth of carburized parts (ISO 2639, now ISO 18203): limit hardness 550 HV1.

A ``limit_hardness`` given explicitly replaces either.

Profile shape
-------------
No standard prescribes the shape of a hardness traverse. bearingkit uses a plateau of the surface
hardness, then a linear fall to the core hardness over a transition of width w = ``transition_width`` ×
case depth (default :data:`TRANSITION_WIDTH`), placed so that the hardness at the case depth equals the
limit hardness:

.. math:: HV(z) = HV_s - (HV_s - HV_c)\\,\\mathrm{clip}\\!\\left(\\frac{z - z_a}{w}, 0, 1\\right),\\quad
          z_a = d_c - w\\,\\frac{HV_s - HV_{lim}}{HV_s - HV_c}

Strength from hardness
----------------------
:data:`STRENGTH_MODELS` (the yield strength the case check compares the von Mises stress with):

- ``"pavlina2008"`` (default) — Pavlina & Van Tyne (2008), J. Mater. Eng. Perform. 17:888-893, Table 1,
  150+ non-austenitic steels: σ_y = −90.7 + 2.876 HV [MPa] (R² 0.92, standard error 102 MPa), fitted on
  HV 129–632; above 632 HV (hardened surfaces) it is extrapolated;
- ``"tabor"`` — Tabor's constraint factor, H ≈ 3 σ_y with H in MPa (Tabor 1951): σ_y = 9.80665 HV / 3
  [MPa], the flow stress at ~8 % strain: an upper estimate (≈ 10 % above SAE J413's yield values at
  40–52 HRC).

The tensile strength R_m = −99.8 + 3.734 HV [MPa] (Pavlina & Van Tyne 2008, HV 129–592) is reported too.
Rockwell C converts to Vickers by HV = (223 HRC + 14500) / (100 − HRC) (Schlecht 2010, as used by
MESYS), valid 20–68 HRC.

Static limit
------------
ISO 76's limit pressures (4200 MPa ball, 4000 MPa roller, 4600 MPa self-aligning ball) hold for raceways
of at least 58 HRC. A softer surface lowers them: bearingkit scales the limit with the surface's yield
strength, f = σ_y(HV_s) / σ_y(HV at 58 HRC) ≤ 1 (an assumption: the onset of plastic flow is
proportional to the yield strength; Harris et al. 2009 (NREL DG03) give a hardness factor for < 58 HRC that
could not be confirmed). ``static_limit_factor`` given explicitly replaces it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from bearingkit import checks, references
from bearingkit.errors import InputError

__all__ = [
    "CASE_DEPTH_DEFINITIONS",
    "HARDNESS_PRESETS",
    "HARDNESS_RANGE_HV",
    "REFERENCE_KEYS",
    "STRENGTH_MODELS",
    "TRANSITION_WIDTH",
    "HardnessProfile",
    "get_hardness",
    "hrc_to_hv",
    "hv_to_hrc",
    "tensile_strength",
    "yield_strength",
]

references.add(
    "pavlina2008",
    "Pavlina E.J., Van Tyne C.J. (2008) Correlation of yield strength and tensile strength with hardness "
    "for steels. J. Mater. Eng. Perform. 17:888-893, doi:10.1007/s11665-008-9225-5.",
)
references.add("tabor1951", "Tabor D. (1951) The Hardness of Metals. Oxford: Clarendon Press.")
references.add("schlecht2010", "Schlecht B. (2010) Maschinenelemente 2. Pearson Studium (HRC-HV conversion).")
references.add(
    "iso18203",
    "ISO 18203:2016 Steel - Determination of the thickness of surface-hardened layers (replaces ISO 2639, "
    "ISO 3754, ISO 4970).",
)
references.add(
    "harris2009dg03",
    "Harris T.A., Rumbarger J.H., Butterfield C.P. (2009) Wind turbine design guideline DG03: yaw and "
    "pitch rolling bearing life. NREL/TP-500-42362.",
)

#: Keys of :data:`bearingkit.references.REFERENCES` this module uses.
REFERENCE_KEYS = ("pavlina2008", "tabor1951", "schlecht2010", "iso18203", "harris2009dg03")

MPA = 1.0e6
#: Standard gravity [m/s²]: 1 kgf/mm² = 9.80665 MPa (Vickers numbers are kgf/mm²).
KGF_MM2_TO_MPA = 9.80665
#: Hardness numbers an input may give [HV]: below 100 HV no steel ring, above 1000 HV no steel at all
#: (ceramic balls reach 1500 HV but have no case). A value outside is a typo.
HARDNESS_RANGE_HV = (100.0, 1000.0)
#: Rockwell C range of the HRC → HV conversion [HRC] (Schlecht 2010).
HRC_RANGE = (20.0, 68.0)
#: Pavlina & Van Tyne (2008) Table 1 "all data": yield σ_y = a + b HV [MPa], fitted on HV 129–632.
PAVLINA_YIELD = (-90.7, 2.876)
PAVLINA_YIELD_RANGE_HV = (129.0, 632.0)
#: Same source, tensile strength R_m = a + b HV [MPa], fitted on HV 129–592.
PAVLINA_TENSILE = (-99.8, 3.734)
#: Tabor's constraint factor H/σ_y [-] (Tabor 1951; ≈ 3 for metals that do not strain-harden much).
TABOR_CONSTRAINT = 3.0
#: Transition width over the effective case depth [-]: the hardness falls from the surface to the core value
#: over w = 0.5 d_c. Assumption (no standard gives the shape); induction-hardened traverses fall within
#: roughly 0.3–0.6 d_c. Valid (0, 1]; a measured traverse should replace it when known.
TRANSITION_WIDTH = 0.5
#: Rockwell C hardness of the surfaces ISO 76 / ISO 281 assume [HRC] (the static limit's reference).
ISO76_HARDNESS_HRC = 58.0


def hrc_to_hv(hrc):
    """Vickers hardness [HV] of a Rockwell C number: HV = (223 HRC + 14500) / (100 − HRC) (Schlecht 2010).

    Parameters
    ----------
    hrc : array_like
        Rockwell C hardness, 20 … 68.
    """
    checks.in_range("hardness (HRC)", hrc, *HRC_RANGE)
    h = np.asarray(hrc, float)
    return (223.0 * h + 14500.0) / (100.0 - h)


def hv_to_hrc(hv):
    """Inverse of :func:`hrc_to_hv`: HRC = (100 HV − 14500) / (HV + 223)."""
    h = np.asarray(hv, float)
    return (100.0 * h - 14500.0) / (h + 223.0)


def _pavlina(hv):
    a, b = PAVLINA_YIELD
    return (a + b * np.asarray(hv, float)) * MPA


def _tabor(hv):
    return KGF_MM2_TO_MPA * np.asarray(hv, float) / TABOR_CONSTRAINT * MPA


#: Yield strength [Pa] from Vickers hardness, by name (module docstring).
STRENGTH_MODELS: dict[str, Callable] = {"pavlina2008": _pavlina, "tabor": _tabor}


def yield_strength(hv, model: str = "pavlina2008"):
    """Tensile yield strength [Pa] of steel of Vickers hardness ``hv`` by a :data:`STRENGTH_MODELS` entry.

    .. math:: \\sigma_y = (-90.7 + 2.876\\,HV)\\ \\mathrm{MPa}\\ \\ (\\text{pavlina2008}),\\qquad
              \\sigma_y = 9.80665\\,HV/3\\ \\mathrm{MPa}\\ \\ (\\text{tabor})

    References
    ----------
    Pavlina & Van Tyne (2008) Table 1; Tabor (1951).
    """
    checks.one_of("strength_model", model, STRENGTH_MODELS)
    return STRENGTH_MODELS[model](hv)


def tensile_strength(hv):
    """Tensile strength R_m [Pa] = (−99.8 + 3.734 HV) MPa (Pavlina & Van Tyne 2008, HV 129–592)."""
    a, b = PAVLINA_TENSILE
    return (a + b * np.asarray(hv, float)) * MPA


#: Limit hardness of each case-depth definition (module docstring): a function of the surface hardness.
CASE_DEPTH_DEFINITIONS: dict[str, Callable] = {
    "SHD": lambda surface: 0.8 * surface,  # ISO 3754 / ISO 18203 [from memory: 0.8]
    "CHD": lambda surface: 550.0 + 0.0 * surface,  # ISO 2639 / ISO 18203: 550 HV1
}


@dataclass(frozen=True)
class HardnessProfile:
    """Hardness of a raceway against depth (module docstring); through-hardened when ``case_depth`` is None.

    Parameters
    ----------
    surface_hardness : float
        HV_s [HV] at the surface (and down to the transition), in :data:`HARDNESS_RANGE_HV`.
    case_depth : float or None
        Effective case depth d_c [m] (> 0), by ``depth_definition``; None: through-hardened.
    core_hardness : float or None
        HV_c [HV] of the core (< HV_s); required with a case depth.
    depth_definition : {"SHD", "CHD"}
        Limit hardness of the case depth (:data:`CASE_DEPTH_DEFINITIONS`).
    limit_hardness : float or None
        HV_lim [HV] replacing the definition's (HV_c < HV_lim < HV_s).
    transition_width : float
        w / d_c [-], (0, 1] (:data:`TRANSITION_WIDTH`).
    strength_model : str
        Key of :data:`STRENGTH_MODELS`.
    static_limit_factor : float or None
        Multiplies ISO 76's limit pressures [-], (0, 1.5]; None: from the surface hardness (module docstring).
    name, source : str
    """

    surface_hardness: float
    case_depth: float | None = None
    core_hardness: float | None = None
    depth_definition: str = "SHD"
    limit_hardness: float | None = None
    transition_width: float = TRANSITION_WIDTH
    strength_model: str = "pavlina2008"
    static_limit_factor: float | None = None
    name: str = "custom"
    source: str = ""

    def __post_init__(self):
        low, high = HARDNESS_RANGE_HV
        checks.in_range("surface_hardness (HV)", self.surface_hardness, low, high)
        checks.one_of("depth_definition", self.depth_definition, CASE_DEPTH_DEFINITIONS)
        checks.one_of("strength_model", self.strength_model, STRENGTH_MODELS)
        checks.in_range("transition_width", self.transition_width, 0.0, 1.0)
        checks.positive("transition_width", self.transition_width)
        if self.static_limit_factor is not None:
            checks.in_range("static_limit_factor", self.static_limit_factor, 0.0, 1.5)
            checks.positive("static_limit_factor", self.static_limit_factor)
        if self.case_depth is None:
            if self.core_hardness is not None or self.limit_hardness is not None:
                raise InputError(
                    "case_depth (not given) is needed with core_hardness / limit_hardness; give the "
                    "effective case depth, or drop them for a through-hardened ring"
                )
            return
        checks.positive("case_depth", self.case_depth, "m")
        if self.core_hardness is None:
            raise InputError("core_hardness (not given) is needed with a case_depth: give the core's HV")
        checks.in_range("core_hardness (HV)", self.core_hardness, low, high)
        if not self.core_hardness < self.surface_hardness:
            raise InputError(
                f"core_hardness ({self.core_hardness:g} HV) must be below surface_hardness "
                f"({self.surface_hardness:g} HV); for a through-hardened ring drop case_depth"
            )
        lim = self.limit
        if not self.core_hardness < lim < self.surface_hardness:
            raise InputError(
                f"limit hardness of the case depth ({lim:g} HV, {self.depth_definition}) must lie between "
                f"core_hardness ({self.core_hardness:g} HV) and surface_hardness ({self.surface_hardness:g} "
                "HV); give limit_hardness or another depth_definition"
            )
        if self._fall_fraction * self.transition_width > 1.0:
            raise InputError(
                f"transition_width ({self.transition_width:g}) is too wide for the limit hardness "
                f"({lim:g} HV): the hardness would have to fall before the surface; use a narrower one"
            )

    # ----------------------------------------------------------------------------------- shape
    @property
    def through_hardened(self) -> bool:
        return self.case_depth is None

    @property
    def limit(self) -> float:
        """HV_lim [HV]: the hardness at the effective case depth."""
        if self.limit_hardness is not None:
            return float(self.limit_hardness)
        return float(CASE_DEPTH_DEFINITIONS[self.depth_definition](self.surface_hardness))

    @property
    def _fall_fraction(self) -> float:
        return (self.surface_hardness - self.limit) / (self.surface_hardness - self.core_hardness)

    def transition(self, case_depth=None):
        """(z_a, z_b) [m]: start and end of the fall from surface to core hardness (module docstring).

        ``case_depth`` (array_like) replaces the profile's d_c (the search of a required depth scales it).
        """
        if self.through_hardened and case_depth is None:
            return np.inf, np.inf
        d = np.asarray(self.case_depth if case_depth is None else case_depth, float)
        w = self.transition_width * d
        start = d - w * self._fall_fraction
        return start, start + w

    def hardness(self, depth, case_depth=None):
        """HV(z) [HV] at depth z [m] (array_like; broadcast with ``case_depth``)."""
        z = np.asarray(depth, float)
        if self.through_hardened and case_depth is None:
            return np.full(z.shape, float(self.surface_hardness))
        start, end = self.transition(case_depth)
        frac = np.clip((z - start) / (end - start), 0.0, 1.0)
        return self.surface_hardness - (self.surface_hardness - self.core_hardness) * frac

    def strength(self, depth, case_depth=None):
        """Local yield strength σ_y(z) [Pa] (:func:`yield_strength` of :meth:`hardness`)."""
        return yield_strength(self.hardness(depth, case_depth), self.strength_model)

    def with_case_depth(self, case_depth: float) -> HardnessProfile:
        return replace(self, case_depth=float(case_depth))

    # ----------------------------------------------------------------------------------- static limit
    def limit_factor(self) -> float:
        """Factor on ISO 76's limit pressures [-]: the given one, else min(1, σ_y(HV_s)/σ_y(58 HRC))."""
        if self.static_limit_factor is not None:
            return float(self.static_limit_factor)
        reference = float(hrc_to_hv(ISO76_HARDNESS_HRC))
        if self.surface_hardness >= reference:
            return 1.0
        ratio = yield_strength(self.surface_hardness, self.strength_model) / yield_strength(
            reference, self.strength_model
        )
        return float(np.clip(ratio, 0.0, 1.0))

    def describe(self) -> str:
        """One line for reports: ``613 HV (56.0 HRC), SHD 4 mm (at 491 HV), core 260 HV`` and the like."""
        hrc = float(hv_to_hrc(self.surface_hardness))
        if self.through_hardened:
            return f"through-hardened {self.surface_hardness:.0f} HV ({hrc:.1f} HRC)"
        return (
            f"{self.surface_hardness:.0f} HV ({hrc:.1f} HRC), {self.depth_definition} "
            f"{self.case_depth * 1e3:.3g} mm (at {self.limit:.0f} HV), core {self.core_hardness:.0f} HV"
        )


def _hrc(value: float) -> float:
    return float(hrc_to_hv(value))


#: Preset profiles. Values are typical, not sourced to a catalogue: give your drawing's values.
#: - ``through_hardened``: bearing steel (100Cr6 / GCr15 / 52100), 700 HV ≈ 60 HRC, the lower end of
#:   through-hardened rings (the value of :mod:`bearingkit.materials` presets);
#: - ``42CrMo4_induction``: quenched-and-tempered 42CrMo4 ring (core ≈ 260 HV ≈ R_m 870 MPa, EN 10083-3
#:   large sections 750–900 MPa [from memory]) with induction-hardened raceways, 56 HRC, SHD 4 mm [typical
#:   of 20–40 mm balls, from memory];
#: - ``50CrMo4_induction``: 50CrMo4 + QT (core ≈ 290 HV ≈ R_m 980 MPa [from memory]), raceways 58 HRC, SHD
#:   5 mm [from memory].
HARDNESS_PRESETS: dict[str, HardnessProfile] = {
    "through_hardened": HardnessProfile(
        surface_hardness=700.0,
        name="through_hardened",
        source="through-hardened bearing steel, 700 HV (ISO 76/281 assume >= 58 HRC)",
    ),
    "42CrMo4_induction": HardnessProfile(
        surface_hardness=_hrc(56.0),
        case_depth=4.0e-3,
        core_hardness=260.0,
        name="42CrMo4_induction",
        source="42CrMo4+QT, induction-hardened raceways: typical values [from memory], not a catalogue's",
    ),
    "50CrMo4_induction": HardnessProfile(
        surface_hardness=_hrc(58.0),
        case_depth=5.0e-3,
        core_hardness=290.0,
        name="50CrMo4_induction",
        source="50CrMo4+QT, induction-hardened raceways: typical values [from memory], not a catalogue's",
    ),
}


def get_hardness(name: str) -> HardnessProfile:
    """The preset :class:`HardnessProfile` called ``name`` (InputError listing the presets otherwise)."""
    checks.one_of("hardness preset", name, HARDNESS_PRESETS)
    return HARDNESS_PRESETS[name]
