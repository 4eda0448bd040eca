"""No case holds a batch hostage (issue 41, Deliver 5): a case that cannot converge is stopped by its own
budget, and the rest of its batch finishes as it would alone.

The audit's case: a 51209 under F_z = 1 mN at 3,000 rpm (the balls' centrifugal forces dwarf the load:
there is no balance to find) ran past 190 s of processor time, and in a two-case file it held the other
case with it past 300 s. The numpy reference now charges every case its row evaluations and its share
of the processor time, and stops a case past either (``SolverOptions.max_evaluations``,
``BEARINGKIT_CASE_SECONDS``) with a reason naming the budget and how to raise it.
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest

import bearingkit as bk

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "thrust_ball_51209.toml"
CASES = """
[[load_cases]]
name = "usual"
F_z = "2 kN"
speed = "1879 rpm"

[[load_cases]]
name = "hostage"
F_z = "0.001 N"
speed = "3000 rpm"
"""


def _file(tmp_path: Path, cases: str) -> str:
    text = EXAMPLE.read_text()
    head, solver = text.split("[[load_cases]]")[0], "[solver]" + text.split("[solver]")[1]
    path = tmp_path / "two_cases.toml"
    path.write_text(head + cases + "\n" + solver)
    return str(path)


@pytest.fixture
def numpy_core(monkeypatch):
    """The numpy reference (where the per-case budget lives), with a 1 s budget per case."""
    monkeypatch.setenv("BEARINGKIT_BACKEND", "numpy")
    monkeypatch.setenv("BEARINGKIT_CASE_SECONDS", "1")


def test_an_unsolvable_case_is_stopped_by_its_budget_and_its_batch_finishes(tmp_path, numpy_core):
    t0 = time.process_time()
    statics = bk.analyze(_file(tmp_path, CASES)).statics
    spent = time.process_time() - t0
    usual, hostage = statics.to_dict()
    assert usual["converged"] and not hostage["converged"]
    reason = hostage["reason"]
    assert "\n" not in reason and "budget" in reason, reason
    assert "BEARINGKIT_CASE_SECONDS" in reason or "max_iterations" in reason, reason
    # the batch took about the hostage's budget, not minutes (the audit: > 300 s)
    assert spent < 15.0, f"{spent:.1f} s of processor time"
    alone = bk.analyze(_file(tmp_path, CASES.split('[[load_cases]]\nname = "hostage"')[0])).statics
    (one,) = alone.to_dict()
    q_batch = np.array(list(usual["displacement"].values()))
    q_alone = np.array(list(one["displacement"].values()))
    assert np.allclose(q_batch, q_alone, rtol=1e-9, atol=1e-9 * np.abs(q_alone).max())
    assert usual["rows"][0]["max_load_N"] == pytest.approx(one["rows"][0]["max_load_N"], rel=1e-9)
