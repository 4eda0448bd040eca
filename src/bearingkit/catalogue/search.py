"""Search the catalogue by dimensions and ratings, estimate masses, and screen rows against a duty by the
catalogue method (ISO 281 P = X F_r + Y F_a and ISO 76 P0). SI units (m, N, kg, rev).

:func:`search` answers "d = 40, D ≤ 80, deep groove, C ≥ 30 kN" (``bearingkit catalogue --d 40 --D-max
80 --kind deep_groove --C-min 30kN``); :func:`screen` gives each row's catalogue-method life and static
safety for a load, the first pass of :func:`bearingkit.pipeline.selection.select`, which then runs the
full analysis (ISO 281 and ISO/TS 16281) on the rows that pass. The ratings a search compares with are
the catalogue's where the table row has them, else the ISO 281 / ISO 76 ratings of the estimated
geometry (``rating_source`` says which).

**Mass** (:func:`mass`) is an ESTIMATE from the estimated geometry, not a catalogue value: steel rings
= the annulus π/4 (D² − d²) B less the element rows' envelope (π d_m D_w by D_w for balls, by L_we for
rollers, per row), plus the elements (balls π D_w³/6, rollers π D_we² L_we/4 each); cages, chamfers,
grooves and seals are left out. Checked against SKF's printed masses of five bearings in
tests/catalogue/test_search.py (within 25 %).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from bearingkit.catalogue import tables
from bearingkit.catalogue.internal import estimate
from bearingkit.catalogue.iso_ratings import basis, radial_basis, ratings
from bearingkit.errors import InputError
from bearingkit.materials import get_material
from bearingkit.physics.life import iso76, iso281_load
from bearingkit.physics.life import kinds as life_kinds

#: Short kind names of the command line → catalogue families (``--kind deep_groove``).
KINDS = {
    "deep_groove": ("deep_groove_ball",),
    "angular_contact": ("angular_contact_ball",),
    "double_row_angular_contact": ("double_row_angular_contact_ball",),
    "four_point": ("four_point_contact_ball",),
    "self_aligning": ("self_aligning_ball",),
    "cylindrical": ("cylindrical_roller", "double_row_cylindrical_roller"),
    "tapered": ("tapered_roller",),
    "spherical": ("spherical_roller",),
    "needle": ("needle_roller",),
    "thrust_ball": ("thrust_ball",),
    "thrust_cylindrical": ("thrust_cylindrical_roller",),
    "thrust_spherical": ("spherical_roller_thrust",),
    "ball": ("deep_groove_ball", "angular_contact_ball", "double_row_angular_contact_ball",
             "four_point_contact_ball", "self_aligning_ball", "thrust_ball"),
    "roller": ("cylindrical_roller", "double_row_cylindrical_roller", "tapered_roller", "spherical_roller",
               "needle_roller", "thrust_cylindrical_roller", "spherical_roller_thrust"),
}  # fmt: skip
#: Family → (ISO 281 P law, ISO 76 P0 law, rows whose X, Y apply) of the catalogue method (the laws of
#: :mod:`bearingkit.physics.life.iso281_load` / ``iso76``; four-point, self-aligning, spherical and
#: needle bearings as :data:`bearingkit.physics.life.kinds.KIND_LOAD_LAWS`).
SCREEN_LAWS = {
    "deep_groove_ball": ("deep_groove_ball", "deep_groove_ball", 1),
    "angular_contact_ball": ("angular_contact_ball", "angular_contact_ball", 1),
    "double_row_angular_contact_ball": ("angular_contact_ball", "angular_contact_ball", 2),
    "four_point_contact_ball": life_kinds.KIND_LOAD_LAWS["four_point"],
    "self_aligning_ball": life_kinds.KIND_LOAD_LAWS["self_aligning_ball"],
    "cylindrical_roller": ("radial_roller", "radial_roller", 1),
    "double_row_cylindrical_roller": ("radial_roller", "radial_roller", 2),
    "tapered_roller": ("radial_roller", "radial_roller", 1),
    "spherical_roller": life_kinds.KIND_LOAD_LAWS["spherical_roller"],
    "needle_roller": life_kinds.KIND_LOAD_LAWS["needle"],
    "thrust_ball": ("thrust_ball", "thrust_ball", 1),
    "thrust_cylindrical_roller": ("thrust_roller", "thrust_roller", 1),
    "spherical_roller_thrust": ("thrust_roller", "thrust_roller", 1),
}
#: Families of single rows that carry axial load one way only (a lone one needs F_a >= F_r tan α).
LONE_ONE_DIRECTION = ("angular_contact_ball", "tapered_roller")
#: Density of the rings and elements in the mass estimate [kg/m³] (bearing steel, materials preset).
STEEL = "GCr15"


def families_of(kind: str | None) -> tuple[str, ...]:
    """Catalogue families of a ``--kind`` (a short name of :data:`KINDS` or a family name); all without."""
    if kind is None:
        return tuple(tables.FAMILIES)
    if kind in KINDS:
        return KINDS[kind]
    if kind in tables.FAMILIES:
        return (kind,)
    raise InputError(
        f"kind ({kind!r}) must be one of {', '.join(KINDS)} or a family ({', '.join(tables.FAMILIES)})"
    )


@dataclass(frozen=True)
class Row:
    """A catalogue row with the ratings a search compares (SI).

    Attributes
    ----------
    entry : tables.Entry
    C, C0 : float or None [N]
        The catalogue's where printed, else the estimate's (``rating_source``).
    C_estimate, C0_estimate : float or None [N]
        ISO 281 / ISO 76 of the estimated geometry.
    rating_source : str
        ``"catalogue"`` or ``"estimate"``.
    mass : float or None [kg]
        Estimated (module docstring).
    estimate : internal.Estimate or None
        The estimated geometry (None where the rules fail).
    """

    entry: tables.Entry
    C: float | None
    C0: float | None
    C_estimate: float | None
    C0_estimate: float | None
    rating_source: str
    mass: float | None
    estimate: object = None

    def to_dict(self) -> dict:
        """JSON-ready (SI, units in keys)."""
        e = self.entry
        return {
            "designation": e.designation,
            "family": e.family,
            "d_m": e.bore,
            "D_m": e.outer_diameter,
            "B_m": e.width,
            "C_catalogue_N": e.C,
            "C0_catalogue_N": e.C0,
            "C_estimate_N": self.C_estimate,
            "C0_estimate_N": self.C0_estimate,
            "rating_basis": basis(e.family),
            "mass_estimate_kg": self.mass,
            "source": e.source,
        }


def mass(est) -> float:
    """Estimated mass [kg] of a bearing from its estimated geometry (module docstring)."""
    e = est.entry
    rho = get_material(STEEL).density
    d, big_d, width, dm = e.bore, e.outer_diameter, e.width, est.pitch_diameter
    dw, rows, z = est.element_diameter, est.rows, est.n_elements
    annulus = 0.25 * math.pi * (big_d**2 - d**2) * width
    if est.effective_length is None:
        envelope, elements = math.pi * dm * dw * dw, z * math.pi * dw**3 / 6.0
    else:
        lw = est.effective_length
        envelope, elements = math.pi * dm * dw * lw, z * 0.25 * math.pi * dw**2 * lw
    if e.family in ("thrust_ball", "thrust_cylindrical_roller"):
        envelope = 0.0  # the washers are flat discs beside the row: the annulus is the washers' outline
        annulus *= 1.0 - dw / width
    return rho * max(annulus - rows * envelope, 0.0) + rho * rows * elements


def row_of(entry) -> Row:
    """The :class:`Row` of a catalogue entry (estimate, ratings, mass); ratings None where the rules fail."""
    return _row_of(entry.family, entry.designation)


@functools.cache
def _row_of(family: str, designation: str) -> Row:
    entry = tables.entries(family)[designation]
    try:
        est = estimate(entry)
        c_est, c0_est = ratings(est)
        m = mass(est)
    except InputError:
        est = c_est = c0_est = m = None
    cat = entry.C is not None
    return Row(
        entry,
        entry.C if cat else c_est,
        entry.C0 if cat and entry.C0 is not None else c0_est,
        c_est,
        c0_est,
        "catalogue" if cat else "estimate",
        m,
        est,
    )


def search(
    pattern: str | None = None,
    *,
    kind: str | None = None,
    d: float | None = None,
    d_min: float | None = None,
    d_max: float | None = None,
    D_min: float | None = None,
    D_max: float | None = None,
    B_max: float | None = None,
    C_min: float | None = None,
    C0_min: float | None = None,
) -> list[Row]:
    """Catalogue rows meeting every given bound, in table order.

    Parameters
    ----------
    pattern : str, optional
        Shell pattern of the base designation (``"62*"``), as :func:`bearingkit.catalogue.find`.
    kind : str, optional
        :data:`KINDS` key or family.
    d, d_min, d_max, D_min, D_max, B_max : float, optional [m]
        Bore (exact, 1 µm) and bounds on bore, outside diameter and width (tapered: T).
    C_min, C0_min : float, optional [N]
        Lower bounds on C, C0 (catalogue's, else the estimate's; thrust rows: axial ratings).
    """
    from bearingkit.catalogue import find

    fams = set(families_of(kind))
    candidates = find(pattern) if pattern else tables.all_entries()
    out = []
    for e in candidates:
        if e.family not in fams or e.extra.get("inner_ring") == "no":
            continue
        if not _within(e.bore, d, d_min, d_max) or not _within(e.outer_diameter, None, D_min, D_max):
            continue
        if B_max is not None and e.width > B_max * (1 + 1e-9):
            continue
        row = row_of(e)
        if C_min is not None and not (row.C is not None and row.C >= C_min):
            continue
        if C0_min is not None and not (row.C0 is not None and row.C0 >= C0_min):
            continue
        out.append(row)
    return out


def _within(x: float, exact, lo, hi) -> bool:
    if exact is not None and abs(x - exact) > 1e-6:
        return False
    return (lo is None or x >= lo * (1 - 1e-9)) and (hi is None or x <= hi * (1 + 1e-9))


@dataclass(frozen=True)
class Screen:
    """A row's catalogue-method result for one load (SI): ``P`` [N], ``life`` [rev] (L10 = (C/P)^p 10⁶),
    ``P0`` [N] and ``static_safety`` C0/P0; ``reason`` why there is none (None when computed)."""

    row: Row
    P: float | None = None
    life: float | None = None
    P0: float | None = None
    static_safety: float | None = None
    reason: str | None = None


def screen(row: Row, load_radial: float, load_axial: float) -> Screen:
    """ISO 281 P, L10 and ISO 76 P0, s0 of one row for F_r, F_a [N] by the catalogue method (one bearing)."""
    e = row.entry
    if row.C is None or row.C0 is None or row.estimate is None:
        return Screen(row, reason="no ratings (the estimate rules do not apply)")
    p_law, p0_law, n_rows = SCREEN_LAWS[e.family]
    alpha = 0.5 * math.pi if e.family.startswith("thrust") else row.estimate.contact_angle
    f0 = None
    if p_law in ("deep_groove_ball", "angular_contact_ball"):
        # ISO 281 Table 3 reads e, X, Y at i f0 F_a/C0r for deep groove and angular contact below 20°
        gamma = row.estimate.element_diameter * math.cos(alpha) / row.estimate.pitch_diameter
        f0 = float(iso76.f0_radial_ball(gamma))
    try:
        p = float(
            iso281_load.equivalent_dynamic_load(load_radial, load_axial, p_law, alpha, n_rows, row.C0, f0)
        )
        p0 = float(iso76.equivalent_static_load(load_radial, load_axial, p0_law, alpha, n_rows))
    except InputError as exc:
        return Screen(row, reason=f"no ISO 281 P: {exc}")
    if not p > 0:
        return Screen(row, reason="no load")
    if e.family in LONE_ONE_DIRECTION and load_radial > 0 and load_axial < load_radial * math.tan(alpha):
        # one row at α carries F_a >= F_r tan α at least (a single loaded element): below it no equilibrium
        return Screen(
            row, reason="alone it cannot carry F_a < F_r tan(alpha): pair it with an opposing bearing"
        )
    exponent = 3.0 if tables.FAMILIES[e.family][2] == "ball" else 10.0 / 3.0
    c, c0 = radial_basis(e.family, row.C, row.C0)  # QJ: the axial C_a, C_0a as C_r, C_0r (P = X F_r + Y F_a)
    return Screen(row, p, (c / p) ** exponent * 1e6, p0, c0 / p0 if p0 > 0 else np.inf)
