r"""Supports of a flexible ring: a housing or shaft seat, a flange bolted at n points, a split housing.

SI units (m, N, rad). A ring (:class:`bearingkit.rings.curved_beam.FlexibleRing`) is held by

- a **uniform Winkler foundation** (:class:`Foundation`) — a housing bore or shaft seat (radial k_r,
  with the twist it resists across the width, k_φ = k_r b²/12), a flange face (axial k_a at a radial
  offset e from the centroid: k_aφ = −k_a e, k_φ = k_a(e² + w²/12) over a face of radial width w),
  all per unit circumferential length (Hetényi 1946, the bilateral foundation); it enters the ring's
  Fourier harmonics exactly;
- **point supports** (:class:`BoltedFlange`): n bolts on a circle, each an axial spring (the bolt and
  the clamped flange in series) and radial/tangential springs (the joint held by friction or a
  spigot), at the bolt's point of the section;
- **a split housing** (:class:`SplitHousing`): a housing foundation whose support is reduced (or
  absent) over arcs beside the split planes; the missing part enters as point springs of negative
  stiffness at Gauss points of those arcs (the foundation minus what the split takes away).

**Point supports, exactly.** With G⁺ the ring's compliance over its elastic modes (the Fourier series
of :mod:`bearingkit.physics.structure.curved_ring`, rigid-body modes R left out where the foundation
does not hold them), element loads P and support forces F = −K_s u_s, the ring's motion is
u = G⁺(P + F) + Rα with

.. math::
    (I + K_s G^+_{ss}) F + K_s R_s \alpha = -K_s G^+_{se} P, \qquad R_s^T F = -R_e^T P

(the supports' springs, and the equilibrium of a ring whose rigid motion only the supports hold), a
linear map P → (F, α) solved once (:func:`condense`); the compliance at the elements is then
G⁺_ee + G⁺_es X_F + R_e X_α, symmetric (Maxwell–Betti, checked). A rigid-body mode that nothing
holds is held by the frame (the ring's share of load in that mode reacted in the mode's shape) and
named in ``Condensation.unheld``, which the faces show.

Sign conventions: (w, v, u, φ) of :mod:`~bearingkit.physics.structure.curved_ring`; a support point at
(r, z) moves by (w + φ(z − z_c), v, u − φ(r − r_c)) (radial, tangential, axial).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit import checks
from bearingkit.physics.structure import curved_ring

#: Gauss points per arc of a split housing's missing support (the arcs' point springs).
SPLIT_POINTS = 8
#: Largest asymmetry of a condensed compliance, relative to its largest entry, before it is refused
#: (round-off of the solve is ~1e-13; a larger one is a modelling error).
SYMMETRY_TOLERANCE = 1e-8


@dataclass(frozen=True)
class Foundation:
    """A uniform bilateral Winkler foundation of a ring, per unit circumferential length (SI).

    Parameters
    ----------
    radial : float [N/m²]
        k_r (housing bore or shaft seat).
    tangential : float [N/m²]
        k_t (the seat's friction or key; 0 by default).
    axial : float [N/m²]
        k_a (a flange face or shoulder).
    twist : float [N]
        k_φ, moment per unit length per radian of section rotation.
    coupling : float [N/m]
        k_aφ (an axial foundation off the centroid).
    """

    radial: float = 0.0
    tangential: float = 0.0
    axial: float = 0.0
    twist: float = 0.0
    coupling: float = 0.0

    def __post_init__(self):
        for name in ("radial", "tangential", "axial", "twist"):
            checks.non_negative(name, getattr(self, name))
        checks.finite("coupling", self.coupling, "N/m")

    @property
    def springs(self) -> tuple:
        return (self.radial, self.tangential, self.axial, self.twist, self.coupling)

    def __add__(self, other: Foundation) -> Foundation:
        return Foundation(*(a + b for a, b in zip(self.springs, other.springs, strict=True)))

    @classmethod
    def seat(cls, stiffness, width, offset_z=0.0) -> Foundation:
        """A housing bore or shaft seat of radial stiffness k_r [N/m²] over the ring's ``width`` [m],
        its middle ``offset_z`` [m] from the centroid: k_φ = k_r(width²/12 + offset_z²)."""
        checks.non_negative("stiffness", stiffness)
        checks.positive("width", width, "m")
        return cls(radial=stiffness, twist=stiffness * (width**2 / 12 + offset_z**2))

    @classmethod
    def face(cls, stiffness, offset_r, face_width) -> Foundation:
        """An axial face (a flange) of axial stiffness k_a [N/m²] at radial offset e = ``offset_r`` [m]
        from the centroid, ``face_width`` [m] radially: k_aφ = −k_a e, k_φ = k_a (e² + w²/12)."""
        checks.non_negative("stiffness", stiffness)
        checks.non_negative("face_width", face_width)
        return cls(
            axial=stiffness,
            twist=stiffness * (offset_r**2 + face_width**2 / 12),
            coupling=-stiffness * offset_r,
        )


@dataclass(frozen=True)
class PointSupports:
    """Springs at points of the ring (SI): the generalised stiffness (w, v, u, φ) of each.

    Attributes
    ----------
    azimuth : ndarray (S,) [rad]
    stiffness : ndarray (S, 4, 4) [N/m, N, N·m/rad]
    """

    azimuth: np.ndarray
    stiffness: np.ndarray

    @staticmethod
    def at(azimuth, radial, tangential, axial, d_r, d_z) -> PointSupports:
        """Springs (k_r, k_t, k_a) [N/m] at azimuths, acting at a point (d_r, d_z) [m] from the centroid."""
        psi = np.atleast_1d(np.asarray(azimuth, dtype=float))
        k = np.broadcast_to(np.stack(np.broadcast_arrays(radial, tangential, axial), -1), (psi.size, 3))
        t = np.zeros((psi.size, 3, 4))
        t[:, 0, 0], t[:, 0, 3] = 1.0, d_z
        t[:, 1, 1] = 1.0
        t[:, 2, 2], t[:, 2, 3] = 1.0, -d_r
        return PointSupports(psi, np.einsum("sai,sa,saj->sij", t, k, t))

    def __add__(self, other: PointSupports) -> PointSupports:
        return PointSupports(
            np.concatenate([self.azimuth, other.azimuth]), np.concatenate([self.stiffness, other.stiffness])
        )


@dataclass(frozen=True)
class BoltedFlange:
    """A ring bolted to a flange at n points (SI).

    Parameters
    ----------
    n_bolts : int
    bolt_circle_radius : float [m]
    axial_stiffness : float [N/m]
        Each bolt with its clamped parts, in series (VDI 2230's bolt and clamp compliances).
    radial_stiffness, tangential_stiffness : float [N/m]
        Each joint across the bolt (friction or a spigot); 0: free.
    face_z : float [m]
        Axial position of the bolted face (the springs act there).
    phase : float [rad]
        Azimuth of the first bolt.
    face_stiffness : float [N/m²]
        Axial Winkler stiffness of the flange face under the ring (0: the ring touches the flange only
        at the bolts). Bilateral, as every support here: a face that would lift off is not modelled.
    face_width : float [m]
        Radial width of that face (its twist stiffness).
    """

    n_bolts: int
    bolt_circle_radius: float
    axial_stiffness: float
    radial_stiffness: float = 0.0
    tangential_stiffness: float = 0.0
    face_z: float = 0.0
    phase: float = 0.0
    face_stiffness: float = 0.0
    face_width: float = 0.0

    def __post_init__(self):
        checks.integer("n_bolts", self.n_bolts, low=1)
        checks.positive("bolt_circle_radius", self.bolt_circle_radius, "m")
        checks.positive("axial_stiffness", self.axial_stiffness, "N/m")
        checks.non_negative("radial_stiffness", self.radial_stiffness)
        checks.non_negative("tangential_stiffness", self.tangential_stiffness)
        checks.non_negative("face_stiffness", self.face_stiffness)
        checks.non_negative("face_width", self.face_width)

    def azimuths(self) -> np.ndarray:
        return self.phase + 2 * np.pi * np.arange(self.n_bolts) / self.n_bolts

    def points(self, centroid_radius, centroid_z) -> PointSupports:
        d_r, d_z = self.bolt_circle_radius - centroid_radius, self.face_z - centroid_z
        return PointSupports.at(
            self.azimuths(), self.radial_stiffness, self.tangential_stiffness, self.axial_stiffness, d_r, d_z
        )

    def foundation(self, centroid_radius, centroid_z) -> Foundation:
        """The flange face's uniform part (at the bolt circle, ``face_width`` wide)."""
        if self.face_stiffness == 0:
            return Foundation()
        return Foundation.face(
            self.face_stiffness, self.bolt_circle_radius - centroid_radius, self.face_width
        )


@dataclass(frozen=True)
class SplitHousing:
    """A housing split in two halves (SI): its bore support reduced beside the split planes.

    Parameters
    ----------
    split_azimuth : float [rad]
        Azimuth of the split plane (the joint lies at this azimuth and the opposite one).
    gap_angle : float [rad]
        Half-width of the arc of reduced support on each side of each joint line.
    remaining : float [–]
        Share of the housing stiffness left over those arcs (0: no support there, 1: no split).
    """

    split_azimuth: float = np.pi / 2
    gap_angle: float = np.radians(10.0)
    remaining: float = 0.0

    def __post_init__(self):
        checks.finite("split_azimuth", self.split_azimuth, "rad")
        checks.in_range("gap_angle", self.gap_angle, 0.0, np.pi / 2, closed=False)
        checks.in_range("remaining", self.remaining, 0.0, 1.0, closed=True)

    def points(self, foundation: Foundation, radius) -> PointSupports:
        """Negative point springs that take (1 − remaining) of ``foundation``'s radial and twist stiffness
        away over the gap arcs (Gauss–Legendre, :data:`SPLIT_POINTS` per arc)."""
        x, w = np.polynomial.legendre.leggauss(SPLIT_POINTS)
        psi, weight = [], []
        for centre in (self.split_azimuth, self.split_azimuth + np.pi):
            psi.append(centre + self.gap_angle * x)
            weight.append(self.gap_angle * w * radius)  # arc length per point [m]
        psi, weight = np.concatenate(psi), np.concatenate(weight)
        cut = -(1.0 - self.remaining) * weight
        k = np.zeros((psi.size, 4, 4))
        k[:, 0, 0] = cut * foundation.radial
        k[:, 1, 1] = cut * foundation.tangential
        k[:, 3, 3] = cut * foundation.twist
        return PointSupports(psi, k)


@dataclass
class Condensation:
    """The ring condensed onto its element points: compliance and the maps to the support forces.

    Attributes
    ----------
    compliance : ndarray (4N, 4N)
        Generalised displacement (w, v, u, φ) at the element points per generalised load there.
    support_map : ndarray (4S, 4N) or None
        Support forces per element load.
    rigid_map : ndarray (m, 4N) or None
        Amplitudes of the rigid-body modes the supports hold (``held`` (6, m)) per element load.
    held : ndarray (6, m) or None
        Those modes as combinations of :data:`~bearingkit.physics.structure.curved_ring.RIGID_MODES`.
    unheld : tuple of str
        Rigid-body modes nothing holds: the frame holds them (module docstring).
    """

    compliance: np.ndarray
    support_map: np.ndarray | None
    rigid_map: np.ndarray | None
    held: np.ndarray | None = None
    unheld: tuple = ()


def pair_influence(theta_a, theta_b, ring, harmonics, first_harmonic) -> np.ndarray:
    """Influence blocks (A, B, 4, 4) between angles θ_a (response) and θ_b (load), unique angles once."""
    d = np.mod(np.subtract.outer(np.asarray(theta_a, float), np.asarray(theta_b, float)), 2 * np.pi)
    key = np.round(d, 13)
    uniq, inv = np.unique(key, return_inverse=True)
    g = curved_ring.influence(uniq, ring, harmonics, first_harmonic)
    return g[inv.reshape(d.shape)]


def _blocks(g):
    """(A, B, 4, 4) → (4A, 4B)."""
    a, b = g.shape[:2]
    return g.transpose(0, 2, 1, 3).reshape(4 * a, 4 * b)


def condense(
    ring, harmonics, first_harmonic, theta, supports: PointSupports | None, what="ring"
) -> Condensation:
    """Condense a ring with point supports onto the angles ``theta`` (N,) of its element points.

    Parameters
    ----------
    ring : curved_ring.RingRigidities
    harmonics, first_harmonic : int
    theta : array_like (N,) [rad]
    supports : PointSupports or None
    what : str
        Name of the ring in messages.

    Returns
    -------
    Condensation

    Notes
    -----
    Rigid-body modes that neither the foundation nor the point supports hold are held by the frame
    the ring is measured from (the bearing's outer ring is its reference): their share of the element
    loads is reacted in the shape of the mode (uniform for the axial translation, ∝ sin/cos θ for the
    tilts), which the pseudo-inverse G⁺ does by itself; they are listed in ``unheld``.
    """
    theta = np.asarray(theta, dtype=float)
    free = curved_ring.free_modes(ring, first_harmonic)
    names = np.array(curved_ring.RIGID_MODES)[free]
    g_ee = _blocks(pair_influence(theta, theta, ring, harmonics, first_harmonic))
    if supports is None or supports.azimuth.size == 0:
        return Condensation(g_ee, None, None, None, tuple(names))
    s = supports.azimuth
    g_ss = _blocks(pair_influence(s, s, ring, harmonics, first_harmonic))
    g_se = _blocks(pair_influence(s, theta, ring, harmonics, first_harmonic))
    k_s = np.zeros((4 * s.size, 4 * s.size))
    for i in range(s.size):
        k_s[4 * i : 4 * i + 4, 4 * i : 4 * i + 4] = supports.stiffness[i]
    r = float(ring.radius)
    modes_e = curved_ring.rigid_modes(theta, r)[:, free, :].transpose(0, 2, 1).reshape(4 * theta.size, -1)
    modes_s = curved_ring.rigid_modes(s, r)[:, free, :].transpose(0, 2, 1).reshape(4 * s.size, -1)
    held, unheld = _held_modes(modes_s, k_s, r, names)
    r_e, r_s = modes_e @ held, modes_s @ held
    m = held.shape[1]
    n_s = 4 * s.size
    a = np.zeros((n_s + m, n_s + m))
    a[:n_s, :n_s] = np.eye(n_s) + k_s @ g_ss
    a[:n_s, n_s:] = k_s @ r_s
    a[n_s:, :n_s] = r_s.T
    b = np.concatenate([-k_s @ g_se, -r_e.T])
    x = np.linalg.solve(a, b)
    x_f, x_a = x[:n_s], x[n_s:]
    c = g_ee + g_se.T @ x_f + (r_e @ x_a if m else 0.0)
    asym = np.abs(c - c.T).max() / max(np.abs(c).max(), 1e-300)
    if asym > SYMMETRY_TOLERANCE or not np.all(np.isfinite(c)):
        raise checks.InputError(
            f"{what}: the condensed compliance is not symmetric ({asym:.2g} of its largest entry): the "
            "supports make the ring unstable (negative springs beyond the foundation?)"
        )
    full = np.zeros((6, m))
    full[free] = held
    return Condensation(0.5 * (c + c.T), x_f, x_a if m else None, full if m else None, unheld)


def _held_modes(modes_s, k_s, radius, names):
    """(held (m_free, m) orthonormal combinations of the free modes the supports hold, names of the rest)."""
    m_free = modes_s.shape[1]
    if m_free == 0:
        return np.zeros((0, 0)), ()
    # rotations carry a radius: scale them so that a unit rotation moves the ring by ~1
    stiff = modes_s.T @ k_s @ modes_s
    val, vec = np.linalg.eigh(stiff)
    top = max(float(np.abs(val).max()), 1e-300)
    keep = val > 1e-10 * top
    unheld = ()
    if not keep.all():
        loose = vec[:, ~keep]
        unheld = tuple(n for n, w in zip(names, np.abs(loose).max(axis=1), strict=True) if w > 1e-6)
    return vec[:, keep], unheld
