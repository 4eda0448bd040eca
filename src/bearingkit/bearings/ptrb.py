"""Planetary thread roller bearing (PTRB): the seed-004 prototype and a one-call evaluation.

SI units inside; result keys carry their unit. ``ptrb_prototype()`` is Table 1 of Zheng et al. (2022)
with flat ring flanks (r_I = r_O = inf: Table 1 leaves them blank; flat flanks reproduce the paper's
C_r to 0.02 %). ``evaluate_ptrb`` computes the contact pairs, ratings C0a, C0r, Ca, Cr and the tooth
root checks at the static axial rating.

References: ``zheng2022``, ``zheng2021``, ``zheng2020``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit.analysis.solver.model import BearingModel
from bearingkit.errors import InputError
from bearingkit.physics.life import ptrb_rating as pr
from bearingkit.physics.structure import ptrb_strength as ps
from bearingkit.rows.threaded.distribution import axial_tooth_distribution
from bearingkit.rows.threaded.geometry import PTRBGeometry, contact_pairs
from bearingkit.rows.threaded.row import ThreadedRow

__all__ = [
    "DISTRIBUTION_SOURCES",
    "PTRBRatings",
    "design_f_amax",
    "evaluate_ptrb",
    "identify_body_compliance_factor",
    "ptrb_model",
    "ptrb_prototype",
    "ptrb_ratings",
]

REFERENCE_KEYS = ("zheng2022", "zheng2021", "zheng2020", "iso76", "iso281")
MM = 1.0e-3
#: Where f_amax and f_rmax come from: ``"design"`` (default: f_amax of the design from the tooth
#: load-sharing model with the identified core compliance, f_rmax calibrated), ``"calibrated"`` (both
#: the prototype's constants) or ``"model"`` (the bare physical models, nothing identified).
DISTRIBUTION_SOURCES = ("design", "calibrated", "model")


def ptrb_prototype(**changes) -> PTRBGeometry:
    """The PTRB prototype of Zheng et al. (2022), Table 1 (fields may be overridden by keyword)."""
    base = dict(
        pitch_diameter=42.5 * MM,
        roller_pitch_diameter=6.0 * MM,
        roller_contact_radius=5.1 * MM,
        n_elements=11,
        n_teeth=10,
        contact_angle=np.radians(45.0),
        thread_pitch=1.2 * MM,
        dedendum=0.24 * MM,
        ridge_thickness=0.6 * MM,
        bottom_thickness_roller=1.05 * MM,
        bottom_thickness_inner=1.08 * MM,
        bottom_thickness_outer=1.08 * MM,
        bore_diameter=30.0 * MM,
        outside_diameter=55.0 * MM,
        width=18.0 * MM,
        inner_pitch_diameter=36.5 * MM,
        outer_pitch_diameter=48.5 * MM,
        youngs_modulus=212.0e9,
        poisson_ratio=0.29,
    )
    base.update(changes)
    return PTRBGeometry(**base)


def ptrb_model(
    geometry: PTRBGeometry | None = None, clearance: float = 0.0, name: str = "PTRB"
) -> BearingModel:
    """A :class:`BearingModel` with one :class:`ThreadedRow` (for the quasi-static engine)."""
    geometry = geometry or ptrb_prototype()
    row = ThreadedRow(geometry, clearance=clearance, name="threaded")
    return BearingModel((row,), name=name, references=REFERENCE_KEYS, metadata={"seed": "004"})


@dataclass(frozen=True)
class PTRBRatings:
    """Ratings and strength of a PTRB (SI)."""

    static_axial: float
    static_radial: float
    dynamic_axial: float
    dynamic_radial: float
    thread_axial: float
    thread_radial: float
    contact_load_limit: float
    f_amax: float
    f_rmax: float
    fc_axial: float
    fc_radial: float
    bending_stress: dict
    shear_stress: dict
    distribution: str
    references: tuple = field(default=REFERENCE_KEYS)

    @property
    def strength_ok(self) -> bool:
        """All root stresses at C0a within [σ_b] and [τ_c]."""
        return all(v <= ps.ALLOWED_BENDING_STRESS for v in self.bending_stress.values()) and all(
            v <= ps.ALLOWED_SHEAR_STRESS for v in self.shear_stress.values()
        )

    def to_dict(self) -> dict:
        """JSON-ready, units in the keys."""
        out = {
            "C0a_N": self.static_axial,
            "C0r_N": self.static_radial,
            "Ca_N": self.dynamic_axial,
            "Cr_N": self.dynamic_radial,
            "C_Da_N": self.thread_axial,
            "C_Dr_N": self.thread_radial,
            "contact_load_limit_N": self.contact_load_limit,
            "f_amax": self.f_amax,
            "f_rmax": self.f_rmax,
            "f_ca": self.fc_axial,
            "f_cr": self.fc_radial,
            "distribution": self.distribution,
            "strength_ok": self.strength_ok,
            "references": list(self.references),
        }
        out.update({f"root_bending_stress_{k}_Pa": v for k, v in self.bending_stress.items()})
        out.update({f"root_shear_stress_{k}_Pa": v for k, v in self.shear_stress.items()})
        return out


def design_f_amax(geometry: PTRBGeometry, load=None, body_compliance_factor=None) -> float:
    """f_amax [1] of ``geometry``: the tooth load-sharing model of ``physics.life.ptrb_load_sharing``.

    Parameters
    ----------
    geometry : PTRBGeometry
    load : float or None [N]
        Bearing axial load; None = :data:`~bearingkit.physics.life.ptrb_rating.F_AMAX_REFERENCE_LOAD`.
    body_compliance_factor : float or None [1]
        None = the identified :data:`~bearingkit.physics.life.ptrb_rating.BODY_COMPLIANCE_FACTOR`.
    """
    from bearingkit.physics.life import ptrb_load_sharing as pls

    g = geometry
    return float(
        pls.design_f_amax(
            pr.F_AMAX_REFERENCE_LOAD if load is None else load,
            n_elements=g.n_elements,
            n_teeth=g.n_teeth,
            contact_angle=g.contact_angle,
            roller_pitch_diameter=g.roller_pitch_diameter,
            inner_pitch_diameter=g.d_inner,
            outer_pitch_diameter=g.d_outer,
            roller_contact_radius=g.roller_contact_radius,
            contact_radius_inner=g.contact_radius_inner,
            contact_radius_outer=g.contact_radius_outer,
            thread_pitch=g.thread_pitch,
            dedendum=g.dedendum,
            bottom_thickness_roller=g.bottom_thickness_roller,
            bottom_thickness_inner=g.bottom_thickness_inner,
            bottom_thickness_outer=g.bottom_thickness_outer,
            bore_diameter=g.bore_diameter,
            outside_diameter=g.outside_diameter,
            youngs_modulus=g.youngs_modulus,
            poisson_ratio=g.poisson_ratio,
            body_compliance_factor=(
                pr.BODY_COMPLIANCE_FACTOR if body_compliance_factor is None else body_compliance_factor
            ),
        )[0]
    )


def identify_body_compliance_factor() -> float:
    """The core-compliance factor [1] whose f_amax meets the prototype's C0a = 38.36 kN — the calibration."""
    from scipy.optimize import brentq

    g = ptrb_prototype()
    return float(
        brentq(
            lambda k: design_f_amax(g, body_compliance_factor=k) - pr.F_AMAX_CALIBRATED, 0.05, 2.0, xtol=1e-9
        )
    )


def ptrb_ratings(
    geometry: PTRBGeometry, distribution: str = "design", tooth_model: str = "paper", azimuth_phase=None
) -> PTRBRatings:
    """C0a, C0r, Ca, Cr and the tooth-root checks of a PTRB.

    Parameters
    ----------
    geometry : PTRBGeometry
    distribution : {"design", "calibrated", "model"}
        ``"design"``: f_amax of this design (:func:`design_f_amax`, the load-sharing model with the
        identified core compliance at 20 kN), f_rmax calibrated; ``"calibrated"``: both from
        :func:`bearingkit.physics.life.ptrb_rating.calibrated_distribution_coefficients` (the prototype's);
        ``"model"``: the physical models with nothing identified (axial:
        :func:`~bearingkit.rows.threaded.distribution.axial_tooth_distribution` evaluated
        self-consistently at C0a; radial: Stribeck sum with roller 0 under the load, or at
        ``azimuth_phase``).
    tooth_model : str
        Key of :data:`bearingkit.physics.structure.ptrb_strength.CONTACTS_PER_TOOTH`.
    azimuth_phase : float or None
        Roller phase for the radial model [rad] (None: 0, the worst case).
    """
    from bearingkit.rows.threaded.distribution import radial_roller_distribution

    if distribution not in DISTRIBUTION_SOURCES:
        raise InputError(f"distribution ({distribution!r}) must be one of {', '.join(DISTRIBUTION_SOURCES)}")
    g = geometry
    pairs = contact_pairs(g)
    q0 = float(
        min(
            pr.static_contact_load(p.curvature_sum, p.curvature_difference, g.e_reduced)
            for p in pairs.values()
        )
    )
    if distribution in ("calibrated", "design"):
        f_amax, f_rmax = (float(v) for v in pr.calibrated_distribution_coefficients(g.n_elements))
        if distribution == "design":
            f_amax = design_f_amax(g)
    else:
        f_amax = 1.0
        for _ in range(20):  # fixed point: f_amax evaluated at the load C0a it implies
            c0a = float(pr.static_rating_axial(q0, g.n_elements, g.n_teeth, g.contact_angle, f_amax))
            new = float(axial_tooth_distribution(g, c0a).fa_max[0])
            if abs(new - f_amax) < 1e-9:
                break
            f_amax = new
        f_rmax = float(radial_roller_distribution(g.n_elements, azimuth_phase or 0.0)[1][0])
    c0a = float(pr.static_rating_axial(q0, g.n_elements, g.n_teeth, g.contact_angle, f_amax))
    c0r = float(pr.static_rating_radial(q0, g.n_teeth, g.contact_angle, f_rmax))
    args = (
        g.gamma,
        g.contact_angle,
        g.roller_contact_radius,
        g.contact_radius_inner,
        g.roller_pitch_diameter,
    )
    fca, fcr = float(pr.fc_axial(*args)), float(pr.fc_radial(*args))
    cda = float(pr.dynamic_rating_thread(fca, g.element_diameter, g.n_elements, g.contact_angle, axial=True))
    cdr = float(pr.dynamic_rating_thread(fcr, g.element_diameter, g.n_elements, g.contact_angle, axial=False))
    bending, shear = {}, {}
    parts = {
        "roller": (g.roller_pitch_diameter, g.bottom_thickness_roller),
        "inner": (g.d_inner, g.bottom_thickness_inner),
        "outer": (g.d_outer, g.bottom_thickness_outer),
    }
    for part, (d_x, b_x) in parts.items():
        k = ps.contacts_per_tooth(g.n_elements, part, tooth_model)
        bending[part] = float(ps.tooth_root_bending_stress(q0, g.contact_angle, k, g.dedendum, d_x, b_x))
        shear[part] = float(ps.tooth_root_shear_stress(q0, g.contact_angle, k, d_x, b_x))
    return PTRBRatings(
        static_axial=c0a,
        static_radial=c0r,
        dynamic_axial=float(pr.basic_dynamic_axial(cda, g.n_teeth, f_amax)),
        dynamic_radial=float(pr.basic_dynamic_radial(cdr, g.n_teeth)),
        thread_axial=cda,
        thread_radial=cdr,
        contact_load_limit=q0,
        f_amax=f_amax,
        f_rmax=f_rmax,
        fc_axial=fca,
        fc_radial=fcr,
        bending_stress=bending,
        shear_stress=shear,
        distribution=distribution,
    )


def evaluate_ptrb(geometry: PTRBGeometry | None = None, **kwargs) -> PTRBRatings:
    """Everything bearingkit computes for a PTRB at once (currently ratings and strength)."""
    return ptrb_ratings(geometry or ptrb_prototype(), **kwargs)
