"""The validation registry and `bearingkit validate` (keys, exit codes, prefixes)."""

import json

import numpy as np
import pytest
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.errors import InputError
from bearingkit.validation.registry import Case, failures, relative_error, run_case, run_cases

KEYS = {
    "id",
    "group",
    "role",
    "note",
    "tolerance_reason",
    "error",
    "source",
    "quantity",
    "unit",
    "published",
    "computed",
    "rel_error",
    "tolerance",
    "passed",
    "known_deviation",
}


def test_case_outcomes():
    ok = run_case(Case("t/ok", "src", "q", "1", 2.0, lambda: 2.01, 0.01))
    bad = run_case(Case("t/bad", "src", "q", "1", 2.0, lambda: 2.5, 0.01))
    known = run_case(Case("t/known", "src", "q", "1", 2.0, lambda: 2.5, 0.01, known_deviation="why"))
    boom = run_case(Case("t/boom", "src", "q", "1", 2.0, lambda: 1 / 0, 0.01))
    assert ok.passed and not bad.passed and not known.passed and not boom.passed
    assert ok.rel_error == pytest.approx(0.005)
    assert "ZeroDivisionError" in boom.error
    assert [r.case.id for r in failures([ok, bad, known, boom])] == ["t/bad", "t/boom"]
    assert set(ok.to_dict()) == KEYS
    assert boom.to_dict()["computed"] is None  # JSON-safe, never NaN


def test_relative_error_sign_and_zero():
    assert relative_error(0.9, 1.0) == pytest.approx(-0.1)
    assert relative_error(0.1, 0.0) == pytest.approx(0.1)


def test_case_rejects_bad_ids():
    with pytest.raises(InputError, match="id"):
        Case("has space", "s", "q", "1", 1.0, lambda: 1.0, 0.1)


def test_validate_json_prefix_and_exit_code():
    runner = CliRunner()
    res = runner.invoke(app, ["validate", "--json", "stribeck"])
    assert res.exit_code == 0, res.output
    rows = json.loads(res.stdout)
    assert {r["id"] for r in rows} == {"stribeck/ball-zero-clearance", "stribeck/line-zero-clearance"}
    assert all(set(r) == KEYS and r["passed"] for r in rows)
    none = runner.invoke(app, ["validate", "no-such-prefix"])
    assert none.exit_code == 2


def test_every_case_serialises_to_plain_json_types():
    """A case registered with numpy scalars (published value, a numpy bool from the comparison) is
    written as plain JSON by ``validate --json`` (the ring cases once stopped it with a TypeError)."""
    case = Case("numpy/scalar", "s", "q", "1", np.float64(2.0), lambda: np.float64(2.0), np.float64(0.01))
    row = run_cases([case])[0].to_dict()
    assert json.loads(json.dumps(row))["passed"] is True
    assert all(type(v) in (str, float, bool, type(None)) for v in row.values()), row
