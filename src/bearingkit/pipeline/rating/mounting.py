"""A single bearing of one axial direction as mounted: the axial force its radial load induces, and the
reaction of a held axial displacement.

SI units: forces in N, angles in rad. A lone tapered roller or angular contact ball row carries axial load
one way only; in a machine it sits against an opposite bearing. Two situations need saying in every face:

- u_z held (automatically when a case gives no axial load, :func:`bearingkit.io.load_cases.mounted_free`,
  or by ``--hold u_z``): the axial reaction F_z of each case is the load the opposite bearing takes —
  :func:`mounting_notes`;
- u_z free with 0 < F_a below the induced axial force F_a,ind: the row alone balances F_a with a load zone
  of less than half the circle, so only a few elements carry load; mounted against an opposite bearing it
  would carry at least F_a,ind — :func:`mounting_warnings`.

The induced axial force of the ε = 0.5 load zone (half the elements loaded, zero clearance):

- tapered roller: F_a,ind = 0.5 F_r / Y with Y = 0.4 cot α (ISO 281:2007 7.2, single-row radial roller
  bearings with α ≠ 0; the 0.5 F_r/Y of catalogue mounting calculations, e.g. SKF and Timken), i.e.
  1.25 F_r tan α; α the cup angle;
- angular contact ball: F_a,ind = F_r tan α / 0.8225 (Harris & Kotzalas 2007, Table 7.4: F_r tan α / F_a =
  0.8225 at ε = 0.5, point contact), i.e. 1.216 F_r tan α; α the nominal contact angle.
"""

from __future__ import annotations

import numpy as np

from bearingkit.io.load_cases import one_way_row

__all__ = [
    "BALL_HALF_ZONE_RATIO",
    "TAPERED_Y_FACTOR",
    "induced_axial_force",
    "mounting_notes",
    "mounting_warnings",
]

#: ISO 281:2007 7.2: Y = 0.4 cot α of a single-row radial roller bearing with α ≠ 0 (F_a/F_r > e) [-].
TAPERED_Y_FACTOR = 0.4
#: Harris & Kotzalas (2007) Table 7.4: F_r tan α / F_a at ε = 0.5 (half the balls loaded, point contact) [-].
BALL_HALF_ZONE_RATIO = 0.8225
#: An element counts as carrying the applied load when its load exceeds this share of the largest [-]
#: (wording of the warning only; chosen so that the centrifugal load at speed is not counted).
LOADED_SHARE = 0.1


def induced_axial_force(row, radial_load):
    """F_a,ind [N] that a radial load F_r [N] induces in a one-way row (module docstring) and its
    formula as text."""
    fr = np.asarray(radial_load, float)
    if row.kind == "tapered":
        alpha = abs(float(row.contact_angle_outer))
        y = TAPERED_Y_FACTOR / np.tan(alpha)
        return 0.5 * fr / y, f"0.5 F_r/Y, Y = {y:.3g} (ISO 281: 0.4 cot α, α = {np.degrees(alpha):.3g}°)"
    alpha = abs(float(np.max(row.contact_angle)))
    return fr * np.tan(alpha) / BALL_HALF_ZONE_RATIO, (
        f"F_r tan α / {BALL_HALF_ZONE_RATIO} (half the balls loaded, Harris Table 7.4; α = "
        f"{np.degrees(alpha):.3g}°)"
    )


def _kn(x) -> str:
    return f"{float(x) / 1e3:.3g} kN"


def mounting_notes(analysis) -> list[str]:
    """Per case, the axial reaction of a one-way row whose u_z is held (the opposite bearing's load)."""
    found = one_way_row(analysis.input.model)
    if found is None or analysis.setup.free[2]:
        return []
    res = analysis.statics
    row, _ = found
    out = []
    fr = np.hypot(res.load[:, 0], res.load[:, 1])
    induced, formula = induced_axial_force(row, fr)
    for c, name in enumerate(analysis.case_names):
        if not res.converged[c]:
            continue
        out.append(
            f"case {name!r}: u_z held, axial reaction F_z = {_kn(res.load[c, 2])} (the load the opposite "
            f"bearing takes; the induced axial force {formula} is {_kn(induced[c])})"
        )
    return out


def mounting_warnings(analysis, case: int) -> list[str]:
    """A one-way row with u_z free under 0 < F_a < F_a,ind: why only a few elements carry load."""
    found = one_way_row(analysis.input.model)
    res = analysis.statics
    if found is None or not analysis.setup.free[2] or not res.converged[case]:
        return []
    row, sign = found
    load = res.load[case]
    fr, fa = float(np.hypot(load[0], load[1])), float(load[2]) * sign
    if fr <= 0.0 or fa <= 0.0:
        return []
    induced, formula = induced_axial_force(row, fr)
    if fa >= induced:
        return []
    q = np.asarray(res.rows[0].load[case], float)
    # at speed the centrifugal force presses every element on the outer ring: count the ones the
    # applied load carries (more than LOADED_SHARE of the largest)
    loaded, z = int(np.sum(q > LOADED_SHARE * q.max())), q.shape[-1]
    what = "rollers" if row.kind == "tapered" else "balls"
    return [
        f"F_a = {_kn(fa)} is below the axial force {_kn(induced)} that F_r induces in this row ({formula}): "
        f"alone, the bearing balances F_a with a narrow load zone ({loaded} of {z} {what} carry it); mounted "
        "against an opposite bearing it takes at least the induced force and loads half its elements — "
        "solve it so with F_a = 0 (u_z is then held and the reaction is that load) or model the pair"
    ]
