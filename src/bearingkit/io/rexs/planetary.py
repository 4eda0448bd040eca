"""REXS planetary stages: a ``planetary_stage`` read as a ``[[planetary]]`` table of a drivetrain file.

A REXS planetary stage (REXS 1.1–1.4 as FVA Workbench writes it; the public example is
examples/rexs/FVA_Planetary_stage_-_Minus_gearing_1.1.rexsj) is a ``planetary_stage`` component with
relations ``central_shaft`` (the sun's shaft, the ring's shaft), ``planet_shaft`` (one per planet) and
``planet_carrier_shaft``; a ``cylindrical_stage`` (relation ``stage``) for every sun–planet and
planet–ring mesh, each with ``rotating_angle_around_neg_u_axis``; each planet turns on bearings whose
inner part is a pin (a ``shaft``) and outer part the planet; pins, side plates (``side_plate``) and
carrier shafts are joined by couplings into the carrier. bearingkit's stage (docs/drivetrains.md) is
read from it so:

- sun: the ``cylindrical_gear`` of a central shaft meshing with the planets; ring: the ``ring_gear``,
  held in the housing when its shaft sits on couplings to the ``gear_casing`` only (a ring turning in
  bearings, or loaded, is refused in one line);
- carrier: the ``planet_carrier_shaft`` on bearings; another carrier shaft that bears and carries
  nothing is part of the rigid carrier and left out; pins are rigid arms of the carrier, the couplings
  joining pins, side plates and carrier shafts rigid (their 10²⁰–10²³ stiffnesses in the public file);
- planets: identical (teeth, module, body, bearings) and equally spaced, planet i at
  ψ_i = −(``rotating_angle_around_neg_u_axis`` of its sun–planet mesh) about +u from v [the angle's zero
  direction is from memory of FVA Workbench's models, not confirmed: it turns the whole stage only];
- axial places: a part without a ``support_vector`` is placed by the relations that join two parts at
  given coordinates: bearings and couplings (``u_coordinate_on_shaft_inner_side`` on the inner part is
  ``_outer_side`` on the outer) and meshes (the two gears' ``u_coordinate_on_shaft`` mid-planes
  coincide); parts with a ``support_vector`` keep its u;
- a carrier shaft that ends before the planets' mid-plane (FVA's two-plate carrier: the shaft stops at
  the first side plate, pins bridge to the second) is extended to its farthest side plate by a tube of
  the side plates' diameters: the cage of plates and pins as one stiff body (said in a note).
"""

from __future__ import annotations

import numpy as np

from bearingkit.errors import InputError
from bearingkit.io.rexs.detailed import rexs_bearing
from bearingkit.io.rexs.parse import _number, roles
from bearingkit.io.rexs.parts import angle_deg, mm, number, q_text, section_tables, shaft_axis, vector_mm

#: Component types that are bodies with their own u coordinate (placed by the relations).
BODIES = ("shaft", "side_plate")
#: Component types of the couplings that join the carrier's parts and hold the ring.
COUPLINGS = ("coupling", "switchable_coupling")
#: Places that must agree when two paths of relations reach one part [mm].
PLACE_TOL_MM = 1e-3


def _type(comps, i) -> str:
    return (comps.get(i) or {}).get("type") or ""


def axial_offsets(m, src: str, root, mesh_gears=None) -> dict:
    """u offset [mm] of every body reachable through bearings, couplings and meshes (module docstring).

    Bodies with a ``support_vector`` are seeded with its u component (``root`` at 0 where none has one)
    and keep it; the others take the place the relations give. Meshes place only where one gear is in
    ``mesh_gears`` (a planetary stage's; ordinary stages may have offset mid-planes); one InputError
    line where two paths place a body differently.
    """
    comps = m["components"]
    part_of = {}
    for r in m["relations"]:
        if r["type"] == "assembly":
            ro = roles(r)
            part_of[ro.get("part")] = ro.get("assembly")
    edges = {}

    def join(a, ua, b, ub, where):  # o[a] + ua = o[b] + ub
        edges.setdefault(a, []).append((b, ua - ub, where))
        edges.setdefault(b, []).append((a, ub - ua, where))

    for r in m["relations"]:
        ro = roles(r)
        if r["type"] == "side":
            a, inner, outer = ro.get("assembly"), ro.get("inner_part"), ro.get("outer_part")
            if _type(comps, inner) in BODIES and _type(comps, outer) in BODIES:
                at, where = comps[a]["attrs"], f"{src}: {_type(comps, a)} {a} ({comps[a]['name']})"
                if "u_coordinate_on_shaft_inner_side" not in at:
                    continue  # a joint at no given place (FVA's carrier web): places nothing
                ui = mm(at, "u_coordinate_on_shaft_inner_side", where)
                join(inner, ui, outer, mm(at, "u_coordinate_on_shaft_outer_side", where, ui), where)
        elif r["type"] == "stage":
            g1, g2 = ro.get("gear_1"), ro.get("gear_2")
            b1, b2 = part_of.get(g1), part_of.get(g2)
            if mesh_gears is not None and not {g1, g2} & set(mesh_gears):
                continue
            if _type(comps, b1) in BODIES and _type(comps, b2) in BODIES:
                where = f"{src}: stage {ro.get('stage')}"
                join(
                    b1,
                    mm(comps[g1]["attrs"], "u_coordinate_on_shaft", f"{where}: gear {g1}"),
                    b2,
                    mm(comps[g2]["attrs"], "u_coordinate_on_shaft", f"{where}: gear {g2}"),
                    where,
                )
    axis = shaft_axis(m, src, root)
    offsets = {}
    for i, c in comps.items():
        if c["type"] in BODIES:
            v = vector_mm(c["attrs"], "support_vector", f"{src}: {c['type']} {i}")
            if v is not None:
                offsets[i] = float(v @ axis)  # the u part (the stage's shafts lie along u)
    seeded = set(offsets)
    if not offsets:
        offsets[root] = 0.0
    queue = list(offsets)
    while queue:
        n = queue.pop()
        for other, delta, where in edges.get(n, []):
            o = offsets[n] + delta
            if other not in offsets:
                offsets[other] = o
                queue.append(other)
            elif other not in seeded and abs(offsets[other] - o) > PLACE_TOL_MM:
                raise InputError(
                    f"{where}: places {comps[other]['type']} {other} ({comps[other]['name']}) at u = "
                    f"{o:.6g} mm where other relations put it at {offsets[other]:.6g} mm"
                )
    return offsets


def _alike(table):
    """A planet's table without what names it (its bearings' names and sources: FVA names each planet's
    copy "… @ angle", an unnamed bearing is named by its id), to compare the planets."""
    if isinstance(table, dict):
        return {k: _alike(v) for k, v in table.items() if k not in ("name", "source")}
    if isinstance(table, (list, tuple)):
        return [_alike(v) for v in table]
    return table


def _flank_shift(m, gear) -> float:
    for r in m["relations"]:
        ro = roles(r)
        if r["type"] == "flank" and ro.get("gear") == gear:
            fa = m["components"][ro.get("left") or ro.get("right")]["attrs"]
            if "addendum_modification_coefficient" in fa:
                return _number(fa["addendum_modification_coefficient"][0], f"flank of gear {gear}")
    return 0.0


def _carrier_extension(comps, parts, carrier, offsets, plates, webs, position, half, cw, notes) -> list:
    """Sections that extend the carrier shaft over its side plates to the planets (module docstring).

    Along u from the shaft's end: each side plate as a section of its diameters, the gaps between them
    as the web shaft's section (a shaft coupled to the carrier at no given place) or, without one, a
    tube of the side plates' diameters; down from the shaft's start the same, mirrored. Nothing where
    the shaft already spans the planets and plates.
    """
    own = section_tables(comps, parts, carrier, 0.0, cw)
    if not own:
        raise InputError(f"{cw}: no shaft_section parts")
    lo = min(float(s["start"].split()[0]) for s in own)
    hi = max(float(s["start"].split()[0]) + float(s["length"].split()[0]) for s in own)
    pieces = []  # (start, end, outer, inner) [mm] of each side plate
    for p in plates:
        a, pw = comps[p]["attrs"], f"{cw}: side plate {p}"
        if p not in offsets:
            raise InputError(
                f"{pw} ({comps[p]['name']}): joined to nothing that places it (couplings at given u)"
            )
        start = offsets[p] - offsets[carrier]
        pieces.append(
            (
                start,
                start + mm(a, "length", pw),
                mm(a, "outer_diameter", pw),
                mm(a, "inner_diameter", pw, 0.0),
            )
        )
    if webs:
        w = section_tables(comps, parts, webs[0], 0.0, f"{cw}: web shaft {webs[0]}")
        if not w:
            raise InputError(
                f"{cw}: web shaft {webs[0]} ({comps[webs[0]]['name']}) has no shaft_section parts"
            )
        fill = (float(w[0]["outer_diameter"].split()[0]), float(w[0]["inner_diameter"].split()[0]))
        what = f"the web shaft {comps[webs[0]]['name']}'s section"
    elif pieces:
        fill, what = pieces[0][2:], "a tube of the side plates' diameters"
    else:
        fill = (float(own[-1]["outer_diameter"].split()[0]), float(own[-1]["inner_diameter"].split()[0]))
        what = "its own last section"
    top = max([position + half] + [e for _, e, _, _ in pieces])
    bottom = min([position - half] + [s for s, _, _, _ in pieces])
    out = []

    def add(a, b, diameters):
        if b - a > PLACE_TOL_MM:
            out.append(
                {
                    "start": f"{a} mm",
                    "length": f"{b - a} mm",
                    "outer_diameter": f"{diameters[0]} mm",
                    "inner_diameter": f"{diameters[1]} mm",
                }
            )

    cursor = hi
    for s0, e0, do, di in sorted(pieces):
        if e0 > cursor + PLACE_TOL_MM:
            add(cursor, s0, fill)
            add(max(s0, cursor), e0, (do, di))
            cursor = e0
    add(cursor, top, fill)
    cursor = lo
    for s0, e0, do, di in sorted(pieces, reverse=True):
        if s0 < cursor - PLACE_TOL_MM:
            add(e0, cursor, fill)
            add(s0, min(e0, cursor), (do, di))
            cursor = s0
    add(bottom, cursor, fill)
    if out:
        notes.append(
            f"carrier shaft {comps[carrier]['name']} ({lo:.6g}–{hi:.6g} mm) ends before the planets' "
            f"mid-plane ({position:.6g} mm): extended to {min(lo, bottom):.6g}–{max(hi, top):.6g} mm by its "
            "side plates and, "
            f"between them, {what}, all of the carrier shaft's material (a web's own material is not "
            "kept): the carrier's parts joined rigidly, as its couplings' stiffnesses say"
        )
    return out


def read_stage(m, src: str, notes: list, collected: list) -> dict | None:
    """The model's planetary stage as a ``[[planetary]]`` table and what it takes from the model.

    Returns None without a ``planetary_stage``, else a dictionary: ``table`` (the ``[[planetary]]``
    table; ``sun`` and ``carrier`` hold component ids, the reader puts the names in), ``carrier`` (its
    id), ``sun_shaft``, ``carrier_sections`` (tables to add to the carrier shaft), ``across`` (where the
    stage's axis passes across u [mm], from a placed sun or carrier), ``offsets`` (u [mm]
    of the bodies), ``taken`` (ids of the components the stage stands for: planets, pins, ring shaft,
    side plates, other carrier shafts, planet bearings, couplings, meshes) and ``planet_bearing_ids``
    (per planet in bearingkit's order, the REXS ids of its bearings in the table's order).
    """
    comps = m["components"]
    ids = [i for i, c in comps.items() if c["type"] == "planetary_stage"]
    if not ids:
        return None
    if len(ids) > 1:
        raise InputError(
            f"{src}: {len(ids)} planetary stages; bearingkit imports one per model (write more as "
            "[[planetary]] tables of a drivetrain TOML)"
        )
    pid = ids[0]
    pw = f"{src}: planetary_stage {pid} ({comps[pid]['name']})"
    rel = {"central_shaft": [], "planet_shaft": [], "planet_carrier_shaft": []}
    parts, part_of, sides, stages = {}, {}, [], []
    for r in m["relations"]:
        ro = roles(r)
        if r["type"] in rel and ro.get("planetary_stage") == pid:
            rel[r["type"]].append(ro.get("shaft"))
        elif r["type"] == "assembly":
            parts.setdefault(ro.get("assembly"), []).append(ro.get("part"))
            part_of[ro.get("part")] = ro.get("assembly")
        elif r["type"] == "side":
            sides.append((ro.get("assembly"), ro.get("inner_part"), ro.get("outer_part")))
        elif r["type"] == "stage":
            stages.append((ro.get("stage"), ro.get("gear_1"), ro.get("gear_2")))
    planets = rel["planet_shaft"]
    if len(planets) < 2 or not rel["central_shaft"] or not rel["planet_carrier_shaft"]:
        raise InputError(
            f"{pw}: needs central_shaft, planet_shaft (two or more) and planet_carrier_shaft relations"
        )

    def gear_of(body, types=("cylindrical_gear",)):
        found = [p for p in parts.get(body, []) if _type(comps, p) in types]
        return found[0] if len(found) == 1 else None

    planet_gear = {p: gear_of(p) for p in planets}
    for p, g in planet_gear.items():
        if g is None:
            raise InputError(
                f"{pw}: planet shaft {p} ({comps[p]['name']}) needs exactly one cylindrical_gear"
            )
    on_planets = set(planet_gear.values())
    sun = ring = None
    angle = {}
    for sid, g1, g2 in stages:
        pair = {g1, g2}
        if not pair & on_planets:
            continue
        other = (pair - on_planets).pop() if len(pair - on_planets) == 1 else None
        if other is None:
            raise InputError(f"{pw}: stage {sid} meshes two planets")
        if _type(comps, other) == "ring_gear" or (
            _type(comps, other) == "cylindrical_gear"
            and _number(comps[other]["attrs"].get("number_of_teeth", (1, ""))[0], f"{pw}: gear {other}") < 0
        ):
            ring = other
        else:
            sun = other
            sa = comps[sid]["attrs"]
            a = angle_deg(sa, "rotating_angle_around_neg_u_axis", f"{pw}: stage {sid}", 0.0)
            angle[part_of[(pair & on_planets).pop()]] = (-a) % 360.0
    if sun is None or ring is None or _type(comps, sun) != "cylindrical_gear":
        raise InputError(f"{pw}: needs a sun (a cylindrical_gear) and a ring gear meshing with the planets")
    sun_shaft, ring_body = part_of.get(sun), part_of.get(ring)
    if sun_shaft not in rel["central_shaft"]:
        raise InputError(f"{pw}: the sun gear {sun} is not on a central shaft of the stage")
    offsets = axial_offsets(m, src, sun_shaft, on_planets | {ring})
    axis = shaft_axis(m, src, sun_shaft)
    across = np.zeros(3)  # where the stage's axis passes (a placed sun or carrier says)
    for body in [sun_shaft, *rel["planet_carrier_shaft"]]:
        v = vector_mm(comps[body]["attrs"], "support_vector", pw)
        if v is not None:
            across = v - (v @ axis) * axis
            break
    taken = set(planets) | {sid for sid, g1, g2 in stages if {g1, g2} & on_planets}

    # the ring: held in the housing by couplings only
    if _type(comps, ring_body) == "shaft":
        holds = [(a, o) for a, i, o in sides if i == ring_body]
        bad = [a for a, o in holds if _type(comps, a) not in COUPLINGS or _type(comps, o) != "gear_casing"]
        loaded = [p for p in parts.get(ring_body, []) if _type(comps, p) == "external_load"]
        if bad or loaded or not holds:
            raise InputError(
                f"{pw}: the ring gear's shaft {ring_body} ({comps[ring_body]['name']}) turns or is loaded "
                "(bearings, loads, or no coupling to the casing): only a ring held in the housing is "
                "imported; write a rotating ring as [[planetary]] ring = <gear> in a drivetrain TOML"
            )
        off = [a for a, o in holds if comps[a]["attrs"].get("is_engaged", (True, ""))[0] is False]
        if off:
            notes.append(
                f"switchable couplings {', '.join(map(str, off))} holding the ring gear say is_engaged "
                "false; "
                "read as holding it (the model has one gear, and without them its stage carries no torque)"
            )
        taken |= {ring_body} | {a for a, o in holds}
    elif _type(comps, ring_body) != "gear_casing":
        raise InputError(f"{pw}: the ring gear {ring} is neither on a shaft nor in the casing")
    ra = comps[ring]["attrs"]
    rw = f"{pw}: ring gear {ring}"

    # the carrier: the one carrier shaft on bearings; the rest of the carrier is rigid
    def bearings_of(body):
        return [a for a, i, o in sides if i == body and "bearing" in _type(comps, a)]

    supported = [c for c in rel["planet_carrier_shaft"] if bearings_of(c)]
    if len(supported) != 1:
        raise InputError(
            f"{pw}: {len(supported)} planet_carrier_shafts sit in bearings; bearingkit's carrier is one "
            "shaft on its bearings (the others part of the rigid carrier)"
        )
    carrier = supported[0]
    for c in rel["planet_carrier_shaft"]:
        if c == carrier:
            continue
        if any(_type(comps, p) in ("external_load", "cylindrical_gear") for p in parts.get(c, [])):
            raise InputError(f"{pw}: carrier shaft {c} ({comps[c]['name']}) carries a gear or a load")
        taken.add(c)
        notes.append(
            f"carrier shaft {c} ({comps[c]['name']}) bears nothing: part of the rigid carrier, left out"
        )

    # the planets: identical, equally spaced
    tables, bearing_ids, psi, planes = [], [], [], []
    for p in sorted(planets, key=lambda p: angle.get(p, 0.0)):
        g = planet_gear[p]
        ga, gw = comps[g]["attrs"], f"{pw}: planet gear {g} ({comps[g]['name']})"
        for key, ref in (("normal_module", comps[sun]["attrs"]), ("normal_module", ra)):
            if key in ref and number(ga, key, gw) != _number(ref[key][0], f"{pw}: {key}"):
                raise InputError(
                    f"{gw}: mismatched modules: {ga[key][0]} against the sun's or ring's {ref[key][0]}"
                )
        if p not in offsets:
            raise InputError(
                f"{pw}: planet shaft {p} ({comps[p]['name']}) is joined to nothing that places it"
            )
        u_gear = mm(ga, "u_coordinate_on_shaft", gw)
        rows = []
        for a, pin, o in sides:
            if o != p or "bearing" not in _type(comps, a):
                continue
            at, bw = comps[a]["attrs"], f"{pw}: planet bearing {a} ({comps[a]['name']})"
            if pin not in offsets:
                raise InputError(f"{bw}: its pin {pin} is joined to nothing that places it")
            on_planet = mm(at, "u_coordinate_on_shaft_outer_side", bw) - u_gear
            on_pin = offsets[pin] + mm(at, "u_coordinate_on_shaft_inner_side", bw) - offsets[p] - u_gear
            if abs(on_planet - on_pin) > PLACE_TOL_MM:
                raise InputError(
                    f"{bw}: sits at {on_planet:.6g} mm in its planet but {on_pin:.6g} mm on its pin "
                    "(from the planet's mid-plane)"
                )
            name = comps[a]["name"].split(" @ ")[0] or f"bearing {a}"  # FVA names planet copies "… @ angle"
            rows.append((on_planet, a, rexs_bearing(m, a, name, bw, f"{on_planet} mm", notes, collected)))
            taken |= {a, pin}
        if not rows:
            raise InputError(f"{pw}: planet shaft {p} ({comps[p]['name']}) turns on no bearing")
        rows.sort(key=lambda row: row[0])
        table = {
            "teeth": abs(int(number(ga, "number_of_teeth", gw))),
            "face_width": q_text(ga, "face_width", gw),
            "profile_shift": _flank_shift(m, g),
            "sections": section_tables(comps, parts, p, u_gear, f"{pw}: planet shaft {p}"),
        }
        if not table["sections"]:
            raise InputError(f"{pw}: planet shaft {p} ({comps[p]['name']}) has no shaft_section parts")
        tables.append((table, [row[2] for row in rows]))
        bearing_ids.append([row[1] for row in rows])
        psi.append(angle.get(p, 0.0))
        planes.append(offsets[p] + u_gear)
    if any(_alike(t) != _alike(tables[0]) for t in tables):
        raise InputError(
            f"{pw}: the planets differ (teeth, body or bearings); bearingkit's planets are alike"
        )
    if max(planes) - min(planes) > PLACE_TOL_MM:
        raise InputError(f"{pw}: the planets' mid-planes differ ({min(planes):.6g}–{max(planes):.6g} mm)")
    z_plane = planes[0]
    n = len(planets)
    spacing = (np.diff([*psi, psi[0] + 360.0]) - 360.0 / n) if n else []
    if np.any(np.abs(spacing) > 1e-6):
        raise InputError(f"{pw}: the planets at {psi} deg are not equally spaced")

    # the carrier: every plate, pin and coupling of the carrier's assembly is taken; extend its shaft
    cage = part_of.get(carrier)
    plates = [p for p in parts.get(cage, []) if _type(comps, p) == "side_plate"] if cage is not None else []
    carriers = set(rel["planet_carrier_shaft"])
    # a shaft coupled to the carrier shafts at no given place (FVA's web between the side plates)
    webs = {
        x
        for a, i, o in sides
        if _type(comps, a) in COUPLINGS and {i, o} & carriers
        for x in (i, o)
        if x not in carriers and _type(comps, x) == "shaft" and x not in offsets
    }
    cage_parts = taken | set(plates) | webs | carriers
    taken |= set(plates) | webs
    taken |= {a for a, i, o in sides if _type(comps, a) in COUPLINGS and {i, o} <= cage_parts}
    cw = f"{pw}: carrier shaft {carrier} ({comps[carrier]['name']})"
    if carrier not in offsets:
        raise InputError(f"{cw}: joined to no planet (couplings to side plates and pins)")
    position = z_plane - offsets[carrier]
    first = planet_gear[planets[0]]
    half = mm(comps[first]["attrs"], "face_width", f"{pw}: planet gear {first}") / 2.0
    added = _carrier_extension(
        comps, parts, carrier, offsets, plates, sorted(webs), position, half, cw, notes
    )
    table0, planet_bearings = tables[0]
    stage = {
        "name": comps[pid]["name"] or f"planetary stage {pid}",
        "sun": sun,
        "carrier": carrier,
        "carrier_position": f"{position} mm",
        "planets": n,
        "first_planet_angle": f"{psi[0]} deg",
        "planet": table0,
        "planet_bearings": planet_bearings,
        "ring_teeth": abs(int(number(ra, "number_of_teeth", rw))),
        "ring_profile_shift": _flank_shift(m, ring),
    }
    if "face_width" in ra:
        stage["ring_face_width"] = q_text(ra, "face_width", rw)
    return {
        "table": stage,
        "carrier": carrier,
        "sun_shaft": sun_shaft,
        "carrier_sections": added,
        "offsets": offsets,
        "across": across,
        "taken": taken,
        "planet_bearing_ids": bearing_ids,
    }


def planet_bearing_ids(m) -> dict:
    """bearingkit's name of every planet bearing → its REXS component id (for the results export)."""
    try:
        got = read_stage(m, "", [], [])
    except InputError:
        return {}
    if got is None:
        return {}
    st = got["table"]
    return {
        f"{st['name']}.planet{k + 1}.{b['name']}": rid
        for k, ids in enumerate(got["planet_bearing_ids"])
        for b, rid in zip(st["planet_bearings"], ids, strict=True)
    }
