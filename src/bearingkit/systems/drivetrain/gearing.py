"""Cylindrical gear pairs of a drivetrain: involute geometry, the line of action, mesh stiffness, mesh loss.

SI units (m, N, N/m, rad). A gear is given by its tooth count z, normal module m_n, normal pressure
angle α_n, helix angle β with its hand, face width b and profile shift coefficient x; an internal gear
(a ring) has teeth on its inside. Involute geometry (ISO 21771; Niemann & Winter, *Maschinenelemente*
vol. II, 1989, ch. 21) [from memory: the clause numbers could not be confirmed with the search tool]:

    m_t = m_n / cos β,   tan α_t = tan α_n / cos β,   d = z m_t,   d_b = d cos α_t,
    tan β_b = tan β cos α_t,
    inv α_wt = inv α_t + 2 tan α_n (x₁ ± x₂) / (z₁ ± z₂)          (inv α = tan α − α),
    a_w = (z₁ ± z₂) m_t cos α_t / (2 cos α_wt),   d_w = d cos α_t / cos α_wt,

the lower sign for an internal pair (z₂, x₂ of the ring). Tip diameters from the standard basic rack
(addendum m_n): d_a = d + 2 m_n (1 + x) (external), d_a = d − 2 m_n (1 − x) (internal), and the
transverse contact ratio ε_α = (g_α) / (π m_t cos α_t) with the length of the path of contact g_α.

Line of action. At the pitch point P the normal force of gear a on gear b points along

    n ∝ s cos α_wt t + sin α_wt e − s cos α_wt tan β_w ẑ,

e the unit vector from a's axis towards P, t = ẑ × e, s = ±1 the loaded flank (which way the torque
flows) and β_w the signed helix angle of gear a at the working pitch circle (tan β_w = tan β d_w/d;
positive for a right-hand helix). The force is perpendicular to both tooth lines (h = sin β t + cos β ẑ
for a right-hand helix of angle β > 0), and the separating component pushes b away from a.

Mesh stiffness (ISO 6336-1:2006 §9, method B) [from memory: the constants and equations could not be
confirmed with the search tool]: the single stiffness c' = c'_th C_M C_R C_B cos β with
c'_th = 1/q', q' = C₁ + C₂/z_n1 + C₃/z_n2 + C₄ x₁ + C₅ x₁/z_n1 + C₆ x₂ + C₇ x₂/z_n2 + C₈ x₁² + C₉ x₂²
[mm µm/N] (z_n = z/cos³β the virtual tooth counts, z_n2 = ∞ for an internal gear), and the mesh
stiffness c_γα = c' (0.75 ε_α + 0.25) [N/(mm µm)], per unit face width along the transverse line of
action. The mesh spring along the normal n is k_n = c_γα b / cos² β_b.

Mesh loss (optional, the load-dependent mesh power loss with a mean coefficient of friction; Ohlendorf
1958, as given by Niemann & Winter vol. II §21.8) [from memory]: P_loss = μ_mz H_V P with the tooth loss
factor H_V = π (u + 1) / (z₁ u) (1 − ε_α + ε₁² + ε₂²) / cos β_b, u = z₂/z₁ (negative for an internal
pair), ε₁, ε₂ the addendum contact ratios; μ_mz is the user's (no default: a value depends on the
lubricant, roughness and speed; Schlenk's μ_mz correlation is not implemented).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError

#: Coefficients C₁ … C₉ of q' [mm·µm/N] (ISO 6336-1:2006 Table 8) [from memory].
ISO6336_Q_COEFFICIENTS = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)
#: Correction factor C_M between the theoretical and measured single stiffness of solid gears [-]
#: (ISO 6336-1:2006 §9.3.3) [from memory].
ISO6336_C_M = 0.8
#: Gear blank factor C_R of solid discs [-] (ISO 6336-1 §9.3.4) [from memory].
ISO6336_C_R = 1.0
#: Basic rack factor C_B of the standard basic rack (ISO 53 profile A) [-] (ISO 6336-1 §9.3.5) [from memory].
ISO6336_C_B = 1.0
#: One N/(mm·µm) in N/m² (the unit of c' and c_γ).
N_PER_MM_UM = 1e9
#: Addendum coefficient of the standard basic rack h_aP/m_n [-] (ISO 53:1998).
ADDENDUM_COEFFICIENT = 1.0
#: Relative tolerance of the centre distance check (given shaft axes vs the gears' working centre
#: distance) [-]: 1e-4 is 10 µm on 100 mm, far below a backlash allowance.
CENTRE_DISTANCE_RTOL = 1e-4


def involute(alpha):
    """inv α = tan α − α [rad]."""
    return np.tan(alpha) - alpha


def inverse_involute(value: float) -> float:
    """α with inv α = value (Newton from the Cheng-type start α₀ = (3 value)^(1/3)) [rad]."""
    if not value > 0.0:
        raise InputError(f"involute ({value:.6g}) must be positive (a working pressure angle above 0)")
    a = (3.0 * value) ** (1.0 / 3.0)
    for _ in range(50):
        f = np.tan(a) - a - value
        a -= f / np.tan(a) ** 2
        if abs(f) < 1e-15:
            break
    return float(a)


@dataclass(frozen=True)
class GearGeometry:
    """An involute cylindrical gear.

    Parameters
    ----------
    teeth : int
        Number of teeth z (of the ring, for an internal gear).
    normal_module : float [m]
    pressure_angle : float [rad]
        Normal pressure angle α_n.
    helix_angle : float [rad]
        Signed helix angle β at the reference circle: positive right hand, negative left hand.
    face_width : float [m]
    profile_shift : float [-]
        Profile shift coefficient x.
    internal : bool
        Teeth on the inside (a ring gear).
    """

    teeth: int
    normal_module: float
    pressure_angle: float = float(np.deg2rad(20.0))
    helix_angle: float = 0.0
    face_width: float = 0.02
    profile_shift: float = 0.0
    internal: bool = False

    def __post_init__(self):
        checks.integer("teeth", self.teeth, low=5 if not self.internal else 10)
        checks.positive("normal_module", self.normal_module, "m")
        checks.in_range("pressure_angle", self.pressure_angle, 0.0, np.pi / 4, "rad", closed=False)
        checks.in_range("helix_angle", self.helix_angle, -np.pi / 4, np.pi / 4, "rad", closed=False)
        checks.positive("face_width", self.face_width, "m")
        checks.in_range("profile_shift", self.profile_shift, -2.0, 2.0, "")

    @property
    def transverse_module(self) -> float:
        """m_t = m_n / cos β [m]."""
        return self.normal_module / np.cos(self.helix_angle)

    @property
    def transverse_pressure_angle(self) -> float:
        """α_t = atan(tan α_n / cos β) [rad]."""
        return float(np.arctan(np.tan(self.pressure_angle) / np.cos(self.helix_angle)))

    @property
    def reference_diameter(self) -> float:
        """d = z m_t [m]."""
        return self.teeth * self.transverse_module

    @property
    def base_diameter(self) -> float:
        """d_b = d cos α_t [m]."""
        return self.reference_diameter * np.cos(self.transverse_pressure_angle)

    @property
    def base_helix_angle(self) -> float:
        """β_b with tan β_b = tan β cos α_t, signed [rad]."""
        return float(np.arctan(np.tan(self.helix_angle) * np.cos(self.transverse_pressure_angle)))

    @property
    def tip_diameter(self) -> float:
        """d_a of the standard basic rack (module docstring) [m]."""
        h = ADDENDUM_COEFFICIENT * self.normal_module
        if self.internal:
            return self.reference_diameter - 2.0 * h * (1.0 - self.profile_shift)
        return self.reference_diameter + 2.0 * h * (1.0 + self.profile_shift)

    @property
    def virtual_teeth(self) -> float:
        """z_n = z / cos³β (ISO 6336-1, for q') [-]."""
        return self.teeth / np.cos(self.helix_angle) ** 3


@dataclass(frozen=True)
class GearPair:
    """Two meshing gears: gear ``a`` external, gear ``b`` external or internal (module docstring).

    Raises InputError (one line naming ``name``) for mismatched modules, pressure angles or helices,
    two internal gears, or an internal gear that is not larger than its pinion.
    """

    a: GearGeometry
    b: GearGeometry
    name: str = "mesh"

    def __post_init__(self):
        a, b, n = self.a, self.b, self.name
        if a.internal:
            raise InputError(f"{n}: the first gear must be the external one (the pinion of an internal pair)")
        if not np.isclose(a.normal_module, b.normal_module, rtol=1e-9, atol=0.0):
            raise InputError(
                f"{n}: mismatched normal modules ({a.normal_module * 1e3:.6g} mm and "
                f"{b.normal_module * 1e3:.6g} "
                "mm); meshing gears need one module"
            )
        if not np.isclose(a.pressure_angle, b.pressure_angle, rtol=1e-9, atol=0.0):
            raise InputError(
                f"{n}: mismatched normal pressure angles ({np.rad2deg(a.pressure_angle):.6g}° and "
                f"{np.rad2deg(b.pressure_angle):.6g}°); meshing gears need one"
            )
        expected = a.helix_angle if b.internal else -a.helix_angle
        if not np.isclose(b.helix_angle, expected, rtol=1e-9, atol=1e-12):
            rule = "the same hand (internal pair)" if b.internal else "opposite hands (external pair)"
            raise InputError(
                f"{n}: helix angles {np.rad2deg(a.helix_angle):.6g}° and {np.rad2deg(b.helix_angle):.6g}° "
                f"do not mesh; expected equal angles of {rule}"
            )
        if b.internal and not b.teeth > a.teeth:
            raise InputError(
                f"{n}: the internal gear ({b.teeth} teeth) must have more teeth than its pinion ({a.teeth})"
            )

    @property
    def sign(self) -> int:
        """+1 external, −1 internal pair."""
        return -1 if self.b.internal else 1

    @property
    def ratio(self) -> float:
        """u = z_b / z_a, negative for an internal pair (the wheels turn the same way) [-]."""
        return self.sign * self.b.teeth / self.a.teeth

    @property
    def working_pressure_angle(self) -> float:
        """α_wt from inv α_wt = inv α_t + 2 tan α_n (x_a ± x_b)/(z_a ± z_b) [rad]."""
        a, b, s = self.a, self.b, self.sign
        inv = involute(a.transverse_pressure_angle) + 2.0 * np.tan(a.pressure_angle) * (
            a.profile_shift + s * b.profile_shift
        ) / (a.teeth + s * b.teeth)
        return inverse_involute(float(inv))

    @property
    def centre_distance(self) -> float:
        """Working centre distance a_w [m] (|z_a ± z_b| m_t cos α_t / (2 cos α_wt))."""
        a, s = self.a, self.sign
        return (
            abs(a.teeth + s * self.b.teeth)
            * a.transverse_module
            * np.cos(a.transverse_pressure_angle)
            / (2.0 * np.cos(self.working_pressure_angle))
        )

    def working_diameter(self, which: str) -> float:
        """d_w = d cos α_t / cos α_wt of gear ``"a"`` or ``"b"`` [m]."""
        g = self.a if which == "a" else self.b
        return (
            g.reference_diameter * np.cos(g.transverse_pressure_angle) / np.cos(self.working_pressure_angle)
        )

    @property
    def working_helix_angle(self) -> float:
        """β_w of gear a at its working pitch circle, signed [rad]."""
        a = self.a
        return float(np.arctan(np.tan(a.helix_angle) * self.working_diameter("a") / a.reference_diameter))

    @property
    def face_width(self) -> float:
        """Common face width b = min(b_a, b_b) [m]."""
        return min(self.a.face_width, self.b.face_width)

    def addendum_contact_ratios(self) -> tuple[float, float]:
        """ε_a, ε_b: the parts of the path of contact on each side of the pitch point / p_bt [-]."""
        a, b, s = self.a, self.b, self.sign
        awt = self.working_pressure_angle
        p_bt = np.pi * a.transverse_module * np.cos(a.transverse_pressure_angle)
        ga = 0.5 * np.sqrt(max(a.tip_diameter**2 - a.base_diameter**2, 0.0)) - 0.5 * a.base_diameter * np.tan(
            awt
        )
        gb = s * (
            0.5 * np.sqrt(max(b.tip_diameter**2 - b.base_diameter**2, 0.0))
            - 0.5 * b.base_diameter * np.tan(awt)
        )
        return float(ga / p_bt), float(gb / p_bt)

    @property
    def contact_ratio(self) -> float:
        """Transverse contact ratio ε_α = ε_a + ε_b [-]."""
        ea, eb = self.addendum_contact_ratios()
        return ea + eb

    def single_stiffness(self) -> float:
        """c' [N/m²] (ISO 6336-1 method B, module docstring)."""
        c = ISO6336_Q_COEFFICIENTS
        a, b = self.a, self.b
        x1, x2 = a.profile_shift, b.profile_shift
        inv_zn2 = 0.0 if b.internal else 1.0 / b.virtual_teeth
        q = (
            c[0]
            + c[1] / a.virtual_teeth
            + c[2] * inv_zn2
            + c[3] * x1
            + c[4] * x1 / a.virtual_teeth
            + c[5] * x2
            + c[6] * x2 * inv_zn2
            + c[7] * x1**2
            + c[8] * x2**2
        )
        c_th = 1.0 / q
        return c_th * ISO6336_C_M * ISO6336_C_R * ISO6336_C_B * np.cos(a.helix_angle) * N_PER_MM_UM

    def mesh_stiffness(self) -> float:
        """k_n = c_γα b / cos² β_b [N/m] along the line of action (module docstring)."""
        c_gamma = self.single_stiffness() * (0.75 * self.contact_ratio + 0.25)
        return c_gamma * self.face_width / np.cos(self.a.base_helix_angle) ** 2

    def loss_factor(self) -> float:
        """Tooth loss factor H_V (Ohlendorf; module docstring) [-]."""
        ea, eb = self.addendum_contact_ratios()
        eps = ea + eb
        u = self.ratio
        return float(
            np.pi
            * (u + 1.0)
            / (self.a.teeth * u)
            * (1.0 - eps + ea**2 + eb**2)
            / np.cos(self.a.base_helix_angle)
        )

    def direction(self, e: np.ndarray, flank) -> np.ndarray:
        """Unit normal n (..., 3) of the force of a on b for the loaded flank s = ±1 (...,) and e (3,)."""
        awt = self.working_pressure_angle
        bw = self.working_helix_angle
        e = np.asarray(e, dtype=float)
        t = np.cross([0.0, 0.0, 1.0], e)
        s = np.asarray(flank, dtype=float)[..., None]
        n = s * np.cos(awt) * t + np.sin(awt) * e - s * np.cos(awt) * np.tan(bw) * np.array([0.0, 0.0, 1.0])
        return n / np.linalg.norm(n, axis=-1, keepdims=True)
