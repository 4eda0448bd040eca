"""Seals and shields of standard bearings: what a designation suffix says about the bearing's closures.

A seal or shield suffix of a designation (``Designation.seal``: ``2RS1``, ``2Z``, ``LLU``, ``DDU`` …)
names the closure (a rubbing lip seal, a low-friction seal, a non-contact seal or a sheet-steel shield)
and whether it is fitted on one side or both. The friction of a closure is modelled with the SKF seal
constants (:mod:`bearingkit.physics.friction.skf`), which are given for SKF's own seal types; every
maker's suffix is mapped here to the SKF type of the same construction:

========================================  =======================  ==================================
suffixes                                   construction             SKF seal type (friction constants)
========================================  =======================  ==================================
RS, 2RS, RS1, 2RS1, RSR, 2RSR, LLU, DDU    contact lip seal (NBR)   RS1
RSH, 2RSH                                  contact lip seal (NBR)   RSH
RSL, 2RSL, LLH, DD                         low-friction seal        RSL
RZ, 2RZ, LLB, VV                           non-contact seal         RZ (no friction)
Z, 2Z, ZZ                                  shield                   none (no friction)
========================================  =======================  ==================================

Sources: the suffix meanings are every maker's designation system (SKF ``RS1``/``RSH``/``RSL``/``RZ``/
``Z``; Schaeffler ``2RSR``; NTN ``LLU`` contact, ``LLH`` low-torque, ``LLB`` non-contact; NSK ``DDU``
contact, ``DD`` light contact, ``VV`` non-contact). The mapping of another maker's seal to the SKF type
of the same construction is bearingkit's documented choice (makers publish no friction constants of
their own seals). A ``2`` prefix, or a doubled letter (``ZZ``, ``LLU``, ``DDU``, ``VV``), means both
sides; a single ``RS``/``Z`` one side.
"""

from __future__ import annotations

from dataclasses import dataclass

from bearingkit.errors import InputError, did_you_mean

__all__ = ["SEALS", "Seal", "seal_of_suffix"]


@dataclass(frozen=True)
class Seal:
    """The closures a seal suffix names.

    Attributes
    ----------
    suffix : str
        As in the designation (``"2RS1"``).
    construction : str
        ``"contact"``, ``"low_friction"``, ``"non_contact"`` or ``"shield"``.
    sides : int
        1 or 2.
    skf_type : str or None
        SKF seal type whose friction constants apply (``"RS1"``, ``"RSH"``, ``"RSL"``, ``"RZ"``); None for
        a shield (no contact, no friction term).
    """

    suffix: str
    construction: str
    sides: int
    skf_type: str | None

    @property
    def rubbing(self) -> bool:
        """True when a lip touches the inner ring (a contact or low-friction seal): friction and a
        lip sliding-speed limit."""
        return self.construction in ("contact", "low_friction")


def _row(suffix: str, construction: str, sides: int, skf: str | None) -> tuple[str, Seal]:
    return suffix, Seal(suffix, construction, sides, skf)


#: Seal or shield suffix → :class:`Seal` (module docstring).
SEALS: dict[str, Seal] = dict(
    [
        _row("RS", "contact", 1, "RS1"),
        _row("2RS", "contact", 2, "RS1"),
        _row("RS1", "contact", 1, "RS1"),
        _row("2RS1", "contact", 2, "RS1"),
        _row("RSR", "contact", 1, "RS1"),
        _row("2RSR", "contact", 2, "RS1"),
        _row("LLU", "contact", 2, "RS1"),
        _row("DDU", "contact", 2, "RS1"),
        _row("RSH", "contact", 1, "RSH"),
        _row("2RSH", "contact", 2, "RSH"),
        _row("RSL", "low_friction", 1, "RSL"),
        _row("2RSL", "low_friction", 2, "RSL"),
        _row("LLH", "low_friction", 2, "RSL"),
        _row("DD", "low_friction", 2, "RSL"),
        _row("RZ", "non_contact", 1, "RZ"),
        _row("2RZ", "non_contact", 2, "RZ"),
        _row("LLB", "non_contact", 2, "RZ"),
        _row("VV", "non_contact", 2, "RZ"),
        _row("LU", "contact", 1, "RS1"),
        _row("DU", "contact", 1, "RS1"),
        _row("2HRS", "contact", 2, "RS1"),
        _row("LH", "low_friction", 1, "RSL"),
        _row("LB", "non_contact", 1, "RZ"),
        _row("Z", "shield", 1, None),
        _row("Z1", "shield", 1, None),
        _row("2Z", "shield", 2, None),
        _row("2Z1", "shield", 2, None),
        _row("ZZ", "shield", 2, None),
    ]
)
#: Words a file may give for a bearing without seals or shields.
OPEN = ("none", "open")


def seal_of_suffix(suffix: str | None, field: str = "seal") -> Seal | None:
    """The :class:`Seal` of a suffix (``"2RS1"``); None for None, ``"none"`` or ``"open"``.

    An unknown suffix raises :class:`~bearingkit.errors.InputError` naming the valid ones (one line).
    """
    if suffix is None:
        return None
    text = str(suffix).strip().upper().replace("-", "")
    if text.lower() in OPEN:
        return None
    if text not in SEALS:
        raise InputError(
            f"{field} ({suffix!r}) is not a seal or shield suffix bearingkit knows; valid: "
            f"{', '.join(SEALS)} or 'none'{did_you_mean(text, SEALS)}"
        )
    return SEALS[text]
