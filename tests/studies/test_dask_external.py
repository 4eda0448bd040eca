"""A study on an external Dask cluster survives a killed worker and gives the one-process result.

Issue 34, "distributed for real": the test starts ``dask-scheduler`` and two ``dask-worker``
processes on 127.0.0.1 (each with its own ``--memory-limit``, no nanny, so a killed worker stays
dead), runs a generic study of the 6209 against ``tcp://127.0.0.1:PORT``, SIGKILLs one worker while
it computes a chunk, and checks that the chunk was computed again on the other worker, that the
store holds every chunk once, and that the results equal an in-process run bit for bit. The
workers need no file of the study: the generic evaluator carries the parsed bearing input.
"""

import dataclasses
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pandas as pd
import pytest

from bearingkit.studies.definition import load as sd
from bearingkit.studies.run.cases import plan_study
from bearingkit.studies.run.executors import DaskExecutor, InProcessExecutor
from bearingkit.studies.run.runner import run_study
from bearingkit.studies.run.store import ParquetStore

HERE = Path(__file__).resolve().parent
EXAMPLE = HERE.parents[1] / "examples" / "dgbb_6209.toml"
CHUNKS, CHUNK = 8, 250
F_X = "load_cases.radial_4kN.F_x"
#: ``dask-scheduler`` and ``dask-worker`` are these modules (the console scripts may not be on PATH).
PY = [sys.executable, "-m"]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _study():
    return sd.from_dict(
        {
            "study": {
                "name": "external_6209",
                "design": "monte_carlo",
                "bearing": str(EXAMPLE),
                "load_case": "radial_4kN",
                "samples": CHUNKS * CHUNK,
                "seed": 34,
                "chunk_size": CHUNK,
                "outputs": ["u_x_m", "u_z_m", "k_xx_N_per_m", "balls_max_load_N", "converged"],
            },
            "factors": [
                {"name": F_X, "distribution": "uniform", "low": "1 kN", "high": "15 kN"},
                {
                    "name": "load_cases.radial_4kN.F_z",
                    "distribution": "uniform",
                    "low": "0 kN",
                    "high": "2 kN",
                },
            ],
        },
        source="external_6209",
    )


def _logged_plan(d):
    """The study's plan with its evaluator wrapped to log every chunk it starts (and its process)."""
    from bk_study_helpers import Logged

    plan = plan_study(d)
    ev = dataclasses.replace(plan.evaluator, function=Logged(plan.evaluator.function, F_X))
    return dataclasses.replace(plan, evaluator=ev)


def _log(path: Path) -> list[tuple[float, int]]:
    if not path.exists():
        return []
    return [(float(a), int(b)) for a, b in (line.split() for line in path.read_text().splitlines() if line)]


@pytest.mark.slow  # a dask-scheduler and two workers started, one killed: ~13 s
def test_external_scheduler_survives_a_killed_worker(tmp_path):
    d = _study()
    log = tmp_path / "calls.log"
    env = {
        **os.environ,
        "PYTHONPATH": os.pathsep.join([str(HERE), os.environ.get("PYTHONPATH", "")]),
        "BK_CALL_LOG": str(log),
        "BK_SLEEP": "0.4",  # each chunk takes ≥ 0.4 s: the kill lands inside one
    }
    port = _free_port()
    address = f"tcp://127.0.0.1:{port}"
    procs = [
        subprocess.Popen(
            [*PY, "distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", str(port),
             "--no-dashboard"],
            env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        )
    ]  # fmt: skip
    try:
        for name, memory in (("w1", "1.5GiB"), ("w2", "2GiB")):
            procs.append(
                subprocess.Popen(
                    [*PY, "distributed.cli.dask_worker", address, "--name", name, "--nthreads", "1",
                     "--memory-limit", memory, "--no-nanny", "--no-dashboard", "--host", "127.0.0.1"],
                    env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                )
            )  # fmt: skip
        workers = {p.pid for p in procs[1:]}
        store = ParquetStore(tmp_path / "out")
        executor = DaskExecutor(scheduler=address)
        deadline = time.monotonic() + 45
        while len(executor.client.scheduler_info()["workers"]) < 2:  # both workers joined
            assert time.monotonic() < deadline, "the workers never joined the scheduler"
            time.sleep(0.1)
        limits = {w["name"]: w["memory_limit"] for w in executor.client.scheduler_info()["workers"].values()}
        assert limits == {"w1": int(1.5 * 2**30), "w2": 2 * 2**30}

        outcome = {}

        def run():
            try:
                outcome["result"] = run_study(
                    d, executor=executor, store=store, progress=False, plan=_logged_plan(d)
                )
            except BaseException as exc:  # reported by the main thread
                outcome["error"] = exc

        runner = threading.Thread(target=run)
        runner.start()
        victim = None
        while victim is None and runner.is_alive():  # the first chunk a worker starts after 2 done
            started = [pid for _, pid in _log(log) if pid in workers]
            if len(started) >= 3:
                victim = started[-1]
            time.sleep(0.02)
        assert victim is not None, f"the study ended before a worker could be killed: {outcome}"
        os.kill(victim, signal.SIGKILL)
        runner.join(timeout=60)
        executor.close()
        assert not runner.is_alive(), "the study did not finish after the kill"
        assert "error" not in outcome, outcome.get("error")
        result = outcome["result"]

        calls = _log(log)
        lost = [x for x, pid in calls if pid == victim][-1]  # the chunk the killed worker was computing
        again = [pid for x, pid in calls if x == lost]
        assert len(again) >= 2 and again[-1] != victim, "the killed worker's chunk was computed again"
        files = sorted((tmp_path / "out" / "chunks").glob("chunk-*.parquet"))
        assert [f.name for f in files] == [f"chunk-{i:06d}.parquet" for i in range(CHUNKS)]
        assert result.results["case"].is_unique and len(result.results) == CHUNKS * CHUNK

        one = run_study(d, executor=InProcessExecutor(threads=1), progress=False)
        pd.testing.assert_frame_equal(result.results, one.results, check_exact=True)
    finally:
        for p in procs:
            if p.poll() is None:
                p.kill()
            p.wait(timeout=10)
