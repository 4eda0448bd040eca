"""TRB Monte Carlo and seed 001 validation cases."""

import numpy as np
import pytest

from bearingkit.analysis.trb import contact_forces, monte_carlo
from bearingkit.bearings.tapered import seed001_row
from bearingkit.physics.deviations import seed001_series
from bearingkit.validation.registry import all_cases, run_case

IDEAL = 10_000.0 / (23 * np.sin(0.2473))


def test_ideal_case_and_series_ordering():
    dev = np.stack([seed001_series(k) for k in range(1, 7)])
    st = contact_forces(seed001_row(), 10_000.0, dev)
    assert st.converged.all()
    m, v = st.max_contact_force, st.variance
    # Table 3's qualitative findings: max force grows with S_d; descending order lowers the variance.
    assert m[0] < m[2] < m[4] and m[1] < m[3] < m[5]
    assert v[1] < v[0] and v[3] < v[2] and v[5] < v[4]
    assert np.all(m > IDEAL)
    # axial equilibrium of every realisation (seed 001 eq. 6)
    np.testing.assert_allclose(st.load_outer.sum(1) * np.sin(0.2473), 10_000.0, rtol=1e-8)


def test_monte_carlo_batched_and_reproducible():
    a = monte_carlo(seed001_row(), 10_000.0, 1e-6, 64, seed=3)
    b = monte_carlo(seed001_row(), 10_000.0, 1e-6, 64, seed=3)
    np.testing.assert_array_equal(a.stats.max_contact_force, b.stats.max_contact_force)
    assert a.stats.converged.all()
    s = a.summary()
    assert s["ideal_max_contact_force_N"] == pytest.approx(IDEAL, rel=1e-9)
    assert s["max_contact_force_mean_N"] > IDEAL


def test_validation_cases_registered_and_ideal_passes():
    ids = {c.id for c in all_cases(["seed001/"])}
    assert "seed001/ideal/max-contact-force" in ids
    for k in range(1, 7):
        assert f"seed001/table3/series{k}/max-contact-force" in ids
        assert f"seed001/table3/series{k}/variance" in ids
    case = next(c for c in all_cases(["seed001/ideal"]))
    assert run_case(case).passed
    var = next(c for c in all_cases(["seed001/table3/series1/variance"]))
    assert var.published == pytest.approx(0.0162e6)
