"""What the statics of an analysis are solved with: speed, fits and temperatures, tilt, preload.

SI units (m, N, rad, rad/s; temperatures in °C). :func:`statics_setup` turns an input's
``[operating]`` and ``[fits]`` sections and the operating point into the arguments of
:func:`bearingkit.analysis.solver.quasistatic.solve`:

- **speed**: the rolling elements' inertia at the rotating ring's speed (per case), unless
  ``[operating] speed_effects = false`` (:mod:`bearingkit.analysis.solver.speed`);
- **fits and temperatures**: the clearance chain of every radial row (:mod:`bearingkit.analysis.
  clearance`) as a radial shift of its outer raceway;
- **tilt**: a single-row bearing (all rows in one axial plane) whose file does not say which DOFs are
  free, under no moment and no imposed tilt, is solved with its tilt fixed (θ_x = θ_y = 0), as
  commercial tools do for a single bearing; a note says so. ``[operating] tilt_x/tilt_y`` impose a
  misalignment of the inner ring against the outer (those DOFs are then displacement-controlled);
- **preload**: ``preload_displacement`` pushes the rows that face the other way by that axial
  distance into their contacts; ``preload_force`` finds that distance so that each row carries the
  force at rest without external load (:func:`preload_for_force`). A bearing whose rows all face one
  way takes a preload force as a constant axial spring force and a preload displacement as an imposed
  axial displacement.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

import numpy as np

from bearingkit.errors import InputError

__all__ = ["StaticsSetup", "preload_for_force", "row_directions", "statics_setup"]

#: Largest preload displacement searched for a preload force, as a fraction of the smallest element
#: diameter (1 %: far beyond any real preload, whose approaches are ~1e-4 D).
PRELOAD_SEARCH_LIMIT = 0.01
#: Relative tolerance on the preload force.
PRELOAD_RTOL = 1e-9
#: Element centrifugal force below this share of the external load: speed effects are left out (the
#: turntable bearings of the seeds at ≤ 90 rpm: F_c ~ 1e-8 of the load), so slow bearings keep exactly
#: the zero-speed statics [-].
NEGLIGIBLE_INERTIA = 1e-6


@dataclass
class StaticsSetup:
    """Arguments of the solve and what they imply, for the faces.

    Attributes
    ----------
    free : ndarray (5,) of bool
    displacement : ndarray (C, 5) or None [m, rad]
        Prescribed values of the fixed DOFs (imposed tilt, axial preload displacement).
    load : ndarray (C, 5) [N, N·m]
    speed : OperatingSpeed or None
    offsets : dict row → RacewayOffset, or None
    clearance : ClearanceChain or None
    preload_offset : float or None [m]
        Axial displacement pushing the opposed rows into their contacts.
    notes : list of str
        Assumptions made (tilt fixed by default, speed effects, fits, preload).
    """

    free: np.ndarray
    displacement: np.ndarray | None
    load: np.ndarray
    speed: object = None
    offsets: dict | None = None
    clearance: object = None
    preload_offset: float | None = None
    notes: list = field(default_factory=list)

    @property
    def plain(self) -> bool:
        """True when nothing differs from the input's own solve."""
        return self.speed is None and not self.offsets and self.displacement is None


def row_directions(model) -> np.ndarray:
    """Axial direction (+1, −1, 0) of every row: which way along z each row carries load."""
    out = []
    for r in model.rows:
        if r.kind == "ball":
            out.append(int(np.sign(np.max(r.contact_angle))))
        elif r.kind == "tapered" or (r.kind == "cylindrical" and r.direction != 0):
            out.append(int(r.direction))
        else:
            out.append(0)
    return np.array(out)


def _opposed(model):
    """Rows facing −(first facing row's direction): the ones a preload displacement pushes; or None."""
    dirs = row_directions(model)
    facing = dirs[dirs != 0]
    if facing.size == 0 or np.all(facing == facing[0]):
        return None
    second = -facing[0]
    return [r.name for r, d in zip(model.rows, dirs, strict=True) if d == second], int(second)


def _preload_offsets(model, names, direction, delta, n_cases, base=None):
    from bearingkit.rows.base import RacewayOffset

    out = dict(base or {})
    shift = np.zeros((n_cases, 5))
    shift[:, 2] = -direction * delta  # the contacts see q − shift: u_z = direction·δ into these rows
    for name in names:
        old = out.get(name)
        radial = None if old is None else old.radial
        out[name] = RacewayOffset(shift=shift, radial=radial)
    return out


def preload_for_force(model, force: float, options=None, base_offsets=None) -> float:
    """Axial displacement [m] of the opposed rows that makes each row carry ``force`` at rest, unloaded.

    Parameters
    ----------
    model : BearingModel
        A bearing with rows facing both ways (a DB/DF pair, a composite bearing).
    force : float [N]
        Axial preload force, > 0.
    options : SolverOptions, optional
    base_offsets : dict, optional
        Raceway offsets already applied (fits), kept.

    Returns
    -------
    float [m]
        The preload displacement (bisection on the monotone force–displacement curve).
    """
    from bearingkit.analysis.solver.quasistatic import solve

    opposed = _opposed(model)
    if opposed is None:
        raise InputError("preload_force: the bearing has no rows facing each other to preload")
    names, direction = opposed
    free = np.array([False, False, True, False, False])
    d_min = min(float(np.min(r.element_diameter)) for r in model.rows if hasattr(r, "element_diameter"))

    def carried(delta):
        offs = _preload_offsets(model, names, direction, delta, 1, base_offsets)
        res = solve(model, np.zeros(5), free=free, options=options, raceway_offsets=offs)
        if not res.converged[0]:
            return np.nan
        return float(np.sum([abs(res.row_load(n)[0, 2]) for n in names]))

    lo, hi = 0.0, PRELOAD_SEARCH_LIMIT * d_min
    f_hi = carried(hi)
    if not np.isfinite(f_hi) or f_hi < force:
        raise InputError(
            f"preload_force ({force:.6g} N) cannot be reached within an axial interference of "
            f"{hi * 1e6:.3g} µm; check the force"
        )
    f_lo = carried(lo)
    if f_lo >= force:
        return 0.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        f_mid = carried(mid)
        if not np.isfinite(f_mid) or f_mid > force:
            hi = mid
        else:
            lo = mid
        if hi - lo <= PRELOAD_RTOL * hi:
            break
    return 0.5 * (lo + hi)


def _sections(bearing):
    """The input's parsed [operating]/[fits]/[lubrication] sections (empty for an input built in code)."""
    from bearingkit.io.optional_sections.operating import OperatingSections

    return bearing.sections if bearing.sections is not None else OperatingSections()


def _coplanar(model) -> bool:
    positions = {round(float(np.max(getattr(r, "axial_position", 0.0))), 12) for r in model.rows}
    return len(positions) == 1


def _negligible(analysis, density: float) -> bool:
    """True when every element's centrifugal force (at the orbital speed of the faster ring's half, an
    upper bound) is below :data:`NEGLIGIBLE_INERTIA` of the case's load, in every case."""
    from bearingkit.physics.dynamics import centrifugal

    op = analysis.operating
    load = np.abs(analysis.input.load_matrix()[:, :3]).max(axis=1)
    if np.any(load == 0.0):
        return False
    f_c = np.zeros(op.n_cases)
    for r in analysis.input.model.rows:
        d = float(np.max(getattr(r, "element_diameter", getattr(r, "large_diameter", 0.0))))
        dm = float(np.max(getattr(r, "pitch_diameter", 0.0)))
        if d <= 0 or dm <= 0:
            continue
        length = float(np.max(getattr(r, "effective_length", d)))
        mass = (
            centrifugal.ball_mass(d, density)
            if r.kind == "ball"
            else centrifugal.roller_mass(d, length, density)
        )
        f_c = np.maximum(f_c, centrifugal.centrifugal_force(mass, dm / 2, op.abs_speed / 2))
    return bool(np.all(f_c < NEGLIGIBLE_INERTIA * load))


def _speed(analysis, spec):
    from bearingkit.analysis.solver.speed import OperatingSpeed

    op = analysis.operating
    if spec is not None and spec.speed_effects is False:
        return None, []
    if not np.any(op.speed != 0.0):
        return None, []
    density = float(getattr(analysis.input.material, "density", 7810.0))
    if _negligible(analysis, density):
        return None, [
            "speed effects negligible at these speeds (element centrifugal forces below "
            f"{NEGLIGIBLE_INERTIA:g} of the load): the zero-speed statics are used"
        ]
    control = (spec.raceway_control if spec is not None else None) or "outer"
    zero = np.zeros_like(op.speed)
    inner, outer = (op.speed, zero) if op.rotating == "inner" else (zero, op.speed)
    speed = OperatingSpeed(inner, outer, density, control)
    kinds = {r.kind for r in analysis.input.model.rows}
    gyro = f" and gyroscopic moment of the balls ({control}-raceway control)" if "ball" in kinds else ""
    note = f"speed effects in the statics: centrifugal force of the rolling elements{gyro}"
    return speed, [note]


def _clearance(analysis):
    from bearingkit.analysis.clearance import FitConditions, Temperatures, operating_clearance
    from bearingkit.materials import get_material

    sections = _sections(analysis.input)
    fits, opsec = sections.fits, sections.operating
    temps_given = opsec is not None and any(
        getattr(opsec, f"temperature_{k}") is not None
        for k in ("inner_ring", "outer_ring", "shaft", "housing")
    )
    if fits is None and not temps_given:
        return None
    geometry = analysis.input.geometry.model_dump()
    op_t = analysis.operating.temperature

    def pick(name, default):
        value = None if opsec is None else getattr(opsec, f"temperature_{name}")
        return default if value is None else value

    fit = (
        FitConditions()
        if fits is None
        else FitConditions(
            shaft_tolerance=fits.shaft,
            housing_tolerance=fits.housing,
            statistic=fits.statistic,
            shaft_interference=fits.shaft_interference,
            housing_interference=fits.housing_interference,
            shaft_bore=fits.shaft_bore or 0.0,
            housing_outer_diameter=fits.housing_outer_diameter or np.inf,
            shaft_material=None if fits.shaft_material is None else get_material(fits.shaft_material),
            housing_material=None if fits.housing_material is None else get_material(fits.housing_material),
        )
    )
    inner = pick("inner_ring", op_t)
    outer = pick("outer_ring", op_t)
    temps = Temperatures(
        inner_ring=inner,
        outer_ring=outer,
        shaft=pick("shaft", None),
        housing=pick("housing", None),
        elements=pick("elements", None),
    )
    return operating_clearance(
        analysis.input.model,
        geometry.get("bore"),
        geometry.get("outer_diameter"),
        analysis.input.material,
        fit,
        temps,
    )


def statics_setup(analysis) -> StaticsSetup:
    """The solve arguments of ``analysis`` (module docstring)."""
    b = analysis.input
    spec = _sections(b).operating
    n = analysis.n_cases
    load = b.load_matrix().copy()
    free = np.array(b.free, dtype=bool)
    notes: list[str] = []
    displacement = None
    model = b.model

    speed, speed_notes = _speed(analysis, spec)
    notes += speed_notes
    chain = _clearance(analysis)
    offsets = chain.offsets(model, n) if chain is not None and chain.rows else None

    tilt = [None if spec is None else spec.tilt_x, None if spec is None else spec.tilt_y]
    for k, (value, moment) in enumerate(zip(tilt, ("M_x", "M_y"), strict=True)):
        if value is None:
            continue
        if np.any(load[:, 3 + k] != 0.0):
            raise InputError(
                f"{b.source}: operating.tilt_{'xy'[k]} imposes the tilt, and a load case gives {moment}: "
                "give "
                "either the misalignment or the moment"
            )
        free[3 + k] = False
        displacement = np.zeros((n, 5)) if displacement is None else displacement
        displacement[:, 3 + k] = value
        notes.append(
            f"imposed misalignment theta_{'xy'[k]} = {value * 1e3:.4g} mrad (inner ring against outer)"
        )
    notes += list(getattr(b, "free_notes", ()))
    set_by_caller = {name for name, _ in getattr(b, "dof_overrides", ())}
    default_tilt = (
        b.spec.solver.free is None
        and not set_by_caller & {"theta_x", "theta_y"}
        and all(t is None for t in tilt)
        and _coplanar(model)
        and not np.any(load[:, 3:5] != 0.0)
        and (free[3] or free[4])
    )
    if default_tilt:
        free[3] = free[4] = False
        notes.append(
            "tilt fixed: a single-row bearing is solved with theta_x = theta_y = 0 (the default of "
            "commercial "
            "tools for one bearing on a shaft); list theta_x, theta_y in [solver] free to free them"
        )

    preload_offset = None
    if spec is not None and (spec.preload_force is not None or spec.preload_displacement is not None):
        if spec.preload_force is not None and spec.preload_displacement is not None:
            raise InputError(f"{b.source}: operating: give preload_force or preload_displacement, not both")
        opposed = _opposed(model)
        if opposed is not None:
            names, direction = opposed
            delta = spec.preload_displacement
            if delta is None:
                delta = preload_for_force(model, spec.preload_force, b.options, offsets)
                if delta == 0.0:
                    notes.append(
                        f"preload force {spec.preload_force:.6g} N: the bearing already carries more at "
                        "rest (negative "
                        "clearance or fits), so no preload displacement is added; the preload shown per "
                        "row is it"
                    )
                notes.append(
                    f"preload force {spec.preload_force:.6g} N: rows {names} pushed {delta * 1e6:.4g} µm "
                    "axially "
                    "into their contacts (found at rest, without external load)"
                )
            else:
                notes.append(f"preload displacement {delta * 1e6:.4g} µm on rows {names}")
            offsets = _preload_offsets(model, names, direction, delta, n, offsets)
            preload_offset = float(delta)
        else:
            dirs = row_directions(model)
            direction = int(dirs[dirs != 0][0]) if np.any(dirs != 0) else 0
            if direction == 0:
                raise InputError(f"{b.source}: operating: a preload needs a row that carries axial load")
            if spec.preload_force is not None:
                load[:, 2] += direction * spec.preload_force
                notes.append(
                    f"preload force {spec.preload_force:.6g} N as a constant axial spring force on the "
                    "inner ring"
                )
            else:
                free[2] = False
                displacement = np.zeros((n, 5)) if displacement is None else displacement
                displacement[:, 2] = direction * spec.preload_displacement
                notes.append(
                    f"preload displacement {spec.preload_displacement * 1e6:.4g} µm imposed on u_z (rows "
                    "facing one "
                    "way: axial displacement control)"
                )
    if chain is not None:
        notes.append("fits and temperatures: operating clearance from the clearance chain (see clearance)")
    return StaticsSetup(free, displacement, load, speed, offsets, chain, preload_offset, notes)


def with_free(setup: StaticsSetup, free) -> StaticsSetup:
    """A copy with other free DOFs (used to solve the preload state)."""
    return dataclasses.replace(setup, free=np.asarray(free, dtype=bool))
