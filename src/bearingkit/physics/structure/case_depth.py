"""Strength of a hardened layer against the stress below a contact: safety against depth, case safety,
required case depth.

SI units (m, Pa). The stress is the von Mises stress σ_vM(z) below a contact
(:mod:`bearingkit.physics.contact.subsurface`), the strength the local yield strength σ_y(z) of the
hardness profile (:class:`bearingkit.hardness.HardnessProfile`): distortion energy against first yield,
the criterion of case-hardened contact design (e.g. Sadeghi-type "contact yield initiation" analyses; the
core-strength checks of MESYS and NREL DG03 compare a shear stress with the core's shear strength instead).

- safety against depth S(z) = σ_y(z) / σ_vM(z);
- **case safety** S_case = min S(z) over the depths where the hardness has left the surface value
  (z ≥ z_a, the transition zone and the core). Inside the plateau the raceway is judged by ISO 76's limit
  pressure (s0), which allows a small permanent deformation: first yield there is expected at the
  static limit (σ_vM,max ≈ 0.6 p₀ exceeds σ_y of 58–62 HRC steel above p₀ ≈ 3 GPa) and is not the case
  check's concern. A through-hardened ring has no case safety (None);
- **required case depth** d_c* for a target S_case: the profile is scaled in depth (its shape, hardness
  values and limit hardness kept) and d_c found by bisection (S_case grows with d_c: deeper cases hold a
  higher hardness at every depth).

Sources: the strength from hardness of :mod:`bearingkit.hardness` (Pavlina & Van Tyne 2008); the
alternative core checks of Harris, Rumbarger & Butterfield (2009, NREL DG03) are discussed in
docs/subsurface.md.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from bearingkit import checks

__all__ = ["CaseCheck", "case_check", "depth_safety", "required_case_depth"]

#: Bisection steps of :func:`required_case_depth` (the bracket shrinks 2⁻⁴⁸: far below a micrometre).
_BISECTION_STEPS = 48


class CaseCheck(NamedTuple):
    """The case check of contacts (leading axes of the stress arrays).

    Attributes
    ----------
    safety : ndarray (..., N)
        S(z) = σ_y(z)/σ_vM(z) [-] (inf where σ_vM = 0).
    case_safety : ndarray (...)
        min S over z ≥ z_a [-]; NaN for a through-hardened ring.
    depth_case_safety : ndarray (...)
        Depth of that minimum [m]; NaN for a through-hardened ring.
    zone : ndarray (...) of str
        Where the minimum lies: ``"transition"`` (z_a ≤ z < z_b), ``"core"`` (z ≥ z_b), ``""``
        (through-hardened).
    """

    safety: np.ndarray
    case_safety: np.ndarray
    depth_case_safety: np.ndarray
    zone: np.ndarray


def depth_safety(von_mises, strength):
    """S(z) = σ_y / σ_vM [-]; +inf where σ_vM = 0.

    Parameters
    ----------
    von_mises, strength : array_like
        σ_vM(z) ≥ 0 and σ_y(z) > 0 [Pa].
    """
    vm = np.asarray(von_mises, float)
    with np.errstate(divide="ignore"):
        return np.where(vm > 0.0, np.asarray(strength, float) / np.where(vm > 0.0, vm, 1.0), np.inf)


def _case_min(depth, von_mises, profile, case_depth=None):
    strength = profile.strength(depth, None if case_depth is None else case_depth[..., None])
    s = depth_safety(von_mises, strength)
    start, end = profile.transition(case_depth)
    start = np.asarray(start, float)[..., None] if np.ndim(start) else start
    masked = np.where(depth >= start, s, np.inf)
    k = np.argmin(masked, axis=-1)[..., None]
    low = np.take_along_axis(masked, k, -1)[..., 0]
    return s, low, np.take_along_axis(depth, k, -1)[..., 0], end


def case_check(depth, von_mises, profile) -> CaseCheck:
    """Safety against depth and the case safety of a hardness profile (module docstring).

    .. math:: S(z) = \\frac{\\sigma_y(HV(z))}{\\sigma_{vM}(z)},\\qquad S_{case} = \\min_{z \\ge z_a} S(z)

    Parameters
    ----------
    depth : array_like (..., N)
        Depths z ≥ 0 [m], increasing along the last axis.
    von_mises : array_like (..., N)
        σ_vM(z) [Pa] (the largest over the rolling position at each depth).
    profile : HardnessProfile
        The raceway's hardness profile.

    Returns
    -------
    CaseCheck
    """
    checks.non_negative("depth", depth, "m")
    checks.non_negative("von_mises", von_mises, "Pa")
    z, vm = np.broadcast_arrays(np.asarray(depth, float), np.asarray(von_mises, float))
    if profile.through_hardened:
        s = depth_safety(vm, profile.strength(z))
        nan = np.full(z.shape[:-1], np.nan)
        return CaseCheck(s, nan, nan.copy(), np.full(z.shape[:-1], "", dtype=object))
    s, low, where, end = _case_min(z, vm, profile)
    zone = np.where(where >= end, "core", "transition").astype(object)
    return CaseCheck(s, low, where, zone)


def required_case_depth(depth, von_mises, profile, target: float = 1.0):
    """Smallest effective case depth d_c* [m] whose case safety reaches ``target`` (profile scaled in depth).

    Parameters
    ----------
    depth, von_mises : array_like (..., N)
        As in :func:`case_check`; the depths must reach below the stressed zone (the search cannot look
        deeper than ``depth[..., -1]``).
    profile : HardnessProfile
        A case-hardened profile (its surface, limit and core hardness and transition shape are kept).
    target : float
        S_case wanted [-], > 0.

    Returns
    -------
    numpy.ndarray (...)
        d_c* [m]; 0 where the core alone reaches the target; +inf where even a case whose transition
        starts at ``depth[..., -1]`` does not (the surface hardness is too low for the stress there); NaN
        for a through-hardened profile.
    """
    checks.positive("target", target)
    z, vm = np.broadcast_arrays(np.asarray(depth, float), np.asarray(von_mises, float))
    shape = z.shape[:-1]
    if profile.through_hardened:
        return np.full(shape, np.nan)
    frac = (
        profile.transition_width
        * (profile.surface_hardness - profile.limit)
        / (profile.surface_hardness - profile.core_hardness)
    )
    # d_c whose transition starts at the deepest depth: only that depth is checked (at the surface
    # hardness); if it fails there, no case depth the grid can judge reaches the target
    hi = np.broadcast_to(z[..., -1] * (1.0 - 1e-9) / (1.0 - frac), shape).copy()
    lo = np.full(shape, 1.0e-9)
    ok_hi = _case_min(z, vm, profile, hi)[1] >= target
    ok_lo = _case_min(z, vm, profile, lo)[1] >= target
    for _ in range(_BISECTION_STEPS):
        mid = 0.5 * (lo + hi)
        good = _case_min(z, vm, profile, mid)[1] >= target
        hi, lo = np.where(good, mid, hi), np.where(good, lo, mid)
    return np.where(ok_lo, 0.0, np.where(ok_hi, hi, np.inf))
