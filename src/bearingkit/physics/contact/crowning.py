"""Roller crowning profile kinds: straight, full crown, arc–slope, Lundberg, Johns–Gohar, ISO/TS 16281.

All quantities are SI: lengths in m, loads in N, moduli in Pa. Each kind is a frozen dataclass
deriving from :class:`~bearingkit.physics.contact.profile_base.Profile`; the registry of names is
:data:`bearingkit.physics.contact.profiles.PROFILES`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics.contact.profile_base import (
    DEFAULT_END_DROP_RATIO,
    ISO16281_COEFF_LONG,
    ISO16281_COEFF_SHORT,
    ISO16281_COEFF_TAPERED,
    ISO16281_LENGTH_RATIO_LIMIT,
    JOHNS_GOHAR_END_CONSTANT,
    LOG_CLIP_DEFAULT,
    Profile,
    _arc_drop,
    _flat_length,
    _log_relief,
    _optional_positive,
    _require,
    _resolve_radius,
    _validate_arc_inputs,
    _validate_clip,
    _validate_flat,
    hertz_line_half_width,
)

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
