"""Operating clearance from fits and temperatures: the clearance chain (initial → mounted → operating).

SI units (m, Pa, 1/K; temperatures in °C). For every radial row of a bearing:

1. **Mounted** (at the reference temperature T_ref, 20 °C): the interference of the inner ring on
   its shaft (shaft field, e.g. k5, against the ring bore's ISO 492 tolerance) gives the Lamé fit
   pressure (solid or hollow shaft, shaft and ring materials) and the growth of the inner raceway;
   the interference of the outer ring in its housing (e.g. N7) shrinks the outer raceway
   (:mod:`bearingkit.physics.structure.fits`, :mod:`~bearingkit.physics.structure.tolerances`).
2. **Thermal**: the rings and elements grow with their temperatures (inner ring T_i, outer ring T_o,
   elements at (T_i + T_o)/2 unless given), and the fits change with the shaft and housing
   temperatures (interference d[α_s(T_s − T_ref) − α_r(T_i − T_ref)] on the shaft, D[α_r(T_o − T_ref)
   − α_h(T_h − T_ref)] in the housing; a fit that opens no longer presses the ring).
3. **Operating** = initial + changes. A negative operating clearance is a preload.

Diametral (radial) clearance changes are reported per row; rows whose clearance is measured along an
inclined contact line (angular-contact ball, tapered) show it changed by ΔP_d cos α (first order),
while the solve applies the exact radial shift of the outer raceway by ΔP_d/2 for every element
(:class:`~bearingkit.rows.base.RacewayOffset` ``radial``). Thrust rows keep their axial play (a radial
fit does not change it). The rings are taken as thick cylinders between the seat and the raceway
(contact) diameter d_m ∓ D cos α: the shoulders make a real ring stiffer, so the raceway change is an
upper estimate (a documented choice; catalogue methods use an "equivalent" ring diameter instead).
Balls at the mean ring temperature is a choice too (no source here gives it).

References: ISO 286-1:2010, ISO 492:2014; Timoshenko & Goodier (1951) §28; Harris & Kotzalas (2007)
Essential Concepts ch. 2 (fitting practice, thermal change of clearance).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearingkit import checks
from bearingkit.errors import InputError
from bearingkit.physics.structure import fits as lame
from bearingkit.physics.structure import tolerances

#: Assembly (reference) temperature of the fits and clearances [°C] (ISO 1: 20 °C).
REFERENCE_TEMPERATURE_C = 20.0


@dataclass(frozen=True)
class FitConditions:
    """How the bearing sits on its shaft and in its housing.

    Parameters
    ----------
    shaft_tolerance : str or None
        ISO 286 field of the shaft seat (``"k5"``); None with ``shaft_interference`` None: no fit.
    housing_tolerance : str or None
        ISO 286 field of the housing seat (``"H7"``).
    statistic : str or float
        ``"mean"``, ``"min"``, ``"max"`` or a percentile in (0, 100) (:func:`fit_interference`).
    shaft_interference, housing_interference : float or None [m]
        Given diametral interferences (replace the fields).
    shaft_bore : float [m]
        Bore of a hollow shaft (0: solid).
    housing_outer_diameter : float [m]
        Outside diameter of the housing around the ring (``inf``: a housing much larger than the ring).
    shaft_material, housing_material : Material or None
        Default: structural steel (:data:`bearingkit.materials.MATERIALS`).
    """

    shaft_tolerance: str | None = None
    housing_tolerance: str | None = None
    statistic: object = "mean"
    shaft_interference: float | None = None
    housing_interference: float | None = None
    shaft_bore: float = 0.0
    housing_outer_diameter: float = np.inf
    shaft_material: object = None
    housing_material: object = None

    def __post_init__(self):
        checks.non_negative("shaft_bore", self.shaft_bore, "m")
        if not np.isinf(self.housing_outer_diameter):
            checks.positive("housing_outer_diameter", self.housing_outer_diameter, "m")


@dataclass(frozen=True)
class Temperatures:
    """Operating temperatures [°C], scalars or (C,) arrays per load case.

    Parameters
    ----------
    inner_ring, outer_ring : float or array
    shaft, housing : float or array or None
        Default: the inner and outer ring's.
    elements : float or array or None
        Default: the mean of the rings'.
    reference : float
        Assembly temperature (default 20 °C).
    """

    inner_ring: object = REFERENCE_TEMPERATURE_C
    outer_ring: object = REFERENCE_TEMPERATURE_C
    shaft: object = None
    housing: object = None
    elements: object = None
    reference: float = REFERENCE_TEMPERATURE_C

    def __post_init__(self):
        for name in ("inner_ring", "outer_ring", "shaft", "housing", "elements", "reference"):
            value = getattr(self, name)
            if value is not None:
                checks.in_range(name, value, -273.15, 1000.0, "degC")


@dataclass
class ClearanceChain:
    """The clearance chain per radial row (arrays (C,) over the load cases, SI).

    Attributes
    ----------
    rows : list of str
        Names of the radial rows (thrust rows are left out).
    initial, mounted, operating : dict of row → ndarray (C,) [m]
        The row's clearance in its own measure (diametral for radial rows, along the contact line
        for angular rows) before mounting, mounted at T_ref, and at the operating temperatures.
    fit_inner, fit_outer, thermal : dict of row → ndarray (C,) [m]
        Diametral (radial) clearance changes: inner raceway growth from the shaft fit, outer raceway
        shrink from the housing fit (both at T_ref, as reductions ≥ 0), thermal change (signed).
    radial_change : dict of row → ndarray (C,) [m]
        Total diametral change operating − initial, applied to the solve as a radial raceway shift.
    interference_inner, interference_outer : ndarray (C,) [m]
        Interference of the inner and outer ring fits at the operating temperatures (negative: loose).
    pressure_inner, pressure_outer : ndarray (C,) [Pa]
        Fit pressures at the operating temperatures.
    warnings : list of str
    """

    rows: list
    initial: dict
    mounted: dict
    operating: dict
    fit_inner: dict
    fit_outer: dict
    thermal: dict
    radial_change: dict
    interference_inner: np.ndarray
    interference_outer: np.ndarray
    pressure_inner: np.ndarray
    pressure_outer: np.ndarray
    warnings: list = field(default_factory=list)

    def offsets(self, model, n_cases: int) -> dict:
        """Raceway offsets for the solve: the outer raceway of each radial row moved outward by ΔP/2."""
        from bearingkit.rows.base import RacewayOffset

        out = {}
        for row in model.rows:
            if row.name in self.radial_change:
                change = np.broadcast_to(self.radial_change[row.name], (n_cases,))
                out[row.name] = RacewayOffset(
                    radial=np.repeat((change / 2.0)[:, None], row.n_elements, axis=1)
                )
        return out

    def to_dict(self, case: int) -> dict:
        """JSON-ready chain of one case (µm-free SI, units in keys)."""
        pick = lambda d, r: float(np.broadcast_to(d[r], (case + 1,))[case])  # noqa: E731
        return {
            "rows": [
                {
                    "name": r,
                    "initial_m": pick(self.initial, r),
                    "fit_inner_m": pick(self.fit_inner, r),
                    "fit_outer_m": pick(self.fit_outer, r),
                    "mounted_m": pick(self.mounted, r),
                    "thermal_m": pick(self.thermal, r),
                    "operating_m": pick(self.operating, r),
                }
                for r in self.rows
            ],
            "interference_inner_m": float(np.broadcast_to(self.interference_inner, (case + 1,))[case]),
            "interference_outer_m": float(np.broadcast_to(self.interference_outer, (case + 1,))[case]),
            "pressure_inner_Pa": float(np.broadcast_to(self.pressure_inner, (case + 1,))[case]),
            "pressure_outer_Pa": float(np.broadcast_to(self.pressure_outer, (case + 1,))[case]),
            "warnings": list(self.warnings),
        }


def _row_geometry(row):
    """(contact angle, inner raceway diameter, outer raceway diameter, element diameter) or None (thrust)."""
    if row.kind == "tapered":
        from bearingkit.rows.tapered.row import TapGeometry

        geo = TapGeometry(row)
        return (
            float(row.contact_angle_outer),
            2 * geo.radius_inner,
            2 * geo.radius_outer,
            geo.radius_outer - geo.radius_inner,
        )
    if row.kind == "ball":
        alpha = float(np.max(np.abs(row.contact_angle)))
        if alpha > np.radians(60.0):
            return None
    elif row.kind == "cylindrical":
        if row.direction != 0:
            return None
        alpha = 0.0
    else:
        return None
    d, dm = float(np.max(row.element_diameter)), float(np.max(row.pitch_diameter))
    return alpha, dm - d * np.cos(alpha), dm + d * np.cos(alpha), d


def _alpha(material, default_note: list, what: str) -> float:
    from bearingkit.materials import BEARING_STEEL_THERMAL_EXPANSION

    if material.thermal_expansion is None:
        default_note.append(
            f"{what} material {material.name!r} has no thermal expansion coefficient; bearing steel's "
            f"{BEARING_STEEL_THERMAL_EXPANSION:.3g} 1/K is used"
        )
        return BEARING_STEEL_THERMAL_EXPANSION
    return float(material.thermal_expansion)


def _interference(given, code, seat_diameter, ring: str, statistic) -> float:
    if given is not None:
        return float(given)
    if code is None:
        return 0.0
    seat = tolerances.tolerance_field(code, seat_diameter)
    ring_dev = tolerances.ring_deviation(ring, seat_diameter)
    if ring == "inner":  # shaft (inner part) in the ring bore (outer part)
        return tolerances.fit_interference(seat, ring_dev, statistic)
    return tolerances.fit_interference(ring_dev, seat, statistic)  # ring (inner part) in the housing


def operating_clearance(
    model, bore, outer_diameter, ring_material, fit: FitConditions, temps: Temperatures
) -> ClearanceChain:
    """The clearance chain of every radial row (module docstring).

    Parameters
    ----------
    model : BearingModel
    bore, outer_diameter : float [m]
        Bearing bore d and outside diameter D (the seat diameters).
    ring_material : Material
        Rings and elements (E, ν, α).
    fit : FitConditions
    temps : Temperatures

    Returns
    -------
    ClearanceChain
    """
    from bearingkit.materials import get_material

    if bore is None or outer_diameter is None:
        raise InputError(
            "fits: the bearing's bore and outer_diameter are needed for the fits; give them in [geometry]"
        )
    notes: list[str] = []
    shaft_mat = fit.shaft_material or get_material("structural_steel")
    housing_mat = fit.housing_material or get_material("structural_steel")
    a_r = _alpha(ring_material, notes, "ring")
    a_s = _alpha(shaft_mat, notes, "shaft")
    a_h = _alpha(housing_mat, notes, "housing")
    t_ref = float(temps.reference)
    t_i = np.atleast_1d(np.asarray(temps.inner_ring, dtype=float))
    t_o = np.atleast_1d(np.asarray(temps.outer_ring, dtype=float))
    t_s = t_i if temps.shaft is None else np.atleast_1d(np.asarray(temps.shaft, dtype=float))
    t_h = t_o if temps.housing is None else np.atleast_1d(np.asarray(temps.housing, dtype=float))
    t_e = (
        0.5 * (t_i + t_o)
        if temps.elements is None
        else np.atleast_1d(np.asarray(temps.elements, dtype=float))
    )
    if fit.shaft_bore >= bore:
        raise InputError(
            f"fits.shaft_bore ({fit.shaft_bore:.6g} m) must be smaller than the bearing bore ({bore:.6g} m)"
        )
    i_ref = _interference(fit.shaft_interference, fit.shaft_tolerance, bore, "inner", fit.statistic)
    o_ref = _interference(
        fit.housing_interference, fit.housing_tolerance, outer_diameter, "outer", fit.statistic
    )
    i_op = i_ref + bore * (a_s * (t_s - t_ref) - a_r * (t_i - t_ref))
    o_op = o_ref + outer_diameter * (a_r * (t_o - t_ref) - a_h * (t_h - t_ref))
    if i_ref > 0 and np.any(i_op <= 0):
        notes.append(
            "the inner ring's interference fit opens at the operating temperatures (ring creep risk)"
        )
    if o_ref > 0 and np.any(o_op <= 0):
        notes.append("the outer ring's interference fit opens at the operating temperatures")
    e_r, nu_r = ring_material.youngs_modulus, ring_material.poisson_ratio
    chain = dict(
        initial={}, mounted={}, operating={}, fit_inner={}, fit_outer={}, thermal={}, radial_change={}
    )
    rows = []
    p_i_op = p_o_op = np.zeros_like(t_i)
    for row in model.rows:
        geo = _row_geometry(row)
        if geo is None:
            continue
        alpha, d_ir, d_or, d_el = geo
        if not bore < d_ir < d_or < outer_diameter:
            raise InputError(
                f"row {row.name!r}: raceway diameters {d_ir * 1e3:.4g}/{d_or * 1e3:.4g} mm must lie "
                f"between the bore ({bore * 1e3:.4g} mm) and the outer diameter "
                f"({outer_diameter * 1e3:.4g} mm)"
            )

        def grow(interference, d_ir=d_ir):
            p = lame.fit_pressure(
                interference,
                bore,
                fit.shaft_bore,
                d_ir,
                shaft_mat.youngs_modulus,
                shaft_mat.poisson_ratio,
                e_r,
                nu_r,
            )
            return p, lame.ring_expansion(p, bore, d_ir, e_r)

        def shrink(interference, d_or=d_or):
            p = lame.fit_pressure(
                interference,
                outer_diameter,
                d_or,
                fit.housing_outer_diameter,
                e_r,
                nu_r,
                housing_mat.youngs_modulus,
                housing_mat.poisson_ratio,
            )
            return p, lame.ring_contraction(p, d_or, outer_diameter, e_r)

        _, fi_ref = grow(i_ref)
        _, fo_ref = shrink(o_ref)
        p_i_op, fi_op = grow(i_op)
        p_o_op, fo_op = shrink(o_op)
        # Raceways and elements grow with their own temperatures (elements of the ring material).
        rings = (
            lame.thermal_growth(d_or, a_r, t_o - t_ref)
            - lame.thermal_growth(d_ir, a_r, t_i - t_ref)
            - 2 * lame.thermal_growth(d_el, a_r, t_e - t_ref)
        )
        mounted_change = -(fi_ref + fo_ref)
        total = -(fi_op + fo_op) + rings
        scale = np.cos(alpha)
        initial = float(np.max(row.clearance))
        name = row.name
        rows.append(name)
        chain["initial"][name] = np.full(t_i.shape, initial)
        chain["fit_inner"][name] = np.full(t_i.shape, float(fi_ref))
        chain["fit_outer"][name] = np.full(t_i.shape, float(fo_ref))
        chain["mounted"][name] = np.full(t_i.shape, float(initial + mounted_change * scale))
        chain["thermal"][name] = (total - mounted_change) * np.ones_like(t_i)
        chain["radial_change"][name] = total * np.ones_like(t_i)
        chain["operating"][name] = initial + total * scale
        if np.any(chain["operating"][name] < 0) and initial >= 0:
            worst = float(np.min(chain["operating"][name]))
            notes.append(
                f"row {name!r}: the clearance is lost to the fits and temperatures: operating clearance "
                f"{worst * 1e6:.3g} µm (a preload); check the fit, the clearance class or the temperatures"
            )
    return ClearanceChain(
        rows=rows,
        **chain,
        interference_inner=np.broadcast_to(i_op, t_i.shape).astype(float),
        interference_outer=np.broadcast_to(o_op, t_i.shape).astype(float),
        pressure_inner=np.broadcast_to(p_i_op, t_i.shape).astype(float),
        pressure_outer=np.broadcast_to(p_o_op, t_i.shape).astype(float),
        warnings=notes,
    )
