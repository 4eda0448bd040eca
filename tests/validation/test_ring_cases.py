"""The ring cases of ``bearingkit validate`` (validation/literature_rings.py): each passes its tolerance
against Roark's, Hetényi's, the everted ring's and the in-plane couples' closed forms, and its result
serialises (a numpy bool or float in a published value once broke ``validate --json``)."""

import json

import pytest

from bearingkit.validation.registry import all_cases, run_case

PREFIXES = ("roark/", "hetenyi1946/", "ring-eversion/", "ring-couples/")


def _ring_cases():
    return all_cases(PREFIXES)


def test_ring_cases_are_registered():
    ids = {c.id for c in _ring_cases()}
    for name in ("case1/load-line", "case2/theta60/M_A", "case15/M_B"):
        assert f"roark/table9.2/{name}" in ids
    assert "roark/table13.1/case1a/thin-ring-pressure" in ids
    assert "ring-eversion/uniform-twisting-moment" in ids
    for name in ("M_A", "M_C", "N_A"):
        assert f"ring-couples/in-plane/theta60/{name}" in ids


@pytest.mark.parametrize("case", _ring_cases(), ids=lambda c: c.id)
def test_ring_case_passes_and_serialises(case):
    result = run_case(case)
    assert result.error is None
    assert result.passed, (case.id, result.computed, case.published)
    assert json.loads(json.dumps(result.to_dict()))["id"] == case.id
