"""Builders of standard bearing types from their internal geometry. SI units.

Each builder returns a :class:`~bearingkit.analysis.solver.model.BearingModel`. Internal geometry (ball or
roller diameter, pitch diameter, count, conformities, clearance) is what the mechanics needs;
catalogue boundary dimensions alone do not determine it.
"""

from __future__ import annotations

import numpy as np

from bearingkit import checks
from bearingkit.analysis.solver.model import BearingModel
from bearingkit.bearings.common import e_reduced_of
from bearingkit.errors import InputError
from bearingkit.rows.ball.row import BallRow
from bearingkit.rows.cylindrical.row import CylindricalRow


def deep_groove_ball(
    *,
    n_elements: int,
    element_diameter: float,
    pitch_diameter: float,
    conformity_inner: float = 0.52,
    conformity_outer: float = 0.53,
    clearance_radial: float = 0.0,
    material=None,
    tilt_arm: str = "groove_centre",
    name: str = "deep groove ball bearing",
) -> BearingModel:
    """Single-row deep groove ball bearing (free contact angle from the radial clearance)."""
    row = BallRow(
        n_elements=n_elements,
        element_diameter=element_diameter,
        pitch_diameter=pitch_diameter,
        contact_angle=0.0,
        conformity_inner=conformity_inner,
        conformity_outer=conformity_outer,
        clearance=clearance_radial,
        e_reduced=e_reduced_of(material),
        tilt_arm=tilt_arm,
        name="balls",
    )
    return BearingModel((row,), name=name, references=("harris2007",))


def angular_contact_ball(
    *,
    n_elements: int,
    element_diameter: float,
    pitch_diameter: float,
    contact_angle: float,
    conformity_inner: float = 0.52,
    conformity_outer: float = 0.53,
    clearance: float = 0.0,
    material=None,
    tilt_arm: str = "groove_centre",
    name: str = "angular contact ball bearing",
) -> BearingModel:
    """Single-row angular contact ball bearing; carries +F_z (contact_angle > 0) and radial load."""
    checks.in_range("contact_angle", contact_angle, 0.0, np.pi / 2, "rad", closed=False)
    row = BallRow(
        n_elements=n_elements,
        element_diameter=element_diameter,
        pitch_diameter=pitch_diameter,
        contact_angle=contact_angle,
        conformity_inner=conformity_inner,
        conformity_outer=conformity_outer,
        clearance=clearance,
        e_reduced=e_reduced_of(material),
        tilt_arm=tilt_arm,
        name="balls",
    )
    return BearingModel((row,), name=name, references=("harris2007",))


#: Signs of the contact angles (row at −z, row at +z) for paired angular contact bearings. Back-to-back
#: (DB, "O"): contact lines diverge outwards, the pressure centres lie outside the pair; face-to-face
#: (DF, "X"): they converge; tandem (DT): both rows carry the same axial direction.
PAIR_ARRANGEMENTS = {"DB": (+1, -1), "DF": (-1, +1), "DT": (+1, +1)}


def angular_contact_pair(
    *,
    arrangement: str,
    n_elements: int,
    element_diameter: float,
    pitch_diameter: float,
    contact_angle: float,
    row_spacing: float,
    axial_clearance: float = 0.0,
    conformity_inner: float = 0.52,
    conformity_outer: float = 0.53,
    material=None,
    tilt_arm: str = "groove_centre",
    name: str | None = None,
) -> BearingModel:
    """A pair of identical angular contact ball bearings, DB, DF or DT.

    Parameters
    ----------
    arrangement : str
        ``"DB"`` back-to-back, ``"DF"`` face-to-face, ``"DT"`` tandem.
    row_spacing : float [m]
        Axial distance between the two ball rows.
    axial_clearance : float [m]
        Axial play of the pair (negative = axial preload as an interference). Each row gets the
        contact-line clearance s_a·sin α₀ (the inner ring moving by s_a/2 closes one row's gap).
        Ignored for DT (tandem rows are not set against each other).
    """
    checks.one_of("arrangement", arrangement, PAIR_ARRANGEMENTS)
    checks.in_range("contact_angle", contact_angle, 0.0, np.pi / 2, "rad", closed=False)
    checks.positive("row_spacing", row_spacing, "m")
    e_red = e_reduced_of(material)
    signs = PAIR_ARRANGEMENTS[arrangement]
    clearance = 0.0 if arrangement == "DT" else axial_clearance * np.sin(contact_angle)
    rows = tuple(
        BallRow(
            n_elements=n_elements,
            element_diameter=element_diameter,
            pitch_diameter=pitch_diameter,
            contact_angle=sign * contact_angle,
            conformity_inner=conformity_inner,
            conformity_outer=conformity_outer,
            clearance=clearance,
            axial_position=z,
            e_reduced=e_red,
            tilt_arm=tilt_arm,
            name=f"balls_{label}",
        )
        for sign, z, label in zip(signs, (-row_spacing / 2, row_spacing / 2), ("A", "B"), strict=True)
    )
    return BearingModel(
        rows, name=name or f"angular contact ball pair {arrangement}", references=("harris2007",)
    )


def thrust_ball(
    *,
    n_elements: int,
    element_diameter: float,
    pitch_diameter: float,
    conformity: float = 0.54,
    material=None,
    tilt_arm: str = "groove_centre",
    name: str = "thrust ball bearing",
) -> BearingModel:
    """Single-direction thrust ball bearing (α = 90°) carrying +F_z and moments with it."""
    row = BallRow(
        n_elements=n_elements,
        element_diameter=element_diameter,
        pitch_diameter=pitch_diameter,
        contact_angle=np.pi / 2,
        conformity_inner=conformity,
        conformity_outer=conformity,
        e_reduced=e_reduced_of(material),
        tilt_arm=tilt_arm,
        name="balls",
    )
    return BearingModel((row,), name=name, references=("harris2007",))


def cylindrical_roller(
    *,
    n_elements: int,
    element_diameter: float,
    effective_length: float,
    pitch_diameter: float,
    clearance_radial: float = 0.0,
    n_slices: int = 20,
    profile=None,
    line_law: str = "kunert",
    rows: int = 1,
    row_spacing: float | None = None,
    material=None,
    name: str = "cylindrical roller bearing",
) -> BearingModel:
    """Radial cylindrical roller bearing (rollers sliced; carries F_x, F_y and, through the slices, M).

    ``rows = 2`` with ``row_spacing``: the double-row bearing (NN) of :func:`cylindrical_roller_double`.
    """
    if rows not in (1, 2):
        raise InputError(f"rows ({rows}) must be 1 or 2 for a cylindrical roller bearing")
    if rows == 2 or row_spacing is not None:
        if rows != 2 or row_spacing is None:
            raise InputError(
                f"rows ({rows}) and row_spacing ({row_spacing}) go together: rows = 2 needs the axial "
                "distance of the two rows (row_spacing), and row_spacing needs rows = 2"
            )
        if name == "cylindrical roller bearing":
            name = "double-row cylindrical roller bearing"
        return cylindrical_roller_double(
            n_elements=n_elements, element_diameter=element_diameter, effective_length=effective_length,
            pitch_diameter=pitch_diameter, row_spacing=row_spacing, clearance_radial=clearance_radial,
            n_slices=n_slices, profile=profile, line_law=line_law, material=material, name=name,
        )  # fmt: skip
    row = dict(n_elements=n_elements, element_diameter=element_diameter, effective_length=effective_length)
    row |= dict(pitch_diameter=pitch_diameter, n_slices=n_slices, profile=profile, line_law=line_law)
    return _roller_bearing(row, "radial", clearance_radial, material, name)


def cylindrical_roller_double(
    *,
    n_elements: int,
    element_diameter: float,
    effective_length: float,
    pitch_diameter: float,
    row_spacing: float,
    clearance_radial: float = 0.0,
    n_slices: int = 20,
    profile=None,
    line_law: str = "kunert",
    material=None,
    name: str = "double-row cylindrical roller bearing",
) -> BearingModel:
    """Double-row cylindrical roller bearing (NN, NNU): two equal sliced roller rows on shared rings.

    The rows sit at z = ∓row_spacing/2 of one inner and one outer ring (the rings are rigid, as for every
    row of the engine), so a tilt loads one row more than the other and the pair resists the moment
    through both. Carries F_x, F_y and M (no axial load: the rollers are guided by ribs, not loaded).

    Parameters
    ----------
    n_elements, element_diameter, effective_length, pitch_diameter : int, float [m]
        Each row's roller count Z, D_we, L_we and d_m.
    row_spacing : float [m]
        Axial distance of the two row centres (> L_we: the rows do not overlap).
    clearance_radial : float [m]
        Radial internal clearance P_d of the bearing (both rows).
    """
    checks.positive("row_spacing", row_spacing, "m")
    if row_spacing <= effective_length:
        raise InputError(
            f"row_spacing ({row_spacing:g} m) must exceed effective_length ({effective_length:g} m): the "
            "rows would overlap"
        )
    row = dict(n_elements=n_elements, element_diameter=element_diameter, effective_length=effective_length)
    row |= dict(pitch_diameter=pitch_diameter, n_slices=n_slices, profile=profile, line_law=line_law)
    e_red = e_reduced_of(material)
    rows = tuple(
        CylindricalRow(
            **row,
            orientation="radial",
            clearance=clearance_radial,
            axial_position=z,
            e_reduced=e_red,
            name=f"rollers_{label}",
        )
        for z, label in ((-0.5 * row_spacing, "A"), (0.5 * row_spacing, "B"))
    )
    return BearingModel(rows, name=name, references=("harris2007", "kunert1961"))


def cylindrical_roller_thrust(
    *,
    n_elements: int,
    element_diameter: float,
    effective_length: float,
    pitch_diameter: float,
    n_slices: int = 20,
    profile=None,
    line_law: str = "kunert",
    material=None,
    name: str = "cylindrical roller thrust bearing",
) -> BearingModel:
    """Single-direction cylindrical roller thrust bearing carrying +F_z (and moments with it)."""
    row = dict(n_elements=n_elements, element_diameter=element_diameter, effective_length=effective_length)
    row |= dict(pitch_diameter=pitch_diameter, n_slices=n_slices, profile=profile, line_law=line_law)
    return _roller_bearing(row, "thrust_up", 0.0, material, name)


def _roller_bearing(row: dict, orientation: str, clearance: float, material, name: str) -> BearingModel:
    """One sliced cylindrical roller row called ``rollers``: the radial and the thrust bearing alike."""
    rollers = CylindricalRow(
        **row, orientation=orientation, clearance=clearance, e_reduced=e_reduced_of(material), name="rollers"
    )
    return BearingModel((rollers,), name=name, references=("harris2007", "kunert1961"))
