"""Reading a REXS file (XML or JSON) into plain data: components, relations, load cases, typed values.

The model dictionary :func:`parse` returns is what :mod:`bearingkit.io.rexs.reader` turns into a drivetrain;
here only the syntax is read and checked: integer ids, relations and load cases that name existing
components, numbers that are finite (one :class:`~bearingkit.errors.InputError` line naming the file and the
attribute otherwise). REXS versions 1.0–1.6 share this syntax (XML; the JSON syntax of 1.5).
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from bearingkit.errors import InputError
from bearingkit.io.reading import read_text


def _value_xml(el):
    arr = el.find("array")
    if arr is not None:
        return [_float_or_text(c.text) for c in arr.findall("c")]
    text = (el.text or "").strip()
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    return text  # numbers stay text until read (a designation like "6208" is a string)


def _float_or_text(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return text  # _number / _vector say which attribute it is


def _number(value, where: str) -> float:
    """A finite number from an attribute value, or one InputError line naming the attribute."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        x = float("nan")
    if not np.isfinite(x):
        raise InputError(f"{where}: {value!r} is not a finite number")
    return x


def _vector(value, where: str) -> np.ndarray:
    """A 3-vector of finite numbers (``u_axis_vector``, ``support_vector``, …) or one InputError line."""
    items = value if isinstance(value, list) else [value]
    v = np.array([_number(x, where) for x in items])
    if v.shape != (3,):
        raise InputError(f"{where}: {value!r} is not a vector of 3 numbers")
    return v


def _attrs_xml(comp) -> dict:
    return {a.get("id"): (_value_xml(a), a.get("unit") or "") for a in comp.findall("attribute")}


def _attrs_json(comp) -> dict:
    out = {}
    for a in comp.get("attributes", []):
        value = None
        for key, v in a.items():
            if key not in ("id", "unit"):
                value = v
        out[a["id"]] = (value, a.get("unit", "") or "")
    return out


def _id(value, where: str) -> int:
    """A component id of the model (an integer), or one InputError line naming where it was read."""
    try:
        return int(value)
    except (TypeError, ValueError):
        raise InputError(f"{where}: id {value!r} is not an integer (REXS ids are integers)") from None


#: Roles each relation type must have (REXS 1.1–1.6 relation types the readers follow): a relation
#: missing one is one InputError line, not a KeyError deep in a reader. ``flank`` needs its gear and one
#: of ``left``/``right`` (checked below).
REQUIRED_ROLES = {
    "assembly": ("assembly", "part"),
    "ordered_assembly": ("assembly", "part"),
    "side": ("assembly", "inner_part", "outer_part"),
    "stage": ("stage", "gear_1", "gear_2"),
    "stage_gear_data": ("stage", "gear", "stage_gear_data"),
    "reference": ("origin", "referenced"),
    "flank": ("gear",),
    "central_shaft": ("planetary_stage", "shaft"),
    "planet_shaft": ("planetary_stage", "shaft"),
    "planet_carrier_shaft": ("planetary_stage", "shaft"),
}


def roles(relation: dict) -> dict:
    """A relation's references as {role: component id}."""
    return {role: i for i, role in relation["refs"]}


def _check_roles(path, r) -> None:
    roles = [role for _, role in r["refs"]]
    missing = [role for role in REQUIRED_ROLES.get(r["type"], ()) if role not in roles]
    if r["type"] == "flank" and not {"left", "right"} & set(roles):
        missing.append("left or right")
    if missing or (r["type"] in REQUIRED_ROLES and len(roles) != len(set(roles))):
        what = f"no {missing[0]!r} reference" if missing else "a role given twice"
        raise InputError(f"{path}: relation {r.get('id')!r} ({r['type']}): {what}")


def parse(path) -> dict:
    """A REXS file as {version, components: {id: {type, name, attrs}}, relations: [{type, refs}],
    load_cases: [{id, components: {id: attrs}}]} (XML or JSON)."""
    try:
        model = _parse(path)
    except (KeyError, TypeError, AttributeError) as exc:  # a JSON model missing a required member
        raise InputError(f"{path}: not a REXS model bearingkit reads ({type(exc).__name__}: {exc})") from None
    known = model["components"]
    for r in model["relations"]:
        _check_roles(path, r)
        for cid, role in r["refs"]:
            if cid not in known:
                raise InputError(
                    f"{path}: relation {r.get('id')!r} ({r['type']}): its {role!r} refers to component "
                    f"{cid}, which the model does not have"
                )
    for lc in model["load_cases"]:
        for cid in lc["components"]:
            if cid not in known:
                raise InputError(
                    f"{path}: load case {lc['id']!r} gives attributes of component {cid}, which the model "
                    "does not have"
                )
    return model


def _parse(path) -> dict:
    path = Path(path)
    text = read_text(path).lstrip("\ufeff")
    model = {"components": {}, "relations": [], "load_cases": []}
    if text.lstrip().startswith("{"):
        try:
            root = json.loads(text)["model"]
        except (ValueError, KeyError, TypeError):
            raise InputError(f'{path}: not a REXS JSON model (expected {{"model": {{...}}}})') from None
        model["version"] = str(root.get("version", ""))
        for c in root.get("components", []):
            model["components"][_id(c.get("id"), f"{path}: component")] = {
                "type": c.get("type"),
                "name": c.get("name", ""),
                "attrs": _attrs_json(c),
            }
        for r in root.get("relations", []):
            model["relations"].append(
                {
                    "id": r.get("id"),
                    "type": r.get("type"),
                    "refs": [
                        (_id(x.get("id"), f"{path}: relation {r.get('id')!r}"), x.get("role"))
                        for x in r.get("refs", [])
                    ],
                }
            )
        for lc in (root.get("load_spectrum") or {}).get("load_cases", []):
            model["load_cases"].append(
                {
                    "id": lc.get("id"),
                    "components": {
                        _id(c.get("id"), f"{path}: load case {lc.get('id')!r}"): _attrs_json(c)
                        for c in lc.get("components", [])
                    },
                }
            )
        return model
    try:
        root = ET.fromstring(text)
    except ET.ParseError as exc:
        raise InputError(f"{path}: not a REXS XML model ({exc})") from None
    if root.tag != "model":
        raise InputError(f"{path}: not a REXS model (root element {root.tag!r}, expected 'model')")
    model["version"] = root.get("version", "")
    components = root.find("components")
    for c in [] if components is None else components.findall("component"):
        model["components"][_id(c.get("id"), f"{path}: component")] = {
            "type": c.get("type"),
            "name": c.get("name", ""),
            "attrs": _attrs_xml(c),
        }
    for r in root.iter("relation"):
        model["relations"].append(
            {
                "id": r.get("id"),
                "type": r.get("type"),
                "refs": [
                    (_id(x.get("id"), f"{path}: relation {r.get('id')!r}"), x.get("role"))
                    for x in r.findall("ref")
                ],
            }
        )
    spectrum = root.find("load_spectrum")
    if spectrum is not None:
        for lc in spectrum.findall("load_case"):
            model["load_cases"].append(
                {
                    "id": lc.get("id"),
                    "components": {
                        _id(c.get("id"), f"{path}: load case {lc.get('id')!r}"): _attrs_xml(c)
                        for c in lc.findall("component")
                    },
                }
            )
    return model


def load_cases(model: dict) -> list[tuple[str, dict]]:
    """The model's load cases as (name, {component id: attrs}), the one place that names them.

    Named ``load case ID`` (``load case K`` by position when a case has no id). A model without a
    ``load_spectrum`` (REXS 1.0 files write the operating values on the components) has one case: the
    components' own attributes. The reader solves these cases; the export writes their inputs back.
    """
    spectrum = model["load_cases"] or [
        {"id": 1, "components": {cid: c["attrs"] for cid, c in model["components"].items()}}
    ]
    return [
        (f"load case {lc['id'] if lc['id'] is not None else k + 1}", lc["components"])
        for k, lc in enumerate(spectrum)
    ]
