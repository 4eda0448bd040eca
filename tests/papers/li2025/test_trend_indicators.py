"""The rises/falls indicators of the seed-002 trend validation: round-off on a plateau is no reversal.

Closed cases: a strictly rising series, a plateau whose last step is −2e-12 N on 13.5 kN (1.3e-16
relative, the size two solves of the same equilibrium differ by), and a genuine dip of 1 N.
"""

import numpy as np

from bearingkit.papers.li2025.validation_trends import PLATEAU_RTOL, _monotone


def test_rounding_on_a_plateau_is_not_a_reversal():
    assert _monotone(np.array([12621.27, 13500.000000000005, 13500.000000000004]), +1) == 1.0
    assert _monotone(np.array([3.0, 2.0, 2.0 + PLATEAU_RTOL]), -1) == 1.0  # step 1e-12 < 3e-12


def test_a_real_reversal_or_a_flat_sweep_fails():
    assert _monotone(np.array([12621.27, 13500.0, 13499.0]), +1) == 0.0
    assert _monotone(np.array([13500.0, 13500.0, 13500.0 * (1 + 1e-16)]), +1) == 0.0  # no rise at all
    assert _monotone(np.array([1.0, 2.0, 3.0]), -1) == 0.0
