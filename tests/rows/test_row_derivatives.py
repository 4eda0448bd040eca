"""Row derivatives: analytic Jacobian vs central finite differences, force = −∂U/∂q (virtual work)."""

import numpy as np
import pytest

from bearingkit.physics.contact.profiles import make_profile
from bearingkit.rows.ball.row import BallRow
from bearingkit.rows.cylindrical.row import CylindricalRow

E_RED = 2.28e11  # [Pa] any positive value; the derivative identities do not depend on it


def _rows():
    yield BallRow(
        n_elements=13,
        element_diameter=0.0127,
        pitch_diameter=0.065,
        contact_angle=0.4,
        clearance=-2e-6,
        axial_position=0.003,
        azimuth_phase=0.1,
        e_reduced=E_RED,
    )
    yield BallRow(
        n_elements=11,
        element_diameter=0.006,
        pitch_diameter=0.1778,
        contact_angle=-np.pi / 2,
        conformity_inner=0.52,
        conformity_outer=0.52,
        clearance=-4e-6,
        axial_position=-0.01,
        e_reduced=E_RED,
    )
    yield CylindricalRow(
        n_elements=17,
        element_diameter=0.005,
        effective_length=0.008,
        pitch_diameter=0.155,
        orientation="radial",
        clearance=-1e-6,
        n_slices=9,
        axial_position=0.002,
        e_reduced=E_RED,
        profile=make_profile("full_crown", effective_length=0.008, element_diameter=0.005),
    )
    yield CylindricalRow(
        n_elements=15,
        element_diameter=0.004,
        effective_length=0.0048,
        pitch_diameter=0.167,
        orientation="thrust_down",
        clearance=-2e-6,
        n_slices=7,
        e_reduced=E_RED,
    )


def _q(rng, n):
    # displacements of a few µm and rotations of ~1e-4 rad: every row has some contacts closed
    return rng.normal(size=(n, 5)) * np.array([3e-6, 3e-6, 3e-6, 5e-5, 5e-5])


@pytest.mark.parametrize("row", list(_rows()), ids=lambda r: f"{r.kind}-{getattr(r, 'orientation', '')}")
def test_jacobian_matches_finite_differences(row):
    kernel = row.kernel()
    q = _q(np.random.default_rng(1), 4)
    jac = kernel.response(q).jacobian
    steps = np.array([1e-10, 1e-10, 1e-10, 1e-9, 1e-9])
    fd = np.empty_like(jac)
    for i in range(5):
        dq = np.zeros(5)
        dq[i] = steps[i]
        fd[:, :, i] = (kernel.response(q + dq).force - kernel.response(q - dq).force) / (2 * steps[i])
    scale = np.abs(fd).max()
    assert scale > 0
    np.testing.assert_allclose(jac, fd, atol=1e-5 * scale, rtol=1e-4)


@pytest.mark.parametrize("row", list(_rows()), ids=lambda r: f"{r.kind}-{getattr(r, 'orientation', '')}")
def test_force_is_minus_energy_gradient(row):
    kernel = row.kernel()
    q = _q(np.random.default_rng(2), 3)
    force = kernel.response(q).force
    steps = np.array([1e-10, 1e-10, 1e-10, 1e-9, 1e-9])
    for i in range(5):
        dq = np.zeros(5)
        dq[i] = steps[i]
        grad = (kernel.response(q + dq).energy - kernel.response(q - dq).energy) / (2 * steps[i])
        np.testing.assert_allclose(-grad, force[:, i], rtol=1e-4, atol=1e-6 * np.abs(force).max())


@pytest.mark.parametrize("row", list(_rows()), ids=lambda r: f"{r.kind}-{getattr(r, 'orientation', '')}")
def test_jacobian_symmetric_negative_semidefinite(row):
    jac = row.kernel().response(_q(np.random.default_rng(3), 5)).jacobian
    np.testing.assert_allclose(jac, np.swapaxes(jac, 1, 2), atol=1e-9 * np.abs(jac).max())
    assert np.linalg.eigvalsh(jac).max() <= 1e-9 * np.abs(jac).max()


def test_state_loads_match_response_force():
    """The per-element loads reported sum (as vectors) to the generalised force of the row."""
    row = CylindricalRow(
        n_elements=20,
        element_diameter=0.004,
        effective_length=0.0048,
        pitch_diameter=0.167,
        orientation="thrust_up",
        n_slices=10,
        e_reduced=E_RED,
    )
    kernel = row.kernel()
    q = np.array([[0.0, 0.0, 3e-6, 1e-5, 0.0]])
    st = kernel.state(q)
    assert np.isclose(st.load.sum(), -kernel.response(q).force[0, 2], rtol=1e-12)
    assert np.isclose(st.slice_load.sum(axis=-1), st.load).all()


def test_batched_geometry_equals_separate_rows():
    """A row whose clearance is an array over cases answers like one row per case."""
    clear = np.array([0.0, -2e-6, 3e-6])
    kw = dict(
        n_elements=17,
        element_diameter=0.005,
        effective_length=0.008,
        pitch_diameter=0.155,
        orientation="radial",
        n_slices=9,
        e_reduced=E_RED,
        profile=make_profile("full_crown", effective_length=0.008, element_diameter=0.005),
    )
    q = _q(np.random.default_rng(4), 3)
    batched = CylindricalRow(clearance=clear, **kw).kernel().response(q)
    for c in range(3):
        one = CylindricalRow(clearance=float(clear[c]), **kw).kernel().response(q[c : c + 1])
        np.testing.assert_allclose(batched.force[c], one.force[0], rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(batched.jacobian[c], one.jacobian[0], rtol=1e-12, atol=1e-3)
        np.testing.assert_allclose(batched.energy[c], one.energy[0], rtol=1e-12, atol=1e-18)


def test_dense_small_batch_path_equals_the_per_roller_path(monkeypatch):
    import bearingkit.rows.cylindrical.row as cyl

    for row in list(_rows())[2:]:
        kernel = row.kernel()
        q = _q(np.random.default_rng(5), 4)
        dense = kernel.response(q)
        monkeypatch.setattr(cyl, "SMALL_BATCH", 0)
        sliced = kernel.response(q)
        monkeypatch.setattr(cyl, "SMALL_BATCH", 8)
        np.testing.assert_allclose(dense.force, sliced.force, rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(dense.jacobian, sliced.jacobian, rtol=1e-12, atol=1e-3)
        np.testing.assert_allclose(dense.energy, sliced.energy, rtol=1e-12, atol=1e-18)
