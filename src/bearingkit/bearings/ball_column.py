"""The ball–column composite bearing of seed 002: two angular-contact ball rows + one roller row.

SI units. Li et al. 2025 (Machines 13:785, §2, Table 1): three rows on three inner rings that sit
on one rigid inner body, one shared outer ring with a spherical (arc) back that self-aligns in the
housing. Rows: ``ball_1`` (z = −a), ``roller_2`` (z = 0, sliced cylindrical), ``ball_3`` (z = +a).
The ball rows face each other back to back (O arrangement): ``ball_1`` resists −u_z, ``ball_3`` +u_z.

Values the paper does not give, and the values chosen (all overridable):

- pitch diameter of every row: the mean of bore and outside diameter, (342 + 406)/2 = 374 mm;
- roller diameter: Table 1 says 16 mm, but 78 rollers of Ø16 need a pitch circle of at least
  78·16/π = 397 mm, which does not fit inside Ø406; we use 15 mm (π·374/78 = 15.06 mm of pitch);
  the Kunert line stiffness does not depend on the diameter, only the pressures do (−3 %);
- row spacing a = inner-ring width 25 mm (three 25 mm inner rings, bearing width 75 mm);
- contact angle of the ball rows 40° (Fig. 12e, condition 2); groove curvature f_i = 0.52, f_o = 0.53;
- "radial clearance" of a ball row P_d is converted to the clearance along its contact line,
  P_d·cos α₀ (counted twice, as BallRow expects);
- roller slices 20, straight rollers (no crowning data), Kunert law, both contacts in series;
- outer ring: arc-backed section, bore = outer raceway radius (d_m + D_roller)/2, sphere radius
  = D/2; housing supports at the two ball rows (seed 002 §2.3.1: "A and B … parallel to the bearing
  centres of the first- and third-row bearings"); beam strip width π R_c/2 (assumed);
- housing: the outer ring sits without radial play in a steel housing wall of 20 mm
  (:data:`DEFAULT_HOUSING_WALL`, E = 208 GPa), a bilateral Winkler foundation of stiffness
  k_h = E_h t_h b/R_h² on the ring's ovalisation (:mod:`bearingkit.physics.structure.thin_ring`). The paper
  says only that the arc back sits in the housing; a free ring (k_h = 0, ``housing_stiffness = 0``)
  would let the unloaded side move ~40 µm outward through the housing wall.

Input files: ``bearing.type = "ball_column"`` (:mod:`bearingkit.io.schema`), the ring options in
``[geometry.ring]`` (:class:`RingOptions`); :func:`solve_flexible_input` runs the coupled solve.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from bearingkit import checks
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.bearings.common import e_reduced_of
from bearingkit.physics.structure import thin_ring
from bearingkit.rings.flexible import BEAM_MODES, FlexibleOuterRing
from bearingkit.rings.section import RingSection
from bearingkit.rows.ball.row import BallRow
from bearingkit.rows.cylindrical.row import CylindricalRow

ROWS = ("ball_1", "roller_2", "ball_3")
#: How ``n_balls`` counts the balls (issue 32): ``"per_row"`` — every ball row has n_balls; ``"total"`` —
#: n_balls is the total of the two ball rows (n_balls/2 each), and ball row 1 is staggered half a pitch
#: against ball row 3 (one ball of row 3 under the radial load). Seed 002's counts follow ``"total"``:
#: Table 1's 74 balls are 37 per row, §3.2's row-3 count 19 = the loaded half of 37, §3.3.1's 35 → 39
#: counts both rows for 70 → 78 balls (17 + 18, 19 + 20); docs/seed002.md.
BALL_COUNTS = ("per_row", "total")
#: Default slices per roller (the paper does not state its slice count).
DEFAULT_SLICES = 20
#: Young's modulus of the GCr15 outer ring [Pa] (bearing steel, 208 GPa).
RING_E = 2.08e11
#: Young's modulus of the housing [Pa] (steel, 208 GPa; a cast-iron housing would be ~110-170 GPa).
HOUSING_E = 2.08e11
#: Default housing wall thickness around the outer ring [m]: 20 mm of steel, the middle (on a log
#: scale) of the 10-40 mm walls of housings for bearings of this size; an assumption (seed 002 gives
#: no housing). docs/seed002.md shows the counts and shares from a free ring to a rigid housing.
DEFAULT_HOUSING_WALL = 0.020


@dataclass(frozen=True)
class BallColumnGeometry:
    """Seed-002 Table 1 geometry plus the values the paper leaves out (SI; see module docstring)."""

    n_balls: int = 74
    ball_diameter: float = 0.015
    n_rollers: int = 78
    roller_diameter: float = 0.015
    roller_length: float = 0.018
    outer_diameter: float = 0.406
    bore: float = 0.342
    width: float = 0.075
    inner_ring_width: float = 0.025
    pitch_diameter: float = 0.374
    contact_angle: float = float(np.deg2rad(40.0))
    conformity_inner: float = 0.52
    conformity_outer: float = 0.53
    clearance_ball: float = 0.0  # radial (diametral) clearance of each ball row [m]
    clearance_roller: float = 0.0  # radial (diametral) clearance of the roller row [m]
    n_slices: int = DEFAULT_SLICES
    support_positions: tuple | None = None  # housing supports (z_A, z_B) [m]; default the ball rows
    ball_count: str = "per_row"  # how n_balls counts (BALL_COUNTS)
    beam_width: float | None = None  # circumferential width of the beam strip [m]

    def __post_init__(self):
        checks.positive("bore", self.bore, "m")
        checks.greater("outer_diameter", self.outer_diameter, "bore", self.bore, "m")
        checks.greater("pitch_diameter", self.pitch_diameter, "bore", self.bore, "m")
        checks.greater("outer_diameter", self.outer_diameter, "pitch_diameter", self.pitch_diameter, "m")
        checks.positive("width", self.width, "m")
        checks.positive("inner_ring_width", self.inner_ring_width, "m")
        if 3 * self.inner_ring_width > self.width + 1e-12:
            raise checks.InputError(
                f"inner_ring_width ({self.inner_ring_width:.6g} m) × 3 must not exceed "
                f"width ({self.width:.6g} m)"
            )
        checks.in_range("contact_angle", self.contact_angle, 0.0, np.pi / 2, "rad", closed=False)
        checks.one_of("ball_count", self.ball_count, BALL_COUNTS)
        if self.ball_count == "total" and (self.n_balls % 2 or self.n_balls < 6):
            raise checks.InputError(
                f"n_balls ({self.n_balls}) with ball_count 'total' must be an even number >= 6 (two rows)"
            )
        checks.non_negative("clearance_ball", self.clearance_ball, "m")
        checks.non_negative("clearance_roller", self.clearance_roller, "m")
        if self.support_positions is not None:
            za, zb = (float(v) for v in self.support_positions)
            half = self.width / 2
            if not (-half - 1e-12 <= za < zb <= half + 1e-12):
                raise checks.InputError(
                    f"support_positions ({za:.6g}, {zb:.6g} m): the support span must lie within the ring "
                    f"(−{half:.6g} … {half:.6g} m, width {self.width:.6g} m) with z_A < z_B"
                )
            a = self.inner_ring_width  # the ball rows sit at ∓a, the roller row at 0
            if not (za <= -a + 1e-12 and zb >= a - 1e-12):
                raise checks.InputError(
                    f"support_positions ({za:.6g}, {zb:.6g} m): every row must lie between the housing "
                    f"supports (rows at −{a:.6g}, 0, {a:.6g} m)"
                )

    @property
    def balls_per_row(self) -> int:
        """Balls in each ball row (see :data:`BALL_COUNTS`)."""
        return self.n_balls // 2 if self.ball_count == "total" else self.n_balls

    @property
    def row_spacing(self) -> float:
        """Axial distance a between the roller row and each ball row [m]."""
        return self.inner_ring_width


@dataclass(frozen=True)
class RingOptions:
    """How the shared outer ring is modelled (input files: ``[geometry.ring]``).

    Parameters
    ----------
    flexible : bool
        Solve with the ring's compliance (:func:`bearingkit.analysis.flexible.solve_flexible`);
        False: the ring is rigid.
    compliance_scale : float [–]
        Multiplies both compliances (≥ 0; 0 = rigid; seed 002 §3.2 varies the deflection).
    bending : bool
        Thin-ring ovalisation (seed 002 eqs. 7–10) on top of the beam between the supports.
    beam_mode : str
        How the beam deflection acts on a row (:data:`bearingkit.rings.flexible.BEAM_MODES`).
    beam_tilt : bool
        Apply the beam slope as a rigid raceway tilt.
    housing_stiffness : float or None [N/m²]
        Winkler stiffness k_h of the housing on the ring's ovalisation, given directly (0 = free
        ring, np.inf = rigid housing). Exclusive with ``housing_wall_thickness``.
    housing_wall_thickness : float or None [m]
        Housing wall thickness t_h: k_h = E_h t_h b/R_h² (:func:`bearingkit.physics.structure.thin_ring.
        housing_wall_stiffness`, R_h = outer radius + t_h/2, b = ring width). When neither is given:
        :data:`DEFAULT_HOUSING_WALL`.
    housing_youngs_modulus : float [Pa]
        E_h of the housing (:data:`HOUSING_E`).
    """

    flexible: bool = True
    compliance_scale: float = 1.0
    bending: bool = True
    beam_mode: str = "clearance"
    beam_tilt: bool = False
    housing_stiffness: float | None = None
    housing_wall_thickness: float | None = None
    housing_youngs_modulus: float = HOUSING_E

    def __post_init__(self):
        checks.non_negative("compliance_scale", self.compliance_scale)
        checks.one_of("beam_mode", self.beam_mode, BEAM_MODES)
        for name in ("flexible", "bending", "beam_tilt"):
            if not isinstance(getattr(self, name), bool):
                raise checks.InputError(f"{name} ({getattr(self, name)!r}) must be true or false")
        if self.housing_stiffness is not None:
            k = float(self.housing_stiffness)
            if np.isnan(k) or k < 0:
                raise checks.InputError(
                    f"housing_stiffness ({k:.6g} N/m²) must be non-negative "
                    "(0 = free ring, inf = rigid housing)"
                )
            if self.housing_wall_thickness is not None:
                raise checks.InputError(
                    f"housing_stiffness ({k:.6g} N/m²) and housing_wall_thickness "
                    f"({self.housing_wall_thickness:.6g} m): give one of them, not both"
                )
        if self.housing_wall_thickness is not None:
            checks.positive("housing_wall_thickness", self.housing_wall_thickness, "m")
        checks.positive("housing_youngs_modulus", self.housing_youngs_modulus, "Pa")

    def housing_stiffness_of(self, geometry: BallColumnGeometry) -> float:
        """The housing's Winkler stiffness k_h [N/m²] for this bearing geometry (see the fields)."""
        if self.housing_stiffness is not None:
            return float(self.housing_stiffness)
        return wall_housing_stiffness(geometry, self.housing_wall_thickness, self.housing_youngs_modulus)


def wall_housing_stiffness(
    geometry: BallColumnGeometry | None = None, wall_thickness=None, youngs_modulus=HOUSING_E
):
    """k_h [N/m²] of a housing wall of thickness t_h around the ring (default :data:`DEFAULT_HOUSING_WALL`).

    k_h = E_h t_h b/R_h² with R_h = D/2 + t_h/2 and b the ring width
    (:func:`bearingkit.physics.structure.thin_ring.housing_wall_stiffness`, Roark & Young 2012 Table 13.1).
    """
    g = geometry or BallColumnGeometry()
    t = DEFAULT_HOUSING_WALL if wall_thickness is None else float(wall_thickness)
    return float(thin_ring.housing_wall_stiffness(youngs_modulus, t, g.outer_diameter / 2 + t / 2, g.width))


def ball_column(
    geometry: BallColumnGeometry | None = None,
    *,
    material=None,
    ring: RingOptions | None = None,
    **overrides,
) -> BearingModel:
    """The seed-002 ball–column composite bearing as three rows on one rigid inner body.

    ``ring`` (default :class:`RingOptions`) and the ring's Young's modulus (the material's, GCr15
    when none is given) are kept in ``metadata`` for :func:`outer_ring_of`.
    """
    g = geometry or BallColumnGeometry()
    if overrides:
        g = replace(g, **overrides)
    ring = RingOptions() if ring is None else ring
    if not isinstance(ring, RingOptions):
        raise checks.InputError(f"ring ({ring!r}) must be a RingOptions")
    e_red = e_reduced_of(material)
    a = g.row_spacing
    rows = []
    z_row = g.balls_per_row
    stagger = np.pi / z_row if g.ball_count == "total" else 0.0  # row 1 half a pitch off row 3
    for name, z, sign, phase in (("ball_1", -a, -1.0, stagger), ("ball_3", a, 1.0, 0.0)):
        rows.append(
            BallRow(
                n_elements=z_row,
                element_diameter=g.ball_diameter,
                pitch_diameter=g.pitch_diameter,
                contact_angle=sign * g.contact_angle,
                conformity_inner=g.conformity_inner,
                conformity_outer=g.conformity_outer,
                clearance=g.clearance_ball * np.cos(g.contact_angle),
                axial_position=z,
                azimuth_phase=phase,
                e_reduced=e_red,
                name=name,
            )
        )
    roller = CylindricalRow(
        n_elements=g.n_rollers,
        element_diameter=g.roller_diameter,
        effective_length=g.roller_length,
        pitch_diameter=g.pitch_diameter,
        clearance=g.clearance_roller,
        n_slices=g.n_slices,
        axial_position=0.0,
        e_reduced=e_red,
        name="roller_2",
    )
    return BearingModel(
        (rows[0], roller, rows[1]),
        name="ball-column composite (Li et al. 2025)",
        references=("li2025", "harris2007", "kunert1961"),
        metadata={
            "geometry": g,
            "source": "Li et al. 2025 Table 1 (+ assumed values, see module)",
            "ring": ring,
            "ring_youngs_modulus": RING_E if material is None else float(material.youngs_modulus),
        },
    )


def outer_ring(
    geometry: BallColumnGeometry | None = None,
    *,
    compliance_scale=1.0,
    bending=True,
    youngs_modulus=RING_E,
    beam_mode="clearance",
    beam_tilt=False,
    housing_stiffness=None,
) -> FlexibleOuterRing:
    """The arc-backed flexible outer ring of the seed-002 bearing.

    ``housing_stiffness`` k_h [N/m²]: None = the default housing (a :data:`DEFAULT_HOUSING_WALL` steel
    wall, :func:`wall_housing_stiffness`), 0 = free ring, np.inf = rigid housing.
    """
    g = geometry or BallColumnGeometry()
    bore_radius = (g.pitch_diameter + max(g.roller_diameter, g.ball_diameter)) / 2
    section = RingSection.arc_backed(g.width, bore_radius, g.outer_diameter / 2, beam_width=g.beam_width)
    supports = g.support_positions or (-g.row_spacing, g.row_spacing)
    return FlexibleOuterRing(
        section,
        youngs_modulus,
        0.0,
        tuple(supports),
        bending=bending,
        compliance_scale=compliance_scale,
        beam_mode=beam_mode,
        beam_tilt=beam_tilt,
        housing_stiffness=wall_housing_stiffness(g)
        if housing_stiffness is None
        else float(housing_stiffness),
    )


def outer_ring_of(model: BearingModel) -> FlexibleOuterRing | None:
    """The flexible outer ring a :func:`ball_column` model carries in its metadata (None: rigid ring)."""
    g = model.metadata.get("geometry")
    opts = model.metadata.get("ring")
    if not isinstance(g, BallColumnGeometry) or not isinstance(opts, RingOptions):
        raise checks.InputError(f"model ({model.name!r}) is not a ball–column bearing built by ball_column()")
    if not opts.flexible:
        return None
    return outer_ring(
        g,
        compliance_scale=opts.compliance_scale,
        bending=opts.bending,
        youngs_modulus=model.metadata.get("ring_youngs_modulus", RING_E),
        beam_mode=opts.beam_mode,
        beam_tilt=opts.beam_tilt,
        housing_stiffness=opts.housing_stiffness_of(g),
    )


def solve_flexible_input(bearing):
    """Coupled flexible-ring solve of a loaded input file of type ``ball_column`` (None: rigid ring).

    Parameters
    ----------
    bearing : bearingkit.io.loader.BearingInput
        Its model must come from :func:`ball_column` (``bearing.type = "ball_column"``).

    Returns
    -------
    FlexibleResult or None
        None when ``[geometry.ring] flexible = false``.
    """
    from bearingkit.analysis.flexible import solve_flexible

    ring = outer_ring_of(bearing.model)
    if ring is None:
        return None
    free = None if bool(np.all(bearing.free)) else bearing.free
    return solve_flexible(bearing.model, bearing.load_matrix(), ring, free=free, options=bearing.options)
