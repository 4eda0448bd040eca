"""Evaluators used by the study tests (importable as ``bk_study_helpers:NAME`` in subprocesses too)."""

import os
import time

import numpy as np
import pandas as pd

from bearingkit.studies.evaluators import Evaluator, Factor


def _slow(cases):
    """y = x² + 1 after a short sleep; logs the chunk's first x to $BK_CALL_LOG (counts calls)."""
    log = os.environ.get("BK_CALL_LOG")
    if log:
        with open(log, "a", encoding="utf-8") as fh:
            fh.write(f"{float(cases['x'].iloc[0])!r}\n")
    time.sleep(float(os.environ.get("BK_SLEEP", "0.25")))
    x = cases["x"].to_numpy(float)
    return pd.DataFrame({"y": x**2 + 1.0})


SLOW = Evaluator("slow_counter", _slow, {"x": Factor("x", "dimensionless", 0.0)}, outputs=("y",))

#: Known additive effects a_j(level) of the synthetic model y = 10 + Σ_j a_j(x_j).
EFFECTS = {"p": (0.0, 5.0, 2.0), "q": (0.0, 0.5, 1.0), "r": (3.0, 0.0, 0.0), "s": (0.0, 0.1, 0.2)}


def _additive(cases):
    y = np.full(len(cases), 10.0)
    for f, eff in EFFECTS.items():
        y += np.asarray(eff)[cases[f].to_numpy(int)]
    return pd.DataFrame({"y": y})


ADDITIVE = Evaluator("additive", _additive, {f: Factor(f, "count", 0) for f in EFFECTS}, outputs=("y",))


def _mixed(cases):
    """Two objectives of an integer n ∈ 1..6 and a continuous x ∈ [0, 2]; constraint c = n·x ≥ 1."""
    n = cases["n"].to_numpy(float)
    x = cases["x"].to_numpy(float)
    return pd.DataFrame({"cost": n + x, "loss": 1.0 / n + (x - 1.0) ** 2, "c": n * x})


MIXED = Evaluator(
    "mixed",
    _mixed,
    {"n": Factor("n", "count", 1), "x": Factor("x", "dimensionless", 0.0)},
    outputs=("cost", "loss"),
)
