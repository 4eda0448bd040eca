"""The ``drivetrain`` study evaluator: a drivetrain file (docs/drivetrains.md) varied case by case.

Factors (SI; a study sets the ones it varies or fixes, the file gives the rest):

- ``file`` (text): the drivetrain file (TOML or REXS), relative to the working directory;
- ``torque_scale``, ``speed_scale`` [-]: every load case's input torques and speeds scaled (the
  duty cycle's level);
- ``ratio_gear`` (text) and ``ratio_teeth`` (count): that gear gets ``ratio_teeth`` teeth and its
  mating gear z₁ + z₂ − ``ratio_teeth`` (the centre distance stays: a gear-ratio study);
- ``bearing`` (text) with ``designation`` (text): that bearing replaced by a standard one (bearing
  choice), and ``axial_offset`` [m]: its outer ring's axial adjustment (preload).

Outputs per study case: the system L10h (ISO/TS 16281 and ISO 281; the Palmgren–Miner duty-cycle life
when the cases give time fractions, else the shortest over the load cases), the shortest bearing
L10h, the largest contact pressure, the efficiency (the smallest over the load cases), the largest
power loss and whether every load case converged. Each study case is one drivetrain solve (the
drivetrain is one batched Newton over its own load cases).
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
    "system_L10h_h",
    "min_bearing_L10h_h",
    "max_pressure_Pa",
    "efficiency",
    "power_loss_W",
    "converged",
)


def _edit(data: dict, row) -> dict:
    data = copy.deepcopy(data)
    from bearingkit.units import parse

    def scaled(value, dimension, unit, factor):
        si = parse(value, dimension, "load_cases") if isinstance(value, str) else float(value)
        return f"{si * factor!r} {unit}"

    for case in data["load_cases"]:
        case["torques"] = {
            k: scaled(v, "moment", "N*m", row["torque_scale"]) for k, v in case.get("torques", {}).items()
        }
        case["speed"] = {
            k: scaled(v, "angular_velocity", "rad/s", row["speed_scale"])
            for k, v in case.get("speed", {}).items()
        }
    gears = {g["name"]: g for s in data["shafts"] for g in s.get("gears", [])}
    if row["ratio_gear"]:
        name, teeth = row["ratio_gear"], int(row["ratio_teeth"])
        mesh = next((m for m in data.get("meshes", []) if name in m["gears"]), None)
        if name not in gears or mesh is None:
            raise InputError(f"ratio_gear ({name!r}) is no gear of a [[meshes]] entry; gears: {list(gears)}")
        other = gears[next(g for g in mesh["gears"] if g != name)]
        total = gears[name]["teeth"] + other["teeth"]
        gears[name]["teeth"], other["teeth"] = teeth, total - teeth
    if row["bearing"]:
        found = [b for s in data["shafts"] for b in s.get("bearings", []) if b["name"] == row["bearing"]]
        if not found:
            raise InputError(f"bearing ({row['bearing']!r}) is no bearing of the drivetrain file")
        b = found[0]
        if row["designation"]:
            for key in ("file", "designation", "stiffness"):
                b.pop(key, None)
            b["designation"] = row["designation"]
        if row["axial_offset"]:
            b["axial_offset"] = float(row["axial_offset"])
    return data


def _lives(da):
    duty = da.duty_cycle()
    if duty is not None:
        return duty["system"]["L10h_h"], duty["system"]["L10h_iso281_h"]
    lives = da.system_lives
    return float(np.nanmin(lives["L10h_h"])), float(np.nanmin(lives["L10h_iso281_h"]))


def evaluate(cases: pd.DataFrame) -> pd.DataFrame:
    """One drivetrain solve per study case (module docstring)."""
    from bearingkit.io.reading import load_toml
    from bearingkit.systems.drivetrain.analysis import DrivetrainAnalysis
    from bearingkit.systems.drivetrain.input import drivetrain_from_dict

    rows, loaded = [], {}
    for _, row in cases.iterrows():  # each case is a whole drivetrain solve (its own batch of load cases)
        path = Path(str(row["file"]))
        if path not in loaded:
            if path.suffix.lower() in (".rexs", ".rexsj", ".json", ".xml"):
                from bearingkit.io.rexs.reader import REXS_NOTES, read_rexs

                loaded[path] = read_rexs(path)
                loaded[path].pop(REXS_NOTES, None)  # a study's table has no notes column
            else:
                loaded[path] = load_toml(path)
        inp = drivetrain_from_dict(_edit(loaded[path], row), str(path), base=path.parent)
        da = DrivetrainAnalysis(inp)
        res = da.result
        ts, iso = _lives(da)
        bearing = [np.nanmin(da.bearing_lives(n)["L10h_h"]) for n in da.bearings]
        pressure = [float(np.max(r.max_pressure)) for a in da.bearings.values() for r in a.statics.rows]
        power = da.power
        rows.append(
            {
                "system_L10h_h": ts,
                "system_L10h_iso281_h": iso,
                "min_bearing_L10h_h": float(min(bearing)) if bearing else np.nan,
                "max_pressure_Pa": max(pressure) if pressure else np.nan,
                "efficiency": np.nan if power is None else float(np.nanmin(power["efficiency"])),
                "power_loss_W": np.nan if power is None else float(np.nanmax(power["loss_W"])),
                "converged": bool(res.converged.all()),
            }
        )
    return pd.DataFrame(rows, columns=list(OUTPUTS))


DRIVETRAIN = Evaluator(
    name="drivetrain",
    function=evaluate,
    factors={
        "file": Factor("file", "text", ""),
        "torque_scale": Factor("torque_scale", "dimensionless", 1.0),
        "speed_scale": Factor("speed_scale", "dimensionless", 1.0),
        "ratio_gear": Factor("ratio_gear", "text", ""),
        "ratio_teeth": Factor("ratio_teeth", "count", 0),
        "bearing": Factor("bearing", "text", ""),
        "designation": Factor("designation", "text", ""),
        "axial_offset": Factor("axial_offset", "length", 0.0),
    },
    outputs=OUTPUTS,
    description="a drivetrain file: gear ratio, bearing choice, preload, duty-cycle level",
)
