"""Friction forces of a tapered roller bearing: EHL rolling, sliding traction, rib sliding, kinematics.

SI units throughout (N, m, Pa, Pa·s, 1/Pa, m/s, rad/s, N·m). Pure numpy functions broadcasting over
their arguments (leading case axis first). They implement seed 001 (Liu et al. 2022, §2.2, eqs. 7–13,
doi:10.3390/lubricants10070154); the extracted seed text lost exponents and minus signs, so every
form is re-derived here and the reading is stated. docs/seed001.md summarises the readings and results.

Readings of the seed's equations
--------------------------------
- **Eq. (7), EHL rolling resistance** (Aihara 1987): ``F_ro = C (1/α) (G U)^0.658 W^0.31 R l``. The
  text prints the constant as "0.88 × 10 2". bearingkit reads C = 0.88 × 10² = 88 (registry
  :data:`ROLLING_COEFFICIENTS`, default ``"aihara1987"``): Aihara writes the moment on a contact as
  176 (1/α)(GU)^0.658 W^0.31 R² a with the half length a = l/2, i.e. a force 88 (…) R l; and for the
  seed bearing C = 88 puts the rolling torque within a factor 2 of the SKF catalogue's rolling moment
  of a 320-series TRB (tests), whereas C = 0.88 × 10⁻² would make it 10⁴ times smaller. The literal
  negative-exponent reading is kept as ``"liu2022_literal"`` for comparison.
- **Eq. (8), sliding traction** (Harris 1966, after Zhou & Hoeprich 1991 for I). Printed (flattened)
  "F r s = 0.168 v s η 0 l w I U 0.74 G 0.4 W 0.2 R 1". The trailing "R 1" is R⁻¹ with its minus sign
  lost, so the other exponents may have lost theirs too; dimensions decide part of it:
  [v_s η₀ l_w / R] = Pa·m = N/m, so I must be a length for F_rs to be a force — a dimensionless mean
  ∫…dx/b is excluded. The groups read U^−0.74 G^−0.4 W^0.2 (a Newtonian shear force falls with the
  film, which grows with U and G and falls with W): ``F_rs = v_s η₀ l I / h*`` with the film
  h* = R U^0.74 G^0.4 W^−0.2 / 0.168 (:func:`sliding_film_thickness`). 2h* is within 10 % of the
  Pan–Hamrock central film for the seed contacts (tests), which fixes the half-strip integral as
  printed: eq. (8) is Newtonian shear over the whole strip (2I) across the central film (2h*).
- **Eq. (10), tractive integral**: ``I = ∫₀ᵇ exp{(ln η₀ + 9.67)[(1 + 5.1×10⁻⁹ p)^Z − 1]} dx`` —
  Roelands' viscosity ratio η(p)/η₀ (η₀ in Pa·s, p in Pa: 5.1 × 10⁻⁹ 1/Pa = 1/p_r with
  p_r = 1.96 × 10⁸ Pa) over a Hertz pressure p = p_max √(1 − x²/b²); I has the unit of length. Two
  other readings the flattened text admits are rejected: p in MPa (η(p) ≈ η₀, i.e. no
  piezoviscosity, contrary to Roelands' p_r) and exp applied to (ln η₀ + 9.67) alone (the integrand
  η₀/η_∞ · [(1 + p/p_r)^Z − 1] is not a viscosity). The seed prints Z = 0.601
  (:data:`ROELANDS_EXPONENT_LIU2022`); :func:`roelands_exponent` gives the Z that matches a
  lubricant's Barus α instead.
- **Limiting shear stress (bearingkit default, not in the seed)**: Newtonian shear with Roelands
  viscosity at p_max ≈ 1.3 GPa gives local stresses of ~0.3 p at a slide-to-roll ratio of 2e-4
  (S_c = 0.01 %), several times the limiting shear stress of mineral oils, τ_L = Λ_L p with
  Λ_L ≈ 0.05…0.1 (Bair & Winer 1979); the Newtonian integral then grows like Q^~5. bearingkit's
  default (``model="limiting_shear"``, :data:`SLIDING_MODELS`) keeps eqs. (8) and (10) unchanged and
  caps the local stress with the Bair–Winer law τ = τ_L[1 − exp(−τ_N/τ_L)], τ_N = η(p) v_s/(2h*), over
  the full strip: it equals eq. (8) where τ_N ≪ τ_L and is bounded by Λ_L Q. ``model="newtonian"``
  is eq. (8) as printed.
- **Eq. (9), rib sliding**: :func:`bearingkit.physics.lubrication.traction.flange_friction_force` (reused).
- **Eq. (13), kinematics under outer-raceway control**: v_se = 0, v_si = ω_i R_i S_c, derived in
  :func:`outer_control_kinematics`.
- **Eqs. (11)–(12), ring torques**: :func:`ring_torques`.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from bearingkit import checks, references
from bearingkit.errors import InputError
from bearingkit.physics.friction import components as fc
from bearingkit.physics.friction.trb_rheology import (
    ROELANDS_EXPONENT_LIU2022,
    SLIDING_LIMITING_SHEAR_COEFF,
    _arr,
    limited_shear_integral,
    roelands_exponent,
    roelands_viscosity_ratio,
    tractive_integral,
)

references.add(
    "harris1966",
    "Harris T.A. (1966) An analytical method to predict skidding in high speed roller bearings. "
    "ASLE Trans. 9(3):229-241. (DOI not verified here)",
)
references.add(
    "zhou1991",
    "Zhou R.S., Hoeprich M.R. (1991) Torque of tapered roller bearings. J. Tribol. 113(3):590-597. "
    "(DOI not verified here)",
)
references.add(
    "roelands1966",
    "Roelands C.J.A. (1966) Correlational aspects of the viscosity-temperature-pressure relationship "
    "of lubricating oils. PhD thesis, TH Delft.",
)

#: Citation keys used by this module.
REFERENCE_KEYS = ("liu2022", "aihara1987", "harris1966", "zhou1991", "roelands1966", "bair1979")

# --- Eq. (7): EHL rolling resistance -----------------------------------------------------------
#: Coefficient C of eq. (7) by reading (documented names). ``"aihara1987"``: 0.88 × 10² (Aihara's
#: 176 per half length, see module docstring; the value of :data:`friction_components.AIHARA_COEFF`).
#: ``"liu2022_literal"``: 0.88 × 10⁻², the seed text with a lost minus sign (kept for comparison only).
ROLLING_COEFFICIENTS = {"aihara1987": float(fc.AIHARA_COEFF), "liu2022_literal": 0.88e-2}
#: Exponents of eq. (7) (Aihara 1987, isothermal; valid for mineral oils, W = Q/(E′ R l) ~ 1e-5…1e-3).
ROLLING_GU_EXP = fc.AIHARA_GU_EXP  # [-] 0.658
ROLLING_W_EXP = fc.AIHARA_W_EXP  # [-] 0.31

# --- Eq. (8): sliding traction -------------------------------------------------------------------
#: Constant and exponents of eq. (8) (Harris 1966 as used by Liu et al. 2022). They define the film
#: h* = R U^0.74 G^0.4 W^−0.2 / 0.168 of a Newtonian shear integral; valid U ~ 1e-12…1e-9,
#: G ~ 2000…6000, W ~ 1e-5…1e-3 (line-contact load per length, W = Q/(E′ R l)).
SLIDING_COEFF = 0.168  # [-]
SLIDING_U_EXP = -0.74  # [-]
SLIDING_G_EXP = -0.4  # [-]
SLIDING_W_EXP = 0.2  # [-]
#: Readings of eq. (8) (documented names): ``"limiting_shear"`` (default) caps the Newtonian shear of
#: eq. (8) by the Bair–Winer limiting shear stress τ_L = Λ_L p; ``"newtonian"`` is eq. (8) as printed.
SLIDING_MODELS = ("limiting_shear", "newtonian", "newtonian_mpa")
#: Pressure unit factor of the ``"newtonian_mpa"`` reading: p in MPa inserted into Roelands' per-Pa
#: constant 5.1e-9 (a unit slip the flattened eq. 10 admits; diagnostic only, it drops piezoviscosity).
MPA_READING_SCALE = 1e-6  # [MPa/Pa]


def rolling_friction_force(
    load,
    viscosity,
    entrainment_speed,
    pressure_viscosity,
    e_reduced,
    radius_x,
    effective_length,
    model="aihara1987",
):
    """EHL rolling resistance of one roller–raceway line contact (seed 001 eq. 7) [N].

    Parameters
    ----------
    load : array_like
        Contact load Q [N], ``>= 0`` (0 gives 0).
    viscosity : array_like
        η₀ [Pa·s].
    entrainment_speed : array_like
        Mean rolling speed u = (u_roller + u_race)/2 [m/s], ``>= 0``.
    pressure_viscosity : array_like
        Barus α [1/Pa].
    e_reduced : array_like
        E′ [Pa].
    radius_x : array_like
        Equivalent radius R in the rolling direction [m].
    effective_length : array_like
        Contact length l [m].
    model : str
        Coefficient reading, :data:`ROLLING_COEFFICIENTS` (default ``"aihara1987"``, C = 88).

    Returns
    -------
    ndarray
        F_ro [N].

    Notes
    -----
    .. math::

        F_{ro} = C\\,\\frac{1}{\\alpha}\\,(G U)^{0.658}\\,W^{0.31}\\,R\\,l,\\quad
        U = \\frac{\\eta_0 u}{E' R},\\ G = \\alpha E',\\ W = \\frac{Q}{E' R l}

    References
    ----------
    Aihara S. (1987) J. Tribol. 109(3):471-477; Liu et al. (2022) eq. (7).
    """
    checks.one_of("rolling_model", model, ROLLING_COEFFICIENTS)
    checks.non_negative("load", load, "N")
    checks.positive("viscosity", viscosity, "Pa*s")
    checks.non_negative("entrainment_speed", entrainment_speed, "m/s")
    checks.positive("pressure_viscosity", pressure_viscosity, "1/Pa")
    checks.positive("e_reduced", e_reduced, "Pa")
    checks.positive("radius_x", radius_x, "m")
    checks.positive("effective_length", effective_length, "m")
    e, r, ln, a = _arr(e_reduced), _arr(radius_x), _arr(effective_length), _arr(pressure_viscosity)
    u_dim = _arr(viscosity) * _arr(entrainment_speed) / (e * r)
    w_dim = _arr(load) / (e * r * ln)
    c = ROLLING_COEFFICIENTS[model]
    return c / a * (a * e * u_dim) ** ROLLING_GU_EXP * w_dim**ROLLING_W_EXP * r * ln


def sliding_film_thickness(
    viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, load, length
):
    """Film thickness implied by eq. (8): h* = R U^0.74 G^0.4 W^−0.2 / 0.168 [m].

    Parameters
    ----------
    viscosity : array_like
        η₀ [Pa·s].
    entrainment_speed : array_like
        u [m/s], ``> 0``.
    pressure_viscosity : array_like
        α [1/Pa].
    e_reduced : array_like
        E′ [Pa].
    radius_x : array_like
        R [m].
    load : array_like
        Q [N], ``> 0``.
    length : array_like
        l [m].

    Returns
    -------
    ndarray
        h* [m].

    Notes
    -----
    .. math:: h^* = \\frac{R\\,U^{0.74} G^{0.4} W^{-0.2}}{0.168}

    so that eq. (8) reads F_rs = v_s η₀ l I / h* (Newtonian shear over the strip). Harris (1966).
    """
    checks.positive("entrainment_speed", entrainment_speed, "m/s")
    checks.positive("load", load, "N")
    u_dim, g_dim, w_dim = _groups(
        viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, load, length
    )
    return (
        _arr(radius_x) / SLIDING_COEFF * u_dim**-SLIDING_U_EXP * g_dim**-SLIDING_G_EXP * w_dim**-SLIDING_W_EXP
    )


def _groups(viscosity, speed, alpha, e_reduced, radius_x, load, length):
    checks.positive("viscosity", viscosity, "Pa*s")
    checks.non_negative("entrainment_speed", speed, "m/s")
    checks.positive("pressure_viscosity", alpha, "1/Pa")
    checks.positive("e_reduced", e_reduced, "Pa")
    checks.positive("radius_x", radius_x, "m")
    checks.non_negative("load", load, "N")
    checks.positive("effective_length", length, "m")
    e, r = _arr(e_reduced), _arr(radius_x)
    return _arr(viscosity) * _arr(speed) / (e * r), _arr(alpha) * e, _arr(load) / (e * r * _arr(length))


def sliding_friction_force(
    slide_speed,
    load,
    viscosity,
    entrainment_speed,
    pressure_viscosity,
    e_reduced,
    radius_x,
    effective_length,
    exponent=ROELANDS_EXPONENT_LIU2022,
    model="limiting_shear",
    limiting_shear_coeff=SLIDING_LIMITING_SHEAR_COEFF,
):
    """Sliding traction of one roller–raceway line contact (seed 001 eqs. 8, 10) [N].

    Parameters
    ----------
    slide_speed : array_like
        Sliding speed v_s [m/s] (signed; the force carries its sign).
    load : array_like
        Contact load Q [N], ``>= 0`` (0 gives 0).
    viscosity : array_like
        η₀ [Pa·s].
    entrainment_speed : array_like
        u [m/s], ``>= 0`` (u = 0 with v_s = 0 gives 0; u = 0 with v_s ≠ 0 is an error: no film).
    pressure_viscosity : array_like
        α [1/Pa] (material parameter G = α E′).
    e_reduced : array_like
        E′ [Pa].
    radius_x : array_like
        R [m].
    effective_length : array_like
        l [m].
    exponent : array_like
        Roelands index Z of the tractive integral [-].
    model : str
        Reading of eq. (8), :data:`SLIDING_MODELS`: ``"limiting_shear"`` (default), ``"newtonian"`` (as
        printed) or ``"newtonian_mpa"`` (diagnostic: p in MPa inside Roelands' per-Pa constant).
    limiting_shear_coeff : array_like
        Λ_L = τ_L/p of the ``"limiting_shear"`` reading [-] (default
        :data:`SLIDING_LIMITING_SHEAR_COEFF`).

    Returns
    -------
    ndarray
        F_rs [N].

    Notes
    -----
    ``"newtonian"`` (eq. 8 as printed, Newtonian shear across the film h*):

    .. math::

        F_{rs} = 0.168\\,\\frac{v_s\\,\\eta_0\\,l\\,I}{R}\\,U^{-0.74} G^{-0.4} W^{0.2}
               = \\frac{v_s\\,\\eta_0\\,l\\,I}{h^*},
        \\quad I = \\int_0^b \\eta(p)/\\eta_0\\,dx

    with the Hertz strip b = √(8QR/(πlE′)), p_max = √(QE′/(2πlR)). ``"limiting_shear"``: the same
    Newtonian stress τ_N = η(p)|v_s|/(2h*) over the whole strip (−b … b), capped by the Bair–Winer
    limiting shear stress (:func:`limited_shear_integral`):

    .. math::

        F_{rs} = \\operatorname{sgn}(v_s)\\,l\\int_{-b}^{b}\\tau_L
                 \\left[1 - e^{-\\tau_N/\\tau_L}\\right]dx,\\quad \\tau_L = \\Lambda_L\\,p

    — equal to the ``"newtonian"`` value where τ_N ≪ τ_L, and at most Λ_L Q.

    References
    ----------
    Harris (1966) ASLE Trans. 9:229; Zhou & Hoeprich (1991); Bair & Winer (1979) J. Lubr. Technol.
    101:258; Liu et al. (2022) eqs. (8), (10).
    """
    from bearingkit.physics.contact.line import line_contact

    checks.one_of("sliding_model", model, SLIDING_MODELS)
    checks.finite("slide_speed", slide_speed, "m/s")
    u_dim, g_dim, w_dim = _groups(
        viscosity, entrainment_speed, pressure_viscosity, e_reduced, radius_x, load, effective_length
    )
    vs = _arr(slide_speed)
    if np.any((u_dim == 0) & (vs != 0) & (w_dim > 0)):
        raise InputError(
            "entrainment_speed (0 m/s) must be positive where slide_speed is not zero (eq. 8 has no film)"
        )
    if not np.any(vs):  # no sliding anywhere (e.g. the cup under outer-raceway control)
        return np.zeros(np.broadcast_shapes(vs.shape, u_dim.shape, w_dim.shape))
    contact = line_contact(load, effective_length, radius_x, e_reduced)
    on = (u_dim > 0) & (w_dim > 0)
    u_safe = np.where(on, u_dim, 1.0)
    factor = u_safe**SLIDING_U_EXP * g_dim**SLIDING_G_EXP * np.where(on, w_dim, 1.0) ** SLIDING_W_EXP
    if model in ("newtonian", "newtonian_mpa"):
        scale = MPA_READING_SCALE if model == "newtonian_mpa" else 1.0
        integral = tractive_integral(scale * contact.max_pressure, contact.half_width, viscosity, exponent)
        force = (
            SLIDING_COEFF * vs * _arr(viscosity) * _arr(effective_length) * integral / _arr(radius_x) * factor
        )
        return np.where(on, force, 0.0)
    # 1/h* = 0.168 U^-0.74 G^-0.4 W^0.2 / R; the whole strip shears across 2h* (module docstring).
    shear_rate = np.abs(vs) * SLIDING_COEFF * factor / (2.0 * _arr(radius_x))
    per_length = limited_shear_integral(
        contact.max_pressure, contact.half_width, viscosity, shear_rate, exponent, limiting_shear_coeff
    )
    return np.where(on, np.sign(vs) * _arr(effective_length) * per_length, 0.0)


class TRBKinematics(NamedTuple):
    """Speeds of a tapered roller under outer-raceway control (SI; relative to the cage)."""

    cage_speed: np.ndarray  #: ω_c [rad/s]
    roller_speed: np.ndarray  #: ω_r, roller spin about its axis [rad/s]
    entrainment_inner: np.ndarray  #: u_i [m/s]
    entrainment_outer: np.ndarray  #: u_e [m/s]
    entrainment_flange: np.ndarray  #: u_f at the rib contact [m/s]
    slide_inner: np.ndarray  #: v_si = cone − roller surface speed [m/s]
    slide_outer: np.ndarray  #: v_se [m/s] (0: outer-raceway control)
    slide_flange: np.ndarray  #: v_sf = rib − roller end speed [m/s]


def outer_control_kinematics(
    speed_inner, cage_slip, radius_inner, radius_outer, roller_radius, radius_flange, flange_roller_radius
) -> TRBKinematics:
    """Cage, roller, rolling and sliding speeds with outer-raceway control (seed 001 eq. 13).

    Parameters
    ----------
    speed_inner : array_like
        Inner-ring (cone) speed ω_i [rad/s], ``>= 0``; the cup is fixed.
    cage_slip : array_like
        Cage slip rate S_c [-] in [0, 1): ω_c = (1 − S_c) ω_c0.
    radius_inner, radius_outer : array_like
        Radii R_i, R_e of the cone and cup contacts at mid-length [m].
    roller_radius : array_like
        Roller radius at mid-length r_m [m] (distance of both contact lines from the roller axis).
    radius_flange : array_like
        Radius of the rib contact point R_f [m].
    flange_roller_radius : array_like
        Distance ρ_f of the rib contact point from the roller axis [m] (cone side).

    Returns
    -------
    TRBKinematics

    Notes
    -----
    In the cage frame the cone moves at (ω_i − ω_c)R_i, the cup at ω_c R_e, the roller surface at
    ω_r r_m on both lines. Pure rolling on both gives ω_c0 = ω_i R_i/(R_i + R_e). Outer control keeps
    the cup contact rolling (ω_r r_m = ω_c R_e, v_se = 0) while the cage lags by S_c:

    .. math::

        \\omega_c = (1 - S_c)\\,\\frac{\\omega_i R_i}{R_i + R_e},\\quad
        v_{si} = (\\omega_i - \\omega_c)R_i - \\omega_c R_e = \\omega_i R_i S_c,\\quad
        u_e = \\omega_c R_e,\\ u_i = u_e + v_{si}/2,

    and at the rib v_sf = (ω_i − ω_c)R_f − ω_r ρ_f, u_f = [(ω_i − ω_c)R_f + ω_r ρ_f]/2.

    References
    ----------
    Liu et al. (2022) eq. (13); Harris & Kotzalas (2007) ch. 7 (outer-raceway control).
    """
    checks.non_negative("speed_inner", speed_inner, "rad/s")
    checks.in_range("cage_slip", cage_slip, 0.0, 1.0)
    if np.any(_arr(cage_slip) >= 1.0):
        raise InputError(f"cage_slip ({float(np.max(cage_slip)):.6g}) must be below 1")
    for name, v in (
        ("radius_inner", radius_inner),
        ("radius_outer", radius_outer),
        ("roller_radius", roller_radius),
        ("radius_flange", radius_flange),
    ):
        checks.positive(name, v, "m")
    checks.non_negative("flange_roller_radius", flange_roller_radius, "m")
    w_i, s = _arr(speed_inner), _arr(cage_slip)
    r_i, r_e = _arr(radius_inner), _arr(radius_outer)
    w_c = (1.0 - s) * w_i * r_i / (r_i + r_e)
    u_e = w_c * r_e
    w_r = u_e / _arr(roller_radius)
    v_i = (w_i - w_c) * r_i - u_e
    rib = (w_i - w_c) * _arr(radius_flange)
    end = w_r * _arr(flange_roller_radius)
    out = np.broadcast_arrays(w_c, w_r, u_e + 0.5 * v_i, u_e, 0.5 * (rib + end), v_i, 0.0 * u_e, rib - end)
    return TRBKinematics(*(np.array(a) for a in out))


def ring_torques(
    rolling_outer, sliding_outer, rolling_inner, sliding_inner, flange, radius_outer, radius_inner, flange_arm
):
    """Friction torques on the outer and inner ring (seed 001 eqs. 11–12) [N·m].

    Parameters
    ----------
    rolling_outer, sliding_outer : array_like (…, Z)
        F_ro,e and F_rs,e per roller [N].
    rolling_inner, sliding_inner : array_like (…, Z)
        F_ro,i and F_rs,i per roller [N].
    flange : array_like (…, Z)
        F_fs per roller [N].
    radius_outer, radius_inner : array_like
        R_e, R_i [m].
    flange_arm : array_like
        Moment arm of the rib friction [m] (seed: R_i + e_r).

    Returns
    -------
    (M_er, M_ir) : tuple of ndarray (…)
        Torques summed over the rollers (last axis) [N·m].

    Notes
    -----
    .. math::

        M_{er} = \\sum_j (F_{ro,ej} - F_{rs,ej})\\,R_e,\\qquad
        M_{ir} = \\sum_j (F_{ro,ij} + F_{rs,ij})\\,R_i + F_{fs,j}\\,(R_i + e_r)

    (the operator in eq. 11 is lost in the text; read as the minus sign the extraction drops. Under
    outer-raceway control F_rs,e = 0 and the reading does not matter.)

    Liu et al. (2022) eqs. (11)–(12), doi:10.3390/lubricants10070154.
    """
    m_e = ((_arr(rolling_outer) - _arr(sliding_outer)) * _arr(radius_outer)).sum(-1)
    m_i = (
        (_arr(rolling_inner) + _arr(sliding_inner)) * _arr(radius_inner) + _arr(flange) * _arr(flange_arm)
    ).sum(-1)
    return m_e, m_i


__all__ = [
    "REFERENCE_KEYS",
    "ROLLING_COEFFICIENTS",
    "SLIDING_LIMITING_SHEAR_COEFF",
    "SLIDING_MODELS",
    "TRBKinematics",
    "limited_shear_integral",
    "outer_control_kinematics",
    "ring_torques",
    "roelands_exponent",
    "roelands_viscosity_ratio",
    "rolling_friction_force",
    "sliding_film_thickness",
    "sliding_friction_force",
    "tractive_integral",
]
