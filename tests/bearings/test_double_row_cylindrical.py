"""Double-row cylindrical roller bearing (NN30): two equal sliced rows on shared rings. Checked against
two single-row bearings built independently (the same rollers), the moment balance of the two rows, the
ISO 281 double-row rating C = 2^(7/9) C_row with P = F_r, and bad input."""

from __future__ import annotations

import json

import numpy as np
import pytest
from typer.testing import CliRunner

from bearingkit.analysis.solver.quasistatic import solve
from bearingkit.bearings.standard import cylindrical_roller, cylindrical_roller_double
from bearingkit.cli import app
from bearingkit.errors import InputError
from bearingkit.physics.contact.profiles import make_profile

GEOM = dict(n_elements=31, element_diameter=0.011, effective_length=0.01065, pitch_diameter=0.125)
PROFILE = make_profile("iso16281", effective_length=0.01065, element_diameter=0.011)
SPACING = 0.0185


def _double(**kw):
    return cylindrical_roller_double(
        **GEOM, row_spacing=SPACING, clearance_radial=30e-6, profile=PROFILE, **kw
    )


def test_radial_load_is_shared_and_deflects_like_one_row_with_half_the_load():
    """Under F_x alone each row carries F/2; the deflection equals a single-row bearing's (same rollers,
    same clearance) under F/2: the rows are independent springs in parallel on the shared rings."""
    free = [True, True, False, False, False]
    res2 = solve(_double(), [20e3, 0, 0, 0, 0], free=free, raise_on_failure=True)
    single = cylindrical_roller(**GEOM, clearance_radial=30e-6, profile=PROFILE)
    res1 = solve(single, [10e3, 0, 0, 0, 0], free=free, raise_on_failure=True)
    assert res2.displacement[0, 0] == pytest.approx(res1.displacement[0, 0], rel=1e-8)
    per_row = [float(np.sum(r.load[0] * np.cos(r.azimuth[0]))) for r in res2.rows]
    np.testing.assert_allclose(per_row, [10e3, 10e3], rtol=1e-6)


def test_moment_is_carried_by_the_pair():
    """M_y with the tilt free: the row on the loaded side carries more; the radial forces still sum to
    F_x, and their difference times the half spacing gives most of M (the rest: each row's own slices)."""
    free = [True, True, False, True, True]
    res = solve(_double(), [20e3, 0, 0, 0, 50.0], free=free, raise_on_failure=True)
    fa, fb = (float(np.sum(r.load[0] * np.cos(r.azimuth[0]))) for r in res.rows)
    assert fa + fb == pytest.approx(20e3, rel=1e-6)
    assert fb > fa
    assert 0.7 * 50.0 < (fb - fa) * SPACING / 2 <= 50.0


def test_overlapping_rows_are_refused():
    with pytest.raises(InputError, match=r"row_spacing.*must exceed effective_length"):
        cylindrical_roller_double(**GEOM, row_spacing=0.01)


def test_nn3020_has_the_double_row_iso281_rating():
    """`bearingkit rating NN3020`: ISO 281 rates the two equal rows as one double-row bearing, C = 2^(7/9)
    C_row (ISO 281 7.1, i = 2) with P = F_r (α = 0)."""
    result = CliRunner().invoke(
        app, ["rating", "NN3020", "--load", "Fr=20kN", "--speed", "1500rpm", "--json"]
    )
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["bearing_type"] == "cylindrical_roller"
    case = data["cases"][0]
    system = case["system"]
    c_rows = [r["C_N"] for r in case["rows"]]
    assert len(c_rows) == 2 and c_rows[0] == pytest.approx(c_rows[1])
    assert system["C_iso281_N"] == pytest.approx(2 ** (7 / 9) * c_rows[0], rel=1e-9)
    assert system["P_iso281_N"] == pytest.approx(20e3, rel=1e-9)


FILE = """
[bearing]
type = "cylindrical_roller"
[geometry]
n_elements = 31
element_diameter = "11 mm"
effective_length = "10.65 mm"
pitch_diameter = "125 mm"
{extra}
[[load_cases]]
name = "radial"
F_x = "20 kN"
"""


def test_input_file_rows_2_builds_the_double_row_bearing():
    from bearingkit.io.loader import loads

    b = loads(FILE.format(extra='rows = 2\nrow_spacing = "18.5 mm"'))
    assert [r.name for r in b.model.rows] == ["rollers_A", "rollers_B"]
    np.testing.assert_allclose([r.axial_position for r in b.model.rows], [-0.00925, 0.00925])


@pytest.mark.parametrize("extra", ["rows = 2", 'row_spacing = "18.5 mm"', "rows = 3"])
def test_input_file_rows_and_spacing_go_together(extra):
    from bearingkit.io.loader import loads

    with pytest.raises(InputError) as err:
        loads(FILE.format(extra=extra))
    assert "\n" not in str(err.value) and "rows" in str(err.value)
