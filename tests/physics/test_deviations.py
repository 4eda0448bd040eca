"""Roller diameter deviations: generators, arrangement, Table 2 data."""

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.physics.deviations import arrange, gaussian_deviations, seed001_series, seed001_series_info


def test_reproducible_and_sigma_is_magnitude():
    a = gaussian_deviations(23, 1e-6, 4000, seed=7)
    b = gaussian_deviations(23, 1e-6, 4000, seed=7)
    np.testing.assert_array_equal(a, b)
    assert a.shape == (4000, 23)
    assert abs(a.std() / 1e-6 - 1.0) < 0.02 and abs(a.mean()) < 0.02e-6


def test_descending_arrangement():
    d = gaussian_deviations(23, 1e-6, 5, arrangement="descending", seed=1)
    assert np.all(np.diff(d, axis=1) <= 0)
    np.testing.assert_allclose(np.sort(d, axis=1), np.sort(gaussian_deviations(23, 1e-6, 5, seed=1), axis=1))


def test_table2_series_structure():
    s = {k: seed001_series(k) for k in range(1, 7)}
    for k in (1, 3, 5):
        # the descending series hold the same values sorted (Table 2)
        np.testing.assert_allclose(s[k + 1], arrange(s[k], "descending"), atol=0.011e-6)
        assert seed001_series_info(k)["arrangement"] == "random"
    # series 3 and 5 are series 1 scaled by S_d = 1 and 1.5 µm over 0.5 µm (to the table's rounding)
    np.testing.assert_allclose(s[3], 2 * s[1], atol=0.04e-6)
    np.testing.assert_allclose(s[5], 3 * s[1], atol=0.04e-6)
    assert seed001_series_info(6)["magnitude"] == pytest.approx(1.5e-6)


def test_bad_input():
    with pytest.raises(InputError):
        seed001_series(7)
    with pytest.raises(InputError):
        gaussian_deviations(23, -1e-6)
    with pytest.raises(InputError):
        gaussian_deviations(23, 1e-6, arrangement="ascending")
    with pytest.raises(InputError):
        arrange([0.0, np.inf], "random")
