"""ROSS export: a rotor with bearingkit's exported stiffness has the critical speeds of the same rotor
with that stiffness typed in by hand.

Needs ross-rotordynamics (the ``[ross]`` extra, ROSS 2.3+ or 3). ``make test-slow`` installs it and runs
this file (ROSS's start-up, numba compilation included, takes 12-20 s, once per test process). Under CI a
missing ROSS is a failure, not a skip; elsewhere it is skipped.
"""

from __future__ import annotations

import dataclasses
import os
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bearingkit.errors import InputError
from bearingkit.systems.shaft.input import load_shaft_file
from bearingkit.systems.shaft.solver import solve
from bearingkit.systems.shaft.stiffness import shaft_stiffness_table, write_tables

SPINDLE = Path(__file__).resolve().parents[2] / "examples" / "shaft_spindle.toml"
# One test process runs every ROSS test (--dist loadgroup): importing ROSS takes 12-20 s, paid once instead of
# once per process. Slow (make test-slow, which installs the [ross] extra): ROSS's start-up and eight rotors,
# ~33 s (a ninth of `make test`'s parallel run when it ran there). What make test keeps: the stiffness
# tables these rotors are built from (tests/systems/test_stiffness_export.py) and the one-line error
# without the extra (tests/test_extras.py).
pytestmark = [pytest.mark.ross, pytest.mark.slow, pytest.mark.xdist_group("ross")]


def _ross():
    from bearingkit.systems.ross import import_ross

    try:
        return import_ross()
    except InputError:
        if os.environ.get("CI"):
            pytest.fail("ross-rotordynamics must be installed in CI (make test-slow installs [ross])")
        pytest.skip("ross-rotordynamics not installed (pip install 'bearingkit[ross]')")


def _speed_keyword(rs) -> str:
    """How a user types a rotor-speed table into the installed ROSS: ``speed=`` from ROSS 3.0 (PR #1371),
    ``frequency=`` before (read from ROSS's version, independently of bearingkit's signature check)."""
    return "speed" if int(rs.__version__.split(".")[0]) >= 3 else "frequency"


def _first_critical_speeds(rotor, n=2):
    # Rotors with the same matrices follow the same Newton path in ROSS, so its default tolerance
    # (0.5 %) still gives equal results to round-off; 6 modes hold the first two whirl pairs.
    return np.sort(rotor.run_critical_speed(num_modes=6).wn())[:n]


def test_exported_stiffness_gives_the_critical_speeds_of_hand_entered_stiffness(tmp_path):
    rs = _ross()
    from bearingkit.systems.ross import ross_rotor

    inp = load_shaft_file(SPINDLE)
    # A coarser mesh than the file's (nodal results are exact either way) keeps ROSS's eigen solves short.
    inp = dataclasses.replace(inp, system=dataclasses.replace(inp.system, max_element_length=0.03))
    res = inp.solve()
    assert res.converged.all()
    # 1. Exported: constant stiffness of load case 0 at each seat.
    exported = ross_rotor(res, cases=[0])
    # 2. By hand: the same shaft elements, bearings typed from the CSV file bearingkit wrote.
    path = write_tables([shaft_stiffness_table(res, b.name) for b in inp.system.bearings], tmp_path / "k.csv")
    csv = pd.read_csv(path)
    hand_bearings = []
    for b, node in zip(inp.system.bearings, res.assembly.seat_nodes, strict=True):
        row = csv[(csv["bearing"] == b.name) & (csv["point"] == inp.loads.names[0])].iloc[0]
        hand_bearings.append(
            rs.BearingElement(
                n=int(node),
                kxx=float(row["K_ux_ux_N_per_m"]),
                kxy=float(row["K_ux_uy_N_per_m"]),
                kyx=float(row["K_uy_ux_N_per_m"]),
                kyy=float(row["K_uy_uy_N_per_m"]),
                kzz=float(row["K_uz_uz_N_per_m"]),
                cxx=0.0,
            )
        )
    by_hand = rs.Rotor(exported.shaft_elements, exported.disk_elements, hand_bearings)
    # 3. Speed-indexed: load case 0 at four speeds (the rows soften with their centrifugal force) →
    #    elements whose coefficients ROSS interpolates over speed, against the same four-point tables
    #    typed by hand from the CSV bearingkit writes.
    speeds = np.array([100.0, 400.0, 900.0, 1600.0])
    sweep = dataclasses.replace(inp.loads.take([0]), names=tuple("abcd"), speed=speeds)
    res4 = solve(inp.system, sweep)
    indexed = ross_rotor(res4)
    from bearingkit.systems.ross import speed_axis

    assert speed_axis(rs) == _speed_keyword(rs)
    axis = getattr(indexed.bearing_elements[0], _speed_keyword(rs))
    assert axis is not None and len(axis) == 4
    path4 = write_tables(
        [shaft_stiffness_table(res4, b.name) for b in inp.system.bearings], tmp_path / "k4.csv"
    )
    csv4 = pd.read_csv(path4).sort_values("speed_rad_s", kind="stable")
    hand_indexed = []
    for b, node in zip(inp.system.bearings, res4.assembly.seat_nodes, strict=True):
        rows = csv4[csv4["bearing"] == b.name]
        hand_indexed.append(
            rs.BearingElement(
                n=int(node),
                **{_speed_keyword(rs): rows["speed_rad_s"].to_numpy(float)},
                cxx=np.zeros(len(rows)),
                **{
                    key: rows[col].to_numpy(float)
                    for key, col in (
                        ("kxx", "K_ux_ux_N_per_m"),
                        ("kxy", "K_ux_uy_N_per_m"),
                        ("kyx", "K_uy_ux_N_per_m"),
                        ("kyy", "K_uy_uy_N_per_m"),
                        ("kzz", "K_uz_uz_N_per_m"),
                    )
                },
            )
        )
    by_hand_indexed = rs.Rotor(indexed.shaft_elements, indexed.disk_elements, hand_indexed)
    # the spindle's bearings soften with speed: the speed-indexed table is not flat
    kxx = csv4[csv4["bearing"] == inp.system.bearings[0].name]["K_ux_ux_N_per_m"].to_numpy(float)
    assert kxx[-1] < 0.99 * kxx[0]

    wn_exported = _first_critical_speeds(exported)
    wn_hand = _first_critical_speeds(by_hand)
    wn_indexed = _first_critical_speeds(indexed)
    wn_hand_indexed = _first_critical_speeds(by_hand_indexed)
    assert np.all(wn_exported > 100.0)
    assert np.allclose(wn_exported, wn_hand, rtol=1e-6)
    assert np.allclose(wn_indexed, wn_hand_indexed, rtol=1e-6)
    # The bearings matter in this rotor: ten times stiffer bearings move the first critical speed.
    stiff = [
        rs.BearingElement(
            n=b.n, kxx=10 * b.kxx[0], kyy=10 * b.kyy[0], kxy=10 * b.kxy[0], kyx=10 * b.kyx[0], cxx=0.0
        )
        for b in hand_bearings
    ]
    wn_stiff = _first_critical_speeds(rs.Rotor(exported.shaft_elements, exported.disk_elements, stiff))
    assert wn_stiff[0] / wn_hand[0] - 1 > 0.01


def _modal_wn(rotor, speed, n=4, **whirl):
    return np.sort(np.asarray(rotor.run_modal(speed=speed, num_modes=12, **whirl).wn))[:n]


def test_a_speed_table_is_read_along_the_rotor_speed_axis(tmp_path):
    """Issue 42 (ROSS 3 gave ``frequency=`` the meaning of the whirl frequency): at a speed of the
    exported table, the natural frequencies of the rotor equal those of the same rotor with the bearings'
    stiffness AT that speed typed in as constants (from the CSV bearingkit writes). On ROSS 3 the modal
    analysis is asked for another whirl frequency (another point of the table): a rotor-speed table
    ignores it, a table wrongly passed along the whirl axis would be read there, and the frequencies
    would differ (checked by hand with the ROSS 2 keyword on ROSS 3.1: this assertion fails). On ROSS 2
    both axes are the rotor speed (synchronous evaluation)."""
    rs = _ross()
    from bearingkit.systems.ross import ross_rotor

    inp = load_shaft_file(SPINDLE)
    inp = dataclasses.replace(inp, system=dataclasses.replace(inp.system, max_element_length=0.03))
    speeds = np.array([100.0, 700.0, 1300.0, 1900.0, 2500.0])
    sweep = dataclasses.replace(inp.loads.take([0]), names=tuple("abcde"), speed=speeds)
    res = solve(inp.system, sweep)
    assert res.converged.all()
    indexed = ross_rotor(res)
    csv = pd.read_csv(
        write_tables([shaft_stiffness_table(res, b.name) for b in inp.system.bearings], tmp_path / "k.csv")
    )
    keys = (("kxx", "K_ux_ux_N_per_m"), ("kxy", "K_ux_uy_N_per_m"), ("kyx", "K_uy_ux_N_per_m"),
            ("kyy", "K_uy_uy_N_per_m"), ("kzz", "K_uz_uz_N_per_m"))  # fmt: skip
    kxx = csv[csv["bearing"] == inp.system.bearings[0].name]["K_ux_ux_N_per_m"].to_numpy(float)
    assert kxx[-1] < 0.97 * kxx[0]  # the table is not flat: the axis matters
    for i in (1, 3):  # table points inside the range (no end effects of the interpolation)
        at = csv[np.isclose(csv["speed_rad_s"], speeds[i])]
        constant = [
            rs.BearingElement(
                n=b.n, cxx=0.0, **{k: float(at[at["bearing"] == b.tag][col].iloc[0]) for k, col in keys}
            )
            for b in indexed.bearing_elements
        ]
        fixed = rs.Rotor(indexed.shaft_elements, indexed.disk_elements, constant)
        whirl = {"frequency": float(speeds[4 - i])} if _speed_keyword(rs) == "speed" else {}
        wn_table, wn_fixed = _modal_wn(indexed, speeds[i], **whirl), _modal_wn(fixed, speeds[i], **whirl)
        assert np.all(wn_fixed > 0)
        assert np.allclose(wn_table, wn_fixed, rtol=1e-6), (speeds[i], wn_table, wn_fixed)


def test_repeated_names_become_distinct_rotor_tags(tmp_path):
    """Two masses of one name (the default "mass", or a table repeated: the fuzz's seed 20261202 #1333
    ended in ROSS's 'Tags should be unique' as an internal error): the rotor loads, each element tagged
    once, later repeats with " #2", " #3"."""
    from bearingkit.systems.ross import ross_rotor

    _ross()
    text = SPINDLE.read_text(encoding="utf-8")
    start = text.index("[[shaft.masses]]")
    block = text[start:].split("\n\n")[0] + "\n\n"
    for line in text.splitlines():  # the bearing files it names, beside it
        if line.strip().startswith("file"):
            name = line.split("=", 1)[1].split("#")[0].strip().strip('"')
            (tmp_path / name).write_bytes((SPINDLE.parent / name).read_bytes())
    path = tmp_path / "spindle.toml"
    path.write_text(text[:start] + block * 3 + text[start + len(block) :], encoding="utf-8")
    inp = load_shaft_file(path)
    masses = inp.system.masses
    assert len(masses) == 3 and len({m.name for m in masses}) == 1
    res = inp.solve()
    assert res.converged.all()
    rotor = ross_rotor(res, [0])
    name = masses[0].name
    tags = [d.tag for d in rotor.disk_elements]
    assert [t for t in tags if t.startswith(name)] == [name, f"{name} #2", f"{name} #3"]
    assert len(set(tags)) == len(tags)
