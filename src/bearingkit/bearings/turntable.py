"""Turntable bearings: the seed-000 ball–roller composite bearing and a YRT-type three-row roller bearing.

SI units. Seed 000 (Tian et al. 2025, Machines 13:588, §3 and Table 1): two axial rows (upper, lower),
each of alternating cylindrical rollers and balls in one cage, and one radial roller row; the inner
ring (three bolted parts) is one rigid body, the outer ring is fixed. Each axial row is modelled as
two bearingkit rows sharing the axial direction: a thrust cylindrical row at d_m1 and a thrust ball
row (α = 90°) at d_m2, their azimuths interleaved by half a pitch.

Geometry the paper does not give, and the values chosen (stated in docs and the examples):
- axial positions of the upper and lower contact planes: ±``AXIAL_ROW_OFFSET`` (YRT 120-like height);
  they do not enter the axial/tilt equilibrium of thrust rows, only the small radial coupling of the
  ball grooves;
- slice count: ``DEFAULT_SLICES``;
- crowning dimensions: those of :mod:`bearingkit.physics.contact.profiles` defaults;
- material: GCr15 on GCr15;
- roller slice law: Kunert, applied as the paper writes it (``pairing="total_approach"``: the one-contact
  law on the raceway-to-raceway approach, eqs. 3–5). ``pairing="series"`` puts the two raceway
  contacts in series (physically softer by 2^(10/9) in load at equal approach); the §6.1.1 mechanism
  "at roller clearance −2 µm both axial roller rows carry load" needs the paper's reading (or straight
  rollers) — see docs/seed000.md.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit import checks
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.bearings.common import e_reduced_of
from bearingkit.rows.ball.row import BallRow
from bearingkit.rows.cylindrical.row import CylindricalRow

#: Axial distance of each axial row's contact plane from the radial row [m]; assumed (seed 000 gives
#: no section drawing dimensions). Only affects the radial–tilt coupling of the ball grooves.
AXIAL_ROW_OFFSET = 0.012
#: Slices per roller; the issue asks for ≥ 20 (Tian et al. do not state n).
DEFAULT_SLICES = 20
#: How the roller slice law is applied in the seed-000 bearings: as Tian et al. 2025 write it
#: (eqs. 3–5, the one-contact Kunert law on the total approach). See CylindricalRow.pairing.
SEED000_PAIRING = "total_approach"


@dataclass(frozen=True)
class CompositeTurntableGeometry:
    """Seed-000 Table 1 geometry of the ball–roller composite turntable bearing (SI).

    Defaults are the published values (Tian et al. 2025, Table 1). Clearances default to the
    experimental setting of §5.3.2 (axial roller 0 µm, axial ball −2 µm) and radial 0.
    """

    bore: float = 0.120
    outer_diameter: float = 0.210
    pitch_diameter_axial_roller: float = 0.167
    pitch_diameter_axial_ball: float = 0.1778
    pitch_diameter_radial_roller: float = 0.15525
    n_axial_rollers: int = 31  # per axial row
    n_axial_balls: int = 31  # per axial row
    n_radial_rollers: int = 97
    axial_roller_diameter: float = 0.004
    axial_roller_length: float = 0.0048
    ball_diameter: float = 0.006
    radial_roller_diameter: float = 0.005
    radial_roller_length: float = 0.008
    groove_curvature: float = 0.52  # f = r/D_w of the ball grooves (both rings), §6.1.2 default
    clearance_axial_roller: float = 0.0
    clearance_axial_ball: float = -2e-6
    clearance_radial: float = 0.0
    crowning: str = "a"  # seed-000 letter a–e or a profile registry name
    n_slices: int = DEFAULT_SLICES
    pairing: str = SEED000_PAIRING

    def __post_init__(self):
        checks.positive("bore", self.bore, "m")
        checks.greater("outer_diameter", self.outer_diameter, "bore", self.bore, "m")
        for f in ("pitch_diameter_axial_roller", "pitch_diameter_axial_ball", "pitch_diameter_radial_roller"):
            d = getattr(self, f)
            checks.greater(f, d, "bore", self.bore, "m")
            checks.greater("outer_diameter", self.outer_diameter, f, d, "m")
        if np.any(np.asarray(self.groove_curvature) <= 0.5):
            raise checks.InputError(
                f"groove_curvature ({np.min(self.groove_curvature):.6g}) must exceed 0.5 "
                "(r/D_w of the ball grooves)"
            )
        r_in = np.asarray(self.pitch_diameter_axial_roller) / 2 - np.asarray(self.axial_roller_length) / 2
        r_out = np.asarray(self.pitch_diameter_axial_roller) / 2 + np.asarray(self.axial_roller_length) / 2
        if np.any(r_in < np.asarray(self.bore) / 2) or np.any(r_out > np.asarray(self.outer_diameter) / 2):
            raise checks.InputError(
                "axial rollers (pitch_diameter_axial_roller ± axial_roller_length) do not fit "
                "between bore and "
                "outer_diameter"
            )


def _profile(letter_or_name: str, length, diameter):
    from bearingkit.physics.contact.profiles import SEED000_CROWNING, make_profile

    name = SEED000_CROWNING.get(letter_or_name, letter_or_name)
    return make_profile(name, effective_length=length, element_diameter=diameter)


def _radial_row(g, profile, e_red) -> CylindricalRow:
    """The radial roller row shared by the composite and the YRT-type bearing."""
    return CylindricalRow(
        n_elements=g.n_radial_rollers,
        element_diameter=g.radial_roller_diameter,
        effective_length=g.radial_roller_length,
        pitch_diameter=g.pitch_diameter_radial_roller,
        orientation="radial",
        clearance=g.clearance_radial,
        n_slices=g.n_slices,
        profile=profile,
        pairing=g.pairing,
        e_reduced=e_red,
        name="roller_radial",
    )


def _axial_roller_row(g, n_elements, side, profile, e_red) -> CylindricalRow:
    """An axial (thrust) roller row, ``side`` "upper" (resists +u_z) or "lower"."""
    sign = 1 if side == "upper" else -1
    return CylindricalRow(
        n_elements=n_elements,
        element_diameter=g.axial_roller_diameter,
        effective_length=g.axial_roller_length,
        pitch_diameter=g.pitch_diameter_axial_roller,
        orientation="thrust_up" if sign > 0 else "thrust_down",
        clearance=g.clearance_axial_roller,
        n_slices=g.n_slices,
        profile=profile,
        pairing=g.pairing,
        axial_position=sign * AXIAL_ROW_OFFSET,
        e_reduced=e_red,
        name=f"roller_{side}",
    )


def composite_turntable(
    geometry: CompositeTurntableGeometry | None = None, *, material=None, **overrides
) -> BearingModel:
    """The seed-000 ball–roller composite turntable bearing as five rows on one rigid inner ring.

    Rows: ``roller_upper``, ``ball_upper`` (resist +u_z), ``roller_lower``, ``ball_lower`` (resist −u_z),
    ``roller_radial``. Per-row gaps follow the paper: δ = ±δ_a … − u_a0/2 (axial), δ_r cos ψ … − u_r0/2.
    Keyword overrides replace fields of the geometry (``clearance_axial_ball=-5e-6`` …).
    """
    g = geometry or CompositeTurntableGeometry()
    if overrides:
        g = CompositeTurntableGeometry(**{**g.__dict__, **overrides})
    e_red = e_reduced_of(material)
    axial_profile = _profile(g.crowning, g.axial_roller_length, g.axial_roller_diameter)
    radial_profile = _profile(g.crowning, g.radial_roller_length, g.radial_roller_diameter)
    half_pitch = np.pi / g.n_axial_balls
    rows = []
    for side, sign, z in (("upper", +1, AXIAL_ROW_OFFSET), ("lower", -1, -AXIAL_ROW_OFFSET)):
        rows.append(_axial_roller_row(g, g.n_axial_rollers, side, axial_profile, e_red))
        rows.append(
            BallRow(
                n_elements=g.n_axial_balls,
                element_diameter=g.ball_diameter,
                pitch_diameter=g.pitch_diameter_axial_ball,
                contact_angle=sign * np.pi / 2,
                conformity_inner=g.groove_curvature,
                conformity_outer=g.groove_curvature,
                clearance=g.clearance_axial_ball,
                axial_position=z,
                azimuth_phase=half_pitch,
                e_reduced=e_red,
                name=f"ball_{side}",
            )
        )
    rows.append(_radial_row(g, radial_profile, e_red))
    return BearingModel(
        tuple(rows),
        name="ball-roller composite turntable bearing (Tian et al. 2025)",
        references=("tian2025", "kunert1961", "harris2007"),
        metadata={"geometry": g.__dict__, "axial_row_offset_m": AXIAL_ROW_OFFSET},
    )


@dataclass(frozen=True)
class YRTGeometry:
    """YRT-type three-row roller turntable bearing in the seed-000 envelope (120 × 210 mm).

    Seed 000 compares against "a typical traditional YRT turntable bearing" of identical dimensions
    but gives no internal geometry. Assumed here (documented in examples/yrt_120.toml): each axial
    row is the composite bearing's axial rollers with the balls replaced by rollers of the same
    size, i.e. 62 rollers Ø4 × 4.8 mm per axial row on d_m 167 mm; the radial row is unchanged.
    """

    pitch_diameter_axial_roller: float = 0.167
    n_axial_rollers: int = 62
    axial_roller_diameter: float = 0.004
    axial_roller_length: float = 0.0048
    pitch_diameter_radial_roller: float = 0.15525
    n_radial_rollers: int = 97
    radial_roller_diameter: float = 0.005
    radial_roller_length: float = 0.008
    clearance_axial_roller: float = 0.0
    clearance_radial: float = 0.0
    crowning: str = "a"
    n_slices: int = DEFAULT_SLICES
    pairing: str = SEED000_PAIRING


def yrt_turntable(geometry: YRTGeometry | None = None, *, material=None, **overrides) -> BearingModel:
    """YRT-type three-row roller turntable bearing (two axial roller rows, one radial roller row)."""
    g = geometry or YRTGeometry()
    if overrides:
        g = YRTGeometry(**{**g.__dict__, **overrides})
    e_red = e_reduced_of(material)
    axial_profile = _profile(g.crowning, g.axial_roller_length, g.axial_roller_diameter)
    radial_profile = _profile(g.crowning, g.radial_roller_length, g.radial_roller_diameter)
    rows = [
        _axial_roller_row(g, g.n_axial_rollers, side, axial_profile, e_red) for side in ("upper", "lower")
    ]
    rows.append(_radial_row(g, radial_profile, e_red))
    return BearingModel(
        tuple(rows),
        name="YRT-type three-row roller turntable bearing (assumed geometry)",
        references=("tian2025", "kunert1961"),
        metadata={"geometry": g.__dict__},
    )
