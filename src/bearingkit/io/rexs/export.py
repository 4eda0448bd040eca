"""REXS export: the bearing results of a drivetrain written into a REXS JSON model (version 1.4 content,
the JSON syntax of REXS 1.5).

Where the model came from a REXS file, its components and relations are kept (same ids) and the
results are added to its load spectrum; otherwise a model of one component per bearing is written.
Per load case and bearing: the relative displacement of the inner ring against the outer ring in the
standard attributes ``axial_deflection`` [µm] and ``angular_deflection_in_v`` / ``_in_w`` [rad]
(REXS 1.0–1.4 attribute database), and, where REXS has no attribute for a bearingkit result, the
extension attributes the specification allows (``custom_`` prefix): ``custom_bearingkit_radial_force``
and ``custom_bearingkit_axial_force`` [N], ``custom_bearingkit_l10h_iso_ts_16281`` and
``custom_bearingkit_l10h_iso_281`` [h], ``custom_bearingkit_power_loss`` [W],
``custom_bearingkit_static_safety`` [-], ``custom_bearingkit_max_contact_pressure`` [N/mm²].
Input is the JSON dictionary of :meth:`bearingkit.systems.drivetrain.analysis.DrivetrainAnalysis.to_dict`.
"""

from __future__ import annotations

import datetime
import json
import math
from pathlib import Path

from bearingkit.io.export import to_json, write_atomic

#: REXS version whose attribute names the export uses.
REXS_VERSION = "1.4"


def _attr(i, unit, value):
    return {"id": i, "unit": unit, "floating_point": value}


def _typed(key: str, value, unit: str) -> tuple[str, object]:
    """REXS JSON's typed value of a parsed attribute: XML gives text, so a number with a unit is a
    ``floating_point``, a whole ``number_of_…`` an ``integer``, other text a ``string`` (a designation
    such as "6208" has no unit and stays text)."""
    if isinstance(value, bool):
        return "boolean", value
    if isinstance(value, list):
        return "floating_point_array", value
    if isinstance(value, (int, float)):
        return ("integer", value) if isinstance(value, int) else ("floating_point", value)
    try:
        number = float(value)
    except (TypeError, ValueError):
        return "string", value
    if unit not in ("", "none") and math.isfinite(number):
        return "floating_point", number
    if key.startswith("number_of") and number.is_integer():
        return "integer", int(number)
    return "string", value


def _json_attrs(attrs: dict) -> list:
    """Parsed attributes {id: (value, unit)} back as REXS JSON attributes (:func:`_typed`)."""
    out = []
    for key, (value, unit) in attrs.items():
        kind, typed = _typed(key, value, unit)
        out.append({"id": key, "unit": unit, kind: typed})
    return out


def _source_components(source) -> tuple[list, list, dict, dict]:
    """(components, relations, bearing name → id, load-case name → its input components) of a source REXS
    model, as JSON; the load cases as :func:`bearingkit.io.rexs.parse.load_cases` names them (the reader's
    names, so that each result finds its case's inputs)."""
    from bearingkit.io.rexs.parse import load_cases, parse
    from bearingkit.io.rexs.planetary import planet_bearing_ids

    m = parse(source)
    comps, ids = [], {}
    for cid, c in m["components"].items():
        comps.append({"id": cid, "name": c["name"], "type": c["type"], "attributes": _json_attrs(c["attrs"])})
        if "bearing" in (c["type"] or ""):
            ids[c["name"]] = cid
    ids.update(planet_bearing_ids(m))  # a planet bearing per planet: bearingkit's stage names them
    rels = [
        {"id": k + 1, "type": r["type"], "refs": [{"id": i, "role": role} for i, role in r["refs"]]}
        for k, r in enumerate(m["relations"])
    ]
    inputs = {
        name: {cid: _json_attrs(attrs) for cid, attrs in given.items()} for name, given in load_cases(m)
    }
    return comps, rels, ids, inputs


def write_rexs_results(data: dict, path, source=None) -> Path:
    """Write the results of ``data`` (a DrivetrainAnalysis dict) as a REXS JSON model to ``path``."""
    path = Path(path)
    src = source if source is not None else data.get("file")
    comps, rels, ids, inputs = [], [], {}, {}
    if src is not None and str(src).lower().endswith((".rexs", ".rexsj", ".rexs.json", ".rexs.xml")):
        comps, rels, ids, inputs = _source_components(src)
    next_id = max([c["id"] for c in comps], default=0) + 1
    for b in data["inputs"]["bearings"]:
        if b["name"] not in ids:
            ids[b["name"]] = next_id
            comps.append({"id": next_id, "name": b["name"], "type": "concept_bearing", "attributes": []})
            next_id += 1
    cases = []
    for k, c in enumerate(data["cases"]):
        # the case's inputs (speeds, torques, forces, temperatures, time share) stay, so that the model
        # written is the model read plus the results: read again, it solves to the same results
        given = {cid: list(attrs) for cid, attrs in inputs.get(c["case"], {}).items()}
        entries = []
        for b in c["bearings"]:
            s, q = b["summary"], b["relative_displacement"]
            attrs = [
                _attr("axial_deflection", "mum", q["u_z_m"] * 1e6),
                _attr("angular_deflection_in_v", "rad", q["theta_x_rad"]),
                _attr("angular_deflection_in_w", "rad", q["theta_y_rad"]),
                _attr("custom_bearingkit_radial_force", "N", s["radial_load_N"]),
                _attr("custom_bearingkit_axial_force", "N", s["axial_load_N"]),
            ]
            for key, rid, unit, scale in (
                ("L10h_h", "custom_bearingkit_l10h_iso_ts_16281", "h", 1.0),
                ("L10h_iso281_h", "custom_bearingkit_l10h_iso_281", "h", 1.0),
                ("power_loss_W", "custom_bearingkit_power_loss", "W", 1.0),
                ("static_safety", "custom_bearingkit_static_safety", "none", 1.0),
                ("max_pressure_Pa", "custom_bearingkit_max_contact_pressure", "N / mm^2", 1e-6),
            ):
                if s.get(key) is not None:
                    attrs.append(_attr(rid, unit, s[key] * scale))
            entries.append({"id": ids[b["name"]], "attributes": given.pop(ids[b["name"]], []) + attrs})
        entries += [{"id": cid, "attributes": attrs} for cid, attrs in given.items()]
        cases.append({"id": k + 1, "components": entries})
    model = {
        "model": {
            "version": REXS_VERSION,
            "applicationId": "bearingkit",
            "applicationVersion": "0.1",
            "date": datetime.datetime.now(datetime.UTC).replace(microsecond=0).isoformat(),
            "applicationLanguage": "en",
            "relations": rels,
            "components": comps,
            "load_spectrum": {"id": 1, "load_cases": cases},
        }
    }
    text = to_json(model)
    json.loads(text)  # strict JSON (no NaN)
    # the one writer of output files: parent folders made, all or nothing (a bare temporary file beside
    # ``path`` failed when the folder did not exist yet, after the command's other files were written)
    return write_atomic(
        path, lambda tmp: tmp.write_text("\ufeff" + text + "\n", encoding="utf-8"), "REXS model"
    )
