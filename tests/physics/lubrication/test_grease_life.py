"""NSK grease life formula: values and the clamps of its validity conditions."""

import numpy as np
import pytest

from bearingkit.physics.lubrication.grease_life import HOUR, grease_life

RPM = np.pi / 30


def test_general_purpose_value_and_clamps():
    # n/N_max = 0.5, T = 80 °C: log t = 6.54 − 2.6·0.5 − (0.025 − 0.012·0.5)·80 = 3.72.
    t = grease_life(5000 * RPM, 10000 * RPM, 80.0)
    assert t / HOUR == pytest.approx(10**3.72, rel=1e-12)
    # Below n/N_max = 0.25 and 70 °C the formula holds its value there.
    assert grease_life(100 * RPM, 10000 * RPM, 20.0) == pytest.approx(
        grease_life(2500 * RPM, 10000 * RPM, 70.0)
    )
    # Above the grease's temperature range: no estimate.
    assert np.isnan(grease_life(5000 * RPM, 10000 * RPM, 120.0))


def test_wide_range_grease_lasts_longer_when_hot():
    hot = 110.0
    assert grease_life(0.5, 1.0, hot, "wide_range") > grease_life(0.5, 1.0, hot, "general_purpose")
