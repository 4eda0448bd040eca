"""Helpers of the tapered-row tests: an equilibrium check independent of the solver's directions.

Importable from the tests of this folder (``conftest.py`` puts it on ``sys.path``).
"""

import numpy as np


def _meridian_to_3d(v, psi, sigma):
    """(r, s) components → (x, y, z) at azimuths psi (…, Z) for a row of direction sigma."""
    v = np.asarray(v, float)
    r, s = np.broadcast_arrays(v[..., 0], v[..., 1], psi)[:2]
    return np.stack([r * np.cos(psi), r * np.sin(psi), sigma * s], axis=-1)


def load_from_contacts(model, q):
    """Load (C, 5) the contacts balance, assembled from per-roller contact forces and points in 3D.

    Independent of the solver's generalised directions: every cone slice and rib force of every
    roller is placed at its contact point and summed with explicit cross products. Returns also the
    force sum of the cup contacts (C, 3), which the fixed cup receives.
    """
    total = np.zeros((q.shape[0], 6))
    cup = np.zeros((q.shape[0], 3))
    for kernel in model.kernels:
        row, geo = kernel.row, kernel.geo
        sigma, z0 = float(row.direction), float(row.axial_position)
        psi = kernel.psi  # (Z,)
        st = kernel.roller_state(q)
        # Loads the rollers put on the cone (−n_i per slice) and on the rib (−n_f); the applied
        # load balances them, so it equals their negative: +q n.
        f_i = st["slice_load_inner"][..., None] * geo.n_i  # (C, Z, n_s, 2)
        f_f = st["load_flange"][..., None] * geo.n_f  # (C, Z, 2)
        p_i = kernel.p_i  # (n_s, 2)
        f3_i = _meridian_to_3d(f_i, psi[None, :, None], sigma)
        f3_f = _meridian_to_3d(f_f, psi[None, :], sigma)
        axial = np.array([0.0, 0.0, z0])  # the row plane on the bearing axis
        x3_i = _meridian_to_3d(p_i[None, :, :], psi[:, None], sigma) + axial
        x3_f = _meridian_to_3d(geo.p_f[None, :], psi[:, None], sigma)[:, 0] + axial
        force = f3_i.sum(axis=(1, 2)) + f3_f.sum(axis=1)
        moment = np.cross(x3_i[None], f3_i).sum(axis=(1, 2)) + np.cross(x3_f[None], f3_f).sum(axis=1)
        total += np.concatenate([force, moment], axis=1)
        cup += _meridian_to_3d(st["load_outer"][..., None] * geo.n_e, psi[None, :], sigma).sum(axis=1)
    return total, cup


def assert_equilibrium(model, res, load, rtol=1e-9, atol=0.0):
    """The contact forces balance ``load`` (C, 5) to rtol × its scale + ``atol`` [N] (moments / L).

    ``atol`` allows for the absolute tolerance of each roller's own balance (the kernel's
    ``force_floor`` per roller): the check re-solves the rollers at the solution, so its contact
    forces may differ from the solver's by that much. It matters only under loads of a few newtons.
    """
    q = res.displacement
    got, cup = load_from_contacts(model, q)
    length = max(k.char_length for k in model.kernels)
    scale = np.abs(load[:, :3]).max(axis=1) + np.abs(load[:, 3:]).max(axis=1) / length
    scale = np.maximum(scale, np.abs(got[:, :3]).max(axis=1))
    # Forces and moments (moments over the pitch radius scale, the solver's convention).
    tol = rtol * scale + atol
    np.testing.assert_array_less(np.abs(got[:, :3] - load[:, :3]).max(axis=1), tol)
    np.testing.assert_array_less(np.abs(got[:, 3:5] - load[:, 3:5]).max(axis=1) / length, tol)
    # No torque about the bearing axis (the contact normals lie in meridian planes).
    np.testing.assert_array_less(np.abs(got[:, 5]) / length, tol)
    # Without centrifugal force the cup receives the applied force (the rollers are in balance).
    if all(k.f_c == 0.0 for k in model.kernels):
        np.testing.assert_array_less(np.abs(cup - load[:, :3]).max(axis=1), tol)
