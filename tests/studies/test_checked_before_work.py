"""A study's definition is checked whole before any work, and a study that would run for minutes is
refused before it starts (issue 41): quantiles, plots, outputs and names the results would lack,
workers and scheduler addresses, the work estimate of the probe. Nothing is written when refused.
"""

from __future__ import annotations

import os
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.studies.run import executors

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "fuzz"))  # its TOML writer
from bk_fuzz_inputs import toml_text

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
STUDY = EXAMPLES / "studies" / "dgbb_6209_clearance_load.toml"
runner = CliRunner()


def _write(tmp_path: Path, edit) -> Path:
    """The 6209 clearance × load study with ``edit(data)`` applied, beside a copy of its bearing."""
    data = tomllib.loads(STUDY.read_text())
    edit(data)
    folder = tmp_path / "proj" / "studies"
    folder.mkdir(parents=True)
    (folder.parent / "dgbb_6209.toml").write_text((EXAMPLES / "dgbb_6209.toml").read_text())
    path = folder / "s.toml"
    path.write_text(toml_text(data))
    return path


def _refused(tmp_path, edit, fragment, *extra):
    path = _write(tmp_path, edit)
    out = tmp_path / "out"
    res = runner.invoke(app, ["study", str(path), "--out", str(out), *extra])
    assert res.exit_code == 2, (res.stdout, res.stderr)
    assert res.stderr.count("\n") == 1 and fragment in res.stderr, res.stderr
    assert not out.exists()  # nothing written, no chunk computed
    return res.stderr


def _set(path, value):
    def edit(data):
        node = data
        for key in path[:-1]:
            node = node[key]
        node[path[-1]] = value

    return edit


@pytest.mark.parametrize("value", [[float("nan")], [1.5], [0.0], [0.5] * 21])
def test_quantiles_are_checked_by_the_schema(tmp_path, value):
    _refused(tmp_path, _set(("study", "quantiles"), value), "study.quantiles")


def test_a_histogram_asking_for_y_a_thousand_times_is_refused(tmp_path):
    """It cost 225 s."""
    _refused(tmp_path, _set(("plots",), [{"kind": "histogram", "y": ["u_x_m"] * 1000}]), "at most 12 outputs")


def test_plots_and_response_naming_columns_the_results_lack_are_refused_before_any_chunk(
    tmp_path, monkeypatch
):
    calls = []
    real = executors.evaluate_chunk

    def counting(evaluator, cases, with_ids=True):
        calls.append(len(cases))
        return real(evaluator, cases, with_ids)

    monkeypatch.setattr(executors, "evaluate_chunk", counting)

    def edit(data):
        data["study"]["outputs"] = ["u_x_m", "converged"]  # L10r_h, the response, no longer computed
        data.pop("plots")

    _refused(tmp_path, edit, "study.response ('L10r_h') is not an output")
    assert sum(calls) <= 2 * (1 + 4)  # the probe's warm-up and timed calls (1 case, 4): never a chunk of 24


def test_more_workers_than_cores_are_refused(tmp_path):
    cores = os.cpu_count() or 1
    _refused(tmp_path, lambda d: None, "the cores of this machine", "--workers", str(cores + 10))
    _refused(tmp_path / "b", lambda d: None, "must lie in 1", "--workers", "0")


def test_workers_inside_a_daemonic_process_are_refused_in_one_line(tmp_path, monkeypatch):
    """The fuzz (seed 20261129, #302, #4321): ``study --workers 2`` run inside a daemonic process (a
    multiprocessing pool's worker) was an internal error (Python's AssertionError "daemonic processes are
    not allowed to have children") after the probe had run."""
    import multiprocessing

    me = multiprocessing.current_process()
    monkeypatch.setattr(me, "_config", {**me._config, "daemon": True})
    monkeypatch.setattr(os, "cpu_count", lambda: 4)
    line = _refused(tmp_path, lambda d: None, "daemonic worker process", "--workers", "2")
    assert "--workers 1" in line and "--scheduler" in line


@pytest.mark.parametrize("address", ["udp://x", "nonsense", "tcp://", "tcp://host:99999", ""])
def test_a_scheduler_address_is_checked_before_dask_sees_it(tmp_path, address):
    _refused(tmp_path, lambda d: None, "--scheduler", "--scheduler", address)


def test_a_study_past_the_work_limit_is_refused_before_it_starts(tmp_path, monkeypatch):
    monkeypatch.setenv("BEARINGKIT_MAX_WORK_S", "0.001")
    line = _refused(tmp_path, lambda d: None, "would take")
    assert "72 cases" in line and "BEARINGKIT_MAX_WORK_S=" in line and "give fewer levels" in line


def test_within_the_limit_the_study_runs_and_equals_a_run_without_the_probe(tmp_path, monkeypatch):
    """The probe's results are not kept: the study computes every case itself."""
    path = _write(tmp_path, lambda d: None)
    out = tmp_path / "out"
    res = runner.invoke(app, ["study", str(path), "--out", str(out)])
    assert res.exit_code == 0, res.stderr
    import pandas as pd

    from bearingkit.studies.definition.load import load_study
    from bearingkit.studies.run.runner import run_study

    plain = run_study(load_study(path), progress=False).results
    pd.testing.assert_frame_equal(pd.read_parquet(out / "results.parquet"), plain, check_dtype=False)


def test_the_probe_does_not_price_a_one_off_load_as_work_per_case(monkeypatch):
    """The first chunk of several cases loads another compiled driver than a chunk of one (~70 ms for
    the tapered core): timed, it priced seed 001's 6,000-case study at 23 ms a case (0.25 ms measured)
    and refused it. An evaluator with a 60 ms load at the first call of each chunk length and 5 ms a
    case: the estimate is the 5 ms."""
    import time
    from types import SimpleNamespace

    import pandas as pd

    from bearingkit.studies import evaluators
    from bearingkit.studies.run import probe

    def spin(seconds):
        end = time.process_time() + seconds
        while time.process_time() < end:
            pass

    seen = set()

    def function(cases):
        if len(cases) not in seen:
            seen.add(len(cases))
            spin(0.060)
        spin(0.005 * len(cases))
        return pd.DataFrame({"y": np.zeros(len(cases))})

    factors = {"x": evaluators.Factor("x", "dimensionless", 0.0)}
    ev = evaluators.Evaluator("fake", function, factors, fill_defaults=False)
    definition = SimpleNamespace(
        design="factorial", chunk_size=1000, name="fake", source="fake.toml", outputs=None, response=None,
        objectives=[], constraints=[], plots=[], monte_carlo=None, factors=[], fixed={},
    )  # fmt: skip
    cases = pd.DataFrame({"case": np.arange(1000), "x": np.linspace(0.0, 1.0, 1000)})
    plan = SimpleNamespace(definition=definition, evaluator=ev, cases=cases, base={})
    priced = []
    monkeypatch.setattr(probe, "check_work", lambda seconds, what, fewer: priced.append(seconds))
    probe.probe_study(plan)
    # 1,000 cases at 5 ms and one chunk: 5 s of work (the 60 ms loads are not work per case; priced as
    # work they would make it ~20 s). 5 ms, not 1 ms: the evaluate path's own CPU per call (pandas, ~1–2
    # ms, more on a loaded machine) is split over PROBE_CASES − 1 = 3 cases; at 1 ms a case it priced
    # 1.56 s for 1 s in a CI run beside other work
    assert priced and 4.0 < priced[0] < 7.5, priced
