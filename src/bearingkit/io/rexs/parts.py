"""REXS attributes read as drivetrain-file values: units, lengths, vectors and one bearing's table.

Shared by the gearbox reader (:mod:`bearingkit.io.rexs.reader`) and the planetary-stage reader
(:mod:`bearingkit.io.rexs.planetary`). Values keep their units as text (``"25.0 mm"``) so that the
drivetrain file's own validation reads them; a unit bearingkit does not read is one InputError line.
"""

from __future__ import annotations

import numpy as np

from bearingkit.errors import InputError
from bearingkit.io.rexs.parse import _number, _vector

#: REXS unit names → the unit text bearingkit parses.
UNITS = {
    "mm": "mm",
    "m": "m",
    "mum": "um",
    "deg": "deg",
    "°": "deg",  # REXS 1.0 files (e.g. FVA Workbench 5.0) write the degree sign
    "rad": "rad",
    "N": "N",
    "kN": "kN",
    "N m": "N*m",
    "N mm": "N*mm",
    "1 / min": "rpm",
    "C": "degC",
    "N / mm^2": "N/mm^2",
    "kg / dm^3": "kg/dm^3",
    "kg / m^3": "kg/m^3",
    "N / m": "N/m",
    "N / mm": "N/mm",
    "N / mum": "N/um",
    "N mm / rad": "N*mm/rad",
    "N m / rad": "N*m/rad",
    "%": "%",
    "": "",
    "none": "",
    "mm^2 / s": "mm^2/s",
}
#: Length units of positions and vectors → millimetres.
TO_MM = {"mm": 1.0, "m": 1e3, "mum": 1e-3}

#: Stiffness units → SI (N/m, N·m/rad).
STIFFNESS_SI = {"N / m": 1.0, "N / mm": 1e3, "N / mum": 1e6, "N m / rad": 1.0, "N mm / rad": 1e-3}
#: The stiffest concept bearing the import keeps [N/m]: bearingkit's "rigid" (the value given where a
#: concept bearing leaves its stiffness out). FVA Workbench writes 1e20 N/m for rigid; the drivetrain
#: Newton, whose residual is taken against the load scale, does not converge with it (the public planetary
#: stage: residual 0.9 % of the load scale at 1e20 N/m, converged at 1e12–1e16 N/m). 1e12 N/m is 1000×
#: a mesh's stiffness (about 1e9 N/m), so a rigid support stays rigid in every load share.
RIGID_N_PER_M = 1e12
#: The stiffest tilt the import keeps [N·m/rad]: the public two-stage FVA gearbox's concept bearings give
#: 1e15 N·mm/rad (1e12 N·m/rad) and converge; stiffer is untried and read as this.
RIGID_N_M_PER_RAD = 1e12

#: REXS ``bearing_type`` words of the bearings whose contacts carry axial load one way only (their
#: orientation is all ``axial_force_absorption`` needs to say).
ONE_WAY_KINDS = ("tapered", "angular")

#: ``axial_force_absorption`` of a one-direction bearing → its orientation: ``positive`` supports an axial
#: force on its inner part (the shaft) along +u (bearingkit's +z) and so pushes the shaft back along −u, as
#: a ``+z`` tapered row does. Confirmed by FVA Workbench 8.1's solution of the FVA two-stage gearbox
#: (tests/systems/test_rexs_fva_workbench.py): its four tapered bearings labelled so push the shafts
#: that way (the ``positive`` 33012 and 33016 along −u, the ``negative`` 33014 and 33016 along +u).
AXIAL_DIRECTION = {"positive": "+z", "negative": "-z"}
#: The same for a concept bearing's one-way spring, named by the way it pushes the shaft
#: (``stiffness.axial_direction``): ``positive`` pushes along −u.
SPRING_PUSH = {"positive": "-z", "negative": "+z"}


def q_text(attrs: dict, key: str, where: str, required: bool = True):
    """An attribute as the drivetrain file writes it (``"25.0 mm"``), a fraction for %, None if absent."""
    if key not in attrs:
        if required:
            raise InputError(f"{where}: attribute {key!r} missing")
        return None
    value, unit = attrs[key]
    if unit not in UNITS:
        raise InputError(
            f"{where}.{key}: unit {unit!r} is not one bearingkit reads ({', '.join(k for k in UNITS if k)})"
        )
    if isinstance(value, list):
        return value
    if unit == "%":
        return float(value) / 100.0
    return f"{value} {UNITS[unit]}".strip() if UNITS[unit] else value


def scaled(attrs: dict, key: str, where: str, units: dict, kind: str, default: float | None = None) -> float:
    """An attribute in the unit ``units`` scale to (``units``: REXS unit → factor), ``default`` where left out
    (None: required); one InputError line for a missing value, another unit or a non-finite number."""
    if key not in attrs:
        if default is None:
            raise InputError(f"{where}: attribute {key!r} missing")
        return default
    value, unit = attrs[key]
    if unit not in units:
        raise InputError(f"{where}.{key}: unit {unit!r} is not {kind} unit ({', '.join(units)})")
    return _number(value, f"{where}.{key}") * units[unit]


def mm(attrs: dict, key: str, where: str, default: float | None = None) -> float:
    """A length attribute (a position on a shaft, a diameter) in millimetres."""
    return scaled(attrs, key, where, TO_MM, "a length", default)


def number(attrs: dict, key: str, where: str) -> float:
    """A number attribute (no unit read), or one InputError line: missing, or not a finite number."""
    if key not in attrs:
        raise InputError(f"{where}: attribute {key!r} missing")
    return _number(attrs[key][0], f"{where}.{key}")


#: Length units → micrometres (clearances).
TO_UM = {"mum": 1.0, "mm": 1e3, "m": 1e6}
#: Force units → kN (load ratings).
TO_KN = {"kN": 1.0, "N": 1e-3}
#: Angle units → degrees.
TO_DEG = {"deg": 1.0, "°": 1.0, "rad": 180.0 / np.pi}


def angle_deg(attrs: dict, key: str, where: str, default: float | None = None) -> float:
    """An angle attribute in degrees (deg, ° or rad), or one InputError line."""
    return scaled(attrs, key, where, TO_DEG, "an angle", default)


def vector_mm(attrs: dict, key: str, where: str) -> np.ndarray | None:
    """A position vector in millimetres, or None where the model leaves it out: absent, or written as the
    boolean ``false`` (FVA Workbench writes ``support_vector`` so when the gear unit places the part)."""
    if key not in attrs or isinstance(attrs[key][0], bool):
        return None
    value, unit = attrs[key]
    return _vector(value, f"{where}.{key}") * TO_MM.get(unit, 1.0)


def direction(attrs: dict, key: str, where: str, default) -> np.ndarray:
    """An axis vector (``u_axis_vector``, ``w_axis_vector``); ``default`` where left out (module doc)."""
    if key not in attrs or isinstance(attrs[key][0], bool):
        return np.asarray(default, dtype=float)
    return _vector(attrs[key][0], f"{where}.{key}")


def shaft_axis(m, src: str, root) -> np.ndarray:
    """The unit u axis of the shafts (``root``'s ``u_axis_vector``, else the gear unit's, else x)."""
    comps = m["components"]
    unit = next((c for c in comps.values() if c["type"] == "gear_unit"), {"attrs": {}})
    u = direction(unit["attrs"], "u_axis_vector", f"{src}: gear_unit", [1.0, 0.0, 0.0])
    u = direction(comps[root]["attrs"], "u_axis_vector", f"{src}: shaft {root}", u)
    norm = float(np.linalg.norm(u))
    if norm == 0.0:
        raise InputError(f"{src}: shaft {root}.u_axis_vector is zero")
    return u / norm


#: REXS attribute names of a bearing's radial ratings (C, C0) [kN]: REXS 1.1+ and REXS 1.0.
RATING_KEYS = (
    ("radial_dynamic_load_rating", "radial_static_load_rating"),
    ("dynamic_capacity", "static_capacity"),
)


def file_ratings(attrs: dict, where: str) -> tuple[float, float | None] | None:
    """The bearing's radial (C, C0) [kN] as the file gives them (C0 None when only C is given), else None."""
    for keys in RATING_KEYS:
        if keys[0] in attrs:
            values = [scaled(attrs, k, where, TO_KN, "a force") if k in attrs else None for k in keys]
            if min(v for v in values if v is not None) <= 0.0:
                raise InputError(f"{where}.{keys[0]}: ratings {values} kN must be positive")
            return values[0], values[1]
    return None


def bearing_table(
    comp: dict,
    name: str,
    where: str,
    position: str,
    notes: list,
    collected: list,
    tables: dict | None = None,
) -> dict:
    """The ``[[shafts.bearings]]`` table of a REXS bearing component (``position``: its place as text).

    ``rolling_bearing_with_catalog_geometry``: the designation (bearingkit's catalogue estimate);
    ``concept_bearing``: a linear bearing of its ``radial_stiffness``, ``axial_stiffness``,
    ``bending_stiffness`` (left out: radial rigid, 10¹² N/m; axial rigid, or 0 when floating; tilt 0);
    ``axial_force_absorption`` ``no_direction``: floating, ``positive``/``negative``: one way (module
    constants), else locating.
    A catalogue bearing that gives its radial ratings (:func:`file_ratings`) is rated with them
    (``ratings``, the lives; the geometry stays the catalogue's estimate).
    ``rolling_bearing_with_detailed_geometry``: ``tables`` (its bearing file's tables, from
    :func:`bearingkit.io.rexs.detailed.detailed_bearing`) inline, else its ``catalogue_designation``.
    A concept bearing stiffer than :data:`RIGID_N_PER_M` (:data:`RIGID_N_M_PER_RAD` in tilt) gets that
    value; its name and the values it gave go to ``collected`` (:func:`collected_notes` says them once).
    """
    a = comp["attrs"]
    bearing = {"name": name, "position": position}
    absorption = a.get("axial_force_absorption", ("both_directions", ""))[0]
    if not isinstance(absorption, (str, bool)):
        raise InputError(
            f"{where}.axial_force_absorption: {absorption!r} is not one of both_directions, positive, "
            "negative, no_direction"
        )
    bearing["axial"] = "floating" if absorption == "no_direction" else "locating"
    if comp["type"] == "rolling_bearing_with_catalog_geometry":
        # REXS 1.0 files (FVA Workbench 5) name the catalogue bearing in a ``name`` attribute
        key = "catalogue_designation" if "catalogue_designation" in a or "name" not in a else "name"
        bearing["designation"] = str(q_text(a, key, where))
        ratings = file_ratings(a, where)
        if ratings is not None:  # the maker's ratings the file gives: the lives use them
            bearing["ratings"] = {"C": f"{ratings[0]} kN"}
            if ratings[1] is not None:
                bearing["ratings"]["C0"] = f"{ratings[1]} kN"
            collected.append(("rated", name, ratings))
        if absorption in AXIAL_DIRECTION:  # a one-direction bearing (a tapered row): which way it faces
            bearing["orientation"] = AXIAL_DIRECTION[absorption]
        kind = str(a.get("bearing_type", ("", ""))[0])
        if absorption in AXIAL_DIRECTION and not any(k in kind for k in ONE_WAY_KINDS):
            notes.append(
                f"{bearing['name']}: axial_force_absorption {absorption!r} read as the bearing's "
                f"orientation ({AXIAL_DIRECTION[absorption]}); a bearing whose contacts carry both "
                "ways (e.g. a deep groove ball bearing) still does: its seat's one-sided shoulder is "
                "not modelled"
            )
    elif comp["type"] == "rolling_bearing_with_detailed_geometry":
        if tables is not None:
            bearing["bearing"] = tables
            if absorption in AXIAL_DIRECTION and tables["bearing"]["type"] in (
                "tapered_roller",
                "angular_contact_ball",
            ):
                bearing["orientation"] = AXIAL_DIRECTION[absorption]  # which way the one-way row faces
        elif "catalogue_designation" in a:
            bearing["designation"] = str(q_text(a, "catalogue_designation", where))
            notes.append(
                f"{name}: a bearing with detailed geometry of a kind or row count not read from geometry "
                f"({a.get('bearing_type', ('?', ''))[0]}): read by its designation, bearingkit's catalogue "
                "estimate"
            )
        else:
            raise InputError(
                f"{where}: a bearing with detailed geometry of kind {a.get('bearing_type', ('?', ''))[0]!r} "
                "and no catalogue_designation: bearingkit reads one-row deep groove and angular contact "
                "ball, cylindrical, needle and tapered roller bearings from geometry; give its designation "
                "or write a bearing file"
            )
    elif comp["type"] == "concept_bearing":
        capped = []

        def stiffness(key, default, cap, unit):
            if key not in a:
                return default
            value, given = a[key]
            k = _number(value, f"{where}.{key}") * STIFFNESS_SI.get(given, np.nan)
            if k > cap:  # FVA's "rigid" (1e20): bearingkit's rigid, which its Newton converges with
                capped.append(f"{key} {k / STIFFNESS_SI[given]:g} {given}")
                return f"{cap} {unit}"
            return q_text(a, key, where)

        rigid = f"{RIGID_N_PER_M} N/m"
        k_r = stiffness("radial_stiffness", rigid, RIGID_N_PER_M, "N/m")
        k_a = stiffness(
            "axial_stiffness", "0 N/m" if absorption == "no_direction" else rigid, RIGID_N_PER_M, "N/m"
        )
        k_t = stiffness("bending_stiffness", "0 N*m/rad", RIGID_N_M_PER_RAD, "N*m/rad")
        if capped:
            collected.append(("rigid", name, capped))
        bearing["stiffness"] = {"radial": k_r, "axial": k_a, "tilt": k_t}
        if absorption in SPRING_PUSH:  # one way only: a shoulder on one side (LinearBearing)
            bearing["stiffness"]["axial_direction"] = SPRING_PUSH[absorption]
    else:
        raise InputError(f"{where}: bearing type {comp['type']!r} is not supported")
    return bearing


def collected_notes(collected: list) -> list:
    """One note naming the concept bearings read as rigid and one naming the bearings rated with the
    file's ratings (:func:`bearing_table`), each only when there are some."""
    out = []
    rigid = [item for item in collected if item[0] == "rigid"]
    names = list(dict.fromkeys(name for _, name, _ in rigid))
    if names:
        given = sorted({v for _, _, values in rigid for v in values})
        out.append(
            f"concept bearings {', '.join(names)}: {'; '.join(given)} read as rigid ({RIGID_N_PER_M:g} N/m, "
            f"{RIGID_N_M_PER_RAD:g} N·m/rad): stiffer supports stop the drivetrain Newton short of its "
            "tolerance"
        )
    rated = [item for item in collected if item[0] == "rated"]
    if rated:
        each = ", ".join(
            dict.fromkeys(
                f"{name} (C {c:g} kN, " + (f"C0 {c0:g} kN)" if c0 is not None else "no C0 given)")
                for _, name, (c, c0) in rated
            )
        )
        out.append(
            f"the lives use the file's ratings in place of bearingkit's catalogue or geometry ratings: {each}"
        )
    return out


def section_tables(comps, parts, body, shift: float, where: str) -> list:
    """The ``shaft_section`` parts of a body as section tables in mm, u shifted by ``shift`` [mm]; a conical
    section is one InputError line."""
    out = []
    for p in parts.get(body, []):
        if comps[p]["type"] != "shaft_section":
            continue
        a, sw = comps[p]["attrs"], f"{where}: section {p}"
        for key in ("outer_diameter", "inner_diameter"):
            if key + "_begin" in a and a[key + "_begin"][0] != a.get(key + "_end", a[key + "_begin"])[0]:
                raise InputError(
                    f"{sw}: a conical section ({key} changes) is not supported; split it into steps"
                )
        out.append(
            {
                "start": f"{mm(a, 'u_coordinate_on_shaft', sw) - shift} mm",
                "length": f"{mm(a, 'length', sw)} mm",
                "outer_diameter": f"{mm(a, 'outer_diameter_begin', sw)} mm",
                "inner_diameter": f"{mm(a, 'inner_diameter_begin', sw, 0.0)} mm",
            }
        )
    return sorted(out, key=lambda s: float(s["start"].split()[0]))
