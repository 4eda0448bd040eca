r"""A bearing ring as a closed curved beam with its supports: the compliance the raceways see.

SI units (m, N, Pa, rad). :class:`FlexibleRing` is an inner or outer ring of any bearing: a section
(:mod:`bearingkit.rings.sections`), a material, a uniform foundation (housing bore, shaft seat, flange
face) and point supports (bolts, a split housing), :mod:`bearingkit.rings.supports`. Its motion is
the Fourier solution of :mod:`bearingkit.physics.structure.curved_ring` (radial, tangential, axial and
twist of the section). At an element's reference point (its centre: pitch radius r_e, row position
z_e; :class:`~bearingkit.rows.base.RacewayOffset`), offset (Δr, Δz) = (r_e − r_c, z_e − z_c) from the
ring's centroid, the raceway moves by

.. math::
    d_r = w + \varphi\,\Delta z,\qquad d_z = u - \varphi\,\Delta r,\qquad \text{tilt} = -\varphi

(the section is rigid; the tilt has the sense of θ_t), and the generalised loads (F_r, F_z, M_t) that
element puts on the raceway act on the ring as (F_r, 0, F_z, F_r Δz − F_z Δr − M_t) on (w, v, u, φ):
the same matrix T, transposed (virtual work). :meth:`FlexibleRing.compliance` gives the (3N × 3N)
compliance of (radial, axial, tilt) per (F_r, F_z, M_t) at N element points, symmetric. An inner
ring sees the elements' loads reversed; its raceway motion enters the contacts reversed too, so its
compliance adds to the outer ring's (:mod:`bearingkit.analysis.structure`).

``stiffness_scale`` multiplies E of the ring and of every support (a study factor: ∞ is the rigid
ring, whose compliance is zero).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks
from bearingkit.physics.structure import curved_ring
from bearingkit.rings.sections import CurvedSection
from bearingkit.rings.supports import (
    BoltedFlange,
    Condensation,
    Foundation,
    PointSupports,
    SplitHousing,
    condense,
)

#: Ring sides (documented names).
SIDES = ("outer", "inner")
#: |I_rz|/√(I_in I_out) above which the section's principal axes are too far from r and z for the
#: decoupled in-plane / out-of-plane model (a warning, not a refusal) [–].
COUPLING_WARN = 0.2


@dataclass(frozen=True)
class FlexibleRing:
    """An inner or outer ring as a curved beam on its supports.

    Parameters
    ----------
    section : CurvedSection
    youngs_modulus : float [Pa]
    poisson_ratio : float [–]
    side : str
        ``"outer"`` or ``"inner"`` (:data:`SIDES`).
    foundation : Foundation
        Uniform supports (housing or seat, flange face).
    flange : BoltedFlange or None
        Bolts (and their face, added to the foundation).
    split : SplitHousing or None
        A split housing: the foundation's radial and twist stiffness reduced beside the joints.
    harmonics : int
        Last harmonic of the Fourier series.
    stiffness_scale : float [–]
        Multiplies the ring's and the supports' stiffness (np.inf: rigid; > 0).
    inextensible : bool
        EA = ∞ (the thin-ring reading of seed 002).
    in_plane_only : bool
        Rigid out of its plane (axial and twist left out).
    first_harmonic : int
        Harmonics below it left out (2: seed 002's housing holds n = 0, 1 rigidly).
    rows : tuple of str or None
        Names of the rows whose raceway this ring carries (None: every row).
    """

    section: CurvedSection
    youngs_modulus: float = 2.08e11
    poisson_ratio: float = 0.3
    side: str = "outer"
    foundation: Foundation = field(default_factory=Foundation)
    flange: BoltedFlange | None = None
    split: SplitHousing | None = None
    harmonics: int = curved_ring.DEFAULT_HARMONICS
    stiffness_scale: float = 1.0
    inextensible: bool = False
    in_plane_only: bool = False
    first_harmonic: int = 0
    rows: tuple | None = None

    def __post_init__(self):
        checks.one_of("side", self.side, SIDES)
        if not isinstance(self.section, CurvedSection):
            raise checks.InputError(f"section ({type(self.section).__name__}) must be a CurvedSection")
        checks.positive("youngs_modulus", self.youngs_modulus, "Pa")
        checks.in_range("poisson_ratio", self.poisson_ratio, -1.0, 0.5, closed=False)
        s = float(self.stiffness_scale)
        if np.isnan(s) or s <= 0:
            raise checks.InputError(f"stiffness_scale ({s:.6g}) must be positive (np.inf: rigid ring)")
        checks.integer("harmonics", self.harmonics, low=8)
        checks.integer("first_harmonic", self.first_harmonic, low=0)

    @property
    def rigid(self) -> bool:
        return np.isinf(float(self.stiffness_scale))

    @property
    def shear_modulus(self) -> float:
        return self.youngs_modulus / (2 * (1 + self.poisson_ratio))

    @property
    def warnings(self) -> list[str]:
        """What the curved-beam model leaves out for this section (every face shows it)."""
        out = []
        if self.section.coupling > COUPLING_WARN:
            out.append(
                f"{self.side} ring: its section's principal axes are {self.section.coupling:.2f} off r and z "
                "(∫(r − r_c)(z − z_c) dA); the curved-beam model keeps in- and out-of-plane bending apart"
            )
        return out

    def rigidities(self) -> curved_ring.RingRigidities:
        """Rigidities of the ring with its uniform foundation (flange face included), scaled."""
        sec, s = self.section, float(self.stiffness_scale)
        e, g = self.youngs_modulus * s, self.shear_modulus * s
        found = self.foundation
        if self.flange is not None:
            found = found + self.flange.foundation(sec.centroid_radius, sec.centroid_z)
        springs = tuple(k * s for k in found.springs)
        out_of_plane = np.inf if self.in_plane_only else e * sec.inertia_out
        torsion = np.inf if self.in_plane_only else g * sec.torsion
        if self.in_plane_only:
            springs = (springs[0], springs[1], 0.0, 0.0, 0.0)
        return curved_ring.RingRigidities(
            sec.centroid_radius,
            np.inf if self.inextensible else e * sec.area,
            e * sec.inertia_in,
            out_of_plane,
            torsion,
            springs,
        )

    def point_supports(self) -> PointSupports | None:
        """Bolts and the split housing's missing arcs as point springs (scaled), or None."""
        sec, s = self.section, float(self.stiffness_scale)
        parts = []
        if self.flange is not None:
            parts.append(self.flange.points(sec.centroid_radius, sec.centroid_z))
        if self.split is not None:
            parts.append(self.split.points(self.foundation, sec.centroid_radius))
        if not parts:
            return None
        out = functools.reduce(lambda a, b: a + b, parts)
        k = out.stiffness * s
        if self.in_plane_only:  # axial and twist springs hold nothing a rigid out-of-plane ring does
            k = k.copy()
            k[:, 2:, :] = 0.0
            k[:, :, 2:] = 0.0
        return PointSupports(out.azimuth, k)

    def carried(self, model) -> list:
        """Indices of the model's rows this ring carries."""
        names = [r.name for r in model.rows]
        if self.rows is None:
            return list(range(len(names)))
        unknown = set(self.rows) - set(names)
        if unknown:
            raise checks.InputError(
                f"{self.side} ring rows {sorted(unknown)} are not in the bearing; rows are {names}"
            )
        return [names.index(n) for n in self.rows]

    # -- compliance -------------------------------------------------------------------------------
    def transform(self, radius, z) -> np.ndarray:
        """T (N, 3, 4): (radial, axial, tilt) of the raceway at points (radius, z) per (w, v, u, φ)."""
        d_r = np.asarray(radius, dtype=float) - self.section.centroid_radius
        d_z = np.asarray(z, dtype=float) - self.section.centroid_z
        d_r, d_z = np.broadcast_arrays(d_r, d_z)
        t = np.zeros((d_r.size, 3, 4))
        t[:, 0, 0], t[:, 0, 3] = 1.0, d_z.ravel()
        t[:, 1, 2], t[:, 1, 3] = 1.0, -d_r.ravel()
        t[:, 2, 3] = -1.0
        return t

    def condensation(self, azimuth) -> Condensation:
        """The ring with its point supports condensed onto the azimuths (N,) of element points."""
        return condense(
            self.rigidities(),
            self.harmonics,
            self.first_harmonic,
            azimuth,
            self.point_supports(),
            f"{self.side} ring",
        )

    def compliance(self, azimuth, radius, z) -> np.ndarray:
        """(3N, 3N) compliance [m/N, m/(N·m), rad/N, rad/(N·m)] of (radial, axial, tilt) of the raceway at
        N element points per (F_r, F_z, M_t) there (element-major: 3 entries per element)."""
        azimuth = np.asarray(azimuth, dtype=float).reshape(-1)
        n = azimuth.size
        if self.rigid:
            return np.zeros((3 * n, 3 * n))
        c = self.condensation(azimuth).compliance  # (4N, 4N)
        t = self.transform(radius, z)  # (N, 3, 4)
        c4 = c.reshape(n, 4, n, 4)
        return np.einsum("iab,ibjc,jdc->iajd", t, c4, t).reshape(3 * n, 3 * n)

    # -- the ring under given element loads (outputs) ---------------------------------------------
    def generalised_loads(self, loads, radius, z) -> np.ndarray:
        """Element loads (C, N, 3) (F_r, F_z, M_t) on the raceway → (C, N, 4) on (w, v, u, φ) (Tᵀ f)."""
        return np.einsum("nab,cna->cnb", self.transform(radius, z), np.asarray(loads, dtype=float))

    def response(self, theta, azimuth, loads, radius, z):
        """Displacement (C, M, 4) (w, v, u, φ) and resultants (C, M, 4) (N, M_in, M_b, T) of the ring at
        angles θ (M,) under element loads (C, N, 3) at the element points (azimuth, radius, z).

        The supports' forces come from the same condensation as the compliance; a rigid ring returns
        zero displacement and its resultants as a ring of the given section at unit stiffness scale
        (the forces in a statically held ring do not depend on its stiffness only when determinate;
        here they are the flexible ring's).
        """
        theta = np.asarray(theta, dtype=float).reshape(-1)
        azimuth = np.asarray(azimuth, dtype=float).reshape(-1)
        ring = self if not self.rigid else _unit(self)
        p = ring.generalised_loads(loads, radius, z)  # (C, N, 4)
        cond = ring.condensation(azimuth)
        rig = ring.rigidities()
        sup = ring.point_supports()
        flat = p.reshape(p.shape[0], -1)
        from bearingkit.rings.supports import pair_influence

        def field(kernel):
            k = kernel(theta, azimuth)  # (M, N, 4, 4)
            out = np.einsum("mnij,cnj->cmi", k, p)
            if sup is not None:
                f = (cond.support_map @ flat.T).T.reshape(p.shape[0], -1, 4)
                out += np.einsum("msij,csj->cmi", kernel(theta, sup.azimuth), f)
            return out

        disp = field(lambda a, b: pair_influence(a, b, rig, ring.harmonics, ring.first_harmonic))
        if cond.rigid_map is not None:
            free = curved_ring.free_modes(rig, ring.first_harmonic)
            modes = curved_ring.rigid_modes(theta, rig.radius)[:, free, :]  # (M, m, 4)
            alpha = (cond.rigid_map @ flat.T).T  # (C, m)
            disp += np.einsum("mki,ck->cmi", modes, alpha)
        forces = field(lambda a, b: _pair_resultants(a, b, rig, ring.harmonics, ring.first_harmonic))
        if self.rigid:
            disp = np.zeros_like(disp)
        return disp, forces

    def fibre_stress(self, forces) -> np.ndarray | None:
        """Hoop stress (C, M, K) [Pa] at the section's outline points from resultants (C, M, 4); None for a
        section given by its properties only (no outline: its fibres are unknown)."""
        sec = self.section
        if sec.corners is None:
            return None
        pts = sec.corners
        d_r = pts[:, 0] - sec.centroid_radius
        d_z = pts[:, 1] - sec.centroid_z
        n, m_in, m_b = forces[..., 0:1], forces[..., 1:2], forces[..., 2:3]
        return n / sec.area + m_in * d_r / sec.inertia_in + m_b * d_z / sec.inertia_out


def _unit(ring: FlexibleRing) -> FlexibleRing:
    from dataclasses import replace

    return replace(ring, stiffness_scale=1.0)


def _pair_resultants(theta_a, theta_b, ring, harmonics, first_harmonic):
    d = np.mod(np.subtract.outer(np.asarray(theta_a, float), np.asarray(theta_b, float)), 2 * np.pi)
    uniq, inv = np.unique(np.round(d, 13), return_inverse=True)
    return curved_ring.resultants(uniq, ring, harmonics, first_harmonic)[inv.reshape(d.shape)]


__all__ = ["SIDES", "BoltedFlange", "FlexibleRing", "Foundation", "PointSupports", "SplitHousing"]
