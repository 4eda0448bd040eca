"""ISO 76 Table 1 column 2 (self-aligning ball bearings), shipped from memory, against its definition."""

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.physics import tables
from bearingkit.physics.life import kinds


def test_remembered_table_follows_the_stress_definition_within_3_percent():
    """The column's values (one decimal) against f0 from ISO 76's definition at 4600 MPa with the ISO inner
    conformity 0.53 and the outer sphere: a wrong remembered value (a typo of 0.1 is 3-5 %) would fail."""
    g = tables.column("iso76_f0_self_aligning_ball.csv", "gamma")[1:]  # the definition needs γ > 0
    table = kinds.f0_self_aligning_ball_table(g)
    derived = kinds.f0_self_aligning_ball(g)
    np.testing.assert_allclose(table, derived, rtol=0.03)
    assert (np.diff(kinds.f0_self_aligning_ball_table(np.linspace(0, 0.4, 81))) >= 0).all()


def test_table_outside_its_range_refused():
    with pytest.raises(InputError, match="gamma"):
        kinds.f0_self_aligning_ball_table(0.45)
