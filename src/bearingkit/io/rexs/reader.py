"""REXS import: a gearbox model in the FVA's open exchange format as a drivetrain dictionary.

REXS (Reusable Engineering EXchange Standard, rexs.info) version followed: 1.4 (XML; the JSON syntax of
1.5, which 1.4 files may use too). The model has ``components`` (each with an id, a type, a name and
attributes with units) and ``relations`` between them, and a ``load_spectrum`` of load cases that give
attributes per component. This reader turns one into the dictionary of a drivetrain TOML file
(docs/drivetrains.md), values with their units as text, so the same validation builds the model.

What is read (everything else is ignored; a part that cannot be modelled is refused with one line):

- ``shaft``: ``u_axis_vector`` (all shafts parallel), ``support_vector`` (where its u = 0 sits),
  ``defines_speed``; its ``shaft_section`` parts (assembly relation): ``u_coordinate_on_shaft``,
  ``length``, ``outer_diameter_begin/end``, ``inner_diameter_begin/end`` (cylindrical only); its
  ``material`` (reference relation): ``elastic_modulus``, ``poisson_ratio``, ``density``.
- bearings (``side`` relation: ``inner_part`` a shaft, ``outer_part`` a shaft or the ``gear_casing``):
  ``rolling_bearing_with_catalog_geometry`` (``catalogue_designation``: bearingkit's catalogue
  estimate, docs/catalogue.md), ``rolling_bearing_with_detailed_geometry`` (its rows and elements as
  an inline bearing file, :mod:`bearingkit.io.rexs.detailed`) and ``concept_bearing``
  (``radial_stiffness``, ``axial_stiffness``, ``bending_stiffness``: a linear bearing, at most
  bearingkit's rigid, :mod:`~bearingkit.io.rexs.parts`); ``u_coordinate_on_shaft_inner_side``/
  ``_outer_side``; ``axial_force_absorption`` (``no_direction``: floating, else locating).
- ``cylindrical_gear`` on a shaft: ``u_coordinate_on_shaft``, ``number_of_teeth`` (negative: internal),
  ``normal_module``, ``helix_angle_reference_diameter`` (signed: positive right hand; the axial
  gear forces this gives are FVA Workbench's, tests/systems/test_rexs_fva_workbench.py),
  ``face_width``; its flank (``flank`` relation, the left one): ``normal_pressure_angle``,
  ``addendum_modification_coefficient``; ``cylindrical_stage`` (``stage`` relation ``gear_1``,
  ``gear_2``) makes a mesh.
- ``external_load`` on a shaft: ``u_coordinate_on_shaft``; ``defines_torque`` true: its
  ``torque_around_u_axis`` is the input torque (or, without it, ``power``/ω of the shaft's
  ``rotational_speed``: REXS's P = T ω); ``transmits_torque`` true and ``defines_torque``
  false: its shaft is the held output; ``force_u/v/w_direction``, ``torque_around_v/w_axis``.
- the bearings' ``contamination_factor_according_to_iso_281_2007`` when they share one value (the
  ISO 281 e_C of every bearing: a_ISO and L_nm).
- ``lubricant``: ``viscosity_at_40_degree_celsius`` within ±10 % of an ISO VG grade (ISO 3448) gives
  bearingkit's preset of that grade.
- load cases: ``rotational_speed`` of the shaft that ``defines_speed``, the casing's
  ``temperature_lubricant``, the gear unit's ``load_duration_fraction`` (or its ``custom_`` form).

- a ``planetary_stage``: a ``[[planetary]]`` table (:mod:`bearingkit.io.rexs.planetary`); its planets,
  pins, side plates, held ring shaft and their couplings and meshes are the stage's, not shafts.
- the gear unit's ``account_for_gravity`` and ``direction_vector_gravity_u/v/w`` (along an axis).

Axes: u (the shafts' axis) is bearingkit's z; v = w × u and w of the gear unit are x and y. A shaft joined
to nothing (no bearing, coupling, gear or load) is left out, with a note; two coaxial shafts joined end to
end by a rigid coupling are read as one (:mod:`bearingkit.io.rexs.couplings`).
Refused: non-parallel shafts, conical sections, gear types other than
cylindrical (bevel, worm), more than one input speed, a planetary stage bearingkit's stage cannot stand for.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from bearingkit.errors import InputError
from bearingkit.io.rexs.couplings import merge_coupled_shafts
from bearingkit.io.rexs.detailed import rexs_bearing
from bearingkit.io.rexs.parse import _number, load_cases, parse, roles
from bearingkit.io.rexs.parts import collected_notes, direction, q_text, section_tables, vector_mm
from bearingkit.io.rexs.planetary import read_stage

SUPPORTED_VERSIONS = ("1.0", "1.1", "1.2", "1.3", "1.4", "1.5", "1.6")
_REFUSED_TYPES = {
    "bevel_gear": "a bevel gear (only cylindrical gears are modelled)",
    "worm_gear": "a worm gear (only cylindrical gears are modelled)",
    "worm_wheel": "a worm wheel (only cylindrical gears are modelled)",
}


#: Key of the returned dictionary holding the import's notes (not a drivetrain file field).
REXS_NOTES = "rexs_notes"
#: REXS gravity direction (u, v, w components) → the drivetrain file's ``gravity`` axis.
GRAVITY_AXES = {
    (0, 1, 0): "+x",
    (0, -1, 0): "-x",
    (0, 0, 1): "+y",
    (0, 0, -1): "-y",
    (1, 0, 0): "+z",
    (-1, 0, 0): "-z",
}


#: Power units → W.
POWER_W = {"W": 1.0, "kW": 1e3, "MW": 1e6}


def _torque_of_power(given: dict, load, shaft, speed_shaft: list, where: str) -> float:
    """T = P/ω [N·m] of an input given by its ``power`` (REXS: P = T ω, signed), on the shaft whose
    ``rotational_speed`` the load case gives; one InputError line otherwise."""
    value, unit = given[load]["power"]
    if unit not in POWER_W:
        raise InputError(f"{where}.power: unit {unit!r} is not a power unit ({', '.join(POWER_W)})")
    if shaft not in speed_shaft or "rotational_speed" not in given.get(shaft, {}):
        raise InputError(
            f"{where}: an input power without torque_around_u_axis needs its shaft's rotational_speed "
            "(T = P/ω): give the torque, or the speed on that shaft"
        )
    speed, speed_unit = given[shaft]["rotational_speed"]
    if speed_unit != "1 / min":
        raise InputError(f"{where}: rotational_speed in {speed_unit!r}; expected 1 / min")
    omega = _number(speed, f"{where}: rotational_speed") * 2.0 * np.pi / 60.0
    if omega == 0.0:
        raise InputError(f"{where}: an input power at zero speed gives no torque; give torque_around_u_axis")
    return _number(value, f"{where}.power") * POWER_W[unit] / omega


def read_rexs(path) -> dict:
    """The drivetrain dictionary of a REXS model (module docstring); one InputError line if refused."""
    path = Path(path)
    m = parse(path)
    src = str(path)
    if m.get("version") and m["version"] not in SUPPORTED_VERSIONS:
        raise InputError(
            f"{src}: REXS version {m['version']!r} is not read; bearingkit reads "
            f"{', '.join(SUPPORTED_VERSIONS)}"
        )
    comps = m["components"]
    for cid, c in comps.items():
        if c["type"] in _REFUSED_TYPES:
            raise InputError(
                f"{src}: component {cid} ({c['name']}): {_REFUSED_TYPES[c['type']]} is not supported"
            )
    notes = []
    collected = []  # concept bearings stiffer than bearingkit's rigid (one note, at the end)
    stage = read_stage(m, src, notes, collected)  # a planetary stage: its planets, pins, ring … are taken
    taken = stage["taken"] if stage else set()
    keep = {stage["carrier"], stage["sun_shaft"]} if stage else set()
    m = merge_coupled_shafts(m, src, taken, notes, keep)  # shafts joined by rigid couplings: one shaft
    comps = m["components"]
    parts = {}
    for r in m["relations"]:
        if r["type"] == "assembly":
            ro = roles(r)
            parts.setdefault(ro.get("assembly"), []).append(ro.get("part"))
    joined = set()  # parts of a relation besides their own sections: bearings, couplings, gears, loads
    for r in m["relations"]:
        if r["type"] not in ("assembly", "ordered_assembly", "reference"):  # a material joins nothing
            joined |= {i for i, _ in r["refs"]}
    shafts = []
    for i, c in comps.items():
        if c["type"] != "shaft" or i in taken:
            continue
        if i not in joined and not any(comps[p]["type"] != "shaft_section" for p in parts.get(i, [])):
            notes.append(f"shaft {i} ({c['name']}) is joined to nothing (no bearing, gear or load): left out")
            continue
        shafts.append(i)
    if not shafts:
        raise InputError(f"{src}: no shaft component")
    unit = next((c for c in comps.values() if c["type"] == "gear_unit"), None)
    u = direction(comps[shafts[0]]["attrs"], "u_axis_vector", f"{src}: shaft {shafts[0]}", [1.0, 0.0, 0.0])
    if np.linalg.norm(u) == 0.0:
        raise InputError(f"{src}: shaft {shafts[0]}.u_axis_vector is zero")
    u /= np.linalg.norm(u)
    w_ref = direction((unit or {"attrs": {}})["attrs"], "w_axis_vector", f"{src}: gear_unit", [0.0, 0.0, 1.0])
    w = w_ref - (w_ref @ u) * u
    if np.linalg.norm(w) < 1e-9:
        w = np.array([0.0, 1.0, 0.0]) - u[1] * u
    w /= np.linalg.norm(w)
    v = np.cross(w, u)
    materials = {}
    for r in m["relations"]:
        if r["type"] == "reference":
            ro = roles(r)
            materials[ro.get("origin")] = ro.get("referenced")
    names = {i: comps[i]["name"] or f"shaft {i}" for i in shafts}
    out_shafts, gear_names, gear_shaft = [], {}, {}
    for i in shafts:
        c = comps[i]
        where = f"{src}: shaft {i} ({c['name']})"
        ax = direction(c["attrs"], "u_axis_vector", where, u)
        if abs(abs(ax @ u) / np.linalg.norm(ax) - 1.0) > 1e-9:
            raise InputError(
                f"{where}: its axis {ax.tolist()} is not parallel to the others' {u.tolist()}: "
                "non-parallel shafts (bevel, worm stages) are not supported"
            )
        support = vector_mm(c["attrs"], "support_vector", where)
        if support is None:  # placed by its relations (a planetary stage: on its axis), else at the origin
            support = (
                stage["across"] + u * stage["offsets"][i] if stage and i in stage["offsets"] else 0.0 * u
            )
        sections = section_tables(comps, parts, i, 0.0, where)
        if stage and i == stage["carrier"]:
            sections = sorted(
                sections + stage["carrier_sections"], key=lambda s: float(s["start"].split()[0])
            )
        if not sections:
            raise InputError(f"{where}: no shaft_section parts")
        shaft = {
            "name": names[i],
            "centre": [f"{support @ v} mm", f"{support @ w} mm"],
            "axial_offset": f"{support @ u} mm",
            "sections": sections,
            "bearings": [],
            "gears": [],
        }
        mat = materials.get(i)
        if mat is not None and comps[mat]["type"] == "material":
            a = comps[mat]["attrs"]
            mw = f"{where}: material {mat}"
            shaft["material"] = {
                "youngs_modulus": q_text(a, "elastic_modulus", mw),
                "poisson_ratio": _number(a.get("poisson_ratio", (None, ""))[0], f"{mw}.poisson_ratio"),
                "density": q_text(a, "density", mw),
            }
        for p in parts.get(i, []):
            if comps[p]["type"] == "cylindrical_gear":
                gear_names[p] = comps[p]["name"] or f"gear {p}"
                gear_shaft[p] = i
        out_shafts.append(shaft)
    by_id = dict(zip(shafts, out_shafts, strict=True))
    flank = {}
    for r in m["relations"]:
        if r["type"] == "flank":
            ro = roles(r)
            flank[ro.get("gear")] = ro.get("left") or ro.get("right")
    for gid, sid in gear_shaft.items():
        a = comps[gid]["attrs"]
        gw = f"{src}: cylindrical_gear {gid} ({gear_names[gid]})"
        teeth = (
            int(_number(a["number_of_teeth"][0], f"{gw}.number_of_teeth")) if "number_of_teeth" in a else None
        )
        if teeth is None:
            raise InputError(f"{gw}: attribute 'number_of_teeth' missing")
        beta = _number(
            a.get("helix_angle_reference_diameter", (0.0, "deg"))[0], f"{gw}.helix_angle_reference_diameter"
        )
        fa = comps[flank[gid]]["attrs"] if gid in flank else {}
        gear = {
            "name": gear_names[gid],
            "position": q_text(a, "u_coordinate_on_shaft", gw),
            "teeth": abs(teeth),
            "normal_module": q_text(a, "normal_module", gw),
            "helix_angle": f"{abs(beta)} deg",
            "hand": "right" if beta >= 0 else "left",
            "face_width": q_text(a, "face_width", gw),
            "internal": teeth < 0,
        }
        if "normal_pressure_angle" in fa:
            gear["pressure_angle"] = q_text(fa, "normal_pressure_angle", gw)
        if "addendum_modification_coefficient" in fa:
            gear["profile_shift"] = _number(
                fa["addendum_modification_coefficient"][0], f"{gw}: flank.addendum_modification_coefficient"
            )
        by_id[sid]["gears"].append(gear)
    meshes = []
    for r in m["relations"]:
        if r["type"] == "stage":
            ro = roles(r)
            g1, g2 = ro.get("gear_1"), ro.get("gear_2")
            if ro.get("stage") in taken:  # a planetary stage's mesh: the stage makes its own
                continue
            if g1 not in gear_names or g2 not in gear_names:
                raise InputError(
                    f"{src}: stage {ro.get('stage')}: gears {g1}, {g2} are not cylindrical gears on shafts"
                )
            meshes.append(
                {
                    "name": comps[ro["stage"]]["name"] or f"stage {ro['stage']}",
                    "gears": [gear_names[g1], gear_names[g2]],
                }
            )
    for r in m["relations"]:
        if r["type"] != "side":
            continue
        ro = roles(r)
        bid, inner, outer = ro.get("assembly"), ro.get("inner_part"), ro.get("outer_part")
        if bid in taken:  # a planet bearing, or a coupling of a planetary stage's carrier or ring
            continue
        c = comps[bid]
        bw = f"{src}: bearing {bid} ({c['name']})"
        if inner not in by_id:
            raise InputError(f"{bw}: its inner part {inner} is not a shaft")
        position = q_text(c["attrs"], "u_coordinate_on_shaft_inner_side", bw)
        bearing = rexs_bearing(m, bid, c["name"] or f"bearing {bid}", bw, position, notes, collected)
        if outer in by_id:
            bearing["outer"] = by_id[outer]["name"]
            bearing["outer_position"] = q_text(c["attrs"], "u_coordinate_on_shaft_outer_side", bw)
        by_id[inner]["bearings"].append(bearing)
    held, inputs, loads_at = None, {}, {}
    for sid in taken:
        for p in parts.get(sid, []):
            if comps[p]["type"] == "external_load":
                raise InputError(
                    f"{src}: external_load {p} ({comps[p]['name']}) sits on {comps[sid]['type']} {sid} "
                    f"({comps[sid]['name']}), a part of the planetary stage bearingkit does not model as a "
                    "shaft (a planet, pin or the held ring)"
                )
    for sid in shafts:
        for p in parts.get(sid, []):
            if comps[p]["type"] != "external_load":
                continue
            a = comps[p]["attrs"]
            loads_at[p] = (
                sid,
                q_text(a, "u_coordinate_on_shaft", f"{src}: external_load {p}", False) or "0 mm",
            )
            if a.get("defines_torque", (False, ""))[0] is True:
                inputs[p] = sid
            elif a.get("transmits_torque", (False, ""))[0] is True:
                held = by_id[sid]["name"]
    speed_shaft = [sid for sid in shafts if comps[sid]["attrs"].get("defines_speed", (False, ""))[0] is True]
    if len(speed_shaft) > 1:
        raise InputError(f"{src}: more than one shaft defines the speed; bearingkit takes one input speed")
    casing = [i for i, c in comps.items() if c["type"] == "gear_casing"]
    unit_id = next((i for i, c in comps.items() if c["type"] == "gear_unit"), None)
    if not m["load_cases"]:  # the operating values sit on the components themselves (REXS 1.0)
        notes.append(
            "the model has no load_spectrum: its one load case is read from the components' attributes"
        )
    cases = []
    for name, given in load_cases(m):
        case = {
            "name": name,
            "torques": {},
            "forces": [],
        }
        cw = f"{src}: {name}"
        for p, sid in inputs.items():
            if p in given and "torque_around_u_axis" in given[p]:
                case["torques"][by_id[sid]["name"]] = q_text(given[p], "torque_around_u_axis", cw)
            elif p in given and "power" in given[p]:  # FVA Workbench writes the input power as well
                torque = _torque_of_power(given, p, sid, speed_shaft, f"{cw}: external_load {p}")
                case["torques"][by_id[sid]["name"]] = f"{torque} N*m"
        for p, (sid, pos) in loads_at.items():
            a = given.get(p, {})
            vals = {
                key: a[key]
                for key in (
                    "force_u_direction",
                    "force_v_direction",
                    "force_w_direction",
                    "torque_around_v_axis",
                    "torque_around_w_axis",
                )
                if key in a
            }
            if any(_number(x[0], f"{cw}: external_load {p}.{key}") != 0.0 for key, x in vals.items()):
                f = {"shaft": by_id[sid]["name"], "name": comps[p]["name"] or f"load {p}", "position": pos}
                for key, field in (
                    ("force_v_direction", "F_x"),
                    ("force_w_direction", "F_y"),
                    ("force_u_direction", "F_z"),
                    ("torque_around_v_axis", "M_x"),
                    ("torque_around_w_axis", "M_y"),
                ):
                    if key in vals:
                        f[field] = q_text(vals, key, cw)
                case["forces"].append(f)
        if speed_shaft and "rotational_speed" in given.get(speed_shaft[0], {}):
            case["speed"] = {
                by_id[speed_shaft[0]]["name"]: q_text(given[speed_shaft[0]], "rotational_speed", cw)
            }
        for cid in casing:
            if "temperature_lubricant" in given.get(cid, {}):
                case["temperature"] = q_text(given[cid], "temperature_lubricant", cw)
        ua = given.get(unit_id, {})
        for key in ("load_duration_fraction", "custom_load_duration_fraction"):
            if key in ua:
                value, share_unit = ua[key]
                if share_unit not in ("%", "none", ""):
                    raise InputError(f"{cw}: {key} in {share_unit!r}; expected % (or a fraction, no unit)")
                share = _number(value, f"{cw}: {key}")
                case["time_fraction"] = share / 100.0 if share_unit == "%" else share
        cases.append(case)
    fractions = [c.get("time_fraction") for c in cases]
    if all(f is not None for f in fractions) and sum(fractions) > 0:
        for c in cases:
            c["time_fraction"] = c["time_fraction"] / sum(fractions)
    else:
        for c in cases:
            c.pop("time_fraction", None)
    out = {}
    for c in comps.values():  # an ISO VG oil: bearingkit's preset of that grade (friction, κ, L_nm)
        if c["type"] == "lubricant" and "viscosity_at_40_degree_celsius" in c["attrs"]:
            nu40 = _number(
                c["attrs"]["viscosity_at_40_degree_celsius"][0],
                f"{src}: lubricant.viscosity_at_40_degree_celsius",
            )
            grade = min((32, 46, 68, 100, 150, 220), key=lambda g: abs(g - nu40))
            if abs(grade - nu40) <= 0.1 * grade:  # ISO 3448: a grade spans ±10 % of its mid-point
                out["lubricant"] = {"name": f"ISO_VG{grade}"}
    e_c = {
        _number(
            c["attrs"]["contamination_factor_according_to_iso_281_2007"][0],
            f"{src}: {c['name']}.contamination_factor",
        )
        for c in comps.values()
        if "contamination_factor_according_to_iso_281_2007" in c["attrs"]
    }
    if len(e_c) == 1:  # one ISO 281 e_C for every bearing: the file's [lubrication] contamination
        out["lubrication"] = {"contamination": e_c.pop()}
    if held is None:
        raise InputError(
            f"{src}: no output: give an external_load with transmits_torque true and defines_torque false"
        )
    notes = list(dict.fromkeys(notes + collected_notes(collected)))  # a planet's note once, not per planet
    if notes:  # said on every face of the result (load_drivetrain_file takes them out of the data)
        out[REXS_NOTES] = [f"REXS import: {n}" for n in notes]
    drivetrain = {"name": (unit or {}).get("name") or path.stem, "held": held}
    ua = (unit or {"attrs": {}})["attrs"]
    if ua.get("account_for_gravity", (False, ""))[0] is True:
        g = np.array(
            [
                _number(
                    ua.get(f"direction_vector_gravity_{k}", (0.0, ""))[0], f"{src}: gear_unit gravity {k}"
                )
                for k in "uvw"
            ]
        )
        unit_g = g / np.linalg.norm(g) if np.linalg.norm(g) > 0 else g
        along = np.abs(unit_g).max(initial=0.0) > 1 - 1e-9  # an axis, whatever the vector's length
        axis = tuple(int(np.rint(x)) for x in unit_g) if along else None
        if axis not in GRAVITY_AXES:
            raise InputError(
                f"{src}: gear_unit direction_vector_gravity {tuple(g.tolist())} (u, v, w) is not along an "
                "axis; bearingkit's gravity acts along x (v), y (w) or z (u)"
            )
        drivetrain["gravity"] = GRAVITY_AXES[axis]
    if stage:  # the sun and carrier by their names in the drivetrain file
        table = dict(stage["table"], sun=gear_names[stage["table"]["sun"]], carrier=names[stage["carrier"]])
        out["planetary"] = [table]
    return {
        "drivetrain": drivetrain,
        "shafts": out_shafts,
        "meshes": meshes,
        "load_cases": cases,
        **out,
    }
