"""The fuzz itself: it finds each class of finding it claims to, its generator reaches every command,
input kind and mutation kind, and a short run over bearingkit finds nothing (issue 41).

The day's 300 mutants run in ``make test`` (tests/fuzz/bk_fuzz_run.py, the seed printed first);
``make fuzz SEED=… N=…`` runs any number.
"""

from __future__ import annotations

import bk_fuzz_inputs as inputs
import bk_fuzz_run as run
import pytest

from bearingkit.app import create_app
from bearingkit.cli import app


def test_each_finding_class_is_found_in_a_planted_app():
    """Every command of the planted app breaks one promise; the fuzz names each.

    Seed 62's first 10 mutants reach every planted command (``badjson`` with ``--json``), ``sleepy``
    once (seed 1 needed 40 mutants, eight of them ``sleepy``: eight 5 s hangs and worker restarts
    made this test 43 s of the suite)."""
    s = run.fuzz(seed=62, n=10, workers=2, hang=5.0, app_spec="bk_fuzz_planted:app")
    by_command = {}
    for r in s["details"]:
        for cls, _ in r["problems"]:
            by_command.setdefault(r["command"], set()).add(cls)
    assert {"traceback"} <= by_command["boom"]
    assert {"json"} <= by_command["badjson"]
    assert {"message"} <= by_command["chatty"]
    assert {"stray"} <= by_command["litter"]
    assert {"warning"} <= by_command["warny"]
    assert "fine" not in by_command
    assert s["findings"]["hang"] >= 1  # sleepy: killed after 5 s, its worker replaced
    assert s["mutants"] == 10  # nothing lost when a worker was killed


def test_a_server_error_is_found():
    class Answer:
        status_code = 500
        text = '{"error": "internal error", "field": null}'

        def __init__(self):
            self.headers = {"content-type": "application/json"}

    class Client:
        def request(self, *args, **kwargs):
            return Answer()

    case = run.Case(
        0, "app", request={"method": "GET", "path": "/", "json": None, "raw": None, "headers": {}}
    )
    problems, *_ = run.run_app_case(Client(), case)
    assert [c for c, _ in problems] == ["server"]


def test_the_generator_covers_every_command_input_kind_and_mutation_kind():
    cmds = run.commands(app)
    files = inputs.example_files()
    routes = [r.path for r in create_app().routes if hasattr(r, "path")]
    kinds = {k for k, _, _ in files.values()}
    kinds |= {"designation", "cli options", "path", "app request", "tolerances", "duty cycle"}
    mutations = set(inputs.FILE_MUTATIONS) | {"option", "unmutated"}
    seen_cmds, seen_kinds, seen_mutations = set(), set(), set()
    for i in range(4000):  # within the first 4000 mutants; stops as soon as everything is seen
        case = run.make_case(20261128, i, cmds, files, routes)
        seen_cmds.add(case.command)
        seen_kinds |= set(case.inputs)
        seen_mutations |= {m.split()[0] for m in case.mutations}
        if set(cmds) | {"app"} <= seen_cmds and kinds <= seen_kinds and mutations <= seen_mutations:
            break
    assert set(cmds) | {"app"} == seen_cmds  # every command of the app, whatever was added since
    assert kinds <= seen_kinds
    assert set(inputs.FILE_MUTATIONS) - {"truncate"} <= seen_mutations
    assert {"truncate", "option", "unmutated"} <= seen_mutations


def test_a_mutant_is_made_again_from_its_seed_and_index():
    cmds, files = run.commands(app), inputs.example_files()
    a = run.make_case(7, 123, cmds, files, ["/api/download/{name}"])
    b = run.make_case(7, 123, cmds, files, ["/api/download/{name}"])
    assert (a.argv, a.files, a.request) == (b.argv, b.files, b.request)


# Slow: it duplicates `make test`'s own fuzz step (tests/fuzz/bk_fuzz_run.py --n 300, which exits 1 on any
# finding) with 60 mutants of a fixed seed; `make test-slow` runs it.
@pytest.mark.slow
def test_sixty_mutants_through_bearingkit_find_nothing():
    s = run.fuzz(seed=2024, n=60, workers=2)
    assert s["details"] == [], s["details"][:3]
    assert s["mutants"] == 60


def test_many_cases_does_not_copy_a_huge_nested_array():
    """many_cases copies the first load case 101-5000 times without its large values, however deeply
    nested: seed 20261201's mutant #4179 (huge_array in load_cases.0.torques.sun, then many_cases
    x 5000) was a 500 MB file whose making took 63 s, reported as a hang of bearingkit."""
    import random

    data = {"load_cases": [{"name": "a", "speed": "100 rpm", "torques": {"sun": [13] * 20_000}}]}
    for seed in range(40):
        trial = {"load_cases": [dict(c) for c in data["load_cases"]]}
        what = inputs._apply("many_cases", trial, random.Random(seed), 20_000)
        assert what.startswith("many_cases load_cases x")
        assert len(trial["load_cases"]) in (101, 1001, 5000)
        assert all("torques" not in c and c["speed"] == "100 rpm" for c in trial["load_cases"])
    case = run.make_case(20261201, 4179, run.commands(app), inputs.example_files(), [])
    assert "many_cases load_cases x 5000" in case.mutations
    assert max(len(t) for t in case.files.values()) < 5_000_000
