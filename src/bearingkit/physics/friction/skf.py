"""The SKF four-component model of the frictional moment of standard rolling bearings.

SI units at the boundary: diameters in m, loads in N, speed in rad/s, kinematic viscosity in m²/s,
moments returned in N·m. Inside, every formula is evaluated in the catalogue's own units — d_m, d, D,
d_s, H, B in **mm**, n in **r/min**, ν in **mm²/s**, loads in **N**, moments in **N·mm** — because the
SKF constants (R1 … S3, K_rs, K_S1 …) are defined in those units; the conversion happens once in
:func:`skf_friction_moment` (``_to_skf_units``) and once on the way out (N·mm → N·m).

Model (SKF Group, Rolling bearings catalogue 10000 EN 2012 / 17000 EN 2018, chapter "Friction"):

.. math::

    M = M_{rr} + M_{sl} + M_{seal} + M_{drag}, \\qquad
    M_{rr} = \\phi_{ish}\\,\\phi_{rs}\\,G_{rr}\\,(\\nu n)^{0.6}, \\qquad M_{sl} = G_{sl}\\,\\mu_{sl}

    \\phi_{ish} = \\frac{1}{1 + 1.84\\cdot10^{-9}(n d_m)^{1.28}\\nu^{0.64}}, \\qquad
    \\phi_{rs} = \\exp\\Big[-K_{rs}\\,\\nu n (d + D)\\sqrt{\\tfrac{K_Z}{2(D - d)}}\\Big]

    \\mu_{sl} = \\phi_{bl}\\mu_{bl} + (1 - \\phi_{bl})\\mu_{EHL}, \\qquad
    \\phi_{bl} = \\exp[-2.6\\cdot10^{-8}(n\\nu)^{1.4} d_m]

G_rr and G_sl per bearing type are in :data:`G_MODELS` (the registry of bearing types; the types SKF does
not cover, e.g. needle roller bearings, are refused with what is missing, :data:`NOT_COVERED`); their
constants per series are data (``data/skf_friction_constants.csv``, K_Z/K_L in ``skf_friction_kz.csv``,
seal constants in ``skf_seal_constants.csv``), each row tagged with how far it was verified.

Drag losses (oil bath). SKF gives the drag loss factor V_M **only as a diagram** (V_M versus H/d_m, one
curve for ball and one for roller bearings). bearingkit does not digitise it: ``drag_loss_factor`` takes
V_M read from the SKF diagram; without it, V_M is approximated from the immersion geometry
(:func:`bearingkit.physics.friction.skf_drag.drag_loss_factor`, stated there with its sources). The
second (viscous) term is fully analytical and always evaluated when an oil level is given.
``oil_level=None`` means a low-level bath, jet, oil–air or grease: no drag term.

Zero speed: M_rr = 0, M_drag = 0, φ_bl = 1 so M_sl = G_sl μ_bl (the load-dependent part), plus the
speed-independent seal moment when seals are fitted (SKF's seal formula has no speed term).
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks, references
from bearingkit.errors import InputError
from bearingkit.physics.friction import skf_drag
from bearingkit.physics.friction.skf_terms import (
    _ROLLER_TYPES,
    _THRUST_TYPES,
    G_MODELS,
    LUBRICATION_METHODS,
    M2S_TO_MM2S,
    M_TO_MM,
    MU_BL,
    NMM_TO_NM,
    NOT_COVERED,
    RAD_S_TO_RPM,
    RR_EXP,
    boundary_weighting,
    drag_moment,
    inlet_shear_factor,
    mu_ehl_default,
    replenishment_factor,
    seal_constants,
    series_constants,
    sliding_coefficient,
)

references.add(
    "skf2018_friction",
    "SKF Group (2018) Rolling bearings, PUB BU/P1 17000 EN, chapter 'Friction': the SKF model for "
    "calculating the frictional moment (M = M_rr + M_sl + M_seal + M_drag); same model in PUB BU/P1 "
    "10000 EN (2012).",
)


# --- the model ------------------------------------------------------------------------------------
def _to_skf_units(bore_diameter, outside_diameter, speed, kinematic_viscosity):
    d = np.asarray(bore_diameter, dtype=float) * M_TO_MM
    big_d = np.asarray(outside_diameter, dtype=float) * M_TO_MM
    n = np.abs(np.asarray(speed, dtype=float)) * RAD_S_TO_RPM
    nu = np.asarray(kinematic_viscosity, dtype=float) * M2S_TO_MM2S
    return d, big_d, 0.5 * (d + big_d), n, nu


def skf_friction_moment(
    bearing_type: str,
    *,
    bore_diameter,
    outside_diameter,
    speed,
    kinematic_viscosity,
    load_radial=0.0,
    load_axial=0.0,
    series: str | None = None,
    lubrication: str = "oil_bath",
    lubricant_base: str = "mineral",
    static_rating=None,
    axial_factor=None,
    mu_bl: float = MU_BL,
    mu_ehl: float | None = None,
    seal: str | None = None,
    seal_counterface_diameter=None,
    n_seals: int = 2,
    oil_level=None,
    drag_loss_factor=None,
    width=None,
    n_rows: int = 1,
) -> dict:
    """Frictional moment of a standard bearing by the SKF four-component model [N·m].

    .. math:: M = \\phi_{ish}\\phi_{rs}G_{rr}(\\nu n)^{0.6} + G_{sl}\\mu_{sl} + M_{seal} + M_{drag}

    (see the module docstring for every factor). Inputs broadcast over a leading case axis.

    Parameters
    ----------
    bearing_type : str
        One of :data:`G_MODELS`.
    bore_diameter, outside_diameter : array_like
        Bearing bore d and outside diameter D [m] (d_m = (d + D)/2).
    speed : array_like
        Rotational speed of the rotating ring relative to the other [rad/s] (sign ignored).
    kinematic_viscosity : array_like
        Operating kinematic viscosity of the oil or of the grease's base oil [m²/s], > 0.
    load_radial, load_axial : array_like
        F_r, F_a [N], ≥ 0 (thrust types: F_r must be 0).
    series : str or None
        Series key of the constants table (None = the type's default row).
    lubrication : str
        ``oil_bath``, ``oil_jet`` (K_rs = 3e-8), ``grease``, ``oil_air`` (K_rs = 6e-8).
    lubricant_base : str
        ``mineral``, ``synthetic``, ``transmission`` or ``grease`` (selects μ_EHL).
    static_rating : array_like or None
        C_0 [N], needed for deep groove ball bearings with F_a > 0 (α_F).
    axial_factor : float or None
        Y [-] of the product tables, needed for tapered roller bearings with F_a > 0.
    mu_bl : float
        Boundary friction coefficient μ_bl [-] (SKF ≈ 0.15).
    mu_ehl : float or None
        Full-film coefficient μ_EHL [-]; None = SKF's value for the type and lubricant.
    seal : str or None
        SKF seal designation (``data/skf_seal_constants.csv``); None = open bearing.
    seal_counterface_diameter : array_like or None
        Seal counterface diameter d_s [m] (product tables), required with ``seal``.
    n_seals : int
        0, 1 or 2 seals (the table gives two; one seal = half).
    oil_level : array_like or None
        Oil bath level H [m] (None = no drag term).
    drag_loss_factor : array_like or None
        V_M [-] read from the SKF diagram; None = approximated
        (:func:`bearingkit.physics.friction.skf_drag.drag_loss_factor`).
    width : array_like or None
        Bearing width B [m] (roller drag).
    n_rows : int
        Rows of balls (ball drag).

    Returns
    -------
    dict
        ``rolling_Nm``, ``sliding_Nm``, ``seal_Nm``, ``drag_Nm``, ``total_Nm`` [N·m] and the factors
        ``phi_ish``, ``phi_rs``, ``phi_bl``, ``mu_sl`` [-], ``G_rr`` [N·mm/(mm²/s·r/min)^0.6], ``G_sl``
        [N·mm], all broadcast to the case shape.

    References
    ----------
    SKF Group (2018) Rolling bearings, PUB BU/P1 17000 EN, chapter "Friction" (SKF 2012, 10000 EN, same
    model); G_rr/G_sl forms: Tables 2a/2b.
    """
    if bearing_type in NOT_COVERED:
        raise InputError(f"bearing_type ({bearing_type!r}): SKF model refused: {NOT_COVERED[bearing_type]}")
    checks.one_of("bearing_type", bearing_type, G_MODELS)
    checks.one_of("lubrication", lubrication, LUBRICATION_METHODS)
    checks.positive("bore_diameter", bore_diameter, "m")
    checks.greater("outside_diameter", outside_diameter, "bore_diameter", bore_diameter, "m")
    checks.finite("speed", speed, "rad/s")
    checks.positive("kinematic_viscosity", kinematic_viscosity, "m^2/s")
    checks.non_negative("load_radial", load_radial, "N")
    checks.non_negative("load_axial", load_axial, "N")
    checks.in_range("mu_bl", mu_bl, 0.0, 1.0)
    if bearing_type in _THRUST_TYPES and np.any(np.asarray(load_radial) > 0):
        raise InputError(
            f"load_radial ({float(np.max(load_radial)):.6g} N) must be 0 for {bearing_type} (SKF: F_a only)"
        )
    c = series_constants(bearing_type, series)
    d, big_d, dm, n, nu = _to_skf_units(bore_diameter, outside_diameter, speed, kinematic_viscosity)
    fr = np.asarray(load_radial, dtype=float)
    fa = np.asarray(load_axial, dtype=float)
    d, big_d, dm, n, nu, fr, fa = np.broadcast_arrays(d, big_d, dm, n, nu, fr, fa)
    extra = {"static_rating_N": static_rating, "axial_factor": axial_factor, "nu_mm2s": nu}
    g_rr, g_sl = G_MODELS[bearing_type](c, dm, fr, fa, n, extra)
    phi_ish = inlet_shear_factor(n, dm, nu)
    phi_rs = replenishment_factor(n, nu, d, big_d, c["K_Z"], LUBRICATION_METHODS[lubrication])
    m_rr = phi_ish * phi_rs * g_rr * (nu * n) ** RR_EXP
    if mu_ehl is None:
        mu_ehl = mu_ehl_default(bearing_type, lubricant_base)
    checks.in_range("mu_ehl", mu_ehl, 0.0, 1.0)
    phi_bl = boundary_weighting(n, nu, dm)
    mu_sl = sliding_coefficient(phi_bl, mu_ehl, mu_bl)
    m_sl = g_sl * mu_sl
    m_seal = np.zeros_like(m_rr)
    n_seals = checks.integer("n_seals", n_seals, low=0)
    if seal is not None and n_seals > 0:
        if n_seals > 2:
            raise InputError(f"n_seals ({n_seals}) must be 0, 1 or 2")
        if seal_counterface_diameter is None:
            raise InputError(f"seal_counterface_diameter (None m) must be given with seal {seal!r}")
        checks.positive("seal_counterface_diameter", seal_counterface_diameter, "m")
        if np.ndim(outside_diameter) > 0 and np.ptp(np.asarray(outside_diameter)) > 0:
            raise InputError(
                "outside_diameter must be one value when a seal is given (the seal table is per size)"
            )
        beta, ks1, ks2 = seal_constants(bearing_type, seal, float(np.max(big_d)))
        ds = np.asarray(seal_counterface_diameter, dtype=float) * M_TO_MM
        m_seal = m_seal + 0.5 * n_seals * (ks1 * ds**beta + ks2)
    m_drag = np.zeros_like(m_rr)
    if oil_level is not None:
        checks.non_negative("oil_level", oil_level, "m")
        if lubrication != "oil_bath":
            raise InputError(
                f"oil_level ({oil_level!r} m) applies to lubrication 'oil_bath', not {lubrication!r}"
            )
        roller = bearing_type in _ROLLER_TYPES
        if drag_loss_factor is None:
            d_m = 0.5 * (np.asarray(bore_diameter, float) + np.asarray(outside_diameter, float))
            drag_loss_factor = skf_drag.drag_loss_factor(oil_level, d_m, roller)
        b_mm = (
            None if width is None else np.asarray(checks.positive("width", width, "m"), dtype=float) * M_TO_MM
        )
        m_drag = drag_moment(
            n,
            nu,
            dm,
            d,
            big_d,
            np.asarray(oil_level, dtype=float) * M_TO_MM,
            c["K_Z"],
            roller=roller,
            k_l=c["K_L"],
            width_mm=b_mm,
            n_rows=checks.integer("n_rows", n_rows),
            drag_loss_factor=drag_loss_factor,
        )
    total = m_rr + m_sl + m_seal + m_drag
    return {
        "rolling_Nm": m_rr * NMM_TO_NM,
        "sliding_Nm": m_sl * NMM_TO_NM,
        "seal_Nm": np.broadcast_to(m_seal * NMM_TO_NM, total.shape).copy(),
        "drag_Nm": np.broadcast_to(m_drag * NMM_TO_NM, total.shape).copy(),
        "total_Nm": total * NMM_TO_NM,
        "phi_ish": phi_ish,
        "phi_rs": phi_rs,
        "phi_bl": phi_bl,
        "mu_sl": np.broadcast_to(mu_sl, total.shape).copy(),
        "G_rr": g_rr,
        "G_sl": g_sl,
    }


#: Citation keys of this module.
REFERENCE_KEYS = ("skf2018_friction", "skf_friction")

__all__ = [
    "G_MODELS",
    "LUBRICATION_METHODS",
    "NOT_COVERED",
    "boundary_weighting",
    "drag_moment",
    "inlet_shear_factor",
    "mu_ehl_default",
    "replenishment_factor",
    "seal_constants",
    "series_constants",
    "skf_friction_moment",
    "sliding_coefficient",
]
