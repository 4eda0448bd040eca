"""Shared by the REXS tests: whether a (mutated) model loads or is refused in one line."""

from __future__ import annotations

import pytest

from bearingkit.errors import InputError


@pytest.fixture
def escape_of():
    """A function: path → None when the model builds a drivetrain or is refused with one InputError
    line, else (what escaped, the message's start) — what the mutation tests look for."""
    from bearingkit.systems.drivetrain.input import load_drivetrain_file

    def check(path):
        try:
            load_drivetrain_file(path)
        except InputError as exc:
            return ("several lines", str(exc)[:120]) if "\n" in str(exc) else None
        except Exception as exc:  # what the mutation tests look for
            return (type(exc).__name__, str(exc)[:120])
        return None

    return check


@pytest.fixture
def assert_same_loads():
    """A function: (cases a, cases b) of two DrivetrainAnalysis dicts → asserts b converged and every
    bearing's radial and axial load equal a's to 1e-9 of that bearing's largest load (its name too)."""

    def check(cases_a, cases_b):
        assert len(cases_a) == len(cases_b)
        for a, b in zip(cases_a, cases_b, strict=True):
            assert b["converged"]
            for x, y in zip(a["bearings"], b["bearings"], strict=True):
                assert y["name"] == x["name"]
                scale = max(abs(x["radial_load_N"]), abs(x["axial_load_N"]), 1.0)
                assert y["radial_load_N"] == pytest.approx(x["radial_load_N"], abs=1e-9 * scale)
                assert y["axial_load_N"] == pytest.approx(x["axial_load_N"], abs=1e-9 * scale)

    return check
