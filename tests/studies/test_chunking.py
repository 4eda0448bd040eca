"""Chunk sizes from measured costs (``chunk_size = "auto"``) and chunks side by side in threads (issue 34).

The expected sizes below are hand calculations of the rule in ``studies/run/chunking.py``: a
multiple of the workers' count of equal chunks, up to TASKS_PER_WORKER (4) per worker while the fixed
cost stays under OVERHEAD_SHARE (2.5 %) of a chunk, more when a chunk would exceed 60 s.
"""

import threading
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from bearingkit.studies.definition import load as sd
from bearingkit.studies.evaluators import Evaluator, Factor
from bearingkit.studies.run import chunking
from bearingkit.studies.run.chunking import ChunkCost, choose
from bearingkit.studies.run.executors import InProcessExecutor
from bearingkit.studies.run.runner import run_study
from bearingkit.studies.run.store import ParquetStore

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "dgbb_6209.toml"


def test_choose_by_hand():
    # 40 µs per case, 5 ms per chunk: the 2.5 % floor is 5e-3·0.975/(0.025·40e-6) = 4,875 cases
    cost = ChunkCost(per_case_s=40e-6, per_chunk_s=5e-3)
    assert choose(100_000, 2, cost, 10**6) == 12_500  # 4 chunks per worker (100,000 // 9,750 = 10 ≥ 4)
    assert choose(20_000, 2, cost, 10**6) == 5_000  # 20,000 // 9,750 = 2 chunks per worker
    assert choose(5_000, 2, cost, 10**6) == 2_500  # below the floor: still one chunk per worker
    assert choose(5_000, 1, cost, 10**6) == 5_000
    # 1 s per case: a chunk of at most 60 cases; 1,000 cases on 2 workers → ⌈1000 / 120⌉ = 9 per worker
    assert choose(1_000, 2, ChunkCost(1.0, 0.0), 10**6) == 56  # ⌈1000 / 18⌉
    assert choose(100, 4, None, 10**6) == 25  # not measured: one chunk per worker
    assert choose(10**7, 1, ChunkCost(1e-9, 0.0), 10**6) == 10**6  # the cap of a study file
    assert cost.overhead(12_500) == pytest.approx(5e-3 / (5e-3 + 0.5))


def test_measure_recovers_a_linear_cost(monkeypatch):
    """An evaluation costing 5 ms + 40 µs per case (on a fake clock) is measured exactly; the first
    call (warm-up) is not counted; a slow case alone is not probed further."""
    clock = [0.0]
    calls = []

    def evaluate(frame, fixed=5e-3, per_case=40e-6):
        calls.append(len(frame))
        clock[0] += (1.0 if len(calls) == 1 else 0.0) + fixed + per_case * len(frame)

    monkeypatch.setattr(chunking.time, "perf_counter", lambda: clock[0])
    cases = pd.DataFrame({"x": np.arange(100.0)})
    cost = chunking.measure(evaluate, cases, executor_overhead_s=0.004)
    assert calls == [1, 1, 1, 64, 64]  # warm-up, best of two of 1 case, best of two of 64
    assert cost.per_case_s == pytest.approx(40e-6, rel=1e-9)
    assert cost.per_chunk_s == pytest.approx(5e-3 + 0.004, rel=1e-9)
    calls.clear()
    slow = chunking.measure(lambda f: evaluate(f, fixed=0.0, per_case=0.5), cases)
    assert calls == [1, 1, 1] and slow == ChunkCost(per_case_s=0.5, per_chunk_s=0.0)


def _generic(n: int, chunk_size="auto", outputs=("u_x_m", "k_xx_N_per_m", "balls_max_load_N", "converged")):
    return sd.from_dict(
        {
            "study": {
                "name": "chunks_6209",
                "design": "monte_carlo",
                "bearing": str(EXAMPLE),
                "load_case": "radial_4kN",
                "samples": n,
                "seed": 3,
                "chunk_size": chunk_size,
                "outputs": list(outputs),
            },
            "factors": [
                {
                    "name": "load_cases.radial_4kN.F_x",
                    "distribution": "uniform",
                    "low": "1 kN",
                    "high": "15 kN",
                }
            ],
        },
        source="chunks_6209",
    )


def test_auto_size_is_measured_recorded_and_kept_on_resume(tmp_path, monkeypatch):
    d = _generic(chunking.MEASURE_FROM_CASES)
    first = run_study(d, executor=InProcessExecutor(threads=2), store=tmp_path / "out", progress=False)
    size = first.stats["chunk_size"]
    assert first.stats["chunk_cost"]["per_case_s"] > 0
    assert first.stats["chunks"] == -(-len(first.results) // size)
    assert first.stats["chunks"] % 2 == 0, "a multiple of the two threads"
    assert ParquetStore(tmp_path / "out").recorded_chunk_size(_fingerprint(d)) == size
    monkeypatch.setattr(chunking, "choose", lambda *a: pytest.fail("a resumed run measures nothing"))
    again = run_study(d, store=tmp_path / "out", resume=True, progress=False)
    assert again.stats["chunk_size"] == size and again.stats["computed"] == 0
    pd.testing.assert_frame_equal(again.results, first.results, check_exact=True)


def _fingerprint(d):
    from bearingkit.studies.run.cases import plan_study

    return plan_study(d).fingerprint


def test_threads_give_the_sequential_results_bit_for_bit():
    d = _generic(600, chunk_size=100)
    one = run_study(d, executor=InProcessExecutor(threads=1), progress=False)
    two = run_study(d, executor=InProcessExecutor(threads=2), progress=False)
    pd.testing.assert_frame_equal(two.results, one.results, check_exact=True)
    other = run_study(_generic(600, chunk_size=37), executor=InProcessExecutor(threads=2), progress=False)
    cols = ["case", "u_x_m", "k_xx_N_per_m", "balls_max_load_N", "converged"]
    pd.testing.assert_frame_equal(other.results[cols], one.results[cols], check_exact=True)  # compiled core


_BARRIER: list = []


def _meet(cases):
    """Waits until another chunk is inside this function too (fails when chunks run one at a time)."""
    _BARRIER[0].wait(timeout=20)
    return pd.DataFrame({"y": cases["x"].to_numpy(float), "thread": threading.current_thread().name})


MEET = Evaluator("meet", _meet, {"x": Factor("x", "dimensionless", 0.0)}, outputs=("y",))


def test_in_process_threads_run_chunks_side_by_side():
    from bearingkit.studies.run.workers import evaluate_chunk

    _BARRIER[:] = [threading.Barrier(2)]
    cases = [pd.DataFrame({"case": [i], "x": [float(i)]}) for i in range(4)]
    got = dict(InProcessExecutor(threads=2).map_unordered(lambda c: evaluate_chunk(MEET, c), cases))
    assert sorted(got) == [0, 1, 2, 3]
    assert len({got[i]["thread"].iloc[0] for i in got}) == 2
    _BARRIER[:] = [threading.Barrier(2)]
    with pytest.raises(threading.BrokenBarrierError):  # one thread: the first chunk waits alone
        _BARRIER[0].wait(timeout=0.01)


def test_the_stores_take_columns_as_the_workers_send_them(tmp_path):
    """A chunk of numpy columns (text with a missing value among them) reads back as the DataFrame the
    same values make, from the Parquet store and from the memory store alike."""
    from bearingkit.studies.run.store import MemoryStore

    cols = {
        "case": np.array([4, 5, 6]),
        "y": np.array([0.5, np.nan, 2.0]),
        "n": np.array([1, 2, 3], dtype=np.int64),
        "ok": np.array([True, False, True]),
        "error": np.array(["", None, "refused"], dtype=object),
    }
    parquet = ParquetStore(tmp_path / "s")
    parquet.open("f" * 64, 1, 3, resume=False, study="s")
    parquet.write(0, cols)
    memory = MemoryStore()
    memory.open("f" * 64, 1, 3, resume=False)
    memory.write(0, cols)
    expected = pd.DataFrame({k: v for k, v in cols.items() if k != "error"})
    for got in (parquet.read(), memory.read()):
        pd.testing.assert_frame_equal(got.drop(columns="error"), expected, check_exact=True)
        assert (
            got["error"].iloc[0] == "" and pd.isna(got["error"].iloc[1]) and got["error"].iloc[2] == "refused"
        )
    parquet.close()
