"""The PTRB prototype of Zheng et al. (2022) as a design: rules, traction calibration, §6 objectives.

SI units: N, m, rad, rad/s, N·m. :func:`design_geometry` changes the §5/§6 design variables under the
paper's rules (D_pw and n·P held); :func:`calibrate_contact_traction` recomputes the one calibrated
friction constant from :data:`CALIBRATION_POINT`; :func:`ptrb_objectives` is the friction model of
:mod:`bearingkit.analysis.friction.threaded` with the ratings of :mod:`bearingkit.physics.life.ptrb_rating`
as a pure function of design-variable arrays (the population axis of an optimiser).

Reference: Zheng et al. (2022) Machines 10:1051, doi:10.3390/machines10111051.
"""

from __future__ import annotations

from dataclasses import replace
from functools import cache

import numpy as np

from bearingkit import checks
from bearingkit.analysis.friction.threaded import (
    CASES,
    RPM,
    TEST_TEMPERATURE_C,
    PTRBFrictionParameters,
    _lubricant_props,
    _sum_contacts,
    ptrb_friction,
)
from bearingkit.bearings.ptrb import ptrb_prototype
from bearingkit.physics.contact import hertz
from bearingkit.physics.friction import ptrb as pf
from bearingkit.physics.life import ptrb_load_sharing as pls
from bearingkit.physics.life import ptrb_rating as pr
from bearingkit.rows.threaded.distribution import radial_roller_distribution
from bearingkit.rows.threaded.geometry import PTRBGeometry

__all__ = [
    "CALIBRATION_POINT",
    "PROTOTYPE_PITCH_DIAMETER",
    "PROTOTYPE_THREAD_LENGTH",
    "calibrate_contact_traction",
    "design_geometry",
    "ptrb_objectives",
]

#: The ONE published number the contact traction is calibrated against: Zheng et al. (2022) Table 7,
#: axial simulation, 20 kN, 600 rpm → 0.476 N·m.
CALIBRATION_POINT = {"case": "axial", "load_N": 20.0e3, "speed_rpm": 600.0, "torque_Nm": 0.476}
#: D_pw of the prototype, held in the §5 sweeps and §6 optimisation ("the dimension was unchanged") [m].
PROTOTYPE_PITCH_DIAMETER = 42.5e-3
#: n·P of the prototype, held when n changes (§5 (2): n = 8–16 ↔ P = 1.6–0.8 mm) [m].
PROTOTYPE_THREAD_LENGTH = 12.0e-3


@cache
def _prototype() -> PTRBGeometry:
    """The default prototype, built once (a frozen dataclass: its checks cost ~0.2 ms per build)."""
    return ptrb_prototype()


def calibrate_contact_traction(
    geometry: PTRBGeometry | None = None,
    convention: str | None = None,
    parameters: PTRBFrictionParameters | None = None,
) -> float:
    """Recompute :data:`~bearingkit.physics.friction.ptrb_laws.CONTACT_TRACTION_CALIBRATED` [1].

    The torque is affine in μ_c (spin and differential sliding ∝ μ_c, the rest independent of it), so
    two evaluations at :data:`CALIBRATION_POINT` give the μ_c that reproduces 0.476 N·m exactly.
    ``parameters`` (its ``traction`` ignored) sets the other model choices (default: the default
    reading; ``PTRBFrictionParameters.power_balance()`` recomputes
    :data:`~bearingkit.physics.friction.ptrb_laws.CONTACT_TRACTION_POWER_BALANCE`); ``convention``, if
    given, overrides its convention (with that convention's default viscous projection).
    """
    g = geometry or ptrb_prototype()
    base = parameters or PTRBFrictionParameters()
    if convention is not None:
        base = replace(base, convention=convention, viscous_projection=None)
    p = CALIBRATION_POINT
    args = (g, p["load_N"], p["speed_rpm"] * RPM, p["case"])
    m0 = float(ptrb_friction(*args, parameters=replace(base, traction=0.0)).torque)
    m1 = float(ptrb_friction(*args, parameters=replace(base, traction=1.0)).torque)
    return (p["torque_Nm"] - m0) / (m1 - m0)


def design_geometry(
    contact_angle=None, n_teeth=None, roller_contact_radius=None, roller_pitch_diameter=None, **kw
):
    """The prototype with §5/§6 design variables changed under the paper's rules [SI].

    D_pw is held (d_I = D_pw − d_R, d_O = D_pw + d_R) and n·P is held at 12 mm (P = 12 mm / n).
    Other :class:`PTRBGeometry` fields may be given by keyword (e.g. ``n_elements``).
    """
    changes = dict(kw)
    if contact_angle is not None:
        changes["contact_angle"] = float(contact_angle)
    if roller_contact_radius is not None:
        changes["roller_contact_radius"] = float(roller_contact_radius)
    if roller_pitch_diameter is not None:
        d_r = float(roller_pitch_diameter)
        changes.update(
            roller_pitch_diameter=d_r,
            inner_pitch_diameter=PROTOTYPE_PITCH_DIAMETER - d_r,
            outer_pitch_diameter=PROTOTYPE_PITCH_DIAMETER + d_r,
        )
    if n_teeth is not None:
        n = checks.integer("n_teeth", n_teeth)
        changes.update(n_teeth=n, thread_pitch=PROTOTYPE_THREAD_LENGTH / n)
    return ptrb_prototype(**changes)


def _share_solver(n_designs: int):
    """The tooth load sharing's solver: the compiled one where the solver core runs compiled, else None
    (numpy).

    The solver core's switch (:mod:`bearingkit.analysis.solver.backend`): ``BEARINGKIT_BACKEND=numpy``
    keeps numpy, ``compiled`` asks for the compiled one; ``auto`` takes it where the solver core is
    loaded in this process (a study's chunks load it: one core for every chunk, so results do not depend
    on the chunking) or built (``bearingkit compile`` caches this kernel too) and the population is larger
    than :data:`~bearingkit.analysis.solver.backend.SMALL_JOB_CASES`; it neither loads nor builds the
    solver core itself. The two agree to 1e-10 (tests/rows/test_compiled_sharing.py).
    """
    from bearingkit.analysis.solver import backend
    from bearingkit.rows import numba_cache

    name = backend.requested(None)
    if name == "numpy":
        return None
    if name == "auto":
        built_and_large = n_designs > backend.SMALL_JOB_CASES and numba_cache.is_built()
        if not (backend.loaded() or built_and_large) or not numba_cache.numba_installed():
            return None
    elif backend.compiled_module() is None:  # "compiled" without a usable numba: warned once, numpy answers
        return None
    from bearingkit.rows.threaded import compiled_sharing

    return compiled_sharing.max_tooth_share


def ptrb_objectives(
    alpha,
    n,
    R_rr,
    d_R,
    case: str = "axial",
    load=20.0e3,
    speed=4000.0 * RPM,
    n_elements: int = 11,
    lubricant="L-AN",
    temperature_C: float = TEST_TEMPERATURE_C,
    parameters: PTRBFrictionParameters | None = None,
) -> dict:
    """Objectives of the §6 optimisation for a population of designs (pure, vectorised).

    Parameters
    ----------
    alpha : array_like
        Contact angle α [rad], in (0, π/2), shape (P,).
    n : array_like
        Teeth per roller [1] (rounded to integers), shape (P,).
    R_rr : array_like
        Roller flank radius [m].
    d_R : array_like
        Roller pitch diameter [m].
    case : {"axial", "radial"}
    load : float
        Load of the friction objective [N] (§6: 20 kN).
    speed : float
        ω [rad/s] (§6: 4000 rpm).
    n_elements : int
        Z (§6: the maximum, 11).

    Returns
    -------
    dict of ndarray (P,)
        ``C0`` [N] (C0a or C0r), ``C`` [N] (Ca or Cr), ``M`` [N·m], ``mu`` [1], all four ratings
        ``C0a, Ca, C0r, Cr``, and ``feasible`` (bool: d_R ≤ 2 R_rr cos α, §5 (3)-(4), and the roller
        fits between the pitch circles).

    Notes
    -----
    Same rules as :func:`design_geometry` (D_pw = 42.5 mm, n·P = 12 mm, flat ring flanks, E = 212 GPa,
    ν = 0.29); ratings as :func:`bearingkit.bearings.ptrb.ptrb_ratings` (f_amax of each design from the tooth
    load-sharing model at 20 kN, calibrated f_rmax),
    friction as :func:`ptrb_friction` (uniform tooth shares). Infeasible designs are evaluated anyway
    (flagged, not NaN) as long as the inputs are physical.
    """
    # The contacts' κ, K, E are solved once and reused by the rating, the stiffness of the load sharing
    # and the friction (the same curvatures three times; bit for bit what three solves give).
    with hertz.reusing_integrals():
        return _objectives(
            alpha, n, R_rr, d_R, case, load, speed, n_elements, lubricant, temperature_C, parameters
        )


def _objectives(alpha, n, R_rr, d_R, case, load, speed, n_elements, lubricant, temperature_C, parameters):
    """:func:`ptrb_objectives` (its arguments, in its order)."""
    checks.one_of("case", case, CASES)
    params = parameters or PTRBFrictionParameters()
    base = _prototype()
    alpha, n_f, r_rr, d_r = np.broadcast_arrays(
        *(np.atleast_1d(np.asarray(x, float)) for x in (alpha, n, R_rr, d_R))
    )
    checks.in_range("alpha", alpha, 0.0, np.pi / 2, "rad", closed=False)
    checks.positive("R_rr", r_rr, "m")
    checks.in_range("d_R", d_r, 0.0, PROTOTYPE_PITCH_DIAMETER, "m", closed=False)
    n_t = np.rint(checks.positive("n", n_f))
    z = checks.integer("n_elements", n_elements, low=3)
    e_red = base.e_reduced
    d_i, d_o = PROTOTYPE_PITCH_DIAMETER - d_r, PROTOTYPE_PITCH_DIAMETER + d_r
    inf = np.full_like(d_r, np.inf)
    q0 = np.minimum(
        *(
            pr.static_contact_load(*pr.thread_contact_curvature(d_r, dx, r_rr, inf, alpha, side)[:2], e_red)
            for side, dx in (("inner", d_i), ("outer", d_o))
        )
    )
    _, f_rmax = pr.calibrated_distribution_coefficients(z)
    f_amax = pls.design_f_amax(
        pr.F_AMAX_REFERENCE_LOAD,
        n_elements=z,
        n_teeth=n_t,
        contact_angle=alpha,
        roller_pitch_diameter=d_r,
        inner_pitch_diameter=d_i,
        outer_pitch_diameter=d_o,
        roller_contact_radius=r_rr,
        contact_radius_inner=inf,
        contact_radius_outer=inf,
        thread_pitch=PROTOTYPE_THREAD_LENGTH / n_t,
        dedendum=base.dedendum,
        bottom_thickness_roller=base.bottom_thickness_roller,
        bottom_thickness_inner=base.bottom_thickness_inner,
        bottom_thickness_outer=base.bottom_thickness_outer,
        bore_diameter=base.bore_diameter,
        outside_diameter=base.outside_diameter,
        youngs_modulus=base.youngs_modulus,
        poisson_ratio=base.poisson_ratio,
        body_compliance_factor=pr.BODY_COMPLIANCE_FACTOR,
        solver=_share_solver(d_r.size),
    )
    gamma = d_r / PROTOTYPE_PITCH_DIAMETER
    dw = d_r / np.cos(alpha)
    fca = pr.fc_axial(gamma, alpha, r_rr, inf, d_r)
    fcr = pr.fc_radial(gamma, alpha, r_rr, inf, d_r)
    out = {
        "C0a": pr.static_rating_axial(q0, z, n_t, alpha, f_amax),
        "C0r": pr.static_rating_radial(q0, n_t, alpha, f_rmax),
        "Ca": pr.basic_dynamic_axial(pr.dynamic_rating_thread(fca, dw, z, alpha, axial=True), n_t, f_amax),
        "Cr": pr.basic_dynamic_radial(pr.dynamic_rating_thread(fcr, dw, z, alpha, axial=False), n_t),
    }
    eta, alpha_p = _lubricant_props(lubricant, temperature_C)
    geom = {
        "d_R": d_r,
        "d_I": d_i,
        "d_O": d_o,
        "R_rr": r_rr,
        "r_I": inf,
        "r_O": inf,
        "alpha": alpha,
        "E": e_red,
    }
    geom = {k: np.asarray(v)[:, None] if np.ndim(v) else v for k, v in geom.items()}
    f = float(checks.positive("load", load, "N"))
    if case == "axial":
        q = (f / (z * n_t * np.sin(alpha)))[:, None]
        weights = (z * n_t)[:, None]
    else:
        share = radial_roller_distribution(z)[0].reshape(1, -1)
        q = f * share / (2.0 * n_t * np.cos(alpha))[:, None]
        weights = np.broadcast_to((2.0 * n_t)[:, None], q.shape)
    comps = _sum_contacts(geom, q, q, weights, float(speed), params, eta, alpha_p)
    m_h = pf.carrier_torque(
        z, d_r, d_i, d_o, PROTOTYPE_THREAD_LENGTH, params.carrier_friction, params.journal_ratio
    )
    torque = sum(sum(d.values()) for d in comps.values()) + m_h
    out["M"] = torque
    out["mu"] = pf.friction_coefficient(torque, f, base.bore_diameter)
    out["C0"] = out["C0a"] if case == "axial" else out["C0r"]
    out["C"] = out["Ca"] if case == "axial" else out["Cr"]
    fits = np.pi * PROTOTYPE_PITCH_DIAMETER / z >= d_r
    out["feasible"] = (d_r <= 2.0 * r_rr * np.cos(alpha) * (1 + 1e-12)) & fits
    return out
