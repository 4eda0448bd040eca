"""Readings of the seed-000 friction model (VARIANTS): what the paper leaves open, kept apart from studies."""

from __future__ import annotations

from dataclasses import dataclass

from bearingkit import checks
from bearingkit.analysis.friction.kinematics import RACEWAY_CONTROLS
from bearingkit.papers.tian2025 import calibration as cal
from bearingkit.physics.contact.profiles import SEED000_CROWNING
from bearingkit.physics.friction.components import VISCOUS_LINE_MODELS, VISCOUS_POINT_MODELS

#: Spin-coefficient readings of Tian's M4 = (3/8) f_s E(e) a Q sin α0 (see
#: :func:`bearingkit.papers.tian2025.friction._friction`).
SPIN_READINGS = ("mixed", "boundary", "ehl")
#: Readings of the traction coefficient μ_ij of E2 (differential sliding of the axial rollers), name →
#: (μ_bl, μ_EHL) of the Λ-interpolation (None: the operating point's, SKF μ_bl 0.12 / cylindrical-roller
#: μ_EHL 0.02). Sources: SKF catalogue constants of :mod:`bearingkit.physics.lubrication.traction`
#: (μ_EHL = 0.05 for mineral oils; μ_bl = 0.12 run-in, 0.15 not run-in); "boundary…" holds μ at μ_bl
#: for every Λ (a grease at 5 r/min read as boundary-lubricated). docs/seed000-friction.md.
SLIDING_READINGS = {
    "mixed": None,
    "mixed_mineral": (0.12, 0.05),
    "boundary": (0.12, 0.12),
    "boundary_unrun": (0.15, 0.15),
}


@dataclass(frozen=True)
class FrictionVariant:
    """One documented reading of the seed-000 friction model.

    Parameters
    ----------
    name : str
    pairing : str
        Roller slice-law pairing (``"total_approach"`` = Tian eqs. 3–5 literally, ``"series"``).
    crowning : str
        Crowning of the base bearing (seed-000 letter a–e); the paper does not state it for §6.1.1–6.1.4.
    spin : str
        f_s of M4: ``"mixed"`` (interpolated by Λ, as E2), ``"boundary"`` (μ_bl) or ``"ehl"`` (μ_EHL).
    sliding : str
        μ_ij of E2, a key of :data:`SLIDING_READINGS` (``"mixed"``: the operating point's).
    viscous_line_model, viscous_point_model, raceway_control : str
        Registry keys of :mod:`bearingkit.analysis.friction.components`.
    yrt_clearance : float [m]
        Axial roller clearance of the YRT comparator (0 = as the validation case; < 0 preloaded).
    viscosity_factor : float or None [-]
        η_eff/η_base (1: base oil); None = identify it on Table 3 run 1
        (:func:`~bearingkit.papers.tian2025.friction.calibrated_factor`).
    roller_sliding : float or None [-]
        μ_rs of the axial roller rows; None = identify it on Table 3 run 1
        (:func:`~bearingkit.papers.tian2025.friction.calibrated_sliding`).
        At most one of the two is None.
    description : str
    """

    name: str
    pairing: str = "total_approach"
    crowning: str = "a"
    spin: str = "mixed"
    sliding: str = "mixed"
    viscous_line_model: str = "matsuyama"
    viscous_point_model: str = "fujiwara"
    raceway_control: str = "tangent"
    yrt_clearance: float = 0.0
    viscosity_factor: float | None = 1.0
    roller_sliding: float | None = None
    description: str = ""

    def __post_init__(self):
        checks.one_of("pairing", self.pairing, ("total_approach", "series"))
        checks.one_of("crowning", self.crowning, SEED000_CROWNING)
        checks.one_of("spin", self.spin, SPIN_READINGS)
        checks.one_of("sliding", self.sliding, SLIDING_READINGS)
        checks.one_of("viscous_line_model", self.viscous_line_model, VISCOUS_LINE_MODELS)
        checks.one_of("viscous_point_model", self.viscous_point_model, VISCOUS_POINT_MODELS)
        checks.one_of("raceway_control", self.raceway_control, RACEWAY_CONTROLS)
        checks.in_range("yrt_clearance", self.yrt_clearance, -10e-6, 0.0, "m")
        if self.viscosity_factor is not None:
            checks.positive("viscosity_factor", self.viscosity_factor)
        if self.roller_sliding is not None:
            checks.in_range("roller_sliding", self.roller_sliding, 0.0, 1.0)
        if self.viscosity_factor is None and self.roller_sliding is None:
            raise checks.InputError(
                f"variant {self.name!r}: viscosity_factor and roller_sliding are both None; one constant "
                "is identified on Table 3 run 1, the other must be given"
            )

    @property
    def geometry(self) -> dict:
        """Builder overrides of this reading."""
        return {"pairing": self.pairing, "crowning": self.crowning}


VARIANTS: dict[str, FrictionVariant] = {
    v.name: v
    for v in (
        FrictionVariant(
            "seed000",
            viscosity_factor=cal.VISCOSITY_FACTOR,
            roller_sliding=cal.ROLLER_SLIDING,
            description="validated reading (papers/tian2025/validation.py, constants in calibration.py)",
        ),
        FrictionVariant(
            "viscous_only",
            viscosity_factor=None,
            roller_sliding=0.0,
            description="before issue 32: no roller sliding term, grease viscosity factor fitted on run 1",
        ),
        FrictionVariant("spin_ehl", spin="ehl", description="f_s = mu_EHL (full-film traction in the spin)"),
        FrictionVariant("spin_boundary", spin="boundary", description="f_s = mu_bl (Harris: Coulomb)"),
        FrictionVariant(
            "sliding_mineral", sliding="mixed_mineral", description="E2 with mu_EHL = 0.05 (SKF, mineral oil)"
        ),
        FrictionVariant(
            "sliding_boundary", sliding="boundary", description="E2 at mu_bl = 0.12 at any film (SKF run-in)"
        ),
        FrictionVariant(
            "sliding_boundary_unrun",
            sliding="boundary_unrun",
            description="E2 at mu_bl = 0.15 for every film (SKF, not run-in)",
        ),
        FrictionVariant("series", pairing="series", description="raceway contacts of a slice in series"),
        FrictionVariant("straight_base", crowning="e", description="base bearing with straight rollers"),
        FrictionVariant("houpert", viscous_point_model="houpert", description="Houpert ball EHL resistance"),
        FrictionVariant("outer_control", raceway_control="outer", description="outer-raceway control"),
        FrictionVariant(
            "yrt_preloaded",
            yrt_clearance=-2e-6,
            viscosity_factor=cal.VISCOSITY_FACTOR,
            roller_sliding=cal.ROLLER_SLIDING,
            description="YRT comparator preloaded (roller clearance -2 um, Schaeffler YRT are preloaded)",
        ),
    )
}


def _variant(variant) -> FrictionVariant:
    if isinstance(variant, FrictionVariant):
        return variant
    checks.one_of("variant", variant, VARIANTS)
    return VARIANTS[variant]
