"""Every contact of a four-point ball in the JSON (issue 41, Deliver 6): the element loads of the JSON
add up to the load the row carries.

A four-point ball under a radial load or a moment carries on both diagonals; ``loads_N`` gives the most
loaded contact of each ball only (the audit found them summing to about 0.55 of a 5 kN radial load of
QJ 208). ``rows[].contacts`` gives all four with their angles. The sums here are taken from the JSON
alone, independently of the solver: the inner ring's contacts push it along (cos α cos ψ,
cos α sin ψ, sin α) with their loads Q, and at equilibrium that sum is the applied force to the
solver's tolerance (rtol 1e-10 of the load scale).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import bearingkit as bk

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"


def _force(row: dict, side: str) -> np.ndarray:
    """Σ over balls and the ``side`` ring's contacts of Q (cos α cos ψ, cos α sin ψ, sin α), from the
    JSON row alone."""
    contacts = row["contacts"]
    on = [i for i, n in enumerate(contacts["names"]) if n.startswith(side)]
    q = np.asarray(contacts["loads_N"])[:, on]
    a = np.asarray(contacts["contact_angle_rad"])[:, on]
    psi = np.asarray(row["azimuth_rad"])[:, None]
    return np.array(
        [(q * np.cos(a) * np.cos(psi)).sum(), (q * np.cos(a) * np.sin(psi)).sum(), (q * np.sin(a)).sum()]
    )


def _case(file: str, load: dict) -> dict:
    a = bk.analyze(str(EXAMPLES / file), load=load)
    return json.loads(json.dumps(a.statics.to_dict(0)))  # what --json prints: nothing but the JSON


@pytest.mark.parametrize(
    ("file", "load", "force"),
    [
        ("qj_208.toml", {"F_x": "5 kN"}, (5000.0, 0.0, 0.0)),
        ("qj_208.toml", {"F_x": "3 kN", "F_z": "2 kN"}, (3000.0, 0.0, 2000.0)),
        ("slewing_four_point.toml", {"F_z": "50 kN", "M_y": "20 kN*m"}, (0.0, 0.0, 50000.0)),
    ],
)
def test_the_contacts_of_the_json_add_up_to_the_applied_force(file, load, force):
    case = _case(file, load)
    assert case["converged"]
    (row,) = case["rows"]
    contacts = row["contacts"]
    z = len(row["loads_N"])
    assert contacts["names"] == ["outer_upper", "outer_lower", "inner_lower", "inner_upper"]
    assert np.shape(contacts["loads_N"]) == np.shape(contacts["contact_angle_rad"]) == (z, 4)
    # the most loaded contact of each ball is the one loads_N shows
    assert np.allclose(np.max(contacts["loads_N"], axis=1), row["loads_N"], rtol=0, atol=0)
    scale = max(np.abs(force).max(), 1.0)
    inner, outer = _force(row, "inner"), _force(row, "outer")
    assert np.allclose(inner, force, rtol=0, atol=1e-9 * scale), (inner, force)
    # and the outer ring's contacts carry the same (each ball is in equilibrium)
    assert np.allclose(outer, force, rtol=0, atol=1e-9 * scale), (outer, force)


def test_a_radial_load_is_carried_on_both_diagonals():
    """QJ 208 under F_r = 5 kN: the largest contact per ball alone is well short of the load (the
    audit found 0.55); with both diagonals the sum is the load. The groove is symmetric about the ball
    plane, so under a pure radial load each ball carries equally on its two diagonals: one contact
    per ball sums to exactly half the load."""
    (row,) = _case("qj_208.toml", {"F_x": "5 kN"})["rows"]
    q = np.asarray(row["loads_N"])
    psi = np.asarray(row["azimuth_rad"])
    one_pair = (q * np.cos(row["contact_angle_rad"]) * np.cos(psi)).sum()
    assert one_pair == pytest.approx(2500.0, rel=1e-9)
    loaded = np.asarray(row["contacts"]["loads_N"]) > 0
    assert (loaded[:, [0, 2]].any(axis=1) & loaded[:, [1, 3]].any(axis=1)).any(), "both diagonals carry"


def test_a_crossed_roller_row_sums_from_its_element_loads():
    """A crossed roller touches each race once with the same load, along ±α alternately: ``loads_N``
    and ``contact_angle_rad`` are every contact, and their sum is the applied force (the table case of
    the example: F_x 10 kN, F_z 100 kN, M_y 60 kN·m)."""
    case = _case("slewing_crossed_roller.toml", {"F_x": "10 kN", "F_z": "100 kN", "M_y": "60 kN*m"})
    (row,) = case["rows"]
    assert "contacts" not in row
    q, a, psi = (np.asarray(row[k]) for k in ("loads_N", "contact_angle_rad", "azimuth_rad"))
    total = np.array(
        [(q * np.cos(a) * np.cos(psi)).sum(), (q * np.cos(a) * np.sin(psi)).sum(), (q * np.sin(a)).sum()]
    )
    assert np.allclose(total, (1e4, 0.0, 1e5), rtol=0, atol=1e-9 * 1e5), total
    assert (np.sign(a[q > 0]) > 0).any() and (np.sign(a[q > 0]) < 0).any()  # both orientations carry


def test_a_threaded_roller_gives_each_tooth_flank():
    """The PTRB prototype under F_r = 3 kN, F_a = 5 kN and M = 20 N·m loads both flanks of the teeth:
    the sum over ``loads_N`` (every flank at +α) overstates the axial force; ``contacts`` (each tooth,
    flank σ = ±1 at ±α) sums to the applied force."""
    case = _case("ptrb_prototype.toml", {"F_x": "3 kN", "F_z": "5 kN", "M_y": "20 N*m"})
    (row,) = case["rows"]
    contacts = row["contacts"]
    assert set(contacts["ring"]) == {"inner"} and contacts["names"][:2] == ["tooth_1_plus", "tooth_1_minus"]
    q, a = np.asarray(contacts["loads_N"]), np.asarray(contacts["contact_angle_rad"])
    assert np.allclose(q.sum(axis=1), row["loads_N"], rtol=1e-12)  # loads_N: a roller's teeth together
    assert (q[:, 1::2] > 0).any() and np.allclose(a[:, 0::2], -a[:, 1::2])
    psi = np.asarray(row["azimuth_rad"])[:, None]
    total = [(q * np.cos(a) * np.cos(psi)).sum(), (q * np.cos(a) * np.sin(psi)).sum(), (q * np.sin(a)).sum()]
    assert np.allclose(total, (3000.0, 0.0, 5000.0), rtol=0, atol=1e-9 * 5000.0), total
