"""REXS couplings between shafts: two coaxial shafts joined end to end by a rigid coupling become one.

A ``coupling`` (or an engaged ``switchable_coupling``) whose ``side`` relation joins two shafts (inner and
outer part) carries every force and moment between them; bearingkit's shafts are rigid in torsion, and a
rigid coupling of two coaxial shafts end to end is the same beam as one shaft of both lengths. So the
coupled shaft (the relation's ``outer_part``) is read into the other: its sections, gears, loads and
bearings move onto it at u + Δ, Δ = ``u_coordinate_on_shaft_inner_side`` − ``_outer_side`` of the
coupling, and its speed (``defines_speed``, the load cases' ``rotational_speed``) and material go with it
where the other has none. Refused with one line: a coupling softer than bearingkit's rigid (10¹² N/m,
10¹² N·m/rad; a flexible coupling is not modelled), shafts that are not coaxial, or that overlap (a shaft
in a shaft is joined by bearings, not merged). A note names each merge. The model's dictionary of
:func:`bearingkit.io.rexs.parse.parse` is changed in a copy; the reader then reads one shaft.
"""

from __future__ import annotations

import copy

import numpy as np

from bearingkit.errors import InputError
from bearingkit.io.rexs.parse import _number, roles
from bearingkit.io.rexs.parts import (
    RIGID_N_M_PER_RAD,
    RIGID_N_PER_M,
    STIFFNESS_SI,
    mm,
    shaft_axis,
    vector_mm,
)

#: Coupling attributes and the stiffness a rigid one reaches (SI).
RIGID_KEYS = {
    "radial_stiffness": RIGID_N_PER_M,
    "axial_stiffness": RIGID_N_PER_M,
    "bending_stiffness": RIGID_N_M_PER_RAD,
    "rotational_stiffness": RIGID_N_M_PER_RAD,
}
#: Position attributes of a shaft's parts that move with it.
POSITION_KEYS = ("u_coordinate_on_shaft",)


def _span(m, shaft, where) -> tuple[float, float] | None:
    """(start, end) [mm] of a shaft's sections, None when it has none."""
    ends = []
    for r in m["relations"]:
        ro = roles(r)
        part = ro.get("part")
        if (
            r["type"] == "assembly"
            and ro.get("assembly") == shaft
            and m["components"][part]["type"] == "shaft_section"
        ):
            a, w = m["components"][part]["attrs"], f"{where}: section {part}"
            u = mm(a, "u_coordinate_on_shaft", w, 0.0)
            ends.append((u, u + mm(a, "length", w)))
    if not ends:
        return None
    return min(e[0] for e in ends), max(e[1] for e in ends)


def _shift(attrs: dict, key: str, delta: float, where: str) -> None:
    if key in attrs:
        attrs[key] = (mm(attrs, key, where) + delta, "mm")


def merge_coupled_shafts(m: dict, src: str, taken: set, notes: list, keep=frozenset()) -> dict:
    """The model with every rigid coupling between two coaxial shafts read as one shaft (module
    docstring); ``m`` itself is not changed. Couplings whose parts are in ``taken`` (a planetary stage's
    own) are left to the stage; a shaft in ``keep`` (the stage's sun shaft and carrier) is the one the
    other is read into."""
    couplings = []
    for r in m["relations"]:
        ro = roles(r)
        a, inner, outer = ro.get("assembly"), ro.get("inner_part"), ro.get("outer_part")
        kind = (m["components"].get(a) or {}).get("type")
        if r["type"] != "side" or kind not in ("coupling", "switchable_coupling") or a in taken:
            continue
        types = [(m["components"].get(x) or {}).get("type") for x in (inner, outer)]
        if types != ["shaft", "shaft"] or {inner, outer} & taken:
            continue
        couplings.append((a, inner, outer))
    if not couplings:
        return m
    m = copy.deepcopy(m)
    comps = m["components"]
    merged = {}  # shaft id → (the shaft it is read into, Δ [mm])
    for a, inner, outer in couplings:
        c = comps[a]
        where = f"{src}: {c['type']} {a} ({c['name']})"
        attrs = c["attrs"]
        if c["type"] == "switchable_coupling" and attrs.get("is_engaged", (True, ""))[0] is False:
            continue  # disengaged: the shafts turn apart
        for key, rigid in RIGID_KEYS.items():
            if key in attrs:
                value, unit = attrs[key]
                k = _number(value, f"{where}.{key}") * STIFFNESS_SI.get(unit, float("nan"))
                if not k >= rigid:
                    raise InputError(
                        f"{where}.{key}: {value} {unit} is a flexible coupling; bearingkit joins coupled "
                        f"shafts rigidly (≥ {rigid:g} SI) only: give the shafts' supports instead"
                    )
        u_in = mm(attrs, "u_coordinate_on_shaft_inner_side", where)
        delta = u_in - mm(attrs, "u_coordinate_on_shaft_outer_side", where, u_in)
        if outer in keep and inner not in keep:  # read the other way: the stage's shaft stays
            inner, outer, delta = outer, inner, -delta
        while inner in merged:  # a chain of couplings: into the shaft the inner one went into
            inner, d0 = merged[inner]
            delta += d0
        if outer in merged or outer == inner:
            raise InputError(
                f"{where}: joins shaft {outer}, already joined to another: a loop or a shaft coupled twice"
            )
        axis = shaft_axis(m, where, inner)
        centres = []
        for x in (inner, outer):  # where the shaft's axis passes, across it
            v = vector_mm(comps[x]["attrs"], "support_vector", where)
            centres.append(np.zeros(3) if v is None else v - (v @ axis) * axis)
        if np.linalg.norm(centres[0] - centres[1]) > 1e-6:
            raise InputError(f"{where}: joins shafts {inner} and {outer} that are not coaxial")
        span_in, span_out = _span(m, inner, where), _span(m, outer, where)
        if span_in and span_out:
            lo, hi = span_out[0] + delta, span_out[1] + delta
            if lo < span_in[1] - 1e-6 and hi > span_in[0] + 1e-6:
                raise InputError(
                    f"{where}: joins shafts {inner} and {outer} that overlap ({span_in[0]:g}–{span_in[1]:g} "
                    f"and {lo:g}–{hi:g} mm on one axis): a shaft in a shaft is held by bearings, not merged"
                )
        merged[outer] = (inner, delta)
        notes.append(
            f"{c['type']} {a} joins shafts {comps[inner]['name']} and {comps[outer]['name']} rigidly: read "
            f"as one shaft ({comps[outer]['name']}'s parts at u + {delta:g} mm)"
        )
    if not merged:
        return m
    with_material = {roles(r).get("origin") for r in m["relations"] if r["type"] == "reference"}
    for outer, (inner, delta) in merged.items():
        where = f"{src}: shaft {outer}"
        for r in m["relations"]:
            ro = roles(r)
            if r["type"] == "assembly" and ro.get("assembly") == outer:
                part = ro.get("part")
                for key in POSITION_KEYS:
                    _shift(comps[part]["attrs"], key, delta, f"{where}: part {part}")
            if r["type"] == "side" and outer in (ro.get("inner_part"), ro.get("outer_part")):
                side = "inner" if ro.get("inner_part") == outer else "outer"
                _shift(comps[ro["assembly"]]["attrs"], f"u_coordinate_on_shaft_{side}_side", delta, where)
            if r["type"] == "reference" and ro.get("origin") == outer and inner in with_material:
                continue  # the shaft read into keeps its own material
            r["refs"] = [(inner if i == outer else i, role) for i, role in r["refs"]]
        for key in ("defines_speed", "rotational_speed"):
            if key in comps[outer]["attrs"] and key not in comps[inner]["attrs"]:
                comps[inner]["attrs"][key] = comps[outer]["attrs"][key]
        for lc in m["load_cases"]:
            given = lc["components"].pop(outer, None)
            if given:
                lc["components"].setdefault(inner, {}).update(
                    {k: v for k, v in given.items() if k not in lc["components"].get(inner, {})}
                )
    drop = {a for a, inner, outer in couplings if outer in merged} | set(merged)
    # every relation naming a dropped coupling or a shaft read into another goes with them
    m["relations"] = [r for r in m["relations"] if not any(i in drop for i, _ in r["refs"])]
    for x in drop:
        comps.pop(x, None)
    return m
