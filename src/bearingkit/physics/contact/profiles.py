"""Roller crowning profiles: the crown drop C(x) of a cylindrical or tapered roller.

All quantities are SI: lengths in m, loads in N, moduli in Pa.

A profile gives the crown drop :math:`C(x) \\ge 0` [m] -- the material removed from the roller
radius relative to a straight roller -- at axial positions :math:`x` measured from the roller
middle, :math:`|x| \\le L/2`, for a roller of effective length :math:`L` (``effective_length``) and
diameter :math:`D` (``element_diameter``).  ``Profile.crown_drop(x)`` is pure and vectorised: ``x``
may have any shape (e.g. cases x elements x slices) and the result has the same shape.

The profiles are small frozen dataclasses behind the registry :data:`PROFILES`, keyed by a
documented name; :func:`make_profile` builds one by name and rejects unknown names or parameters
with :class:`bearingkit.errors.InputError`.

Registry names
--------------
``straight``            C = 0.
``full_crown``          one circular arc over the whole length (crown radius or end drop).
``arc_slope_sides``     flat middle + circular end arcs tangent to the flat; arc centres on the
                        perpendiculars through the flat's end points ("centres at both sides").
``arc_slope_midline``   flat middle + end arcs of one circle centred on the roller mid-plane
                        x = 0 ("centre on the midline"); slope kink at the flat's end.
``lundberg`` (alias ``logarithmic``)  Lundberg (1939) logarithmic profile for a design load.
``johns_gohar``         Johns & Gohar (1981) logarithmic profile with a finite end drop.
``iso16281``            ISO/TS 16281:2008 eqs. (42)-(43) logarithmic profile (cylindrical rollers).
``iso16281_tapered``    ISO/TS 16281:2008 eq. (44) logarithmic profile (tapered rollers).

Seed 000 (Tian et al. 2025, section 6.1.5, Fig. 18) compares five crowning types a-e without giving
any crowning dimension; :data:`SEED000_CROWNING` maps its letters to registry names and the
``DEFAULT_*`` constants below fix comparable default sizes (see their comments).
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
# Profiles
# ---------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class StraightProfile(Profile):
    """Straight (uncrowned) roller: :math:`C(x) = 0` (seed 000 type e).

    Parameters
    ----------
    effective_length : float
        Effective roller length L [m].
    element_diameter : float
        Roller diameter D [m].
    """

    name: ClassVar[str] = "straight"

    def _drop(self, xa):
        return np.zeros_like(xa)


@dataclass(frozen=True)
class FullCrownProfile(Profile):
    """Full crown: one circular arc of crown radius :math:`R_c` over the whole length (seed 000 type d).

    .. math:: C(x) = R_c - \\sqrt{R_c^2 - x^2}, \\qquad |x| \\le L/2

    Give either ``crown_radius`` or ``end_drop`` (:math:`C(L/2)`); they are related by
    :math:`R_c = [(L/2)^2 + C_{end}^2] / (2 C_{end})`. With neither, ``end_drop`` defaults to
    :data:`DEFAULT_END_DROP_RATIO` x D.

    Parameters
    ----------
    effective_length : float
        Effective roller length L [m].
    element_diameter : float
        Roller diameter D [m].
    crown_radius : float, optional
        Crown radius :math:`R_c` [m], must be >= L/2 (the arc must reach the roller ends).
    end_drop : float, optional
        Drop at the roller ends :math:`C(L/2)` [m], 0 < C_end <= min(L/2, D/2).

    References
    ----------
    Harris T.A., Kotzalas M.N. (2007) Rolling Bearing Analysis, 5th ed., Vol. 2, ch. 1 (crowned
    rollers); geometry of a circle. Seed 000: Tian et al. (2025) Machines 13:588, §6.1.5 type d.
    """

    crown_radius: float | None = None
    end_drop: float | None = None

    name: ClassVar[str] = "full_crown"
    references: ClassVar[tuple[str, ...]] = ("harris2007", "tian2025")

    def __post_init__(self):
        super().__post_init__()
        _validate_arc_inputs(self, self.half_length)

    @property
    def radius(self) -> float:
        """Crown radius :math:`R_c` [m] (given, or from the end drop)."""
        return _resolve_radius(self, self.half_length)

    def _drop(self, xa):
        return _arc_drop(xa, self.radius)


@dataclass(frozen=True)
class ArcSlopeSidesProfile(Profile):
    """Flat middle with circular end arcs tangent to it, arc centres at both sides (seed 000 type b).

    The straight middle :math:`|x| \\le x_f = L_{flat}/2` carries no drop; each end carries an arc
    of radius :math:`R_c` tangent to the flat at :math:`\\pm x_f`, i.e. with its centre on the
    perpendicular to the axis through :math:`x = \\pm x_f` (two centres, one on each side):

    .. math::
        C(x) = \\begin{cases} 0, & |x| \\le x_f \\\\
        R_c - \\sqrt{R_c^2 - (|x| - x_f)^2}, & x_f < |x| \\le L/2 \\end{cases}

    C and dC/dx are continuous at the junction (tangent arc). This is the usual "partial" or
    "line-arc" (straight + arc) crowning of cylindrical rollers. Give ``crown_radius`` or
    ``end_drop``; :math:`R_c = [(L/2 - x_f)^2 + C_{end}^2] / (2 C_{end})`.

    Parameters
    ----------
    effective_length : float
        Effective roller length L [m].
    element_diameter : float
        Roller diameter D [m].
    flat_length : float, optional
        Straight middle length :math:`L_{flat}` [m], 0 <= L_flat < L; default
        :data:`DEFAULT_FLAT_FRACTION` x L.
    crown_radius : float, optional
        End-arc radius :math:`R_c` [m], >= (L - L_flat)/2.
    end_drop : float, optional
        :math:`C(L/2)` [m]; default :data:`DEFAULT_END_DROP_RATIO` x D.

    References
    ----------
    Seed 000: Tian et al. (2025) Machines 13:588, §6.1.5 type b ("arc-slope crowning with the
    centers positioned at both sides"); crowning types compared by Ju S., Horng T., Cha K. (2000)
    Proc. IMechE J 214:147 (cited by seed 000 as [19]; not accessed -- the geometry is derived
    from the description).
    """

    flat_length: float | None = None
    crown_radius: float | None = None
    end_drop: float | None = None

    name: ClassVar[str] = "arc_slope_sides"
    references: ClassVar[tuple[str, ...]] = ("tian2025", "ju2000")

    def __post_init__(self):
        super().__post_init__()
        _validate_flat(self)
        _validate_arc_inputs(self, self.half_length - self.flat_half_length)

    @property
    def flat_half_length(self) -> float:
        """:math:`x_f = L_{flat}/2` [m]."""
        return 0.5 * _flat_length(self)

    @property
    def radius(self) -> float:
        """End-arc radius :math:`R_c` [m]."""
        return _resolve_radius(self, self.half_length - self.flat_half_length)

    def _drop(self, xa):
        s = np.maximum(xa - self.flat_half_length, 0.0)
        return _arc_drop(s, self.radius)


@dataclass(frozen=True)
class ArcSlopeMidlineProfile(Profile):
    """Flat middle with end arcs of one circle centred on the midline (seed 000 type c).

    Both end arcs belong to one circle of radius :math:`R_c` whose centre lies on the roller's
    mid-plane :math:`x = 0`, at the depth :math:`h = \\sqrt{R_c^2 - x_f^2}` below the surface, so
    that the circle passes through the flat's end points :math:`(\\pm x_f, 0)`, :math:`x_f =
    L_{flat}/2`. Geometrically: a full crown of radius :math:`R_c` whose top is ground flat. Then

    .. math::
        C(x) = \\begin{cases} 0, & |x| \\le x_f \\\\
        \\sqrt{R_c^2 - x_f^2} - \\sqrt{R_c^2 - x^2}, & x_f < |x| \\le L/2 \\end{cases}

    C is continuous at the junction but its slope jumps from 0 to :math:`x_f / h` (a kink --
    the "slope" of "arc-slope"). Given the end drop instead of :math:`R_c`, with
    :math:`a = x_f^2`, :math:`e = (L/2)^2`: :math:`\\sqrt{R_c^2 - a} - \\sqrt{R_c^2 - e} = C_{end}`
    and :math:`\\sqrt{R_c^2 - a} + \\sqrt{R_c^2 - e} = (e - a)/C_{end}`, hence

    .. math:: R_c^2 = a + \\left[\\tfrac{1}{2}\\left(\\tfrac{e - a}{C_{end}} + C_{end}\\right)\\right]^2,

    which needs :math:`C_{end} \\le \\sqrt{e - a}`. With ``flat_length = 0`` this is the full crown.

    Parameters
    ----------
    effective_length : float
        Effective roller length L [m].
    element_diameter : float
        Roller diameter D [m].
    flat_length : float, optional
        Straight middle length :math:`L_{flat}` [m], 0 <= L_flat < L; default
        :data:`DEFAULT_FLAT_FRACTION` x L.
    crown_radius : float, optional
        Circle radius :math:`R_c` [m], >= L/2 (the circle must reach the roller ends).
    end_drop : float, optional
        :math:`C(L/2)` [m]; default :data:`DEFAULT_END_DROP_RATIO` x D.

    References
    ----------
    Seed 000: Tian et al. (2025) Machines 13:588, §6.1.5 type c ("arc-slope crowning with the
    center on the midline"); see also Ju, Horng & Cha (2000) Proc. IMechE J 214:147 (not
    accessed; geometry derived from the description).
    """

    flat_length: float | None = None
    crown_radius: float | None = None
    end_drop: float | None = None

    name: ClassVar[str] = "arc_slope_midline"
    references: ClassVar[tuple[str, ...]] = ("tian2025", "ju2000")

    def __post_init__(self):
        super().__post_init__()
        _validate_flat(self)
        if self.crown_radius is not None and self.end_drop is not None:
            raise InputError("crown_radius and end_drop must not both be given; give one of them")
        xf, h = self.flat_half_length, self.half_length
        if self.crown_radius is not None:
            checks.positive("crown_radius", self.crown_radius, "m")
            if self.crown_radius < h:
                raise InputError(
                    f"crown_radius ({self.crown_radius:.6g} m) must be at least effective_length/2 "
                    f"({h:.6g} m) to reach the roller end"
                )
        else:
            drop = self._end_drop()
            checks.positive("end_drop", drop, "m")
            limit = math.sqrt(h * h - xf * xf)
            limit = min(limit, 0.5 * self.element_diameter)
            if drop > limit:
                raise InputError(
                    f"end_drop ({drop:.6g} m) must not exceed {limit:.6g} m "
                    "(sqrt((L/2)^2 - (L_flat/2)^2) for a circle centred on the midline, and D/2)"
                )

    @property
    def flat_half_length(self) -> float:
        """:math:`x_f = L_{flat}/2` [m]."""
        return 0.5 * _flat_length(self)

    def _end_drop(self) -> float:
        return DEFAULT_END_DROP_RATIO * self.element_diameter if self.end_drop is None else self.end_drop

    @property
    def radius(self) -> float:
        """Circle radius :math:`R_c` [m]."""
        if self.crown_radius is not None:
            return float(self.crown_radius)
        a = self.flat_half_length**2
        e = self.half_length**2
        c = self._end_drop()
        return math.sqrt(a + (0.5 * ((e - a) / c + c)) ** 2)

    def _drop(self, xa):
        r = self.radius
        xf = self.flat_half_length
        xs = np.maximum(xa, xf)
        # sqrt(R^2 - xf^2) - sqrt(R^2 - x^2) = (x^2 - xf^2) / (sqrt(R^2 - xf^2) + sqrt(R^2 - x^2))
        return (xs * xs - xf * xf) / (math.sqrt(r * r - xf * xf) + np.sqrt(r * r - xs * xs))


@dataclass(frozen=True)
class LundbergProfile(Profile):
    """Lundberg (1939) logarithmic profile for a design load.

    .. math:: C(x) = \\frac{2 Q}{\\pi\\, l\\, E'}
              \\ln\\frac{1}{1 - \\left(\\min(2|x|/l,\\ u_{clip})\\right)^2}

    with :math:`l` = ``effective_length``, :math:`Q` = ``design_load`` and :math:`E'` =
    ``e_reduced`` (Hamrock's reduced modulus, so that :math:`2/E' = (1-\\nu_1^2)/E_1 +
    (1-\\nu_2^2)/E_2`). This is the total gap (both bodies) that makes the contact pressure
    uniform along the roller at the design load: a line load :math:`q = Q/l` on the half-spaces
    gives the relative approach difference :math:`(q/\\pi)(2/E') \\ln[1/(1-(2x/l)^2)]` between
    the centre and :math:`x` (Boussinesq). The profile is singular at :math:`|x| = l/2`; the
    logarithm is held constant beyond :math:`u_{clip}` (``clip``, default
    :data:`LOG_CLIP_DEFAULT`).

    Parameters
    ----------
    effective_length : float
        Effective roller length l [m].
    element_diameter : float
        Roller diameter D [m] (not used by the formula).
    design_load : float
        Design (roller) load Q [N], > 0.
    e_reduced : float
        Reduced modulus E' [Pa], > 0.
    clip : float, optional
        Normalised position :math:`u = 2|x|/l` beyond which the logarithm is held constant [-],
        0 < clip < 1.

    References
    ----------
    Lundberg G. (1939) Elastische Berührung zweier Halbräume. Forsch. Ing.-Wes. 10(5):201-211.
    Harris & Kotzalas (2007) Vol. 2, ch. 1.
    """

    design_load: float | None = None
    e_reduced: float | None = None
    clip: float = LOG_CLIP_DEFAULT

    name: ClassVar[str] = "lundberg"
    references: ClassVar[tuple[str, ...]] = ("lundberg1939", "harris2007")

    def __post_init__(self):
        super().__post_init__()
        _require("design_load", self.design_load, "N")
        _require("e_reduced", self.e_reduced, "Pa")
        _validate_clip(self.clip)

    @property
    def coefficient(self) -> float:
        """:math:`2Q/(\\pi l E')` [m]."""
        return 2.0 * self.design_load / (math.pi * self.effective_length * self.e_reduced)

    def _drop(self, xa):
        return self.coefficient * _log_relief(xa / self.half_length, self.clip)


@dataclass(frozen=True)
class JohnsGoharProfile(Profile):
    """Johns & Gohar (1981) logarithmic profile: Lundberg's law with a finite end drop.

    .. math:: C(x) = \\frac{2 Q}{\\pi\\, l\\, E'} \\ln\\frac{1}
              {1 - \\left(1 - 0.3033\\,\\frac{2b}{l}\\right)\\left(\\frac{2x}{l}\\right)^2}

    with :math:`b` the Hertz half-width of the contact at the design load (``semi_minor``, or
    computed from ``curvature_sum`` by :func:`hertz_line_half_width`). At the ends the argument
    of the logarithm is :math:`0.3033 \\cdot 2b/l`, so
    :math:`C(l/2) = (2Q/\\pi l E')\\ln[l/(0.6066\\, b)]` is finite.

    Parameters
    ----------
    effective_length : float
        Effective roller length l [m].
    element_diameter : float
        Roller diameter D [m] (not used by the formula).
    design_load : float
        Design load Q [N], > 0.
    e_reduced : float
        Reduced modulus E' [Pa], > 0.
    semi_minor : float, optional
        Hertz half-width b at the design load [m]. Give this or ``curvature_sum``.
    curvature_sum : float, optional
        Curvature sum in the rolling direction :math:`1/R_x` [1/m], used to compute b.

    References
    ----------
    Johns P.M., Gohar R. (1981) Roller bearings under radial and eccentric loads. Tribology
    International 14(3):131-136. Constant 0.3033 verified
    against the formula quoted with MASTA's Johns-Gohar profile (secondary source); see also
    Fujiwara H., Kawase T. (2007) NTN Technical Review 75.
    """

    design_load: float | None = None
    e_reduced: float | None = None
    semi_minor: float | None = None
    curvature_sum: float | None = None

    name: ClassVar[str] = "johns_gohar"
    references: ClassVar[tuple[str, ...]] = ("johns1981", "lundberg1939")

    def __post_init__(self):
        super().__post_init__()
        _require("design_load", self.design_load, "N")
        _require("e_reduced", self.e_reduced, "Pa")
        if (self.semi_minor is None) == (self.curvature_sum is None):
            raise InputError(
                f"semi_minor ({self.semi_minor!r} m) or curvature_sum ({self.curvature_sum!r} 1/m): "
                "exactly one must be given"
            )
        _optional_positive("semi_minor", self.semi_minor, "m")
        _optional_positive("curvature_sum", self.curvature_sum, "1/m")
        if self._end_argument() <= 0.0 or self._end_argument() >= 1.0:
            raise InputError(
                f"semi_minor ({self.half_width:.6g} m) must satisfy 0 < 0.3033*2b/l < 1 "
                f"(l = {self.effective_length:.6g} m)"
            )

    @property
    def half_width(self) -> float:
        """Hertz half-width b [m]."""
        if self.semi_minor is not None:
            return float(self.semi_minor)
        return float(
            hertz_line_half_width(self.design_load, self.effective_length, self.e_reduced, self.curvature_sum)
        )

    def _end_argument(self) -> float:
        return JOHNS_GOHAR_END_CONSTANT * 2.0 * self.half_width / self.effective_length

    @property
    def coefficient(self) -> float:
        """:math:`2Q/(\\pi l E')` [m]."""
        return 2.0 * self.design_load / (math.pi * self.effective_length * self.e_reduced)

    def _drop(self, xa):
        u = xa / self.half_length
        return -self.coefficient * np.log1p(-(1.0 - self._end_argument()) * u * u)


@dataclass(frozen=True)
class Iso16281Profile(Profile):
    """ISO/TS 16281:2008 logarithmic profile of cylindrical rollers, eqs. (42)-(43) (seed 000 type a).

    For :math:`L_{we} \\le 2.5 D_{we}` (eq. 42):

    .. math:: C(x) = 0.00035\\, D_{we} \\ln\\frac{1}{1 - (2x/L_{we})^2}

    For :math:`L_{we} > 2.5 D_{we}` (eq. 43) the middle :math:`|x| \\le (L_{we} - 2.5D_{we})/2` is
    straight and

    .. math:: C(x) = 0.0005\\, D_{we} \\ln\\frac{1}{1 - \\left(
              \\frac{2|x| - (L_{we} - 2.5 D_{we})}{2.5 D_{we}}\\right)^2}

    (rewritten with :math:`|x|`). ISO evaluates the profile at slice centres, where it is finite;
    here the normalised position in the logarithm is clipped at ``clip`` (default
    :data:`LOG_CLIP_DEFAULT`) so that :math:`C(\\pm L/2)` is finite too. Needs no load: the profile
    is the load-independent logarithmic crowning of the standard's reference roller.

    Parameters
    ----------
    effective_length : float
        Effective roller length :math:`L_{we}` [m].
    element_diameter : float
        Roller diameter :math:`D_{we}` [m].
    clip : float, optional
        Normalised position beyond which the logarithm is held constant [-], 0 < clip < 1.

    References
    ----------
    ISO/TS 16281:2008, §7.2, eqs. (42)-(43).
    """

    clip: float = LOG_CLIP_DEFAULT

    name: ClassVar[str] = "iso16281"
    references: ClassVar[tuple[str, ...]] = ("iso16281",)

    def __post_init__(self):
        super().__post_init__()
        _validate_clip(self.clip)

    @property
    def flat_half_length(self) -> float:
        """Half the straight middle, :math:`\\max(0, L_{we} - 2.5 D_{we})/2` [m]."""
        return 0.5 * max(0.0, self.effective_length - ISO16281_LENGTH_RATIO_LIMIT * self.element_diameter)

    def _drop(self, xa):
        d = self.element_diameter
        if self.effective_length <= ISO16281_LENGTH_RATIO_LIMIT * d:
            return ISO16281_COEFF_SHORT * d * _log_relief(xa / self.half_length, self.clip)
        crowned_half = 0.5 * ISO16281_LENGTH_RATIO_LIMIT * d
        v = np.maximum(xa - self.flat_half_length, 0.0) / crowned_half
        return ISO16281_COEFF_LONG * d * _log_relief(v, self.clip)


@dataclass(frozen=True)
class Iso16281TaperedProfile(Profile):
    """ISO/TS 16281:2008 logarithmic profile of tapered rollers, eq. (44).

    .. math:: C(x) = 0.00045\\, D_{we} \\ln\\frac{1}{1 - \\left(\\min(2|x|/L_{we},\\ u_{clip})\\right)^2}

    Parameters
    ----------
    effective_length : float
        Effective roller length :math:`L_{we}` [m].
    element_diameter : float
        Mean roller diameter :math:`D_{we}` [m].
    clip : float, optional
        Normalised position beyond which the logarithm is held constant [-], 0 < clip < 1.

    References
    ----------
    ISO/TS 16281:2008, §7.2, eq. (44).
    """

    clip: float = LOG_CLIP_DEFAULT

    name: ClassVar[str] = "iso16281_tapered"
    references: ClassVar[tuple[str, ...]] = ("iso16281",)

    def __post_init__(self):
        super().__post_init__()
        _validate_clip(self.clip)

    def _drop(self, xa):
        return ISO16281_COEFF_TAPERED * self.element_diameter * _log_relief(xa / self.half_length, self.clip)


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


# ---------------------------------------------------------------------------------------------
# Registry
# ---------------------------------------------------------------------------------------------

#: Registry of profile classes keyed by documented name. ``logarithmic`` is an alias of
#: ``lundberg`` (the load-based logarithmic law); seed 000's type a uses ``iso16281`` instead.
PROFILES: dict[str, type[Profile]] = {
    StraightProfile.name: StraightProfile,
    FullCrownProfile.name: FullCrownProfile,
    ArcSlopeSidesProfile.name: ArcSlopeSidesProfile,
    ArcSlopeMidlineProfile.name: ArcSlopeMidlineProfile,
    LundbergProfile.name: LundbergProfile,
    "logarithmic": LundbergProfile,
    JohnsGoharProfile.name: JohnsGoharProfile,
    Iso16281Profile.name: Iso16281Profile,
    Iso16281TaperedProfile.name: Iso16281TaperedProfile,
}

#: Seed 000 (Tian et al. 2025, §6.1.5, Fig. 18) crowning letters -> registry names.
#: "a" logarithmic: the paper gives no crowning data, so the load-independent ISO/TS 16281
#: logarithmic profile is used (the Lundberg/Johns-Gohar laws would need a design load the paper
#: does not state). b-d use the DEFAULT_* sizes above (same end drop 0.001 D; half the length flat).
SEED000_CROWNING: dict[str, str] = {
    "a": "iso16281",
    "b": "arc_slope_sides",
    "c": "arc_slope_midline",
    "d": "full_crown",
    "e": "straight",
}

_BASE_FIELDS = {f.name for f in dataclasses.fields(Profile)}


def make_profile(name: str, effective_length: float, element_diameter: float, **parameters) -> Profile:
    """Build a registered profile by name.

    Parameters
    ----------
    name : str
        Registry name, one of :data:`PROFILES`.
    effective_length : float
        Effective roller length L [m].
    element_diameter : float
        Roller diameter D [m].
    **parameters
        The profile's own parameters (SI), e.g. ``crown_radius`` [m], ``end_drop`` [m],
        ``flat_length`` [m], ``design_load`` [N], ``e_reduced`` [Pa], ``semi_minor`` [m],
        ``curvature_sum`` [1/m], ``clip`` [-].

    Returns
    -------
    Profile

    Raises
    ------
    InputError
        Unknown name (the message lists the valid names), unknown parameter (lists the valid
        ones), or an invalid value.
    """
    checks.one_of("profile", name, PROFILES)
    cls = PROFILES[name]
    allowed = [f.name for f in dataclasses.fields(cls) if f.name not in _BASE_FIELDS]
    for key in parameters:
        if key not in allowed:
            raise InputError(
                f"{key} is not a parameter of profile {name!r}; valid: {', '.join(allowed) or '(none)'}"
            )
    return cls(effective_length=effective_length, element_diameter=element_diameter, **parameters)


def seed000_profile(letter: str, effective_length: float, element_diameter: float) -> Profile:
    """Seed 000 crowning type ``letter`` (a-e) with documented defaults (Tian et al. 2025 §6.1.5).

    Parameters
    ----------
    letter : str
        ``"a"`` logarithmic … ``"e"`` straight (:data:`SEED000_CROWNING`).
    effective_length : float [m]
        Roller effective length.
    element_diameter : float [m]
        Roller diameter.
    """
    checks.one_of("crowning", letter, SEED000_CROWNING)
    return make_profile(SEED000_CROWNING[letter], effective_length, element_diameter)
