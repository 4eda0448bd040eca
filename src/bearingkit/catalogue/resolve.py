"""A designation → bearing type, geometry (SI, the input format's ``[geometry]`` fields) and notes.

:func:`resolve` is what the input loader and the command line call for ``designation = "6205-2RS C3"``:
it parses the designation (:mod:`.designation`), estimates the internal geometry (:mod:`.internal`),
optionally scales the element size so the ISO 281 C matches a catalogue C the user gives, adds the
ISO 5753-1 clearance of the designation's class (CN when none is given) and returns everything with
notes saying that and how the geometry is estimated.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from bearingkit.catalogue import clearances as clearance_mod
from bearingkit.catalogue import designation as designation_mod
from bearingkit.catalogue import pairs, tables
from bearingkit.catalogue.internal import Estimate, envelope_margins, estimate, with_element_diameter
from bearingkit.catalogue.iso_ratings import ratings
from bearingkit.errors import InputError

#: Slices of a catalogue tapered roller: the ISO/TS 16281 life is a lamina method (its profile and edge
#: factor act per slice; a whole-roller contact, n_slices = 1, rates a tapered bearing as if its rollers
#: were loaded evenly along their length). 20 as the cylindrical rows' builder default; the TS asks for at
#: least 30 (§5.2.2, as a public implementation quotes it), which moves the life by < 1 % here.
CATALOGUE_TAPERED_SLICES = 20
#: Relative band in which a user's catalogue C may move the element diameter (beyond it the rules no
#: longer describe the bearing; the request is refused with the achievable range).
CALIBRATION_BAND = 0.25


@dataclass(frozen=True)
class Resolved:
    """A designation resolved to the input format.

    Attributes
    ----------
    designation : designation.Designation
    estimate : Estimate
    bearing_type : str
        ``[bearing] type`` of the input format.
    geometry : dict
        ``[geometry]`` fields in SI (m, rad; counts and conformities as numbers).
    C, C0 : float or None [N]
        ISO 281 / ISO 76 ratings of the estimated geometry (one bearing; a pair's are in ISO 281's
        paired-unit law, :func:`bearingkit.physics.life.iso281.paired_unit_ratings`).
    notes : tuple of str
    preload_force : float or None [N]
        The axial preload of a DB/DF pair (a class or a given force; :mod:`.pairs`), None without.
    """

    designation: object
    estimate: Estimate
    bearing_type: str
    geometry: dict
    C: float | None
    C0: float | None
    notes: tuple
    preload_force: float | None = None

    @property
    def source(self) -> str:
        """One line for ``[bearing] source``: estimated, how, from where."""
        return "; ".join(self.notes)


def resolve(text: str, C: float | None = None, clearance_position: float = 0.5, preload=None) -> Resolved:
    """Resolve ``text`` (e.g. ``"6205-2RS C3"``, ``"7014 C DB"``).

    Parameters
    ----------
    text : str
        The designation.
    C : float, optional [N]
        A catalogue dynamic load rating to calibrate to: D_w (D_we) is scaled within
        ±:data:`CALIBRATION_BAND` so the ISO 281 C of the estimate equals it (count and pitch kept).
    clearance_position : float
        Where in the ISO 5753-1 class range the radial clearance is taken (0 min, 0.5 mean, 1 max).
    preload : str or float, optional
        Preload of a DB/DF pair: a class (``"light"`` …, :data:`.pairs.PRELOAD_FRACTIONS`) or a force [N];
        replaces the designation's preload class (``DBB``, ``GA``, ``UL`` …).
    """
    des = designation_mod.parse(text)
    entry = tables.entries(des.family)[des.base]
    est = estimate(entry)
    if C is not None:
        est = _calibrate(est, C)
    c, c0 = ratings(est)
    notes = list(est.notes)
    bearing_type = tables.FAMILIES[des.family][1]
    geometry = _geometry(est, des, notes, clearance_position)
    acting = (des.arrangement, des.preload_code, des.tapered_bore, des.seal)
    if des.seal is not None:
        notes.append(
            f"seal {des.seal}: in the friction (SKF seal term) and the seal speed limit, not the statics"
        )
    plain = [s for s in des.suffixes if s not in acting]
    if plain:
        notes.append(f"suffixes {' '.join(plain)} noted (no effect on the mechanics)")
    notes.extend(des.notes)
    if entry.C is not None:
        text = f"catalogue ratings C = {entry.C / 1e3:g} kN, C0 = {entry.C0 / 1e3:g} kN ({entry.source})"
        if entry.family == "four_point_contact_ball":
            from bearingkit.catalogue.iso_ratings import radial_basis

            c_r, c0_r = radial_basis(entry.family, entry.C, entry.C0)
            text += (
                f"; axial ratings: the ISO 281 / ISO 76 rating uses the double-row radial C_r = 1.07 C_a = "
                f"{c_r / 1e3:.4g} kN, C_0r = 0.58 C_0a = {c0_r / 1e3:.4g} kN"
            )
        notes.append(text)
    force = None
    if des.is_pair:
        bearing_type, force = _pair(des, est, geometry, notes, preload, entry.C or c)
    elif preload is not None:
        raise InputError(
            f"preload ({preload!r}): {des.base} is a single bearing; a preload is set on a pair, e.g. "
            f"'{des.text} DB' (DB back-to-back, DF face-to-face)"
        )
    return Resolved(des, est, bearing_type, geometry, c, c0, tuple(notes), force)


def _pair(des, est: Estimate, geometry: dict, notes: list, preload, rating: float):
    """Bearing type and preload force [N] of a DB/DF/DT pair; the pair's fields go into ``geometry``."""
    spacing = pairs.row_spacing(est.entry.width)
    what = "T" if des.family == "tapered_roller" else "B"
    notes.append(
        f"matched pair {des.arrangement} of two {des.base}: rows {what} = {spacing * 1e3:g} mm apart "
        "(bearings side by side without spacer)"
    )
    geometry.update(arrangement=des.arrangement, row_spacing=spacing)
    if des.family == "angular_contact_ball":
        geometry.pop("clearance", None)
        geometry["clearance_axial"] = 0.0
        bearing_type = "angular_contact_pair"
    else:
        bearing_type = "tapered_roller"
    chosen = preload if preload is not None else des.preload_class
    if chosen is None:
        notes.append(
            "no preload given: the rows touch without play or preload (give a preload class or force)"
        )
        return bearing_type, None
    if des.arrangement == "DT":
        notes.append(f"preload {chosen}: a tandem pair carries load in one direction only; no preload is set")
        return bearing_type, None
    force, note = pairs.preload_force(chosen, rating, des.base, des.tolerance_class)
    notes.append(note)
    return bearing_type, force


def _calibrate(est: Estimate, target: float) -> Estimate:
    if not target > 0 or not math.isfinite(target):
        raise InputError(f"C ({target!r} N) must be a positive force")
    c_est, _ = ratings(est)
    if c_est is None:
        raise InputError(f"{est.entry.designation}: no ISO 281 rating for this family; C cannot calibrate it")
    lo, hi = (1.0 - CALIBRATION_BAND) * est.element_diameter, (1.0 + CALIBRATION_BAND) * est.element_diameter

    def c_of(dw: float) -> float:
        return ratings(with_element_diameter(est, dw, ""))[0]

    c_lo, c_hi = c_of(lo), c_of(hi)
    if not c_lo <= target <= c_hi:
        raise InputError(
            f"C ({target / 1e3:g} kN) lies outside what {est.entry.designation} can reach by its element "
            f"size (±{CALIBRATION_BAND:.0%} of D_w: {c_lo / 1e3:.3g}–{c_hi / 1e3:.3g} kN); check the value "
            "or give the "
            "geometry explicitly"
        )
    for _ in range(60):  # bisection: C grows monotonically with D_w at fixed Z and d_m
        mid = 0.5 * (lo + hi)
        if c_of(mid) < target:
            lo = mid
        else:
            hi = mid
    dw = 0.5 * (lo + hi)
    note = (
        f"D_w scaled from {est.element_diameter * 1e3:.3f} mm to {dw * 1e3:.3f} mm so that ISO 281 C = "
        f"{target / 1e3:g} kN (user catalogue C)"
    )
    out = with_element_diameter(est, dw, note)
    if (envelope_margins(out) <= 0).any():
        raise InputError(
            f"C ({target / 1e3:g} kN): the calibrated elements of {est.entry.designation} no longer fit"
        )
    return out


def _geometry(est: Estimate, des, notes: list, position: float) -> dict:
    e = est.entry
    g = {
        "bore": e.bore,
        "outer_diameter": e.outer_diameter,
        "n_elements": est.n_elements,
        "pitch_diameter": est.pitch_diameter,
    }
    fam = des.family
    clearance = _clearance(est, des, notes, position)
    if _tapered_bore(des):
        notes.append(
            "tapered bore (K 1:12, K30 1:30): the geometry is the cylindrical-bore estimate and the "
            "clearance the UNMOUNTED one; the drive-up on the taper reduces it, give clearance_radial in "
            "[geometry] for the mounted value"
        )
    if fam == "deep_groove_ball":
        g.update(element_diameter=est.element_diameter, clearance_radial=clearance)
        g.update({k: est.extra[k] for k in ("conformity_inner", "conformity_outer")})
    elif fam == "angular_contact_ball":
        g.update(element_diameter=est.element_diameter, contact_angle=est.contact_angle, clearance=0.0)
        g.update({k: est.extra[k] for k in ("conformity_inner", "conformity_outer")})
    elif fam == "double_row_angular_contact_ball":
        g.update(
            element_diameter=est.element_diameter,
            contact_angle=est.contact_angle,
            arrangement="DB",
            row_spacing=est.extra["row_spacing"],
            clearance_axial=0.0,
            conformity_inner=est.extra["conformity_inner"],
            conformity_outer=est.extra["conformity_outer"],
        )
    elif fam == "four_point_contact_ball":
        g.update(
            element_diameter=est.element_diameter,
            contact_angle=est.contact_angle,
            conformity_inner=est.extra["conformity_inner"],
            conformity_outer=est.extra["conformity_outer"],
            clearance_radial=clearance,
        )
    elif fam == "self_aligning_ball":
        g.update(
            element_diameter=est.element_diameter,
            contact_angle=est.contact_angle,
            conformity_inner=est.extra["conformity_inner"],
            clearance_radial=clearance,
        )
    elif fam == "spherical_roller":
        g.update(
            element_diameter=est.element_diameter,
            effective_length=est.effective_length,
            contact_angle=est.contact_angle,
            clearance_radial=clearance,
        )
        notes.append("roller/raceway osculations: the builder's 0.98 (assumed; catalogues do not print them)")
    elif fam == "spherical_roller_thrust":
        g.update(
            element_diameter=est.element_diameter,
            effective_length=est.effective_length,
            contact_angle=est.contact_angle,
        )
        notes.append("roller/raceway osculations: the builder's 0.98 (assumed; catalogues do not print them)")
    elif fam == "needle_roller":
        g.update(
            element_diameter=est.element_diameter,
            effective_length=est.effective_length,
            clearance_radial=clearance,
            inner_ring=est.extra["inner_ring"],
            construction="machined",
            profile={"name": "iso16281"},
        )
        notes.append("crowning: ISO/TS 16281 logarithmic profile (profile 'iso16281')")
        if not est.extra["inner_ring"]:
            g["bore"] = None  # no inner ring: the needles touch the shaft (F_w), nothing to fit inside
            notes.append(
                "no inner ring (RNA): the needles run on the shaft (F_w); the clearance then follows from "
                "the shaft tolerance (NSK E1102 B245 Table 6: CN with a g5 shaft for F_w <= 180 mm)"
            )
    elif fam == "thrust_ball":
        g.update(element_diameter=est.element_diameter, conformity=est.extra["conformity"])
    elif fam == "cylindrical_roller":
        g.update(
            element_diameter=est.element_diameter,
            effective_length=est.effective_length,
            clearance_radial=clearance,
            profile={"name": "iso16281"},
        )
        notes.append("crowning: ISO/TS 16281 logarithmic profile (profile 'iso16281')")
    elif fam == "double_row_cylindrical_roller":
        g.update(
            element_diameter=est.element_diameter,
            effective_length=est.effective_length,
            rows=2,
            row_spacing=est.extra["row_spacing"],
            clearance_radial=clearance,
            profile={"name": "iso16281"},
        )
        notes.append("crowning: ISO/TS 16281 logarithmic profile (profile 'iso16281')")
    elif fam == "thrust_cylindrical_roller":
        g.update(
            element_diameter=est.element_diameter,
            effective_length=est.effective_length,
            profile={"name": "iso16281"},
        )
        notes.append("crowning: ISO/TS 16281 logarithmic profile (profile 'iso16281')")
    elif fam == "tapered_roller":
        g.update(
            small_diameter=est.extra["small_diameter"],
            large_diameter=est.extra["large_diameter"],
            effective_length=est.effective_length,
            contact_angle_outer=est.contact_angle,
            contact_angle_inner=est.extra["contact_angle_inner"],
            roller_angle=est.extra["roller_angle"],
            clearance=0.0,
            n_slices=CATALOGUE_TAPERED_SLICES,
            profile={"name": "iso16281_tapered"},
        )
        notes.append(
            f"crowning: ISO/TS 16281 logarithmic profile of tapered rollers (profile 'iso16281_tapered'), "
            f"{CATALOGUE_TAPERED_SLICES} slices"
        )
    return g


def _clearance(est: Estimate, des, notes: list, position: float) -> float | None:
    """The clearance of the designation's class (CN when none), or None where the type has no group.

    Radial groups are ISO 5753-1's. Four-point (QJ) bearings are classed by their AXIAL clearance s_a; the
    row takes the diametral P_d, and its arches give s_a = P_d / tan α0 (rows.four_point: a ball closes a
    diagonal after P_d/2 radially or (P_d/2) cot α0 axially), so P_d = s_a tan α0.
    """
    e = est.entry
    group = clearance_mod.CLEARANCE_GROUP.get(des.family)
    if _tapered_bore(des) and des.family in clearance_mod.TAPERED_BORE_GROUP:
        group = clearance_mod.TAPERED_BORE_GROUP[des.family]
    cls = des.clearance_class or "CN"
    if des.clearance_class is not None and group is None:
        raise InputError(
            f"designation ({des.text!r}): clearance class {des.clearance_class} has no ISO 5753-1 radial "
            "group for this type; give clearance explicitly in [geometry]"
        )
    if group is None:
        return None
    value = clearance_mod.clearance(group, e.bore, cls, position)
    lo, hi = clearance_mod.clearance_range(group, e.bore, cls)
    if group in clearance_mod.AXIAL_GROUPS:
        radial = value * math.tan(est.contact_angle)
        notes.append(
            f"axial clearance {cls} ({clearance_mod.GROUP_SOURCES[group]}, {lo * 1e6:g}-{hi * 1e6:g} um): "
            f"{value * 1e6:.3g} um at {position:.0%} of the class range, i.e. P_d = s_a tan(alpha) = "
            f"{radial * 1e6:.3g} um"
        )
        return radial
    notes.append(
        f"radial clearance {cls} ({clearance_mod.GROUP_SOURCES[group]}, {lo * 1e6:g}–{hi * 1e6:g} um): "
        f"{value * 1e6:.3g} um at {position:.0%} of the class range"
    )
    return value


def _tapered_bore(des) -> bool:
    return des.tapered_bore is not None
