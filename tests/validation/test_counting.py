"""Issue 32: every published number of the four papers is counted once, with a role, and nothing else is.

Registry-level checks (no case is computed here except a few fast ones): the lists of the issue (the 47
numbers that were never compared, the numbers that were compared twice), the roles, the tolerances and
the per-paper summary of ``bearingkit validate``.
"""

import json
import re

import pytest
from typer.testing import CliRunner

from bearingkit.cli import app
from bearingkit.errors import InputError
from bearingkit.validation.registry import (
    PAPERS,
    Case,
    all_cases,
    not_computable,
    run_case,
    run_cases,
    summarize,
)

#: The 47 published numbers the issue lists as never compared → the case id (or not-computable id).
NEVER_COMPARED = {
    # seed 000: recommended clearances and groove range (§6.1.1, §6.1.2, conclusions)
    "seed000 roller -1 um": "seed000/section6.1.1/recommended-roller-clearance",
    "seed000 ball -5 um": "seed000/section6.1.1/recommended-ball-clearance",
    "seed000 groove 0.515": "seed000/section6.1.2/recommended-groove-range-low",
    "seed000 groove 0.53": "seed000/section6.1.2/recommended-groove-range-high",
    # seed 004 §4 lives, §8 mu_a, §5 "< 0.1 N m", §7.2.4, §7.2
    "seed004 life 15.6": "seed004/section4/life/40pct",
    "seed004 life 1.0": "seed004/section4/life/100pct",
    "seed004 mu_a 0.0023": "seed004/section8/mu_a/max",
    "seed004 < 0.1 N m": "seed004/section5/other-parameters-below-0.1Nm",
    "seed004 shock pulse 10 dB": "seed004/section7.2.4/shock-pulse-before",
    "seed004 shock pulse 27 dB": "seed004/section7.2.4/shock-pulse-after",
    "seed004 > 100,000 impacts": "seed004/section7.2.4/impact-count",
    "seed004 efficiency 97 %": "seed004/section7.2/actuator-efficiency",
    "seed004 deviation <= 0.5 %": "seed004/section7.2/efficiency-deviation",
}
for _point in ("xa1", "xa2", "xr1", "xr2"):  # Table 6 design variables (20)
    for _var in ("P", "d_R", "R_rr", "alpha", "n"):
        NEVER_COMPARED[f"seed004 Table 6 {_point} {_var}"] = f"seed004/table6/{_point}/{_var}"
for _case in ("axial", "radial"):  # the Table 7 deviation row (14)
    for _load in (1, 5, 10, 15, 20, 25, 30):
        NEVER_COMPARED[f"seed004 Table 7 deviation {_case} {_load} kN"] = (
            f"seed004/table7/deviation/{_case}/{_load}kN"
        )

#: Numbers that were counted twice (or are derived / the project's alternatives): now diagnostics.
NOT_COUNTED = (
    *(f"seed000/study/table3/run{k}/friction-torque" for k in range(1, 10)),  # Table 3 twice
    *(f"seed000/study/table3/range/{f}" for f in "ABCD"),  # derived from Table 3
    "seed001/ideal/max-contact-force",  # 1776 N = F_a/(Z sin α_e), not in the paper
    "seed001/figure5/inner-torque-falls-first-newtonian_mpa",  # a rejected reading
    "seed001/figure6a/inner-change-speed-dependent-then-constant-newtonian_mpa",
    "seed001/finding/sliding-increment-ratio-slip-invariance-newtonian",
    *(f"seed004/table4/n_elements/11/{r}" for r in ("C0a", "C0r", "Ca", "Cr")),  # prototype ratings twice
    "seed004/table7/axial/5kN",  # Table 7 / Table 8 share 5 kN, 600 rpm
    "seed004/table7/radial/5kN",
    "seed004/table7-test/axial/5kN",
    "seed004/table7-test/radial/5kN",
    "seed004/section7/friction/axial/5kN/800rpm",  # = Table 8 test, 5 kN, 800 rpm
    "seed004/section7/friction/radial/5kN/800rpm",
    "seed004/section7/impact/before/axial",  # = Table 7 test, 10 kN
    "seed004/section7/impact/before/radial",
    *(
        f"seed004/study/table6/{p}/{q}"  # Table 6 at the nearest Pareto point (counted at the published x)
        for p in ("xa1", "xa2", "xr1", "xr2")
        for q in ("C0a", "Ca", "mu_a", "C0r", "Cr", "mu_r")
    ),
    "seed002/condition1/flexible-ovalised/roller-loaded-count",  # another ring model of the same count
    "seed002/condition1/flexible-ovalised/ball-row3-loaded-count",
    "seed002/figure16/rigid/loaded-rollers-78",  # = §3.2's 39 at the same state
    "seed002/figure15/flexible/loaded-balls-70",
    "seed002/figure15/flexible/loaded-balls-78",
    "seed002/figure16/flexible/loaded-rollers-74",
    "seed002/figure16/flexible/loaded-rollers-78",
    "seed002/gradient/heavy-load/roller-radial-share-flexible",
)

#: The calibrations (the published number each identified constant is fitted on), per paper.
CALIBRATIONS = {
    "seed000/table3/run1/friction-torque",
    "seed001/table3/series1/max-contact-force",
    "seed002/condition1/flexible/roller-loaded-count",
    "seed004/prototype/C0a",
    "seed004/prototype/C0r",
    "seed004/table7/axial/20kN",
}


def _state(case_id: str):
    """The (quantity, state) a published torque or count of the duplicate-prone families refers to."""
    m = re.fullmatch(r"seed004/table([78])(-test)?/(axial|radial)/(\d+)kN(?:/(\d+)rpm)?", case_id)
    if m:
        return ("test" if m[2] else "sim", m[3], int(m[4]), int(m[5] or 600))
    m = re.fullmatch(r"seed004/section7/friction/(axial|radial)/5kN/800rpm", case_id)
    if m:
        return ("test", m[1], 5, 800)
    m = re.fullmatch(r"seed004/section7/impact/before/(axial|radial)", case_id)
    if m:
        return ("test", m[1], 10, 600)
    m = re.fullmatch(r"seed004/section4/(axial|radial)/30kN/(\d+)rpm", case_id)
    if m:
        return ("sim", m[1], 30, int(m[2]))
    m = re.fullmatch(r"seed004/(?:prototype|table4/n_elements/11)/(C0a|C0r|Ca|Cr)", case_id)
    if m:
        return ("rating", "prototype", m[1])
    m = re.fullmatch(r"seed000/(?:study/)?table3/run(\d)/friction-torque", case_id)
    if m:
        return ("table3", int(m[1]))
    m = re.fullmatch(r"seed002/condition1/\w+/roller-loaded-count", case_id)
    if m:
        return ("rollers", case_id.split("/")[2] == "rigid")
    if case_id == "seed002/figure16/rigid/loaded-rollers-78":
        return ("rollers", True)
    return None


def test_every_number_of_the_issue_list_is_present():
    ids = {c.id for c in all_cases()} | {i.id for i in not_computable()}
    missing = {k: v for k, v in NEVER_COMPARED.items() if v not in ids}
    assert not missing
    assert len(NEVER_COMPARED) == 47


def test_duplicates_derived_values_and_alternatives_are_not_counted():
    cases = {c.id: c for c in all_cases()}
    for cid in NOT_COUNTED:
        assert cid in cases, cid
        assert cases[cid].role == "diagnostic" and cases[cid].note, cid


def test_no_published_state_in_two_counted_cases():
    """The same published quantity at the same state (Table 7/8's shared 5 kN points, §7.2's repeats of
    Table 7/8, the prototype's ratings, Table 3 through the study, §3.3.2's count at §3.2's state) is
    counted once."""
    seen = {}
    for c in all_cases(diagnostics=False):
        state = _state(c.id)
        if state is None:
            continue
        assert state not in seen, (c.id, seen.get(state))
        seen[state] = c.id
    assert len(seen) >= 139  # the families above are there (Tables 7, 8, §4, ratings, Table 3, counts)


def test_roles_calibrations_and_tolerances():
    cases = all_cases()
    assert {c.id for c in cases if c.role == "calibration"} == CALIBRATIONS
    for c in cases:
        assert c.role in ("prediction", "calibration", "diagnostic"), c.id
        if c.role != "prediction":
            assert c.note, c.id
        if c.counted and c.group != "literature" and c.tolerance > 0.10:
            assert c.tolerance_reason, f"{c.id}: tolerance {c.tolerance:.3g} > 10 % needs a stated reason"
    # literature cases are their own group, never a paper's
    assert {c.group for c in cases} == {*PAPERS, "literature"}
    assert all(c.group == "literature" for c in cases if not c.id.startswith("seed"))
    # a not-computable number says why, and each paper has its list
    items = not_computable()
    assert all(i.why and i.published for i in items)
    assert {i.group for i in items} == {"seed000", "seed004"}


def test_case_rejects_a_role_without_a_note():
    with pytest.raises(InputError, match="role"):
        Case("t/x", "s", "q", "1", 1.0, lambda: 1.0, 0.0, role="guess")
    with pytest.raises(InputError, match="note"):
        Case("t/x", "s", "q", "1", 1.0, lambda: 1.0, 0.0, role="diagnostic")


def test_summary_counts_predictions_calibrations_and_deviations():
    pred_ok = Case("seed000/t/a", "s", "q", "1", 2.0, lambda: 2.0, 0.01)
    pred_known = Case("seed000/t/b", "s", "q", "1", 2.0, lambda: 3.0, 0.01, known_deviation="why")
    cal = Case("seed000/t/c", "s", "q", "1", 2.0, lambda: 2.0, 0.01, role="calibration", note="fit")
    diag = Case("seed000/t/d", "s", "q", "1", 2.0, lambda: 9.0, 0.01, role="diagnostic", note="derived")
    lit = Case("harris/t/e", "s", "q", "1", 2.0, lambda: 2.0, 0.01)
    results = run_cases([pred_ok, pred_known, cal, diag, lit])
    assert [r.status for r in results] == ["pass", "known", "calibrated", "diagnostic", "pass"]
    s000, lit_s = summarize(results, ["no-such-prefix"])
    assert (s000.group, s000.predictions, s000.passing, s000.calibrations, s000.deviations) == (
        "seed000",
        2,
        1,
        1,
        1,
    )
    assert s000.diagnostics == 1 and s000.failures == 0
    assert (lit_s.group, lit_s.predictions, lit_s.passing) == ("literature", 1, 1)
    missed_cal = run_case(
        Case("seed000/t/f", "s", "q", "1", 2.0, lambda: 3.0, 0.01, role="calibration", note="x")
    )
    assert missed_cal.status == "FAIL"


def test_validate_prints_a_summary_a_table_and_roles():
    runner = CliRunner()
    res = runner.invoke(app, ["validate", "seed001/ideal", "seed001/table3/series1", "stribeck"])
    assert res.exit_code == 0, res.output
    assert "predictions passing" in res.stdout and "seed001" in res.stdout and "literature" in res.stdout
    assert "seed001/table3" not in res.stdout  # the summary only, not the rows
    table = runner.invoke(app, ["validate", "seed001/ideal", "seed001/table3/series1", "--table", "--all"])
    assert "seed001/ideal/max-contact-force" in table.stdout and "diagnostic" in table.stdout
    counted = runner.invoke(app, ["validate", "seed001/ideal", "seed001/table3/series1", "--json"])
    rows = {r["id"]: r for r in json.loads(counted.stdout)}
    assert "seed001/ideal/max-contact-force" not in rows  # a diagnostic: only with --all
    assert rows["seed001/table3/series1/max-contact-force"]["role"] == "calibration"
    assert rows["seed001/table3/series1/variance"]["role"] == "prediction"
    every = runner.invoke(app, ["validate", "seed001/ideal", "--json", "--all"])
    assert json.loads(every.stdout)[0]["role"] == "diagnostic"
