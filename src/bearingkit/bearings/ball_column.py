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
  centres of the first- and third-row bearings"); beam strip width π R_c/2 (assumed).
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, fields, replace
from pathlib import Path

import numpy as np

from bearingkit import checks
from bearingkit.analysis.model import BearingModel
from bearingkit.bearings.common import e_reduced_of
from bearingkit.rings.flexible import FlexibleOuterRing
from bearingkit.rings.section import RingSection
from bearingkit.rows.ball import BallRow
from bearingkit.rows.cylindrical import CylindricalRow

ROWS = ("ball_1", "roller_2", "ball_3")
#: Default slices per roller (the paper does not state its slice count).
DEFAULT_SLICES = 20
#: Young's modulus of the GCr15 outer ring [Pa] (bearing steel, 208 GPa).
RING_E = 2.08e11


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
        checks.non_negative("clearance_ball", self.clearance_ball, "m")
        checks.non_negative("clearance_roller", self.clearance_roller, "m")

    @property
    def row_spacing(self) -> float:
        """Axial distance a between the roller row and each ball row [m]."""
        return self.inner_ring_width


def ball_column(geometry: BallColumnGeometry | None = None, *, material=None, **overrides) -> BearingModel:
    """The seed-002 ball–column composite bearing as three rows on one rigid inner body."""
    g = geometry or BallColumnGeometry()
    if overrides:
        g = replace(g, **overrides)
    e_red = e_reduced_of(material)
    a = g.row_spacing
    rows = []
    for name, z, sign in (("ball_1", -a, -1.0), ("ball_3", a, 1.0)):
        rows.append(
            BallRow(
                n_elements=g.n_balls,
                element_diameter=g.ball_diameter,
                pitch_diameter=g.pitch_diameter,
                contact_angle=sign * g.contact_angle,
                conformity_inner=g.conformity_inner,
                conformity_outer=g.conformity_outer,
                clearance=g.clearance_ball * np.cos(g.contact_angle),
                axial_position=z,
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
        metadata={"geometry": g, "source": "Li et al. 2025 Table 1 (+ assumed values, see module)"},
    )


def outer_ring(
    geometry: BallColumnGeometry | None = None, *, compliance_scale=1.0, bending=True, youngs_modulus=RING_E
) -> FlexibleOuterRing:
    """The arc-backed flexible outer ring of the seed-002 bearing."""
    g = geometry or BallColumnGeometry()
    bore_radius = (g.pitch_diameter + max(g.roller_diameter, g.ball_diameter)) / 2
    section = RingSection.arc_backed(g.width, bore_radius, g.outer_diameter / 2, beam_width=g.beam_width)
    supports = g.support_positions or (-g.row_spacing, g.row_spacing)
    return FlexibleOuterRing(
        section, youngs_modulus, 0.0, tuple(supports), bending=bending, compliance_scale=compliance_scale
    )


#: TOML keys (section [geometry]) → (field, dimension for bearingkit.units.parse).
_TOML_FIELDS = {
    "n_balls": ("n_balls", None),
    "ball_diameter": ("ball_diameter", "length"),
    "n_rollers": ("n_rollers", None),
    "roller_diameter": ("roller_diameter", "length"),
    "roller_length": ("roller_length", "length"),
    "outer_diameter": ("outer_diameter", "length"),
    "bore": ("bore", "length"),
    "width": ("width", "length"),
    "inner_ring_width": ("inner_ring_width", "length"),
    "pitch_diameter": ("pitch_diameter", "length"),
    "contact_angle": ("contact_angle", "angle"),
    "conformity_inner": ("conformity_inner", "dimensionless"),
    "conformity_outer": ("conformity_outer", "dimensionless"),
    "clearance_ball": ("clearance_ball", "length"),
    "clearance_roller": ("clearance_roller", "length"),
    "n_slices": ("n_slices", None),
    "beam_width": ("beam_width", "length"),
}


def load_example(path) -> tuple[BallColumnGeometry, np.ndarray, dict]:
    """Read a seed-002 example TOML (units as strings) → (geometry, load (5,) [SI], ring options)."""
    from bearingkit.analysis.quasistatic import load_vector
    from bearingkit.units import parse

    data = tomllib.loads(Path(path).read_text())
    geo = {}
    for key, value in data.get("geometry", {}).items():
        if key not in _TOML_FIELDS:
            raise checks.InputError(
                f"{path}: geometry.{key} is not a field; expected one of {sorted(_TOML_FIELDS)}"
            )
        name, dim = _TOML_FIELDS[key]
        geo[name] = value if dim is None else parse(value, dim, f"geometry.{key}")
    if "support_positions" in data.get("ring", {}):
        geo["support_positions"] = tuple(
            parse(v, "length", "ring.support_positions") for v in data["ring"]["support_positions"]
        )
    known = {f.name for f in fields(BallColumnGeometry)}
    geometry = BallColumnGeometry(**{k: v for k, v in geo.items() if k in known})
    ld = data.get("load", {})
    load = load_vector(
        F_x=parse(ld.get("radial", "0 N"), "force", "load.radial"),
        F_z=parse(ld.get("axial", "0 N"), "force", "load.axial"),
        M_y=parse(ld.get("moment", "0 N*m"), "moment", "load.moment"),
    )
    ring = {
        "compliance_scale": float(data.get("ring", {}).get("compliance_scale", 1.0)),
        "bending": bool(data.get("ring", {}).get("bending", True)),
    }
    return geometry, load, ring
