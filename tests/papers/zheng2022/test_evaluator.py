"""The seed-004 study evaluator (a whole population per call) against the one-design API."""

import numpy as np
import pandas as pd
import pytest

from bearingkit.analysis.friction.threaded import RPM, ptrb_friction
from bearingkit.bearings.ptrb import ptrb_ratings
from bearingkit.papers.zheng2022 import evaluators as zev
from bearingkit.papers.zheng2022.design import design_geometry
from bearingkit.studies.run.executors import evaluate_chunk

#: (α [deg], n, R_rr [m], d_R [m]): the prototype, corners of the §5 ranges, a Table 6-like design.
DESIGNS = [
    (45.0, 10, 5.1e-3, 6.0e-3),
    (32.0, 8, 4.6e-3, 7.1e-3),
    (58.0, 16, 7.4e-3, 4.9e-3),
    (50.0, 12, 6.0e-3, 6.5e-3),
]


@pytest.mark.parametrize("case", ["axial", "radial"])
def test_population_equals_one_design_at_a_time(case):
    # Same formulas on arrays of 4 designs and on one PTRBGeometry each: equal to round-off (the
    # batched Hertz Newton runs a common iteration count, hence not bit for bit; 1e-12 is 4000 ulp).
    a, n, r, d = map(np.array, zip(*DESIGNS, strict=True))
    cases = pd.DataFrame(
        {
            "case": [5, 6, 7, 8],
            "contact_angle": np.radians(a),
            "n_teeth": n,
            "roller_contact_radius": r,
            "roller_pitch_diameter": d,
            "load_case": case,
        }
    )
    out = evaluate_chunk(zev.PTRB, cases)
    assert out["case"].to_list() == [5, 6, 7, 8]
    s = "a" if case == "axial" else "r"
    for i, (ai, ni, ri, di) in enumerate(DESIGNS):
        g = design_geometry(np.radians(ai), ni, ri, di)
        rating = ptrb_ratings(g)
        torque = float(ptrb_friction(g, 20e3, 4000 * RPM, case).torque)
        expected = {
            "C0a_N": rating.static_axial,
            "Ca_N": rating.dynamic_axial,
            "C0r_N": rating.static_radial,
            "Cr_N": rating.dynamic_radial,
            "C0_N": getattr(rating, "static_axial" if s == "a" else "static_radial"),
            "C_N": getattr(rating, "dynamic_axial" if s == "a" else "dynamic_radial"),
            "M_Nm": torque,
            "mu": 2.0 * torque / (g.bore_diameter * 20e3),
            "hertz_margin_m": 2.0 * ri * np.cos(np.radians(ai)) - di,
        }
        for k, v in expected.items():
            assert out[k][i] == pytest.approx(v, rel=1e-12, abs=0.0), (case, i, k)
        assert bool(out["feasible"][i])


def test_columns_equal_the_table():
    """The numpy columns a study's workers take (Evaluator.columns → seed004_ptrb.columns, issue 34) are
    the function's table column for column, bit for bit, over two groups of load case."""
    from bearingkit.studies.run.workers import evaluate_columns

    a, n, r, d = map(np.array, zip(*DESIGNS, strict=True))
    cases = pd.DataFrame(
        {
            "contact_angle": np.radians(a),
            "n_teeth": n,
            "roller_contact_radius": r,
            "roller_pitch_diameter": d,
            "load_case": ["axial", "radial", "axial", "radial"],
        }
    )
    cols = evaluate_columns(zev.PTRB, cases)
    table = evaluate_chunk(zev.PTRB, cases)
    assert list(cols) == list(table.columns)
    for k, v in cols.items():
        np.testing.assert_array_equal(v, table[k].to_numpy(), err_msg=k)
        assert v.dtype == table[k].to_numpy().dtype, k
