"""The ``shaft`` study evaluator: a shaft file (docs/systems.md) varied case by case.

Factors (SI; a study sets the ones it varies or fixes, the file gives the rest):

- ``file`` (text): the shaft file, relative to the working directory (its bearing files relative to it);
- ``load_scale`` [-]: every load case's forces, moments, line loads and gear torques scaled;
- ``speed_scale`` [-]: every load case's speed scaled;
- ``bearing`` (text): the bearing the next three factors change, by its name in the file;
- ``designation`` (text): that bearing replaced by a standard one (bearing choice);
- ``position_change`` [m]: added to that bearing's position (bearing spacing);
- ``axial_offset_change`` [m]: added to that bearing's axial offset (axial adjustment, preload).

Outputs per study case, over the file's load cases (each study case is one shaft solve: one batched
Newton over its load cases, then every bearing's analysis, :class:`~bearingkit.systems.shaft.
shaft_analysis.ShaftAnalysis`): first the shortest ISO 281 system L10h and L_nmh (the bearings' ISO 281
lives combined by the Weibull rule, :func:`~bearingkit.systems.shaft.life.iso281_system_life`), then the
shortest system L10h (ISO/TS 16281; the bearings combined by
:func:`~bearingkit.systems.shaft.life.combine_ratings`) and system L_nmh, the shortest bearing L10h by
ISO/TS 16281 and by ISO 281, the smallest static safety, the largest contact pressure, radial bearing
load, seat misalignment, shaft deflection and bending moment, the largest power loss, and whether
every load case converged.
"""

from __future__ import annotations

import copy
from pathlib import Path

import numpy as np
import pandas as pd

from bearingkit.errors import InputError
from bearingkit.studies.evaluators import Evaluator, Factor

OUTPUTS = (
    "system_L10h_iso281_h",
    "system_Lnmh_iso281_h",
    "system_L10h_h",
    "system_Lnmh_h",
    "min_bearing_L10h_h",
    "min_bearing_L10h_iso281_h",
    "min_static_safety",
    "max_pressure_Pa",
    "max_bearing_radial_load_N",
    "max_misalignment_rad",
    "max_radial_deflection_m",
    "max_bending_moment_Nm",
    "power_loss_W",
    "converged",
)
#: Load-case fields a ``load_scale`` multiplies → their dimension and SI unit.
_SCALED = {
    "F_x": ("force", "N"),
    "F_y": ("force", "N"),
    "F_z": ("force", "N"),
    "M_x": ("moment", "N*m"),
    "M_y": ("moment", "N*m"),
    "q_x": ("line_load", "N/m"),
    "q_y": ("line_load", "N/m"),
    "q_z": ("line_load", "N/m"),
}


def _scaled(value, dimension: str, unit: str, factor: float, where: str) -> str:
    from bearingkit.units import parse

    si = parse(value, dimension, where) if isinstance(value, str) else float(value)
    return f"{si * factor!r} {unit}"


def edit(data: dict, row) -> dict:
    """A copy of the parsed shaft file with the row's factors applied (module docstring)."""
    data = copy.deepcopy(data)
    load, speed = float(row["load_scale"]), float(row["speed_scale"])
    for i, case in enumerate(data.get("load_cases", [])):
        where = f"load_cases[{i}]"
        if load != 1.0:
            case["gears"] = {
                k: _scaled(v, "moment", "N*m", load, f"{where}.gears.{k}")
                for k, v in case.get("gears", {}).items()
            }
            for key in ("forces", "line_loads"):
                for item in case.get(key, []):
                    for field, (dimension, unit) in _SCALED.items():
                        if field in item:
                            item[field] = _scaled(
                                item[field], dimension, unit, load, f"{where}.{key}.{field}"
                            )
        if speed != 1.0 and case.get("speed") is not None:
            case["speed"] = _scaled(case["speed"], "angular_velocity", "rad/s", speed, f"{where}.speed")
    name = row["bearing"]
    changes = row["designation"] or row["position_change"] or row["axial_offset_change"]
    if not name:
        if changes:
            raise InputError(
                "bearing: give the bearing that designation / position_change / axial_offset_change change"
            )
        return data
    bearings = data.get("shaft", {}).get("bearings", [])
    found = [b for b in bearings if b.get("name") == name]
    if not found:
        raise InputError(
            f"bearing ({name!r}) is no bearing of the shaft file; bearings: "
            f"{[b.get('name') for b in bearings]}"
        )
    b = found[0]
    if row["designation"]:
        for key in ("file", "designation", "stiffness"):
            b.pop(key, None)
        b["designation"] = row["designation"]
    from bearingkit.units import parse

    for key, change in (("position", row["position_change"]), ("axial_offset", row["axial_offset_change"])):
        if change:
            given = b.get(key, 0.0)
            si = parse(given, "length", f"shaft.bearings.{key}") if isinstance(given, str) else float(given)
            b[key] = f"{si + float(change)!r} m"
    return data


def _case_outputs(sa) -> dict:
    """The outputs of one solved ShaftAnalysis (module docstring)."""
    data = sa.to_dict()
    cases = data["cases"]
    lives, modified, bearing_ts, bearing_iso, safety, pressure, radial, tilt, deflection, moment, loss = (
        [] for _ in range(11)
    )
    iso_lives, iso_modified = [], []
    for c in cases:
        system = c["rating"]["system"]
        iso_lives.append(system.get("L10h_iso281_h"))
        iso_modified.append(system.get("Lnm_iso281_h"))
        lives.append(system.get("L10h_h"))
        modified.append(system.get("Lnmr_h"))
        deflection.append(c["shaft"]["max_radial_deflection_m"])
        moment.append(c["shaft"]["max_bending_moment_Nm"])
        loss.append(c["power_loss_W"])
        for b in c["bearings"]:
            s = b["summary"]
            bearing_ts.append(s["L10h_h"])
            safety.append(s["static_safety"])
            pressure.append(s["max_pressure_Pa"])
            radial.append(s["radial_load_N"])
            tilt.append(s["misalignment_rad"])
            rated = (c["rating"].get("bearings") or {}).get(b["name"]) or {}
            bearing_iso.append(rated.get("L10h_iso281_h"))

    def lowest(values):
        v = [float(x) for x in values if x is not None and np.isfinite(x)]
        return min(v) if v else np.nan

    def highest(values):
        v = [float(x) for x in values if x is not None and np.isfinite(x)]
        return max(v) if v else np.nan

    return {
        "system_L10h_iso281_h": lowest(iso_lives),
        "system_Lnmh_iso281_h": lowest(iso_modified),
        "system_L10h_h": lowest(lives),
        "system_Lnmh_h": lowest(modified),
        "min_bearing_L10h_h": lowest(bearing_ts),
        "min_bearing_L10h_iso281_h": lowest(bearing_iso),
        "min_static_safety": lowest(safety),
        "max_pressure_Pa": highest(pressure),
        "max_bearing_radial_load_N": highest(radial),
        "max_misalignment_rad": highest(tilt),
        "max_radial_deflection_m": highest(deflection),
        "max_bending_moment_Nm": highest(moment),
        "power_loss_W": highest(loss),
        "converged": bool(sa.result.converged.all()),
    }


def evaluate(cases: pd.DataFrame) -> pd.DataFrame:
    """One shaft solve per study case (module docstring)."""
    from bearingkit.io.reading import load_toml
    from bearingkit.systems.shaft.input import shaft_from_dict
    from bearingkit.systems.shaft.shaft_analysis import ShaftAnalysis

    rows, loaded = [], {}
    for _, row in cases.iterrows():  # each case is a whole shaft solve (its own batch of load cases)
        path = Path(str(row["file"]))
        if path not in loaded:
            loaded[path] = load_toml(path)
        inp = shaft_from_dict(edit(loaded[path], row), str(path), base=path.parent)
        rows.append(_case_outputs(ShaftAnalysis(inp)))
    return pd.DataFrame(rows, columns=list(OUTPUTS))


SHAFT = Evaluator(
    name="shaft",
    function=evaluate,
    factors={
        "file": Factor("file", "text", ""),
        "load_scale": Factor("load_scale", "dimensionless", 1.0),
        "speed_scale": Factor("speed_scale", "dimensionless", 1.0),
        "bearing": Factor("bearing", "text", ""),
        "designation": Factor("designation", "text", ""),
        "position_change": Factor("position_change", "length", 0.0),
        "axial_offset_change": Factor("axial_offset_change", "length", 0.0),
    },
    outputs=OUTPUTS,
    description="a shaft file: load and speed level, bearing choice, bearing spacing, axial adjustment",
)
