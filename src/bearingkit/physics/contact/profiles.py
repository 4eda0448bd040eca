"""Roller crowning profiles: the crown drop C(x) of a cylindrical or tapered roller.

All quantities are SI: lengths in m, loads in N, moduli in Pa.

A profile gives the crown drop :math:`C(x) \\ge 0` [m] -- the material removed from the roller
radius relative to a straight roller -- at axial positions :math:`x` measured from the roller
middle, :math:`|x| \\le L/2`, for a roller of effective length :math:`L` (``effective_length``) and
diameter :math:`D` (``element_diameter``).  ``Profile.crown_drop(x)`` is pure and vectorised: ``x``
may have any shape (e.g. cases x elements x slices) and the result has the same shape.

The profiles are small frozen dataclasses behind the registry :data:`PROFILES`, keyed by a
documented name; :func:`make_profile` builds one by name and rejects unknown names or parameters
with :class:`bearingkit.errors.InputError`.

Registry names
--------------
``straight``            C = 0.
``full_crown``          one circular arc over the whole length (crown radius or end drop).
``arc_slope_sides``     flat middle + circular end arcs tangent to the flat; arc centres on the
                        perpendiculars through the flat's end points ("centres at both sides").
``arc_slope_midline``   flat middle + end arcs of one circle centred on the roller mid-plane
                        x = 0 ("centre on the midline"); slope kink at the flat's end.
``lundberg`` (alias ``logarithmic``)  Lundberg (1939) logarithmic profile for a design load.
``johns_gohar``         Johns & Gohar (1981) logarithmic profile with a finite end drop.
``iso16281``            ISO/TS 16281:2008 eqs. (42)-(43) logarithmic profile (cylindrical rollers).
``iso16281_tapered``    ISO/TS 16281:2008 eq. (44) logarithmic profile (tapered rollers).

Seed 000 (Tian et al. 2025, section 6.1.5, Fig. 18) compares five crowning types a-e without giving
any crowning dimension; :data:`SEED000_CROWNING` maps its letters to registry names and the
``DEFAULT_*`` constants below fix comparable default sizes (see their comments), in
:mod:`bearingkit.physics.contact.profile_base`.
"""

from __future__ import annotations

import dataclasses

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics.contact.crowning import (
    ArcSlopeMidlineProfile,
    ArcSlopeSidesProfile,
    FullCrownProfile,
    Iso16281Profile,
    Iso16281TaperedProfile,
    JohnsGoharProfile,
    LundbergProfile,
    StraightProfile,
)
from bearingkit.physics.contact.profile_base import Profile

__all__ = [
    "PROFILES",
    "SEED000_CROWNING",
    "ArcSlopeMidlineProfile",
    "ArcSlopeSidesProfile",
    "FullCrownProfile",
    "Iso16281Profile",
    "Iso16281TaperedProfile",
    "JohnsGoharProfile",
    "LundbergProfile",
    "Profile",
    "StraightProfile",
    "make_profile",
    "seed000_profile",
]

# ---------------------------------------------------------------------------------------------
# Registry
# ---------------------------------------------------------------------------------------------

#: Registry of profile classes keyed by documented name. ``logarithmic`` is an alias of
#: ``lundberg`` (the load-based logarithmic law); seed 000's type a uses ``iso16281`` instead.
PROFILES: dict[str, type[Profile]] = {
    StraightProfile.name: StraightProfile,
    FullCrownProfile.name: FullCrownProfile,
    ArcSlopeSidesProfile.name: ArcSlopeSidesProfile,
    ArcSlopeMidlineProfile.name: ArcSlopeMidlineProfile,
    LundbergProfile.name: LundbergProfile,
    "logarithmic": LundbergProfile,
    JohnsGoharProfile.name: JohnsGoharProfile,
    Iso16281Profile.name: Iso16281Profile,
    Iso16281TaperedProfile.name: Iso16281TaperedProfile,
}

#: Seed 000 (Tian et al. 2025, §6.1.5, Fig. 18) crowning letters -> registry names.
#: "a" logarithmic: the paper gives no crowning data, so the load-independent ISO/TS 16281
#: logarithmic profile is used (the Lundberg/Johns-Gohar laws would need a design load the paper
#: does not state). b-d use the DEFAULT_* sizes above (same end drop 0.001 D; half the length flat).
SEED000_CROWNING: dict[str, str] = {
    "a": "iso16281",
    "b": "arc_slope_sides",
    "c": "arc_slope_midline",
    "d": "full_crown",
    "e": "straight",
}

_BASE_FIELDS = {f.name for f in dataclasses.fields(Profile)}


def make_profile(name: str, effective_length: float, element_diameter: float, **parameters) -> Profile:
    """Build a registered profile by name.

    Parameters
    ----------
    name : str
        Registry name, one of :data:`PROFILES`.
    effective_length : float
        Effective roller length L [m].
    element_diameter : float
        Roller diameter D [m].
    **parameters
        The profile's own parameters (SI), e.g. ``crown_radius`` [m], ``end_drop`` [m],
        ``flat_length`` [m], ``design_load`` [N], ``e_reduced`` [Pa], ``semi_minor`` [m],
        ``curvature_sum`` [1/m], ``clip`` [-].

    Returns
    -------
    Profile

    Raises
    ------
    InputError
        Unknown name (the message lists the valid names), unknown parameter (lists the valid
        ones), or an invalid value.
    """
    checks.one_of("profile", name, PROFILES)
    cls = PROFILES[name]
    allowed = [f.name for f in dataclasses.fields(cls) if f.name not in _BASE_FIELDS]
    for key in parameters:
        if key not in allowed:
            raise InputError(
                f"{key} is not a parameter of profile {name!r}; valid: {', '.join(allowed) or '(none)'}"
            )
    return cls(effective_length=effective_length, element_diameter=element_diameter, **parameters)


def seed000_profile(letter: str, effective_length: float, element_diameter: float) -> Profile:
    """Seed 000 crowning type ``letter`` (a-e) with documented defaults (Tian et al. 2025 §6.1.5).

    Parameters
    ----------
    letter : str
        ``"a"`` logarithmic … ``"e"`` straight (:data:`SEED000_CROWNING`).
    effective_length : float [m]
        Roller effective length.
    element_diameter : float [m]
        Roller diameter.
    """
    checks.one_of("crowning", letter, SEED000_CROWNING)
    return make_profile(SEED000_CROWNING[letter], effective_length, element_diameter)
