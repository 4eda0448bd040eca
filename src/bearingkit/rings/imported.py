r"""A structure's condensed stiffness or compliance at the raceway nodes, exported from any FE code.

SI units (m, N, rad). An engineer's Abaqus, ANSYS or Code_Aster model of a hub, a housing or a tower
flange is condensed (Guyan / superelement) onto one node per rolling element at the raceway, each with
translational DOFs (u_x, u_y, u_z) and optionally rotations (r_x, r_y, r_z) in the bearing frame (axis z).
:class:`ImportedStructure` checks that matrix and gives the compliance the coupled solve needs
(:mod:`bearingkit.analysis.structure`), in the elements' local (radial, axial, tilt) components:

.. math:: d_r = u_x\cos\psi + u_y\sin\psi,\quad d_z = u_z,\quad
          \text{tilt} = r_x\sin\psi - r_y\cos\psi

(the rigid-ring kinematics of :mod:`bearingkit.rows.base`); the element loads map back by the
transpose. Without rotational DOFs the raceway does not tilt (ball rows need no tilt; roller rows then
see the translations only).

**Checks** (each a one-line refusal naming the problem):

- the matrix is square and its size is the number of nodes times the DOFs per node;
- finite and symmetric (|K_ij − K_ji| ≤ :data:`SYMMETRY_TOLERANCE` of the largest entry);
- rigid-body modes: the six rigid motions built from the node coordinates, as far as the DOFs show
  them (u_x, u_y of nodes in a plane show three: u_x, u_y, rot_z), K R ≈ 0 being a mode: a
  stiffness of a supported structure has none, one of a free structure all of them (accepted only when
  ``free`` says so; the structure's rigid motion then merges with the bearing's, the loads' rigid
  part being reacted in proportion to the modes: the pseudo-inverse); any other count is refused;
- positive definiteness on the complement of those modes (a mechanism or a negative eigenvalue is
  refused); a compliance must be positive definite;
- the node ↔ element mapping: one node per element of the rows it carries, each node at its
  element's azimuth (within a quarter of the element pitch) — a count that does not match is refused.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit import checks

#: DOF names a node may carry, in the bearing frame.
DOF_NAMES = ("ux", "uy", "uz", "rx", "ry", "rz")
#: Matrix kinds.
KINDS = ("stiffness", "compliance")
#: Largest |K_ij − K_ji| relative to the largest entry of an accepted matrix (FE exports print ~8–17
#: significant digits: 1e-8 accepts an 8-digit export, refuses a real asymmetry).
SYMMETRY_TOLERANCE = 1e-8
#: Eigenvalues below this share of the largest are zero (a rigid-body mode or a mechanism).
ZERO_EIGENVALUE = 1e-10
#: |K R|/(|K| |R|) below which a rigid motion R is a rigid-body mode of the matrix.
RIGID_TOLERANCE = 1e-7
#: Largest azimuth difference between a node and its element, as a share of the element pitch.
AZIMUTH_TOLERANCE = 0.25


def _fail(source: str, what: str):
    raise checks.InputError(f"{source}: {what}")


@dataclass(frozen=True)
class ImportedStructure:
    """A condensed structure matrix at raceway nodes (SI).

    Parameters
    ----------
    matrix : ndarray (K, K)
        Stiffness [N/m, N/rad, N·m/rad] or compliance (its inverse) in the order node-major, DOFs as
        ``dofs``.
    nodes : ndarray (N, 3) [m]
        Node coordinates (x, y, z) in the bearing frame.
    dofs : tuple of str
        DOFs per node (:data:`DOF_NAMES`, translations first).
    kind : str
        ``"stiffness"`` or ``"compliance"``.
    side : str
        ``"outer"`` (the raceway of the outer ring) or ``"inner"``.
    rows : tuple of str or None
        Rows whose elements the nodes carry (None: every row).
    free : bool
        A stiffness with every rigid-body mode its DOFs show (a free structure) is accepted (module
        docstring).
    stiffness_scale : float
        Multiplies the stiffness (a study factor; np.inf: rigid).
    source : str
        Where it came from (messages).
    """

    matrix: np.ndarray
    nodes: np.ndarray
    dofs: tuple = ("ux", "uy", "uz")
    kind: str = "stiffness"
    side: str = "outer"
    rows: tuple | None = None
    free: bool = False
    stiffness_scale: float = 1.0
    source: str = "structure.import"

    def __post_init__(self):
        src = self.source
        if self.kind not in KINDS:
            _fail(src, f"kind ({self.kind!r}) must be one of {', '.join(KINDS)}")
        if self.side not in ("outer", "inner"):
            _fail(src, f"ring ({self.side!r}) must be 'outer' or 'inner'")
        bad = [d for d in self.dofs if d not in DOF_NAMES]
        if bad or len(set(self.dofs)) != len(self.dofs) or not self.dofs:
            _fail(src, f"dofs ({list(self.dofs)}) must be distinct names of {', '.join(DOF_NAMES)}")
        k = np.asarray(self.matrix, dtype=float)
        nodes = np.asarray(self.nodes, dtype=float)
        if nodes.ndim != 2 or nodes.shape[1] != 3 or not np.all(np.isfinite(nodes)):
            _fail(src, f"nodes (shape {nodes.shape}) must be finite coordinates x, y, z, one node per line")
        if k.ndim != 2 or k.shape[0] != k.shape[1]:
            _fail(src, f"matrix (shape {k.shape}) must be square")
        size = nodes.shape[0] * len(self.dofs)
        if k.shape[0] != size:
            _fail(
                src,
                f"matrix ({k.shape[0]} × {k.shape[1]}) does not match the nodes: {nodes.shape[0]} nodes × "
                f"{len(self.dofs)} DOFs = {size}",
            )
        if not np.all(np.isfinite(k)):
            _fail(src, "matrix has non-finite entries")
        top = np.abs(k).max()
        if top == 0:
            _fail(src, "matrix is zero")
        asym = np.abs(k - k.T).max() / top
        if asym > SYMMETRY_TOLERANCE:
            i, j = np.unravel_index(np.argmax(np.abs(k - k.T)), k.shape)
            _fail(
                src,
                f"matrix is not symmetric: |K[{i},{j}] − K[{j},{i}]| is {asym:.2g} of its largest entry "
                f"(at most {SYMMETRY_TOLERANCE:g}); export the symmetric condensed matrix",
            )
        s = float(self.stiffness_scale)
        if np.isnan(s) or s <= 0:
            _fail(src, f"stiffness_scale ({s:.6g}) must be positive (inf: rigid)")
        self._spectrum(0.5 * (k + k.T))

    # -- checks ---------------------------------------------------------------------------------------
    def rigid_motions(self) -> np.ndarray:
        """The six rigid motions (K, 6) of the nodes in the matrix's DOFs (translations, then rotations)."""
        x, y, z = (self.nodes[:, i] for i in range(3))
        n = x.size
        cols = []
        for mode in range(6):
            t = np.zeros((n, 6))
            if mode < 3:
                t[:, mode] = 1.0
            else:
                w = np.zeros(3)
                w[mode - 3] = 1.0
                t[:, :3] = np.cross(w, np.stack([x, y, z], -1))
                t[:, mode] = 1.0
            cols.append(t[:, [DOF_NAMES.index(d) for d in self.dofs]].reshape(-1))
        return np.stack(cols, axis=-1)

    def _spectrum(self, k):
        src = self.source
        val = np.linalg.eigvalsh(k)
        top = np.abs(val).max()
        zero = np.abs(val) <= ZERO_EIGENVALUE * top
        if np.any(val < -ZERO_EIGENVALUE * top):
            _fail(
                src,
                f"matrix is not positive definite: eigenvalue {val.min():.3g} against the largest {top:.3g} "
                f"({self.kind} of an unstable or wrongly condensed model)",
            )
        if self.kind == "compliance":
            if zero.any():
                _fail(
                    src, f"compliance is singular ({int(zero.sum())} zero eigenvalues): it must be invertible"
                )
            return
        # The rigid motions the DOFs can show: with u_x, u_y of nodes in a plane only the plane's three
        # (u_x, u_y, rot_z) are there — u_z, rot_x, rot_y vanish on these DOFs and are no modes of K.
        u, sv, _ = np.linalg.svd(self.rigid_motions(), full_matrices=False)
        basis = u[:, sv > RIGID_TOLERANCE * sv.max()]
        possible = basis.shape[1]
        kq = np.linalg.svd(k @ basis, compute_uv=False)
        rigid = int(np.count_nonzero(kq <= RIGID_TOLERANCE * np.linalg.norm(k, 2)))
        n_zero = int(zero.sum())
        if n_zero > rigid:
            _fail(
                src,
                f"stiffness is singular: {n_zero} zero eigenvalues, {rigid} of them rigid-body modes — the "
                "rest are mechanisms (an unconnected or unsupported node?)",
            )
        if rigid not in (0, possible):
            _fail(
                src,
                f"stiffness has {rigid} rigid-body modes: a structure is either supported (0) or free "
                f"({possible} with these DOFs and nodes); check its boundary conditions",
            )
        if rigid and not self.free:
            _fail(
                src,
                f"stiffness has {rigid} rigid-body modes (a free structure): export it with its supports, or "
                "set free = true to let the bearing's displacement take the rigid motion",
            )

    # -- compliance ----------------------------------------------------------------------------------
    def node_compliance(self) -> np.ndarray:
        """(K, K) compliance of the nodes [m/N …] (the pseudo-inverse of a free structure's stiffness)."""
        k = 0.5 * (np.asarray(self.matrix, float) + np.asarray(self.matrix, float).T)
        s = float(self.stiffness_scale)
        if np.isinf(s):
            return np.zeros_like(k)
        if self.kind == "compliance":
            return k / s
        c = np.linalg.pinv(k, rcond=ZERO_EIGENVALUE, hermitian=True) if self.free else np.linalg.inv(k)
        return 0.5 * (c + c.T) / s

    def node_of(self, azimuth, radius, z) -> np.ndarray:
        """Index of each element's node (N,), refusing a count or position that does not match."""
        azimuth = np.asarray(azimuth, dtype=float).reshape(-1)
        z = np.broadcast_to(np.asarray(z, dtype=float), azimuth.shape)
        n_el, n_nodes = azimuth.size, self.nodes.shape[0]
        if n_nodes != n_el:
            _fail(
                self.source,
                f"{n_nodes} nodes for {n_el} elements of the rows it carries"
                f"{'' if self.rows is None else ' ' + str(list(self.rows))}: give one node per element",
            )
        node_psi = np.arctan2(self.nodes[:, 1], self.nodes[:, 0])
        node_z = self.nodes[:, 2]
        pitch = 2 * np.pi / max(n_el, 1)
        if len(set(np.round(z, 9))) > 1:  # several rows: each node to its row's z
            pitch = 2 * np.pi / max(np.bincount(np.unique(np.round(z, 9), return_inverse=True)[1]).max(), 1)
        d_psi = np.abs(np.angle(np.exp(1j * (azimuth[:, None] - node_psi[None, :]))))
        d_z = np.abs(z[:, None] - node_z[None, :])
        score = d_psi / pitch + d_z / max(float(np.ptp(node_z)) + 1e-12, 1e-3)
        pick = np.argmin(score, axis=1)
        if len(set(pick.tolist())) != n_el or np.any(
            d_psi[np.arange(n_el), pick] > AZIMUTH_TOLERANCE * pitch
        ):
            worst = int(np.argmax(d_psi[np.arange(n_el), pick]))
            _fail(
                self.source,
                f"node ↔ element mapping: element {worst} at azimuth {np.degrees(azimuth[worst]):.4g}° has "
                f"no node within {AZIMUTH_TOLERANCE:g} of the element pitch; nodes must sit at the elements",
            )
        return pick

    def compliance(self, azimuth, radius, z) -> np.ndarray:
        """(3N, 3N) compliance of (radial, axial, tilt) at the elements per (F_r, F_z, M_t) (see above)."""
        azimuth = np.asarray(azimuth, dtype=float).reshape(-1)
        node = self.node_of(azimuth, radius, z)
        d = len(self.dofs)
        c = self.node_compliance().reshape(self.nodes.shape[0], d, self.nodes.shape[0], d)[node][:, :, node]
        t = np.zeros((azimuth.size, 3, d))
        pos = {name: i for i, name in enumerate(self.dofs)}
        cos, sin = np.cos(azimuth), np.sin(azimuth)
        for name, row, coef in (
            ("ux", 0, cos),
            ("uy", 0, sin),
            ("uz", 1, np.ones_like(cos)),
            ("rx", 2, sin),
            ("ry", 2, -cos),
        ):
            if name in pos:
                t[:, row, pos[name]] = coef
        return np.einsum("iab,ibjc,jdc->iajd", t, c, t).reshape(3 * azimuth.size, 3 * azimuth.size)

    def describe(self) -> dict:
        return {
            "model": "imported",
            "kind": self.kind,
            "nodes": int(self.nodes.shape[0]),
            "dofs": list(self.dofs),
            "free": bool(self.free),
            "source": self.source,
        }


def ring_export(ring, azimuth, radius, z, dofs=("ux", "uy", "uz")):
    """The compliance (K, K) and nodes (N, 3) of a :class:`~bearingkit.rings.curved_beam.FlexibleRing` at
    element points, in Cartesian node DOFs: what an FE export of the same ring would hold.

    The raceway point of element j moves by (d_r, d_t, d_z) = (w + φΔz, v, u − φΔr) and rotates by
    φ about e_θ: (r_x, r_y) = φ(−sin ψ, cos ψ). The section's rotation about e_r (the slope of u) and
    about z are not in the model, so an export with r_x, r_y is singular (one zero eigenvalue per node);
    the translations (the default) are what a raceway node of an FE model carries.
    """
    azimuth = np.asarray(azimuth, dtype=float).reshape(-1)
    n = azimuth.size
    c4 = ring.condensation(azimuth).compliance.reshape(n, 4, n, 4)
    d_r = np.asarray(radius, float) - ring.section.centroid_radius
    d_z = np.asarray(z, float) - ring.section.centroid_z
    d_r, d_z = np.broadcast_to(d_r, (n,)), np.broadcast_to(d_z, (n,))
    cos, sin = np.cos(azimuth), np.sin(azimuth)
    full = np.zeros((n, 6, 4))  # (ux, uy, uz, rx, ry, rz) per (w, v, u, φ)
    full[:, 0, 0], full[:, 0, 1], full[:, 0, 3] = cos, -sin, cos * d_z
    full[:, 1, 0], full[:, 1, 1], full[:, 1, 3] = sin, cos, sin * d_z
    full[:, 2, 2], full[:, 2, 3] = 1.0, -d_r
    full[:, 3, 3], full[:, 4, 3] = -sin, cos
    pick = [DOF_NAMES.index(d) for d in dofs]
    t = full[:, pick, :]
    c = np.einsum("iab,ibjc,jdc->iajd", t, c4, t).reshape(n * len(dofs), n * len(dofs))
    r = np.asarray(radius, float) * np.ones(n)
    nodes = np.stack([r * cos, r * sin, np.asarray(z, float) * np.ones(n)], axis=-1)
    return 0.5 * (c + c.T), nodes
