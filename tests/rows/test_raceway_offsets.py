"""Per-element raceway offsets (radial, axial, tilt) for every row kind (issue 37).

Two identities, independent of the kernels' own bookkeeping:

- **a rigid move is a rigid move**: per-element offsets equal to the motion of the element's outer
  raceway under a rigid shift s (radial = B_r(z_e) s, axial = B_a(r_e) s, tilt = B_θ s) give the
  contacts the ``shift`` field gives (exact wherever the kernel's kinematics are those of a rigid
  section; the ball rows' shift acts at the INNER groove centre, a tapered roller cannot tilt (its
  two DOFs translate it) and a spherical raceway takes no tilt, so for them the check uses
  translations only);
- **virtual work**: ``raceway_loads`` is −∂U/∂(offset of that element), checked by central differences
  of the row's energy with ONE element's offset moved (the other elements untouched).
"""

import dataclasses

import numpy as np
import pytest

from bearingkit.bearings.ptrb import ptrb_prototype
from bearingkit.bearings.tapered import seed001_row
from bearingkit.physics.contact.profiles import make_profile
from bearingkit.rows.ball.four_point import FourPointRow
from bearingkit.rows.ball.row import BallRow
from bearingkit.rows.ball.speed import BallSpeedKernel
from bearingkit.rows.base import RacewayOffset, axial_row, radial_row, tilt_row
from bearingkit.rows.cylindrical.crossed import CrossedRollerRow
from bearingkit.rows.cylindrical.needle import NeedleRow
from bearingkit.rows.cylindrical.row import CylindricalRow
from bearingkit.rows.cylindrical.speed import CylindricalSpeedKernel
from bearingkit.rows.self_aligning import SelfAligningBallRow, SphericalRollerRow
from bearingkit.rows.threaded.row import ThreadedRow

E_RED = 2.28e11
DEG = np.pi / 180


def _rows():
    """(id, kernel, q scale, exact rigid tilt, energy check) of every row kind."""
    yield (
        "ball-angular",
        BallRow(
            n_elements=13,
            element_diameter=0.0127,
            pitch_diameter=0.065,
            contact_angle=0.4,
            clearance=-2e-6,
            axial_position=0.003,
            e_reduced=E_RED,
        ).kernel(),
        1.0,
        False,
        True,
    )
    dg = BallRow(
        n_elements=9, element_diameter=0.0127, pitch_diameter=0.065, clearance=-1e-6, e_reduced=E_RED
    )
    yield "ball-deep-groove", dg.kernel(), 1.0, False, True
    at_speed = BallSpeedKernel(dataclasses.replace(dg, contact_angle=0.3), 800.0)
    yield "ball-at-speed", at_speed, 1.0, False, False
    yield (
        "four_point",
        FourPointRow(
            n_elements=20,
            element_diameter=0.02,
            pitch_diameter=0.5,
            contact_angle=45 * DEG,
            clearance=-4e-6,
            axial_position=0.004,
            e_reduced=E_RED,
        ).kernel(),
        1.0,
        False,
        True,
    )
    radial = CylindricalRow(
        n_elements=17,
        element_diameter=0.005,
        effective_length=0.008,
        pitch_diameter=0.155,
        clearance=-1e-6,
        n_slices=9,
        axial_position=0.002,
        e_reduced=E_RED,
        profile=make_profile("full_crown", effective_length=0.008, element_diameter=0.005),
    )
    yield "cylindrical-radial", radial.kernel(), 1.0, True, True
    yield "cylindrical-at-speed", CylindricalSpeedKernel(radial, 900.0), 1.0, True, False
    yield (
        "cylindrical-thrust",
        CylindricalRow(
            n_elements=15,
            element_diameter=0.004,
            effective_length=0.0048,
            pitch_diameter=0.167,
            orientation="thrust_down",
            clearance=-2e-6,
            n_slices=7,
            e_reduced=E_RED,
        ).kernel(),
        1.0,
        True,
        True,
    )
    yield (
        "needle",
        NeedleRow(
            n_elements=30,
            element_diameter=0.003,
            effective_length=0.016,
            pitch_diameter=0.053,
            n_slices=8,
            clearance=-2e-6,
            e_reduced=E_RED,
        ).kernel(),
        0.3,
        True,
        True,
    )
    yield (
        "crossed",
        CrossedRollerRow(
            n_elements=60,
            element_diameter=0.012,
            effective_length=0.010,
            pitch_diameter=0.4,
            clearance=-2e-6,
            n_slices=7,
            e_reduced=E_RED,
        ).kernel(),
        1.0,
        True,
        True,
    )
    # The tapered roller has two DOFs (its translation in the meridian plane), no tilt: a cup tilted by an
    # offset loads the cup slices unevenly, a shift tilts the cone's instead (6e-5 apart in the force).
    yield "tapered", seed001_row(deviation_model="exact").kernel(), 1.0, False, True
    yield (
        "spherical_roller",
        SphericalRollerRow(
            n_elements=17,
            element_diameter=0.020,
            effective_length=0.020,
            pitch_diameter=0.14,
            contact_angle=10 * DEG,
            clearance=-5e-6,
            e_reduced=E_RED,
        ).kernel(),
        1.0,
        False,
        True,
    )
    yield (
        "self_aligning_ball",
        SelfAligningBallRow(
            n_elements=15,
            element_diameter=0.0127,
            pitch_diameter=0.072,
            contact_angle=12 * DEG,
            clearance=-3e-6,
            e_reduced=E_RED,
        ).kernel(),
        1.0,
        False,
        True,
    )
    threaded = ThreadedRow(ptrb_prototype(), clearance=-2e-6, axial_position=1e-3, azimuth_phase=0.2)
    yield "threaded", threaded.kernel(), 1.0, True, True


ROWS = list(_rows())
IDS = [r[0] for r in ROWS]


def _q(kernel, scale, n=3, seed=1):
    q = np.random.default_rng(seed).normal(size=(n, 5)) * np.array([3e-6, 3e-6, 3e-6, 1e-5, 1e-5]) * scale
    if getattr(kernel.row, "kind", "") == "tapered":
        q[:, 2] = 30e-6 + np.abs(q[:, 2])  # the cups must be loaded
    if getattr(kernel.row, "direction", 0) not in (0, None) and kernel.row.kind == "cylindrical":
        q[:, 2] = kernel.row.direction * (3e-6 + np.abs(q[:, 2]))
    return q


def _reference(kernel):
    """(psi (Z,), r_e, z_e) of the elements' reference points."""
    row = kernel.row
    psi = np.asarray(kernel.psi, float).reshape(-1)
    if row.kind == "threaded":
        return psi, row.geometry.pitch_diameter / 2, row.axial_position
    return psi, float(np.max(row.pitch_diameter)) / 2, float(np.max(row.axial_position))


def _rigid_offsets(kernel, s):
    psi, r_e, z_e = _reference(kernel)
    return RacewayOffset(
        radial=s @ radial_row(psi, z_e).T, axial=s @ axial_row(psi, r_e).T, tilt=s @ tilt_row(psi).T
    )


@pytest.mark.parametrize("name,kernel,scale,tilt_exact,_", ROWS, ids=IDS)
def test_offsets_of_a_rigid_move_equal_the_shift(name, kernel, scale, tilt_exact, _):
    q = _q(kernel, scale)
    s = np.random.default_rng(7).normal(size=q.shape) * np.array([1e-6, 1e-6, 1e-6, 3e-6, 3e-6]) * scale
    if not tilt_exact:
        s[:, 3:] = 0.0  # translations only (module docstring)
    by_shift = kernel.response(q, RacewayOffset(shift=s))
    local = kernel.response(q, _rigid_offsets(kernel, s))
    scale_f = np.abs(by_shift.force).max()
    rtol = 1e-9
    assert np.abs(local.force - by_shift.force).max() <= rtol * scale_f
    assert local.energy == pytest.approx(by_shift.energy, rel=10 * rtol)


# At speed the ring loads are the outer contacts' (tested below): the rows' energy is not their potential.
POTENTIAL = [r for r in ROWS if r[4]]


@pytest.mark.parametrize("name,kernel,scale,_,energy", POTENTIAL, ids=[r[0] for r in POTENTIAL])
def test_raceway_loads_are_minus_the_energy_gradient(name, kernel, scale, _, energy):
    """−∂U/∂x_j of one element j by central differences against raceway_loads (C, Z, 3)."""
    q = _q(kernel, scale, n=2)
    z = len(np.asarray(kernel.psi).reshape(-1))
    base = np.zeros((q.shape[0], z))
    x0 = {"radial": base + 2e-7, "axial": base - 1e-7, "tilt": base + 3e-6}
    loads = kernel.raceway_loads(q, RacewayOffset(**x0))
    assert loads.shape == (q.shape[0], z, 3)
    steps = {"radial": 1e-9, "axial": 1e-9, "tilt": 1e-7}
    j = int(np.argmax(loads[0, :, :2].sum(-1) ** 2 + loads[0, :, 0] ** 2))  # a loaded element
    for k, key in enumerate(("radial", "axial", "tilt")):
        h = steps[key]
        plus, minus = dict(x0), dict(x0)
        plus[key], minus[key] = base + x0[key], base + x0[key]
        plus[key][:, j] += h
        minus[key][:, j] -= h
        u_plus = kernel.response(q, RacewayOffset(**plus)).energy
        u_minus = kernel.response(q, RacewayOffset(**minus)).energy
        du = (u_plus - u_minus) / (2 * h)
        ref = np.abs(loads[:, j, :]).max() * (1.0 if key != "tilt" else 0.02)
        assert -du == pytest.approx(loads[:, j, k], abs=2e-6 * ref + 1e-9), key


@pytest.mark.parametrize("name", ["ball-at-speed", "cylindrical-at-speed"])
def test_speed_rows_put_their_outer_contact_loads_on_the_ring(name):
    kernel, scale = next((r[1], r[2]) for r in ROWS if r[0] == name)
    q = _q(kernel, scale)
    loads = kernel.raceway_loads(q)
    st = kernel.state(q)
    outer = st.extras["load_outer"]
    if name == "ball-at-speed":
        alpha = st.extras["contact_angle_outer"]
        assert loads[..., 0] == pytest.approx(outer * np.cos(alpha), rel=1e-12, abs=1e-12)
        assert loads[..., 1] == pytest.approx(outer * np.sin(alpha), rel=1e-12, abs=1e-12)
    else:
        assert loads[..., 0] == pytest.approx(outer, rel=1e-12, abs=1e-12)
        assert outer.sum() > st.load.sum()  # the outer contacts carry the centrifugal force too


def test_radial_offsets_alone_keep_the_old_contacts():
    """A radial-only offset (the seed-002 path) gives bit for bit what it gave before axial and tilt
    existed: the outer groove centre moved outward by the offset, s − (w, 0)."""
    kernel = ROWS[0][1]
    q = _q(kernel, 1.0)
    w = np.linspace(0.0, 2e-6, 13)[None, :] * np.ones((q.shape[0], 1))
    _, s, _ = kernel._geometry(q)
    s = s - np.stack([w, np.zeros_like(w)], axis=-1)  # the former code of BallKernel._geometry
    a = np.sqrt(s[..., 0] ** 2 + s[..., 1] ** 2)
    expected = kernel.k_n * kernel._approach(s, a) ** 1.5
    got = kernel.state(q, RacewayOffset(radial=w)).load
    assert np.array_equal(got, expected)
