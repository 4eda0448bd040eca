"""Roller crowning profiles, the common part: the :class:`Profile` base, its constants and checks.

All quantities are SI: lengths in m, loads in N, moduli in Pa. The profile kinds are in
:mod:`bearingkit.physics.contact.crowning`, the registry and :func:`make_profile` in
:mod:`bearingkit.physics.contact.profiles`.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError

# ---------------------------------------------------------------------------------------------
# Constants
# ---------------------------------------------------------------------------------------------

#: ISO/TS 16281:2008 eq. (42) profile coefficient for cylindrical rollers with L_we <= 2.5 D_we
#: [-] (multiplies D_we). Source: ISO/TS 16281:2008 §7.2 eq. (42); valid for L_we <= 2.5 D_we.
ISO16281_COEFF_SHORT = 0.00035
#: ISO/TS 16281:2008 eq. (43) coefficient for the crowned end zones of long cylindrical rollers
#: (L_we > 2.5 D_we) [-] (multiplies D_we). Source: ISO/TS 16281:2008 eq. (43).
ISO16281_COEFF_LONG = 0.0005
#: ISO/TS 16281:2008 eq. (44) coefficient for tapered rollers [-] (multiplies D_we).
ISO16281_COEFF_TAPERED = 0.00045
#: Length ratio L_we / D_we above which ISO/TS 16281 uses the flat-middle form eq. (43) [-].
#: Source: ISO/TS 16281:2008 eqs. (42)-(43).
ISO16281_LENGTH_RATIO_LIMIT = 2.5

#: Johns & Gohar (1981) end-relief constant [-]: the log argument at the roller end is
#: 0.3033 * (2 b / l) instead of 0 (Lundberg), so the end drop is finite. Source: Johns P.M.,
#: Gohar R. (1981) Tribol. Int. 14(3):131-136; read via the formula quoted with MASTA's
#: Johns-Gohar profile, P(x) = 2Q(1-nu^2)/(pi l E) ln{1/[1-(1-0.3033 a/b)(2x/l)^2]} with a the
#: Hertz half-width and b the half-length. Valid for 2b/l << 1.
JOHNS_GOHAR_END_CONSTANT = 0.3033

#: Hertz line-contact half-width constant: b = sqrt(8 Q R_x / (pi l E')) [-] (the 8 in it), with
#: Hamrock's E' = 2 E* (Johnson's contact modulus E*). Source: Johnson K.L. (1985) Contact
#: Mechanics, §4.2 (b = sqrt(4 w R / (pi E*)), w = Q/l); Hamrock's b = R_x sqrt(8 W'/pi).
HERTZ_LINE_HALF_WIDTH_FACTOR = 8.0

#: Default clip of the logarithmic profiles [-]: the logarithm ln[1/(1 - u^2)] (u = normalised
#: axial position, 1 at the roller end) is evaluated at most at u = 0.999 and held constant
#: beyond. 0.999 is the outermost slice centre of a roller cut into 1000 slices, so the clip is
#: never active at slice centres of any practical slicing (ISO/TS 16281 evaluates the profile at
#: slice centres); it only keeps C finite at x = +-L/2 (plots, end checks).
LOG_CLIP_DEFAULT = 0.999

#: Default end drop of the circular-arc profiles (full_crown, arc_slope_sides, arc_slope_midline)
#: as a fraction of the roller diameter [-]: C(L/2) = 0.001 D, i.e. 4 um for seed 000's axial
#: 4 mm x 4.8 mm rollers and 5 um for its radial 5 mm x 8 mm rollers. Reasoning (seed 000 gives
#: no crowning data): precision rollers of a few mm carry crown drops of a few um, and 0.001 D
#: equals the ISO/TS 16281 eq. (42) drop 0.00035 D ln[1/(1 - u^2)] at u = 2|x|/L = 0.971, i.e.
#: near the outermost slice centre of a ~30-slice roller, so seed types a-d reach the same drop
#: near the roller ends and the comparison of seed 000 section 6.1.5 is like for like.
DEFAULT_END_DROP_RATIO = 0.001

#: Default flat (straight) length of the arc-slope profiles as a fraction of L [-]. Choice, not a
#: source value: half the effective length straight, a quarter crowned at each end (partial
#: crowning of cylindrical rollers typically leaves the middle 40-70 % straight).
DEFAULT_FLAT_FRACTION = 0.5

#: Relative tolerance on |x| <= L/2 (round-off of slice centres computed by callers) [-].
_X_RANGE_RTOL = 1e-9


# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------


def _log_relief(u, clip: float):
    """ln[1/(1 - u^2)] for normalised positions 0 <= u, with u clipped at ``clip`` (< 1)."""
    uc = np.minimum(u, clip)
    return -np.log1p(-(uc * uc))


def _circle_radius_through_drop(half_span: float, drop: float) -> float:
    """Radius of the circle tangent to the axis at 0 that drops by ``drop`` over ``half_span``.

    From :math:`R - \\sqrt{R^2 - h^2} = C`: :math:`R = (h^2 + C^2)/(2C)`.
    """
    return (half_span * half_span + drop * drop) / (2.0 * drop)


def _arc_drop(s, radius: float):
    """Drop of a circular arc of radius R tangent at s = 0: R - sqrt(R^2 - s^2), computed stably."""
    s2 = s * s
    return s2 / (radius + np.sqrt(radius * radius - s2))


def hertz_line_half_width(load, effective_length, e_reduced, curvature_sum):
    """Hertz half-width of a line contact.

    Parameters
    ----------
    load : array_like
        Contact load Q [N].
    effective_length : array_like
        Contact length l [m].
    e_reduced : array_like
        Reduced modulus E' [Pa], :math:`2/[(1-\\nu_1^2)/E_1 + (1-\\nu_2^2)/E_2]`.
    curvature_sum : array_like
        Curvature sum in the rolling direction :math:`\\Sigma\\rho = 1/R_x` [1/m].

    Returns
    -------
    ndarray
        Half-width b [m].

    Notes
    -----
    .. math:: b = \\sqrt{\\frac{8\\,Q\\,R_x}{\\pi\\,l\\,E'}}

    Johnson K.L. (1985) Contact Mechanics, Cambridge University Press, §4.2, with
    :math:`E' = 2E^*`.
    """
    q = np.asarray(load, dtype=float)
    return np.sqrt(
        HERTZ_LINE_HALF_WIDTH_FACTOR
        * q
        / (math.pi * np.asarray(effective_length, dtype=float))
        / (np.asarray(e_reduced, dtype=float) * np.asarray(curvature_sum, dtype=float))
    )


# ---------------------------------------------------------------------------------------------
# Base class
# ---------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Profile:
    """Base of all roller profiles (abstract; use a registered subclass or :func:`make_profile`).

    Attributes
    ----------
    effective_length : float
        Effective roller length L [m] (``l``, ``L_we``).
    element_diameter : float
        Roller (mean) diameter D [m] (``D_we``).
    """

    effective_length: float
    element_diameter: float

    name: ClassVar[str] = ""
    #: Keys of :data:`bearingkit.references.REFERENCES` this profile is built on.
    references: ClassVar[tuple[str, ...]] = ()

    def __post_init__(self):
        checks.positive("effective_length", self.effective_length, "m")
        checks.positive("element_diameter", self.element_diameter, "m")

    @property
    def half_length(self) -> float:
        """L/2 [m]."""
        return 0.5 * float(self.effective_length)

    def crown_drop(self, x) -> np.ndarray:
        """Crown drop C(x) [m] at axial positions ``x`` [m] (any shape, |x| <= L/2).

        Raises :class:`InputError` for non-finite positions or positions beyond the roller ends.
        """
        xa = np.abs(np.asarray(x, dtype=float))
        checks.finite("x", xa, "m")
        if xa.size and float(np.max(xa)) > self.half_length * (1.0 + _X_RANGE_RTOL):
            raise InputError(
                f"x ({float(np.max(xa)):.6g} m) must lie within +-effective_length/2 "
                f"({self.half_length:.6g} m)"
            )
        return self._drop(np.minimum(xa, self.half_length))

    def end_drop_value(self) -> float:
        """Crown drop at the roller end, C(L/2) [m] (for the logarithmic profiles: at the clip)."""
        return float(self.crown_drop(self.half_length))

    def _drop(self, xa: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    def parameters(self) -> dict[str, float | None]:
        """The profile's fields as a JSON-ready dict (SI)."""
        return {f.name: getattr(self, f.name) for f in dataclasses.fields(self)}


def _optional_positive(field: str, value, unit: str):
    if value is not None:
        checks.positive(field, value, unit)


# ---------------------------------------------------------------------------------------------
# Validation helpers shared by the arc profiles
# ---------------------------------------------------------------------------------------------


def _require(field: str, value, unit: str):
    if value is None:
        raise InputError(f"{field} (None {unit}) must be given (a positive value)")
    checks.positive(field, value, unit)


def _validate_clip(clip):
    checks.in_range("clip", clip, 0.0, 1.0, "", closed=False)


def _flat_length(p) -> float:
    return DEFAULT_FLAT_FRACTION * p.effective_length if p.flat_length is None else float(p.flat_length)


def _validate_flat(p):
    if p.flat_length is not None:
        checks.non_negative("flat_length", p.flat_length, "m")
        if p.flat_length >= p.effective_length:
            raise InputError(
                f"flat_length ({p.flat_length:.6g} m) must be less than effective_length "
                f"({p.effective_length:.6g} m)"
            )


def _validate_arc_inputs(p, arc_span: float):
    """Crown radius / end drop of an arc tangent at its start, spanning ``arc_span`` to the end."""
    if p.crown_radius is not None and p.end_drop is not None:
        raise InputError("crown_radius and end_drop must not both be given; give one of them")
    if p.crown_radius is not None:
        checks.positive("crown_radius", p.crown_radius, "m")
        if p.crown_radius < arc_span:
            raise InputError(
                f"crown_radius ({p.crown_radius:.6g} m) must be at least the crowned length per end "
                f"({arc_span:.6g} m) to reach the roller end"
            )
    elif p.end_drop is not None:
        checks.positive("end_drop", p.end_drop, "m")
        limit = min(arc_span, 0.5 * p.element_diameter)
        if p.end_drop > limit:
            raise InputError(
                f"end_drop ({p.end_drop:.6g} m) must not exceed {limit:.6g} m "
                "(the crowned length per end and D/2)"
            )


def _resolve_radius(p, arc_span: float) -> float:
    if p.crown_radius is not None:
        return float(p.crown_radius)
    drop = DEFAULT_END_DROP_RATIO * p.element_diameter if p.end_drop is None else float(p.end_drop)
    return _circle_radius_through_drop(arc_span, drop)
