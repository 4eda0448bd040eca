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
    "evaluate_ptrb",
    "ptrb_model",
    "ptrb_prototype",
    "ptrb_ratings",
]

REFERENCE_KEYS = ("zheng2022", "zheng2021", "zheng2020", "iso76", "iso281")
MM = 1.0e-3
#: Where f_amax and f_rmax come from: the calibration (default) or the physical distribution models.
DISTRIBUTION_SOURCES = ("calibrated", "model")


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


def ptrb_ratings(
    geometry: PTRBGeometry, distribution: str = "calibrated", tooth_model: str = "paper", azimuth_phase=None
) -> PTRBRatings:
    """C0a, C0r, Ca, Cr and the tooth-root checks of a PTRB.

    Parameters
    ----------
    geometry : PTRBGeometry
    distribution : {"calibrated", "model"}
        f_amax, f_rmax from :func:`bearingkit.physics.life.ptrb_rating.calibrated_distribution_coefficients`
        or from the physical models (axial:
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
    if distribution == "calibrated":
        f_amax, f_rmax = (float(v) for v in pr.calibrated_distribution_coefficients(g.n_elements))
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
