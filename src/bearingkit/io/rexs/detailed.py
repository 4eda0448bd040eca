"""REXS bearings with detailed geometry: a ``rolling_bearing_with_detailed_geometry`` as a bearing file.

The REXS attribute database (REXS 1.1–1.6; ``api/src/main/resources/info/rexs/db/rexs_model_1.5_en.xml``
and ``RexsStandardAttributeIds.java`` of fva-net/rexs-api-java, read 2026-11) puts a bearing's internal
geometry on its parts (``assembly`` relations): each ``rolling_bearing_row`` gives
``number_of_rolling_elements``, ``reference_diameter`` (the pitch diameter D_pw), ``pressure_angle`` (the
nominal contact angle α), ``raceway_radius_of_inner_ring`` and ``raceway_radius_of_outer_ring``; each
row's ``rolling_element`` gives ``diameter_of_rolling_element``, ``length_of_rolling_element`` and
``roller_crowning_radius``; the bearing itself ``bearing_type``, ``inner_diameter``, ``outer_diameter``,
``width``, ``number_of_bearing_rows`` and the clearances. REXS 1.0 spells some differently
(``running_path_radius_of_inner_ring``/``_outer_ring``, ``roller_shell_radius``): both are read.

They become the ``[bearing]`` and ``[geometry]`` tables of a bearing file (docs/input-format.md), given
inline in the drivetrain file's bearing (``bearing = {...}``):

=================================  =====================  ========================================
REXS ``bearing_type``              bearingkit ``type``    geometry read
=================================  =====================  ========================================
``radial_grooved_ball_bearing``    ``deep_groove_ball``   Z, D_w, D_pw, f_i = R_i/D_w, f_o = R_o/D_w,
                                                          diametral clearance
``angular_contact_ball_bearing``   ``angular_contact_     as above and α (the clearance along the
                                   ball``                 contact line is taken as zero)
``radial_roller_bearing``          ``cylindrical_roller`` Z, D_w, L_we, D_pw, clearance, a full crown
                                                          of the crowning radius (else ISO/TS 16281's
                                                          logarithmic profile)
``radial_needle_roller_bearing``   ``needle_roller``      as cylindrical
``radial_tapered_roller_bearing``  ``tapered_roller``     Z, D_w ∓ L tan γ, L, D_pw, α_o, α_i = α_o −
                                                          2γ (:func:`_tapered`), clearance zero
=================================  =====================  ========================================

The radial clearance is ``radial_bearing_clearance`` (before mounting), else the middle of
``minimum_``/``maximum_radial_bearing_clearance``, else zero (said in a note); the mounted and operating
clearances are results of the writing tool and are not read. One row only (a bearing of several rows,
or another kind, is read by its ``catalogue_designation`` where bearingkit knows it, else refused in one
line). The file's radial ratings (``radial_dynamic_load_rating``, ``radial_static_load_rating``; REXS 1.0
``dynamic_capacity``, ``static_capacity``) are the lives' C and C0 (``[bearing] rating_C``, ``rating_C0``),
as a designation's catalogue ratings are; without them bearingkit rates the geometry (ISO 281, ISO 76).
"""

from __future__ import annotations

import math

from bearingkit.catalogue.resolve import CATALOGUE_TAPERED_SLICES
from bearingkit.errors import InputError
from bearingkit.io.rexs.parse import roles
from bearingkit.io.rexs.parts import TO_UM, angle_deg, bearing_table, file_ratings, mm, number, scaled

#: REXS ``bearing_type`` → (bearingkit ``type``, whether its rows are rollers).
KINDS = {
    "radial_grooved_ball_bearing": ("deep_groove_ball", False),
    "angular_contact_ball_bearing": ("angular_contact_ball", False),
    "radial_roller_bearing": ("cylindrical_roller", True),
    "radial_needle_roller_bearing": ("needle_roller", True),
    "radial_tapered_roller_bearing": ("tapered_roller", True),
}
#: REXS 1.0 names of attributes REXS 1.1 renamed (the changelog 1.0 → 1.1).
OLD_NAMES = {
    "raceway_radius_of_inner_ring": "running_path_radius_of_inner_ring",
    "raceway_radius_of_outer_ring": "running_path_radius_of_outer_ring",
    "roller_crowning_radius": "roller_shell_radius",
}


def _get(attrs: dict, key: str):
    """The attribute under its REXS 1.1+ name or its REXS 1.0 one, None when neither is there."""
    for name in (key, OLD_NAMES.get(key)):
        if name in attrs:
            return name
    return None


def _length(attrs, key, where, default=None) -> float:
    name = _get(attrs, key)
    if name is None:
        if default is None:
            raise InputError(f"{where}: attribute {key!r} missing")
        return default
    return mm(attrs, name, where)


def _parts(m, owner, kind) -> list:
    out = []
    for r in m["relations"]:
        if r["type"] in ("assembly", "ordered_assembly"):
            ro = roles(r)
            part = ro.get("part")
            if ro.get("assembly") == owner and (m["components"].get(part) or {}).get("type") == kind:
                out.append(part)
    return out


def detailed_bearing(m, bid, where: str, notes: list, collected: list) -> dict | None:
    """A bearing file's tables ({"bearing": …, "geometry": …}) for the detailed bearing ``bid``, or None
    where its kind or rows are not read from geometry (the caller then tries its designation)."""
    comp = m["components"][bid]
    a = comp["attrs"]
    kind = str(a.get("bearing_type", ("", ""))[0])
    rows = _parts(m, bid, "rolling_bearing_row")
    if kind not in KINDS or len(rows) != 1:
        return None
    btype, rollers = KINDS[kind]
    row = rows[0]
    ra, rw = m["components"][row]["attrs"], f"{where}: rolling_bearing_row {row}"
    elements = _parts(m, row, "rolling_element")
    if not elements:
        raise InputError(f"{rw}: no rolling_element part (its diameter and length)")
    ea, ew = m["components"][elements[0]]["attrs"], f"{where}: rolling_element {elements[0]}"
    d_w = _length(ea, "diameter_of_rolling_element", ew)
    if not d_w > 0.0:
        raise InputError(f"{ew}.diameter_of_rolling_element: {d_w:g} mm must be positive")
    count = number(ra, "number_of_rolling_elements", rw)
    if count != int(count) or count < 3:
        raise InputError(f"{rw}.number_of_rolling_elements: {count:g} is not a count of 3 or more")
    geometry = {
        "bore": f"{_length(a, 'inner_diameter', where)} mm",
        "outer_diameter": f"{_length(a, 'outer_diameter', where)} mm",
        "n_elements": int(count),
        "element_diameter": f"{d_w} mm",
        "pitch_diameter": f"{_length(ra, 'reference_diameter', rw)} mm",
    }
    clearance = _clearance(a, where, notes, comp["name"])
    if btype == "tapered_roller":
        geometry.update(_tapered(ra, rw, ea, ew, d_w))
        geometry.pop("element_diameter")
        if clearance:
            notes.append(
                f"{comp['name']}: its radial clearance ({clearance:g} µm) is not read: a tapered row's "
                "clearance is along its cup normal (taken as zero)"
            )
    elif rollers:
        geometry["effective_length"] = f"{_length(ea, 'length_of_rolling_element', ew)} mm"
        geometry["clearance_radial"] = f"{clearance} um"
        crown = _get(ea, "roller_crowning_radius")
        if crown is not None and mm(ea, crown, ew) > 0.0:
            geometry["profile"] = {"name": "full_crown", "crown_radius": f"{mm(ea, crown, ew)} mm"}
        else:
            geometry["profile"] = {"name": "iso16281"}
    else:
        for side in ("inner", "outer"):
            name = _get(ra, f"raceway_radius_of_{side}_ring")
            if name is None:
                raise InputError(
                    f"{rw}: attribute 'raceway_radius_of_{side}_ring' missing (the groove radius)"
                )
            geometry[f"conformity_{side}"] = mm(ra, name, rw) / d_w
        if btype == "deep_groove_ball":
            geometry["clearance_radial"] = f"{clearance} um"
        else:
            geometry["contact_angle"] = f"{angle_deg(ra, 'pressure_angle', rw)} deg"
            if clearance:
                notes.append(
                    f"{comp['name']}: its radial clearance ({clearance:g} µm) is not read: an angular "
                    "contact row's clearance is along its contact line (taken as zero)"
                )
    header = {"type": btype, "name": comp["name"], "source": f"REXS detailed geometry ({where})"}
    ratings = file_ratings(a, where)
    if ratings is not None:  # the maker's ratings the file gives: the lives use them
        header["rating_C"] = f"{ratings[0]} kN"
        if ratings[1] is not None:
            header["rating_C0"] = f"{ratings[1]} kN"
        collected.append(("rated", comp["name"], ratings))
    return {"bearing": header, "geometry": geometry}


def _clearance(a: dict, where: str, notes: list, name: str) -> float:
    """Radial (diametral) clearance before mounting [µm] (module docstring)."""
    if "radial_bearing_clearance" in a:
        return scaled(a, "radial_bearing_clearance", where, TO_UM, "a length")
    keys = [
        _get(a, f"{k}_radial_bearing_clearance") or f"{k}_bearing_clearance" for k in ("minimum", "maximum")
    ]
    if all(k in a for k in keys):
        return 0.5 * (
            scaled(a, keys[0], where, TO_UM, "a length") + scaled(a, keys[1], where, TO_UM, "a length")
        )
    notes.append(f"{name}: no radial clearance before mounting in the file: zero")
    return 0.0


def rexs_bearing(m, bid, name: str, where: str, position: str, notes: list, collected: list) -> dict:
    """The drivetrain file's table of the REXS bearing ``bid`` (:func:`bearing_table`), a bearing with
    detailed geometry read from its rows where it can be (:func:`detailed_bearing`)."""
    comp = m["components"][bid]
    tables = None
    if comp["type"] == "rolling_bearing_with_detailed_geometry":
        tables = detailed_bearing(m, bid, where, notes, collected)
    return bearing_table(comp, name, where, position, notes, collected, tables)


def _tapered(ra: dict, rw: str, ea: dict, ew: str, d_w: float) -> dict:
    """A tapered row's geometry: the cup angle α_o = ``pressure_angle`` (ISO 281's nominal contact angle),
    the roller's half cone angle γ = ``roller_angle``, its mean diameter D_w = ``diameter_of_rolling_element``
    and effective length L = ``length_of_rolling_element`` [the database does not say which diameter and
    length: mean and effective are read, as ISO 281's D_we and L_we], so the ends are D_w ∓ L tan γ and the
    cone angle α_i = α_o − 2γ; the crown ISO/TS 16281's (``iso16281_tapered``)."""
    length = _length(ea, "length_of_rolling_element", ew)
    gamma = math.radians(angle_deg(ea, "roller_angle", ew))
    alpha = math.radians(angle_deg(ra, "pressure_angle", rw))
    if not 0.0 <= gamma < alpha:
        raise InputError(f"{ew}.roller_angle: {math.degrees(gamma):g} deg must lie in [0, pressure_angle)")
    half = length * math.tan(gamma)
    if half >= d_w:
        raise InputError(f"{ew}: the roller's ends D_w ∓ L tan γ reach zero; check its diameter and angle")
    return {
        "small_diameter": f"{d_w - half} mm",
        "large_diameter": f"{d_w + half} mm",
        "effective_length": f"{length} mm",
        "contact_angle_outer": f"{math.degrees(alpha)} deg",
        "contact_angle_inner": f"{math.degrees(alpha - 2.0 * gamma)} deg",
        "roller_angle": f"{math.degrees(gamma)} deg",
        "clearance": "0 um",
        "profile": {"name": "iso16281_tapered"},
        "n_slices": CATALOGUE_TAPERED_SLICES,  # as a catalogue tapered row (the builder's default is 1)
    }
