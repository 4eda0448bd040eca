"""ISO 281 C and ISO 76 C0 of an estimated catalogue geometry (:mod:`.internal`). SI units.

The formulas are those of :mod:`bearingkit.physics.life` (``iso281``, ``iso76`` and, for the kinds whose
factors the shipped tables leave out, ``kinds``), evaluated on the estimate as a catalogue would rate the
bearing (one rating for the whole bearing, on the basis the catalogue prints, :data:`BASIS`):

- radial ball / roller rows: C_r with i rows, C_0r (ISO 281 cl. 5.1, 7.1; ISO 76 cl. 6.1, 7.1);
  spherical roller bearings i = 2 with b_m = 1.15, needle roller bearings b_m = 1.1 (machined rings);
- thrust rows (α = 90°): C_a, C_0a (ISO 281 cl. 6.1, 8.1; ISO 76 cl. 8.1, 9.1); spherical roller thrust
  (one row at α ≈ 50°) by the same clauses' α ≠ 90° formulas with b_m = 1.15;
- self-aligning ball: C_r, C_0r with i = 2, the f_c of :mod:`bearingkit.physics.life.kinds` (derived
  there: ISO 281 Table 2 column 3 is not shipped) and ISO 76 Table 1 column 2's f0 (shipped from memory,
  checked against the stress definition: ``kinds.f0_self_aligning_ball_table``);
- four-point (QJ): rated as the double-row angular contact ball bearing at 35° that ISO's equivalent-load
  factors describe (ISO 281 Table 3 / ISO 76 Table 2, double-row column: e = 0.95, Y = 1.07 for
  F_a/F_r > e, Y0 = 0.58 — the factors SKF prints for QJ bearings, P = 0.6 F_r + 1.07 F_a,
  P0 = F_r + 0.58 F_a; :func:`bearingkit.physics.life.kinds.equivalent_loads`). Catalogues that print axial
  ratings for QJ bearings (NSK E1102 B68: C_a, C_0a with P_a = F_a) give the pure-axial capacity, the
  load whose equivalent load equals the radial rating: C_a = C_r / Y, C_0a = C_0r / Y0 (F_r = 0).
  :func:`ratings` returns those axial values; :func:`four_point_radial` the radial C_r, C_0r.
"""

from __future__ import annotations

import numpy as np

from bearingkit.catalogue.internal import FOUR_POINT_ANGLE, Estimate
from bearingkit.physics.life import iso76, iso281
from bearingkit.physics.life import kinds as life_kinds

#: ISO 281 bearing types (Table 1 b_m) per family.
ISO281_TYPES = {
    "deep_groove_ball": "deep_groove_ball",
    "angular_contact_ball": "angular_contact_ball",
    "double_row_angular_contact_ball": "angular_contact_ball",
    "four_point_contact_ball": "angular_contact_ball",
    "self_aligning_ball": "self_aligning_ball",
    "cylindrical_roller": "cylindrical_roller",
    "double_row_cylindrical_roller": "cylindrical_roller",
    "tapered_roller": "tapered_roller",
    "thrust_ball": "thrust_ball",
    "thrust_cylindrical_roller": "thrust_cylindrical_roller",
    "spherical_roller": "spherical_roller",
    "spherical_roller_thrust": "thrust_spherical_roller",
    "needle_roller": "needle_roller_machined",
}
#: What C, C0 mean per family (the catalogue's basis, which :func:`ratings` follows).
BASIS = {
    "thrust_ball": "axial",
    "thrust_cylindrical_roller": "axial",
    "spherical_roller_thrust": "axial",
    "four_point_contact_ball": "axial (C_a = C_r/Y, C_0a = C_0r/Y0 of a double-row 35 deg bearing)",
}
#: Rows four-point contact bearings are rated with (ISO's double-row angular contact treatment).
FOUR_POINT_ROWS = 2


def basis(family: str) -> str:
    """``"radial"``, ``"axial"`` or the four-point axial-equivalent basis of ``family``'s C, C0."""
    return BASIS.get(family, "radial")


def four_point_radial(est: Estimate) -> tuple[float, float]:
    """(C_r, C_0r) [N] of a four-point bearing rated as a double-row angular contact ball bearing (i = 2)."""
    z, dw, dm, a = est.n_elements, est.element_diameter, est.pitch_diameter, est.contact_angle
    c = iso281.dynamic_rating_ball(dw, dm, a, z, FOUR_POINT_ROWS, "angular_contact_ball")
    c0 = iso76.static_rating_ball(dw, dm, a, z, FOUR_POINT_ROWS, "radial")
    return float(c), float(c0)


def axial_factors(contact_angle: float) -> tuple[float, float]:
    """(Y, Y0) of a four-point bearing under pure axial load: P = Y F_a, P0 = Y0 F_a (F_r = 0)."""
    p, p0 = life_kinds.equivalent_loads("four_point", 0.0, 1.0, contact_angle)
    return float(p), float(p0)


def radial_basis(family: str, c, c0) -> tuple[float | None, float | None]:
    """(C, C0) [N] of a catalogue row on the basis the whole-bearing ISO 281 / ISO 76 rating uses with
    P = X F_r + Y F_a, P0 = X0 F_r + Y0 F_a.

    Four-point (QJ) rows print the pure-axial capacities C_a = C_r / Y, C_0a = C_0r / Y0 (module
    docstring), so C_r = Y C_a and C_0r = Y0 C_0a with the double-row factors at 35° (Y = 1.07,
    Y0 = 0.58: ISO 281 Table 3, ISO 76 Table 2; SKF 6000 p. 455); every other family is returned as is
    (thrust families are rated on their axial basis by P_a = F_a).
    """
    if family != "four_point_contact_ball":
        return c, c0
    y, y0 = axial_factors(FOUR_POINT_ANGLE)
    return (None if c is None else float(c) * y), (None if c0 is None else float(c0) * y0)


def ratings(est: Estimate) -> tuple[float | None, float | None]:
    """(C, C0) [N] of the estimated geometry on the catalogue's basis (:func:`basis`)."""
    fam = est.entry.family
    z, dw, dm, a = est.n_elements, est.element_diameter, est.pitch_diameter, est.contact_angle
    kind = ISO281_TYPES[fam]
    if fam == "four_point_contact_ball":
        c_r, c0_r = four_point_radial(est)
        y, y0 = axial_factors(a)
        return c_r / y, c0_r / y0
    if fam == "self_aligning_ball":
        fi = est.extra["conformity_inner"]
        gamma = dw * np.cos(a) / dm
        c = iso281.dynamic_rating_ball(
            dw, dm, a, z, est.rows, kind, fc=life_kinds.fc_self_aligning_ball(gamma, fi)
        )
        c0 = iso76.static_rating_ball(
            dw, dm, a, z, est.rows, f0=life_kinds.f0_self_aligning_ball_table(gamma)
        )
        return float(c), float(c0)
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
