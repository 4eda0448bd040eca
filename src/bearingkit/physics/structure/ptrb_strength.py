"""Strength of the annular thread teeth of a PTRB: root bending and root shear under axial load.

SI units (m, N, Pa). Zheng et al. (2022) eq. (3)-(4) check the tooth roots of the roller (X = R), the
inner ring (X = I) and the outer ring (X = O) with the thread-connection formulas: the axial tooth
force acts at the dedendum h from the root, spread over the circumference π d_X of the annular
tooth whose root (bottom) thickness is B_X. Under radial load both flanks of a tooth carry equal
loads, whose moments and shears cancel at the root, so no check is needed (paper §3.1).

The paper prints the factor Z (rollers) in both formulas for every part. A ring tooth does carry
the Z contacts of all rollers; a roller tooth carries one contact per flank. Both readings are
offered (:data:`CONTACTS_PER_TOOTH`): ``"paper"`` (Z for every part, as printed; default, since it
is the paper's own check) and ``"per_part"`` (Z for the rings, 1 for the roller).

References: ``zheng2022`` eq. (3)-(4); GB/T 192-2003 / ISO 68-1 (thread profile).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks

__all__ = [
    "ALLOWED_BENDING_STRESS",
    "ALLOWED_SHEAR_STRESS",
    "CONTACTS_PER_TOOTH",
    "PARTS",
    "contacts_per_tooth",
    "tooth_root_bending_stress",
    "tooth_root_shear_stress",
]

#: Allowed root bending stress [σ_b] of GCr15 teeth [Pa]; Zheng et al. (2022) eq. (3).
ALLOWED_BENDING_STRESS = 348.0e6
#: Allowed root shear stress [τ_c] [Pa] (= 0.6 [σ_b]); Zheng et al. (2022) eq. (4).
ALLOWED_SHEAR_STRESS = 208.8e6
#: Parts with thread teeth: roller, inner ring, outer ring.
PARTS = ("roller", "inner", "outer")


def _paper(n_elements, part):
    return np.asarray(n_elements, dtype=float)


def _per_part(n_elements, part):
    z = np.asarray(n_elements, dtype=float)
    return np.ones_like(z) if part == "roller" else z


#: Registry: how many contact loads one annular tooth of a part carries.
CONTACTS_PER_TOOTH = {"paper": _paper, "per_part": _per_part}


def contacts_per_tooth(n_elements, part, model="paper"):
    """Number of contact loads on one annular tooth of ``part`` [1] under the named ``model``.

    Zheng et al. (2022) eqs. (3)–(4) print Z for every part (``"paper"``); ``"per_part"`` uses Z on the
    rings and 1 on the roller.

    Parameters
    ----------
    n_elements : int
        Rollers Z.
    part : str
        ``"roller"``, ``"inner"`` or ``"outer"``.
    model : str
        ``"paper"`` or ``"per_part"``.
    """
    checks.one_of("part", part, PARTS)
    checks.one_of("model", model, CONTACTS_PER_TOOTH)
    return CONTACTS_PER_TOOTH[model](n_elements, part)


def tooth_root_bending_stress(
    contact_load, contact_angle, n_contacts, dedendum, pitch_diameter, bottom_thickness
):
    """Root bending stress of an annular thread tooth σ_b [Pa], Zheng et al. (2022) eq. (3).

    Parameters
    ----------
    contact_load : array_like
        Normal load of the most loaded contact F_n,max [N].
    contact_angle : array_like
        α [rad].
    n_contacts : array_like
        Contacts carried by the tooth (Z for a ring; see :func:`contacts_per_tooth`) [1].
    dedendum : array_like
        Lever arm h of the axial force about the root [m].
    pitch_diameter : array_like
        d_X of the part [m].
    bottom_thickness : array_like
        Root thickness B_X [m].

    Notes
    -----
    .. math:: \\sigma_b = \\frac{6\\,h\\,Z F_{n,max}\\sin\\alpha}{\\pi d_X B_X^2} \\le [\\sigma_b]

    (moment Z F sin α · h over the section modulus π d_X B_X²/6 of the annular root).
    """
    checks.non_negative("contact_load", contact_load, "N")
    checks.positive("bottom_thickness", bottom_thickness, "m")
    checks.positive("pitch_diameter", pitch_diameter, "m")
    axial = (
        np.asarray(n_contacts, float) * np.asarray(contact_load, float) * np.sin(np.asarray(contact_angle))
    )
    return (
        6.0
        * np.asarray(dedendum, float)
        * axial
        / (np.pi * np.asarray(pitch_diameter) * np.asarray(bottom_thickness) ** 2)
    )


def tooth_root_shear_stress(contact_load, contact_angle, n_contacts, pitch_diameter, bottom_thickness):
    """Root shear stress of an annular thread tooth τ_c [Pa], Zheng et al. (2022) eq. (4).

    Parameters
    ----------
    contact_load : array_like [N]
        F_n,max, the largest equivalent-ball contact load on the tooth.
    contact_angle : array_like [rad]
        Flank angle α.
    n_contacts : array_like
        Contact loads on the tooth (:func:`contacts_per_tooth`).
    pitch_diameter : array_like [m]
        d_X of the part.
    bottom_thickness : array_like [m]
        Tooth root thickness B_X.

    Notes
    -----
    .. math:: \\tau_c = \\frac{Z F_{n,max}\\sin\\alpha}{\\pi d_X B_X} \\le [\\tau_c]
    """
    checks.non_negative("contact_load", contact_load, "N")
    checks.positive("bottom_thickness", bottom_thickness, "m")
    checks.positive("pitch_diameter", pitch_diameter, "m")
    axial = (
        np.asarray(n_contacts, float) * np.asarray(contact_load, float) * np.sin(np.asarray(contact_angle))
    )
    return axial / (np.pi * np.asarray(pitch_diameter) * np.asarray(bottom_thickness))
