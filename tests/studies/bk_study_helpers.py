"""Evaluators used by the study tests (importable as ``bk_study_helpers:NAME`` in subprocesses too)."""

import multiprocessing
import os
import time

import numpy as np
import pandas as pd

from bearingkit.studies.evaluators import Evaluator, Factor


def _slow(cases):
    """y = x² + 1 after a short sleep; logs the chunk's first x to $BK_CALL_LOG (counts calls).

    ``$BK_FAIL_AT``: a chunk whose first x is this value raises after 0.5 s (a study that fails
    mid-run). ``$BK_DONE_LOG``: each chunk that finishes appends its first x there.
    ``$BK_WORKERS_ONLY``: in the study's own process (the probe of bearingkit.studies.run.probe, before
    any worker starts) no log, no sleep and no failure: the logs then count the pool workers' chunks.
    """
    if os.environ.get("BK_WORKERS_ONLY") and multiprocessing.parent_process() is None:
        return pd.DataFrame({"y": cases["x"].to_numpy(float) ** 2 + 1.0})
    log = os.environ.get("BK_CALL_LOG")
    first = float(cases["x"].iloc[0])
    if log:
        with open(log, "a", encoding="utf-8") as fh:
            fh.write(f"{first!r}\n")
    if os.environ.get("BK_FAIL_AT") and first == float(os.environ["BK_FAIL_AT"]):
        time.sleep(0.5)
        raise RuntimeError(f"chunk of x = {first} fails on purpose")
    time.sleep(float(os.environ.get("BK_SLEEP", "0.25")))
    if os.environ.get("BK_DONE_LOG"):
        with open(os.environ["BK_DONE_LOG"], "a", encoding="utf-8") as fh:
            fh.write(f"{first!r}\n")
    x = cases["x"].to_numpy(float)
    return pd.DataFrame({"y": x**2 + 1.0})


def pid_of(_item):
    """The process id of the worker that runs it (top-level: picklable by reference)."""
    return os.getpid()


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


class Logged:
    """An evaluator function that logs each chunk it starts and then runs ``inner`` (picklable).

    Each chunk appends ``"<first case value> <pid>"`` to ``$BK_CALL_LOG`` of the process that runs it
    and sleeps ``$BK_SLEEP`` seconds (default 0) before computing, so that a test can see which
    worker started which chunk and kill one mid-chunk.
    """

    def __init__(self, inner, first: str):
        self.inner = inner
        self.first = first  # the factor whose first value names the chunk in the log

    def _log(self, cases):
        log = os.environ.get("BK_CALL_LOG")
        if log:
            with open(log, "a", encoding="utf-8") as fh:
                fh.write(f"{float(cases[self.first].iloc[0])!r} {os.getpid()}\n")
        time.sleep(float(os.environ.get("BK_SLEEP", "0")))

    def __call__(self, cases):
        self._log(cases)
        return self.inner(cases)

    def columns(self, cases):
        self._log(cases)
        return self.inner.columns(cases)
