"""Imported structure matrices: the round trip of a ring model through node DOFs, and every check's
one-line refusal (non-symmetric, singular, rigid-body modes, sizes, the node ↔ element mapping)."""

import numpy as np
import pytest

from bearingkit.errors import InputError
from bearingkit.rings.curved_beam import FlexibleRing
from bearingkit.rings.imported import ImportedStructure, ring_export
from bearingkit.rings.sections import rectangular_section
from bearingkit.rings.supports import Foundation

SEC = rectangular_section(0.20, 0.23, -0.02, 0.02)
RING = FlexibleRing(
    SEC, foundation=Foundation.seat(4e9, 0.04) + Foundation(tangential=1e8, axial=2e8, twist=30.0)
)
PSI = np.linspace(0, 2 * np.pi, 20, endpoint=False) + 0.05
R_E, Z_E = 0.19, 0.004


@pytest.mark.parametrize("kind", ["compliance", "stiffness"])
def test_a_ring_exported_and_imported_is_the_same_ring(kind):
    """The ring's translations at its raceway nodes, written as an FE export would (Cartesian u_x, u_y,
    u_z), read back: the radial and axial compliance of the ring model; no rotational DOF, no tilt."""
    c, nodes = ring_export(RING, PSI, R_E, Z_E)
    matrix = c if kind == "compliance" else np.linalg.inv(c)
    got = ImportedStructure(matrix, nodes, ("ux", "uy", "uz"), kind).compliance(PSI, R_E, Z_E)
    ref = RING.compliance(PSI, R_E, Z_E).reshape(20, 3, 20, 3)
    got = got.reshape(20, 3, 20, 3)
    assert got[:, :2, :, :2] == pytest.approx(ref[:, :2, :, :2], rel=1e-7, abs=1e-9 * np.abs(ref).max())
    assert np.all(got[:, 2] == 0) and np.all(got[:, :, :, 2] == 0)


def test_rotations_of_the_ring_alone_are_singular():
    """r_x, r_y from the twist only: rotation about e_r is not a ring DOF, so the export is singular."""
    c, nodes = ring_export(RING, PSI, R_E, Z_E, dofs=("ux", "uy", "uz", "rx", "ry"))
    with pytest.raises(InputError, match="compliance is singular"):
        ImportedStructure(c, nodes, ("ux", "uy", "uz", "rx", "ry"), "compliance")


def _valid():
    c, nodes = ring_export(RING, PSI, R_E, Z_E, dofs=("ux", "uy", "uz"))
    return np.linalg.inv(c), nodes


@pytest.mark.parametrize(
    "change,message",
    [
        (lambda k, n: (k + np.triu(np.full_like(k, 1e-3 * np.abs(k).max()), 1), n), "not symmetric"),
        (lambda k, n: (k[:-1], n), "must be square"),
        (lambda k, n: (k[:-3, :-3], n), "does not match the nodes"),
        (
            lambda k, n: (k - np.eye(len(k)) * 2 * np.abs(np.linalg.eigvalsh(k)).max(), n),
            "not positive definite",
        ),
        (lambda k, n: (np.where(np.isfinite(k), k, 0) * np.nan, n), "non-finite"),
    ],
    ids=["asymmetric", "not-square", "size", "negative", "nan"],
)
def test_bad_matrices_are_refused_in_one_line(change, message):
    k, nodes = change(*_valid())
    with pytest.raises(InputError, match=message) as err:
        ImportedStructure(k, nodes, ("ux", "uy", "uz"), "stiffness", source="hub.mtx")
    assert "\n" not in str(err.value) and str(err.value).startswith("hub.mtx: ")


def _truss(nodes):
    """Stiffness of a complete truss on the nodes (axial springs): a free body, exactly 6 rigid modes."""
    n = len(nodes)
    k = np.zeros((3 * n, 3 * n))
    for i in range(n):
        for j in range(i + 1, n):
            e = nodes[j] - nodes[i]
            e = e / np.linalg.norm(e)
            b = 1e8 * np.outer(e, e)
            for a, s in ((i, 1), (j, -1)):
                for c, t in ((i, 1), (j, -1)):
                    k[3 * a : 3 * a + 3, 3 * c : 3 * c + 3] += s * t * b
    return k


def test_rigid_body_modes_are_counted():
    z = np.where(np.arange(20) % 2 == 0, 0.004, -0.004)  # not coplanar: the truss holds out of plane too
    nodes = np.stack([R_E * np.cos(PSI), R_E * np.sin(PSI), z], -1)
    free = _truss(nodes)
    with pytest.raises(InputError, match="6 rigid-body modes"):
        ImportedStructure(free, nodes)
    imp = ImportedStructure(free, nodes, free=True)
    c = imp.node_compliance()
    assert np.abs(c @ imp.rigid_motions()).max() <= 1e-8 * np.abs(c).max()  # the rigid part left out
    # a singular stiffness whose null space is not rigid motion: a mechanism
    bad = free.copy()
    bad[:3, :] = 0.0
    bad[:, :3] = 0.0
    with pytest.raises(InputError, match=r"mechanisms|rigid-body"):
        ImportedStructure(bad, nodes, free=True)
    singular = np.zeros((60, 60))
    singular[:-1, :-1] = np.eye(59)
    with pytest.raises(InputError, match="compliance is singular"):
        ImportedStructure(singular, nodes, kind="compliance")


def test_node_element_mapping():
    k, nodes = _valid()
    imp = ImportedStructure(k, nodes)
    with pytest.raises(InputError, match="20 nodes for 19 elements"):
        imp.compliance(PSI[:19], R_E, Z_E)
    with pytest.raises(InputError, match="mapping"):
        imp.compliance(PSI + 0.1, R_E, Z_E)  # a third of the element pitch off
    with pytest.raises(InputError, match="dofs"):
        ImportedStructure(k, nodes, ("ux", "uy", "uq"))


def test_in_plane_dofs_count_the_plane_rigid_modes_only():
    """u_x, u_y of nodes in a plane show three rigid motions (u_x, u_y, rot_z); u_z, rot_x and rot_y
    vanish there and are no modes: grounded springs (a supported structure) are accepted, a free plane
    truss has exactly three modes (refused unless free, then its compliance leaves them out)."""
    nodes = np.stack([R_E * np.cos(PSI), R_E * np.sin(PSI), np.zeros(20)], -1)
    springs = ImportedStructure(1e9 * np.eye(40), nodes, ("ux", "uy"))
    assert springs.node_compliance() == pytest.approx(1e-9 * np.eye(40))
    plane = _truss(nodes).reshape(20, 3, 20, 3)[:, :2, :, :2].reshape(40, 40)
    with pytest.raises(InputError, match="3 rigid-body modes") as err:
        ImportedStructure(plane, nodes, ("ux", "uy"))
    assert "set free = true" in str(err.value)
    imp = ImportedStructure(plane, nodes, ("ux", "uy"), free=True)
    c = imp.node_compliance()
    assert np.abs(c @ imp.rigid_motions()).max() <= 1e-8 * np.abs(c).max()
    # one spring to the ground holds one of them: 2 modes, neither supported nor free
    with pytest.raises(InputError, match=r"2 rigid-body modes: .* free \(3 with these DOFs"):
        ImportedStructure(plane + np.diag(np.r_[1e8, np.zeros(39)]), nodes, ("ux", "uy"))
