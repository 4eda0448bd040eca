"""ISO 281 C and ISO 76 C0 of an estimated catalogue geometry (:mod:`.internal`). SI units.

The formulas are those of :mod:`bearingkit.physics.life.iso281` and :mod:`bearingkit.physics.life.iso76`,
evaluated on the estimate as a catalogue would rate the bearing (one rating for the whole bearing):

- radial ball / roller rows: C_r with i rows, C_0r (ISO 281 cl. 5.1, 7.1; ISO 76 cl. 6.1, 7.1);
- thrust rows (α = 90°): C_a, C_0a (ISO 281 cl. 6.1, 8.1; ISO 76 cl. 8.1, 9.1);
- four-point (QJ): not rated here. The source prints axial ratings C_a, C_0a; ISO 281/76 give thrust
  forms only for α > 45° and the radial form at 35° is not what the source prints (C_r tan α falls
  ~60 % below NSK's C_a), so no comparison is claimed until the four-point row kind rates itself;
- self-aligning ball: not rated (ISO 281 Table 2's self-aligning f_c column is not shipped).
"""

from __future__ import annotations

from bearingkit.catalogue.internal import Estimate
from bearingkit.physics.life import iso76, iso281

#: ISO 281 bearing types (Table 1 b_m) per family.
ISO281_TYPES = {
    "deep_groove_ball": "deep_groove_ball",
    "angular_contact_ball": "angular_contact_ball",
    "double_row_angular_contact_ball": "angular_contact_ball",
    "four_point_contact_ball": "angular_contact_ball",
    "cylindrical_roller": "cylindrical_roller",
    "tapered_roller": "tapered_roller",
    "thrust_ball": "thrust_ball",
    "thrust_cylindrical_roller": "thrust_cylindrical_roller",
}


def ratings(est: Estimate) -> tuple[float | None, float | None]:
    """(C, C0) [N] of the estimated geometry; (None, None) where ISO gives no closed form here."""
    fam = est.entry.family
    z, dw, dm, a = est.n_elements, est.element_diameter, est.pitch_diameter, est.contact_angle
    if fam in ("self_aligning_ball", "four_point_contact_ball"):
        return None, None
    kind = ISO281_TYPES[fam]
    if est.effective_length is None:
        c = iso281.dynamic_rating_ball(dw, dm, a, z, est.rows, kind)
        c0 = iso76.static_rating_ball(dw, dm, a, z, est.rows, "thrust" if kind == "thrust_ball" else "radial")
    else:
        lw = est.effective_length
        c = iso281.dynamic_rating_roller(dw, lw, dm, a, z, est.rows, kind)
        c0 = iso76.static_rating_roller(
            dw, lw, dm, a, z, est.rows, "thrust" if kind.startswith("thrust") else "radial"
        )
    return float(c), float(c0)
