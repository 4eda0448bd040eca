"""The equilibrium audit (issue 41, Deliver 6): on 650 random valid load cases across every kind of row
the examples hold (deep groove, angular contact, thrust ball, four-point, self-aligning ball,
cylindrical, needle, crossed and spherical roller, tapered, threaded, ball columns), the element
forces of the JSON — summed here, independently of the solver, from ``azimuth_rad``, ``loads_N``,
``contact_angle_rad`` and, for four-point balls and threaded rollers, ``contacts`` — equal the
applied force to 1e-9 of its scale; and every case that does not converge says why in one line
(never a silent result).

Each example bearing file's own load cases are drawn again with every given component scaled by a
random factor in 0.3 … 2 (the file's speeds, fits and temperatures kept), so the cases stay of the kind
the file was written for. The inner ring's contacts push it along (cos α cos ψ, cos α sin ψ, sin α)
with load Q; the moments are left out (they need each contact's position, which the JSON does not
give). Found by this audit: a threaded roller's ``loads_N`` sums its teeth on both flanks at +α, so
under a radial and an axial load (both flanks carry) the axial force summed from ``loads_N`` was up
to 1.8 times the applied one; ``contacts`` gives each flank with its sign.
"""

from __future__ import annotations

import copy
import json
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

import bearingkit as bk
from bearingkit.io import loader

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"
#: Cases drawn per example bearing file (26 files today: 650 cases).
PER_FILE = 25
COMPONENTS = ("F_x", "F_y", "F_z", "M_x", "M_y")
NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)(.*)$")


def _bearing_files() -> list[Path]:
    out = []
    for path in sorted(EXAMPLES.glob("*.toml")):
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        if "bearing" in data and data.get("load_cases") and "shaft" not in data and "shafts" not in data:
            out.append(path)
    return out


def _scaled(value, factor: float):
    m = NUMBER.match(value) if isinstance(value, str) else None
    return f"{float(m.group(1)) * factor!r}{m.group(2)}" if m else value


def _drawn(data: dict, rng: np.random.Generator) -> dict:
    """The file with PER_FILE cases: its own cases in turn, each given component scaled at random."""
    out = copy.deepcopy(data)
    own = data["load_cases"]
    cases = []
    for i in range(PER_FILE):
        case = copy.deepcopy(own[i % len(own)])
        case["name"] = f"draw_{i}"
        for k in COMPONENTS:
            if k in case:
                case[k] = _scaled(case[k], float(rng.uniform(0.3, 2.0)))
        cases.append(case)
    out["load_cases"] = cases
    return out


def _force(row: dict) -> np.ndarray:
    psi = np.asarray(row["azimuth_rad"], float)
    contacts = row.get("contacts")
    if contacts is not None:
        inner = [i for i, ring in enumerate(contacts["ring"]) if ring == "inner"]
        q = np.asarray(contacts["loads_N"], float)[:, inner]
        a = np.asarray(contacts["contact_angle_rad"], float)[:, inner]
        psi = psi[:, None]
    else:
        q = np.asarray(row["loads_N"], float)
        a = np.asarray(row["contact_angle_rad"], float)
    return np.array(
        [(q * np.cos(a) * np.cos(psi)).sum(), (q * np.cos(a) * np.sin(psi)).sum(), (q * np.sin(a)).sum()]
    )


@pytest.mark.slow  # 650 cases of 26 bearings: 48 s on the loaded shared 2-core machine
def test_element_forces_of_the_json_equal_the_applied_force_on_650_random_cases():
    rng = np.random.default_rng(20261128)
    files = _bearing_files()
    kinds, converged, refused = set(), 0, []
    worst = (0.0, None)
    for path in files:
        data = _drawn(tomllib.loads(path.read_text(encoding="utf-8")), rng)
        bearing = loader.from_dict(data, source=str(path))
        cases = json.loads(json.dumps(bk.analyze(bearing).statics.to_dict()))  # the JSON, nothing else
        assert len(cases) == PER_FILE
        for case in cases:
            if not case["converged"]:
                reason = case["reason"] or ""
                assert reason.strip() and "\n" not in reason, (path.name, case)
                refused.append((path.name, reason[:80]))
                continue
            converged += 1
            applied = np.array([case["load"][f"{k}_N"] for k in ("F_x", "F_y", "F_z")])
            total = sum(_force(row) for row in case["rows"])
            kinds |= {row["kind"] for row in case["rows"]}
            scale = max(np.abs(applied).max(), 1.0)
            err = np.abs(total - applied).max() / scale
            if err > worst[0]:
                worst = (err, path.name)
    assert converged >= 500, f"{converged} converged of {PER_FILE * len(files)}; refused: {refused[:5]}"
    assert worst[0] <= 1e-9, worst
    assert {"ball", "four_point", "cylindrical", "tapered", "spherical_roller", "crossed_roller",
            "self_aligning_ball", "threaded"} <= kinds, kinds  # fmt: skip
